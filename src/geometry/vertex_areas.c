/* Barycentric vertex dual areas: the diagonal Hodge star *0 of soliman2021 App. D (one third of each face). */
#include "cs_geometry.h"

PetscErrorCode CSGeometryVertexAreas(CSMesh m, Vec x, Vec area)
{
  Vec              xl;
  CSLocalSum       s;
  const PetscReal *p;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSLocalSumBegin(m->dmV1, &s));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal an[3], A;
    CSTriangleAreaVector(F.c, an);
    A = CSVecNorm(an);
    for (int k = 0; k < 3; k++) s.a[F.v[k]] += A / 3;
  }
  PetscCall(CSLocalSumEnd(&s, area));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(PetscLogEventEnd(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
