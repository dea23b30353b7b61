/* File-order I/O of distributed fields: gather to rank 0 for writing, scatter from rank 0 after reading. */
#include "cs_mesh.h"
#include "cs_util.h"

PetscErrorCode CSMeshGather(CSMeshNatural *field, Vec g, Vec *nat)
{
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(field->sc, g, field->vec, INSERT_VALUES, SCATTER_REVERSE));
  PetscCall(VecScatterEnd(field->sc, g, field->vec, INSERT_VALUES, SCATTER_REVERSE));
  *nat = field->vec;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshScatter(CSMeshNatural *field, Vec nat, Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(VecScatterBegin(field->sc, nat, g, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(field->sc, nat, g, INSERT_VALUES, SCATTER_FORWARD));
  PetscFunctionReturn(0);
}

/* rank 0: the natural-order positions nat with the input's faces into path */
static PetscErrorCode WriteRoot(CSMesh m, Vec nat, const char path[])
{
  CSMeshData         out = m->serial;
  const PetscScalar *a;
  PetscErrorCode     ierr;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(3 * out.nv, &out.x));
  PetscCall(VecGetArrayRead(nat, &a));
  for (PetscInt i = 0; i < 3 * out.nv; i++) out.x[i] = PetscRealPart(a[i]);
  PetscCall(VecRestoreArrayRead(nat, &a));
  CSCaptureError(ierr, CSMeshDataWrite(path, &out));
  PetscCall(PetscFree(out.x));
  PetscCall(CSSyncError(PETSC_COMM_SELF, ierr));
  PetscFunctionReturn(0);
}

/* Collective: a failure on rank 0 reaches every rank */
PetscErrorCode CSMeshWrite(CSMesh m, Vec x, const char path[])
{
  Vec nat = NULL;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGather(&m->natV3, x, &nat));
  CSRootCall(m->comm, WriteRoot(m, nat, path));
  PetscFunctionReturn(0);
}

/* Rank 0: read path, validate, and insist on the same triangles as the mesh (the same vertex numbering). */
static PetscErrorCode ReadCompatible(CSMesh m, const char option[], const char path[], CSMeshData *md)
{
  CSTopology topo;
  PetscFunctionBeginUser;
  PetscCall(CSMeshDataRead(path, md));
  PetscCall(CSMeshDataValidate(md, &topo));
  if (md->nv != m->serial.nv || md->nf != m->serial.nf) {
    PetscInt nv = md->nv, nf = md->nf;
    PetscCall(CSMeshDataDestroy(md));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "%s %s: has %" PetscInt_FMT " vertices and %" PetscInt_FMT " faces, the mesh %s has %" PetscInt_FMT " and %" PetscInt_FMT ": not the same connectivity", option, path, nv, nf, m->name, m->serial.nv, m->serial.nf);
  }
  for (PetscInt f = 0; f < md->nf; f++) {
    const PetscInt *a = md->f + 3 * f, *b = m->serial.f + 3 * f;
    PetscInt        sa[3] = {a[0], a[1], a[2]}, sb[3] = {b[0], b[1], b[2]};
    /* compare vertex sets: the mesh may have been flipped to outward orientation after reading */
    PetscCall(PetscSortInt(3, sa));
    PetscCall(PetscSortInt(3, sb));
    if (sa[0] != sb[0] || sa[1] != sb[1] || sa[2] != sb[2]) {
      PetscInt a0 = a[0], a1 = a[1], a2 = a[2];
      PetscCall(CSMeshDataDestroy(md));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "%s %s: face %" PetscInt_FMT " is (%" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "), in %s it is (%" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "): not the same connectivity", option, path, f, a0, a1, a2, m->name, b[0], b[1], b[2]);
    }
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshLoadCompatiblePositions(CSMesh m, const char option[], const char path[], Vec *x)
{
  CSMeshData  md;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  PetscCall(PetscMemzero(&md, sizeof(md)));
  CSRootCall(m->comm, ReadCompatible(m, option, path, &md));
  if (!rank) {
    PetscScalar *a;
    PetscCall(VecGetArray(m->natV3.vec, &a));
    for (PetscInt i = 0; i < 3 * md.nv; i++) a[i] = md.x[i];
    PetscCall(VecRestoreArray(m->natV3.vec, &a));
    PetscCall(CSMeshDataDestroy(&md));
  }
  PetscCall(DMCreateGlobalVector(m->dmV3, x));
  PetscCall(CSMeshScatter(&m->natV3, m->natV3.vec, *x));
  PetscFunctionReturn(0);
}
