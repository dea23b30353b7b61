/* The task named by -task, run on comm: what bin/confsurf does (src/driver/main.c) and what the library's entry
   layer does for a caller (src/api), so that both take one path from the options to the result. */
#include "cs_driver.h"

/* Every task, by -task name (like KSPSetType); later issues register theirs here. */
static PetscErrorCode RegisterTasks(PetscFunctionList *tasks)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListAdd(tasks, "info", CSTaskInfo));
  PetscCall(PetscFunctionListAdd(tasks, "flow", CSTaskFlow));
  PetscCall(PetscFunctionListAdd(tasks, "spin", CSTaskSpin));
  PetscCall(PetscFunctionListAdd(tasks, "spectrum", CSTaskSpectrum));
  PetscCall(PetscFunctionListAdd(tasks, "curveflow", CSTaskCurveFlow));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDriverRun(MPI_Comm comm)
{
  char              task[64] = "info";
  PetscFunctionList tasks    = NULL;
  PetscErrorCode (*run)(MPI_Comm) = NULL;
  PetscFunctionBeginUser;
  PetscCall(RegisterTasks(&tasks));
  PetscOptionsBegin(comm, NULL, "confsurf", NULL);
  PetscCall(PetscOptionsFList("-task", "What to do", NULL, tasks, task, task, sizeof(task), NULL));
  PetscOptionsEnd();
  PetscCall(PetscFunctionListFind(tasks, task, &run));
  if (!run) {
    char known[256];
    PetscCall(CSFunctionListNames(tasks, known, sizeof(known)));
    PetscCall(PetscFunctionListDestroy(&tasks));
    SETERRQ(comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-task %s: unknown task (known: %s)", task, known);
  }
  PetscCall(PetscFunctionListDestroy(&tasks));
  PetscCall((*run)(comm));
  PetscFunctionReturn(0);
}
