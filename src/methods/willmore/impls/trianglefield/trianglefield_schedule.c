/* When integrability is enforced (soliman2021 Fig. 8: "Enforcing integrability only near the end of the
   optimization then provides a richer set of paths"). The schedule acts on the multiplier metric of the lens
   rows d1 omega (Eq. 31) and the period rows <<Y_i|omega>> (Eq. 13): before iteration -flow_integrability_start
   they get the weight -flow_integrability_relaxed_weight (default 1e4, against the stiff 1e-4 after) and the step
   filter's violation ceiling is lifted (CSTFScheduleApply), so CGD's
   regularised dual block -I_Q/t_mu makes their multipliers step by t_mu/w * c ~ 0 and the rows barely act on
   the primal step (the Schur complement's t_mu X^T w^{-1} X term of these rows is 1e8 times weaker): the
   triangles move without having to glue. The face closure rows always keep the stiff weight: they make omega a
   triangle field (three halfedges per face summing to zero, Sec. 5.1), which the paper's variables are by
   construction. From the start iteration on, every row is stiff and the stopping rule (every row below
   -flow_ctol) applies as before; the default start 0 is the always-on schedule. */
#include "trianglefield_impl.h"
#include "cs_util.h"

/* inside the flow's options block (CSTFSetFromOptions) */
PetscErrorCode CSTFScheduleSetFromOptions(CSWillmoreFlow F, CSTriangleField *d, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Triangle-field integrability schedule (soliman2021 Fig. 8)");
  PetscCall(CSOptionsInt("-integrability_start", "Iteration from which the lens and period rows are enforced (before: relaxed weight); 0 = always", NULL, d->istart, &d->istart, NULL));
  PetscCall(CSOptionsReal("-integrability_relaxed_weight", "Multiplier metric of the lens and period rows before -flow_integrability_start (large = relaxed)", NULL, d->wrelax, &d->wrelax, NULL));
  PetscOptionsHeadEnd();
  PetscFunctionReturn(0);
}

/* after the flow's options block (CSTFCheckOptions) */
PetscErrorCode CSTFScheduleCheck(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscFunctionBeginUser;
  PetscCheck(d->istart >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sintegrability_start %" PetscInt_FMT ": must be >= 0", F->hdr.prefix, d->istart);
  PetscCheck(d->wrelax > 0 && !PetscIsInfOrNanReal(d->wrelax), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sintegrability_relaxed_weight %g: must be > 0", F->hdr.prefix, (double)d->wrelax);
  PetscFunctionReturn(0);
}

/* The weight of the lens and period rows at the current iteration. */
PetscReal CSTFIntegrabilityWeight(CSWillmoreFlow F, CSTriangleField *d)
{
  return F->it < d->istart ? d->wrelax : d->wint;
}

/* At every step: the step filter's violation ceiling -flow_vmax (a trial step whose violation exceeds max(v,
   vmax) is rejected) is lifted while the rows are relaxed, or the violation of the relaxed rows reaches it and t
   collapses (measured: the spiky sphere of options/trianglefield_spiky.opts sat at violation 1e-2 with t falling
   to 4e-6 in five steps); it is restored when integrability is switched on. */
void CSTFScheduleApply(CSWillmoreFlow F, CSTriangleField *d)
{
  if (d->vmax0 <= 0) d->vmax0 = F->vmax;
  F->vmax = F->it < d->istart ? PETSC_MAX_REAL : d->vmax0;
}
