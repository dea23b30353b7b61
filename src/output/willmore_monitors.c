/* Monitors of the Willmore flow: the progress line, the -history_csv CSV and the checkpoint writer. */
#include "cs_output_willmore.h"

static PetscErrorCode MonitorProgress(CSWillmoreFlow flow, PetscInt it, void *ctx)
{
  CSWillmoreFlowInfo i;
  CSMesh             mesh;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(PetscPrintf(mesh->comm, "%4" PetscInt_FMT " E %.12g area %.8g vol %.8g |c|inf %.3e |xi| %.3e el %.3e t %.3g ksp %" PetscInt_FMT " els %.3e\n", it, (double)i.energy, (double)i.area, (double)i.volume, (double)i.conformal_violation, (double)i.constraint_violation, (double)i.el_residual, (double)i.t, i.ksp_its, (double)i.el_residual_scaled));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowMonitorProgressSet(CSWillmoreFlow flow)
{
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowMonitorSet(flow, MonitorProgress, NULL, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorHistory(CSWillmoreFlow flow, PetscInt it, void *ctx)
{
  CSWillmoreFlowInfo i;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  {
    PetscReal row[14] = {(PetscReal)it, i.energy, i.area, i.volume, i.conformal_violation, i.constraint_violation, i.el_residual, i.t, (PetscReal)i.ksp_its, (PetscReal)i.rejections, i.seconds, i.area_spread, i.q_max, i.el_residual_scaled};
    PetscCall(CSHistoryAppend((CSHistory)ctx, 14, row));
  }
  PetscFunctionReturn(0);
}

/* After CSWillmoreFlowResume: a resumed run writes the row of its first iteration again (from the same state). */
PetscErrorCode CSWillmoreFlowMonitorHistorySet(CSWillmoreFlow flow, CSOutput *out)
{
  CSWillmoreFlowInfo i;
  CSMesh             mesh;
  CSHistory          h;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(CSOutputHistoryCreate(out, mesh->comm, "it,energy,area,volume,conformal_violation,constraint_violation,el_residual,t,ksp_its,rejections,seconds,area_spread,q_max,el_residual_scaled", i.it, &h));
  if (h) PetscCall(CSWillmoreFlowMonitorSet(flow, MonitorHistory, h, CSHistoryMonitorDestroy));
  PetscFunctionReturn(0);
}

typedef struct {
  CSOutput  *out;
  PetscInt   first; /* the first iteration of this run: its state is the input or the checkpoint */
  PetscReal *ck;
} CheckpointCtx;

/* -checkpoint FILE -checkpoint_every N: the state after it accepted steps, every N. */
static PetscErrorCode WriteCheckpoint(CSWillmoreFlow flow, CSOutput *out, PetscInt it, PetscBool force, PetscReal ck[])
{
  PetscInt           nreal;
  Vec                x0;
  CSMesh             mesh;
  CSCheckpointFields v;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(CSWillmoreFlowGetStart(flow, &x0));
  PetscCall(CSWillmoreFlowGetStateSize(flow, &nreal));
  PetscCall(CSWillmoreFlowGetState(flow, ck, &v));
  PetscCall(CSOutputCheckpoint(out, mesh, x0, it, force, nreal, ck, &v));
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorCheckpoint(CSWillmoreFlow flow, PetscInt it, void *ctx)
{
  CheckpointCtx *c = (CheckpointCtx *)ctx;
  PetscFunctionBeginUser;
  if (it > c->first) PetscCall(WriteCheckpoint(flow, c->out, it, PETSC_FALSE, c->ck));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckpointDestroy(void **ctx)
{
  CheckpointCtx *c = (CheckpointCtx *)*ctx;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->ck));
  PetscCall(PetscFree(c));
  *ctx = NULL;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowMonitorCheckpointSet(CSWillmoreFlow flow, CSOutput *out)
{
  CheckpointCtx     *c;
  CSWillmoreFlowInfo i;
  PetscInt           nreal;
  PetscFunctionBeginUser;
  if (!out->has_checkpoint) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  PetscCall(CSWillmoreFlowGetStateSize(flow, &nreal));
  PetscCall(PetscNew(&c));
  c->out   = out;
  c->first = i.it;
  PetscCall(PetscMalloc1(nreal, &c->ck));
  PetscCall(CSWillmoreFlowMonitorSet(flow, MonitorCheckpoint, c, CheckpointDestroy));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowResume(CSWillmoreFlow flow, CSOutput *out)
{
  PetscInt           nreal, it = 0;
  PetscReal         *ck;
  Vec                x0;
  CSMesh             mesh;
  PetscBool          resumed;
  CSCheckpointFields v = {NULL, NULL, NULL};
  PetscErrorCode     ierr;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(CSWillmoreFlowGetStart(flow, &x0));
  if (!out->has_checkpoint && !out->has_resume) { /* marks the options as supported; reads nothing */
    PetscCall(CSOutputResume(out, mesh, x0, &it, 0, NULL, &v, &resumed));
    PetscFunctionReturn(0);
  }
  PetscCall(CSWillmoreFlowGetStateSize(flow, &nreal));
  PetscCall(PetscMalloc1(nreal, &ck));
  ierr = CSWillmoreFlowGetState(flow, ck, &v); /* x0 (input, conformal target, q_mean) stays the input */
  if (!ierr) ierr = CSOutputResume(out, mesh, x0, &it, nreal, ck, &v, &resumed);
  if (!ierr && resumed) ierr = CSWillmoreFlowSetState(flow, it, ck);
  PetscCall(PetscFree(ck)); /* on the error paths too (a refused option, a damaged checkpoint) */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PETSC_INTERN PetscErrorCode CSWillmoreFlowCheckpointFinal(CSWillmoreFlow flow, CSOutput *out);
/* the last accepted state, converged or not */
PetscErrorCode CSWillmoreFlowCheckpointFinal(CSWillmoreFlow flow, CSOutput *out)
{
  CSWillmoreFlowInfo i;
  PetscInt           nreal;
  PetscReal         *ck;
  PetscFunctionBeginUser;
  if (!out->has_checkpoint) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  PetscCall(CSWillmoreFlowGetStateSize(flow, &nreal));
  PetscCall(PetscMalloc1(nreal, &ck));
  PetscCall(WriteCheckpoint(flow, out, i.it, PETSC_TRUE, ck));
  PetscCall(PetscFree(ck));
  PetscFunctionReturn(0);
}
