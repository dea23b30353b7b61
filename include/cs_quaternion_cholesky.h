/* Sparse Cholesky factorisation K - sigma = L L^H of a quaternionic Hermitian positive definite matrix in
   quaternion arithmetic (src/linalg/quaternion_cholesky.c): supernodal multifrontal, on the V x V pattern
   analysed by CHOLMOD (ordering and relaxed supernodes), with the dense kernels as real BLAS products.
   A quaternion multiply-add is 32 real flops against 64 for the 2 x 2 complex block of the complex form
   (cholmod_factor.c) and 128 for the 4 x 4 real block: half the flops and half the memory of the complex form.
   Serial only (one process); the symbolic analysis is kept while the nonzero pattern of K stays. */
#ifndef CS_QUATERNION_CHOLESKY_H
#define CS_QUATERNION_CHOLESKY_H
#include <petscmat.h>

typedef struct _p_CSQuatCholesky *CSQuatCholesky;
/* ordering: "amd", "metis", "nesdis" or "auto" (CHOLMOD's own choice among several) */
PETSC_EXTERN PetscErrorCode CSQuatCholeskyCreate(const char ordering[], CSQuatCholesky *f);
/* factor K - sigma I; K: SeqAIJ, every 4x4 block the left multiplication by a quaternion (CSQuatBlock) */
PETSC_EXTERN PetscErrorCode CSQuatCholeskySetUp(CSQuatCholesky f, Mat K, PetscReal sigma);
/* y = (K - sigma)^{-1} x for real 4V vectors (x and y may be the same vector) */
PETSC_EXTERN PetscErrorCode CSQuatCholeskySolve(CSQuatCholesky f, Vec x, Vec y);
PETSC_EXTERN PetscErrorCode CSQuatCholeskyDestroy(CSQuatCholesky *f);
#endif
