/* The loop state a checkpoint keeps besides its fields (the positions and mu, the edge field; a triangle field's
   own, trianglefield_state.c): [flow kind, t, t_mu, rejections, KSP its in total, KSP its of the last step, edges
   with guarded I_Q weight, seconds, the kind's switch (ops.get_switch: whether CGD's -t_mu_final fired), the step
   model's last accepted t and the violation it added (willmore_step_model.c), nu_1..nu_k, the stationarity window and the drift test's smallest residual
   (willmore_stop.c), the point stage (willmore_points_continuation.c: a checkpoint written before it was stored is
   refused by its count of scalars), the kind's own scalars]. The kept best state (-flow_keep_best) is not stored: a resumed run keeps the best
   of its own iterations. The rest (g, c, X, metric, residual) is
   recomputed from x at the top of the loop, so a resumed run continues exactly like the uninterrupted one. */
#include "willmore_impl.h"

#define FLOW_CK_NREAL 11

PetscErrorCode CSWillmoreFlowGetStateSize(CSWillmoreFlow F, PetscInt *nreal)
{
  PetscFunctionBeginUser;
  PetscCheck(F->setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowGetStateSize before CSWillmoreFlowSetUp");
  *nreal = FLOW_CK_NREAL + F->k + CS_WF_STAT_NREAL + CS_WF_POINTS_NREAL + F->ops.state_nreal;
  PetscFunctionReturn(0);
}

/* the options whose state is not stored, refused by name */
static PetscErrorCode CheckStorable(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(!CSWFOwnVariables(F) || F->ops.get_state, F->hdr.comm, PETSC_ERR_SUP, "-checkpoint/-resume with -%stype %s: its variables are not stored in checkpoints", F->hdr.prefix, F->type);
  PetscCheck(!F->normals, F->hdr.comm, PETSC_ERR_SUP, "-checkpoint/-resume with -%sboundary normals: the multipliers of the normal constraint are not stored in checkpoints", F->hdr.prefix);
  if (F->ops.storable) PetscCall((*F->ops.storable)(F)); /* a kind whose state is not stored refuses (ALM) */
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetStart(CSWillmoreFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  PetscCheck(F->setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowGetStart before CSWillmoreFlowSetUp");
  *x = F->xstart ? F->xstart : F->x0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetState(CSWillmoreFlow F, PetscReal ck[], CSCheckpointFields *v)
{
  PetscLogDouble now;
  PetscBool      on = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCheck(F->setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowGetState before CSWillmoreFlowSetUp");
  PetscCall(CheckStorable(F));
  PetscCall(PetscTime(&now));
  if (F->ops.get_switch) PetscCall((*F->ops.get_switch)(F, &on));
  if (ck) {
    ck[0] = (PetscReal)F->ops.id;
    ck[1] = F->t;
    ck[2] = F->tmu;
    ck[3] = (PetscReal)F->rejections;
    ck[4] = (PetscReal)F->kspits_total;
    ck[5] = (PetscReal)F->kspits;
    ck[6] = (PetscReal)F->nguard;
    ck[7] = (PetscReal)(now - F->t0);
    ck[8] = (PetscReal)on; /* the kind's switch (CGD: -t_mu_final fired; t_mu >= T does not tell) */
    ck[9]  = F->step_tacc; /* the predictive step's growth fits the violation of the next step against this one */
    ck[10] = F->step_dacc;
    for (PetscInt j = 0; j < F->k; j++) ck[FLOW_CK_NREAL + j] = F->nu[j];
    CSWFStationaryGetState(F, ck + FLOW_CK_NREAL + F->k);
    CSWFPointsContinuationGetState(F, ck + FLOW_CK_NREAL + F->k + CS_WF_STAT_NREAL);
  }
  if (F->ops.get_state) { /* a kind with its own variables packs them (and its scalars after the flow's) */
    PetscCall((*F->ops.get_state)(F, ck ? ck + FLOW_CK_NREAL + F->k + CS_WF_STAT_NREAL + CS_WF_POINTS_NREAL : NULL, v));
    PetscFunctionReturn(0);
  }
  v->x    = F->x;
  v->edge = F->conformal ? F->mu : NULL;
  v->face = NULL;
  PetscFunctionReturn(0);
}

/* The stored scalars in their ranges (issue 36, item 8: t = -1, t_mu = -1 or 1e18 rejections behind a valid
   checksum were taken as they were): step sizes positive, counters whole numbers in [0, 1e9], the switch 0 or 1. */
static PetscErrorCode CheckScalars(CSWillmoreFlow F, PetscInt it, const PetscReal ck[])
{
  const char *names[FLOW_CK_NREAL - 1] = {"t", "t_mu", "rejections", "KSP iterations", "KSP iterations of the last step", "guarded edges", "seconds", "-t_mu_final switch", "step model's last accepted t", "step model's added violation"};
  PetscFunctionBeginUser;
  PetscCheck(it <= F->max_it, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-resume: the checkpoint is at iteration %" PetscInt_FMT ", beyond -%smax_it %" PetscInt_FMT ": nothing left to run", it, F->hdr.prefix, F->max_it);
  for (PetscInt i = 1; i < FLOW_CK_NREAL; i++) {
    PetscReal v  = ck[i];
    PetscBool ok = (PetscBool)(PetscIsNormalReal(v) || v == 0);
    if (i <= 2) ok = (PetscBool)(ok && v > 0 && v < 1e300);
    else if (i == 7) ok = (PetscBool)(ok && v >= 0);
    else if (i == 8) ok = (PetscBool)(v == 0 || v == 1);
    else if (i == 9) ok = (PetscBool)(ok && v >= 0 && v < 1e300); /* willmore_step_model.c: 0 before the first accepted step */
    else if (i == 10) ok = (PetscBool)(ok && PetscAbsReal(v) < 1e300); /* the added violation: negative when the step lowered it (CSWFStepModelGrow) */
    else ok = (PetscBool)(ok && v >= 0 && v <= 1e9 && v == PetscFloorReal(v));
    PetscCheck(ok, F->hdr.comm, PETSC_ERR_FILE_UNEXPECTED, "-resume: the checkpoint's %s is %g, out of range (a damaged or crafted file)", names[i - 1], (double)v);
  }
  PetscFunctionReturn(0);
}

/* After the fields of GetState and ck were overwritten by a checkpoint of iteration it. */
PetscErrorCode CSWillmoreFlowSetState(CSWillmoreFlow F, PetscInt it, const PetscReal ck[])
{
  PetscFunctionBeginUser;
  PetscCheck(ck[0] == (PetscReal)F->ops.id, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-resume: the checkpoint was written by another flow type (this run is %s)", F->type);
  PetscCall(CheckScalars(F, it, ck));
  F->t            = ck[1];
  F->tmu          = ck[2];
  F->rejections   = (PetscInt)ck[3];
  F->step_tacc    = ck[9];
  F->step_dacc    = ck[10];
  F->kspits_total = (PetscInt)ck[4];
  F->kspits       = (PetscInt)ck[5];
  F->nguard       = (PetscInt)ck[6];
  F->t0          -= ck[7]; /* the seconds column of the history continues */
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] = ck[FLOW_CK_NREAL + j];
  CSWFStationarySetState(F, ck + FLOW_CK_NREAL + F->k);
  PetscCall(CSWFPointsContinuationSetState(F, it, ck + FLOW_CK_NREAL + F->k + CS_WF_STAT_NREAL));
  if (F->ops.set_switch) PetscCall((*F->ops.set_switch)(F, (PetscBool)(ck[8] != 0))); /* CGD: the -t_mu_final switch had fired */
  F->it      = it;
  F->resumed = PETSC_TRUE;
  if (F->ops.set_state) PetscCall((*F->ops.set_state)(F, ck + FLOW_CK_NREAL + F->k + CS_WF_STAT_NREAL + CS_WF_POINTS_NREAL)); /* may override the above */
  PetscFunctionReturn(0);
}
