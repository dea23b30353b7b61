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
  for (PetscInt f = 0; f < m->nf; f++) {
    const PetscInt  *v    = m->faceVert + 3 * f;
    const PetscReal *c[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    PetscReal        an[3];
    CSTriangleAreaVector(c, an);
    a[f] = CSVecNorm(an);
  }
  PetscCall(VecRestoreArray(area, &a));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}
