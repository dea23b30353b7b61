/* The signed Dirac spectrum of crane2011 Sec. 6.2 (Fig. 8) from the generalised problem Eq. 6,
     A^* A lam = gamma B^* A lam      (rho = 0: X lam = gamma Y lam, X = D^H M_F D, Y = B^H M_F D),
   and its eigenvectors (the Dirac spheres of Fig. 9, 11).
   The pencil (X, Y) is singular: X c = Y c = 0 for every constant c (Sec. 6.2: "constant solutions are in the
   null space of the system"), so neither shift-and-invert of X - sigma Y nor a solver with B = Y applies. Two
   steps instead:
   1. the kernel of A (= ker X: D lam = 0, the eigenvalue 0 of D) from the definite pencil X lam = mu M_V lam
      (shift-and-invert toward a small negative target, prefix spin_kernel_); its vectors count as gamma = 0;
   2. the rest from the Hermitian-definite pencil Y lam = theta (X + eps M_V) lam, theta = 1/gamma, largest
      |theta| (Krylov-Schur, B-inner product; prefix spin_signed_). eps = 1e-10 (4 pi / area) sends the
      constants to theta = 0 and moves the other eigenvalues by ~eps / gamma (relative 1e-10). */
#include "spin_impl.h"

/* one eigenpair of the combined list */
typedef struct {
  PetscReal gamma;
  PetscInt  src, idx; /* 0: kernel EPS, 1: the signed pairs found (SignedSolve); index there */
} SignedPair;

static int CompareAbs(const void *a, const void *b)
{
  const SignedPair *p = (const SignedPair *)a, *q = (const SignedPair *)b;
  PetscReal         x = PetscAbsReal(p->gamma), y = PetscAbsReal(q->gamma);
  /* ties (within rounding) ascending by the signed value: -2 before 2 */
  if (PetscAbsReal(x - y) > 1e-9 * (x + y)) return x < y ? -1 : 1;
  return p->gamma < q->gamma ? -1 : (p->gamma > q->gamma ? 1 : 0);
}

/* M_V (x) I_4 as an AIJ matrix with X's pattern (so MatAXPY keeps the pattern) and as a vector */
static PetscErrorCode MassMatrix(CSSpin s, Vec x, Mat X, Vec m4, Mat *M)
{
  const PetscScalar *m;
  PetscScalar       *a;
  PetscInt           n;
  PetscFunctionBeginUser;
  if (!s->mass) PetscCall(DMCreateGlobalVector(s->mesh->dmV1, &s->mass));
  PetscCall(CSGeometryVertexAreas(s->mesh, x, s->mass));
  PetscCall(VecGetLocalSize(s->mass, &n));
  PetscCall(VecGetArrayRead(s->mass, &m));
  PetscCall(VecGetArray(m4, &a));
  for (PetscInt i = 0; i < n; i++)
    for (int c = 0; c < 4; c++) a[4 * i + c] = m[i];
  PetscCall(VecRestoreArray(m4, &a));
  PetscCall(VecRestoreArrayRead(s->mass, &m));
  PetscCall(MatDuplicate(X, MAT_DO_NOT_COPY_VALUES, M));
  PetscCall(MatZeroEntries(*M));
  PetscCall(MatDiagonalSet(*M, m4, INSERT_VALUES));
  PetscFunctionReturn(0);
}

/* suffix: "kernel_" or "signed_" after the object's prefix */
static PetscErrorCode CreateEPS(CSSpin s, const char suffix[], Mat A, Mat B, PetscInt nev, EPS *eps)
{
  ST   st;
  KSP  ksp;
  PC   pc;
  char prefix[256];
  PetscFunctionBeginUser;
  PetscCall(CSSpinSubPrefix(s, suffix, prefix, sizeof(prefix)));
  PetscCall(EPSCreate(s->mesh->comm, eps));
  PetscCall(EPSSetOptionsPrefix(*eps, prefix));
  PetscCall(EPSSetOperators(*eps, A, B));
  PetscCall(EPSSetProblemType(*eps, EPS_GHEP));
  PetscCall(EPSSetDimensions(*eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
  PetscCall(EPSSetTolerances(*eps, 1e-10, PETSC_DEFAULT));
  PetscCall(EPSGetST(*eps, &st));
  PetscCall(STGetKSP(st, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(CSSetDefaultCholesky(pc)); /* the factored matrix (X - sigma M or X + eps M) is real SPD */
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckConverged(CSSpin s, EPS eps, PetscInt need, PetscInt *nconv)
{
  EPSConvergedReason reason;
  PetscInt           its;
  const char        *prefix;
  PetscFunctionBeginUser;
  PetscCall(EPSGetOptionsPrefix(eps, &prefix));
  PetscCall(EPSGetConverged(eps, nconv));
  PetscCall(EPSGetConvergedReason(eps, &reason));
  PetscCall(EPSGetIterationNumber(eps, &its));
  PetscCheck(*nconv >= need, s->mesh->comm, PETSC_ERR_NOT_CONVERGED, "spectrum: %" PetscInt_FMT " of %" PetscInt_FMT " eigenpairs converged after %" PetscInt_FMT " iterations (reason %s; -%seps_max_it, -%seps_ncv)", *nconv, need, its, EPSConvergedReasons[reason], prefix, prefix);
  s->eps_its += its;
  PetscFunctionReturn(0);
}

/* Step 1: ker A from X lam = mu M lam; the eigenpairs with mu (4 pi / area)^-1 < 1e-6 (the first nonzero
   eigenvalue of a unit sphere is 1). */
static PetscErrorCode KernelSolve(CSSpin s, Mat X, Mat M, PetscReal unit, EPS *eps, PetscInt *nker)
{
  PetscInt nconv;
  PetscFunctionBeginUser;
  PetscCall(CreateEPS(s, "kernel_", X, M, 8, eps));
  PetscCall(EPSSetWhichEigenpairs(*eps, EPS_TARGET_MAGNITUDE));
  PetscCall(EPSSetTarget(*eps, -s->target * unit));
  {
    ST st;
    PetscCall(EPSGetST(*eps, &st));
    PetscCall(STSetType(st, STSINVERT));
  }
  PetscCall(EPSSetFromOptions(*eps));
  PetscCall(EPSSolve(*eps));
  PetscCall(CheckConverged(s, *eps, 8, &nconv));
  *nker = 0;
  for (PetscInt i = 0; i < nconv; i++) {
    PetscScalar kr;
    PetscCall(EPSGetEigenvalue(*eps, i, &kr, NULL));
    if (PetscAbsReal(PetscRealPart(kr)) < 1e-6 * unit) (*nker)++;
  }
  PetscCheck(*nker < nconv, s->mesh->comm, PETSC_ERR_NOT_CONVERGED, "spectrum: the kernel of the Dirac operator has %" PetscInt_FMT " or more dimensions; raise -%skernel_eps_nev", nconv, s->hdr.prefix);
  PetscFunctionReturn(0);
}

/* The smallest |theta| among the want largest: the end of the requested range */
static PetscReal RangeEnd(PetscInt n, const PetscReal theta[], PetscInt want)
{
  PetscReal end = PETSC_MAX_REAL;
  for (PetscInt k = 0; k < want && k < n; k++) { /* want passes of a selection: n is small (nev + a margin) */
    PetscReal best = -1;
    for (PetscInt i = 0; i < n; i++)
      if (PetscAbsReal(theta[i]) < end && PetscAbsReal(theta[i]) > best) best = PetscAbsReal(theta[i]);
    if (best < 0) break;
    end = best;
  }
  return end;
}

/* Appends the converged pairs of eps with |theta| >= tmin (all with tmin = 0) to (theta, V), growing the arrays. */
static PetscErrorCode TakePairs(EPS eps, PetscInt nconv, PetscReal tmin, PetscInt *n, PetscInt *cap, PetscReal **theta, Vec **V, PetscInt *taken)
{
  PetscFunctionBeginUser;
  *taken = 0;
  for (PetscInt i = 0; i < nconv; i++) {
    PetscScalar th;
    PetscCall(EPSGetEigenvalue(eps, i, &th, NULL));
    if (PetscAbsReal(PetscRealPart(th)) < tmin) continue;
    if (*n == *cap) {
      *cap = 2 * *cap + 8;
      PetscCall(PetscRealloc(sizeof(PetscReal) * (size_t)*cap, theta));
      PetscCall(PetscRealloc(sizeof(Vec) * (size_t)*cap, V));
    }
    (*theta)[*n] = PetscRealPart(th);
    {
      Mat A;
      PetscCall(EPSGetOperators(eps, &A, NULL));
      PetscCall(MatCreateVecs(A, &(*V)[*n], NULL));
    }
    PetscCall(EPSGetEigenvector(eps, i, (*V)[*n], NULL));
    (*n)++;
    (*taken)++;
  }
  PetscFunctionReturn(0);
}

/* Step 2 with its completion. Krylov-Schur sees the copies of a multiple eigenvalue only through round-off, and can
   converge the requested number of pairs before it has them all: on the level-3 unit icosphere with one BLAS thread
   it returned 10 of the 12 copies of n = 2 and put 3.071 (n = 3) in the place of the other two, silently. So the
   pairs found are completed: the problem is solved again on the X-orthogonal complement of the pairs found
   (EPSSetDeflationSpace; the pencil's eigenvectors are X-orthogonal) and what it finds at or beyond the end of the
   requested range (the smallest kept |theta|) is added, until a solve adds nothing (at most 8 rounds). A missed
   copy of a cluster in the range has |theta| at or beyond that end, so none stays missing. */
static PetscErrorCode SignedSolve(CSSpin s, Mat Y, Mat X, PetscInt want, PetscInt nker, PetscInt *n, PetscReal **theta, Vec **V)
{
  EPS      es;
  PetscInt nconv, cap = 0, taken, round;
  PetscFunctionBeginUser;
  *n = 0;
  *theta = NULL;
  *V = NULL;
  PetscCall(CreateEPS(s, "signed_", Y, X, PetscMin(want + PetscMax(8, want / 4), 4 * s->mesh->Nv - nker - 1), &es));
  PetscCall(EPSSetWhichEigenpairs(es, EPS_LARGEST_MAGNITUDE));
  PetscCall(EPSSetFromOptions(es));
  PetscCall(EPSSolve(es));
  PetscCall(CheckConverged(s, es, want, &nconv));
  PetscCall(TakePairs(es, nconv, 0, n, &cap, theta, V, &taken));
  PetscCall(EPSDestroy(&es));
  for (round = 0; round < 8; round++) {
    PetscReal end = RangeEnd(*n, *theta, want);
    if (*n + 8 >= 4 * s->mesh->Nv - nker - 1) break; /* nothing left to deflate into */
    PetscCall(CreateEPS(s, "signed_", Y, X, 8, &es));
    PetscCall(EPSSetWhichEigenpairs(es, EPS_LARGEST_MAGNITUDE));
    PetscCall(EPSSetDeflationSpace(es, *n, *V));
    PetscCall(EPSSetFromOptions(es));
    PetscCall(EPSSetDimensions(es, 8, PETSC_DEFAULT, PETSC_DEFAULT)); /* after the options: -eps_nev is the first solve's */
    PetscCall(EPSSolve(es));
    PetscCall(CheckConverged(s, es, 1, &nconv));
    PetscCall(TakePairs(es, nconv, end * (1 - 1e-6), n, &cap, theta, V, &taken));
    PetscCall(EPSDestroy(&es));
    if (!taken) break;
    PetscCall(PetscInfo(NULL, "spectrum: completion round %" PetscInt_FMT " added %" PetscInt_FMT " pairs at |theta| >= %g\n", round + 1, taken, (double)end));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSpectrumSigned(CSSpin s, Vec x, PetscInt nev, PetscReal eig[], PetscInt nvec, Vec vecs[], PetscInt *nkernel)
{
  Mat         X, Y, M;
  Vec         m4;
  EPS         ek;
  PetscReal   area, unit, *theta;
  PetscInt    nker = 0, nconv, want;
  Vec        *V;
  SignedPair *all;
  PetscFunctionBeginUser;
  PetscCheck(nvec <= nev, s->mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "spectrum: %" PetscInt_FMT " eigenvectors wanted of %" PetscInt_FMT " eigenpairs", nvec, nev);
  PetscCall(CSDiracAssemble(s->mesh, s->dm, x, CS_RHO_NONE, NULL, MAT_INITIAL_MATRIX, &X));
  PetscCall(CSDiracAssembleBA(s->mesh, s->dm, x, CS_RHO_NONE, NULL, MAT_INITIAL_MATRIX, &Y));
  PetscCall(MatSetOption(X, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(Y, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatCreateVecs(X, &m4, NULL));
  PetscCall(MassMatrix(s, x, X, m4, &M));
  PetscCall(VecSum(s->mass, &area));
  unit       = 4 * PETSC_PI / area; /* gamma^2 of n = 1 on a sphere of this area */
  s->eps_its = 0;
  PetscCall(KernelSolve(s, X, M, unit, &ek, &nker));
  /* step 2 on X + eps M; Krylov methods can miss copies of a multiple eigenvalue at the end of the range */
  PetscCall(MatAXPY(X, 1e-10 * unit, M, SAME_NONZERO_PATTERN));
  want = PetscMax(nev - nker, 1);
  PetscCall(SignedSolve(s, Y, X, want, nker, &nconv, &theta, &V));
  PetscCall(PetscMalloc1(nker + nconv, &all));
  for (PetscInt i = 0; i < nker; i++) all[i] = (SignedPair){0, 0, i};
  for (PetscInt i = 0; i < nconv; i++) all[nker + i] = (SignedPair){1 / theta[i], 1, i};
  qsort(all, (size_t)(nker + nconv), sizeof(SignedPair), CompareAbs);
  PetscCheck(nker + nconv >= nev, s->mesh->comm, PETSC_ERR_NOT_CONVERGED, "spectrum: only %" PetscInt_FMT " eigenpairs", nker + nconv);
  for (PetscInt i = 0; i < nev; i++) eig[i] = all[i].gamma;
  for (PetscInt i = 0; i < nvec; i++) {
    PetscCall(DMCreateGlobalVector(s->dm, &vecs[i]));
    if (all[i].src) PetscCall(VecCopy(V[all[i].idx], vecs[i]));
    else PetscCall(EPSGetEigenvector(ek, all[i].idx, vecs[i], NULL));
  }
  *nkernel = nker;
  PetscCall(PetscFree(all));
  PetscCall(EPSDestroy(&ek));
  for (PetscInt i = 0; i < nconv; i++) PetscCall(VecDestroy(&V[i]));
  PetscCall(PetscFree(V));
  PetscCall(PetscFree(theta));
  PetscCall(MatDestroy(&X));
  PetscCall(MatDestroy(&Y));
  PetscCall(MatDestroy(&M));
  PetscCall(VecDestroy(&m4));
  PetscFunctionReturn(0);
}

/* Sec. 6.2: "we must remove the constant component from each eigenvector, since constant solutions are in the
   null space of the system": lam <- lam - (sum M_i lam_i) / (sum M_i). A kernel vector (the ground state) is
   itself constant and is kept (its sphere is the input up to a similarity). */
static PetscErrorCode RemoveConstant(CSSpin s, Vec lambda)
{
  const PetscScalar *m;
  PetscScalar       *l;
  PetscReal          mean[5] = {0, 0, 0, 0, 0};
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(s->mass, &n));
  PetscCall(VecGetArrayRead(s->mass, &m));
  PetscCall(VecGetArray(lambda, &l));
  for (PetscInt i = 0; i < n; i++) {
    for (int c = 0; c < 4; c++) mean[c] += PetscRealPart(m[i] * l[4 * i + c]);
    mean[4] += PetscRealPart(m[i]);
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, mean, 5, MPIU_REAL, MPIU_SUM, s->mesh->comm));
  for (PetscInt i = 0; i < n; i++)
    for (int c = 0; c < 4; c++) l[4 * i + c] -= mean[c] / mean[4];
  PetscCall(VecRestoreArray(lambda, &l));
  PetscCall(VecRestoreArrayRead(s->mass, &m));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinDiracSphere(CSSpin s, Vec x, Vec lambda, PetscBool kernel, Vec xnew)
{
  PetscFunctionBeginUser;
  if (!s->mass) PetscCall(DMCreateGlobalVector(s->mesh->dmV1, &s->mass));
  PetscCall(CSGeometryVertexAreas(s->mesh, x, s->mass));
  if (!kernel) PetscCall(RemoveConstant(s, lambda));
  PetscCall(CSSpinNormalize(s, lambda, NULL, PETSC_TRUE));
  PetscCall(CSSpinReconstruct(s, x, lambda, x, xnew));
  PetscCall(CSSpinRestoreArea(s, x, xnew));
  PetscFunctionReturn(0);
}
