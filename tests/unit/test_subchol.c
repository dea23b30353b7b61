static const char help[] = "Checks of the substructured CHOLMOD Cholesky (PC cssubchol, issue 3) on a matrix shaped like the\n"
                           "flow's Schur complement: 3 dofs per node of an n x n grid, two-ring couplings,\n"
                           "S = (L L + eps I) (x) K with the 5-point Laplacian L (Dirichlet) and K = tridiag(1,2,1) (3x3).\n"
                           "Relative residual of a direct solve (KSP preonly), after new values on the same pattern\n"
                           "(numeric phase only), with the AMD and NESDIS interior orderings; the interface size;\n"
                           "an indefinite matrix stops the KSP with DIVERGED_PC_FAILED on every rank (no error, no hang).\n"
                           "Exit status = number of failed checks.\n";

#include "cs_substructured_cholesky.h"
#include "cs_package.h"
#include "cs_test.h"

/* S = (L L + eps I) (x) K (ring 2) or (L + eps I) (x) K (ring 1), K = tridiag(1,2,1) of size dof (1 or 3). The
   n^2 nodes are distributed by PETSc's default layout, or (last_empty, several ranks) over all ranks but the
   last, which owns no rows. */
static PetscErrorCode BuildMatrix(MPI_Comm comm, PetscInt n, PetscReal eps, PetscInt ring, PetscInt dof, PetscBool last_empty, Mat *S)
{
  Mat         L, LL;
  PetscInt    rs, re, nloc = PETSC_DECIDE;
  PetscMPIInt size, rank;
  const PetscReal K3[3][3] = {{2, 1, 0}, {1, 2, 1}, {0, 1, 2}};
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (last_empty && size > 1) nloc = rank == size - 1 ? 0 : n * n / (size - 1) + (rank < (n * n) % (size - 1) ? 1 : 0);
  PetscCall(MatCreateAIJ(comm, nloc, nloc, n * n, n * n, 5, NULL, 4, NULL, &L));
  PetscCall(MatGetOwnershipRange(L, &rs, &re));
  for (PetscInt r = rs; r < re; r++) {
    PetscInt i = r / n, j = r % n;
    PetscCall(MatSetValue(L, r, r, 4.0, INSERT_VALUES));
    if (i > 0) PetscCall(MatSetValue(L, r, r - n, -1.0, INSERT_VALUES));
    if (i < n - 1) PetscCall(MatSetValue(L, r, r + n, -1.0, INSERT_VALUES));
    if (j > 0) PetscCall(MatSetValue(L, r, r - 1, -1.0, INSERT_VALUES));
    if (j < n - 1) PetscCall(MatSetValue(L, r, r + 1, -1.0, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(L, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(L, MAT_FINAL_ASSEMBLY));
  if (ring == 2) PetscCall(MatMatMult(L, L, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &LL));
  else PetscCall(MatDuplicate(L, MAT_COPY_VALUES, &LL));
  PetscCall(MatShift(LL, eps));
  PetscCall(MatCreateAIJ(comm, dof * (re - rs), dof * (re - rs), PETSC_DETERMINE, PETSC_DETERMINE, 39, NULL, 39, NULL, S));
  for (PetscInt r = rs; r < re; r++) {
    PetscInt           nc;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(LL, r, &nc, &cols, &vals));
    for (PetscInt k = 0; k < nc; k++)
      for (PetscInt a = 0; a < dof; a++)
        for (PetscInt b = 0; b < dof; b++) {
          PetscReal kab = dof == 3 ? K3[a][b] : 1.0;
          if (kab != 0) PetscCall(MatSetValue(*S, dof * r + a, dof * cols[k] + b, vals[k] * kab, INSERT_VALUES));
        }
    PetscCall(MatRestoreRow(LL, r, &nc, &cols, &vals));
  }
  PetscCall(MatAssemblyBegin(*S, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*S, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(*S, MAT_SPD, PETSC_TRUE));
  PetscCall(MatDestroy(&L));
  PetscCall(MatDestroy(&LL));
  PetscFunctionReturn(0);
}

/* |S x - b| / |b| after a preonly solve with the PC as it stands */
static PetscErrorCode Residual(KSP ksp, Mat S, Vec b, PetscReal *rel, KSPConvergedReason *reason)
{
  Vec       x, r;
  PetscReal nb, nr;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(b, &x));
  PetscCall(VecDuplicate(b, &r));
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPGetConvergedReason(ksp, reason));
  PetscCall(MatMult(S, x, r));
  PetscCall(VecAXPY(r, -1.0, b));
  PetscCall(VecNorm(r, NORM_2, &nr));
  PetscCall(VecNorm(b, NORM_2, &nb));
  *rel = nr / nb;
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(0);
}

/* A fresh preonly KSP with PC cssubchol (option -<prefix>_pc_cssubchol_<option> value, when given) solves
   S x = b; the check passes when |Sx - b|/|b| < 1e-11 and the solve converged */
static PetscErrorCode CheckFreshSolve(MPI_Comm comm, Mat S, Vec b, const char prefix[], const char option[], const char value[], const char what[])
{
  KSP                ksp;
  PC                 pc;
  PetscReal          rel;
  KSPConvergedReason reason;
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, "cssubchol"));
  if (option) {
    char name[64], pre[32];
    PetscCall(PetscSNPrintf(pre, sizeof(pre), "%s_", prefix));
    PetscCall(KSPSetOptionsPrefix(ksp, pre));
    PetscCall(PetscSNPrintf(name, sizeof(name), "-%s_pc_cssubchol_%s", prefix, option));
    PetscCall(PetscOptionsSetValue(NULL, name, value));
  }
  PetscCall(KSPSetOperators(ksp, S, S));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(Residual(ksp, S, b, &rel, &reason));
  PetscCall(CSTestCheck(comm, (PetscBool)(rel < 1e-11 && reason > 0), what, rel, 1e-11));
  PetscCall(KSPDestroy(&ksp));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm           comm;
  PetscMPIInt        size;
  Mat                S;
  Vec                b;
  KSP                ksp;
  PC                 pc;
  PetscRandom        rnd;
  PetscReal          rel;
  PetscInt           G, n = 40, nfact;
  KSPConvergedReason reason;
  const char        *orderings[] = {"amd", "nesdis"}, *sides[] = {"lower", "upper"};
  char               what[128];

  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  comm = PETSC_COMM_WORLD;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(CSInitializePackage());
  PetscCall(BuildMatrix(comm, n, 1e-3, 2, 3, PETSC_FALSE, &S));
  PetscCall(MatCreateVecs(S, &b, NULL));
  PetscCall(CSTestRandom(comm, 0, 1, 7, &rnd));
  PetscCall(VecSetRandom(b, rnd));

  PetscCall(KSPCreate(comm, &ksp));
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, "cssubchol"));
  PetscCall(KSPSetOperators(ksp, S, S));
  PetscCall(KSPSetFromOptions(ksp));
  PetscCall(Residual(ksp, S, b, &rel, &reason));
  PetscCall(CSTestCheck(comm, (PetscBool)(rel < 1e-11 && reason > 0), "direct solve, METIS interior: |Sx - b|/|b|", rel, 1e-11));
  PetscCall(CSSubCholGetInfo(pc, &G, &nfact));
  /* two grid rows of nodes (3 dofs each) per cut between consecutive ranks */
  PetscCall(CSTestCheck(comm, (PetscBool)(size == 1 ? G == 0 : (G >= 3 * 2 * n && G <= (size - 1) * 3 * 2 * n + 3 * 2 * n)), "interface dofs (0 on one rank, about 6n per cut)", (PetscReal)G, (PetscReal)(size - 1) * 6 * n));

  PetscCall(CSTestCheck(comm, (PetscBool)(nfact == 1), "factorisations after one solve", (PetscReal)nfact, 1));

  /* new values, same pattern: the numeric phase alone */
  PetscCall(MatScale(S, 2.0));
  PetscCall(MatShift(S, 0.5));
  PetscCall(KSPSetOperators(ksp, S, S));
  PetscCall(Residual(ksp, S, b, &rel, &reason));
  PetscCall(CSTestCheck(comm, (PetscBool)(rel < 1e-11 && reason > 0), "refactorisation with new values: |Sx - b|/|b|", rel, 1e-11));

  for (int o = 0; o < 2; o++) {
    PetscCall(PetscSNPrintf(what, sizeof(what), "direct solve, %s interior: |Sx - b|/|b|", orderings[o]));
    PetscCall(CheckFreshSolve(comm, S, b, orderings[o], "ordering", orderings[o], what));
  }
  for (int o = 0; o < 2; o++) { /* the interface on either side of each cut */
    PetscCall(PetscSNPrintf(what, sizeof(what), "interface on the %s side: |Sx - b|/|b|", sides[o]));
    PetscCall(CheckFreshSolve(comm, S, b, sides[o], "interface", sides[o], what));
  }

  /* other shapes: a one-ring scalar matrix on a small grid (CHOLMOD's postorder may put interface columns before
     interior ones there), and a last rank that owns no rows */
  {
    struct {
      PetscInt    n, ring, dof;
      PetscBool   empty;
      const char *label;
    } cases[] = {
      {5,  1, 1, PETSC_FALSE, "one-ring, 1 dof, 5 x 5 grid"},
      {3,  1, 3, PETSC_FALSE, "one-ring, 3 dofs, 3 x 3 grid"},
      {12, 2, 3, PETSC_TRUE,  "two-ring, 3 dofs, last rank without rows"},
    };
    for (size_t c = 0; c < sizeof(cases) / sizeof(cases[0]); c++) {
      Mat A;
      Vec bb;
      PetscCall(BuildMatrix(comm, cases[c].n, 1e-2, cases[c].ring, cases[c].dof, cases[c].empty, &A));
      PetscCall(MatCreateVecs(A, &bb, NULL));
      PetscCall(VecSetRandom(bb, rnd));
      PetscCall(PetscSNPrintf(what, sizeof(what), "%s: |Sx - b|/|b|", cases[c].label));
      PetscCall(CheckFreshSolve(comm, A, bb, NULL, NULL, NULL, what));
      PetscCall(VecDestroy(&bb));
      PetscCall(MatDestroy(&A));
    }
  }

  /* indefinite: shift below the smallest eigenvalue of S (>= 0.5 + 2 eps) and above its largest */
  PetscCall(MatShift(S, -300.0));
  PetscCall(KSPSetOperators(ksp, S, S));
  PetscCall(Residual(ksp, S, b, &rel, &reason));
  PetscCall(CSTestCheck(comm, (PetscBool)(reason == KSP_DIVERGED_PC_FAILED), "indefinite matrix: KSP reason DIVERGED_PC_FAILED (-11)", (PetscReal)reason, (PetscReal)KSP_DIVERGED_PC_FAILED));

  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&b));
  PetscCall(MatDestroy(&S));
  PetscCall(PetscRandomDestroy(&rnd));
  return CSTestFinalize(comm, PetscFinalize);
}
