/* Checkpoint/resume in natural order (independent of the number of ranks), PETSc binary format:
   [magic, it, nreal, Nv, Ne, has_edge] ints, reals, positions (3 Nv), edge field (Ne). */
#include "cs_mesh.h"
#include <petscviewer.h>
#include <stdio.h>

#define CS_CHECKPOINT_MAGIC 20211107

PetscErrorCode CSCheckpointWrite(CSMesh m, const char path[], PetscInt it, PetscInt nreal, const PetscReal reals[], Vec x, Vec edgeField)
{
  PetscViewer v;
  PetscMPIInt rank;
  PetscInt    head[6] = {CS_CHECKPOINT_MAGIC, it, nreal, m->Nv, m->Ne, edgeField ? 1 : 0};
  char        tmp[PETSC_MAX_PATH_LEN];
  Vec         nat;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  PetscCall(PetscSNPrintf(tmp, sizeof(tmp), "%s.tmp", path));
  PetscCall(PetscViewerBinaryOpen(m->comm, tmp, FILE_MODE_WRITE, &v));
  PetscCall(PetscViewerBinarySetSkipInfo(v, PETSC_TRUE));
  PetscCall(PetscViewerBinaryWrite(v, head, 6, PETSC_INT));
  if (nreal) PetscCall(PetscViewerBinaryWrite(v, reals, nreal, PETSC_REAL));
  PetscCall(CSMeshGather(&m->natV3, x, &nat));
  PetscCall(VecView(nat, v));
  if (edgeField) {
    PetscCall(CSMeshGather(&m->natE1, edgeField, &nat));
    PetscCall(VecView(nat, v));
  }
  PetscCall(PetscViewerDestroy(&v));
  {
    int ok = 1; /* rank 0 renames; every rank learns the outcome, so a failure cannot leave the others waiting */
    if (!rank) ok = !rename(tmp, path);
    PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, m->comm));
    PetscCheck(ok, m->comm, PETSC_ERR_FILE_WRITE, "checkpoint: cannot rename %s to %s", tmp, path);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSCheckpointRead(CSMesh m, const char path[], PetscInt *it, PetscInt nreal, PetscReal reals[], Vec x, Vec edgeField)
{
  PetscViewer v;
  PetscInt    head[6];
  PetscBool   exists;
  PetscFunctionBeginUser;
  PetscCall(PetscTestFile(path, 'r', &exists));
  PetscCheck(exists, m->comm, PETSC_ERR_FILE_OPEN, "-resume %s: no such checkpoint file", path);
  PetscCall(PetscViewerBinaryOpen(m->comm, path, FILE_MODE_READ, &v));
  PetscCall(PetscViewerBinarySetSkipInfo(v, PETSC_TRUE));
  PetscCall(PetscViewerBinaryRead(v, head, 6, NULL, PETSC_INT));
  PetscCheck(head[0] == CS_CHECKPOINT_MAGIC, m->comm, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: not a confsurf checkpoint", path);
  PetscCheck(head[3] == m->Nv && head[4] == m->Ne, m->comm, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: written for %" PetscInt_FMT " vertices and %" PetscInt_FMT " edges, the mesh has %" PetscInt_FMT " and %" PetscInt_FMT, path, head[3], head[4], m->Nv, m->Ne);
  PetscCheck(head[2] == nreal, m->comm, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: %" PetscInt_FMT " scalars stored, %" PetscInt_FMT " expected (written by another method?)", path, head[2], nreal);
  PetscCheck(head[5] == (edgeField ? 1 : 0), m->comm, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: the edge field is %s", path, head[5] ? "present but not expected" : "missing");
  *it = head[1];
  if (nreal) PetscCall(PetscViewerBinaryRead(v, reals, nreal, NULL, PETSC_REAL));
  PetscCall(VecLoad(m->natV3.vec, v));
  PetscCall(CSMeshScatter(&m->natV3, m->natV3.vec, x));
  if (edgeField) {
    PetscCall(VecLoad(m->natE1.vec, v));
    PetscCall(CSMeshScatter(&m->natE1, m->natE1.vec, edgeField));
  }
  PetscCall(PetscViewerDestroy(&v));
  PetscFunctionReturn(0);
}
