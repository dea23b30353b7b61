/* The pieces of a trial step every kind's trial is made of (impls/<kind>/): the step's operators, the saddle solve
   (soliman2021 Algorithm 1 line 11), a Gauss-Newton correction toward the constraints, the rejection message. */
#include "willmore_impl.h"

PetscErrorCode CSWFSetOperators(CSWillmoreFlow F, PetscReal t, PetscReal tmu)
{
  PetscFunctionBeginUser;
  PetscCall(CSSaddleSetOperators(&F->saddle, F->metric.H, t, F->iq, tmu, F->conformal ? F->Xc : NULL, F->rows, F->gw));
  PetscFunctionReturn(0);
}

/* CSSaddleSolve; a linear solve that did not converge is reported in *ok (and printed): the step control
   then treats it as a rejected step (t halved, like the semi-implicit BS flow), and a run that keeps failing
   stops cleanly with its last accepted state. */
PetscErrorCode CSWFTrySolve(CSWillmoreFlow F, Vec rE, Vec rV, const PetscReal rX[], Vec zE, Vec zV, PetscReal zX[], PetscInt *its, PetscBool *ok)
{
  KSPConvergedReason reason;
  PetscFunctionBeginUser;
  *its = 0;
  PetscCall(CSSaddleSolve(&F->saddle, rE, rV, rX, zE, zV, zX, its, &reason));
  *ok = (PetscBool)(reason > 0);
  if (!*ok) PetscCall(PetscPrintf(F->hdr.comm, "     linear solve failed: the saddle solve (prefix -%s) did not converge: %s after %" PetscInt_FMT " iterations; try -%smatrix_type aij -%spc_type cholesky -%spc_factor_mat_solver_type mumps, or a smaller -%st\n", F->saddle.prefix, KSPConvergedReasons[reason], *its, F->hdr.prefix, F->saddle.prefix, F->saddle.prefix, F->hdr.prefix));
  PetscFunctionReturn(0);
}

/* One Gauss-Newton correction toward the constraints with the operator set last: the saddle system with
   right-hand side [-c; 0; -xi] for the c, xi held in F->ct, F->cxt (both overwritten); the position part in zV. */
PetscErrorCode CSWFSolveCorrection(CSWillmoreFlow F, Vec zE, Vec zV, PetscInt *its, PetscBool *ok)
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecScale(F->ct, -1.0));
  for (PetscInt j = 0; j < F->k; j++) F->cxt[j] = -F->cxt[j];
  PetscCall(VecSet(F->tmp, 0));
  PetscCall(CSWFTrySolve(F, F->ct, F->tmp, F->cxt, zE, zV, F->dnu2, its, ok));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFRejected(CSWillmoreFlow F, const char what[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: %s with t = %g; halving t\n", what, (double)F->t));
  PetscFunctionReturn(0);
}

