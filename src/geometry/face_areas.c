/* Per-face areas as a dmF1 vector (faces are never ghosted: overlap 0, so each face's sum is its own area). */
#include "cs_geometry.h"

static void AddArea(CSMesh m, const PetscReal *p, const CSFaceIter *F, PetscScalar *a)
{
  PetscReal an[3];
  CSTriangleAreaVector(F->c, an);
  a[F->f] += CSVecNorm(an);
}

PetscErrorCode CSGeometryFaceAreas(CSMesh m, Vec x, Vec area)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryFaceSum(m, x, m->dmF1, AddArea, area));
  PetscFunctionReturn(0);
}
