/* -flow_type pgd: projected gradient descent (soliman2021 Sec. 4.1): an explicit step in the H^2 metric
   tangent to the constraints (the saddle solve with right-hand side [0; -g; 0], refined), then a Gauss-Newton
   projection back onto the constraint set (willmore_projection.c). */
#include "../../willmore_impl.h"

/* The PGD matrix [[H/t, X^T], [X, 0]] is singular (dependent rows of X); we solve with -I_Q/pgd_t_mu in the
   (2,2) block and remove the regularisation error by iterative refinement against the unregularised system:
   only its second row differs, residual -X df (and -B^T df). */
static PetscErrorCode RefinePGD(CSWillmoreFlow F, PetscBool *accept)
{
  Vec dmu2, df2;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->dmu, &dmu2));
  PetscCall(VecDuplicate(F->df, &df2));
  for (PetscInt ref = 0; ref < 3 && *accept; ref++) {
    PetscInt its;
    PetscCall(MatMult(F->Xc, F->df, F->ct));
    PetscCall(VecScale(F->ct, -1.0));
    for (PetscInt j = 0; j < F->k; j++) {
      PetscScalar v;
      PetscCall(VecDot(F->rows[j], F->df, &v));
      F->cxt[j] = -PetscRealPart(v);
    }
    PetscCall(VecSet(F->tmp, 0));
    PetscCall(CSWFTrySolve(F, F->ct, F->tmp, F->cxt, dmu2, df2, F->dnu2, &its, accept));
    F->kspits += its;
    if (!*accept) PetscCall(CSWFRejected(F, "linear solve failed"));
    else {
      PetscCall(VecAXPY(F->dmu, 1.0, dmu2));
      PetscCall(VecAXPY(F->df, 1.0, df2));
      for (PetscInt j = 0; j < F->k; j++) F->dnu[j] += F->dnu2[j];
    }
  }
  PetscCall(VecDestroy(&dmu2));
  PetscCall(VecDestroy(&df2));
  PetscFunctionReturn(0);
}

/* PGD (soliman2021 Sec. 4.1): right-hand side [0; -g; 0], refinement, then the projection of xt = x + df. */
static PetscErrorCode TrialPGD(CSWillmoreFlow F, PetscBool *accept)
{
  PetscInt its;
  PetscFunctionBeginUser;
  PetscCall(CSWFSetOperators(F, F->t, F->proj_tmu));
  PetscCall(VecSet(F->ct, 0));
  PetscCall(VecCopy(F->g, F->tmp));
  PetscCall(VecScale(F->tmp, -1.0));
  for (PetscInt j = 0; j < F->k; j++) F->cxt[j] = 0;
  PetscCall(CSWFTrySolve(F, F->ct, F->tmp, F->cxt, F->dmu, F->df, F->dnu, &its, accept));
  F->kspits += its;
  if (!*accept) PetscCall(CSWFRejected(F, "linear solve failed"));
  if (*accept) PetscCall(RefinePGD(F, accept));
  if (!*accept) PetscFunctionReturn(0);
  PetscCall(VecWAXPY(F->xt, 1.0, F->df, F->x));
  PetscCall(CSWFProject(F, F->xt, accept, &F->kspits));
  if (!*accept) PetscCall(CSWFRejected(F, "the projection onto the constraint set failed"));
  PetscFunctionReturn(0);
}

static PetscErrorCode SetUpPGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(!F->target[0], F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%starget_mesh with -%stype pgd: PGD keeps the class of its input and cannot move to another class (soliman2021 Sec. 4.2); use cgd", F->hdr.prefix, F->hdr.prefix);
  PetscFunctionReturn(0);
}

/* PGD starts on the constraint set */
static PetscErrorCode StartPGD(CSWillmoreFlow F)
{
  PetscBool ok;
  PetscFunctionBeginUser;
  /* the global rows are counted in the set-up (CSWFSetUpConstraints) */
  PetscCheck(F->conformal || F->k == 0, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "pgd without the conformal constraint is not supported");
  PetscCall(CSWFProject(F, F->x, &ok, &F->kspits_total));
  PetscCheck(ok, F->hdr.comm, PETSC_ERR_NOT_CONVERGED, "pgd: the initial projection onto the constraint set did not converge");
  PetscFunctionReturn(0);
}

/* PGD's multipliers are those of the last linearised problem */
static PetscErrorCode AcceptPGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecCopy(F->dmu, F->mu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] = F->dnu[j];
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewPGD(CSWillmoreFlow F, PetscViewer viewer)
{
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  projection: t_mu %g, at most %" PetscInt_FMT " Gauss-Newton iterations\n", (double)F->proj_tmu, F->proj_max_it));
  PetscFunctionReturn(0);
}

/* the kind's strategy (willmore_impl.h), grouped: identity, the step, hooks, its own data and options */
static const struct _CSWillmoreFlowOps PGDOps = {
  .id = 1, .conformal = PETSC_TRUE,
  .trial = TrialPGD, .filter = CSWFFilterEnergy, .accept = AcceptPGD, .grow = CSWFGrowPrimal, .shrink = CSWFShrinkPrimal,
  .setup = SetUpPGD, .start = StartPGD, .view = ViewPGD,
};

PetscErrorCode CSWillmoreFlowCreate_PGD(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  F->ops = PGDOps;
  PetscFunctionReturn(0);
}
