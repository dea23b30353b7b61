/* The Willmore flow object (soliman2021 Sec. 4, Algorithm 1): creation, kind (PetscFunctionList of the kinds in
   impls/<kind>/), prefix, monitors, getters, checkpoint state, destruction. The method itself: willmore_step.c,
   willmore_filter.c, willmore_projection.c, willmore_guards.c, willmore_solve.c. */
#include "willmore_impl.h"
#include "cs_package.h"
#include "cs_util.h"

const char *const CSWillmoreFlowConvergedReasons[] = {"ITERATING", "CONVERGED_RTOL", "DIVERGED_MAX_IT", "DIVERGED_REJECTIONS", "DIVERGED_AREA", "DIVERGED_MESH_DEGENERATE", "STALLED", "CONVERGED_ENERGY_TARGET", "DIVERGED_FOLDED", "CONVERGED_STATIONARY", "DIVERGED_DRIFT", NULL};
/* the summary's stop_reason (unchanged from before the object) */
const char *const CSWillmoreFlowDegenerations[] = {"none", "fins", "squeeze", "smooth", NULL};
const char *const CSWillmoreFlowStopReasons[] = {"iterating", "converged", "max_it", "rejections", "diverged", "mesh_degenerate", "stalled", "energy_target", "folded", "stationary", "drift", NULL};

static PetscFunctionList CSWillmoreFlowList = NULL;
/* the ops.id of each registered kind: stored in checkpoints, so a resume finds the kind that wrote one */
typedef struct {
  char     name[16];
  PetscInt id;
} KindId;
static KindId   *KindIds = NULL;
static PetscInt  KindIdCount = 0, KindIdMax = 0;
static PetscBool KindsRegistered = PETSC_FALSE;
static PetscErrorCode RegisterAll(void);

/* A kind's ops.id, read by creating it on a bare flow (a kind's create fills only ops and its data). */
static PetscErrorCode KindIdOf(const char name[], PetscErrorCode (*create)(CSWillmoreFlow), PetscInt *id)
{
  CSWillmoreFlow F;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&F));
  PetscCall(PetscStrncpy(F->type, name, sizeof(F->type)));
  PetscCall((*create)(F));
  *id = F->ops.id;
  if (F->ops.destroy) PetscCall((*F->ops.destroy)(F));
  PetscCall(PetscFree(F));
  PetscFunctionReturn(0);
}

/* Registers a kind whose ops.id no other registered kind has (the same name again replaces the kind). */
PetscErrorCode CSWillmoreFlowRegister(const char name[], PetscErrorCode (*create)(CSWillmoreFlow))
{
  PetscInt id = -1, j;
  PetscFunctionBeginUser;
  PetscCall(RegisterAll()); /* the built-ins first, whoever registers first */
  PetscCall(KindIdOf(name, create, &id));
  for (j = 0; j < KindIdCount; j++) {
    PetscBool same;
    PetscCall(PetscStrcmp(KindIds[j].name, name, &same));
    if (same) break;
    PetscCheck(KindIds[j].id != id, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "CSWillmoreFlowRegister(%s): its ops.id %" PetscInt_FMT " is that of the kind %s (the id stored in checkpoints: give each kind its own)", name, id, KindIds[j].name);
  }
  if (j == KindIdCount) {
    PetscCall(CSArrayGrow(sizeof(KindId), KindIdCount, 16, &KindIdMax, (void **)&KindIds));
    PetscCall(PetscStrncpy(KindIds[KindIdCount++].name, name, sizeof(KindIds[0].name)));
  }
  KindIds[j].id = id;
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowList, name, create));
  PetscFunctionReturn(0);
}

static PetscErrorCode ListDestroy(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&CSWillmoreFlowList));
  PetscCall(PetscFree(KindIds));
  KindIdCount = KindIdMax = 0;
  KindsRegistered         = PETSC_FALSE;
  PetscFunctionReturn(0);
}

static PetscErrorCode RegisterAll(void)
{
  PetscFunctionBeginUser;
  if (KindsRegistered) PetscFunctionReturn(0);
  KindsRegistered = PETSC_TRUE;
  PetscCall(PetscRegisterFinalize(ListDestroy));
  PetscCall(CSWillmoreFlowRegister(CSWILLMOREFLOWCGD, CSWillmoreFlowCreate_CGD));
  PetscCall(CSWillmoreFlowRegister(CSWILLMOREFLOWPGD, CSWillmoreFlowCreate_PGD));
  PetscCall(CSWillmoreFlowRegister(CSWILLMOREFLOWGD, CSWillmoreFlowCreate_GD));
  PetscCall(CSWillmoreFlowRegister(CSWILLMOREFLOWNEWTON, CSWillmoreFlowCreate_Newton));
  PetscCall(CSWillmoreFlowRegister(CSWILLMOREFLOWALM, CSWillmoreFlowCreate_ALM));
  PetscCall(CSWillmoreFlowRegister(CSWILLMOREFLOWTRIANGLEFIELD, CSWillmoreFlowCreate_TriangleField));
  /* baselines of the fairing comparison (crane2013 Fig. 17; fairing_baselines.c) */
  for (int k = 0; k < 7; k++) {
    const char *baseline[] = {"emcf", "ebilap", "imcf", "ibilap", "cmcf", "vmcf", "isobend"};
    PetscCall(CSWillmoreFlowRegister(baseline[k], CSWillmoreFlowCreate_Fairing));
  }
  PetscFunctionReturn(0);
}

/* The registered kinds (cgd, pgd, gd, newton, alm, the fairing baselines, and any a user registers): the one list
   that -flow_type's help and the driver's flow types are read from. */
PetscErrorCode CSWillmoreFlowGetTypeList(PetscFunctionList *list)
{
  PetscFunctionBeginUser;
  PetscCall(RegisterAll());
  *list = CSWillmoreFlowList;
  PetscFunctionReturn(0);
}

/* Defaults of every option (SetFromOptions may change them). */
static void SetDefaults(CSWillmoreFlow F)
{
  F->t               = 1.0;
  F->tmu             = 0; /* 0: the kind's default, ops.tmu_ratio t (CheckOptions) */
  F->tmax            = 2.0;
  F->grow            = 2.0;
  F->rtol            = 5e-7; /* of el_residual_scaled: the median unit-scale input has el_residual_scaled ~ 0.3 el_residual, and 5e-7 stops the converged tests and golden cases of the old 1e-6 at the same iteration or within a few (docs/willmore_flow.md "Stopping") */
  F->el_norm         = CS_FLOW_EL_NORM_SCALED;
  F->E0              = -1; /* computed at the first evaluation */
  /* on, strict: on the converged tests no run stops earlier than by -rtol; the catenoid (area energy) whose
     el_residual floors at 1.25e-6 stops at iteration 19 with W to 2e-13 (docs/willmore_flow.md "Stopping") */
  F->stat_window     = 10;
  F->stat_rtol       = 1e-11;
  F->stat_xtol       = 1e-6;
  F->stat_it         = -1;
  /* the fat-class drift of a remeshed torus (docs/real_meshes.md, issue 35): W changes by 4e-8 per step while EL
     rises; runs/stationary_rule.py on the measured histories: 50, 2e-7, 1.5 stop every drift and no converging run */
  F->drift_window    = 50;
  F->drift_wtol      = 2e-7;
  F->drift_rise      = 1.5;
  /* a sustained rise, not a spike: the longest run of risen residuals measured in a run that does not drift is 6
     steps (the step-size limit cycles of a triangle field at t_max 5-8); a drift rises for 100-250 steps, so 10 costs
     it 9 (runs/stationary_rule.py on the histories of docs/willmore_flow.md "Drift") */
  F->drift_rise_steps = 10;
  F->els_min         = -1;
  F->els_min_it      = -1;
  F->keep_best       = CS_FLOW_KEEP_BEST_GUARD;
  F->best_it         = -1;
  F->last_it         = -1;
  F->ctol            = 1e-10;
  F->wmin            = 1e-2;
  F->max_it          = 100;
  F->max_rej         = 30;
  F->t_min           = 1e-10; /* 2^-33: far below any step that still moves the surface */
  F->proj_max_it     = 20;
  F->soc_max_it      = 2;
  F->proj_tmu        = 1e6;
  F->step_control    = PETSC_TRUE;
  F->step_model      = CS_WF_STEP_PREDICTIVE;
  F->vmax            = 1e-2;
  F->restore_stalled = PETSC_TRUE;
  F->max_area_ratio  = 200;
  F->project_at_stop = PETSC_TRUE;
  F->fin_q           = 3; /* measured at the guard's stop: smooth squeezes 1.15-2.4, eight_cgal's fins 4.9 and growing */
  F->reuse_its       = -1; /* the saddle solver's default */
  F->metric_type     = CS_FLOW_METRIC_H2;
  F->boundary        = CS_FLOW_BOUNDARY_DIRICHLET;
  F->saddle_mat      = CS_SADDLE_MAT_NEST;
  F->viol_min        = -1; /* none evaluated yet */
  F->pcont.rtol      = 1e-2; /* the point stages (willmore_points_continuation.c): 1e-3 cost 400 iterations where 1e-2 took 245 (docs/willmore_flow.md "Fig. 18") */
  F->pcont.ctol      = 1e-4;
}

/* The flow's own members (hdr.destroy: CSWillmoreFlowDestroy cancels the monitors first and frees the header after) */
static PetscErrorCode DestroyMembers(CSObject obj)
{
  CSWillmoreFlow F = (CSWillmoreFlow)obj;
  PetscFunctionBeginUser;
  if (F->ops.destroy) PetscCall((*F->ops.destroy)(F));
  PetscCall(VecDestroy(&F->xgood));
  PetscCall(CSWFStopDestroy(F));
  /* also after a set-up that failed half-way (the parts are zeroed at creation; their destroys take NULL) */
  PetscCall(CSSaddleDestroy(&F->saddle));
  PetscCall(CSMetricDestroy(&F->metric));
  PetscCall(CSConformalConstraintDestroy(&F->cc));
  PetscCall(CSNormalConstraintDestroy(&F->nc));
  PetscCall(CSWFConstraintsDestroy(F));
  if (F->k) PetscCall(VecDestroyVecs(F->k, &F->rows));
  PetscCall(PetscFree(F->dnu2));
  PetscCall(PetscFree6(F->cx, F->cxt, F->nu, F->dnu, F->gw, F->nun));
  if (F->energy) PetscCall(CSEnergyDestroy(&F->energy));
  PetscCall(VecDestroy(&F->x));
  PetscCall(VecDestroy(&F->x0));
  PetscCall(VecDestroy(&F->area0));
  PetscCall(VecDestroy(&F->areat));
  PetscCall(VecDestroy(&F->g));
  PetscCall(VecDestroy(&F->r));
  PetscCall(VecDestroy(&F->df));
  PetscCall(VecDestroy(&F->xt));
  PetscCall(VecDestroy(&F->tmp));
  PetscCall(VecDestroy(&F->c));
  PetscCall(VecDestroy(&F->cE));
  PetscCall(VecDestroy(&F->cN));
  PetscCall(VecDestroy(&F->iqE));
  PetscCall(VecDestroy(&F->iqN));
  PetscCall(MatDestroy(&F->Xext));
  PetscCall(ISDestroy(&F->isM[0]));
  PetscCall(ISDestroy(&F->isM[1]));
  PetscCall(VecDestroy(&F->mu));
  PetscCall(VecDestroy(&F->dmu));
  PetscCall(VecDestroy(&F->iq));
  PetscCall(VecDestroy(&F->ct));
  PetscCall(VecDestroy(&F->mun));
  PetscCall(ISDestroy(&F->fixedIS));
  PetscCall(PetscFree(F->fixed));
  PetscFunctionReturn(0);
}

/* ops.destroy of a kind whose data (F->data) is one allocation holding no objects (cgd, gd, alm) */
PetscErrorCode CSWFDestroyData(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(F->data));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowCreate(CSMesh mesh, CSWillmoreFlow *flow)
{
  CSWillmoreFlow F;
  PetscFunctionBeginUser;
  PetscCall(CSInitializePackage()); /* as KSPCreate does: events, PCs and solver types before any use */
  PetscCall(RegisterAll());
  PetscCall(CSObjectCreate(sizeof(*F), mesh->comm, "flow_", DestroyMembers, &F));
  F->mesh        = mesh;
  SetDefaults(F);
  PetscCall(PetscStrncpy(F->energy_name, "willmore", sizeof(F->energy_name)));
  PetscCall(CSWillmoreFlowSetType(F, CSWILLMOREFLOWCGD));
  *flow = F;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowSetType(CSWillmoreFlow F, CSWillmoreFlowType type)
{
  PetscErrorCode (*create)(CSWillmoreFlow);
  PetscFunctionBeginUser;
  PetscCheck(!F->setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowSetType after CSWillmoreFlowSetUp");
  PetscCall(RegisterAll());
  PetscCall(PetscFunctionListFind(CSWillmoreFlowList, type, &create));
  PetscCheck(create, F->hdr.comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-%stype %s: unknown Willmore flow type", F->hdr.prefix, type);
  if (F->ops.destroy) PetscCall((*F->ops.destroy)(F)); /* the previous kind's data */
  PetscCall(PetscMemzero(&F->ops, sizeof(F->ops)));
  PetscCall(PetscStrncpy(F->type, type, sizeof(F->type)));
  PetscCall((*create)(F));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetType(CSWillmoreFlow F, CSWillmoreFlowType *type)
{
  PetscFunctionBeginUser;
  *type = F->type;
  PetscFunctionReturn(0);
}

/* SetOptionsPrefix, GetOptionsPrefix, MonitorSet, Destroy: the skeleton of every method object (include/cs_object.h) */
CS_OBJECT_DEFINE(CSWillmoreFlow, CSWillmoreFlowMonitorFn)

/* one-member getters (include/cs_object.h) */
CS_OBJECT_GETTER(CSWillmoreFlow, ConvergedReason, CSWillmoreFlowConvergedReason, reason)
CS_OBJECT_GETTER(CSWillmoreFlow, Mesh, CSMesh, mesh)
CS_OBJECT_GETTER(CSWillmoreFlow, Conformal, PetscBool, conformal)
CS_OBJECT_GETTER(CSWillmoreFlow, EnergyName, const char *, energy_name)
CS_OBJECT_GETTER_AFTER(CSWillmoreFlow, Variables, Vec, x, setupcalled, "CSWillmoreFlowSetUp")
CS_OBJECT_GETTER_AFTER(CSWillmoreFlow, Energy, CSEnergy, energy, setupcalled, "CSWillmoreFlowSetUp")

PetscErrorCode CSWillmoreFlowMonitorCancel(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSMonitorListCancel(&F->hdr.monitors));
  PetscFunctionReturn(0);
}

/* the positions of the current or the initial state: the kind's surface of its own variables, or x / x0 */
static PetscErrorCode GetPositions(CSWillmoreFlow F, PetscBool initial, const char caller[], Vec *x)
{
  PetscFunctionBeginUser;
  PetscCheck(F->setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "%s before CSWillmoreFlowSetUp", caller);
  if (F->ops.positions) PetscCall((*F->ops.positions)(F, initial, x));
  else *x = initial ? F->x0 : F->x;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetSolution(CSWillmoreFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  PetscCall(GetPositions(F, PETSC_FALSE, "CSWillmoreFlowGetSolution", x));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetInitial(CSWillmoreFlow F, Vec *x0)
{
  PetscFunctionBeginUser;
  PetscCall(GetPositions(F, PETSC_TRUE, "CSWillmoreFlowGetInitial", x0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetLastSolution(CSWillmoreFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  *x = F->best_used ? F->last_x : NULL;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetInitialEnergy(CSWillmoreFlow F, PetscReal *E0)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyValue(F->energy, F->x0, E0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetInfo(CSWillmoreFlow F, CSWillmoreFlowInfo *info)
{
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  info->it                   = F->it;
  info->energy               = F->E;
  info->area                 = F->A;
  info->volume               = F->V;
  info->conformal_violation  = F->conf;
  info->constraint_violation = F->glob;
  info->el_residual          = F->el;
  info->el_residual_scaled   = F->els;
  info->best_it              = F->best_it;
  info->best_el_residual_scaled = F->best_els;
  info->best_energy          = F->best_E;
  info->best_used            = F->best_used;
  info->last_it              = F->best_used ? F->last_it : F->it;
  info->last_energy          = F->best_used ? F->last_E : F->E;
  info->last_el_residual_scaled = F->best_used ? F->last_els : F->els;
  info->t                    = F->t;
  info->ksp_its              = F->kspits;
  info->ksp_its_total        = F->kspits_total;
  info->rejections           = F->rejections;
  info->nguard               = F->nguard;
  info->pc_setups            = F->saddle.setups;
  info->linear_solves        = F->saddle.solves;
  info->area_spread          = F->spread;
  info->violation_max        = F->viol_max;
  info->violation_max_it     = F->viol_max_it;
  info->violation_min        = PetscMax(F->viol_min, 0);
  info->violation_min_it     = F->viol_min_it;
  /* grew: the end's violation above -flow_ctol and 10x the smallest of the run (issue 21: reported, never silent) */
  info->violation_grew       = (PetscBool)(PetscMax(F->conf, F->glob) > F->ctol && PetscMax(F->conf, F->glob) > 10 * PetscMax(F->viol_min, 0));
  info->el_first             = F->el_first;
  info->el_min               = F->el_min;
  info->energy_el_min        = F->E_el_min;
  info->it_el_min            = F->it_el_min;
  info->q_max                = F->qmax;
  info->degeneration         = F->degeneration;
  info->seconds              = now - F->t0;
  info->k                    = F->k;
  info->constraint_values    = F->cx;
  PetscFunctionReturn(0);
}


/* One line: the problem the flow solves; then the kind's own lines (ops.view). */
PetscErrorCode CSWillmoreFlowView(CSWillmoreFlow F, PetscViewer viewer)
{
  CSMesh m = F->mesh;
  PetscFunctionBeginUser;
  if (!viewer) viewer = PETSC_VIEWER_STDOUT_(F->hdr.comm);
  PetscCall(PetscViewerASCIIPrintf(viewer, "flow %s: mesh %s V=%" PetscInt_FMT " E=%" PetscInt_FMT " F=%" PetscInt_FMT ", energy %s, metric %s, conformal %s, %" PetscInt_FMT " global constraint rows%s, t=%g t_mu=%g\n", F->type, m->name, m->Nv, m->Ne, m->Nf, F->energy_name, CSFlowMetricTypes[F->metric_type], F->conformal ? "on" : "off", F->k, F->fixedIS ? ", Dirichlet boundary" : "", (double)F->t, (double)F->tmu));
  if (F->ops.view) PetscCall((*F->ops.view)(F, viewer));
  PetscFunctionReturn(0);
}

/* Like KSPSetTolerances: stop when el_residual_scaled (-flow_el_norm absolute: el_residual) < rtol and the violation < ctol, or after max_it iterations
   (PETSC_DEFAULT keeps a value). */
PetscErrorCode CSWillmoreFlowSetTolerances(CSWillmoreFlow F, PetscReal rtol, PetscReal ctol, PetscInt max_it)
{
  PetscFunctionBeginUser;
  if (rtol != (PetscReal)PETSC_DEFAULT) F->rtol = rtol;
  if (ctol != (PetscReal)PETSC_DEFAULT) F->ctol = ctol;
  if (max_it != PETSC_DEFAULT) F->max_it = max_it;
  PetscFunctionReturn(0);
}
