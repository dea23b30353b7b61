/* The driver bin/confsurf: one function per task (registered by -task name in src/driver/main.c), each
   creating the mesh and the output from the options and handing the mesh to a method object. */
#ifndef CS_DRIVER_H
#define CS_DRIVER_H
#include "cs_output.h"

/* before MPI starts (src/driver/startup.c): Open MPI defaults for a serial run, its private session tree */
PETSC_EXTERN void CSSingletonDefaults(void);
/* before MPI starts: 0 (after one line on stderr) when a file PetscInitialize opens cannot be used */
PETSC_EXTERN int CSStartupFilesUsable(int argc, char **argv);

/* the task of -task (default info) on comm (src/driver/task_run.c): bin/confsurf and the library's callers (src/api) */
PETSC_EXTERN PetscErrorCode CSDriverRun(MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSTaskInfo(MPI_Comm comm);
/* -task spin's rho as an array of n values on rank 0 in place of -rho FILE (vertex order, or faces with
   -rho_location face) while set; set and cleared on every rank (src/driver/spin_input.c; src/api) */
PETSC_EXTERN PetscErrorCode CSDriverSpinSetRhoArray(PetscBool set, PetscInt n, const PetscReal rho[]);
PETSC_EXTERN PetscErrorCode CSTaskFlow(MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSTaskSpin(MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSTaskSpectrum(MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSTaskCurveFlow(MPI_Comm comm); /* src/driver/task_curveflow.c */
/* -task flow -flow_type bs (src/driver/task_flow_bs.c), registered in task_flow.c */
PETSC_EXTERN PetscErrorCode CSFlowBS(MPI_Comm comm, CSOutput *out);
/* -task flow -flow_type conformal (src/driver/task_flow_conformal.c) */
PETSC_EXTERN PetscErrorCode CSFlowConformal(MPI_Comm comm, CSOutput *out);
/* every flow, once all its options are read and before its first step: options given and not used are an error */
PETSC_EXTERN PetscErrorCode CSFlowCheckUnusedOptions(MPI_Comm comm);

#endif
