/* Triangle fields omega (halfedge vectors, soliman2021 Sec. 5.1) on the halfedge layout of
   include/cs_operators_lens.h: from positions, their log lengths, and the extended Willmore energy of App. D.1. */
#include "cs_operators_lens.h"
#include "cs_mesh_adjacency.h"

PetscErrorCode CSTriangleFieldFromPositions(CSMesh m, Vec x, DM dmH3, Vec omega)
{
  Vec              xl, ol;
  const PetscReal *p;
  PetscScalar     *o;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(VecGetArray(ol, &o));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscReal d[3];
    CSVecSub(p + 3 * m->edgeVert[2 * e + 1], p + 3 * m->edgeVert[2 * e], d);
    for (int c = 0; c < 3; c++) {
      o[6 * e + c]     = d[c];  /* side 0 runs along the edge */
      o[6 * e + 3 + c] = -d[c]; /* side 1 against it */
    }
  }
  PetscCall(VecRestoreArray(ol, &o));
  PetscCall(DMLocalToGlobal(dmH3, ol, INSERT_VALUES, omega));
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldLogLengths(CSMesh m, DM dmH3, Vec omega, DM dmH1, Vec lambda)
{
  PetscInt           n;
  const PetscScalar *o;
  PetscScalar       *l;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(lambda, &n));
  PetscCall(VecGetArrayRead(omega, &o));
  PetscCall(VecGetArray(lambda, &l));
  for (PetscInt h = 0; h < n; h++) {
    PetscReal w[3] = {PetscRealPart(o[3 * h]), PetscRealPart(o[3 * h + 1]), PetscRealPart(o[3 * h + 2])};
    l[h]           = PetscLogReal(CSVecNorm(w));
  }
  PetscCall(VecRestoreArray(lambda, &l));
  PetscCall(VecRestoreArrayRead(omega, &o));
  PetscFunctionReturn(0);
}

/* h_{2e} = h_{2e+1} = phi(e_e): an edge field on both halfedges of each edge. */
static PetscErrorCode HalfedgesFromEdges(CSMesh m, Vec l, DM dmH1, PetscBool takelog, Vec lambda)
{
  Vec                lE, lH;
  const PetscScalar *e;
  PetscScalar       *h;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(m->dmE1, &lE));
  PetscCall(DMGetLocalVector(dmH1, &lH));
  PetscCall(DMGlobalToLocal(m->dmE1, l, INSERT_VALUES, lE));
  PetscCall(VecGetArrayRead(lE, &e));
  PetscCall(VecGetArray(lH, &h));
  for (PetscInt i = 0; i < m->ne; i++) h[2 * i] = h[2 * i + 1] = takelog ? PetscLogReal(PetscRealPart(e[i])) : e[i];
  PetscCall(VecRestoreArray(lH, &h));
  PetscCall(VecRestoreArrayRead(lE, &e));
  PetscCall(DMLocalToGlobal(dmH1, lH, INSERT_VALUES, lambda));
  PetscCall(DMRestoreLocalVector(dmH1, &lH));
  PetscCall(DMRestoreLocalVector(m->dmE1, &lE));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldLogLengthsFromEdges(CSMesh m, Vec l, DM dmH1, Vec lambda)
{
  PetscFunctionBeginUser;
  PetscCall(HalfedgesFromEdges(m, l, dmH1, PETSC_TRUE, lambda));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldHalfedgesFromEdges(CSMesh m, Vec c, DM dmH1, Vec ch)
{
  PetscFunctionBeginUser;
  PetscCall(HalfedgesFromEdges(m, c, dmH1, PETSC_FALSE, ch));
  PetscFunctionReturn(0);
}

/* Per face the halfedge vectors w[a] (opposite corner a, running v[a+1] -> v[a+2]): the edges leaving corner a
   are w[a+2] and -w[a+1], so cot(theta_a) = <w[a+2], -w[a+1]> / |w[a+2] x w[a+1]| and the area is
   |w[a+2] x w[a+1]|/2. Halfedge a adds 1/2 cot(theta_a) w[a] to Y at its tail v[a+1] and subtracts it at its head
   v[a+2]: for w = df that is Y_i = sum_j w_ij (f_j - f_i) = -(L f)_i. A_i gets a third of the area. */
static PetscReal FaceCotans(const PetscReal w[3][3], PetscReal cot[3])
{
  PetscReal n[3], an;
  CSVecCross(w[2], w[1], n);
  an = CSVecNorm(n);
  for (int a = 0; a < 3; a++) cot[a] = -CSVecDot(w[(a + 2) % 3], w[(a + 1) % 3]) / an;
  return an;
}

/* the three halfedge vectors of face F from the local triangle field array o */
static void FaceVectors(CSMesh m, const CSFaceIter *F, const PetscScalar *o, PetscReal w[3][3])
{
  for (int a = 0; a < 3; a++)
    for (int d = 0; d < 3; d++) w[a][d] = PetscRealPart(o[6 * F->e[a] + 3 * CSMeshEdgeSide(m, F, a) + d]);
}

static void AddFace(const PetscReal w[3][3], const PetscInt v[3], PetscScalar *Y, PetscScalar *A)
{
  PetscReal cot[3], an = FaceCotans(w, cot);
  for (int a = 0; a < 3; a++) {
    PetscInt t = v[(a + 1) % 3], h = v[(a + 2) % 3];
    for (int d = 0; d < 3; d++) {
      Y[3 * t + d] += 0.5 * cot[a] * w[a][d];
      Y[3 * h + d] -= 0.5 * cot[a] * w[a][d];
    }
    A[v[a]] += an / 6;
  }
}

/* The differential of W~ with respect to the three halfedge vectors w[a] of one face, given z_i = Y_i/(2 A_i) and
   s_i = |Y_i|^2/(4 A_i^2) at its corners (dW~ = sum_i z_i . dY_i - s_i dA_i). With c_a = <w[a+2], w[a+1]>,
   an = |n|, n = w[2] x w[1], cot_a = -c_a/an: halfedge a adds (z_tail - z_head) . d(cot_a w[a] / 2), and the
   area an/6 at each corner gives -(s_0 + s_1 + s_2)/6 d an, with d an = (w[1] x n/an) . dw[2] + (n/an x w[2]) . dw[1]. */
static void FaceGradient(const PetscReal w[3][3], const PetscReal z[3][3], const PetscReal sv[3], PetscReal G[3][3])
{
  PetscReal n[3], an, nh[3], cot[3], K, t[3];
  CSVecCross(w[2], w[1], n);
  an = CSVecNorm(n);
  for (int d = 0; d < 3; d++) nh[d] = n[d] / an;
  an = FaceCotans(w, cot);
  K  = -(sv[0] + sv[1] + sv[2]) / 6;
  for (int a = 0; a < 3; a++) G[a][0] = G[a][1] = G[a][2] = 0;
  for (int a = 0; a < 3; a++) {
    int       p = (a + 1) % 3, q = (a + 2) % 3; /* tail corner p, head corner q; c_a = <w[q], w[p]> */
    PetscReal dz[3], g;
    CSVecSub(z[p], z[q], dz);
    g = CSVecDot(dz, w[a]);
    for (int d = 0; d < 3; d++) {
      G[a][d] += 0.5 * cot[a] * dz[d];
      G[q][d] -= 0.5 * g * w[p][d] / an;
      G[p][d] -= 0.5 * g * w[q][d] / an;
    }
    K += 0.5 * g * (-cot[a] * an) / (an * an); /* c_a = -cot_a an */
  }
  CSVecCross(w[1], nh, t);
  for (int d = 0; d < 3; d++) G[2][d] += K * t[d];
  CSVecCross(nh, w[2], t);
  for (int d = 0; d < 3; d++) G[1][d] += K * t[d];
}

/* The gradient pass: per face the differential into the face's own halfedges (each halfedge has one face). */
static PetscErrorCode WillmoreGradient(CSMesh m, DM dmH3, const PetscScalar *o, const PetscScalar *Y, const PetscScalar *A, Vec grad)
{
  CSLocalSum sg;
  PetscFunctionBeginUser;
  PetscCall(CSLocalSumBegin(dmH3, &sg));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal w[3][3], z[3][3], sv[3], G[3][3];
    FaceVectors(m, &F, o, w);
    for (int a = 0; a < 3; a++) {
      PetscReal Ai = PetscRealPart(A[F.v[a]]);
      for (int d = 0; d < 3; d++) z[a][d] = PetscRealPart(Y[3 * F.v[a] + d]) / (2 * Ai);
      sv[a] = CSVecDot(z[a], z[a]);
    }
    FaceGradient(w, z, sv, G);
    for (int a = 0; a < 3; a++)
      for (int d = 0; d < 3; d++) sg.a[6 * F.e[a] + 3 * CSMeshEdgeSide(m, &F, a) + d] += G[a][d];
  }
  PetscCall(CSLocalSumEnd(&sg, grad));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTriangleFieldWillmore(CSMesh m, DM dmH3, Vec omega, PetscReal *W, Vec grad)
{
  Vec                ol;
  CSLocalSum         sy, sa;
  const PetscScalar *o;
  PetscReal          loc = 0;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(DMGlobalToLocal(dmH3, omega, INSERT_VALUES, ol));
  PetscCall(VecGetArrayRead(ol, &o));
  PetscCall(CSLocalSumBegin(m->dmV3, &sy));
  PetscCall(CSLocalSumBegin(m->dmV1, &sa));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal w[3][3];
    FaceVectors(m, &F, o, w);
    AddFace(w, F.v, sy.a, sa.a);
  }
  PetscCall(CSLocalSumShare(&sy));
  PetscCall(CSLocalSumShare(&sa));
  for (PetscInt i = 0; i < m->nv; i++) {
    PetscReal y[3] = {PetscRealPart(sy.a[3 * i]), PetscRealPart(sy.a[3 * i + 1]), PetscRealPart(sy.a[3 * i + 2])};
    if (m->vertOwned[i]) loc += 0.25 * CSVecDot(y, y) / PetscRealPart(sa.a[i]);
  }
  if (grad) PetscCall(WillmoreGradient(m, dmH3, o, sy.a, sa.a, grad));
  PetscCall(CSLocalSumEnd(&sy, NULL));
  PetscCall(CSLocalSumEnd(&sa, NULL));
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  if (W) PetscCall(MPIU_Allreduce(&loc, W, 1, MPIU_REAL, MPIU_SUM, m->comm));
  PetscFunctionReturn(0);
}

/* The metric of the triangle field (Sec. 5.1): the halfedge star (*1 omega)_h = 1/2 cot(theta_h) omega_h (dmH1)
   and the vertex areas *0 = a third of the incident triangle field areas (dmV1). */
PetscErrorCode CSTriangleFieldStars(CSMesh m, DM dmH3, Vec omega, DM dmH1, Vec star1, Vec star0)
{
  Vec                ol;
  CSLocalSum         s1, s0;
  const PetscScalar *o;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(DMGlobalToLocal(dmH3, omega, INSERT_VALUES, ol));
  PetscCall(VecGetArrayRead(ol, &o));
  PetscCall(CSLocalSumBegin(dmH1, &s1));
  PetscCall(CSLocalSumBegin(m->dmV1, &s0));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal w[3][3], cot[3], an;
    FaceVectors(m, &F, o, w);
    an = FaceCotans(w, cot);
    for (int a = 0; a < 3; a++) {
      s1.a[2 * F.e[a] + CSMeshEdgeSide(m, &F, a)] += 0.5 * cot[a];
      s0.a[F.v[a]] += an / 6;
    }
  }
  PetscCall(CSLocalSumEnd(&s1, star1));
  PetscCall(CSLocalSumEnd(&s0, star0));
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  PetscFunctionReturn(0);
}

/* I_Q on halfedges (soliman2021 Eq. 25 for triangle fields, Algorithm 2 step 10): (I_Q)_h = 1/(w_h l_h^2) with the
   halfedge weight w_h = 1/2 cot theta_h of omega's own triangle and l_h = |omega_h|, w_h floored at wmin as in
   CSOperatorQuadDiffMetric (*nguard: the global number of floored halfedges, may be NULL). Why this form: for
   halfedge multipliers q_h, q_twin carrying an edge's q = q_h + q_twin, min q_h^2 (I_Q)_h + q_twin^2 (I_Q)_twin is
   q^2 / ((w_h + w_twin) l^2), Eq. 25's edge metric, when omega = df (the two halves in series). */
PetscErrorCode CSTriangleFieldQuadDiffMetric(CSMesh m, DM dmH3, Vec omega, DM dmH1, PetscReal wmin, Vec iq, PetscInt *nguard)
{
  Vec                s0;
  PetscInt           n, ng = 0;
  PetscScalar       *a;
  const PetscScalar *o;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(m->dmV1, &s0));
  PetscCall(CSTriangleFieldStars(m, dmH3, omega, dmH1, iq, s0));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &s0));
  PetscCall(VecGetLocalSize(iq, &n));
  PetscCall(VecGetArray(iq, &a));
  PetscCall(VecGetArrayRead(omega, &o));
  for (PetscInt h = 0; h < n; h++) {
    PetscReal w = PetscRealPart(a[h]), v[3] = {PetscRealPart(o[3 * h]), PetscRealPart(o[3 * h + 1]), PetscRealPart(o[3 * h + 2])};
    if (w < wmin) {
      w = wmin;
      ng++;
    }
    a[h] = 1.0 / (w * CSVecDot(v, v));
  }
  PetscCall(VecRestoreArrayRead(omega, &o));
  PetscCall(VecRestoreArray(iq, &a));
  if (nguard) PetscCall(MPIU_Allreduce(&ng, nguard, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscFunctionReturn(0);
}

/* The halfedge vectors opposite corner a of every face (3 entries per local face, a new vector like the face
   vector fields of the viewer): the face's own triangle, not glued to its neighbours. */
PetscErrorCode CSTriangleFieldFaceVectors(CSMesh m, DM dmH3, Vec omega, PetscInt a, Vec *w)
{
  Vec                ol;
  const PetscScalar *o;
  PetscScalar       *p;
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(m->comm, 3 * m->nf, PETSC_DETERMINE, w));
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(DMGlobalToLocal(dmH3, omega, INSERT_VALUES, ol));
  PetscCall(VecGetArrayRead(ol, &o));
  PetscCall(VecGetArray(*w, &p));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal v[3][3];
    FaceVectors(m, &F, o, v);
    for (int d = 0; d < 3; d++) p[3 * F.f + d] = v[a][d];
  }
  PetscCall(VecRestoreArray(*w, &p));
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  PetscFunctionReturn(0);
}
