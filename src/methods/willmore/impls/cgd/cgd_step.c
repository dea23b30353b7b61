/* CGD/GD's trial step (soliman2021 Algorithm 1 line 11): the saddle solve of the step, then the second-order
   corrections of the trial point toward the constraints. */
#include "cgd_impl.h"

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
  if (!*accept) PetscCall(CSWFRejected(F, "linear solve failed"));
  if (!*accept) PetscFunctionReturn(0);
  PetscCall(VecWAXPY(F->xt, 1.0, F->df, F->x));
  its = 0;
  PetscCall(SecondOrderCorrection(F, F->xt, &its, accept));
  F->kspits += its;
  if (!*accept) PetscCall(CSWFRejected(F, "the linear solve of the second-order correction failed"));
  PetscFunctionReturn(0);
}

