/* Getters of the Bobenko-Schroeder flow object (include/cs_methods_bs.h). */
#include "bs_flow_impl.h"

PetscErrorCode CSBSFlowGetConvergedReason(CSBSFlow F, CSBSConvergedReason *reason)
{
  PetscFunctionBeginUser;
  *reason = F->reason;
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowGetSolution(CSBSFlow F, Vec *x)
{
  PetscFunctionBeginUser;
  *x = F->xmon ? F->xmon : F->x;
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowGetInitialSolution(CSBSFlow F, Vec *x0)
{
  PetscFunctionBeginUser;
  *x0 = F->x0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowGetMesh(CSBSFlow F, CSMesh *mesh)
{
  PetscFunctionBeginUser;
  *mesh = F->mesh;
  PetscFunctionReturn(0);
}

PetscErrorCode CSBSFlowGetEnergy(CSBSFlow F, CSEnergy *bs)
{
  PetscFunctionBeginUser;
  *bs = F->bs;
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
  *seconds = F->tsteps0 + (F->started && !F->finished ? now - F->tstart : 0);
  PetscFunctionReturn(0);
}
