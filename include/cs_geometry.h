/* Discrete geometry of the distributed mesh: per-triangle kernels (lengths, angles, cotans, areas, normals,
   and their derivatives) and the assembled per-vertex/per-edge quantities built from them. */
#ifndef CS_GEOMETRY_H
#define CS_GEOMETRY_H
#include "cs_mesh.h"

/* ---- per-triangle kernels; corners p[0], p[1], p[2] counter-clockwise ---- */
static inline void CSVecSub(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[0] - b[0];
  c[1] = a[1] - b[1];
  c[2] = a[2] - b[2];
}
static inline PetscReal CSVecDot(const PetscReal a[3], const PetscReal b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}
static inline void CSVecCross(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}
static inline PetscReal CSVecNorm(const PetscReal a[3])
{
  return PetscSqrtReal(CSVecDot(a, a));
}

/* Area vector (p1-p0)x(p2-p0)/2 = A N. */
static inline void CSTriangleAreaVector(const PetscReal *const p[3], PetscReal an[3])
{
  PetscReal u[3], v[3];
  CSVecSub(p[1], p[0], u);
  CSVecSub(p[2], p[0], v);
  CSVecCross(u, v, an);
  an[0] *= 0.5;
  an[1] *= 0.5;
  an[2] *= 0.5;
}

/* Unit normal N = A N / A of the triangle; returns its area A. */
static inline PetscReal CSTriangleNormal(const PetscReal *const p[3], PetscReal N[3])
{
  PetscReal an[3], A;
  CSTriangleAreaVector(p, an);
  A = CSVecNorm(an);
  for (int d = 0; d < 3; d++) N[d] = an[d] / A;
  return A;
}

/* The triangle's right-handed orthonormal frame, rows F = (t1, t2, n): t1 along p1 - p0, n the unit normal,
   t2 = n x t1; and its corners in that frame's plane with p0 at the origin: p1 = (s0, s1) = (|p1 - p0|, 0),
   p2 = (s2, s3). The planar coordinates are what a map between two triangles is measured in (crane2011
   Secs. 6.1 and 7.2). */
static inline void CSTriangleFrame(const PetscReal *const p[3], PetscReal F[9], PetscReal s[4])
{
  PetscReal e1[3], e2[3], n[3], l1, ln;
  CSVecSub(p[1], p[0], e1);
  CSVecSub(p[2], p[0], e2);
  CSVecCross(e1, e2, n);
  l1 = CSVecNorm(e1);
  ln = CSVecNorm(n);
  for (int d = 0; d < 3; d++) {
    F[d]     = e1[d] / l1;
    F[6 + d] = n[d] / ln;
  }
  CSVecCross(F + 6, F, F + 3);
  s[0] = l1;
  s[1] = 0;
  s[2] = CSVecDot(e2, F);
  s[3] = CSVecDot(e2, F + 3);
}

/* Q = sigma_max / sigma_min >= 1 of the affine map A = E E0^{-1} taking a triangle with edges E0 to one with edges E
   (each given as the two edge vectors of CSTriangleFrame's s: columns (s[0], s[1]) and (s[2], s[3])); 1 for a
   similarity (crane2011 Sec. 6.1). Singular values without cancellation: with E = |(a+d, c-b)|/2 and
   F = |(a-d, c+b)|/2, sigma_max = E + F and sigma_min = |E - F| (the conformal and anti-conformal parts of A). */
static inline PetscReal CSAffineQ(const PetscReal t[4], const PetscReal t0[4])
{
  PetscReal E[2][2], E0[2][2], det0, A[2][2], Em, Fm;
  E[0][0]  = t[0];
  E[1][0]  = t[1];
  E[0][1]  = t[2];
  E[1][1]  = t[3];
  E0[0][0] = t0[0];
  E0[1][0] = t0[1];
  E0[0][1] = t0[2];
  E0[1][1] = t0[3];
  det0     = E0[0][0] * E0[1][1] - E0[0][1] * E0[1][0];
  A[0][0]  = (E[0][0] * E0[1][1] - E[0][1] * E0[1][0]) / det0;
  A[0][1]  = (-E[0][0] * E0[0][1] + E[0][1] * E0[0][0]) / det0;
  A[1][0]  = (E[1][0] * E0[1][1] - E[1][1] * E0[1][0]) / det0;
  A[1][1]  = (-E[1][0] * E0[0][1] + E[1][1] * E0[0][0]) / det0;
  Em       = 0.5 * PetscSqrtReal(PetscSqr(A[0][0] + A[1][1]) + PetscSqr(A[1][0] - A[0][1]));
  Fm       = 0.5 * PetscSqrtReal(PetscSqr(A[0][0] - A[1][1]) + PetscSqr(A[1][0] + A[0][1]));
  return (Em + Fm) / PetscAbsReal(Em - Fm);
}

/* cot of the interior angle at each corner: cot = (u.v)/|u x v| with u, v the two edges leaving the corner. */
static inline void CSTriangleCotans(const PetscReal *const p[3], PetscReal cot[3])
{
  for (int a = 0; a < 3; a++) {
    PetscReal u[3], v[3], w[3];
    CSVecSub(p[(a + 1) % 3], p[a], u);
    CSVecSub(p[(a + 2) % 3], p[a], v);
    CSVecCross(u, v, w);
    cot[a] = CSVecDot(u, v) / CSVecNorm(w);
  }
}

/* d(area)/d p[k] = 1/2 N x (p[k-1] - p[k+1]): in-plane, orthogonal to the opposite edge, pointing away. */
static inline void CSTriangleAreaGradient(const PetscReal *const p[3], const PetscReal N[3], PetscReal dA[3][3])
{
  for (int k = 0; k < 3; k++) {
    PetscReal e[3];
    CSVecSub(p[(k + 2) % 3], p[(k + 1) % 3], e);
    CSVecCross(N, e, dA[k]);
    for (int d = 0; d < 3; d++) dA[k][d] *= 0.5;
  }
}

/* d cot(angle at corner a) / d p[k] for k = 0,1,2, by the quotient rule on cot = (u.v)/(2A). */
static inline void CSTriangleCotanGradient(const PetscReal *const p[3], int a, PetscReal dcot[3][3])
{
  PetscReal u[3], v[3], an[3], N[3], A, cot, dA[3][3];
  int       b = (a + 1) % 3, c = (a + 2) % 3;
  CSVecSub(p[b], p[a], u);
  CSVecSub(p[c], p[a], v);
  CSTriangleAreaVector(p, an);
  A = CSVecNorm(an);
  for (int d = 0; d < 3; d++) N[d] = an[d] / A;
  cot = CSVecDot(u, v) / (2 * A);
  CSTriangleAreaGradient(p, N, dA);
  for (int d = 0; d < 3; d++) {
    PetscReal dd[3];
    dd[a] = -(u[d] + v[d]);
    dd[b] = v[d];
    dd[c] = u[d];
    for (int k = 0; k < 3; k++) dcot[k][d] = (dd[k] - 2 * cot * dA[k][d]) / (2 * A);
  }
}

/* ---- distributed quantities ---- */
/* Local (ghosted) copy of a global dmV3 positions vector; give it back with CSMeshRestoreLocalPositions. */
PETSC_EXTERN PetscErrorCode CSMeshGetLocalPositions(CSMesh mesh, Vec x, Vec *xl, const PetscReal **p);
PETSC_EXTERN PetscErrorCode CSMeshRestoreLocalPositions(CSMesh mesh, Vec x, Vec *xl, const PetscReal **p);
/* Face-by-face assembly of a global vector g of dm: add(mesh, p, F, a) adds the share of face F (corners F->c
   in the local positions p) into the local array a of dm, ghosts included; the copies over the ranks are
   then summed into g (see CSLocalSum). */
typedef void (*CSFaceAdd)(CSMesh mesh, const PetscReal *p, const CSFaceIter *F, PetscScalar *a);
PETSC_EXTERN PetscErrorCode CSGeometryFaceSum(CSMesh mesh, Vec x, DM dm, CSFaceAdd add, Vec g);

/* Triangle quality (src/geometry/triangle_quality.c, issue 35): the smallest corner angle (degrees), the share of
   obtuse faces, the share of non-Delaunay interior edges (opposite angles summing above pi: cotan weight below
   -1e-12), the longest over the shortest edge of the mesh, and the largest longest/shortest edge ratio of a face.
   Collective; the same on any number of ranks. */
typedef struct {
  PetscReal min_angle_deg, obtuse_share, nondelaunay_share, edge_ratio, face_edge_ratio;
  PetscInt  interior_edges;
} CSTriangleQuality;
PETSC_EXTERN PetscErrorCode CSGeometryTriangleQuality(CSMesh mesh, Vec x, CSTriangleQuality *q);
/* Before a flow: one warning line naming -mesh_remesh when the min angle is below CS_STALL_MIN_ANGLE, or both the
   non-Delaunay share is above CS_STALL_NONDELAUNAY and the obtuse share above CS_STALL_OBTUSE. The stalling meshes
   of issue 35 had 0.08-2.8 deg, 42-55 % obtuse, 9-17 % non-Delaunay; their remeshes that moved ~30 deg (15-35 here)
   and <= 0.2 % non-Delaunay. Obtuse alone does not predict a stall: -gen torus is 50 % obtuse, 0 % non-Delaunay,
   and flows (docs/remeshing.md). Collective. */
#define CS_STALL_MIN_ANGLE   3.0
#define CS_STALL_OBTUSE      0.30
#define CS_STALL_NONDELAUNAY 0.05
PETSC_EXTERN PetscErrorCode CSTriangleQualityWarnStall(CSMesh mesh, Vec x);

/* Sum of the corner angles at each vertex (a dmV1 vector; K_i = 2 pi - sum at interior vertices). */
PETSC_EXTERN PetscErrorCode CSGeometryAngleSums(CSMesh mesh, Vec x, Vec s);
/* Barycentric vertex dual areas A_i = sum of one third of the incident face areas (the diagonal *0). */
PETSC_EXTERN PetscErrorCode CSGeometryVertexAreas(CSMesh mesh, Vec x, Vec area);
/* Cotan edge weights w_ij = (cot a_ij + cot b_ij)/2 (one term on boundary edges), a dmE1 vector. */
PETSC_EXTERN PetscErrorCode CSGeometryCotanWeights(CSMesh mesh, Vec x, Vec w);
/* Edge lengths l_ij = |f_j - f_i|, a dmE1 vector. */
PETSC_EXTERN PetscErrorCode CSGeometryEdgeLengths(CSMesh mesh, Vec x, Vec l);
/* Face areas (dmF1) and unit normals (3 per face, local array of length 3*nf owned by the caller). */
PETSC_EXTERN PetscErrorCode CSGeometryFaceAreas(CSMesh mesh, Vec x, Vec area);
/* Mean edge length sum_e l_e / E. */
PETSC_EXTERN PetscErrorCode CSGeometryMeanEdgeLength(CSMesh mesh, Vec x, PetscReal *h);
/* Area-weighted unit vertex normals N_i = sum_f A_f N_f / |.| (dmV3). */
PETSC_EXTERN PetscErrorCode CSGeometryVertexNormals(CSMesh mesh, Vec x, Vec N);
/* Unit boundary tangents (dmV3): at a boundary vertex i the direction of its outgoing boundary half-edge
   i -> j (counter-clockwise in the only face of the edge); 0 at interior vertices. */
PETSC_EXTERN PetscErrorCode CSGeometryBoundaryTangents(CSMesh mesh, Vec x, Vec T);
/* Lf (dmV3; (Lf)_i = sum_j w_ij (f_i - f_j), the positive cotan Laplacian of soliman2021 Sec. 2) and the
   vertex areas *0 (dmV1) in one pass over the faces; either output may be NULL. */
PETSC_EXTERN PetscErrorCode CSGeometryLaplacianPositions(CSMesh mesh, Vec x, Vec Lf, Vec area);
/* Integrated mean curvature vector Lf (dmV3) and pointwise h = 1/2 *0^{-1} L f (soliman2021 Eq. 27). */
PETSC_EXTERN PetscErrorCode CSGeometryMeanCurvature(CSMesh mesh, Vec x, Vec h);
/* Signed pointwise mean curvature H_i = (L f)_i . N_i / (2 A_i) (dmV1; positive on a sphere with outward normals);
   N (dmV3, the area-weighted vertex normals) and area (dmV1, *0) are returned when not NULL. */
PETSC_EXTERN PetscErrorCode CSGeometrySignedMeanCurvature(CSMesh mesh, Vec x, Vec H, Vec N, Vec area);
/* H_i = (L f)_i . n_i / (2 A_i) with the mixed Voronoi area (Meyer et al. 2003) and n_i the normal of the sphere
   fitted through vertex i and its neighbours: exactly 1/R on a mesh inscribed in a sphere with non-obtuse triangles
   (src/geometry/mean_curvature_voronoi.c). N gets n_i; area the barycentric vertex areas (as above). */
PETSC_EXTERN PetscErrorCode CSGeometryVoronoiMeanCurvature(CSMesh mesh, Vec x, Vec H, Vec N, Vec area);
/* Total area, enclosed volume (soliman2021 App. B.2: 1/6 sum f_i.(f_j x f_k)). */
PETSC_EXTERN PetscErrorCode CSGeometryAreaVolume(CSMesh mesh, Vec x, PetscReal *area, PetscReal *volume);
PETSC_EXTERN PetscErrorCode CSGeometryBoundaryLength(CSMesh mesh, Vec x, PetscReal *len); /* sum of the boundary edge lengths */
/* Quasi-conformal error (crane2011 Sec. 6.1): per face the ratio sigma_max/sigma_min of the affine map from
   the reference triangle to the current one; q_mean is weighted by reference face area. q may be NULL. */
/* The mean and max of a per-face distortion over the ranks: s = the local (sum of w Q, sum of w), mx the local max
   (quasi_conformal.c; shared by CSGeometryQuasiConformal and CSGeometryTextureQ). */
PETSC_EXTERN PetscErrorCode CSGeometryReduceQ(MPI_Comm comm, const PetscReal s[2], PetscReal mx, PetscReal *qmean, PetscReal *qmax);
PETSC_EXTERN PetscErrorCode CSGeometryQuasiConformal(CSMesh mesh, Vec xref, Vec x, Vec q, PetscReal *qmean, PetscReal *qmax);
/* The quasi-conformal distortion of the texture (issue 38): per face Q = sigma_max/sigma_min of the affine map from
   the face's UV triangle (mesh->faceUV) to its triangle in x (CSAffineQ), into q (dmF1, or NULL); the mean weighted
   by the UV area (the same weights for the input and every result with these UVs) and the max over faces.
   mesh->faceUV must be set (CSMeshTextureCreate). Collective (src/geometry/texture_quality.c). */
PETSC_EXTERN PetscErrorCode CSGeometryTextureQ(CSMesh mesh, Vec x, Vec q, PetscReal *qmean, PetscReal *qmax);
/* The conformal stress of an edge field q (dmE1; soliman2021 Eq. 20): per face the principal stress direction
   (unit, 3 per face, a vector laid out like dmF1 times 3), the larger and smaller eigenvalues (dmF1). */
PETSC_EXTERN PetscErrorCode CSGeometryConformalStress(CSMesh mesh, Vec x, Vec q, Vec dir, Vec smax, Vec smin);
/* s_i = sum of q over the edges at vertex i (dmE1 -> dmV1): zero for a quadratic differential (Eq. 6). */
PETSC_EXTERN PetscErrorCode CSGeometryEdgeSumAtVertices(CSMesh mesh, Vec q, Vec s);

/* Number of faces (over all ranks) whose area vector in x does not point the way it does in xref. */
PETSC_EXTERN PetscErrorCode CSGeometryFoldedFaces(CSMesh mesh, Vec xref, Vec x, PetscInt *nfolded);
/* Number of interior edges (over all ranks) whose two faces' normals make an angle above `angle` degrees in x but
   not in xref: creases where the surface folds back on itself (src/geometry/creased_edges.c). */
PETSC_EXTERN PetscErrorCode CSGeometryCreasedEdges(CSMesh mesh, Vec xref, Vec x, PetscReal angle, PetscInt *ncreased);

#endif
