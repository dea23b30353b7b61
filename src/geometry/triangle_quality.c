/* Triangle quality of a distributed mesh (issue 35): the smallest angle, the share of obtuse faces, the share of
   non-Delaunay interior edges (opposite angles summing above pi, i.e. a negative cotan weight w_ij, since
   cot a + cot b = sin(a + b) / (sin a sin b)), and the edge-length ratios. Faces are owned where they are (overlap
   0), edges counted once by their owner; min/max/sum reductions, so the numbers do not depend on the ranks. The
   meshes whose quality stalled the constrained Willmore flow at its first iterations had min angle 0.08-2.8 deg,
   42-55 % obtuse faces and 9-17 % non-Delaunay edges; their isotropic remeshes (min angle ~30 deg, <= 0.2 %
   non-Delaunay) moved: CSTriangleQualityWarnStall's thresholds sit between the two (docs/remeshing.md). */
#include "cs_geometry.h"

#define CS_NONDELAUNAY_TOL 1e-12 /* w_ij below -tol: a flat pair of faces (w = 0 up to round-off) is Delaunay */

/* min angle (radians), obtuse count and worst longest/shortest edge over the local (= owned) faces */
static PetscErrorCode FaceStats(CSMesh m, Vec x, PetscReal *amin, PetscInt *obtuse, PetscReal *fratio)
{
  Vec              xl;
  const PetscReal *p;
  PetscFunctionBeginUser;
  *amin   = PETSC_PI;
  *obtuse = 0;
  *fratio = 1;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal amax = 0, lmin = PETSC_MAX_REAL, lmax = 0;
    for (int a = 0; a < 3; a++) {
      PetscReal u[3], v[3], n[3];
      CSVecSub(F.c[(a + 1) % 3], F.c[a], u);
      CSVecSub(F.c[(a + 2) % 3], F.c[a], v);
      CSVecCross(u, v, n);
      amax  = PetscMax(amax, PetscAtan2Real(CSVecNorm(n), CSVecDot(u, v)));
      *amin = PetscMin(*amin, PetscAtan2Real(CSVecNorm(n), CSVecDot(u, v)));
      lmin  = PetscMin(lmin, CSVecNorm(u));
      lmax  = PetscMax(lmax, CSVecNorm(u));
    }
    *obtuse += amax > PETSC_PI / 2;
    *fratio = PetscMax(*fratio, lmax / lmin);
  }
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}

/* non-Delaunay and interior edges, each counted by its owner */
static PetscErrorCode EdgeStats(CSMesh m, Vec x, PetscInt *nondel, PetscInt *interior)
{
  Vec                w, wl;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  *nondel = *interior = 0;
  PetscCall(DMGetGlobalVector(m->dmE1, &w));
  PetscCall(DMGetLocalVector(m->dmE1, &wl));
  PetscCall(CSGeometryCotanWeights(m, x, w));
  PetscCall(DMGlobalToLocal(m->dmE1, w, INSERT_VALUES, wl));
  PetscCall(VecGetArrayRead(wl, &a));
  for (PetscInt e = 0; e < m->ne; e++) {
    if (!m->edgeOwned[e] || m->edgeBoundary[e]) continue;
    (*interior)++;
    *nondel += PetscRealPart(a[e]) < -CS_NONDELAUNAY_TOL;
  }
  PetscCall(VecRestoreArrayRead(wl, &a));
  PetscCall(DMRestoreLocalVector(m->dmE1, &wl));
  PetscCall(DMRestoreGlobalVector(m->dmE1, &w));
  PetscFunctionReturn(0);
}

PetscErrorCode CSGeometryTriangleQuality(CSMesh m, Vec x, CSTriangleQuality *q)
{
  PetscReal amin, fratio, lmin, lmax, mm[2];
  PetscInt  cnt[3];
  Vec       l;
  PetscFunctionBeginUser;
  PetscCall(FaceStats(m, x, &amin, &cnt[0], &fratio));
  PetscCall(EdgeStats(m, x, &cnt[1], &cnt[2]));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, cnt, 3, MPIU_INT, MPI_SUM, m->comm));
  mm[0] = -amin; /* one MPI_MAX for both */
  mm[1] = fratio;
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, mm, 2, MPIU_REAL, MPI_MAX, m->comm));
  PetscCall(DMGetGlobalVector(m->dmE1, &l));
  PetscCall(CSGeometryEdgeLengths(m, x, l));
  PetscCall(VecMin(l, NULL, &lmin));
  PetscCall(VecMax(l, NULL, &lmax));
  PetscCall(DMRestoreGlobalVector(m->dmE1, &l));
  q->min_angle_deg      = -mm[0] * 180 / PETSC_PI;
  q->obtuse_share       = (PetscReal)cnt[0] / (PetscReal)m->Nf;
  q->nondelaunay_share  = cnt[2] ? (PetscReal)cnt[1] / (PetscReal)cnt[2] : 0;
  q->edge_ratio         = lmax / lmin;
  q->face_edge_ratio    = mm[1];
  q->interior_edges     = cnt[2];
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleQualityWarnStall(CSMesh m, Vec x)
{
  CSTriangleQuality q;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryTriangleQuality(m, x, &q));
  if (q.min_angle_deg >= CS_STALL_MIN_ANGLE && (q.obtuse_share <= CS_STALL_OBTUSE || q.nondelaunay_share <= CS_STALL_NONDELAUNAY)) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(m->comm, "Warning: mesh %s: min angle %.3g deg, %.1f %% obtuse faces, %.1f %% non-Delaunay edges: meshes like this stalled the flow at its start; remesh with -mesh_remesh N (docs/remeshing.md)\n", m->name, (double)q.min_angle_deg, (double)(100 * q.obtuse_share), (double)(100 * q.nondelaunay_share)));
  PetscFunctionReturn(0);
}
