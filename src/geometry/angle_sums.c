/* Sum of the corner angles of the faces at each vertex (the discrete Gauss curvature of an interior vertex is
   K_i = 2 pi - this sum; bobenko-schroeder2005 Sec. 2). */
#include "cs_geometry.h"

static void AddCornerAngles(CSMesh m, const PetscReal *p, const CSFaceIter *F, PetscScalar *a)
{
  for (int k = 0; k < 3; k++) {
    PetscReal u[3], v[3], w[3];
    CSVecSub(F->c[(k + 1) % 3], F->c[k], u);
    CSVecSub(F->c[(k + 2) % 3], F->c[k], v);
    CSVecCross(u, v, w);
    a[F->v[k]] += PetscAtan2Real(CSVecNorm(w), CSVecDot(u, v));
  }
}

PetscErrorCode CSGeometryAngleSums(CSMesh m, Vec x, Vec s)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryFaceSum(m, x, m->dmV1, AddCornerAngles, s));
  PetscFunctionReturn(0);
}
