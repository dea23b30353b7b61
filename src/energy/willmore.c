/* Discrete Willmore energy W = <*0 h, h> = 1/4 <Lf, *0^{-1} Lf> (soliman2021 Eq. 28) and its gradient 2-form.
   Gradient derivation (soliman2021 Eq. 29; the extracted text has sign typos, so we derive it here):
   W = sum_i |y_i|^2 / (4 A_i), y = Lf, A_i the barycentric area. With h_i = y_i / (2 A_i),
     dW = sum_i ( h_i . dy_i - |h_i|^2 dA_i ).
   Both y_i and A_i are sums of per-face terms, so with h frozen dW = d( sum_faces phi_f ) where
     phi_f = sum_{edges ij of f} (cot_k / 2) (h_i - h_j).(f_i - f_j) - (A_f / 3) sum_{i in f} |h_i|^2
   (k the corner opposite ij). Differentiating phi_f gives, per face, the L h term (cotans constant), the
   cotan-derivative term w (the d w_ij / d f of Eq. 29) and the area-derivative term (the d A_j / d f of Eq. 29). */
#include "cs_energy.h"

typedef struct {
  Vec y, area; /* global Lf (dmV3) and *0 (dmV1) */
} WillmoreCtx;

/* W from y and A: a sum over owned vertices. */
static PetscErrorCode WillmoreFromLf(CSEnergy e, Vec x, PetscReal *W)
{
  WillmoreCtx       *c = (WillmoreCtx *)e->ctx;
  const PetscScalar *y, *a;
  PetscInt           n;
  PetscReal          s = 0;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryLaplacianPositions(e->mesh, x, c->y, c->area));
  PetscCall(VecGetLocalSize(c->area, &n));
  PetscCall(VecGetArrayRead(c->y, &y));
  PetscCall(VecGetArrayRead(c->area, &a));
  for (PetscInt i = 0; i < n; i++) s += (y[3 * i] * y[3 * i] + y[3 * i + 1] * y[3 * i + 1] + y[3 * i + 2] * y[3 * i + 2]) / (4 * a[i]);
  PetscCall(VecRestoreArrayRead(c->y, &y));
  PetscCall(VecRestoreArrayRead(c->area, &a));
  PetscCall(MPIU_Allreduce(&s, W, 1, MPIU_REAL, MPIU_SUM, e->mesh->comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode WillmoreValue(CSEnergy e, Vec x, PetscReal *W)
{
  PetscFunctionBeginUser;
  PetscCall(WillmoreFromLf(e, x, W));
  PetscFunctionReturn(0);
}

static PetscErrorCode WillmoreGradient(CSEnergy e, Vec x, PetscReal *W, Vec g)
{
  WillmoreCtx     *c = (WillmoreCtx *)e->ctx;
  CSMesh           m = e->mesh;
  PetscReal        Wv;
  Vec              hl, xl;
  CSLocalSum       gs;
  const PetscReal *p, *h;
  PetscScalar     *ya;
  const PetscScalar *aa;
  PetscInt         n;
  PetscFunctionBeginUser;
  PetscCall(WillmoreFromLf(e, x, &Wv));
  if (W) *W = Wv;
  /* h = y / (2A) in place of y, then ghosted */
  PetscCall(VecGetLocalSize(c->area, &n));
  PetscCall(VecGetArray(c->y, &ya));
  PetscCall(VecGetArrayRead(c->area, &aa));
  for (PetscInt i = 0; i < n; i++)
    for (int d = 0; d < 3; d++) ya[3 * i + d] /= 2 * aa[i];
  PetscCall(VecRestoreArrayRead(c->area, &aa));
  PetscCall(VecRestoreArray(c->y, &ya));
  PetscCall(DMGetLocalVector(m->dmV3, &hl));
  PetscCall(DMGlobalToLocal(m->dmV3, c->y, INSERT_VALUES, hl));
  PetscCall(CSLocalSumBegin(m->dmV3, &gs));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(VecGetArrayRead(hl, (const PetscScalar **)&h));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscInt  *v     = F.v;
    const PetscReal *const *pc = F.c;
    const PetscReal *hc[3] = {h + 3 * v[0], h + 3 * v[1], h + 3 * v[2]};
    PetscReal        cot[3], an[3], A, N[3], dA[3][3], hh = 0, gf[3][3] = {{0}};
    CSTriangleCotans(pc, cot);
    CSTriangleAreaVector(pc, an);
    A = CSVecNorm(an);
    for (int d = 0; d < 3; d++) N[d] = an[d] / A;
    CSTriangleAreaGradient(pc, N, dA);
    for (int k = 0; k < 3; k++) hh += CSVecDot(hc[k], hc[k]);
    for (int k = 0; k < 3; k++) {
      int       i = (k + 1) % 3, j = (k + 2) % 3;
      PetscReal dh[3], df[3], s, dcot[3][3];
      CSVecSub(hc[i], hc[j], dh);
      CSVecSub(pc[i], pc[j], df);
      s = CSVecDot(dh, df);
      CSTriangleCotanGradient(pc, k, dcot);
      for (int d = 0; d < 3; d++) {
        gf[i][d] += 0.5 * cot[k] * dh[d]; /* L h */
        gf[j][d] -= 0.5 * cot[k] * dh[d];
        for (int q = 0; q < 3; q++) gf[q][d] += 0.5 * s * dcot[q][d]; /* cotan-weight derivative */
      }
    }
    for (int q = 0; q < 3; q++)
      for (int d = 0; d < 3; d++) gf[q][d] -= hh / 3 * dA[q][d]; /* vertex-area derivative */
    for (int q = 0; q < 3; q++)
      for (int d = 0; d < 3; d++) gs.a[3 * v[q] + d] += gf[q][d];
  }
  PetscCall(VecRestoreArrayRead(hl, (const PetscScalar **)&h));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(CSLocalSumEnd(&gs, g));
  PetscCall(DMRestoreLocalVector(m->dmV3, &hl));
  PetscFunctionReturn(0);
}

static PetscErrorCode WillmoreDestroy(CSEnergy e)
{
  WillmoreCtx *c = (WillmoreCtx *)e->ctx;
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&c->y));
  PetscCall(VecDestroy(&c->area));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyCreateWillmore(CSMesh mesh, CSEnergy *e)
{
  WillmoreCtx *c;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateShell(mesh, "willmore", e));
  PetscCall(PetscNew(&c));
  PetscCall(DMCreateGlobalVector(mesh->dmV3, &c->y));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &c->area));
  (*e)->ctx      = c;
  (*e)->value    = WillmoreValue;
  (*e)->gradient = WillmoreGradient;
  (*e)->destroy  = WillmoreDestroy;
  PetscFunctionReturn(0);
}
