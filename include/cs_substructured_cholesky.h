/* PC type "cssubchol": a parallel direct solve of a sparse SPD matrix by substructuring (one Schur complement
   on the interface), with CHOLMOD on every rank. See src/operators/substructured_cholesky.c. */
#ifndef CS_SUBSTRUCTURED_CHOLESKY_H
#define CS_SUBSTRUCTURED_CHOLESKY_H
#include <petscksp.h>

/* PCRegister("cssubchol", ...) once per process */
PETSC_EXTERN PetscErrorCode CSSubCholRegister(void);
/* size of the interface (global) of a set-up PC of this type, for reports; 0 on one process */
PETSC_EXTERN PetscErrorCode CSSubCholGetInterfaceSize(PC pc, PetscInt *G);
#endif
