/* Global (few-row) constraints: total area, enclosed volume, point positions (soliman2021 App. D
   "Constraints", App. B). */
#include "cs_constraints.h"
#include "cs_util.h"

PetscErrorCode CSGlobalConstraintEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[])
{
  PetscFunctionBeginUser;
  PetscCall(g->evaluate(g, x, c, rows));
  PetscFunctionReturn(0);
}

PetscErrorCode CSGlobalConstraintDestroy(CSGlobalConstraint *g)
{
  PetscFunctionBeginUser;
  if (!*g) PetscFunctionReturn(0);
  if ((*g)->destroy) PetscCall((*g)->destroy(*g));
  PetscCall(PetscFree(*g));
  PetscFunctionReturn(0);
}

PetscErrorCode CSGlobalConstraintCreateShell(CSMesh mesh, const char name[], PetscInt k, CSGlobalConstraint *g)
{
  PetscFunctionBeginUser;
  PetscCall(PetscNew(g));
  PetscCall(PetscStrncpy((*g)->name, name, sizeof((*g)->name)));
  (*g)->mesh = mesh;
  (*g)->k    = k;
  PetscFunctionReturn(0);
}

/* Central differences of c along n seeded random directions d against the rows: the largest over d of
   max_j |(c_j(x+hd) - c_j(x-hd))/2h - <row_j, d>| / max_j |<row_j, d>| (relative to the largest row's slope, so
   that a row with a vanishing slope along d does not divide by zero). */
PetscErrorCode CSGlobalConstraintCheckRows(CSGlobalConstraint g, Vec x, PetscReal h, PetscInt n, PetscReal *relerr)
{
  PetscInt    k = g->k;
  Vec        *rows, d, xp;
  PetscReal  *cp, *cm;
  PetscRandom rnd;
  PetscFunctionBeginUser;
  *relerr = 0;
  PetscCall(VecDuplicateVecs(x, k, &rows));
  PetscCall(VecDuplicate(x, &d));
  PetscCall(VecDuplicate(x, &xp));
  PetscCall(PetscMalloc2(k, &cp, k, &cm));
  PetscCall(CSGlobalConstraintEvaluate(g, x, cp, rows));
  PetscCall(PetscRandomCreate(g->mesh->comm, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1, 1));
  PetscCall(PetscRandomSetSeed(rnd, 20210811));
  PetscCall(PetscRandomSeed(rnd));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal err = 0, slope = 0;
    PetscCall(VecSetRandom(d, rnd));
    PetscCall(VecWAXPY(xp, h, d, x));
    PetscCall(CSGlobalConstraintEvaluate(g, xp, cp, NULL));
    PetscCall(VecWAXPY(xp, -h, d, x));
    PetscCall(CSGlobalConstraintEvaluate(g, xp, cm, NULL));
    for (PetscInt j = 0; j < k; j++) {
      PetscScalar an;
      PetscCall(VecDot(rows[j], d, &an));
      err   = PetscMax(err, PetscAbsReal((cp[j] - cm[j]) / (2 * h) - PetscRealPart(an)));
      slope = PetscMax(slope, PetscAbsScalar(an));
    }
    *relerr = PetscMax(*relerr, err / PetscMax(slope, 1e-300));
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(PetscFree2(cp, cm));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&xp));
  PetscCall(VecDestroyVecs(k, &rows));
  PetscFunctionReturn(0);
}

/* The object common to all global constraints; ctx is owned (freed by destroy). */
static PetscErrorCode GlobalConstraintNew(CSMesh mesh, const char name[], PetscInt k, void *ctx, PetscErrorCode (*evaluate)(CSGlobalConstraint, Vec, PetscReal[], Vec[]), PetscErrorCode (*destroy)(CSGlobalConstraint), CSGlobalConstraint *g)
{
  PetscFunctionBeginUser;
  PetscCall(CSGlobalConstraintCreateShell(mesh, name, k, g));
  (*g)->ctx      = ctx;
  (*g)->evaluate = evaluate;
  (*g)->destroy  = destroy;
  PetscFunctionReturn(0);
}

typedef struct {
  CSEnergy  e; /* area or volume energy: value and gradient */
  PetscReal target;
} EnergyConstraintCtx;

static PetscErrorCode EnergyConstraintEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[])
{
  EnergyConstraintCtx *ctx = (EnergyConstraintCtx *)g->ctx;
  PetscReal            v;
  PetscFunctionBeginUser;
  if (rows) PetscCall(CSEnergyGradient(ctx->e, x, &v, rows[0]));
  else PetscCall(CSEnergyValue(ctx->e, x, &v));
  c[0] = v - ctx->target;
  PetscFunctionReturn(0);
}

static PetscErrorCode EnergyConstraintDestroy(CSGlobalConstraint g)
{
  EnergyConstraintCtx *ctx = (EnergyConstraintCtx *)g->ctx;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyDestroy(&ctx->e));
  PetscCall(PetscFree(ctx));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateEnergyConstraint(CSMesh mesh, const char name[], CSEnergy e, PetscReal target, CSGlobalConstraint *g)
{
  EnergyConstraintCtx *ctx;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&ctx));
  ctx->e      = e;
  ctx->target = target;
  PetscCall(GlobalConstraintNew(mesh, name, 1, ctx, EnergyConstraintEvaluate, EnergyConstraintDestroy, g));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreateArea(CSMesh mesh, PetscReal target, CSGlobalConstraint *g)
{
  CSEnergy e;
  PetscFunctionBeginUser;
  PetscCheck(target > 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_constraint_area %g: the target area must be positive", (double)target);
  PetscCall(CSEnergyCreateArea(mesh, &e));
  PetscCall(CreateEnergyConstraint(mesh, "area", e, target, g));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreateVolume(CSMesh mesh, PetscReal target, CSGlobalConstraint *g)
{
  CSEnergy e;
  PetscFunctionBeginUser;
  PetscCheck(mesh->topo.boundary_loops == 0, mesh->comm, PETSC_ERR_ARG_WRONG, "-flow_constraint_volume: the mesh %s has %" PetscInt_FMT " boundary loop(s); the enclosed volume is only defined for closed surfaces", mesh->name, mesh->topo.boundary_loops);
  PetscCheck(target > 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_constraint_volume %g: the target volume must be positive (outward-oriented surface)", (double)target);
  PetscCall(CSEnergyCreateVolume(mesh, &e));
  PetscCall(CreateEnergyConstraint(mesh, "volume", e, target, g));
  PetscFunctionReturn(0);
}

/* ---- point constraints ---- */
typedef struct {
  PetscInt   n;     /* points */
  PetscInt  *vnat;  /* file-order vertex index */
  PetscReal *p;     /* 3n targets */
  PetscInt  *vloc;  /* local vertex owning point k on this rank, or -1 */
} PointsCtx;

static PetscErrorCode PointsEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[])
{
  PointsCtx       *ctx = (PointsCtx *)g->ctx;
  CSMesh           m   = g->mesh;
  Vec              xl;
  const PetscReal *p;
  PetscReal       *cl;
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(3 * ctx->n, &cl));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  for (PetscInt k = 0; k < ctx->n; k++)
    if (ctx->vloc[k] >= 0)
      for (int d = 0; d < 3; d++) cl[3 * k + d] = p[3 * ctx->vloc[k] + d] - ctx->p[3 * k + d];
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MPIU_Allreduce(cl, c, 3 * ctx->n, MPIU_REAL, MPIU_SUM, m->comm));
  PetscCall(PetscFree(cl));
  if (rows) {
    for (PetscInt k = 0; k < ctx->n; k++)
      for (int d = 0; d < 3; d++) {
        CSLocalSum s;
        PetscCall(CSLocalSumBegin(m->dmV3, &s));
        if (ctx->vloc[k] >= 0) s.a[3 * ctx->vloc[k] + d] = 1.0;
        PetscCall(CSLocalSumEnd(&s, rows[3 * k + d]));
      }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode PointsDestroy(CSGlobalConstraint g)
{
  PointsCtx *ctx = (PointsCtx *)g->ctx;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(ctx->vnat));
  PetscCall(PetscFree(ctx->p));
  PetscCall(PetscFree(ctx->vloc));
  PetscCall(PetscFree(ctx));
  PetscFunctionReturn(0);
}

typedef enum {
  POINT_OK,
  POINT_END,
  POINT_FORMAT,
  POINT_RANGE,
  POINT_LARGE,
  POINT_TWICE
} PointRecord;

/* One record "index x y z" alone on its line *line (CSTokens) */
static PointRecord ReadPointRecord(CSTokens *t, PetscInt Nv, const PetscBool seen[], long long *idx, double x[3], PetscInt *line)
{
  const char *tok;
  size_t      len;
  PetscInt    l;
  CSTokens    peek;
  if (!CSTokensNext(t, &tok, &len, line)) return POINT_END;
  if (CSTokenInt(tok, len, idx)) return POINT_FORMAT;
  for (int d = 0; d < 3; d++)
    if (!CSTokensNext(t, &tok, &len, &l) || l != *line || CSTokenReal(tok, len, &x[d])) return POINT_FORMAT;
  peek = *t;
  if (CSTokensNext(&peek, &tok, &len, &l) && l == *line) return POINT_FORMAT;
  if (*idx < 0 || *idx >= Nv) return POINT_RANGE;
  for (int d = 0; d < 3; d++)
    if (PetscAbsReal(x[d]) > 1e12) return POINT_LARGE; /* a target no surface reaches: 31 rejections, exit 0 (issue 36) */
  return seen[*idx] ? POINT_TWICE : POINT_OK;
}

/* Rank 0: read and check the file (errors name option, file, line). */
static PetscErrorCode ReadPointsFile(const char option[], const char path[], PetscInt Nv, PetscInt *n, PetscInt **vnat, PetscReal **p)
{
  CSTokens    t;
  PetscInt    capv = 0, capp = 0, cnt = 0, line = 0;
  PetscBool  *seen;
  long long   idx = 0;
  double      x[3];
  PointRecord r;
  char        msg[PETSC_MAX_PATH_LEN + 160] = "";
  PetscFunctionBeginUser;
  *vnat = NULL;
  *p    = NULL;
  PetscCall(CSTokensLoad(option, path, &t));
  PetscCall(PetscCalloc1(Nv, &seen));
  while ((r = ReadPointRecord(&t, Nv, seen, &idx, x, &line)) == POINT_OK) {
    seen[idx] = PETSC_TRUE;
    PetscCall(CSArrayGrow(sizeof(PetscInt), cnt, 16, &capv, (void **)vnat));
    PetscCall(CSArrayGrow(3 * sizeof(PetscReal), cnt, 16, &capp, (void **)p));
    (*vnat)[cnt] = (PetscInt)idx;
    for (int d = 0; d < 3; d++) (*p)[3 * cnt + d] = x[d];
    cnt++;
  }
  if (r == POINT_FORMAT) PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s %s line %" PetscInt_FMT ": expected 'vertex_index x y z' (0-based index and three finite numbers)", option, t.name, line));
  if (r == POINT_LARGE) PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s %s line %" PetscInt_FMT ": the target point (%g, %g, %g) lies beyond 1e12", option, t.name, line, x[0], x[1], x[2]));
  if (r == POINT_RANGE) PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s %s line %" PetscInt_FMT ": vertex index %lld out of range [0, %" PetscInt_FMT ")", option, t.name, line, idx, Nv));
  if (r == POINT_TWICE) PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s %s line %" PetscInt_FMT ": vertex %lld is constrained twice", option, t.name, line, idx));
  if (r == POINT_END && !cnt) PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s %s: no point constraints in the file", option, t.name));
  PetscCall(PetscFree(seen));
  PetscCall(CSTokensDestroy(&t));
  if (msg[0]) { /* nothing leaks on the error paths (issue 18, item 12) */
    PetscCall(PetscFree(*vnat));
    PetscCall(PetscFree(*p));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s", msg);
  }
  *n = cnt;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreatePointsFromFile(CSMesh mesh, const char option[], const char path[], CSGlobalConstraint *g)
{
  PointsCtx  *ctx;
  PetscInt    n = 0, *vnat = NULL;
  PetscReal  *p = NULL;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(mesh->comm, &rank));
  CSRootCall(mesh->comm, ReadPointsFile(option, path, mesh->Nv, &n, &vnat, &p));
  PetscCallMPI(MPI_Bcast(&n, 1, MPIU_INT, 0, mesh->comm));
  PetscCall(PetscNew(&ctx));
  ctx->n = n;
  PetscCall(PetscMalloc1(n, &ctx->vnat));
  PetscCall(PetscMalloc1(3 * n, &ctx->p));
  PetscCall(PetscMalloc1(n, &ctx->vloc));
  if (!rank) {
    PetscCall(PetscArraycpy(ctx->vnat, vnat, n));
    PetscCall(PetscArraycpy(ctx->p, p, 3 * n));
    PetscCall(PetscFree(vnat));
    PetscCall(PetscFree(p));
  }
  PetscCallMPI(MPI_Bcast(ctx->vnat, n, MPIU_INT, 0, mesh->comm));
  PetscCallMPI(MPI_Bcast(ctx->p, 3 * n, MPIU_REAL, 0, mesh->comm));
  for (PetscInt k = 0; k < n; k++) {
    ctx->vloc[k] = -1;
    for (PetscInt v = 0; v < mesh->nv; v++)
      if (mesh->vertOwned[v] && mesh->vertNatural[v] == ctx->vnat[k]) ctx->vloc[k] = v;
  }
  PetscCall(GlobalConstraintNew(mesh, "points", 3 * n, ctx, PointsEvaluate, PointsDestroy, g));
  PetscFunctionReturn(0);
}

/* ---- Moebius balancing ----
   The conformal constraint (length cross ratios) and the smooth Willmore energy are invariant under Moebius
   transformations, but the discrete energy (soliman2021 Eq. 28) is not: it decreases when the vertices are
   graded along a Moebius orbit (a Moebius-boosted icosphere keeps every cross ratio to 1e-13 and has a lower
   discrete W; far enough along, W drops below 4 pi). Left free, CGD slides along that orbit and ends on a
   mesh whose resolution has collapsed (options/flow_vesicle.opts, options/flow_class_change.opts). The three
   rows below fix the Moebius gauge as Hersch's balancing condition does (the centre of mass of the current
   area distribution, placed on the input's vertices, stays at the input's centroid):
     m(f) = sum_i A_i(f) (f0_i - c0) / (A(f0) sqrt(A(f0))) = 0,   c0 = sum_i A_i(f0) f0_i / A(f0),
   A_i the barycentric vertex areas, so m(f0) = 0 exactly. Similarities of f leave m = 0 (m only sees the areas,
   and a scaling scales all of them), a Moebius boost b changes it to first order by 2 I0 b with the positive
   definite area-inertia tensor I0 of the input, so the rows fix exactly the three boost directions.
   Per face, sum_i A_i y_i = sum_f A_f ybar_f (ybar_f the mean of y over the face's corners), and the row d at
   a corner k is ybar_f[d] dA_f/df_k (CSTriangleAreaGradient). */
typedef struct {
  PetscReal *y;     /* (f0_i - c0) / (A0 sqrt(A0)) for the local vertices (with ghosts), 3 per vertex */
} MobiusCtx;

static PetscErrorCode MobiusEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[])
{
  MobiusCtx       *ctx = (MobiusCtx *)g->ctx;
  CSMesh           m   = g->mesh;
  Vec              xl;
  CSLocalSum       rs[3];
  const PetscReal *p;
  PetscReal        cl[3] = {0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  if (rows)
    for (int d = 0; d < 3; d++) PetscCall(CSLocalSumBegin(m->dmV3, &rs[d]));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) { /* every face lives on exactly one rank */
    const PetscInt  *v = F.v;
    const PetscReal *const *q = F.c;
    PetscReal        an[3], A, N[3], ybar[3], dA[3][3];
    CSTriangleAreaVector(q, an);
    A = CSVecNorm(an);
    for (int d = 0; d < 3; d++) ybar[d] = (ctx->y[3 * v[0] + d] + ctx->y[3 * v[1] + d] + ctx->y[3 * v[2] + d]) / 3;
    for (int d = 0; d < 3; d++) cl[d] += A * ybar[d];
    if (!rows || !(A > 0)) continue;
    for (int d = 0; d < 3; d++) N[d] = an[d] / A;
    CSTriangleAreaGradient(q, N, dA);
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 3; d++)
        for (int e = 0; e < 3; e++) rs[d].a[3 * v[k] + e] += ybar[d] * dA[k][e];
  }
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MPIU_Allreduce(cl, c, 3, MPIU_REAL, MPIU_SUM, m->comm));
  if (rows)
    for (int d = 0; d < 3; d++) PetscCall(CSLocalSumEnd(&rs[d], rows[d]));
  PetscFunctionReturn(0);
}

static PetscErrorCode MobiusDestroy(CSGlobalConstraint g)
{
  MobiusCtx *ctx = (MobiusCtx *)g->ctx;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(ctx->y));
  PetscCall(PetscFree(ctx));
  PetscFunctionReturn(0);
}

/* Sums over the faces of x0 (local positions p) of A_f and A_f times the mean of y over the corners (y NULL:
   of the corner positions): t[0..2], t[3] = area, summed over the ranks. */
static PetscErrorCode InputAreaSums(CSMesh mesh, const PetscReal *p, const PetscReal *y, PetscReal t[4])
{
  PetscReal s[4] = {0, 0, 0, 0};
  PetscFunctionBeginUser;
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, p, &F);) {
    PetscReal an[3], A;
    CSTriangleAreaVector(F.c, an);
    A = CSVecNorm(an);
    s[3] += A;
    for (int d = 0; d < 3; d++) s[d] += A * (y ? y[3 * F.v[0] + d] + y[3 * F.v[1] + d] + y[3 * F.v[2] + d] : F.c[0][d] + F.c[1][d] + F.c[2][d]) / 3;
  }
  PetscCall(MPIU_Allreduce(s, t, 4, MPIU_REAL, MPIU_SUM, mesh->comm));
  PetscFunctionReturn(0);
}

/* The balancing rows (rotation false) or the rotation gauge (true, below) on the input x0. */
static PetscErrorCode CreateAreaMoments(CSMesh mesh, Vec x0, PetscBool rotation, CSGlobalConstraint *g)
{
  MobiusCtx       *ctx;
  Vec              xl;
  const PetscReal *p;
  PetscReal        t[4], c0[3], scale, mean[4];
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(mesh, x0, &xl, &p));
  PetscCall(InputAreaSums(mesh, p, NULL, t));
  PetscCheck(t[3] > 0, mesh->comm, PETSC_ERR_ARG_WRONG, "-flow_constraint_%s: the input mesh %s has zero area", rotation ? "rotation" : "mobius", mesh->name);
  for (int d = 0; d < 3; d++) c0[d] = t[d] / t[3];
  scale = 1.0 / (t[3] * PetscSqrtReal(t[3]));
  PetscCall(PetscNew(&ctx));
  PetscCall(PetscMalloc1(3 * mesh->nv, &ctx->y));
  for (PetscInt i = 0; i < mesh->nv; i++) {
    const PetscReal *q = p + 3 * i;
    const int        a[3] = {0, 0, 1}, b[3] = {1, 2, 2}; /* the off-diagonal pairs xy, xz, yz */
    for (int d = 0; d < 3; d++) ctx->y[3 * i + d] = rotation ? (q[a[d]] - c0[a[d]]) * (q[b[d]] - c0[b[d]]) * scale / PetscSqrtReal(t[3]) : (q[d] - c0[d]) * scale;
  }
  if (rotation) { /* minus the input's area-weighted mean, so that the rows vanish at x0 */
    PetscCall(InputAreaSums(mesh, p, ctx->y, mean));
    for (PetscInt i = 0; i < mesh->nv; i++)
      for (int d = 0; d < 3; d++) ctx->y[3 * i + d] -= mean[d] / mean[3];
  }
  PetscCall(CSMeshRestoreLocalPositions(mesh, x0, &xl, &p));
  PetscCall(GlobalConstraintNew(mesh, rotation ? "rotation" : "mobius", 3, ctx, MobiusEvaluate, MobiusDestroy, g));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreateMobiusBalance(CSMesh mesh, Vec x0, CSGlobalConstraint *g)
{
  PetscFunctionBeginUser;
  PetscCall(CreateAreaMoments(mesh, x0, PETSC_FALSE, g));
  PetscFunctionReturn(0);
}

/* ---- rotation gauge of the domain ----
   The balancing fixes the three boosts of the Moebius group of the domain sphere; its three rotations stay free:
   f o R keeps the conformal class, W, area, volume and the balance. The discrete W depends on them at O(h^2) only,
   a very flat direction along which a nearly axisymmetric vesicle tumbles for hundreds of iterations with the EL
   residual stuck (docs/vesicle.md). These rows fix them as the balancing fixes the boosts: the off-diagonal entries
   of the second moment of the current area distribution placed on the input's vertices,
     r(f) = sum_i A_i(f) (y_i - ybar),  y_i = ((p_x p_y), (p_x p_z), (p_y p_z)) / A(f0)^2,  p = f0_i - c0,
   ybar the input's area-weighted mean of y (so r(f0) = 0). r only sees the areas: rotations and scalings of f in
   space (exact symmetries) leave it unchanged; a rotation of the domain turns the quadrupole of the area
   distribution and changes r once the conformal factor is anisotropic (a prolate's poles against its waist).
   The rotation about an axis of symmetry of that quadrupole stays free. */
PetscErrorCode CSConstraintCreateRotationGauge(CSMesh mesh, Vec x0, CSGlobalConstraint *g)
{
  PetscFunctionBeginUser;
  PetscCall(CreateAreaMoments(mesh, x0, PETSC_TRUE, g));
  PetscFunctionReturn(0);
}
