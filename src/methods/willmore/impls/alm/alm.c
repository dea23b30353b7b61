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
#include "cs_util.h"

const char *const CSALMMetricTypes[] = {"plain", "gauss_newton", "CSALMMetricType", "CS_ALM_METRIC_", NULL};

typedef struct {
  PetscReal       rho, grow, rho_max; /* -alm_rho (relative to |E(input)|), -alm_rho_grow, -alm_rho_max (scaled by ScaleALM) */
  PetscInt        inner_it;           /* -alm_inner_it: accepted steps per inner loop */
  CSALMMetricType metric;             /* -alm_metric: metric of the inner steps */
  PetscInt        inner, update, updates; /* loop state: steps in this inner loop, iteration of the last update, updates */
  PetscReal       vlast;              /* violation at the last multiplier update */
} ALM;

static PetscErrorCode SetFromOptionsALM(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject)
{
  ALM *alm = (ALM *)F->data;
  PetscFunctionBeginUser;
  PetscCall(CSOptionsReal("-alm_rho", "ALM: initial penalty rho of the augmented Lagrangian, relative to |E(input)|", NULL, alm->rho, &alm->rho, NULL));
  PetscCall(CSOptionsReal("-alm_rho_grow", "ALM: factor on rho at a multiplier update that did not reduce the violation 4-fold", NULL, alm->grow, &alm->grow, NULL));
  PetscCall(CSOptionsReal("-alm_rho_max", "ALM: largest rho (relative to |E(input)|)", NULL, alm->rho_max, &alm->rho_max, NULL));
  PetscCall(CSOptionsEnum("-alm_metric", "ALM: metric of the inner gradient steps: the flow's metric alone (plain) or with the penalty's Gauss-Newton curvature", NULL, CSALMMetricTypes, (PetscEnum)alm->metric, (PetscEnum *)&alm->metric, NULL));
  PetscCall(CSOptionsInt("-alm_inner_it", "ALM: accepted gradient steps between multiplier updates", NULL, alm->inner_it, &alm->inner_it, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode SetUpALM(CSWillmoreFlow F)
{
  ALM                *alm      = (ALM *)F->data;
  const CSOptionCheck checks[] = {
    {"alm_rho", alm->rho, alm->rho > 0, "must be > 0"},
    {"alm_rho_grow", alm->grow, alm->grow >= 1, "must be >= 1"},
    {"alm_rho_max", alm->rho_max, alm->rho_max >= alm->rho, "must be >= -alm_rho"},
    {"alm_inner_it", (PetscReal)alm->inner_it, alm->inner_it >= 1, "must be >= 1"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(F->hdr.comm, F->hdr.prefix, sizeof(checks) / sizeof(checks[0]), checks));
  PetscCheck(F->conformal || F->area_set || F->vol_set || F->points[0] || F->mobius, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype alm without any constraint is plain gradient descent: use -%stype gd", F->hdr.prefix, F->hdr.prefix);
  PetscCheck(F->boundary != CS_FLOW_BOUNDARY_NORMALS, F->hdr.comm, PETSC_ERR_SUP, "-%stype alm with -%sboundary normals is not supported", F->hdr.prefix, F->hdr.prefix);
  F->rho            = alm->rho; /* scaled by |E(input)| in CSWFSetUpScaling, as -merit_rho */
  F->project_at_stop = PETSC_FALSE; /* the projection needs the saddle's edge block */
  PetscFunctionReturn(0);
}

/* The multiplier estimates mu~ = mu + rho c (into F->mun) and nu~ (into F->nun) at the constraints c, cx. */
static PetscErrorCode MultiplierEstimate(CSWillmoreFlow F, Vec c, const PetscReal cx[])
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecWAXPY(F->mun, F->rho, c, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nun[j] = F->nu[j] + F->rho * cx[j] / F->gw[j];
  PetscFunctionReturn(0);
}

/* The first-order multiplier update and the penalty schedule, between inner loops. */
static PetscErrorCode UpdateMultipliers(CSWillmoreFlow F)
{
  ALM      *alm = (ALM *)F->data;
  PetscReal v   = PetscMax(F->conf, F->glob);
  PetscFunctionBeginUser;
  PetscCall(MultiplierEstimate(F, F->c, F->cx));
  if (F->conformal) PetscCall(VecCopy(F->mun, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] = F->nun[j];
  if (alm->vlast > 0 && v > 0.25 * alm->vlast) F->rho = PetscMin(F->rho * alm->grow, alm->rho_max);
  alm->vlast  = v;
  alm->inner  = 0;
  alm->update = F->it;
  alm->updates++;
  PetscFunctionReturn(0);
}

/* r = grad L_A = g + X^T mu~ + sum_j nu~_j rows_j: the residual of soliman2021 Eq. 7 with the multipliers the
   method would take next (the stopping residual, and the direction of the next step). */
static PetscErrorCode ResidualALM(CSWillmoreFlow F, PetscReal *el)
{
  PetscFunctionBeginUser;
  if (F->k) PetscCall(CSWFGlobalWeights(F));
  PetscCall(MultiplierEstimate(F, F->c, F->cx));
  PetscCall(CSWFResidualWith(F, F->mun, F->nun, el));
  PetscFunctionReturn(0);
}

/* the conformal multiplier reported (CSWillmoreFlowGetConformalMultiplier): its first-order estimate mu + rho c */
static PetscErrorCode MultipliersALM(CSWillmoreFlow F, Vec *mu)
{
  PetscFunctionBeginUser;
  PetscCall(MultiplierEstimate(F, F->c, F->cx));
  *mu = F->mun;
  PetscFunctionReturn(0);
}

/* The penalty |c|^2 is unweighted: I_Q stays the identity set at the start (no Eq. 25 weights at x). */
static PetscErrorCode WeightsALM(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  (void)F;
  PetscFunctionReturn(0);
}

/* -alm_rho_max relative to |E(input)|, as rho itself (CSWFSetUpScaling) */
static PetscErrorCode ScaleALM(CSWillmoreFlow F, PetscReal sc, PetscReal E0)
{
  ALM *alm = (ALM *)F->data;
  PetscFunctionBeginUser;
  (void)sc;
  alm->rho_max *= PetscMax(PetscAbsReal(E0), PETSC_SMALL);
  PetscFunctionReturn(0);
}

/* -alm_metric plain: the metric solve alone, no multiplier block and no bordering */
static PetscErrorCode SaddleBlocksALM(CSWillmoreFlow F, PetscBool *edges, PetscInt *k)
{
  ALM      *alm   = (ALM *)F->data;
  PetscBool plain = (PetscBool)(alm->metric == CS_ALM_METRIC_PLAIN);
  PetscFunctionBeginUser;
  *edges = (PetscBool)(F->conformal && !plain);
  *k     = plain ? 0 : F->k;
  PetscFunctionReturn(0);
}

static PetscErrorCode StorableALM(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  SETERRQ(F->hdr.comm, PETSC_ERR_SUP, "-checkpoint/-resume with -%stype alm: the penalty schedule is not stored in checkpoints", F->hdr.prefix);
}

static PetscErrorCode ViewALM(CSWillmoreFlow F, PetscViewer viewer)
{
  ALM *alm = (ALM *)F->data;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  augmented Lagrangian: rho %g (growth %g, at most %g), %" PetscInt_FMT " steps per inner loop, metric %s\n", (double)F->rho, (double)alm->grow, (double)alm->rho_max, alm->inner_it, CSALMMetricTypes[alm->metric]));
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
  ALM      *alm = (ALM *)F->data;
  PetscInt  its;
  PetscBool gn = (PetscBool)(alm->metric == CS_ALM_METRIC_GAUSS_NEWTON);
  PetscFunctionBeginUser;
  if (alm->update != F->it && (alm->inner >= alm->inner_it || CSWFStopResidual(F) < F->rtol)) {
    PetscCall(UpdateMultipliers(F));
    PetscCall(ResidualALM(F, &F->el)); /* grad L_A with the new mu, rho: the step's direction */
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
  if (!*accept) PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: linear solve failed with t = %g; halving t\n", (double)F->t));
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
  if (!*accept) PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: augmented Lagrangian %.15g -> %.15g with t = %g; halving t\n", (double)L0, (double)Lt, (double)F->t));
  PetscFunctionReturn(0);
}

static PetscErrorCode AcceptALM(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  ((ALM *)F->data)->inner++;
  PetscFunctionReturn(0);
}

/* the kind's strategy (willmore_impl.h), grouped: identity, the step, hooks, its own data and options */
static const struct _CSWillmoreFlowOps ALMOps = {
  .id = 4, .conformal = PETSC_TRUE, /* id: its own (newton has 3; unique: checked at CSWillmoreFlowRegister) */
  .trial = TrialALM, .filter = FilterALM, .accept = AcceptALM, .grow = CSWFGrowPrimal, .shrink = CSWFShrinkPrimal,
  .residual = ResidualALM, .multipliers = MultipliersALM, .weights = WeightsALM, .saddle_blocks = SaddleBlocksALM, .scale = ScaleALM, .storable = StorableALM, .start = StartALM,
  .setfromoptions = SetFromOptionsALM, .setup = SetUpALM, .view = ViewALM, .destroy = CSWFDestroyData,
};

PetscErrorCode CSWillmoreFlowCreate_ALM(CSWillmoreFlow F)
{
  ALM *alm;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&alm));
  alm->rho              = 10;
  alm->grow             = 10;
  alm->rho_max          = 1e8;
  alm->inner_it         = 10;
  alm->update           = -1;
  alm->metric           = CS_ALM_METRIC_GAUSS_NEWTON; /* converges for moderate rho; plain (the paper's explicit baseline) does not (docs/alm.md) */
  F->data               = alm;
  F->ops                = ALMOps;
  PetscFunctionReturn(0);
}
