/* A pointwise mean curvature that is exactly constant on meshes inscribed in a sphere (crane2013 Table 1 step I,
   -flow_curvature voronoi of the conformal flow; docs/conformal_flow.md "A curvature exact on spheres"):
     H_i = (L f)_i . n_i / (2 A_i)
   with the same cotan mean-curvature vector L f as CSGeometrySignedMeanCurvature but
   - A_i the mixed Voronoi area of Meyer et al. 2003 (the circumcentric part (|e_ij|^2 cot + |e_ik|^2 cot)/8 of a
     non-obtuse triangle, A/2 at an obtuse corner, A/4 at the other corners of an obtuse triangle), and
   - n_i the normal of the sphere through vertex i that best fits its neighbours: every neighbour j of a vertex on a
     sphere of radius R with outward normal n satisfies e_ij . n + |e_ij|^2 / (2R) = 0 (e_ij = f_j - f_i), so n
     minimises sum_j (e_ij . n + k |e_ij|^2/2)^2 over |n| = 1 and k; eliminating k leaves the smallest eigenvector
     of M = E^T E - (E^T q)(E^T q)^T / |q|^2 (rows e_ij, q_j = |e_ij|^2/2), computed by power iteration on adj(M),
     its sign that of the area-weighted normal (flat rings give the plane's normal, k = 0).
   On an inscribed mesh with non-obtuse triangles (L f)_i . n_i = sum_j L_ij |e_ij|^2 / (2R) = 2 A_i / R exactly
   (sum_j L_ij |e_ij|^2 / 4 is the circumcentric area, equal to the mixed one there): H_i = 1/R at every vertex. */
#include "cs_geometry.h"

/* the Meyer et al. mixed area of each corner of a triangle */
static void MixedAreas(const PetscReal *const c[3], PetscReal a[3])
{
  PetscReal cot[3], an[3], A, e2[3];
  CSTriangleCotans(c, cot);
  CSTriangleAreaVector(c, an);
  A = CSVecNorm(an);
  for (int k = 0; k < 3; k++) {
    PetscReal e[3];
    CSVecSub(c[(k + 2) % 3], c[(k + 1) % 3], e); /* the edge opposite corner k */
    e2[k] = CSVecDot(e, e);
  }
  for (int k = 0; k < 3; k++) {
    int obtuse = -1;
    for (int j = 0; j < 3; j++)
      if (cot[j] < 0) obtuse = j;
    if (obtuse < 0) a[k] = (e2[(k + 1) % 3] * cot[(k + 1) % 3] + e2[(k + 2) % 3] * cot[(k + 2) % 3]) / 8;
    else a[k] = obtuse == k ? A / 2 : A / 4;
  }
}

/* the smallest eigenvector of the symmetric PSD 3x3 m (row-major), started from (and signed like) n0 */
static void SmallestEigenvector(const PetscReal m[9], const PetscReal n0[3], PetscReal n[3])
{
  PetscReal adj[9], y[3], l;
  adj[0] = m[4] * m[8] - m[5] * m[7];
  adj[1] = m[2] * m[7] - m[1] * m[8];
  adj[2] = m[1] * m[5] - m[2] * m[4];
  adj[4] = m[0] * m[8] - m[2] * m[6];
  adj[5] = m[2] * m[3] - m[0] * m[5];
  adj[8] = m[0] * m[4] - m[1] * m[3];
  adj[3] = adj[1];
  adj[6] = adj[2];
  adj[7] = adj[5];
  for (int d = 0; d < 3; d++) n[d] = n0[d];
  for (int it = 0; it < 8; it++) {
    for (int d = 0; d < 3; d++) y[d] = adj[3 * d] * n[0] + adj[3 * d + 1] * n[1] + adj[3 * d + 2] * n[2];
    l = CSVecNorm(y);
    if (!(l > 0)) return; /* no usable fit: keep the start */
    for (int d = 0; d < 3; d++) n[d] = y[d] / l;
  }
  if (CSVecDot(n, n0) < 0)
    for (int d = 0; d < 3; d++) n[d] = -n[d];
}

/* per vertex the sums E^T E (6: xx xy xz yy yz zz), E^T q (3), |q|^2 and the mixed area, over the corners' edges */
static PetscErrorCode Moments(CSMesh m, Vec x, Vec S6a, Vec S6b, Vec Eq, Vec qq, Vec area)
{
  Vec              xl;
  const PetscReal *p;
  CSLocalSum       sa, sb, se, sq, sm;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSLocalSumBegin(m->dmV3, &sa));
  PetscCall(CSLocalSumBegin(m->dmV3, &sb));
  PetscCall(CSLocalSumBegin(m->dmV3, &se));
  PetscCall(CSLocalSumBegin(m->dmV1, &sq));
  PetscCall(CSLocalSumBegin(m->dmV1, &sm));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal am[3];
    MixedAreas(F.c, am);
    for (int k = 0; k < 3; k++) {
      PetscInt i = F.v[k];
      sm.a[i] += am[k];
      for (int o = 1; o <= 2; o++) {
        PetscReal e[3], q;
        CSVecSub(F.c[(k + o) % 3], F.c[k], e);
        q = CSVecDot(e, e) / 2;
        sa.a[3 * i] += e[0] * e[0];
        sa.a[3 * i + 1] += e[0] * e[1];
        sa.a[3 * i + 2] += e[0] * e[2];
        sb.a[3 * i] += e[1] * e[1];
        sb.a[3 * i + 1] += e[1] * e[2];
        sb.a[3 * i + 2] += e[2] * e[2];
        for (int d = 0; d < 3; d++) se.a[3 * i + d] += e[d] * q;
        sq.a[i] += q * q;
      }
    }
  }
  PetscCall(CSLocalSumEnd(&sa, S6a));
  PetscCall(CSLocalSumEnd(&sb, S6b));
  PetscCall(CSLocalSumEnd(&se, Eq));
  PetscCall(CSLocalSumEnd(&sq, qq));
  PetscCall(CSLocalSumEnd(&sm, area));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSGeometryVoronoiMeanCurvature(CSMesh m, Vec x, Vec H, Vec N, Vec area)
{
  Vec                Lf, Am, S6a, S6b, Eq, qq;
  const PetscScalar *l, *sa, *sb, *se, *sq, *a;
  PetscScalar       *h, *n;
  PetscInt           nl;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(m->dmV3, &Lf));
  PetscCall(DMGetGlobalVector(m->dmV1, &Am));
  PetscCall(DMGetGlobalVector(m->dmV3, &S6a));
  PetscCall(DMGetGlobalVector(m->dmV3, &S6b));
  PetscCall(DMGetGlobalVector(m->dmV3, &Eq));
  PetscCall(DMGetGlobalVector(m->dmV1, &qq));
  PetscCall(CSGeometryLaplacianPositions(m, x, Lf, area)); /* area: the barycentric one, as the other H */
  PetscCall(CSGeometryVertexNormals(m, x, N)); /* the start and the sign */
  PetscCall(Moments(m, x, S6a, S6b, Eq, qq, Am));
  PetscCall(VecGetLocalSize(H, &nl));
  PetscCall(VecGetArrayRead(Lf, &l));
  PetscCall(VecGetArrayRead(S6a, &sa));
  PetscCall(VecGetArrayRead(S6b, &sb));
  PetscCall(VecGetArrayRead(Eq, &se));
  PetscCall(VecGetArrayRead(qq, &sq));
  PetscCall(VecGetArrayRead(Am, &a));
  PetscCall(VecGetArray(N, &n));
  PetscCall(VecGetArray(H, &h));
  for (PetscInt i = 0; i < nl; i++) {
    PetscReal M[9], b[3], n0[3], ni[3], s = 0, q2 = PetscRealPart(sq[i]);
    for (int d = 0; d < 3; d++) {
      b[d]  = PetscRealPart(se[3 * i + d]);
      n0[d] = PetscRealPart(n[3 * i + d]);
    }
    M[0] = PetscRealPart(sa[3 * i]);
    M[1] = PetscRealPart(sa[3 * i + 1]);
    M[2] = PetscRealPart(sa[3 * i + 2]);
    M[4] = PetscRealPart(sb[3 * i]);
    M[5] = PetscRealPart(sb[3 * i + 1]);
    M[8] = PetscRealPart(sb[3 * i + 2]);
    M[3] = M[1];
    M[6] = M[2];
    M[7] = M[5];
    for (int d = 0; d < 3; d++)
      for (int e = 0; e < 3; e++) M[3 * d + e] -= b[d] * b[e] / q2;
    SmallestEigenvector(M, n0, ni);
    for (int d = 0; d < 3; d++) {
      n[3 * i + d] = ni[d];
      s += PetscRealPart(l[3 * i + d]) * ni[d];
    }
    h[i] = s / (2 * PetscRealPart(a[i]));
  }
  PetscCall(VecRestoreArray(H, &h));
  PetscCall(VecRestoreArray(N, &n));
  PetscCall(VecRestoreArrayRead(Am, &a));
  PetscCall(VecRestoreArrayRead(qq, &sq));
  PetscCall(VecRestoreArrayRead(Eq, &se));
  PetscCall(VecRestoreArrayRead(S6b, &sb));
  PetscCall(VecRestoreArrayRead(S6a, &sa));
  PetscCall(VecRestoreArrayRead(Lf, &l));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &qq));
  PetscCall(DMRestoreGlobalVector(m->dmV3, &Eq));
  PetscCall(DMRestoreGlobalVector(m->dmV3, &S6b));
  PetscCall(DMRestoreGlobalVector(m->dmV3, &S6a));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &Am));
  PetscCall(DMRestoreGlobalVector(m->dmV3, &Lf));
  PetscFunctionReturn(0);
}
