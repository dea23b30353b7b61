/* Triangle-field extensions of position functions (soliman2021 App. B): the Poisson reconstruction as a fixed
   linear map R omega = L0^{-1} d0^T *1(x0) omega (vertex 0 grounded), its transpose for gradients (Eq. 22).
   Why a fixed L0: App. B writes f_dot = Poisson reconstruction of omega_dot, which holds when L does not depend on
   omega. With omega's own *1 (CSTriangleFieldReconstruct) the map is nonlinear; at an integrable omega = df its
   derivative is the linear reconstruction with L(omega) (the L_dot f and d0^T *1_dot df terms cancel), but away
   from integrable fields it is not, and the paper's gradient would not be the derivative of the value. Freezing
   the metric at the input keeps F(R omega) an extension (R df = f - f_0 for every f) with an exact gradient. */
#include "triangle_field_poisson_impl.h"
#include "cs_cholmod.h"

struct _p_CSTriangleFieldPoisson {
  PetscInt refct;
  Mat      L, B;  /* grounded d0^T *1 d0 and *1 d0 at x0 */
  KSP      ksp;
  Vec      w1, v1, f1; /* one component: halfedges, vertices (two) */
};

PetscErrorCode CSTriangleFieldPoissonCreate(CSMesh m, DM dmH1, DM dmH3, Vec x0, CSTriangleFieldPoisson *P)
{
  Vec omega0, star1, star0;
  PC  pc;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(P));
  (*P)->refct = 1;
  PetscCall(DMCreateGlobalVector(dmH3, &omega0));
  PetscCall(CSTriangleFieldFromPositions(m, x0, dmH3, omega0));
  PetscCall(DMCreateGlobalVector(dmH1, &star1));
  PetscCall(DMCreateGlobalVector(m->dmV1, &star0));
  PetscCall(CSTriangleFieldStars(m, dmH3, omega0, dmH1, star1, star0));
  PetscCall(CSTriangleFieldPoissonOperator(m, dmH1, star1, &(*P)->L, &(*P)->B));
  PetscCall(KSPCreate(m->comm, &(*P)->ksp));
  PetscCall(KSPSetOptionsPrefix((*P)->ksp, "trianglefield_extension_"));
  PetscCall(KSPSetOperators((*P)->ksp, (*P)->L, (*P)->L));
  PetscCall(KSPSetType((*P)->ksp, KSPPREONLY));
  PetscCall(KSPGetPC((*P)->ksp, &pc));
  PetscCall(CSSetDefaultCholesky(pc));
  PetscCall(KSPSetFromOptions((*P)->ksp));
  PetscCall(KSPSetUp((*P)->ksp));
  (*P)->w1 = star1;
  (*P)->v1 = star0;
  PetscCall(VecDuplicate(star0, &(*P)->f1));
  PetscCall(VecDestroy(&omega0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldPoissonReference(CSTriangleFieldPoisson P)
{
  PetscFunctionBeginUser;
  P->refct++;
  PetscFunctionReturn(0);
}

/* f1 = L0^{-1} v1 with the grounded vertex's entry of v1 set to 0 (then f1_0 = 0): the symmetric map G of both R
   = G B^T and R^T = B G. */
static PetscErrorCode GroundedSolve(CSTriangleFieldPoisson P)
{
  PetscInt rs;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(P->v1, &rs, NULL));
  if (rs == 0) PetscCall(VecSetValue(P->v1, 0, 0.0, INSERT_VALUES));
  PetscCall(VecAssemblyBegin(P->v1));
  PetscCall(VecAssemblyEnd(P->v1));
  PetscCall(KSPSolve(P->ksp, P->v1, P->f1));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldPoissonApply(CSTriangleFieldPoisson P, Vec omega, Vec f)
{
  PetscFunctionBeginUser;
  for (PetscInt c = 0; c < 3; c++) {
    PetscCall(CSTriangleFieldComponent(omega, c, P->w1, PETSC_TRUE));
    PetscCall(MatMultTranspose(P->B, P->w1, P->v1));
    PetscCall(GroundedSolve(P));
    PetscCall(CSTriangleFieldComponent(f, c, P->f1, PETSC_FALSE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldPoissonApplyTranspose(CSTriangleFieldPoisson P, Vec v, Vec w)
{
  PetscFunctionBeginUser;
  for (PetscInt c = 0; c < 3; c++) {
    PetscCall(CSTriangleFieldComponent(v, c, P->v1, PETSC_TRUE));
    PetscCall(GroundedSolve(P));
    PetscCall(MatMult(P->B, P->f1, P->w1));
    PetscCall(CSTriangleFieldComponent(w, c, P->w1, PETSC_FALSE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldPoissonDestroy(CSTriangleFieldPoisson *P)
{
  PetscFunctionBeginUser;
  if (!*P) PetscFunctionReturn(0);
  if (--(*P)->refct > 0) {
    *P = NULL;
    PetscFunctionReturn(0);
  }
  PetscCall(KSPDestroy(&(*P)->ksp));
  PetscCall(MatDestroy(&(*P)->L));
  PetscCall(MatDestroy(&(*P)->B));
  PetscCall(VecDestroy(&(*P)->w1));
  PetscCall(VecDestroy(&(*P)->v1));
  PetscCall(VecDestroy(&(*P)->f1));
  PetscCall(PetscFree(*P));
  PetscFunctionReturn(0);
}
