/* Direct CHOLMOD factorisation of a quaternionic matrix in complex form (include/cs_cholmod.h).

   K - sigma is quaternionic Hermitian, each 4x4 block the left multiplication by a
   quaternion (crane2011 Sec. 5.1, CSQuatBlock). Writing lam = z + w j with complex z = l0 + l1 i,
   w = l2 + l3 i and a block q = a + b j (a = q0 + q1 i, b = q2 + q3 i):
     q lam = (a z - b conj(w)) + (a w + b conj(z)) j,
   which is complex-linear in (z, conj(w)):  [z'; conj(w')] = [a, -b; conj(b), conj(a)] [z; conj(w)].
   So K - sigma acts as a complex Hermitian 2V x 2V matrix with the same spectrum (each eigenvalue twice instead
   of four times); its Cholesky factorisation costs half the flops of the real 4V x 4V one (a complex
   multiply-add is 4 real ones, on a matrix of half the dimension: 4 / 2^3) and half the memory. PETSc here is
   real, so the vectors are converted on the way in and out. */
#include <suitesparse/cholmod.h>
#include "cs_cholmod.h"
#include "cs_linalg.h"
#include "cs_quaternion.h"

struct _p_CSCholmod {
  cholmod_common  common;
  cholmod_factor *L;
  cholmod_sparse *A;
  cholmod_dense  *b;
  PetscInt        n; /* rows of the PETSc matrix (4 per vertex) */
};

static PetscErrorCode CholmodCheck(cholmod_common *c, const char *what)
{
  PetscFunctionBeginUser;
  PetscCheck(c->status >= CHOLMOD_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "CHOLMOD %s failed (status %d)", what, c->status);
  PetscFunctionReturn(0);
}

/* A new pattern: drop the old matrix, analysis and work vector. */
static void Reset(CSCholmod f)
{
  cholmod_free_sparse(&f->A, &f->common);
  cholmod_free_factor(&f->L, &f->common);
  cholmod_free_dense(&f->b, &f->common);
}

/* Column pointers from per-column counts, and cnt turned into fill positions. The symbolic analysis belongs
   to one pattern: if the column counts differ from the kept matrix's, everything is rebuilt (equal counts with
   other row indices are caught by BuildQuaternion, which then drops the analysis). */
static PetscErrorCode AllocateLower(CSCholmod f, PetscInt ncol, PetscInt *cnt)
{
  int *colp;
  PetscFunctionBeginUser;
  if (f->A) {
    colp = (int *)f->A->p;
    for (PetscInt c = 0; c < ncol; c++)
      if (colp[c + 1] - colp[c] != (int)cnt[c]) {
        Reset(f);
        break;
      }
  }
  if (!f->A) {
    PetscInt nnz = 0;
    for (PetscInt c = 0; c < ncol; c++) nnz += cnt[c];
    f->A = cholmod_allocate_sparse((size_t)ncol, (size_t)ncol, (size_t)nnz, 1, 1, -1, CHOLMOD_COMPLEX, &f->common);
    PetscCall(CholmodCheck(&f->common, "allocate"));
  }
  colp    = (int *)f->A->p;
  colp[0] = 0;
  for (PetscInt c = 0; c < ncol; c++) colp[c + 1] = colp[c] + (int)cnt[c];
  for (PetscInt c = 0; c < ncol; c++) cnt[c] = colp[c];
  PetscFunctionReturn(0);
}

/* The lower triangle of the complex form of K - sigma in compressed columns (stype -1). Row 4i of a block
   holds (q0, -q1, -q2, -q3). */
static PetscErrorCode BuildQuaternion(CSCholmod f, Mat K, PetscReal sigma)
{
  PetscInt  n4, nb, *cnt;
  int      *rowi;
  PetscBool moved = PETSC_FALSE; /* a row index differs from the kept pattern's (the same column counts) */
  double  *val;
  PetscFunctionBeginUser;
  PetscCall(MatGetSize(K, &n4, NULL));
  PetscCheck(n4 % 4 == 0, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "matrix of size %" PetscInt_FMT " is not quaternionic", n4);
  if (f->A && f->n != n4) Reset(f);
  f->n = n4;
  nb   = n4 / 4;
  PetscCall(PetscCalloc1(2 * nb + 1, &cnt));
  for (PetscInt i = 0; i < nb; i++) { /* pass 1: entries per complex column */
    PetscInt        nc;
    const PetscInt *cols;
    PetscCall(MatGetRow(K, 4 * i, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc;) {
      PetscInt j = CSQuatRowNextBlock(nc, cols, NULL, &k, NULL);
      if (j > i) continue; /* lower blocks only */
      if (j < i) cnt[2 * j] += 2, cnt[2 * j + 1] += 2;
      else cnt[2 * j] += 2, cnt[2 * j + 1] += 1; /* diagonal block: (0,0), (1,0), (1,1) */
    }
    PetscCall(MatRestoreRow(K, 4 * i, &nc, &cols, NULL));
  }
  PetscCall(AllocateLower(f, 2 * nb, cnt));
  rowi = (int *)f->A->i;
  val  = (double *)f->A->x;
  /* pass 2: block row i gives complex rows 2i, 2i+1 in increasing order, so each column stays sorted */
  for (PetscInt i = 0; i < nb; i++) {
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *v;
    PetscCall(MatGetRow(K, 4 * i, &nc, &cols, &v));
    for (PetscInt k = 0; k < nc;) {
      PetscReal q[4];
      PetscInt  j = CSQuatRowNextBlock(nc, cols, v, &k, q);
      if (j > i) continue;
      if (j == i) q[0] -= sigma;
      {
        /* [a, -b; conj(b), conj(a)] at rows (2i, 2i+1), columns (2j, 2j+1), as (re, im) */
        const double B[2][2][2] = {
          {{q[0], q[1]},  {-q[2], -q[3]}},
          {{q[2], -q[3]}, {q[0], -q[1]} }
        };
        for (int r = 0; r < 2; r++)
          for (int c = 0; c < 2; c++) {
            PetscInt col = 2 * j + c, pos;
            if (j == i && c > r) continue;
            pos              = cnt[col]++;
            if (f->L && rowi[pos] != (int)(2 * i + r)) moved = PETSC_TRUE; /* (only a kept pattern is compared) */
            rowi[pos]        = (int)(2 * i + r);
            val[2 * pos]     = B[r][c][0];
            val[2 * pos + 1] = B[r][c][1];
          }
      }
    }
    PetscCall(MatRestoreRow(K, 4 * i, &nc, &cols, &v));
  }
  if (moved && f->L) cholmod_free_factor(&f->L, &f->common); /* the analysis was of another pattern: Factor redoes it */
  PetscCall(PetscFree(cnt));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCholmodStartCommon(const char ordering[], cholmod_common *c)
{
  PetscBool amd, metis, nesdis, autom;
  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(ordering, "amd", &amd));
  PetscCall(PetscStrcmp(ordering, "metis", &metis));
  PetscCall(PetscStrcmp(ordering, "nesdis", &nesdis));
  PetscCall(PetscStrcmp(ordering, "auto", &autom));
  PetscCheck(amd || metis || nesdis || autom, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "CHOLMOD ordering %s: use amd, metis, nesdis or auto", ordering);
  PetscCheck(cholmod_start(c), PETSC_COMM_SELF, PETSC_ERR_LIB, "cholmod_start failed");
  c->supernodal = CHOLMOD_SUPERNODAL;
  if (!autom) {
    c->nmethods           = 1;
    c->method[0].ordering = amd ? CHOLMOD_AMD : (metis ? CHOLMOD_METIS : CHOLMOD_NESDIS);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSCholmodCreate(const char ordering[], CSCholmod *fac)
{
  CSCholmod f;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&f));
  PetscCall(CSCholmodStartCommon(ordering, &f->common));
  *fac = f;
  PetscFunctionReturn(0);
}

PetscErrorCode CSCholmodDestroy(CSCholmod *fac)
{
  CSCholmod f = *fac;
  PetscFunctionBeginUser;
  if (!f) PetscFunctionReturn(0);
  Reset(f);
  cholmod_finish(&f->common);
  PetscCall(PetscFree(f));
  *fac = NULL;
  PetscFunctionReturn(0);
}

static PetscErrorCode Factor(CSCholmod f)
{
  PetscFunctionBeginUser;
  if (!f->L) {
    PetscCall(PetscLogEventBegin(CS_EVENT_CholmodSym, 0, 0, 0, 0));
    f->L = cholmod_analyze(f->A, &f->common);
    PetscCall(PetscLogEventEnd(CS_EVENT_CholmodSym, 0, 0, 0, 0));
    PetscCall(CholmodCheck(&f->common, "analyze"));
  }
  cholmod_factorize(f->A, f->L, &f->common);
  PetscCall(CholmodCheck(&f->common, "factorize"));
  PetscCheck(f->L->minor == f->L->n, PETSC_COMM_SELF, PETSC_ERR_MAT_CH_ZRPVT, "CHOLMOD: the matrix is not positive definite (stopped at column %d of %d)", (int)f->L->minor, (int)f->L->n);
  if (!f->b) {
    f->b = cholmod_allocate_dense(f->L->n, 1, f->L->n, CHOLMOD_COMPLEX, &f->common);
    PetscCall(CholmodCheck(&f->common, "allocate"));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSCholmodSetUpQuaternion(CSCholmod f, Mat K, PetscReal sigma)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_CholmodNum, 0, 0, 0, 0));
  PetscCall(BuildQuaternion(f, K, sigma));
  PetscCall(Factor(f));
  PetscCall(PetscLogEventEnd(CS_EVENT_CholmodNum, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* (z, conj(w)) = (l0 + l1 i, l2 - l3 i) per vertex, and back. */
PetscErrorCode CSCholmodSolve(CSCholmod f, Vec x, Vec y)
{
  const PetscScalar *xa;
  PetscScalar       *ya;
  double            *b = (double *)f->b->x, *s;
  cholmod_dense     *sol;
  PetscFunctionBeginUser;
  PetscCheck(f->L, PETSC_COMM_SELF, PETSC_ERR_ORDER, "CSCholmodSolve before a SetUp");
  PetscCall(PetscLogEventBegin(CS_EVENT_CholmodSolve, 0, 0, 0, 0));
  PetscCall(VecGetArrayRead(x, &xa));
  for (PetscInt i = 0; i < f->n; i += 4) {
    b[i]     = PetscRealPart(xa[i]);
    b[i + 1] = PetscRealPart(xa[i + 1]);
    b[i + 2] = PetscRealPart(xa[i + 2]);
    b[i + 3] = -PetscRealPart(xa[i + 3]);
  }
  PetscCall(VecRestoreArrayRead(x, &xa));
  sol = cholmod_solve(CHOLMOD_A, f->L, f->b, &f->common);
  PetscCall(CholmodCheck(&f->common, "solve"));
  s = (double *)sol->x;
  PetscCall(VecGetArray(y, &ya));
  for (PetscInt i = 0; i < f->n; i += 4) {
    ya[i]     = s[i];
    ya[i + 1] = s[i + 1];
    ya[i + 2] = s[i + 2];
    ya[i + 3] = -s[i + 3];
  }
  PetscCall(VecRestoreArray(y, &ya));
  cholmod_free_dense(&sol, &f->common);
  PetscCall(PetscLogEventEnd(CS_EVENT_CholmodSolve, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSetDefaultCholesky(PC pc)
{
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)pc), &size));
  if (size > 1) { /* substructured CHOLMOD (substructured_cholesky.c): MUMPS here orders only with PORD/AMD */
    PetscCall(PCSetType(pc, PCCSSUBCHOL));
    PetscFunctionReturn(0);
  }
  PetscCall(PCSetType(pc, PCCHOLESKY));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERCHOLMOD));
  PetscFunctionReturn(0);
}
