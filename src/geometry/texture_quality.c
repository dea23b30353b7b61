/* The quasi-conformal distortion of a texture (issue 38): how far the map from each UV triangle to its surface
   triangle is from a similarity. A conformal method composes this map with its own, near-similar one, so per face
   Q(result) lies within [Q(input)/q, Q(input) q] for the method's q (crane2011 Sec. 6.1): the checkerboards of
   soliman2021 Fig. 2, 12, crane2011 Fig. 1, 10 and crane2013 Fig. 2, 5 keep their squares. */
#include "cs_geometry.h"

PetscErrorCode CSGeometryTextureQ(CSMesh m, Vec x, Vec q, PetscReal *qmean, PetscReal *qmax)
{
  Vec              xl;
  const PetscReal *p;
  PetscScalar     *qa = NULL;
  PetscReal        s[2] = {0, 0}, mx = 1;
  PetscFunctionBeginUser;
  PetscCheck(m->faceUV, m->comm, PETSC_ERR_ARG_WRONGSTATE, "%s: the input has no texture coordinates", m->name);
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  if (q) PetscCall(VecGetArray(q, &qa));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscReal *w = m->faceUV + 6 * F.f;
    PetscReal        fr[9], t[4], t0[4] = {w[2] - w[0], w[3] - w[1], w[4] - w[0], w[5] - w[1]}, Q, a0;
    CSTriangleFrame(F.c, fr, t); /* the surface triangle's edges in its own plane */
    Q  = CSAffineQ(t, t0);
    a0 = 0.5 * PetscAbsReal(t0[0] * t0[3] - t0[1] * t0[2]); /* UV area */
    if (qa) qa[F.f] = Q;
    s[0] += a0 * Q;
    s[1] += a0;
    mx = PetscMax(mx, Q);
  }
  if (q) PetscCall(VecRestoreArray(q, &qa));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(CSGeometryReduceQ(m->comm, s, mx, qmean, qmax));
  PetscFunctionReturn(0);
}
