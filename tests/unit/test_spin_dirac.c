/* Unit checks of the quaternion kernels and the Dirac operators (crane2011 Sec. 5, crane2013 App. G):
   block = Hamilton product, block^T = conjugate; AIJ X == shell X == A^T M_F A (to round-off), X symmetric,
   Y = B^T M_F A, constants in the kernel of X for rho = 0. Exit status = number of failures.
   Run: build/tests/test_spin_dirac [-gen_level 2]   (also under mpirun -n 2) */
#include <slepcsys.h>
#include "cs_methods_spin.h"
#include "cs_quaternion_cholesky.h"
#include "cs_linalg.h"
#include "cs_package.h"
#include "cs_test.h"

static PetscErrorCode Check(MPI_Comm comm, const char what[], PetscReal err, PetscReal tol)
{
  PetscFunctionBeginUser;
  if (!(err <= tol)) cs_test_failures++;
  PetscCall(PetscPrintf(comm, "%s %-60s err %.3e (tol %.1e)\n", err <= tol ? "ok  " : "BAD ", what, (double)err, (double)tol));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckQuaternions(MPI_Comm comm)
{
  PetscRandom r;
  PetscReal   e1 = 0, e2 = 0, e3 = 0, e4 = 0;
  PetscFunctionBeginUser;
  PetscCall(CSTestRandom(PETSC_COMM_SELF, -1, 1, 7, &r));
  for (int t = 0; t < 50; t++) {
    PetscReal   p[4], q[4], pq[4], cq[4], cpq[4], n[4], R[9], u[4];
    PetscScalar B[16], Bc[16];
    for (int c = 0; c < 4; c++) PetscCall(PetscRandomGetValueReal(r, &p[c]));
    for (int c = 0; c < 4; c++) PetscCall(PetscRandomGetValueReal(r, &q[c]));
    CSQuatMul(q, p, pq);
    CSQuatBlock(q, B);
    for (int s = 0; s < 4; s++) {
      PetscReal v = 0;
      for (int t2 = 0; t2 < 4; t2++) v += PetscRealPart(B[4 * s + t2]) * p[t2];
      e1 = PetscMax(e1, PetscAbsReal(v - pq[s]));
    }
    CSQuatConj(q, cq);
    CSQuatBlock(cq, Bc);
    for (int s = 0; s < 4; s++)
      for (int t2 = 0; t2 < 4; t2++) e2 = PetscMax(e2, PetscAbsScalar(B[4 * s + t2] - Bc[4 * t2 + s]));
    CSQuatConjMul(q, p, cpq);
    CSQuatMul(cq, p, pq);
    for (int c = 0; c < 4; c++) e3 = PetscMax(e3, PetscAbsReal(cpq[c] - pq[c]));
    /* rotation matrix of a unit quaternion and back (up to sign) */
    {
      PetscReal nn = PetscSqrtReal(CSQuatNorm2(q)), w, x, y, z, d1 = 0, d2 = 0;
      for (int c = 0; c < 4; c++) n[c] = q[c] / nn;
      w    = n[0];
      x    = n[1];
      y    = n[2];
      z    = n[3];
      R[0] = 1 - 2 * (y * y + z * z);
      R[1] = 2 * (x * y - w * z);
      R[2] = 2 * (x * z + w * y);
      R[3] = 2 * (x * y + w * z);
      R[4] = 1 - 2 * (x * x + z * z);
      R[5] = 2 * (y * z - w * x);
      R[6] = 2 * (x * z - w * y);
      R[7] = 2 * (y * z + w * x);
      R[8] = 1 - 2 * (x * x + y * y);
      CSQuatFromRotation(R, u);
      for (int c = 0; c < 4; c++) {
        d1 = PetscMax(d1, PetscAbsReal(u[c] - n[c]));
        d2 = PetscMax(d2, PetscAbsReal(u[c] + n[c]));
      }
      e4 = PetscMax(e4, PetscMin(d1, d2));
      /* conj(n) v n rotates by R^T: check on a vector */
      {
        PetscReal v[3] = {p[1], p[2], p[3]}, rv[3];
        CSQuatSandwich(n, v, rv);
        for (int d = 0; d < 3; d++) e4 = PetscMax(e4, PetscAbsReal(rv[d] - (R[d] * v[0] + R[3 + d] * v[1] + R[6 + d] * v[2])));
      }
    }
  }
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(Check(comm, "4x4 block of q times p == Hamilton product q p", e1, 1e-14));
  PetscCall(Check(comm, "block(q)^T == block(conj q)", e2, 0));
  PetscCall(Check(comm, "CSQuatConjMul == conj then multiply", e3, 1e-14));
  PetscCall(Check(comm, "rotation <-> quaternion, conj(q) v q == R^T v", e4, 1e-13));
  PetscFunctionReturn(0);
}

/* crane2013 App. G printed formula X_ij = -e_i e_j/(4A) + (rho_i e_j - rho_j e_i)/6 + A rho_i rho_j/9 against
   the face kernel A conj(a_i) a_j used by the code (a_j = -e_j/(2A) - rho_j/3). */
static PetscErrorCode CheckAppendixG(MPI_Comm comm)
{
  PetscReal   err = 0;
  PetscRandom r;
  PetscFunctionBeginUser;
  PetscCall(CSTestRandom(PETSC_COMM_SELF, -1, 1, 5, &r));
  for (int t = 0; t < 20; t++) {
    PetscReal P[3][3], rho[3], e[3][4], an[3], A;
    for (int k = 0; k < 3; k++) {
      for (int d = 0; d < 3; d++) PetscCall(PetscRandomGetValueReal(r, &P[k][d]));
      PetscCall(PetscRandomGetValueReal(r, &rho[k]));
    }
    {
      const PetscReal *c[3] = {P[0], P[1], P[2]};
      CSTriangleAreaVector(c, an);
      A = CSVecNorm(an);
    }
    for (int j = 0; j < 3; j++) {
      e[j][0] = 0;
      for (int d = 0; d < 3; d++) e[j][d + 1] = P[(j + 2) % 3][d] - P[(j + 1) % 3][d];
    }
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        PetscReal ai[4], aj[4], x[4], ee[4], g[4];
        for (int c = 0; c < 4; c++) {
          ai[c] = -e[i][c] / (2 * A);
          aj[c] = -e[j][c] / (2 * A);
        }
        ai[0] -= rho[i] / 3;
        aj[0] -= rho[j] / 3;
        CSQuatConjMul(ai, aj, x);
        CSQuatMul(e[i], e[j], ee);
        for (int c = 0; c < 4; c++) g[c] = -ee[c] / (4 * A) + (rho[i] * e[j][c] - rho[j] * e[i][c]) / 6;
        g[0] += A * rho[i] * rho[j] / 9;
        for (int c = 0; c < 4; c++) err = PetscMax(err, PetscAbsReal(A * x[c] - g[c]));
      }
  }
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(Check(comm, "crane2013 App. G closed form == A conj(a_i) a_j", err, 1e-13));
  PetscFunctionReturn(0);
}

static PetscErrorCode RelDiff(Vec a, Vec b, PetscReal *err)
{
  Vec       d;
  PetscReal na, nd;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(a, &d));
  PetscCall(VecWAXPY(d, -1, b, a));
  PetscCall(VecNorm(d, NORM_INFINITY, &nd));
  PetscCall(VecNorm(a, NORM_INFINITY, &na));
  *err = nd / PetscMax(na, PETSC_SMALL);
  PetscCall(VecDestroy(&d));
  PetscFunctionReturn(0);
}

/* A SeqAIJ quaternionic matrix of n vertices from blocks (i, j, q): the 4x4 left multiplication by q at (i, j). */
static PetscErrorCode QuatMat(PetscInt n, PetscInt nb, const PetscInt ij[][2], const PetscReal q[][4], Mat *K)
{
  PetscFunctionBeginUser;
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, 4 * n, 4 * n, 16, NULL, K));
  for (PetscInt b = 0; b < nb; b++) {
    PetscScalar B[16];
    PetscInt    rows[4], cols[4];
    CSQuatBlock(q[b], B);
    for (int c = 0; c < 4; c++) rows[c] = 4 * ij[b][0] + c, cols[c] = 4 * ij[b][1] + c;
    PetscCall(MatSetValues(*K, 4, rows, 4, cols, B, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*K, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*K, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* quaternion_cholesky.c on small hand-made matrices: a forest (two components), clear errors for a missing diagonal
   block, an unsymmetric pattern and vectors of the wrong size, and a good factorisation again after a failed one. */
static PetscErrorCode CheckQuatCholeskyInputs(void)
{
  const PetscInt  fij[8][2] = {{0, 0}, {1, 1}, {2, 2}, {3, 3}, {0, 2}, {2, 0}, {1, 3}, {3, 1}};
  const PetscReal fq[8][4]  = {{4, 0, 0, 0}, {3, 0, 0, 0}, {5, 0, 0, 0}, {2, 0, 0, 0}, {1, 0.5, -0.3, 0.2}, {1, -0.5, 0.3, -0.2}, {0.5, 0.1, 0.2, -0.4}, {0.5, -0.1, -0.2, 0.4}};
  const PetscInt  nij[3][2] = {{0, 0}, {0, 1}, {1, 0}}, uij[3][2] = {{0, 0}, {1, 1}, {0, 1}};
  const PetscReal nq[3][4]  = {{2, 0, 0, 0}, {0.3, 0.1, 0, 0}, {0.3, -0.1, 0, 0}}, uq[3][4] = {{2, 0, 0, 0}, {2, 0, 0, 0}, {0.3, 0.1, 0, 0}};
  Mat             F, N, U;
  Vec             u, y, r, w;
  CSQuatCholesky  qc;
  PetscRandom     rnd;
  PetscErrorCode  ierr;
  PetscReal       err;
  PetscFunctionBeginUser;
  PetscCall(QuatMat(4, 8, fij, fq, &F));
  PetscCall(QuatMat(2, 3, nij, nq, &N));
  PetscCall(QuatMat(2, 3, uij, uq, &U));
  PetscCall(MatCreateVecs(F, &u, &y));
  PetscCall(VecDuplicate(u, &r));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 8, &w));
  PetscCall(PetscRandomCreate(PETSC_COMM_SELF, &rnd));
  PetscCall(VecSetRandom(u, rnd));
  PetscCall(CSQuatCholeskyCreate("amd", &qc));
  for (int pass = 0; pass < 2; pass++) {
    PetscCall(CSQuatCholeskySetUp(qc, F, -0.5));
    PetscCall(CSQuatCholeskySolve(qc, u, y));
    PetscCall(MatMult(F, y, r));
    PetscCall(VecAXPY(r, 0.5, y));
    PetscCall(RelDiff(u, r, &err));
    PetscCall(Check(PETSC_COMM_SELF, pass ? "quaternion Cholesky: a forest again after a failed analysis" : "quaternion Cholesky: a forest of two components", err, 1e-14));
    if (pass) break;
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CSQuatCholeskySetUp(qc, N, -0.5);
    PetscCall(PetscPopErrorHandler());
    PetscCall(Check(PETSC_COMM_SELF, "quaternion Cholesky: no diagonal block -> ARG_WRONG", ierr == PETSC_ERR_ARG_WRONG ? 0 : 1, 0));
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CSQuatCholeskySetUp(qc, U, -0.5);
    PetscCall(PetscPopErrorHandler());
    PetscCall(Check(PETSC_COMM_SELF, "quaternion Cholesky: unsymmetric pattern -> ARG_WRONG", ierr == PETSC_ERR_ARG_WRONG ? 0 : 1, 0));
  }
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = CSQuatCholeskySolve(qc, w, y);
  PetscCall(PetscPopErrorHandler());
  PetscCall(Check(PETSC_COMM_SELF, "quaternion Cholesky: vector of the wrong size -> ARG_SIZ", ierr == PETSC_ERR_ARG_SIZ ? 0 : 1, 0));
  PetscCall(CSQuatCholeskyDestroy(&qc));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&r));
  PetscCall(VecDestroy(&w));
  PetscCall(MatDestroy(&F));
  PetscCall(MatDestroy(&N));
  PetscCall(MatDestroy(&U));
  PetscFunctionReturn(0);
}
static PetscErrorCode CheckOperators(CSMesh mesh, Vec x, CSRhoLocation loc, Vec rho, const char label[])
{
  DM          dm;
  Mat         X, S, A, B, Y;
  Vec         MF, u, y1, y2, y3, fa, fb;
  PetscRandom r;
  PetscReal   err;
  PetscBool   sym;
  char        what[128];
  PetscFunctionBeginUser;
  PetscCall(CSDiracCreateDM(mesh, NULL, &dm));
  PetscCall(CSDiracAssemble(mesh, dm, x, loc, rho, MAT_INITIAL_MATRIX, &X));
  PetscCall(CSDiracCreateShell(mesh, dm, x, loc, rho, &S));
  PetscCall(CSDiracCreateFaceOperators(mesh, dm, x, loc, rho, NULL, &B, &A, &MF));
  PetscCall(CSDiracAssembleBA(mesh, dm, x, loc, rho, MAT_INITIAL_MATRIX, &Y));
  PetscCall(DMCreateGlobalVector(dm, &u));
  PetscCall(VecDuplicate(u, &y1));
  PetscCall(VecDuplicate(u, &y2));
  PetscCall(VecDuplicate(u, &y3));
  PetscCall(MatCreateVecs(A, NULL, &fa));
  PetscCall(VecDuplicate(fa, &fb));
  PetscCall(CSTestRandom(mesh->comm, 0, 1, 11, &r));
  PetscCall(VecSetRandom(u, r));
  {
    PetscInt bs;
    PetscCall(MatGetBlockSize(X, &bs));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: AIJ block size is 4 (got %" PetscInt_FMT ")", label, bs));
    PetscCall(Check(mesh->comm, what, (PetscReal)PetscAbsInt(bs - 4), 0));
  }
  PetscCall(MatMult(X, u, y1));
  PetscCall(MatMult(S, u, y2));
  PetscCall(RelDiff(y1, y2, &err));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: shell X u == AIJ X u", label));
  PetscCall(Check(mesh->comm, what, err, 1e-12));
  PetscCall(MatGetDiagonal(X, y1));
  PetscCall(MatGetDiagonal(S, y2));
  PetscCall(RelDiff(y1, y2, &err));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: shell diag == AIJ diag", label));
  PetscCall(Check(mesh->comm, what, err, 1e-12));
  PetscCall(MatIsSymmetric(X, 1e-12, &sym));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: X symmetric", label));
  PetscCall(Check(mesh->comm, what, sym ? 0 : 1, 0));
  /* X = A^T M_F A (crane2011 Sec. 5.4 adjoint) */
  PetscCall(MatMult(X, u, y1));
  PetscCall(MatMult(A, u, fa));
  PetscCall(VecPointwiseMult(fa, fa, MF));
  PetscCall(MatMultTranspose(A, fa, y3));
  PetscCall(RelDiff(y1, y3, &err));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: X u == A^T M_F A u", label));
  PetscCall(Check(mesh->comm, what, err, 1e-12));
  /* Y = B^T M_F A */
  PetscCall(MatMult(Y, u, y1));
  PetscCall(MatMultTranspose(B, fa, y3));
  PetscCall(RelDiff(y1, y3, &err));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: Y u == B^T M_F A u", label));
  PetscCall(Check(mesh->comm, what, err, 1e-12));
  /* the complex form of cholmod_factor.c (serial): (X - sigma) y = u to round-off, sigma < 0 */
  {
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(mesh->comm, &size));
    if (size == 1) {
      CSCholmod           cf;
      PetscReal           sigma = -0.5;
      PetscCall(CSCholmodCreate("amd", &cf));
      PetscCall(CSCholmodSetUpQuaternion(cf, X, sigma));
      PetscCall(CSCholmodSolve(cf, u, y1));
      PetscCall(MatMult(X, y1, y2));
      PetscCall(VecAXPY(y2, -sigma, y1));
      PetscCall(RelDiff(u, y2, &err));
      PetscCall(PetscSNPrintf(what, sizeof(what), "%s: complex-form Cholesky solve, (X - sigma) y == u", label));
      PetscCall(Check(mesh->comm, what, err, 1e-12));
      PetscCall(CSCholmodDestroy(&cf));
      /* the quaternion-arithmetic factorisation (quaternion_cholesky.c): the same solve, twice with the kept
         symbolic phase, and a clear error when K - sigma is indefinite */
      {
        CSQuatCholesky qc;
        PetscErrorCode ierr;
        Vec            y4;
        PetscCall(VecDuplicate(u, &y4));
        PetscCall(CSQuatCholeskyCreate("amd", &qc));
        for (int pass = 0; pass < 2; pass++) {
          const PetscReal sg = pass ? -2.0 : sigma;
          PetscCall(CSQuatCholeskySetUp(qc, X, sg));
          PetscCall(CSQuatCholeskySolve(qc, u, y4));
          PetscCall(MatMult(X, y4, y2));
          PetscCall(VecAXPY(y2, -sg, y4));
          PetscCall(RelDiff(u, y2, &err));
          PetscCall(PetscSNPrintf(what, sizeof(what), "%s: quaternion Cholesky solve (sigma %g), (X - sigma) y == u", label, (double)sg));
          PetscCall(Check(mesh->comm, what, err, 1e-12));
          if (!pass) {
            PetscCall(RelDiff(y1, y4, &err));
            PetscCall(PetscSNPrintf(what, sizeof(what), "%s: quaternion Cholesky == complex-form Cholesky", label));
            PetscCall(Check(mesh->comm, what, err, 1e-12));
          }
        }
        PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
        ierr = CSQuatCholeskySetUp(qc, X, 1e3);
        PetscCall(PetscPopErrorHandler());
        PetscCall(PetscSNPrintf(what, sizeof(what), "%s: quaternion Cholesky of an indefinite X - sigma fails with ZRPVT", label));
        PetscCall(Check(mesh->comm, what, ierr == PETSC_ERR_MAT_CH_ZRPVT ? 0 : 1, 0));
        PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
        ierr = CSQuatCholeskySolve(qc, u, y4);
        PetscCall(PetscPopErrorHandler());
        PetscCall(PetscSNPrintf(what, sizeof(what), "%s: no solve after a failed factorisation", label));
        PetscCall(Check(mesh->comm, what, ierr == PETSC_ERR_ORDER ? 0 : 1, 0));
        PetscCall(CSQuatCholeskyDestroy(&qc));
        PetscCall(VecDestroy(&y4));
      }
      /* the same factorisations as PETSc MatSolverTypes (quaternion_factor.c): PCCHOLESKY on X - sigma I */
      for (int t = 0; t < 2; t++) {
        const char *type = t ? MATSOLVERCSCHOLMOD : MATSOLVERCSQUAT;
        KSP         ksp;
        PC          pc;
        Mat         Xs;
        Vec         y5;
        PetscCall(VecDuplicate(u, &y5));
        PetscCall(MatDuplicate(X, MAT_COPY_VALUES, &Xs));
        PetscCall(MatShift(Xs, -sigma));
        PetscCall(KSPCreate(mesh->comm, &ksp));
        PetscCall(KSPSetType(ksp, KSPPREONLY));
        PetscCall(KSPGetPC(ksp, &pc));
        PetscCall(PCSetType(pc, PCCHOLESKY));
        PetscCall(PCFactorSetMatSolverType(pc, type));
        PetscCall(KSPSetOperators(ksp, Xs, Xs));
        PetscCall(KSPSolve(ksp, u, y5));
        PetscCall(RelDiff(y1, y5, &err));
        PetscCall(PetscSNPrintf(what, sizeof(what), "%s: -pc_factor_mat_solver_type %s == complex-form Cholesky", label, type));
        PetscCall(Check(mesh->comm, what, err, 1e-12));
        PetscCall(KSPDestroy(&ksp));
        PetscCall(MatDestroy(&Xs));
        PetscCall(VecDestroy(&y5));
      }
    }
  }
  /* kernel: for rho = 0 every constant quaternion field is in ker D and ker X */
  if (!rho) {
    PetscScalar *ua;
    PetscInt     n;
    PetscReal    nx, nu;
    PetscCall(VecGetLocalSize(u, &n));
    PetscCall(VecGetArray(u, &ua));
    for (PetscInt i = 0; i < n; i += 4) {
      ua[i]     = 0.3;
      ua[i + 1] = -1.1;
      ua[i + 2] = 0.7;
      ua[i + 3] = 2.0;
    }
    PetscCall(VecRestoreArray(u, &ua));
    PetscCall(MatMult(X, u, y1));
    PetscCall(MatMult(S, u, y2));
    PetscCall(VecNorm(y1, NORM_INFINITY, &nx));
    PetscCall(MatMult(A, u, fa));
    PetscCall(VecNorm(fa, NORM_INFINITY, &nu));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: X const == 0 and D const == 0", label));
    PetscCall(Check(mesh->comm, what, PetscMax(nx, nu), 1e-12));
  }
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&y1));
  PetscCall(VecDestroy(&y2));
  PetscCall(VecDestroy(&y3));
  PetscCall(VecDestroy(&fa));
  PetscCall(VecDestroy(&fb));
  PetscCall(VecDestroy(&MF));
  PetscCall(MatDestroy(&X));
  PetscCall(MatDestroy(&S));
  PetscCall(MatDestroy(&A));
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(&Y));
  PetscCall(DMDestroy(&dm));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  CSMesh      mesh;
  Vec         x, rv, rf, d;
  PetscRandom r;
  MPI_Comm    comm;
  PetscCall(SlepcInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CSInitializePackage());
  comm = PETSC_COMM_WORLD;
  PetscCall(PetscOptionsSetValue(NULL, "-gen", "icosphere"));
  {
    PetscBool has;
    PetscCall(PetscOptionsHasName(NULL, NULL, "-gen_level", &has));
    if (!has) PetscCall(PetscOptionsSetValue(NULL, "-gen_level", "2"));
  }
  PetscCall(CheckQuaternions(comm));
  PetscCall(CheckAppendixG(comm));
  {
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(comm, &size));
    if (size == 1) PetscCall(CheckQuatCholeskyInputs());
  }
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  /* a generic (non-round) surface: perturb the positions */
  PetscCall(CSTestRandom(comm, -0.05, 0.05, 3, &r));
  PetscCall(VecDuplicate(mesh->x, &x));
  PetscCall(VecDuplicate(mesh->x, &d));
  PetscCall(VecSetRandom(d, r));
  PetscCall(VecWAXPY(x, 1, d, mesh->x));
  PetscCall(PetscRandomSetInterval(r, -2, 2));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &rv));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &rf));
  PetscCall(VecSetRandom(rv, r));
  PetscCall(VecSetRandom(rf, r));
  PetscCall(CheckOperators(mesh, x, CS_RHO_NONE, NULL, "rho=0"));
  PetscCall(CheckOperators(mesh, x, CS_RHO_VERTEX, rv, "rho per vertex"));
  PetscCall(CheckOperators(mesh, x, CS_RHO_FACE, rf, "rho per face"));
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&rv));
  PetscCall(VecDestroy(&rf));
  PetscCall(CSMeshDestroy(&mesh));
  return CSTestFinalize(comm, SlepcFinalize);
}
