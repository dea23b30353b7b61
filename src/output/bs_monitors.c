/* Monitors of the Bobenko-Schroeder flow: progress line, history CSV, ParaView series, checkpoint; resume.
   See include/cs_output_bs.h. */
#include "cs_output_bs.h"
#include "cs_geometry.h"

PetscErrorCode CSBSFlowMonitorProgress(CSBSFlow flow, const CSBSMonitorInfo *info, void *ctx)
{
  CSMesh      mesh;
  const char *name;
  PetscBool   semi, euler;
  PetscFunctionBeginUser;
  PetscCall(CSBSFlowGetMesh(flow, &mesh));
  PetscCall(CSBSFlowGetSchemeName(flow, &name));
  PetscCall(PetscStrcmp(name, "semi", &semi));
  PetscCall(PetscStrcmp(name, "tao_euler", &euler));
  if (info->event == CS_BS_MONITOR_END) PetscFunctionReturn(0);
  if (semi && info->event == CS_BS_MONITOR_START) PetscCall(PetscPrintf(mesh->comm, "bs semi step %3" PetscInt_FMT "  W=%.10e  dt=%.3e%s\n", info->it, (double)info->W, (double)info->dt, info->resumed ? "  (resumed)" : ""));
  if (info->event != CS_BS_MONITOR_STEP) PetscFunctionReturn(0);
  if (semi) PetscCall(PetscPrintf(mesh->comm, "bs semi step %3" PetscInt_FMT "  W=%.10e  dt=%.3e  ksp_its=%" PetscInt_FMT "\n", info->it, (double)info->W, (double)info->dt, info->inner_its));
  else if (euler) PetscCall(PetscPrintf(mesh->comm, "bs tao euler step %3" PetscInt_FMT "  W=%.10e  dt=%.3e  tao_its=%" PetscInt_FMT " (%s)\n", info->it, (double)info->W, (double)info->dt, info->inner_its, info->inner_reason));
  else PetscCall(PetscPrintf(mesh->comm, "bs tao it %3" PetscInt_FMT "  W=%.10e  |g|=%.3e\n", info->it, (double)info->W, (double)info->gnorm));
  PetscFunctionReturn(0);
}

/* a state to record: every step, and the start unless it is already in the file (resume) */
static PetscBool Records(const CSBSMonitorInfo *info)
{
  return (PetscBool)(info->event == CS_BS_MONITOR_STEP || (info->event == CS_BS_MONITOR_START && !info->resumed));
}

typedef struct {
  CSHistory hist;
  CSEnergy  will; /* the cotan Willmore energy, column willmore */
} HistoryCtx;

static PetscErrorCode MonitorHistory(CSBSFlow flow, const CSBSMonitorInfo *info, void *ctx)
{
  HistoryCtx *H = (HistoryCtx *)ctx;
  CSMesh      mesh;
  Vec         x;
  PetscReal   Wc, area, vol, row[7];
  PetscFunctionBeginUser;
  if (!Records(info)) PetscFunctionReturn(0);
  PetscCall(CSBSFlowGetMesh(flow, &mesh));
  PetscCall(CSBSFlowGetSolution(flow, &x));
  PetscCall(CSEnergyValue(H->will, x, &Wc));
  PetscCall(CSGeometryAreaVolume(mesh, x, &area, &vol));
  row[0] = (PetscReal)info->row;
  row[1] = info->W;
  row[2] = Wc;
  row[3] = area;
  row[4] = info->dt;
  row[5] = (PetscReal)info->inner_its;
  row[6] = info->seconds;
  PetscCall(CSHistoryAppend(H->hist, 7, row));
  PetscFunctionReturn(0);
}

static PetscErrorCode HistoryDestroy(void **ctx)
{
  HistoryCtx *H = (HistoryCtx *)*ctx;
  PetscFunctionBeginUser;
  PetscCall(CSHistoryDestroy(&H->hist));
  PetscCall(CSEnergyDestroy(&H->will));
  PetscCall(PetscFree(*ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowMonitorSetHistory(CSBSFlow flow, CSOutput *out)
{
  HistoryCtx  *H;
  CSMesh       mesh;
  CSBSFlowInfo i;
  PetscFunctionBeginUser;
  if (!out->has_history && !CSHistoryCaptureActive()) PetscFunctionReturn(0); /* a library caller keeps it in memory (src/api) */
  PetscCall(CSBSFlowGetMesh(flow, &mesh));
  PetscCall(CSBSFlowGetInfo(flow, &i));
  PetscCall(PetscNew(&H));
  PetscCall(CSOutputHistoryCreate(out, mesh->comm, "it,willmore_bs,willmore,area,dt,ksp_its,seconds", i.it + 1, &H->hist));
  PetscCall(CSEnergyCreateWillmore(mesh, &H->will));
  PetscCall(CSBSFlowMonitorSet(flow, MonitorHistory, H, HistoryDestroy));
  PetscFunctionReturn(0);
}

typedef struct {
  CSViewer v;
  Vec      Wv; /* per-vertex W_i */
  Vec      WK; /* per-vertex W_i + K_i */
  PetscInt every;
} ViewerCtx;

static PetscErrorCode MonitorViewer(CSBSFlow flow, const CSBSMonitorInfo *info, void *ctx)
{
  ViewerCtx *V = (ViewerCtx *)ctx;
  CSEnergy   bs;
  Vec        x;
  PetscReal  wkmin;
  PetscInt   nneg;
  PetscFunctionBeginUser;
  if (!Records(info) || info->row % V->every) PetscFunctionReturn(0);
  PetscCall(CSBSFlowGetEnergy(flow, &bs));
  PetscCall(CSBSFlowGetSolution(flow, &x));
  PetscCall(CSEnergyWillmoreBSVertex(bs, x, V->Wv, NULL));
  PetscCall(CSViewerAddVertexField(V->v, "W_i", V->Wv));
  PetscCall(CSEnergyWillmoreBSGaussBound(bs, x, V->WK, &wkmin, &nneg));
  PetscCall(CSViewerAddVertexField(V->v, "W_plus_K", V->WK)); /* Sec. 2: >= 0 */
  PetscCall(CSViewerWriteStep(V->v, x, (PetscReal)info->row));
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewerDestroy(void **ctx)
{
  ViewerCtx *V = (ViewerCtx *)*ctx;
  PetscFunctionBeginUser;
  PetscCall(CSViewerDestroy(&V->v));
  PetscCall(VecDestroy(&V->Wv));
  PetscCall(VecDestroy(&V->WK));
  PetscCall(PetscFree(*ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowMonitorSetViewer(CSBSFlow flow, CSOutput *out, PetscInt every)
{
  ViewerCtx *V;
  CSMesh     mesh;
  PetscFunctionBeginUser;
  if (!out->has_viewer) PetscFunctionReturn(0);
  PetscCall(CSBSFlowGetMesh(flow, &mesh));
  PetscCall(PetscNew(&V));
  V->every = every;
  PetscCall(CSViewerCreate(mesh, NULL, out->viewer_dir, &V->v));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &V->Wv));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &V->WK));
  PetscCall(CSBSFlowMonitorSet(flow, MonitorViewer, V, ViewerDestroy));
  PetscFunctionReturn(0);
}

/* After every accepted step that does not end the run (every -checkpoint_every), and always at the end. */
static PetscErrorCode MonitorCheckpoint(CSBSFlow flow, const CSBSMonitorInfo *info, void *ctx)
{
  CSOutput           *out = (CSOutput *)ctx;
  CSBSConvergedReason reason;
  CSMesh              mesh;
  Vec                 x, x0;
  PetscReal           r[CS_BS_CHECKPOINT_NREAL];
  PetscBool           end = (PetscBool)(info->event == CS_BS_MONITOR_END);
  PetscFunctionBeginUser;
  PetscCall(CSBSFlowGetConvergedReason(flow, &reason));
  if (!end && (info->event != CS_BS_MONITOR_STEP || reason != CS_BS_ITERATING)) PetscFunctionReturn(0);
  PetscCall(CSBSFlowGetMesh(flow, &mesh));
  PetscCall(CSBSFlowGetSolution(flow, &x));
  PetscCall(CSBSFlowGetInitialSolution(flow, &x0));
  PetscCall(CSBSFlowGetCheckpointState(flow, r));
  {
    CSCheckpointFields v = {x, NULL, NULL};
    PetscCall(CSOutputCheckpoint(out, mesh, x0, info->it, end, CS_BS_CHECKPOINT_NREAL, r, &v));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowMonitorSetCheckpoint(CSBSFlow flow, CSOutput *out)
{
  const char *name;
  PetscBool   semi;
  PetscFunctionBeginUser;
  PetscCall(CSBSFlowGetSchemeName(flow, &name));
  PetscCall(PetscStrcmp(name, "semi", &semi));
  if (semi) PetscCall(CSBSFlowMonitorSet(flow, MonitorCheckpoint, out, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowResume(CSBSFlow flow, CSOutput *out)
{
  const char *name;
  PetscBool   semi, resumed;
  CSMesh      mesh;
  Vec         x, x0;
  PetscInt    it = 0;
  PetscReal   r[CS_BS_CHECKPOINT_NREAL];
  PetscFunctionBeginUser;
  PetscCall(CSBSFlowGetMesh(flow, &mesh));
  PetscCall(CSBSFlowGetSchemeName(flow, &name));
  PetscCall(PetscStrcmp(name, "semi", &semi));
  PetscCheck(semi || (!out->has_checkpoint && !out->has_resume), mesh->comm, PETSC_ERR_ARG_INCOMP, "-checkpoint/-resume: only -bs_scheme semi writes checkpoints");
  if (!semi) PetscFunctionReturn(0);
  PetscCall(CSBSFlowGetSolution(flow, &x));
  PetscCall(CSBSFlowGetInitialSolution(flow, &x0));
  {
    CSCheckpointFields v = {x, NULL, NULL};
    PetscCall(CSOutputResume(out, mesh, x0, &it, CS_BS_CHECKPOINT_NREAL, r, &v, &resumed));
  }
  if (resumed) PetscCall(CSBSFlowSetCheckpointState(flow, it, r));
  PetscFunctionReturn(0);
}
