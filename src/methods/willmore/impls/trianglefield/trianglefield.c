/* -flow_type trianglefield: soliman2021 Algorithm 2, constrained Willmore flow over triangle fields omega (three
   halfedge vectors per face, stored on the edges, include/cs_operators_lens.h) with the CGD step of Algorithm 1:
   the same saddle solver, step control (filter, second-order corrections, t / t_mu schedule) and stopping rule
   (el_residual < rtol, every row below ctol). Its own variables, energy W~ (App. D.1), constraint rows
     [C~ lambda(omega) - c0; d1 omega; S omega]   (Eq. 14 / 30, Eq. 31, face closure; sparse, multiplier block)
     <<Y_i|omega>> = 0, i < 2g                     (Eq. 13; dense, bordered like the global constraints)
   and metric I_H1 (Eq. 32). Integrability (d1, closure, Y rows) is enforced at every step (docs/triangle_fields.md).
   The surface of a state is the solution of the Poisson problem L f = d*omega (CSTriangleFieldReconstruct).
   -flow_variables spinor: the same kind over x = (u, psi), omega = S_c(u, psi) (App. C.2/C.3, trianglefield_spinor.c). */
#include "trianglefield_impl.h"
#include "cs_quaternion.h"
#include "cs_util.h"

static PetscReal HashUniform(PetscInt seed, PetscInt e, PetscInt s, PetscInt c);
static PetscErrorCode SetUpTriangleFieldSpinor(CSWillmoreFlow F, CSTriangleField *d);

/* W~(omega) + wspin E_tau(psi(omega)), psi(omega) the face lift with the signs nearest to the accepted state's
   spinors (the regulariser of App. C.3 on triangle fields). */
static PetscErrorCode EnergyEval(CSEnergy e, Vec x, PetscReal *E, Vec g)
{
  CSTriangleField *d = (CSTriangleField *)e->ctx;
  PetscReal        Es = 0;
  PetscFunctionBeginUser;
  if (d->spinor) {
    PetscCall(CSTFSpinorEnergy(d->flow, d, x, E, g));
    PetscFunctionReturn(0);
  }
  PetscCall(CSTriangleFieldWillmore(e->mesh, d->dmH3, x, E, g));
  if (d->wspin <= 0) PetscFunctionReturn(0);
  if (g && !d->gspin) PetscCall(VecDuplicate(g, &d->gspin)); /* kept for the run */
  PetscCall(CSSpinorDirichletTriangleField(d->sp, d->dmH3, x, d->psi, &Es, g ? d->gspin : NULL, NULL));
  if (E) *E += d->wspin * Es;
  if (g) PetscCall(VecAXPY(g, d->wspin, d->gspin));
  PetscFunctionReturn(0);
}

static PetscErrorCode EnergyValue(CSEnergy e, Vec x, PetscReal *E)
{
  PetscFunctionBeginUser;
  PetscCall(EnergyEval(e, x, E, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode EnergyGradient(CSEnergy e, Vec x, PetscReal *E, Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(EnergyEval(e, x, E, g));
  PetscFunctionReturn(0);
}

/* W~(omega) = 1/4 <d*omega, d*omega> (App. D.1), plus -flow_spin_weight E_tau, as a CSEnergy on dmH3 vectors
   (ctx: the kind's data, which outlives the evaluations). */
static PetscErrorCode CreateEnergy(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateShell(F->mesh, "willmore_trianglefield", &F->energy));
  F->energy->ctx      = d;
  F->energy->value    = EnergyValue;
  F->energy->gradient = EnergyGradient;
  PetscFunctionReturn(0);
}

/* -flow_init random_spinor: omega = S(l0, psi) (App. C.2) in the target metric l0, psi_f = psi_ref,f r_f with
   psi_ref the input's face spinors and r_f a rotation by an angle uniform in [-a pi, a pi] about a uniform random
   axis (hashed from the seed and the face's natural number: the same field on any number of ranks), scaled to the
   input's size (|omega| = |df|). Conformal rows and face closure hold exactly; the lenses do not close. */
static PetscErrorCode RandomSpinorField(CSWillmoreFlow F, CSTriangleField *d, Vec psiref)
{
  CSMesh       m = F->mesh;
  Vec          psi;
  PetscScalar *p;
  PetscReal    n0, n1;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(psiref, &psi));
  PetscCall(VecCopy(psiref, psi));
  PetscCall(VecGetArray(psi, &p));
  for (PetscInt f = 0; f < m->nf; f++) {
    PetscReal ax[3], an = d->amp * PETSC_PI * HashUniform(d->seed, m->faceNatural[f], 2, 3), r[4], q[4], t[4];
    for (int c = 0; c < 3; c++) ax[c] = HashUniform(d->seed, m->faceNatural[f], 2, c);
    n0 = PetscSqrtReal(ax[0] * ax[0] + ax[1] * ax[1] + ax[2] * ax[2]);
    if (n0 == 0) ax[0] = n0 = 1; /* the hash gave the zero vector: any axis */
    r[0] = PetscCosReal(an / 2);
    for (int c = 0; c < 3; c++) r[1 + c] = PetscSinReal(an / 2) * ax[c] / n0;
    for (int c = 0; c < 4; c++) q[c] = PetscRealPart(p[4 * f + c]);
    CSQuatMul(q, r, t);
    for (int c = 0; c < 4; c++) p[4 * f + c] = t[c];
  }
  PetscCall(VecRestoreArray(psi, &p));
  PetscCall(CSSpinorTriangleField(d->sp, NULL, psi, d->dmH3, F->x));
  PetscCall(VecNorm(F->x0, NORM_2, &n0));
  PetscCall(VecNorm(F->x, NORM_2, &n1));
  PetscCall(VecScale(F->x, n0 / n1));
  PetscCall(VecDestroy(&psi));
  PetscFunctionReturn(0);
}

/* The spinors (App. C): charts and weights of the target metric lambda0 (d->lambda), the spin connection of the
   input's df (x0), psi = the lift of the start omega with the signs nearest to the input's own spinors. */
static PetscErrorCode SetUpSpinors(CSWillmoreFlow F, CSTriangleField *d)
{
  DM dmF4;
  PetscFunctionBeginUser;
  PetscCall(CSSpinorSpaceCreate(F->mesh, d->dmH1, d->lambda, &d->sp));
  PetscCall(CSSpinorSpaceSetConnection(d->sp, d->dmH3, F->x0));
  PetscCall(CSSpinorSpaceGetDM(d->sp, &dmF4));
  PetscCall(DMCreateGlobalVector(dmF4, &d->psi));
  PetscCall(VecDuplicate(d->psi, &d->psit));
  PetscCall(CSSpinorFromTriangleField(d->sp, d->dmH3, F->x0, NULL, d->psit));
  if (d->init == CS_TF_INIT_RANDOM_SPINOR) PetscCall(RandomSpinorField(F, d, d->psit));
  PetscCall(CSSpinorFromTriangleField(d->sp, d->dmH3, F->x, d->psit, d->psi));
  PetscFunctionReturn(0);
}

/* A uniform number in [-1, 1) from (seed, natural edge, side, component): the same field on any number of ranks. */
static PetscReal HashUniform(PetscInt seed, PetscInt e, PetscInt s, PetscInt c)
{
  unsigned long long h = 1469598103934665603ULL;
  PetscInt           k[4] = {seed, e, s, c};
  for (int i = 0; i < 4; i++) {
    h ^= (unsigned long long)k[i] + 0x9e3779b97f4a7c15ULL + (h << 6) + (h >> 2);
    h *= 1099511628211ULL;
  }
  h ^= h >> 33;
  h *= 0xff51afd7ed558ccdULL;
  h ^= h >> 33;
  return 2.0 * (PetscReal)(h >> 11) / 9007199254740992.0 - 1.0;
}

/* -flow_init random: omega += a lbar U[-1, 1]^3 on every halfedge (lbar the mean edge length of the input). */
static PetscErrorCode RandomizeField(CSWillmoreFlow F, CSTriangleField *d)
{
  CSMesh       m = F->mesh;
  Vec          ol;
  PetscScalar *o;
  PetscReal    lsum = 0, lbar;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(d->dmH3, &ol));
  PetscCall(DMGlobalToLocal(d->dmH3, F->x, INSERT_VALUES, ol));
  PetscCall(VecGetArray(ol, &o));
  for (PetscInt e = 0; e < m->ne; e++)
    if (m->edgeOwned[e]) lsum += PetscSqrtReal(PetscSqr(PetscRealPart(o[6 * e])) + PetscSqr(PetscRealPart(o[6 * e + 1])) + PetscSqr(PetscRealPart(o[6 * e + 2])));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &lsum, 1, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  lbar = lsum / m->Ne;
  for (PetscInt e = 0; e < m->ne; e++)
    for (PetscInt s = 0; s < 2; s++)
      for (PetscInt c = 0; c < 3; c++) o[6 * e + 3 * s + c] += d->amp * lbar * HashUniform(d->seed, m->edgeNatural[e], s, c);
  PetscCall(VecRestoreArray(ol, &o));
  PetscCall(DMLocalToGlobal(d->dmH3, ol, INSERT_VALUES, F->x));
  PetscCall(DMRestoreLocalVector(d->dmH3, &ol));
  PetscFunctionReturn(0);
}

/* The options this kind does not take, refused by name. */
static PetscErrorCode CheckOptions(CSWillmoreFlow F)
{
  const char *p = F->hdr.prefix;
  PetscBool   willmore;
  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(F->energy_name, "willmore", &willmore));
  PetscCheck(willmore, F->hdr.comm, PETSC_ERR_SUP, "-%senergy %s: -%stype trianglefield minimises the Willmore energy W~ of App. D.1 only", p, F->energy_name, p);
  PetscCheck(!F->area_set && !F->rotation && !F->target[0], F->hdr.comm, PETSC_ERR_SUP, "-%stype trianglefield: the area and rotation constraints and -%starget_mesh are not built for triangle fields (App. B: volume, points and the Moebius balancing only)", p, p);
  PetscCheck(F->metric_type == CS_FLOW_METRIC_H2, F->hdr.comm, PETSC_ERR_SUP, "-%smetric %s: -%stype trianglefield has its own metric, the I_H1 of triangle fields (Eq. 32), which the default -%smetric h2 selects", p, CSFlowMetricTypes[F->metric_type], p, p);
  PetscFunctionReturn(0);
}

/* The constant operators: C~, Klin = [d1; S] (x) I_3, and the first D, X_conf, X (patterns fixed for the run). */
static PetscErrorCode SetUpOperators(CSWillmoreFlow F, CSTriangleField *d)
{
  Mat d1, S, B[2], lin;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLensCrossRatio(F->mesh, d->dmH1, &d->C));
  PetscCall(CSOperatorLensD1(F->mesh, d->dmH1, &d1));
  PetscCall(MatGetLocalSize(d1, &d->nD1, NULL));
  PetscCall(CSOperatorLensFaceClosure(F->mesh, d->dmH1, &S));
  B[0] = d1;
  B[1] = S;
  PetscCall(CSMatStackRows(2, B, MAT_INITIAL_MATRIX, &lin));
  PetscCall(CSMatKronIdentity(lin, 3, MAT_INITIAL_MATRIX, &d->Klin));
  PetscCall(MatDestroy(&d1));
  PetscCall(MatDestroy(&S));
  PetscCall(MatDestroy(&lin));
  PetscCall(CSOperatorLensLogLengthDerivative(F->mesh, d->dmH1, d->dmH3, F->x0, MAT_INITIAL_MATRIX, &d->D));
  PetscCall(MatMatMult(d->C, d->D, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &d->CD));
  B[0] = d->CD;
  B[1] = d->Klin;
  PetscCall(CSMatStackRows(d->noconf ? 1 : 2, d->noconf ? B + 1 : B, MAT_INITIAL_MATRIX, &d->X));
  PetscCall(MatGetLocalSize(d->CD, &d->nH, NULL));
  if (d->noconf) d->nH = 0;
  PetscCall(MatGetLocalSize(d->Klin, &d->nL, NULL));
  PetscFunctionReturn(0);
}

/* The rows <<Y_i|omega>> per component (Eq. 13): y_i = CSLensHarmonicDual of the harmonic basis at the input's
   positions, co-closed, so <<Y_i|df>> = 0 for every f and the rows only remove omega's periods. The App. B rows
   (CSTFAppBSetUp) follow them. */
static PetscErrorCode SetUpHarmonicRows(CSWillmoreFlow F, CSTriangleField *d)
{
  CSHarmonicBasis hb = NULL;
  Vec             y;
  PetscInt        n;
  PetscFunctionBeginUser;
  if (F->mesh->topo.genus > 0) {
    PetscCall(CSHarmonicBasisCreate(F->mesh, d->xpos0, &hb));
    PetscCall(CSHarmonicBasisSetFromOptions(hb));
    PetscCall(CSHarmonicBasisGetSize(hb, &d->nforms));
  }
  F->k = 3 * d->nforms + CSTFAppBRows(F) + (d->spinor && d->wgauge > 0 ? 1 : 0); /* spinor: the scale gauge row last */
  if (F->k) PetscCall(VecDuplicateVecs(F->x, F->k, &F->rows));
  if (d->spinor && d->nforms) PetscCall(VecDuplicateVecs(d->omega, 3 * d->nforms, &d->rowsOm));
  if (!hb) PetscFunctionReturn(0);
  PetscCall(DMCreateGlobalVector(d->dmH1, &y));
  PetscCall(VecGetLocalSize(y, &n));
  for (PetscInt i = 0; i < d->nforms; i++) {
    Vec                eta;
    const PetscScalar *a;
    PetscCall(CSHarmonicBasisGetForm(hb, i, &eta));
    PetscCall(CSLensHarmonicDual(F->mesh, d->xpos0, eta, d->dmH1, y));
    PetscCall(VecGetArrayRead(y, &a));
    for (PetscInt c = 0; c < 3; c++) {
      PetscScalar *r;
      Vec row = d->spinor ? d->rowsOm[3 * i + c] : F->rows[3 * i + c];
      PetscCall(VecGetArray(row, &r));
      for (PetscInt h = 0; h < 3 * n; h++) r[h] = 0;
      for (PetscInt h = 0; h < n; h++) r[3 * h + c] = a[h];
      PetscCall(VecRestoreArray(row, &r));
    }
    PetscCall(VecRestoreArrayRead(y, &a));
  }
  PetscCall(VecDestroy(&y));
  PetscCall(CSHarmonicBasisDestroy(&hb));
  PetscFunctionReturn(0);
}

static PetscErrorCode SetUpVectors(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFSetUpPrimalVectors(F));
  PetscCall(VecCreateMPI(F->hdr.comm, d->nH + d->nL, PETSC_DETERMINE, &F->c)); /* rows [C~ lambda - c0; d1 omega; closure] */
  PetscCall(CSWFSetUpMultiplierVectors(F));
  PetscCall(DMCreateGlobalVector(d->dmH1, &d->lambda));
  PetscCall(VecDuplicate(d->lambda, &d->c0));
  PetscCall(VecDuplicate(d->lambda, &d->star1));
  PetscCall(VecDuplicate(d->lambda, &d->iqH));
  PetscCall(DMCreateGlobalVector(F->mesh->dmV1, &d->star0));
  PetscCall(MatCreateVecs(d->Klin, NULL, &d->clin));
  PetscFunctionReturn(0);
}

/* Size independence as in Algorithm 1 (CSWFSetUpScaling): s^2 = area / 4 pi of the input. */
static PetscErrorCode SetUpScaling(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscReal A, V, E0;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryAreaVolume(F->mesh, d->xpos0, &A, &V));
  d->sc = A / (4 * PETSC_PI);
  if (F->tmu_max <= 0) F->tmu_max = F->tmu_grow > 0 ? 1e3 * F->tmax : PETSC_MAX_REAL;
  F->tmu /= d->sc;
  CSWFDualStepScale(&d->ds, d->sc);
  if (F->tmu_max < PETSC_MAX_REAL) F->tmu_max /= d->sc;
  F->tmu_ratio_max = 1e3 * F->tmu / F->t;
  PetscCall(CSEnergyValue(F->energy, F->x0, &E0));
  F->rho *= PetscMax(PetscAbsReal(E0), PETSC_SMALL);
  PetscFunctionReturn(0);
}

/* The input's vertex areas, against which the surface of every state is measured (CSWFMeasureQualityOf). */
static PetscErrorCode SetUpResolutionMeasures(CSWillmoreFlow F, CSTriangleField *d)
{
  PetscScalar a0;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(F->mesh->dmV1, &F->area0));
  PetscCall(VecDuplicate(F->area0, &F->areat));
  PetscCall(CSGeometryVertexAreas(F->mesh, d->xpos0, F->area0));
  PetscCall(VecSum(F->area0, &a0));
  F->area0_total = PetscRealPart(a0);
  PetscFunctionReturn(0);
}

/* The variables omega_0 = df of the mesh's positions, the energy, the rows and their target c0 = C~ lambda(omega_0)
   (or C~ log l of the input's intrinsic lengths l = mesh->lt when it has them: -gen lattice),
   the vectors, the scaling and the saddle solver (multiplier block: the sparse rows; bordering: the Y rows). */
static PetscErrorCode SetUpTriangleField(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  CSMesh           m = F->mesh;
  char             prefix[80];
  PetscFunctionBeginUser;
  PetscCheck(m->topo.boundary_loops == 0, F->hdr.comm, PETSC_ERR_SUP, "-%stype trianglefield: the mesh %s has %" PetscInt_FMT " boundary loop(s); triangle-field flows are built for closed surfaces", F->hdr.prefix, m->name, m->topo.boundary_loops);
  PetscCall(CheckOptions(F));
  d->ds.final_from = d->istart; /* -flow_t_mu_final (cgd_dual_step.c): armed once the rows are enforced (the relaxed phase before) */
  d->noconf    = (PetscBool)!F->conformal; /* unconstrained W~ (Fig. 8): integrability rows only */
  F->conformal = PETSC_TRUE;               /* the multiplier block holds the integrability rows either way */
  PetscCall(CSLensCreateHalfedgeDM(m, 1, &d->dmH1));
  PetscCall(CSLensCreateHalfedgeDM(m, 3, &d->dmH3));
  PetscCall(VecDuplicate(m->x, &d->xpos0));
  PetscCall(VecCopy(m->x, d->xpos0));
  PetscCall(VecDuplicate(m->x, &d->xpos));
  PetscCall(CSTriangleFieldReconstructionCreate(m, d->dmH1, d->dmH3, &d->recon));
  PetscCall(SetUpResolutionMeasures(F, d));
  d->flow = F;
  if (d->spinor) {
    PetscCall(SetUpTriangleFieldSpinor(F, d));
    PetscCall(CSTFStateSetUp(F, d)); /* refuses -checkpoint/-resume by name */
    PetscFunctionReturn(0);
  }
  PetscCall(DMCreateGlobalVector(d->dmH3, &F->x));
  PetscCall(CSTriangleFieldFromPositions(m, d->xpos0, d->dmH3, F->x));
  PetscCall(VecDuplicate(F->x, &F->x0));
  PetscCall(VecCopy(F->x, F->x0)); /* c0 is the input's class: C~ lambda(df) */
  if (d->init == CS_TF_INIT_RANDOM) PetscCall(RandomizeField(F, d));
  if (d->init == CS_TF_INIT_SMOOTH) PetscCall(CSTFInitSmooth(F, d, HashUniform));
  PetscCall(CreateEnergy(F, d));
  PetscCall(SetUpOperators(F, d));
  PetscCall(CSTFAppBSetUp(F, d));
  PetscCall(SetUpHarmonicRows(F, d));
  PetscCall(SetUpVectors(F, d));
  if (m->lt) PetscCall(CSTriangleFieldLogLengthsFromEdges(m, m->lt, d->dmH1, d->lambda)); /* -gen lattice: the lattice's class */
  else PetscCall(CSTriangleFieldLogLengths(m, d->dmH3, F->x0, d->dmH1, d->lambda));
  PetscCall(MatMult(d->C, d->lambda, d->c0));
  if (m->ct) PetscCall(CSTriangleFieldHalfedgesFromEdges(m, m->ct, d->dmH1, d->c0)); /* -mesh_cross_ratios (the spinor charts keep df's lengths) */
  PetscCall(SetUpSpinors(F, d));
  PetscCall(SetUpScaling(F, d));
  PetscCall(CSTFStateSetUp(F, d));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%ssaddle_", F->hdr.prefix));
  PetscCall(CSSaddleCreate(m, prefix, PETSC_TRUE, PETSC_TRUE, (PetscBool)(F->saddle_mat == CS_SADDLE_MAT_AIJ), F->reuse_its, F->k, &F->saddle));
  PetscFunctionReturn(0);
}

/* -flow_variables spinor: the target class l0 (the lattice's lengths, or df's), the spin structure of df, the
   variables x = (u, psi) and their start, the energy, the rows [d1 omega; sphere] and <<Y_i|omega>>, the vectors,
   the scaling and the saddle solver (trianglefield_spinor.c). */
static PetscErrorCode SetUpTriangleFieldSpinor(CSWillmoreFlow F, CSTriangleField *d)
{
  CSMesh m = F->mesh;
  char   prefix[80];
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(d->dmH1, &d->lambda));
  PetscCall(VecDuplicate(d->lambda, &d->c0));
  PetscCall(VecDuplicate(d->lambda, &d->lamt));
  PetscCall(VecDuplicate(d->lambda, &d->star1));
  PetscCall(VecDuplicate(d->lambda, &d->iqH));
  PetscCall(DMCreateGlobalVector(m->dmV1, &d->star0));
  PetscCall(DMCreateGlobalVector(d->dmH3, &d->omt));
  PetscCall(CSTriangleFieldFromPositions(m, d->xpos0, d->dmH3, d->omt)); /* df: the spin structure */
  if (m->lt) PetscCall(CSTriangleFieldLogLengthsFromEdges(m, m->lt, d->dmH1, d->lambda));
  else PetscCall(CSTriangleFieldLogLengths(m, d->dmH3, d->omt, d->dmH1, d->lambda));
  PetscCall(CSOperatorLensCrossRatio(m, d->dmH1, &d->C));
  PetscCall(MatMult(d->C, d->lambda, d->c0));
  PetscCall(CSSpinorSpaceCreate(m, d->dmH1, d->lambda, &d->sp));
  PetscCall(CSSpinorSpaceSetConnection(d->sp, d->dmH3, d->omt));
  PetscCall(VecDestroy(&d->omt));
  PetscCall(CSTFSpinorSetUp(F, d));
  PetscCall(CSTriangleFieldFromPositions(m, d->xpos0, d->dmH3, d->omega));
  PetscCall(CSTFSpinorStart(F, d, HashUniform));
  PetscCall(VecDuplicate(F->x, &F->x0));
  PetscCall(VecCopy(F->x, F->x0));
  PetscCall(CreateEnergy(F, d));
  PetscCall(CSTFAppBSetUp(F, d));
  PetscCheck(CSTFAppBRows(F) == 0, F->hdr.comm, PETSC_ERR_SUP, "-%svariables spinor: the App. B constraints (volume, points, Moebius) are built for -%svariables omega only", F->hdr.prefix, F->hdr.prefix);
  PetscCall(SetUpHarmonicRows(F, d));
  if (d->wgauge > 0) { /* the gauge row: d mean(u) */
    PetscScalar *r;
    PetscCall(VecSet(F->rows[F->k - 1], 0));
    PetscCall(VecGetArray(F->rows[F->k - 1], &r));
    for (PetscInt i = 0; i < d->nVo; i++) r[i] = 1.0 / m->Nv;
    PetscCall(VecRestoreArray(F->rows[F->k - 1], &r));
  }
  PetscCall(CSWFSetUpPrimalVectors(F));
  PetscCall(VecCreateMPI(F->hdr.comm, d->nL + m->nf, PETSC_DETERMINE, &F->c)); /* rows [d1 omega; (|psi_f|^2 - 1)/2] */
  PetscCall(CSWFSetUpMultiplierVectors(F));
  PetscCall(SetUpScaling(F, d));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%ssaddle_", F->hdr.prefix));
  PetscCall(CSSaddleCreate(m, prefix, PETSC_TRUE, PETSC_TRUE, (PetscBool)(F->saddle_mat == CS_SADDLE_MAT_AIJ), F->reuse_its, F->k, &F->saddle));
  PetscFunctionReturn(0);
}

/* x = xt done: the restoration onto the rows near the violation ceiling (trianglefield_restore.c), the multipliers
   mu += dmu, nu += dnu; the spinors follow omega (signs nearest to the previous ones). */
static PetscErrorCode Accept(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  PetscCall(CSTFRestore(F));
  if (d->spinor) { /* the renormalisation onto (S^3)^F (the step is tangent to first order) */
    PetscCall(CSTFSpinorNormalize(F, d, F->x));
    PetscCall(CSTFSpinorOmega(d, F->x, d->omega));
  } else {
    PetscCall(CSSpinorFromTriangleField(d->sp, d->dmH3, F->x, d->psi, d->psit));
    PetscCall(VecCopy(d->psit, d->psi));
  }
  PetscCall(VecAXPY(F->mu, 1.0, F->dmu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] += F->dnu[j];
  PetscFunctionReturn(0);
}

/* The surface: the input's positions, or the Poisson reconstruction of the current omega. */
static PetscErrorCode Positions(CSWillmoreFlow F, PetscBool initial, Vec *x)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  if (initial) *x = d->xpos0;
  else {
    PetscCall(CSTriangleFieldReconstructionSolve(d->recon, d->spinor ? d->omega : F->x, d->xpos0, d->xpos));
    *x = d->xpos;
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode Destroy(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscFunctionBeginUser;
  if (!d) PetscFunctionReturn(0);
  PetscCall(DMDestroy(&d->dmH1));
  PetscCall(DMDestroy(&d->dmH3));
  PetscCall(MatDestroy(&d->C));
  PetscCall(MatDestroy(&d->D));
  PetscCall(MatDestroy(&d->CD));
  PetscCall(MatDestroy(&d->Klin));
  PetscCall(MatDestroy(&d->X));
  PetscCall(VecDestroy(&d->lambda));
  PetscCall(VecDestroy(&d->c0));
  PetscCall(VecDestroy(&d->star1));
  PetscCall(VecDestroy(&d->star0));
  PetscCall(VecDestroy(&d->iqH));
  PetscCall(VecDestroy(&d->clin));
  PetscCall(VecDestroy(&d->xpos0));
  PetscCall(VecDestroy(&d->xpos));
  PetscCall(CSTriangleFieldReconstructionDestroy(&d->recon));
  PetscCall(VecDestroy(&d->psi));
  PetscCall(VecDestroy(&d->psit));
  PetscCall(VecDestroy(&d->lamt));
  PetscCall(VecDestroy(&d->gspin));
  PetscCall(CSTFSpinorDestroy(d));
  PetscCall(CSSpinorSpaceDestroy(&d->sp));
  PetscCall(CSTFStateDestroy(d));
  PetscCall(PetscFree(F->data));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowTriangleFieldGetInfo(CSWillmoreFlow F, CSWillmoreFlowTriangleFieldInfo *info, PetscBool *is)
{
  CSTriangleField *d;
  PetscBool        tf;
  PetscFunctionBeginUser;
  PetscCall(PetscStrcmp(F->type, CSWILLMOREFLOWTRIANGLEFIELD, &tf));
  PetscCheck(tf || is, F->hdr.comm, PETSC_ERR_ARG_WRONG, "CSWillmoreFlowTriangleFieldGetInfo: -%stype %s is not trianglefield", F->hdr.prefix, F->type);
  if (is) *is = tf;
  info->integrability_violation = info->immersion_tol = info->spin_energy = -1;
  info->pinch_edges = info->pinch_vertices = -1;
  if (!tf) PetscFunctionReturn(0);
  d                             = (CSTriangleField *)F->data;
  info->integrability_violation = d->integ;
  info->immersion_tol           = d->immersion_tol;
  info->spin_energy             = d->espin;
  info->pinch_edges             = d->pinch;
  info->pinch_vertices          = d->pinchv;
  PetscFunctionReturn(0);
}

/* the kind's strategy (willmore_impl.h): CGD's step on its own variables (the triangle field), grouped: identity, the
   step, the variables' pipeline, its own data and options */
static const struct _CSWillmoreFlowOps TriangleFieldOps = {
  .id = 6, .conformal = PETSC_TRUE,
  /* the predictive step model was fitted on the vertex kinds; on triangle fields it fell behind (Morin 24 x 12, 7
     iterations: W 165.59 against 150.73 halving; Fig. 8's spiky sphere did not reach 1 % of the round icosphere's W
     in 40), so halving stays this kind's default until the model knows the integrability rows */
  .step_halving = PETSC_TRUE,
  /* the peak RSS of one step (docs/hardening.md "Memory per flow kind"): its 18 unknowns per vertex against the vertex
     kinds' 3, the same bytes per unknown (bunny_closed_cgal 5.7 GB, icosphere 5 1.6 GB, 48 x 48 lattice 397 MB / 2304) */
  .bytes_per_vertex = 160000,
  .trial = CSWFTrialCGD, .filter = CSWFFilterLagrangian, .accept = Accept, .grow = CSTFGrow, .shrink = CSWFShrinkCGD,
  .get_switch = CSWFDualStepGetSwitch, .set_switch = CSWFDualStepSetSwitch,
  .setup_problem = SetUpTriangleField, .evaluate = CSTFEvaluate, .operators = CSTFOperators, .constraints = CSTFConstraints, .positions = Positions,
  .setfromoptions = CSTFSetFromOptions, .setup = CSTFCheckOptions, .view = CSTFView, .destroy = Destroy,
};

PetscErrorCode CSWillmoreFlowCreate_TriangleField(CSWillmoreFlow F)
{
  CSTriangleField *d;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&d));
  F->data              = d;
  F->ops               = TriangleFieldOps;
  CSWFDualStepInitialize(&d->ds);
  d->wint              = 1e-4;
  d->restore_near      = 0.5;
  d->init              = CS_TF_INIT_DF;
  d->seed              = 1;
  d->amp               = 0.5;
  d->modes             = 8;
  d->wrelax            = 1e4;
  d->wgauge            = 0;
  d->mshift            = 0;
  d->wdecay            = 1;
  d->wspin_min         = 1e-3;
  d->stage_rtol        = 1e-3;
  d->stage_ctol        = 1e-8;
  d->immersion_tol     = 1e-6;
  d->integ             = -1; /* not evaluated yet */
  d->pinch             = -1;
  d->pinchv            = -1;
  d->cap_rises         = 0; /* off: see trianglefield_stepcap.c */
  d->cap_wtol          = 1e-6;
  d->cap_it            = -2;
  PetscFunctionReturn(0);
}
