/* The Bobenko-Schroeder flow through TAO (bobenko-schroeder2005 Sec. 4: "PETSc and TAO"): the static problem
   min W in one TaoSolve (-bs_problem static) or backward Euler steps min W(x) + |x - x_n|^2 / (2 dt)
   (-bs_problem euler). TAO's options prefix is the flow's. */
#include <petsctao.h>
#include "bs_flow_impl.h"

typedef struct {
  Tao tao;
  Mat K, K3;
  Vec xn; /* backward Euler: previous step */
  Vec xw; /* work: TAO's iterate with the fixed vertices reset */
} BSTao;

static PetscErrorCode TaoFG(Tao tao, Vec x, PetscReal *f, Vec g, void *ctx)
{
  CSBSFlow F = (CSBSFlow)ctx;
  BSTao   *T = (BSTao *)F->data;
  PetscFunctionBeginUser;
  PetscCall(VecCopy(x, T->xw));
  PetscCall(CSBSFlowResetFixed(F, T->xw));
  PetscCall(CSEnergyGradient(F->bs, T->xw, f, g));
  if (F->problem == CS_BS_PROBLEM_EULER) {
    Vec       dx;
    PetscReal n2;
    PetscCall(VecDuplicate(x, &dx));
    PetscCall(VecWAXPY(dx, -1, T->xn, T->xw));
    PetscCall(VecNorm(dx, NORM_2, &n2));
    *f += n2 * n2 / (2 * F->dt);
    PetscCall(CSBSFlowResetFixed(F, dx)); /* xw - xn is 0 there anyway; keeps g exactly 0 on fixed vertices */
    PetscCall(VecAXPY(g, 1.0 / F->dt, dx));
    PetscCall(VecDestroy(&dx));
  }
  PetscFunctionReturn(0);
}

/* The 3V x 3V AIJ (block size 3) for K on each coordinate, preallocated from K's rows. */
static PetscErrorCode CreateK3(CSBSFlow F, BSTao *T)
{
  PetscInt  rs, re, *nnz;
  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(T->K, &rs, &re));
  PetscCall(PetscMalloc1(3 * (re - rs), &nnz));
  for (PetscInt r = rs; r < re; r++) {
    PetscInt nc;
    PetscCall(MatGetRow(T->K, r, &nc, NULL, NULL));
    for (int d = 0; d < 3; d++) nnz[3 * (r - rs) + d] = nc;
    PetscCall(MatRestoreRow(T->K, r, &nc, NULL, NULL));
  }
  PetscCall(MatCreate(F->mesh->comm, &T->K3));
  PetscCall(MatSetSizes(T->K3, 3 * (re - rs), 3 * (re - rs), 3 * F->mesh->Nv, 3 * F->mesh->Nv));
  PetscCall(MatSetType(T->K3, MATAIJ));
  PetscCall(MatSetBlockSize(T->K3, 3));
  PetscCall(MatSeqAIJSetPreallocation(T->K3, 0, nnz));
  PetscCall(MatMPIAIJSetPreallocation(T->K3, 0, nnz, 0, nnz));
  PetscCall(MatSetOption(T->K3, MAT_SYMMETRIC, PETSC_TRUE)); /* K is symmetric (checked in test_bs_energy) */
  PetscCall(PetscFree(nnz));
  PetscFunctionReturn(0);
}

/* K on each coordinate: (3r+d, 3c+d) = K_rc, with 1 on fixed diagonals, plus 1/dt. */
static PetscErrorCode TaoHess(Tao tao, Vec x, Mat H, Mat Hpre, void *ctx)
{
  CSBSFlow F = (CSBSFlow)ctx;
  BSTao   *T = (BSTao *)F->data;
  PetscInt rs, re;
  PetscFunctionBeginUser;
  PetscCall(VecCopy(x, T->xw));
  PetscCall(CSBSFlowResetFixed(F, T->xw));
  PetscCall(CSEnergyWillmoreBSHessian(F->bs, T->xw, 1, T->K ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &T->K, NULL, NULL));
  if (!T->K3) PetscCall(CreateK3(F, T));
  else PetscCall(MatZeroEntries(T->K3));
  PetscCall(MatGetOwnershipRange(T->K, &rs, &re));
  for (PetscInt r = rs; r < re; r++) {
    PetscInt           nc, *c3;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(T->K, r, &nc, &cols, &vals));
    PetscCall(PetscMalloc1(nc, &c3));
    for (int d = 0; d < 3; d++) {
      PetscInt row = 3 * r + d;
      for (PetscInt k = 0; k < nc; k++) c3[k] = 3 * cols[k] + d;
      PetscCall(MatSetValues(T->K3, 1, &row, nc, c3, vals, INSERT_VALUES));
    }
    PetscCall(PetscFree(c3));
    PetscCall(MatRestoreRow(T->K, r, &nc, &cols, &vals));
  }
  PetscCall(MatAssemblyBegin(T->K3, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(T->K3, MAT_FINAL_ASSEMBLY));
  /* K alone is useless as a Newton Hessian: grad W = K x exactly, so K d = -grad W gives d = -x + const, a
     homothety along which the scale-invariant W does not change. Backward Euler adds I/dt; the static
     problem gets the same proximal (Levenberg-Marquardt) term with dt growing by -bs_dt_grow per Hessian
     (the semi-implicit step of Sec. 4 with TAO's line search on top). */
  PetscCall(MatShift(T->K3, 1.0 / F->dt));
  if (F->problem == CS_BS_PROBLEM_STATIC && tao) F->dt = PetscMin(F->dt * F->dt_grow, F->dt_max);
  PetscFunctionReturn(0);
}

/* static problem: every TAO iteration is a monitored state */
static PetscErrorCode TaoMon(Tao tao, void *ctx)
{
  CSBSFlow        F = (CSBSFlow)ctx;
  BSTao          *T = (BSTao *)F->data;
  CSBSMonitorInfo info;
  Vec             x;
  PetscFunctionBeginUser;
  if (F->problem != CS_BS_PROBLEM_STATIC) PetscFunctionReturn(0);
  PetscCall(PetscMemzero(&info, sizeof(info)));
  info.event = CS_BS_MONITOR_STEP;
  PetscCall(TaoGetSolutionStatus(tao, &info.it, &info.W, &info.gnorm, NULL, NULL, NULL));
  PetscCall(TaoGetSolution(tao, &x));
  PetscCall(VecCopy(x, T->xw));
  PetscCall(CSBSFlowResetFixed(F, T->xw));
  F->xmon = T->xw;
  PetscCall(CSBSFlowMonitor(F, &info));
  F->xmon = F->x;
  PetscFunctionReturn(0);
}

/* TAO's own tests, then W < atol (the minimum of a closed genus-0 surface is 0). */
static PetscErrorCode TaoConv(Tao tao, void *ctx)
{
  CSBSFlow  F = (CSBSFlow)ctx;
  PetscReal f;
  PetscFunctionBeginUser;
  PetscCall(TaoDefaultConvergenceTest(tao, NULL));
  if (F->problem == CS_BS_PROBLEM_STATIC) {
    TaoConvergedReason r;
    PetscCall(TaoGetConvergedReason(tao, &r));
    PetscCall(TaoGetSolutionStatus(tao, NULL, &f, NULL, NULL, NULL, NULL));
    if (r == TAO_CONTINUE_ITERATING && f < F->atol) PetscCall(TaoSetConvergedReason(tao, TAO_CONVERGED_USER));
  }
  PetscFunctionReturn(0);
}

/* Default NLS with CG + BoomerAMG set before TaoSetFromOptions (docs/bs_flow.md: NLS's default Steihaug-CG
   trust region stalls here); -<prefix>tao_nls_ksp_type / _pc_type override. */
static PetscErrorCode TaoSchemeSetUp(CSBSFlow F)
{
  BSTao *T;
  KSP    tksp;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&T));
  F->data = T;
  PetscCall(VecDuplicate(F->x, &T->xw));
  PetscCall(VecDuplicate(F->x, &T->xn));
  PetscCall(VecCopy(F->x, T->xn));
  PetscCall(TaoHess(NULL, F->x, NULL, NULL, F)); /* creates K and K3 */
  PetscCall(TaoCreate(F->mesh->comm, &T->tao));
  PetscCall(TaoSetOptionsPrefix(T->tao, F->hdr.prefix));
  PetscCall(TaoSetType(T->tao, TAONLS));
  PetscCall(TaoGetKSP(T->tao, &tksp));
  if (tksp) {
    PC tpc;
    PetscCall(KSPSetType(tksp, KSPCG));
    PetscCall(KSPGetPC(tksp, &tpc));
    PetscCall(PCSetType(tpc, PCHYPRE));
  }
  PetscCall(TaoSetObjectiveAndGradient(T->tao, NULL, TaoFG, F));
  PetscCall(TaoSetHessian(T->tao, T->K3, T->K3, TaoHess, F));
  PetscCall(TaoSetConvergenceTest(T->tao, TaoConv, F));
  PetscCall(TaoSetMonitor(T->tao, TaoMon, F, NULL));
  PetscCall(TaoSetTolerances(T->tao, 1e-9, 0, 0));
  PetscCall(TaoSetMaximumIterations(T->tao, F->problem == CS_BS_PROBLEM_STATIC ? F->loop.max_it : 50));
  PetscCall(TaoSetFromOptions(T->tao));
  if (F->problem == CS_BS_PROBLEM_STATIC) F->ops = &CSBSSchemeTaoStatic;
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoStaticStart(CSBSFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyValue(F->bs, F->x, &F->W));
  PetscFunctionReturn(0);
}

/* the whole static problem in one TaoSolve */
static PetscErrorCode TaoStaticStep(CSBSFlow F)
{
  BSTao             *T = (BSTao *)F->data;
  TaoConvergedReason reason;
  PetscFunctionBeginUser;
  PetscCall(TaoSetSolution(T->tao, F->x));
  PetscCall(TaoSolve(T->tao));
  PetscCall(TaoGetConvergedReason(T->tao, &reason));
  PetscCall(TaoGetIterationNumber(T->tao, &F->it));
  PetscCall(CSBSFlowResetFixed(F, F->x));
  PetscCall(CSEnergyValue(F->bs, F->x, &F->W));
  F->reason = reason > 0 ? CS_BS_CONVERGED : CS_BS_DIVERGED_TAO;
  PetscCall(PetscPrintf(F->mesh->comm, "bs tao static: %s after %" PetscInt_FMT " iterations, W=%.10e\n", TaoConvergedReasons[reason], F->it, (double)F->W));
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoEulerStart(CSBSFlow F)
{
  CSBSMonitorInfo info;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyValue(F->bs, F->x, &F->W));
  PetscCall(PetscMemzero(&info, sizeof(info)));
  info.event = CS_BS_MONITOR_START;
  info.W     = F->W;
  info.dt    = F->dt;
  PetscCall(CSBSFlowMonitor(F, &info));
  PetscFunctionReturn(0);
}

/* one backward Euler step min W(x) + |x - x_n|^2 / (2 dt) */
static PetscErrorCode TaoEulerStep(CSBSFlow F)
{
  BSTao             *T    = (BSTao *)F->data;
  PetscReal          Wold = F->W;
  TaoConvergedReason reason;
  CSBSMonitorInfo    info;
  PetscFunctionBeginUser;
  PetscCall(VecCopy(F->x, T->xn));
  PetscCall(TaoSetSolution(T->tao, F->x));
  PetscCall(TaoSolve(T->tao));
  PetscCall(TaoGetConvergedReason(T->tao, &reason));
  PetscCall(PetscMemzero(&info, sizeof(info)));
  PetscCall(TaoGetIterationNumber(T->tao, &info.inner_its));
  PetscCall(CSBSFlowResetFixed(F, F->x));
  PetscCall(CSEnergyValue(F->bs, F->x, &F->W));
  F->it++;
  info.event        = CS_BS_MONITOR_STEP;
  info.it           = F->it;
  info.W            = F->W;
  info.dt           = F->dt;
  info.inner_reason = TaoConvergedReasons[reason];
  PetscCall(CSBSFlowMonitor(F, &info));
  PetscCheck(!PetscIsInfOrNanReal(F->W), F->mesh->comm, PETSC_ERR_NOT_CONVERGED, "bs tao euler: W is not finite after step %" PetscInt_FMT " (reduce -%sdt)", F->it, F->hdr.prefix);
  if (F->W < F->atol || PetscAbsReal(Wold - F->W) <= F->rtol * Wold) F->reason = CS_BS_CONVERGED;
  else F->dt = PetscMin(F->dt * F->dt_grow, F->dt_max);
  PetscFunctionReturn(0);
}

static PetscErrorCode TaoSchemeDestroy(CSBSFlow F)
{
  BSTao *T = (BSTao *)F->data;
  PetscFunctionBeginUser;
  if (!T) PetscFunctionReturn(0);
  PetscCall(TaoDestroy(&T->tao));
  PetscCall(MatDestroy(&T->K));
  PetscCall(MatDestroy(&T->K3));
  PetscCall(VecDestroy(&T->xn));
  PetscCall(VecDestroy(&T->xw));
  PetscCall(PetscFree(F->data));
  PetscFunctionReturn(0);
}

/* the static problem: TAO counts the iterations (max_it_reason ITERATING: no count by the flow) */
const CSBSSchemeOps CSBSSchemeTaoStatic = {TaoSchemeSetUp, TaoStaticStart, TaoStaticStep, TaoSchemeDestroy, CS_BS_ITERATING};
const CSBSSchemeOps CSBSSchemeTao       = {TaoSchemeSetUp, TaoEulerStart, TaoEulerStep, TaoSchemeDestroy, CS_BS_DIVERGED_TAO};
