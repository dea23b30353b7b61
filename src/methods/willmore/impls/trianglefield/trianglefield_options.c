/* -flow_type trianglefield (soliman2021 Algorithm 2): the kind's own options, read inside the flow's options block
   (ops.setfromoptions, after the shared ones), their checks after it (ops.setup) and its lines of
   CSWillmoreFlowView (ops.view). */
#include "trianglefield_impl.h"
#include "cs_util.h"

const char *const CSTriangleFieldVariables[] = {"omega", "spinor", NULL};
const char *const CSTriangleFieldInits[]     = {"df", "random", "random_spinor", "smooth", "CSTriangleFieldInit", "CS_TF_INIT_", NULL};

/* The start, the variables and the weights of the rows and of the spin regulariser. */
static PetscErrorCode FieldOptions(CSWillmoreFlow F, CSTriangleField *d, PetscOptionItems *PetscOptionsObject)
{
  PetscInt v = d->spinor;
  PetscFunctionBeginUser;
  PetscCall(CSOptionsEnum("-init", "Initial triangle field: df of the input, df plus a random field, S(l0, psi) with randomly rotated face spinors (App. C.2), or d(f + u) for a smooth random displacement u (plane waves)", NULL, CSTriangleFieldInits, (PetscEnum)d->init, (PetscEnum *)&d->init, NULL));
  PetscCall(CSOptionsEList("-variables", "Variables of the flow: the triangle field omega, or (u, psi) with omega = S_c(u, psi) (soliman2021 App. C.2)", NULL, CSTriangleFieldVariables, 2, CSTriangleFieldVariables[v], &v, NULL));
  d->spinor = (PetscBool)(v == 1);
  /* the spinor variables mix units (u dimensionless, psi ~ length^1/2): no power of the area makes their residual
     scale-free, so -flow_rtol tests it as it is unless -flow_el_norm is given (docs/willmore_flow.md "Stopping") */
  if (d->spinor && !F->el_norm_set) F->el_norm = CS_FLOW_EL_NORM_ABSOLUTE;
  PetscCall(CSOptionsReal("-scale_gauge_weight", "-flow_variables spinor: multiplier metric of the scale gauge row mean(u) = const, relative to its |row|^2; 0: no gauge row", NULL, d->wgauge, &d->wgauge, NULL));
  PetscCall(CSOptionsReal("-spinor_metric_shift", "-flow_variables spinor: add this times the mean psi diagonal of J^T I_H1 J to the whole metric (0: none)", NULL, d->mshift, &d->mshift, NULL));
  PetscCall(CSOptionsInt("-seed", "Seed of -flow_init random, random_spinor and smooth", NULL, d->seed, &d->seed, NULL));
  PetscCall(CSOptionsReal("-immersion_tol", "-o writes the Poisson reconstruction of omega only when its integrability violation is at most this (else it is no immersion of omega)", NULL, d->immersion_tol, &d->immersion_tol, NULL));
  PetscCall(CSOptionsReal("-init_amplitude", "-flow_init random: each halfedge vector gets a uniform random vector in [-a, a]^3 times the mean edge length; random_spinor: each face rotated by up to a pi; smooth: the largest vertex displacement is a times the mean edge length", NULL, d->amp, &d->amp, NULL));
  PetscCall(CSOptionsInt("-init_modes", "-flow_init smooth: number of random plane waves (wavelength the input's bounding-box diagonal) in the displacement", NULL, d->modes, &d->modes, NULL));
  PetscCall(CSOptionsReal("-spin_weight", "Weight of the spin Dirichlet energy E_tau(psi(omega)) added to W~ (soliman2021 App. C.3); 0: none", NULL, d->wspin, &d->wspin, NULL));
  PetscCall(CSOptionsReal("-restore_near_ceiling", "Project an accepted omega back onto its rows (Gauss-Newton, I_H1 metric) when its violation exceeds this times -flow_vmax (0: only -flow_restore_above / -flow_restore_stalled)", NULL, d->restore_near, &d->restore_near, NULL));
  PetscCall(CSOptionsReal("-integrability_weight", "Multiplier metric of the integrability rows (d1 omega, face closure, <<Y_i|omega>>) relative to their size; small = stiff", NULL, d->wint, &d->wint, NULL));
  PetscFunctionReturn(0);
}

/* ops.setfromoptions: inside the flow's options block, after the shared options. */
PetscErrorCode CSTFSetFromOptions(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  /* the resolution guard (-flow_max_area_ratio, read with the shared options) measures the reconstructed surface
     (CSTFEvaluate): opt-in for this kind, since a change of class (Fig. 8's spiky sphere to the round class)
     squeezes on purpose */
  if (!F->max_area_ratio_set) F->max_area_ratio = 0;
  PetscCall(CSWFDualStepSetFromOptions(F, &d->ds, PetscOptionsObject)); /* CGD's -t_mu_final (cgd_impl.h) */
  PetscOptionsHeadBegin(PetscOptionsObject, "Triangle-field flow (soliman2021 Algorithm 2)");
  PetscCall(FieldOptions(F, d, PetscOptionsObject));
  PetscOptionsHeadEnd();
  PetscCall(CSTFScheduleSetFromOptions(F, d, PetscOptionsObject));
  PetscCall(CSTFContinuationSetFromOptions(F, d, PetscOptionsObject));
  PetscCall(CSTFStepCapSetFromOptions(F, d, PetscOptionsObject));
  PetscFunctionReturn(0);
}

/* ops.setup: the values read above, in range and consistent with each other (after the flow's options block). */
PetscErrorCode CSTFCheckOptions(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  const char      *p = F->hdr.prefix;
  PetscFunctionBeginUser;
  PetscCall(CSWFDualStepCheck(F, &d->ds));
  PetscCall(CSTFScheduleCheck(F, d));
  PetscCall(CSTFContinuationCheck(F, d));
  PetscCall(CSTFStepCapCheck(F, d));
  /* -flow_t_mu_final is armed once the rows are enforced (SetUp); a continuation's stages end at small EL residuals */
  PetscCheck(d->ds.final == 0 || d->wdecay == 1, F->hdr.comm, PETSC_ERR_SUP, "-%st_mu_final with -%sspin_weight_decay %g: the switch would fire at the end of the first stage of the continuation; use one or the other", p, p, (double)d->wdecay);
  PetscCheck(d->restore_near >= 0 && !PetscIsInfOrNanReal(d->restore_near), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%srestore_near_ceiling %g: must be >= 0", p, (double)d->restore_near);
  PetscCheck(d->wint > 0 && !PetscIsInfOrNanReal(d->wint), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sintegrability_weight %g: must be > 0", p, (double)d->wint);
  PetscCheck(d->mshift >= 0 && !PetscIsInfOrNanReal(d->mshift), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sspinor_metric_shift %g: must be >= 0", p, (double)d->mshift);
  PetscCheck(d->wgauge >= 0 && !PetscIsInfOrNanReal(d->wgauge), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sscale_gauge_weight %g: must be >= 0", p, (double)d->wgauge);
  PetscCheck(d->wspin >= 0 && !PetscIsInfOrNanReal(d->wspin), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sspin_weight %g: must be >= 0", p, (double)d->wspin);
  /* the waves cost modes x vertices at the start; 1e4 is far more than a smooth displacement needs */
  PetscCheck(d->modes > 0 && d->modes <= 10000, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sinit_modes %" PetscInt_FMT ": must lie in [1, 10000]", p, d->modes);
  PetscCheck(d->immersion_tol >= 0 && !PetscIsInfOrNanReal(d->immersion_tol), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%simmersion_tol %g: must be a finite number >= 0", p, (double)d->immersion_tol);
  PetscCheck(d->amp >= 0 && !PetscIsInfOrNanReal(d->amp), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sinit_amplitude %g: must be a finite number >= 0", p, (double)d->amp);
  PetscCheck(!d->spinor || d->init != CS_TF_INIT_SMOOTH, F->hdr.comm, PETSC_ERR_SUP, "-%sinit smooth: built for the omega variables, not -%svariables spinor (use df, random or random_spinor)", p, p);
  /* the spinor variables evaluate through their own path, which has no stages (rather refused than ignored) */
  PetscCheck(!d->spinor || d->wdecay == 1, F->hdr.comm, PETSC_ERR_SUP, "-%sspin_weight_decay %g: the spin-weight continuation is built for the omega variables, not -%svariables spinor", p, (double)d->wdecay, p);
  PetscFunctionReturn(0);
}

/* ops.view: the kind's parameters, below the flow's line. */
PetscErrorCode CSTFView(CSWillmoreFlow F, PetscViewer viewer)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPushTab(viewer));
  PetscCall(PetscViewerASCIIPrintf(viewer, "triangle field: variables %s, start %s (seed %" PetscInt_FMT ", amplitude %g), %" PetscInt_FMT " period rows, conformal rows %s\n", CSTriangleFieldVariables[d->spinor ? 1 : 0], CSTriangleFieldInits[d->init], d->seed, (double)d->amp, 3 * d->nforms, d->noconf ? "off" : "on"));
  PetscCall(PetscViewerASCIIPrintf(viewer, "integrability weight %g from iteration %" PetscInt_FMT " (%g before), spin weight %g (decay %g), restore near %g vmax, immersion tol %g, max area ratio %g\n", (double)d->wint, d->istart, (double)d->wrelax, (double)d->wspin, (double)d->wdecay, (double)d->restore_near, (double)d->immersion_tol, (double)F->max_area_ratio));
  if (d->cap_rises) PetscCall(PetscViewerASCIIPrintf(viewer, "step cap t_max halved after %" PetscInt_FMT " consecutive rises of el_residual at it with W flat to %g\n", d->cap_rises, (double)d->cap_wtol));
  if (d->cap_rejects) PetscCall(PetscViewerASCIIPrintf(viewer, "step cap t_max halved after %" PetscInt_FMT " consecutive iterations whose trial at it was rejected\n", d->cap_rejects));
  PetscCall(PetscViewerASCIIPopTab(viewer));
  PetscCall(CSWFDualStepView(F, &d->ds, viewer));
  PetscFunctionReturn(0);
}
