/* CGD's dual step t_mu after a step (soliman2021 Algorithm 1 with separate primal and dual steps, docs/willmore_flow.md):
   it follows t (or its own -t_mu_grow ramp) and, with -t_mu_final, is fixed large once the EL residual is small. Used
   by the kinds built on CGD's step (cgd, gd, trianglefield; newton without the switch); cgd_impl.h. */
#include "cgd_impl.h"
#include "cs_util.h"

/* -t_mu_final T: once an iterate's EL residual is below -t_mu_final_el, t_mu = max(t_mu, T) for the rest of the run. Why: CGD
   restores a direction of the rows with singular value s by ~ t t_mu s^2 / lambda_H per step (the Schur complement
   H/t + t_mu X^T I_Q^-1 X); at an isothermic surface (the Clifford torus of soliman2021 Fig. 16) one class direction
   has s ~ 1e-4, so with the default t_mu ~ 1e3 t the class stalls at ~1e-8 while EL -> 0. A large t_mu from the start
   seeds the unstable mode of a large change of class (options/flow_class_change.opts; a random start far from the
   class diverges), hence only near the end (docs/triangle_fields.md, "The class floor"). */
static PetscErrorCode FinalDualStep(CSWillmoreFlow F, CSWFDualStep *ds, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = PETSC_FALSE;
  if (!ds) PetscFunctionReturn(0);
  if (ds->final > 0 && !ds->final_on && F->it >= ds->final_from && F->el < ds->final_el) {
    ds->final_on = PETSC_TRUE;
    PetscCall(PetscPrintf(F->hdr.comm, "     iteration %" PetscInt_FMT ": EL residual %.3e below -%st_mu_final_el %g: the dual step t_mu is fixed from here on (-%st_mu_final; %g after the size scaling)\n", F->it, (double)F->el, F->hdr.prefix, (double)ds->final_el, F->hdr.prefix, (double)PetscMax(F->tmu, ds->final)));
  }
  *on = ds->final_on;
  PetscFunctionReturn(0);
}

void CSWFDualStepInitialize(CSWFDualStep *ds)
{
  ds->final      = 0; /* off */
  ds->final_el   = 1e-3;
  ds->final_on   = PETSC_FALSE;
  ds->final_from = 0;
  ds->tmu_default = PETSC_FALSE;
}

static PetscErrorCode CheckValues(CSWillmoreFlow F, const CSWFDualStep *ds)
{
  const CSOptionCheck checks[] = {
    {"t_mu_final", ds->final, ds->final >= 0, "use 0 (off) or a positive dual step"},
    {"t_mu_final_el", ds->final_el, ds->final_el > 0, "must be > 0"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(F->hdr.comm, F->hdr.prefix, sizeof(checks) / sizeof(checks[0]), checks));
  PetscFunctionReturn(0);
}

/* -t_mu_final, -t_mu_final_el (inside the flow's options block), in range */
PetscErrorCode CSWFDualStepSetFromOptions(CSWillmoreFlow F, CSWFDualStep *ds, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBeginUser;
  ds->tmu_default = (PetscBool)(F->tmu == 0); /* read before CheckOptions sets the default */
  PetscCall(CSOptionsReal("-t_mu_final", "CGD: once an iterate's EL residual is below -t_mu_final_el, the dual step t_mu is max(t_mu, this), fixed (0: off; in the units of t_mu; docs/triangle_fields.md, \"The class floor\")", NULL, ds->final, &ds->final, NULL));
  PetscCall(CSOptionsReal("-t_mu_final_el", "CGD: the EL residual below which -t_mu_final takes over", NULL, ds->final_el, &ds->final_el, NULL));
  PetscCall(CheckValues(F, ds));
  PetscFunctionReturn(0);
}

/* the switch acts on the rows of CGD's step: refused when there are none; called once they are set up (F->k known:
   cgd and gd from their ops.scale in SetUp; trianglefield, whose rows are always there, from its options check) */
PetscErrorCode CSWFDualStepCheck(CSWillmoreFlow F, CSWFDualStep *ds)
{
  const char *p = F->hdr.prefix;
  PetscFunctionBeginUser;
  PetscCheck(ds->final == 0 || F->conformal || F->k || F->ops.setup_problem, F->hdr.comm, PETSC_ERR_SUP, "-%st_mu_final: a dual step of CGD's rows, for -%stype cgd or trianglefield (or gd with constraints), not -%stype %s without constraint rows", p, p, p, F->type);
  PetscFunctionReturn(0);
}

/* given for unit-size meshes, as t_mu (CSWFSetUpScaling) */
void CSWFDualStepScale(CSWFDualStep *ds, PetscReal sc)
{
  ds->final /= sc;
}

/* The kind's default dual step (ops.tmu_ratio t: 1e5 t for cgd) is for a start on its constraints (soliman2021 Fig. 7;
   runs/study_dual_step.sh: with 1e3 t the bumpy torus's first steps hit the violation ceiling). A start off them by
   more than -vmax (a change of class, -target_mesh; a global row's target away from the input, the vesicle's volume)
   keeps 1e3 t: a large t_mu there makes the first steps Gauss-Newton on the constraints and the violation ceiling
   rejects them (options/flow_vesicle.opts stalled at t = 5e-6 with 1e5 t; docs/studies.md "The dual step"). Called
   once the rows and the size scaling are set up (ScaleCGD); t_mu is then in the units of the mesh. */
PetscErrorCode CSWFDualStepDefault(CSWillmoreFlow F, CSWFDualStep *ds)
{
  PetscReal conf, glob, ratio = F->ops.tmu_ratio;
  PetscFunctionBeginUser;
  if (!ds->tmu_default || ratio <= 1e3 || (!F->conformal && !F->k)) PetscFunctionReturn(0);
  PetscCall(CSWFEvalConstraints(F, F->x0, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
  if (!(PetscMax(conf, glob) > F->vmax)) PetscFunctionReturn(0);
  F->tmu *= 1e3 / ratio;
  F->tmu_ratio_max = 1e3 * F->tmu / F->t;
  PetscCall(PetscPrintf(F->hdr.comm, "flow %s: the start is off its constraints (violation %.3e > -%svmax %g): the default dual step is t_mu = 1e3 t, not %.0e t (-%st_mu sets it)\n", F->type, (double)PetscMax(conf, glob), F->hdr.prefix, (double)F->vmax, (double)ratio, F->hdr.prefix));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFDualStepView(CSWillmoreFlow F, CSWFDualStep *ds, PetscViewer viewer)
{
  PetscFunctionBeginUser;
  if (ds->final > 0) PetscCall(PetscViewerASCIIPrintf(viewer, "  dual step: t_mu fixed at max(t_mu, %g) once EL < %g (from iteration %" PetscInt_FMT ")\n", (double)ds->final, (double)ds->final_el, ds->final_from));
  PetscFunctionReturn(0);
}

/* ck[8] of the flow's checkpoint: t_mu >= T does not tell (t_mu may pass T before EL falls) */
PetscErrorCode CSWFDualStepGetSwitch(CSWillmoreFlow F, PetscBool *on)
{
  PetscFunctionBeginUser;
  *on = ((CSWFDualStep *)F->data)->final_on;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFDualStepSetSwitch(CSWillmoreFlow F, PetscBool on)
{
  PetscFunctionBeginUser;
  ((CSWFDualStep *)F->data)->final_on = on;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFGrowDual(CSWillmoreFlow F, CSWFDualStep *ds)
{
  PetscBool fixed;
  PetscReal r;
  PetscFunctionBeginUser;
  PetscCall(FinalDualStep(F, ds, &fixed));
  PetscCall(CSWFGrowStep(F, &r));
  if (fixed) F->tmu = PetscMax(F->tmu, ds->final); /* t_mu = max(t_mu, T): a ramp (-t_mu_grow) already above T is kept */
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
PetscErrorCode CSWFShrinkDual(CSWillmoreFlow F, CSWFDualStep *ds)
{
  PetscFunctionBeginUser;
  F->t *= CSWFStepModelShrink(F);
  if (F->tmu_grow == 0 && !(ds && ds->final_on)) F->tmu = PetscMin(F->tmu, F->tmu_ratio_max * F->t);
  PetscFunctionReturn(0);
}

/* the ops of the kinds whose data begin with a CSWFDualStep (cgd_impl.h) */
PetscErrorCode CSWFGrowCGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFGrowDual(F, (CSWFDualStep *)F->data));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFShrinkCGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFShrinkDual(F, (CSWFDualStep *)F->data));
  PetscFunctionReturn(0);
}

