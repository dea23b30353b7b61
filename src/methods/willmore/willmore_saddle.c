/* The linear solve of each CGD / PGD / GD step (soliman2021 Algorithm 1 line 11) through one KSP of prefix
   "<flow prefix>saddle_" (see willmore_impl.h for the block layout). The default solver is set in code on the
   KSP and its PCs before their SetFromOptions (why this one, and the measurements: docs/willmore_flow.md,
   "The saddle solve"): FGMRES + PCFIELDSPLIT Schur with the multiplier (edge) block first,
   A00 = -I_Q/t_mu diagonal, so the Schur complement S = H/t + t_mu X^T I_Q^{-1} X is sparse, SPD and exact; we
   assemble S with a pattern fixed over the run and hand it to the fieldsplit as the `user` Schur
   preconditioner, factored by CHOLMOD serially and by PC cssubchol in parallel. Without multipliers: CG with
   the factored H^2 preconditioner (PC csh2), or Jacobi for the L2 mass. A user who sets <prefix>pc_type
   chooses the whole solver (no defaults are applied). */
#include "willmore_impl.h"
#include <petscblaslapack.h>
#include "cs_substructured_cholesky.h"
#include "cs_util.h"

/* The defaults of the outer KSP, before KSPSetFromOptions. */
static PetscErrorCode SetDefaultSolver(CSSaddle *s)
{
  PC pc;
  PetscFunctionBeginUser;
  PetscCall(KSPGetPC(s->ksp, &pc));
  if (s->edges) {
    PetscCall(KSPSetType(s->ksp, KSPFGMRES));
    /* relative to |b| = |(-g - X^T mu, -c)|, which falls with the run (docs/willmore_flow.md) */
    PetscCall(KSPSetTolerances(s->ksp, 1e-6, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
    if (s->schur != CS_SCHUR_DIRECT) PetscCall(CSSchurIterativeSetDefaults(pc, s->schur));
    else {
      PetscCall(PCSetType(pc, PCFIELDSPLIT));
      PetscCall(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR));
      PetscCall(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_FULL));
      PetscCall(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_USER, NULL));
    }
  } else {
    PetscCall(KSPSetType(s->ksp, KSPCG));
    PetscCall(KSPSetTolerances(s->ksp, 1e-9, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
    PetscCall(PCSetType(pc, s->h2 ? "csh2" : PCJACOBI));
  }
  PetscFunctionReturn(0);
}

/* The defaults of the fieldsplit's two solvers (they exist once the outer PC is set up), then their own
   SetFromOptions so that any -<prefix>fieldsplit_{0,1}_* option still overrides them: Jacobi on the diagonal
   A00, and a direct factorisation of S (CHOLMOD serially, the substructured cssubchol in parallel). */
static PetscErrorCode SetDefaultSubSolvers(CSSaddle *s, PC pc)
{
  KSP        *sub;
  PC          subpc;
  PetscInt    n;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(s->mesh->comm, &size));
  PetscCall(PCFieldSplitSchurGetSubKSP(pc, &n, &sub));
  PetscCall(KSPSetType(sub[0], KSPPREONLY));
  PetscCall(KSPGetPC(sub[0], &subpc));
  PetscCall(PCSetType(subpc, PCJACOBI));
  PetscCall(KSPSetFromOptions(sub[0]));
  PetscCall(KSPSetType(sub[1], KSPPREONLY));
  PetscCall(KSPGetPC(sub[1], &subpc));
  if (size > 1) PetscCall(PCSetType(subpc, "cssubchol"));
  else {
    PetscCall(PCSetType(subpc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(subpc, MATSOLVERCHOLMOD));
  }
  PetscCall(KSPSetFromOptions(sub[1]));
  PetscCall(PetscFree(sub));
  PetscFunctionReturn(0);
}

/* -<prefix>schur_solver and -<prefix>schur_rtol (only with the edge block and without -<prefix>pc_type) */
static PetscErrorCode ReadSchurOptions(CSSaddle *s)
{
  PetscFunctionBeginUser;
  if (!s->edges || s->monolithic) PetscFunctionReturn(0);
  PetscOptionsBegin(s->mesh->comm, s->prefix, "Saddle solve of the CGD/PGD step", NULL);
  PetscCall(CSOptionsEnum("-schur_solver", "Solver of the Schur complement: direct factorisation, or iterative in the primal or the multiplier space (docs/scaling.md)", NULL, CSSchurSolveTypes, (PetscEnum)s->schur, (PetscEnum *)&s->schur, NULL));
  PetscCall(CSOptionsReal("-schur_rtol", "Relative tolerance of the iterative Schur solve", NULL, s->schur_rtol, &s->schur_rtol, NULL));
  PetscOptionsEnd();
  /* a kept BDDC (built for an earlier S) preconditions the current S badly: level 3 on 4 ranks, 8-9 CG iterations
     in the first step, 41-64 in the second, 147-220 in the third (docs/scaling.md); rebuilt every step unless the
     user set -flow_factor_reuse_its */
  if (s->schur == CS_SCHUR_BDDC && !s->reuse_set) s->reuse_its = 0;
  PetscCheck(s->schur_rtol > 0 && s->schur_rtol < 1, s->mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sschur_rtol %g: must be in (0, 1)", s->prefix, (double)s->schur_rtol);
  PetscFunctionReturn(0);
}

/* -<prefix>reuse_borders (with global rows only) */
static PetscErrorCode ReadBorderOptions(CSSaddle *s)
{
  PetscFunctionBeginUser;
  if (!s->k) PetscFunctionReturn(0);
  PetscOptionsBegin(s->mesh->comm, s->prefix, "Bordering of the global constraint rows", NULL);
  PetscCall(PetscOptionsBool("-reuse_borders", "Solve K W = B once per operator and keep W for the step's later solves (second-order corrections, refinement, restoration)", NULL, s->reuse_borders, &s->reuse_borders, NULL));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

/* the KSP of the saddle solve, configured at the next CSSaddleSetOperators */
static PetscErrorCode NewKSP(CSSaddle *s)
{
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(s->mesh->comm, &s->ksp));
  PetscCall(KSPSetOptionsPrefix(s->ksp, s->prefix));
  s->have_pc = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSaddleCreate(CSMesh mesh, const char prefix[], PetscBool edges, PetscBool h2, PetscBool monolithic, PetscInt reuse_its, PetscInt k, CSSaddle *s)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(s, sizeof(*s)));
  s->mesh       = mesh;
  s->edges      = edges;
  s->h2         = h2;
  s->monolithic = monolithic;
  s->k          = k;
  s->schur      = CS_SCHUR_DIRECT; /* the measured fastest on this machine (docs/scaling.md) */
  s->schur_rtol = 1e-4;
  /* the csh2 metric PC is cheap to rebuild, and a kept one costs 3x the CG its */
  s->reuse_its  = reuse_its >= 0 ? reuse_its : (edges ? 10 : 0);
  s->reuse_set  = (PetscBool)(reuse_its >= 0);
  s->reuse_borders = PETSC_TRUE;
  PetscCall(PetscStrncpy(s->prefix, prefix, sizeof(s->prefix)));
  /* the saddle's own options are read here, with the flow's set-up, not at the first solve: every option of a run is
     read before its first step (the driver's check of unused options, issue 36 item 18) */
  PetscCall(ReadSchurOptions(s));
  PetscCall(ReadBorderOptions(s));
  PetscCall(NewKSP(s));
  if (k) {
    PetscCall(PetscMalloc1(k, &s->G));
    PetscCall(PetscCalloc1(k, &s->W));
  }
  PetscFunctionReturn(0);
}

/* S = H11 + X^T diag(t_mu / iq) X = H11 - A10 A00^{-1} A01 (A00 = -diag(iq)/t_mu), into a matrix whose pattern
   (the union of both terms) is fixed at the first call, so that its factorisation keeps the symbolic part. */
static PetscErrorCode AssembleSchur(CSSaddle *s, Vec iq, PetscReal tmu, Mat X)
{
  Vec  d;
  PetscBool first = s->S ? PETSC_FALSE : PETSC_TRUE;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(iq, &d));
  PetscCall(VecCopy(iq, d));
  PetscCall(VecReciprocal(d));
  PetscCall(VecScale(d, tmu));
  if (first) PetscCall(MatDuplicate(s->Xt, MAT_COPY_VALUES, &s->XtD));
  else PetscCall(MatCopy(s->Xt, s->XtD, SAME_NONZERO_PATTERN));
  PetscCall(MatDiagonalScale(s->XtD, NULL, d));
  PetscCall(VecDestroy(&d));
  PetscCall(MatMatMult(s->XtD, X, first ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, PETSC_DEFAULT, &s->XtDX));
  if (first) {
    PetscCall(MatDuplicate(s->XtDX, MAT_COPY_VALUES, &s->S));
    PetscCall(MatAXPY(s->S, 1.0, s->H11, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatSetOption(s->S, MAT_SYMMETRIC, PETSC_TRUE));
    PetscCall(MatSetOption(s->S, MAT_SPD, PETSC_TRUE));
  } else {
    PetscCall(MatZeroEntries(s->S));
    PetscCall(CSMatAddFixedPattern(s->S, 1.0, s->XtDX, &s->add_xtdx));
    PetscCall(CSMatAddFixedPattern(s->S, 1.0, s->H11, &s->add_h11));
  }
  PetscFunctionReturn(0);
}

/* bddc: S = H/t + t_mu X^T I_Q^{-1} X unassembled (MATIS) from the terms of H = scale (w *0 + L *0^{-1} L)
   (soliman2021 Eq. 26; scale != 1 for the fairing energy's metric, willmore_setup.c) and of X, each rank's share from its owned rows (CSMatISFromSquares): d = w *0 / t, L with *0^{-1} / t,
   X with t_mu / I_Q. The L2 metric (H diagonal): d = diag(H)/t, X only. Dirichlet dofs: identity rows/columns
   (1/t) as in H11. */
static PetscErrorCode AssembleSchurIS(CSSaddle *s, Vec iq, PetscReal tmu, Mat X)
{
  CSMetric *m = s->metric;
  Vec       d, w[2];
  Mat       A[2];
  PetscInt  n = 0;
  PetscFunctionBeginUser;
  PetscCheck(m, s->mesh->comm, PETSC_ERR_ARG_WRONGSTATE, "-%sschur_solver bddc: no metric to build the unassembled Schur complement from", s->prefix);
  PetscCheck(!m->h1, s->mesh->comm, PETSC_ERR_SUP, "-%sschur_solver bddc: not built for -flow_metric h1 (use the direct Schur solve)", s->prefix);
  PetscCall(VecDuplicate(iq, &w[1]));
  PetscCall(VecCopy(iq, w[1]));
  PetscCall(VecReciprocal(w[1]));
  PetscCall(VecScale(w[1], tmu));
  PetscCall(VecDuplicate(m->m3, &d));
  if (m->h2) {
    PetscCall(VecAXPBY(d, m->scale * m->mass_weight / s->t, 0.0, m->m3)); /* H = scale (w *0 + L *0^{-1} L) */
    PetscCall(VecDuplicate(m->minv3, &w[0]));
    PetscCall(VecAXPBY(w[0], m->scale / s->t, 0.0, m->minv3));
    A[n++] = m->L3;
  } else PetscCall(MatGetDiagonal(s->H11, d));
  A[n] = X;
  if (n == 0) w[0] = w[1];
  PetscCall(CSMatISFromSquares(d, n + 1, A, w, s->Sis ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->Sis));
  if (s->fixed) PetscCall(MatZeroRowsColumnsIS(s->Sis, s->fixed, 1.0 / s->t, NULL, NULL));
  PetscCall(VecDestroy(&d));
  if (n == 1) PetscCall(VecDestroy(&w[0]));
  else w[0] = NULL;
  PetscCall(VecDestroy(&w[1]));
  PetscFunctionReturn(0);
}

/* The MATNEST [[A00, X], [X^T, H/t]] (and its AIJ form with aij), refilled at later calls; *op the operator. */
static PetscErrorCode EdgeOperator(CSSaddle *s, PetscBool first, Vec iq, PetscReal tmu, Mat X, Mat *op)
{
  Vec d;
  PetscFunctionBeginUser;
  if (first) {
    PetscInt nE, NE;
    PetscCall(VecGetLocalSize(iq, &nE));
    PetscCall(VecGetSize(iq, &NE));
    PetscCall(MatCreateAIJ(s->mesh->comm, nE, nE, NE, NE, 1, NULL, 0, NULL, &s->A00));
    PetscCall(MatSetUp(s->A00));
    PetscCall(MatSetOption(s->A00, MAT_SYMMETRIC, PETSC_TRUE));
  }
  PetscCall(VecDuplicate(iq, &d));
  PetscCall(VecCopy(iq, d));
  PetscCall(VecScale(d, -1.0 / tmu));
  PetscCall(MatDiagonalSet(s->A00, d, INSERT_VALUES));
  PetscCall(VecDestroy(&d));
  PetscCall(MatTranspose(X, first ? MAT_INITIAL_MATRIX : MAT_REUSE_MATRIX, &s->Xt));
  if (first) {
    Mat blocks[4] = {s->A00, X, s->Xt, s->H11};
    PetscCall(MatCreateNest(s->mesh->comm, 2, NULL, 2, NULL, blocks, &s->K));
    PetscCall(MatNestGetISs(s->K, s->is, NULL));
    PetscCall(PetscObjectReference((PetscObject)s->is[0]));
    PetscCall(PetscObjectReference((PetscObject)s->is[1]));
    PetscCall(MatCreateVecs(s->K, NULL, &s->b));
  } else {
    Mat Xold;
    PetscCall(MatNestGetSubMat(s->K, 0, 1, &Xold));
    if (Xold != X) PetscCall(MatNestSetSubMat(s->K, 0, 1, X));
  }
  PetscCall(MatAssemblyBegin(s->K, MAT_FINAL_ASSEMBLY)); /* bumps the nest's state: the PC sees a new operator */
  PetscCall(MatAssemblyEnd(s->K, MAT_FINAL_ASSEMBLY));
  if (s->monolithic) {
    PetscCall(MatConvert(s->K, MATAIJ, s->Kaij ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->Kaij));
    PetscCall(MatSetOption(s->Kaij, MAT_SYMMETRIC, PETSC_TRUE));
    *op = s->Kaij;
  } else *op = s->K;
  PetscFunctionReturn(0);
}

/* The k bordering rows B_j (in the layout of b) and G = diag(g_j) / t_mu. */
static PetscErrorCode CopyParts(CSSaddle *s, Vec w, Vec E, Vec V, PetscBool in);

static PetscErrorCode BorderRows(CSSaddle *s, Vec rows[], const PetscReal g[], PetscReal tmu)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < s->k; j++) {
    if (!s->B) PetscCall(PetscCalloc1(s->k, &s->B));
    if (!s->B[j]) PetscCall(VecDuplicate(s->b, &s->B[j]));
    if (!s->W[j]) {
      PetscCall(VecDuplicate(s->b, &s->W[j]));
      PetscCall(VecSet(s->W[j], 0)); /* later steps start from the previous step's W_j */
      if (s->WV && s->WV[j]) PetscCall(CopyParts(s, s->W[j], s->WE[j], s->WV[j], PETSC_TRUE)); /* a resumed run's */
    }
    PetscCall(VecSet(s->B[j], 0));
    if (s->edges) {
      Vec sub;
      PetscCall(VecGetSubVector(s->B[j], s->is[1], &sub));
      PetscCall(VecCopy(rows[j], sub));
      PetscCall(VecRestoreSubVector(s->B[j], s->is[1], &sub));
    } else PetscCall(VecCopy(rows[j], s->B[j]));
    s->G[j] = g[j] / tmu;
  }
  s->w_valid = PETSC_FALSE; /* new operators or rows: the bordering solves are due again */
  PetscFunctionReturn(0);
}

/* The splits (multipliers first), the exact Schur complement as the user Schur preconditioner, and the
   defaults of the two split solvers unless the user chose the solver. */
static PetscErrorCode ConfigureFieldSplit(CSSaddle *s, PC pc, PetscBool chosen, Vec iq, PetscReal tmu, Mat X)
{
  PCFieldSplitSchurPreType pre;
  PCCompositeType          type;
  Mat                      pmat;
  PetscFunctionBeginUser;
  if (!chosen && s->schur != CS_SCHUR_DIRECT) PetscCall(CSSchurIterativeSetSplits(pc, s->schur, s->is[0], s->is[1]));
  else {
    PetscCall(PCFieldSplitSetIS(pc, "0", s->is[0])); /* multipliers (edges) first */
    PetscCall(PCFieldSplitSetIS(pc, "1", s->is[1])); /* positions */
  }
  PetscCall(PCFieldSplitGetType(pc, &type));
  PetscCall(PCFieldSplitGetSchurPre(pc, &pre, &pmat)); /* (the matrix argument may not be NULL in 3.18) */
  if (type == PC_COMPOSITE_SCHUR && pre == PC_FIELDSPLIT_SCHUR_PRE_USER) {
    if (!chosen && s->schur == CS_SCHUR_BDDC) PetscCall(AssembleSchurIS(s, iq, tmu, X));
    else PetscCall(AssembleSchur(s, iq, tmu, X));
    PetscCall(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_USER, s->Sis ? s->Sis : s->S));
  }
  if (!chosen && type == PC_COMPOSITE_SCHUR) {
    PetscCall(KSPSetUp(s->ksp)); /* creates the fieldsplit's solvers */
    if (s->schur != CS_SCHUR_DIRECT) PetscCall(CSSchurIterativeSetSubSolvers(pc, s->schur, s->schur_rtol));
    else PetscCall(SetDefaultSubSolvers(s, pc));
  }
  PetscFunctionReturn(0);
}

/* A -<prefix>pc_type among the KSP's own options (its database and prefix, where its PC's SetFromOptions will read
   it): the user chose the whole solver, and none of the defaults apply. Asked before the SetFromOptions because the
   PC's type after it cannot tell a user's -pc_type fieldsplit or cholesky from the defaults, and the defaults of
   the outer KSP (FGMRES, rtol 1e-6) must not be imposed on a solver the user chose (docs/willmore_flow.md). */
static PetscErrorCode UserChoseSolver(KSP ksp, PetscBool *chosen)
{
  PetscOptions options;
  const char  *prefix;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetOptions((PetscObject)ksp, &options));
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  PetscCall(PetscOptionsHasName(options, prefix, "-pc_type", chosen));
  PetscFunctionReturn(0);
}

/* First configuration of a (new) KSP: the defaults unless the user chose a solver, the options, the splits. */
static PetscErrorCode ConfigureKSP(CSSaddle *s, Vec iq, PetscReal tmu, Mat X)
{
  PC        pc;
  PetscBool chosen, fs = PETSC_FALSE, preonly;
  PetscFunctionBeginUser;
  PetscCall(UserChoseSolver(s->ksp, &chosen));
  if (!chosen) PetscCall(SetDefaultSolver(s));
  PetscCall(KSPSetFromOptions(s->ksp));
  PetscCall(KSPGetPC(s->ksp, &pc));
  if (s->edges && !s->monolithic) PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &fs));
  if (fs) PetscCall(ConfigureFieldSplit(s, pc, chosen, iq, tmu, X));
  s->have_pc = PETSC_TRUE;
  s->t_pc    = s->t;
  s->tmu_pc  = tmu;
  if (!s->setups && s->wait > 0) s->wait--; /* a resumed run's first step is fresh like those it waited for */
  s->setups++; /* 1 at the first call; more after a new solver (failed factorisation) */
  s->reusing = PETSC_FALSE;
  PetscCall(KSPSetReusePreconditioner(s->ksp, PETSC_FALSE));
  PetscCall(KSPGetTolerances(s->ksp, NULL, NULL, NULL, &s->max_it));
  /* a kept preconditioner needs a Krylov method to correct it: with preonly it would give wrong steps */
  PetscCall(PetscObjectTypeCompare((PetscObject)s->ksp, KSPPREONLY, &preonly));
  if (preonly) s->reuse_its = 0;
  s->krylov = (PetscBool)!preonly;
  /* tolerances relative to the initial residual |b - K z0| (UIRNorm): for the bordering solves, which start from
     the previous step's W, that is more accurate than relative to |b| (PETSc's default with a nonzero guess).
     Measured without it on Fig. 16 (24 x 24, 40 iterations): 1623 KSP iterations against 1717, the same W to
     1e-15: not worth the accuracy */
  if (s->krylov) PetscCall(KSPConvergedDefaultSetUIRNorm(s->ksp));
  PetscFunctionReturn(0);
}

/* A later step: keep the preconditioner or rebuild it. */
static PetscErrorCode ReuseOrRebuild(CSSaddle *s, Vec iq, PetscReal tmu, Mat X)
{
  PetscFunctionBeginUser;
  /* an earlier factorisation is a strong preconditioner for the slightly changed matrix (docs/solvers.md). To
     keep it, S is left as it is (the Schur sub-solver refactors whenever S changes). Reuse while the last
     solve was cheap; after a failed attempt (more than reuse_its iterations with the kept factorisation)
     take 1, 2, 4, ... 16 fresh steps before trying again: early in a run the surface changes fast and every
     attempt would waste its iterations. */
  if (s->wait > 0) {
    s->reusing = PETSC_FALSE;
    s->wait--;
  } else s->reusing = (PetscBool)(s->reuse_its > 0 && s->last_its <= s->reuse_its);
  PetscCall(PetscInfo(s->ksp, "saddle: t = %g, t_mu = %g, factorisation of t = %g, t_mu = %g %s\n", (double)s->t, (double)tmu, (double)s->t_pc, (double)s->tmu_pc, s->reusing ? "kept" : "rebuilt"));
  if (!s->reusing) {
    s->t_pc   = s->t;
    s->tmu_pc = tmu;
    if (s->S) PetscCall(AssembleSchur(s, iq, tmu, X));
    if (s->Sis) PetscCall(AssembleSchurIS(s, iq, tmu, X));
    s->setups++;
  }
  PetscCall(KSPSetReusePreconditioner(s->ksp, s->reusing));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSaddleSetOperators(CSSaddle *s, Mat H, PetscReal t, Vec iq, PetscReal tmu, Mat X, Vec rows[], const PetscReal g[])
{
  PetscBool first = s->H11 ? PETSC_FALSE : PETSC_TRUE;
  Mat       op = NULL;
  PetscFunctionBeginUser;
  if (first) PetscCall(MatDuplicate(H, MAT_COPY_VALUES, &s->H11));
  else PetscCall(MatCopy(H, s->H11, SAME_NONZERO_PATTERN));
  PetscCall(MatScale(s->H11, 1.0 / t));
  s->t = t;
  if (s->fixed) PetscCall(MatZeroRowsColumnsIS(s->H11, s->fixed, 1.0 / t, NULL, NULL));
  PetscCall(CSH2PCComposeFrom(H, s->H11, 1.0 / t, s->fixed)); /* for -flow_saddle_[fieldsplit_1_]pc_type csh2 */
  if (s->edges) PetscCall(EdgeOperator(s, first, iq, tmu, X, &op));
  else {
    op = s->H11;
    if (first) PetscCall(MatCreateVecs(s->H11, NULL, &s->b));
  }
  if (first) PetscCall(VecDuplicate(s->b, &s->z));
  PetscCall(BorderRows(s, rows, g, tmu));
  PetscCall(KSPSetOperators(s->ksp, op, op));
  if (!s->have_pc) PetscCall(ConfigureKSP(s, iq, tmu, X));
  else PetscCall(ReuseOrRebuild(s, iq, tmu, X));
  s->iq  = iq; /* for a refresh in KSolve */
  s->tmu = tmu;
  s->X   = X;
  PetscFunctionReturn(0);
}

/* A solve with a kept preconditioner is given at most 2 reuse_its (at least 20) iterations; if it needs more,
   the preconditioner is rebuilt for the current matrix and the solve repeated, so a stale factorisation
   costs a bounded number of wasted iterations and never a rejected step. */
static PetscErrorCode KSolve(CSSaddle *s, Vec b, Vec z, PetscInt *its, KSPConvergedReason *kreason)
{
  KSPConvergedReason reason;
  PetscInt           n;
  PetscFunctionBeginUser;
  s->solves++;
  if (s->reusing) {
    PetscCall(KSPSetTolerances(s->ksp, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, PetscMin(s->max_it, PetscMax(20, 2 * s->reuse_its))));
    PetscCall(KSPSolve(s->ksp, b, z));
    PetscCall(KSPSetTolerances(s->ksp, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT, s->max_it));
    PetscCall(KSPGetConvergedReason(s->ksp, &reason));
    PetscCall(KSPGetIterationNumber(s->ksp, &n));
    s->last_its = n;
    PetscCall(PetscInfo(s->ksp, "saddle: the kept factorisation of t = %g at t = %g: %" PetscInt_FMT " iterations (reuse while <= %" PetscInt_FMT ")\n", (double)s->t_pc, (double)s->t, n, s->reuse_its));
    if (n > s->reuse_its) { /* a failed attempt: back off */
      s->backoff = PetscMin(16, PetscMax(1, 2 * s->backoff));
      s->wait    = s->backoff;
    } else s->backoff = 0;
    *its += n; /* spent, even if wasted */
    *kreason = reason;
    if (reason > 0) PetscFunctionReturn(0);
    s->reusing = PETSC_FALSE;
    s->setups++;
    s->t_pc   = s->t;
    s->tmu_pc = s->tmu;
    if (s->S) PetscCall(AssembleSchur(s, s->iq, s->tmu, s->X));
    if (s->Sis) PetscCall(AssembleSchurIS(s, s->iq, s->tmu, s->X));
    PetscCall(KSPSetReusePreconditioner(s->ksp, PETSC_FALSE));
  }
  PetscCall(KSPSolve(s->ksp, b, z));
  PetscCall(KSPGetConvergedReason(s->ksp, &reason));
  PetscCall(KSPGetIterationNumber(s->ksp, &n));
  s->last_its = n;
  if (reason == KSP_DIVERGED_PC_FAILED) {
    /* a failed factorisation (not positive definite, or MUMPS out of workspace: its numeric refactorisations
       reuse the first analysis and its memory estimate) would fail again at every smaller t: the next attempt
       starts from a new solver (analysis included) */
    PetscCall(KSPDestroy(&s->ksp));
    PetscCall(NewKSP(s));
  }
  *kreason = reason;
  if (reason > 0) *its += n; /* a failed solve is reported, not counted (as before the reason was returned) */
  PetscFunctionReturn(0);
}

/* k x k dense solve (column-major S), Gaussian elimination with partial pivoting; k is a handful (LAPACK gesv
   rounds differently and moves the golden results: docs/willmore_flow.md). */
/* The k x k bordered system S y = b of the global constraints (k <= ~10), by LAPACK's LU with partial pivoting
   (getrf + getrs = gesv). The pivots are U's diagonal: a pivot below 1e-14 max|S| means dependent constraints,
   reported as such rather than solved. S and b are replicated on every rank, so every rank decides alike. */
static PetscErrorCode SmallSolve(MPI_Comm comm, PetscInt k, PetscScalar *S, PetscScalar *b)
{
  PetscReal    big = 0, small;
  PetscBLASInt n, one = 1, info;
  PetscBLASInt ipiv[64];
  PetscFunctionBeginUser;
  PetscCheck(k <= 64, comm, PETSC_ERR_SUP, "flow: %" PetscInt_FMT " global constraints; at most 64 are supported", k);
  PetscCall(PetscBLASIntCast(k, &n));
  for (PetscInt i = 0; i < k * k; i++) big = PetscMax(big, PetscAbsScalar(S[i]));
  PetscCallBLAS("LAPACKgetrf", LAPACKgetrf_(&n, &n, S, &n, ipiv, &info));
  PetscCheck(info >= 0, comm, PETSC_ERR_LIB, "flow: LAPACK getrf argument %d is invalid", (int)-info);
  small = big;
  for (PetscInt c = 0; c < k; c++) small = PetscMin(small, PetscAbsScalar(S[c + c * k]));
  PetscCheck(info == 0 && small > 1e-14 * big, comm, PETSC_ERR_MAT_LU_ZRPVT, "flow: the bordered system of the area/volume/point constraints is singular: are the constraints dependent (e.g. area + volume + points fixing the same thing)?");
  PetscCallBLAS("LAPACKgetrs", LAPACKgetrs_("N", &n, &one, S, &n, ipiv, b, &n, &info));
  PetscCheck(info == 0, comm, PETSC_ERR_LIB, "flow: LAPACK getrs failed (info %d)", (int)info);
  PetscFunctionReturn(0);
}

/* Copies between a saddle vector w = [E; V] (w = V without edge unknowns) and its parts: into w if in, else
   out of it. */
static PetscErrorCode CopyParts(CSSaddle *s, Vec w, Vec E, Vec V, PetscBool in)
{
  Vec part[2] = {E, V};
  PetscFunctionBeginUser;
  if (!s->edges) {
    PetscCall(in ? VecCopy(V, w) : VecCopy(w, V));
    PetscFunctionReturn(0);
  }
  for (PetscInt i = 0; i < 2; i++) {
    Vec sub;
    PetscCall(VecGetSubVector(w, s->is[i], &sub));
    PetscCall(in ? VecCopy(part[i], sub) : VecCopy(sub, part[i]));
    PetscCall(VecRestoreSubVector(w, s->is[i], &sub));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSSaddleSolve(CSSaddle *s, Vec rE, Vec rV, const PetscReal rX[], Vec zE, Vec zV, PetscReal zX[], PetscInt *its, KSPConvergedReason *reason)
{
  PetscInt n = 0, nfirst;
  PetscFunctionBeginUser;
  *its = 0;
  PetscCall(CopyParts(s, s->b, rE, rV, PETSC_TRUE));
  PetscCall(KSPSetInitialGuessNonzero(s->ksp, PETSC_FALSE));
  PetscCall(KSolve(s, s->b, s->z, &n, reason));
  if (*reason <= 0) PetscFunctionReturn(0);
  nfirst = s->last_its; /* the iterations of the (last) solve of the step's own right-hand side */
  if (s->k) {
    /* bordering: z = K^{-1}(r - B zX), (B^T K^{-1} B + G) zX = B^T K^{-1} r - rX */
    PetscScalar   *S, *rhs;
    PetscErrorCode ierr;
    /* the solves first: a failed one (a rejected step, retried by the flow) then leaves nothing allocated */
    /* W_j = K^{-1} B_j depends on the operators only: solved once after CSSaddleSetOperators and kept for the
       later right-hand sides of the same step (second-order corrections, PGD's refinement, the restorations),
       which needed k solves each before */
    if (!(s->reuse_borders && s->w_valid)) {
      /* W_j changes little from step to step: start from the last one (Krylov solvers only) */
      PetscCall(KSPSetInitialGuessNonzero(s->ksp, s->krylov));
      for (PetscInt j = 0; j < s->k; j++) { /* (reset before the next step's first solve) */
        PetscCall(KSolve(s, s->B[j], s->W[j], &n, reason));
        if (*reason <= 0) PetscFunctionReturn(0);
      }
      s->w_valid = PETSC_TRUE;
    }
    PetscCall(PetscMalloc2(s->k * s->k, &S, s->k, &rhs));
    for (PetscInt i = 0; i < s->k; i++) {
      PetscScalar v;
      PetscCall(VecDot(s->z, s->B[i], &v));
      rhs[i] = v - rX[i];
      for (PetscInt j = 0; j < s->k; j++) {
        PetscCall(VecDot(s->W[j], s->B[i], &v));
        S[i + j * s->k] = v + (i == j ? s->G[i] : 0.0);
      }
    }
    ierr = SmallSolve(s->mesh->comm, s->k, S, rhs);
    if (ierr) PetscCall(PetscFree2(S, rhs));
    PetscCall(ierr);
    for (PetscInt j = 0; j < s->k; j++) {
      zX[j] = PetscRealPart(rhs[j]);
      PetscCall(VecAXPY(s->z, -rhs[j], s->W[j]));
    }
    PetscCall(PetscFree2(S, rhs));
  }
  PetscCall(CopyParts(s, s->z, zE, zV, PETSC_FALSE));
  s->last_its = nfirst;
  *its        = n;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSaddleDestroy(CSSaddle *s)
{
  PetscFunctionBeginUser;
  PetscCall(KSPDestroy(&s->ksp));
  PetscCall(MatDestroy(&s->A00));
  PetscCall(MatDestroy(&s->Xt));
  PetscCall(MatDestroy(&s->XtD));
  PetscCall(MatDestroy(&s->XtDX));
  PetscCall(MatDestroy(&s->S));
  PetscCall(MatDestroy(&s->Sis));
  PetscCall(CSMatAddMapDestroy(&s->add_xtdx));
  PetscCall(CSMatAddMapDestroy(&s->add_h11));
  PetscCall(MatDestroy(&s->H11));
  PetscCall(MatDestroy(&s->K));
  PetscCall(MatDestroy(&s->Kaij));
  PetscCall(ISDestroy(&s->is[0]));
  PetscCall(ISDestroy(&s->is[1]));
  PetscCall(VecDestroy(&s->b));
  PetscCall(VecDestroy(&s->z));
  for (PetscInt j = 0; j < s->k; j++) {
    if (s->B) PetscCall(VecDestroy(&s->B[j]));
    if (s->W) PetscCall(VecDestroy(&s->W[j]));
    if (s->WE) PetscCall(VecDestroy(&s->WE[j]));
    if (s->WV) PetscCall(VecDestroy(&s->WV[j]));
  }
  PetscCall(PetscFree(s->B));
  PetscCall(PetscFree(s->W));
  PetscCall(PetscFree2(s->WE, s->WV));
  PetscCall(PetscFree(s->G));
  PetscFunctionReturn(0);
}

/* Checkpoints: the initial guess W_j of bordering solve j (the last solution), as its parts E (NULL without the edge
   block) and V; zero before the first step. */
PetscErrorCode CSSaddleGetGuess(CSSaddle *s, PetscInt j, Vec E, Vec V)
{
  PetscFunctionBeginUser;
  if (s->W[j]) {
    PetscCall(CopyParts(s, s->W[j], E, V, PETSC_FALSE));
    PetscFunctionReturn(0);
  }
  if (s->WV && s->WV[j]) { /* resumed, no step since */
    if (E) PetscCall(VecCopy(s->WE[j], E));
    PetscCall(VecCopy(s->WV[j], V));
    PetscFunctionReturn(0);
  }
  if (E) PetscCall(VecSet(E, 0));
  PetscCall(VecSet(V, 0));
  PetscFunctionReturn(0);
}

/* The inverse at a resume: into W_j, or kept until the first step creates it (BorderRows). */
PetscErrorCode CSSaddleSetGuess(CSSaddle *s, PetscInt j, Vec E, Vec V)
{
  PetscFunctionBeginUser;
  s->w_valid = PETSC_FALSE; /* W_j is a guess again: the next solve with these operators must solve for it */
  if (s->W[j]) {
    PetscCall(CopyParts(s, s->W[j], E, V, PETSC_TRUE));
    PetscFunctionReturn(0);
  }
  if (!s->WV) PetscCall(PetscCalloc2(s->k, &s->WE, s->k, &s->WV));
  if (E && !s->WE[j]) PetscCall(VecDuplicate(E, &s->WE[j]));
  if (!s->WV[j]) PetscCall(VecDuplicate(V, &s->WV[j]));
  if (E) PetscCall(VecCopy(E, s->WE[j]));
  PetscCall(VecCopy(V, s->WV[j]));
  PetscFunctionReturn(0);
}
