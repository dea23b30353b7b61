/* Cholesky factorisation of a quaternionic Hermitian K - sigma (real AIJ with 4x4 blocks of left
   multiplication, crane2011 Sec. 5.1) in its complex form with CHOLMOD (SuiteSparse) called directly: half the
   flops of the real 4V x 4V factorisation (see cholmod_factor.c); PETSc's real build cannot express it.
   Serial only (one process); the symbolic analysis is kept while the pattern stays. */
#ifndef CS_CHOLMOD_H
#define CS_CHOLMOD_H
#include <petscksp.h>

typedef struct _p_CSCholmod *CSCholmod;
/* ordering: "amd", "metis", "nesdis" or "auto" (CHOLMOD's own choice among several) */
PETSC_EXTERN PetscErrorCode CSCholmodCreate(const char ordering[], CSCholmod *f);
/* factor K - sigma I in complex form; K: SeqAIJ, every 4x4 block the left multiplication by a quaternion */
PETSC_EXTERN PetscErrorCode CSCholmodSetUpQuaternion(CSCholmod f, Mat K, PetscReal sigma);
/* y = (K - sigma)^{-1} x for real 4V vectors */
PETSC_EXTERN PetscErrorCode CSCholmodSolve(CSCholmod f, Vec x, Vec y);
PETSC_EXTERN PetscErrorCode CSCholmodDestroy(CSCholmod *f);

/* cholmod_start on c with the project's settings: supernodal, and the ordering named ("amd", "metis", "nesdis", or
   "auto": CHOLMOD's own choice among several). Shared by cholmod_factor.c and quaternion_cholesky.c. */
struct cholmod_common_struct;
PETSC_EXTERN PetscErrorCode CSCholmodStartCommon(const char ordering[], struct cholmod_common_struct *c);

/* The project's default sparse Cholesky for an SPD operator: CHOLMOD on one rank, the substructured CHOLMOD
   factorisation (PC cssubchol) on several. */
PETSC_EXTERN PetscErrorCode CSSetDefaultCholesky(PC pc);
#endif
