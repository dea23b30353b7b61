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

/* What the concentration that tripped the guard is, from what was measured (docs/real_meshes.md, 1):
   - FINS: a face whose quasi-conformal error against the input exceeds -flow_fin_q. With the cross ratios kept,
     a face changes shape only where the discrete conformal factor u jumps across it, so this is a few vertex stars
     blown out into large flat triangles (eight_cgal: q_max 4.9 at the stop, 120 after 150 PGD iterations at
     |c| < 1e-10): the discrete energy (soliman2021 Eq. 28) itself rewards it, unconstrained descent on the same
     mesh takes W below the smooth lower bound.
   - SQUEEZE: every face kept its shape and the three Moebius boosts are fixed (-flow_constraint_mobius): u varies
     smoothly over orders of magnitude, a genuine conformal squeeze toward a shape this mesh cannot resolve (the
     low-res bunny's ears toward the round sphere, the trefoil tube's outer bends: q_max 2.4 and 1.15).
   - SMOOTH: every face kept its shape, the Moebius gauge free: a squeeze or a slide along a Moebius orbit, to
     which the cross ratios are blind and along which the discrete W falls; -flow_constraint_mobius tells them apart. */
static CSWillmoreFlowDegeneration Classify(CSWillmoreFlow F)
{
  if (F->qmax > F->fin_q) return CS_WILLMORE_FLOW_DEGENERATION_FINS;
  return F->mobius ? CS_WILLMORE_FLOW_DEGENERATION_SQUEEZE : CS_WILLMORE_FLOW_DEGENERATION_SMOOTH;
}

static const char *DegenerationText(CSWillmoreFlowDegeneration d)
{
  switch (d) {
  case CS_WILLMORE_FLOW_DEGENERATION_FINS:
    return "fins: the conformal factor jumps across faces, a few vertex stars are blown out into large flat triangles, which the discrete Willmore energy (soliman2021 Eq. 28) rewards on this mesh; neither a Moebius slide nor constraint drift";
  case CS_WILLMORE_FLOW_DEGENERATION_SQUEEZE:
    return "a smooth conformal squeeze: every face keeps its shape and the Moebius gauge is fixed, so part of the surface is genuinely being shrunk (or blown up) by orders of magnitude toward a shape this mesh cannot resolve";
  default:
    return "a smooth concentration: every face keeps its shape; either a slide along a Moebius orbit, to which the cross ratios are blind and along which the discrete energy falls, or a genuine conformal squeeze (-flow_constraint_mobius fixes the Moebius gauge and tells them apart)";
  }
}

/* The resolution guard (-flow_max_area_ratio, docs/willmore_flow.md): sets *reason to DIVERGED_AREA when the total
   area has changed by more than the ratio, or to DIVERGED_MESH_DEGENERATE when the vertex areas relative to the input
   spread by more than it, and then says which concentration it measured (Classify); leaves it alone otherwise. */
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
    F->degeneration = Classify(F);
    PetscCall(PetscPrintf(F->comm, "flow: mesh resolution collapse at iteration %" PetscInt_FMT ": the vertex areas relative to the input spread by max(A/A0)/min(A/A0) = %g, beyond -%smax_area_ratio (%g), with the constraints %s (violation %.2e) and the largest quasi-conformal error of a face %.3g (-%sfin_q %g): %s. Stopping with this state; it is not a critical point and its energy is not trustworthy (docs/real_meshes.md; -%smax_area_ratio 0 disables this check)\n", it, (double)F->spread, F->prefix, (double)F->max_area_ratio, viol < 1e3 * F->ctol ? "met" : "NOT met", (double)viol, (double)F->qmax, F->prefix, (double)F->fin_q, DegenerationText(F->degeneration), F->prefix));
    *reason = CS_WILLMORE_FLOW_DIVERGED_MESH_DEGENERATE;
  }
  PetscFunctionReturn(0);
}
