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
   (dlsym RTLD_NEXT), except one call while CSCholmodFactorKeepLast has armed it: the first whose order and
   leading dimension are those of the last supernode. CSCholmodFactorKeepLast then checks that the block
   stopped early was that supernode's (the pointer is compared); if the binding did not happen (a static or
   -Bsymbolic CHOLMOD) or another block of the same size was hit, it factors normally and says so, so nothing
   but speed depends on the hook. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <stdio.h>
#include <stdlib.h>
#include <suitesparse/cholmod.h>
#include "cs_cholmod.h" /* petscksp.h first: petscblaslapack.h needs it */
#include <petscblaslapack.h>

typedef void (*PotrfFn)(const char *, const int *, double *, const int *, int *);

static struct {
  int     armed; /* stop the next call with n == lda == order early */
  int     order; /* of the last supernode */
  int     lead;  /* its columns to factor; the trailing order - lead are left as the Schur complement */
  double *block; /* the block it stopped early */
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
  if (hook.armed && *n == hook.order && *lda == hook.order && uplo[0] == 'L') {
    /* [A11 .; A21 A22]: A11 = L11 L11^T, L21 = A21 L11^{-T}, A22 -= L21 L21^T; A22 is then the Schur complement */
    const int    k = hook.lead, r = hook.order - hook.lead;
    const double one = 1, minus = -1;
    hook.armed = 0;
    hook.block = a;
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
  const int *sup = ns ? (const int *)L->super : NULL, *pi = ns ? (const int *)L->pi : NULL, *px = ns ? (const int *)L->px : NULL;
  PetscFunctionBeginUser;
  *kept = PETSC_FALSE;
  PetscCheck(L->is_super, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "CSCholmodFactorKeepLast: needs a supernodal symbolic factor");
  if (!ns || ntrail <= 0 || ntrail > sup[ns] - sup[ns - 1] || pi[ns] - pi[ns - 1] != sup[ns] - sup[ns - 1]) {
    cholmod_factorize(A, L, c); /* the trailing columns are not a root block's: nothing to keep */
    PetscFunctionReturn(0);
  }
  hook.order = sup[ns] - sup[ns - 1];
  hook.lead  = hook.order - (int)ntrail;
  hook.block = NULL;
  hook.armed = 1;
  cholmod_factorize(A, L, c);
  hook.armed = 0;
  if (c->status < CHOLMOD_OK || c->status == CHOLMOD_NOT_POSDEF) PetscFunctionReturn(0); /* the caller reports it */
  if (hook.block == (double *)L->x + px[ns - 1]) *kept = PETSC_TRUE;
  else if (hook.block) cholmod_factorize(A, L, c); /* another block of that size was stopped early: redo */
  PetscFunctionReturn(0);
}
