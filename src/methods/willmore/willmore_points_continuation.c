/* Continuation of the point targets (-flow_points_stages K; issue 39, soliman2021 Fig. 18). A start far from its point
   targets (docs/willmore_flow.md "Fig. 18": an edge or more) does not start: CGD's first step trades the points'
   violation for class violation up to the ceiling the points' violation sets, and every later trial is rejected by that
   ceiling. With K stages the targets move from the input's own positions of the constrained vertices (violation 0) to
   the file's targets: stage k of K holds
     p_k = x0_v + (k/K) (p_v - x0_v),   so the rows are c_k(x) = x_v - p_k = c(x) - (1 - k/K) c(x0),
   the rows' Jacobian unchanged. A stage ends when el_residual_scaled < -points_stage_rtol and the violation <
   -points_stage_ctol, or after -points_stage_max_it iterations; the last (k = K) is the run itself, stopped by the
   flow's own rule. While k < K the flow neither converges nor stops as stationary or drifting, and keeps no best
   state (willmore_solve.c, willmore_stop.c): those states meet other targets. PGD begins each stage with its
   projection onto the new targets (StartFeasible). The stage is stored in checkpoints (willmore_state.c). */
#include "willmore_impl.h"
#include "cs_util.h"

typedef struct {
  CSGlobalConstraint      inner; /* the point constraint of the file (owned) */
  CSWFPointsContinuation *pc;    /* the flow's stage (borrowed: the flow outlives its constraints) */
  PetscReal              *c0;    /* c(x0): the input's offsets from the file's targets */
} WrapCtx;

/* c(x) - (1 - k/K) c(x0): the rows of the targets of stage k (the rows' gradients are the point constraint's) */
static PetscErrorCode WrapEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[])
{
  WrapCtx  *w = (WrapCtx *)g->ctx;
  PetscReal s = CSWFPointsFraction(w->pc);
  PetscFunctionBeginUser;
  PetscCall(CSGlobalConstraintEvaluate(w->inner, x, c, rows));
  for (PetscInt j = 0; j < g->k; j++) c[j] -= (1 - s) * w->c0[j];
  PetscFunctionReturn(0);
}

static PetscErrorCode WrapDestroy(CSGlobalConstraint g)
{
  WrapCtx *w = (WrapCtx *)g->ctx;
  PetscFunctionBeginUser;
  PetscCall(CSGlobalConstraintDestroy(&w->inner));
  PetscCall(PetscFree(w->c0));
  PetscCall(PetscFree(w));
  PetscFunctionReturn(0);
}

/* inside the flow's options block */
PetscErrorCode CSWFPointsContinuationOptions(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject)
{
  CSWFPointsContinuation *pc = &F->pcont;
  PetscFunctionBeginUser;
  PetscCall(CSOptionsInt("-points_stages", "Move the targets of -constraint_points from the input's positions to the file's in this many stages, target_k = x0 + (k/K)(target - x0) (0: off, the file's targets from the start; docs/willmore_flow.md \"Fig. 18\")", NULL, pc->stages, &pc->stages, NULL));
  PetscCall(CSOptionsReal("-points_stage_rtol", "A stage of -points_stages ends when el_residual_scaled is below this ...", NULL, pc->rtol, &pc->rtol, NULL));
  PetscCall(CSOptionsReal("-points_stage_ctol", "... and the violation below this", NULL, pc->ctol, &pc->ctol, NULL));
  PetscCall(CSOptionsInt("-points_stage_max_it", "A stage of -points_stages ends after this many iterations even if not converged (0: no limit)", NULL, pc->max_it, &pc->max_it, NULL));
  PetscFunctionReturn(0);
}

/* after the options block: values in range, and a problem the continuation applies to */
PetscErrorCode CSWFPointsContinuationCheck(CSWillmoreFlow F)
{
  CSWFPointsContinuation *pc = &F->pcont;
  const char             *p  = F->hdr.prefix;
  const CSOptionCheck     checks[] = {
    {"points_stages", (PetscReal)pc->stages, pc->stages >= 0 && pc->stages <= 100000, "use 0 (off) or a count of stages in [1, 100000]"},
    {"points_stage_rtol", pc->rtol, pc->rtol > 0, "must be > 0"},
    {"points_stage_ctol", pc->ctol, pc->ctol > 0, "must be > 0"},
    {"points_stage_max_it", (PetscReal)pc->max_it, pc->max_it >= 0, "use 0 (no limit) or a positive count"},
  };
  PetscFunctionBeginUser;
  PetscCall(CSCheckOptionValues(F->hdr.comm, p, sizeof(checks) / sizeof(checks[0]), checks));
  if (!pc->stages) PetscFunctionReturn(0);
  PetscCheck(F->points[0], F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%spoints_stages %" PetscInt_FMT ": moves the targets of -%sconstraint_points, which is not given", p, pc->stages, p);
  PetscCheck(!CSWFOwnVariables(F), F->hdr.comm, PETSC_ERR_SUP, "-%spoints_stages: not available for -%stype %s (its point rows are its own)", p, p, F->type);
  PetscFunctionReturn(0);
}

/* The point constraint *g of the file replaced by the staged one (no change when off); the first stage is k = 1 (k = 0
   is the input itself, already met). */
PetscErrorCode CSWFPointsContinuationWrap(CSWillmoreFlow F, CSGlobalConstraint *g)
{
  CSWFPointsContinuation *pc = &F->pcont;
  WrapCtx                *w;
  CSGlobalConstraint      s;
  PetscFunctionBeginUser;
  if (!pc->stages) PetscFunctionReturn(0);
  PetscCall(PetscNew(&w));
  w->inner = *g;
  w->pc    = pc;
  PetscCall(PetscMalloc1((*g)->k, &w->c0));
  PetscCall(CSGlobalConstraintEvaluate(*g, F->x0, w->c0, NULL));
  PetscCall(CSGlobalConstraintCreateShell(F->mesh, (*g)->name, (*g)->k, &s));
  s->ctx      = w;
  s->evaluate = WrapEvaluate;
  s->destroy  = WrapDestroy;
  pc->stage   = 1;
  pc->it0     = 0;
  pc->c0      = w->c0;
  pc->k       = (*g)->k;
  pc->off     = 0; /* its rows' place among the global rows: after those added before it (CSWFAddConstraint appends) */
  for (PetscInt j = 0; j < F->ng; j++) pc->off += F->gc[j]->k;
  *g          = s;
  PetscFunctionReturn(0);
}

/* the largest |c_j(x) - target_j| against the file's targets, from the rows' values cx of this stage */
static PetscReal FileViolation(CSWillmoreFlow F)
{
  CSWFPointsContinuation *pc = &F->pcont;
  PetscReal               s = CSWFPointsFraction(pc), v = 0;
  for (PetscInt j = 0; j < pc->k; j++) v = PetscMax(v, PetscAbsReal(F->cx[pc->off + j] + (1 - s) * pc->c0[j]));
  return v;
}

/* A kind whose filter compares energies only (PGD) steps from a state on the constraint set: x is projected onto the
   new targets (a stage's move is small, so PGD's projection converges where it fails from the far start). */
static PetscErrorCode StartFeasible(CSWillmoreFlow F)
{
  PetscBool ok;
  PetscFunctionBeginUser;
  if (F->ops.filter != CSWFFilterEnergy) PetscFunctionReturn(0);
  PetscCall(CSWFProject(F, F->x, &ok, &F->kspits_total));
  if (!ok) PetscCall(PetscPrintf(F->hdr.comm, "flow: the projection onto the targets of point stage %" PetscInt_FMT " did not converge; the flow goes on from the state as it is (more -%spoints_stages move the targets less per stage)\n", F->pcont.stage, F->hdr.prefix));
  PetscFunctionReturn(0);
}

/* After the evaluation at x: the stage ends when converged to its tolerances or after its iterations; *moved when the
   targets moved (the caller evaluates again). */
PetscErrorCode CSWFPointsContinuationAdvance(CSWillmoreFlow F, PetscBool *moved)
{
  CSWFPointsContinuation *pc = &F->pcont;
  PetscReal               v  = PetscMax(F->conf, F->glob);
  PetscBool               conv, maxit;
  PetscFunctionBeginUser;
  *moved = PETSC_FALSE;
  if (CSWFPointsFinal(pc) || F->reason) PetscFunctionReturn(0);
  conv  = (PetscBool)(F->els < pc->rtol && v < pc->ctol);
  maxit = (PetscBool)(pc->max_it > 0 && F->it - pc->it0 >= pc->max_it);
  if (!conv && !maxit) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(F->hdr.comm, "flow: point stage %" PetscInt_FMT " of %" PetscInt_FMT " %s at iteration %" PetscInt_FMT ": W %.10g, el_residual_scaled %.3e, violation %.3e; the targets move to %g of the way from the input\n", pc->stage, pc->stages, conv ? "converged" : "ended (-points_stage_max_it)", F->it, (double)F->E, (double)F->els, (double)v, (double)(pc->stage + 1) / (double)pc->stages));
  pc->stage++;
  pc->it0     = F->it;
  F->els_min  = -1; /* the drift test's reference restarts with the new targets (an earlier stage's is no reference) */
  F->drift_risen = 0;
  *moved      = PETSC_TRUE;
  PetscCall(StartFeasible(F));
  PetscFunctionReturn(0);
}

/* At a stop before the last stage: say so, with the distance from the file's targets (the reported violation is the
   stage's). */
PetscErrorCode CSWFPointsContinuationReport(CSWillmoreFlow F)
{
  CSWFPointsContinuation *pc = &F->pcont;
  PetscFunctionBeginUser;
  if (CSWFPointsFinal(pc) || !F->reason || !F->k) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(F->hdr.comm, "flow: stopped in point stage %" PetscInt_FMT " of %" PetscInt_FMT " (-%spoints_stages; the targets %g of the way from the input): the violation reported is this stage's, the points are %.3e from the file's targets\n", pc->stage, pc->stages, F->hdr.prefix, (double)CSWFPointsFraction(pc), (double)FileViolation(F)));
  PetscFunctionReturn(0);
}

/* checkpoint scalars [stages, stage, it0]: a resume continues the stage it was written in */
void CSWFPointsContinuationGetState(CSWillmoreFlow F, PetscReal ck[])
{
  ck[0] = (PetscReal)F->pcont.stages;
  ck[1] = (PetscReal)F->pcont.stage;
  ck[2] = (PetscReal)F->pcont.it0;
}

PetscErrorCode CSWFPointsContinuationSetState(CSWillmoreFlow F, PetscInt it, const PetscReal ck[])
{
  CSWFPointsContinuation *pc = &F->pcont;
  PetscFunctionBeginUser;
  PetscCheck(ck[0] == (PetscReal)pc->stages, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-resume: the checkpoint was written with -%spoints_stages %.0f, this run has %" PetscInt_FMT " (give the same)", F->hdr.prefix, (double)ck[0], pc->stages);
  if (!pc->stages) PetscFunctionReturn(0);
  PetscCheck(ck[1] >= 1 && ck[1] <= pc->stages && ck[1] == PetscFloorReal(ck[1]) && ck[2] >= 0 && ck[2] <= it && ck[2] == PetscFloorReal(ck[2]), F->hdr.comm, PETSC_ERR_FILE_UNEXPECTED, "-resume: the checkpoint's point stage %.0f (from iteration %.0f) is out of range (a damaged or crafted file)", (double)ck[1], (double)ck[2]);
  pc->stage = (PetscInt)ck[1];
  pc->it0   = (PetscInt)ck[2];
  PetscFunctionReturn(0);
}
