/* The Bobenko-Schroeder Willmore flow object (bobenko-schroeder2005 Sec. 4): options, set-up, the stepping
   loop and the monitors; the schemes are in bs_semi.c and bs_tao.c. See include/cs_methods_bs.h. */
#include "bs_flow_impl.h"
#include "cs_package.h"
#include "cs_log.h"
#include "cs_util.h"

static const CSFlowLoopOps LoopOps; /* the flow's parts for the iteration driver (defined below) */

const char *const CSBSSchemes[]  = {"semi", "tao", "CSBSScheme", "CS_BS_SCHEME_", NULL};
const char *const CSBSProblems[] = {"static", "euler", "CSBSProblem", "CS_BS_PROBLEM_", NULL};
const char *const CSBSIslandsTypes[] = {"vertex", "face", "CSBSIslandsType", "CS_BS_ISLANDS_", NULL};
static const char *const ReasonsShifted[] = {"stalled", "diverged", "not_converged", "rejections", "max_it", "iterating", "converged", "energy_target"};
const char *const       *CSBSConvergedReasons = ReasonsShifted + 5;

CS_OBJECT_DEFINE(CSBSFlow, CSBSFlowMonitorFn) /* SetOptionsPrefix, GetOptionsPrefix, MonitorSet, Destroy */

/* the header's destroy op (CSBSFlowDestroy) */
static PetscErrorCode DestroyMembers(CSObject obj)
{
  CSBSFlow F = (CSBSFlow)obj;
  PetscFunctionBeginUser;
  if (F->ops) PetscCall(F->ops->destroy(F));
  PetscCall(VecDestroy(&F->x));
  PetscCall(VecDestroy(&F->x0));
  PetscCall(VecDestroy(&F->area0));
  PetscCall(VecDestroy(&F->areat));
  PetscCall(CSEnergyDestroy(&F->bs));
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowCreate(CSMesh mesh, CSBSFlow *flow)
{
  CSBSFlow F;
  PetscFunctionBeginUser;
  PetscCall(CSInitializePackage()); /* as KSPCreate does: events, PCs and solver types before any use */
  PetscCall(CSObjectCreate(sizeof(*F), mesh->comm, "bs_", DestroyMembers, &F));
  PetscCall(CSFlowLoopInit(&F->loop, mesh->comm, &LoopOps, CS_BS_DIVERGED_MAX_IT, CS_EVENT_BSStep, CS_EVENT_BSSolve));
  F->loop.own_rejection_limit = PETSC_TRUE; /* semi: -bs_max_rejections in a row and -bs_dt_min_rel */
  F->mesh       = mesh;
  F->scheme     = CS_BS_SCHEME_SEMI;
  F->problem    = CS_BS_PROBLEM_STATIC;
  F->bc         = CS_BS_BOUNDARY_FIXED;
  F->beta_eps   = 1e-6; /* the paper's value (Sec. 3.2) */
  F->dt_rel     = 1;
  F->dt_grow    = 2;
  F->atol       = 1e-8;
  F->rtol       = 1e-9;
  F->loop.max_it = 100;
  F->max_rej    = 30;
  F->monotone   = PETSC_TRUE;
  F->dt_min_rel = 1e-6;
  F->max_area_ratio = 200; /* as the Willmore flow's resolution guard */
  *flow = F;
  PetscFunctionReturn(0);
}

/* A clear one-line error naming the option (with the prefix) for every bad value. */
static PetscErrorCode CheckOptions(CSBSFlow F)
{
  MPI_Comm            comm     = F->mesh->comm;
  const char         *p        = F->hdr.prefix;
  const CSOptionCheck checks[] = {
    {"dt", F->dt_opt, !F->dt_set || F->dt_opt > 0, "must be > 0"},
    {"dt_rel", F->dt_rel, F->dt_rel > 0, "must be > 0"},
    {"dt_grow", F->dt_grow, F->dt_grow >= 1, "must be >= 1"},
    {"dt_max", F->dt_max_opt, F->dt_max_opt >= 0, "must be >= 0 (0: the default)"},
    {"atol", F->atol, F->atol >= 0, "must be >= 0"},
    {"rtol", F->rtol, F->rtol >= 0, "must be >= 0"},
    {"beta_eps", F->beta_eps, F->beta_eps >= 0 && F->beta_eps < 1, "must lie in [0, 1)"},
    {"perturb", F->perturb, F->perturb >= 0 && F->perturb < 1, "must lie in [0, 1)"},
    {"max_it", (PetscReal)F->loop.max_it, F->loop.max_it >= 0, "must be >= 0"},
    {"max_rejections", (PetscReal)F->max_rej, F->max_rej >= 0, "must be >= 0"},
    {"dt_min_rel", F->dt_min_rel, F->dt_min_rel >= 0 && F->dt_min_rel < 1, "must lie in [0, 1)"},
    {"max_area_ratio", F->max_area_ratio, F->max_area_ratio == 0 || F->max_area_ratio > 1, "use 0 (off) or a ratio above 1"},
    {"energy_target", F->energy_target, !PetscIsInfOrNanReal(F->energy_target), "must be finite"},
    {"hessian_eps", F->hessian_eps, !F->hessian_eps_set || (F->hessian_eps >= F->beta_eps && F->hessian_eps < 1), "must lie in [beta_eps, 1)"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(comm, p, sizeof(checks) / sizeof(checks[0]), checks));
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowSetFromOptions(CSBSFlow F)
{
  PetscFunctionBeginUser;
  PetscOptionsBegin(F->mesh->comm, F->hdr.prefix, "Bobenko-Schroeder Willmore flow (bobenko-schroeder2005)", NULL);
  PetscCall(CSOptionsEnum("-scheme", "semi: semi-implicit (1/dt I + K) dx = -grad W; tao: TAO (static problem or backward Euler)", "CSBSFlowSetFromOptions", CSBSSchemes, (PetscEnum)F->scheme, (PetscEnum *)&F->scheme, NULL));
  PetscCall(CSOptionsEnum("-boundary", "fixed: G1, boundary and one-ring fixed; free: vertex at infinity (Sec. 3.3)", "CSBSFlowSetFromOptions", CSBSBoundaries, (PetscEnum)F->bc, (PetscEnum *)&F->bc, NULL));
  PetscCall(CSOptionsReal("-beta_eps", "Diamonds with |sin beta| below this contribute no gradient (Sec. 3.2)", NULL, F->beta_eps, &F->beta_eps, NULL));
  PetscCall(CSOptionsInt("-max_it", "Maximum number of accepted steps (TAO static: iterations)", NULL, F->loop.max_it, &F->loop.max_it, NULL));
  PetscCall(CSOptionsReal("-dt", "Initial time step (units length^2); default -dt_rel times the squared mean edge length", NULL, F->dt_opt, &F->dt_opt, &F->dt_set));
  PetscCall(CSOptionsReal("-dt_rel", "Initial time step relative to the squared mean edge length", NULL, F->dt_rel, &F->dt_rel, NULL));
  PetscCall(CSOptionsReal("-dt_grow", "Factor on dt after an accepted step", NULL, F->dt_grow, &F->dt_grow, NULL));
  PetscCall(CSOptionsReal("-dt_max", "Largest dt (default 1e4 times the initial dt)", NULL, F->dt_max_opt, &F->dt_max_opt, NULL));
  PetscCall(CSOptionsInt("-max_rejections", "semi: consecutive rejected steps (each divides dt by 4) before giving up", NULL, F->max_rej, &F->max_rej, NULL));
  PetscCall(CSOptionsReal("-atol", "Stop when W is below this", NULL, F->atol, &F->atol, NULL));
  PetscCall(CSOptionsReal("-rtol", "Stop when a step decreases W by less than this fraction", NULL, F->rtol, &F->rtol, NULL));
  PetscCall(CSOptionsEnum("-problem", "tao: static minimises W in one TaoSolve; euler: backward Euler steps through TAO", "CSBSFlowSetFromOptions", CSBSProblems, (PetscEnum)F->problem, (PetscEnum *)&F->problem, NULL));
  PetscCall(CSOptionsReal("-hessian_eps", "Leave diamonds with sin beta below this out of K (default -beta_eps)", NULL, F->hessian_eps, &F->hessian_eps, &F->hessian_eps_set));
  PetscCall(CSOptionsReal("-perturb", "Move the free vertices randomly by this fraction of the mean edge length before flowing (breaks co-circular diamonds, beta = 0, of grid-like meshes)", NULL, F->perturb, &F->perturb, NULL));
  PetscCall(CSOptionsReal("-dt_min_rel", "semi: stop as stalled when dt falls below this times the initial dt", NULL, F->dt_min_rel, &F->dt_min_rel, NULL));
  PetscCall(CSOptionsReal("-max_area_ratio", "semi: stop with the last good state when the total area, or max(A/A0)/min(A/A0) of the vertex areas, exceeds this (0: off)", NULL, F->max_area_ratio, &F->max_area_ratio, NULL));
  PetscCall(CSOptionsReal("-energy_target", "semi: stop when W is at or below this (stop_reason energy_target)", NULL, F->energy_target, &F->energy_target, &F->energy_target_set));
  PetscCall(CSOptionsString("-islands", "File of 0-based vertex (or face) indices in file order held fixed with their one-ring (Sec. 3.3, islands)", NULL, F->islands, F->islands, sizeof(F->islands), NULL));
  PetscCall(CSOptionsEnum("-islands_type", "What -islands lists", "CSBSFlowSetFromOptions", CSBSIslandsTypes, (PetscEnum)F->islands_type, (PetscEnum *)&F->islands_type, NULL));
  PetscCall(CSOptionsEnum("-singular", "Vanishing beta (Sec. 3.2): heuristic (its gradient set to 0), single (the paper's steepest descent where one beta at a vertex vanishes) or delta (the paper's delta minimisation, any number)", "CSBSFlowSetFromOptions", CSBSSingularRules, (PetscEnum)F->singular, (PetscEnum *)&F->singular, NULL));
  PetscCall(PetscOptionsBool("-monotone", "semi: reject steps that increase W (false: accept them, as needed when many diamonds start at beta = 0)", NULL, F->monotone, &F->monotone, NULL));
  PetscOptionsEnd();
  PetscCall(CheckOptions(F));
  PetscFunctionReturn(0);
}

/* x <- x with every fixed vertex set back to x0 (keeps G1 data bit-identical, Sec. 3.3). */
PetscErrorCode CSBSFlowResetFixed(CSBSFlow F, Vec x)
{
  CSMesh             m = F->mesh;
  PetscScalar       *a;
  const PetscScalar *a0;
  PetscInt           n = 0;
  PetscFunctionBeginUser;
  if (!F->nfixed) PetscFunctionReturn(0);
  PetscCall(VecGetArray(x, &a));
  PetscCall(VecGetArrayRead(F->x0, &a0));
  for (PetscInt v = 0; v < m->nv; v++) {
    if (!m->vertOwned[v]) continue;
    if (F->fixed[v])
      for (int d = 0; d < 3; d++) a[3 * n + d] = a0[3 * n + d];
    n++;
  }
  PetscCall(VecRestoreArrayRead(F->x0, &a0));
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(0);
}

/* -bs_perturb: fixed vertices are reset to x0, so G1 data stay untouched; seeded, so runs repeat. */
static PetscErrorCode Perturb(CSBSFlow F)
{
  PetscRandom rnd;
  Vec         d;
  PetscFunctionBeginUser;
  PetscCall(PetscRandomCreate(F->mesh->comm, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -F->perturb * F->h, F->perturb * F->h));
  PetscCall(PetscRandomSetSeed(rnd, 20050705));
  PetscCall(PetscRandomSeed(rnd));
  PetscCall(VecDuplicate(F->x, &d));
  PetscCall(VecSetRandom(d, rnd));
  PetscCall(VecAXPY(F->x, 1, d));
  PetscCall(CSBSFlowResetFixed(F, F->x));
  PetscCall(VecDestroy(&d));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscFunctionReturn(0);
}

/* Sec. 3.3: "one can fix some islands of internal vertices (or faces)", held like the boundary strip (the G1
   data of the islands: the masked vertices and their one-ring) */
static PetscErrorCode SetIslands(CSBSFlow F)
{
  Vec  m;
  char opt[128];
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sislands", F->hdr.prefix ? F->hdr.prefix : ""));
  PetscCheck(F->bc == CS_BS_BOUNDARY_FIXED, F->mesh->comm, PETSC_ERR_ARG_INCOMP, "%s needs -%sboundary fixed (islands are G1 data, Sec. 3.3)", opt, F->hdr.prefix ? F->hdr.prefix : "");
  PetscCall(DMCreateGlobalVector(F->mesh->dmV1, &m));
  PetscCall(CSMeshReadIndexMask(F->mesh, opt, F->islands, (PetscBool)(F->islands_type == CS_BS_ISLANDS_FACE), m));
  PetscCall(CSEnergyWillmoreBSSetIslands(F->bs, m));
  PetscCall(VecDestroy(&m));
  PetscFunctionReturn(0);
}

/* the loop's set-up (CSFlowLoopSetUp times it) */
static PetscErrorCode SetUpFlow(void *ctx)
{
  CSBSFlow F    = (CSBSFlow)ctx;
  CSMesh   mesh = F->mesh;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateWillmoreBS(mesh, F->bc, F->beta_eps, &F->bs));
  if (F->hessian_eps_set) PetscCall(CSEnergyWillmoreBSSetHessianEps(F->bs, F->hessian_eps));
  if (F->islands[0]) PetscCall(SetIslands(F));
  PetscCall(CSEnergyWillmoreBSSetSingularRule(F->bs, F->singular));
  PetscCall(CSEnergyWillmoreBSGetFixed(F->bs, &F->fixed, &F->nfixed));
  PetscCall(VecDuplicate(mesh->x, &F->x0));
  PetscCall(VecCopy(mesh->x, F->x0));
  PetscCall(VecDuplicate(mesh->x, &F->x));
  PetscCall(VecCopy(mesh->x, F->x));
  F->xmon = F->x;
  PetscCall(CSGeometryMeanEdgeLength(mesh, F->x, &F->h));
  if (F->perturb > 0) PetscCall(Perturb(F));
  F->dt     = F->dt_set ? F->dt_opt : F->dt_rel * F->h * F->h;
  F->dt_max = F->dt_max_opt == 0 ? 1e4 * F->dt : F->dt_max_opt;
  F->dt0    = F->dt;
  F->dt_min = F->dt_min_rel * F->dt;
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &F->area0));
  PetscCall(VecDuplicate(F->area0, &F->areat));
  PetscCall(CSGeometryVertexAreas(mesh, F->x0, F->area0));
  PetscCall(PetscPrintf(mesh->comm, "bs flow: scheme %s, boundary %s (%" PetscInt_FMT " fixed vertices), beta_eps %g, dt0 %.3e (mean edge %.3e)\n", CSBSSchemes[F->scheme], CSBSBoundaries[F->bc], F->nfixed, (double)F->beta_eps, (double)F->dt, (double)F->h));
  F->ops = F->scheme == CS_BS_SCHEME_SEMI ? &CSBSSchemeSemi : &CSBSSchemeTao;
  PetscCall(F->ops->setup(F));
  F->loop.max_it_reason = F->ops->max_it_reason; /* (the TAO set-up may switch to the static problem) */
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowCheckGuard(CSBSFlow F, Vec x, PetscBool *ok)
{
  PetscScalar a, a0;
  PetscReal   amax, amin, ratio, spread, lim = F->max_area_ratio, V = 1, V0 = 1;
  PetscFunctionBeginUser;
  *ok = PETSC_TRUE;
  if (!(lim > 0)) PetscFunctionReturn(0);
  if (F->mesh->topo.boundary_loops == 0) { /* a closed surface turned inside out, or through itself */
    PetscCall(CSGeometryAreaVolume(F->mesh, x, NULL, &V));
    PetscCall(CSGeometryAreaVolume(F->mesh, F->x0, NULL, &V0));
  }
  PetscCall(CSGeometryVertexAreas(F->mesh, x, F->areat));
  PetscCall(VecSum(F->areat, &a));
  PetscCall(VecSum(F->area0, &a0));
  ratio = PetscRealPart(a) / PetscRealPart(a0);
  PetscCall(VecPointwiseDivide(F->areat, F->areat, F->area0));
  PetscCall(VecMax(F->areat, NULL, &amax));
  PetscCall(VecMin(F->areat, NULL, &amin));
  spread = amin > 0 ? amax / amin : PETSC_INFINITY;
  *ok    = (PetscBool)(ratio < lim && ratio > 1 / lim && spread <= lim && V * V0 > 0);
  if (!*ok) PetscCall(PetscPrintf(F->mesh->comm, "bs flow: the flow diverges at step %" PetscInt_FMT ": the total area would be %g times the input's, the vertex areas relative to the input spread by %g (-%smax_area_ratio %g), the enclosed volume %g (input %g); stopping with the last good state\n", F->it + 1, (double)ratio, (double)spread, F->hdr.prefix, (double)lim, (double)V, (double)V0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowMonitor(CSBSFlow F, CSBSMonitorInfo *info)
{
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  info->row     = F->row;
  info->resumed = (PetscBool)(info->event == CS_BS_MONITOR_START && F->resumed);
  info->seconds = (PetscReal)(now - F->loop.t0);
  CS_OBJECT_MONITORS_CALL(F, CSBSFlowMonitorFn, info);
  if (info->event == CS_BS_MONITOR_STEP || (info->event == CS_BS_MONITOR_START && !F->resumed)) F->row++;
  PetscFunctionReturn(0);
}

/* the input's state (or the checkpoint's): the scheme's start, which monitors it */
static PetscErrorCode Start(void *ctx)
{
  CSBSFlow F = (CSBSFlow)ctx;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&F->tstart));
  PetscCall(F->ops->start(F));
  PetscFunctionReturn(0);
}

/* one step of the scheme, which evaluates, tests and monitors the new state itself; taken when it counted one */
static PetscErrorCode Advance(void *ctx, PetscBool *taken)
{
  CSBSFlow F  = (CSBSFlow)ctx;
  PetscInt it = F->it;
  PetscFunctionBeginUser;
  PetscCall(F->ops->step(F));
  *taken = (PetscBool)(F->it > it);
  PetscFunctionReturn(0);
}

static PetscErrorCode Judge(void *ctx, PetscInt *reason)
{
  PetscFunctionBeginUser;
  *reason = ((CSBSFlow)ctx)->reason;
  PetscFunctionReturn(0);
}

/* START and STEP: the schemes monitored them (TAO static: every TAO iteration); END: the state returned */
static PetscErrorCode Monitor(void *ctx, CSFlowEvent ev)
{
  CSBSFlow        F = (CSBSFlow)ctx;
  CSBSMonitorInfo info;
  PetscFunctionBeginUser;
  if (ev != CS_FLOW_EVENT_END) PetscFunctionReturn(0);
  if (!F->finished) { /* the stepping time stops here */
    PetscLogDouble t;
    PetscCall(CSBSFlowGetStepSeconds(F, &t));
    F->tsteps0  = t;
    F->finished = PETSC_TRUE;
  }
  PetscCall(PetscMemzero(&info, sizeof(info)));
  info.event = CS_BS_MONITOR_END;
  info.it    = F->it;
  info.W     = F->W;
  info.dt    = F->dt;
  F->xmon    = F->x;
  PetscCall(CSBSFlowMonitor(F, &info));
  PetscFunctionReturn(0);
}

static const CSFlowLoopOps LoopOps = {SetUpFlow, Start, Advance, NULL, Judge, Monitor};

CS_FLOW_LOOP_DEFINE(CSBSFlow) /* SetUp, Step, Solve */

PetscErrorCode CSBSFlowGetCheckpointState(CSBSFlow F, PetscReal r[CS_BS_CHECKPOINT_NREAL])
{
  PetscLogDouble now, steps;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  PetscCall(CSBSFlowGetStepSeconds(F, &steps));
  r[0] = F->dt;
  r[1] = (PetscReal)F->rejected;
  r[2] = (PetscReal)(now - F->loop.t0);
  r[3] = (PetscReal)steps;
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowSetCheckpointState(CSBSFlow F, PetscInt it, const PetscReal r[CS_BS_CHECKPOINT_NREAL])
{
  PetscFunctionBeginUser;
  PetscCheck(F->loop.setupcalled && !F->loop.started, F->mesh->comm, PETSC_ERR_ORDER, "CSBSFlowSetCheckpointState: call after CSBSFlowSetUp, before the first step");
  PetscCall(CSFlowLoopResume(&F->loop, it, r[2])); /* the history's seconds column continues */
  F->it       = it;
  F->dt       = r[0];
  F->rejected = (PetscInt)r[1];
  F->tsteps0  = r[3];
  F->row      = it + 1;     /* history row of the next accepted step (the row of step it is in the file) */
  F->resumed  = PETSC_TRUE;
  PetscFunctionReturn(0);
}
