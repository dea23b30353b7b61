/* Quasi-conformal error of crane2011 Sec. 6.1: per face, the ratio of the singular values of the affine map
   taking the reference triangle to the current one (1 for a similarity). */
#include "cs_geometry.h"

/* Edge vectors of a triangle in an orthonormal frame of its own plane: columns (e1, e2) of a 2x2 matrix. */
static void TriangleFrame(const PetscReal *const c[3], PetscReal E[2][2])
{
  PetscReal u[3], v[3], t1[3], n[3], t2[3], lu;
  CSVecSub(c[1], c[0], u);
  CSVecSub(c[2], c[0], v);
  lu = CSVecNorm(u);
  for (int d = 0; d < 3; d++) t1[d] = u[d] / lu;
  CSVecCross(u, v, n);
  CSVecCross(n, t1, t2);
  {
    PetscReal ln = CSVecNorm(t2);
    for (int d = 0; d < 3; d++) t2[d] /= ln;
  }
  E[0][0] = lu;
  E[1][0] = 0;
  E[0][1] = CSVecDot(v, t1);
  E[1][1] = CSVecDot(v, t2);
}

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
  for (PetscInt f = 0; f < m->nf; f++) {
    const PetscInt  *v     = m->faceVert + 3 * f;
    const PetscReal *c[3]  = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    const PetscReal *c0[3] = {r + 3 * v[0], r + 3 * v[1], r + 3 * v[2]};
    PetscReal        E[2][2], E0[2][2], det0, A[2][2], Em, Fm, smax, smin, Q, an[3];
    TriangleFrame(c, E);
    TriangleFrame(c0, E0);
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
    if (qa) qa[f] = Q;
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
