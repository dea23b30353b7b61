/* Iterative Schur-complement solvers for a two-field saddle system (issue #16; docs/scaling.md)
     K = [ -D/t_mu  X   ]     D = I_Q (diagonal, E x E), X (E x 3V), H (3V x 3V) SPD with a factored
         [  X^T     H/t ]     preconditioner (PC csh2, condition <= 2),
   configured on a PCFIELDSPLIT of type Schur (full factorisation) in place of the direct factorisation of the
   primal Schur complement S = H/t + t_mu X^T D^{-1} X (CHOLMOD / cssubchol, the default):
   - CS_SCHUR_PRIMAL ("primal"): the splits edges first, positions second, as the direct default; the Schur
     complement S is applied matrix-free (MATSCHURCOMPLEMENT: A00^{-1} = -t_mu D^{-1} exact by Jacobi) and solved by
     CG preconditioned with csh2 on A11 = H/t (schur_precondition a11): the spectrum of (H/t)^{-1} S is
     1 + t t_mu lambda(X^T D^{-1} X, H), bounded independently of the mesh (X^T D^{-1} X is of order 2, H of order 4)
     but growing with c = t t_mu: CG needs O(sqrt(1 + c lambda_max)) iterations.
   - CS_SCHUR_MULTIPLIER ("multiplier", the (a)): positions first, edges second; the Schur complement is
     -S_mu, S_mu = D/t_mu + t X H^{-1} X^T, applied with an inner CG + csh2 solve of H/t, preconditioned by
     A11 = -D/t_mu (Jacobi). With Z the E x V star incidence (Z^T X = 0, the log cross ratios around a vertex star
     sum to zero) S_mu Z y = D Z y / t_mu: this preconditioner is exact on range(Z), so the coarse space of the
     issue's two-level split is already solved exactly; on the D-orthogonal complement range(D^{-1} X),
     S_mu D^{-1} X = (t/t_mu) X H^{-1} S, i.e. the same spectrum 1 + c lambda(X^T D^{-1} X, H) as the primal path.
     S_mu is negative definite in the fieldsplit's sign, so the outer Krylov method is GMRES (CG checks the sign).
   - CS_SCHUR_BDDC ("bddc", the (b)): splits as primal; S (applied matrix-free) solved by CG preconditioned
     by PCBDDC on the unassembled S (MATIS, built by the caller from the mesh partition: CSMatISFromSquares), the
     user Schur preconditioner, with deluxe scaling and the adaptive coarse space (threshold 2) by default: measured
     on the level-4 bumpy sphere at c = 800, plain BDDC (vertices, edges) needs 500-1300 CG iterations on 2-4 ranks,
     deluxe alone is exact on 2 ranks (1 iteration) but not on 4 (570-690), deluxe + adaptive 5-6 on 4 ranks
     (docs/scaling.md). The options -<prefix>fieldsplit_1_pc_bddc_* override (SetBDDCDefaults).
   Every choice is a default set in code before the sub-solvers' SetFromOptions: -<prefix>fieldsplit_{0,1}_*
   options still override it. */
#include "cs_linalg.h"

const char *const CSSchurSolveTypes[] = {"direct", "primal", "multiplier", "bddc", "CSSchurSolveType", "CS_SCHUR_", NULL};

/* CG with the csh2 preconditioner on a positions (H/t) block, to relative tolerance rtol */
static PetscErrorCode SetCGH2(KSP ksp, PetscReal rtol)
{
  PC pc;
  PetscFunctionBeginUser;
  PetscCall(KSPSetType(ksp, KSPCG));
  PetscCall(KSPSetTolerances(ksp, rtol, PETSC_DEFAULT, PETSC_DEFAULT, 10000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, "csh2"));
  PetscFunctionReturn(0);
}

/* PCBDDC's defaults of the project, deluxe scaling and the adaptive coarse space (threshold 2), which have no setters
   in 3.18: a SetFromOptions pass of the PC reads them from a private options database that holds only them (every
   other BDDC option's default is its current value, so nothing else changes), before the KSP's SetFromOptions reads
   the user's -<prefix>pc_bddc_* over them. The global options database is not written, and no private PETSc struct
   is touched. */
static PetscErrorCode SetBDDCDefaults(PC bddc)
{
  PetscOptions defaults, user;
  const char  *prefix;
  PetscFunctionBeginUser;
  PetscCall(PCGetOptionsPrefix(bddc, &prefix));
  PetscCall(PetscObjectGetOptions((PetscObject)bddc, &user));
  PetscCall(PetscOptionsCreate(&defaults));
  if (prefix) PetscCall(PetscOptionsPrefixPush(defaults, prefix));
  PetscCall(PetscOptionsSetValue(defaults, "-pc_bddc_use_deluxe_scaling", "true"));
  PetscCall(PetscOptionsSetValue(defaults, "-pc_bddc_adaptive_threshold", "2.0"));
  if (prefix) PetscCall(PetscOptionsPrefixPop(defaults));
  PetscCall(PetscObjectSetOptions((PetscObject)bddc, defaults));
  PetscCall(PCSetFromOptions(bddc));
  PetscCall(PetscObjectSetOptions((PetscObject)bddc, user));
  PetscCall(PetscOptionsDestroy(&defaults));
  PetscFunctionReturn(0);
}

/* Jacobi (exact on the diagonal block A00 = -D/t_mu, or the preconditioner D/t_mu of S_mu) */
static PetscErrorCode SetJacobi(KSP ksp, KSPType type, PetscReal rtol)
{
  PC pc;
  PetscFunctionBeginUser;
  PetscCall(KSPSetType(ksp, type));
  if (rtol > 0) PetscCall(KSPSetTolerances(ksp, rtol, PETSC_DEFAULT, PETSC_DEFAULT, 10000));
  PetscCall(KSPGetPC(ksp, &pc));
  PetscCall(PCSetType(pc, PCJACOBI));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSchurIterativeSetDefaults(PC pc, CSSchurSolveType type)
{
  PetscFunctionBeginUser;
  PetscCall(PCSetType(pc, PCFIELDSPLIT));
  PetscCall(PCFieldSplitSetType(pc, PC_COMPOSITE_SCHUR));
  PetscCall(PCFieldSplitSetSchurFactType(pc, PC_FIELDSPLIT_SCHUR_FACT_FULL));
  /* no assembled S, or (bddc) the caller's unassembled one */
  PetscCall(PCFieldSplitSetSchurPre(pc, type == CS_SCHUR_BDDC ? PC_FIELDSPLIT_SCHUR_PRE_USER : PC_FIELDSPLIT_SCHUR_PRE_A11, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSchurIterativeSetSplits(PC pc, CSSchurSolveType type, IS isE, IS isV)
{
  PetscFunctionBeginUser;
  if (type == CS_SCHUR_PRIMAL || type == CS_SCHUR_BDDC) {
    PetscCall(PCFieldSplitSetIS(pc, "0", isE));
    PetscCall(PCFieldSplitSetIS(pc, "1", isV));
  } else {
    PetscCall(PCFieldSplitSetIS(pc, "0", isV));
    PetscCall(PCFieldSplitSetIS(pc, "1", isE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSSchurIterativeSetSubSolvers(PC pc, CSSchurSolveType type, PetscReal schur_rtol)
{
  KSP     *sub;
  PetscInt n;
  PetscFunctionBeginUser;
  PetscCall(PCFieldSplitSchurGetSubKSP(pc, &n, &sub));
  if (type == CS_SCHUR_PRIMAL) {
    PetscCall(SetJacobi(sub[0], KSPPREONLY, 0));
    PetscCall(SetCGH2(sub[1], schur_rtol));
  } else if (type == CS_SCHUR_BDDC) {
    PC bddc;
    PetscCall(SetJacobi(sub[0], KSPPREONLY, 0));
    PetscCall(KSPSetType(sub[1], KSPCG));
    PetscCall(KSPSetTolerances(sub[1], schur_rtol, PETSC_DEFAULT, PETSC_DEFAULT, 10000));
    PetscCall(KSPGetPC(sub[1], &bddc));
    PetscCall(PCSetType(bddc, PCBDDC));
    PetscCall(SetBDDCDefaults(bddc));
  } else {
    /* the inner H solve sits inside every application of S_mu: it must be much tighter than the outer one */
    PetscCall(SetCGH2(sub[0], 1e-3 * schur_rtol));
    PetscCall(SetJacobi(sub[1], KSPGMRES, schur_rtol));
    PetscCall(KSPGMRESSetRestart(sub[1], 200));
  }
  for (PetscInt i = 0; i < 2; i++) PetscCall(KSPSetFromOptions(sub[i]));
  PetscCall(PetscFree(sub));
  PetscFunctionReturn(0);
}
