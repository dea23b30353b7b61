/* -flow_type cgd: competitive gradient descent (soliman2021 Sec. 4.2, Algorithm 1) with the conformal
   constraint on by default. The primal step t and the dual step t_mu are separate (docs/willmore_flow.md). */
#include "cgd_impl.h"
#include "cs_util.h"

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

static PetscErrorCode SetFromOptionsCGD(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject)
{
  CSWF_CGD *cgd = (CSWF_CGD *)F->data;
  PetscFunctionBeginUser;
  PetscCall(CSWFDualStepSetFromOptions(F, &cgd->ds, PetscOptionsObject));
  PetscCall(CSWFMultiplierLSOptions(F, cgd, PetscOptionsObject));
  PetscFunctionReturn(0);
}

/* the options against the problem (gd calls it from its own; -t_mu_final is checked in ScaleCGD, with the rows) */
PetscErrorCode CSWFSetUpCGD(CSWillmoreFlow F)
{
  CSWF_CGD *cgd = (CSWF_CGD *)F->data;
  PetscFunctionBeginUser;
  PetscCall(CSWFMultiplierLSCheck(F, cgd));
  PetscFunctionReturn(0);
}

/* ops.scale runs in CSWillmoreFlowSetUp after CSWFSetUpConstraints: F->k, the global rows, is known here, and
   not yet when the options are checked (a gd run with -flow_constraint_volume has rows, and was refused) */
static PetscErrorCode ScaleCGD(CSWillmoreFlow F, PetscReal sc, PetscReal E0)
{
  CSWF_CGD *cgd = (CSWF_CGD *)F->data;
  PetscFunctionBeginUser;
  (void)E0;
  PetscCall(CSWFDualStepCheck(F, &cgd->ds));
  CSWFDualStepScale(&cgd->ds, sc);
  PetscCall(CSWFDualStepDefault(F, &cgd->ds));
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewCGD(CSWillmoreFlow F, PetscViewer viewer)
{
  CSWF_CGD *cgd = (CSWF_CGD *)F->data;
  PetscFunctionBeginUser;
  PetscCall(CSWFDualStepView(F, &cgd->ds, viewer));
  if (cgd->ls_every > 0) PetscCall(PetscViewerASCIIPrintf(viewer, "  least-squares multipliers every %" PetscInt_FMT " iterations (t_mu %g)\n", cgd->ls_every, (double)cgd->ls_tmu));
  PetscFunctionReturn(0);
}

/* the kind's strategy (willmore_impl.h), grouped: identity, the step, hooks, its own data and options */
static const struct _CSWillmoreFlowOps CGDOps = {
  .id = 0, .conformal = PETSC_TRUE,
  /* t_mu = 1e5 t: with 1e3 t the bumpy torus's first steps hit the violation ceiling and CGD fell behind PGD at equal
     iterations (soliman2021 Fig. 7); 1e4-1e6 t take every step (runs/study_dual_step.sh, docs/studies.md). A start
     off its constraints keeps 1e3 t (CSWFDualStepDefault) */
  .tmu_ratio = 1e5,
  .trial = CSWFTrialCGD, .filter = CSWFFilterLagrangian, .accept = CSWFAcceptCGD, .grow = CSWFGrowCGD, .shrink = CSWFShrinkCGD,
  .dual = CSWFMultiplierLS, .get_switch = CSWFDualStepGetSwitch, .set_switch = CSWFDualStepSetSwitch, .scale = ScaleCGD,
  .setfromoptions = SetFromOptionsCGD, .setup = CSWFSetUpCGD, .view = ViewCGD, .destroy = CSWFDestroyData,
};

PetscErrorCode CSWillmoreFlowCreate_CGD(CSWillmoreFlow F)
{
  CSWF_CGD *cgd;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&cgd));
  CSWFDualStepInitialize(&cgd->ds);
  cgd->ls_every         = 0;
  cgd->ls_tmu           = 1e12;
  F->data               = cgd;
  F->ops                = CGDOps;
  PetscFunctionReturn(0);
}
