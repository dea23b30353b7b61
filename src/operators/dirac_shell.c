/* Matrix-free X = A^H M_F A (crane2013 App. G): the "callback routine that applies the Hamilton product
   directly" of crane2011 Sec. 5.1. Per face k: s = sum_j a_j x_j (the face value (A x)_k), then
   y_i += A_k conj(a_i) s. Same operator as CSDiracAssemble to round-off (tests/unit/test_spin_dirac.c). */
#include "cs_operators_dirac.h"

typedef struct {
  CSMesh     mesh;
  DM         dm;
  PetscReal *coef; /* 12 per face: a_0, a_1, a_2 */
  PetscReal *area; /* per face */
} DiracShell;

static PetscErrorCode DiracShellMult(Mat X, Vec x, Vec y)
{
  DiracShell        *ctx;
  Vec                xl;
  CSLocalSum         ys;
  const PetscScalar *xa;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(X, &ctx));
  PetscCall(DMGetLocalVector(ctx->dm, &xl));
  PetscCall(DMGlobalToLocal(ctx->dm, x, INSERT_VALUES, xl));
  PetscCall(CSLocalSumBegin(ctx->dm, &ys));
  PetscCall(VecGetArrayRead(xl, &xa));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(ctx->mesh, NULL, &F);) {
    const PetscInt  *v = F.v;
    const PetscReal *a = ctx->coef + 12 * F.f;
    PetscReal        s[4] = {0, 0, 0, 0};
    for (int j = 0; j < 3; j++) {
      PetscReal q[4], t[4];
      for (int c = 0; c < 4; c++) q[c] = PetscRealPart(xa[4 * v[j] + c]);
      CSQuatMul(a + 4 * j, q, t);
      CSQuatAXPY(1, t, s);
    }
    for (int i = 0; i < 3; i++) {
      PetscReal t[4];
      CSQuatConjMul(a + 4 * i, s, t);
      for (int c = 0; c < 4; c++) ys.a[4 * v[i] + c] += ctx->area[F.f] * t[c];
    }
  }
  PetscCall(VecRestoreArrayRead(xl, &xa));
  PetscCall(CSLocalSumEnd(&ys, y));
  PetscCall(DMRestoreLocalVector(ctx->dm, &xl));
  PetscFunctionReturn(0);
}

/* The diagonal of the block X_ii is Re(X_ii) = sum_k A_k |a_i|^2 on all four components. */
static PetscErrorCode DiracShellGetDiagonal(Mat X, Vec d)
{
  DiracShell  *ctx;
  CSLocalSum   ds;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(X, &ctx));
  PetscCall(CSLocalSumBegin(ctx->dm, &ds));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(ctx->mesh, NULL, &F);)
    for (int i = 0; i < 3; i++) {
      PetscReal n2 = CSQuatNorm2(ctx->coef + 12 * F.f + 4 * i);
      for (int c = 0; c < 4; c++) ds.a[4 * F.v[i] + c] += ctx->area[F.f] * n2;
    }
  PetscCall(CSLocalSumEnd(&ds, d));
  PetscFunctionReturn(0);
}

static PetscErrorCode DiracShellDestroy(Mat X)
{
  DiracShell *ctx;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(X, &ctx));
  PetscCall(PetscFree2(ctx->coef, ctx->area));
  PetscCall(DMDestroy(&ctx->dm));
  PetscCall(PetscFree(ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDiracCreateShell(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, Mat *X)
{
  DiracShell        *ctx;
  Vec                xl, rl, g;
  const PetscReal   *p;
  const PetscScalar *r;
  PetscInt           n, N;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&ctx));
  ctx->mesh = mesh;
  ctx->dm   = dm;
  PetscCall(PetscObjectReference((PetscObject)dm));
  PetscCall(PetscMalloc2(12 * mesh->nf, &ctx->coef, mesh->nf, &ctx->area));
  PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &p));
  PetscCall(CSDiracGetRho(mesh, loc, rho, &rl, &r));
  for (PetscInt f = 0; f < mesh->nf; f++) {
    PetscReal a[3][4];
    CSDiracFaceCoefficients(mesh, p, loc, r, f, a, &ctx->area[f]);
    for (int j = 0; j < 3; j++)
      for (int c = 0; c < 4; c++) ctx->coef[12 * f + 4 * j + c] = a[j][c];
  }
  PetscCall(CSDiracRestoreRho(mesh, loc, rho, &rl, &r));
  PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &p));
  PetscCall(DMGetGlobalVector(dm, &g));
  PetscCall(VecGetLocalSize(g, &n));
  PetscCall(VecGetSize(g, &N));
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscCall(MatCreateShell(mesh->comm, n, n, N, N, ctx, X));
  PetscCall(MatSetBlockSize(*X, 4));
  PetscCall(MatShellSetOperation(*X, MATOP_MULT, (void (*)(void))DiracShellMult));
  PetscCall(MatShellSetOperation(*X, MATOP_MULT_TRANSPOSE, (void (*)(void))DiracShellMult));
  PetscCall(MatShellSetOperation(*X, MATOP_GET_DIAGONAL, (void (*)(void))DiracShellGetDiagonal));
  PetscCall(MatShellSetOperation(*X, MATOP_DESTROY, (void (*)(void))DiracShellDestroy));
  PetscCall(MatSetOption(*X, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(*X, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  PetscCall(MatShellSetVecType(*X, VECSTANDARD));
  PetscFunctionReturn(0);
}
