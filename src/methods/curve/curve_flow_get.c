/* Setters and getters of the curve flow object (include/cs_methods_curve.h). */
#include "curve_flow_impl.h"

CS_OBJECT_GETTER(CSCurveFlow, ConvergedReason, CSCurveFlowConvergedReason, loop.reason)
CS_OBJECT_GETTER(CSCurveFlow, Curve, CSCurve, curve)


PetscErrorCode CSCurveFlowGetSolution(CSCurveFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  PetscCheck(F->loop.setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "CSCurveFlowGetSolution: call CSCurveFlowSetUp first");
  *x = F->x;
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowGetCurvature(CSCurveFlow F, Vec *kappa)
{
  PetscFunctionBeginUser;
  PetscCheck(F->loop.started, F->hdr.comm, PETSC_ERR_ORDER, "CSCurveFlowGetCurvature: no state evaluated yet (call CSCurveFlowStep or Solve)");
  *kappa = F->kappa;
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowGetInfo(CSCurveFlow F, CSCurveFlowInfo *info)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(info, sizeof(*info)));
  info->state           = F->s;
  info->state.event     = CS_CURVE_MONITOR_START;
  info->gap_max         = F->gap_max;
  info->distortion_max  = F->dist_max;
  info->energy_initial  = F->E0;
  info->length          = F->length;
  info->tau             = F->tau;
  info->turning_initial = F->turning0;
  info->setup_seconds   = F->loop.t_setup;
  info->step_seconds    = F->loop.t_steps;
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowSetTimeStep(CSCurveFlow F, PetscReal tau)
{
  PetscFunctionBeginUser;
  PetscCheck(tau > 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "CSCurveFlowSetTimeStep: tau %g must be > 0", (double)tau);
  F->tau = tau;
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowSetTolerances(CSCurveFlow F, PetscReal rtol, PetscInt max_it)
{
  PetscFunctionBeginUser;
  PetscCheck(rtol >= 0 && max_it >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "CSCurveFlowSetTolerances: rtol %g and max_it %" PetscInt_FMT " must be >= 0", (double)rtol, max_it);
  F->rtol        = rtol;
  F->loop.max_it = max_it;
  PetscFunctionReturn(0);
}
