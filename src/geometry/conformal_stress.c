/* The conformal stress tensor of a quadratic differential q (soliman2021 Eq. 20, here for the surface case
   where q lives on the edges): per face S = sum over its edges ij of q_ij P_ij, P_ij = e e^T / |e|^2 the
   projector onto the edge e = f_j - f_i in the face plane. Its principal stress direction (the eigenvector of
   the larger eigenvalue) is a line field, the horizontal foliation of q (Fig. 11). */
#include "cs_geometry.h"

/* The 2x2 in-plane form of S in the frame (t1, t2) of the face; eigenvalues s1 >= s2 and the unit eigenvector
   of s1 in space. */
static void FaceStress(const PetscReal *const c[3], const PetscReal q[3], PetscReal dir[3], PetscReal *s1, PetscReal *s2)
{
  PetscReal Fr[9], s[4], a = 0, b = 0, d = 0, m, r, th;
  CSTriangleFrame(c, Fr, s);
  for (int k = 0; k < 3; k++) { /* edge opposite corner k, from corner k+1 to k+2 */
    PetscReal e[3], x, y, l2;
    CSVecSub(c[(k + 2) % 3], c[(k + 1) % 3], e);
    x  = CSVecDot(e, Fr);
    y  = CSVecDot(e, Fr + 3);
    l2 = x * x + y * y;
    a += q[k] * x * x / l2;
    b += q[k] * x * y / l2;
    d += q[k] * y * y / l2;
  }
  m   = 0.5 * (a + d);
  r   = PetscSqrtReal(0.25 * (a - d) * (a - d) + b * b);
  *s1 = m + r;
  *s2 = m - r;
  th  = 0.5 * PetscAtan2Real(2 * b, a - d); /* angle of the major axis in the (t1, t2) plane */
  for (int k = 0; k < 3; k++) dir[k] = PetscCosReal(th) * Fr[k] + PetscSinReal(th) * Fr[3 + k];
}

PetscErrorCode CSGeometryConformalStress(CSMesh m, Vec x, Vec q, Vec dir, Vec smax, Vec smin)
{
  Vec                xl, ql;
  const PetscReal   *p;
  const PetscScalar *qa;
  PetscScalar       *da, *s1a, *s2a;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(DMGetLocalVector(m->dmE1, &ql));
  PetscCall(DMGlobalToLocal(m->dmE1, q, INSERT_VALUES, ql));
  PetscCall(VecGetArrayRead(ql, &qa));
  PetscCall(VecGetArray(dir, &da));
  PetscCall(VecGetArray(smax, &s1a));
  PetscCall(VecGetArray(smin, &s2a));
  /* faces are never ghosted (overlap 0): the local face f is entry f of the global face vectors */
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal qf[3], d[3], s1, s2;
    for (int k = 0; k < 3; k++) qf[k] = PetscRealPart(qa[F.e[k]]);
    FaceStress(F.c, qf, d, &s1, &s2);
    for (int k = 0; k < 3; k++) da[3 * F.f + k] = d[k];
    s1a[F.f] = s1;
    s2a[F.f] = s2;
  }
  PetscCall(VecRestoreArray(smin, &s2a));
  PetscCall(VecRestoreArray(smax, &s1a));
  PetscCall(VecRestoreArray(dir, &da));
  PetscCall(VecRestoreArrayRead(ql, &qa));
  PetscCall(DMRestoreLocalVector(m->dmE1, &ql));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}

/* (A^T q)_i = sum over the edges ij at vertex i of q_ij (soliman2021 Eq. 6 holds when this is zero), dmV1. */
PetscErrorCode CSGeometryEdgeSumAtVertices(CSMesh m, Vec q, Vec s)
{
  Vec                ql, sl;
  const PetscScalar *qa;
  PetscScalar       *sa;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(m->dmE1, &ql));
  PetscCall(DMGlobalToLocal(m->dmE1, q, INSERT_VALUES, ql));
  PetscCall(DMGetLocalVector(m->dmV1, &sl));
  PetscCall(VecSet(sl, 0));
  PetscCall(VecGetArrayRead(ql, &qa));
  PetscCall(VecGetArray(sl, &sa));
  for (PetscInt e = 0; e < m->ne; e++) {
    if (!m->edgeOwned[e]) continue; /* each edge counted once over the ranks */
    sa[m->edgeVert[2 * e]] += qa[e];
    sa[m->edgeVert[2 * e + 1]] += qa[e];
  }
  PetscCall(VecRestoreArray(sl, &sa));
  PetscCall(VecRestoreArrayRead(ql, &qa));
  PetscCall(VecSet(s, 0));
  PetscCall(DMLocalToGlobal(m->dmV1, sl, ADD_VALUES, s));
  PetscCall(DMRestoreLocalVector(m->dmV1, &sl));
  PetscCall(DMRestoreLocalVector(m->dmE1, &ql));
  PetscFunctionReturn(0);
}
