/* Barycentric vertex dual areas: the diagonal Hodge star *0 of soliman2021 App. D (one third of each face). */
#include "cs_geometry.h"

/* a third of the face's area to each corner */
static void AddThirdArea(CSMesh m, const PetscReal *p, const CSFaceIter *F, PetscScalar *a)
{
  PetscReal an[3], A;
  CSTriangleAreaVector(F->c, an);
  A = CSVecNorm(an);
  for (int k = 0; k < 3; k++) a[F->v[k]] += A / 3;
}

PetscErrorCode CSGeometryVertexAreas(CSMesh m, Vec x, Vec area)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscCall(CSGeometryFaceSum(m, x, m->dmV1, AddThirdArea, area));
  PetscCall(PetscLogEventEnd(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
