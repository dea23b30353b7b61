/* Per-vertex unit directions: area-weighted vertex normals (the sum of the area vectors A_f N_f of the incident
   faces, normalised) and the boundary tangents of crane2011 Sec. 5.7. */
#include "cs_geometry.h"

/* Normalises every 3-block of the global dmV3 vector v that is not zero. */
static PetscErrorCode NormaliseBlocks(Vec v)
{
  PetscScalar *a;
  PetscInt     n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArray(v, &a));
  for (PetscInt i = 0; i < n / 3; i++) {
    PetscReal l = PetscSqrtReal(PetscSqr(PetscRealPart(a[3 * i])) + PetscSqr(PetscRealPart(a[3 * i + 1])) + PetscSqr(PetscRealPart(a[3 * i + 2])));
    if (l > 0)
      for (int d = 0; d < 3; d++) a[3 * i + d] /= l;
  }
  PetscCall(VecRestoreArray(v, &a));
  PetscFunctionReturn(0);
}

/* the face's area vector to each of its corners */
static void AddAreaVector(CSMesh m, const PetscReal *p, const CSFaceIter *F, PetscScalar *a)
{
  PetscReal an[3];
  CSTriangleAreaVector(F->c, an);
  for (int k = 0; k < 3; k++)
    for (int d = 0; d < 3; d++) a[3 * F->v[k] + d] += an[d];
}

/* the boundary half-edge i -> j in the counter-clockwise order of its only face: the outgoing tangent at i */
static void AddBoundaryEdge(CSMesh m, const PetscReal *p, const CSFaceIter *F, PetscScalar *a)
{
  for (int k = 0; k < 3; k++) {
    PetscInt i = F->v[k], j = F->v[(k + 1) % 3];
    if (m->edgeBoundary[F->e[(k + 2) % 3]])
      for (int d = 0; d < 3; d++) a[3 * i + d] += p[3 * j + d] - p[3 * i + d];
  }
}

PetscErrorCode CSGeometryVertexNormals(CSMesh m, Vec x, Vec N)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryFaceSum(m, x, m->dmV3, AddAreaVector, N));
  PetscCall(NormaliseBlocks(N));
  PetscFunctionReturn(0);
}

PetscErrorCode CSGeometryBoundaryTangents(CSMesh m, Vec x, Vec T)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryFaceSum(m, x, m->dmV3, AddBoundaryEdge, T));
  PetscCall(NormaliseBlocks(T));
  PetscFunctionReturn(0);
}
