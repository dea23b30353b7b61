/* src/linalg/: sparse factorisations and matrix utilities that know nothing of meshes. Registered with PETSc by
   CSInitializePackage (include/cs_package.h): the PC "cssubchol" and the MatSolverTypes "csquat" and
   "cscholmod" (Cholesky of a quaternionic Hermitian SeqAIJ matrix, chosen with
   -<prefix>pc_factor_mat_solver_type). Solver notes and measurements: docs/solvers.md. */
#ifndef CS_LINALG_H
#define CS_LINALG_H
#include <petscksp.h>
#include "cs_log.h"

#define PCCSSUBCHOL        "cssubchol"
#define MATSOLVERCSQUAT    "csquat"
#define MATSOLVERCSCHOLMOD "cscholmod"

/* for CSInitializePackage: PCRegister(PCCSSUBCHOL, ...), MatSolverTypeRegister(MATSOLVERCS*, MATSEQAIJ, MAT_FACTOR_CHOLESKY, ...) */
PETSC_EXTERN PetscErrorCode PCCreate_CSSubChol(PC);
PETSC_EXTERN PetscErrorCode MatGetFactor_SeqAIJ_CSQuat(Mat, MatFactorType, Mat *);
PETSC_EXTERN PetscErrorCode MatGetFactor_SeqAIJ_CSCholmod(Mat, MatFactorType, Mat *);
/* a csquat or cscholmod factor F (PCFactorGetMatrix) factors A - shift I for the matrix A it is given: the
   shift-and-invert of the spin method hands it K itself, no shifted copy (docs/solvers.md, csquat) */
PETSC_EXTERN PetscErrorCode MatCSQuatFactorSetShift(Mat F, PetscReal shift);

/* Y += a X for AIJ matrices (Seq or MPI, same layout) whose nonzero patterns stay fixed, X's within Y's: the
   position of each of X's entries in Y is found once (*map, created at the first call, freed with
   CSMatAddMapDestroy), later calls are one pass over the values. MatAXPY with SUBSET_NONZERO_PATTERN searches every
   row again (PETSc 3.18 MatAXPY_Basic): 60 ms per call at 82k faces. Increases Y's state. */
typedef struct _p_CSMatAddMap *CSMatAddMap;
PETSC_EXTERN PetscErrorCode CSMatAddFixedPattern(Mat Y, PetscScalar a, Mat X, CSMatAddMap *map);
PETSC_EXTERN PetscErrorCode CSMatAddMapDestroy(CSMatAddMap *map);

/* S = A + shift I for a square SeqAIJ A storing every diagonal entry: S shares A's row structure (and
   references A), only the values are its own; MAT_REUSE_MATRIX refills them (A's pattern unchanged). The value
   added to each diagonal entry is exactly MatShift's. */
PETSC_EXTERN PetscErrorCode CSMatShiftedShared(Mat A, PetscScalar shift, MatReuse reuse, Mat *S);

/* Iterative solvers of the Schur complement of the two-field saddle system [[-D/t_mu, X], [X^T, H/t]] on a
   PCFIELDSPLIT (src/linalg/schur_iterative.c, docs/scaling.md): "direct" = the caller's factorisation of the
   assembled S (nothing here), "primal" = CG + csh2 on S = H/t + t_mu X^T D^-1 X applied matrix-free,
   "multiplier" = GMRES + Jacobi(D/t_mu) on S_mu = D/t_mu + t X H^-1 X^T with an inner CG + csh2 solve of H/t.
   SetDefaults (before the PC's SetFromOptions): fieldsplit Schur, full factorisation, Schur preconditioner a11.
   SetSplits: the splits in the type's order (isE the multiplier/edge rows, isV the positions). SetSubSolvers (after
   the PC's first KSPSetUp): the split solvers' defaults, then their SetFromOptions; schur_rtol is the Schur
   solve's relative tolerance. "bddc" = CG + PCBDDC on S as a MATIS (the caller assembles it, CSMatISFromSquares,
   and hands it to the fieldsplit as the user Schur preconditioner; SetDefaults sets schur_precondition user). */
typedef enum {
  CS_SCHUR_DIRECT,
  CS_SCHUR_PRIMAL,
  CS_SCHUR_MULTIPLIER,
  CS_SCHUR_BDDC
} CSSchurSolveType;
PETSC_EXTERN const char *const CSSchurSolveTypes[];
PETSC_EXTERN PetscErrorCode    CSSchurIterativeSetDefaults(PC pc, CSSchurSolveType type);
PETSC_EXTERN PetscErrorCode    CSSchurIterativeSetSplits(PC pc, CSSchurSolveType type, IS isE, IS isV);
PETSC_EXTERN PetscErrorCode    CSSchurIterativeSetSubSolvers(PC pc, CSSchurSolveType type, PetscReal schur_rtol);

/* norms_i = 2-norm of block i of x (blocks of bs consecutive entries; norms has one entry per local block) */
PETSC_EXTERN PetscErrorCode CSVecBlockNorms(Vec x, PetscInt bs, Vec norms);

/* X = [B_0; B_1; ...]: per rank its owned rows of B_0, then of B_1, ... (a vector of X's rows is the per-rank
   concatenation of the blocks' local parts); same column layout for all blocks; MAT_REUSE_MATRIX refills *X. */
PETSC_EXTERN PetscErrorCode CSMatStackRows(PetscInt n, Mat B[], MatReuse reuse, Mat *X);
/* B = A (x) I_bs on interlaced vectors, B(bs i + c, bs j + c) = A(i, j), as AIJ; MAT_REUSE_MATRIX refills *B. */
PETSC_EXTERN PetscErrorCode CSMatKronIdentity(Mat A, PetscInt bs, MatReuse reuse, Mat *B);
/* After the PC's SetFromOptions: if pc is a MUMPS LU/Cholesky without -<prefix>mat_mumps_icntl_7, order with AMD
   (ICNTL(7) = 0; src/linalg/mumps_ordering.c). Needs operators: A (of the size and type of the matrix to be
   factored) is set when pc has none yet. */
PETSC_EXTERN PetscErrorCode CSMumpsDefaultOrdering(PC pc, Mat A);
/* S = diag(d) + sum_k A_k^T diag(w_k) A_k (d, w_k >= 0; A_k MPIAIJ with d's column layout, w_k with A_k's row layout)
   as an unassembled MATIS for PCBDDC: rank p holds d / (the number of ranks holding the dof) on every dof it holds,
   and the terms of A_k's owned rows (src/linalg/mat_is_squares.c). MAT_REUSE_MATRIX replaces the local matrix of *S;
   the caller must keep the pattern of the A_k (the local-to-global map is not compared). */
PETSC_EXTERN PetscErrorCode CSMatISFromSquares(Vec d, PetscInt n, Mat A[], Vec w[], MatReuse reuse, Mat *S);
#endif
