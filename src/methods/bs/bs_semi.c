/* The semi-implicit scheme of bobenko-schroeder2005 Sec. 4: (1/dt I + K) dx = -grad W per coordinate, with
   step rejection (failed solve or energy increase: dt / 4) and dt growth on accepted steps. */
#include <petscksp.h>
#include "bs_flow_impl.h"

typedef struct {
  KSP       ksp;
  Mat       K;
  Vec       g, xnew, b1, z1;
  PetscReal shift; /* the 1/dt already added to K */
  PetscInt  consecutive;
} BSSemi;

/* Default: MUMPS LDL^T (1/dt I + K is indefinite at large dt) with MUMPS's own ordering choice; measurements
   and the alternatives in docs/bs_flow.md. Set on the KSP before KSPSetFromOptions, so every
   -<prefix>semi_ksp_*, _pc_* and _mat_mumps_* option overrides. */
static PetscErrorCode SemiSetUp(CSBSFlow F)
{
  BSSemi *S;
  PC      pc;
  char    prefix[256];
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&S));
  F->data  = S;
  PetscCall(VecDuplicate(F->x, &S->g));
  PetscCall(VecDuplicate(F->x, &S->xnew));
  PetscCall(DMCreateGlobalVector(F->mesh->dmV1, &S->b1));
  PetscCall(VecDuplicate(S->b1, &S->z1));
  PetscCall(KSPCreate(F->mesh->comm, &S->ksp));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%ssemi_", F->hdr.prefix));
  PetscCall(KSPSetOptionsPrefix(S->ksp, prefix));
  PetscCall(KSPSetType(S->ksp, KSPPREONLY));
  PetscCall(KSPGetPC(S->ksp, &pc));
  PetscCall(PCSetType(pc, PCCHOLESKY));
  PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
  PetscCall(KSPSetTolerances(S->ksp, 1e-6, 1e-50, PETSC_DEFAULT, 1000));
  PetscCall(KSPSetFromOptions(S->ksp));
  PetscFunctionReturn(0);
}

static PetscErrorCode SemiStart(CSBSFlow F)
{
  BSSemi         *S = (BSSemi *)F->data;
  CSBSMonitorInfo info;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyWillmoreBSHessian(F->bs, F->x, 0, MAT_INITIAL_MATRIX, &S->K, &F->W, S->g));
  PetscCall(PetscMemzero(&info, sizeof(info)));
  info.event = CS_BS_MONITOR_START;
  info.it    = F->it;
  info.W     = F->W;
  info.dt    = F->dt;
  PetscCall(CSBSFlowMonitor(F, &info));
  PetscFunctionReturn(0);
}

/* (1/dt I + K) dx_d = -g_d for d = x, y, z into S->xnew; *ok = PETSC_FALSE on a failed solve. */
static PetscErrorCode SemiSolve(CSBSFlow F, PetscBool *ok, PetscInt *kits, KSPConvergedReason *reason)
{
  BSSemi *S = (BSSemi *)F->data;
  PetscFunctionBeginUser;
  PetscCall(MatShift(S->K, 1.0 / F->dt - S->shift));
  S->shift = 1.0 / F->dt;
  PetscCall(KSPSetOperators(S->ksp, S->K, S->K));
  *ok      = PETSC_TRUE;
  *kits    = 0;
  *reason  = KSP_CONVERGED_ITERATING;
  for (PetscInt d = 0; d < 3 && *ok; d++) {
    PetscInt its;
    PetscCall(VecStrideGather(S->g, d, S->b1, INSERT_VALUES));
    PetscCall(VecScale(S->b1, -1));
    PetscCall(KSPSolve(S->ksp, S->b1, S->z1));
    PetscCall(KSPGetConvergedReason(S->ksp, reason));
    PetscCall(KSPGetIterationNumber(S->ksp, &its));
    *kits += its;
    if (*reason < 0) *ok = PETSC_FALSE;
    else PetscCall(VecStrideScatter(S->z1, d, S->xnew, INSERT_VALUES));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode SemiReject(CSBSFlow F, KSPConvergedReason reason)
{
  BSSemi *S = (BSSemi *)F->data;
  PetscFunctionBeginUser;
  F->rejected++;
  PetscCall(PetscPrintf(F->mesh->comm, "bs semi: step rejected (%s), dt %.3e -> %.3e\n", reason < 0 ? KSPConvergedReasons[reason] : "energy increased", (double)F->dt, (double)(F->dt / 4)));
  F->dt /= 4;
  if (F->dt < F->dt_min) {
    /* an accepted step at such a dt moves nothing: "converged" by the relative decrease would be false (the
       co-circular torus, bobenko-schroeder2005 Sec. 4: no descent from beta = 0) */
    PetscCall(PetscPrintf(F->mesh->comm, "bs semi: dt %.3e fell below -%sdt_min_rel times the initial dt (%.3e): stalled, stopping with the last accepted state (step %" PetscInt_FMT ")\n", (double)F->dt, F->hdr.prefix, (double)F->dt_min, F->it));
    F->reason = CS_BS_STALLED;
  } else if (++S->consecutive > F->max_rej) {
    PetscCall(PetscPrintf(F->mesh->comm, "bs semi: %" PetscInt_FMT " consecutive rejected steps (-%smax_rejections), stopping with the last accepted state (step %" PetscInt_FMT ")\n", S->consecutive, F->hdr.prefix, F->it));
    F->reason = CS_BS_DIVERGED_REJECTIONS;
  }
  PetscFunctionReturn(0);
}

/* One attempted step: accepted (new x, W, K, grad W; convergence test; dt grows) or rejected. */
static PetscErrorCode SemiStep(CSBSFlow F)
{
  BSSemi            *S = (BSSemi *)F->data;
  PetscBool          ok     = PETSC_FALSE;
  PetscInt           kits   = 0;
  PetscReal          Wnew   = 0, Wold = F->W, dtstep = F->dt;
  KSPConvergedReason reason = KSP_CONVERGED_ITERATING;
  CSBSMonitorInfo    info;
  PetscFunctionBeginUser;
  PetscCall(SemiSolve(F, &ok, &kits, &reason));
  if (ok) {
    PetscCall(VecAXPY(S->xnew, 1, F->x)); /* xnew held dx */
    PetscCall(CSBSFlowResetFixed(F, S->xnew));
    PetscCall(CSEnergyValue(F->bs, S->xnew, &Wnew));
    /* -bs_monotone false: the paper's plain stepping, which must accept increases while diamonds leave
       beta = 0 (Sec. 4, Fig. 10: the heuristic's zero gradient is not a descent direction there) */
    ok = (PetscBool)(!PetscIsInfOrNanReal(Wnew) && (Wnew <= Wold || !F->monotone));
  }
  if (!ok) {
    PetscCall(SemiReject(F, reason));
    PetscFunctionReturn(0);
  }
  PetscCall(CSBSFlowCheckGuard(F, S->xnew, &ok));
  if (!ok) {
    F->reason = CS_BS_DIVERGED_GUARD; /* x is the last accepted state */
    PetscFunctionReturn(0);
  }
  S->consecutive = 0;
  F->it++;
  PetscCall(VecCopy(S->xnew, F->x));
  PetscCall(CSEnergyWillmoreBSHessian(F->bs, F->x, 0, MAT_REUSE_MATRIX, &S->K, &F->W, S->g));
  S->shift = 0;
  if (F->energy_target_set && F->W <= F->energy_target) {
    PetscCall(PetscPrintf(F->mesh->comm, "bs semi: W = %.10g reached -%senergy_target %.10g\n", (double)F->W, F->hdr.prefix, (double)F->energy_target));
    F->reason = CS_BS_CONVERGED_ENERGY_TARGET;
  } else if (F->W < F->atol || (F->W <= Wold && Wold - F->W <= F->rtol * Wold && dtstep >= F->dt0)) F->reason = CS_BS_CONVERGED;
  /* a small decrease at a dt cut down by rejections is no evidence of a minimum: dt grows back first */
  else F->dt = PetscMin(F->dt * F->dt_grow, F->dt_max);
  PetscCall(PetscMemzero(&info, sizeof(info)));
  info.event     = CS_BS_MONITOR_STEP;
  info.it        = F->it;
  info.W         = F->W;
  info.dt        = dtstep;
  info.inner_its = kits;
  PetscCall(CSBSFlowMonitor(F, &info));
  PetscFunctionReturn(0);
}

static PetscErrorCode SemiDestroy(CSBSFlow F)
{
  BSSemi *S = (BSSemi *)F->data;
  PetscFunctionBeginUser;
  if (!S) PetscFunctionReturn(0);
  PetscCall(KSPDestroy(&S->ksp));
  PetscCall(MatDestroy(&S->K));
  PetscCall(VecDestroy(&S->g));
  PetscCall(VecDestroy(&S->xnew));
  PetscCall(VecDestroy(&S->b1));
  PetscCall(VecDestroy(&S->z1));
  PetscCall(PetscFree(F->data));
  PetscFunctionReturn(0);
}

const CSBSSchemeOps CSBSSchemeSemi = {SemiSetUp, SemiStart, SemiStep, SemiDestroy, CS_BS_DIVERGED_MAX_IT};
