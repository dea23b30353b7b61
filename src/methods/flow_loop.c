/* The iteration driver the stepping flows share (include/cs_flow_loop.h). */
#include "cs_flow_loop.h"

PetscErrorCode CSFlowLoopInit(CSFlowLoop *L, MPI_Comm comm, const CSFlowLoopOps *ops, PetscInt max_it_reason, PetscLogEvent event_step, PetscLogEvent event_solve)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(L, sizeof(*L)));
  L->ops           = *ops;
  L->comm          = comm;
  L->max_it_reason = max_it_reason;
  L->event_step    = event_step;
  L->event_solve   = event_solve;
  PetscFunctionReturn(0);
}

PetscErrorCode CSFlowLoopSetUp(CSFlowLoop *L, void *flow)
{
  PetscLogDouble t1;
  PetscFunctionBeginUser;
  if (L->setupcalled) PetscFunctionReturn(0);
  PetscCall(PetscTime(&L->t0));
  PetscCall(L->ops.setup(flow));
  PetscCall(PetscTime(&t1));
  L->t_setup     = t1 - L->t0;
  L->setupcalled = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode CSFlowLoopResume(CSFlowLoop *L, PetscInt it, PetscReal seconds)
{
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCheck(L->setupcalled && !L->started, L->comm, PETSC_ERR_ORDER, "CSFlowLoopResume: after the set-up, before the first step");
  PetscCall(PetscTime(&now));
  L->it = it;
  L->t0 = now - seconds;
  PetscFunctionReturn(0);
}

static PetscErrorCode Monitor(CSFlowLoop *L, void *flow, CSFlowEvent ev)
{
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  L->seconds = (PetscReal)(now - L->t0);
  PetscCall(L->ops.monitor(flow, ev));
  PetscFunctionReturn(0);
}

/* the flow's own tests first, then -max_it, then (after a step) the wall-time budget: rank 0's clock decides for
   all ranks (no rank stops alone) */
static PetscErrorCode Judge(CSFlowLoop *L, void *flow, PetscBool timed)
{
  PetscLogDouble now;
  PetscMPIInt    over;
  PetscFunctionBeginUser;
  PetscCall(L->ops.judge(flow, &L->reason));
  /* rejected steps count too, so that a flow that keeps rejecting (its judge saying go on) still stops */
  if (!L->reason && (L->it >= L->max_it || (!L->own_rejection_limit && L->rejections >= L->max_it))) L->reason = L->max_it_reason;
  if (L->reason || !timed || L->max_seconds <= 0) PetscFunctionReturn(0);
  PetscCall(PetscTime(&now));
  over = (PetscMPIInt)(now - L->t0 >= L->max_seconds);
  PetscCallMPI(MPI_Bcast(&over, 1, MPI_INT, 0, L->comm));
  if (over) L->reason = L->max_it_reason;
  PetscFunctionReturn(0);
}

/* the set-up, then (once) the input's state, its tests and the START event */
static PetscErrorCode Start(CSFlowLoop *L, void *flow)
{
  PetscFunctionBeginUser;
  PetscCall(CSFlowLoopSetUp(L, flow));
  if (L->started) PetscFunctionReturn(0);
  L->started = PETSC_TRUE;
  PetscCall(L->ops.start(flow));
  PetscCall(Judge(L, flow, PETSC_FALSE));
  PetscCall(Monitor(L, flow, CS_FLOW_EVENT_START));
  PetscFunctionReturn(0);
}

PetscErrorCode CSFlowLoopStep(CSFlowLoop *L, void *flow)
{
  PetscLogDouble t0, t1;
  PetscFunctionBeginUser;
  PetscCall(Start(L, flow));
  if (L->reason) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(L->event_step, 0, 0, 0, 0));
  PetscCall(PetscTime(&t0));
  PetscCall(L->ops.advance(flow, &L->step_taken));
  if (L->step_taken) {
    L->it++;
    if (L->ops.evaluate) PetscCall(L->ops.evaluate(flow));
  } else L->rejections++;
  PetscCall(PetscTime(&t1));
  PetscCall(PetscLogEventEnd(L->event_step, 0, 0, 0, 0));
  L->step_seconds = (PetscReal)(t1 - t0);
  L->t_steps += t1 - t0;
  PetscCall(Judge(L, flow, PETSC_TRUE));
  if (L->step_taken) PetscCall(Monitor(L, flow, CS_FLOW_EVENT_STEP));
  PetscFunctionReturn(0);
}

PetscErrorCode CSFlowLoopSolve(CSFlowLoop *L, void *flow)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(L->event_solve, 0, 0, 0, 0));
  PetscCall(Start(L, flow));
  while (!L->reason) PetscCall(CSFlowLoopStep(L, flow));
  PetscCall(Monitor(L, flow, CS_FLOW_EVENT_END));
  PetscCall(PetscLogEventEnd(L->event_solve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
