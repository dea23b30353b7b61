/* Projection onto the constraint set (PGD, soliman2021 Sec. 4.1) and the restoration of a CGD/GD state by it. */
#include "willmore_impl.h"

/* PGD projection onto the constraint set (soliman2021 Sec. 4.1: the explicit step leaves the nonlinear
   constraint manifold): Gauss-Newton steps, each the minimal-H^2-norm correction dx with X dx = -c,
   solved as the saddle system with t = 1 and a huge t_mu (the -I_Q/t_mu block only regularises the
   rank deficiency of X, docs/solvers.md). */
PetscErrorCode CSWFProject(CSWillmoreFlow F, Vec x, PetscBool *ok, PetscInt *kspits)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFProjectTo(F, x, 0.1 * F->ctol, ok, kspits));
  PetscFunctionReturn(0);
}

/* The projection, done once the violation is below vtarget (ok), or after -pgd_projection_max_it steps if it is
   below -flow_ctol by then. */
PetscErrorCode CSWFProjectTo(CSWillmoreFlow F, Vec x, PetscReal vtarget, PetscBool *ok, PetscInt *kspits)
{
  PetscReal conf, glob;
  Vec       pmu = NULL, pdf;
  PetscBool done = PETSC_FALSE;
  PetscFunctionBeginUser;
  *ok = PETSC_FALSE;
  /* the Newton corrections get their own vectors: F->dmu, F->df, F->dnu hold the step's solution, whose
     multipliers become PGD's mu and nu (overwriting them with the projection's left PGD with area/volume
     constraints at el_residual ~0.7 at the constrained minimum) */
  if (F->dmu) PetscCall(VecDuplicate(F->dmu, &pmu));
  PetscCall(VecDuplicate(F->df, &pdf));
  for (PetscInt it = 0; it < F->proj_max_it; it++) {
    PetscInt its;
    PetscCall(CSWFEvalConstraints(F, x, F->ct, F->cxt, PETSC_TRUE));
    PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
    if (!(conf == conf) || !(glob == glob)) done = PETSC_TRUE;
    else if (PetscMax(conf, glob) < vtarget) *ok = done = PETSC_TRUE;
    if (done) break;
    if (F->k) PetscCall(CSWFGlobalWeights(F));
    PetscCall(CSMetricUpdate(&F->metric, x));
    PetscCall(CSWFQuadDiffMetric(F, x, NULL));
    PetscCall(CSWFSetOperators(F, 1.0, F->proj_tmu));
    PetscCall(CSWFSolveCorrection(F, pmu, pdf, &its, ok));
    *kspits += its;
    if (!*ok) done = PETSC_TRUE;
    else PetscCall(VecAXPY(x, 1.0, pdf));
    *ok = PETSC_FALSE;
  }
  if (!done) { /* all Newton steps taken: feasible enough? */
    PetscCall(CSWFEvalConstraints(F, x, F->ct, F->cxt, PETSC_FALSE));
    PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
    *ok = (PetscBool)(PetscMax(conf, glob) < PetscMax(vtarget, F->ctol));
  }
  PetscCall(VecDestroy(&pmu));
  PetscCall(VecDestroy(&pdf));
  PetscFunctionReturn(0);
}

/* Restoration of an accepted CGD/GD state by PGD's Gauss-Newton projection (Project) onto the constraint set,
   with its own operator (t = 1, t_mu = -pgd_t_mu), whose restoring strength does not shrink with t as the
   step's does (the step's Schur complement H/t + t_mu X^T I_Q^{-1} X restores by a Levenberg-Marquardt step of
   parameter 1/(t t_mu)). Done when the state is stalled near the violation ceiling (-flow_restore_stalled, on:
   t < 1e-3 t_max and a violation above -flow_vmax / 10; a torus of revolution R = 2, bump 0.2, sat at |c| = 1e-2
   with t ~ 1e-14 for 300 iterations without it, and goes on with it), or, with -flow_restore_above V (off),
   whenever the violation exceeds V. The multipliers are kept; the next step factors its own operator. If the
   projection fails the state is left as it was and no restoration is tried again in the run (cow_cgal: it
   fails from |c| = 9e-3). -flow_restore_above 1e-3 helped nowhere (measured, docs/real_meshes.md): on the area +
   volume case of tests/cases/willmore_constraints.sh one restoration at iteration 0 sent the run past the
   critical point it converges to without. With -flow_step_model predictive the step model also restores a state
   (to vmax / 100) where no next step would stay below the ceiling (willmore_step_model.c). */
PetscErrorCode CSWFRestore(CSWillmoreFlow F, PetscInt *kspits)
{
  PetscReal conf, glob, v;
  PetscBool stalled;
  PetscFunctionBeginUser;
  stalled = (PetscBool)(F->restore_stalled && F->t < 1e-3 * F->tmax);
  if (F->restore_failed || (!stalled && !(F->vrestore > 0))) PetscFunctionReturn(0);
  PetscCall(CSWFEvalConstraints(F, F->x, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
  v = PetscMax(conf, glob);
  if (!((F->vrestore > 0 && v > F->vrestore) || (stalled && v > 0.1 * F->vmax))) PetscFunctionReturn(0);
  PetscCall(CSWFRestoreTo(F, v, 0.1 * F->ctol, kspits));
  PetscFunctionReturn(0);
}

/* The restoration of x (violation v) to vtarget, kept as it was if the projection fails (then never again). */
PetscErrorCode CSWFRestoreTo(CSWillmoreFlow F, PetscReal v, PetscReal vtarget, PetscInt *kspits)
{
  PetscBool ok;
  Vec       keep;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->x, &keep));
  PetscCall(VecCopy(F->x, keep));
  PetscCall(CSWFProjectTo(F, F->x, vtarget, &ok, kspits));
  F->saddle.wait = PetscMax(F->saddle.wait, 1); /* else the projection's factorisation preconditions the steps
                                                   in ~8 iterations, under the refactorisation threshold, for good */
  if (!ok) {
    PetscCall(VecCopy(keep, F->x));
    F->restore_failed = PETSC_TRUE; /* a failed projection costs -pgd_projection_max_it solves: not again in this run */
  }
  PetscCall(VecDestroy(&keep));
  PetscCall(PetscPrintf(F->hdr.comm, "     restoration after iteration %" PetscInt_FMT ": violation %.3e (t = %g): %s\n", F->it, (double)v, (double)F->t, ok ? "projected back onto the constraints" : "the projection failed; state kept, no more restorations in this run"));
  PetscFunctionReturn(0);
}
