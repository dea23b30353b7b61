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
  PetscCall(PetscNew(g));
  PetscCall(PetscNew(&ctx));
  ctx->e      = e;
  ctx->target = target;
  PetscCall(PetscStrncpy((*g)->name, name, sizeof((*g)->name)));
  (*g)->mesh     = mesh;
  (*g)->k        = 1;
  (*g)->ctx      = ctx;
  (*g)->evaluate = EnergyConstraintEvaluate;
  (*g)->destroy  = EnergyConstraintDestroy;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreateArea(CSMesh mesh, PetscReal target, CSGlobalConstraint *g)
{
  CSEnergy e;
  PetscFunctionBeginUser;
  PetscCheck(target > 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-constraint_area %g: the target area must be positive", (double)target);
  PetscCall(CSEnergyCreateArea(mesh, &e));
  PetscCall(CreateEnergyConstraint(mesh, "area", e, target, g));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreateVolume(CSMesh mesh, PetscReal target, CSGlobalConstraint *g)
{
  CSEnergy e;
  PetscFunctionBeginUser;
  PetscCheck(mesh->topo.boundary_loops == 0, mesh->comm, PETSC_ERR_ARG_WRONG, "-constraint_volume: the mesh %s has %" PetscInt_FMT " boundary loop(s); the enclosed volume is only defined for closed surfaces", mesh->name, mesh->topo.boundary_loops);
  PetscCheck(target > 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-constraint_volume %g: the target volume must be positive (outward-oriented surface)", (double)target);
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
        Vec          r = rows[3 * k + d], rl;
        PetscScalar *a;
        PetscCall(DMGetLocalVector(m->dmV3, &rl));
        PetscCall(VecSet(rl, 0));
        PetscCall(VecGetArray(rl, &a));
        if (ctx->vloc[k] >= 0) a[3 * ctx->vloc[k] + d] = 1.0;
        PetscCall(VecRestoreArray(rl, &a));
        PetscCall(VecSet(r, 0));
        PetscCall(DMLocalToGlobal(m->dmV3, rl, ADD_VALUES, r));
        PetscCall(DMRestoreLocalVector(m->dmV3, &rl));
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

/* Rank 0: read and check the file (errors name option, file, line). */
static PetscErrorCode ReadPointsFile(const char option[], const char path[], PetscInt Nv, PetscInt *n, PetscInt **vnat, PetscReal **p)
{
  FILE     *fp;
  char      line[1024];
  PetscInt  cap = 16, cnt = 0, lineno = 0;
  PetscBool *seen;
  PetscFunctionBeginUser;
  fp = fopen(path, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot open the point-constraint file", option, path);
  PetscCall(PetscMalloc2(cap, vnat, 3 * cap, p));
  PetscCall(PetscCalloc1(Nv, &seen));
  while (fgets(line, sizeof(line), fp)) {
    long   idx;
    double a, b, c;
    char  *s = line, extra[2];
    int    nr;
    lineno++;
    while (*s == ' ' || *s == '\t') s++;
    if (*s == '#' || *s == '\n' || *s == '\r' || *s == 0) continue;
    nr = sscanf(s, "%ld %lf %lf %lf %1s", &idx, &a, &b, &c, extra);
    if (nr != 4 || PetscIsInfOrNanReal((PetscReal)a) || PetscIsInfOrNanReal((PetscReal)b) || PetscIsInfOrNanReal((PetscReal)c)) {
      fclose(fp);
      PetscCall(PetscFree(seen));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s line %" PetscInt_FMT ": expected 'vertex_index x y z' (0-based index and three finite numbers)", option, path, lineno);
    }
    if (idx < 0 || idx >= Nv || seen[idx]) {
      fclose(fp);
      PetscCall(PetscFree(seen));
      PetscCheck(idx >= 0 && idx < Nv, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s %s line %" PetscInt_FMT ": vertex index %ld out of range [0, %" PetscInt_FMT ")", option, path, lineno, idx, Nv);
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s %s line %" PetscInt_FMT ": vertex %ld is constrained twice", option, path, lineno, idx);
    }
    seen[idx] = PETSC_TRUE;
    if (cnt == cap) {
      PetscInt  *nv;
      PetscReal *np;
      PetscCall(PetscMalloc2(2 * cap, &nv, 6 * cap, &np));
      PetscCall(PetscArraycpy(nv, *vnat, cnt));
      PetscCall(PetscArraycpy(np, *p, 3 * cnt));
      PetscCall(PetscFree2(*vnat, *p));
      *vnat = nv;
      *p    = np;
      cap *= 2;
    }
    (*vnat)[cnt]      = (PetscInt)idx;
    (*p)[3 * cnt]     = a;
    (*p)[3 * cnt + 1] = b;
    (*p)[3 * cnt + 2] = c;
    cnt++;
  }
  fclose(fp);
  PetscCall(PetscFree(seen));
  PetscCheck(cnt > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: no point constraints in the file", option, path);
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
    PetscCall(PetscFree2(vnat, p));
  }
  PetscCallMPI(MPI_Bcast(ctx->vnat, n, MPIU_INT, 0, mesh->comm));
  PetscCallMPI(MPI_Bcast(ctx->p, 3 * n, MPIU_REAL, 0, mesh->comm));
  for (PetscInt k = 0; k < n; k++) {
    ctx->vloc[k] = -1;
    for (PetscInt v = 0; v < mesh->nv; v++)
      if (mesh->vertOwned[v] && mesh->vertNatural[v] == ctx->vnat[k]) ctx->vloc[k] = v;
  }
  PetscCall(PetscNew(g));
  PetscCall(PetscStrncpy((*g)->name, "points", sizeof((*g)->name)));
  (*g)->mesh     = mesh;
  (*g)->k        = 3 * n;
  (*g)->ctx      = ctx;
  (*g)->evaluate = PointsEvaluate;
  (*g)->destroy  = PointsDestroy;
  PetscFunctionReturn(0);
}
