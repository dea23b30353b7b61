/* -flow_type trianglefield -flow_variables spinor: Algorithm 2 in the spinor parametrisation of soliman2021 App. C.2
   and C.3. The variables are x = (u, psi) in R^V x H^F (per rank: its owned vertices' u, then its faces' psi, 4
   reals each), the triangle field is omega = S_c(u, psi) = S(e^u l0, psi) (CSSpinorTriangleField), conformal by
   construction, so the conformal rows are dropped. The energy is W~(S_c(u, psi)) + w E_tau(psi) (App. D.1, C.3),
   its gradient J^T grad W~ + w grad E_tau with J = dS_c (assembled, 3H x (V + 4F)). The constraint rows are the
   lens integrability d1 omega (Eq. 31) and the periods <<Y_i|omega>> (Eq. 13), linearised through J, and the sphere
   rows (|psi_f|^2 - 1)/2 = 0. The metric is the pull-back J^T I_H1 J of the triangle fields' metric (Eq. 32) plus
   a psi_f psi_f^T on each face (J^T I_H1 J vanishes on (du, dpsi) = (2, -psi), the trade of a uniform scale
   between u and |psi|; the radial term, with one a = the mean over all faces of J^T I_H1 J's psi diagonal, makes it
   definite), and the
   sphere rows make the step tangent to (S^3)^F to first order; each accepted state is renormalised to |psi_f| = 1
   exactly (docs/triangle_fields.md, "The spinor flow"). */
#include "trianglefield_impl.h"
#include "cs_quaternion.h"
#include "cs_mesh_adjacency.h"
#include <math.h>

/* The two parts of x: u as a dmV1 global vector, psi as a dmF4 global vector (copies). */
static PetscErrorCode SplitX(CSTriangleField *d, Vec x, Vec u, Vec psi)
{
  const PetscScalar *a;
  PetscScalar       *b;
  PetscInt           nu, np;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(u, &nu));
  PetscCall(VecGetLocalSize(psi, &np));
  PetscCall(VecGetArrayRead(x, &a));
  PetscCall(VecGetArray(u, &b));
  PetscCall(PetscArraycpy(b, a, nu));
  PetscCall(VecRestoreArray(u, &b));
  PetscCall(VecGetArray(psi, &b));
  PetscCall(PetscArraycpy(b, a + nu, np));
  PetscCall(VecRestoreArray(psi, &b));
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscFunctionReturn(0);
}

/* x = (u, psi) */
static PetscErrorCode JoinX(CSTriangleField *d, Vec u, Vec psi, Vec x)
{
  const PetscScalar *b;
  PetscScalar       *a;
  PetscInt           nu, np;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(u, &nu));
  PetscCall(VecGetLocalSize(psi, &np));
  PetscCall(VecGetArray(x, &a));
  PetscCall(VecGetArrayRead(u, &b));
  PetscCall(PetscArraycpy(a, b, nu));
  PetscCall(VecRestoreArrayRead(u, &b));
  PetscCall(VecGetArrayRead(psi, &b));
  PetscCall(PetscArraycpy(a + nu, b, np));
  PetscCall(VecRestoreArrayRead(psi, &b));
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(0);
}

/* omega = S_c(u, psi) of x (dmH3); the parts are left in d->ug, d->pg. */
PetscErrorCode CSTFSpinorOmega(CSTriangleField *d, Vec x, Vec omega)
{
  PetscFunctionBeginUser;
  PetscCall(SplitX(d, x, d->ug, d->pg));
  PetscCall(CSSpinorTriangleField(d->sp, d->ug, d->pg, d->dmH3, omega));
  PetscFunctionReturn(0);
}

/* The canonical chart of CSSpinorTriangleField (spinor.c Chart) and its derivatives ddz[b][.] with respect to the
   halfedge lengths l_b: z(v0) = X + iY, X = (l0^2 + l2^2 - l1^2)/(2 l0), Y = sqrt(l2^2 - X^2). */
static void ChartDerivative(const PetscReal l[3], PetscReal dz[6], PetscReal ddz[3][6])
{
  PetscReal X = (l[0] * l[0] + l[2] * l[2] - l[1] * l[1]) / (2 * l[0]), Y = PetscSqrtReal(PetscMax(l[2] * l[2] - X * X, 0.0)), dX[3], dY[3];
  dX[0] = 0.5 - (l[2] * l[2] - l[1] * l[1]) / (2 * l[0] * l[0]);
  dX[1] = -l[1] / l[0];
  dX[2] = l[2] / l[0];
  for (int b = 0; b < 3; b++) dY[b] = ((b == 2 ? l[2] : 0) - X * dX[b]) / PetscMax(Y, PETSC_SMALL * l[0]);
  dz[0] = l[0];
  dz[1] = 0;
  dz[2] = X - l[0];
  dz[3] = Y;
  dz[4] = -X;
  dz[5] = -Y;
  for (int b = 0; b < 3; b++) {
    ddz[b][0] = b == 0;
    ddz[b][1] = 0;
    ddz[b][2] = dX[b] - (b == 0);
    ddz[b][3] = dY[b];
    ddz[b][4] = -dX[b];
    ddz[b][5] = -dY[b];
  }
}

/* The 9 x 7 Jacobian of one face's omega_a = conj(psi) (dz_a j) psi (a = 0, 1, 2, 3 components each) with respect
   to (u_v0, u_v1, u_v2, psi_0..3), row major: l_a = l0_a e^{(u_{a+1} + u_{a+2})/2}, dl_a/du_v = l_a/2 for the
   two ends v of halfedge a; d(conj(psi) v psi) = conj(dpsi) v psi + conj(psi) v dpsi. */
static void FaceJacobian(const PetscReal l0[3], const PetscReal uf[3], const PetscReal psi[4], PetscReal Jf[63])
{
  PetscReal l[3], dz[6], ddz[3][6];
  for (int a = 0; a < 3; a++) l[a] = l0[a] * PetscExpReal(0.5 * (uf[(a + 1) % 3] + uf[(a + 2) % 3]));
  ChartDerivative(l, dz, ddz);
  for (int a = 0; a < 3; a++) {
    PetscReal vq[4] = {0, 0, dz[2 * a], dz[2 * a + 1]};
    for (int k = 0; k < 3; k++) { /* u of corner k: the halfedges a != k have k as an end */
      PetscReal dv[3] = {0, 0, 0}, r[3];
      for (int b = 0; b < 3; b++)
        if (b != k) {
          dv[1] += ddz[b][2 * a] * 0.5 * l[b];
          dv[2] += ddz[b][2 * a + 1] * 0.5 * l[b];
        }
      CSQuatSandwich(psi, dv, r);
      for (int c = 0; c < 3; c++) Jf[7 * (3 * a + c) + k] = r[c];
    }
    for (int q = 0; q < 4; q++) {
      PetscReal e[4] = {0, 0, 0, 0}, t[4], A[4], B[4];
      e[q] = 1;
      CSQuatConjMul(e, vq, t);
      CSQuatMul(t, psi, A);
      CSQuatConjMul(psi, vq, t);
      CSQuatMul(t, e, B);
      for (int c = 0; c < 3; c++) Jf[7 * (3 * a + c) + 3 + q] = A[1 + c] + B[1 + c];
    }
  }
}

/* J = dS_c at x (rows dmH3, columns x; every face sets its 9 x 7 block, the pattern is fixed). */
PetscErrorCode CSTFSpinorJacobian(CSWillmoreFlow F, CSTriangleField *d, Vec x)
{
  CSMesh             m = F->mesh;
  Vec                ul;
  const PetscScalar *ua, *pa;
  const PetscReal   *l0;
  PetscFunctionBeginUser;
  PetscCall(SplitX(d, x, d->ug, d->pg));
  PetscCall(CSSpinorSpaceGetLengths(d->sp, &l0));
  PetscCall(DMGetLocalVector(m->dmV1, &ul));
  PetscCall(DMGlobalToLocal(m->dmV1, d->ug, INSERT_VALUES, ul));
  PetscCall(VecGetArrayRead(ul, &ua));
  PetscCall(VecGetArrayRead(d->pg, &pa));
  PetscCall(MatZeroEntries(d->J));
  for (CSFaceIter f = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &f);) {
    PetscReal   uf[3], q[4], Jf[63];
    PetscInt    rows[9], cols[7];
    PetscScalar v[63];
    for (int k = 0; k < 3; k++) uf[k] = PetscRealPart(ua[f.v[k]]);
    for (int c = 0; c < 4; c++) q[c] = PetscRealPart(pa[4 * f.f + c]);
    FaceJacobian(l0 + 3 * f.f, uf, q, Jf);
    for (int a = 0; a < 3; a++)
      for (int c = 0; c < 3; c++) rows[3 * a + c] = 6 * f.e[a] + 3 * CSMeshEdgeSide(m, &f, a) + c;
    for (int k = 0; k < 3; k++) cols[k] = f.v[k];
    for (int c = 0; c < 4; c++) cols[3 + c] = m->nv + 4 * f.f + c;
    for (int i = 0; i < 63; i++) v[i] = Jf[i];
    PetscCall(MatSetValuesLocal(d->J, 9, rows, 7, cols, v, INSERT_VALUES));
  }
  PetscCall(VecRestoreArrayRead(d->pg, &pa));
  PetscCall(VecRestoreArrayRead(ul, &ua));
  PetscCall(DMRestoreLocalVector(m->dmV1, &ul));
  PetscCall(MatAssemblyBegin(d->J, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(d->J, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* The faces (global count) whose lengths e^{(u_i + u_j)/2} l0 violate a triangle inequality at the split u (d->ug):
   S_c is not defined there (the chart does not exist; CSSpinorTriangleField flattens such a face, which breaks the
   conformal class). */
static PetscErrorCode FlatFaces(CSWillmoreFlow F, CSTriangleField *d, PetscInt *nflat)
{
  CSMesh             m = F->mesh;
  Vec                ul;
  const PetscScalar *ua;
  const PetscReal   *l0;
  PetscInt           n = 0;
  PetscFunctionBeginUser;
  PetscCall(CSSpinorSpaceGetLengths(d->sp, &l0));
  PetscCall(DMGetLocalVector(m->dmV1, &ul));
  PetscCall(DMGlobalToLocal(m->dmV1, d->ug, INSERT_VALUES, ul));
  PetscCall(VecGetArrayRead(ul, &ua));
  for (CSFaceIter f = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &f);) {
    PetscReal l[3];
    for (int a = 0; a < 3; a++) l[a] = l0[3 * f.f + a] * PetscExpReal(0.5 * PetscRealPart(ua[f.v[(a + 1) % 3]] + ua[f.v[(a + 2) % 3]]));
    if (!(l[0] < l[1] + l[2] && l[1] < l[2] + l[0] && l[2] < l[0] + l[1])) n++;
  }
  PetscCall(VecRestoreArrayRead(ul, &ua));
  PetscCall(DMRestoreLocalVector(m->dmV1, &ul));
  PetscCall(MPIU_Allreduce(&n, nflat, 1, MPIU_INT, MPI_SUM, F->hdr.comm));
  PetscFunctionReturn(0);
}

/* The energy in the spinor variables: W~(S_c(x)) + w E_tau(psi), gradient J^T grad W~ + w (0, grad E_tau); not a
   number outside S_c's domain (a face violating the triangle inequality), so that the step filter rejects it. */
PetscErrorCode CSTFSpinorEnergy(CSWillmoreFlow F, CSTriangleField *d, Vec x, PetscReal *E, Vec g)
{
  PetscReal Es = 0;
  PetscInt  nflat;
  PetscFunctionBeginUser;
  PetscCall(CSTFSpinorOmega(d, x, d->omt));
  PetscCall(FlatFaces(F, d, &nflat));
  if (nflat && E && !g) {
    *E = (PetscReal)NAN;
    PetscFunctionReturn(0);
  }
  PetscCall(CSTriangleFieldWillmore(F->mesh, d->dmH3, d->omt, E, g ? d->gom : NULL));
  if (g) {
    PetscCall(CSTFSpinorJacobian(F, d, x));
    PetscCall(MatMultTranspose(d->J, d->gom, g));
  }
  if (d->wspin <= 0) PetscFunctionReturn(0);
  PetscCall(CSSpinorDirichlet(d->sp, d->pg, &Es, g ? d->gpsi : NULL));
  if (E) *E += d->wspin * Es;
  if (g) {
    PetscScalar       *a;
    const PetscScalar *b;
    PetscInt           nu, np;
    PetscCall(VecGetLocalSize(d->ug, &nu));
    PetscCall(VecGetLocalSize(d->gpsi, &np));
    PetscCall(VecGetArray(g, &a));
    PetscCall(VecGetArrayRead(d->gpsi, &b));
    for (PetscInt i = 0; i < np; i++) a[nu + i] += d->wspin * b[i];
    PetscCall(VecRestoreArrayRead(d->gpsi, &b));
    PetscCall(VecRestoreArray(g, &a));
  }
  PetscFunctionReturn(0);
}

/* The sphere rows' Jacobian P (nf x x: psi_f^T in face f's psi columns), refilled at x. */
static PetscErrorCode SphereJacobian(CSWillmoreFlow F, CSTriangleField *d)
{
  const PetscScalar *p;
  PetscInt           rs;
  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(d->P, &rs, NULL));
  PetscCall(VecGetArrayRead(d->pg, &p));
  for (PetscInt f = 0; f < F->mesh->nf; f++) {
    PetscInt row = rs + f, cols[4];
    for (int c = 0; c < 4; c++) cols[c] = d->xstart + d->nVo + 4 * f + c;
    PetscCall(MatSetValues(d->P, 1, &row, 4, cols, p + 4 * f, INSERT_VALUES));
  }
  PetscCall(VecRestoreArrayRead(d->pg, &p));
  PetscCall(MatAssemblyBegin(d->P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(d->P, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* c = [d1 omega | (|psi_f|^2 - 1)/2], cx_j = <<Y_j|omega>>; with wantJ X = [Kd1 J; P] and rows_j = J^T Y_j. */
PetscErrorCode CSTFSpinorConstraints(CSWillmoreFlow F, Vec x, Vec c, PetscReal cx[], PetscBool wantJ)
{
  CSTriangleField   *d = (CSTriangleField *)F->data;
  PetscScalar       *a;
  const PetscScalar *b, *p;
  PetscFunctionBeginUser;
  PetscCall(CSTFSpinorOmega(d, x, d->omt));
  PetscCall(MatMult(d->Klin, d->omt, d->clin));
  PetscCall(VecGetArray(c, &a));
  PetscCall(VecGetArrayRead(d->clin, &b));
  for (PetscInt i = 0; i < d->nL; i++) a[i] = b[i];
  PetscCall(VecRestoreArrayRead(d->clin, &b));
  PetscCall(VecGetArrayRead(d->pg, &p));
  for (PetscInt f = 0; f < F->mesh->nf; f++) {
    PetscReal n2 = 0;
    for (int k = 0; k < 4; k++) n2 += PetscSqr(PetscRealPart(p[4 * f + k]));
    a[d->nL + f] = 0.5 * (n2 - 1);
  }
  PetscCall(VecRestoreArrayRead(d->pg, &p));
  PetscCall(VecRestoreArray(c, &a));
  for (PetscInt j = 0; j < 3 * d->nforms; j++) {
    PetscScalar v;
    PetscCall(VecDot(d->rowsOm[j], d->omt, &v));
    cx[j] = PetscRealPart(v);
  }
  if (d->wgauge > 0) { /* the scale gauge: mean(u) = its start value (W~ is scale invariant, the homogeneous integrability rows are
       met by omega -> 0; without it the first steps of a non-integrable start shrink the field 5000-fold) */
    const PetscScalar *xa;
    PetscReal          s = 0;
    PetscCall(VecGetArrayRead(x, &xa));
    for (PetscInt i = 0; i < d->nVo; i++) s += PetscRealPart(xa[i]);
    PetscCall(VecRestoreArrayRead(x, &xa));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &s, 1, MPIU_REAL, MPIU_SUM, F->hdr.comm));
    cx[3 * d->nforms] = s / F->mesh->Nv - d->ubar0;
  }
  if (!wantJ) PetscFunctionReturn(0);
  PetscCall(CSTFSpinorJacobian(F, d, x));
  PetscCall(SphereJacobian(F, d));
  {
    Mat B[2];
    PetscCall(MatMatMult(d->Klin, d->J, d->KJ ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, PETSC_DEFAULT, &d->KJ));
    B[0] = d->KJ;
    B[1] = d->P;
    PetscCall(CSMatStackRows(2, B, d->X ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &d->X));
  }
  F->Xc = d->X;
  for (PetscInt j = 0; j < 3 * d->nforms; j++) PetscCall(MatMultTranspose(d->J, d->rowsOm[j], F->rows[j]));
  PetscFunctionReturn(0);
}

/* The metric of the step: J^T I_H1 J (the triangle fields' metric Hom pulled back) plus a psi_f psi_f^T per face. */
PetscErrorCode CSTFSpinorMetric(CSWillmoreFlow F, CSTriangleField *d)
{
  Vec                dg;
  const PetscScalar *g, *p;
  PetscReal          a = 0;
  PetscInt           rs;
  PetscFunctionBeginUser;
  PetscCall(MatPtAP(d->Hom, d->J, F->metric.H ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, 2.0, &F->metric.H));
  PetscCall(MatCreateVecs(F->metric.H, &dg, NULL));
  PetscCall(MatGetDiagonal(F->metric.H, dg));
  PetscCall(VecGetArrayRead(dg, &g));
  for (PetscInt i = d->nVo; i < d->nVo + 4 * F->mesh->nf; i++) a += PetscRealPart(g[i]);
  PetscCall(VecRestoreArrayRead(dg, &g));
  PetscCall(VecDestroy(&dg));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &a, 1, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  a /= 4.0 * F->mesh->Nf;
  PetscCall(MatGetOwnershipRange(F->metric.H, &rs, NULL));
  PetscCall(VecGetArrayRead(d->pg, &p));
  for (PetscInt f = 0; f < F->mesh->nf; f++) {
    PetscInt    idx[4];
    PetscScalar v[16];
    for (int c = 0; c < 4; c++) idx[c] = rs + d->nVo + 4 * f + c;
    for (int r = 0; r < 4; r++)
      for (int c = 0; c < 4; c++) v[4 * r + c] = a * p[4 * f + r] * p[4 * f + c];
    PetscCall(MatSetValues(F->metric.H, 4, idx, 4, idx, v, ADD_VALUES));
  }
  PetscCall(VecRestoreArrayRead(d->pg, &p));
  PetscCall(MatAssemblyBegin(F->metric.H, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(F->metric.H, MAT_FINAL_ASSEMBLY));
  if (d->mshift > 0) PetscCall(MatShift(F->metric.H, d->mshift * a)); /* -flow_spinor_metric_shift */
  PetscFunctionReturn(0);
}

/* |psi_f| = 1 for every face of x (after an accepted step). */
PetscErrorCode CSTFSpinorNormalize(CSWillmoreFlow F, CSTriangleField *d, Vec x)
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(x, &a));
  for (PetscInt f = 0; f < F->mesh->nf; f++) {
    PetscScalar *q = a + d->nVo + 4 * f;
    PetscReal    n = PetscSqrtReal(PetscSqr(PetscRealPart(q[0])) + PetscSqr(PetscRealPart(q[1])) + PetscSqr(PetscRealPart(q[2])) + PetscSqr(PetscRealPart(q[3])));
    for (int c = 0; c < 4; c++) q[c] /= n;
  }
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(0);
}

/* The layout of x and the operators of the spinor variables: x (u owned, then psi), J's pattern (column map: local
   vertices' u by their x index, then the faces' psi), P, and the lens rows Kd1 = d1 (x) I_3 (no face closure rows:
   S(l, psi) closes every face by construction). */
PetscErrorCode CSTFSpinorSetUp(CSWillmoreFlow F, CSTriangleField *d)
{
  CSMesh                 m = F->mesh;
  DM                     dmF4;
  Vec                    ix, il;
  const PetscScalar     *ia;
  PetscInt              *cidx, nH3, NH3;
  ISLocalToGlobalMapping rmap, cmap;
  Mat                    d1;
  PetscFunctionBeginUser;
  PetscCall(CSSpinorSpaceGetDM(d->sp, &dmF4));
  PetscCall(DMCreateGlobalVector(m->dmV1, &d->ug));
  PetscCall(DMCreateGlobalVector(dmF4, &d->pg));
  PetscCall(VecDuplicate(d->pg, &d->gpsi));
  PetscCall(VecGetLocalSize(d->ug, &d->nVo));
  PetscCall(VecCreateMPI(F->hdr.comm, d->nVo + 4 * m->nf, PETSC_DETERMINE, &F->x));
  PetscCall(VecGetOwnershipRange(F->x, &d->xstart, NULL));
  PetscCall(VecDuplicate(d->ug, &ix));
  {
    PetscScalar *a;
    PetscCall(VecGetArray(ix, &a));
    for (PetscInt i = 0; i < d->nVo; i++) a[i] = d->xstart + i;
    PetscCall(VecRestoreArray(ix, &a));
  }
  PetscCall(DMGetLocalVector(m->dmV1, &il));
  PetscCall(DMGlobalToLocal(m->dmV1, ix, INSERT_VALUES, il));
  PetscCall(PetscMalloc1(m->nv + 4 * m->nf, &cidx));
  PetscCall(VecGetArrayRead(il, &ia));
  for (PetscInt v = 0; v < m->nv; v++) cidx[v] = (PetscInt)PetscFloorReal(PetscRealPart(ia[v]) + 0.5);
  PetscCall(VecRestoreArrayRead(il, &ia));
  PetscCall(DMRestoreLocalVector(m->dmV1, &il));
  PetscCall(VecDestroy(&ix));
  for (PetscInt i = 0; i < 4 * m->nf; i++) cidx[m->nv + i] = d->xstart + d->nVo + i;
  PetscCall(ISLocalToGlobalMappingCreate(F->hdr.comm, 1, m->nv + 4 * m->nf, cidx, PETSC_OWN_POINTER, &cmap));
  PetscCall(DMCreateGlobalVector(d->dmH3, &d->omega));
  PetscCall(VecDuplicate(d->omega, &d->omt));
  PetscCall(VecDuplicate(d->omega, &d->gom));
  PetscCall(VecGetLocalSize(d->omega, &nH3));
  PetscCall(VecGetSize(d->omega, &NH3));
  PetscCall(DMGetLocalToGlobalMapping(d->dmH3, &rmap));
  PetscCall(MatCreateAIJ(F->hdr.comm, nH3, d->nVo + 4 * m->nf, NH3, PETSC_DETERMINE, 7, NULL, 7, NULL, &d->J));
  PetscCall(MatSetLocalToGlobalMapping(d->J, rmap, cmap));
  PetscCall(MatSetOption(d->J, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_FALSE));
  PetscCall(ISLocalToGlobalMappingDestroy(&cmap));
  PetscCall(MatCreateAIJ(F->hdr.comm, m->nf, d->nVo + 4 * m->nf, PETSC_DETERMINE, PETSC_DETERMINE, 4, NULL, 0, NULL, &d->P));
  PetscCall(CSOperatorLensD1(m, d->dmH1, &d1));
  PetscCall(MatGetLocalSize(d1, &d->nD1, NULL));
  PetscCall(CSMatKronIdentity(d1, 3, MAT_INITIAL_MATRIX, &d->Klin));
  PetscCall(MatDestroy(&d1));
  PetscCall(MatCreateVecs(d->Klin, NULL, &d->clin));
  d->nL = 3 * d->nD1;
  d->nH = 0;
  PetscFunctionReturn(0);
}

/* The start x0 = (u, psi): psi = the lift of the input's df (-flow_init df), or random unit spinors
   (-flow_init random: psi_f = N(U[-1, 1]^4) hashed from the seed and the face's natural number), or the input's
   spinors rotated at random (random_spinor, RandomRotation); u uniform, scaling S(l0, psi) to |df|. */
PetscErrorCode CSTFSpinorStart(CSWillmoreFlow F, CSTriangleField *d, PetscReal (*hash)(PetscInt, PetscInt, PetscInt, PetscInt))
{
  CSMesh       m = F->mesh;
  PetscScalar *p;
  PetscReal    n0, n1;
  PetscFunctionBeginUser;
  PetscCall(CSSpinorFromTriangleField(d->sp, d->dmH3, d->omega, NULL, d->pg)); /* d->omega = df here */
  PetscCall(VecNorm(d->omega, NORM_2, &n0));
  PetscCall(VecGetArray(d->pg, &p));
  for (PetscInt f = 0; f < m->nf && d->init != CS_TF_INIT_DF; f++) {
    PetscReal q[4], r[4], t[4], nq = 0;
    for (int c = 0; c < 4; c++) q[c] = PetscRealPart(p[4 * f + c]);
    if (d->init == CS_TF_INIT_RANDOM) {
      for (int c = 0; c < 4; c++) {
        t[c] = hash(d->seed, m->faceNatural[f], 3, c);
        nq += t[c] * t[c];
      }
      if (nq == 0) t[0] = nq = 1;
    } else {
      PetscReal ax[3], an = d->amp * PETSC_PI * hash(d->seed, m->faceNatural[f], 2, 3), na;
      for (int c = 0; c < 3; c++) ax[c] = hash(d->seed, m->faceNatural[f], 2, c);
      na = PetscSqrtReal(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
      if (na == 0) ax[0] = na = 1;
      r[0] = PetscCosReal(an / 2);
      for (int c = 0; c < 3; c++) r[1 + c] = PetscSinReal(an / 2) * ax[c] / na;
      CSQuatMul(q, r, t);
      nq = 1;
    }
    for (int c = 0; c < 4; c++) p[4 * f + c] = t[c] / PetscSqrtReal(nq);
  }
  PetscCall(VecRestoreArray(d->pg, &p));
  PetscCall(VecSet(d->ug, 0));
  PetscCall(CSSpinorTriangleField(d->sp, NULL, d->pg, d->dmH3, d->omt));
  PetscCall(VecNorm(d->omt, NORM_2, &n1));
  PetscCall(VecSet(d->ug, PetscLogReal(n0 / n1)));
  d->ubar0 = PetscLogReal(n0 / n1);
  PetscCall(JoinX(d, d->ug, d->pg, F->x));
  PetscCall(CSTFSpinorOmega(d, F->x, d->omega));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTFSpinorDestroy(CSTriangleField *d)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&d->ug));
  PetscCall(VecDestroy(&d->pg));
  PetscCall(VecDestroy(&d->gpsi));
  PetscCall(VecDestroy(&d->omega));
  PetscCall(VecDestroy(&d->omt));
  PetscCall(VecDestroy(&d->gom));
  PetscCall(MatDestroy(&d->J));
  PetscCall(MatDestroy(&d->P));
  PetscCall(MatDestroy(&d->KJ));
  PetscCall(MatDestroy(&d->Hom));
  if (d->rowsOm) PetscCall(VecDestroyVecs(3 * d->nforms, &d->rowsOm));
  PetscFunctionReturn(0);
}
