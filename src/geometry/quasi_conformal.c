/* Quasi-conformal error of crane2011 Sec. 6.1: per face, the ratio of the singular values of the affine map
   taking the reference triangle to the current one (1 for a similarity). */
#include "cs_geometry.h"

PetscErrorCode CSGeometryReduceQ(MPI_Comm comm, const PetscReal s[2], PetscReal mx, PetscReal *qmean, PetscReal *qmax)
{
  PetscReal g[2], gmx;
  PetscFunctionBeginUser;
  PetscCall(MPIU_Allreduce(s, g, 2, MPIU_REAL, MPIU_SUM, comm));
  PetscCall(MPIU_Allreduce(&mx, &gmx, 1, MPIU_REAL, MPIU_MAX, comm));
  if (qmean) *qmean = g[0] / g[1];
  if (qmax) *qmax = gmx;
  PetscFunctionReturn(0);
}

PetscErrorCode CSGeometryQuasiConformal(CSMesh m, Vec xref, Vec x, Vec q, PetscReal *qmean, PetscReal *qmax)
{
  Vec              xl, rl;
  const PetscReal *p, *r;
  PetscScalar     *qa = NULL;
  PetscReal        s[2] = {0, 0}, mx = 1;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSMeshGetLocalPositions(m, xref, &rl, &r));
  if (q) PetscCall(VecGetArray(q, &qa));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscReal *c0[3] = {r + 3 * F.v[0], r + 3 * F.v[1], r + 3 * F.v[2]};
    PetscReal        fr[9], t[4], t0[4], Q, an[3];
    /* edge vectors in the triangle's own plane, current and reference */
    CSTriangleFrame(F.c, fr, t);
    CSTriangleFrame(c0, fr, t0);
    Q = CSAffineQ(t, t0);
    if (qa) qa[F.f] = Q;
    CSTriangleAreaVector(c0, an);
    s[0] += CSVecNorm(an) * Q;
    s[1] += CSVecNorm(an);
    mx = PetscMax(mx, Q);
  }
  if (q) PetscCall(VecRestoreArray(q, &qa));
  PetscCall(CSMeshRestoreLocalPositions(m, xref, &rl, &r));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(CSGeometryReduceQ(m->comm, s, mx, qmean, qmax));
  PetscFunctionReturn(0);
}
