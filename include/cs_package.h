/* CSInitializePackage: registers confsurf's PetscLogEvents (include/cs_log.h), its PCs (cssubchol, csh2) and its
   MatSolverTypes (csquat, cscholmod) with PETSc, once per PetscInitialize (PETSc's XInitializePackage style).
   Call it after SlepcInitialize and before any options are read (bin/confsurf and the unit tests do). */
#ifndef CS_PACKAGE_H
#define CS_PACKAGE_H
#include <petscsys.h>

PETSC_EXTERN PetscErrorCode CSInitializePackage(void);
PETSC_EXTERN PetscErrorCode CSFinalizePackage(void);
#endif
