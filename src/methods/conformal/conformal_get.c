/* Getters of the conformal flow object (include/cs_methods_conformal.h). */
#include "conformal_impl.h"

CS_OBJECT_GETTER(CSConformalFlow, ConvergedReason, CSConformalFlowConvergedReason, loop.reason)
CS_OBJECT_GETTER(CSConformalFlow, Solution, Vec, x)
CS_OBJECT_GETTER(CSConformalFlow, InitialSolution, Vec, x0)
CS_OBJECT_GETTER(CSConformalFlow, Mesh, CSMesh, mesh)

PetscErrorCode CSConformalFlowGetFields(CSConformalFlow F, Vec *H, Vec *rhodot)
{
  PetscFunctionBeginUser;
  if (H) *H = F->H;
  if (rhodot) *rhodot = F->v;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowGetQuasiConformal(CSConformalFlow F, Vec q)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryQuasiConformal(F->mesh, F->x0, F->x, q, NULL, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowGetInfo(CSConformalFlow F, CSConformalFlowInfo *info)
{
  PetscFunctionBeginUser;
  info->state         = F->s;
  info->W_initial     = F->W0;
  info->tau           = F->tau;
  info->filter_sigma  = F->sigma;
  info->filter_k      = F->fk;
  info->inversion     = F->inversion;
  info->mobius        = F->mobius;
  info->exactness     = (PetscBool)(F->exactness && F->ng > 0);
  info->genus         = F->mesh->topo.genus;
  info->closing_max   = F->closing_max;
  info->q_step_max    = F->q_step_max;
  info->setup_seconds = F->loop.t_setup;
  info->step_seconds  = F->loop.t_steps;
  PetscFunctionReturn(0);
}
