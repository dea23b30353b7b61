/* Quaternions as 4 reals q = {w, x, y, z} = w + x i + y j + z k (crane2011 Sec. 3), with R^3 identified
   with Im H: (x, y, z) -> x i + y j + z k. Hamilton product, conjugate, and the real 4x4 block of left
   multiplication used to store quaternionic matrices as real ones (crane2011 Sec. 5.1). */
#ifndef CS_QUATERNION_H
#define CS_QUATERNION_H
#include <petscsys.h>

/* r = p q (Hamilton product; i^2 = j^2 = k^2 = ijk = -1). r may alias neither p nor q. */
static inline void CSQuatMul(const PetscReal p[4], const PetscReal q[4], PetscReal r[4])
{
  r[0] = p[0] * q[0] - p[1] * q[1] - p[2] * q[2] - p[3] * q[3];
  r[1] = p[0] * q[1] + p[1] * q[0] + p[2] * q[3] - p[3] * q[2];
  r[2] = p[0] * q[2] - p[1] * q[3] + p[2] * q[0] + p[3] * q[1];
  r[3] = p[0] * q[3] + p[1] * q[2] - p[2] * q[1] + p[3] * q[0];
}

/* r = conj(p) q, without forming conj(p) */
static inline void CSQuatConjMul(const PetscReal p[4], const PetscReal q[4], PetscReal r[4])
{
  r[0] = p[0] * q[0] + p[1] * q[1] + p[2] * q[2] + p[3] * q[3];
  r[1] = p[0] * q[1] - p[1] * q[0] - p[2] * q[3] + p[3] * q[2];
  r[2] = p[0] * q[2] + p[1] * q[3] - p[2] * q[0] - p[3] * q[1];
  r[3] = p[0] * q[3] - p[1] * q[2] + p[2] * q[1] - p[3] * q[0];
}

static inline void CSQuatConj(const PetscReal p[4], PetscReal r[4])
{
  r[0] = p[0];
  r[1] = -p[1];
  r[2] = -p[2];
  r[3] = -p[3];
}

static inline PetscReal CSQuatNorm2(const PetscReal q[4])
{
  return q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3];
}

/* r += s q */
static inline void CSQuatAXPY(PetscReal s, const PetscReal q[4], PetscReal r[4])
{
  r[0] += s * q[0];
  r[1] += s * q[1];
  r[2] += s * q[2];
  r[3] += s * q[3];
}

/* The 4x4 real block (row major) of left multiplication p -> q p (crane2011 Sec. 5.1):
     [ a -b -c -d ]
     [ b  a -d  c ]
     [ c  d  a -b ]
     [ d -c  b  a ]   for q = a + bi + cj + dk.
   Its transpose is the block of conj(q), so the real transpose of a quaternionic matrix is its conjugate
   transpose (X^T = X^H), which is what makes the assembled operators real symmetric. */
static inline void CSQuatBlock(const PetscReal q[4], PetscScalar M[16])
{
  const PetscReal a = q[0], b = q[1], c = q[2], d = q[3];
  M[0]  = a;
  M[1]  = -b;
  M[2]  = -c;
  M[3]  = -d;
  M[4]  = b;
  M[5]  = a;
  M[6]  = -d;
  M[7]  = c;
  M[8]  = c;
  M[9]  = d;
  M[10] = a;
  M[11] = -b;
  M[12] = d;
  M[13] = -c;
  M[14] = b;
  M[15] = a;
}

/* The next 4x4 block of row 4i of a quaternionic AIJ matrix (nc, cols, v from MatGetRow of that row): returns
   its block column and advances *k past it; with q, also its quaternion, read off the block's first row
   (a, -b, -c, -d) of CSQuatBlock (v is then needed). One visit per block, whichever of its 4 entries are stored. */
static inline PetscInt CSQuatRowNextBlock(PetscInt nc, const PetscInt cols[], const PetscScalar v[], PetscInt *k, PetscReal q[4])
{
  const PetscInt j = cols[*k] / 4;
  if (q) q[0] = q[1] = q[2] = q[3] = 0;
  for (; *k < nc && cols[*k] / 4 == j; (*k)++)
    if (q) q[cols[*k] % 4] = (cols[*k] % 4 ? -1 : 1) * PetscRealPart(v[*k]);
  return j;
}

/* conj(l) v l for v imaginary (only the imaginary part is returned, in r[3]): the similarity of crane2011
   Sec. 3 -- rotation and scaling by |l|^2. */
static inline void CSQuatSandwich(const PetscReal l[4], const PetscReal v[3], PetscReal r[3])
{
  PetscReal vq[4] = {0, v[0], v[1], v[2]}, t[4], u[4];
  CSQuatConjMul(l, vq, t);
  CSQuatMul(t, l, u);
  r[0] = u[1];
  r[1] = u[2];
  r[2] = u[3];
}

/* Unit quaternion q with q v conj(q) = R v for a proper rotation matrix R (row major), Shepperd's method
   (picks the largest diagonal combination, so it is stable for every angle). */
static inline void CSQuatFromRotation(const PetscReal R[9], PetscReal q[4])
{
  PetscReal tr = R[0] + R[4] + R[8], s;
  if (tr >= R[0] && tr >= R[4] && tr >= R[8]) {
    s    = 2 * PetscSqrtReal(1 + tr);
    q[0] = s / 4;
    q[1] = (R[7] - R[5]) / s;
    q[2] = (R[2] - R[6]) / s;
    q[3] = (R[3] - R[1]) / s;
  } else if (R[0] >= R[4] && R[0] >= R[8]) {
    s    = 2 * PetscSqrtReal(1 + R[0] - R[4] - R[8]);
    q[0] = (R[7] - R[5]) / s;
    q[1] = s / 4;
    q[2] = (R[1] + R[3]) / s;
    q[3] = (R[2] + R[6]) / s;
  } else if (R[4] >= R[8]) {
    s    = 2 * PetscSqrtReal(1 + R[4] - R[0] - R[8]);
    q[0] = (R[2] - R[6]) / s;
    q[1] = (R[1] + R[3]) / s;
    q[2] = s / 4;
    q[3] = (R[5] + R[7]) / s;
  } else {
    s    = 2 * PetscSqrtReal(1 + R[8] - R[0] - R[4]);
    q[0] = (R[3] - R[1]) / s;
    q[1] = (R[2] + R[6]) / s;
    q[2] = (R[5] + R[7]) / s;
    q[3] = s / 4;
  }
}

#endif
