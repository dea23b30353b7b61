/* Private to src/methods/curve: the CSCurveFlow object (include/cs_methods_curve.h). */
#ifndef CS_CURVE_FLOW_IMPL_H
#define CS_CURVE_FLOW_IMPL_H
#include "cs_methods_curve.h"
#include "cs_curve_geometry.h"
#include "cs_object.h"
#include "cs_flow_loop.h"

struct _p_CSCurveFlow {
  CSObjectHeader hdr; /* comm (the curve's), prefix, monitors (CSCurveFlowMonitorFn) */
  CSCurve        curve;
  /* options */
  PetscReal tau, rtol, sigma, egrow;
  PetscInt  fk;
  PetscBool filter;
  /* geometry of the input: edge lengths l (kept: the flow is isometric), dual lengths d, total length */
  Vec       x, xold, len, d, lwork;
  PetscReal length;
  /* the step: curvature, direction, constraint basis, angles, Poisson right-hand sides and corrections */
  Vec kappa, v, c[3], w, theta, rhs[2], del[2];
  Mat L, Lf; /* L with vertex 0 grounded (Sec. 5.2; see poisson.c); the filter matrix */
  KSP ksp, kspf;
  /* state */
  CSFlowLoop         loop; /* it, reason, -max_it, -max_seconds, the times (src/methods/flow_loop.c) */
  CSCurveMonitorInfo s;
  PetscReal          gap_max, dist_max, E0;
  PetscInt           turning0;
};

/* curve_direction.c: kappa, E, the filtered and projected direction v and the measures of the state */
PETSC_INTERN PetscErrorCode CSCurveFlowEvaluate(CSCurveFlow F);
/* curve_integrate.c: kappa + tau v -> theta -> tangents -> Poisson right-hand sides; the closure gap */
PETSC_INTERN PetscErrorCode CSCurveFlowIntegrate(CSCurveFlow F);
/* curve_poisson.c: L (and the filter matrix) with their KSPs; the Poisson solve and the rigid alignment */
PETSC_INTERN PetscErrorCode CSCurveFlowSetUpPoisson(CSCurveFlow F);
PETSC_INTERN PetscErrorCode CSCurveFlowSetUpFilter(CSCurveFlow F);
PETSC_INTERN PetscErrorCode CSCurveFlowReconstruct(CSCurveFlow F);

#endif
