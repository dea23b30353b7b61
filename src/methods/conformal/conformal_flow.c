/* The conformal curvature flow object (crane2013 Sec. 6): options, set-up, the stepping loop and the monitors.
   The step's parts: conformal_direction.c (Table 1 I-IV, Sec. 4's filter, App. E), conformal_integrate.c
   (V-VII: Eq. 5 and 6 through CSSpin). See include/cs_methods_conformal.h. */
#include "conformal_impl.h"
#include "cs_package.h"
#include "cs_log.h"
#include "cs_util.h"

static const CSFlowLoopOps LoopOps; /* the flow's parts for the iteration driver (defined below) */
static PetscErrorCode      DestroyMembers(CSObject); /* the header's destroy op (defined at the end) */
static const char *const ReasonsShifted[]              = {"stalled", "resolution", "energy_growth", "max_it", "iterating", "converged_atol", "converged_rtol"};
const char *const       *CSConformalFlowConvergedReasons = ReasonsShifted + 4;
const char *const        CSConformalCurvatures[]       = {"barycentric", "voronoi", "CSConformalCurvature", "CS_CONFORMAL_CURVATURE_", NULL};
const char *const        CSConformalMobiusSteps[]      = {"newton", "paper", "CSConformalMobiusStep", "CS_CONFORMAL_MOBIUS_", NULL};
const char *const        CSConformalEigensolvers[]      = {"inverse", "eps", "CSConformalEigensolver", "CS_CONFORMAL_EIGEN_", NULL};

CS_OBJECT_DEFINE(CSConformalFlow, CSConformalFlowMonitorFn) /* SetOptionsPrefix, GetOptionsPrefix, MonitorSet, Destroy */

PetscErrorCode CSConformalFlowCreate(CSMesh mesh, CSConformalFlow *flow)
{
  CSConformalFlow F;
  PetscFunctionBeginUser;
  PetscCall(CSInitializePackage());
  PetscCall(CSObjectCreate(sizeof(*F), mesh->comm, "flow_", DestroyMembers, &F));
  PetscCall(CSFlowLoopInit(&F->loop, mesh->comm, &LoopOps, CS_CONFORMAL_DIVERGED_MAX_IT, CS_EVENT_ConformalStep, CS_EVENT_ConformalSolve));
  F->mesh          = mesh;
  F->tau           = 0.95; /* stable for tau < 1 (Sec. 4: |1 - 2 tau| < 1) */
  F->loop.max_it   = 100;
  F->atol          = 0;
  F->rtol          = 1e-6;
  F->egrow         = 1e3;
  F->fk            = 2;
  F->sigma         = 0;
  F->inversion     = PETSC_TRUE;
  F->exactness     = PETSC_TRUE;
  F->mobius_weight = 1;
  F->hfactor       = 2; /* rho' = -2 H: conformal_direction.c */
  F->keep_area     = PETSC_TRUE;
  F->eigensolver   = CS_CONFORMAL_EIGEN_INVERSE;
  F->curvature     = CS_CONFORMAL_CURVATURE_VORONOI; /* exact on inscribed spheres: the round sphere is a fixed point */
  F->bmode         = CS_CONFORMAL_BOUNDARY_NONE;
  F->max_halvings  = 6;
  F->min_edge      = 1e-12; /* edge vectors then carry >= 4 digits: conformal_integrate.c */
  F->frame[2]      = 1; /* V = B: Sec. 6.3.1's choice for CMC surfaces */
  *flow            = F;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowSetTimeStep(CSConformalFlow F, PetscReal tau)
{
  PetscFunctionBeginUser;
  F->tau = tau;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowSetTolerances(CSConformalFlow F, PetscReal atol, PetscReal rtol, PetscInt max_it)
{
  PetscFunctionBeginUser;
  F->atol        = atol;
  F->rtol        = rtol;
  F->loop.max_it = max_it;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowSetFilter(CSConformalFlow F, PetscReal sigma, PetscInt k)
{
  PetscFunctionBeginUser;
  F->sigma = sigma;
  F->fk    = k;
  PetscFunctionReturn(0);
}

/* a clear one-line error naming the option (with the prefix) for every bad value */
static PetscErrorCode CheckOptions(CSConformalFlow F)
{
  const CSOptionCheck checks[] = {
    /* below 1e-14 rho = tau v is rounding noise against D: the step moves nothing (tests take 1e-12 as the identity) */
    {"tau", F->tau, F->tau >= 1e-14 && F->tau <= 1e3, "must lie in [1e-14, 1e3] (the flow is stable for 0 < tau < 1; rho = tau v below 1e-14 is rounding noise)"},
    {"max_it", (PetscReal)F->loop.max_it, F->loop.max_it >= 0, "must be >= 0"},
    {"atol", F->atol, F->atol >= 0, "must be >= 0"},
    {"rtol", F->rtol, F->rtol >= 0, "must be >= 0"},
    {"max_energy_growth", F->egrow, F->egrow > 1, "must be > 1"},
    /* the filter removes the modes with sigma lambda^k < 1: below 1e-12 that is every mode of any mesh, so v = 0 */
    {"filter_sigma", F->sigma, F->sigma == 0 || (F->sigma >= 1e-12 && F->sigma <= 1e12), "must be 0 (no filter) or lie in [1e-12, 1e12] (a smaller sigma removes every mode: no step)"},
    {"filter_k", (PetscReal)F->fk, F->fk >= 0 && F->fk <= 4, "must lie in 0..4"},
    {"curvature_factor", F->hfactor, F->hfactor >= 0 && F->hfactor <= 1e3, "must lie in [0, 1e3] (2: the gradient of |mu|^2; 0: rho = 0, the boundary data alone)"},
    {"mobius_weight", F->mobius_weight, F->mobius_weight >= 0 && F->mobius_weight <= 1e6, "must lie in [0, 1e6]"},
    {"max_seconds", F->loop.max_seconds, F->loop.max_seconds >= 0, "use 0 (no limit) or a positive number of seconds"},
    {"max_nonexact", F->max_nonexact, F->max_nonexact >= 0, "must be >= 0 (0: off)"},
    /* 2^-50 tau is below double precision's resolution of tau: more halvings change nothing */
    {"max_halvings", (PetscReal)F->max_halvings, F->max_halvings >= 0 && F->max_halvings <= 50, "must lie in 0..50 (2^-50 tau moves nothing)"},
    {"min_edge", F->min_edge, F->min_edge >= 0 && F->min_edge < 1, "must lie in [0, 1) (0: off)"},
    /* a nan frame was blamed on a boundary vertex (issue 36, item 17) */
    {"boundary_frame (cN)", F->frame[0], PetscAbsReal(F->frame[0]) <= 1e6, "must lie in [-1e6, 1e6]"},
    {"boundary_frame (cT)", F->frame[1], PetscAbsReal(F->frame[1]) <= 1e6, "must lie in [-1e6, 1e6]"},
    {"boundary_frame (cB)", F->frame[2], PetscAbsReal(F->frame[2]) <= 1e6, "must lie in [-1e6, 1e6]"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(F->hdr.comm, F->hdr.prefix, sizeof(checks) / sizeof(checks[0]), checks));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowSetFromOptions(CSConformalFlow F)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(F->hdr.comm, F->hdr.prefix, "Conformal curvature flow (crane2013 Sec. 6)", NULL);
  PetscCall(CSOptionsReal("-tau", "Time step of rho = tau v, v = -2 H projected (Table 1 V); stable for tau < 1", NULL, F->tau, &F->tau, NULL));
  PetscCall(CSOptionsInt("-max_it", "Maximum number of steps", NULL, F->loop.max_it, &F->loop.max_it, NULL));
  PetscCall(CSOptionsReal("-atol", "Stop when W is at most this (0: off)", NULL, F->atol, &F->atol, NULL));
  PetscCall(CSOptionsReal("-rtol", "Stop when a step changes W by at most this fraction", NULL, F->rtol, &F->rtol, NULL));
  PetscCall(CSOptionsReal("-max_energy_growth", "Stop (diverged) when W exceeds this times the initial W", NULL, F->egrow, &F->egrow, NULL));
  PetscCall(CSOptionsReal("-filter_sigma", "Spectral filter v <- v - (id + sigma A^k)^-1 v (Sec. 4, A = M^-1 L >= 0); sigma in units of (area/4pi)^k, 0: off", NULL, F->sigma, &F->sigma, NULL));
  PetscCall(CSOptionsInt("-filter_k", "Filter order k (0..4)", NULL, F->fk, &F->fk, NULL));
  PetscCall(PetscOptionsBool("-inversion", "Constrain sphere inversions: <<v, N^x,y,z>> = 0 (Sec. 6.2, App. D)", NULL, F->inversion, &F->inversion, NULL));
  PetscCall(PetscOptionsBool("-exactness", "Genus >= 1: constrain <<v, Z_i^x,y,z>> = 0 with D Z_i = v_i for the harmonic vector fields v_i (App. C, C.1)", NULL, F->exactness, &F->exactness, NULL));
  PetscCall(PetscOptionsBool("-exactness_paper", "Exactness functions as App. C.1 writes them (Im Z_i, D Z_i = v_i) instead of the discrete linearisation of the closing condition", NULL, F->exactness_paper, &F->exactness_paper, NULL));
  PetscCall(PetscOptionsBool("-mobius", "Moebius balancing v += w <a, N> toward the input's area distribution (App. E, E.1)", NULL, F->mobius, &F->mobius, NULL));
  PetscCall(CSOptionsEnum("-mobius_step", "Moebius balancing step: newton (the least-squares inversion that removes the balanceable part of the area distortion in one step) or paper (App. E.1's unit direction)", NULL, CSConformalMobiusSteps, (PetscEnum)F->mobius_step, (PetscEnum *)&F->mobius_step, NULL));
  PetscCall(CSOptionsReal("-mobius_weight", "Moebius balancing: the weight w of the unit-norm direction", NULL, F->mobius_weight, &F->mobius_weight, NULL));
  PetscCall(CSOptionsReal("-curvature_factor", "c in rho' = -c H: 2 is the gradient of |mu|^2 (Eq. 1, stable for tau < 1); 1 is the paper's (D + tau H) lambda = gamma lambda; 0: rho = 0, only the boundary data of -flow_boundary vector move the surface (Sec. 6.3.1, Fig. 14 top)", NULL, F->hfactor, &F->hfactor, NULL));
  PetscCall(PetscOptionsBool("-keep_area", "Scale every new surface to the input's area", NULL, F->keep_area, &F->keep_area, NULL));
  {
    PetscInt  nf = 4; /* room for one more than three, to tell a longer list */
    PetscReal fr[4] = {F->frame[0], F->frame[1], F->frame[2], 0};
    PetscBool fset;
    PetscCall(CSOptionsEnum("-boundary", "Boundary condition (Sec. 6.3): none (closed meshes), vector (6.3.1: prescribed directions V~ for V in span{N, T, B}), fixed (6.3.2: prescribed positions)", NULL, CSConformalBoundaries, (PetscEnum)F->bmode, (PetscEnum *)&F->bmode, NULL));
    PetscCall(PetscOptionsRealArray("-boundary_frame", "-boundary vector: V = cN N + cT T + cB B (cN,cT,cB; not +-N)", NULL, fr, &nf, &fset));
    /* a shorter list would be completed silently with the defaults' tail (1 read as 1,0,1), a longer one cut */
    PetscCheck(!fset || nf == 3, F->hdr.comm, PETSC_ERR_ARG_WRONG, "-%sboundary_frame: give exactly three numbers cN,cT,cB (%s given)", F->hdr.prefix, nf > 3 ? "more" : (nf == 2 ? "2" : (nf == 1 ? "1" : "0")));
    for (int c = 0; c < 3; c++) F->frame[c] = fr[c];
    PetscCall(CSOptionsString("-target_mesh", "-boundary vector|fixed: the targets (V~ of this mesh, or its boundary positions; same connectivity)", NULL, F->target, F->target, sizeof(F->target), NULL));
  }
  PetscCall(CSOptionsEnum("-curvature", "Table 1 I: H = (L f).N/(2A) with the barycentric area and area-weighted normal, or with the mixed Voronoi area and the 1-ring sphere-fit normal (exactly constant on inscribed spheres)", NULL, CSConformalCurvatures, (PetscEnum)F->curvature, (PetscEnum *)&F->curvature, NULL));
  PetscCall(CSOptionsReal("-max_seconds", "Stop (as at max_it) once this many seconds have passed since the set-up (0: no limit); rank 0's clock decides", NULL, F->loop.max_seconds, &F->loop.max_seconds, NULL));
  PetscCall(CSOptionsReal("-max_nonexact", "Safeguard (not the paper's): retry a step with tau / 2 while the Poisson step's relative least-squares residual |df~ - conj(lambda) df lambda| / |conj(lambda) df lambda| exceeds this (0: off)", NULL, F->max_nonexact, &F->max_nonexact, NULL));
  PetscCall(CSOptionsReal("-min_edge", "Reject a step (stop with reason resolution, the last good state kept) whose shortest edge is below this times the surface's bounding-box diagonal, or that has a face of zero area (0: off)", NULL, F->min_edge, &F->min_edge, NULL));
  PetscCall(CSOptionsInt("-max_halvings", "-max_nonexact: at most this many halvings of tau per step", NULL, F->max_halvings, &F->max_halvings, NULL));
  PetscCall(CSOptionsEnum("-eigensolver", "Eq. 5: one inverse-iteration step on a factorisation of the current X (Sec. 6.4.2), or SLEPc to convergence (options -spin_eps_*, -spin_st_*)", NULL, CSConformalEigensolvers, (PetscEnum)F->eigensolver, (PetscEnum *)&F->eigensolver, NULL));
  PetscOptionsEnd();
  PetscCall(CheckOptions(F));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckMesh(CSConformalFlow F)
{
  CSMesh m = F->mesh;
  PetscFunctionBeginUser;
  PetscCheck(m->topo.components == 1, m->comm, PETSC_ERR_SUP, "-flow_type conformal: mesh %s has %" PetscInt_FMT " components; the constraints are per surface (one component only)", m->name, m->topo.components);
  if (m->topo.genus > 0 && !F->exactness) PetscCall(PetscPrintf(m->comm, "Warning: conformal flow: mesh %s has genus %" PetscInt_FMT " and -%sexactness false: the surface may fail to close (closing_error in the history)\n", m->name, m->topo.genus, F->hdr.prefix));
  PetscFunctionReturn(0);
}

/* the spin object of Eq. 5 and 6: one inverse-iteration step with a fresh factorisation of the current X by
   default (symbolic analysis kept), -spin_* options still apply */
static PetscErrorCode SetUpSpin(CSConformalFlow F)
{
  DM dm;
  PetscFunctionBeginUser;
  PetscCall(CSSpinCreate(F->mesh, &F->spin));
  PetscCall(CSSpinSetInverseIteration(F->spin, (PetscBool)(F->eigensolver == CS_CONFORMAL_EIGEN_INVERSE), 1));
  PetscCall(CSSpinSetBoundaryType(F->spin, CS_SPIN_BOUNDARY_NONE));
  PetscCall(CSSpinSetFromOptions(F->spin));
  PetscCall(CSSpinGetDM(F->spin, &dm));
  PetscCall(DMCreateGlobalVector(dm, &F->lambda));
  PetscFunctionReturn(0);
}

/* the loop's set-up (CSFlowLoopSetUp times it) */
static PetscErrorCode SetUpFlow(void *ctx)
{
  CSConformalFlow F = (CSConformalFlow)ctx;
  CSMesh          m = F->mesh;
  PetscReal       vol;
  PetscFunctionBeginUser;
  PetscCall(CheckOptions(F)); /* again: the API setters (SetTimeStep, SetFilter, ...) bypass SetFromOptions */
  PetscCall(CheckMesh(F));
  PetscCall(VecDuplicate(m->x, &F->x));
  PetscCall(VecCopy(m->x, F->x));
  PetscCall(VecDuplicate(m->x, &F->x0));
  PetscCall(VecCopy(m->x, F->x0));
  PetscCall(VecDuplicate(m->x, &F->xnew));
  PetscCall(VecDuplicate(m->x, &F->N));
  PetscCall(VecDuplicate(m->x, &F->work3));
  PetscCall(DMCreateGlobalVector(m->dmV1, &F->area));
  {
    Vec *vs[] = {&F->area0, &F->H, &F->v, &F->rho, &F->work};
    for (size_t k = 0; k < sizeof(vs) / sizeof(vs[0]); k++) PetscCall(VecDuplicate(F->area, vs[k]));
  }
  PetscCall(CSGeometryVertexAreas(m, F->x0, F->area0));
  PetscCall(CSGeometryAreaVolume(m, F->x0, &F->area_initial, &vol));
  PetscCall(CSEnergyCreateWillmore(m, &F->will));
  PetscCall(SetUpSpin(F));
  PetscCall(CSConformalFlowBoundarySetUp(F)); /* Sec. 6.3 */
  PetscCall(CSConformalFlowExactnessSetUp(F));
  F->ncmax = 4 + (F->exactness ? 3 * F->ng : 0);
  PetscCall(VecDuplicateVecs(F->area, F->ncmax, &F->c));
  PetscFunctionReturn(0);
}

static PetscErrorCode Monitor(void *ctx, CSFlowEvent ev)
{
  CSConformalFlow F = (CSConformalFlow)ctx;
  PetscFunctionBeginUser;
  F->s.event        = (CSConformalMonitorEvent)ev;
  F->s.it           = F->loop.it;
  F->s.seconds      = F->loop.seconds;
  F->s.step_seconds = F->loop.step_seconds;
  CS_OBJECT_MONITORS_CALL(F, CSConformalFlowMonitorFn, &F->s);
  PetscFunctionReturn(0);
}

/* the flow's convergence tests of a new state (then the loop's -max_it and -max_seconds) */
static PetscErrorCode Judge(void *ctx, PetscInt *reason)
{
  CSConformalFlow         F = (CSConformalFlow)ctx;
  CSConformalMonitorInfo *s = &F->s;
  PetscFunctionBeginUser;
  *reason = CS_CONFORMAL_ITERATING;
  if (F->rejected) *reason = CS_CONFORMAL_DIVERGED_RESOLUTION; /* conformal_integrate.c: the step was not taken */
  else if (F->stalled) *reason = CS_CONFORMAL_DIVERGED_STALLED; /* a step that moved nothing is not convergence */
  else if (!(s->W == s->W) || s->W > F->egrow * F->W0) *reason = CS_CONFORMAL_DIVERGED_ENERGY;
  else if (F->atol > 0 && s->W <= F->atol) *reason = CS_CONFORMAL_CONVERGED_ATOL;
  else if (F->loop.it > 0 && PetscAbsReal(s->W - F->Wprev) <= F->rtol * F->Wprev) *reason = CS_CONFORMAL_CONVERGED_RTOL;
  PetscFunctionReturn(0);
}

/* the input's state (Table 1 I-IV) */
static PetscErrorCode Start(void *ctx)
{
  CSConformalFlow F = (CSConformalFlow)ctx;
  PetscFunctionBeginUser;
  F->s.tau      = F->tau;
  F->s.q_step   = 1;
  F->q_step_max = 1;
  PetscCall(CSConformalFlowEvaluate(F));
  F->W0    = F->s.W;
  F->Wprev = F->s.W;
  PetscFunctionReturn(0);
}

/* Table 1 V-VII */
static PetscErrorCode Advance(void *ctx, PetscBool *taken)
{
  CSConformalFlow F = (CSConformalFlow)ctx;
  PetscFunctionBeginUser;
  F->Wprev = F->s.W;
  PetscCall(CSConformalFlowIntegrate(F));
  *taken = (PetscBool)!F->rejected;
  PetscFunctionReturn(0);
}

/* the new state and the next direction (I-IV) */
static PetscErrorCode Evaluate(void *ctx)
{
  PetscFunctionBeginUser;
  PetscCall(CSConformalFlowEvaluate((CSConformalFlow)ctx));
  PetscFunctionReturn(0);
}

static const CSFlowLoopOps LoopOps = {SetUpFlow, Start, Advance, Evaluate, Judge, Monitor};

CS_FLOW_LOOP_DEFINE(CSConformalFlow) /* SetUp, Step, Solve */

/* the header's destroy op (CSConformalFlowDestroy) */
static PetscErrorCode DestroyMembers(CSObject obj)
{
  CSConformalFlow F = (CSConformalFlow)obj;
  PetscFunctionBeginUser;
  {
    Vec *vs[] = {&F->x, &F->x0, &F->xnew, &F->work3, &F->area0, &F->area, &F->N, &F->H, &F->v, &F->rho, &F->work, &F->lambda};
    for (size_t k = 0; k < sizeof(vs) / sizeof(vs[0]); k++) PetscCall(VecDestroy(vs[k]));
  }
  if (F->c) PetscCall(VecDestroyVecs(F->ncmax, &F->c));
  PetscCall(CSConformalFlowExactnessDestroy(F));
  PetscCall(CSConformalFlowBoundaryDestroy(F));
  PetscCall(CSSpinDestroy(&F->spin));
  PetscCall(CSEnergyDestroy(&F->will));
  PetscCall(MatDestroy(&F->L));
  PetscCall(MatDestroy(&F->B));
  PetscCall(KSPDestroy(&F->kspf));
  PetscFunctionReturn(0);
}
