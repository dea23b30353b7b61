/* The isometric curve flow object (crane2013 Sec. 5): options, set-up, the stepping loop, monitors and
   getters. The step's parts: curve_direction.c (Eq. 1, the filter, the constraints), curve_integrate.c
   (Eq. 2, Sec. 5.1-5.2 angles and tangents), curve_poisson.c (Sec. 5.2 positions). */
#include "curve_flow_impl.h"
#include "cs_package.h"
#include "cs_log.h"
#include "cs_util.h"

static const CSFlowLoopOps LoopOps; /* the flow's parts for the iteration driver (defined below) */
static PetscErrorCode      DestroyMembers(CSObject); /* the header's destroy op (defined at the end) */
static const char *const ReasonsShifted[]         = {"turning_changed", "energy_growth", "max_it", "iterating", "converged"};
const char *const       *CSCurveFlowConvergedReasons = ReasonsShifted + 3;

CS_OBJECT_DEFINE(CSCurveFlow, CSCurveFlowMonitorFn) /* SetOptionsPrefix, GetOptionsPrefix, MonitorSet, Destroy */

PetscErrorCode CSCurveFlowCreate(CSCurve curve, CSCurveFlow *flow)
{
  CSCurveFlow F;
  PetscFunctionBeginUser;
  PetscCall(CSInitializePackage());
  PetscCall(CSObjectCreate(sizeof(*F), curve->comm, "curve_", DestroyMembers, &F));
  PetscCall(CSFlowLoopInit(&F->loop, curve->comm, &LoopOps, CS_CURVE_DIVERGED_MAX_IT, CS_EVENT_CurveStep, CS_EVENT_CurveSolve));
  F->curve       = curve;
  F->tau         = 0.95; /* the default; stable for tau < 1 (Sec. 5: |1 - 2 tau| < 1) */
  F->loop.max_it = 100;
  F->rtol   = 1e-9;
  F->sigma  = 1;
  F->fk     = 2;
  F->egrow  = 1e6;
  *flow = F;
  PetscFunctionReturn(0);
}

/* a clear one-line error naming the option (with the prefix) for every bad value */
static PetscErrorCode CheckOptions(CSCurveFlow F)
{
  const CSOptionCheck checks[] = {
    {"tau", F->tau, F->tau > 0, "must be > 0"},
    {"max_it", (PetscReal)F->loop.max_it, F->loop.max_it >= 0, "must be >= 0"},
    {"rtol", F->rtol, F->rtol >= 0, "must be >= 0"},
    {"filter_sigma", F->sigma, F->sigma > 0, "must be > 0"},
    {"filter_k", (PetscReal)F->fk, F->fk >= 0 && F->fk <= 4, "must lie in 0..4"},
    {"max_energy_growth", F->egrow, F->egrow > 1, "must be > 1"},
    {"max_seconds", F->loop.max_seconds, F->loop.max_seconds >= 0, "use 0 (no limit) or a positive number of seconds"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(F->hdr.comm, F->hdr.prefix, sizeof(checks) / sizeof(checks[0]), checks));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowSetFromOptions(CSCurveFlow F)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(F->hdr.comm, F->hdr.prefix, "Isometric curve flow (crane2013 Sec. 5)", NULL);
  PetscCall(CSOptionsReal("-tau", "Time step of the forward Euler step kappa <- kappa - 2 tau kappa (Eq. 2); stable for tau < 1", NULL, F->tau, &F->tau, NULL));
  PetscCall(CSOptionsInt("-max_it", "Maximum number of steps", NULL, F->loop.max_it, &F->loop.max_it, NULL));
  PetscCall(CSOptionsReal("-rtol", "Stop when |v|_d sqrt(length)/2pi (v: the constrained direction) and the last step's max |f - f_old| / (length/2pi) are below this", NULL, F->rtol, &F->rtol, NULL));
  PetscCall(PetscOptionsBool("-filter", "Spectral filter v <- v - (id + sigma A^k)^{-1} v of the direction (Sec. 4)", NULL, F->filter, &F->filter, NULL));
  PetscCall(CSOptionsReal("-filter_sigma", "Filter sigma in units of (length/2pi)^(2k)", NULL, F->sigma, &F->sigma, NULL));
  PetscCall(CSOptionsInt("-filter_k", "Filter order k (0..4)", NULL, F->fk, &F->fk, NULL));
  PetscCall(CSOptionsReal("-max_energy_growth", "Stop (diverged) when E exceeds this times the initial E", NULL, F->egrow, &F->egrow, NULL));
  PetscCall(CSOptionsReal("-max_seconds", "Stop (as at max_it) once this many seconds have passed since the set-up (0: no limit); rank 0's clock decides", NULL, F->loop.max_seconds, &F->loop.max_seconds, NULL));
  PetscOptionsEnd();
  PetscCall(CheckOptions(F));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateVecs(CSCurveFlow F)
{
  CSCurve c = F->curve;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(c->x, &F->x));
  PetscCall(VecCopy(c->x, F->x));
  PetscCall(VecDuplicate(c->x, &F->xold));
  PetscCall(VecDuplicate(c->x, &F->w));
  PetscCall(CSCurveCreateScalarVec(c, &F->len));
  {
    Vec *vs[] = {&F->d, &F->lwork, &F->kappa, &F->v, &F->theta};
    for (size_t k = 0; k < sizeof(vs) / sizeof(vs[0]); k++) PetscCall(VecDuplicate(F->len, vs[k]));
  }
  for (int k = 0; k < 3; k++) PetscCall(VecDuplicate(F->len, &F->c[k]));
  for (int k = 0; k < 2; k++) PetscCall(VecDuplicate(F->len, &F->rhs[k]));
  for (int k = 0; k < 2; k++) PetscCall(VecDuplicate(F->len, &F->del[k]));
  PetscFunctionReturn(0);
}

/* the loop's set-up (CSFlowLoopSetUp times it) */
static PetscErrorCode SetUpFlow(void *ctx)
{
  CSCurveFlow F = (CSCurveFlow)ctx;
  PetscScalar L;
  PetscFunctionBeginUser;
  PetscCall(CreateVecs(F));
  PetscCall(CSCurveEdgeLengths(F->curve, F->x, F->len));
  PetscCall(CSCurveDualLengths(F->curve, F->len, F->d));
  PetscCall(VecSum(F->len, &L));
  F->length = PetscRealPart(L);
  PetscCall(CSCurveFlowSetUpPoisson(F));
  if (F->filter) PetscCall(CSCurveFlowSetUpFilter(F));
  PetscFunctionReturn(0);
}

static PetscErrorCode Monitor(void *ctx, CSFlowEvent ev)
{
  CSCurveFlow F = (CSCurveFlow)ctx;
  PetscFunctionBeginUser;
  F->s.event        = (CSCurveMonitorEvent)ev;
  F->s.it           = F->loop.it;
  F->s.seconds      = F->loop.seconds;
  F->s.step_seconds = F->loop.step_seconds;
  CS_OBJECT_MONITORS_CALL(F, CSCurveFlowMonitorFn, &F->s);
  PetscFunctionReturn(0);
}

/* the flow's convergence tests of a new state (then the loop's -max_it and -max_seconds) */
static PetscErrorCode Judge(void *ctx, PetscInt *reason)
{
  CSCurveFlow         F = (CSCurveFlow)ctx;
  CSCurveMonitorInfo *s = &F->s;
  PetscFunctionBeginUser;
  *reason = CS_CURVE_ITERATING;
  if (!(s->energy == s->energy) || s->energy > F->egrow * F->E0) *reason = CS_CURVE_DIVERGED_ENERGY;
  else if (F->curve->closed && PetscAbsReal(s->turning - (PetscReal)F->turning0) > 0.5) *reason = CS_CURVE_DIVERGED_TURNING; /* open: total curvature is free */
  else if (s->stationarity < F->rtol && (F->loop.it == 0 || s->change < F->rtol)) *reason = CS_CURVE_CONVERGED_RTOL;
  PetscFunctionReturn(0);
}

/* the input's state */
static PetscErrorCode Start(void *ctx)
{
  CSCurveFlow F = (CSCurveFlow)ctx;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFlowEvaluate(F));
  F->E0       = F->s.energy;
  F->turning0 = (PetscInt)PetscFloorReal(F->s.turning + 0.5);
  PetscFunctionReturn(0);
}

static PetscErrorCode Advance(void *ctx, PetscBool *taken)
{
  CSCurveFlow F = (CSCurveFlow)ctx;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFlowIntegrate(F));   /* Eq. 2 and Sec. 5.2: theta, tangents, right-hand side, gap */
  PetscCall(CSCurveFlowReconstruct(F)); /* Sec. 5.2: L f = b, minus the mean motion */
  *taken = PETSC_TRUE;                  /* (the curve flow never rejects a step) */
  PetscFunctionReturn(0);
}

/* the new state and the next direction (Eq. 1, Sec. 4, Sec. 5); the largest gap and distortion so far */
static PetscErrorCode Evaluate(void *ctx)
{
  CSCurveFlow F = (CSCurveFlow)ctx;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFlowEvaluate(F));
  F->gap_max  = PetscMax(F->gap_max, F->s.gap);
  F->dist_max = PetscMax(F->dist_max, F->s.distortion);
  PetscFunctionReturn(0);
}

static const CSFlowLoopOps LoopOps = {SetUpFlow, Start, Advance, Evaluate, Judge, Monitor};

CS_FLOW_LOOP_DEFINE(CSCurveFlow) /* SetUp, Step, Solve */

/* the header's destroy op (CSCurveFlowDestroy) */
static PetscErrorCode DestroyMembers(CSObject obj)
{
  CSCurveFlow F = (CSCurveFlow)obj;
  PetscFunctionBeginUser;
  {
    Vec *vs[] = {&F->x, &F->xold, &F->w, &F->len, &F->d, &F->lwork, &F->kappa, &F->v, &F->theta};
    for (size_t k = 0; k < sizeof(vs) / sizeof(vs[0]); k++) PetscCall(VecDestroy(vs[k]));
  }
  for (int k = 0; k < 3; k++) PetscCall(VecDestroy(&F->c[k]));
  for (int k = 0; k < 2; k++) PetscCall(VecDestroy(&F->rhs[k]));
  for (int k = 0; k < 2; k++) PetscCall(VecDestroy(&F->del[k]));
  PetscCall(MatDestroy(&F->L));
  PetscCall(MatDestroy(&F->Lf));
  PetscCall(KSPDestroy(&F->ksp));
  PetscCall(KSPDestroy(&F->kspf));
  PetscFunctionReturn(0);
}
