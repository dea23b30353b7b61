/* Creases: interior edges whose two faces' unit normals make an angle beyond a threshold, i.e. the surface folds
   back on itself across the edge (a fold of the surface, not a smooth rotation of a region: issue #19). */
#include "cs_geometry.h"

/* Adds the unit normal of every local face in x (slots 0-2) and xref (slots 3-5) to its three edges. */
static PetscErrorCode AddFaceNormals(CSMesh m, Vec xref, Vec x, PetscScalar *a)
{
  Vec              xl, rl;
  const PetscReal *p, *r;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSMeshGetLocalPositions(m, xref, &rl, &r));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscReal *c0[3] = {r + 3 * F.v[0], r + 3 * F.v[1], r + 3 * F.v[2]};
    PetscReal        n[6], l, l0;
    CSTriangleAreaVector(F.c, n);
    CSTriangleAreaVector(c0, n + 3);
    l  = CSVecNorm(n);
    l0 = CSVecNorm(n + 3);
    for (int d = 0; d < 3; d++) {
      n[d]     = l > 0 ? n[d] / l : 0;
      n[3 + d] = l0 > 0 ? n[3 + d] / l0 : 0;
    }
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 6; d++) a[6 * F.e[k] + d] += n[d];
  }
  PetscCall(CSMeshRestoreLocalPositions(m, xref, &rl, &r));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSGeometryCreasedEdges(CSMesh m, Vec xref, Vec x, PetscReal angle, PetscInt *ncreased)
{
  DM         dmE6;
  CSLocalSum s;
  PetscInt   n = 0;
  /* |n1 + n2|^2 = 2 + 2 cos(angle between the normals) */
  const PetscReal lim = 2 + 2 * PetscCosReal(angle * PETSC_PI / 180);
  PetscFunctionBeginUser;
  PetscCall(CSMeshCreateFieldDM(m->dm, 1, 6, "crease_normals", &dmE6));
  PetscCall(CSLocalSumBegin(dmE6, &s));
  PetscCall(AddFaceNormals(m, xref, x, s.a));
  PetscCall(CSLocalSumShare(&s)); /* the two faces of an edge on a partition cut live on two ranks */
  for (PetscInt e = 0; e < m->ne; e++) {
    const PetscReal *a = (const PetscReal *)s.a + 6 * e;
    if (!m->edgeOwned[e] || m->edgeBoundary[e]) continue;
    if (CSVecDot(a, a) < lim && !(CSVecDot(a + 3, a + 3) < lim)) n++;
  }
  PetscCall(CSLocalSumEnd(&s, NULL));
  PetscCall(DMDestroy(&dmE6));
  PetscCall(MPIU_Allreduce(&n, ncreased, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscFunctionReturn(0);
}
