/* The stopping rule of the flow (docs/willmore_flow.md "Stopping"): the scale-free Euler-Lagrange residual that
   -flow_rtol tests, the stationarity test (reason CONVERGED_STATIONARY) and the kept best state (-flow_keep_best). */
#include "willmore_impl.h"
#include "cs_linalg.h"
#include "cs_util.h"

const char *const CSFlowELNormTypes[]   = {"scaled", "absolute", "CSFlowELNormType", "CS_FLOW_EL_NORM_", NULL};
const char *const CSFlowKeepBestTypes[] = {"none", "guard", "all", "CSFlowKeepBestType", "CS_FLOW_KEEP_BEST_", NULL};

PetscErrorCode CSWFStopOptions(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject)
{
  PetscBool set;
  PetscFunctionBeginUser;
  PetscCall(CSOptionsEnum("-el_norm", "What -rtol tests: the scale-free residual el_residual_scaled = el_residual sqrt(A) / max(|E|, 1e-3 |E_input|) (scaled), or el_residual itself (absolute)", NULL, CSFlowELNormTypes, (PetscEnum)F->el_norm, (PetscEnum *)&F->el_norm, &F->el_norm_set));
  PetscCall(CSOptionsInt("-stationary_window", "Stop as converged (stop_reason stationary) when over this many accepted steps W changed by at most -stationary_rtol (relative) and the vertices moved by at most -stationary_xtol mean edge lengths in total, with the violation below -ctol (0: off)", NULL, F->stat_window, &F->stat_window, NULL));
  PetscCall(CSOptionsReal("-stationary_rtol", "Stationarity: largest relative spread (max - min) / |W| of W over the window", NULL, F->stat_rtol, &F->stat_rtol, NULL));
  PetscCall(CSOptionsInt("-drift_window", "Stop (stop_reason drift, not converged) when over this many accepted steps W changed by at most -drift_wtol (relative, per step) while el_residual_scaled stayed at least -drift_rise times its smallest value of the run for the last -drift_rise_steps steps, the violation below -ctol (0: off)", NULL, F->drift_window, &F->drift_window, NULL));
  PetscCall(CSOptionsReal("-drift_wtol", "Drift: largest relative change of W per step over the window", NULL, F->drift_wtol, &F->drift_wtol, NULL));
  PetscCall(CSOptionsReal("-drift_rise", "Drift: el_residual_scaled at least this many times its smallest value of the run", NULL, F->drift_rise, &F->drift_rise, NULL));
  PetscCall(CSOptionsInt("-drift_rise_steps", "Drift: the residual must have been -drift_rise times its smallest at each of the last this many accepted steps (a sustained rise, not a spike of a converging run; 1: the current step only)", NULL, F->drift_rise_steps, &F->drift_rise_steps, NULL));
  PetscCall(CSOptionsReal("-stationary_xtol", "Stationarity: largest sum over the window of the steps' largest vertex displacements, in mean edge lengths", NULL, F->stat_xtol, &F->stat_xtol, NULL));
  PetscCall(CSOptionsEnum("-keep_best", "Keep the state of smallest el_residual_scaled with the violation <= -ctol, and return it (-o, the summary) at the resolution guard's stops (guard), at every non-converged stop (all), or never (none)", NULL, CSFlowKeepBestTypes, (PetscEnum)F->keep_best, (PetscEnum *)&F->keep_best, &set));
  /* a triangle field's state is more than (x, mu, nu): its continuation and spinor data are not kept */
  PetscCheck(!set || F->keep_best == CS_FLOW_KEEP_BEST_NONE || !CSWFOwnVariables(F), F->hdr.comm, PETSC_ERR_SUP, "-%skeep_best %s: not available for -%stype %s (its spin continuation and spinor state are not kept); use -%skeep_best none", F->hdr.prefix, CSFlowKeepBestTypes[F->keep_best], F->hdr.prefix, F->type, F->hdr.prefix);
  if (CSWFOwnVariables(F)) F->keep_best = CS_FLOW_KEEP_BEST_NONE;
  PetscFunctionReturn(0);
}

/* el_residual_scaled. Under x -> s x, W is invariant, so its gradient g = dW/dx (and the multiplier terms
   X^T mu + sum nu_j row_j, which balance it) scale as s^-1; the residual's norm is the plain 2-norm of the nodal
   vector, whose count of entries does not change, so el_residual ~ s^-1 and el_residual sqrt(A) is invariant.
   For an energy of degree m (E ~ s^m: W m = 0, area m = 2) el_residual ~ s^(m-1), and el_residual sqrt(A) / |E| is
   invariant for every m: the relative first variation of E per unit relative displacement. |E| is floored at
   1e-3 |E(input)| (also homogeneous of degree m) so that a flow whose energy tends to zero (a Willmore patch
   flattening) still has a falling residual. The count of vertices is not scaled away: finer meshes of a shape have
   a smaller el_residual_scaled (docs/willmore_flow.md "Stopping"). */
PetscErrorCode CSWFScaledResidual(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->E0 < 0) {
    PetscReal E0;
    PetscCall(CSEnergyValue(F->energy, F->x0, &E0));
    F->E0 = PetscAbsReal(E0);
  }
  F->els = F->el * PetscSqrtReal(PetscMax(F->A, 0)) / PetscMax(PetscAbsReal(F->E), PetscMax(1e-3 * F->E0, PETSC_SMALL));
  PetscFunctionReturn(0);
}

/* the positions of the current state (a triangle field: its reconstruction) */
static PetscErrorCode Positions(CSWillmoreFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  if (F->ops.positions) PetscCall((*F->ops.positions)(F, PETSC_FALSE, x));
  else *x = F->x;
  PetscFunctionReturn(0);
}

/* max_i |x_i - y_i| / (mean edge length of x) */
static PetscErrorCode Displacement(CSWillmoreFlow F, Vec x, Vec y, PetscReal *d)
{
  PetscReal h, dmax;
  Vec       v, dn;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryMeanEdgeLength(F->mesh, x, &h));
  PetscCall(VecDuplicate(x, &v));
  PetscCall(VecWAXPY(v, -1.0, y, x));
  PetscCall(DMGetGlobalVector(F->mesh->dmV1, &dn));
  PetscCall(CSVecBlockNorms(v, 3, dn));
  PetscCall(VecMax(dn, NULL, &dmax));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmV1, &dn));
  PetscCall(VecDestroy(&v));
  *d = h > 0 ? dmax / h : PETSC_INFINITY;
  PetscFunctionReturn(0);
}

/* After the evaluation at the top of an iteration: W and the largest displacement of the accepted step into the
   window (newest last, at most CS_WF_STAT_MAX steps kept), and the count of accepted steps in a row whose residual is
   at least -drift_rise times the smallest (a new smallest ends the run of risen steps) with the first one's residual.
   A state evaluated again at the same iteration (a resume from a checkpoint, which stores the window and the count)
   is not recorded twice. */
PetscErrorCode CSWFTrackStationarity(CSWillmoreFlow F)
{
  Vec       x;
  PetscReal d = 0;
  PetscFunctionBeginUser;
  if ((!F->stat_window && !F->drift_window) || F->E != F->E) PetscFunctionReturn(0);
  if (F->els == F->els && F->it > 0 && (F->els_min < 0 || F->els < F->els_min)) { /* the input's residual is no reference */
    F->els_min    = F->els;
    F->els_min_it = F->it;
  }
  PetscCall(Positions(F, &x));
  if (!F->stat_x || F->stat_it < 0 || F->it <= F->stat_it) {
    if (!F->stat_x) PetscCall(VecDuplicate(x, &F->stat_x));
    PetscCall(VecCopy(x, F->stat_x));
    if (F->stat_it < 0 || F->it < F->stat_it) { /* the first state: the window starts here */
      F->stat_n      = 0;
      F->stat_W[0]   = F->E;
      F->stat_it     = F->it;
      F->drift_risen = 0;
    }
    PetscFunctionReturn(0);
  }
  PetscCall(Displacement(F, x, F->stat_x, &d));
  PetscCall(VecCopy(x, F->stat_x));
  if (F->stat_n == CS_WF_STAT_MAX) { /* full: drop the oldest */
    for (PetscInt j = 0; j < CS_WF_STAT_MAX; j++) F->stat_W[j] = F->stat_W[j + 1];
    for (PetscInt j = 0; j + 1 < CS_WF_STAT_MAX; j++) F->stat_d[j] = F->stat_d[j + 1];
    F->stat_n--;
  }
  F->stat_d[F->stat_n] = d;
  F->stat_n++;
  F->stat_W[F->stat_n] = F->E;
  F->stat_it           = F->it;
  if (F->els_min > 0 && F->els >= F->drift_rise * F->els_min) {
    if (!F->drift_risen) F->drift_risen_els = F->els;
    F->drift_risen++;
  } else F->drift_risen = 0;
  PetscFunctionReturn(0);
}

/* CONVERGED_STATIONARY: over the last K = -stationary_window accepted steps the spread of W relative to |W| is at
   most -stationary_rtol and the steps' largest vertex displacements sum to at most -stationary_xtol mean edge
   lengths (a bound on every vertex's displacement over the window), with the violation below -ctol: the iteration
   has reached a fixed point, whatever el_residual says. */
PetscErrorCode CSWFCheckStationary(CSWillmoreFlow F, CSWillmoreFlowConvergedReason *reason)
{
  PetscInt  K = F->stat_window, n = F->stat_n;
  PetscReal wmax = -PETSC_MAX_REAL, wmin = PETSC_MAX_REAL, dsum = 0, wrel;
  PetscFunctionBeginUser;
  if (!K || n < K || !(PetscMax(F->conf, F->glob) < F->ctol)) PetscFunctionReturn(0);
  for (PetscInt j = n - K; j <= n; j++) {
    wmax = PetscMax(wmax, F->stat_W[j]);
    wmin = PetscMin(wmin, F->stat_W[j]);
  }
  for (PetscInt j = n - K; j < n; j++) dsum += F->stat_d[j];
  wrel = (wmax - wmin) / PetscMax(PetscAbsReal(F->E), PETSC_SMALL);
  if (!(wrel <= F->stat_rtol && dsum <= F->stat_xtol)) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(F->hdr.comm, "flow: stationary at iteration %" PetscInt_FMT ": over the last %" PetscInt_FMT " steps W changed by %.2e (relative; -%sstationary_rtol %g) and the vertices moved by at most %.2e mean edge lengths (-%sstationary_xtol %g), violation %.2e; el_residual_scaled %.3e (-%srtol %g), t %g\n", F->it, K, (double)wrel, F->hdr.prefix, (double)F->stat_rtol, (double)dsum, F->hdr.prefix, (double)F->stat_xtol, (double)PetscMax(F->conf, F->glob), (double)F->els, F->hdr.prefix, (double)F->rtol, (double)F->t));
  *reason = CS_WILLMORE_FLOW_CONVERGED_STATIONARY;
  PetscFunctionReturn(0);
}

/* The likely cause in the user's words: without the Moebius gauge a closed surface can slide along a Moebius orbit
   (the R/r = 1.8 torus and the genus-2 theta converge once it is fixed, docs/real_meshes.md sections 4-5); with it,
   what is left is a saddle of the discrete energy (the remeshed R/r = 2 torus). */
static const char *DriftCause(CSWillmoreFlow F)
{
  if (F->conformal && !F->mobius && F->mesh->topo.boundary_loops == 0) return "likely a slide along a Moebius orbit, to which the conformal constraint is blind: rerun with -flow_constraint_mobius to fix that gauge";
  return "a saddle of the discrete energy, as on a remeshed torus at R/r = 2";
}

/* DIVERGED_DRIFT: over the last K = -drift_window accepted steps W changed by at most -drift_wtol per step
   (relative) while el_residual_scaled has been at least -drift_rise times its smallest value of the run at each of
   the last -drift_rise_steps accepted steps and is not below its value at the first of them (still rising: a spike
   that decays slowly does not count), inside the class (violation below -ctol). A converging run has a falling
   residual; the step-size limit cycles of a triangle field at t_max 5-8 stay risen for at most 6 steps (measured,
   docs/willmore_flow.md "Drift"); a squeeze or a descent changes W faster. What
   is left is a slide along a direction of nearly constant W away from the nearest critical point: the remeshed
   fat torus's cos 2phi mode, a saddle of the discrete problem whose growth rate shrinks like h^2 (docs/real_meshes.md,
   issue 35). It cannot converge at this mesh, so it stops, and -flow_keep_best returns the smallest residual. */
PetscErrorCode CSWFCheckDrift(CSWillmoreFlow F, CSWillmoreFlowConvergedReason *reason)
{
  PetscInt  K = F->drift_window, n = F->stat_n;
  PetscReal dw = 0;
  PetscFunctionBeginUser;
  if (!K || n < K || F->els_min <= 0 || F->drift_risen < F->drift_rise_steps || !(F->els >= F->drift_risen_els) || !(PetscMax(F->conf, F->glob) < F->ctol)) PetscFunctionReturn(0);
  for (PetscInt j = n - K + 1; j <= n; j++) dw = PetscMax(dw, PetscAbsReal(F->stat_W[j] - F->stat_W[j - 1]) / PetscMax(PetscAbsReal(F->stat_W[j]), PETSC_SMALL));
  if (!(dw <= F->drift_wtol)) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(F->hdr.comm, "flow: drifting at iteration %" PetscInt_FMT ", not converging: over the last %" PetscInt_FMT " steps W changed by at most %.1e per step (relative; -%sdrift_wtol %g) while el_residual_scaled rose to %.3e, %.2f times its smallest value %.3e at iteration %" PetscInt_FMT " and at least -%sdrift_rise %g times it for the last %" PetscInt_FMT " steps (-%sdrift_rise_steps %" PetscInt_FMT "), violation %.2e. The flow slides along a direction of nearly constant W (%s, docs/real_meshes.md)\n", F->it, K, (double)dw, F->hdr.prefix, (double)F->drift_wtol, (double)F->els, (double)(F->els / F->els_min), (double)F->els_min, F->els_min_it, F->hdr.prefix, (double)F->drift_rise, F->drift_risen, F->hdr.prefix, F->drift_rise_steps, (double)PetscMax(F->conf, F->glob), DriftCause(F)));
  *reason = CS_WILLMORE_FLOW_DIVERGED_DRIFT;
  PetscFunctionReturn(0);
}

/* checkpoint scalars of the window: [stat_it, stat_n, W[0..MAX], d[0..MAX], els_min, els_min_it, drift_risen,
   drift_risen_els]. A checkpoint written before the run of risen steps was stored (134 scalars) is refused by its
   count (mesh/checkpoint.c: "N scalars stored, M expected"). */
void CSWFStationaryGetState(CSWillmoreFlow F, PetscReal ck[])
{
  ck[0] = (PetscReal)F->stat_it;
  ck[1] = (PetscReal)F->stat_n;
  for (PetscInt j = 0; j <= CS_WF_STAT_MAX; j++) ck[2 + j] = F->stat_W[j];
  for (PetscInt j = 0; j <= CS_WF_STAT_MAX; j++) ck[3 + CS_WF_STAT_MAX + j] = F->stat_d[j];
  ck[4 + 2 * CS_WF_STAT_MAX] = F->els_min;
  ck[5 + 2 * CS_WF_STAT_MAX] = (PetscReal)F->els_min_it;
  ck[6 + 2 * CS_WF_STAT_MAX] = (PetscReal)F->drift_risen;
  ck[7 + 2 * CS_WF_STAT_MAX] = F->drift_risen_els;
}

void CSWFStationarySetState(CSWillmoreFlow F, const PetscReal ck[])
{
  F->stat_it = (PetscInt)ck[0];
  F->stat_n  = (PetscInt)ck[1];
  for (PetscInt j = 0; j <= CS_WF_STAT_MAX; j++) F->stat_W[j] = ck[2 + j];
  for (PetscInt j = 0; j <= CS_WF_STAT_MAX; j++) F->stat_d[j] = ck[3 + CS_WF_STAT_MAX + j];
  F->els_min         = ck[4 + 2 * CS_WF_STAT_MAX];
  F->els_min_it      = (PetscInt)ck[5 + 2 * CS_WF_STAT_MAX];
  F->drift_risen     = PetscMax((PetscInt)ck[6 + 2 * CS_WF_STAT_MAX], 0);
  F->drift_risen_els = ck[7 + 2 * CS_WF_STAT_MAX];
}

/* -flow_keep_best: the state (x, mu, nu) of smallest el_residual_scaled among the evaluated states with the violation
   at most -ctol, the input excluded. CGD's iterates carry a violation up to -vmax (1e-3 on eight_cgal), so there the
   candidates are mostly the states a restoration or the projection at the stop put into the class; PGD's are all in
   it. Not stored in checkpoints: a resumed run keeps the best of its own iterations (documented). */
PetscErrorCode CSWFTrackBest(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->keep_best == CS_FLOW_KEEP_BEST_NONE || PetscIsInfOrNanReal(F->els) || PetscIsInfOrNanReal(F->E)) PetscFunctionReturn(0);
  if (F->it == 0 && !F->resumed) PetscFunctionReturn(0); /* the input is no candidate: -o writes a state the flow computed */
  if (!CSWFPointsFinal(&F->pcont)) PetscFunctionReturn(0); /* a point stage's state meets other targets */
  if (!(PetscMax(F->conf, F->glob) <= F->ctol) || (F->best_it >= 0 && !(F->els < F->best_els))) PetscFunctionReturn(0);
  if (!F->best_x) PetscCall(VecDuplicate(F->x, &F->best_x));
  PetscCall(VecCopy(F->x, F->best_x));
  if (F->mu) {
    if (!F->best_mu) PetscCall(VecDuplicate(F->mu, &F->best_mu));
    PetscCall(VecCopy(F->mu, F->best_mu));
  }
  if (F->k && !F->best_nu) PetscCall(PetscMalloc1(F->k, &F->best_nu));
  for (PetscInt j = 0; j < F->k; j++) F->best_nu[j] = F->nu[j];
  F->best_it  = F->it;
  F->best_els = F->els;
  F->best_E   = F->E;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFStopDestroy(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&F->stat_x));
  PetscCall(VecDestroy(&F->best_x));
  PetscCall(VecDestroy(&F->best_mu));
  PetscCall(VecDestroy(&F->last_x));
  PetscCall(PetscFree(F->best_nu));
  PetscFunctionReturn(0);
}
