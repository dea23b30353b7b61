/* A CHOLMOD supernodal factorisation that leaves the trailing block of its last supernode as a Schur complement.

   Why: the substructured Cholesky (PC cssubchol) needs, on each rank, the Schur complement
       T = A(G,G) - A(G,I) A(I,I)^{-1} A(I,G)
   of its local matrix on the interface G, which it orders last. CHOLMOD has no partial factorisation, but it
   builds T on the way: the interface columns end the last supernode (with the interior's top separator before
   them), and when CHOLMOD reaches that supernode it has summed into its diagonal block the original entries and
   every update from the rest of the interior; it then factors the block with one LAPACK dpotrf call. Stopping
   that call after the leading (interior) columns -- their Cholesky factor, the triangular solve for the rows
   below, the update of the trailing block -- leaves T in the trailing block. Without this, T costs two more
   dense steps of |G|^3/3 flops each: the rest of CHOLMOD's dpotrf, then L_GG L_GG^T (dlauum) to multiply it
   back (level 6 on 2 ranks: |G| = 2256, 2 x 3.8e9 flops on the critical path of a 3.3e10-flop factorisation).

   How: this file defines LAPACK's dpotrf_. The dynamic linker binds every caller of dpotrf_ in the process
   (CHOLMOD, PETSc, ...) to this definition, which passes each call on to the library's own dpotrf
   (dlsym RTLD_NEXT), except the one call on the last supernode's block (recognised by its address) while
   CSCholmodFactorKeepLast has armed it. If the binding does not happen (a static or -Bsymbolic CHOLMOD), the
   factorisation is a normal one and CSCholmodFactorKeepLast says so: nothing but speed depends on the hook.
   Checked against CHOLMOD 3.0's supernodal numeric factorisation (CPU path): the block handed to dpotrf is the
   root supernode's fully assembled diagonal block (lda = its rows = its columns), nothing in CHOLMOD reads it
   afterwards but the solves, and a failure in the leading columns returns the info a full dpotrf would.
   One thread: the hook is armed only around our own cholmod_factorize call (CHOLMOD calls dpotrf from the calling
   thread). */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <suitesparse/cholmod.h>
#include "cs_cholmod.h" /* petscksp.h first: petscblaslapack.h needs it */
#include <petscblaslapack.h>

typedef void (*PotrfFn)(const char *, const int *, double *, const int *, int *);

static struct {
  double *block; /* armed: the last supernode's block, to be factored only partially; NULL: pass every call on */
  int     order; /* its columns (= rows) */
  int     lead;  /* its columns to factor; the trailing order - lead are left as the Schur complement */
  int     done;  /* the block was met */
} hook;

static void LapackPotrf(const char *uplo, const int *n, double *a, const int *lda, int *info)
{
  static PotrfFn lapack = NULL;
  if (!lapack) {
    lapack = (PotrfFn)dlsym(RTLD_NEXT, "dpotrf_");
    if (!lapack) { /* cannot happen while the program links LAPACK; dpotrf has no error channel for it */
      fprintf(stderr, "confsurf: LAPACK dpotrf_ not found behind src/operators/cholmod_last_supernode.c\n");
      abort();
    }
  }
  lapack(uplo, n, a, lda, info);
}

/* LAPACK dpotrf (its interface): Cholesky factorisation of a dense SPD matrix, lower triangle for CHOLMOD */
void dpotrf_(const char *uplo, const int *n, double *a, const int *lda, int *info)
{
  if (hook.block && a == hook.block && *n == hook.order && *lda == hook.order && uplo[0] == 'L') {
    /* [A11 .; A21 A22]: A11 = L11 L11^T, L21 = A21 L11^{-T}, A22 -= L21 L21^T; A22 is then the Schur complement */
    const int    k = hook.lead, r = hook.order - hook.lead;
    const double one = 1, minus = -1;
    hook.block = NULL;
    hook.done  = 1;
    *info      = 0;
    if (k == 0) return;
    LapackPotrf("L", &k, a, lda, info);
    if (*info || r == 0) return; /* not positive definite at leading column *info: CHOLMOD reports it */
    BLAStrsm_("R", "L", "T", "N", &r, &k, &one, a, lda, a + k, lda);
    BLASsyrk_("L", "N", &r, &k, &minus, a + k, lda, &one, a + k + (size_t)k * *lda, lda);
    return;
  }
  LapackPotrf(uplo, n, a, lda, info);
}

PetscErrorCode CSCholmodFactorKeepLast(cholmod_sparse *A, cholmod_factor *L, PetscInt ntrail, cholmod_common *c, PetscBool *kept)
{
  size_t     ns  = L->nsuper;
  const int *sup = ns ? (const int *)L->super : NULL, *pi = ns ? (const int *)L->pi : NULL;
  PetscFunctionBeginUser;
  *kept = PETSC_FALSE;
  PetscCheck(L->is_super, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "CSCholmodFactorKeepLast: needs a supernodal symbolic factor");
  if (!ns || ntrail <= 0 || ntrail > sup[ns] - sup[ns - 1] || pi[ns] - pi[ns - 1] != sup[ns] - sup[ns - 1]) {
    cholmod_factorize(A, L, c); /* the trailing columns are not a root block's: nothing to keep */
    PetscFunctionReturn(0);
  }
  /* a factor converted after the factorisation (LDL', simplicial) would take the kept block for a factor */
  PetscCheck(c->final_asis, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "CSCholmodFactorKeepLast: needs Common->final_asis");
  if (L->xtype == CHOLMOD_PATTERN) { /* the numeric space now (as cholmod_factorize would), to know the block's address */
    cholmod_change_factor(CHOLMOD_REAL, 1, 1, 1, 1, L, c); /* LL', supernodal, packed, monotonic */
    if (c->status < CHOLMOD_OK) PetscFunctionReturn(0); /* the caller reports it */
  }
  hook.order = sup[ns] - sup[ns - 1];
  hook.lead  = hook.order - (int)ntrail;
  hook.done  = 0;
  hook.block = (double *)L->x + ((const int *)L->px)[ns - 1]; /* read after the numeric space exists */
  cholmod_factorize(A, L, c);
  hook.block = NULL;
  *kept      = (PetscBool)(hook.done && c->status == CHOLMOD_OK);
  PetscFunctionReturn(0);
}
