/* The triangle-field kind at a state omega (soliman2021 Algorithm 2): the constraint rows
   [C~ lambda - c0; d1 omega; S omega] and <<Y_i|omega>> with their Jacobians, the evaluation (W~, gradient,
   residual, violations) and the step's operators (I_H1 metric, I_Q, weights). */
#include "trianglefield_impl.h"

/* c = [C~ lambda(x) - c0 | Klin x] (per rank: its conformal rows, then its linear rows), cx_j = <row_j, x>;
   with wantJ the Jacobian X = [C~ Dlambda; Klin] in F->Xc. */
PetscErrorCode CSTFConstraints(CSWillmoreFlow F, Vec x, Vec c, PetscReal cx[], PetscBool wantJ)
{
  CSTriangleField   *d = (CSTriangleField *)F->data;
  PetscScalar       *a;
  const PetscScalar *b;
  PetscFunctionBeginUser;
  if (d->spinor) {
    PetscCall(CSTFSpinorConstraints(F, x, c, cx, wantJ));
    PetscFunctionReturn(0);
  }
  PetscCall(CSTriangleFieldLogLengths(F->mesh, d->dmH3, x, d->dmH1, d->lambda));
  PetscCall(VecGetArray(c, &a));
  if (!d->noconf) { /* conformal rows: C~ lambda - c0 written straight into c's first nH entries */
    Vec cH;
    PetscCall(VecCreateMPIWithArray(F->hdr.comm, 1, d->nH, PETSC_DETERMINE, a, &cH));
    PetscCall(MatMult(d->C, d->lambda, cH));
    PetscCall(VecAXPY(cH, -1.0, d->c0));
    PetscCall(VecDestroy(&cH));
  }
  PetscCall(MatMult(d->Klin, x, d->clin));
  PetscCall(VecGetArrayRead(d->clin, &b));
  for (PetscInt i = 0; i < d->nL; i++) a[d->nH + i] = b[i];
  PetscCall(VecRestoreArrayRead(d->clin, &b));
  PetscCall(VecRestoreArray(c, &a));
  for (PetscInt j = 0; j < 3 * d->nforms; j++) {
    PetscScalar v;
    PetscCall(VecDot(F->rows[j], x, &v));
    cx[j] = PetscRealPart(v);
  }
  PetscCall(CSTFAppBEvaluate(F, x, cx + 3 * d->nforms, F->rows ? F->rows + 3 * d->nforms : NULL, wantJ));
  if (wantJ && d->noconf) F->Xc = d->X; /* = Klin, constant */
  else if (wantJ) {
    Mat B[2];
    PetscCall(CSOperatorLensLogLengthDerivative(F->mesh, d->dmH1, d->dmH3, x, MAT_REUSE_MATRIX, &d->D));
    PetscCall(MatMatMult(d->C, d->D, MAT_REUSE_MATRIX, PETSC_DEFAULT, &d->CD));
    B[0] = d->CD;
    B[1] = d->Klin;
    PetscCall(CSMatStackRows(2, B, MAT_REUSE_MATRIX, &d->X));
    F->Xc = d->X;
  }
  PetscFunctionReturn(0);
}

/* Violations at x: conformal (the C~ rows), integrability (d1, closure, <<Y|omega>>): F->conf, F->glob = d->integ. */
static PetscErrorCode Violations(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscReal        vc = 0, vl = 0, vy = 0;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(F->c, &a));
  for (PetscInt i = 0; i < d->nH; i++) vc = PetscMax(vc, PetscAbsScalar(a[i]));
  for (PetscInt i = d->nH; i < d->nH + d->nL; i++) vl = PetscMax(vl, PetscAbsScalar(a[i]));
  PetscCall(VecRestoreArrayRead(F->c, &a));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &vc, 1, MPIU_REAL, MPIU_MAX, F->hdr.comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &vl, 1, MPIU_REAL, MPIU_MAX, F->hdr.comm));
  for (PetscInt j = 0; j < 3 * d->nforms; j++) vy = PetscMax(vy, PetscAbsReal(F->cx[j]));
  F->conf  = vc;
  d->integ = PetscMax(vl, vy);
  F->glob  = d->integ; /* the stopping test takes max(conf, glob): every row, App. B's included */
  for (PetscInt j = 3 * d->nforms; j < F->k; j++) F->glob = PetscMax(F->glob, PetscAbsReal(F->cx[j]));
  PetscFunctionReturn(0);
}

/* The spinor variables' violations: the class |C~ lambda(omega) - c0|inf is measured (S_c meets it by
   construction), integrability = max(d1 omega, <<Y|omega>>), glob also the sphere rows. */
static PetscErrorCode ViolationsSpinor(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscReal          vl = 0, vs = 0, vy = 0;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(CSTriangleFieldLogLengths(F->mesh, d->dmH3, d->omega, d->dmH1, d->lamt));
  PetscCall(MatMult(d->C, d->lamt, d->star1));
  PetscCall(VecAXPY(d->star1, -1.0, d->c0));
  PetscCall(VecNorm(d->star1, NORM_INFINITY, &F->conf));
  PetscCall(VecGetArrayRead(F->c, &a));
  for (PetscInt i = 0; i < d->nL; i++) vl = PetscMax(vl, PetscAbsScalar(a[i]));
  for (PetscInt i = d->nL; i < d->nL + F->mesh->nf; i++) vs = PetscMax(vs, PetscAbsScalar(a[i]));
  PetscCall(VecRestoreArrayRead(F->c, &a));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &vl, 1, MPIU_REAL, MPIU_MAX, F->hdr.comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &vs, 1, MPIU_REAL, MPIU_MAX, F->hdr.comm));
  for (PetscInt j = 0; j < 3 * d->nforms; j++) vy = PetscMax(vy, PetscAbsReal(F->cx[j]));
  d->integ = PetscMax(vl, vy);
  F->glob  = PetscMax(d->integ, vs);
  PetscFunctionReturn(0);
}

/* CSTFEvaluate for x = (u, psi): omega = S_c(x), E, its gradient, the rows, the residual, the violations, the
   stars and area of omega, and the spinor diagnostics of psi itself (pinch edges, E_tau). */
static PetscErrorCode EvaluateSpinor(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscScalar A;
  PetscFunctionBeginUser;
  PetscCall(CSTFSpinorOmega(d, F->x, d->omega));
  PetscCall(CSEnergyGradient(F->energy, F->x, &F->E, F->g));
  PetscCall(CSWFEvalConstraints(F, F->x, F->c, F->cx, PETSC_TRUE));
  PetscCall(CSWFResidual(F, &F->el));
  PetscCall(ViolationsSpinor(F, d));
  PetscCall(CSTriangleFieldStars(F->mesh, d->dmH3, d->omega, d->dmH1, d->star1, d->star0));
  PetscCall(VecSum(d->star0, &A));
  F->A = PetscRealPart(A);
  PetscCall(CSTFSpinorOmega(d, F->x, d->omt)); /* d->pg = psi of x */
  PetscCall(CSSpinorPinchEdges(d->sp, d->pg, &d->pinch, NULL));
  PetscCall(CSSpinorPinchVertices(d->sp, d->pg, &d->pinchv));
  PetscCall(CSSpinorDirichlet(d->sp, d->pg, &d->espin, NULL));
  F->V = 0;
  /* the surface of this state against the input, as for the omega variables (area spread, q_max, the guard) */
  PetscCall(CSTriangleFieldReconstructionSolve(d->recon, d->omega, d->xpos0, d->xpos));
  PetscCall(CSWFMeasureQualityOf(F, d->xpos0, d->xpos));
  PetscFunctionReturn(0);
}

/* Everything the stopping test, the monitors and the step need at x = omega: W~ and its gradient (App. D.1), the
   rows, the residual r = g + X^T mu + sum_j nu_j row_j, the violations, the triangle field's stars and area. */
static PetscErrorCode EvaluateAt(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscScalar      A;
  PetscFunctionBeginUser;
  if (d->spinor) {
    PetscCall(EvaluateSpinor(F, d));
    PetscFunctionReturn(0);
  }
  PetscCall(CSEnergyGradient(F->energy, F->x, &F->E, F->g));
  PetscCall(CSWFEvalConstraints(F, F->x, F->c, F->cx, PETSC_TRUE));
  PetscCall(CSWFResidual(F, &F->el));
  PetscCall(Violations(F));
  PetscCall(CSTriangleFieldStars(F->mesh, d->dmH3, F->x, d->dmH1, d->star1, d->star0));
  PetscCall(VecSum(d->star0, &A));
  F->A      = PetscRealPart(A);
  PetscCall(CSSpinorFromTriangleField(d->sp, d->dmH3, F->x, d->psi, d->psit));
  PetscCall(CSSpinorPinchEdges(d->sp, d->psit, &d->pinch, NULL));
  PetscCall(CSSpinorPinchVertices(d->sp, d->psit, &d->pinchv));
  PetscCall(CSSpinorDirichlet(d->sp, d->psit, &d->espin, NULL));
  F->V      = 0; /* not tracked: a triangle field encloses no volume until it is integrated (docs/triangle_fields.md) */
  /* the surface of this state (the Poisson reconstruction) against the input: vertex-area spread and q_max for the
     history, the summary and the resolution guard (issue 21: the bunny's squeeze was invisible here) */
  PetscCall(CSTriangleFieldReconstructionSolve(d->recon, F->x, d->xpos0, d->xpos));
  PetscCall(CSWFMeasureQualityOf(F, d->xpos0, d->xpos));
  PetscFunctionReturn(0);
}

/* The evaluation at x, then the spin-weight continuation (trianglefield_continuation.c). */
PetscErrorCode CSTFEvaluate(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscBool        next;
  PetscFunctionBeginUser;
  PetscCall(EvaluateAt(F, d));
  PetscCall(CSTFContinuationAdvance(F, d, &next)); /* a new spin weight: the energy, gradient and residual change */
  if (next) PetscCall(EvaluateAt(F, d));
  PetscFunctionReturn(0);
}

/* The metric of the primal step: I_H1 = *1/s^2 + *1 d0 *0^{-1} d0^T *1 (soliman2021 Eq. 32) per component, with *1
   floored at -flow_iq_wmin so that it is positive definite, and the 1/s^2 (s^2 = area/4pi of the input) making it
   scale like length^-2 as the H^2 metric of Algorithm 1 (docs/triangle_fields.md). */
static PetscErrorCode Metric(CSWillmoreFlow F, Mat *H)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  Vec              s1;
  Mat              H1;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(d->star1, &s1));
  PetscCall(VecCopy(d->star1, s1));
  {
    PetscInt     n;
    PetscScalar *a;
    PetscCall(VecGetLocalSize(s1, &n));
    PetscCall(VecGetArray(s1, &a));
    for (PetscInt i = 0; i < n; i++) a[i] = PetscMax(PetscRealPart(a[i]), F->wmin);
    PetscCall(VecRestoreArray(s1, &a));
  }
  PetscCall(CSOperatorLensH1Metric(F->mesh, d->dmH1, s1, d->star0, &H1));
  PetscCall(VecScale(s1, 1.0 / d->sc - 1.0));
  PetscCall(MatDiagonalSet(H1, s1, ADD_VALUES));
  PetscCall(CSMatKronIdentity(H1, 3, *H ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, H));
  PetscCall(MatDestroy(&H1));
  PetscCall(VecDestroy(&s1));
  PetscFunctionReturn(0);
}

/* The spinor variables' step operators: the metric J^T I_H1 J + radial (CSTFSpinorMetric, I_H1 at omega), and the
   multipliers' metric: the integrability weight on the lens rows and the period rows, the stiff -flow_integrability_
   weight on the sphere rows. J is the one of the last evaluation (at x). */
static PetscErrorCode OperatorsSpinor(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(Metric(F, &d->Hom));
  PetscCall(CSTFSpinorJacobian(F, d, F->x));
  PetscCall(CSTFSpinorMetric(F, d));
  PetscCall(VecGetArray(F->iq, &a));
  for (PetscInt i = 0; i < d->nL; i++) a[i] = CSTFIntegrabilityWeight(F, d);
  for (PetscInt i = d->nL; i < d->nL + F->mesh->nf; i++) a[i] = d->wint;
  PetscCall(VecRestoreArray(F->iq, &a));
  if (F->k) PetscCall(CSWFGlobalWeights(F));
  for (PetscInt j = 0; j < 3 * d->nforms; j++) F->gw[j] *= CSTFIntegrabilityWeight(F, d);
  if (d->wgauge > 0) F->gw[F->k - 1] *= d->wgauge; /* the scale gauge row */
  PetscFunctionReturn(0);
}

/* The operators of the step at x: the metric, the multipliers' metric [I_Q on halfedges | w on the linear rows],
   and w |row_j|^2 on the <<Y|omega>> rows, w = -flow_integrability_weight (default 1e-4). The rows are
   dimensionless (entries +-1), so w = 1 would weigh them like X^T I_Q^{-1} X; the small default makes them stiff:
   CGD's regularised dual block leaves each row at (I_Q / t_mu) dmu, and the integrability rows' residue, seen
   through the conformal rows, drives the multipliers along the large null space of X^T (dependent rows); with w = 1
   that loop made el_residual creep up ~1 % per step below ~1e-7 (1e-6 on a 12 x 6 torus), with 1e-4 the runs
   converge to 1e-9 (docs/triangle_fields.md). */
PetscErrorCode CSTFOperators(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscInt         ng;
  PetscScalar     *a;
  const PetscScalar *b;
  PetscFunctionBeginUser;
  CSTFScheduleApply(F, d);
  if (d->spinor) {
    PetscCall(OperatorsSpinor(F, d));
    PetscFunctionReturn(0);
  }
  PetscCall(Metric(F, &F->metric.H));
  PetscCall(CSTriangleFieldQuadDiffMetric(F->mesh, d->dmH3, F->x, d->dmH1, F->wmin, d->iqH, &ng));
  F->nguard = PetscMax(F->nguard, ng);
  PetscCall(VecGetArray(F->iq, &a));
  PetscCall(VecGetArrayRead(d->iqH, &b));
  for (PetscInt i = 0; i < d->nH; i++) a[i] = b[i];
  for (PetscInt i = d->nH; i < d->nH + d->nL; i++) a[i] = i < d->nH + 3 * d->nD1 ? CSTFIntegrabilityWeight(F, d) : d->wint;
  PetscCall(VecRestoreArrayRead(d->iqH, &b));
  PetscCall(VecRestoreArray(F->iq, &a));
  if (F->k) PetscCall(CSWFGlobalWeights(F));
  for (PetscInt j = 0; j < 3 * d->nforms; j++) F->gw[j] *= CSTFIntegrabilityWeight(F, d); /* not the App. B rows */
  PetscFunctionReturn(0);
}
