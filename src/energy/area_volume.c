/* Total area (gradient Lf, soliman2021 Sec. 2) and enclosed volume (App. B.2, gradient Eq. 23) as energies.
   The volume gradient used is the exact derivative of 1/6 sum f_i.(f_j x f_k): per face 1/6 f_j x f_k at i.
   On a closed mesh it equals Eq. 23's 1/3 sum A_ijk N_ijk (the difference sums to zero over a vertex star). */
#include "cs_energy.h"

typedef enum { FACE_AREA, FACE_VOLUME } FaceSum;

/* Sum over faces of area or signed volume, and optionally its gradient. */
static PetscErrorCode FaceSumGradient(CSEnergy e, Vec x, PetscReal *E, Vec g)
{
  CSMesh           m    = e->mesh;
  FaceSum          kind = (FaceSum)(size_t)e->ctx;
  Vec              xl;
  CSLocalSum       gs;
  const PetscReal *p;
  PetscScalar     *ga = NULL;
  PetscReal        s  = 0;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  if (g) {
    PetscCall(CSLocalSumBegin(m->dmV3, &gs));
    ga = gs.a;
  }
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscInt  *v = F.v;
    const PetscReal *const *c = F.c;
    PetscReal        gf[3][3];
    if (kind == FACE_AREA) {
      PetscReal an[3], A, N[3];
      CSTriangleAreaVector(c, an);
      A = CSVecNorm(an);
      s += A;
      for (int d = 0; d < 3; d++) N[d] = an[d] / A;
      CSTriangleAreaGradient(c, N, gf);
    } else {
      CSVecCross(c[1], c[2], gf[0]);
      CSVecCross(c[2], c[0], gf[1]);
      CSVecCross(c[0], c[1], gf[2]);
      for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) gf[k][d] /= 6;
      s += CSVecDot(c[0], gf[0]);
    }
    if (ga)
      for (int k = 0; k < 3; k++)
        for (int d = 0; d < 3; d++) ga[3 * v[k] + d] += gf[k][d];
  }
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  if (g) PetscCall(CSLocalSumEnd(&gs, g));
  if (E) PetscCall(MPIU_Allreduce(&s, E, 1, MPIU_REAL, MPIU_SUM, m->comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode FaceSumValue(CSEnergy e, Vec x, PetscReal *E)
{
  PetscFunctionBeginUser;
  PetscCall(FaceSumGradient(e, x, E, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateFaceSum(CSMesh mesh, const char name[], FaceSum kind, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateShell(mesh, name, e));
  (*e)->ctx      = (void *)(size_t)kind;
  (*e)->value    = FaceSumValue;
  (*e)->gradient = FaceSumGradient;
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyCreateArea(CSMesh mesh, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CreateFaceSum(mesh, "area", FACE_AREA, e));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyCreateVolume(CSMesh mesh, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CreateFaceSum(mesh, "volume", FACE_VOLUME, e));
  PetscFunctionReturn(0);
}
