/* The trial step: the saddle solve of soliman2021 Algorithm 1 line 11 (CGD/GD) or of PGD, with the
   second-order corrections (CGD/GD) or the iterative refinement and projection (PGD). */
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
  if (!*ok) PetscCall(PetscPrintf(F->comm, "     linear solve failed: the saddle solve (prefix -%s) did not converge: %s after %" PetscInt_FMT " iterations; try -%smatrix_type aij -%spc_type cholesky -%spc_factor_mat_solver_type mumps, or a smaller -%st\n", F->saddle.prefix, KSPConvergedReasons[reason], *its, F->prefix, F->saddle.prefix, F->saddle.prefix, F->prefix));
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

/* Second-order correction of a CGD/GD trial point (Nocedal & Wright, Numerical Optimization, Sec. 18.3):
   up to -flow_soc_max_it solves of the step's own system with right-hand side [-c(xt); 0; -xi(xt)] (the
   factorisation of the step is reused), each moving xt by the H-smallest correction of the linearised
   constraints at x. It removes the O(|df|^2) violation that the linearisation leaves, so the violation of an
   accepted step does not accumulate; at a fixed point c = 0 and the correction is zero. */
static PetscErrorCode SecondOrderCorrection(CSWillmoreFlow F, Vec xt, PetscInt *kspits, PetscBool *ok)
{
  Vec       dmu2 = NULL, df2;
  PetscReal conf, glob, v0 = 0;
  PetscFunctionBeginUser;
  *ok = PETSC_TRUE;
  F->trial.q = 0; /* no correction needed: the operator's restoring is not measured, none assumed left */
  if (F->soc_max_it <= 0 || (!F->conformal && !F->k)) PetscFunctionReturn(0);
  if (F->dmu) PetscCall(VecDuplicate(F->dmu, &dmu2));
  PetscCall(VecDuplicate(F->df, &df2));
  for (PetscInt i = 0; i < F->soc_max_it; i++) {
    PetscInt its;
    PetscCall(CSWFEvalConstraints(F, xt, F->ct, F->cxt, PETSC_FALSE));
    PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
    if (i == 0) v0 = PetscMax(conf, glob);
    if (i == 1 && v0 > 0) F->trial.q = PetscMin(1.0, PetscMax(conf, glob) / v0); /* the step model's restoring ratio */
    if (!(PetscMax(conf, glob) >= 0.1 * F->ctol)) break; /* feasible enough, or not a number (the filter rejects it) */
    PetscCall(CSWFSolveCorrection(F, dmu2, df2, &its, ok));
    *kspits += its;
    if (!*ok) break;
    PetscCall(VecAXPY(xt, 1.0, df2));
  }
  PetscCall(VecDestroy(&dmu2));
  PetscCall(VecDestroy(&df2));
  PetscFunctionReturn(0);
}

static PetscErrorCode Rejected(CSWillmoreFlow F, const char what[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(F->comm, "     step rejected: %s with t = %g; halving t\n", what, (double)F->t));
  PetscFunctionReturn(0);
}

/* CGD/GD (Algorithm 1 line 11): right-hand side [-c; -g - X^T mu - B^T nu; -xi], then the second-order
   corrections of the trial point xt = x + df. */
PetscErrorCode CSWFTrialCGD(CSWillmoreFlow F, PetscBool *accept)
{
  PetscInt its;
  PetscFunctionBeginUser;
  PetscCall(CSWFSetOperators(F, F->t, F->tmu));
  if (F->conformal) {
    PetscCall(VecCopy(F->c, F->ct));
    PetscCall(VecScale(F->ct, -1.0));
  }
  PetscCall(VecCopy(F->r, F->tmp));
  PetscCall(VecScale(F->tmp, -1.0));
  for (PetscInt j = 0; j < F->k; j++) F->cxt[j] = -F->cx[j];
  PetscCall(CSWFTrySolve(F, F->ct, F->tmp, F->cxt, F->dmu, F->df, F->dnu, &its, accept));
  F->kspits += its;
  if (!*accept) PetscCall(Rejected(F, "linear solve failed"));
  if (!*accept) PetscFunctionReturn(0);
  PetscCall(VecWAXPY(F->xt, 1.0, F->df, F->x));
  its = 0;
  PetscCall(SecondOrderCorrection(F, F->xt, &its, accept));
  F->kspits += its;
  if (!*accept) PetscCall(Rejected(F, "the linear solve of the second-order correction failed"));
  PetscFunctionReturn(0);
}

/* The PGD matrix [[H/t, X^T], [X, 0]] is singular (dependent rows of X); we solve with -I_Q/pgd_t_mu in the
   (2,2) block and remove the regularisation error by iterative refinement against the unregularised system:
   only its second row differs, residual -X df (and -B^T df). */
static PetscErrorCode RefinePGD(CSWillmoreFlow F, PetscBool *accept)
{
  Vec dmu2, df2;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->dmu, &dmu2));
  PetscCall(VecDuplicate(F->df, &df2));
  for (PetscInt ref = 0; ref < 3 && *accept; ref++) {
    PetscInt its;
    PetscCall(MatMult(F->Xc, F->df, F->ct));
    PetscCall(VecScale(F->ct, -1.0));
    for (PetscInt j = 0; j < F->k; j++) {
      PetscScalar v;
      PetscCall(VecDot(F->rows[j], F->df, &v));
      F->cxt[j] = -PetscRealPart(v);
    }
    PetscCall(VecSet(F->tmp, 0));
    PetscCall(CSWFTrySolve(F, F->ct, F->tmp, F->cxt, dmu2, df2, F->dnu2, &its, accept));
    F->kspits += its;
    if (!*accept) PetscCall(Rejected(F, "linear solve failed"));
    else {
      PetscCall(VecAXPY(F->dmu, 1.0, dmu2));
      PetscCall(VecAXPY(F->df, 1.0, df2));
      for (PetscInt j = 0; j < F->k; j++) F->dnu[j] += F->dnu2[j];
    }
  }
  PetscCall(VecDestroy(&dmu2));
  PetscCall(VecDestroy(&df2));
  PetscFunctionReturn(0);
}

/* PGD (soliman2021 Sec. 4.1): right-hand side [0; -g; 0], refinement, then the projection of xt = x + df. */
PetscErrorCode CSWFTrialPGD(CSWillmoreFlow F, PetscBool *accept)
{
  PetscInt its;
  PetscFunctionBeginUser;
  PetscCall(CSWFSetOperators(F, F->t, F->proj_tmu));
  PetscCall(VecSet(F->ct, 0));
  PetscCall(VecCopy(F->g, F->tmp));
  PetscCall(VecScale(F->tmp, -1.0));
  for (PetscInt j = 0; j < F->k; j++) F->cxt[j] = 0;
  PetscCall(CSWFTrySolve(F, F->ct, F->tmp, F->cxt, F->dmu, F->df, F->dnu, &its, accept));
  F->kspits += its;
  if (!*accept) PetscCall(Rejected(F, "linear solve failed"));
  if (*accept) PetscCall(RefinePGD(F, accept));
  if (!*accept) PetscFunctionReturn(0);
  PetscCall(VecWAXPY(F->xt, 1.0, F->df, F->x));
  PetscCall(CSWFProject(F, F->xt, accept, &F->kspits));
  if (!*accept) PetscCall(Rejected(F, "the projection onto the constraint set failed"));
  PetscFunctionReturn(0);
}
