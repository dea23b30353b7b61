/* Global constraints on triangle fields (soliman2021 App. B): a translation-invariant position constraint c(f)
   evaluated at the frozen-metric Poisson reconstruction f = R omega (include/cs_operators_lens.h), its rows pulled
   back by R^T (Eq. 22). The volume (B.2), relative point positions (B.1) and the Moebius balancing (the vertex
   flow's gauge rows, constraints_global.c, extended the same way). */
#include "cs_constraints.h"

typedef struct {
  CSGlobalConstraint     pos;      /* the position constraint (dmV3 rows) */
  CSTriangleFieldPoisson P;
  PetscBool              relative; /* points: rows 3 + j minus rows j % 3 (the first point anchors) */
  Vec                    f;        /* R omega */
  Vec                   *rpos;     /* pos->k position rows */
  PetscReal             *cpos;
} ExtensionCtx;

static PetscErrorCode ExtensionEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[])
{
  ExtensionCtx *ctx = (ExtensionCtx *)g->ctx;
  PetscInt      off = ctx->relative ? 3 : 0;
  PetscFunctionBeginUser;
  PetscCall(CSTriangleFieldPoissonApply(ctx->P, x, ctx->f));
  PetscCall(CSGlobalConstraintEvaluate(ctx->pos, ctx->f, ctx->cpos, rows ? ctx->rpos : NULL));
  for (PetscInt j = 0; j < g->k; j++) c[j] = ctx->cpos[off + j] - (ctx->relative ? ctx->cpos[j % 3] : 0);
  if (!rows) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < g->k; j++) {
    if (ctx->relative) PetscCall(VecAXPY(ctx->rpos[off + j], -1.0, ctx->rpos[j % 3]));
    PetscCall(CSTriangleFieldPoissonApplyTranspose(ctx->P, ctx->rpos[off + j], rows[j]));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ExtensionDestroy(CSGlobalConstraint g)
{
  ExtensionCtx *ctx = (ExtensionCtx *)g->ctx;
  PetscFunctionBeginUser;
  PetscCall(VecDestroyVecs(ctx->pos->k, &ctx->rpos));
  PetscCall(PetscFree(ctx->cpos));
  PetscCall(VecDestroy(&ctx->f));
  PetscCall(CSGlobalConstraintDestroy(&ctx->pos));
  PetscCall(CSTriangleFieldPoissonDestroy(&ctx->P));
  PetscCall(PetscFree(ctx));
  PetscFunctionReturn(0);
}

/* g = the extension of pos (owned from here on). */
static PetscErrorCode CreateExtension(CSMesh m, CSTriangleFieldPoisson P, CSGlobalConstraint pos, PetscBool relative, CSGlobalConstraint *g)
{
  ExtensionCtx *ctx;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&ctx));
  ctx->pos      = pos;
  ctx->P        = P;
  ctx->relative = relative;
  PetscCall(CSTriangleFieldPoissonReference(P));
  PetscCall(VecDuplicate(m->x, &ctx->f));
  PetscCall(VecDuplicateVecs(m->x, pos->k, &ctx->rpos));
  PetscCall(PetscCalloc1(pos->k, &ctx->cpos));
  PetscCall(PetscNew(g));
  PetscCall(PetscSNPrintf((*g)->name, sizeof((*g)->name), "trianglefield_%s", pos->name));
  (*g)->mesh     = m;
  (*g)->k        = pos->k - (relative ? 3 : 0);
  (*g)->ctx      = ctx;
  (*g)->evaluate = ExtensionEvaluate;
  (*g)->destroy  = ExtensionDestroy;
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreateTriangleFieldVolume(CSMesh m, CSTriangleFieldPoisson P, PetscReal target, CSGlobalConstraint *g)
{
  CSGlobalConstraint pos;
  PetscFunctionBeginUser;
  PetscCall(CSConstraintCreateVolume(m, target, &pos));
  PetscCall(CreateExtension(m, P, pos, PETSC_FALSE, g));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConstraintCreateTriangleFieldPoints(CSMesh m, CSTriangleFieldPoisson P, const char option[], const char path[], CSGlobalConstraint *g)
{
  CSGlobalConstraint pos;
  PetscFunctionBeginUser;
  PetscCall(CSConstraintCreatePointsFromFile(m, option, path, &pos));
  if (pos->k < 6) {
    PetscCall(CSGlobalConstraintDestroy(&pos));
    SETERRQ(m->comm, PETSC_ERR_ARG_WRONG, "%s %s: one point; a triangle field fixes positions only up to translation, so give at least 2 points (the first anchors the others)", option, path);
  }
  PetscCall(CreateExtension(m, P, pos, PETSC_TRUE, g));
  PetscFunctionReturn(0);
}

/* The Moebius balancing m(R omega) = 0 (the vertex flow's rows, CSConstraintCreateMobiusBalance, on the input x0):
   m only sees the vertex areas, so it is translation invariant and m(R df) = m(f) for every f; rows R^T grad m.
   The discrete W~ (App. D.1) is not Moebius invariant and falls along the Moebius orbit (docs/triangle_fields.md,
   Fig. 16); the three rows fix the boosts as they do for cgd. */
PetscErrorCode CSConstraintCreateTriangleFieldMobius(CSMesh m, CSTriangleFieldPoisson P, Vec x0, CSGlobalConstraint *g)
{
  CSGlobalConstraint pos;
  PetscFunctionBeginUser;
  PetscCall(CSConstraintCreateMobiusBalance(m, x0, &pos));
  PetscCall(CreateExtension(m, P, pos, PETSC_FALSE, g));
  PetscFunctionReturn(0);
}
