/* What the flow evaluates at a state: constraints and their Jacobians, the violation, the Lagrangian of the
   step filter, the Euler-Lagrange residual, the metrics of the multipliers. */
#include "willmore_impl.h"
#include "cs_linalg.h"

PetscErrorCode CSWFZeroFixed(CSWillmoreFlow F, Vec v)
{
  PetscFunctionBeginUser;
  if (F->fixedIS) PetscCall(VecISSet(v, F->fixedIS, 0.0));
  PetscFunctionReturn(0);
}

/* Xext = [X; DN] in the multiplier layout (rows of X, then rows of DN, per rank: the layout of F->c), copied row by
   row by CSMatStackRows (MatConvert of a MATNEST with MAT_REUSE_MATRIX fails in parallel in PETSc 3.18: "Reuse
   matrix has changed nonzero structure"). The pattern is fixed, so later calls only refill the values. */
static PetscErrorCode StackRows(CSWillmoreFlow F)
{
  Mat B[2] = {F->cc.X, F->nc.DN};

  PetscFunctionBeginUser;
  PetscCall(CSMatStackRows(2, B, F->Xext ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &F->Xext));
  PetscFunctionReturn(0);
}

/* Constraint values at x (c and cx), with Jacobians (X in F->Xc, rows) if wantJ. */
PetscErrorCode CSWFEvalConstraints(CSWillmoreFlow F, Vec x, Vec c, PetscReal cx[], PetscBool wantJ)
{
  PetscInt off = 0;
  PetscFunctionBeginUser;
  if (F->ops.constraints) {
    PetscCall((*F->ops.constraints)(F, x, c, cx, wantJ));
    PetscFunctionReturn(0);
  }
  if (F->conformal && !F->normals) {
    PetscCall(CSConformalConstraintEvaluate(&F->cc, x, c, wantJ));
    F->Xc = F->cc.X;
  } else if (F->normals) {
    PetscCall(CSConformalConstraintEvaluate(&F->cc, x, F->cE, wantJ));
    PetscCall(CSNormalConstraintEvaluate(&F->nc, x, F->cN, wantJ));
    PetscCall(VecISCopy(c, F->isM[0], SCATTER_FORWARD, F->cE));
    PetscCall(VecISCopy(c, F->isM[1], SCATTER_FORWARD, F->cN));
    if (wantJ) {
      PetscCall(StackRows(F));
      F->Xc = F->Xext;
    }
  }
  for (PetscInt j = 0; j < F->ng; j++) {
    PetscCall(CSGlobalConstraintEvaluate(F->gc[j], x, cx + off, wantJ ? F->rows + off : NULL));
    off += F->gc[j]->k;
  }
  if (wantJ)
    for (PetscInt j = 0; j < F->k; j++) PetscCall(CSWFZeroFixed(F, F->rows[j]));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFViolation(CSWillmoreFlow F, Vec c, const PetscReal cx[], PetscReal *conf, PetscReal *glob)
{
  PetscReal v = 0;
  PetscFunctionBeginUser;
  *conf = 0;
  if (F->conformal) PetscCall(VecNorm(c, NORM_INFINITY, conf));
  for (PetscInt j = 0; j < F->k; j++) v = PetscMax(v, PetscAbsReal(cx[j]));
  *glob = v;
  PetscFunctionReturn(0);
}

/* The Lagrangian of the CGD/GD step control with multipliers F->mun, nun (plus the optional quadratic
   penalty -flow_merit_rho, default 0; see the top of the file). */
PetscErrorCode CSWFMerit(CSWillmoreFlow F, PetscReal E, Vec c, const PetscReal cx[], const PetscReal nun[], PetscReal *phi)
{
  PetscReal s = E;
  PetscFunctionBeginUser;
  if (F->conformal) {
    PetscScalar d;
    PetscReal   n2;
    PetscCall(VecDot(F->mun, c, &d));
    PetscCall(VecNorm(c, NORM_2, &n2));
    s += PetscRealPart(d) + 0.5 * F->rho * n2 * n2;
  }
  for (PetscInt j = 0; j < F->k; j++) s += nun[j] * cx[j] + 0.5 * F->rho * cx[j] * cx[j] / F->gw[j];
  *phi = s;
  PetscFunctionReturn(0);
}

/* r = g + X^T mu + sum_j nu_j rows_j (the Euler-Lagrange residual, soliman2021 Eq. 7) with the given multipliers,
   fixed entries zero (ALM passes its first-order estimates: r = grad L_A, impls/alm/alm.c). */
PetscErrorCode CSWFResidualWith(CSWillmoreFlow F, Vec mu, const PetscReal nu[], PetscReal *el)
{
  PetscFunctionBeginUser;
  PetscCall(VecCopy(F->g, F->r));
  if (F->conformal) PetscCall(MatMultTransposeAdd(F->Xc, mu, F->r, F->r));
  for (PetscInt j = 0; j < F->k; j++) PetscCall(VecAXPY(F->r, nu[j], F->rows[j]));
  PetscCall(CSWFZeroFixed(F, F->r));
  PetscCall(VecNorm(F->r, NORM_2, el));
  PetscFunctionReturn(0);
}

/* the residual with the multipliers mu, nu of x */
PetscErrorCode CSWFResidual(CSWillmoreFlow F, PetscReal *el)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFResidualWith(F, F->mu, F->nu, el));
  PetscFunctionReturn(0);
}

/* Metric weights of the global multipliers: g_j = |row_j|^2, so that the dual step acts alike on
   constraints of any unit (the paper leaves this metric open). */
PetscErrorCode CSWFGlobalWeights(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < F->k; j++) {
    PetscReal n;
    PetscCall(VecNorm(F->rows[j], NORM_2, &n));
    F->gw[j] = PetscMax(n * n, PETSC_SMALL);
  }
  PetscFunctionReturn(0);
}

/* The metric of the multipliers at x: I_Q (Eq. 25) on the edge rows, 1/(2A) on normal rows. */
PetscErrorCode CSWFQuadDiffMetric(CSWillmoreFlow F, Vec x, PetscInt *ng)
{
  PetscFunctionBeginUser;
  if (!F->conformal) PetscFunctionReturn(0);
  if (F->normals) {
    PetscCall(CSOperatorQuadDiffMetric(F->mesh, x, F->wmin, F->iqE, ng));
    PetscCall(CSNormalConstraintMetric(&F->nc, x, F->iqN));
    PetscCall(VecISCopy(F->iq, F->isM[0], SCATTER_FORWARD, F->iqE));
    PetscCall(VecISCopy(F->iq, F->isM[1], SCATTER_FORWARD, F->iqN));
  } else PetscCall(CSOperatorQuadDiffMetric(F->mesh, x, F->wmin, F->iq, ng));
  PetscFunctionReturn(0);
}
