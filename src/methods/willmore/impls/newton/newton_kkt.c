/* -flow_type newton with -flow_conformal (issue 39, soliman2021 Fig. 17): Newton's method on the first-order
   conditions of the constrained problem (SQP; Nocedal & Wright, Numerical Optimization, Sec. 18.1), which finds
   critical points that are not minimisers (saddles), where a descent leaves them. Each iteration solves the KKT system
     [ 0    X     0 ] [dmu]   [ -c  ]
     [ X^T  H_L   B ] [dx ] = [ -r  ]      r = g + X^T mu + B nu (soliman2021 Eq. 7), c = C lambda(x) - c0,
     [ 0    B^T   0 ] [dnu]   [ -xi ]      H_L = D^2 (W + <mu, c> + <nu, xi>), the Hessian of the Lagrangian,
   in the layout of the saddle solver (multiplier block first). H_L is never assembled: its products are central
   differences of the Lagrangian's gradient r(x) at fixed mu, nu (as CSEnergyHessianMult does for W alone). The
   outer Krylov solver is FGMRES (prefix <flow prefix>newton_kkt_) preconditioned by one saddle solve of the CGD step
   (willmore_saddle.c) with H_L replaced by the H^2 metric H / t_pc (soliman2021 Eq. 26: the same leading order,
   fourth derivatives) and the dual block -I_Q / t_mu: a constraint preconditioner, exact on the rows of X and B.
   The step (dx, dmu, dnu) is taken with t = 1 first, halved while the KKT residual |r|^2 + |c|^2 + |xi|^2 at
   (x + t dx, mu + t dmu, nu + t dnu) does not fall (a merit with no preference for minima: saddles are found).
   W and c are scale invariant (r(s x) = r(x) / s): a scale row (-flow_constraint_area) is needed, else the step grows
   the surface. At isothermic surfaces (the homogeneous tori) X loses rank (soliman2021 Sec. 3, Lam-Pinkall 2017), the
   KKT matrix is singular at the solution and the convergence only linear (x1/4 per iteration, docs/triangle_fields.md
   "Fig. 17"); at the lobed tori it is quadratic. */
#include "../cgd/cgd_impl.h"
#include "newton_impl.h"
#include "cs_geometry.h"
#include "cs_util.h"

struct _NewtonKKT {
  Mat        K;            /* the KKT operator (shell) on the flat vector [E | 3V | k on rank 0] */
  KSP        ksp;          /* FGMRES on K */
  Mat        X0;           /* X at x (the FD products evaluate X elsewhere; F->cc.X is restored from it) */
  Vec       *B0, *Bw;      /* the k global rows at x, and at the FD points */
  PetscReal *cxw;          /* global values at the FD points */
  Vec        cw, zE, rE;   /* multiplier layout (E) */
  Vec        zV, rV, xp, gp, gm; /* dmV3 */
  Vec        b, z;         /* flat */
  PetscInt   nE, n3, nk;   /* local sizes of the three parts (nk = k on rank 0, else 0) */
  PetscReal  eps;          /* largest vertex displacement of the central difference */
  PetscReal  pc_t;         /* t of the H^2 metric in the preconditioner (-flow_newton_kkt_pc_t) */
  PetscInt   it_dir;       /* the iteration whose direction is held */
  PetscReal  merit0;       /* |r|^2 + |c|^2 + |xi|^2 at x */
  PetscInt   kkt_its;
  PetscInt   k;            /* global rows */
  Vec       *rigid;        /* an orthonormal basis of the rigid motions at x (translations, rotations) */
};

/* The Lagrangian's gradient at y with the multipliers of x: g(y) + X(y)^T mu + sum_j nu_j row_j(y) (F->cc.X and the
   work rows overwritten; c(y), xi(y) into cw, cxw). */
static PetscErrorCode LagrangianGradient(CSWillmoreFlow F, NewtonKKT *d, Vec y, const PetscReal nu[], Vec mu, Vec out, PetscReal *E)
{
  PetscInt off = 0;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyGradient(F->energy, y, E, out));
  PetscCall(CSConformalConstraintEvaluate(&F->cc, y, d->cw, PETSC_TRUE));
  PetscCall(MatMultTransposeAdd(F->cc.X, mu, out, out));
  for (PetscInt j = 0; j < F->ng; j++) {
    PetscCall(CSGlobalConstraintEvaluate(F->gc[j], y, d->cxw + off, d->Bw + off));
    off += F->gc[j]->k;
  }
  for (PetscInt j = 0; j < F->k; j++) PetscCall(VecAXPY(out, nu[j], d->Bw[j]));
  PetscCall(CSWFZeroFixed(F, out));
  PetscFunctionReturn(0);
}

/* y = H_L v by a central difference of the Lagrangian's gradient, largest vertex displacement eps. */
static PetscErrorCode LagrangianHessianMult(CSWillmoreFlow F, NewtonKKT *d, Vec v, Vec y)
{
  PetscReal vmax, s, E;
  PetscFunctionBeginUser;
  PetscCall(VecNorm(v, NORM_INFINITY, &vmax));
  if (vmax == 0) {
    PetscCall(VecSet(y, 0));
    PetscFunctionReturn(0);
  }
  s = d->eps / vmax;
  PetscCall(VecWAXPY(d->xp, s, v, F->x));
  PetscCall(LagrangianGradient(F, d, d->xp, F->nu, F->mu, y, &E));
  PetscCall(VecWAXPY(d->xp, -s, v, F->x));
  PetscCall(LagrangianGradient(F, d, d->xp, F->nu, F->mu, d->gm, &E));
  PetscCall(VecAXPY(y, -1.0, d->gm));
  PetscCall(VecScale(y, 1.0 / (2 * s)));
  PetscCall(MatCopy(d->X0, F->cc.X, SAME_NONZERO_PATTERN)); /* the preconditioner's X is F->cc.X: X at x again */
  PetscFunctionReturn(0);
}

/* flat [E | 3V | k] <-> parts; the k entries live on rank 0 and are broadcast on unpacking */
static PetscErrorCode Unpack(CSWillmoreFlow F, NewtonKKT *d, Vec flat, Vec E, Vec V, PetscReal X[])
{
  const PetscScalar *a;
  PetscScalar       *e, *v;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(flat, &a));
  PetscCall(VecGetArrayWrite(E, &e));
  PetscCall(VecGetArrayWrite(V, &v));
  for (PetscInt i = 0; i < d->nE; i++) e[i] = a[i];
  for (PetscInt i = 0; i < d->n3; i++) v[i] = a[d->nE + i];
  for (PetscInt j = 0; j < d->nk; j++) X[j] = PetscRealPart(a[d->nE + d->n3 + j]);
  PetscCall(VecRestoreArrayWrite(V, &v));
  PetscCall(VecRestoreArrayWrite(E, &e));
  PetscCall(VecRestoreArrayRead(flat, &a));
  if (F->k) PetscCallMPI(MPI_Bcast(X, (PetscMPIInt)F->k, MPIU_REAL, 0, F->hdr.comm));
  PetscFunctionReturn(0);
}

static PetscErrorCode Pack(NewtonKKT *d, Vec E, Vec V, const PetscReal X[], Vec flat)
{
  PetscScalar       *a;
  const PetscScalar *e, *v;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayWrite(flat, &a));
  PetscCall(VecGetArrayRead(E, &e));
  PetscCall(VecGetArrayRead(V, &v));
  for (PetscInt i = 0; i < d->nE; i++) a[i] = e[i];
  for (PetscInt i = 0; i < d->n3; i++) a[d->nE + i] = v[i];
  for (PetscInt j = 0; j < d->nk; j++) a[d->nE + d->n3 + j] = X[j];
  PetscCall(VecRestoreArrayRead(V, &v));
  PetscCall(VecRestoreArrayRead(E, &e));
  PetscCall(VecRestoreArrayWrite(flat, &a));
  PetscFunctionReturn(0);
}

/* K z = [X zV; X^T zE + H_L zV + B zX; B^T zV] */
static PetscErrorCode KKTMult(Mat K, Vec z, Vec y)
{
  CSWillmoreFlow F;
  NewtonKKT     *d;
  PetscReal      zX[CS_NEWTON_KKT_MAXK], yX[CS_NEWTON_KKT_MAXK];
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(K, &F));
  d = CSNewtonGetKKT(F);
  PetscCall(Unpack(F, d, z, d->zE, d->zV, zX));
  PetscCall(LagrangianHessianMult(F, d, d->zV, d->rV));
  PetscCall(MatMultTransposeAdd(d->X0, d->zE, d->rV, d->rV));
  for (PetscInt j = 0; j < F->k; j++) {
    PetscScalar dot;
    PetscCall(VecAXPY(d->rV, zX[j], d->B0[j]));
    PetscCall(VecDot(d->B0[j], d->zV, &dot));
    yX[j] = PetscRealPart(dot);
  }
  PetscCall(CSWFZeroFixed(F, d->rV));
  PetscCall(MatMult(d->X0, d->zV, d->rE));
  PetscCall(Pack(d, d->rE, d->rV, yX, y));
  PetscFunctionReturn(0);
}

/* the preconditioner: the CGD step's saddle solve with the operators set for this iteration */
static PetscErrorCode KKTPCApply(PC pc, Vec r, Vec z)
{
  CSWillmoreFlow     F;
  NewtonKKT         *d;
  PetscReal          rX[CS_NEWTON_KKT_MAXK], zX[CS_NEWTON_KKT_MAXK];
  PetscInt           its;
  KSPConvergedReason reason;
  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &F));
  d = CSNewtonGetKKT(F);
  PetscCall(Unpack(F, d, r, d->rE, d->rV, rX));
  PetscCall(CSSaddleSolve(&F->saddle, d->rE, d->rV, rX, d->zE, d->zV, zX, &its, &reason));
  F->kspits += its;
  PetscCall(Pack(d, d->zE, d->zV, zX, z));
  PetscFunctionReturn(0);
}

PetscErrorCode CSNewtonKKTCreate(CSWillmoreFlow F, PetscReal pc_t, NewtonKKT **out)
{
  NewtonKKT  *d;
  PetscMPIInt rank;
  PetscInt    n;
  PC          pc;
  char        prefix[96];
  PetscFunctionBeginUser;
  PetscCheck(F->k <= CS_NEWTON_KKT_MAXK, F->hdr.comm, PETSC_ERR_SUP, "-%stype newton -%sconformal: at most %d global constraint rows (given %" PetscInt_FMT ")", F->hdr.prefix, F->hdr.prefix, CS_NEWTON_KKT_MAXK, F->k);
  PetscCall(PetscNew(&d));
  d->pc_t   = pc_t;
  d->k      = F->k;
  d->it_dir = -1;
  PetscCallMPI(MPI_Comm_rank(F->hdr.comm, &rank));
  PetscCall(VecGetLocalSize(F->c, &d->nE));
  PetscCall(VecGetLocalSize(F->x, &d->n3));
  d->nk = rank == 0 ? F->k : 0;
  PetscCall(VecDuplicate(F->c, &d->cw));
  PetscCall(VecDuplicate(F->c, &d->zE));
  PetscCall(VecDuplicate(F->c, &d->rE));
  PetscCall(VecDuplicate(F->x, &d->zV));
  PetscCall(VecDuplicate(F->x, &d->rV));
  PetscCall(VecDuplicate(F->x, &d->xp));
  PetscCall(VecDuplicate(F->x, &d->gp));
  PetscCall(VecDuplicate(F->x, &d->gm));
  if (F->k) {
    PetscCall(VecDuplicateVecs(F->x, F->k, &d->B0));
    PetscCall(VecDuplicateVecs(F->x, F->k, &d->Bw));
    PetscCall(PetscMalloc1(F->k, &d->cxw));
  }
  n = d->nE + d->n3 + d->nk;
  PetscCall(VecCreateMPI(F->hdr.comm, n, PETSC_DETERMINE, &d->b));
  PetscCall(VecDuplicate(d->b, &d->z));
  PetscCall(MatCreateShell(F->hdr.comm, n, n, PETSC_DETERMINE, PETSC_DETERMINE, F, &d->K));
  PetscCall(MatShellSetOperation(d->K, MATOP_MULT, (void (*)(void))KKTMult));
  PetscCall(KSPCreate(F->hdr.comm, &d->ksp));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%snewton_kkt_", F->hdr.prefix));
  PetscCall(KSPSetOptionsPrefix(d->ksp, prefix));
  PetscCall(KSPSetType(d->ksp, KSPFGMRES));
  PetscCall(KSPGMRESSetRestart(d->ksp, 100));
  PetscCall(KSPSetTolerances(d->ksp, 1e-6, PETSC_DEFAULT, PETSC_DEFAULT, 200)); /* the central differences of H_L set a floor near 1e-8 relative (FGMRES stalls there) */
  PetscCall(KSPGetPC(d->ksp, &pc));
  PetscCall(PCSetType(pc, PCSHELL));
  PetscCall(PCShellSetContext(pc, F));
  PetscCall(PCShellSetApply(pc, KKTPCApply));
  PetscCall(PCShellSetName(pc, "the CGD saddle solve with the H^2 metric / t_pc"));
  PetscCall(KSPSetOperators(d->ksp, d->K, d->K));
  PetscCall(KSPSetFromOptions(d->ksp));
  *out = d;
  PetscFunctionReturn(0);
}

PetscErrorCode CSNewtonKKTDestroy(NewtonKKT **pd)
{
  NewtonKKT *d = *pd;
  PetscFunctionBeginUser;
  if (!d) PetscFunctionReturn(0);
  PetscCall(MatDestroy(&d->K));
  PetscCall(KSPDestroy(&d->ksp));
  PetscCall(MatDestroy(&d->X0));
  if (d->rigid) PetscCall(VecDestroyVecs(6, &d->rigid));
  if (d->k) {
    PetscCall(VecDestroyVecs(d->k, &d->B0));
    PetscCall(VecDestroyVecs(d->k, &d->Bw));
    PetscCall(PetscFree(d->cxw));
  }
  PetscCall(VecDestroy(&d->cw));
  PetscCall(VecDestroy(&d->zE));
  PetscCall(VecDestroy(&d->rE));
  PetscCall(VecDestroy(&d->zV));
  PetscCall(VecDestroy(&d->rV));
  PetscCall(VecDestroy(&d->xp));
  PetscCall(VecDestroy(&d->gp));
  PetscCall(VecDestroy(&d->gm));
  PetscCall(VecDestroy(&d->b));
  PetscCall(VecDestroy(&d->z));
  PetscCall(PetscFree(*pd));
  PetscFunctionReturn(0);
}
/* dx minus its rigid-motion part (L2). W, c and the area and Moebius rows are invariant under rigid motions, so at a
   critical point they span a null space of the KKT matrix, and near one its smallest singular values: the Krylov
   solution's component there is amplified round-off (a tilt of the axis by 2.6e-6 rad on 12 x 6, breaking the
   symmetry about z while the shape keeps it to 7e-12). The step does not need it. */
static PetscErrorCode ProjectRigid(CSWillmoreFlow F, NewtonKKT *d, Vec dx)
{
  PetscScalar       *a, dots[6];
  const PetscScalar *x;
  PetscReal          c[3] = {0, 0, 0}, cl[3] = {0, 0, 0};
  PetscInt           nl, N;
  PetscFunctionBeginUser;
  if (!d->rigid) PetscCall(VecDuplicateVecs(F->x, 6, &d->rigid));
  PetscCall(VecGetLocalSize(F->x, &nl));
  PetscCall(VecGetSize(F->x, &N));
  PetscCall(VecGetArrayRead(F->x, &x));
  for (PetscInt i = 0; i < nl; i++) cl[i % 3] += PetscRealPart(x[i]) / (N / 3);
  PetscCall(MPIU_Allreduce(cl, c, 3, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  for (int k = 0; k < 6; k++) {
    PetscCall(VecGetArrayWrite(d->rigid[k], &a));
    for (PetscInt i = 0; i < nl / 3; i++) {
      PetscReal p[3] = {PetscRealPart(x[3 * i]) - c[0], PetscRealPart(x[3 * i + 1]) - c[1], PetscRealPart(x[3 * i + 2]) - c[2]};
      for (int e = 0; e < 3; e++) a[3 * i + e] = k < 3 ? (PetscReal)(e == k) : 0;
      if (k >= 3) { /* e_{k-3} x p */
        int u = k - 3, v = (u + 1) % 3, w = (u + 2) % 3;
        a[3 * i + v] = -p[w];
        a[3 * i + w] = p[v];
      }
    }
    PetscCall(VecRestoreArrayWrite(d->rigid[k], &a));
  }
  PetscCall(VecRestoreArrayRead(F->x, &x));
  for (int k = 0; k < 6; k++) { /* Gram-Schmidt, twice */
    for (int pass = 0; pass < 2 && k > 0; pass++) {
      PetscCall(VecMDot(d->rigid[k], k, d->rigid, dots));
      for (int j = 0; j < k; j++) dots[j] = -dots[j];
      PetscCall(VecMAXPY(d->rigid[k], k, dots, d->rigid));
    }
    PetscCall(VecNormalize(d->rigid[k], NULL));
  }
  PetscCall(VecMDot(dx, 6, d->rigid, dots));
  for (int j = 0; j < 6; j++) dots[j] = -dots[j];
  PetscCall(VecMAXPY(dx, 6, dots, d->rigid));
  PetscFunctionReturn(0);
}

/* |r|^2 + |c|^2 + |xi|^2 of the given residual parts */
static PetscErrorCode Merit(CSWillmoreFlow F, Vec r, Vec c, const PetscReal cx[], PetscReal *m)
{
  PetscReal nr, nc;
  PetscFunctionBeginUser;
  PetscCall(VecNorm(r, NORM_2, &nr));
  PetscCall(VecNorm(c, NORM_2, &nc));
  *m = nr * nr + nc * nc;
  for (PetscInt j = 0; j < F->k; j++) *m += cx[j] * cx[j];
  PetscFunctionReturn(0);
}

/* The Newton direction (dx, dmu, dnu) at x into F->df, F->dmu, F->dnu (once per iteration). */
static PetscErrorCode Direction(CSWillmoreFlow F, NewtonKKT *d)
{
  KSPConvergedReason reason;
  PetscInt           its, kspits0 = F->kspits;
  PetscReal          h, rX[CS_NEWTON_KKT_MAXK];
  PetscFunctionBeginUser;
  PetscCall(CSGeometryMeanEdgeLength(F->mesh, F->x, &h));
  d->eps = 1e-5 * h;
  PetscCall(CSMetricUpdate(&F->metric, F->x)); /* the kind's own metric (own_metric): only the preconditioner uses it */
  PetscCall(CSWFSetOperators(F, d->pc_t, d->pc_t * F->tmu / F->t));
  if (!d->X0) PetscCall(MatDuplicate(F->cc.X, MAT_COPY_VALUES, &d->X0));
  else PetscCall(MatCopy(F->cc.X, d->X0, SAME_NONZERO_PATTERN));
  for (PetscInt j = 0; j < F->k; j++) PetscCall(VecCopy(F->rows[j], d->B0[j]));
  PetscCall(Merit(F, F->r, F->c, F->cx, &d->merit0));
  for (PetscInt j = 0; j < F->k; j++) rX[j] = -F->cx[j];
  PetscCall(VecCopy(F->r, d->rV));
  PetscCall(VecScale(d->rV, -1.0));
  PetscCall(VecCopy(F->c, d->rE));
  PetscCall(VecScale(d->rE, -1.0));
  PetscCall(Pack(d, d->rE, d->rV, rX, d->b));
  PetscCall(VecSet(d->z, 0));
  PetscCall(KSPSolve(d->ksp, d->b, d->z));
  PetscCall(KSPGetConvergedReason(d->ksp, &reason));
  PetscCall(KSPGetIterationNumber(d->ksp, &its));
  d->kkt_its += its;
  PetscCall(Unpack(F, d, d->z, F->dmu, F->df, F->dnu));
  PetscCall(ProjectRigid(F, d, F->df));
  PetscCall(PetscPrintf(F->hdr.comm, "     newton (KKT): FGMRES %" PetscInt_FMT " iterations (%s), %" PetscInt_FMT " saddle-solve iterations\n", its, KSPConvergedReasons[reason], F->kspits - kspits0));
  F->kspits += its;
  d->it_dir = F->it;
  PetscFunctionReturn(0);
}

PetscErrorCode CSNewtonKKTTrial(CSWillmoreFlow F, NewtonKKT *d, PetscBool *accept)
{
  PetscFunctionBeginUser;
  if (d->it_dir != F->it) PetscCall(Direction(F, d));
  PetscCall(VecWAXPY(F->xt, F->t, F->df, F->x));
  *accept = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* accepted when the KKT residual at (xt, mu + t dmu, nu + t dnu) is below the one at x (the Armijo factor 1e-4 t
   of a Newton step on |KKT|^2) */
PetscErrorCode CSNewtonKKTFilter(CSWillmoreFlow F, NewtonKKT *d, PetscBool *accept)
{
  PetscReal E, mt, nun[CS_NEWTON_KKT_MAXK];
  PetscFunctionBeginUser;
  PetscCall(VecWAXPY(F->mun, F->t, F->dmu, F->mu));
  for (PetscInt j = 0; j < F->k; j++) nun[j] = F->nu[j] + F->t * F->dnu[j];
  PetscCall(LagrangianGradient(F, d, F->xt, nun, F->mun, d->gp, &E));
  PetscCall(Merit(F, d->gp, d->cw, d->cxw, &mt));
  PetscCall(MatCopy(d->X0, F->cc.X, SAME_NONZERO_PATTERN));
  *accept = (PetscBool)(mt == mt && E == E && mt <= (1 - 2e-4 * F->t) * d->merit0);
  if (!*accept) PetscCall(PetscPrintf(F->hdr.comm, "     step rejected: KKT residual^2 %.6e -> %.6e with t = %g; halving t\n", (double)d->merit0, (double)mt, (double)F->t));
  PetscFunctionReturn(0);
}

/* x = xt done: the multipliers of the step */
PetscErrorCode CSNewtonKKTAccept(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(VecAXPY(F->mu, F->t, F->dmu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] += F->t * F->dnu[j];
  PetscFunctionReturn(0);
}

PetscInt CSNewtonKKTIterations(NewtonKKT *d)
{
  return d ? d->kkt_its : 0;
}
