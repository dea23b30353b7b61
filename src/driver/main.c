static const char help[] = "confsurf: conformal geometry processing of triangle meshes on PETSc/SLEPc.\n"
                           "  -task info|flow|spin|spectrum|curveflow   what to do (default info)\n"
                           "  -mesh FILE (.obj .off .ply) or -gen icosphere|torus|flattorus|lattice|cylinder|disk\n"
                           "  curveflow: -curve FILE (.obj or text x y) or -gen_curve circle|ellipse|star|noisy|limacon\n"
                           "  -o FILE -viewer_dir DIR -summary FILE.json -history_csv FILE.csv -reference FILE\n"
                           "Unknown options are an error, before the work starts (PETSc's solver options: at the end of the run).\n";

/* The tasks and what they do, for -help (the same names as RegisterTasks). */
static const char *const task_help[][2] = {
  {"info",     "facts of a mesh: counts, genus, boundary loops, area, volume, Willmore energies"},
  {"flow",     "-flow_type KIND: conformally constrained Willmore (area, fairing) flow (soliman2021), KIND a registered kind; bs: Bobenko-Schroeder flow"},
  {"spin",     "spin transformation (crane2011): curvature change rho, or the nearest one to -spin_target_mesh"},
  {"spectrum", "the smallest eigenvalues of the Dirac problem with rho = 0 (crane2011 Fig. 8)"},
  {"curveflow", "isometric curvature flow of a closed planar curve (crane2013 Sec. 5): -curve FILE or -gen_curve SHAPE"},
};

#include <slepcsys.h>
#include <errno.h>
#include <signal.h>
#include <unistd.h>
#include "cs_driver.h"
#include "cs_package.h"
#include "cs_methods_willmore.h"

/* -help. PETSc's own -help prints its banner, the options of every PETSc program, and then those of whatever
   the run reaches (and fails without a mesh). Here -help is taken out of argv before PETSc starts: alone it prints
   the task list; with -task NAME the task runs on a small generated mesh with zero iterations, its normal output
   discarded, and only the option blocks of confsurf's own objects are printed (with their defaults: PETSc's
   "<now V : formerly D>" shows the default D); the solver objects' (KSP, PC, EPS, ST, TAO) blocks are left out,
   as PETSc's `-help all` (a bare -help given to PETSc, added to a real run: it lists what that run reaches) shows them. */
static PetscBool HelpKeep = PETSC_FALSE;
static PetscErrorCode (*HelpSavedVFPrintf)(FILE *, const char[], va_list) = NULL;
/* The titles of confsurf's own PetscOptionsBegin blocks (a kind's PetscOptionsHeadBegin sub-headings print inside
   its flow's block, e.g. the triangle field's three in "Constrained Willmore flow (soliman2021)"). */
static const char *const HelpSections[] = {"confsurf", "confsurf flow", "confsurf output", "Mesh orientation", "Mesh source", "Isotropic remeshing (CGAL) of the input", "Test-input deformation", "ParaView output (-viewer_dir)", "Bobenko-Schroeder flow output", "Dirac spectrum (crane2011 Fig. 8)", "Willmore flow output", "Bobenko-Schroeder Willmore flow (bobenko-schroeder2005)", "Constrained Willmore flow (soliman2021)", "Fairing energy (soliman2021 Eq. 21)", "Change of mean curvature half-density rho (crane2011 Sec. 4.1)", "Spin boundary tangents (crane2011 Sec. 5.7)", "Spin transformations (crane2011)", "confsurf curve input", "Isometric curve flow (crane2013 Sec. 5)", "Curve flow output"};

/* Everything the task prints is dropped, except the lines of an enumerated option's help, which PETSc prints
   with PetscFPrintf (PetscFunctionListPrintTypes) instead of PetscHelpPrintf. */
static PetscErrorCode HelpDiscard(FILE *fd, const char format[], va_list ap)
{
  static PetscBool inlist = PETSC_FALSE;
  if (strstr(format, "<now %s : formerly %s>: %s (one of)")) inlist = PETSC_TRUE;
  if (inlist) {
    if (HelpKeep) vfprintf(stdout, format, ap);
    if (strchr(format, '\n')) inlist = PETSC_FALSE;
  }
  return 0;
}

static PetscErrorCode HelpFilter(MPI_Comm comm, const char format[], ...)
{
  char        buf[8192];
  const char *dash = "----------------------------------------\n";
  PetscMPIInt rank = 0;
  va_list     ap;
  if (comm != MPI_COMM_NULL) MPI_Comm_rank(comm, &rank);
  if (rank) return 0;
  va_start(ap, format);
  vsnprintf(buf, sizeof(buf), format, ap);
  va_end(ap);
  if (!strncmp(buf, dash, strlen(dash))) {
    char  *title = buf + strlen(dash);
    size_t n     = strcspn(title, "\n");
    if (n && title[n - 1] == ':') n--;
    HelpKeep = PETSC_FALSE;
    for (size_t i = 0; i < sizeof(HelpSections) / sizeof(HelpSections[0]); i++)
      if (strlen(HelpSections[i]) == n && !strncmp(title, HelpSections[i], n)) HelpKeep = PETSC_TRUE;
    if (HelpKeep) fprintf(stdout, "\n%.*s:\n", (int)n, title);
    return 0;
  }
  if (HelpKeep) fputs(buf, stdout);
  return 0;
}

/* Removes -help/--help/-h from argv and returns whether it was there; "-help all" becomes PETSc's own bare -help. */
static PetscBool HelpFromArgs(int *argc, char **argv)
{
  PetscBool found = PETSC_FALSE;
  int       j     = 1;
  for (int i = 1; i < *argc; i++) {
    if (!strcmp(argv[i], "-help") || !strcmp(argv[i], "--help") || !strcmp(argv[i], "-h")) {
      if (i + 1 < *argc && !strcmp(argv[i + 1], "all")) { /* PETSc's full help: a bare -help (3.18 reads its value as a bool) */
        static char petsc_help[] = "-help";
        argv[j++]                = petsc_help;
        i++;
        continue;
      }
      found = PETSC_TRUE;
      continue;
    }
    argv[j++] = argv[i];
  }
  *argc   = j;
  argv[j] = NULL;
  return found;
}

static PetscErrorCode HelpTaskList(void)
{
  PetscFunctionList kinds;
  char              names[512];
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetTypeList(&kinds)); /* the kinds as registered, not a list written here */
  PetscCall(CSFunctionListJoin(kinds, "|", names, sizeof(names)));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s\nTasks (-task NAME; `bin/confsurf -task NAME -help` lists that task's options and their defaults):\n", help));
  for (size_t i = 0; i < sizeof(task_help) / sizeof(task_help[0]); i++) {
    PetscBool flow;
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %-9s %s\n", task_help[i][0], task_help[i][1]));
    PetscCall(PetscStrcmp(task_help[i][0], "flow", &flow));
    if (flow) PetscCall(PetscPrintf(PETSC_COMM_WORLD, "  %-9s the kinds registered: %s\n", "", names));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "Experiments: options/*.opts (bin/confsurf -options_file F); PETSc's own help with every solver option a run reaches: -help all added to a run (e.g. -task flow -gen icosphere -flow_max_it 1 -help all)\n"));
  PetscFunctionReturn(0);
}

/* -task NAME -help: the task runs on a private options database, pushed as the default for the pass (PetscOptionsPush)
   and popped after it, so the global database is never written: the user's options, -help, a small generated mesh
   and curve unless one is given, and zero iterations. PETSc's help hooks filter what is printed: PetscHelpPrintf
   keeps confsurf's option blocks, PetscVFPrintf drops the task's own output (and keeps the lines of an enumerated
   option's list, which PETSc prints with PetscFPrintf on stdout). */
static PetscErrorCode HelpTaskSetUp(PetscOptions *help)
{
  PetscBool mesh, gen, curve, gencurve;
  char     *all;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasName(NULL, NULL, "-mesh", &mesh));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-gen", &gen));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-curve", &curve));
  PetscCall(PetscOptionsHasName(NULL, NULL, "-gen_curve", &gencurve));
  PetscCall(PetscOptionsGetAll(NULL, &all));
  PetscCall(PetscOptionsCreate(help));
  PetscCall(PetscOptionsInsertString(*help, all));
  PetscCall(PetscFree(all));
  if (!mesh && !gen) PetscCall(PetscOptionsSetValue(*help, "-gen", "icosphere"));
  if (!curve && !gencurve) PetscCall(PetscOptionsSetValue(*help, "-gen_curve", "circle"));
  PetscCall(PetscOptionsSetValue(*help, "-flow_max_it", "0"));
  PetscCall(PetscOptionsSetValue(*help, "-bs_max_it", "0"));
  PetscCall(PetscOptionsSetValue(*help, "-curve_max_it", "0"));
  PetscCall(PetscOptionsSetValue(*help, "-help", NULL));
  PetscCall(PetscOptionsPush(*help));
  PetscHelpPrintf   = HelpFilter;
  HelpSavedVFPrintf = PetscVFPrintf;
  PetscVFPrintf     = HelpDiscard;
  PetscFunctionReturn(0);
}

/* The end of the help pass: PETSc's printing and the global options database back as they were. */
static PetscErrorCode HelpTaskEnd(PetscOptions *help)
{
  PetscFunctionBeginUser;
  PetscVFPrintf = HelpSavedVFPrintf;
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "\n(<now V : formerly D>: D is the default; -flow_max_it, -bs_max_it and -curve_max_it are 0 here only to list the options. Solver objects take PETSc's options under their prefixes, e.g. -flow_saddle_ksp_*, -bs_semi_*, -spin_st_*: listed by -help all added to a run that reaches them, with a mesh and -flow_max_it 1.)\n"));
  PetscCall(PetscOptionsPop());
  PetscCall(PetscOptionsDestroy(help));
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

int main(int argc, char **argv)
{
  PetscErrorCode ierr;
  PetscBool      bad = PETSC_FALSE, traceback = PETSC_FALSE, helpmode, task;
  PetscOptions   helpdb = NULL; /* the help pass's options */

  helpmode = HelpFromArgs(&argc, argv);
  if (!CSStartupFilesUsable(argc, argv)) return 1;
  CSSingletonDefaults();
  PetscCall(SlepcInitialize(&argc, &argv, NULL, help));
  if (helpmode) {
    PetscCall(PetscOptionsHasName(NULL, NULL, "-task", &task));
    if (!task) {
      PetscCall(HelpTaskList());
      PetscCall(SlepcFinalize());
      return 0;
    }
    PetscCall(HelpTaskSetUp(&helpdb));
  }
  /* output into a closed pipe (| head -1) is dropped, not a crash dump from PETSc's signal handler: the writes fail
     with EPIPE and the run ends as it would, its files written (issue 36, item 19) */
  signal(SIGPIPE, SIG_IGN);
  PetscCall(CSLimitThreads(PETSC_COMM_WORLD));
  PetscCall(CSInitializePackage()); /* events, PCs and solver types, before any options are read */
  PetscCall(PetscOptionsHasName(NULL, NULL, "-cs_traceback", &traceback));
  if (!traceback) PetscCall(PetscPushErrorHandler(ConciseErrorHandler, NULL));
  ierr = CSDriverRun(PETSC_COMM_WORLD); /* src/driver/task_run.c */
  if (!traceback) PetscCall(PetscPopErrorHandler());
  if (!ierr && !helpmode) PetscCall(CheckUnusedOptions(PETSC_COMM_WORLD, &bad));
  if (helpmode) PetscCall(HelpTaskEnd(&helpdb));
  /* finalize also after an error so -malloc_debug/valgrind see a clean exit */
  PetscCall(SlepcFinalize());
  return ierr ? (int)ierr : (bad ? 2 : 0);
}
