/* Getters of the Bobenko-Schroeder flow object (include/cs_methods_bs.h). */
#include "bs_flow_impl.h"

CS_OBJECT_GETTER(CSBSFlow, ConvergedReason, CSBSConvergedReason, loop.reason)
CS_OBJECT_GETTER(CSBSFlow, InitialSolution, Vec, x0)
CS_OBJECT_GETTER(CSBSFlow, Mesh, CSMesh, mesh)
CS_OBJECT_GETTER(CSBSFlow, Energy, CSEnergy, bs)

PetscErrorCode CSBSFlowGetSolution(CSBSFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  *x = F->xmon ? F->xmon : F->x;
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowGetInfo(CSBSFlow F, CSBSFlowInfo *info)
{
  PetscFunctionBeginUser;
  info->it       = F->it;
  info->rejected = F->rejected;
  info->W        = F->W;
  info->dt       = F->dt;
  info->bc       = F->bc;
  info->nfixed   = F->nfixed;
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowGetSchemeName(CSBSFlow F, const char *name[])
{
  PetscFunctionBeginUser;
  *name = F->scheme == CS_BS_SCHEME_SEMI ? "semi" : (F->problem == CS_BS_PROBLEM_STATIC ? "tao_static" : "tao_euler");
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowGetStepSeconds(CSBSFlow F, PetscLogDouble *seconds)
{
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  *seconds = F->tsteps0 + (F->loop.started && !F->finished ? now - F->tstart : 0);
  PetscFunctionReturn(0);
}
