/* The MUMPS ordering default of the project: AMD (ICNTL(7) = 0). Debian's MUMPS has neither METIS nor SCOTCH and
   falls back to PORD, which is slow and fill-heavy (level-5 saddle: 52.3M factor entries in 4.3 s with PORD,
   15.9M in 0.55 s with AMD; ../shared/PETSC-NOTES.md, docs/solvers.md). */
#include "cs_linalg.h"

PetscErrorCode CSMumpsDefaultOrdering(PC pc, Mat A)
{
  PetscBool     isfactor, set, has_op;
  MatSolverType st = NULL;
  const char   *prefix;
  PetscOptions  options;
  Mat           F;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompareAny((PetscObject)pc, &isfactor, PCLU, PCCHOLESKY, ""));
  if (!isfactor) PetscFunctionReturn(0);
  PetscCall(PCFactorGetMatSolverType(pc, &st));
  if (!st || strcmp(st, MATSOLVERMUMPS)) PetscFunctionReturn(0);
  /* the user's ordering wins: asked of the PC's own options database under its prefix, where MUMPS reads it */
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PetscObjectGetOptions((PetscObject)pc, &options));
  PetscCall(PetscOptionsHasName(options, prefix, "-mat_mumps_icntl_7", &set));
  if (set) PetscFunctionReturn(0);
  PetscCall(PCGetOperatorsSet(pc, NULL, &has_op));
  if (!has_op) PetscCall(PCSetOperators(pc, A, A));
  PetscCall(PCFactorSetUpMatSolverType(pc));
  PetscCall(PCFactorGetMatrix(pc, &F));
  PetscCall(MatMumpsSetIcntl(F, 7, 0));
  PetscFunctionReturn(0);
}
