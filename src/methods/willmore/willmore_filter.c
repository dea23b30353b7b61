/* Acceptance of a trial point xt (the step control; docs/willmore_flow.md):
     PGD:    E does not increase (after the projection back onto the constraint set).
     CGD/GD: a two-criteria filter on the Lagrangian with the updated multipliers
               L(f) = E(f) + <mu+dmu, c(f)> + <nu+dnu, xi(f)>   (+ rho/2 |c|^2 with -flow_merit_rho, default 0)
             and the violation v(f) = max(||c(f)||_inf, max_j |xi_j(f)|): rejected when L increases and (v increases
             or f was feasible, v(f) <= ctol), or v exceeds max(v(f), -flow_vmax).
   Without step control only a non-finite state is rejected: the last good state must survive. */
#include "willmore_impl.h"

static PetscErrorCode Rejected(CSWillmoreFlow F, const char what[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: %s with t = %g; halving t\n", what, (double)F->t));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFCheckFinite(CSWillmoreFlow F, PetscBool *accept)
{
  PetscReal Et;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyValue(F->energy, F->xt, &Et));
  *accept = (PetscBool)!PetscIsInfOrNanReal(Et);
  if (!*accept) PetscCall(Rejected(F, "the energy is not finite"));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFFilterEnergy(CSWillmoreFlow F, PetscBool *accept)
{
  PetscReal Et, E = F->E;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyValue(F->energy, F->xt, &Et));
  /* a relative slack of 1e-12 lets converged iterates (changes at round-off level) pass */
  *accept = (PetscBool)!(!(Et == Et) || Et > E + 1e-12 * PetscAbsReal(E));
  if (!*accept) PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: energy %.15g -> %.15g with t = %g; halving t\n", (double)E, (double)Et, (double)F->t));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFFilterLagrangian(CSWillmoreFlow F, PetscBool *accept)
{
  PetscReal v0, vt, ca, cb, L0, Lt, Et;
  PetscInt  why = 0;
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecWAXPY(F->mun, 1.0, F->dmu, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nun[j] = F->nu[j] + F->dnu[j];
  PetscCall(CSWFMerit(F, F->E, F->c, F->cx, F->nun, &L0));
  PetscCall(CSWFViolation(F, F->c, F->cx, &ca, &cb));
  v0 = PetscMax(ca, cb);
  PetscCall(CSEnergyValue(F->energy, F->xt, &Et));
  PetscCall(CSWFEvalConstraints(F, F->xt, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(CSWFMerit(F, Et, F->ct, F->cxt, F->nun, &Lt));
  PetscCall(CSWFViolation(F, F->ct, F->cxt, &ca, &cb));
  vt = PetscMax(ca, cb);
  /* the relative slack 1e-12 (and ctol on v) lets converged iterates, changing at round-off level, pass */
  if (!(Lt == Lt) || !(vt == vt)) why = CS_WF_REJECT_CEILING | CS_WF_REJECT_LAGRANGIAN; /* no model: halved */
  if (Lt > L0 + 1e-12 * PetscAbsReal(L0) && (vt > v0 + F->ctol || v0 <= F->ctol)) why |= CS_WF_REJECT_LAGRANGIAN;
  if (vt > PetscMax(v0, F->vmax)) why |= CS_WF_REJECT_CEILING;
  *accept = (PetscBool)!why;
  PetscCall(CSWFStepModelRecord(F, v0, vt, Lt - L0, why));
  if (!*accept) PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: %s: Lagrangian %.15g -> %.15g, violation %.3e -> %.3e (ceiling %.3e) with t = %g; %s\n", why == CS_WF_REJECT_CEILING ? "violation above the ceiling" : why == CS_WF_REJECT_LAGRANGIAN ? "the Lagrangian increases" : "both criteria", (double)L0, (double)Lt, (double)v0, (double)vt, (double)PetscMax(v0, F->vmax), (double)F->t, F->step_model == CS_WF_STEP_PREDICTIVE ? "t from the step model" : "halving t"));
  PetscFunctionReturn(0);
}
