/* The predictive step size of CGD/GD and the triangle-field kind (-flow_step_model predictive, the default;
   docs/willmore_flow.md "The step size model"). The filter (willmore_filter.c) records each trial: the violation v0 of x,
   v(t) of the trial point after its second-order corrections, and the Lagrangian's change. Two models predict t:
     violation:  v(t) = v0 + a t^p  (a, p fitted to the trials at x; p = 1 until two trials measure it)
     Lagrangian: L(tau t) = L0 - s tau + q tau^2, s = <df, H df>/t the slope of the CGD step (its first row),
                 q from the trial's L(t) (Nocedal & Wright Sec. 3.5, the quadratic backtracking interpolation).
   A rejected trial shrinks t to the smaller prediction, within [1/10, 1/2] of t; an accepted step grows t by the
   largest factor in [1, -flow_t_grow] whose predicted next violation stays below 0.8 -vmax (CSWFStepModelGrow),
   restoring x first where none does and the step restores weakly.
   -flow_step_model halving: t halves on rejection and grows by -flow_t_grow on acceptance (the earlier rule). */
#include "willmore_impl.h"

const char *const CSWFStepModels[] = {"predictive", "halving", "CSWFStepModel", "CS_WF_STEP_", NULL};

#define STEP_SHRINK_MIN 0.1 /* a prediction from one trial may be off by the model's exponent: at most 10x less */
#define STEP_SHRINK_MAX 0.5 /* a rejection always shrinks t by 2 at least: t_min is reached in finitely many trials */
#define STEP_ROOM       0.5 /* after a rejection, the target violation: v0 + this * (ceiling - v0) */
#define STEP_ROOM_GROW  0.8 /* after an accepted step: the next violation predicted below this * vmax */
#define STEP_P_MIN      0.25 /* measured p on the bumped torus 0.3-1 (finite t_mu), 2 when the linearised */
#define STEP_P_MAX      2.0  /* constraint is solved: the fits outside these are noise */
#define STEP_P_RUN_MIN  0.05 /* the run's p (from step to step): ~0 early, up to 3 measured */
#define STEP_P_RUN_MAX  4.0
#define STEP_GROW_LADDER 4 /* growth factors t_grow^(k/4), k = 4..1 */
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
  return PetscMin(STEP_P_MAX, PetscLogReal(r->d1 / d) / PetscLogReal(r->t1 / r->t)); /* below STEP_P_MIN: no model */
}

/* the factor on t that brings the violation model of the last trial to v0 + STEP_ROOM (ceiling - v0) at the same x
   (v0next = v0); +inf when the trial did not raise the violation */
static PetscReal ViolationFactor(CSWillmoreFlow F, PetscReal v0next)
{
  const CSWFTrialRecord *r = &F->trial;
  PetscReal              d = r->vt - r->v0, room = PetscMax(v0next, F->vmax) - v0next;
  PetscReal              p = Exponent(r);
  if (!(d > 0)) return PETSC_INFINITY;
  if (!(p >= STEP_P_MIN)) return STEP_SHRINK_MAX; /* v hardly falls with t at this x (a cylinder at its critical point:
                                                    v(1) 1.01e-2, v(1/2) 1.16e-2): t is not the lever, halve */
  if (!(room > 0)) return STEP_SHRINK_MAX; /* x above -vmax: the ceiling is v0 itself and only the step's restoring
                                              can pass it, which this model does not see (the vesicle at 0.67): halve */
  return PetscPowReal(STEP_ROOM * room / d, 1.0 / p);
}

/* The exponent of the added violation's growth before it is measured from step to step: 0 selects the multipliers'
   lag, d f q_f (CSWFStepModelGrow), the default; 1 (d f) where the restoring was not measured (q = 0: no correction
   needed or -soc_max_it 0); and the trials' own exponent at x where a longer trial there raised the violation above
   the lag's prediction for it, q(t1) t1 |X H^-1 r| with q(t1) = 1 / (1 + K t1 / t), K = (1 - q) / q (t_mu is kept
   between the trials): then the violation grows with t for another reason (the step's nonlinearity), as on the
   elephant of Fig. 5 (v 8.2e-3 at t = 1e-3, 4.2e-2 at 1e-2 against the lag's 2.4e-2; the doubled step of the next
   iteration added 1.36 times as much, f^p with the trials' p = 0.71: 1.64), not on the cylinder at its critical point
   (1.07e-2 at 2 t against 1.26e-2; the doubled step added 0.23 times as much). */
static PetscReal UnmeasuredExponent(const CSWFTrialRecord *r)
{
  PetscReal dx = r->vt - r->v0, K, lag;
  if (!(r->q > 0)) return 1.0;
  if (r->n < 2 || !(r->t1 > r->t) || !(dx > 0)) return 0;
  K   = (1 - r->q) / r->q;
  lag = dx * (r->t1 / r->t) * (1 + K) / (1 + K * r->t1 / r->t);
  return r->d1 > lag ? PetscMax(STEP_P_MIN, Exponent(r)) : 0; /* d1 > lag >= dx: Exponent measures */
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

/* The largest f = t_grow^(k/n), k = n..1, whose predicted next violation fits below STEP_ROOM_GROW -vmax (0: none):
   q_f v + added(f), q_f = q / (q + f^2 (1 - q)) the part of x's violation v left by a step of f t and f t_mu (its
   restoring parameter t t_mu grows by f^2), added(f) the part it adds: d f^p with p measured from step to step
   (p > 0), else d f q_f (the added violation's model before p is measured, CSWFStepModelGrow). */
static PetscReal GrowthFactor(CSWillmoreFlow F, PetscReal v, PetscReal d, PetscReal p)
{
  const CSWFTrialRecord *r = &F->trial;
  for (PetscInt k = STEP_GROW_LADDER; k > 0; k--) {
    PetscReal f = PetscPowReal(F->grow, (PetscReal)k / STEP_GROW_LADDER), qf = r->q / (r->q + f * f * (1 - r->q));
    PetscReal added = p > 0 ? d * PetscPowReal(f, p) : d * f * qf;
    if (qf * v + added <= STEP_ROOM_GROW * F->vmax) return f;
  }
  return 0;
}

/* The factor on t after an accepted step (x is the new state): GrowthFactor, at least 1. p is fitted to the last two
   accepted steps, not to trials at one x: t_mu follows t, so the restoring t t_mu s^2 / (lambda_H + t t_mu s^2)
   strengthens with t and the violation a step adds grows more slowly with t from step to step (measured p ~ 0
   while t t_mu is small, 1-3 once it is large) than at one x. Without two such steps (the first step, or t held)
   the added violation is predicted from the restoring itself: a row direction of singular value s is left the part
   q = 1 / (1 + t t_mu s^2 / lambda_H) of what the unrestored step would put there, d = q t |X H^-1 r| (r the EL
   residual g + X^T mu); a step of f t, f t_mu leaves q_f of f t |X H^-1 r'|, and the accepted step's dual update
   mu += dmu has removed the part 1 - q of the force X H^-1 r against the rows, so r' ~ q r there: d f q_f. It was
   d f (p = 1), which on the cylinder of willmore_boundary_normals (at its critical point, mu = 0 at the start: the
   whole violation is the multipliers' lag) predicted 1.4e-2 for f = 1 after the first step (q 0.61, v 8.8e-3): x
   restored and t held for three iterations, 10 iterations to convergence against 8 with the halving rule, which
   doubled t (measured v 7.0e-3; this model predicts 7.5e-3 and doubles too). Where no f fits and
   the step restores weakly (q > STEP_Q_WEAK: the violation piles up from step to step, the rejection storm of the
   bumped torus) x is restored first (willmore_projection.c, to vmax / 100: one or two Gauss-Newton steps), and f chosen
   for the restored x; with a strong restoring the larger next step brings the violation down itself (the
   figure-eight: v 8.6e-3 at t = 1, 4.1e-3 after the step at t = 2). */
PetscErrorCode CSWFStepModelGrow(CSWillmoreFlow F, PetscReal *factor)
{
  const CSWFTrialRecord *r = &F->trial;
  PetscReal              conf, glob, d = r->vt - r->q * r->v0, v, p; /* the violation the step added: v(t) = q v0 + d */
  PetscFunctionBeginUser;
  *factor = F->grow;
  if (F->step_model != CS_WF_STEP_PREDICTIVE || r->it != F->it || r->t != F->t || r->why) PetscFunctionReturn(0);
  p = UnmeasuredExponent(r); /* (p = 0.05 where q > 1/2 cost the bumped torus 3 more rejections, p = 2 everywhere the
                                 cylinder of willmore_boundary_normals 2 more iterations) */
  if (F->step_dacc > 0 && d > 0 && F->t != F->step_tacc) p = PetscMin(STEP_P_RUN_MAX, PetscMax(STEP_P_RUN_MIN, PetscLogReal(d / F->step_dacc) / PetscLogReal(F->t / F->step_tacc)));
  F->step_tacc = F->t;
  F->step_dacc = d;
  if (!(d > 0)) PetscFunctionReturn(0); /* the step lowered the violation: t_grow */
  PetscCall(CSWFEvalConstraints(F, F->x, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
  v       = PetscMax(conf, glob);
  *factor = GrowthFactor(F, v, d, p);
  if (*factor == 0 && r->q > STEP_Q_WEAK && v > 0.1 * F->vmax && F->restore_stalled && !F->restore_failed && !CSWFOwnVariables(F) && (F->conformal || F->k)) {
    PetscInt its = 0;
    PetscCall(CSWFRestoreTo(F, v, 1e-2 * F->vmax, &its)); /* positions only: not a kind with its own variables */
    F->kspits_total += its;
    PetscCall(CSWFEvalConstraints(F, F->x, F->ct, F->cxt, PETSC_FALSE));
    PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
    v       = PetscMax(conf, glob);
    *factor = GrowthFactor(F, v, d, p);
  }
  *factor = PetscMax(1.0, *factor);
  PetscCall(PetscInfo(NULL, "step model: accepted t = %g, v0 %.3e -> %.3e, restoring ratio q %.3f, added %.3e, p %.2f (0: the multipliers' lag), v(x) %.3e: factor %.3f\n", (double)F->t, (double)r->v0, (double)r->vt, (double)r->q, (double)d, (double)p, (double)v, (double)*factor));
  PetscFunctionReturn(0);
}

/* t after an accepted step: times the step model's factor (CSWFStepModelGrow; -t_grow with -step_model halving), capped
   at -t_max (reached also when t_max is not t times a power of t_grow); *r is the factor t changed by (1 at t_max),
   which t_mu follows */
PetscErrorCode CSWFGrowStep(CSWillmoreFlow F, PetscReal *r)
{
  PetscReal f;
  PetscFunctionBeginUser;
  PetscCall(CSWFStepModelGrow(F, &f));
  if (F->t * f <= F->tmax) {
    F->t *= f;
    *r = f;
    PetscFunctionReturn(0);
  }
  *r   = F->t < F->tmax ? F->tmax / F->t : 1.0;
  F->t = F->tmax; /* t_max itself, not t * r, which may round past it */
  PetscFunctionReturn(0);
}

/* t grows by -flow_t_grow up to -flow_t_max after an accepted step, halves after a rejected one (PGD, ALM) */
PetscErrorCode CSWFGrowPrimal(CSWillmoreFlow F)
{
  PetscReal r;
  PetscFunctionBeginUser;
  PetscCall(CSWFGrowStep(F, &r));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFShrinkPrimal(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->t *= 0.5;
  PetscFunctionReturn(0);
}

