/* Per-face areas as a dmF1 vector (faces are never ghosted: overlap 0). */
#include "cs_geometry.h"

PetscErrorCode CSGeometryFaceAreas(CSMesh m, Vec x, Vec area)
{
  Vec              xl;
  const PetscReal *p;
  PetscScalar     *a;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(VecGetArray(area, &a));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal an[3];
    CSTriangleAreaVector(F.c, an);
    a[F.f] = CSVecNorm(an);
  }
  PetscCall(VecRestoreArray(area, &a));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}
