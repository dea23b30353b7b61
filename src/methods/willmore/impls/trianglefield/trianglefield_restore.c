/* The restoration of the triangle-field flow (issue 15, soliman2021 Fig. 15): Algorithm 1's CGD/GD restores an
   accepted state by PGD's Gauss-Newton projection (willmore_projection.c, CSWFRestore), which works on positions; this is
   the same projection for the omega variables of Algorithm 2, onto the rows [C~ lambda(omega) - c0; d1 omega;
   S omega] (Eq. 14 / 30, Eq. 31, face closure), <<Y_i|omega>> (Eq. 13) and App. B's, in the I_H1 metric (Eq. 32).
   Why: CGD's regularised dual block leaves each row at (I_Q / t_mu) dmu after a step, and the Morin surface's first
   step uses 83-85 % of the filter's ceiling -flow_vmax; then every trial step's violation tends to the current one
   from above as t -> 0 and all are rejected (docs/triangle_fields.md, "Fig. 15"). */
#include "trianglefield_impl.h"

/* One Gauss-Newton correction of omega = F->x toward the rows, the minimal-I_H1 dx with X dx = -c: the saddle system
   with t = 1 and t_mu = -flow_pgd_t_mu (its -I_Q/t_mu block only regularises the dependent rows, as in CSWFProject),
   the operators (I_H1, I_Q, row weights) at omega. On entry F->ct, F->cxt hold c(omega) with X in F->Xc. */
static PetscErrorCode Correction(CSWillmoreFlow F, CSTriangleField *d, Vec pmu, Vec pdf, PetscInt *its, PetscBool *ok)
{
  PetscFunctionBeginUser;
  PetscCall(CSTriangleFieldStars(F->mesh, d->dmH3, F->x, d->dmH1, d->star1, d->star0));
  PetscCall(CSTFOperators(F));
  PetscCall(CSWFSetOperators(F, 1.0, F->proj_tmu));
  PetscCall(CSWFSolveCorrection(F, pmu, pdf, its, ok));
  PetscFunctionReturn(0);
}

static PetscErrorCode ViolationAt(CSWillmoreFlow F, Vec x, PetscBool wantJ, PetscReal *v)
{
  PetscReal conf, glob;
  PetscFunctionBeginUser;
  PetscCall(CSWFEvalConstraints(F, x, F->ct, F->cxt, wantJ));
  PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
  *v = PetscMax(conf, glob);
  PetscFunctionReturn(0);
}

/* Gauss-Newton steps on F->x from violation v0 while each lowers the violation, until it is below 0.1 -flow_ctol
   or -flow_pgd_projection_max_it steps; a step that does not lower it is undone. *v: the violation at the end. */
static PetscErrorCode Project(CSWillmoreFlow F, CSTriangleField *d, PetscReal v0, PetscReal *v, PetscInt *nsteps, PetscInt *kspits)
{
  Vec       pmu, pdf;
  PetscReal vn;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->dmu, &pmu));
  PetscCall(VecDuplicate(F->df, &pdf));
  *v      = v0;
  *nsteps = 0;
  for (PetscInt it = 0; it < F->proj_max_it && *v >= 0.1 * F->ctol; it++) {
    PetscInt  its = 0;
    PetscBool ok;
    PetscCall(ViolationAt(F, F->x, PETSC_TRUE, &vn));
    PetscCall(Correction(F, d, pmu, pdf, &its, &ok));
    *kspits += its;
    if (!ok) break;
    PetscCall(VecAXPY(F->x, 1.0, pdf));
    PetscCall(ViolationAt(F, F->x, PETSC_FALSE, &vn));
    if (!(vn < *v)) { /* not a number, or no progress: undo it */
      PetscCall(VecAXPY(F->x, -1.0, pdf));
      break;
    }
    *v = vn;
    (*nsteps)++;
  }
  PetscCall(VecDestroy(&pmu));
  PetscCall(VecDestroy(&pdf));
  PetscFunctionReturn(0);
}

/* The restoration of an accepted omega (the accept hook's first act): when the violation v is near the ceiling
   (v > -flow_restore_near_ceiling times -flow_vmax, default 0.5), above -flow_restore_above, or the state is stalled
   as CSWFRestore defines it (-flow_restore_stalled: t < 1e-3 t_max and v > vmax / 10), project omega back onto
   the rows (Project). Kept when it lowers v at least tenfold; else omega is left as it was and no restoration is
   tried again in the run. The multipliers are kept; the next step factors its own operator. Not for -flow_variables
   spinor (its rows are the sphere rows of (u, psi)), nor while the integrability rows are relaxed (no ceiling). */
PetscErrorCode CSTFRestore(CSWillmoreFlow F)
{
  CSTriangleField *d = (CSTriangleField *)F->data;
  PetscReal        v, vend = 0;
  PetscInt         nsteps = 0, kspits = 0;
  PetscBool        near, stalled, above, ok;
  Vec              keep;
  PetscFunctionBeginUser;
  if (d->spinor || F->restore_failed || F->it < d->istart || !F->step_control) PetscFunctionReturn(0);
  PetscCall(ViolationAt(F, F->x, PETSC_FALSE, &v));
  near    = (PetscBool)(d->restore_near > 0 && v > d->restore_near * F->vmax);
  stalled = (PetscBool)(F->restore_stalled && F->t < 1e-3 * F->tmax && v > 0.1 * F->vmax);
  above   = (PetscBool)(F->vrestore > 0 && v > F->vrestore);
  if (!near && !stalled && !above) PetscFunctionReturn(0);
  PetscCall(VecDuplicate(F->x, &keep));
  PetscCall(VecCopy(F->x, keep));
  PetscCall(Project(F, d, v, &vend, &nsteps, &kspits));
  F->kspits += kspits;
  F->saddle.wait = PetscMax(F->saddle.wait, 1); /* as CSWFRestore: the projection's factorisation is not the step's */
  ok = (PetscBool)(vend <= 0.1 * v);
  if (!ok) {
    PetscCall(VecCopy(keep, F->x));
    F->restore_failed = PETSC_TRUE;
  }
  PetscCall(VecDestroy(&keep));
  PetscCall(PetscPrintf(F->hdr.comm, "     restoration after iteration %" PetscInt_FMT " (%s%s): violation %.3e -> %.3e in %" PetscInt_FMT " Gauss-Newton steps (t = %g): %s\n", F->it, near || above ? F->hdr.prefix : "", near ? "restore_near_ceiling" : (above ? "restore_above exceeded" : "stalled"), (double)v, (double)vend, nsteps, (double)F->t, ok ? "restored" : "not lowered tenfold; state kept, no more restorations in this run"));
  PetscFunctionReturn(0);
}
