/* PC type "cssubchol": a parallel direct solve of a sparse SPD matrix by substructuring (one Schur complement
   on the interface), with CHOLMOD on every rank. See src/linalg/substructured_cholesky.c
   and docs/solvers.md. */
#ifndef CS_SUBSTRUCTURED_CHOLESKY_H
#define CS_SUBSTRUCTURED_CHOLESKY_H
#include <petscksp.h>

/* Of a set-up PC of this type, for reports (each may be NULL): G the size of the interface (global; 0 on one
   process), factorisations how many numeric factorisations this rank made */
PETSC_EXTERN PetscErrorCode CSSubCholGetInfo(PC pc, PetscInt *G, PetscInt *factorisations);
#endif
