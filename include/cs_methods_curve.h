/* Isometric curvature flow of planar curves (crane2013 Sec. 5, 5.1, 5.2, App. A) as an object on a curve it is
   given, PETSc style:
     CSCurveFlowCreate(curve, &flow); CSCurveFlowSetOptionsPrefix(flow, "curve_") (the default);
     CSCurveFlowMonitorSet(...) (src/output/curve_monitors.c); CSCurveFlowSetFromOptions(flow);
     CSCurveFlowSolve(flow) (or CSCurveFlowSetUp + CSCurveFlowStep until the reason is not ITERATING);
     CSCurveFlowGetConvergedReason; CSCurveFlowGetSolution; CSCurveFlowDestroy.
   The flow works on its own copy of curve->x; the curve is not changed. One step (docs/curve_flow.md):
     kappa_i = phi_i / d_i (turning angle over dual length), v = -2 kappa (Eq. 1), optionally the spectral
     filter v <- v - (id + sigma A^k)^{-1} v (Sec. 4, A = M^{-1} L >= 0), the projection of v onto the
     <.,.>_d-complement of {1, f^x, f^y} by Gram-Schmidt (Sec. 5; closed curves only), kappa <- kappa + tau v
     (Eq. 2), theta by cumulative sums over the ranks (Sec. 5.2, MPI_Exscan), T_ij = l_ij (cos theta_i,
     sin theta_i), the Poisson problem L f = b (KSP prefix "<prefix>poisson_"; L and its factorisation are
     built once: the lengths l are those of the input and never change), then the mean translation and
     rotation of the step removed.
   Options (prefix curve_): -tau (0.95; the flow is stable for tau < 1), -max_it (100), -rtol (1e-9: stop when
   the stationarity |v|_d sqrt(length) / 2pi and the change of the last step both fall below it), -filter (false), -filter_sigma (1, in units of
   (length/2pi)^(2k)), -filter_k (2), -max_energy_growth (1e6: E above this times the initial E diverges),
   -max_seconds (0: no limit; stop as at max_it once this many seconds have passed since the set-up began).
   Open curves (CSCurve with closed = false, -curve_open) flow without the closure constraints. */
#ifndef CS_METHODS_CURVE_H
#define CS_METHODS_CURVE_H
#include <petscksp.h>
#include "cs_curve.h"
#include "cs_object.h"

typedef struct _p_CSCurveFlow *CSCurveFlow;

/* Why the flow stopped; CSCurveFlowConvergedReasons[reason] is the summary's stop_reason. */
typedef enum {
  CS_CURVE_DIVERGED_TURNING = -3, /* the turning number changed: a turning angle passed pi (an unstable tau) */
  CS_CURVE_DIVERGED_ENERGY  = -2, /* E not finite or above -max_energy_growth times the initial E */
  CS_CURVE_DIVERGED_MAX_IT  = -1,
  CS_CURVE_ITERATING        = 0,
  CS_CURVE_CONVERGED_RTOL   = 1 /* stationarity and change below -rtol */
} CSCurveFlowConvergedReason;
PETSC_EXTERN const char *const *CSCurveFlowConvergedReasons;

typedef enum {
  CS_CURVE_MONITOR_START,
  CS_CURVE_MONITOR_STEP,
  CS_CURVE_MONITOR_END
} CSCurveMonitorEvent;

/* The measures of a state (crane2013 Fig. 11): it = steps taken; energy E = |kappa|^2_d; turning = total
   curvature / 2pi; gap = |sum_ij T_ij| / length of the last step's tangents before the Poisson step;
   distortion = max_ij |l~_ij / l_ij - 1| after it (against the input lengths); kappa spread max - min (open
   curves: max |kappa|) and relative to |mean kappa|; stationarity as in -rtol; change = max_i |f_i - f_i^old|
   of the last step over length/2pi; seconds of the last step. */
typedef struct {
  CSCurveMonitorEvent event;
  PetscInt            it;
  PetscReal           energy, turning, gap, distortion, spread, spread_rel, stationarity, change;
  PetscReal           step_seconds, seconds;
} CSCurveMonitorInfo;
typedef PetscErrorCode (*CSCurveFlowMonitorFn)(CSCurveFlow, const CSCurveMonitorInfo *, void *);

PETSC_EXTERN PetscErrorCode CSCurveFlowCreate(CSCurve curve, CSCurveFlow *flow);
PETSC_EXTERN PetscErrorCode CSCurveFlowSetFromOptions(CSCurveFlow flow);
/* The defaults in code (before SetFromOptions, which may override them): tau (> 0); rtol (>= 0) and max_it (>= 0) */
PETSC_EXTERN PetscErrorCode CSCurveFlowSetTimeStep(CSCurveFlow flow, PetscReal tau);
PETSC_EXTERN PetscErrorCode CSCurveFlowSetTolerances(CSCurveFlow flow, PetscReal rtol, PetscInt max_it);
PETSC_EXTERN PetscErrorCode CSCurveFlowSetUp(CSCurveFlow flow);
PETSC_EXTERN PetscErrorCode CSCurveFlowStep(CSCurveFlow flow);
PETSC_EXTERN PetscErrorCode CSCurveFlowSolve(CSCurveFlow flow);
/* CSCurveFlowSetOptionsPrefix, GetOptionsPrefix, MonitorSet (up to 8 monitors, called in the order set; destroy,
   may be NULL, frees ctx at Destroy) and Destroy: the skeleton of every method object (include/cs_object.h) */
CS_OBJECT_DECLARE(CSCurveFlow, CSCurveFlowMonitorFn);

PETSC_EXTERN PetscErrorCode CSCurveFlowGetConvergedReason(CSCurveFlow flow, CSCurveFlowConvergedReason *reason);
PETSC_EXTERN PetscErrorCode CSCurveFlowGetSolution(CSCurveFlow flow, Vec *x);     /* positions, block size 2 (borrowed) */
PETSC_EXTERN PetscErrorCode CSCurveFlowGetCurvature(CSCurveFlow flow, Vec *kappa); /* of the current state (borrowed) */
PETSC_EXTERN PetscErrorCode CSCurveFlowGetCurve(CSCurveFlow flow, CSCurve *curve);
/* The current state's measures (event START), the largest gap and distortion over all steps, the options in
   use, the set-up time (assembly and factorisation of L) and the stepping time. */
typedef struct {
  CSCurveMonitorInfo state;
  PetscReal          gap_max, distortion_max, energy_initial, length, tau;
  PetscInt           turning_initial;
  PetscLogDouble     setup_seconds, step_seconds;
} CSCurveFlowInfo;
PETSC_EXTERN PetscErrorCode CSCurveFlowGetInfo(CSCurveFlow flow, CSCurveFlowInfo *info);

#endif
