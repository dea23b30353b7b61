/* Discrete spinors on triangle fields (soliman2021 App. C; include/cs_operators_spinor.h for the conventions).
   Face data (charts, spinors) meet at the edges through halfedge-side vectors: each rank writes its faces' values
   into the slots (e, side) of a local halfedge vector, a LocalToGlobal ADD and a GlobalToLocal give every rank
   both sides of every local edge (the mesh has overlap 0, so the two faces of a cut edge are on two ranks). */
#include "cs_operators_spinor.h"
#include "cs_mesh_adjacency.h"
#include "cs_quaternion.h"

struct _p_CSSpinorSpace {
  CSMesh     mesh;
  DM         dmF4;      /* psi: 4 reals per face */
  DM         dmS4, dmS6; /* halfedge-side exchange: 4 (psi) or 6 (chart dz and psi) reals per halfedge */
  PetscReal *l0;        /* 3 nf: background halfedge lengths per face, opposite corner a */
  PetscReal *tau;       /* 2 ne: the spin connection (Re, Im) per local edge */
  PetscReal *w;         /* ne: (cot alpha + cot beta)/2 of the background metric per local edge */
  PetscBool  hasTau;
};

/* The canonical isometric chart of a triangle with halfedge lengths l (opposite corners 0, 1, 2): dz[2a], dz[2a+1]
   = Re, Im of the halfedge opposite corner a; z(v1) = 0, z(v2) = l_0, z(v0) = l_2 e^{i beta} (beta the angle at
   v1, in (0, pi): the face is counter-clockwise). */
static void Chart(const PetscReal l[3], PetscReal dz[6])
{
  PetscReal c = (l[0] * l[0] + l[2] * l[2] - l[1] * l[1]) / (2 * l[0] * l[2]), s;
  c     = PetscMax(-1.0, PetscMin(1.0, c));
  s     = PetscSqrtReal(1 - c * c);
  dz[0] = l[0];
  dz[1] = 0;
  dz[2] = l[2] * c - l[0];
  dz[3] = l[2] * s;
  dz[4] = -l[2] * c;
  dz[5] = -l[2] * s;
}

/* omega_a = conj(psi) (dz_a j) psi, dz j = x j + y k */
static void FaceField(const PetscReal psi[4], const PetscReal dz[6], PetscReal om[9])
{
  for (int a = 0; a < 3; a++) {
    PetscReal v[3] = {0, dz[2 * a], dz[2 * a + 1]};
    CSQuatSandwich(psi, v, om + 3 * a);
  }
}

static void Cross(const PetscReal a[3], const PetscReal b[3], PetscReal c[3])
{
  c[0] = a[1] * b[2] - a[2] * b[1];
  c[1] = a[2] * b[0] - a[0] * b[2];
  c[2] = a[0] * b[1] - a[1] * b[0];
}

static void Normalize(PetscReal a[3])
{
  PetscReal n = PetscSqrtReal(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
  if (n > 0)
    for (int c = 0; c < 3; c++) a[c] /= n;
}

/* The unit spinor of a face (include/cs_operators_spinor.h): A(1) = a, A(i) = b from A(dz_0) = om_0, A(dz_1) = om_1,
   the rotation R with R i = n, R j = r1, R k = r2 = n x r1, and psi = conj(q) for q v conj(q) = R v. */
static void FaceSpinor(const PetscReal dz[6], const PetscReal om[9], PetscReal psi[4])
{
  const PetscReal det = dz[0] * dz[3] - dz[2] * dz[1];
  PetscReal       a[3], b[3], n[3], nb[3], r1[3], r2[3], R[9], q[4];
  for (int c = 0; c < 3; c++) {
    a[c] = (dz[3] * om[c] - dz[1] * om[3 + c]) / det;
    b[c] = (-dz[2] * om[c] + dz[0] * om[3 + c]) / det;
  }
  Cross(a, b, n);
  Normalize(n);
  Cross(n, b, nb);
  for (int c = 0; c < 3; c++) r1[c] = a[c] - nb[c];
  Normalize(r1);
  Cross(n, r1, r2);
  for (int r = 0; r < 3; r++) {
    R[3 * r]     = n[r];
    R[3 * r + 1] = r1[r];
    R[3 * r + 2] = r2[r];
  }
  CSQuatFromRotation(R, q);
  CSQuatConj(q, psi);
}

/* FaceSpinor with the sign nearer to prev (4 reals; NULL: the one with Re psi >= 0): the gauge of SetConnection's
   reference spinors and of every lift, so that the pinch test compares spinors and tau in the same gauge. */
static void FaceSpinorSigned(const PetscReal dz[6], const PetscReal om[9], const PetscReal *prev, PetscReal psi[4])
{
  PetscReal dot = 0;
  FaceSpinor(dz, om, psi);
  for (int c = 0; c < 4; c++) dot += psi[c] * (prev ? prev[c] : (c ? 0 : 1));
  if (dot < 0)
    for (int c = 0; c < 4; c++) psi[c] = -psi[c];
}

/* The adjoint of the face lift: given G = dE/dpsi at psi = FaceSpinor(dz, om), the gradient dE/dom (9 reals,
   om_2 gets none). delta psi = -1/2 psi delta theta for the frame's angular velocity delta theta
   = 1/2 sum_c e_c x delta e_c (e = n, r1, r2; delta R = [delta theta]x R, q v conj(q) = R v, psi = conj(q)), so
   dE = gamma . delta theta with gamma = -1/2 Im(conj(psi) G); then back through r2 = n x r1, r1 = N(a - n x b),
   n = N(a x b) and the linear a, b of om_0, om_1 (N(v) = v/|v|, delta N = (I - N N^T) delta v/|v|). */
static void FaceSpinorAdjoint(const PetscReal dz[6], const PetscReal om[9], const PetscReal psi[4], const PetscReal G[4], PetscReal gom[9])
{
  const PetscReal det = dz[0] * dz[3] - dz[2] * dz[1];
  PetscReal       a[3], b[3], c[3], n[3], nb[3], v[3], r1[3], r2[3], cg[4], gam[3], gn[3], gr1[3], gr2[3], gv[3], gc[3], ga[3] = {0, 0, 0}, gb[3] = {0, 0, 0}, t[3], lc, lv, pr;
  for (int k = 0; k < 3; k++) {
    a[k] = (dz[3] * om[k] - dz[1] * om[3 + k]) / det;
    b[k] = (-dz[2] * om[k] + dz[0] * om[3 + k]) / det;
  }
  Cross(a, b, c);
  lc = PetscSqrtReal(c[0] * c[0] + c[1] * c[1] + c[2] * c[2]);
  for (int k = 0; k < 3; k++) n[k] = c[k] / lc;
  Cross(n, b, nb);
  for (int k = 0; k < 3; k++) v[k] = a[k] - nb[k];
  lv = PetscSqrtReal(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
  for (int k = 0; k < 3; k++) r1[k] = v[k] / lv;
  Cross(n, r1, r2);
  CSQuatConjMul(psi, G, cg);
  for (int k = 0; k < 3; k++) gam[k] = -0.5 * cg[1 + k];
  Cross(gam, n, gn); /* dE/de_c = 1/2 gamma x e_c */
  Cross(gam, r1, gr1);
  Cross(gam, r2, gr2);
  for (int k = 0; k < 3; k++) {
    gn[k] *= 0.5;
    gr1[k] *= 0.5;
    gr2[k] *= 0.5;
  }
  Cross(r1, gr2, t); /* r2 = n x r1 */
  for (int k = 0; k < 3; k++) gn[k] += t[k];
  Cross(gr2, n, t);
  for (int k = 0; k < 3; k++) gr1[k] += t[k];
  pr = gr1[0] * r1[0] + gr1[1] * r1[1] + gr1[2] * r1[2]; /* r1 = N(v) */
  for (int k = 0; k < 3; k++) gv[k] = (gr1[k] - pr * r1[k]) / lv;
  for (int k = 0; k < 3; k++) ga[k] += gv[k]; /* v = a - n x b */
  Cross(b, gv, t);
  for (int k = 0; k < 3; k++) gn[k] -= t[k];
  Cross(gv, n, t);
  for (int k = 0; k < 3; k++) gb[k] -= t[k];
  pr = gn[0] * n[0] + gn[1] * n[1] + gn[2] * n[2]; /* n = N(c), c = a x b */
  for (int k = 0; k < 3; k++) gc[k] = (gn[k] - pr * n[k]) / lc;
  Cross(b, gc, t);
  for (int k = 0; k < 3; k++) ga[k] += t[k];
  Cross(gc, a, t);
  for (int k = 0; k < 3; k++) gb[k] += t[k];
  for (int k = 0; k < 3; k++) {
    gom[k]     = (dz[3] * ga[k] - dz[2] * gb[k]) / det;
    gom[3 + k] = (-dz[1] * ga[k] + dz[0] * gb[k]) / det;
    gom[6 + k] = 0;
  }
}

/* Both sides of every local edge: loc (local vector of dmS, k reals per halfedge) holds this rank's faces' sides
   (zeros elsewhere); on return it holds both sides of every local edge. */
static PetscErrorCode ExchangeSides(DM dmS, Vec loc)
{
  Vec g;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(dmS, &g));
  PetscCall(VecZeroEntries(g));
  PetscCall(DMLocalToGlobal(dmS, loc, ADD_VALUES, g));
  PetscCall(DMGlobalToLocal(dmS, g, INSERT_VALUES, loc));
  PetscCall(DMRestoreGlobalVector(dmS, &g));
  PetscFunctionReturn(0);
}

/* Background lengths per face corner and the cotan weights w_e = sum over the two sides of 1/2 cot theta. */
static PetscErrorCode SetUpMetric(CSSpinorSpace sp, DM dmH1, Vec lambda0)
{
  CSMesh             m = sp->mesh;
  Vec                ll, wl;
  const PetscScalar *la;
  PetscScalar       *wa;
  DM                 dmS1;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dmH1, &ll));
  PetscCall(DMGlobalToLocal(dmH1, lambda0, INSERT_VALUES, ll));
  PetscCall(VecGetArrayRead(ll, &la));
  PetscCall(CSLensCreateHalfedgeDM(m, 1, &dmS1));
  PetscCall(DMCreateLocalVector(dmS1, &wl));
  PetscCall(VecGetArray(wl, &wa));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal *l = sp->l0 + 3 * F.f, dz[6], area;
    for (int a = 0; a < 3; a++) l[a] = PetscExpReal(PetscRealPart(la[2 * F.e[a] + CSMeshEdgeSide(m, &F, a)]));
    Chart(l, dz);
    area = 0.5 * dz[0] * dz[5] * -1.0; /* 1/2 l_0 Im z(v0) */
    for (int a = 0; a < 3; a++) wa[2 * F.e[a] + CSMeshEdgeSide(m, &F, a)] = (l[(a + 1) % 3] * l[(a + 1) % 3] + l[(a + 2) % 3] * l[(a + 2) % 3] - l[a] * l[a]) / (8 * area);
  }
  PetscCall(VecRestoreArray(wl, &wa));
  PetscCall(ExchangeSides(dmS1, wl));
  PetscCall(VecGetArray(wl, &wa));
  for (PetscInt e = 0; e < m->ne; e++) sp->w[e] = PetscRealPart(wa[2 * e] + wa[2 * e + 1]);
  PetscCall(VecRestoreArray(wl, &wa));
  PetscCall(VecDestroy(&wl));
  PetscCall(DMDestroy(&dmS1));
  PetscCall(VecRestoreArrayRead(ll, &la));
  PetscCall(DMRestoreLocalVector(dmH1, &ll));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorSpaceCreate(CSMesh mesh, DM dmH1, Vec lambda0, CSSpinorSpace *sp)
{
  CSSpinorSpace s;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  s->mesh = mesh;
  PetscCall(CSMeshCreateFieldDM(mesh->dm, 2, 4, "face4", &s->dmF4));
  PetscCall(CSLensCreateHalfedgeDM(mesh, 4, &s->dmS4));
  PetscCall(CSLensCreateHalfedgeDM(mesh, 6, &s->dmS6));
  PetscCall(PetscCalloc3(3 * mesh->nf, &s->l0, 2 * mesh->ne, &s->tau, mesh->ne, &s->w));
  PetscCall(SetUpMetric(s, dmH1, lambda0));
  *sp = s;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorSpaceDestroy(CSSpinorSpace *sp)
{
  PetscFunctionBeginUser;
  if (!*sp) PetscFunctionReturn(0);
  PetscCall(DMDestroy(&(*sp)->dmF4));
  PetscCall(DMDestroy(&(*sp)->dmS4));
  PetscCall(DMDestroy(&(*sp)->dmS6));
  PetscCall(PetscFree3((*sp)->l0, (*sp)->tau, (*sp)->w));
  PetscCall(PetscFree(*sp));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorSpaceGetDM(CSSpinorSpace sp, DM *dmF4)
{
  PetscFunctionBeginUser;
  *dmF4 = sp->dmF4;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorSpaceGetLengths(CSSpinorSpace sp, const PetscReal **l0)
{
  PetscFunctionBeginUser;
  *l0 = sp->l0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorSpaceGetEdge(CSSpinorSpace sp, PetscInt e, PetscReal tau[2], PetscReal *w)
{
  PetscFunctionBeginUser;
  PetscCheck(sp->hasTau, PETSC_COMM_SELF, PETSC_ERR_ORDER, "CSSpinorSpaceSetConnection first");
  tau[0] = sp->tau[2 * e];
  tau[1] = sp->tau[2 * e + 1];
  *w     = sp->w[e];
  PetscFunctionReturn(0);
}

/* Per local edge: the chart vectors dz0 (side 0, i -> j) and dz1 (side 1, j -> i) give the chart change
   r = -dz1/dz0 (unit for equal lengths) from face ijk to face jil, tau = +-sqrt(r) with the sign of the
   reference spinors: <psi1, tau psi0> >= 0. */
PetscErrorCode CSSpinorSpaceSetConnection(CSSpinorSpace sp, DM dmH3, Vec omega_ref)
{
  CSMesh             m = sp->mesh;
  Vec                ol, sl;
  const PetscScalar *o;
  PetscScalar       *s;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(DMGlobalToLocal(dmH3, omega_ref, INSERT_VALUES, ol));
  PetscCall(VecGetArrayRead(ol, &o));
  PetscCall(DMCreateLocalVector(sp->dmS6, &sl));
  PetscCall(VecGetArray(sl, &s));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal dz[6], om[9], psi[4];
    Chart(sp->l0 + 3 * F.f, dz);
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < 3; c++) om[3 * a + c] = PetscRealPart(o[6 * F.e[a] + 3 * CSMeshEdgeSide(m, &F, a) + c]);
    FaceSpinorSigned(dz, om, NULL, psi);
    for (int a = 0; a < 3; a++) {
      PetscScalar *slot = s + 12 * F.e[a] + 6 * CSMeshEdgeSide(m, &F, a);
      slot[0]           = dz[2 * a];
      slot[1]           = dz[2 * a + 1];
      for (int c = 0; c < 4; c++) slot[2 + c] = psi[c];
    }
  }
  PetscCall(VecRestoreArray(sl, &s));
  PetscCall(ExchangeSides(sp->dmS6, sl));
  PetscCall(VecGetArray(sl, &s));
  for (PetscInt e = 0; e < m->ne; e++) {
    const PetscScalar *s0 = s + 12 * e, *s1 = s0 + 6;
    PetscReal          d2 = PetscSqr(PetscRealPart(s0[0])) + PetscSqr(PetscRealPart(s0[1])), re, im, mod, tq[4], p0[4], p1[4], tp[4], dot = 0;
    re  = -(PetscRealPart(s1[0]) * PetscRealPart(s0[0]) + PetscRealPart(s1[1]) * PetscRealPart(s0[1])) / d2;
    im  = -(PetscRealPart(s1[1]) * PetscRealPart(s0[0]) - PetscRealPart(s1[0]) * PetscRealPart(s0[1])) / d2;
    mod = PetscSqrtReal(re * re + im * im);
    re /= mod;
    im /= mod;
    tq[0] = PetscSqrtReal(PetscMax(0.0, (1 + re) / 2)); /* principal root of the unit complex r */
    tq[1] = (im >= 0 ? 1 : -1) * PetscSqrtReal(PetscMax(0.0, (1 - re) / 2));
    tq[2] = tq[3] = 0;
    for (int c = 0; c < 4; c++) {
      p0[c] = PetscRealPart(s0[2 + c]);
      p1[c] = PetscRealPart(s1[2 + c]);
    }
    CSQuatMul(tq, p0, tp);
    for (int c = 0; c < 4; c++) dot += p1[c] * tp[c];
    sp->tau[2 * e]     = dot >= 0 ? tq[0] : -tq[0];
    sp->tau[2 * e + 1] = dot >= 0 ? tq[1] : -tq[1];
  }
  PetscCall(VecRestoreArray(sl, &s));
  PetscCall(VecDestroy(&sl));
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  sp->hasTau = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorFromTriangleField(CSSpinorSpace sp, DM dmH3, Vec omega, Vec psi_prev, Vec psi)
{
  CSMesh             m = sp->mesh;
  Vec                ol;
  const PetscScalar *o, *pp = NULL;
  PetscScalar       *p;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(DMGlobalToLocal(dmH3, omega, INSERT_VALUES, ol));
  PetscCall(VecGetArrayRead(ol, &o));
  PetscCall(VecGetArray(psi, &p)); /* overlap 0: the local faces are the owned ones, in order (4 per face) */
  if (psi_prev) PetscCall(VecGetArrayRead(psi_prev, &pp));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal dz[6], om[9], q[4], prev[4];
    Chart(sp->l0 + 3 * F.f, dz);
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < 3; c++) om[3 * a + c] = PetscRealPart(o[6 * F.e[a] + 3 * CSMeshEdgeSide(m, &F, a) + c]);
    for (int c = 0; c < 4; c++) prev[c] = pp ? PetscRealPart(pp[4 * F.f + c]) : 0;
    FaceSpinorSigned(dz, om, pp ? prev : NULL, q);
    for (int c = 0; c < 4; c++) p[4 * F.f + c] = q[c];
  }
  if (psi_prev) PetscCall(VecRestoreArrayRead(psi_prev, &pp));
  PetscCall(VecRestoreArray(psi, &p));
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorTriangleField(CSSpinorSpace sp, Vec u, Vec psi, DM dmH3, Vec omega)
{
  CSMesh             m = sp->mesh;
  Vec                ul = NULL, ol;
  const PetscScalar *ua = NULL, *p;
  PetscScalar       *o;
  PetscFunctionBeginUser;
  if (u) {
    PetscCall(DMGetLocalVector(m->dmV1, &ul));
    PetscCall(DMGlobalToLocal(m->dmV1, u, INSERT_VALUES, ul));
    PetscCall(VecGetArrayRead(ul, &ua));
  }
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(VecZeroEntries(ol));
  PetscCall(VecGetArray(ol, &o));
  PetscCall(VecGetArrayRead(psi, &p));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscReal l[3], dz[6], q[4], om[9];
    for (int a = 0; a < 3; a++) l[a] = sp->l0[3 * F.f + a] * (ua ? PetscExpReal(0.5 * PetscRealPart(ua[F.v[(a + 1) % 3]] + ua[F.v[(a + 2) % 3]])) : 1.0);
    Chart(l, dz);
    for (int c = 0; c < 4; c++) q[c] = PetscRealPart(p[4 * F.f + c]);
    FaceField(q, dz, om);
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < 3; c++) o[6 * F.e[a] + 3 * CSMeshEdgeSide(m, &F, a) + c] = om[3 * a + c];
  }
  PetscCall(VecRestoreArrayRead(psi, &p));
  PetscCall(VecRestoreArray(ol, &o));
  PetscCall(VecZeroEntries(omega));
  PetscCall(DMLocalToGlobal(dmH3, ol, ADD_VALUES, omega)); /* each halfedge is written by its face's rank only */
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  if (u) {
    PetscCall(VecRestoreArrayRead(ul, &ua));
    PetscCall(DMRestoreLocalVector(m->dmV1, &ul));
  }
  PetscFunctionReturn(0);
}

/* The spinors of both sides of every local edge (local vector of dmS4, 8 per edge: side 0, side 1). */
static PetscErrorCode SpinorSides(CSSpinorSpace sp, Vec psi, Vec sl)
{
  CSMesh             m = sp->mesh;
  const PetscScalar *p;
  PetscScalar       *s;
  PetscFunctionBeginUser;
  PetscCall(VecZeroEntries(sl));
  PetscCall(VecGetArrayRead(psi, &p));
  PetscCall(VecGetArray(sl, &s));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);)
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < 4; c++) s[8 * F.e[a] + 4 * CSMeshEdgeSide(m, &F, a) + c] = p[4 * F.f + c];
  PetscCall(VecRestoreArray(sl, &s));
  PetscCall(VecRestoreArrayRead(psi, &p));
  PetscCall(ExchangeSides(sp->dmS4, sl));
  PetscFunctionReturn(0);
}

/* r = psi1 - tau psi0 of local edge e from its sides s (8 reals) */
static void EdgeDefect(CSSpinorSpace sp, PetscInt e, const PetscScalar *s, PetscReal r[4])
{
  PetscReal t[4] = {sp->tau[2 * e], sp->tau[2 * e + 1], 0, 0}, p0[4], tp[4];
  for (int c = 0; c < 4; c++) p0[c] = PetscRealPart(s[c]);
  CSQuatMul(t, p0, tp);
  for (int c = 0; c < 4; c++) r[c] = PetscRealPart(s[4 + c]) - tp[c];
}

/* E_tau = 1/2 sum w |r_e|^2, r_e = psi1 - tau psi0: dE/dpsi1 = w r_e, dE/dpsi0 = -w conj(tau) r_e. */
PetscErrorCode CSSpinorDirichlet(CSSpinorSpace sp, Vec psi, PetscReal *E, Vec grad)
{
  CSMesh       m = sp->mesh;
  Vec          sl, gl = NULL;
  PetscScalar *s, *g = NULL;
  PetscReal    sum = 0;
  PetscFunctionBeginUser;
  PetscCheck(sp->hasTau, m->comm, PETSC_ERR_ORDER, "CSSpinorSpaceSetConnection first");
  PetscCall(DMGetLocalVector(sp->dmS4, &sl));
  PetscCall(SpinorSides(sp, psi, sl));
  PetscCall(VecGetArray(sl, &s));
  if (grad) {
    PetscCall(DMGetLocalVector(sp->dmS4, &gl));
    PetscCall(VecZeroEntries(gl));
    PetscCall(VecGetArray(gl, &g));
  }
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscReal r[4], tc[4] = {sp->tau[2 * e], -sp->tau[2 * e + 1], 0, 0}, d0[4];
    if (!m->edgeOwned[e]) continue;
    EdgeDefect(sp, e, s + 8 * e, r);
    sum += 0.5 * sp->w[e] * CSQuatNorm2(r);
    if (!g) continue;
    CSQuatMul(tc, r, d0);
    for (int c = 0; c < 4; c++) {
      g[8 * e + c]     = -sp->w[e] * d0[c];
      g[8 * e + 4 + c] = sp->w[e] * r[c];
    }
  }
  PetscCall(VecRestoreArray(sl, &s));
  PetscCall(DMRestoreLocalVector(sp->dmS4, &sl));
  PetscCall(MPIU_Allreduce(&sum, E, 1, MPIU_REAL, MPIU_SUM, m->comm));
  if (grad) {
    PetscScalar *ga;
    PetscCall(VecRestoreArray(gl, &g));
    PetscCall(ExchangeSides(sp->dmS4, gl)); /* only owned edges wrote: the sum is their value */
    PetscCall(VecGetArray(gl, &g));
    PetscCall(VecGetArray(grad, &ga));
    PetscCall(PetscArrayzero(ga, 4 * m->nf));
    for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);)
      for (int a = 0; a < 3; a++)
        for (int c = 0; c < 4; c++) ga[4 * F.f + c] += g[8 * F.e[a] + 4 * CSMeshEdgeSide(m, &F, a) + c];
    PetscCall(VecRestoreArray(grad, &ga));
    PetscCall(VecRestoreArray(gl, &g));
    PetscCall(DMRestoreLocalVector(sp->dmS4, &gl));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinorPinchEdges(CSSpinorSpace sp, Vec psi, PetscInt *npinch, PetscReal *dmax)
{
  CSMesh       m = sp->mesh;
  Vec          sl;
  PetscScalar *s;
  PetscInt     n = 0;
  PetscReal    mx = 0;
  PetscFunctionBeginUser;
  PetscCheck(sp->hasTau, m->comm, PETSC_ERR_ORDER, "CSSpinorSpaceSetConnection first");
  PetscCall(DMGetLocalVector(sp->dmS4, &sl));
  PetscCall(SpinorSides(sp, psi, sl));
  PetscCall(VecGetArray(sl, &s));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscReal r[4];
    if (!m->edgeOwned[e]) continue;
    EdgeDefect(sp, e, s + 8 * e, r);
    if (CSQuatNorm2(r) >= 2) n++;
    mx = PetscMax(mx, PetscSqrtReal(CSQuatNorm2(r)));
  }
  PetscCall(VecRestoreArray(sl, &s));
  PetscCall(DMRestoreLocalVector(sp->dmS4, &sl));
  PetscCall(MPIU_Allreduce(&n, npinch, 1, MPIU_INT, MPI_SUM, m->comm));
  if (dmax) PetscCall(MPIU_Allreduce(&mx, dmax, 1, MPIU_REAL, MPIU_MAX, m->comm));
  PetscFunctionReturn(0);
}

/* The gauge-invariant pinch-point test: an interior vertex is a pinch point when an odd number of its edges fail the
   edge test (<psi_jil, tau_ij psi_ijk> <= 0, i.e. |psi_jil - tau_ij psi_ijk| >= sqrt 2): the spinor carried around
   its star by tau returns with the sign -1 (the star turns once more than the reference's, Chern et al. 2018).
   Flipping one face's spinor (the Z2 gauge) fails its 3 edges, 2 at each of its corners: the parity is unchanged,
   so the count does not depend on the signs the run's lifts happened to follow, unlike CSSpinorPinchEdges. */
PetscErrorCode CSSpinorPinchVertices(CSSpinorSpace sp, Vec psi, PetscInt *npinch)
{
  CSMesh             m = sp->mesh;
  Vec                sl, pl, pg;
  PetscScalar       *s, *par;
  const PetscScalar *pa;
  PetscInt           n = 0;
  PetscFunctionBeginUser;
  PetscCheck(sp->hasTau, m->comm, PETSC_ERR_ORDER, "CSSpinorSpaceSetConnection first");
  PetscCall(DMGetLocalVector(sp->dmS4, &sl));
  PetscCall(SpinorSides(sp, psi, sl));
  PetscCall(VecGetArray(sl, &s));
  PetscCall(DMGetLocalVector(m->dmV1, &pl));
  PetscCall(VecZeroEntries(pl));
  PetscCall(VecGetArray(pl, &par));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscReal r[4];
    if (!m->edgeOwned[e] || m->edgeBoundary[e]) continue;
    EdgeDefect(sp, e, s + 8 * e, r);
    if (CSQuatNorm2(r) < 2) continue;
    for (int k = 0; k < 2; k++) par[m->edgeVert[2 * e + k]] += 1;
  }
  PetscCall(VecRestoreArray(pl, &par));
  PetscCall(VecRestoreArray(sl, &s));
  PetscCall(DMRestoreLocalVector(sp->dmS4, &sl));
  PetscCall(DMGetGlobalVector(m->dmV1, &pg));
  PetscCall(VecZeroEntries(pg));
  PetscCall(DMLocalToGlobal(m->dmV1, pl, ADD_VALUES, pg)); /* each edge counted once (owned): the star's failures */
  PetscCall(DMGlobalToLocal(m->dmV1, pg, INSERT_VALUES, pl));
  PetscCall(VecGetArrayRead(pl, &pa));
  for (PetscInt v = 0; v < m->nv; v++)
    if (m->vertOwned[v] && !m->vertBoundary[v] && ((PetscInt)(PetscRealPart(pa[v]) + 0.5)) % 2) n++;
  PetscCall(VecRestoreArrayRead(pl, &pa));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &pg));
  PetscCall(DMRestoreLocalVector(m->dmV1, &pl));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &n, 1, MPIU_INT, MPI_SUM, m->comm));
  *npinch = n;
  PetscFunctionReturn(0);
}

/* E_tau(psi(omega)) with psi the lift of omega (signs nearer to psi_prev, NULL: Re psi >= 0), written to psi (dmF4,
   may be NULL), and its gradient with respect to omega (dmH3; may be NULL) through FaceSpinorAdjoint. */
PetscErrorCode CSSpinorDirichletTriangleField(CSSpinorSpace sp, DM dmH3, Vec omega, Vec psi_prev, PetscReal *E, Vec grad, Vec psi)
{
  CSMesh             m = sp->mesh;
  Vec                p = psi, G = NULL, ol, gl;
  const PetscScalar *o, *pa, *ga;
  PetscScalar       *g;
  PetscFunctionBeginUser;
  if (!p) PetscCall(DMGetGlobalVector(sp->dmF4, &p));
  PetscCall(CSSpinorFromTriangleField(sp, dmH3, omega, psi_prev, p));
  if (grad) PetscCall(DMGetGlobalVector(sp->dmF4, &G));
  PetscCall(CSSpinorDirichlet(sp, p, E, G));
  if (grad) {
    PetscCall(DMGetLocalVector(dmH3, &ol));
    PetscCall(DMGlobalToLocal(dmH3, omega, INSERT_VALUES, ol));
    PetscCall(DMGetLocalVector(dmH3, &gl));
    PetscCall(VecZeroEntries(gl));
    PetscCall(VecGetArrayRead(ol, &o));
    PetscCall(VecGetArray(gl, &g));
    PetscCall(VecGetArrayRead(p, &pa));
    PetscCall(VecGetArrayRead(G, &ga));
    for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
      PetscReal dz[6], om[9], q[4], gq[4], gom[9];
      Chart(sp->l0 + 3 * F.f, dz);
      for (int a = 0; a < 3; a++)
        for (int c = 0; c < 3; c++) om[3 * a + c] = PetscRealPart(o[6 * F.e[a] + 3 * CSMeshEdgeSide(m, &F, a) + c]);
      for (int c = 0; c < 4; c++) {
        q[c]  = PetscRealPart(pa[4 * F.f + c]);
        gq[c] = PetscRealPart(ga[4 * F.f + c]);
      }
      FaceSpinorAdjoint(dz, om, q, gq, gom);
      for (int a = 0; a < 3; a++)
        for (int c = 0; c < 3; c++) g[6 * F.e[a] + 3 * CSMeshEdgeSide(m, &F, a) + c] = gom[3 * a + c];
    }
    PetscCall(VecRestoreArrayRead(G, &ga));
    PetscCall(VecRestoreArrayRead(p, &pa));
    PetscCall(VecRestoreArray(gl, &g));
    PetscCall(VecRestoreArrayRead(ol, &o));
    PetscCall(VecZeroEntries(grad));
    PetscCall(DMLocalToGlobal(dmH3, gl, ADD_VALUES, grad));
    PetscCall(DMRestoreLocalVector(dmH3, &gl));
    PetscCall(DMRestoreLocalVector(dmH3, &ol));
    PetscCall(DMRestoreGlobalVector(sp->dmF4, &G));
  }
  if (!psi) PetscCall(DMRestoreGlobalVector(sp->dmF4, &p));
  PetscFunctionReturn(0);
}
