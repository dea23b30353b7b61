/* The predictive step size of CGD/GD and the triangle-field kind (-flow_step_model predictive, the default;
   docs/willmore_flow.md "The step size model"). The filter (filter.c) records each trial: the violation v0 of x,
   v(t) of the trial point after its second-order corrections, and the Lagrangian's change. Two models predict t:
     violation:  v(t) = v0 + a t^p  (a, p fitted to the trials at x; p = 1 until two trials measure it)
     Lagrangian: L(tau t) = L0 - s tau + q tau^2, s = <df, H df>/t the slope of the CGD step (its first row),
                 q from the trial's L(t) (Nocedal & Wright Sec. 3.5, the quadratic backtracking interpolation).
   A rejected trial shrinks t to the smaller prediction, within [1/10, 1/2] of t; an accepted one grows t toward
   the t whose predicted violation fills half the room below the ceiling, within [1/10, -flow_t_grow] of t.
   -flow_step_model halving: t halves on rejection and grows by -flow_t_grow on acceptance (the earlier rule). */
#include "willmore_impl.h"

const char *const CSWFStepModels[] = {"predictive", "halving", "CSWFStepModel", "CS_WF_STEP_", NULL};

#define STEP_SHRINK_MIN 0.1 /* a prediction from one trial may be off by the model's exponent: at most 10x less */
#define STEP_SHRINK_MAX 0.5 /* a rejection always shrinks t by 2 at least: t_min is reached in finitely many trials */
#define STEP_ROOM       0.5 /* after a rejection, the target violation: v0 + this * (ceiling - v0) */
#define STEP_ROOM_GROW  0.8 /* after an accepted step: v + this * (vmax - v) */
#define STEP_P_MIN      0.25 /* measured p on the bumped torus 0.3-1 (finite t_mu), 2 when the linearised */
#define STEP_P_MAX      2.0  /* constraint is solved: the fits outside these are noise */
#define STEP_P_RUN_MIN  0.05 /* the run's p (from step to step): ~0 early, up to 3 measured */
#define STEP_P_RUN_MAX  4.0
#define STEP_Q_WEAK     0.5 /* a step leaving more than this part of a violation restores weakly */

/* The filter's measurements of a trial at step t (why: CS_WF_REJECT_* bits of the criteria that rejected it, 0
   when accepted). The trial before it at the same x is kept for the exponent p. */
PetscErrorCode CSWFStepModelRecord(CSWillmoreFlow F, PetscReal v0, PetscReal vt, PetscReal dL, PetscInt why)
{
  CSWFTrialRecord *r = &F->trial;
  PetscFunctionBeginUser;
  if (r->n > 0 && r->it == F->it) {
    r->t1 = r->t;
    r->d1 = r->vt - r->v0;
  } else r->n = 0;
  r->it  = F->it;
  r->n++;
  r->t   = F->t;
  r->v0  = v0;
  r->vt  = vt;
  r->dL  = dL;
  r->why = why;
  r->slope = 0;
  if (why & CS_WF_REJECT_LAGRANGIAN) { /* s = <df, H df>/t = <df, (H/t) df>, H/t the saddle's block of this t */
    PetscScalar s;
    PetscCall(MatMult(F->saddle.H11, F->df, F->tmp));
    PetscCall(VecDot(F->df, F->tmp, &s));
    r->slope = PetscRealPart(s);
  }
  PetscFunctionReturn(0);
}

/* p of v(t) = v0 + a t^p: the secant of the two trials at this x when both raised v, else 1 */
static PetscReal Exponent(const CSWFTrialRecord *r)
{
  PetscReal d = r->vt - r->v0;
  if (r->n < 2 || !(d > 0) || !(r->d1 > 0) || r->t1 == r->t) return 1.0;
  return PetscMin(STEP_P_MAX, PetscMax(STEP_P_MIN, PetscLogReal(r->d1 / d) / PetscLogReal(r->t1 / r->t)));
}

/* the factor on t that brings the violation model of the last trial to v0' + STEP_ROOM (ceiling - v0'), v0' the
   violation the next step starts from; +inf when the trial did not raise the violation */
static PetscReal ViolationFactor(CSWillmoreFlow F, PetscReal v0next)
{
  const CSWFTrialRecord *r = &F->trial;
  PetscReal              d = r->vt - r->v0, room = PetscMax(v0next, F->vmax) - v0next;
  if (!(d > 0)) return PETSC_INFINITY;
  if (!(room > 0)) return 0;
  return PetscPowReal(STEP_ROOM * room / d, 1.0 / Exponent(r));
}

/* The factor on t after a rejected trial: the smaller of the models' predictions for the criteria that rejected
   it, halving for the others (a failed solve, a non-finite or folded trial: no model), within [1/10, 1/2]. */
PetscReal CSWFStepModelShrink(CSWillmoreFlow F)
{
  const CSWFTrialRecord *r = &F->trial;
  PetscReal              f = STEP_SHRINK_MAX;
  if (F->step_model != CS_WF_STEP_PREDICTIVE || r->it != F->it || r->t != F->t || !r->why) return 0.5; /* not this trial's record */
  if (r->why & CS_WF_REJECT_CEILING) f = PetscMin(f, ViolationFactor(F, r->v0));
  if ((r->why & CS_WF_REJECT_LAGRANGIAN) && r->slope > 0) f = PetscMin(f, 0.5 * r->slope / (r->dL + r->slope)); /* argmin of the quadratic */
  if (!(f == f)) f = STEP_SHRINK_MAX;
  return PetscMax(STEP_SHRINK_MIN, PetscMin(STEP_SHRINK_MAX, f));
}

/* The factor on t after an accepted step (x is the new state, after a restoration): toward the t at which the
   run's violation model a t^p predicts the fraction STEP_ROOM_GROW of the room below the ceiling, within
   [1, -flow_t_grow]. p is fitted to the last two accepted steps, not to trials at one x: t_mu follows t, so the
   restoring t t_mu s^2 / (lambda_H + t t_mu s^2) strengthens with t and the violation a step adds grows more
   slowly with t from step to step (measured p ~ 0 while t t_mu is small, 1-3 once it is large) than at one x.
   Without two such steps (the first step, or the last one lowered the violation) p = 2. */
PetscErrorCode CSWFStepModelGrow(CSWillmoreFlow F, PetscReal *factor)
{
  const CSWFTrialRecord *r = &F->trial;
  PetscReal              conf, glob, d = r->vt - r->q * r->v0, room, p; /* the violation the step added: v(t) = q v0 + d */
  PetscFunctionBeginUser;
  *factor = F->grow;
  if (F->step_model != CS_WF_STEP_PREDICTIVE || r->it != F->it || r->t != F->t || r->why) PetscFunctionReturn(0);
  p = 2; /* the quadratic model of a step whose linearised constraint is solved: the slowest growth */
  if (F->step_dacc > 0 && d > 0 && F->t != F->step_tacc) p = PetscMin(STEP_P_RUN_MAX, PetscMax(STEP_P_RUN_MIN, PetscLogReal(d / F->step_dacc) / PetscLogReal(F->t / F->step_tacc)));
  F->step_tacc = F->t;
  F->step_dacc = d;
  if (!(d > 0)) PetscFunctionReturn(0); /* the step lowered the violation: t_grow */
  PetscCall(CSWFEvalConstraints(F, F->x, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
  room    = F->vmax - r->q * PetscMax(conf, glob); /* the next step leaves ~ q of x's violation */
  *factor = room > 0 ? PetscPowReal(STEP_ROOM_GROW * room / d, 1.0 / p) : 1.0;
  if (!(*factor == *factor)) *factor = 1.0;
  *factor = PetscMax(1.0, PetscMin(F->grow, *factor));
  PetscCall(PetscInfo(NULL, "step model: accepted t = %g, v0 %.3e -> %.3e, restoring ratio q %.3f, added %.3e, p %.2f, v(x) %.3e: factor %.3f\n", (double)F->t, (double)r->v0, (double)r->vt, (double)r->q, (double)d, (double)p, (double)PetscMax(conf, glob), (double)*factor));
  PetscFunctionReturn(0);
}

/* After an accepted step, x at violation v: true when the step just taken, taken again from x, would cross the
   ceiling with v above -vmax / 10 (the threshold of a stalled restoration). The step's operator leaves the part q
   of a violation (measured by its first second-order correction, step.c) and adds d = v(t) - q v0, so the same
   step from x ends at q v + d; a weak restoring (q > 1/2: t t_mu s^2 < lambda_H) lets the violation pile up, while
   with a strong one the next, larger step (t and t_mu both grow) restores it (the figure-eight: v 8.6e-3 at t = 1,
   4.1e-3 after the step at t = 2, where a restoration cost 5 solves and the step's progress). x is then
   projected back onto the constraints (projection.c CSWFRestore) instead of t being cut, which would weaken the
   restoring of the next step, t t_mu s^2 / (lambda_H + t t_mu s^2), with t t_mu ~ t^2 once t_mu is capped at
   tmu_ratio_max t. */
PetscBool CSWFStepModelNearCeiling(CSWillmoreFlow F, PetscReal v)
{
  const CSWFTrialRecord *r = &F->trial;
  if (F->step_model != CS_WF_STEP_PREDICTIVE || r->it != F->it || r->t != F->t || r->why) return PETSC_FALSE;
  return (PetscBool)(v > 0.1 * F->vmax && r->q > STEP_Q_WEAK && r->q * v + (r->vt - r->q * r->v0) > F->vmax);
}
