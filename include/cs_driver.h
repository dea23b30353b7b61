/* The driver bin/confsurf: its tasks (the methods register theirs in src/driver/main.c and task_flow.c). */
#ifndef CS_DRIVER_H
#define CS_DRIVER_H
#include "cs_output.h"

PETSC_EXTERN PetscErrorCode CSTaskInfo(MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSTaskFlow(MPI_Comm comm);

#endif
