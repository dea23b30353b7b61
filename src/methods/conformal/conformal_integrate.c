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
  PetscCall(CSSpinGetEigenvalue(F->spin, &F->s.gamma, NULL));
  /* with a boundary condition only a positive scale: a rotation would turn the prescribed directions */
  PetscCall(CSSpinNormalize(F->spin, F->lambda, NULL, (PetscBool)(F->bmode == CS_CONFORMAL_BOUNDARY_NONE)));
  PetscCall(CSConformalFlowClosingError(F, &F->s.closing)); /* genus >= 1: the harmonic part of conj(lambda) df lambda */
  if (F->bmode == CS_CONFORMAL_BOUNDARY_FIXED) PetscCall(CSConformalFlowReconstructFixed(F)); /* VII, Sec. 6.3.2 */
  else PetscCall(CSSpinReconstruct(F->spin, F->x, F->lambda, F->x, F->xnew));           /* VII */
  PetscCall(CSConformalFlowNonExactResidual(F, F->xnew, &F->s.nonexact));
  PetscFunctionReturn(0);
}

/* Is the new surface resolved in double precision? (issue 13, man_cgal; docs/conformal_flow.md "man_cgal")
   A conformal map of a surface with long thin protrusions onto the sphere shrinks them exponentially in their
   length/width; a step whose shortest edge falls below min_edge times the bounding-box diagonal D carries its edge
   vectors (differences of coordinates of size D) to fewer than log10(min_edge / eps) digits, and the next
   curvature is rounding noise (man_cgal: 6.8e-17 D after step 2, NaN areas at step 3). Such a step, or one with a
   face of zero or non-finite area, is rejected: x is kept and the flow stops with reason "resolution". */
static PetscErrorCode Resolved(CSConformalFlow F, Vec x, PetscBool *ok)
{
  Vec       l, a;
  PetscReal lmin, amin, lo[3], hi[3], d2 = 0;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(F->mesh->dmE1, &l));
  PetscCall(DMGetGlobalVector(F->mesh->dmF1, &a));
  PetscCall(CSGeometryEdgeLengths(F->mesh, x, l));
  PetscCall(CSGeometryFaceAreas(F->mesh, x, a));
  PetscCall(VecMin(l, NULL, &lmin));
  PetscCall(VecMin(a, NULL, &amin));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmE1, &l));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmF1, &a));
  for (PetscInt d = 0; d < 3; d++) {
    PetscCall(VecStrideMin(x, d, NULL, &lo[d]));
    PetscCall(VecStrideMax(x, d, NULL, &hi[d]));
    d2 += (hi[d] - lo[d]) * (hi[d] - lo[d]);
  }
  F->edge_ratio = lmin / PetscSqrtReal(d2);
  *ok           = (PetscBool)(amin > 0 && PetscIsNormalReal(amin) && F->edge_ratio >= F->min_edge);
  PetscFunctionReturn(0);
}

/* Did the step move anything? (issue 36, item 7) The largest vertex displacement against the bounding-box diagonal
   of x: at 1e-13 or below the new surface is x up to rounding, and the W test (|W - W_prev| <= rtol W) would
   report convergence for a step that did nothing (a tau halved to nothing, rho = tau v below rounding). Unless v
   itself is zero relative to c H (a fixed point such as the round sphere: then the step rightly moves nothing). */
static PetscErrorCode Stalled(CSConformalFlow F, Vec x, Vec xnew, PetscBool *stalled)
{
  PetscReal d2 = 0, move;
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < 3; d++) {
    PetscReal lo, hi;
    PetscCall(VecStrideMin(x, d, NULL, &lo));
    PetscCall(VecStrideMax(x, d, NULL, &hi));
    d2 += (hi - lo) * (hi - lo);
  }
  PetscCall(VecWAXPY(F->work3, -1.0, x, xnew));
  PetscCall(VecNorm(F->work3, NORM_INFINITY, &move));
  *stalled = (PetscBool)(move <= 1e-13 * PetscSqrtReal(d2) && F->s.vnorm > 1e-8 * F->hfactor * PetscSqrtReal(F->s.EH));
  PetscFunctionReturn(0);
}

/* With -flow_max_nonexact eta_max > 0 (a safeguard, docs/conformal_flow.md "knot1"): a step whose non-exact
   residual exceeds eta_max is rejected and retried with tau / 2, at most max_halvings (<= 50) times, and not once
   tau / 2 underflows; s.tau reports the step taken. A step that Resolved() refuses is not taken (F->rejected; the
   state and its measures are kept); one that moved nothing is taken and stops the flow (F->stalled). */
PetscErrorCode CSConformalFlowIntegrate(CSConformalFlow F)
{
  PetscReal              tau = F->tau;
  CSConformalMonitorInfo s0  = F->s;
  PetscBool              ok  = PETSC_TRUE;
  PetscFunctionBeginUser;
  F->s.halvings = 0;
  PetscCall(Attempt(F, tau));
  while (F->max_nonexact > 0 && F->s.nonexact > F->max_nonexact && F->s.halvings < F->max_halvings && tau / 2 > 0) {
    tau /= 2;
    F->s.halvings++;
    PetscCall(Attempt(F, tau));
  }
  if (F->min_edge > 0) PetscCall(Resolved(F, F->xnew, &ok)); /* (0: off, nothing measured) */
  if (!ok) {
    PetscCall(PetscPrintf(F->hdr.comm, "conformal flow: step %" PetscInt_FMT " rejected: its shortest edge is %.2e of the diameter (-%smin_edge %g) or a face has no area; the surface's conformal factor is beyond double precision; the state of step %" PetscInt_FMT " is kept\n", F->loop.it + 1, (double)F->edge_ratio, F->hdr.prefix, (double)F->min_edge, F->loop.it));
    F->s        = s0;
    F->rejected = PETSC_TRUE;
    PetscFunctionReturn(0);
  }
  F->s.tau       = tau;
  F->closing_max = PetscMax(F->closing_max, F->s.closing);
  /* the step's own distortion (scale-invariant: before the area is restored) */
  PetscCall(CSGeometryQuasiConformal(F->mesh, F->x, F->xnew, NULL, &F->s.q_step, NULL));
  F->q_step_max = PetscMax(F->q_step_max, F->s.q_step);
  if (F->keep_area && F->bmode != CS_CONFORMAL_BOUNDARY_FIXED) { /* (the fixed boundary sets the scale) */
    PetscReal A, vol;
    PetscCall(CSGeometryAreaVolume(F->mesh, F->xnew, &A, &vol));
    PetscCheck(A > 0 && A == A, F->hdr.comm, PETSC_ERR_NOT_CONVERGED, "conformal flow: step %" PetscInt_FMT " produced a surface of area %g", F->loop.it + 1, (double)A);
    PetscCall(CSSpinRestoreArea(F->spin, F->x0, F->xnew));
  }
  PetscCall(Stalled(F, F->x, F->xnew, &F->stalled));
  if (F->stalled) PetscCall(PetscPrintf(F->hdr.comm, "conformal flow: step %" PetscInt_FMT " (tau %g) moved no vertex beyond rounding (1e-13 of the diameter) though the direction is not zero: stopping as stalled\n", F->loop.it + 1, (double)tau));
  PetscCall(VecCopy(F->xnew, F->x));
  PetscFunctionReturn(0);
}
