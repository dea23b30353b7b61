/* Supernodal multifrontal Cholesky K - sigma = L L^H in quaternion arithmetic (include/cs_quaternion_cholesky.h).

   K is quaternionic Hermitian: its 4x4 real blocks are left multiplications by quaternions q_IJ with
   q_JI = conj(q_IJ) (crane2011 Sec. 5.1), so (K x)_I = sum_J q_IJ x_J for quaternion vectors x. The factor L is a
   lower triangular quaternion matrix: q_IJ = sum_T L_IT conj(L_JT); the diagonal of L is real.

   Symbolic phase: CHOLMOD analyses the V x V pattern (fill-reducing ordering, postordered elimination tree,
   relaxed supernodes). Supernode s owns the columns super[s] .. super[s+1]-1 (k of them) and a list of N rows, the
   first k being its own columns. Its panel of L is stored "split": four real N x k matrices (the components
   1, i, j, k of the quaternions), one after the other, i.e. one real N x 4k column-major matrix.

   Numeric phase, supernodes in postorder: the panel receives the entries of K and the update matrices of its
   children (extend-add); it is factored in blocks of NB columns (quaternion loops inside a block, real BLAS
   products between blocks); then its own update matrix U = -L21 L21^H (plus the children's contributions to rows
   beyond the panel) goes on a stack for the parent.

   The products C -= A B^H of quaternion matrices are single real GEMMs: with A split as [A0 A1 A2 A3]
   (m x 4k), C's component c is sum_r A_r P_{r,c} where P = B^H and the 4k x 4n matrix [P_{r,c}] holds +-P_0..P_3
   following the Hamilton product (CSQuatMul). That is 32 real flops per quaternion multiply-add, the same count as
   the product itself, at BLAS speed.

   The method is the classical one for real matrices: multifrontal factorisation (Duff and Reid, ACM TOMS 9, 1983;
   Liu, SIAM Rev. 34, 1992) on CHOLMOD's relaxed supernodes (Chen, Davis, Hager and Rajamanickam, ACM TOMS 35,
   2008); only the arithmetic is quaternionic. */
#include <suitesparse/cholmod.h>
#include "cs_quaternion.h"
#include "cs_quaternion_cholesky.h"
#include "cs_cholmod.h"
#include "cs_log.h"
#include <petscblaslapack.h>

/* Column blocks (measured on the 14,400-vertex torus of runs/bench_spin.sh; 16/32/64 within noise of each other):
   NB for the panel (quaternion loops inside a block, BLAS between blocks), NBU for the update matrix. */
#define NB  16
#define NBU 64

struct _p_CSQuatCholesky {
  cholmod_common   common;
  PetscInt         nb;      /* quaternion unknowns (block rows of K) */
  PetscObjectId    kid;     /* the matrix and nonzero state the symbolic phase belongs to */
  PetscObjectState kstate;
  PetscBool        factored;
  /* symbolic */
  PetscInt   nsuper;
  PetscInt  *super;  /* nsuper + 1 column boundaries (permuted numbering) */
  PetscInt  *rowptr; /* rows of supernode s: rows[rowptr[s] .. rowptr[s+1]) */
  PetscInt  *rows;
  PetscInt  *parent; /* supernodal parent, -1 at a root */
  PetscInt  *perm;   /* perm[p] = block row of K at permuted position p */
  PetscInt  *iperm, *col2super;
  PetscInt64 *lxptr; /* offset of supernode s's panel in lx (doubles) */
  double    *lx;
  PetscInt   nent;   /* stored entries of the lower triangle of the permuted K, in MatGetRow order */
  PetscInt64 *apos;  /* offset of entry e (component 0) in lx; the other components follow at astride[e] */
  PetscInt64 *astride;
  PetscInt  *map;    /* work: permuted row -> local row of the current supernode, -1 elsewhere */
  PetscInt  *lmap;   /* work: a child's update rows -> local rows of the parent */
  double    *pbig, *apack, *y, *tmp;
  size_t     npbig, napack;
  PetscLogDouble nnzL, flops;
};

/* C (ldc) = beta C + alpha op(A) op(B), sizes as in BLAS. An empty product returns at once, without applying
   beta: every call here has beta = 1 or a k > 0. */
static PetscErrorCode Gemm(const char *ta, const char *tb, PetscInt m, PetscInt n, PetscInt k, double alpha, const double *A, PetscInt lda, const double *B, PetscInt ldb, double beta, double *C, PetscInt ldc)
{
  PetscBLASInt bm, bn, bk, bla, blb, blc;
  PetscFunctionBeginUser;
  if (m <= 0 || n <= 0 || k <= 0) PetscFunctionReturn(0);
  PetscCall(PetscBLASIntCast(m, &bm));
  PetscCall(PetscBLASIntCast(n, &bn));
  PetscCall(PetscBLASIntCast(k, &bk));
  PetscCall(PetscBLASIntCast(lda, &bla));
  PetscCall(PetscBLASIntCast(ldb, &blb));
  PetscCall(PetscBLASIntCast(ldc, &blc));
  PetscCallBLAS("BLASgemm", BLASgemm_(ta, tb, &bm, &bn, &bk, &alpha, A, &bla, B, &blb, &beta, C, &blc));
  PetscFunctionReturn(0);
}

/* The 4nc x 4nr real matrix [sgn(r,c) P_{idx(r,c)}] for the product A P (A split, nc quaternion columns), from
   the Hamilton product: (a p)_c = sum_r sgn(r,c) a_r p_{idx(r,c)}. With conjtrans, P = B^H for B (nr x nc
   quaternions), else P = B (nc x nr); B's component c, entry (row, col), at B[c * cs + col * ld + row]. */
static const int    QIdx[4][4] = {{0, 1, 2, 3}, {1, 0, 3, 2}, {2, 3, 0, 1}, {3, 2, 1, 0}}; /* [r][c] */
static const double QSgn[4][4] = {{1, 1, 1, 1}, {-1, 1, -1, 1}, {-1, 1, 1, -1}, {-1, -1, 1, 1}};

static void BuildP(const double *B, PetscInt64 cs, PetscInt ld, PetscInt nc, PetscInt nr, PetscBool conjtrans, double *P)
{
  const PetscInt64 ldp = 4 * nc;
  for (int r = 0; r < 4; r++)
    for (int c = 0; c < 4; c++) {
      const int     q  = QIdx[r][c];
      const double  sg = QSgn[r][c] * ((conjtrans && q) ? -1.0 : 1.0);
      const double *Bq = B + q * cs;
      for (PetscInt j = 0; j < nr; j++) {
        double *Pc = P + (PetscInt64)(c * nr + j) * ldp + r * nc;
        if (conjtrans)
          for (PetscInt t = 0; t < nc; t++) Pc[t] = sg * Bq[(PetscInt64)t * ld + j];
        else
          for (PetscInt t = 0; t < nc; t++) Pc[t] = sg * Bq[(PetscInt64)j * ld + t];
      }
    }
}

static PetscErrorCode EnsureWork(CSQuatCholesky f, size_t npbig, size_t napack)
{
  PetscFunctionBeginUser;
  if (npbig > f->npbig) {
    PetscCall(PetscFree(f->pbig));
    PetscCall(PetscMalloc1(npbig, &f->pbig));
    f->npbig = npbig;
  }
  if (napack > f->napack) {
    PetscCall(PetscFree(f->apack));
    PetscCall(PetscMalloc1(napack, &f->apack));
    f->napack = napack;
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode FreeSymbolic(CSQuatCholesky f)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree5(f->super, f->rowptr, f->rows, f->parent, f->lxptr));
  PetscCall(PetscFree4(f->perm, f->iperm, f->col2super, f->map));
  PetscCall(PetscFree(f->lx));
  PetscCall(PetscFree2(f->apos, f->astride));
  PetscCall(PetscFree3(f->y, f->tmp, f->lmap));
  f->nsuper   = 0;
  f->factored = PETSC_FALSE;
  f->kid      = 0; /* no matrix: the next SetUp analyses again */
  PetscFunctionReturn(0);
}

/* The pattern of the lower triangle of K's quaternion entries, analysed by CHOLMOD; the supernodes copied out
   with their parents and the position in lx of every entry of K. Everything allocated here belongs to f (freed by
   FreeSymbolic), except cnt and the bucket arrays, which are freed before any check can fail; f->nsuper is set
   last, so a failed analysis is redone at the next SetUp. */
static PetscErrorCode Symbolic(CSQuatCholesky f, Mat K)
{
  PetscInt        n4, nb, nsuper, nent = 0, nlow = 0, nup = 0, nodiag = -1, outside = -1, *cnt, *col2super, *iperm, *eI, *eJ, *bucket, *bptr, *stk, top = 0;
  cholmod_sparse *A;
  cholmod_factor *L;
  int            *Ap, *Ai, *Ls, *Lpi, *Lsuper, *Lperm, status;
  PetscFunctionBeginUser;
  PetscCall(FreeSymbolic(f));
  PetscCall(MatGetSize(K, &n4, NULL));
  PetscCheck(n4 % 4 == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "matrix of size %" PetscInt_FMT " is not quaternionic", n4);
  f->nb = nb = n4 / 4;
  /* lower triangle pattern by columns (stype -1): block (bi, bj), bi >= bj, in column bj; every block row needs its
     diagonal block (it carries -sigma) and the pattern must be symmetric (the upper blocks are not read) */
  PetscCall(PetscCalloc1(nb + 1, &cnt));
  for (PetscInt bi = 0; bi < nb; bi++) {
    PetscInt        nc;
    const PetscInt *cols;
    PetscBool       diag = PETSC_FALSE;
    PetscCall(MatGetRow(K, 4 * bi, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc;) {
      PetscInt bj = CSQuatRowNextBlock(nc, cols, NULL, &k, NULL);
      if (bj <= bi) cnt[bj]++;
      if (bj < bi) nlow++;
      if (bj > bi) nup++;
      if (bj == bi) diag = PETSC_TRUE;
      nent++;
    }
    PetscCall(MatRestoreRow(K, 4 * bi, &nc, &cols, NULL));
    if (!diag && nodiag < 0) nodiag = bi;
  }
  if (nodiag >= 0 || nlow != nup) PetscCall(PetscFree(cnt));
  PetscCheck(nodiag < 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "quaternion Cholesky: K has no diagonal block in block row %" PetscInt_FMT, nodiag);
  PetscCheck(nlow == nup, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "quaternion Cholesky: K is not structurally symmetric (%" PetscInt_FMT " blocks below the diagonal, %" PetscInt_FMT " above)", nlow, nup);
  A = cholmod_allocate_sparse((size_t)nb, (size_t)nb, (size_t)nent, 0, 1, -1, CHOLMOD_PATTERN, &f->common);
  if (!A) PetscCall(PetscFree(cnt));
  PetscCheck(A, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD allocate failed (status %d)", f->common.status);
  Ap    = (int *)A->p;
  Ai    = (int *)A->i;
  Ap[0] = 0;
  for (PetscInt bj = 0; bj < nb; bj++) Ap[bj + 1] = Ap[bj] + (int)cnt[bj];
  for (PetscInt bj = 0; bj < nb; bj++) cnt[bj] = Ap[bj];
  for (PetscInt bi = 0; bi < nb; bi++) {
    PetscInt        nc;
    const PetscInt *cols;
    PetscCall(MatGetRow(K, 4 * bi, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc;) {
      PetscInt bj = CSQuatRowNextBlock(nc, cols, NULL, &k, NULL);
      if (bj <= bi) Ai[cnt[bj]++] = (int)bi;
    }
    PetscCall(MatRestoreRow(K, 4 * bi, &nc, &cols, NULL));
  }
  PetscCall(PetscFree(cnt));
  L      = cholmod_analyze(A, &f->common);
  status = f->common.status;
  cholmod_free_sparse(&A, &f->common);
  if (L && !L->is_super) cholmod_free_factor(&L, &f->common);
  PetscCheck(L, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD supernodal analysis failed (status %d)", status);
  /* copy the supernodes out */
  nsuper = (PetscInt)L->nsuper;
  Lsuper = (int *)L->super;
  Lpi    = (int *)L->pi;
  Ls     = (int *)L->s;
  Lperm  = (int *)L->Perm;
  PetscCall(PetscMalloc5(nsuper + 1, &f->super, nsuper + 1, &f->rowptr, Lpi[nsuper], &f->rows, nsuper, &f->parent, nsuper + 1, &f->lxptr));
  PetscCall(PetscMalloc4(nb, &f->perm, nb, &f->iperm, nb, &f->col2super, nb, &f->map));
  iperm     = f->iperm;
  col2super = f->col2super;
  for (PetscInt s = 0; s <= nsuper; s++) f->super[s] = Lsuper[s], f->rowptr[s] = Lpi[s];
  for (PetscInt p = 0; p < Lpi[nsuper]; p++) f->rows[p] = Ls[p];
  for (PetscInt p = 0; p < nb; p++) f->perm[p] = Lperm[p], iperm[Lperm[p]] = p, f->map[p] = -1;
  cholmod_free_factor(&L, &f->common);
  /* what the numeric phase relies on: a supernode's rows ascend from its own columns; a supernode with rows
     beyond its columns has a parent (the supernode of the first such row) that comes later and whose rows contain
     them; the supernodes are in postorder, so that the children's update matrices are the top of a stack */
  f->lxptr[0] = 0;
  f->nnzL = f->flops = 0;
  for (PetscInt s = 0; s < nsuper; s++) {
    const PetscInt k = f->super[s + 1] - f->super[s], N = f->rowptr[s + 1] - f->rowptr[s], *r = f->rows + f->rowptr[s];
    for (PetscInt t = 0; t < N; t++) PetscCheck(t < k ? r[t] == f->super[s] + t : r[t] > r[t - 1], PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD supernode %" PetscInt_FMT ": rows not in ascending order from its columns", s);
    for (PetscInt t = f->super[s]; t < f->super[s + 1]; t++) col2super[t] = s;
    f->lxptr[s + 1] = f->lxptr[s] + 4 * (PetscInt64)N * k;
    /* nominal counts (the explicit zeros of relaxed supernodes included) */
    for (PetscInt t = 0; t < k; t++) f->nnzL += N - t, f->flops += 32.0 * (N - t) * (N - t) / 2;
  }
  PetscCall(PetscMalloc1(nsuper, &stk));
  for (PetscInt s = 0; s < nsuper; s++) {
    const PetscInt k = f->super[s + 1] - f->super[s], N = f->rowptr[s + 1] - f->rowptr[s], *r = f->rows + f->rowptr[s];
    f->parent[s] = N > k ? col2super[r[k]] : -1;
    while (top > 0 && f->parent[stk[top - 1]] == s) top--;
    if (N > k) {
      const PetscInt p = f->parent[s], Np = f->rowptr[p + 1] - f->rowptr[p], *rp = f->rows + f->rowptr[p];
      for (PetscInt t = 0; t < Np; t++) f->map[rp[t]] = t;
      for (PetscInt t = k; t < N; t++)
        if (f->map[r[t]] < 0 && outside < 0) outside = s;
      for (PetscInt t = 0; t < Np; t++) f->map[rp[t]] = -1;
      if (p <= s && outside < 0) outside = s;
      stk[top++] = s;
    }
  }
  PetscCall(PetscFree(stk));
  PetscCheck(outside < 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD supernode %" PetscInt_FMT ": rows not contained in its parent's", outside);
  PetscCheck(top == 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD supernodes are not in postorder (%" PetscInt_FMT " update matrices left)", top);
  PetscCall(PetscMalloc1(f->lxptr[nsuper], &f->lx));
  PetscCall(PetscMalloc3(4 * nb, &f->y, 4 * nb, &f->tmp, nb, &f->lmap));
  /* where each entry of K goes: entry e = block (bi, bj) in MatGetRow order; stored if iperm[bi] >= iperm[bj], at
     (row iperm[bi], column iperm[bj]) of the panel owning that column. Bucketed by supernode to use map. */
  f->nent = nent;
  PetscCall(PetscMalloc2(nent, &f->apos, nent, &f->astride));
  PetscCall(PetscMalloc4(nent, &eI, nent, &eJ, nent, &bucket, nsuper + 1, &bptr));
  PetscCall(PetscArrayzero(bptr, nsuper + 1));
  nent = 0;
  for (PetscInt bi = 0; bi < nb; bi++) {
    PetscInt        nc;
    const PetscInt *cols;
    PetscCall(MatGetRow(K, 4 * bi, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc;) {
      PetscInt bj   = CSQuatRowNextBlock(nc, cols, NULL, &k, NULL);
      eI[nent]      = iperm[bi];
      eJ[nent]      = iperm[bj];
      f->apos[nent] = -1; /* upper triangle: not stored */
      if (eI[nent] >= eJ[nent]) bptr[col2super[eJ[nent]] + 1]++;
      nent++;
    }
    PetscCall(MatRestoreRow(K, 4 * bi, &nc, &cols, NULL));
  }
  for (PetscInt s = 0; s < nsuper; s++) bptr[s + 1] += bptr[s];
  for (PetscInt e = 0; e < nent; e++)
    if (eI[e] >= eJ[e]) bucket[bptr[col2super[eJ[e]]]++] = e;
  for (PetscInt s = nsuper; s > 0; s--) bptr[s] = bptr[s - 1];
  bptr[0] = 0;
  for (PetscInt s = 0; s < nsuper; s++) {
    const PetscInt k = f->super[s + 1] - f->super[s], N = f->rowptr[s + 1] - f->rowptr[s], *r = f->rows + f->rowptr[s];
    for (PetscInt t = 0; t < N; t++) f->map[r[t]] = t;
    for (PetscInt b = bptr[s]; b < bptr[s + 1]; b++) {
      const PetscInt e = bucket[b], li = f->map[eI[e]], lj = eJ[e] - f->super[s];
      if (li < 0 && outside < 0) outside = e;
      f->apos[e]    = f->lxptr[s] + (PetscInt64)lj * N + li;
      f->astride[e] = (PetscInt64)k * N;
    }
    for (PetscInt t = 0; t < N; t++) f->map[r[t]] = -1;
  }
  PetscCall(PetscFree4(eI, eJ, bucket, bptr));
  PetscCheck(outside < 0, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD: entry %" PetscInt_FMT " of K lies outside the symbolic factor", outside);
  f->nsuper = nsuper;
  PetscFunctionReturn(0);
}

/* c -= a w over n rows, a and c split with component stride cs (different columns: no overlap); the
   Hamilton product of CSQuatMul, written out so that the compiler vectorises over the rows */
static void RankOneUpdate(const double *restrict a, PetscInt64 cs, double *restrict c, PetscInt n, double w0, double w1, double w2, double w3)
{
  const double *restrict a0 = a, *restrict a1 = a + cs, *restrict a2 = a + 2 * cs, *restrict a3 = a + 3 * cs;
  double *restrict c0 = c, *restrict c1 = c + cs, *restrict c2 = c + 2 * cs, *restrict c3 = c + 3 * cs;
  for (PetscInt i = 0; i < n; i++) {
    c0[i] -= a0[i] * w0 - a1[i] * w1 - a2[i] * w2 - a3[i] * w3;
    c1[i] -= a0[i] * w1 + a1[i] * w0 + a2[i] * w3 - a3[i] * w2;
    c2[i] -= a0[i] * w2 - a1[i] * w3 + a2[i] * w0 + a3[i] * w1;
    c3[i] -= a0[i] * w3 + a1[i] * w2 - a2[i] * w1 + a3[i] * w0;
  }
}

/* Factor the N x k panel L (split, ld N) in place: blocks of NB columns, each factored by quaternion loops over
   all N rows, then applied to the panel's later columns by one real GEMM per component. */
static PetscErrorCode PanelFactor(CSQuatCholesky f, double *L, PetscInt N, PetscInt k, PetscInt *bad)
{
  const PetscInt64 cs = (PetscInt64)k * N;
  PetscFunctionBeginUser;
  *bad = -1;
  for (PetscInt jb = 0; jb < k; jb += NB) {
    const PetscInt nbb = PetscMin(NB, k - jb), r0 = jb + nbb;
    for (PetscInt j = jb; j < r0; j++) {
      double *Lj = L + (PetscInt64)j * N, d = Lj[j], inv;
      if (!(d > 0 && PetscIsNormalReal(d))) { /* not positive definite: the caller cleans up and reports */
        *bad = j;
        PetscFunctionReturn(0);
      }
      d     = PetscSqrtReal(d);
      inv   = 1.0 / d;
      Lj[j] = d;
      for (int c = 1; c < 4; c++) Lj[c * cs + j] = 0;
      for (int c = 0; c < 4; c++)
        for (PetscInt i = j + 1; i < N; i++) Lj[c * cs + i] *= inv;
      for (PetscInt j2 = j + 1; j2 < r0; j2++) /* column j2 -= L(:, j) conj(L(j2, j)) */
        RankOneUpdate(Lj + j2, cs, L + (PetscInt64)j2 * N + j2, N - j2, Lj[j2], -Lj[cs + j2], -Lj[2 * cs + j2], -Lj[3 * cs + j2]);
    }
    if (r0 < k) { /* columns r0..k-1, rows >= column: -= L(r0:N, jb:r0) L(r0:k, jb:r0)^H, NB columns at a time */
      const PetscInt m = N - r0, n = k - r0;
      PetscCall(EnsureWork(f, (size_t)16 * nbb * NB, (size_t)4 * nbb * m));
      for (int c = 0; c < 4; c++)
        for (PetscInt t = 0; t < nbb; t++) PetscCall(PetscArraycpy(f->apack + (PetscInt64)(c * nbb + t) * m, L + c * cs + (PetscInt64)(jb + t) * N + r0, m));
      for (PetscInt jc = 0; jc < n; jc += NB) {
        const PetscInt ncb = PetscMin(NB, n - jc);
        BuildP(L + (PetscInt64)jb * N + r0 + jc, cs, N, nbb, ncb, PETSC_TRUE, f->pbig);
        for (int c = 0; c < 4; c++) PetscCall(Gemm("N", "N", m - jc, ncb, 4 * nbb, -1.0, f->apack + jc, m, f->pbig + (PetscInt64)c * ncb * 4 * nbb, 4 * nbb, 1.0, L + c * cs + (PetscInt64)(r0 + jc) * N + r0 + jc, N));
      }
    }
  }
  PetscFunctionReturn(0);
}

typedef struct {
  double  *U;
  PetscInt s;
} Update;

static PetscErrorCode Numeric(CSQuatCholesky f, Mat K, PetscReal sigma)
{
  Update  *stack;
  PetscInt top = 0, e = 0, bad;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_QuatCholNum, 0, 0, 0, 0));
  f->factored = PETSC_FALSE;
  PetscCall(PetscArrayzero(f->lx, f->lxptr[f->nsuper]));
  for (PetscInt bi = 0; bi < f->nb; bi++) { /* K's entries, one quaternion per block */
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *v;
    PetscCall(MatGetRow(K, 4 * bi, &nc, &cols, &v));
    for (PetscInt k = 0; k < nc;) {
      double         q[4];
      const PetscInt bj = CSQuatRowNextBlock(nc, cols, v, &k, q);
      if (bj == bi) q[0] -= sigma;
      if (e >= f->nent) break; /* the pattern grew without a new symbolic phase: reported below */
      if (f->apos[e] >= 0)
        for (int c = 0; c < 4; c++) f->lx[f->apos[e] + c * f->astride[e]] = q[c];
      e++;
    }
    PetscCall(MatRestoreRow(K, 4 * bi, &nc, &cols, &v));
  }
  PetscCheck(e == f->nent, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the pattern of K changed without a new symbolic phase");
  PetscCall(PetscMalloc1(f->nsuper, &stack));
  for (PetscInt s = 0; s < f->nsuper; s++) {
    const PetscInt   k = f->super[s + 1] - f->super[s], N = f->rowptr[s + 1] - f->rowptr[s], m = N - k, *r = f->rows + f->rowptr[s];
    const PetscInt64 cs = (PetscInt64)k * N, us = (PetscInt64)m * m;
    double          *L = f->lx + f->lxptr[s], *U = NULL;
    if (m > 0) PetscCall(PetscCalloc1(4 * us, &U));
    for (PetscInt t = 0; t < N; t++) f->map[r[t]] = t;
    while (top > 0 && f->parent[stack[top - 1].s] == s) { /* extend-add of the children's update matrices */
      const PetscInt  c  = stack[--top].s, kc = f->super[c + 1] - f->super[c], mc = f->rowptr[c + 1] - f->rowptr[c] - kc;
      const PetscInt *rc = f->rows + f->rowptr[c] + kc;
      const double   *Uc = stack[top].U;
      PetscInt       *lm = f->lmap;
      /* rows ascend in child and parent (checked in Symbolic): the lower triangle maps into the lower triangle */
      for (PetscInt ii = 0; ii < mc; ii++) lm[ii] = f->map[rc[ii]];
      for (int q = 0; q < 4; q++)
        for (PetscInt jj = 0; jj < mc; jj++) {
          const PetscInt lj = lm[jj];
          const double  *u  = Uc + q * (PetscInt64)mc * mc + (PetscInt64)jj * mc;
          if (lj < k) { /* a column of the panel */
            double *d = L + q * cs + (PetscInt64)lj * N;
            for (PetscInt ii = jj; ii < mc; ii++) d[lm[ii]] += u[ii];
          } else { /* a column of s's own update matrix */
            double *d = U + q * us + (PetscInt64)(lj - k) * m;
            for (PetscInt ii = jj; ii < mc; ii++) d[lm[ii] - k] += u[ii];
          }
        }
      PetscCall(PetscFree(stack[top].U));
    }
    for (PetscInt t = 0; t < N; t++) f->map[r[t]] = -1;
    PetscCall(PanelFactor(f, L, N, k, &bad));
    if (bad >= 0) {
      const double pivot = L[(PetscInt64)bad * N + bad];
      PetscCall(PetscFree(U));
      while (top > 0) PetscCall(PetscFree(stack[--top].U));
      PetscCall(PetscFree(stack));
      PetscCall(PetscLogEventEnd(CS_EVENT_QuatCholNum, 0, 0, 0, 0));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_MAT_CH_ZRPVT, "quaternion Cholesky: the matrix is not positive definite (pivot %g at block row %" PetscInt_FMT ", elimination step %" PetscInt_FMT " of %" PetscInt_FMT ")", pivot, f->perm[f->super[s] + bad], f->super[s] + bad, f->nb);
    }
    if (m > 0) { /* U -= L21 L21^H, lower triangle by blocks of NBU columns */
      PetscCall(EnsureWork(f, (size_t)16 * k * NBU, 0));
      for (PetscInt jc = 0; jc < m; jc += NBU) {
        const PetscInt ncb = PetscMin(NBU, m - jc);
        BuildP(L + k + jc, cs, N, k, ncb, PETSC_TRUE, f->pbig);
        for (int c = 0; c < 4; c++) PetscCall(Gemm("N", "N", m - jc, ncb, 4 * k, -1.0, L + k + jc, N, f->pbig + (PetscInt64)c * ncb * 4 * k, 4 * k, 1.0, U + c * us + (PetscInt64)jc * m + jc, m));
      }
      stack[top].U   = U;
      stack[top++].s = s;
    }
  }
  PetscCall(PetscFree(stack));
  f->factored = PETSC_TRUE;
  PetscCall(PetscLogFlops(f->flops));
  PetscCall(PetscLogEventEnd(CS_EVENT_QuatCholNum, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSQuatCholeskyCreate(const char ordering[], CSQuatCholesky *fac)
{
  CSQuatCholesky f;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&f));
  PetscCall(CSCholmodStartCommon(ordering, &f->common));
  *fac = f;
  PetscFunctionReturn(0);
}

PetscErrorCode CSQuatCholeskySetUp(CSQuatCholesky f, Mat K, PetscReal sigma)
{
  PetscObjectId    id;
  PetscObjectState st;
  PetscMPIInt      size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)K), &size));
  PetscCheck(size == 1, PetscObjectComm((PetscObject)K), PETSC_ERR_SUP, "the quaternion Cholesky factorisation is serial: K lives on %d processes", size);
  PetscCall(PetscObjectGetId((PetscObject)K, &id));
  PetscCall(MatGetNonzeroState(K, &st));
  if (!f->nsuper || id != f->kid || st != f->kstate) {
    PetscCall(PetscLogEventBegin(CS_EVENT_QuatCholSym, 0, 0, 0, 0));
    PetscCall(Symbolic(f, K));
    PetscCall(PetscLogEventEnd(CS_EVENT_QuatCholSym, 0, 0, 0, 0));
    f->kid    = id;
    f->kstate = st;
  }
  PetscCall(Numeric(f, K, sigma));
  PetscFunctionReturn(0);
}

/* y = L^{-H} L^{-1} x in the permuted numbering; y and the work vector interleaved (4 reals per quaternion) */
PetscErrorCode CSQuatCholeskySolve(CSQuatCholesky f, Vec x, Vec yv)
{
  const PetscScalar *xa;
  PetscScalar       *ya;
  double            *y = f->y, *t = f->tmp;
  PetscFunctionBeginUser;
  PetscCheck(f->factored, PETSC_COMM_SELF, PETSC_ERR_ORDER, "CSQuatCholeskySolve before a successful SetUp");
  {
    PetscInt nx, ny;
    PetscCall(VecGetLocalSize(x, &nx));
    PetscCall(VecGetLocalSize(yv, &ny));
    PetscCheck(nx == 4 * f->nb && ny == 4 * f->nb, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "CSQuatCholeskySolve: vectors of local sizes %" PetscInt_FMT " and %" PetscInt_FMT " for a factor of %" PetscInt_FMT " rows", nx, ny, 4 * f->nb);
  }
  PetscCall(PetscLogEventBegin(CS_EVENT_QuatCholSolve, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(x, &xa));
  for (PetscInt p = 0; p < f->nb; p++)
    for (int c = 0; c < 4; c++) y[4 * p + c] = PetscRealPart(xa[4 * f->perm[p] + c]);
  PetscCall(VecRestoreArrayRead(x, &xa));
  /* forward: L z = y */
  for (PetscInt s = 0; s < f->nsuper; s++) {
    const PetscInt   k = f->super[s + 1] - f->super[s], N = f->rowptr[s + 1] - f->rowptr[s], m = N - k, *r = f->rows + f->rowptr[s];
    const PetscInt64 cs = (PetscInt64)k * N;
    const double    *L  = f->lx + f->lxptr[s];
    double          *z  = y + 4 * f->super[s];
    for (PetscInt j = 0; j < k; j++) {
      const double *Lj = L + (PetscInt64)j * N;
      double       *zj = z + 4 * j;
      for (int c = 0; c < 4; c++) zj[c] /= Lj[j];
      for (PetscInt i = j + 1; i < k; i++) {
        const double l[4] = {Lj[i], Lj[cs + i], Lj[2 * cs + i], Lj[3 * cs + i]};
        double       p[4];
        CSQuatMul(l, zj, p);
        for (int c = 0; c < 4; c++) z[4 * i + c] -= p[c];
      }
    }
    if (m > 0) { /* rows beyond: t = L21 z (m x 4, one column per component), subtracted at their rows */
      PetscCall(EnsureWork(f, (size_t)16 * k, (size_t)4 * k));
      for (int c = 0; c < 4; c++)
        for (PetscInt j = 0; j < k; j++) f->apack[c * k + j] = z[4 * j + c]; /* z as a split k x 1 matrix */
      BuildP(f->apack, k, k, k, 1, PETSC_FALSE, f->pbig);
      PetscCall(Gemm("N", "N", m, 4, 4 * k, 1.0, L + k, N, f->pbig, 4 * k, 0.0, t, m));
      for (PetscInt i = 0; i < m; i++)
        for (int c = 0; c < 4; c++) y[4 * r[k + i] + c] -= t[c * m + i];
    }
  }
  /* backward: L^H w = z */
  for (PetscInt s = f->nsuper - 1; s >= 0; s--) {
    const PetscInt   k = f->super[s + 1] - f->super[s], N = f->rowptr[s + 1] - f->rowptr[s], m = N - k, *r = f->rows + f->rowptr[s];
    const PetscInt64 cs = (PetscInt64)k * N;
    const double    *L  = f->lx + f->lxptr[s];
    double          *w  = y + 4 * f->super[s];
    if (m > 0) { /* w -= L21^H w_rows: G = [L0..L3](rows)^T [w0..w3](rows), then the conj(l) w table */
      double *G;
      PetscCall(EnsureWork(f, (size_t)16 * k, (size_t)4 * m));
      G = f->pbig;
      for (PetscInt i = 0; i < m; i++)
        for (int c = 0; c < 4; c++) f->apack[c * m + i] = y[4 * r[k + i] + c];
      PetscCall(Gemm("T", "N", 4 * k, 4, m, 1.0, L + k, N, f->apack, m, 0.0, G, 4 * k));
      for (PetscInt j = 0; j < k; j++) {
#define Gq(rr, ss) G[(ss) * 4 * k + (rr) * k + j]
        w[4 * j + 0] -= Gq(0, 0) + Gq(1, 1) + Gq(2, 2) + Gq(3, 3);
        w[4 * j + 1] -= Gq(0, 1) - Gq(1, 0) - Gq(2, 3) + Gq(3, 2);
        w[4 * j + 2] -= Gq(0, 2) + Gq(1, 3) - Gq(2, 0) - Gq(3, 1);
        w[4 * j + 3] -= Gq(0, 3) - Gq(1, 2) + Gq(2, 1) - Gq(3, 0);
#undef Gq
      }
    }
    for (PetscInt j = k - 1; j >= 0; j--) {
      const double *Lj = L + (PetscInt64)j * N;
      double       *wj = w + 4 * j;
      for (PetscInt i = j + 1; i < k; i++) {
        const double l[4] = {Lj[i], Lj[cs + i], Lj[2 * cs + i], Lj[3 * cs + i]};
        double       p[4];
        CSQuatConjMul(l, w + 4 * i, p);
        for (int c = 0; c < 4; c++) wj[c] -= p[c];
      }
      for (int c = 0; c < 4; c++) wj[c] /= Lj[j];
    }
  }
  PetscCall(VecGetArray(yv, &ya));
  for (PetscInt p = 0; p < f->nb; p++)
    for (int c = 0; c < 4; c++) ya[4 * f->perm[p] + c] = y[4 * p + c];
  PetscCall(VecRestoreArray(yv, &ya));
  PetscCall(PetscLogFlops(2.0 * 32.0 * f->nnzL));
  PetscCall(PetscLogEventEnd(CS_EVENT_QuatCholSolve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSQuatCholeskyDestroy(CSQuatCholesky *fac)
{
  CSQuatCholesky f = *fac;
  PetscFunctionBeginUser;
  if (!f) PetscFunctionReturn(0);
  PetscCall(FreeSymbolic(f));
  PetscCall(PetscFree(f->pbig));
  PetscCall(PetscFree(f->apack));
  cholmod_finish(&f->common);
  PetscCall(PetscFree(f));
  *fac = NULL;
  PetscFunctionReturn(0);
}
