/* CSWillmoreFlowSetFromOptions: every option of the flow, under its prefix (default "flow_"). */
#include "willmore_impl.h"
#include "cs_util.h"

const char *const CSFlowMetricTypes[]   = {"h2", "l2", "h1", "CSFlowMetricType", "CS_FLOW_METRIC_", NULL};
const char *const CSFlowBoundaryTypes[] = {"dirichlet", "free", "normals", "CSFlowBoundaryType", "CS_FLOW_BOUNDARY_", NULL};
const char *const CSSaddleMatTypes[]    = {"nest", "aij", "CSSaddleMatType", "CS_SADDLE_MAT_", NULL};

/* "-<prefix>constraint_area [value]": no value means the initial value. */
static PetscErrorCode OptionalTarget(const char name[], const char help[], PetscBool *set, PetscReal *value, PetscBool *given, PetscOptionItems *PetscOptionsObject)
{
  char s[128] = "";
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsString(name, help, NULL, s, s, sizeof(s), set));
  *given = PETSC_FALSE;
  if (*set && s[0]) {
    PetscCall(PetscOptionsStringToReal(s, value));
    *given = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

/* "-<prefix>constraint_add NAME[,NAME...]": registered global constraints (CSWillmoreFlowConstraintRegister) added
   by name, as CSWillmoreFlowAddConstraint does from code; each is built at the input positions. Read inside the
   options block; checked and added after it (an error inside would leak the block's option items). */
static PetscErrorCode ConstraintAddRead(CSWillmoreFlow F, char *names[], PetscInt *n, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionList list;
  char              known[256], help[400];
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowConstraintList(&list));
  PetscCall(CSFunctionListJoin(list, "|", known, sizeof(known)));
  PetscCall(PetscSNPrintf(help, sizeof(help), "Add registered global constraints by name, each at its value on the input (%s)", known));
  PetscCall(PetscOptionsStringArray("-constraint_add", help, NULL, names, n, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode ConstraintAddApply(CSWillmoreFlow F, char *names[], PetscInt n)
{
  PetscFunctionList list;
  char              known[256], bad[64] = "";
  PetscErrorCode (*create)(CSMesh, Vec, const char[], CSGlobalConstraint *);
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowConstraintList(&list));
  for (PetscInt i = 0; i < n; i++) {
    PetscCall(PetscFunctionListFind(list, names[i], &create));
    if (create && !bad[0]) PetscCall(CSWillmoreFlowAddConstraint(F, names[i]));
    else if (!bad[0]) PetscCall(PetscStrncpy(bad, names[i], sizeof(bad)));
    PetscCall(PetscFree(names[i]));
  }
  if (bad[0]) PetscCall(CSFunctionListJoin(list, "|", known, sizeof(known)));
  PetscCheck(!bad[0], F->hdr.comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-%sconstraint_add %s: unknown constraint (registered: %s)", F->hdr.prefix, bad, known);
  PetscFunctionReturn(0);
}

/* Step sizes, step control, guards, stopping. */
static PetscErrorCode StepOptions(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject)
{
  const char *p = F->hdr.prefix;
  PetscBool   set;
  PetscFunctionBeginUser;
  PetscCall(CSOptionsReal("-t", "Initial primal step size t", NULL, F->t, &F->t, NULL));
  PetscCall(CSOptionsReal("-t_mu", "Dual step size t_mu of the multipliers, for a unit-size mesh (0: the kind's default, 1e5 t for cgd, 1e3 t for gd, newton and trianglefield)", NULL, F->tmu, &F->tmu, NULL));
  PetscCall(CSOptionsReal("-t_max", "Largest primal step", NULL, F->tmax, &F->tmax, NULL));
  PetscCall(CSOptionsReal("-t_mu_grow", "Grow t_mu by this factor after each accepted step, independently of t, up to t_mu_max (0: t_mu follows t)", NULL, F->tmu_grow, &F->tmu_grow, NULL));
  PetscCall(CSOptionsReal("-t_mu_max", "Largest t_mu (default: 1e3 t_max with t_mu_grow, else none; in the units of t_mu)", NULL, F->tmu_max, &F->tmu_max, NULL));
  PetscCall(CSOptionsReal("-t_grow", "Factor on t after an accepted step", NULL, F->grow, &F->grow, NULL));
  PetscCall(PetscOptionsBool("-step_control", "Accept a step only if the filter accepts it (else shrink t: -step_model)", NULL, F->step_control, &F->step_control, NULL));
  if (F->ops.step_halving) F->step_model = CS_WF_STEP_HALVING;
  PetscCall(CSOptionsEnum("-step_model", "Step size after a trial: predicted from the violation and Lagrangian models of the trials (predictive) or halved on rejection and grown by -t_grow on acceptance (halving); docs/willmore_flow.md", NULL, CSWFStepModels, (PetscEnum)F->step_model, (PetscEnum *)&F->step_model, NULL));
  PetscCall(CSOptionsInt("-max_rejections", "Consecutive rejected steps before giving up", NULL, F->max_rej, &F->max_rej, NULL));
  PetscCall(CSOptionsReal("-t_min", "Stop as stalled (not converged) when the step size t falls below this", NULL, F->t_min, &F->t_min, NULL));
  PetscCall(CSOptionsReal("-energy_target", "Stop when the energy is at or below this value (stop_reason energy_target)", NULL, F->energy_target, &F->energy_target, &F->energy_target_set));
  if (!F->max_step_set) F->max_step = F->ops.max_step;
  if (!F->fold_guard_set) F->fold_guard = F->ops.fold_guard;
  PetscCall(CSOptionsReal("-max_step", "Reject a trial step that moves a vertex by more than this times the mean edge length, or turns a face over (0: off; default 0.5 for gd, 2 for newton, 0 otherwise)", NULL, F->max_step, &F->max_step, &F->max_step_set));
  PetscCall(PetscOptionsBool("-fold_guard", "Stop at the last good state when the enclosed volume changes sign against the input, a face turns over within one iteration, or an edge folds into a crease (default on for gd and newton)", NULL, F->fold_guard, &F->fold_guard, &F->fold_guard_set));
  PetscCall(CSOptionsReal("-merit_rho", "Weight of the quadratic constraint penalty in the merit function, relative to |E(input)|", NULL, F->rho, &F->rho, NULL));
  PetscCall(CSOptionsReal("-vmax", "Step control: reject steps whose constraint violation exceeds max(v, this), v that of the current state", NULL, F->vmax, &F->vmax, NULL));
  PetscCall(CSOptionsReal("-restore_above", "CGD/GD, trianglefield: project an accepted state whose constraint violation exceeds this back onto the constraints (0: never)", NULL, F->vrestore, &F->vrestore, NULL));
  PetscCall(PetscOptionsBool("-restore_stalled", "CGD/GD, trianglefield: project an accepted state back onto the constraints when t has collapsed (t < 1e-3 t_max) with the violation above vmax / 10", NULL, F->restore_stalled, &F->restore_stalled, NULL));
  PetscCall(CSOptionsReal("-max_area_ratio", "Stop when max(A_i/A0_i)/min(A_i/A0_i) of the vertex areas, or the total area relative to the input, exceeds this (0: off)", NULL, F->max_area_ratio, &F->max_area_ratio, &F->max_area_ratio_set));
  PetscCall(PetscOptionsBool("-project_at_stop", "When the resolution guard stops the flow, project the state onto the constraints (PGD's projection) so the result lies in the prescribed conformal class", NULL, F->project_at_stop, &F->project_at_stop, NULL));
  PetscCall(CSOptionsReal("-fin_q", "Resolution guard: a stop with the largest quasi-conformal error of a face above this is reported as fins (a jump of the conformal factor across faces), below it as a smooth concentration", NULL, F->fin_q, &F->fin_q, NULL));
  PetscCall(CSOptionsReal("-rtol", "Stop when the Euler-Lagrange residual is below this: el_residual_scaled = ||g + X^T mu + sum nu_j row_j||_2 sqrt(A) / |E|, scale-free (or ||g + X^T mu + ...||_2 itself with -el_norm absolute)", NULL, F->rtol, &F->rtol, NULL));
  PetscCall(CSOptionsReal("-ctol", "... and the constraint violation (inf-norm) below this", NULL, F->ctol, &F->ctol, NULL));
  PetscCall(CSOptionsInt("-max_it", "Maximum number of iterations", NULL, F->max_it, &F->max_it, NULL));
  PetscCall(CSOptionsReal("-max_seconds", "Stop (as at max_it) once this many seconds have passed since the set-up (0: no limit); rank 0's clock decides for all ranks", NULL, F->max_seconds, &F->max_seconds, NULL));
  PetscCall(CSOptionsReal("-iq_wmin", "Floor on cotan weights in I_Q (Eq. 25) for non-Delaunay edges", NULL, F->wmin, &F->wmin, NULL));
  PetscCall(CSOptionsReal("-pgd_t_mu", "PGD: regularising dual step of the (singular) PGD system and of the projection", NULL, F->proj_tmu, &F->proj_tmu, NULL));
  PetscCall(CSOptionsInt("-soc_max_it", "CGD/GD: second-order corrections of each trial step toward the constraints (0: none)", NULL, F->soc_max_it, &F->soc_max_it, NULL));
  PetscCall(CSOptionsInt("-pgd_projection_max_it", "PGD: Gauss-Newton iterations of the projection onto the constraint set", NULL, F->proj_max_it, &F->proj_max_it, NULL));
  PetscCall(CSOptionsInt("-factor_reuse_its", "Keep the preconditioner (factorisation) of an earlier step while the last solve needed at most this many Krylov iterations (0: refactor every step; default 10 with the conformal constraint, else 0; ignored with a preonly saddle KSP)", NULL, F->reuse_its, &F->reuse_its, &set));
  PetscCheck(!set || F->reuse_its >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sfactor_reuse_its %" PetscInt_FMT ": use 0 (refactor every step) or a positive iteration count", p, F->reuse_its);
  PetscCall(CSOptionsEnum("-matrix_type", "The saddle matrix as MATNEST (fieldsplit) or converted to AIJ (monolithic direct solvers)", NULL, CSSaddleMatTypes, (PetscEnum)F->saddle_mat, (PetscEnum *)&F->saddle_mat, NULL));
  PetscFunctionReturn(0);
}

/* The problem: energy, metric, constraints, boundary. */
static PetscErrorCode ProblemOptions(CSWillmoreFlow F, PetscFunctionList energies, PetscOptionItems *PetscOptionsObject)
{
  PetscBool conformal = F->ops.conformal;
  PetscFunctionBeginUser;
  PetscCall(CSOptionsEnum("-metric", "Metric of the primal step: H^2 (soliman2021 Eq. 26), the mass (l2), or H^1 = sqrt(w) *0 + L, of the area energy's order (docs/boundary_twist.md)", NULL, CSFlowMetricTypes, (PetscEnum)F->metric_type, (PetscEnum *)&F->metric_type, NULL));
  PetscCall(PetscOptionsFList("-energy", "Energy of the flow", NULL, energies, F->energy_name, F->energy_name, sizeof(F->energy_name), NULL));
  PetscCall(PetscOptionsBool("-conformal", "Exact conformal constraint (default on for cgd and pgd)", NULL, conformal, &conformal, &F->conformal_set));
  F->conformal = conformal;
  PetscCall(CSOptionsString("-target_mesh", "Mesh with the same connectivity whose conformal class is the target (soliman2021 Fig. 2)", NULL, F->target, F->target, sizeof(F->target), NULL));
  PetscCall(OptionalTarget("-constraint_area", "Total area constraint [target value, default the initial area]", &F->area_set, &F->area_target, &F->area_given, PetscOptionsObject));
  PetscCall(OptionalTarget("-constraint_volume", "Enclosed volume constraint [target value, default the initial volume]", &F->vol_set, &F->vol_target, &F->vol_given, PetscOptionsObject));
  PetscCall(CSOptionsString("-constraint_points", "File of point constraints: lines 'vertex_index x y z' (0-based)", NULL, F->points, F->points, sizeof(F->points), NULL));
  PetscCall(PetscOptionsBool("-constraint_mobius", "Moebius balancing: fix the three Moebius boosts that the conformal constraint leaves free (closed surfaces; needs the conformal constraint; trianglefield: on the Poisson reconstruction, omega variables)", NULL, F->mobius, &F->mobius, NULL));
  PetscCall(PetscOptionsBool("-constraint_rotation", "Rotation gauge of the domain: fix the three rotations of the Moebius group that the balancing leaves free (closed genus-0 surfaces; with -constraint_mobius; docs/vesicle.md)", NULL, F->rotation, &F->rotation, NULL));
  PetscCall(CSOptionsEnum("-boundary", "Boundary vertices fixed, free (C0 only), or fixed with fixed boundary-face normals (App. D)", NULL, CSFlowBoundaryTypes, (PetscEnum)F->boundary, (PetscEnum *)&F->boundary, &F->boundary_set));
  PetscFunctionReturn(0);
}

/* Every numeric option finite and in range, named in the error (issue 18, item 10). */
static PetscErrorCode CheckValues(CSWillmoreFlow F)
{
  const CSOptionCheck checks[] = {
    /* first, with a range: a t of 1e-300 was blamed on -t_min, one of 1e300 failed inside the factorisation */
    {"t", F->t, F->t >= 1e-12 && F->t <= 1e8, "must lie in [1e-12, 1e8] (a step size of the scaled flow)"},
    {"t_mu", F->tmu, F->tmu >= 0 && F->tmu <= 1e15, "must lie in (0, 1e15] (0: the kind's default)"},
    {"t_max", F->tmax, F->tmax >= F->t && F->tmax <= 1e8, "must lie in [-t, 1e8]"},
    {"t_grow", F->grow, F->grow >= 1, "must be >= 1"},
    {"t_mu_grow", F->tmu_grow, F->tmu_grow == 0 || F->tmu_grow >= 1, "use 0 (t_mu follows t) or a factor >= 1"},
    {"t_mu_max", F->tmu_max, F->tmu_max >= 0, "must be >= 0 (0: the default)"},
    {"merit_rho", F->rho, F->rho >= 0, "must be >= 0"},
    {"vmax", F->vmax, F->vmax > 0, "must be > 0"},
    {"restore_above", F->vrestore, F->vrestore >= 0, "use 0 (off) or a positive violation"},
    {"max_area_ratio", F->max_area_ratio, F->max_area_ratio == 0 || F->max_area_ratio > 1, "use 0 (off) or a ratio above 1"},
    {"fin_q", F->fin_q, F->fin_q >= 1, "a quasi-conformal error is at least 1"},
    {"iq_wmin", F->wmin, F->wmin > 0, "must be > 0"},
    {"rtol", F->rtol, F->rtol >= 0, "must be >= 0"},
    {"ctol", F->ctol, F->ctol >= 0, "must be >= 0"},
    {"stationary_window", (PetscReal)F->stat_window, F->stat_window >= 0 && F->stat_window <= CS_WF_STAT_MAX, "use 0 (off) or a count of steps up to 64"},
    {"stationary_rtol", F->stat_rtol, F->stat_rtol >= 0, "must be >= 0"},
    {"stationary_xtol", F->stat_xtol, F->stat_xtol >= 0, "must be >= 0"},
    {"drift_window", (PetscReal)F->drift_window, F->drift_window >= 0 && F->drift_window <= CS_WF_STAT_MAX, "use 0 (off) or a count of steps up to 64"},
    {"drift_wtol", F->drift_wtol, F->drift_wtol >= 0, "must be >= 0"},
    {"drift_rise", F->drift_rise, F->drift_rise >= 1, "must be >= 1"},
    {"drift_rise_steps", (PetscReal)F->drift_rise_steps, F->drift_rise_steps >= 1, "must be >= 1 (1: a single risen residual is enough)"},
    {"pgd_t_mu", F->proj_tmu, F->proj_tmu > 0, "must be > 0"},
    {"pgd_projection_max_it", (PetscReal)F->proj_max_it, F->proj_max_it >= 1, "must be >= 1"},
    {"max_seconds", F->max_seconds, F->max_seconds >= 0, "use 0 (no limit) or a positive number of seconds"},
    {"max_it", (PetscReal)F->max_it, F->max_it >= 0, "must be >= 0"},
    {"max_rejections", (PetscReal)F->max_rej, F->max_rej >= 1, "must be >= 1"},
    {"t_min", F->t_min, F->t_min >= 0 && F->t_min <= F->t, "must lie in [0, t]"},
    {"max_step", F->max_step, F->max_step >= 0, "use 0 (off) or a positive fraction of the mean edge length"},
    {"energy_target", F->energy_target, !PetscIsInfOrNanReal(F->energy_target), "must be finite"},
    {"soc_max_it", (PetscReal)F->soc_max_it, F->soc_max_it >= 0, "use 0 (no corrections) or a positive count"},
    /* a target the surface cannot have: inf was taken, then 31 rejected steps and exit 0 (issue 36, item 16) */
    {"constraint_area", F->area_given ? F->area_target : 1, !F->area_given || (F->area_target > 0 && F->area_target <= 1e12), "the target area must lie in (0, 1e12]"},
    {"constraint_volume", F->vol_given ? F->vol_target : 1, !F->vol_given || PetscAbsReal(F->vol_target) <= 1e12, "the target volume must lie in [-1e12, 1e12]"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(F->hdr.comm, F->hdr.prefix, sizeof(checks) / sizeof(checks[0]), checks));
  PetscFunctionReturn(0);
}

/* Consistency of the options with each other and with the kind. */
static PetscErrorCode CheckOptions(CSWillmoreFlow F)
{
  const char *p = F->hdr.prefix;
  PetscFunctionBeginUser;
  PetscCall(CheckValues(F));
  if (F->tmu == 0) F->tmu = (F->ops.tmu_ratio > 0 ? F->ops.tmu_ratio : 1e3) * F->t; /* the kind's default */
  PetscCheck(!F->target[0] || F->conformal, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%starget_mesh %s needs the conformal constraint (cgd, or pgd with -%sconformal)", p, F->target, p);
  PetscCheck(!F->boundary_set || F->boundary != CS_FLOW_BOUNDARY_NORMALS || F->conformal, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%sboundary normals needs the conformal constraint (cgd or pgd)", p);
  /* the step-geometry check and the fold guard measure vertex positions; a triangle field's variables are not */
  PetscCheck(!CSWFOwnVariables(F) || (F->max_step == 0 && !F->fold_guard), F->hdr.comm, PETSC_ERR_SUP, "-%smax_step and -%sfold_guard work on vertex positions, not on -%stype %s (its reconstruction is guarded by -%smax_area_ratio)", p, p, p, F->type, p);
  PetscCall(CSWFPointsContinuationCheck(F));
  if (F->ops.setup) PetscCall((*F->ops.setup)(F));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowSetFromOptions(CSWillmoreFlow F)
{
  char              type[16], *added[32];
  PetscInt          nadded = 32;
  PetscBool         set;
  PetscFunctionList energies, kinds;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowEnergyList(&energies));
  PetscCall(CSWillmoreFlowGetTypeList(&kinds));
  PetscCall(PetscStrncpy(type, F->type, sizeof(type)));
  PetscOptionsBegin(F->hdr.comm, F->hdr.prefix, "Constrained Willmore flow (soliman2021)", NULL);
  PetscCall(PetscOptionsFList("-type", "Flow kind", NULL, kinds, type, type, sizeof(type), &set));
  if (set) PetscCall(CSWillmoreFlowSetType(F, type));
  PetscCall(StepOptions(F, PetscOptionsObject));
  PetscCall(CSWFStopOptions(F, PetscOptionsObject));
  PetscCall(ProblemOptions(F, energies, PetscOptionsObject));
  PetscCall(CSWFPointsContinuationOptions(F, PetscOptionsObject));
  PetscCall(ConstraintAddRead(F, added, &nadded, PetscOptionsObject));
  if (F->ops.setfromoptions) PetscCall((*F->ops.setfromoptions)(F, PetscOptionsObject));
  PetscOptionsEnd();
  PetscCall(ConstraintAddApply(F, added, nadded));
  PetscCall(CheckOptions(F));
  PetscFunctionReturn(0);
}
