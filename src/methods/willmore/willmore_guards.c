/* The resolution guard (-flow_max_area_ratio): what it measures and when it stops the flow (docs/willmore_flow.md). */
#include "willmore_impl.h"
#include "cs_linalg.h"

/* The resolution measures of the surface x against the input x0 (positions): the total area relative to the input's,
   the spread max(A/A0)/min(A/A0) of the vertex areas and the largest quasi-conformal error of a face. A kind with its
   own variables passes its surface (trianglefield: the Poisson reconstruction of omega, issue 21). */
PetscErrorCode CSWFMeasureQualityOf(CSWillmoreFlow F, Vec x0, Vec x)
{
  PetscReal   amax, amin;
  PetscScalar atot;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryVertexAreas(F->mesh, x, F->areat));
  PetscCall(VecSum(F->areat, &atot));
  F->area_ratio = PetscRealPart(atot) / F->area0_total;
  PetscCall(VecPointwiseDivide(F->areat, F->areat, F->area0));
  PetscCall(VecMax(F->areat, NULL, &amax));
  PetscCall(VecMin(F->areat, NULL, &amin));
  F->spread = amin > 0 ? amax / amin : PETSC_INFINITY;
  PetscCall(CSGeometryQuasiConformal(F->mesh, x0, x, NULL, NULL, &F->qmax));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFMeasureQuality(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFMeasureQualityOf(F, F->x0, F->x));
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

/* W against 8 pi: Li-Yau (W >= 8 pi for a surface with a double point) and the torus sweep of issue 35 / docs/real_meshes.md
   (every squeeze stop measured so far had W > 8 pi; the fat torus class b = sqrt(3), W 21.33, settles). A reading,
   stated as one: the classes whose infimum needs a degenerating conformal factor end near or above 8 pi. */
static const char *ClassText(CSWillmoreFlow F, char buf[], size_t n)
{
  const PetscReal w8 = 8 * PETSC_PI;
  PetscInt        g  = F->mesh->topo.genus;
  if (g == 0) (void)PetscSNPrintf(buf, n, "W = %.4g on this genus-0 surface (conformal to the round sphere, whose W = 4 pi = 12.57 bounds every closed surface's from below): the conformal factor concentrates where this mesh cannot resolve it", (double)F->E);
  else if (F->E >= w8) (void)PetscSNPrintf(buf, n, "W = %.4g >= 8 pi = 25.13 on this genus-%" PetscInt_FMT " surface, as at every such stop measured so far: this conformal class's infimum of W appears to need a conformal factor that degenerates, which no fixed mesh carries (docs/real_meshes.md)", (double)F->E, g);
  else (void)PetscSNPrintf(buf, n, "W = %.4g < 8 pi = 25.13 on this genus-%" PetscInt_FMT " surface: a minimiser of the class may exist, and a finer or more regular mesh may get further (docs/real_meshes.md)", (double)F->E, g);
  return buf;
}

/* The guard's stop in one sentence: the mechanism measured (fins, or a smooth squeeze; the spread and q_max) and the
   class's W against 8 pi with the genus. */
static PetscErrorCode SayMechanism(CSWillmoreFlow F)
{
  char cls[400];
  PetscFunctionBeginUser;
  (void)ClassText(F, cls, sizeof(cls));
  if (F->degeneration == CS_WILLMORE_FLOW_DEGENERATION_FINS) PetscCall(PetscPrintf(F->hdr.comm, "flow: the surface is growing fins at iteration %" PetscInt_FMT ": the conformal factor jumps across faces (a face's quasi-conformal error is %.3g > -%sfin_q %g) and the vertex areas spread %.0fx against the input; %s.\n", F->it, (double)F->qmax, F->hdr.prefix, (double)F->fin_q, (double)F->spread, cls));
  else PetscCall(PetscPrintf(F->hdr.comm, "flow: the surface is squeezing conformally at iteration %" PetscInt_FMT ": the vertex areas spread %.0fx against the input while every face keeps its shape (q_max %.3g)%s; %s.\n", F->it, (double)F->spread, (double)F->qmax, F->degeneration == CS_WILLMORE_FLOW_DEGENERATION_SMOOTH ? ", or it slides along a Moebius orbit (the gauge is free)" : "", cls));
  PetscFunctionReturn(0);
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
    PetscCall(PetscPrintf(F->hdr.comm, "flow: the flow diverges at iteration %" PetscInt_FMT ": the total area is %g times the input's, beyond -%smax_area_ratio (%g). Stopping with this state; it is not a solution (try a smaller -%st_max, or a constraint target nearer the input)\n", it, (double)F->area_ratio, F->hdr.prefix, (double)F->max_area_ratio, F->hdr.prefix));
    *reason = CS_WILLMORE_FLOW_DIVERGED_AREA;
    PetscFunctionReturn(0);
  }
  if (!(F->spread <= F->max_area_ratio)) {
    F->degeneration = Classify(F);
    PetscCall(SayMechanism(F));
    PetscCall(PetscPrintf(F->hdr.comm, "flow: mesh resolution collapse at iteration %" PetscInt_FMT ": the vertex areas relative to the input spread by max(A/A0)/min(A/A0) = %g, beyond -%smax_area_ratio (%g), with the constraints %s (violation %.2e) and the largest quasi-conformal error of a face %.3g (-%sfin_q %g): %s. Stopping with this state; it is not a critical point and its energy is not trustworthy (docs/real_meshes.md; -%smax_area_ratio 0 disables this check)\n", it, (double)F->spread, F->hdr.prefix, (double)F->max_area_ratio, viol < 1e3 * F->ctol ? "met" : "NOT met", (double)viol, (double)F->qmax, F->hdr.prefix, (double)F->fin_q, DegenerationText(F->degeneration), F->hdr.prefix));
    *reason = CS_WILLMORE_FLOW_DIVERGED_MESH_DEGENERATE;
  }
  PetscFunctionReturn(0);
}

/* The geometric step control of unconstrained descent (-flow_max_step; gd, newton): a trial step is rejected
   (t halved) when it moves a vertex by more than max_step mean edge lengths or turns a face over. The energy
   filter alone accepts any step that lowers the discrete W, and a long step can land in a folded mesh whose
   discrete W happens to be lower: gd's first step at t = 1 took the R = 3 torus from area 118 to 30 and W from
   31.3 to 29.5, with a vertex-area spread of 9.5 (docs/willmore_flow.md "Unconstrained descent"). */
PetscErrorCode CSWFCheckStepGeometry(CSWillmoreFlow F, PetscBool *accept)
{
  PetscReal h, dmax;
  PetscInt  nfold;
  Vec       d, dn;
  PetscFunctionBeginUser;
  *accept = PETSC_TRUE;
  if (!(F->max_step > 0) && !F->fold_guard) PetscFunctionReturn(0);
  PetscCall(CSGeometryMeanEdgeLength(F->mesh, F->x, &h));
  PetscCall(VecDuplicate(F->x, &d));
  PetscCall(VecWAXPY(d, -1.0, F->x, F->xt));
  PetscCall(DMGetGlobalVector(F->mesh->dmV1, &dn));
  PetscCall(CSVecBlockNorms(d, 3, dn));
  PetscCall(VecMax(dn, NULL, &dmax));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmV1, &dn));
  PetscCall(VecDestroy(&d));
  PetscCall(CSGeometryFoldedFaces(F->mesh, F->x, F->xt, &nfold));
  if ((F->max_step > 0 && !(dmax <= F->max_step * h)) || nfold > 0) {
    *accept = PETSC_FALSE;
    PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: it moves a vertex by %.3g mean edge lengths (-%smax_step %g) and turns %" PetscInt_FMT " faces over, with t = %g; halving t\n", (double)(dmax / h), F->hdr.prefix, (double)F->max_step, nfold, (double)F->t));
  }
  PetscFunctionReturn(0);
}

/* The fold guard (-flow_fold_guard; on for gd and newton): *folded when
   - the enclosed volume of a closed surface has changed sign against the input (turned inside out), or
   - a face points against its orientation in the last accepted state (it turned over within one iteration: the
     trial steps are checked the same way by CSWFCheckStepGeometry, but a kind's accept hook, e.g. newton's
     tangential relaxation, moves the vertices after that check), or
   - an interior edge has become a crease of more than CS_WF_FOLD_CREASE degrees between its two faces' normals
     (the surface folds back on itself across it; creases already in the input do not count).
   A face that rotates smoothly with its neighbours is not a fold, however far it turns against the input: the
   low-res bunny's ears flatten and their faces point against their input directions after 16 uncapped gd
   iterations with every neighbour within 26 degrees (issue #19); the first uncapped, unguarded gd step on the
   R = 3 torus makes 384 edges with normals 180 degrees apart. Otherwise x is recorded as the last good state. */
#define CS_WF_FOLD_CREASE 150.0
PetscErrorCode CSWFCheckFolds(CSWillmoreFlow F, PetscBool *folded)
{
  PetscInt nfold, ncrease;
  PetscFunctionBeginUser;
  *folded = PETSC_FALSE;
  if (!F->fold_guard) PetscFunctionReturn(0);
  nfold = 0; /* the first state checked (the input, or a checkpoint's) has no accepted state before it */
  if (F->good_set) PetscCall(CSGeometryFoldedFaces(F->mesh, F->xgood, F->x, &nfold));
  PetscCall(CSGeometryCreasedEdges(F->mesh, F->x0, F->x, CS_WF_FOLD_CREASE, &ncrease));
  *folded = (PetscBool)(nfold > 0 || ncrease > 0 || (F->mesh->topo.boundary_loops == 0 && !(F->V * F->V0 > 0)));
  if (*folded) PetscCall(PetscPrintf(F->hdr.comm, "flow: the surface folds at iteration %" PetscInt_FMT ": enclosed volume %g (input %g), %" PetscInt_FMT " faces turned over since the last accepted state, %" PetscInt_FMT " new creases of more than %.0f degrees between neighbouring faces (-%sfold_guard). Stopping with the last good state\n", F->it, (double)F->V, (double)F->V0, nfold, ncrease, (double)CS_WF_FOLD_CREASE, F->hdr.prefix));
  else {
    PetscCall(VecCopy(F->x, F->xgood));
    F->good_set = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}
