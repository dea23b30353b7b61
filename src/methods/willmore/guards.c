/* The resolution guard (-flow_max_area_ratio): what it measures and when it stops the flow (docs/willmore_flow.md). */
#include "willmore_impl.h"

PetscErrorCode CSWFMeasureQuality(CSWillmoreFlow F)
{
  PetscReal   amax, amin;
  PetscScalar atot;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryVertexAreas(F->mesh, F->x, F->areat));
  PetscCall(VecSum(F->areat, &atot));
  F->area_ratio = PetscRealPart(atot) / F->area0_total;
  PetscCall(VecPointwiseDivide(F->areat, F->areat, F->area0));
  PetscCall(VecMax(F->areat, NULL, &amax));
  PetscCall(VecMin(F->areat, NULL, &amin));
  F->spread = amin > 0 ? amax / amin : PETSC_INFINITY;
  PetscCall(CSGeometryQuasiConformal(F->mesh, F->x0, F->x, NULL, NULL, &F->qmax));
  PetscFunctionReturn(0);
}

/* The resolution guard (-flow_max_area_ratio, docs/willmore_flow.md): sets *reason to DIVERGED_AREA when the total
   area has changed by more than the ratio, or to DIVERGED_MESH_DEGENERATE when the vertex areas relative to the input
   spread by more than it; leaves it alone otherwise. The message says what was measured and what it can mean:
   the guard cannot tell a Moebius slide (closed surfaces, the top of this file) from the discrete problem's own
   degeneration on coarse or far-from-minimiser inputs, a few vertices driven out into large flat triangles
   or a part of the surface squeezed into a few triangles (docs/real_meshes.md), and both happen with the
   constraints met; viol says whether they are. */
PetscErrorCode CSWFCheckResolution(CSWillmoreFlow F, CSWillmoreFlowConvergedReason *reason)
{
  PetscInt  it   = F->it;
  PetscReal viol = PetscMax(F->conf, F->glob);
  PetscFunctionBeginUser;
  if (!(F->max_area_ratio > 0)) PetscFunctionReturn(0);
  if (!(F->area_ratio < F->max_area_ratio && F->area_ratio > 1 / F->max_area_ratio)) { /* e.g. a far-off volume target */
    PetscCall(PetscPrintf(F->comm, "flow: the flow diverges at iteration %" PetscInt_FMT ": the total area is %g times the input's, beyond -%smax_area_ratio (%g). Stopping with this state; it is not a solution (try a smaller -%st_max, or a constraint target nearer the input)\n", it, (double)F->area_ratio, F->prefix, (double)F->max_area_ratio, F->prefix));
    *reason = CS_WILLMORE_FLOW_DIVERGED_AREA;
    PetscFunctionReturn(0);
  }
  if (!(F->spread <= F->max_area_ratio)) {
    PetscCall(PetscPrintf(F->comm, "flow: mesh resolution collapse at iteration %" PetscInt_FMT ": the vertex areas relative to the input spread by max(A/A0)/min(A/A0) = %g, beyond -%smax_area_ratio (%g), with the constraints %s (violation %.2e) and the largest quasi-conformal error of a face %.3g. The discrete Willmore energy is being lowered by moving area between vertices, not only by changing the shape: either a slide along a Moebius orbit, to which the constraints are blind (-%sconstraint_mobius fixes the Moebius gauge), or part of the surface blown up into a few large flat triangles or squeezed into a few small ones, where the mesh no longer resolves it (see docs/real_meshes.md). Stopping with this state; its energy is not trustworthy (-%smax_area_ratio 0 disables this check)\n", it, (double)F->spread, F->prefix, (double)F->max_area_ratio, viol < 1e3 * F->ctol ? "met" : "NOT met", (double)viol, (double)F->qmax, F->prefix, F->prefix));
    *reason = CS_WILLMORE_FLOW_DIVERGED_MESH_DEGENERATE;
  }
  PetscFunctionReturn(0);
}
