/* Barycentric vertex dual areas: the diagonal Hodge star *0 of soliman2021 App. D (one third of each face). */
#include "cs_geometry.h"

PetscErrorCode CSGeometryVertexAreas(CSMesh m, Vec x, Vec area)
{
  Vec              xl, al;
  const PetscReal *p;
  PetscScalar     *a;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(DMGetLocalVector(m->dmV1, &al));
  PetscCall(VecSet(al, 0));
  PetscCall(VecGetArray(al, &a));
  for (PetscInt f = 0; f < m->nf; f++) {
    const PetscInt  *v    = m->faceVert + 3 * f;
    const PetscReal *c[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    PetscReal        an[3], A;
    CSTriangleAreaVector(c, an);
    A = CSVecNorm(an);
    for (int k = 0; k < 3; k++) a[v[k]] += A / 3;
  }
  PetscCall(VecRestoreArray(al, &a));
  PetscCall(VecSet(area, 0));
  PetscCall(DMLocalToGlobal(m->dmV1, al, ADD_VALUES, area));
  PetscCall(DMRestoreLocalVector(m->dmV1, &al));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(PetscLogEventEnd(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
