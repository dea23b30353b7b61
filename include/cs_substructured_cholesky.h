/* PC type "cssubchol": a parallel direct solve of a sparse SPD matrix by substructuring (one Schur complement
   on the interface), with CHOLMOD on every rank. See src/operators/substructured_cholesky.c. */
#ifndef CS_SUBSTRUCTURED_CHOLESKY_H
#define CS_SUBSTRUCTURED_CHOLESKY_H
#include <petscksp.h>

/* PCRegister("cssubchol", ...) once per process */
PETSC_EXTERN PetscErrorCode CSSubCholRegister(void);
/* Of a set-up PC of this type, for reports (each may be NULL): G the size of the interface (global; 0 on one
   process), kept of this rank's factorisations how many took the interface Schur complement as CHOLMOD assembled
   it (cholmod_last_supernode.c), factorisations how many there were */
PETSC_EXTERN PetscErrorCode CSSubCholGetInfo(PC pc, PetscInt *G, PetscInt *kept, PetscInt *factorisations);
#endif
