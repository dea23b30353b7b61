/* -flow_type cgd: competitive gradient descent (soliman2021 Sec. 4.2, Algorithm 1) with the conformal
   constraint on by default. The primal step t and the dual step t_mu are separate (docs/willmore_flow.md). */
#include "../../willmore_impl.h"

/* x = xt done: restoration of a stalled state (willmore_projection.c), then the multipliers mu += dmu, nu += dnu. */
PetscErrorCode CSWFAcceptCGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->conformal || F->k) PetscCall(CSWFRestore(F, &F->kspits));
  if (F->conformal) PetscCall(VecAXPY(F->mu, 1.0, F->dmu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] += F->dnu[j];
  PetscCall(CSWFMultiplierLSRestore(F));
  PetscFunctionReturn(0);
}

/* -t_mu_final T: once an iterate's EL residual is below -t_mu_final_el, t_mu = max(t_mu, T) for the rest of the run. Why: CGD
   restores a direction of the rows with singular value s by ~ t t_mu s^2 / lambda_H per step (the Schur complement
   H/t + t_mu X^T I_Q^-1 X); at an isothermic surface (the Clifford torus of soliman2021 Fig. 16) one class direction
   has s ~ 1e-4, so with the default t_mu ~ 1e3 t the class stalls at ~1e-8 while EL -> 0. A large t_mu from the start
   seeds the unstable mode of a large change of class (options/flow_class_change.opts; a random start far from the
   class diverges), hence only near the end (docs/triangle_fields.md, "The class floor"). */
static PetscErrorCode FinalDualStep(CSWillmoreFlow F, PetscBool *on)
{
  PetscFunctionBeginUser;
  if (F->tmu_final > 0 && !F->tmu_final_on && F->it >= F->tmu_final_from && F->el < F->tmu_final_el) {
    F->tmu_final_on = PETSC_TRUE;
    PetscCall(PetscPrintf(F->comm, "     iteration %" PetscInt_FMT ": EL residual %.3e below -%st_mu_final_el %g: the dual step t_mu is fixed from here on (-%st_mu_final; %g after the size scaling)\n", F->it, (double)F->el, F->prefix, (double)F->tmu_final_el, F->prefix, (double)PetscMax(F->tmu, F->tmu_final)));
  }
  *on = F->tmu_final_on;
  PetscFunctionReturn(0);
}

/* t after an accepted step: times the step model's factor (willmore_step_model.c; -t_grow with -step_model halving), capped
   at -t_max (reached also when t_max is not t times a power of t_grow); *r is the factor t changed by (1 at t_max),
   which t_mu follows */
PetscErrorCode CSWFGrowStep(CSWillmoreFlow F, PetscReal *r)
{
  PetscReal f;
  PetscFunctionBeginUser;
  PetscCall(CSWFStepModelGrow(F, &f));
  if (F->t * f <= F->tmax) {
    F->t *= f;
    *r = f;
    PetscFunctionReturn(0);
  }
  *r   = F->t < F->tmax ? F->tmax / F->t : 1.0;
  F->t = F->tmax; /* t_max itself, not t * r, which may round past it */
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFGrowCGD(CSWillmoreFlow F)
{
  PetscBool fixed = PETSC_FALSE;
  PetscReal r;
  PetscFunctionBeginUser;
  PetscCall(FinalDualStep(F, &fixed));
  PetscCall(CSWFGrowStep(F, &r));
  if (fixed) F->tmu = PetscMax(F->tmu, F->tmu_final); /* t_mu = max(t_mu, T): a ramp (-t_mu_grow) already above T is kept */
  else if (F->tmu_grow > 0) {
    /* a dual step ramped on its own (-flow_t_mu_grow): a large t_mu during the transient of a class change
       seeds an unstable mode (options/flow_class_change.opts) */
    F->tmu = PetscMin(F->tmu * F->tmu_grow, F->tmu_max);
  } else if (r > 1 || F->grow == 1) F->tmu = PetscMin(PetscMin(F->tmu * r, F->tmu_max), F->tmu_ratio_max * F->t);
  PetscFunctionReturn(0);
}

/* A rejection shrinks t (halves it with -step_model halving; willmore_step_model.c) but not t_mu: t_mu sets how strongly
   the step restores the constraints (t t_mu X^T I_Q^-1 X against H in the Schur complement); each rejection raises
   t_mu / t for good, up to tmu_ratio_max (docs/willmore_flow.md, docs/real_meshes.md). */
PetscErrorCode CSWFShrinkCGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->t *= CSWFStepModelShrink(F);
  if (F->tmu_grow == 0 && !F->tmu_final_on) F->tmu = PetscMin(F->tmu, F->tmu_ratio_max * F->t);
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
