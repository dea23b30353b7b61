/* The exact discrete conformal constraint C lambda(f) = c0 (soliman2021 Sec. 3, Prop. 3.1, App. D). */
#include "cs_constraints.h"

PetscErrorCode CSConformalConstraintCreate(CSMesh mesh, Vec xt, PetscBool interior_only, const PetscBool fixed[], CSConformalConstraint *cc)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(cc, sizeof(*cc)));
  cc->mesh          = mesh;
  cc->interior_only = interior_only;
  cc->fixed         = fixed;
  PetscCall(CSOperatorCrossRatio(mesh, interior_only, &cc->C));
  PetscCall(DMCreateGlobalVector(mesh->dmE1, &cc->c0));
  PetscCall(VecDuplicate(cc->c0, &cc->lambda));
  PetscCall(CSOperatorLogLengths(mesh, xt, cc->lambda));
  PetscCall(MatMult(cc->C, cc->lambda, cc->c0));
  PetscFunctionReturn(0);
}

/* The class of an intrinsic metric: c0 = C lambda, lambda = log l (soliman2021 Eq. 3 on the given lengths). */
PetscErrorCode CSConformalConstraintSetTargetLengths(CSConformalConstraint *cc, Vec l)
{
  PetscFunctionBeginUser;
  PetscCall(VecCopy(l, cc->lambda));
  PetscCall(VecLog(cc->lambda));
  PetscCall(MatMult(cc->C, cc->lambda, cc->c0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalConstraintEvaluate(CSConformalConstraint *cc, Vec x, Vec c, PetscBool wantX)
{
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLogLengths(cc->mesh, x, cc->lambda));
  PetscCall(MatMult(cc->C, cc->lambda, c));
  PetscCall(VecAXPY(c, -1.0, cc->c0));
  if (wantX) {
    PetscBool first = cc->D ? PETSC_FALSE : PETSC_TRUE;
    PetscCall(CSOperatorLogLengthDerivative(cc->mesh, x, cc->fixed, first ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, &cc->D));
    /* X = C Dlambda (Algorithm 1 line 9): rows = edges, 3V columns */
    PetscCall(MatMatMult(cc->C, cc->D, first ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, PETSC_DEFAULT, &cc->X));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalConstraintDestroy(CSConformalConstraint *cc)
{
  PetscFunctionBeginUser;
  PetscCall(MatDestroy(&cc->C));
  PetscCall(MatDestroy(&cc->D));
  PetscCall(MatDestroy(&cc->X));
  PetscCall(VecDestroy(&cc->c0));
  PetscCall(VecDestroy(&cc->lambda));
  PetscFunctionReturn(0);
}
