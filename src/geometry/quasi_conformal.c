/* Quasi-conformal error of crane2011 Sec. 6.1: per face, the ratio of the singular values of the affine map
   taking the reference triangle to the current one (1 for a similarity). */
#include "cs_geometry.h"

PetscErrorCode CSGeometryQuasiConformal(CSMesh m, Vec xref, Vec x, Vec q, PetscReal *qmean, PetscReal *qmax)
{
  Vec              xl, rl;
  const PetscReal *p, *r;
  PetscScalar     *qa = NULL;
  PetscReal        s[2] = {0, 0}, g[2], mx = 1, gmx;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSMeshGetLocalPositions(m, xref, &rl, &r));
  if (q) PetscCall(VecGetArray(q, &qa));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscReal *c0[3] = {r + 3 * F.v[0], r + 3 * F.v[1], r + 3 * F.v[2]};
    PetscReal        fr[9], t[4], t0[4], E[2][2], E0[2][2], det0, A[2][2], Em, Fm, smax, smin, Q, an[3];
    /* edge vectors in the triangle's own plane: columns of E (current) and E0 (reference) */
    CSTriangleFrame(F.c, fr, t);
    CSTriangleFrame(c0, fr, t0);
    E[0][0]  = t[0];
    E[1][0]  = t[1];
    E[0][1]  = t[2];
    E[1][1]  = t[3];
    E0[0][0] = t0[0];
    E0[1][0] = t0[1];
    E0[0][1] = t0[2];
    E0[1][1] = t0[3];
    /* A = E E0^{-1} */
    det0    = E0[0][0] * E0[1][1] - E0[0][1] * E0[1][0];
    A[0][0] = (E[0][0] * E0[1][1] - E[0][1] * E0[1][0]) / det0;
    A[0][1] = (-E[0][0] * E0[0][1] + E[0][1] * E0[0][0]) / det0;
    A[1][0] = (E[1][0] * E0[1][1] - E[1][1] * E0[1][0]) / det0;
    A[1][1] = (-E[1][0] * E0[0][1] + E[1][1] * E0[0][0]) / det0;
    /* singular values of a 2x2 matrix without cancellation: with E = |(a+d, c-b)|/2 and F = |(a-d, c+b)|/2,
       sigma_max = E + F and sigma_min = |E - F| (the conformal and anti-conformal parts of A) */
    Em   = 0.5 * PetscSqrtReal(PetscSqr(A[0][0] + A[1][1]) + PetscSqr(A[1][0] - A[0][1]));
    Fm   = 0.5 * PetscSqrtReal(PetscSqr(A[0][0] - A[1][1]) + PetscSqr(A[1][0] + A[0][1]));
    smax = Em + Fm;
    smin = PetscAbsReal(Em - Fm);
    Q    = smax / smin;
    if (qa) qa[F.f] = Q;
    CSTriangleAreaVector(c0, an);
    s[0] += CSVecNorm(an) * Q;
    s[1] += CSVecNorm(an);
    mx = PetscMax(mx, Q);
  }
  if (q) PetscCall(VecRestoreArray(q, &qa));
  PetscCall(CSMeshRestoreLocalPositions(m, xref, &rl, &r));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MPIU_Allreduce(s, g, 2, MPIU_REAL, MPIU_SUM, m->comm));
  PetscCall(MPIU_Allreduce(&mx, &gmx, 1, MPIU_REAL, MPIU_MAX, m->comm));
  if (qmean) *qmean = g[0] / g[1];
  if (qmax) *qmax = gmx;
  PetscFunctionReturn(0);
}
