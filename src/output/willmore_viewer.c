/* The ParaView series of a Willmore flow (-viewer_dir DIR, -flow_viewer_every N and/or -flow_viewer_iterations
   i1,i2,...): one CSViewer for the run, so
   the steps written during the flow and the final state land in one DIR/series.pvd. With N = 0 (the default)
   only the final state is written, as before the flow had monitors. Every step carries the fields
   mean_curvature (|h|, pointwise, as -task info), vertex_area (point data), face_area and Q (cell data: the
   quasi-conformal error of each face against the flow's input, as the summary's q_max), el_residual (the
   Euler-Lagrange residual per vertex, a vector); constrained flows add the conformal multiplier's fields
   (AddMultiplierFields). */
#include "cs_output_willmore.h"
#include "cs_geometry.h"
#include "cs_linalg.h"
#include "cs_operators_lens.h"

struct _n_CSWillmoreViewer {
  CSViewer v;
  PetscInt every, last; /* last: the iteration of the last step written, -1 before any */
  PetscInt nits, its[32]; /* -flow_viewer_iterations: these iterations too (soliman2021 Fig. 16: 1, 10, 20, 30, 47) */
};

/* The conformal multiplier (constrained flows): vertex field conformal_force (soliman2021 Eq. 7, 8: the tension
   force of q, so grad E + conformal_force is the EL residual), face fields stress_direction (the principal
   direction of the stress tensor, Eq. 20, a line field: its sign is arbitrary), stress_max, stress_min. */
static PetscErrorCode AddMultiplierFields(CSWillmoreFlow flow, CSMesh mesh, CSViewer v, Vec x)
{
  Vec       q, force, dir, s1, s2;
  PetscInt  nf;
  PetscBool conformal;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetConformal(flow, &conformal));
  if (!conformal) PetscFunctionReturn(0);
  PetscCall(DMCreateGlobalVector(mesh->dmE1, &q));
  PetscCall(DMCreateGlobalVector(mesh->dmV3, &force));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &s1));
  PetscCall(VecDuplicate(s1, &s2));
  PetscCall(VecGetLocalSize(s1, &nf));
  PetscCall(VecCreateMPI(mesh->comm, 3 * nf, PETSC_DETERMINE, &dir));
  PetscCall(CSWillmoreFlowGetConformalMultiplier(flow, q, force));
  PetscCall(CSGeometryConformalStress(mesh, x, q, dir, s1, s2));
  PetscCall(CSViewerAddVertexField(v, "conformal_force", force));
  PetscCall(CSViewerAddFaceField(v, "stress_direction", dir));
  PetscCall(CSViewerAddFaceField(v, "stress_max", s1));
  PetscCall(CSViewerAddFaceField(v, "stress_min", s2));
  PetscCall(VecDestroy(&q));
  PetscCall(VecDestroy(&force));
  PetscCall(VecDestroy(&dir));
  PetscCall(VecDestroy(&s1));
  PetscCall(VecDestroy(&s2));
  PetscFunctionReturn(0);
}

/* The triangle field omega of -flow_type trianglefield as three face vector fields omega_0, omega_1, omega_2: in
   each face the halfedge vectors opposite its corners 0, 1, 2 (the triangle of the face, not glued to its
   neighbours: omega_a runs from corner a+1 to corner a+2). */
static PetscErrorCode AddTriangleField(CSWillmoreFlow flow, CSMesh mesh, CSViewer v)
{
  Vec omega, w[3];
  DM  dmH3;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetVariables(flow, &omega));
  PetscCall(CSLensCreateHalfedgeDM(mesh, 3, &dmH3));
  for (int a = 0; a < 3; a++) {
    char name[16];
    PetscCall(PetscSNPrintf(name, sizeof(name), "omega_%d", a));
    PetscCall(CSTriangleFieldFaceVectors(mesh, dmH3, omega, a, &w[a]));
    PetscCall(CSViewerAddFaceField(v, name, w[a]));
    PetscCall(VecDestroy(&w[a]));
  }
  PetscCall(DMDestroy(&dmH3));
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteStep(CSWillmoreFlow flow, CSWillmoreViewer V, PetscInt it)
{
  Vec    x, x0, h, hn, area, farea, q, r;
  CSMesh mesh;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(CSWillmoreFlowGetInitial(flow, &x0));
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(DMCreateGlobalVector(mesh->dmV3, &h));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &hn));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &area));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &farea));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &q));
  PetscCall(CSGeometryMeanCurvature(mesh, x, h));
  PetscCall(CSVecBlockNorms(h, 3, hn));
  PetscCall(CSGeometryVertexAreas(mesh, x, area));
  PetscCall(CSGeometryFaceAreas(mesh, x, farea));
  PetscCall(CSGeometryQuasiConformal(mesh, x0, x, q, NULL, NULL));
  PetscCall(CSViewerAddVertexField(V->v, "mean_curvature", hn));
  PetscCall(CSViewerAddVertexField(V->v, "vertex_area", area));
  PetscCall(CSViewerAddFaceField(V->v, "face_area", farea));
  PetscCall(CSViewerAddFaceField(V->v, "Q", q));
  {
    CSWillmoreFlowTriangleFieldInfo info;
    PetscBool                       tf;
    PetscCall(CSWillmoreFlowTriangleFieldGetInfo(flow, &info, &tf)); /* the kind's own getter: no test of its name */
    if (tf) PetscCall(AddTriangleField(flow, mesh, V->v)); /* its multipliers and residual live on halfedges */
    else {
      PetscCall(AddMultiplierFields(flow, mesh, V->v, x));
      PetscCall(CSWillmoreFlowGetResidual(flow, &r));
      PetscCall(CSViewerAddVertexField(V->v, "el_residual", r)); /* its norm is the reported EL residual */
    }
  }
  PetscCall(CSViewerWriteStep(V->v, x, (PetscReal)it));
  PetscCall(VecDestroy(&h));
  PetscCall(VecDestroy(&hn));
  PetscCall(VecDestroy(&area));
  PetscCall(VecDestroy(&farea));
  PetscCall(VecDestroy(&q));
  V->last = it;
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorViewer(CSWillmoreFlow flow, PetscInt it, void *ctx)
{
  CSWillmoreViewer V = (CSWillmoreViewer)ctx;
  PetscFunctionBeginUser;
  PetscBool listed = PETSC_FALSE;
  for (PetscInt k = 0; k < V->nits; k++) listed = (PetscBool)(listed || V->its[k] == it);
  if (((V->every > 0 && it % V->every == 0) || listed) && it != V->last) PetscCall(WriteStep(flow, V, it));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowMonitorViewerSet(CSWillmoreFlow flow, CSOutput *out, PetscInt every, CSWillmoreViewer *wv)
{
  CSMesh      mesh;
  const char *prefix;
  PetscBool   listed = PETSC_FALSE;
  PetscInt    its[32], nits = 32;
  PetscFunctionBeginUser;
  *wv = NULL;
  if (!out->has_viewer) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(CSWillmoreFlowGetOptionsPrefix(flow, &prefix));
  PetscOptionsBegin(mesh->comm, prefix, "ParaView series of the Willmore flow", "CSWillmoreFlowMonitorViewerSet");
  PetscCall(PetscOptionsIntArray("-viewer_iterations", "Also write these iterations i1,i2,... (with -viewer_dir)", "CSWillmoreFlowMonitorViewerSet", its, &nits, &listed));
  PetscOptionsEnd();
  if (!listed) nits = 0;
  /* checked before the context exists, so a refused list leaks nothing */
  for (PetscInt k = 0; k < nits; k++) PetscCheck(its[k] >= 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sviewer_iterations: iteration %" PetscInt_FMT " must be >= 0", prefix, its[k]);
  PetscCall(PetscNew(wv));
  (*wv)->every = every;
  (*wv)->last  = -1;
  (*wv)->nits  = nits;
  PetscCall(PetscArraycpy((*wv)->its, its, nits));
  PetscCall(CSViewerCreate(mesh, NULL, out->viewer_dir, &(*wv)->v));
  /* the context belongs to the caller (CSWillmoreFlowViewerFinish writes the final state with it) */
  if (every > 0 || (*wv)->nits) PetscCall(CSWillmoreFlowMonitorSet(flow, MonitorViewer, *wv, NULL));
  PetscFunctionReturn(0);
}

/* without writing the final state: a run refused before its first step (options not used) */
PetscErrorCode CSWillmoreFlowViewerDestroy(CSWillmoreViewer *wv)
{
  PetscFunctionBeginUser;
  if (!*wv) PetscFunctionReturn(0);
  PetscCall(CSViewerDestroy(&(*wv)->v));
  PetscCall(PetscFree(*wv));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowViewerFinish(CSWillmoreFlow flow, CSWillmoreViewer *wv)
{
  CSWillmoreFlowInfo i;
  PetscFunctionBeginUser;
  if (!*wv) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  if (i.it != (*wv)->last) PetscCall(WriteStep(flow, *wv, i.it));
  PetscCall(CSViewerDestroy(&(*wv)->v));
  PetscCall(PetscFree(*wv));
  PetscFunctionReturn(0);
}
