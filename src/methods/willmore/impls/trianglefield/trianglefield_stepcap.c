/* The step cap that learns from a sawtooth (issue 39, soliman2021 Fig. 15; docs/triangle_fields.md "Fig. 15"). CGD's
   step at t is a semi-implicit Euler step of the flow: a mode whose stability limit lies below -flow_t_max grows at
   t = t_max while W is flat (Kusner's Morin surface on 48 x 24 near the round sphere: el_residual +7 % per step at
   t = 4, W flat to 1e-10), until a rejection (a step at t / 2) cuts it and the halving rule grows t back: the flow saws
   and never converges (the drift rule stops it). After -flow_t_max_rises consecutive accepted steps at the cap that
   raised el_residual while W changed by at most -flow_t_max_rises_wtol (relative), the cap -flow_t_max is halved for
   the rest of the run (t_mu is kept: it sets how strongly the multipliers act, as after a rejection). */
#include "trianglefield_impl.h"
#include "cs_util.h"

/* inside the flow's options block (CSTFSetFromOptions) */
PetscErrorCode CSTFStepCapSetFromOptions(CSWillmoreFlow F, CSTriangleField *d, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Triangle-field step cap (issue 39, Fig. 15)");
  PetscCall(CSOptionsInt("-t_max_rises", "Halve -flow_t_max for the rest of the run after this many consecutive accepted steps at t_max that raised el_residual while W stayed flat (a mode the step amplifies); 0: never", NULL, d->cap_rises, &d->cap_rises, NULL));
  PetscCall(CSOptionsInt("-t_max_rejects", "Halve -flow_t_max for the rest of the run after this many consecutive iterations whose first trial, at t_max, was rejected (every step at the cap fails, each iteration pays for it); 0: never", NULL, d->cap_rejects, &d->cap_rejects, NULL));
  PetscCall(CSOptionsReal("-t_max_rises_wtol", "-flow_t_max_rises: W is flat when it changed by at most this (relative) over the step", NULL, d->cap_wtol, &d->cap_wtol, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}

/* after the flow's options block (CSTFCheckOptions) */
PetscErrorCode CSTFStepCapCheck(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscFunctionBeginUser;
  PetscCheck(d->cap_rises >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%st_max_rises %" PetscInt_FMT ": must be >= 0 (0: off)", F->hdr.prefix, d->cap_rises);
  PetscCheck(d->cap_rejects >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%st_max_rejects %" PetscInt_FMT ": must be >= 0 (0: off)", F->hdr.prefix, d->cap_rejects);
  PetscCheck(d->cap_wtol >= 0 && !PetscIsInfOrNanReal(d->cap_wtol), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%st_max_rises_wtol %g: must be a finite number >= 0", F->hdr.prefix, (double)d->cap_wtol);
  PetscFunctionReturn(0);
}

/* Called after an accepted step, before t grows: F->E, F->el are those of the state the step started from (k), the
   record those of the state before it (k - 1) and the step size that led from k - 1 to k. A rejection in between
   (the step to k taken at t below the cap) resets the count. */
static PetscErrorCode Observe(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscBool atcap = (PetscBool)(d->cap_it == F->it - 1 && d->cap_t >= F->tmax);
  PetscBool flat  = (PetscBool)(PetscAbsReal(F->E - d->cap_E) <= d->cap_wtol * PetscAbsReal(F->E));
  PetscFunctionBeginUser;
  d->cap_n = atcap && flat && F->el > d->cap_el ? d->cap_n + 1 : 0;
  d->cap_E  = F->E;
  d->cap_el = F->el;
  d->cap_t  = F->t; /* the step from k just accepted */
  d->cap_it = F->it;
  if (!d->cap_rises || d->cap_n < d->cap_rises) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(F->hdr.comm, "flow: the step cap -%st_max is lowered %g -> %g at iteration %" PetscInt_FMT ": %" PetscInt_FMT " consecutive steps at t_max raised el_residual (to %.3e) while W changed by at most %g per step (-%st_max_rises %" PetscInt_FMT ", -%st_max_rises_wtol %g)\n", F->hdr.prefix, (double)F->tmax, (double)(0.5 * F->tmax), F->it, d->cap_n, (double)F->el, (double)d->cap_wtol, F->hdr.prefix, d->cap_rises, F->hdr.prefix, (double)d->cap_wtol));
  F->tmax *= 0.5;
  d->cap_n = 0;
  d->cap_lowered++;
  PetscFunctionReturn(0);
}

/* The other sawtooth: every trial at the cap is rejected and the step accepted below it, so no two steps at the cap
   are accepted in a row and Observe never counts. The stretched level-2 icosphere at -flow_t_max 8 (the stand-in of
   tests/cases/trianglefield_step_cap.sh) paid one rejected solve in 136 of 150 iterations and ended at max_it with the
   EL cycling between 2.5e-6 and 7.3e-6. After -flow_t_max_rejects such iterations in a row the cap is halved: the
   accepted steps were below it anyway, and the rejected trials stop. */
static PetscErrorCode ObserveRejects(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscBool rejected_at_cap = (PetscBool)(F->it > 0 && d->cap_tnext >= F->tmax && F->rejections > d->cap_rej0);
  PetscFunctionBeginUser;
  d->cap_nrej = rejected_at_cap ? d->cap_nrej + 1 : 0;
  d->cap_rej0 = F->rejections;
  if (!d->cap_rejects || d->cap_nrej < d->cap_rejects) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(F->hdr.comm, "flow: the step cap -%st_max is lowered %g -> %g at iteration %" PetscInt_FMT ": the trial at t_max was rejected in %" PetscInt_FMT " consecutive iterations (-%st_max_rejects %" PetscInt_FMT ")\n", F->hdr.prefix, (double)F->tmax, (double)(0.5 * F->tmax), F->it, d->cap_nrej, F->hdr.prefix, d->cap_rejects));
  F->tmax *= 0.5;
  d->cap_nrej = 0;
  d->cap_n    = 0;
  d->cap_lowered++;
  PetscFunctionReturn(0);
}

/* ops.grow of the kind: the observations, then CGD's step sizes (t to the possibly lowered cap, t_mu kept there) */
PetscErrorCode CSTFGrow(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  PetscCall(Observe(F, d));
  PetscCall(ObserveRejects(F, d));
  PetscCall(CSWFGrowCGD(F));
  d->cap_tnext = F->t;
  PetscFunctionReturn(0);
}
