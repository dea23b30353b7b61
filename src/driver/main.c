static const char help[] = "confsurf: conformal geometry processing of triangle meshes on PETSc/SLEPc.\n"
                           "  -task info|flow|spin|spectrum   what to do (default info)\n"
                           "  -mesh FILE (.obj .off .ply) or -gen icosphere|torus|flattorus|cylinder|disk\n"
                           "  -o FILE -viewer_dir DIR -summary FILE.json -history FILE.csv -reference FILE\n"
                           "Unknown options are an error (they are listed at the end of the run).\n";

#include <slepcsys.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cs_driver.h"
#include "cs_methods_spin.h"
#include "cs_package.h"

typedef struct {
  const char *name;
  PetscErrorCode (*run)(MPI_Comm);
} CSTask;

/* Every task of bin/confsurf; later issues add theirs here. */
static const CSTask tasks[] = {
  {"info", CSTaskInfo},
  {"flow", CSTaskFlow},
  {"spin", CSTaskSpin},
  {"spectrum", CSTaskSpectrum},
};

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
  char      task[64] = "info";
  PetscBool found    = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "confsurf", NULL);
  PetscCall(PetscOptionsString("-task", "info|flow|spin|spectrum", NULL, task, task, sizeof(task), NULL));
  PetscOptionsEnd();
  for (size_t i = 0; i < sizeof(tasks) / sizeof(tasks[0]); i++) {
    PetscBool same;
    PetscCall(PetscStrcmp(task, tasks[i].name, &same));
    if (same) {
      PetscCall(tasks[i].run(comm));
      found = PETSC_TRUE;
    }
  }
  PetscCheck(found, comm, PETSC_ERR_ARG_OUTOFRANGE, "-task %s: unknown task (known: info flow spin spectrum)", task);
  PetscFunctionReturn(0);
}

/* PETSc reserves -history FILE for its own log (PetscInitialize opens it and copies every PetscPrintf into
   it), but our fixed interface uses -history for the per-iteration CSV. Before PETSc sees the options we
   rename it to -cs_history: on the command line in place, in an -options_file through a private copy of the
   file with the option renamed (removed again at exit). */
static char renamed_files[8][64];
static int  nrenamed = 0;

static void RemoveRenamedFiles(void)
{
  for (int i = 0; i < nrenamed; i++) remove(renamed_files[i]);
}

static const char *RenameHistoryInOptionsFile(const char *path)
{
  FILE  *in = fopen(path, "r"), *out;
  char   line[4096];
  int    found = 0, fd;
  if (!in) return path; /* PETSc reports the missing file itself */
  while (fgets(line, sizeof(line), in)) {
    const char *t = line + strspn(line, " \t");
    if (!strncmp(t, "-history", 8) && (t[8] == 0 || strchr(" \t\r\n", t[8]))) found = 1;
  }
  if (!found || nrenamed == 8) {
    fclose(in);
    return path;
  }
  snprintf(renamed_files[nrenamed], sizeof(renamed_files[0]), "/tmp/confsurf-options-XXXXXX");
  fd = mkstemp(renamed_files[nrenamed]);
  if (fd < 0 || !(out = fdopen(fd, "w"))) {
    fclose(in);
    return path;
  }
  rewind(in);
  while (fgets(line, sizeof(line), in)) {
    char *t = line + strspn(line, " \t");
    if (!strncmp(t, "-history", 8) && (t[8] == 0 || strchr(" \t\r\n", t[8]))) fprintf(out, "-cs_history%s", t + 8);
    else fputs(line, out);
  }
  fclose(in);
  fclose(out);
  if (!nrenamed) atexit(RemoveRenamedFiles);
  return renamed_files[nrenamed++];
}

static void RenameHistoryOption(int argc, char **argv)
{
  static char cs_history[] = "-cs_history";
  for (int i = 1; i < argc; i++) {
    if (!strcmp(argv[i], "-history")) argv[i] = cs_history;
    else if (!strcmp(argv[i], "-options_file") && i + 1 < argc) argv[i + 1] = (char *)RenameHistoryInOptionsFile(argv[i + 1]);
  }
}

int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  PetscBool      bad = PETSC_FALSE, traceback = PETSC_FALSE;

  RenameHistoryOption(argc, argv);
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
