/* CGD's least-squares multipliers with a Gauss-Newton projection (-flow_multiplier_ls_every K; docs/boundary_twist.md
   "The fix"). CGD's dual step (soliman2021 Sec. 4.2, Algorithm 1 line 11 with the I_Q metric of Eq. 25) restores a
   constraint direction of singular value s of X = C Dlambda at the rate ~ t t_mu s^2 / lambda_H; a nearly dependent
   direction (the annulus' modulus with both boundary rings held: s ~ 3e-3) then creeps at 1 - 5e-5 per step. Every
   K iterations, with one factorisation each of the step's saddle matrix at t = 1 and t_mu = -flow_multiplier_ls_t_mu
   (t t_mu -> infinity on every direction; the exact dependencies of X stay regularised by -I_Q/t_mu):
     1. after the accepted step, PGD's Gauss-Newton projection onto c = 0 (willmore_projection.c) with that t_mu;
     2. before the next step, at the projected state, [mu; nu] <- argmin || g + X^T mu + B^T nu ||_{H^-1}: the
        saddle system with right-hand side [0; -r; 0], r = g + X^T mu + B^T nu, i.e. X H^-1 X^T dmu = -X H^-1 r.
   At CGD's fixed point (c = 0, r = 0: the constrained Euler-Lagrange equation, soliman2021 Theorem 3.2) the
   projection is skipped and dmu = 0, so the fixed points, hence the converged answers, are unchanged. */
#include "cgd_impl.h"
#include "cs_util.h"

PetscErrorCode CSWFMultiplierLSOptions(CSWillmoreFlow F, CSWF_CGD *cgd, PetscOptionItems *PetscOptionsObject)
{
  PetscFunctionBeginUser;
  PetscCall(CSOptionsInt("-multiplier_ls_every", "CGD: every this many iterations restore the constraints by a Gauss-Newton projection and replace the multipliers by their least-squares estimate argmin |g + X^T mu|_{H^-1} (0: never; docs/boundary_twist.md)", NULL, cgd->ls_every, &cgd->ls_every, NULL));
  PetscCall(CSOptionsReal("-multiplier_ls_t_mu", "CGD: t_mu (with t = 1) of the projection and of the least-squares multiplier solve; large enough that t_mu s^2 / lambda_H >> 1 for the smallest singular value s of X", NULL, cgd->ls_tmu, &cgd->ls_tmu, NULL));
  PetscCheck(cgd->ls_every >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%smultiplier_ls_every %" PetscInt_FMT ": use 0 (off) or a positive iteration count", F->hdr.prefix, cgd->ls_every);
  PetscCheck(cgd->ls_tmu > 0 && !PetscIsInfOrNanReal(cgd->ls_tmu), F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%smultiplier_ls_t_mu %g: must be finite and > 0", F->hdr.prefix, (double)cgd->ls_tmu);
  PetscFunctionReturn(0);
}

/* rather refused than ignored: the least-squares multipliers are CGD's dual step on the conformal rows */
PetscErrorCode CSWFMultiplierLSCheck(CSWillmoreFlow F, CSWF_CGD *cgd)
{
  PetscFunctionBeginUser;
  PetscCheck(!cgd->ls_every || (F->ops.dual == CSWFMultiplierLS && F->conformal), F->hdr.comm, PETSC_ERR_SUP, "-%smultiplier_ls_every %" PetscInt_FMT ": only for -%stype cgd with the conformal constraint", F->hdr.prefix, cgd->ls_every, F->hdr.prefix);
  PetscFunctionReturn(0);
}

static PetscBool Due(CSWillmoreFlow F, PetscInt it)
{
  CSWF_CGD *cgd = (CSWF_CGD *)F->data;
  return (PetscBool)(cgd->ls_every > 0 && F->conformal && it % cgd->ls_every == 0);
}

/* The next CSSaddleSetOperators builds a fresh factorisation: one kept for the other t_mu would precondition badly. */
static void FreshFactorisation(CSWillmoreFlow F)
{
  F->saddle.wait = PetscMax(F->saddle.wait, 1);
}

/* After an accepted step (x = xt), before the estimate at the next iteration: PGD's Gauss-Newton projection
   (willmore_projection.c) with t_mu = -multiplier_ls_t_mu, strong along the nearly dependent direction too. The
   multipliers are re-estimated at the projected state before they are used (CSWFMultiplierLS). A failed
   projection leaves the state as it was. */
PetscErrorCode CSWFMultiplierLSRestore(CSWillmoreFlow F)
{
  CSWF_CGD *cgd = (CSWF_CGD *)F->data;
  PetscReal conf, glob, keep_tmu = F->proj_tmu;
  PetscBool ok;
  PetscInt  its = 0;
  Vec       keep;
  PetscFunctionBeginUser;
  if (!Due(F, F->it + 1)) PetscFunctionReturn(0);
  PetscCall(CSWFEvalConstraints(F, F->x, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(CSWFViolation(F, F->ct, F->cxt, &conf, &glob));
  if (!(PetscMax(conf, glob) >= 0.1 * F->ctol)) PetscFunctionReturn(0);
  PetscCall(VecDuplicate(F->x, &keep));
  PetscCall(VecCopy(F->x, keep));
  F->proj_tmu = cgd->ls_tmu;
  PetscCall(CSWFProject(F, F->x, &ok, &its));
  F->proj_tmu = keep_tmu;
  F->kspits += its;
  FreshFactorisation(F);
  if (!ok) PetscCall(VecCopy(keep, F->x));
  PetscCall(VecDestroy(&keep));
  PetscCall(PetscInfo(NULL, "projection after iteration %" PetscInt_FMT ": violation %.3e: %s\n", F->it, (double)PetscMax(conf, glob), ok ? "projected" : "failed, state kept"));
  PetscFunctionReturn(0);
}

/* The estimate at x (after the step's operators are set up: H, I_Q, global weights); F->r and F->el updated. */
PetscErrorCode CSWFMultiplierLS(CSWillmoreFlow F)
{
  CSWF_CGD *cgd = (CSWF_CGD *)F->data;
  PetscInt  its = 0;
  PetscBool ok;
  PetscReal el0 = F->el;
  PetscFunctionBeginUser;
  if (!Due(F, F->it)) PetscFunctionReturn(0);
  FreshFactorisation(F);
  PetscCall(CSWFSetOperators(F, 1.0, cgd->ls_tmu));
  PetscCall(VecSet(F->ct, 0));
  PetscCall(VecCopy(F->r, F->tmp));
  PetscCall(VecScale(F->tmp, -1.0));
  for (PetscInt j = 0; j < F->k; j++) F->cxt[j] = 0;
  PetscCall(CSWFTrySolve(F, F->ct, F->tmp, F->cxt, F->dmu, F->df, F->dnu, &its, &ok));
  F->kspits_total += its; /* (F->kspits counts the step's own solves, from zero) */
  FreshFactorisation(F);
  if (!ok) PetscFunctionReturn(0); /* the multipliers are kept; the step goes on with CGD's own */
  PetscCall(VecAXPY(F->mu, 1.0, F->dmu));
  for (PetscInt j = 0; j < F->k; j++) F->nu[j] += F->dnu[j];
  PetscCall(CSWFResidual(F, &F->el));
  cgd->ls_count++;
  PetscCall(PetscInfo(NULL, "least-squares multipliers at iteration %" PetscInt_FMT ": EL residual %.3e -> %.3e (%" PetscInt_FMT " Krylov iterations)\n", F->it, (double)el0, (double)F->el, its));
  PetscFunctionReturn(0);
}
