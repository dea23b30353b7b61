/* -flow_type gd: Sobolev (H^2 or L2) gradient descent, soliman2021 Eq. GD: the CGD step without the conformal
   constraint (area / volume / point constraints still allowed). */
#include "../cgd/cgd_impl.h"

static PetscErrorCode SetUpGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(!F->conformal, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype gd is unconstrained Sobolev gradient descent: -%sconformal true is not allowed (use cgd or pgd)", F->hdr.prefix, F->hdr.prefix);
  PetscCall(CSWFSetUpCGD(F));
  PetscFunctionReturn(0);
}

/* The CGD step and its step control (and CGD's data, cgd_impl.h), without the conformal constraint. */
PetscErrorCode CSWillmoreFlowCreate_GD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowCreate_CGD(F));
  F->ops.id         = 2;
  F->ops.conformal  = PETSC_FALSE;
  F->ops.setup      = SetUpGD;
  F->ops.max_step   = 0.5; /* the geometric step control and the fold guard (willmore_guards.c) */
  F->ops.fold_guard = PETSC_TRUE;
  F->ops.tmu_ratio  = 0; /* t_mu = 1e3 t for its extra rows: cgd's 1e5 t was measured on the conformal rows only */
  PetscFunctionReturn(0);
}
