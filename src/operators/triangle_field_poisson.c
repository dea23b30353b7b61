/* Positions from a triangle field (soliman2021 Algorithm 2, last line): the Poisson problem L f = d*omega, i.e.
   d0^T *1 d0 f = d0^T *1 omega per component, with the lens d0 (H x V) and the halfedge *1 = 1/2 cot of omega's
   own triangles. It is the *1-least-squares fit of df to omega, so an integrable omega = df gives f back up to a
   translation, which is fixed by the centroid of xref. */
#include "triangle_field_poisson_impl.h"
#include "cs_cholmod.h"

/* L = d0^T *1 d0 (the cotan Laplacian of omega's triangles, PSD as a sum of P1 stiffness matrices) with vertex 0
   grounded (its row and column the identity), and B = *1 d0. */
PetscErrorCode CSTriangleFieldPoissonOperator(CSMesh m, DM dmH1, Vec star1, Mat *L, Mat *B)
{
  Mat      d0;
  PetscInt rs, ground = 0;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLensD0(m, dmH1, &d0));
  PetscCall(MatDuplicate(d0, MAT_COPY_VALUES, B));
  PetscCall(MatDiagonalScale(*B, star1, NULL));
  PetscCall(MatTransposeMatMult(d0, *B, MAT_INITIAL_MATRIX, PETSC_DEFAULT, L));
  PetscCall(MatDestroy(&d0));
  PetscCall(MatGetOwnershipRange(*L, &rs, NULL));
  PetscCall(MatZeroRowsColumns(*L, rs == 0 ? 1 : 0, &ground, 1.0, NULL, NULL));
  PetscFunctionReturn(0);
}

/* component c of a dmH3 (dmV3) global vector to / from a dmH1 (dmV1) one: the same points own both, 3 dofs each */
PetscErrorCode CSTriangleFieldComponent(Vec v3, PetscInt c, Vec v1, PetscBool gather)
{
  PetscInt     n;
  PetscScalar *a3, *a1;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v1, &n));
  PetscCall(VecGetArray(v3, &a3));
  PetscCall(VecGetArray(v1, &a1));
  for (PetscInt i = 0; i < n; i++) {
    if (gather) a1[i] = a3[3 * i + c];
    else a3[3 * i + c] = a1[i];
  }
  PetscCall(VecRestoreArray(v1, &a1));
  PetscCall(VecRestoreArray(v3, &a3));
  PetscFunctionReturn(0);
}

/* f from omega (dmH3) into the positions x (dmV3); the translation puts f's vertex centroid at xref's. */
PetscErrorCode CSTriangleFieldReconstruct(CSMesh m, DM dmH1, DM dmH3, Vec omega, Vec xref, Vec x)
{
  Mat      L, B;
  Vec      star1, star0, wc, b, f;
  KSP      ksp;
  PC       pc;
  PetscInt rs;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(dmH1, &star1));
  PetscCall(DMCreateGlobalVector(m->dmV1, &star0));
  PetscCall(CSTriangleFieldStars(m, dmH3, omega, dmH1, star1, star0));
  PetscCall(CSTriangleFieldPoissonOperator(m, dmH1, star1, &L, &B));
  PetscCall(KSPCreate(m->comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "trianglefield_poisson_"));
  PetscCall(KSPSetOperators(ksp, L, L));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(CSSetDefaultCholesky(pc));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(VecDuplicate(star1, &wc));
  PetscCall(VecDuplicate(star0, &b));
  PetscCall(VecDuplicate(star0, &f));
  PetscCall(MatGetOwnershipRange(L, &rs, NULL));
  for (PetscInt c = 0; c < 3; c++) {
    PetscScalar sf, sr;
    PetscInt    nv;
    PetscCall(CSTriangleFieldComponent(omega, c, wc, PETSC_TRUE));
    PetscCall(MatMultTranspose(B, wc, b));
    if (rs == 0) PetscCall(VecSetValue(b, 0, 0.0, INSERT_VALUES)); /* the grounded vertex */
    PetscCall(VecAssemblyBegin(b));
    PetscCall(VecAssemblyEnd(b));
    PetscCall(KSPSolve(ksp, b, f));
    PetscCall(CSTriangleFieldComponent(xref, c, b, PETSC_TRUE));
    PetscCall(VecSum(b, &sr));
    PetscCall(VecSum(f, &sf));
    PetscCall(VecGetSize(f, &nv));
    PetscCall(VecShift(f, (sr - sf) / nv));
    PetscCall(CSTriangleFieldComponent(x, c, f, PETSC_FALSE));
  }
  PetscCall(KSPDestroy(&ksp));
  PetscCall(MatDestroy(&L));
  PetscCall(MatDestroy(&B));
  PetscCall(VecDestroy(&star1));
  PetscCall(VecDestroy(&star0));
  PetscCall(VecDestroy(&wc));
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&f));
  PetscFunctionReturn(0);
}
