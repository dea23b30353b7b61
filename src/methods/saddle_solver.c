/* The linear solve of each CGD / PGD / GD step (soliman2021 Algorithm 1 line 11) through one KSP of
   prefix "flow_". See include/cs_methods_willmore.h for the block layout. Default solver (measured on this
   machine, PETSC-NOTES "The CGD saddle system", runs/bench_flow.sh): FGMRES + PCFIELDSPLIT Schur with the
   multiplier (edge) block first, A00 = -I_Q/t_mu diagonal, so the Schur complement
   S = H/t + t_mu X^T I_Q^{-1} X is sparse, SPD and exact. We assemble S ourselves with a pattern fixed over the
   run and hand it to the fieldsplit as the `user` Schur preconditioner (`selfp` forms the same matrix, but
   with a new nonzero pattern every step, which forces a new symbolic factorisation: 0.5 s per step with
   CHOLMOD at 20k faces); S is factored by CHOLMOD serially (1.8x faster than MUMPS-AMD at 20k faces) and in
   parallel by substructuring (PC cssubchol: CHOLMOD + METIS on each rank's part, then the dense interface; level
   6, 20 steps: 1.99 s/step on 2 ranks against 2.73 serially, runs/bench_flow.md, where MUMPS-PORD on S gained
   nothing); the outer iteration then converges in 1-2 steps. The factorisation is kept over later steps while it
   stays a good preconditioner (-flow_pc_reuse_its, default 10: refactor once a solve needed more than 10 FGMRES
   iterations): at level 5 a 200-step run needs 207 s (201
   factorisations) when refactoring every step and 49.5 s with the kept one (18 factorisations, 1122 FGMRES
   iterations in all; the same W to 1e-13; runs/bench_flow.md). The default is
   inserted as a preset when -flow_pc_type is not given; any single preset option can be overridden on the
   command line (e.g. -flow_pc_fieldsplit_schur_precondition selfp).
   Measured and dropped: the other Schur complement, on the multipliers (vertex block first, exact H/t solves by
   a Cholesky factorisation of H, CG + Jacobi(I_Q) on S_mu = I_Q/t_mu + t X H^{-1} X^T, fieldsplit_1 rtol 1e-8):
   113-260 CG iterations per solve at levels 3, 4 and 5 (mesh-independent, but growing with t t_mu), 2 s per solve
   at level 5 against 0.3 s for a factorisation of S. */
#include "cs_methods_willmore.h"
#include "cs_substructured_cholesky.h"

static const char *PresetSchur[][2] = {
  {"-flow_ksp_type", "fgmres"},
  /* relative to |b| = |(-g - X^T mu, -c)|, which falls with the run: 1e-6 gives the same iterates as 1e-9 (level 6,
     100 steps: W to 1e-14, el_residual to 1e-7 relative) with 380 instead of 574 FGMRES iterations, 83.8 vs 113.2 s */
  {"-flow_ksp_rtol", "1e-6"},
  {"-flow_pc_type", "fieldsplit"},
  {"-flow_pc_fieldsplit_type", "schur"},
  {"-flow_pc_fieldsplit_schur_fact_type", "full"},
  {"-flow_pc_fieldsplit_schur_precondition", "user"},
  {"-flow_fieldsplit_0_ksp_type", "preonly"},
  {"-flow_fieldsplit_0_pc_type", "jacobi"},
  {"-flow_fieldsplit_1_ksp_type", "preonly"},
  /* "serial|parallel" values. In parallel, the substructured CHOLMOD factorisation (PC cssubchol,
     substructured_cholesky.c): each rank factors its part of S with METIS + CHOLMOD, then the dense interface */
  {"-flow_fieldsplit_1_pc_type", "cholesky|cssubchol"},
  {"-flow_fieldsplit_1_pc_factor_mat_solver_type", "cholmod|mumps"}, /* for -flow_fieldsplit_1_pc_type cholesky */
  {"-flow_fieldsplit_1_mat_mumps_icntl_7", "4"}, /* PORD: per step 1.08 vs 1.28 s (AMD) at 20k faces, 5.7 vs 7.9 s at
                                                  82k faces, on 2 ranks; its slow analysis is paid once per run */
};
/* Without multipliers, H^2: the metric alone, CG preconditioned by the factored H^2 preconditioner (PC type
   csh2, h2_pc.c: two shifted-Laplacian Cholesky solves per iteration, 10 CG iterations per step at levels 3
   and 5, test willmore_h2pc) -- 1.20 -> 0.35 s per GD step at level 5, 8.9 -> 1.5 s at level 6, against CG + a MUMPS Cholesky
   factorisation of the two-ring metric itself (-flow_pc_type cholesky -flow_pc_factor_mat_solver_type mumps). */
static const char *PresetMetric[][2] = {
  {"-flow_ksp_type", "cg"},
  {"-flow_ksp_rtol", "1e-9"},
  {"-flow_pc_type", "csh2"},
};
/* Without multipliers, L2: the diagonal mass */
static const char *PresetMass[][2] = {
  {"-flow_ksp_type", "cg"},
  {"-flow_ksp_rtol", "1e-9"},
  {"-flow_pc_type", "jacobi"},
};

static PetscErrorCode InsertPreset(CSSaddle *s, const char *p[][2], PetscInt n)
{
  PetscBool   set;
  PetscMPIInt size;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-flow_pc_type", &set));
  if (set) PetscFunctionReturn(0); /* the user chose a solver: no preset at all */
  PetscCallMPI(MPI_Comm_size(s->mesh->comm, &size));
  PetscCall(PetscMalloc1(n, &s->preset));
  for (PetscInt i = 0; i < n; i++) {
    char        value[64];
    const char *bar;
    PetscCall(PetscOptionsHasName(NULL, NULL, p[i][0], &set));
    if (set) continue;
    /* "serial|parallel": CHOLMOD is sequential */
    PetscCall(PetscStrncpy(value, p[i][1], sizeof(value)));
    PetscCall(PetscStrchr(p[i][1], '|', (char **)&bar));
    if (bar) {
      if (size > 1) PetscCall(PetscStrncpy(value, bar + 1, sizeof(value)));
      else value[bar - p[i][1]] = 0;
    }
    PetscCall(PetscOptionsSetValue(NULL, p[i][0], value));
    PetscCall(PetscStrallocpy(p[i][0], &s->preset[s->npreset++]));
  }
  PetscFunctionReturn(0);
}

/* the KSP of prefix flow_, configured at the next CSSaddleSetOperators */
static PetscErrorCode NewKSP(CSSaddle *s)
{
  PetscFunctionBeginUser;
  PetscCall(KSPCreate(s->mesh->comm, &s->ksp));
  PetscCall(KSPSetOptionsPrefix(s->ksp, "flow_"));
  s->have_pc = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSaddleCreate(CSMesh mesh, PetscBool edges, PetscBool h2, PetscInt k, CSSaddle *s)
{
  char      type[16] = "nest";
  PetscBool aij;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(s, sizeof(*s)));
  s->mesh      = mesh;
  s->edges     = edges;
  s->k         = k;
  s->reuse_its = edges ? 10 : 0; /* the csh2 metric PC is cheap to rebuild, and a kept one costs 3x the CG its */
  PetscOptionsBegin(mesh->comm, NULL, "Willmore flow linear solver", NULL);
  PetscCall(PetscOptionsString("-flow_saddle_mat", "nest|aij: the saddle matrix as MATNEST (fieldsplit) or converted to AIJ (monolithic direct solvers)", NULL, type, type, sizeof(type), NULL));
  PetscCall(PetscOptionsInt("-flow_pc_reuse_its", "Keep the preconditioner (factorisation) of an earlier step while the last solve needed at most this many Krylov iterations (0: refactor every step; default 10 with the conformal constraint, else 0; ignored with -flow_ksp_type preonly)", NULL, s->reuse_its, &s->reuse_its, NULL));
  PetscOptionsEnd();
  PetscCheck(s->reuse_its >= 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_pc_reuse_its %" PetscInt_FMT ": use 0 (refactor every step) or a positive iteration count", s->reuse_its);
  PetscCall(PetscStrcmp(type, "aij", &aij));
  s->monolithic = aij;
  if (!aij) {
    PetscBool nest;
    PetscCall(PetscStrcmp(type, "nest", &nest));
    PetscCheck(nest, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_saddle_mat %s: unknown (nest|aij)", type);
  }
  if (edges) PetscCall(InsertPreset(s, PresetSchur, (PetscInt)(sizeof(PresetSchur) / sizeof(PresetSchur[0]))));
  else if (h2) PetscCall(InsertPreset(s, PresetMetric, (PetscInt)(sizeof(PresetMetric) / sizeof(PresetMetric[0]))));
  else PetscCall(InsertPreset(s, PresetMass, (PetscInt)(sizeof(PresetMass) / sizeof(PresetMass[0]))));
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

PetscErrorCode CSSaddleSetOperators(CSSaddle *s, Mat H, PetscReal t, Vec iq, PetscReal tmu, Mat X, Vec rows[], const PetscReal g[])
{
  PetscBool first = s->H11 ? PETSC_FALSE : PETSC_TRUE;
  Mat       op;
  PetscFunctionBeginUser;
  if (first) PetscCall(MatDuplicate(H, MAT_COPY_VALUES, &s->H11));
  else PetscCall(MatCopy(H, s->H11, SAME_NONZERO_PATTERN));
  PetscCall(MatScale(s->H11, 1.0 / t));
  if (s->fixed) PetscCall(MatZeroRowsColumnsIS(s->H11, s->fixed, 1.0 / t, NULL, NULL));
  PetscCall(CSH2PCComposeFrom(H, s->H11, 1.0 / t, s->fixed)); /* for -flow_[fieldsplit_1_]pc_type csh2 */
  if (s->edges) {
    Vec d;
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
      op = s->Kaij;
    } else op = s->K;
  } else {
    op = s->H11;
    if (first) PetscCall(MatCreateVecs(s->H11, NULL, &s->b));
  }
  if (first) PetscCall(VecDuplicate(s->b, &s->z));
  for (PetscInt j = 0; j < s->k; j++) {
    if (!s->B) PetscCall(PetscCalloc1(s->k, &s->B));
    if (!s->B[j]) PetscCall(VecDuplicate(s->b, &s->B[j]));
    if (!s->W[j]) {
      PetscCall(VecDuplicate(s->b, &s->W[j]));
      PetscCall(VecSet(s->W[j], 0)); /* later steps start from the previous step's W_j */
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
  PetscCall(KSPSetOperators(s->ksp, op, op));
  if (!s->have_pc) {
    PC pc;
    PetscCall(KSPSetFromOptions(s->ksp));
    PetscCall(KSPGetPC(s->ksp, &pc));
    if (s->edges && !s->monolithic) {
      PetscBool fs;
      PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCFIELDSPLIT, &fs));
      if (fs) {
        PCFieldSplitSchurPreType pre;
        PCCompositeType          type;
        Mat                      pmat;
        PetscCall(PCFieldSplitSetIS(pc, "0", s->is[0])); /* multipliers (edges) first: PETSC-NOTES */
        PetscCall(PCFieldSplitSetIS(pc, "1", s->is[1])); /* positions */
        PetscCall(PCFieldSplitGetType(pc, &type));
        PetscCall(PCFieldSplitGetSchurPre(pc, &pre, &pmat)); /* (the matrix argument may not be NULL in 3.18) */
        if (type == PC_COMPOSITE_SCHUR && pre == PC_FIELDSPLIT_SCHUR_PRE_USER) {
          PetscCall(AssembleSchur(s, iq, tmu, X));
          PetscCall(PCFieldSplitSetSchurPre(pc, PC_FIELDSPLIT_SCHUR_PRE_USER, s->S));
        }
      }
    }
    s->have_pc = PETSC_TRUE;
    s->setups++; /* 1 at the first call; more after a new solver (failed factorisation) */
    s->reusing = PETSC_FALSE;
    PetscCall(KSPSetReusePreconditioner(s->ksp, PETSC_FALSE));
    PetscCall(KSPGetTolerances(s->ksp, NULL, NULL, NULL, &s->max_it));
    { /* a kept preconditioner needs a Krylov method to correct it: with preonly it would give wrong steps */
      PetscBool preonly;
      PetscCall(PetscObjectTypeCompare((PetscObject)s->ksp, KSPPREONLY, &preonly));
      if (preonly) s->reuse_its = 0;
      s->krylov = (PetscBool)!preonly;
      /* tolerances relative to |b| (the zero-guess residual), also for the bordering solves that start from the
         previous step's solution: the same accuracy, fewer iterations */
      if (s->krylov) PetscCall(KSPConvergedDefaultSetUIRNorm(s->ksp));
    }
  } else {
    /* an earlier factorisation is a strong preconditioner for the slightly changed matrix (PETSC-NOTES). To
       keep it, S is left as it is (the Schur sub-solver refactors whenever S changes). Reuse while the last
       solve was cheap; after a failed attempt (more than reuse_its iterations with the kept factorisation)
       take 1, 2, 4, ... 16 fresh steps before trying again: early in a run the surface changes fast and every
       attempt would waste its iterations. */
    if (s->wait > 0) {
      s->reusing = PETSC_FALSE;
      s->wait--;
    } else s->reusing = (PetscBool)(s->reuse_its > 0 && s->last_its <= s->reuse_its);
    if (!s->reusing) {
      if (s->S) PetscCall(AssembleSchur(s, iq, tmu, X));
      s->setups++;
    }
    PetscCall(KSPSetReusePreconditioner(s->ksp, s->reusing));
  }
  s->iq  = iq; /* for a refresh in KSolve */
  s->tmu = tmu;
  s->X   = X;
  PetscFunctionReturn(0);
}

/* A solve with a kept preconditioner is given at most 2 reuse_its (at least 20) iterations; if it needs more,
   the preconditioner is rebuilt for the current matrix and the solve repeated, so a stale factorisation
   costs a bounded number of wasted iterations and never a rejected step. */
static PetscErrorCode KSolve(CSSaddle *s, Vec b, Vec z, PetscInt *its)
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
    if (n > s->reuse_its) { /* a failed attempt: back off */
      s->backoff = PetscMin(16, PetscMax(1, 2 * s->backoff));
      s->wait    = s->backoff;
    } else s->backoff = 0;
    *its += n; /* spent, even if wasted */
    if (reason > 0) PetscFunctionReturn(0);
    s->reusing = PETSC_FALSE;
    s->setups++;
    if (s->S) PetscCall(AssembleSchur(s, s->iq, s->tmu, s->X));
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
  PetscCheck(reason > 0, s->mesh->comm, PETSC_ERR_NOT_CONVERGED, "flow: the linear solve (prefix -flow_) did not converge: %s after %" PetscInt_FMT " iterations; try -flow_saddle_mat aij -flow_pc_type cholesky -flow_pc_factor_mat_solver_type mumps, or a smaller -flow_t", KSPConvergedReasons[reason], n);
  *its += n;
  PetscFunctionReturn(0);
}

/* k x k dense solve (column-major S), Gaussian elimination with partial pivoting; k is a handful. */
static PetscErrorCode SmallSolve(MPI_Comm comm, PetscInt k, PetscScalar *S, PetscScalar *b)
{
  PetscReal big = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < k * k; i++) big = PetscMax(big, PetscAbsScalar(S[i]));
  for (PetscInt c = 0; c < k; c++) {
    PetscInt p = c;
    for (PetscInt r = c + 1; r < k; r++)
      if (PetscAbsScalar(S[r + c * k]) > PetscAbsScalar(S[p + c * k])) p = r;
    PetscCheck(PetscAbsScalar(S[p + c * k]) > 1e-14 * big, comm, PETSC_ERR_MAT_LU_ZRPVT, "flow: the bordered system of the area/volume/point constraints is singular: are the constraints dependent (e.g. area + volume + points fixing the same thing)?");
    if (p != c) {
      for (PetscInt j = 0; j < k; j++) {
        PetscScalar tmp = S[c + j * k];
        S[c + j * k]    = S[p + j * k];
        S[p + j * k]    = tmp;
      }
      PetscScalar tb = b[c];
      b[c]           = b[p];
      b[p]           = tb;
    }
    for (PetscInt r = c + 1; r < k; r++) {
      PetscScalar f = S[r + c * k] / S[c + c * k];
      for (PetscInt j = c; j < k; j++) S[r + j * k] -= f * S[c + j * k];
      b[r] -= f * b[c];
    }
  }
  for (PetscInt c = k - 1; c >= 0; c--) {
    for (PetscInt j = c + 1; j < k; j++) b[c] -= S[c + j * k] * b[j];
    b[c] /= S[c + c * k];
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSSaddleSolve(CSSaddle *s, Vec rE, Vec rV, const PetscReal rX[], Vec zE, Vec zV, PetscReal zX[], PetscInt *its)
{
  PetscInt n = 0, nfirst;
  PetscFunctionBeginUser;
  if (s->edges) {
    Vec sub;
    PetscCall(VecGetSubVector(s->b, s->is[0], &sub));
    PetscCall(VecCopy(rE, sub));
    PetscCall(VecRestoreSubVector(s->b, s->is[0], &sub));
    PetscCall(VecGetSubVector(s->b, s->is[1], &sub));
    PetscCall(VecCopy(rV, sub));
    PetscCall(VecRestoreSubVector(s->b, s->is[1], &sub));
  } else PetscCall(VecCopy(rV, s->b));
  PetscCall(KSPSetInitialGuessNonzero(s->ksp, PETSC_FALSE));
  PetscCall(KSolve(s, s->b, s->z, &n));
  nfirst = s->last_its; /* the iterations of the (last) solve of the step's own right-hand side */
  if (s->k) {
    /* bordering: z = K^{-1}(r - B zX), (B^T K^{-1} B + G) zX = B^T K^{-1} r - rX */
    PetscScalar   *S, *rhs;
    PetscErrorCode ierr;
    /* the solves first: a failed one (a rejected step, retried by the flow) then leaves nothing allocated */
    /* W_j = K^{-1} B_j changes little from step to step: start from the last one (Krylov solvers only) */
    PetscCall(KSPSetInitialGuessNonzero(s->ksp, s->krylov));
    for (PetscInt j = 0; j < s->k; j++) PetscCall(KSolve(s, s->B[j], s->W[j], &n)); /* (reset before the next step's first solve) */
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
  if (s->edges) {
    Vec sub;
    PetscCall(VecGetSubVector(s->z, s->is[0], &sub));
    PetscCall(VecCopy(sub, zE));
    PetscCall(VecRestoreSubVector(s->z, s->is[0], &sub));
    PetscCall(VecGetSubVector(s->z, s->is[1], &sub));
    PetscCall(VecCopy(sub, zV));
    PetscCall(VecRestoreSubVector(s->z, s->is[1], &sub));
  } else PetscCall(VecCopy(s->z, zV));
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
  }
  PetscCall(PetscFree(s->B));
  PetscCall(PetscFree(s->W));
  PetscCall(PetscFree(s->G));
  /* preset defaults that the chosen solver did not read are removed, so they do not count as unused */
  for (PetscInt i = 0; i < s->npreset; i++) {
    PetscBool used;
    PetscCall(PetscOptionsUsed(NULL, s->preset[i], &used));
    if (!used) PetscCall(PetscOptionsClearValue(NULL, s->preset[i]));
    PetscCall(PetscFree(s->preset[i]));
  }
  PetscCall(PetscFree(s->preset));
  PetscFunctionReturn(0);
}
