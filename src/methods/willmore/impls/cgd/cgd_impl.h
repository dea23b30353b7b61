/* Private to the kinds built on CGD's step (impls/cgd, gd, newton, trianglefield): the step of soliman2021
   Algorithm 1 line 11 and CGD's dual-step schedule. */
#ifndef CS_WILLMORE_CGD_IMPL_H
#define CS_WILLMORE_CGD_IMPL_H
#include "../../willmore_impl.h"

/* -t_mu_final: a fixed dual step once the EL residual is small (cgd_dual_step.c). A kind whose ops are CSWFGrowCGD,
   CSWFShrinkCGD, CSWFDualStepGetSwitch or CSWFDualStepSetSwitch has a CSWFDualStep as the FIRST member of its
   F->data (as PETSc's derived types begin with their base struct): those ops find it there. */
typedef struct {
  PetscReal final, final_el; /* -t_mu_final (0: off; size-scaled by CSWFDualStepScale), -t_mu_final_el */
  PetscBool final_on;        /* the switch fired (stored in checkpoints) */
  PetscInt  final_from;      /* the switch is armed from this iteration on (a kind's relaxed phase before) */
  PetscBool tmu_default;     /* -t_mu not given: the kind's default (ops.tmu_ratio t), checked against the start */
} CSWFDualStep;

/* CGD's data (cgd, gd): the dual step first, then the least-squares multipliers (cgd_multiplier_ls.c) */
typedef struct {
  CSWFDualStep ds;
  PetscInt     ls_every, ls_count; /* -multiplier_ls_every K (0: off), estimates made */
  PetscReal    ls_tmu;             /* -multiplier_ls_t_mu: t_mu (with t = 1) of its projection and least-squares solve */
} CSWF_CGD;

PETSC_INTERN void           CSWFDualStepInitialize(CSWFDualStep *ds);
PETSC_INTERN PetscErrorCode CSWFDualStepSetFromOptions(CSWillmoreFlow F, CSWFDualStep *ds, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSWFDualStepCheck(CSWillmoreFlow F, CSWFDualStep *ds);
PETSC_INTERN void           CSWFDualStepScale(CSWFDualStep *ds, PetscReal sc);
PETSC_INTERN PetscErrorCode CSWFDualStepDefault(CSWillmoreFlow F, CSWFDualStep *ds);
PETSC_INTERN PetscErrorCode CSWFDualStepView(CSWillmoreFlow F, CSWFDualStep *ds, PetscViewer viewer);
PETSC_INTERN PetscErrorCode CSWFDualStepGetSwitch(CSWillmoreFlow F, PetscBool *on);
PETSC_INTERN PetscErrorCode CSWFDualStepSetSwitch(CSWillmoreFlow F, PetscBool on);
/* step sizes: ds NULL is a kind without the -t_mu_final switch */
PETSC_INTERN PetscErrorCode CSWFGrowDual(CSWillmoreFlow F, CSWFDualStep *ds);
PETSC_INTERN PetscErrorCode CSWFShrinkDual(CSWillmoreFlow F, CSWFDualStep *ds);
PETSC_INTERN PetscErrorCode CSWFGrowCGD(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFShrinkCGD(CSWillmoreFlow F);
/* cgd_step.c */
PETSC_INTERN PetscErrorCode CSWFTrialCGD(CSWillmoreFlow F, PetscBool *accept);
/* cgd_multiplier_ls.c */
PETSC_INTERN PetscErrorCode CSWFMultiplierLSOptions(CSWillmoreFlow F, CSWF_CGD *cgd, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSWFMultiplierLSCheck(CSWillmoreFlow F, CSWF_CGD *cgd);
PETSC_INTERN PetscErrorCode CSWFMultiplierLS(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFMultiplierLSRestore(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFAcceptCGD(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFSetUpCGD(CSWillmoreFlow F);
#endif
