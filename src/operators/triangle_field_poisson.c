/* Positions from a triangle field (soliman2021 Algorithm 2, last line): the Poisson problem L f = d*omega, i.e.
   d0^T *1 d0 f = d0^T *1 omega per component, with the lens d0 (H x V) and the halfedge *1 = 1/2 cot of omega's
   own triangles. It is the *1-least-squares fit of df to omega, so an integrable omega = df gives f back up to a
   translation, which is fixed by the centroid of xref. */
#include "triangle_field_poisson_impl.h"
#include "cs_cholmod.h"

/* L = d0^T *1 d0 (the cotan Laplacian of omega's triangles, PSD as a sum of P1 stiffness matrices) with vertex 0
   grounded (its row and column the identity), and B = *1 d0, from the lens d0; with MAT_REUSE_MATRIX L and B (of an
   earlier call) are refilled in place: the same nonzero pattern, so a factorisation of L keeps its symbolic part. */
static PetscErrorCode PoissonOperatorFromD0(Mat d0, Vec star1, MatReuse reuse, Mat *L, Mat *B)
{
  PetscInt rs, ground = 0;
  PetscFunctionBeginUser;
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(MatDuplicate(d0, MAT_COPY_VALUES, B));
  else PetscCall(MatCopy(d0, *B, SAME_NONZERO_PATTERN));
  PetscCall(MatDiagonalScale(*B, star1, NULL));
  PetscCall(MatTransposeMatMult(d0, *B, reuse, PETSC_DEFAULT, L));
  PetscCall(MatGetOwnershipRange(*L, &rs, NULL));
  PetscCall(MatZeroRowsColumns(*L, rs == 0 ? 1 : 0, &ground, 1.0, NULL, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldPoissonOperator(CSMesh m, DM dmH1, Vec star1, Mat *L, Mat *B)
{
  Mat d0;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLensD0(m, dmH1, &d0));
  PetscCall(PoissonOperatorFromD0(d0, star1, MAT_INITIAL_MATRIX, L, B));
  PetscCall(MatDestroy(&d0));
  PetscFunctionReturn(0);
}

/* component c of a dmH3 (dmV3) global vector to / from a dmH1 (dmV1) one: the same points own both, 3 dofs each;
   the source is only read (its state unchanged: the kept reconstruction recognises an unchanged omega by it) */
PetscErrorCode CSTriangleFieldComponent(Vec v3, PetscInt c, Vec v1, PetscBool gather)
{
  PetscInt           n;
  PetscScalar       *a;
  const PetscScalar *b;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v1, &n));
  if (gather) {
    PetscCall(VecGetArrayRead(v3, &b));
    PetscCall(VecGetArray(v1, &a));
    for (PetscInt i = 0; i < n; i++) a[i] = b[3 * i + c];
    PetscCall(VecRestoreArray(v1, &a));
    PetscCall(VecRestoreArrayRead(v3, &b));
  } else {
    PetscCall(VecGetArrayRead(v1, &b));
    PetscCall(VecGetArray(v3, &a));
    for (PetscInt i = 0; i < n; i++) a[3 * i + c] = b[i];
    PetscCall(VecRestoreArray(v3, &a));
    PetscCall(VecRestoreArrayRead(v1, &b));
  }
  PetscFunctionReturn(0);
}

/* The reconstruction kept alive across calls (the flow reconstructs its surface at every evaluation): d0, the
   operators, the KSP (its symbolic factorisation) and the work vectors are made once; a new omega only refills
   B = *1 d0 and L = d0^T B in place (the same nonzero pattern), so the KSP refactors numerically. */
struct _p_CSTriangleFieldReconstruction {
  CSMesh           m;
  DM               dmH1, dmH3;
  Mat              d0, L, B;
  KSP              ksp;
  Vec              star1, star0, wc, b, f;
  Vec              omega_op;    /* a copy of the omega of the current operator: an equal omega keeps the factorisation */
  PetscBool        have_op;     /* the operators and the KSP are those of omega_op */
};

PetscErrorCode CSTriangleFieldReconstructionCreate(CSMesh m, DM dmH1, DM dmH3, CSTriangleFieldReconstruction *R)
{
  PetscFunctionBeginUser;
  PetscCall(PetscNew(R));
  (*R)->m    = m;
  (*R)->dmH1 = dmH1;
  (*R)->dmH3 = dmH3;
  PetscCall(PetscObjectReference((PetscObject)dmH1));
  PetscCall(PetscObjectReference((PetscObject)dmH3));
  PetscFunctionReturn(0);
}

/* The first set-up: d0, the operators at star1, the KSP and the work vectors. */
static PetscErrorCode ReconstructionSetUpFirst(CSTriangleFieldReconstruction R)
{
  PC pc;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLensD0(R->m, R->dmH1, &R->d0));
  PetscCall(PoissonOperatorFromD0(R->d0, R->star1, MAT_INITIAL_MATRIX, &R->L, &R->B));
  PetscCall(KSPCreate(R->m->comm, &R->ksp));
  PetscCall(KSPSetOptionsPrefix(R->ksp, "trianglefield_poisson_"));
  PetscCall(KSPSetOperators(R->ksp, R->L, R->L));
  PetscCall(KSPSetType(R->ksp, KSPPREONLY));
  PetscCall(KSPGetPC(R->ksp, &pc));
  PetscCall(CSSetDefaultCholesky(pc));
  PetscCall(KSPSetFromOptions(R->ksp));
  PetscCall(VecDuplicate(R->star1, &R->wc));
  PetscCall(VecDuplicate(R->star0, &R->b));
  PetscCall(VecDuplicate(R->star0, &R->f));
  PetscFunctionReturn(0);
}

/* After a failed factorisation: everything but the stars is made again at the next set-up (CHOLMOD refuses to
   analyse again after a failed supernodal numeric factorisation: "cannot operate on supernodal L", issue 36). */
static PetscErrorCode ReconstructionReset(CSTriangleFieldReconstruction R)
{
  PetscFunctionBeginUser;
  PetscCall(KSPDestroy(&R->ksp));
  PetscCall(MatDestroy(&R->d0));
  PetscCall(MatDestroy(&R->L));
  PetscCall(MatDestroy(&R->B));
  PetscCall(VecDestroy(&R->wc));
  PetscCall(VecDestroy(&R->b));
  PetscCall(VecDestroy(&R->f));
  R->have_op = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The operators at omega's *1: B = *1 d0 and L = d0^T B (grounded) refilled in place; nothing is done if omega
   equals (value for value) the omega of the last set-up: the operators depend on omega's values only. */
PetscErrorCode CSTriangleFieldReconstructionSetUp(CSTriangleFieldReconstruction R, Vec omega)
{
  PetscBool same = PETSC_FALSE;
  PetscFunctionBeginUser;
  if (R->have_op) PetscCall(VecEqual(R->omega_op, omega, &same)); /* collective: every rank sets up, or none */
  if (same) PetscFunctionReturn(0);
  if (!R->star1) {
    PetscCall(DMCreateGlobalVector(R->dmH1, &R->star1));
    PetscCall(DMCreateGlobalVector(R->m->dmV1, &R->star0));
    PetscCall(VecDuplicate(omega, &R->omega_op));
  }
  PetscCall(CSTriangleFieldStars(R->m, R->dmH3, omega, R->dmH1, R->star1, R->star0));
  if (!R->ksp) PetscCall(ReconstructionSetUpFirst(R));
  else PetscCall(PoissonOperatorFromD0(R->d0, R->star1, MAT_REUSE_MATRIX, &R->L, &R->B));
  PetscCall(VecCopy(omega, R->omega_op));
  R->have_op = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* f from omega (dmH3) into the positions x (dmV3) with omega's own *1 (set up here if omega is new or changed);
   the translation puts f's vertex centroid at xref's. */
PetscErrorCode CSTriangleFieldReconstructionSolve(CSTriangleFieldReconstruction R, Vec omega, Vec xref, Vec x)
{
  PetscInt rs;
  PetscFunctionBeginUser;
  PetscCall(CSTriangleFieldReconstructionSetUp(R, omega));
  PetscCall(MatGetOwnershipRange(R->L, &rs, NULL));
  for (PetscInt c = 0; c < 3; c++) {
    PetscScalar sf, sr;
    PetscInt    nv;
    PetscCall(CSTriangleFieldComponent(omega, c, R->wc, PETSC_TRUE));
    PetscCall(MatMultTranspose(R->B, R->wc, R->b));
    if (rs == 0) PetscCall(VecSetValue(R->b, 0, 0.0, INSERT_VALUES)); /* the grounded vertex */
    PetscCall(VecAssemblyBegin(R->b));
    PetscCall(VecAssemblyEnd(R->b));
    PetscCall(KSPSolve(R->ksp, R->b, R->f));
    {
      KSPConvergedReason kr; /* a failed factorisation under preonly gives Inf positions without an error */
      PetscCall(KSPGetConvergedReason(R->ksp, &kr));
      if (kr < 0) PetscCall(ReconstructionReset(R)); /* a later call starts afresh (CHOLMOD cannot resymbol a failed L) */
      PetscCheck(kr >= 0, R->m->comm, PETSC_ERR_NOT_CONVERGED, "triangle field: the Poisson reconstruction (-trianglefield_poisson_ksp_type ...) failed: %s", KSPConvergedReasons[kr]);
    }
    PetscCall(CSTriangleFieldComponent(xref, c, R->b, PETSC_TRUE));
    PetscCall(VecSum(R->b, &sr));
    PetscCall(VecSum(R->f, &sf));
    PetscCall(VecGetSize(R->f, &nv));
    PetscCall(VecShift(R->f, (sr - sf) / nv));
    PetscCall(CSTriangleFieldComponent(x, c, R->f, PETSC_FALSE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldReconstructionDestroy(CSTriangleFieldReconstruction *R)
{
  PetscFunctionBeginUser;
  if (!*R) PetscFunctionReturn(0);
  PetscCall(KSPDestroy(&(*R)->ksp));
  PetscCall(MatDestroy(&(*R)->d0));
  PetscCall(MatDestroy(&(*R)->L));
  PetscCall(MatDestroy(&(*R)->B));
  PetscCall(VecDestroy(&(*R)->star1));
  PetscCall(VecDestroy(&(*R)->star0));
  PetscCall(VecDestroy(&(*R)->omega_op));
  PetscCall(VecDestroy(&(*R)->wc));
  PetscCall(VecDestroy(&(*R)->b));
  PetscCall(VecDestroy(&(*R)->f));
  PetscCall(DMDestroy(&(*R)->dmH1));
  PetscCall(DMDestroy(&(*R)->dmH3));
  PetscCall(PetscFree(*R));
  PetscFunctionReturn(0);
}

/* The one-shot reconstruction (output, tests): a reconstruction object made, solved once and destroyed. */
PetscErrorCode CSTriangleFieldReconstruct(CSMesh m, DM dmH1, DM dmH3, Vec omega, Vec xref, Vec x)
{
  CSTriangleFieldReconstruction R;
  PetscFunctionBeginUser;
  PetscCall(CSTriangleFieldReconstructionCreate(m, dmH1, dmH3, &R));
  PetscCall(CSTriangleFieldReconstructionSolve(R, omega, xref, x));
  PetscCall(CSTriangleFieldReconstructionDestroy(&R));
  PetscFunctionReturn(0);
}
