/* Private to src/methods/conformal: the CSConformalFlow object (include/cs_methods_conformal.h). */
#ifndef CS_CONFORMAL_IMPL_H
#define CS_CONFORMAL_IMPL_H
#include "cs_methods_conformal.h"
#include "cs_methods_spin.h"
#include "cs_energy.h"
#include "cs_object.h"
#include "cs_flow_loop.h"
#include "cs_operators_dec.h"


struct _p_CSConformalFlow {
  CSObjectHeader hdr; /* comm (the mesh's), prefix, monitors (CSConformalFlowMonitorFn) */
  CSMesh         mesh;
  /* options */
  PetscReal              tau, atol, rtol, egrow, sigma, mobius_weight, hfactor;
  PetscInt               fk;
  PetscBool              inversion, mobius, keep_area, exactness, exactness_paper;
  CSConformalEigensolver eigensolver;
  CSConformalCurvature   curvature;   /* Table 1 I */
  CSConformalMobiusStep  mobius_step; /* App. E.1 */
  CSConformalBoundary    bmode;       /* Sec. 6.3 (conformal_boundary.c) */
  PetscReal              frame[3];    /* V = frame[0] N + frame[1] T + frame[2] B */
  char                   target[PETSC_MAX_PATH_LEN];
  PetscReal              max_nonexact; /* > 0: retry a step with tau / 2 while its non-exact residual exceeds this */
  PetscInt               max_halvings;
  PetscReal              min_edge;     /* reject a step whose shortest edge is below min_edge times the diameter */
  PetscBool              rejected;     /* the last step was rejected (conformal_integrate.c) */
  PetscBool              stalled;      /* the last step moved no vertex beyond rounding though v was not zero */
  PetscReal              edge_ratio;   /* the new surface's shortest edge / its bounding-box diagonal */
  /* state: positions (current, input, next), per-vertex areas of the input, the step's fields */
  Vec       x, x0, xnew, area0;
  Vec       area, N, H, v, rho, work, lambda, work3; /* work3: like x */
  Vec      *c;             /* the constraint functions {1, N^x,y,z, Z_i^x,y,z}, orthonormalised */
  PetscInt  nc, ncmax;     /* functions in c (after dropping dependent ones), allocated */
  PetscInt  nbefore;       /* c[0..nbefore) are 1 and N (the Moebius step goes after them) */
  /* exactness (App. C, C.1; conformal_exactness.c): the harmonic basis of the current surface, Z_i from X Z_i = D^* v_i */
  CSHarmonicBasis hb;
  PetscInt        ng;      /* 2g */
  Vec            *Z, zr, zt, zb, M4, MF;
  Mat             X0, Xs, Dface;
  KSP             kz;
  Vec       xt, bflag;     /* boundary: target positions (or NULL), 1 on boundary vertices */
  Mat       Ld;            /* fixed boundary: the Dirichlet Laplacian */
  KSP       kd;
  CSSpin    spin;          /* Eq. 5 and 6: the Dirac eigenproblem and the Poisson problem */
  CSEnergy  will;          /* W of soliman2021 Eq. 28 */
  Mat       L, B;          /* the filter: L on the current surface, B = M + s L (M^-1 L)^(k-1) */
  KSP       kspf;
  PetscReal area_initial;
  /* progress */
  CSFlowLoop             loop; /* it, reason, -max_it, -max_seconds, the times (src/methods/flow_loop.c) */
  CSConformalMonitorInfo s;
  PetscReal              W0, Wprev, closing_max, q_step_max;
};

/* conformal_direction.c: H, W, the filtered and projected direction v and the measures of the state */
PETSC_INTERN PetscErrorCode CSConformalFlowEvaluate(CSConformalFlow F);
/* conformal_exactness.c: set-up (genus >= 1), the functions Z_i^x,y,z of the current surface appended to c (from
   c[nc]), and the closing error |harmonic part of conj(lambda) df lambda| / |conj(lambda) df lambda| (*1 norms) */
PETSC_INTERN PetscErrorCode CSConformalFlowExactnessSetUp(CSConformalFlow F);
PETSC_INTERN PetscErrorCode CSConformalFlowExactnessFunctions(CSConformalFlow F, PetscInt *n);
PETSC_INTERN PetscErrorCode CSConformalFlowClosingError(CSConformalFlow F, PetscReal *err);
PETSC_INTERN PetscErrorCode CSConformalFlowExactnessDestroy(CSConformalFlow F);
/* conformal_boundary.c: Sec. 6.3 */
PETSC_INTERN PetscErrorCode CSConformalFlowBoundarySetUp(CSConformalFlow F);
PETSC_INTERN PetscErrorCode CSConformalFlowBoundaryPrepare(CSConformalFlow F);
PETSC_INTERN PetscErrorCode CSConformalFlowBoundaryCurvature(CSConformalFlow F);
PETSC_INTERN PetscErrorCode CSConformalFlowReconstructFixed(CSConformalFlow F);
PETSC_INTERN PetscErrorCode CSConformalFlowBoundaryMeasures(CSConformalFlow F);
PETSC_INTERN PetscErrorCode CSConformalFlowBoundaryDestroy(CSConformalFlow F);
/* conformal_nonexact.c: the Poisson step's relative least-squares residual |df~ - beta|_*1 / |beta|_*1 */
PETSC_INTERN PetscErrorCode CSConformalFlowNonExactResidual(CSConformalFlow F, Vec xnew, PetscReal *eta);
/* conformal_integrate.c: rho = tau v, the eigenproblem, the Poisson problem, x <- the new positions */
PETSC_INTERN PetscErrorCode CSConformalFlowIntegrate(CSConformalFlow F);

#endif
