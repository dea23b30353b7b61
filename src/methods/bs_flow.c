/* Discrete Willmore flow of bobenko-schroeder2005 (Sec. 4): semi-implicit steps with the linearised Hessian
   K of Eq. 1, and the static problem / backward Euler through TAO. See include/cs_methods_bs.h. */
#include <petscksp.h>
#include <petscmat.h>
#include <petsctao.h>
#include "cs_methods_bs.h"

typedef enum {
  BS_SCHEME_SEMI,
  BS_SCHEME_TAO
} BSScheme;
static const char *const BSSchemes[] = {"semi", "tao", "BSScheme", "BS_SCHEME_", NULL};
typedef enum {
  BS_TAO_STATIC,
  BS_TAO_EULER
} BSTaoMode;
static const char *const BSTaoModes[] = {"static", "euler", "BSTaoMode", "BS_TAO_", NULL};

typedef struct {
  CSMesh           mesh;
  CSEnergy         bs, will;
  CSOutput        *out;
  CSHistory        hist;
  CSViewer         viewer;
  Vec              x0;     /* initial positions: fixed vertices are reset to them */
  Vec              xn;     /* backward Euler: previous step */
  Vec              xw;     /* work: TAO's iterate with the fixed vertices reset */
  Vec              Wv;     /* per-vertex W_i for the viewer */
  const PetscBool *fixed;
  PetscInt         nfixed;
  PetscReal        dt, atol, rtol, dtgrow, dtmax;
  BSTaoMode        mode;
  Mat              K, K3;
  PetscLogDouble   t0;
  PetscInt         step;   /* history row counter */
  PetscInt         vevery;
  PetscBool        monotone;
  /* checkpoint/resume (semi scheme): the loop state restored by -resume */
  PetscBool        resumed;
  PetscInt         it0, rej0;
  PetscLogDouble   tsteps0;
  const char      *stop;   /* why the run stopped (summary key stop_reason) */
} BSFlow;

/* x <- x with every fixed vertex set back to x0 (keeps G1 data bit-identical, Sec. 3.3). */
static PetscErrorCode ResetFixed(BSFlow *F, Vec x)
{
  CSMesh             m = F->mesh;
  PetscScalar       *a;
  const PetscScalar *a0;
  PetscInt           n = 0;
  PetscFunctionBeginUser;
  if (!F->nfixed) PetscFunctionReturn(0);
  PetscCall(VecGetArray(x, &a));
  PetscCall(VecGetArrayRead(F->x0, &a0));
  for (PetscInt v = 0; v < m->nv; v++) {
    if (!m->vertOwned[v]) continue;
    if (F->fixed[v])
      for (int d = 0; d < 3; d++) a[3 * n + d] = a0[3 * n + d];
    n++;
  }
  PetscCall(VecRestoreArrayRead(F->x0, &a0));
  PetscCall(VecRestoreArray(x, &a));
  PetscFunctionReturn(0);
}

/* One history row (and a ParaView step). */
static PetscErrorCode Record(BSFlow *F, Vec x, PetscReal W, PetscReal dt, PetscInt kspits)
{
  PetscReal      Wc, area, vol, row[7];
  PetscLogDouble t;
  PetscFunctionBeginUser;
  if (F->hist) {
    PetscCall(CSEnergyValue(F->will, x, &Wc));
    PetscCall(CSGeometryAreaVolume(F->mesh, x, &area, &vol));
    PetscCall(PetscTime(&t));
    row[0] = (PetscReal)F->step;
    row[1] = W;
    row[2] = Wc;
    row[3] = area;
    row[4] = dt;
    row[5] = (PetscReal)kspits;
    row[6] = (PetscReal)(t - F->t0);
    PetscCall(CSHistoryAppend(F->hist, 7, row));
  }
  if (F->viewer && (F->step % F->vevery == 0)) {
    PetscCall(CSEnergyWillmoreBSVertex(F->bs, x, F->Wv, NULL));
    PetscCall(CSViewerAddVertexField(F->viewer, "W_i", F->Wv));
    PetscCall(CSViewerWriteStep(F->viewer, x, (PetscReal)F->step));
  }
  F->step++;
  PetscFunctionReturn(0);
}

static PetscErrorCode MeanEdgeLength(CSMesh m, Vec x, PetscReal *h)
{
  Vec         l;
  PetscScalar s;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(m->dmE1, &l));
  PetscCall(CSGeometryEdgeLengths(m, x, l));
  PetscCall(VecSum(l, &s));
  *h = PetscRealPart(s) / (PetscReal)m->Ne;
  PetscCall(VecDestroy(&l));
  PetscFunctionReturn(0);
}

/* AMD ordering (ICNTL(7) = 0) for a MUMPS factorisation unless the user chose one with -<prefix>mat_mumps_icntl_7
   (PETSC-NOTES: Debian's MUMPS falls back to the slow, fill-heavy PORD). Call after KSPSetOperators. */
static PetscErrorCode MumpsDefaults(KSP ksp, const char prefix[])
{
  PC            pc;
  PetscBool     chol, lu, set;
  MatSolverType st;
  PetscFunctionBeginUser;
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCCHOLESKY, &chol));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCLU, &lu));
  if (!chol && !lu) PetscFunctionReturn(0);
  PetscCall(PCFactorGetMatSolverType(pc, &st));
  if (!st || strcmp(st, MATSOLVERMUMPS)) PetscFunctionReturn(0);
  PetscCall(PetscOptionsHasName(NULL, prefix, "-mat_mumps_icntl_7", &set));
  if (set) PetscFunctionReturn(0);
  {
    Mat Fm;
    PetscCall(PCFactorSetUpMatSolverType(pc));
    PetscCall(PCFactorGetMatrix(pc, &Fm));
    PetscCall(MatMumpsSetIcntl(Fm, 7, 0));
  }
  PetscFunctionReturn(0);
}

/* ------------------------------------------------------------------ semi-implicit (Sec. 4) */
/* The semi scheme's loop state after `it` accepted steps: x, and the scalars [dt, rejected, seconds of the
   history clock, seconds spent in steps]; everything else (W, grad W, K) is recomputed from x, so a resumed run
   continues exactly like the uninterrupted one. */
#define BS_CHECKPOINT_NREAL 4
static PetscErrorCode Checkpoint(BSFlow *F, Vec x, PetscInt it, PetscBool force, PetscInt rej, PetscLogDouble tsteps)
{
  PetscReal      r[BS_CHECKPOINT_NREAL];
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  r[0] = F->dt;
  r[1] = (PetscReal)rej;
  r[2] = (PetscReal)(now - F->t0);
  r[3] = (PetscReal)tsteps;
  PetscCall(CSOutputCheckpoint(F->out, F->mesh, F->x0, it, force, BS_CHECKPOINT_NREAL, r, x, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode RunSemi(BSFlow *F, Vec x, PetscInt maxit, PetscReal dtgrow, PetscReal dtmax, PetscInt maxrej, PetscInt *iters, PetscInt *rejected, PetscBool *converged, PetscReal *Wfinal, PetscLogDouble *tsteps)
{
  CSMesh         m = F->mesh;
  KSP            ksp;
  Vec            g, xnew, b1, z1;
  PetscReal      W, Wnew, shift = 0;
  PetscInt       it = F->it0, rej = F->rej0, consecutive = 0;
  PetscBool      first = PETSC_TRUE;
  PetscLogDouble ta, tb;
  PetscFunctionBeginUser;
  *converged = PETSC_FALSE;
  F->stop    = "max_it";
  PetscCall(VecDuplicate(x, &g));
  PetscCall(VecDuplicate(x, &xnew));
  PetscCall(DMCreateGlobalVector(m->dmV1, &b1));
  PetscCall(VecDuplicate(b1, &z1));
  PetscCall(KSPCreate(m->comm, &ksp));
  PetscCall(KSPSetOptionsPrefix(ksp, "bs_"));
  /* Default: MUMPS LDL^T (symmetric indefinite: 1/dt I + K is indefinite at large dt), AMD ordering
     (PETSC-NOTES: Debian's MUMPS has no METIS/SCOTCH; PORD is slow). Measured (runs/bench_bs.sh, bunny 75k
     faces, serial): 0.66 s per step against 3.2 s for CG + BoomerAMG (17 its per solve); CG + GAMG declares
     the preconditioner indefinite at larger dt (8 rejected steps on the icosahedron test, 21 steps instead
     of 9). CHOLMOD is no option: it stops with an error on an indefinite matrix instead of letting the step
     control reject the step. Iterative alternative: -bs_ksp_type cg -bs_pc_type hypre (rtol 1e-6 default). */
  PetscCall(KSPSetType(ksp, KSPPREONLY));
  {
    PC pc;
    PetscCall(KSPGetPC(ksp, &pc));
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  }
  PetscCall(KSPSetTolerances(ksp, 1e-6, 1e-50, PETSC_DEFAULT, 1000));
  PetscCall(KSPSetFromOptions(ksp));

  PetscCall(PetscTime(&ta));
  PetscCall(CSEnergyWillmoreBSHessian(F->bs, x, 0, MAT_INITIAL_MATRIX, &F->K, &W, g));
  if (!F->resumed) PetscCall(Record(F, x, W, F->dt, 0)); /* a resumed history already has this row */
  PetscCall(PetscPrintf(m->comm, "bs semi step %3" PetscInt_FMT "  W=%.10e  dt=%.3e%s\n", it, (double)W, (double)F->dt, F->resumed ? "  (resumed)" : ""));
  while (it < maxit) {
    PetscInt           kits = 0;
    PetscBool          ok   = PETSC_TRUE;
    KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
    /* A = 1/dt I + K (Sec. 4); shift holds the 1/dt already added to K */
    PetscCall(MatShift(F->K, 1.0 / F->dt - shift));
    shift = 1.0 / F->dt;
    PetscCall(KSPSetOperators(ksp, F->K, F->K));
    if (first) PetscCall(MumpsDefaults(ksp, "bs_"));
    first = PETSC_FALSE;
    for (PetscInt d = 0; d < 3 && ok; d++) {
      PetscInt its;
      PetscCall(VecStrideGather(g, d, b1, INSERT_VALUES));
      PetscCall(VecScale(b1, -1));
      PetscCall(KSPSolve(ksp, b1, z1));
      PetscCall(KSPGetConvergedReason(ksp, &reason));
      PetscCall(KSPGetIterationNumber(ksp, &its));
      kits += its;
      if (reason < 0) ok = PETSC_FALSE;
      else PetscCall(VecStrideScatter(z1, d, xnew, INSERT_VALUES));
    }
    if (ok) {
      PetscCall(VecAXPY(xnew, 1, x)); /* xnew held dx */
      PetscCall(ResetFixed(F, xnew));
      PetscCall(CSEnergyValue(F->bs, xnew, &Wnew));
      /* -bs_monotone false: the paper's plain stepping, which must accept increases while diamonds leave
         beta = 0 (Sec. 4, Fig. 10: the heuristic's zero gradient is not a descent direction there) */
      ok = (PetscBool)(!PetscIsInfOrNanReal(Wnew) && (Wnew <= W || !F->monotone));
    }
    if (!ok) {
      rej++;
      PetscCall(PetscPrintf(m->comm, "bs semi: step rejected (%s), dt %.3e -> %.3e\n", reason < 0 ? KSPConvergedReasons[reason] : "energy increased", (double)F->dt, (double)(F->dt / 4)));
      F->dt /= 4;
      if (++consecutive > maxrej) {
        PetscCall(PetscPrintf(m->comm, "bs semi: %" PetscInt_FMT " consecutive rejected steps (-bs_max_rejections), stopping with the last accepted state (step %" PetscInt_FMT ")\n", consecutive, it));
        F->stop = "rejections";
        break;
      }
      continue;
    }
    consecutive = 0;
    it++;
    PetscCall(VecCopy(xnew, x));
    {
      PetscReal Wold = W;
      PetscCall(CSEnergyWillmoreBSHessian(F->bs, x, 0, MAT_REUSE_MATRIX, &F->K, &W, g));
      shift = 0;
      PetscCall(Record(F, x, W, F->dt, kits));
      PetscCall(PetscPrintf(m->comm, "bs semi step %3" PetscInt_FMT "  W=%.10e  dt=%.3e  ksp_its=%" PetscInt_FMT "\n", it, (double)W, (double)F->dt, kits));
      if (W < F->atol || (W <= Wold && Wold - W <= F->rtol * Wold)) {
        *converged = PETSC_TRUE;
        F->stop    = "converged";
        break;
      }
    }
    F->dt = PetscMin(F->dt * dtgrow, dtmax);
    PetscCall(PetscTime(&tb));
    PetscCall(Checkpoint(F, x, it, PETSC_FALSE, rej, F->tsteps0 + tb - ta));
  }
  PetscCall(PetscTime(&tb));
  *tsteps = F->tsteps0 + tb - ta;
  PetscCall(Checkpoint(F, x, it, PETSC_TRUE, rej, *tsteps)); /* the last accepted state, converged or not */
  *iters    = it;
  *rejected = rej;
  *Wfinal   = W;
  PetscCall(KSPDestroy(&ksp));
  PetscCall(VecDestroy(&g));
  PetscCall(VecDestroy(&xnew));
  PetscCall(VecDestroy(&b1));
  PetscCall(VecDestroy(&z1));
  PetscFunctionReturn(0);
}

/* ------------------------------------------------------------------ TAO (Sec. 4: "PETSc and TAO") */
static PetscErrorCode TaoFG(Tao tao, Vec x, PetscReal *f, Vec g, void *ctx)
{
  BSFlow *F = (BSFlow *)ctx;
  PetscFunctionBeginUser;
  PetscCall(VecCopy(x, F->xw));
  PetscCall(ResetFixed(F, F->xw));
  PetscCall(CSEnergyGradient(F->bs, F->xw, f, g));
  if (F->mode == BS_TAO_EULER) {
    Vec       dx;
    PetscReal n2;
    PetscCall(VecDuplicate(x, &dx));
    PetscCall(VecWAXPY(dx, -1, F->xn, F->xw));
    PetscCall(VecNorm(dx, NORM_2, &n2));
    *f += n2 * n2 / (2 * F->dt);
    PetscCall(ResetFixed(F, dx)); /* xw - xn is 0 there anyway; keeps g exactly 0 on fixed vertices */
    PetscCall(VecAXPY(g, 1.0 / F->dt, dx));
    PetscCall(VecDestroy(&dx));
  }
  PetscFunctionReturn(0);
}

/* K on each coordinate: (3r+d, 3c+d) = K_rc, with 1 on fixed diagonals (and + 1/dt for backward Euler). */
static PetscErrorCode TaoHess(Tao tao, Vec x, Mat H, Mat Hpre, void *ctx)
{
  BSFlow  *F = (BSFlow *)ctx;
  PetscInt rs, re;
  PetscFunctionBeginUser;
  PetscCall(VecCopy(x, F->xw));
  PetscCall(ResetFixed(F, F->xw));
  PetscCall(CSEnergyWillmoreBSHessian(F->bs, F->xw, 1, F->K ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &F->K, NULL, NULL));
  PetscCall(MatGetOwnershipRange(F->K, &rs, &re));
  if (!F->K3) {
    PetscInt *nnz;
    PetscCall(PetscMalloc1(3 * (re - rs), &nnz));
    for (PetscInt r = rs; r < re; r++) {
      PetscInt nc;
      PetscCall(MatGetRow(F->K, r, &nc, NULL, NULL));
      for (int d = 0; d < 3; d++) nnz[3 * (r - rs) + d] = nc;
      PetscCall(MatRestoreRow(F->K, r, &nc, NULL, NULL));
    }
    PetscCall(MatCreate(F->mesh->comm, &F->K3));
    PetscCall(MatSetSizes(F->K3, 3 * (re - rs), 3 * (re - rs), 3 * F->mesh->Nv, 3 * F->mesh->Nv));
    PetscCall(MatSetType(F->K3, MATAIJ));
    PetscCall(MatSetBlockSize(F->K3, 3));
    PetscCall(MatSeqAIJSetPreallocation(F->K3, 0, nnz));
    PetscCall(MatMPIAIJSetPreallocation(F->K3, 0, nnz, 0, nnz));
    PetscCall(MatSetOption(F->K3, MAT_SYMMETRIC, PETSC_TRUE)); /* K is symmetric (checked in test_bs_energy) */
    PetscCall(PetscFree(nnz));
  } else PetscCall(MatZeroEntries(F->K3));
  for (PetscInt r = rs; r < re; r++) {
    PetscInt           nc, *c3, cmax = 0;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(F->K, r, &nc, &cols, &vals));
    cmax = nc;
    PetscCall(PetscMalloc1(cmax, &c3));
    for (int d = 0; d < 3; d++) {
      PetscInt row = 3 * r + d;
      for (PetscInt k = 0; k < nc; k++) c3[k] = 3 * cols[k] + d;
      PetscCall(MatSetValues(F->K3, 1, &row, nc, c3, vals, INSERT_VALUES));
    }
    PetscCall(PetscFree(c3));
    PetscCall(MatRestoreRow(F->K, r, &nc, &cols, &vals));
  }
  PetscCall(MatAssemblyBegin(F->K3, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(F->K3, MAT_FINAL_ASSEMBLY));
  /* K alone is useless as a Newton Hessian: grad W = K x exactly, so K d = -grad W gives d = -x + const, a
     homothety along which the scale-invariant W does not change. Backward Euler adds I/dt; the static
     problem gets the same proximal (Levenberg-Marquardt) term with dt growing by -bs_dt_grow per Hessian
     (the semi-implicit step of Sec. 4 with TAO's line search on top). */
  PetscCall(MatShift(F->K3, 1.0 / F->dt));
  if (F->mode == BS_TAO_STATIC && tao) F->dt = PetscMin(F->dt * F->dtgrow, F->dtmax);
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoMon(Tao tao, void *ctx)
{
  BSFlow   *F = (BSFlow *)ctx;
  PetscInt  its;
  PetscReal f, gn;
  Vec       x;
  PetscFunctionBeginUser;
  if (F->mode != BS_TAO_STATIC) PetscFunctionReturn(0);
  PetscCall(TaoGetSolutionStatus(tao, &its, &f, &gn, NULL, NULL, NULL));
  PetscCall(TaoGetSolution(tao, &x));
  PetscCall(VecCopy(x, F->xw));
  PetscCall(ResetFixed(F, F->xw));
  PetscCall(Record(F, F->xw, f, 0, 0));
  PetscCall(PetscPrintf(F->mesh->comm, "bs tao it %3" PetscInt_FMT "  W=%.10e  |g|=%.3e\n", its, (double)f, (double)gn));
  PetscFunctionReturn(0);
}

/* TAO's own tests, then W < atol (the minimum of a closed genus-0 surface is 0). */
static PetscErrorCode TaoConv(Tao tao, void *ctx)
{
  BSFlow   *F = (BSFlow *)ctx;
  PetscReal f;
  PetscFunctionBeginUser;
  PetscCall(TaoDefaultConvergenceTest(tao, NULL));
  if (F->mode == BS_TAO_STATIC) {
    TaoConvergedReason r;
    PetscCall(TaoGetConvergedReason(tao, &r));
    PetscCall(TaoGetSolutionStatus(tao, NULL, &f, NULL, NULL, NULL, NULL));
    if (r == TAO_CONTINUE_ITERATING && f < F->atol) PetscCall(TaoSetConvergedReason(tao, TAO_CONVERGED_USER));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode RunTao(BSFlow *F, Vec x, PetscInt maxit, PetscReal dtgrow, PetscReal dtmax, PetscInt *iters, PetscBool *converged, PetscReal *Wfinal, PetscLogDouble *tsteps)
{
  CSMesh             m = F->mesh;
  Tao                tao;
  TaoConvergedReason reason;
  PetscReal          W;
  PetscLogDouble     ta, tb;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(x, &F->xw));
  PetscCall(VecDuplicate(x, &F->xn));
  PetscCall(VecCopy(x, F->xn));
  PetscCall(TaoHess(NULL, x, NULL, NULL, F)); /* creates K and K3 */
  PetscCall(TaoCreate(m->comm, &tao));
  PetscCall(TaoSetOptionsPrefix(tao, "bs_"));
  PetscCall(TaoSetType(tao, TAONLS));
  {
    /* NLS's default Steihaug-CG trust region stalls here (it keeps the step at about one CG iteration, 100 its
       did not get below W = 20 on the icosahedron test); plain CG + BoomerAMG with the line search converges
       like the semi-implicit scheme. Options -bs_tao_nls_ksp_type / -bs_tao_nls_pc_type override. */
    KSP tksp;
    PC  tpc;
    PetscCall(TaoGetKSP(tao, &tksp));
    if (tksp) {
      PetscCall(KSPSetType(tksp, KSPCG));
      PetscCall(KSPGetPC(tksp, &tpc));
      PetscCall(PCSetType(tpc, PCHYPRE));
    }
  }
  PetscCall(TaoSetObjectiveAndGradient(tao, NULL, TaoFG, F));
  PetscCall(TaoSetHessian(tao, F->K3, F->K3, TaoHess, F));
  PetscCall(TaoSetConvergenceTest(tao, TaoConv, F));
  PetscCall(TaoSetMonitor(tao, TaoMon, F, NULL));
  PetscCall(TaoSetTolerances(tao, 1e-9, 0, 0));
  PetscCall(TaoSetMaximumIterations(tao, F->mode == BS_TAO_STATIC ? maxit : 50));
  PetscCall(TaoSetFromOptions(tao));
  PetscCall(PetscTime(&ta));
  *converged = PETSC_FALSE;
  if (F->mode == BS_TAO_STATIC) {
    PetscCall(TaoSetSolution(tao, x));
    PetscCall(TaoSolve(tao));
    PetscCall(TaoGetConvergedReason(tao, &reason));
    PetscCall(TaoGetIterationNumber(tao, iters));
    PetscCall(ResetFixed(F, x));
    PetscCall(CSEnergyValue(F->bs, x, &W));
    *converged = (PetscBool)(reason > 0);
    PetscCall(PetscPrintf(m->comm, "bs tao static: %s after %" PetscInt_FMT " iterations, W=%.10e\n", TaoConvergedReasons[reason], *iters, (double)W));
  } else {
    PetscInt it = 0;
    PetscCall(CSEnergyValue(F->bs, x, &W));
    PetscCall(Record(F, x, W, F->dt, 0));
    while (it < maxit) {
      PetscReal Wold = W;
      PetscInt  tits;
      PetscCall(VecCopy(x, F->xn));
      PetscCall(TaoSetSolution(tao, x));
      PetscCall(TaoSolve(tao));
      PetscCall(TaoGetConvergedReason(tao, &reason));
      PetscCall(TaoGetIterationNumber(tao, &tits));
      PetscCall(ResetFixed(F, x));
      PetscCall(CSEnergyValue(F->bs, x, &W));
      it++;
      PetscCall(Record(F, x, W, F->dt, tits));
      PetscCall(PetscPrintf(m->comm, "bs tao euler step %3" PetscInt_FMT "  W=%.10e  dt=%.3e  tao_its=%" PetscInt_FMT " (%s)\n", it, (double)W, (double)F->dt, tits, TaoConvergedReasons[reason]));
      PetscCheck(!PetscIsInfOrNanReal(W), m->comm, PETSC_ERR_NOT_CONVERGED, "bs tao euler: W is not finite after step %" PetscInt_FMT " (reduce -bs_dt)", it);
      if (W < F->atol || PetscAbsReal(Wold - W) <= F->rtol * Wold) {
        *converged = PETSC_TRUE;
        break;
      }
      F->dt = PetscMin(F->dt * dtgrow, dtmax);
    }
    *iters = it;
  }
  PetscCall(PetscTime(&tb));
  *tsteps = tb - ta;
  *Wfinal = W;
  PetscCall(TaoDestroy(&tao));
  PetscFunctionReturn(0);
}

PetscErrorCode CSFlowBS(MPI_Comm comm, CSOutput *out)
{
  BSFlow         F;
  CSMesh         mesh;
  PetscInt       maxrej = 30, scheme = BS_SCHEME_SEMI, bc = CS_BS_BOUNDARY_FIXED, mode = BS_TAO_STATIC, maxit = 100, iters = 0, rejected = 0;
  PetscReal      epsK = 0, perturb = 0, eps = 1e-6, dt = 0, dtrel = 1, dtgrow = 2, dtmax = 0, Wfinal = 0, h = 0;
  PetscBool      converged = PETSC_FALSE, dtset, epsKset = PETSC_FALSE;
  PetscLogDouble tsteps = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&F, sizeof(F)));
  F.atol   = 1e-8;
  F.rtol   = 1e-9;
  F.vevery   = 1;
  F.monotone = PETSC_TRUE;
  PetscOptionsBegin(comm, NULL, "Bobenko-Schroeder Willmore flow (bobenko-schroeder2005)", NULL);
  PetscCall(PetscOptionsEList("-bs_scheme", "semi: semi-implicit (1/dt I + K) dx = -grad W; tao: TAO (static problem or backward Euler)", NULL, BSSchemes, 2, BSSchemes[scheme], &scheme, NULL));
  PetscCall(PetscOptionsEList("-bs_boundary", "fixed: G1, boundary and one-ring fixed; free: vertex at infinity (Sec. 3.3)", NULL, CSBSBoundaries, 2, CSBSBoundaries[bc], &bc, NULL));
  PetscCall(PetscOptionsReal("-bs_beta_eps", "Diamonds with |sin beta| below this contribute no gradient (Sec. 3.2)", NULL, eps, &eps, NULL));
  PetscCall(PetscOptionsInt("-bs_max_it", "Maximum number of accepted steps (TAO static: iterations)", NULL, maxit, &maxit, NULL));
  PetscCall(PetscOptionsReal("-bs_dt", "Initial time step (units length^2); default -bs_dt_rel times the squared mean edge length", NULL, dt, &dt, &dtset));
  PetscCall(PetscOptionsReal("-bs_dt_rel", "Initial time step relative to the squared mean edge length", NULL, dtrel, &dtrel, NULL));
  PetscCall(PetscOptionsReal("-bs_dt_grow", "Factor on dt after an accepted step", NULL, dtgrow, &dtgrow, NULL));
  PetscCall(PetscOptionsReal("-bs_dt_max", "Largest dt (default 1e4 times the initial dt)", NULL, dtmax, &dtmax, NULL));
  PetscCall(PetscOptionsInt("-bs_max_rejections", "semi: consecutive rejected steps (each divides dt by 4) before giving up", NULL, maxrej, &maxrej, NULL));
  PetscCall(PetscOptionsReal("-bs_atol", "Stop when W is below this", NULL, F.atol, &F.atol, NULL));
  PetscCall(PetscOptionsReal("-bs_rtol", "Stop when a step decreases W by less than this fraction", NULL, F.rtol, &F.rtol, NULL));
  PetscCall(PetscOptionsEList("-bs_tao_mode", "static: minimise W in one TaoSolve; euler: backward Euler steps through TAO", NULL, BSTaoModes, 2, BSTaoModes[mode], &mode, NULL));
  PetscCall(PetscOptionsReal("-bs_hessian_eps", "Leave diamonds with sin beta below this out of K (default -bs_beta_eps)", NULL, epsK, &epsK, &epsKset));
  PetscCall(PetscOptionsReal("-bs_perturb", "Move the free vertices randomly by this fraction of the mean edge length before flowing (breaks co-circular diamonds, beta = 0, of grid-like meshes)", NULL, perturb, &perturb, NULL));
  PetscCall(PetscOptionsBool("-bs_monotone", "semi: reject steps that increase W (false: accept them, as needed when many diamonds start at beta = 0)", NULL, F.monotone, &F.monotone, NULL));
  PetscCall(PetscOptionsInt("-bs_viewer_every", "Write a ParaView step every this many steps (with -viewer_dir)", NULL, F.vevery, &F.vevery, NULL));
  PetscOptionsEnd();
  PetscCheck(maxrej >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_max_rejections %" PetscInt_FMT ": must be >= 0", maxrej);
  PetscCheck(maxit >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_max_it %" PetscInt_FMT ": must be >= 0", maxit);
  PetscCheck(!dtset || dt > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_dt %g: must be > 0", (double)dt);
  PetscCheck(dtrel > 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_dt_rel %g: must be > 0", (double)dtrel);
  PetscCheck(dtgrow >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_dt_grow %g: must be >= 1", (double)dtgrow);
  PetscCheck(dtmax >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_dt_max %g: must be > 0", (double)dtmax);
  PetscCheck(F.atol >= 0 && F.rtol >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_atol/-bs_rtol must be >= 0");
  PetscCheck(F.vevery >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_viewer_every %" PetscInt_FMT ": must be >= 1", F.vevery);
  PetscCheck(perturb >= 0 && perturb < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_perturb %g: must lie in [0, 1)", (double)perturb);
  PetscCheck(eps >= 0 && eps < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_beta_eps %g: must lie in [0, 1)", (double)eps);

  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  F.mesh = mesh;
  F.out  = out;
  F.mode = (BSTaoMode)mode;
  PetscCall(PetscTime(&F.t0));
  PetscCall(CSEnergyCreateWillmoreBS(mesh, (CSBSBoundary)bc, eps, &F.bs));
  if (epsKset) {
    PetscCheck(epsK >= eps && epsK < 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_hessian_eps %g: must lie in [-bs_beta_eps, 1)", (double)epsK);
    PetscCall(CSEnergyWillmoreBSSetHessianEps(F.bs, epsK));
  }
  PetscCall(CSEnergyCreateWillmore(mesh, &F.will));
  PetscCall(CSEnergyWillmoreBSGetFixed(F.bs, &F.fixed, &F.nfixed));
  PetscCall(VecDuplicate(mesh->x, &F.x0));
  PetscCall(VecCopy(mesh->x, F.x0));
  PetscCall(MeanEdgeLength(mesh, mesh->x, &h));
  if (perturb > 0) { /* fixed vertices are reset to x0 below, so G1 data stay untouched */
    PetscRandom rnd;
    Vec         d;
    PetscCall(PetscRandomCreate(comm, &rnd));
    PetscCall(PetscRandomSetInterval(rnd, -perturb * h, perturb * h));
    PetscCall(PetscRandomSetSeed(rnd, 20050705));
    PetscCall(PetscRandomSeed(rnd));
    PetscCall(VecDuplicate(mesh->x, &d));
    PetscCall(VecSetRandom(d, rnd));
    PetscCall(VecAXPY(mesh->x, 1, d));
    PetscCall(ResetFixed(&F, mesh->x));
    PetscCall(VecDestroy(&d));
    PetscCall(PetscRandomDestroy(&rnd));
  }
  F.dt = dtset ? dt : dtrel * h * h;
  if (dtmax == 0) dtmax = 1e4 * F.dt;
  F.dtgrow = dtgrow;
  F.dtmax  = dtmax;
  PetscCall(PetscPrintf(comm, "bs flow: scheme %s, boundary %s (%" PetscInt_FMT " fixed vertices), beta_eps %g, dt0 %.3e (mean edge %.3e)\n", BSSchemes[scheme], CSBSBoundaries[bc], F.nfixed, (double)eps, (double)F.dt, (double)h));
  if (scheme == BS_SCHEME_SEMI) {
    PetscReal r[BS_CHECKPOINT_NREAL];
    PetscCall(CSOutputResume(out, mesh, F.x0, &F.it0, BS_CHECKPOINT_NREAL, r, mesh->x, NULL, &F.resumed));
    if (F.resumed) {
      PetscLogDouble now;
      PetscCall(PetscTime(&now));
      F.dt      = r[0];
      F.rej0    = (PetscInt)r[1];
      F.t0      = now - r[2]; /* the history's seconds column continues */
      F.tsteps0 = r[3];
      F.step    = F.it0 + 1;  /* history row of the next accepted step (the row of step it0 is in the file) */
    }
  } else PetscCheck(!out->has_checkpoint && !out->has_resume, comm, PETSC_ERR_ARG_INCOMP, "-checkpoint/-resume: only -bs_scheme semi writes checkpoints");
  PetscCall(CSOutputHistoryCreate(out, comm, "it,willmore_bs,willmore,area,dt,ksp_its,seconds", F.it0 + 1, &F.hist));
  if (out->has_viewer) {
    PetscCall(CSViewerCreate(mesh, out->viewer_dir, &F.viewer));
    PetscCall(DMCreateGlobalVector(mesh->dmV1, &F.Wv));
  }

  if (scheme == BS_SCHEME_SEMI) PetscCall(RunSemi(&F, mesh->x, maxit, dtgrow, dtmax, maxrej, &iters, &rejected, &converged, &Wfinal, &tsteps));
  else PetscCall(RunTao(&F, mesh->x, maxit, dtgrow, dtmax, &iters, &converged, &Wfinal, &tsteps));
  PetscCall(PetscPrintf(comm, "bs flow: %s after %" PetscInt_FMT " steps (%" PetscInt_FMT " rejected), willmore_bs=%.12g, %.3g s per step\n", converged ? "converged" : "NOT converged", iters, rejected, (double)Wfinal, (double)(iters + rejected ? tsteps / (iters + rejected) : 0)));

  PetscCall(CSOutputAddMeshFacts(out, mesh, mesh->x, F.x0));
  PetscCall(CSJSONAddReal(out->json, "willmore_bs", Wfinal)); /* the flow's energy (with the infinity terms for -bs_boundary free) */
  PetscCall(CSJSONAddInt(out->json, "iterations", iters));
  PetscCall(CSJSONAddBool(out->json, "converged", converged));
  PetscCall(CSJSONAddString(out->json, "stop_reason", scheme == BS_SCHEME_SEMI ? F.stop : (converged ? "converged" : "not_converged")));
  PetscCall(CSJSONAddInt(out->json, "rejected", rejected));
  PetscCall(CSJSONAddInt(out->json, "fixed_vertices", F.nfixed));
  PetscCall(CSJSONAddReal(out->json, "dt_final", F.dt));
  PetscCall(CSJSONAddReal(out->json, "seconds_per_step", iters + rejected ? (PetscReal)tsteps / (iters + rejected) : 0));
  PetscCall(CSJSONAddString(out->json, "scheme", scheme == BS_SCHEME_SEMI ? "semi" : (mode == BS_TAO_STATIC ? "tao_static" : "tao_euler")));
  PetscCall(CSJSONAddString(out->json, "boundary", CSBSBoundaries[bc]));
  PetscCall(CSOutputFinish(out, mesh, mesh->x));

  PetscCall(CSHistoryDestroy(&F.hist));
  if (F.viewer) PetscCall(CSViewerDestroy(&F.viewer));
  PetscCall(VecDestroy(&F.Wv));
  PetscCall(VecDestroy(&F.x0));
  PetscCall(VecDestroy(&F.xn));
  PetscCall(VecDestroy(&F.xw));
  PetscCall(MatDestroy(&F.K));
  PetscCall(MatDestroy(&F.K3));
  PetscCall(CSEnergyDestroy(&F.bs));
  PetscCall(CSEnergyDestroy(&F.will));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}
