/* Getters of the conformal flow object (include/cs_methods_conformal.h). */
#include "conformal_impl.h"

PetscErrorCode CSConformalFlowGetConvergedReason(CSConformalFlow F, CSConformalFlowConvergedReason *reason)
{
  PetscFunctionBeginUser;
  *reason = (CSConformalFlowConvergedReason)F->loop.reason;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowGetSolution(CSConformalFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  *x = F->x;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowGetInitialSolution(CSConformalFlow F, Vec *x0)
{
  PetscFunctionBeginUser;
  *x0 = F->x0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowGetMesh(CSConformalFlow F, CSMesh *mesh)
{
  PetscFunctionBeginUser;
  *mesh = F->mesh;
  PetscFunctionReturn(0);
}

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
