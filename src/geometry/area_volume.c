/* Total area and enclosed volume; both are sums over faces, and every face lives on exactly one rank. */
#include "cs_geometry.h"

PetscErrorCode CSGeometryAreaVolume(CSMesh m, Vec x, PetscReal *area, PetscReal *volume)
{
  Vec              xl;
  const PetscReal *p;
  PetscReal        s[2] = {0, 0}, g[2];
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal an[3], jk[3];
    CSTriangleAreaVector(F.c, an);
    s[0] += CSVecNorm(an);
    CSVecCross(F.c[1], F.c[2], jk);
    s[1] += CSVecDot(F.c[0], jk) / 6; /* soliman2021 App. B.2 */
  }
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MPIU_Allreduce(s, g, 2, MPIU_REAL, MPIU_SUM, m->comm));
  if (area) *area = g[0];
  if (volume) *volume = g[1];
  PetscFunctionReturn(0);
}

/* Total length of the boundary edges (crane2011 Sec. 7.3: area / length^2 of the disk flow); each boundary edge lies
   in one face, and every face on one rank. */
PetscErrorCode CSGeometryBoundaryLength(CSMesh mesh, Vec x, PetscReal *len)
{
  Vec              xl;
  const PetscReal *p;
  PetscReal        l = 0;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &p));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, p, &F);)
    for (int k = 0; k < 3; k++)
      if (mesh->edgeBoundary[F.e[k]]) {
        PetscReal e[3];
        CSVecSub(F.c[(k + 1) % 3], F.c[(k + 2) % 3], e);
        l += CSVecNorm(e);
      }
  PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &p));
  PetscCall(MPIU_Allreduce(&l, len, 1, MPIU_REAL, MPIU_SUM, mesh->comm));
  PetscFunctionReturn(0);
}
