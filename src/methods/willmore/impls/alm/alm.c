/* -flow_type alm: the augmented Lagrangian baseline of soliman2021 Sec. 6 (Fig. 7; Bertsekas 1996, Nocedal &
   Wright 2006, Framework 17.3). It minimises
       L_A(f; mu, nu, rho) = E(f) + <mu, c(f)> + rho/2 |c(f)|^2 + sum_j nu_j xi_j(f) + rho/2 xi_j(f)^2 / g_j
   (c: the log cross ratios against the target class, xi_j the global constraints, g_j = |grad xi_j|^2 so that
   every constraint is penalised alike, as in CSWFMerit) by explicit Sobolev gradient steps
       H df = -t grad L_A,    H the H^2 (or L2) metric (soliman2021 Eq. 10, 11),
   each accepted when L_A does not increase (else t is halved). After -flow_alm_inner_it accepted steps, or
   earlier once |grad L_A| < rtol, the multipliers take the first-order update
       mu <- mu + rho c,   nu_j <- nu_j + rho xi_j / g_j,
   and rho grows by -flow_alm_rho_grow (up to -flow_alm_rho_max) when the violation did not fall below a quarter
   of its value at the previous update (Nocedal & Wright Algorithm 17.4). rho is given relative to |E(input)|.
   -flow_alm_metric plain is the paper's baseline: the metric H alone, whose steps the penalty's curvature
   rho X^T X limits to t ~ 1/rho; gauss_newton (the default) adds that curvature to the metric (below), so the
   inner loop takes full steps for any rho (docs/alm.md says why it is the default).
   The reported Euler-Lagrange residual is |g + X^T mu~ + sum nu~_j row_j| with the first-order estimates
   mu~ = mu + rho c, nu~_j = nu_j + rho xi_j / g_j, i.e. |grad L_A|: it is the residual of soliman2021 Eq. 7 with
   the multiplier the method would take next. The saddle solver is used without the edge block (a metric solve). */
#include "../../willmore_impl.h"

static PetscErrorCode SetUpALM(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(F->conformal || F->area_set || F->vol_set || F->points[0] || F->mobius, F->comm, PETSC_ERR_ARG_INCOMP, "-%stype alm without any constraint is plain gradient descent: use -%stype gd", F->prefix, F->prefix);
  PetscCheck(F->boundary != CS_FLOW_BOUNDARY_NORMALS, F->comm, PETSC_ERR_SUP, "-%stype alm with -%sboundary normals is not supported", F->prefix, F->prefix);
  F->rho            = F->alm_rho; /* scaled by |E(input)| in CSWFSetUpScaling, as -merit_rho */
  F->project_at_stop = PETSC_FALSE; /* the projection needs the saddle's edge block */
  PetscFunctionReturn(0);
}

/* The multiplier estimates mu~ = mu + rho c (into F->mun) and nu~ (into F->nun) at the constraints c, cx. */
PetscErrorCode CSWFMultiplierEstimate(CSWillmoreFlow F, Vec c, const PetscReal cx[])
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecWAXPY(F->mun, F->rho, c, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nun[j] = F->nu[j] + F->rho * cx[j] / F->gw[j];
  PetscFunctionReturn(0);
}

/* The first-order multiplier update and the penalty schedule, between inner loops. */
static PetscErrorCode UpdateMultipliers(CSWillmoreFlow F)
{
  PetscReal v = PetscMax(F->conf, F->glob);
  PetscFunctionBeginUser;
  PetscCall(CSWFMultiplierEstimate(F, F->c, F->cx));
  if (F->conformal) PetscCall(VecCopy(F->mun, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] = F->nun[j];
  if (F->alm_vlast > 0 && v > 0.25 * F->alm_vlast) F->rho = PetscMin(F->rho * F->alm_grow, F->alm_rho_max);
  F->alm_vlast  = v;
  F->alm_inner  = 0;
  F->alm_update = F->it;
  F->alm_updates++;
  PetscFunctionReturn(0);
}

/* The Gauss-Newton metric needs the unweighted penalty: I_Q replaced by the identity. */
static PetscErrorCode StartALM(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecSet(F->iq, 1.0));
  PetscFunctionReturn(0);
}

/* One gradient step of L_A: rhs -grad L_A = -(g + X^T mu~ + sum nu~_j rows_j). Metric plain: H df = -t grad L_A
   (the saddle solve without edge block). Metric gauss_newton: (H/t + rho X^T X + sum_j rho/g_j row_j row_j^T) df
   = -grad L_A, the saddle system with I_Q = identity, t_mu = rho and zero constraint right-hand sides (its Schur
   complement is that matrix); the multiplier parts of its solution are discarded. */
static PetscErrorCode TrialALM(CSWillmoreFlow F, PetscBool *accept)
{
  PetscInt its;
  PetscBool gn = (PetscBool)(F->alm_metric == CS_ALM_METRIC_GAUSS_NEWTON);
  PetscFunctionBeginUser;
  if (F->alm_update != F->it && (F->alm_inner >= F->alm_inner_it || CSWFStopResidual(F) < F->rtol)) {
    PetscCall(UpdateMultipliers(F));
    PetscCall(CSWFResidual(F, &F->el)); /* grad L_A with the new mu, rho: the step's direction */
    PetscCall(CSWFScaledResidual(F));
  }
  PetscCall(CSWFSetOperators(F, F->t, F->rho));
  PetscCall(VecCopy(F->r, F->tmp));
  PetscCall(VecScale(F->tmp, -1.0));
  if (gn && F->conformal) PetscCall(VecSet(F->ct, 0));
  for (PetscInt j = 0; j < F->k; j++) F->cxt[j] = 0;
  if (gn) PetscCall(CSWFTrySolve(F, F->conformal ? F->ct : NULL, F->tmp, F->cxt, F->conformal ? F->dmu : NULL, F->df, F->dnu, &its, accept));
  else PetscCall(CSWFTrySolve(F, NULL, F->tmp, NULL, NULL, F->df, NULL, &its, accept));
  F->kspits += its;
  if (!*accept) PetscCall(PetscPrintf(F->comm, "     step rejected: linear solve failed with t = %g; halving t\n", (double)F->t));
  if (*accept) PetscCall(VecWAXPY(F->xt, 1.0, F->df, F->x));
  PetscFunctionReturn(0);
}

/* L_A(xt) <= L_A(x) with the multipliers and rho of this inner loop. */
static PetscErrorCode FilterALM(CSWillmoreFlow F, PetscBool *accept)
{
  PetscReal L0, Lt, Et;
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecCopy(F->mu, F->mun));
  for (PetscInt j = 0; j < F->k; j++) F->nun[j] = F->nu[j];
  PetscCall(CSWFMerit(F, F->E, F->c, F->cx, F->nun, &L0));
  PetscCall(CSEnergyValue(F->energy, F->xt, &Et));
  PetscCall(CSWFEvalConstraints(F, F->xt, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(CSWFMerit(F, Et, F->ct, F->cxt, F->nun, &Lt));
  *accept = (PetscBool)(Lt == Lt && Lt <= L0 + 1e-12 * PetscAbsReal(L0));
  if (!*accept) PetscCall(PetscPrintf(F->comm, "     step rejected: augmented Lagrangian %.15g -> %.15g with t = %g; halving t\n", (double)L0, (double)Lt, (double)F->t));
  PetscFunctionReturn(0);
}

static PetscErrorCode AcceptALM(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->alm_inner++;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowCreate_ALM(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->ops.id        = 3;
  F->ops.conformal = PETSC_TRUE;
  F->ops.penalty   = PETSC_TRUE;
  F->ops.setup     = SetUpALM;
  F->ops.start     = StartALM;
  F->ops.trial     = TrialALM;
  F->ops.filter    = FilterALM;
  F->ops.accept    = AcceptALM;
  F->ops.grow      = CSWFGrowPrimal;
  F->ops.shrink    = CSWFShrinkPrimal;
  PetscFunctionReturn(0);
}
