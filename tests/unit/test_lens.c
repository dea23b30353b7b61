/* Unit checks of the lens-complex operators and triangle fields (include/cs_operators_lens.h), serial and under
   mpirun, on a bumpy icosphere (level 1 for the rank, level 3 otherwise) and a bumpy torus:
   - C~ A~ = 0 exactly and rank C~ = |H| - |V| (soliman2021 Lemma A.1; dense SVD of the small mesh's C~);
   - for omega = df: d1 omega = 0 (exactly), C~ lambda = C lambda on both halfedges of every edge (Eq. 14 reduces to
     Eq. 3 when lambda_ij = lambda_ji), and W~(df) = W(f) to 1e-12 (App. D.1);
   - a non-integrable omega (one halfedge moved) has d1 omega != 0 on exactly that edge;
   - the harmonic dual forms Y_i (Eq. 13) on the torus: <<Y_i|df>> = 0 and <<Y_i|omega_j>> = delta_ij.
   Prints a line per check; exit status = number of failures. */
#include "cs_operators_lens.h"
#include "cs_operators_conformal.h"
#include "cs_energy.h"
#include "cs_package.h"
#include "cs_test.h"
#include <petscblaslapack.h>

/* numerical rank of A (every rank computes it from a redundant copy) */
static PetscErrorCode DenseRank(Mat A, PetscInt *rank)
{
  Mat          R, D;
  PetscInt     mr, nc;
  PetscMPIInt  size;
  PetscScalar *a, *work;
  PetscReal   *sv;
  PetscBLASInt m, n, lda, lwork, info, one = 1;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)A), &size));
  PetscCall(MatCreateRedundantMatrix(A, size, MPI_COMM_NULL, MAT_INITIAL_MATRIX, &R));
  PetscCall(MatConvert(R, MATSEQDENSE, MAT_INITIAL_MATRIX, &D));
  PetscCall(MatGetSize(D, &mr, &nc));
  PetscCall(PetscBLASIntCast(mr, &m));
  PetscCall(PetscBLASIntCast(nc, &n));
  lda   = m;
  lwork = 10 * (m + n);
  PetscCall(PetscMalloc2(PetscMin(mr, nc), &sv, lwork, &work));
  PetscCall(MatDenseGetArray(D, &a));
  PetscCallBLAS("LAPACKgesvd", LAPACKgesvd_("N", "N", &m, &n, a, &lda, sv, NULL, &one, NULL, &one, work, &lwork, &info));
  PetscCall(MatDenseRestoreArray(D, &a));
  PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "gesvd info %d", (int)info);
  *rank = 0;
  for (PetscInt k = 0; k < PetscMin(mr, nc); k++)
    if (sv[k] > 1e-10 * sv[0]) (*rank)++;
  PetscCall(PetscFree2(sv, work));
  PetscCall(MatDestroy(&D));
  PetscCall(MatDestroy(&R));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckLemma(CSMesh m, const char name[], PetscBool rank)
{
  DM        dmH;
  Mat       A, C, P;
  PetscReal nP;
  char      what[160];
  PetscFunctionBeginUser;
  PetscCall(CSLensCreateHalfedgeDM(m, 1, &dmH));
  PetscCall(CSOperatorLensAverage(m, dmH, &A));
  PetscCall(CSOperatorLensCrossRatio(m, dmH, &C));
  PetscCall(MatMatMult(C, A, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &P));
  PetscCall(MatNorm(P, NORM_FROBENIUS, &nP));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: |C~ A~| = 0 exactly", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(nP == 0), what, nP, 0));
  if (rank) {
    PetscInt r = -1, H = 2 * m->Ne;
    PetscCall(DenseRank(C, &r));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: rank C~ = |H| - |V| = %" PetscInt_FMT, name, H - m->Nv));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(r == H - m->Nv), what, (PetscReal)r, (PetscReal)(H - m->Nv)));
  }
  PetscCall(MatDestroy(&P));
  PetscCall(MatDestroy(&A));
  PetscCall(MatDestroy(&C));
  PetscCall(DMDestroy(&dmH));
  PetscFunctionReturn(0);
}

/* max over halfedges |(C~ lambda~)_(e,s) - (C lambda)_e| for omega = df */
static PetscErrorCode CrossRatioAgrees(CSMesh m, DM dmH1, DM dmH3, Vec omega, PetscReal *diff)
{
  Mat                Ct, C;
  Vec                lt, ct, l, c;
  const PetscScalar *a, *b;
  PetscInt           n;
  PetscReal          d = 0;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(dmH1, &lt));
  PetscCall(VecDuplicate(lt, &ct));
  PetscCall(DMCreateGlobalVector(m->dmE1, &l));
  PetscCall(VecDuplicate(l, &c));
  PetscCall(CSTriangleFieldLogLengths(m, dmH3, omega, dmH1, lt));
  PetscCall(CSOperatorLensCrossRatio(m, dmH1, &Ct));
  PetscCall(MatMult(Ct, lt, ct));
  PetscCall(CSOperatorLogLengths(m, m->x, l));
  PetscCall(CSOperatorCrossRatio(m, PETSC_FALSE, &C));
  PetscCall(MatMult(C, l, c));
  PetscCall(VecGetLocalSize(c, &n));
  PetscCall(VecGetArrayRead(ct, &a));
  PetscCall(VecGetArrayRead(c, &b)); /* owned edge k is halfedges 2k, 2k+1 of the owned part */
  for (PetscInt k = 0; k < n; k++)
    for (int s = 0; s < 2; s++) d = PetscMax(d, PetscAbsScalar(a[2 * k + s] - b[k]));
  PetscCall(VecRestoreArrayRead(c, &b));
  PetscCall(VecRestoreArrayRead(ct, &a));
  PetscCall(MPIU_Allreduce(&d, diff, 1, MPIU_REAL, MPIU_MAX, m->comm));
  PetscCall(MatDestroy(&Ct));
  PetscCall(MatDestroy(&C));
  PetscCall(VecDestroy(&lt));
  PetscCall(VecDestroy(&ct));
  PetscCall(VecDestroy(&l));
  PetscCall(VecDestroy(&c));
  PetscFunctionReturn(0);
}

/* comp_h = omega_h[c] (the halfedge vector layout has block size 6: two halfedges per edge) */
static PetscErrorCode Component(Vec omega, PetscInt c, Vec comp)
{
  const PetscScalar *o;
  PetscScalar       *a;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(comp, &n));
  PetscCall(VecGetArrayRead(omega, &o));
  PetscCall(VecGetArray(comp, &a));
  for (PetscInt h = 0; h < n; h++) a[h] = o[3 * h + c];
  PetscCall(VecRestoreArray(comp, &a));
  PetscCall(VecRestoreArrayRead(omega, &o));
  PetscFunctionReturn(0);
}

/* d1 omega per component: |d1 (df)| (exactly 0) and, with one halfedge (global 0, component 0) moved by 0.1, the
   number of nonzero rows (1) */
static PetscErrorCode CheckIntegrability(CSMesh m, DM dmH1, DM dmH3, Vec omega, PetscReal *n0, PetscInt *nbad)
{
  Mat       d1;
  Vec       comp, r;
  PetscInt  lo, hi, cnt = 0, nr;
  PetscReal nrm;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLensD1(m, dmH1, &d1));
  PetscCall(DMCreateGlobalVector(dmH1, &comp));
  PetscCall(DMCreateGlobalVector(m->dmE1, &r));
  *n0 = 0;
  for (PetscInt c = 0; c < 3; c++) {
    PetscCall(Component(omega, c, comp));
    PetscCall(MatMult(d1, comp, r));
    PetscCall(VecNorm(r, NORM_INFINITY, &nrm));
    *n0 = PetscMax(*n0, nrm);
  }
  PetscCall(Component(omega, 0, comp));
  PetscCall(VecGetOwnershipRange(comp, &lo, &hi));
  if (lo == 0 && hi > 0) PetscCall(VecSetValue(comp, 0, 0.1, ADD_VALUES));
  PetscCall(VecAssemblyBegin(comp));
  PetscCall(VecAssemblyEnd(comp));
  PetscCall(MatMult(d1, comp, r));
  {
    const PetscScalar *a;
    PetscCall(VecGetLocalSize(r, &nr));
    PetscCall(VecGetArrayRead(r, &a));
    for (PetscInt k = 0; k < nr; k++)
      if (PetscAbsScalar(a[k]) > 1e-14) cnt++;
    PetscCall(VecRestoreArrayRead(r, &a));
  }
  PetscCall(MPIU_Allreduce(&cnt, nbad, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscCall(MatDestroy(&d1));
  PetscCall(VecDestroy(&comp));
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(0);
}

/* h(e, s) = +-eta_e: an edge 1-form as a scalar halfedge field (owned edge k is halfedges 2k, 2k+1 of the owned part) */
static PetscErrorCode Lift(Vec eta, Vec h)
{
  const PetscScalar *e;
  PetscScalar       *a;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(eta, &n));
  PetscCall(VecGetArrayRead(eta, &e));
  PetscCall(VecGetArray(h, &a));
  for (PetscInt k = 0; k < n; k++) {
    a[2 * k]     = e[k];
    a[2 * k + 1] = -e[k];
  }
  PetscCall(VecRestoreArray(h, &a));
  PetscCall(VecRestoreArrayRead(eta, &e));
  PetscFunctionReturn(0);
}

/* Eq. 13 rows: <<Y_i|df>> = 0 (relative to |y||df|) and <<Y_i|lift(omega_j)>> = delta_ij for the harmonic basis */
static PetscErrorCode CheckHarmonicDual(CSMesh m, DM dmH1, Vec omega, const char name[])
{
  CSHarmonicBasis hb;
  Vec             y, comp, lj;
  PetscInt        n;
  PetscReal       ex = 0, dl = 0;
  char            what[160];
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisCreate(m, m->x, &hb));
  PetscCall(CSHarmonicBasisGetSize(hb, &n));
  PetscCall(DMCreateGlobalVector(dmH1, &y));
  PetscCall(VecDuplicate(y, &comp));
  PetscCall(VecDuplicate(y, &lj));
  for (PetscInt i = 0; i < n; i++) {
    Vec         wi, wj;
    PetscScalar d;
    PetscReal   ny, nc;
    PetscCall(CSHarmonicBasisGetForm(hb, i, &wi));
    PetscCall(CSLensHarmonicDual(m, m->x, wi, dmH1, y));
    PetscCall(VecNorm(y, NORM_2, &ny));
    for (PetscInt c = 0; c < 3; c++) {
      PetscCall(Component(omega, c, comp));
      PetscCall(VecNorm(comp, NORM_2, &nc));
      PetscCall(VecDot(y, comp, &d));
      ex = PetscMax(ex, PetscAbsScalar(d) / (ny * nc));
    }
    for (PetscInt j = 0; j < n; j++) {
      PetscCall(CSHarmonicBasisGetForm(hb, j, &wj));
      PetscCall(Lift(wj, lj));
      PetscCall(VecDot(y, lj, &d));
      dl = PetscMax(dl, PetscAbsScalar(d - (i == j ? 1.0 : 0.0)));
    }
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: <<Y_i|df>> = 0 (%" PetscInt_FMT " forms)", name, n));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(n > 0 && ex < 1e-12), what, ex, 1e-12));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: <<Y_i|omega_j>> = delta_ij", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(dl < 1e-12), what, dl, 1e-12));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&comp));
  PetscCall(VecDestroy(&lj));
  PetscCall(CSHarmonicBasisDestroy(&hb));
  PetscFunctionReturn(0);
}

/* |A - B|_F / |B|_F */
static PetscErrorCode MatRelDiff(Mat A, Mat B, PetscReal *d)
{
  Mat       D;
  PetscReal nb, nd;
  PetscFunctionBeginUser;
  PetscCall(MatDuplicate(A, MAT_COPY_VALUES, &D));
  PetscCall(MatAXPY(D, -1.0, B, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatNorm(D, NORM_FROBENIUS, &nd));
  PetscCall(MatNorm(B, NORM_FROBENIUS, &nb));
  *d = nd / nb;
  PetscCall(MatDestroy(&D));
  PetscFunctionReturn(0);
}

/* lens d0 of the positions = df; d1 d0 = 0; the stars of df: d0^T *1 d0 = L and *0 = vertex areas; d0^T I_H1 d0
   = L + L *0^{-1} L (Eq. 32 against Eq. 26's second term); Dlambda against central differences */
static PetscErrorCode CheckLensMetric(CSMesh m, DM dmH1, DM dmH3, Vec omega, const char name[])
{
  Mat         d0, d1, P, L, H1, LAL, T;
  Vec         s1, s0, A, comp, u, du, dir, wp, wm, lp, lm, Dd;
  PetscReal   e0 = 0, nP, dL, dA, dH, dD, nD, eps = 1e-6;
  PetscRandom rnd;
  char        what[160];
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLensD0(m, dmH1, &d0));
  PetscCall(CSOperatorLensD1(m, dmH1, &d1));
  PetscCall(DMCreateGlobalVector(dmH1, &comp));
  PetscCall(VecDuplicate(comp, &du));
  PetscCall(DMCreateGlobalVector(m->dmV1, &u));
  for (PetscInt c = 0; c < 3; c++) {
    PetscReal n;
    PetscCall(VecStrideGather(m->x, c, u, INSERT_VALUES));
    PetscCall(MatMult(d0, u, du));
    PetscCall(Component(omega, c, comp));
    PetscCall(VecAXPY(du, -1.0, comp));
    PetscCall(VecNorm(du, NORM_INFINITY, &n));
    e0 = PetscMax(e0, n);
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: lens d0 f = df (exactly)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(e0 == 0), what, e0, 0));
  PetscCall(MatMatMult(d1, d0, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &P));
  PetscCall(MatNorm(P, NORM_FROBENIUS, &nP));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: lens d1 d0 = 0 exactly", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(nP == 0), what, nP, 0));
  PetscCall(MatDestroy(&P));
  /* stars and I_H1 */
  PetscCall(VecDuplicate(comp, &s1));
  PetscCall(DMCreateGlobalVector(m->dmV1, &s0));
  PetscCall(VecDuplicate(s0, &A));
  PetscCall(CSTriangleFieldStars(m, dmH3, omega, dmH1, s1, s0));
  PetscCall(CSGeometryVertexAreas(m, m->x, A));
  PetscCall(VecAXPY(A, -1.0, s0));
  PetscCall(VecNorm(A, NORM_INFINITY, &dA));
  PetscCall(VecNorm(s0, NORM_INFINITY, &nD));
  dA /= nD;
  PetscCall(CSOperatorLaplacian(m, m->x, MAT_INITIAL_MATRIX, &L));
  PetscCall(MatDuplicate(d0, MAT_COPY_VALUES, &T));
  PetscCall(MatDiagonalScale(T, s1, NULL));
  PetscCall(MatTransposeMatMult(d0, T, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &P));
  PetscCall(MatRelDiff(P, L, &dL));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: stars of df: d0^T *1 d0 = L, *0 = areas", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(dL < 1e-14 && dA < 1e-14), what, PetscMax(dL, dA), 1e-14));
  PetscCall(MatDestroy(&P));
  PetscCall(MatDestroy(&T));
  PetscCall(CSOperatorLensH1Metric(m, dmH1, s1, s0, &H1));
  PetscCall(MatPtAP(H1, d0, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &P));
  PetscCall(MatDuplicate(L, MAT_COPY_VALUES, &T));
  PetscCall(VecReciprocal(s0));
  PetscCall(MatDiagonalScale(T, s0, NULL));
  PetscCall(MatMatMult(L, T, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &LAL));
  PetscCall(MatAXPY(LAL, 1.0, L, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatRelDiff(P, LAL, &dH));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: d0^T I_H1 d0 = L + L *0^-1 L", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(dH < 1e-13), what, dH, 1e-13));
  /* Dlambda against central differences */
  PetscCall(VecDuplicate(omega, &dir));
  PetscCall(VecDuplicate(omega, &wp));
  PetscCall(VecDuplicate(omega, &wm));
  PetscCall(VecDuplicate(comp, &lp));
  PetscCall(VecDuplicate(comp, &lm));
  PetscCall(VecDuplicate(comp, &Dd));
  PetscCall(CSTestRandom(m->comm, -1, 1, 11, &rnd));
  PetscCall(VecSetRandom(dir, rnd));
  PetscCall(VecWAXPY(wp, eps, dir, omega));
  PetscCall(VecWAXPY(wm, -eps, dir, omega));
  PetscCall(CSTriangleFieldLogLengths(m, dmH3, wp, dmH1, lp));
  PetscCall(CSTriangleFieldLogLengths(m, dmH3, wm, dmH1, lm));
  PetscCall(VecAXPY(lp, -1.0, lm));
  PetscCall(VecScale(lp, 0.5 / eps));
  PetscCall(MatDestroy(&T));
  PetscCall(CSOperatorLensLogLengthDerivative(m, dmH1, dmH3, omega, MAT_INITIAL_MATRIX, &T));
  PetscCall(MatMult(T, dir, Dd));
  PetscCall(VecNorm(Dd, NORM_INFINITY, &nD));
  PetscCall(VecAXPY(lp, -1.0, Dd));
  PetscCall(VecNorm(lp, NORM_INFINITY, &dD));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: Dlambda (halfedges) vs central differences", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(dD <= 1e-6 * nD), what, dD / nD, 1e-6));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(MatDestroy(&d0));
  PetscCall(MatDestroy(&d1));
  PetscCall(MatDestroy(&P));
  PetscCall(MatDestroy(&L));
  PetscCall(MatDestroy(&H1));
  PetscCall(MatDestroy(&LAL));
  PetscCall(MatDestroy(&T));
  {
    Vec *vs[] = {&s1, &s0, &A, &comp, &u, &du, &dir, &wp, &wm, &lp, &lm, &Dd};
    for (size_t k = 0; k < sizeof(vs) / sizeof(vs[0]); k++) PetscCall(VecDestroy(vs[k]));
  }
  PetscFunctionReturn(0);
}

/* halfedge I_Q of df: the two halves of every edge in series = the edge I_Q (Eq. 25) where no weight is floored */
static PetscErrorCode CheckQuadDiff(CSMesh m, DM dmH1, DM dmH3, Vec omega, const char name[])
{
  Vec                ih, ie;
  const PetscScalar *a, *b;
  PetscInt           n, gh, ge;
  PetscReal          d = 0, dd;
  char               what[160];
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(dmH1, &ih));
  PetscCall(DMCreateGlobalVector(m->dmE1, &ie));
  PetscCall(CSTriangleFieldQuadDiffMetric(m, dmH3, omega, dmH1, -1e300, ih, &gh));
  PetscCall(CSOperatorQuadDiffMetric(m, m->x, -1e300, ie, &ge));
  PetscCall(VecGetLocalSize(ie, &n));
  PetscCall(VecGetArrayRead(ih, &a));
  PetscCall(VecGetArrayRead(ie, &b));
  for (PetscInt k = 0; k < n; k++) d = PetscMax(d, PetscAbsReal(1.0 / (1.0 / PetscRealPart(a[2 * k]) + 1.0 / PetscRealPart(a[2 * k + 1])) / PetscRealPart(b[k]) - 1.0));
  PetscCall(VecRestoreArrayRead(ih, &a));
  PetscCall(VecRestoreArrayRead(ie, &b));
  PetscCall(MPIU_Allreduce(&d, &dd, 1, MPIU_REAL, MPIU_MAX, m->comm));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: halfedge I_Q of df in series = edge I_Q (Eq. 25)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(dd < 1e-12 && gh == 0 && ge == 0), what, dd, 1e-12));
  PetscCall(VecDestroy(&ih));
  PetscCall(VecDestroy(&ie));
  PetscFunctionReturn(0);
}

/* dW~ against central differences along a random direction, at omega and at a perturbed (non-integrable) omega */
static PetscErrorCode CheckWillmoreGradient(CSMesh m, DM dmH3, Vec omega, const char name[])
{
  Vec         w, g, dir, wp;
  PetscRandom rnd;
  PetscReal   eps = 1e-6, Wp, Wm, worst = 0;
  PetscScalar dg;
  char        what[160];
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(omega, &w));
  PetscCall(VecDuplicate(omega, &g));
  PetscCall(VecDuplicate(omega, &dir));
  PetscCall(VecDuplicate(omega, &wp));
  PetscCall(CSTestRandom(m->comm, -1, 1, 17, &rnd));
  PetscCall(VecCopy(omega, w));
  for (int k = 0; k < 2; k++) {
    PetscReal fd;
    if (k) { /* a non-integrable field: every halfedge moved by up to 2 % of the mean size */
      PetscReal nrm;
      PetscCall(VecSetRandom(dir, rnd));
      PetscCall(VecNorm(omega, NORM_INFINITY, &nrm));
      PetscCall(VecAXPY(w, 0.02 * nrm, dir));
    }
    PetscCall(VecSetRandom(dir, rnd));
    PetscCall(CSTriangleFieldWillmore(m, dmH3, w, NULL, g));
    PetscCall(VecDot(g, dir, &dg));
    PetscCall(VecWAXPY(wp, eps, dir, w));
    PetscCall(CSTriangleFieldWillmore(m, dmH3, wp, &Wp, NULL));
    PetscCall(VecWAXPY(wp, -eps, dir, w));
    PetscCall(CSTriangleFieldWillmore(m, dmH3, wp, &Wm, NULL));
    fd    = (Wp - Wm) / (2 * eps);
    worst = PetscMax(worst, PetscAbsReal(fd - PetscRealPart(dg)) / PetscAbsReal(fd));
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: dW~ vs central differences (df and a non-integrable field)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(worst < 1e-6), what, worst, 1e-6));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&g));
  PetscCall(VecDestroy(&dir));
  PetscCall(VecDestroy(&wp));
  PetscFunctionReturn(0);
}

/* The Poisson reconstruction L f = d*omega of omega = df gives f back (translation fixed by the reference: here x
   itself), and the face closure S (df) = 0 exactly while a moved halfedge breaks one face. */
static PetscErrorCode CheckReconstruct(CSMesh m, DM dmH1, DM dmH3, Vec omega, const char name[])
{
  Vec       x, w, s;
  Mat       S;
  PetscReal d, sc, n0, n1, n2;
  PetscInt  rs;
  char      what[160];
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(m->x, &x));
  PetscCall(CSTriangleFieldReconstruct(m, dmH1, dmH3, omega, m->x, x));
  PetscCall(VecAXPY(x, -1.0, m->x));
  PetscCall(VecNorm(x, NORM_INFINITY, &d));
  PetscCall(VecNorm(m->x, NORM_INFINITY, &sc));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: Poisson reconstruction of df = f (max |f' - f| / max |f|)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(d <= 1e-12 * sc), what, d / sc, 1e-12));
  PetscCall(CSOperatorLensFaceClosure(m, dmH1, &S));
  PetscCall(MatCreateVecs(S, NULL, &s));
  PetscCall(DMCreateGlobalVector(dmH1, &w));
  PetscCall(Component(omega, 0, w));
  PetscCall(MatMult(S, w, s));
  PetscCall(VecNorm(s, NORM_INFINITY, &n0));
  PetscCall(VecGetOwnershipRange(w, &rs, NULL));
  PetscCall(VecNorm(w, NORM_INFINITY, &n2));
  if (rs == 0) PetscCall(VecSetValue(w, 0, 1.0, ADD_VALUES)); /* one halfedge moved: its face opens */
  PetscCall(VecAssemblyBegin(w));
  PetscCall(VecAssemblyEnd(w));
  PetscCall(MatMult(S, w, s));
  PetscCall(VecNorm(s, NORM_1, &n1));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: face closure of df vanishes (relative), a moved halfedge opens one face", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(n0 <= 1e-15 * n2 && PetscAbsReal(n1 - 1.0) < 1e-12 + 3 * n0), what, n0 / n2, 1e-15));
  PetscCall(MatDestroy(&S));
  PetscCall(VecDestroy(&s));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&x));
  PetscFunctionReturn(0);
}

/* max |x - y| / max |y| */
static PetscErrorCode RelDiff(Vec x, Vec y, Vec w, PetscReal *d)
{
  PetscReal ny;
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(w, -1.0, y, x));
  PetscCall(VecNorm(w, NORM_INFINITY, d));
  PetscCall(VecNorm(y, NORM_INFINITY, &ny));
  *d /= ny;
  PetscFunctionReturn(0);
}

/* The reconstruction kept alive (the flow's CSTriangleFieldReconstruction, L and B refilled in place, the symbolic
   factorisation kept) answers as the one-shot CSTriangleFieldReconstruct: on df, then on two non-integrable fields
   (another vector; then df changed in place, which must be noticed through its state), then on df again. */
static PetscErrorCode CheckReconstructionReuse(CSMesh m, DM dmH1, DM dmH3, Vec omega, const char name[])
{
  CSTriangleFieldReconstruction R;
  PetscRandom rnd;
  Vec         om2, om3, dir, x, y, w;
  PetscReal   d, worst = 0, moved;
  char        what[200];
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(m->x, &x));
  PetscCall(VecDuplicate(m->x, &y));
  PetscCall(VecDuplicate(m->x, &w));
  PetscCall(VecDuplicate(omega, &om2));
  PetscCall(VecDuplicate(omega, &dir));
  PetscCall(CSTestRandom(m->comm, -1, 1, 23, &rnd));
  PetscCall(VecSetRandom(dir, rnd));
  PetscCall(VecWAXPY(om2, 0.05, dir, omega)); /* not integrable: the reconstruction is a least-squares fit */
  PetscCall(VecDuplicate(omega, &om3));
  PetscCall(VecCopy(omega, om3));
  PetscCall(CSTriangleFieldReconstructionCreate(m, dmH1, dmH3, &R));
  for (PetscInt k = 0; k < 4; k++) {
    Vec om = k == 1 ? om2 : om3;
    if (k == 2) PetscCall(VecAXPY(om3, -0.05, dir)); /* in place: same vector, new state */
    if (k == 3) PetscCall(VecAXPY(om3, 0.05, dir));  /* back to df */
    PetscCall(CSTriangleFieldReconstructionSolve(R, om, m->x, x));
    PetscCall(CSTriangleFieldReconstructionSolve(R, om, m->x, x)); /* unchanged: nothing refactored */
    PetscCall(CSTriangleFieldReconstruct(m, dmH1, dmH3, om, m->x, y));
    PetscCall(RelDiff(x, y, w, &d));
    worst = PetscMax(worst, d);
    if (k == 2) PetscCall(RelDiff(x, m->x, w, &moved)); /* the change is not negligible */
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: kept reconstruction = one-shot on 4 fields, 2 of them non-integrable (max rel diff; the in-place change moved f by %.2e)", name, (double)moved));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(worst <= 1e-13 && moved > 1e-3), what, worst, 1e-13));
  PetscCall(CSTriangleFieldReconstructionDestroy(&R));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&om2));
  PetscCall(VecDestroy(&om3));
  PetscCall(VecDestroy(&dir));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckTriangleField(CSMesh m, const char name[])
{
  DM        dmH1, dmH3;
  Vec       omega;
  CSEnergy  e;
  PetscReal Wt, W, d, n0 = -1;
  PetscInt  nbad;
  char      what[160];
  PetscFunctionBeginUser;
  PetscCall(CSLensCreateHalfedgeDM(m, 1, &dmH1));
  PetscCall(CSLensCreateHalfedgeDM(m, 3, &dmH3));
  PetscCall(DMCreateGlobalVector(dmH3, &omega));
  PetscCall(CSTriangleFieldFromPositions(m, m->x, dmH3, omega));
  PetscCall(CSTriangleFieldWillmore(m, dmH3, omega, &Wt, NULL));
  PetscCall(CSEnergyCreateWillmore(m, &e));
  PetscCall(CSEnergyValue(e, m->x, &W));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: |W~(df) - W(f)| / W(f) (W = %.6f)", name, (double)W));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(PetscAbsReal(Wt - W) <= 1e-12 * W), what, PetscAbsReal(Wt - W) / W, 1e-12));
  PetscCall(CrossRatioAgrees(m, dmH1, dmH3, omega, &d));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: C~ lambda(df) = C lambda(f) on both halfedges", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-12), what, d, 1e-12));
  PetscCall(CheckIntegrability(m, dmH1, dmH3, omega, &n0, &nbad));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: d1 (df) = 0 exactly", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(n0 == 0), what, n0, 0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: one moved halfedge breaks d1 on one lens", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(nbad == 1), what, (PetscReal)nbad, 1));
  PetscCall(CheckLensMetric(m, dmH1, dmH3, omega, name));
  PetscCall(CheckQuadDiff(m, dmH1, dmH3, omega, name));
  PetscCall(CheckWillmoreGradient(m, dmH3, omega, name));
  if (m->topo.genus > 0) PetscCall(CheckHarmonicDual(m, dmH1, omega, name));
  PetscCall(CheckReconstruct(m, dmH1, dmH3, omega, name));
  PetscCall(CheckReconstructionReuse(m, dmH1, dmH3, omega, name));
  PetscCall(CSEnergyDestroy(&e));
  PetscCall(VecDestroy(&omega));
  PetscCall(DMDestroy(&dmH1));
  PetscCall(DMDestroy(&dmH3));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm comm;
  CSMesh   m;
  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CSInitializePackage());
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_ICOSPHERE, 1, 0, 0, 0}, 0.05, 3, &m));
  PetscCall(CheckLemma(m, "icosphere 1 bumpy", PETSC_TRUE));
  PetscCall(CSMeshDestroy(&m));
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_TORUS, 8, 6, 2.0, 0.7}, 0.05, 3, &m));
  PetscCall(CheckLemma(m, "torus 8x6 bumpy", PETSC_TRUE));
  PetscCall(CSMeshDestroy(&m));
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_ICOSPHERE, 3, 0, 0, 0}, 0.02, 4, &m));
  PetscCall(CheckLemma(m, "icosphere 3 bumpy", PETSC_FALSE));
  PetscCall(CheckTriangleField(m, "icosphere 3 bumpy"));
  PetscCall(CSMeshDestroy(&m));
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_TORUS, 24, 12, 3.0, 1.0}, 0.02, 5, &m));
  PetscCall(CheckTriangleField(m, "torus 24x12 bumpy"));
  PetscCall(CSMeshDestroy(&m));
  return CSTestFinalize(comm, PetscFinalize);
}
