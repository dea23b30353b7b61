/* Table 1 step VII (crane2013 Sec. 5.2): the Poisson problem L f~ = b with L_ij = -1/l_ij on the edges and
   L_ii = 1/l_{i-1,i} + 1/l_{i,i+1}, the normal equations of min sum_ij |f~_j - f~_i - T~_ij|^2 / l_ij (the
   least-squares fit of Sec. 5.1 weighted by 1/l; the printed b_i = T~_{i-1,i}/l_{i-1,i} - T~_{i,i+1}/l_{i,i+1}
   is exactly its right-hand side, signs as printed). On a closed curve (and an open one) L is singular with the
   constants as null space and sum_i b_i = 0; we factor L + c e_0 e_0^T instead (c = 1/l_0, "grounding"
   vertex 0): summing its rows gives c f~_0 = sum_i b_i = 0, so its solution solves L f~ = b exactly, with
   f~_0 = f_0 for the correction form. The input lengths never change (the flow is isometric), so L and its
   factorisation are built once in CSCurveFlowSetUp and kept for every step.
   Then the mean translation and rotation of the step are removed (Sec. 5.1): the d-weighted centroid is put
   back and the best rotation about it (2D Procrustes) undone. Also the filter matrix of Sec. 4. */
#include "curve_flow_impl.h"
#include "cs_log.h"
#include "cs_operators.h"

/* L of the input lengths (with c e_0 e_0^T when ground) */
static PetscErrorCode AssembleLaplacian(CSCurveFlow F, PetscBool ground, Mat *L)
{
  CSCurve            c = F->curve;
  const PetscScalar *l;
  PetscReal          lr[4];
  PetscFunctionBeginUser;
  PetscCall(MatCreateAIJ(c->comm, c->n, c->n, c->N, c->N, 3, NULL, 2, NULL, L));
  PetscCall(CSCurveGhosts(c, F->len, lr));
  PetscCall(VecGetArrayRead(F->len, &l));
  for (PetscInt i = 0; i < c->n; i++) {
    PetscInt    gi = c->rstart + i, cols[3];
    PetscReal   a = i ? l[i - 1] : lr[0], b = l[i]; /* l_{i-1,i}, l_{i,i+1}; 0 where an open curve ends */
    PetscScalar vals[3];
    PetscInt    nc = 0;
    if (a > 0) {
      cols[nc]   = (gi - 1 + c->N) % c->N;
      vals[nc++] = -1 / a;
    }
    cols[nc]   = gi;
    vals[nc++] = (a > 0 ? 1 / a : 0) + (b > 0 ? 1 / b : 0);
    if (b > 0) {
      cols[nc]   = (gi + 1) % c->N;
      vals[nc++] = -1 / b;
    }
    if (gi == 0 && ground) vals[a > 0 ? 1 : 0] += 1 / b;
    PetscCall(MatSetValues(*L, 1, &gi, nc, cols, vals, INSERT_VALUES));
  }
  PetscCall(VecRestoreArrayRead(F->len, &l));
  PetscCall(MatAssemblyBegin(*L, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*L, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(*L, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(*L, MAT_SPD, PETSC_TRUE));
  PetscFunctionReturn(0);
}

/* Serially a direct solve: Cholesky, PETSc's own (natural ordering: the cyclic tridiagonal L fills only its
   last row). In parallel CG preconditioned by block Jacobi with an exact solve of each rank's block (ILU(0) of
   a tridiagonal block is its LU): the blocks differ from L only by the couplings across the 2P block ends,
   so the preconditioned operator is the identity plus a matrix of rank <= 2P and CG ends in <= 2P + 1
   iterations in exact arithmetic: a direct solve with O(n) work and P-sized communication per iteration.
   Measured at 2k vertices on 2 ranks (loaded machine): 0.42 ms per step, against 9-18 ms with MUMPS
   (-<prefix>poisson_ksp_type preonly -<prefix>poisson_pc_type cholesky
   -<prefix>poisson_pc_factor_mat_solver_type mumps) and 3.3 ms with SuperLU_dist, whose solves gather on the
   host. Defaults set on the KSP before KSPSetFromOptions, so -<prefix>poisson_ksp_type etc. replace them. The
   filter's KSP is made here too, but its matrix M + s L (M^-1 L)^(k-1) has a wider band: for k >= 2 the 2P + 1 bound
   does not hold and CG may need more, or fail on an ill-conditioned filter (curve_direction.c Filter checks it). */
static PetscErrorCode CreateDirectKSP(CSCurveFlow F, Mat A, const char suffix[], KSP *ksp)
{
  PC          pc;
  PetscMPIInt size;
  char        prefix[256];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(F->hdr.comm, &size));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%s%s", F->hdr.prefix, suffix));
  PetscCall(KSPCreate(F->hdr.comm, ksp));
  PetscCall(KSPSetOptionsPrefix(*ksp, prefix));
  PetscCall(KSPSetOperators(*ksp, A, A));
  PetscCall(KSPGetPC(*ksp, &pc));
  if (size == 1) {
    PetscCall(KSPSetType(*ksp, KSPPREONLY));
    PetscCall(PCSetType(pc, PCCHOLESKY));
  } else {
    PetscCall(KSPSetType(*ksp, KSPCG));
    PetscCall(PCSetType(pc, PCBJACOBI));
    PetscCall(KSPSetTolerances(*ksp, 1e-13, 0, PETSC_DEFAULT, 20 * size + 100));
  }
  PetscCall(KSPSetFromOptions(*ksp));
  PetscCall(KSPSetUp(*ksp)); /* the factorisation, once */
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowSetUpPoisson(CSCurveFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_CurvePoissonSetUp, 0, 0, 0, 0));
  PetscCall(AssembleLaplacian(F, PETSC_TRUE, &F->L));
  PetscCall(CreateDirectKSP(F, F->L, "poisson_", &F->ksp));
  PetscCall(PetscLogEventEnd(CS_EVENT_CurvePoissonSetUp, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Sec. 4 filter matrix M + s L (M^{-1} L)^{k-1} (k >= 1) or (1 + s) M (k = 0), s = sigma (length/2pi)^(2k).
   The paper writes (id - sigma Delta^k)^{-1}; with Delta <= 0 that is a low-pass filter only for odd k (for
   k = 2 it has a pole at sigma lambda^2 = 1), so we read Delta^k as A^k with A = -Delta = M^{-1} L >= 0:
   v - (id + sigma A^k)^{-1} v = sigma A^k (id + sigma A^k)^{-1} v damps the low frequencies for every k. */
PetscErrorCode CSCurveFlowSetUpFilter(CSCurveFlow F)
{
  Mat       L;
  PetscReal s = F->sigma * PetscPowReal(F->length / (2 * PETSC_PI), 2.0 * (PetscReal)F->fk);
  PetscFunctionBeginUser;
  PetscCall(AssembleLaplacian(F, PETSC_FALSE, &L));
  PetscCall(CSOperatorSpectralFilter(L, F->d, s, F->fk, &F->Lf)); /* shared with the surface flow */
  PetscCall(CreateDirectKSP(F, F->Lf, "filter_", &F->kspf));
  PetscCall(MatDestroy(&L));
  PetscFunctionReturn(0);
}

/* x <- x + (del[0], del[1]) */
static PetscErrorCode AddCorrection(CSCurveFlow F)
{
  PetscScalar       *a;
  const PetscScalar *dx, *dy;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(F->x, &a));
  PetscCall(VecGetArrayRead(F->del[0], &dx));
  PetscCall(VecGetArrayRead(F->del[1], &dy));
  for (PetscInt i = 0; i < F->curve->n; i++) {
    a[2 * i] += dx[i];
    a[2 * i + 1] += dy[i];
  }
  PetscCall(VecRestoreArrayRead(F->del[1], &dy));
  PetscCall(VecRestoreArrayRead(F->del[0], &dx));
  PetscCall(VecRestoreArray(F->x, &a));
  PetscFunctionReturn(0);
}

/* Sec. 5.1 "remove the mean change in position and angle": d-weighted centroids and the rotation angle
   atan2(sum d p x q, sum d p . q) taking the new shape p onto the old q, both about their centroids */
static PetscErrorCode RemoveRigidMotion(CSCurveFlow F)
{
  PetscInt           n = F->curve->n;
  const PetscScalar *q, *d;
  PetscScalar       *p;
  PetscReal          s[4] = {0, 0, 0, 0}, S[4], r[2] = {0, 0}, R[2], co, si;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(F->x, &p));
  PetscCall(VecGetArrayRead(F->xold, &q));
  PetscCall(VecGetArrayRead(F->d, &d));
  for (PetscInt i = 0; i < n; i++)
    for (int k = 0; k < 2; k++) {
      s[k] += d[i] * p[2 * i + k];
      s[2 + k] += d[i] * q[2 * i + k];
    }
  PetscCallMPI(MPI_Allreduce(s, S, 4, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  for (int k = 0; k < 4; k++) S[k] /= F->length;
  for (PetscInt i = 0; i < n; i++) {
    PetscReal a[2] = {p[2 * i] - S[0], p[2 * i + 1] - S[1]}, b[2] = {q[2 * i] - S[2], q[2 * i + 1] - S[3]};
    r[0] += d[i] * (a[0] * b[1] - a[1] * b[0]);
    r[1] += d[i] * (a[0] * b[0] + a[1] * b[1]);
  }
  PetscCallMPI(MPI_Allreduce(r, R, 2, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  co = PetscCosReal(PetscAtan2Real(R[0], R[1]));
  si = PetscSinReal(PetscAtan2Real(R[0], R[1]));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal a[2] = {p[2 * i] - S[0], p[2 * i + 1] - S[1]};
    p[2 * i]       = S[2] + co * a[0] - si * a[1];
    p[2 * i + 1]   = S[3] + si * a[0] + co * a[1];
  }
  PetscCall(VecRestoreArrayRead(F->d, &d));
  PetscCall(VecRestoreArrayRead(F->xold, &q));
  PetscCall(VecRestoreArray(F->x, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowReconstruct(CSCurveFlow F)
{
  KSPConvergedReason kr;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_CurvePoisson, 0, 0, 0, 0));
  PetscCall(VecCopy(F->x, F->xold));
  for (int k = 0; k < 2; k++) {
    PetscCall(KSPSolve(F->ksp, F->rhs[k], F->del[k]));
    PetscCall(KSPGetConvergedReason(F->ksp, &kr));
    PetscCheck(kr >= 0, F->hdr.comm, PETSC_ERR_NOT_CONVERGED, "curve flow: the Poisson solve (-%spoisson_ksp_type ...) failed: %s", F->hdr.prefix, KSPConvergedReasons[kr]);
  }
  PetscCall(AddCorrection(F));
  PetscCall(RemoveRigidMotion(F));
  PetscCall(VecWAXPY(F->w, -1, F->xold, F->x));
  PetscCall(VecNorm(F->w, NORM_INFINITY, &F->s.change)); /* max coordinate difference */
  F->s.change /= F->length / (2 * PETSC_PI);
  PetscCall(PetscLogEventEnd(CS_EVENT_CurvePoisson, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
