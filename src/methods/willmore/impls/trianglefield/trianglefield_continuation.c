/* Continuation in the weight of the spin regulariser (soliman2021 App. C.3: "a small multiple of the spin Dirichlet
   energy" E_tau). The flow starts with w = -flow_spin_weight and minimises W~ + w E_tau; each time a stage is
   converged (el_residual < -flow_spin_stage_rtol and every row below -flow_spin_stage_ctol) or has run
   -flow_spin_stage_max_it iterations (0: no limit), w <- w * -flow_spin_weight_decay, and once w falls below
   -flow_spin_weight_min it is set to 0: the last stage is W~ alone, stopped by the flow's own rule (el < -flow_rtol,
   rows < -flow_ctol). So the regulariser steers the early, large moves away from pinch points (where it acts) and
   the final point is a critical point of W in the class, not of the regularised energy (docs/triangle_fields.md).
   The step filter compares the Lagrangian at the current state with the trial state under the same w, so a change
   of w between two steps needs no reset: the state is re-evaluated with the new w before the next step. */
#include "trianglefield_impl.h"
#include "cs_util.h"

/* inside the flow's options block (CSTFSetFromOptions) */
PetscErrorCode CSTFContinuationSetFromOptions(CSWillmoreFlow F, CSTriangleField *d, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Triangle-field spin-weight continuation (soliman2021 App. C.3)");
  PetscCall(CSOptionsReal("-spin_weight_decay", "Factor applied to -flow_spin_weight each time a stage converges (1: no continuation)", NULL, d->wdecay, &d->wdecay, NULL));
  PetscCall(CSOptionsReal("-spin_weight_min", "Below this the spin weight is set to 0 (the last stage is W alone)", NULL, d->wspin_min, &d->wspin_min, NULL));
  PetscCall(CSOptionsReal("-spin_stage_rtol", "el_residual at which a stage of the continuation is converged", NULL, d->stage_rtol, &d->stage_rtol, NULL));
  PetscCall(CSOptionsReal("-spin_stage_ctol", "Row violation below which a stage of the continuation may end", NULL, d->stage_ctol, &d->stage_ctol, NULL));
  PetscCall(CSOptionsInt("-spin_stage_max_it", "Iterations after which a stage ends even if not converged (0: no limit)", NULL, d->stage_maxit, &d->stage_maxit, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}

/* after the flow's options block (CSTFCheckOptions) */
PetscErrorCode CSTFContinuationCheck(CSWillmoreFlow F, CSTriangleField *d)
{
  const char *p = F->hdr.prefix;
  PetscFunctionBeginUser;
  PetscCheck(d->wdecay > 0 && d->wdecay <= 1, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sspin_weight_decay %g: must be in (0, 1]", p, (double)d->wdecay);
  PetscCheck(d->wspin_min >= 0 && !PetscIsInfOrNanReal(d->wspin_min), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sspin_weight_min %g: must be >= 0", p, (double)d->wspin_min);
  PetscCheck(d->stage_rtol > 0 && d->stage_ctol > 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sspin_stage_rtol, -%sspin_stage_ctol: must be > 0", p, p);
  PetscCheck(d->stage_maxit >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sspin_stage_max_it %" PetscInt_FMT ": must be >= 0", p, d->stage_maxit);
  PetscFunctionReturn(0);
}

/* After the evaluation at x (F->el, F->conf, F->glob, d->pinch, d->espin of the current w): end the stage if it is
   converged, *next = PETSC_TRUE when w changed (the caller re-evaluates). */
PetscErrorCode CSTFContinuationAdvance(CSWillmoreFlow F, CSTriangleField *d, PetscBool *next)
{
  PetscReal w = d->wspin;
  PetscBool conv, maxit;
  PetscFunctionBeginUser;
  *next = PETSC_FALSE;
  if (d->wdecay >= 1 || w <= 0) PetscFunctionReturn(0);
  conv  = (PetscBool)(F->el < d->stage_rtol && PetscMax(F->conf, F->glob) < d->stage_ctol);
  maxit = (PetscBool)(d->stage_maxit > 0 && F->it - d->stage_it0 >= d->stage_maxit);
  if (!conv && !maxit) PetscFunctionReturn(0);
  d->wspin = w * d->wdecay < d->wspin_min ? 0 : w * d->wdecay;
  d->stage_it0 = F->it;
  d->nstages++;
  PetscCall(PetscPrintf(F->hdr.comm, "flow: spin stage %" PetscInt_FMT " %s at iteration %" PetscInt_FMT " (w = %g): W~ + w E_tau = %.10g, E_tau = %.6g, el_residual %.3e, violation %.3e, pinch edges %" PetscInt_FMT "; w -> %g\n", d->nstages, conv ? "converged" : "ended (-flow_spin_stage_max_it)", F->it, (double)w, (double)F->E, (double)d->espin, (double)F->el, (double)PetscMax(F->conf, F->glob), d->pinch, (double)d->wspin));
  *next = PETSC_TRUE;
  PetscFunctionReturn(0);
}
