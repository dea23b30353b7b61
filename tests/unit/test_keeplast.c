static const char help[] = "Checks of CSCholmodFactorKeepLast (src/operators/cholmod_last_supernode.c): a CHOLMOD factorisation that\n"
                           "leaves the trailing block of its last supernode as the Schur complement T = A22 - A21 A11^{-1} A12.\n"
                           "T is compared with the inverse of (A^{-1})_22 from a normal factorisation, on a dense SPD matrix\n"
                           "(one supernode) and on an arrow matrix (two dense blocks coupled only through the trailing block);\n"
                           "a matrix that is not positive definite in the leading columns reports CHOLMOD_NOT_POSDEF at the\n"
                           "right column; trailing columns that are not the last supernode's give a normal factorisation.\n"
                           "Serial. Exit status = number of failed checks.\n";

#include <suitesparse/cholmod.h>
#include "cs_cholmod.h"
#include "cs_test.h"

/* A (n x n, dense column-major) as a CHOLMOD sparse matrix, upper triangle stored */
static cholmod_sparse *ToCholmod(const double *A, int n, cholmod_common *c)
{
  int             nz = 0;
  cholmod_sparse *S;
  for (int j = 0; j < n; j++)
    for (int i = 0; i <= j; i++)
      if (A[i + j * n] != 0) nz++;
  S = cholmod_allocate_sparse(n, n, nz, 1, 1, 1, CHOLMOD_REAL, c);
  if (!S) return NULL;
  nz = 0;
  for (int j = 0; j < n; j++) {
    ((int *)S->p)[j] = nz;
    for (int i = 0; i <= j; i++)
      if (A[i + j * n] != 0) {
        ((int *)S->i)[nz]    = i;
        ((double *)S->x)[nz] = A[i + j * n];
        nz++;
      }
  }
  ((int *)S->p)[n] = nz;
  return S;
}

/* Symbolic factor of A in the natural order (CHOLMOD postorders it; the trailing columns stay last: a root) */
static cholmod_factor *Analyse(cholmod_sparse *S, cholmod_common *c)
{
  int            *perm = (int *)malloc(sizeof(int) * S->nrow);
  cholmod_factor *L;
  for (size_t k = 0; k < S->nrow; k++) perm[k] = (int)k;
  c->nmethods           = 1;
  c->method[0].ordering = CHOLMOD_GIVEN;
  L                     = cholmod_analyze_p(S, perm, NULL, 0, c);
  free(perm);
  return L;
}

/* max |T Z - I| with T the kept block (lower triangle, in factor order) and Z = (A^{-1}) on the same columns */
static PetscErrorCode CheckSchur(const double *A, int n, int ntrail, const char *label)
{
  cholmod_common  c;
  cholmod_sparse *S;
  cholmod_factor *L, *F;
  cholmod_dense  *E, *X;
  PetscBool       kept;
  double         *T, err = 0;
  int             ns, k1, nsrow;
  const int      *P;
  char            what[160];
  PetscFunctionBeginUser;
  PetscCall(CSCholmodStartCommon("auto", &c));
  c.print = 0;
  S       = ToCholmod(A, n, &c);
  L       = Analyse(S, &c);
  F       = Analyse(S, &c);
  PetscCheck(S && L && F, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD setup failed");
  PetscCall(CSCholmodFactorKeepLast(S, L, ntrail, &c, &kept));
  PetscCheck(c.status == CHOLMOD_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD status %d", c.status);
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: the trailing block was kept", label));
  PetscCall(CSTestCheck(PETSC_COMM_SELF, kept, what, kept ? 1 : 0, 1));
  cholmod_factorize(S, F, &c); /* the reference: a normal factorisation */
  ns    = (int)L->nsuper;
  k1    = ((int *)L->super)[ns - 1];
  nsrow = ((int *)L->pi)[ns] - ((int *)L->pi)[ns - 1];
  P     = (const int *)L->Perm;
  PetscCall(PetscMalloc1(ntrail * ntrail, &T));
  for (int j = 0; j < ntrail; j++) /* T(i,j), i >= j, at row i + lead, column j + lead of the last supernode */
    for (int i = j; i < ntrail; i++) {
      int lead = nsrow - ntrail;
      T[i + j * ntrail] = T[j + i * ntrail] = ((double *)L->x)[((int *)L->px)[ns - 1] + (i + lead) + (size_t)(j + lead) * nsrow];
    }
  PetscCheck(k1 + nsrow == n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "the last supernode does not end the matrix");
  E = cholmod_zeros(n, ntrail, CHOLMOD_REAL, &c);
  for (int j = 0; j < ntrail; j++) ((double *)E->x)[P[n - ntrail + j] + (size_t)j * n] = 1;
  X = cholmod_solve(CHOLMOD_A, F, E, &c);
  for (int i = 0; i < ntrail; i++)
    for (int j = 0; j < ntrail; j++) {
      double tz = 0;
      for (int l = 0; l < ntrail; l++) tz += T[i + l * ntrail] * ((double *)X->x)[P[n - ntrail + l] + (size_t)j * n];
      err = PetscMax(err, PetscAbsReal(tz - (i == j ? 1 : 0)));
    }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: max |T (A^-1)_22 - I|", label));
  PetscCall(CSTestCheck(PETSC_COMM_SELF, (PetscBool)(err < 1e-10), what, err, 1e-10));
  PetscCall(PetscFree(T));
  cholmod_free_dense(&E, &c);
  cholmod_free_dense(&X, &c);
  cholmod_free_factor(&L, &c);
  cholmod_free_factor(&F, &c);
  cholmod_free_sparse(&S, &c);
  cholmod_finish(&c);
  PetscFunctionReturn(0);
}

/* dense SPD: B B^T / n + I with B pseudo-random */
static void DenseSPD(double *A, int n, unsigned seed)
{
  double *B = (double *)malloc(sizeof(double) * n * n);
  for (int k = 0; k < n * n; k++) {
    seed = seed * 1103515245u + 12345u;
    B[k] = ((seed >> 8) & 0xffff) / 65536.0 - 0.5;
  }
  for (int i = 0; i < n; i++)
    for (int j = 0; j < n; j++) {
      double s = 0;
      for (int l = 0; l < n; l++) s += B[i + l * n] * B[j + l * n];
      A[i + j * n] = s / n + (i == j ? 1 : 0);
    }
  free(B);
}

int main(int argc, char **argv)
{
  const int n = 30, m = 12, t = 6, na = 2 * m + t; /* dense case: n, trailing 10; arrow: blocks m, m, trailing t */
  double   *A, *W;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(PetscMalloc2(n * n, &A, na * na, &W));

  DenseSPD(A, n, 1u);
  PetscCall(CheckSchur(A, n, 10, "dense 30 x 30, trailing 10"));
  PetscCall(CheckSchur(A, n, n, "dense 30 x 30, all trailing (nothing factored)"));

  /* arrow: [B1 0 C1; 0 B2 C2; C1^T C2^T D], SPD as a principal-block-dominant matrix */
  DenseSPD(W, na, 2u);
  for (int i = 0; i < m; i++)
    for (int j = m; j < 2 * m; j++) W[i + j * na] = W[j + i * na] = 0;
  for (int i = 0; i < na; i++) W[i + i * na] += 1;
  PetscCall(CheckSchur(W, na, t, "arrow 12 + 12 + 6, trailing 6"));

  { /* not positive definite in the leading columns: CHOLMOD stops there, nothing kept */
    cholmod_common  c;
    cholmod_sparse *S;
    cholmod_factor *L;
    PetscBool       kept;
    DenseSPD(A, n, 3u);
    A[3 + 3 * n] = -100;
    PetscCall(CSCholmodStartCommon("auto", &c));
    c.print = 0;
    S       = ToCholmod(A, n, &c);
    L       = Analyse(S, &c);
    PetscCall(CSCholmodFactorKeepLast(S, L, 10, &c, &kept));
    PetscCall(CSTestCheck(PETSC_COMM_SELF, (PetscBool)(c.status == CHOLMOD_NOT_POSDEF && L->minor == 3 && !kept), "indefinite at column 3: CHOLMOD_NOT_POSDEF, minor 3, nothing kept", (PetscReal)L->minor, 3));
    cholmod_free_factor(&L, &c);
    cholmod_free_sparse(&S, &c);
    cholmod_finish(&c);
  }
  { /* trailing columns beyond the last supernode (the arrow's root holds only its t columns or a few more):
       a normal factorisation */
    cholmod_common  c;
    cholmod_sparse *S;
    cholmod_factor *L;
    PetscBool       kept;
    PetscCall(CSCholmodStartCommon("auto", &c));
    c.print = 0;
    S       = ToCholmod(W, na, &c);
    L       = Analyse(S, &c);
    PetscCall(CSCholmodFactorKeepLast(S, L, na, &c, &kept));
    PetscCall(CSTestCheck(PETSC_COMM_SELF, (PetscBool)(c.status == CHOLMOD_OK && !kept), "arrow, all 30 columns asked: more than the last supernode, a normal factorisation", kept ? 1 : 0, 0));
    cholmod_free_factor(&L, &c);
    cholmod_free_sparse(&S, &c);
    cholmod_finish(&c);
  }
  PetscCall(PetscFree2(A, W));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%" PetscInt_FMT " failed\n", cs_test_failures));
  PetscCall(PetscFinalize());
  return (int)cs_test_failures;
}
