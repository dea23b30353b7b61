/* Conformal curvature flow of crane2013 (Sec. 4, 6, 6.1, 6.2, App. B, D, E, F, G) as an object on a mesh it is
   given, PETSc style:
     CSConformalFlowCreate(mesh, &flow); CSConformalFlowSetOptionsPrefix(flow, "flow_") (the default);
     CSConformalFlowMonitorSet(...) (src/output/conformal_monitors.c); CSConformalFlowSetFromOptions(flow);
     CSConformalFlowSolve(flow) (or CSConformalFlowSetUp + CSConformalFlowStep until the reason is not ITERATING);
     CSConformalFlowGetConvergedReason; CSConformalFlowGetSolution; CSConformalFlowDestroy.
   The flow works on its own copy of mesh->x; the mesh is not changed. One step is Table 1, right column
   (docs/conformal_flow.md):
     I    H_i = (L f)_i . n_i / (2 A_i), the signed pointwise mean curvature (cotan Laplacian; -flow_curvature
          voronoi: mixed area and 1-ring sphere-fit normal, exact on inscribed spheres; barycentric: barycentric
          area and area-weighted normal);
     II   v = -2 H, the L2 gradient of E_W(mu) = |mu|^2 in curvature space (Eq. 1; the factor: see
          conformal_direction.c); (Sec. 4) optionally the spectral filter v <- v - (id + sigma A^k)^{-1} v;
     III  Gram-Schmidt of {1, N^x, N^y, N^z} in <<a, b>> = sum_i A_i a_i b_i (Sec. 6.2; App. B, D);
          optionally Moebius balancing v += w <a, N> after the inversion constraint (App. E, E.1);
     IV   v <- v - sum_i <<v, c_i>> c_i;
     V    rho = tau v (rho expressed on the current surface, rho^m = 0);
     VI   (D - rho) lambda = gamma lambda (Eq. 5, App. G's per-vertex X) by one inverse-iteration step from
          lambda = 1 with a factorisation of the current X (Sec. 6.4.2; the CSSpin object, KSP prefix
          spin_inverse_), or the full SLEPc eigensolve (-flow_eigensolver eps, prefix spin_);
     VII  the Poisson problem L f~ = div(conj(lambda) e lambda) (Eq. 6; prefix spin_poisson_), translated to the
          old vertex mean and scaled to the input's area (W and Q are scale-invariant).
   Meshes with boundary need a boundary condition of Sec. 6.3 (-flow_boundary vector|fixed). On genus
   >= 1 the exactness constraint (App. C, C.1: conformal_exactness.c with the CSHarmonicBasis of
   cs_operators_dec.h) is on by default (-flow_exactness). */
#ifndef CS_METHODS_CONFORMAL_H
#define CS_METHODS_CONFORMAL_H
#include <petscksp.h>
#include "cs_mesh.h"
#include "cs_object.h"

typedef struct _p_CSConformalFlow *CSConformalFlow;

/* Why the flow stopped; CSConformalFlowConvergedReasons[reason] is the summary's stop_reason. */
typedef enum {
  CS_CONFORMAL_DIVERGED_STALLED    = -4, /* a step moved no vertex beyond rounding (1e-13 of the diameter) while the direction was not zero */
  CS_CONFORMAL_DIVERGED_RESOLUTION = -3, /* a step's shortest edge fell below -min_edge times the diameter: rejected, the last good state kept */
  CS_CONFORMAL_DIVERGED_ENERGY = -2, /* W not finite, or above -max_energy_growth times the initial W */
  CS_CONFORMAL_DIVERGED_MAX_IT = -1,
  CS_CONFORMAL_ITERATING       = 0,
  CS_CONFORMAL_CONVERGED_ATOL  = 1, /* W <= -atol */
  CS_CONFORMAL_CONVERGED_RTOL  = 2  /* |W - W_previous| <= -rtol W */
} CSConformalFlowConvergedReason;
PETSC_EXTERN const char *const *CSConformalFlowConvergedReasons;

typedef enum {
  CS_CONFORMAL_EIGEN_INVERSE, /* one inverse-iteration step per time step (Sec. 6.4.2) */
  CS_CONFORMAL_EIGEN_EPS      /* SLEPc's shift-and-invert Krylov-Schur to convergence */
} CSConformalEigensolver;
PETSC_EXTERN const char *const CSConformalEigensolvers[];

/* Table 1 step I: the discrete pointwise mean curvature */
typedef enum {
  CS_CONFORMAL_CURVATURE_BARYCENTRIC, /* (L f) . N / (2 A): barycentric area, area-weighted normal */
  CS_CONFORMAL_CURVATURE_VORONOI      /* (L f) . n / (2 A_mixed), n the 1-ring sphere fit: exact on inscribed meshes */
} CSConformalCurvature;
PETSC_EXTERN const char *const CSConformalCurvatures[];

/* App. E.1's balancing step: the paper's unit direction, or the least-squares (Gauss-Newton) step */
typedef enum {
  CS_CONFORMAL_MOBIUS_NEWTON,
  CS_CONFORMAL_MOBIUS_PAPER
} CSConformalMobiusStep;
PETSC_EXTERN const char *const CSConformalMobiusSteps[];

/* Boundary conditions (crane2013 Sec. 6.3, conformal_boundary.c) */
typedef enum {
  CS_CONFORMAL_BOUNDARY_NONE,   /* closed meshes only */
  CS_CONFORMAL_BOUNDARY_VECTOR, /* 6.3.1: prescribed directions V~ for V = cN N + cT T + cB B */
  CS_CONFORMAL_BOUNDARY_FIXED   /* 6.3.2: prescribed boundary positions */
} CSConformalBoundary;
PETSC_EXTERN const char *const CSConformalBoundaries[];

typedef enum {
  CS_CONFORMAL_MONITOR_START,
  CS_CONFORMAL_MONITOR_STEP,
  CS_CONFORMAL_MONITOR_END
} CSConformalMonitorEvent;

/* The measures of a state: it = steps taken; W = the cotan Willmore energy (soliman2021 Eq. 28); E_H = sum A_i H_i^2
   (the paper's |mu|^2 with the signed H); gamma = the eigenvalue of the last step; q_mean, q_max against the
   input (crane2011 Sec. 6.1); area; res_total, res_inversion, res_exact = the largest |<<v, c>>| / (|v| |c|) of
   the projected direction against 1, N^x,y,z and the Z_i^x,y,z (App. B, D, C); closing = the last step's closing
   error |harmonic part of conj(lambda) df lambda| / |conj(lambda) df lambda| (genus >= 1, App. C);
   log_area_spread = the area-weighted standard deviation of log(A_i / A_i of the input) (App. E); H_spread = the
   area-weighted std(H) / |mean H| over interior vertices; boundary_error = max |f - f~| / sqrt(area) over the boundary
   vertices (fixed boundary, else 0); vnorm = |v| (the step's direction before tau); tau (the one the last step
   used: smaller than the option after -flow_max_nonexact halvings); nonexact = |df~ - beta|_*1 / |beta|_*1, the part
   of the last step's transformed edges beta the Poisson step could not integrate (its least-squares residual);
   halvings = how often the last step was retried with tau / 2; q_step = q_mean of the last step's own map (the
   previous surface to this one; q_mean compounds these; docs/conformal_flow.md "The bumpy torus: why q_mean grows");
   seconds of the last step and since the start. */
typedef struct {
  CSConformalMonitorEvent event;
  PetscInt                it;
  PetscReal               W, EH, gamma, q_mean, q_max, area, res_total, res_inversion, res_exact, closing, log_area_spread, H_spread, boundary_error, vnorm, tau, nonexact, q_step;
  PetscInt                halvings;
  PetscReal               step_seconds, seconds;
} CSConformalMonitorInfo;
typedef PetscErrorCode (*CSConformalFlowMonitorFn)(CSConformalFlow, const CSConformalMonitorInfo *, void *);

PETSC_EXTERN PetscErrorCode CSConformalFlowCreate(CSMesh mesh, CSConformalFlow *flow);
PETSC_EXTERN PetscErrorCode CSConformalFlowSetFromOptions(CSConformalFlow flow);
/* Defaults in code (before SetFromOptions): tau > 0; atol >= 0 (0: off), rtol >= 0, max_it >= 0; the filter
   (sigma > 0 in units of (area/4pi)^k, k >= 0; sigma = 0 turns it off) */
PETSC_EXTERN PetscErrorCode CSConformalFlowSetTimeStep(CSConformalFlow flow, PetscReal tau);
PETSC_EXTERN PetscErrorCode CSConformalFlowSetTolerances(CSConformalFlow flow, PetscReal atol, PetscReal rtol, PetscInt max_it);
PETSC_EXTERN PetscErrorCode CSConformalFlowSetFilter(CSConformalFlow flow, PetscReal sigma, PetscInt k);
PETSC_EXTERN PetscErrorCode CSConformalFlowSetUp(CSConformalFlow flow);
PETSC_EXTERN PetscErrorCode CSConformalFlowStep(CSConformalFlow flow);
PETSC_EXTERN PetscErrorCode CSConformalFlowSolve(CSConformalFlow flow);
/* CSConformalFlowSetOptionsPrefix, GetOptionsPrefix, MonitorSet (up to 8 monitors, called in the order set; destroy,
   may be NULL, frees ctx at Destroy) and Destroy: the skeleton of every method object (include/cs_object.h) */
CS_OBJECT_DECLARE(CSConformalFlow, CSConformalFlowMonitorFn);
/* Sec. 4's filter on the current surface applied to a dmV1 vector v in place (after SetUp; needs sigma > 0). */
PETSC_EXTERN PetscErrorCode CSConformalFlowApplyFilter(CSConformalFlow flow, Vec v);

PETSC_EXTERN PetscErrorCode CSConformalFlowGetConvergedReason(CSConformalFlow flow, CSConformalFlowConvergedReason *reason);
PETSC_EXTERN PetscErrorCode CSConformalFlowGetSolution(CSConformalFlow flow, Vec *x);        /* positions (borrowed) */
PETSC_EXTERN PetscErrorCode CSConformalFlowGetInitialSolution(CSConformalFlow flow, Vec *x0); /* the input (borrowed) */
PETSC_EXTERN PetscErrorCode CSConformalFlowGetMesh(CSConformalFlow flow, CSMesh *mesh);
/* Per-vertex fields of the current state (dmV1, borrowed): the mean curvature H and the projected direction
   rho_dot = v; per-face Q against the input (dmF1, computed into q). */
PETSC_EXTERN PetscErrorCode CSConformalFlowGetFields(CSConformalFlow flow, Vec *H, Vec *rhodot);
PETSC_EXTERN PetscErrorCode CSConformalFlowGetQuasiConformal(CSConformalFlow flow, Vec q);
/* The current state's measures, the initial W, the stepping time (without SetUp) and the options in use. */
typedef struct {
  CSConformalMonitorInfo state;
  PetscReal              W_initial, tau, filter_sigma, closing_max, q_step_max;
  PetscInt               filter_k;
  PetscBool              inversion, mobius, exactness;
  PetscInt               genus;
  PetscLogDouble         setup_seconds, step_seconds;
} CSConformalFlowInfo;
PETSC_EXTERN PetscErrorCode CSConformalFlowGetInfo(CSConformalFlow flow, CSConformalFlowInfo *info);

#endif
