/* The input's texture coordinates distributed with the faces (issue 38): rank 0's per-corner UVs (CSMeshData uv,
   fuv) become every rank's table of its local faces, so what measures or shows them runs distributed. */
#include "cs_mesh.h"
#include "cs_util.h"

/* A face field of 9 values in file order: the three file corners' vertex numbers, then their (u, v) pairs. */
#define CS_UV_DOF 9

static PetscErrorCode FillNatural(const CSMeshData *md, Vec nat)
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(nat, &a));
  for (PetscInt f = 0; f < md->nf; f++)
    for (int k = 0; k < 3; k++) {
      PetscInt t = md->fuv[3 * f + k];
      a[CS_UV_DOF * f + k]         = md->f[3 * f + k];
      a[CS_UV_DOF * f + 3 + 2 * k] = md->uv[2 * t];
      a[CS_UV_DOF * f + 4 + 2 * k] = md->uv[2 * t + 1];
    }
  PetscCall(VecRestoreArray(nat, &a));
  PetscFunctionReturn(0);
}

/* local face f's corners in faceVert order, matched to the file's corners by vertex number (an orientation flip or a
   rotated cell keeps each UV on its vertex) */
static PetscErrorCode TakeLocal(CSMesh m, const PetscScalar *a)
{
  PetscFunctionBeginUser;
  for (PetscInt f = 0; f < m->nf; f++)
    for (int c = 0; c < 3; c++) {
      PetscInt v = m->vertNatural[m->faceVert[3 * f + c]], k = 0;
      while (k < 3 && (PetscInt)PetscRealPart(a[CS_UV_DOF * f + k]) != v) k++;
      PetscCheck(k < 3, PETSC_COMM_SELF, PETSC_ERR_PLIB, "texture coordinates: face %" PetscInt_FMT " has no corner at vertex %" PetscInt_FMT, m->faceNatural[f], v);
      m->faceUV[6 * f + 2 * c]     = PetscRealPart(a[CS_UV_DOF * f + 3 + 2 * k]);
      m->faceUV[6 * f + 2 * c + 1] = PetscRealPart(a[CS_UV_DOF * f + 4 + 2 * k]);
    }
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshTextureCreate(CSMesh m, const CSMeshData *md)
{
  PetscMPIInt        rank;
  PetscInt           has;
  DM                 dm;
  CSMeshNatural      nat;
  Vec                g, l;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  has = (!rank && md->fuv) ? 1 : 0;
  PetscCallMPI(MPI_Bcast(&has, 1, MPIU_INT, 0, m->comm));
  if (!has) PetscFunctionReturn(0);
  PetscCall(CSMeshCreateFieldDM(m->dm, 2, CS_UV_DOF, "face_uv", &dm));
  PetscCall(CSMeshNaturalCreate(m, dm, 2, CS_UV_DOF, &nat));
  if (!rank) PetscCall(FillNatural(md, nat.vec));
  PetscCall(DMGetGlobalVector(dm, &g));
  PetscCall(DMGetLocalVector(dm, &l));
  PetscCall(CSMeshScatter(&nat, nat.vec, g));
  PetscCall(DMGlobalToLocal(dm, g, INSERT_VALUES, l));
  PetscCall(PetscMalloc1(6 * m->nf, &m->faceUV));
  PetscCall(VecGetArrayRead(l, &a));
  PetscCall(TakeLocal(m, a));
  PetscCall(VecRestoreArrayRead(l, &a));
  PetscCall(DMRestoreLocalVector(dm, &l));
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscCall(CSMeshNaturalDestroy(&nat));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}
