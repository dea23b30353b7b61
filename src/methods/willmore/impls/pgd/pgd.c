/* -flow_type pgd: projected gradient descent (soliman2021 Sec. 4.1): an explicit step in the H^2 metric
   tangent to the constraints, then a Gauss-Newton projection back onto the constraint set (willmore_projection.c). */
#include "../../willmore_impl.h"

static PetscErrorCode SetUpPGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(!F->target[0], F->comm, PETSC_ERR_ARG_INCOMP, "-%starget_mesh with -%stype pgd: PGD keeps the class of its input and cannot move to another class (soliman2021 Sec. 4.2); use cgd", F->prefix, F->prefix);
  PetscFunctionReturn(0);
}

/* PGD starts on the constraint set */
static PetscErrorCode StartPGD(CSWillmoreFlow F)
{
  PetscBool ok;
  PetscFunctionBeginUser;
  PetscCall(CSWFProject(F, F->x, &ok, &F->kspits_total));
  PetscCheck(ok, F->comm, PETSC_ERR_NOT_CONVERGED, "pgd: the initial projection onto the constraint set did not converge");
  PetscFunctionReturn(0);
}

/* PGD's multipliers are those of the last linearised problem */
static PetscErrorCode AcceptPGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecCopy(F->dmu, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] = F->dnu[j];
  PetscFunctionReturn(0);
}

/* t grows by -flow_t_grow up to -flow_t_max after an accepted step, halves after a rejected one (PGD, ALM) */
PetscErrorCode CSWFGrowPrimal(CSWillmoreFlow F)
{
  PetscReal r;
  PetscFunctionBeginUser;
  PetscCall(CSWFGrowStep(F, &r));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFShrinkPrimal(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->t *= 0.5;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowCreate_PGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->ops.id        = 1;
  F->ops.conformal = PETSC_TRUE;
  F->ops.projected = PETSC_TRUE;
  F->ops.setup     = SetUpPGD;
  F->ops.start     = StartPGD;
  F->ops.trial     = CSWFTrialPGD;
  F->ops.filter    = CSWFFilterEnergy;
  F->ops.accept    = AcceptPGD;
  F->ops.grow      = CSWFGrowPrimal;
  F->ops.shrink    = CSWFShrinkPrimal;
  PetscFunctionReturn(0);
}
