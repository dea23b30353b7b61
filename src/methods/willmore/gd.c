/* -flow_type gd: Sobolev (H^2 or L2) gradient descent, soliman2021 Eq. GD: the CGD step without the conformal
   constraint (area / volume / point constraints still allowed). */
#include "willmore_impl.h"

static PetscErrorCode SetUpGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(!F->conformal, F->comm, PETSC_ERR_ARG_INCOMP, "-%stype gd is unconstrained Sobolev gradient descent: -%sconformal true is not allowed (use cgd or pgd)", F->prefix, F->prefix);
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowCreate_GD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->ops.id        = 2;
  F->ops.conformal = PETSC_FALSE;
  F->ops.setup     = SetUpGD;
  F->ops.trial     = CSWFTrialCGD;
  F->ops.filter    = CSWFFilterLagrangian;
  F->ops.accept    = CSWFAcceptCGD;
  F->ops.grow      = CSWFGrowCGD;
  F->ops.shrink    = CSWFShrinkCGD;
  PetscFunctionReturn(0);
}
