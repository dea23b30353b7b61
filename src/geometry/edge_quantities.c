/* Per-edge quantities: lengths and cotan weights (dmE1 vectors). */
#include "cs_geometry.h"

PetscErrorCode CSGeometryEdgeLengths(CSMesh m, Vec x, Vec l)
{
  Vec              xl, ll;
  const PetscReal *p;
  PetscScalar     *a;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(DMGetLocalVector(m->dmE1, &ll));
  PetscCall(VecGetArray(ll, &a));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscReal d[3];
    CSVecSub(p + 3 * m->edgeVert[2 * e + 1], p + 3 * m->edgeVert[2 * e], d);
    a[e] = CSVecNorm(d);
  }
  PetscCall(VecRestoreArray(ll, &a));
  PetscCall(DMLocalToGlobal(m->dmE1, ll, INSERT_VALUES, l));
  PetscCall(DMRestoreLocalVector(m->dmE1, &ll));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}

/* w_ij = (cot alpha + cot beta)/2: each face adds half the cotan of the corner opposite the edge. Faces of an
   edge may sit on two ranks, hence the additive local-to-global assembly. */
PetscErrorCode CSGeometryCotanWeights(CSMesh m, Vec x, Vec w)
{
  Vec              xl, wl;
  const PetscReal *p;
  PetscScalar     *a;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(DMGetLocalVector(m->dmE1, &wl));
  PetscCall(VecSet(wl, 0));
  PetscCall(VecGetArray(wl, &a));
  for (PetscInt f = 0; f < m->nf; f++) {
    const PetscInt  *v    = m->faceVert + 3 * f;
    const PetscReal *c[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    PetscReal        cot[3];
    CSTriangleCotans(c, cot);
    for (int k = 0; k < 3; k++) a[m->faceEdge[3 * f + k]] += 0.5 * cot[k];
  }
  PetscCall(VecRestoreArray(wl, &a));
  PetscCall(VecSet(w, 0));
  PetscCall(DMLocalToGlobal(m->dmE1, wl, ADD_VALUES, w));
  PetscCall(DMRestoreLocalVector(m->dmE1, &wl));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}
