/* Mean curvature: Lf and h = 1/2 *0^{-1} L f (soliman2021 Eq. 27), computed face by face. */
#include "cs_geometry.h"

PetscErrorCode CSGeometryLaplacianPositions(CSMesh m, Vec x, Vec Lf, Vec area)
{
  Vec              xl;
  CSLocalSum       ys, as;
  const PetscReal *p;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Geometry, 0, 0, 0, 0));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSLocalSumBegin(m->dmV3, &ys));
  PetscCall(CSLocalSumBegin(m->dmV1, &as));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscInt  *v = F.v;
    const PetscReal *const *c = F.c;
    PetscScalar     *y = ys.a, *a = as.a;
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
  PetscCall(CSLocalSumEnd(&ys, Lf));
  PetscCall(CSLocalSumEnd(&as, area));
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

/* H_i = (L f)_i . N_i / (2 A_i) with the area-weighted vertex normals: positive on a sphere with outward normals,
   signed on saddles (crane2013 Table 1 step I, H = 1/2 <N, Delta f>). */
PetscErrorCode CSGeometrySignedMeanCurvature(CSMesh m, Vec x, Vec H, Vec N, Vec area)
{
  Vec                Lf, Nl = N, Al = area;
  const PetscScalar *l, *n, *a;
  PetscScalar       *h;
  PetscInt           nl;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(m->dmV3, &Lf));
  if (!N) PetscCall(DMGetGlobalVector(m->dmV3, &Nl));
  if (!area) PetscCall(DMGetGlobalVector(m->dmV1, &Al));
  PetscCall(CSGeometryLaplacianPositions(m, x, Lf, Al));
  PetscCall(CSGeometryVertexNormals(m, x, Nl));
  PetscCall(VecGetLocalSize(Al, &nl));
  PetscCall(VecGetArrayRead(Lf, &l));
  PetscCall(VecGetArrayRead(Nl, &n));
  PetscCall(VecGetArrayRead(Al, &a));
  PetscCall(VecGetArray(H, &h));
  for (PetscInt i = 0; i < nl; i++) {
    PetscReal s = 0;
    for (int d = 0; d < 3; d++) s += PetscRealPart(l[3 * i + d] * n[3 * i + d]);
    h[i] = s / (2 * PetscRealPart(a[i]));
  }
  PetscCall(VecRestoreArray(H, &h));
  PetscCall(VecRestoreArrayRead(Al, &a));
  PetscCall(VecRestoreArrayRead(Nl, &n));
  PetscCall(VecRestoreArrayRead(Lf, &l));
  if (!area) PetscCall(DMRestoreGlobalVector(m->dmV1, &Al));
  if (!N) PetscCall(DMRestoreGlobalVector(m->dmV3, &Nl));
  PetscCall(DMRestoreGlobalVector(m->dmV3, &Lf));
  PetscFunctionReturn(0);
}
