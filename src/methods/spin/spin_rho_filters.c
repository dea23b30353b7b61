/* rho from a normal displacement (crane2011 Sec. 7.1, Fig. 20) and a heat-diffusion filter of rho (Fig. 13). */
#include "spin_impl.h"

/* Sec. 7.1: "for a flat surface undergoing a normal deformation f~(t) = f + t g N, the change in H~|df~| at t = 0
   equals Delta g". In this code's units of rho (rho = -H makes a minimal surface with H = (L f).N / (2 M), the
   mean of the principal curvatures: spin_rho.c) the change of H is (L g) / (2 M) for the positive cotan
   Laplacian L and the vertex areas M: rho += (L g)_i / (2 M_i). The factor 1/2 is the paper's Delta g with
   H = k1 + k2; tests/cases/spin_displacement.sh checks it (the error to f + t g N is second order in t). */
PetscErrorCode CSSpinRhoFromDisplacement(CSSpin s, Vec x, Vec g, Vec rho)
{
  Mat L;
  Vec Lg, M;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLaplacian(s->mesh, x, MAT_INITIAL_MATRIX, &L));
  PetscCall(VecDuplicate(g, &Lg));
  PetscCall(VecDuplicate(g, &M));
  PetscCall(CSOperatorMass(s->mesh, x, M));
  PetscCall(MatMult(L, g, Lg));
  PetscCall(VecPointwiseDivide(Lg, Lg, M));
  PetscCall(VecAXPY(rho, 0.5, Lg));
  PetscCall(VecDestroy(&Lg));
  PetscCall(VecDestroy(&M));
  PetscCall(MatDestroy(&L));
  PetscFunctionReturn(0);
}

/* Fig. 13 (low-pass filter of rho): one backward Euler step of the heat equation, (M + t L) rho~ = M rho, t in units
   of length^2 (a Gaussian of variance ~2t); KSP prefix spin_smooth_ (Cholesky by default). */
PetscErrorCode CSSpinRhoSmooth(CSSpin s, Vec x, PetscReal t, Vec rho)
{
  Mat L;
  Vec M, b;
  KSP ksp;
  PC       pc;
  PetscInt its = 0;
  char     prefix[256];
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLaplacian(s->mesh, x, MAT_INITIAL_MATRIX, &L));
  PetscCall(VecDuplicate(rho, &M));
  PetscCall(VecDuplicate(rho, &b));
  PetscCall(CSOperatorMass(s->mesh, x, M));
  PetscCall(MatScale(L, t));
  PetscCall(MatDiagonalSet(L, M, ADD_VALUES));
  PetscCall(VecPointwiseMult(b, M, rho));
  PetscCall(KSPCreate(s->mesh->comm, &ksp));
  PetscCall(CSSpinSubPrefix(s, "smooth_", prefix, sizeof(prefix)));
  PetscCall(KSPSetOptionsPrefix(ksp, prefix));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(CSSetDefaultCholesky(pc));
  PetscCall(KSPSetOperators(ksp, L, L));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(CSSpinKSPSolve(s, ksp, b, rho, "-rho_smooth heat step", &its));
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&M));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&L));
  PetscFunctionReturn(0);
}
