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

PetscErrorCode CSGeometryMeanEdgeLength(CSMesh m, Vec x, PetscReal *h)
{
  Vec         l;
  PetscScalar s;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(m->dmE1, &l));
  PetscCall(CSGeometryEdgeLengths(m, x, l));
  PetscCall(VecSum(l, &s));
  *h = PetscRealPart(s) / (PetscReal)m->Ne;
  PetscCall(VecDestroy(&l));
  PetscFunctionReturn(0);
}

/* w_ij = (cot alpha + cot beta)/2: each face adds half the cotan of the corner opposite the edge. Faces of an
   edge may sit on two ranks, hence the additive local-to-global assembly. */
static void AddHalfCotans(CSMesh m, const PetscReal *p, const CSFaceIter *F, PetscScalar *a)
{
  PetscReal cot[3];
  CSTriangleCotans(F->c, cot);
  for (int k = 0; k < 3; k++) a[F->e[k]] += 0.5 * cot[k];
}

PetscErrorCode CSGeometryCotanWeights(CSMesh m, Vec x, Vec w)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryFaceSum(m, x, m->dmE1, AddHalfCotans, w));
  PetscFunctionReturn(0);
}
