/* Table 1 steps V-VII of crane2013 on the current surface (rho^m = 0, Sec. 6.1): rho = tau v; the smallest
   eigenpair of (D - rho) lambda = gamma lambda (Eq. 5, App. G's per-vertex X) by the CSSpin object: by default
   one inverse-iteration step from lambda = 1 (the identity, the solution for rho = 0) with a factorisation of
   the current X - sigma M (Sec. 6.4.2: "a single power iteration ... identical to a single linear solve");
   lambda fixed up to its global right factor (CSSpinNormalize: the rotation closest to 1, unit mean |lambda|^2);
   the Poisson problem L f~ = div(conj(lambda) e lambda) (Eq. 6, CSSpinReconstruct) with the old vertex mean kept;
   then the input's area restored (W and Q are scale-invariant; -flow_keep_area false keeps |lambda|'s scale). */
#include "conformal_impl.h"

/* one attempt with step tau: V-VII into F->xnew (before the area is restored), the closing error and eta */
static PetscErrorCode Attempt(CSConformalFlow F, PetscReal tau)
{
  PetscFunctionBeginUser;
  PetscCall(VecAXPBY(F->rho, tau, 0, F->v)); /* V */
  PetscCall(CSConformalFlowBoundaryPrepare(F)); /* Sec. 6.3: V -> V~ on the boundary */
  PetscCall(CSSpinResetStart(F->spin));         /* lambda = 1 on the current surface */
  PetscCall(CSSpinSolveEigen(F->spin, F->x, CS_RHO_VERTEX, F->rho, F->lambda)); /* VI */
  F->s.gamma = F->spin->gamma;
  /* with a boundary condition only a positive scale: a rotation would turn the prescribed directions */
  PetscCall(CSSpinNormalize(F->spin, F->lambda, NULL, (PetscBool)(F->bmode == CS_CONFORMAL_BOUNDARY_NONE)));
  PetscCall(CSConformalFlowClosingError(F, &F->s.closing)); /* genus >= 1: the harmonic part of conj(lambda) df lambda */
  if (F->bmode == CS_CONFORMAL_BOUNDARY_FIXED) PetscCall(CSConformalFlowReconstructFixed(F)); /* VII, Sec. 6.3.2 */
  else PetscCall(CSSpinReconstruct(F->spin, F->x, F->lambda, F->x, F->xnew));           /* VII */
  PetscCall(CSConformalFlowNonExactResidual(F, F->xnew, &F->s.nonexact));
  PetscFunctionReturn(0);
}

/* With -flow_max_nonexact eta_max > 0 (a safeguard, docs/conformal_flow.md "knot1"): a step whose non-exact
   residual exceeds eta_max is rejected and retried with tau / 2, at most max_halvings times; s.tau reports the
   step taken. */
PetscErrorCode CSConformalFlowIntegrate(CSConformalFlow F)
{
  PetscReal tau = F->tau;
  PetscFunctionBeginUser;
  F->s.halvings = 0;
  PetscCall(Attempt(F, tau));
  while (F->max_nonexact > 0 && F->s.nonexact > F->max_nonexact && F->s.halvings < F->max_halvings) {
    tau /= 2;
    F->s.halvings++;
    PetscCall(Attempt(F, tau));
  }
  F->s.tau       = tau;
  F->closing_max = PetscMax(F->closing_max, F->s.closing);
  if (F->keep_area && F->bmode != CS_CONFORMAL_BOUNDARY_FIXED) { /* (the fixed boundary sets the scale) */
    PetscReal A, vol;
    PetscCall(CSGeometryAreaVolume(F->mesh, F->xnew, &A, &vol));
    PetscCheck(A > 0 && A == A, F->hdr.comm, PETSC_ERR_NOT_CONVERGED, "conformal flow: step %" PetscInt_FMT " produced a surface of area %g", F->loop.it + 1, (double)A);
    PetscCall(CSSpinRestoreArea(F->spin, F->x0, F->xnew));
  }
  PetscCall(VecCopy(F->xnew, F->x));
  PetscFunctionReturn(0);
}
