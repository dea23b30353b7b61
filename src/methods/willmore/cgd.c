/* -flow_type cgd: competitive gradient descent (soliman2021 Sec. 4.2, Algorithm 1) with the conformal
   constraint on by default. The primal step t and the dual step t_mu are separate (docs/willmore_flow.md). */
#include "willmore_impl.h"

/* x = xt done: restoration of a stalled state (projection.c), then the multipliers mu += dmu, nu += dnu. */
PetscErrorCode CSWFAcceptCGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->conformal || F->k) PetscCall(CSWFRestore(F, &F->kspits));
  if (F->conformal) PetscCall(VecAXPY(F->mu, 1.0, F->dmu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] += F->dnu[j];
  PetscCall(CSWFMultiplierLSRestore(F));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFGrowCGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->tmu_grow > 0) {
    /* a dual step ramped on its own (-flow_t_mu_grow): a large t_mu during the transient of a class change
       seeds an unstable mode (options/flow_class_change.opts) */
    if (F->t * F->grow <= F->tmax) F->t *= F->grow;
    F->tmu = PetscMin(F->tmu * F->tmu_grow, F->tmu_max);
  } else if (F->t * F->grow <= F->tmax) {
    F->t *= F->grow;
    F->tmu = PetscMin(PetscMin(F->tmu * F->grow, F->tmu_max), F->tmu_ratio_max * F->t);
  }
  PetscFunctionReturn(0);
}

/* A rejection halves t but not t_mu: t_mu sets how strongly the step restores the constraints (t t_mu
   X^T I_Q^-1 X against H in the Schur complement); each rejection doubles t_mu / t for good, up to
   tmu_ratio_max (docs/willmore_flow.md, docs/real_meshes.md). */
PetscErrorCode CSWFShrinkCGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->t *= 0.5;
  if (F->tmu_grow == 0) F->tmu = PetscMin(F->tmu, F->tmu_ratio_max * F->t);
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowCreate_CGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->ops.id        = 0;
  F->ops.conformal = PETSC_TRUE;
  F->ops.trial     = CSWFTrialCGD;
  F->ops.filter    = CSWFFilterLagrangian;
  F->ops.accept    = CSWFAcceptCGD;
  F->ops.grow      = CSWFGrowCGD;
  F->ops.shrink    = CSWFShrinkCGD;
  F->ops.dual      = CSWFMultiplierLS;
  PetscFunctionReturn(0);
}
