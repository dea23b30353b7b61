/* The outer iteration: evaluate at x, monitor, stop or step (trial, filter, rejections), accept. */
#include "willmore_impl.h"
#include "cs_log.h"

/* The smallest and largest violation of the run and their iterations: the report says when the violation at the
   end is above both -flow_ctol and 10x the smallest of the run (it grew; issue 21), so no run ends out of the
   prescribed class without saying so. Every kind (trianglefield: its conformal and period rows). */
static void TrackViolation(CSWillmoreFlow F)
{
  PetscReal v = PetscMax(F->conf, F->glob);
  if (v > F->viol_max) F->viol_max_it = F->it;
  F->viol_max = PetscMax(F->viol_max, v); /* reported as violation_max */
  if (F->viol_min < 0 || v < F->viol_min) {
    F->viol_min    = v;
    F->viol_min_it = F->it;
  }
}

/* Everything the stopping tests, the monitors and the next step need at x. */
static PetscErrorCode Evaluate(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->ops.evaluate) PetscCall((*F->ops.evaluate)(F)); /* a kind with its own variables (trianglefield) */
  else {
    PetscCall(CSEnergyGradient(F->energy, F->x, &F->E, F->g));
    PetscCall(CSWFZeroFixed(F, F->g));
    PetscCall(CSWFEvalConstraints(F, F->x, F->c, F->cx, PETSC_TRUE));
    if (F->ops.residual) PetscCall((*F->ops.residual)(F, &F->el));
    else PetscCall(CSWFResidual(F, &F->el));
    PetscCall(CSWFViolation(F, F->c, F->cx, &F->conf, &F->glob));
    PetscCall(CSGeometryAreaVolume(F->mesh, F->x, &F->A, &F->V));
    PetscCall(CSWFMeasureQuality(F));
  }
  PetscCall(CSWFScaledResidual(F));
  TrackViolation(F);
  PetscCall(CSWFTrackPath(F));
  PetscFunctionReturn(0);
}

/* The operators of the step at x: metric, I_Q (with the count of guarded weights), global weights. */
static PetscErrorCode Operators(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->ops.operators) {
    PetscCall((*F->ops.operators)(F));
    PetscFunctionReturn(0);
  }
  if (!F->ops.own_metric) PetscCall(CSMetricUpdate(&F->metric, F->x));
  if (F->conformal && F->ops.weights) PetscCall((*F->ops.weights)(F)); /* ALM: unweighted (impls/alm/alm.c) */
  else if (F->conformal) {
    PetscInt ng;
    PetscCall(CSWFQuadDiffMetric(F, F->x, &ng));
    F->nguard = PetscMax(F->nguard, ng);
  }
  if (F->k) PetscCall(CSWFGlobalWeights(F));
  PetscFunctionReturn(0);
}

/* Trial steps with halved t until one is accepted (*accepted), -flow_max_rejections is exceeded (reason
   DIVERGED_REJECTIONS) or t falls below -flow_t_min (STALLED); x stays the last accepted state. */
static PetscErrorCode StepWithRejections(CSWillmoreFlow F, PetscBool *accepted)
{
  PetscFunctionBeginUser;
  F->kspits = 0;
  for (PetscInt rej = 0;; rej++) {
    PetscBool accept;
    if (F->t < F->t_min) {
      PetscBool atceil = (PetscBool)(F->step_control && PetscMax(F->conf, F->glob) >= 0.5 * F->vmax);
      PetscCall(PetscPrintf(F->hdr.comm, "flow: the step size t = %g fell below -%st_min (%g) at iteration %" PetscInt_FMT ": stalled, stopping with the last accepted state (not converged: el_residual %.3e, conformal violation %.3e, constraint violation %.3e%s%s%s)\n", (double)F->t, F->hdr.prefix, (double)F->t_min, F->it, (double)F->el, (double)F->conf, (double)F->glob, atceil ? "; the violation is near the ceiling -" : "", atceil ? F->hdr.prefix : "", atceil ? "vmax, above which a trial step is rejected" : ""));
      *accepted = PETSC_FALSE;
      F->reason = CS_WILLMORE_FLOW_STALLED;
      PetscFunctionReturn(0);
    }
    if (rej > F->max_rej) {
      /* stop cleanly: x is the last accepted state, and E, el, c belong to it */
      PetscCall(PetscPrintf(F->hdr.comm, "flow: %" PetscInt_FMT " consecutive steps rejected at iteration %" PetscInt_FMT " (t = %g, -%smax_rejections): stopping with the last accepted state\n", rej, F->it, (double)F->t, F->hdr.prefix));
      *accepted = PETSC_FALSE;
      PetscFunctionReturn(0);
    }
    PetscCall((*F->ops.trial)(F, &accept));
    if (accept) PetscCall(CSWFCheckStepGeometry(F, &accept));
    if (accept && !F->step_control) PetscCall(CSWFCheckFinite(F, &accept));
    else if (accept) PetscCall((*F->ops.filter)(F, &accept));
    if (accept) break;
    F->rejections++;
    PetscCall((*F->ops.shrink)(F));
  }
  *accepted = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* The state the resolution guard stopped at is not a critical point, but it can at least be exactly in the
   constraint set: PGD's projection puts it there (-flow_project_at_stop, on), so the result written is a surface
   in the prescribed conformal class with a lower W than the input (docs/real_meshes.md). If the projection fails
   the state is kept as it was. */
static PetscErrorCode ProjectAtStop(CSWillmoreFlow F)
{
  PetscReal v = PetscMax(F->conf, F->glob), E = F->E;
  PetscInt  its = 0;
  PetscBool ok;
  Vec       keep;
  PetscFunctionBeginUser;
  if (!F->project_at_stop || (!F->conformal && !F->k) || v < F->ctol) PetscFunctionReturn(0);
  if (CSWFOwnVariables(F)) PetscFunctionReturn(0); /* the projection works on positions, not on a kind's own variables */
  PetscCall(VecDuplicate(F->x, &keep));
  PetscCall(VecCopy(F->x, keep));
  PetscCall(CSWFProject(F, F->x, &ok, &its));
  if (ok) PetscCall(Evaluate(F));
  else PetscCall(VecCopy(keep, F->x));
  PetscCall(VecDestroy(&keep));
  if (ok) PetscCall(PetscPrintf(F->hdr.comm, "flow: the stopped state is projected onto the constraints (-%sproject_at_stop): violation %.2e -> %.2e, W %.10g -> %.10g, largest quasi-conformal error %.3g\n", F->hdr.prefix, (double)v, (double)PetscMax(F->conf, F->glob), (double)E, (double)F->E, (double)F->qmax));
  else PetscCall(PetscPrintf(F->hdr.comm, "flow: the projection of the stopped state onto the constraints failed (-%sproject_at_stop); the state is kept, violation %.2e\n", F->hdr.prefix, (double)v));
  PetscFunctionReturn(0);
}

/* The fold guard (willmore_guards.c): a folded state is replaced by the last good one, which the monitors then show and
   the flow returns. */
static PetscErrorCode StopIfFolded(CSWillmoreFlow F)
{
  PetscBool folded;
  PetscFunctionBeginUser;
  PetscCall(CSWFCheckFolds(F, &folded));
  if (!folded) PetscFunctionReturn(0);
  if (F->good_set) { /* else the first state is folded already: it is all there is */
    PetscCall(VecCopy(F->xgood, F->x));
    PetscCall(Evaluate(F));
  }
  F->reason = CS_WILLMORE_FLOW_DIVERGED_FOLDED;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowStep(CSWillmoreFlow F, CSWillmoreFlowConvergedReason *reason)
{
  PetscBool accepted;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowSetUp(F));
  PetscCall(PetscLogEventBegin(CS_EVENT_WillmoreStep, 0, 0, 0, 0));
  if (!F->started) {
    F->started = PETSC_TRUE;
    if (F->ops.start && !F->resumed) PetscCall((*F->ops.start)(F)); /* a checkpoint is past the start already */
  }
  F->reason = CS_WILLMORE_FLOW_ITERATING;
  PetscCall(Evaluate(F));
  PetscCall(StopIfFolded(F));
  /* the guard (and the projection of the state it stops at) before the monitors, so the history, the ParaView
     series and the progress line show the state the flow returns; a NaN state is left to the check below */
  if (!F->reason && F->E == F->E && F->el == F->el) PetscCall(CSWFCheckResolution(F, &F->reason));
  if (F->reason == CS_WILLMORE_FLOW_DIVERGED_MESH_DEGENERATE) PetscCall(ProjectAtStop(F));
  if (!F->reason && F->E == F->E && F->el == F->el) { /* -points_stages: the next stage's targets once this one is done */
    PetscBool moved;
    PetscCall(CSWFPointsContinuationAdvance(F, &moved));
    if (moved) PetscCall(Evaluate(F));
  }
  /* the window and the kept best state before the monitors: a checkpoint written by them stores the window */
  PetscCall(CSWFTrackStationarity(F));
  PetscCall(CSWFTrackBest(F));
  CS_OBJECT_MONITORS_CALL(F, CSWillmoreFlowMonitorFn, F->it);
  /* at the first state no step was taken yet: a smaller t cannot help, the start itself is degenerate */
  PetscCheck(F->E == F->E && F->el == F->el, F->hdr.comm, PETSC_ERR_FP, "flow: the energy or the residual is not a number at iteration %" PetscInt_FMT " (degenerate triangles?); %s%s%s", F->it, F->it == 0 && !F->resumed ? "the start state is degenerate: check the input mesh (or the initial field, -" : "try a smaller -", F->hdr.prefix, F->it == 0 && !F->resumed ? "init*)" : "t");
  /* -rtol tests el_residual_scaled (or el_residual with -el_norm absolute; willmore_stop.c) */
  /* before the last point stage the state meets other targets: it neither converges nor is stationary or drifting */
  if (!F->reason && CSWFPointsFinal(&F->pcont)) {
    if (CSWFStopResidual(F) < F->rtol && PetscMax(F->conf, F->glob) < F->ctol) F->reason = CS_WILLMORE_FLOW_CONVERGED_RTOL;
    if (!F->reason) PetscCall(CSWFCheckStationary(F, &F->reason));
    if (!F->reason) PetscCall(CSWFCheckDrift(F, &F->reason));
  }
  if (!F->reason && F->energy_target_set && F->E <= F->energy_target) {
    PetscCall(PetscPrintf(F->hdr.comm, "flow: the energy %.10g reached -%senergy_target %.10g at iteration %" PetscInt_FMT "\n", (double)F->E, F->hdr.prefix, (double)F->energy_target, F->it));
    F->reason = CS_WILLMORE_FLOW_CONVERGED_ENERGY_TARGET;
  }
  if (!F->reason && F->it >= F->max_it) F->reason = CS_WILLMORE_FLOW_DIVERGED_MAX_IT;
  if (!F->reason && F->max_seconds > 0) { /* a wall-time budget (studies at equal time, runs/study_optimizers.sh) */
    PetscLogDouble now;
    PetscMPIInt    over;
    PetscCall(PetscTime(&now));
    over = (PetscMPIInt)(now - F->t0 >= F->max_seconds);
    PetscCallMPI(MPI_Bcast(&over, 1, MPI_INT, 0, F->hdr.comm)); /* rank 0's clock decides for all: no rank stops alone */
    if (over) F->reason = CS_WILLMORE_FLOW_DIVERGED_MAX_IT;
  }
  if (!F->reason) {
    PetscCall(Operators(F));
    if (F->ops.dual) PetscCall((*F->ops.dual)(F));
    PetscCall(StepWithRejections(F, &accepted));
    if (!accepted && !F->reason) F->reason = CS_WILLMORE_FLOW_DIVERGED_REJECTIONS;
    if (F->reason) F->kspits_total += F->kspits; /* the rejected trials of a last, failed iteration count too */
  }
  if (!F->reason) {
    PetscCall(VecCopy(F->xt, F->x));
    PetscCall((*F->ops.accept)(F));
    F->kspits_total += F->kspits;
    PetscCall((*F->ops.grow)(F));
    F->it++;
  }
  PetscCall(CSWFPointsContinuationReport(F)); /* a stop before the last point stage says so */
  PetscCall(PetscLogEventEnd(CS_EVENT_WillmoreStep, 0, 0, 0, 0));
  *reason = F->reason;
  PetscFunctionReturn(0);
}

/* Whether the stop reason returns the kept best state (-flow_keep_best): guard: the resolution guard's stops (its
   state is not a critical point, and an earlier one in the class was nearer one); all: every stop that did not
   converge. The best replaces the last only if its el_residual_scaled is smaller. */
static PetscBool BestApplies(CSWillmoreFlow F)
{
  PetscBool guard = (PetscBool)(F->reason == CS_WILLMORE_FLOW_DIVERGED_MESH_DEGENERATE || F->reason == CS_WILLMORE_FLOW_DIVERGED_AREA || F->reason == CS_WILLMORE_FLOW_DIVERGED_DRIFT);
  if (F->best_it < 0 || F->reason == CS_WILLMORE_FLOW_ITERATING || CSWillmoreFlowReasonConverged(F->reason)) return PETSC_FALSE;
  if (F->keep_best == CS_FLOW_KEEP_BEST_NONE || (F->keep_best == CS_FLOW_KEEP_BEST_GUARD && !guard)) return PETSC_FALSE;
  return (PetscBool)(F->best_els < F->els);
}

PetscErrorCode CSWillmoreFlowUseBest(CSWillmoreFlow F, PetscBool *used)
{
  PetscFunctionBeginUser;
  *used = PETSC_FALSE;
  if (F->best_used || !BestApplies(F)) PetscFunctionReturn(0);
  F->last_it  = F->it;
  F->last_E   = F->E;
  F->last_els = F->els;
  if (!F->last_x) PetscCall(VecDuplicate(F->x, &F->last_x));
  PetscCall(VecCopy(F->x, F->last_x)); /* nothing computed is lost: the report writes it beside -o */
  PetscCall(VecCopy(F->best_x, F->x));
  if (F->mu) PetscCall(VecCopy(F->best_mu, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] = F->best_nu[j];
  PetscCall(Evaluate(F));
  F->best_used = PETSC_TRUE;
  *used        = PETSC_TRUE;
  PetscCall(PetscPrintf(F->hdr.comm, "flow: -o and the summary hold the best state of the run (-%skeep_best %s): iteration %" PetscInt_FMT ", el_residual_scaled %.3e, W %.10g, violation %.2e; the last state (iteration %" PetscInt_FMT ") had el_residual_scaled %.3e, W %.10g\n", F->hdr.prefix, CSFlowKeepBestTypes[F->keep_best], F->best_it, (double)F->els, (double)F->E, (double)PetscMax(F->conf, F->glob), F->last_it, (double)F->last_els, (double)F->last_E));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowSolve(CSWillmoreFlow F)
{
  CSWillmoreFlowConvergedReason reason = CS_WILLMORE_FLOW_ITERATING;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_WillmoreSolve, 0, 0, 0, 0));
  while (reason == CS_WILLMORE_FLOW_ITERATING) PetscCall(CSWillmoreFlowStep(F, &reason));
  PetscCall(PetscLogEventEnd(CS_EVENT_WillmoreSolve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
