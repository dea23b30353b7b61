static const char help[] = "confsurf: conformal geometry processing of triangle meshes on PETSc/SLEPc.\n"
                           "  -task info|flow|spin|spectrum|curveflow   what to do (default info)\n"
                           "  -mesh FILE (.obj .off .ply) or -gen icosphere|torus|flattorus|cylinder|disk\n"
                           "  curveflow: -curve FILE (.obj or text x y) or -gen_curve circle|ellipse|star|noisy|limacon\n"
                           "  -o FILE -viewer_dir DIR -summary FILE.json -history_csv FILE.csv -reference FILE\n"
                           "Unknown options are an error (they are listed at the end of the run).\n";

#include <slepcsys.h>
#include "cs_driver.h"
#include "cs_package.h"

/* Every task of bin/confsurf, by -task name (like KSPSetType); later issues register theirs here. */
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

/* Options nobody asked for are typos: name them and fail, instead of silently running something else. */
static PetscErrorCode CheckUnusedOptions(MPI_Comm comm, PetscBool *bad)
{
  PetscInt  N;
  PetscBool set;
  PetscFunctionBeginUser;
  /* PETSc's own -options_left is read only in PetscFinalize, after this check: not a typo */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-options_left", &set));
  PetscCall(PetscOptionsAllUsed(NULL, &N));
  *bad = (PetscBool)(N > 0);
  if (N) {
    PetscInt n;
    char   **names, **values;
    PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
    for (PetscInt i = 0; i < n; i++) PetscCall(PetscFPrintf(comm, PETSC_STDERR, "Error: unknown or unused option -%s%s%s\n", names[i], values[i] ? " " : "", values[i] ? values[i] : ""));
    PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
    PetscCall(PetscFPrintf(comm, PETSC_STDERR, "Error: %" PetscInt_FMT " option(s) were not used (misspelled, or not valid for this task; see -help)\n", N));
  }
  PetscFunctionReturn(0);
}

/* Users get the message and where it was raised, once per communicator, instead of PETSc's full traceback
   with its configure line; -cs_traceback restores PETSc's default handler for debugging. */
static PetscErrorCode ConciseErrorHandler(MPI_Comm comm, int line, const char *func, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  PetscMPIInt rank = 0, size = 1;
  if (p != PETSC_ERROR_INITIAL) return n;
  if (comm != MPI_COMM_NULL) {
    MPI_Comm_rank(comm, &rank);
    MPI_Comm_size(comm, &size);
  }
  if (rank == 0) {
    PetscMPIInt wrank = 0;
    MPI_Comm_rank(MPI_COMM_WORLD, &wrank);
    if (size == 1 && wrank) fprintf(stderr, "[rank %d] ", (int)wrank);
    fprintf(stderr, "confsurf: error: %s\n  (%s() at %s:%d; -cs_traceback for the PETSc traceback)\n", mess ? mess : "unknown error", func, file, line);
    fflush(stderr);
  }
  return n;
}

static PetscErrorCode Run(MPI_Comm comm)
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
  PetscCall(PetscFunctionListDestroy(&tasks));
  PetscCheck(run, comm, PETSC_ERR_ARG_UNKNOWN_TYPE, "-task %s: unknown task (known: info flow spin spectrum curveflow)", task);
  PetscCall((*run)(comm));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  PetscBool      bad = PETSC_FALSE, traceback = PETSC_FALSE;

  PetscCall(SlepcInitialize(&argc, &argv, NULL, help));
  PetscCall(CSLimitThreads(PETSC_COMM_WORLD));
  PetscCall(CSInitializePackage()); /* events, PCs and solver types, before any options are read */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-cs_traceback", &traceback));
  if (!traceback) PetscCall(PetscPushErrorHandler(ConciseErrorHandler, NULL));
  ierr = Run(PETSC_COMM_WORLD);
  if (!traceback) PetscCall(PetscPopErrorHandler());
  if (!ierr) PetscCall(CheckUnusedOptions(PETSC_COMM_WORLD, &bad));
  /* finalize also after an error so -malloc_debug/valgrind see a clean exit */
  PetscCall(SlepcFinalize());
  return ierr ? (int)ierr : (bad ? 2 : 0);
}
