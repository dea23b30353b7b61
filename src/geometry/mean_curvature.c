/* Mean curvature: Lf and h = 1/2 *0^{-1} L f (soliman2021 Eq. 27), computed face by face. */
#include "cs_geometry.h"

PetscErrorCode CSGeometryLaplacianPositions(CSMesh m, Vec x, Vec Lf, Vec area)
{
  Vec              xl, yl, al;
  const PetscReal *p;
  PetscScalar     *y, *a;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(DMGetLocalVector(m->dmV3, &yl));
  PetscCall(DMGetLocalVector(m->dmV1, &al));
  PetscCall(VecSet(yl, 0));
  PetscCall(VecSet(al, 0));
  PetscCall(VecGetArray(yl, &y));
  PetscCall(VecGetArray(al, &a));
  for (PetscInt f = 0; f < m->nf; f++) {
    const PetscInt  *v    = m->faceVert + 3 * f;
    const PetscReal *c[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    PetscReal        cot[3], an[3], A;
    CSTriangleCotans(c, cot);
    CSTriangleAreaVector(c, an);
    A = CSVecNorm(an);
    for (int k = 0; k < 3; k++) {
      int       i = (k + 1) % 3, j = (k + 2) % 3; /* edge ij opposite corner k */
      PetscReal w = 0.5 * cot[k];
      for (int d = 0; d < 3; d++) {
        PetscReal t = w * (c[i][d] - c[j][d]);
        y[3 * v[i] + d] += t;
        y[3 * v[j] + d] -= t;
      }
      a[v[k]] += A / 3;
    }
  }
  PetscCall(VecRestoreArray(yl, &y));
  PetscCall(VecRestoreArray(al, &a));
  if (Lf) {
    PetscCall(VecSet(Lf, 0));
    PetscCall(DMLocalToGlobal(m->dmV3, yl, ADD_VALUES, Lf));
  }
  if (area) {
    PetscCall(VecSet(area, 0));
    PetscCall(DMLocalToGlobal(m->dmV1, al, ADD_VALUES, area));
  }
  PetscCall(DMRestoreLocalVector(m->dmV3, &yl));
  PetscCall(DMRestoreLocalVector(m->dmV1, &al));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(PetscLogEventEnd(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSGeometryMeanCurvature(CSMesh m, Vec x, Vec h)
{
  Vec                area;
  PetscScalar       *ha;
  const PetscScalar *aa;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(m->dmV1, &area));
  PetscCall(CSGeometryLaplacianPositions(m, x, h, area));
  PetscCall(VecGetLocalSize(area, &n));
  PetscCall(VecGetArray(h, &ha));
  PetscCall(VecGetArrayRead(area, &aa));
  for (PetscInt i = 0; i < n; i++)
    for (int d = 0; d < 3; d++) ha[3 * i + d] /= 2 * aa[i];
  PetscCall(VecRestoreArrayRead(area, &aa));
  PetscCall(VecRestoreArray(h, &ha));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &area));
  PetscFunctionReturn(0);
}
