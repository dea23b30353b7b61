/* The library's entry layer for callers outside C (include/cs_api.h; the Python package python/confsurf). A call
   runs the task through CSDriverRun, the path of bin/confsurf, with three differences: the options are a private
   database pushed for the call (PetscOptionsPush) and destroyed after it, so no call sees another's; the input
   comes from arrays (CSMeshDataSetArraySource, CSCurveDataSetArraySource); the results are kept in memory
   (CSOutputSetCapture) as well as written to whatever files the options name. Errors are recorded by an error
   handler (one line, nothing printed) and returned; every object of the call is destroyed on the error path by the
   tasks themselves, so the process goes on. */
#include <slepcsys.h>
#include <signal.h>
#include "cs_api.h"
#include "cs_driver.h"
#include "cs_package.h"
#include "cs_curve.h"

static PetscBool       Started = PETSC_FALSE; /* CSApiInitialize ran (SlepcFinalize ends what it started) */
static char            LastError[2048];
static int             Refused; /* the last error is the caller's refusal of its input (every rank) */
static CSOutputCapture Result;
static long           *ResultFaces = NULL; /* Result.f as long */
static PetscErrorCode (*SavedVFPrintf)(FILE *, const char[], va_list) = NULL;

/* The first message of the call: PETSC_ERROR_INITIAL is where an error is raised (CSSyncError raises again on every
   rank with the failing rank's message); the PETSC_ERROR_REPEAT frames of the callers add nothing. */
static PetscErrorCode RecordError(MPI_Comm comm, int line, const char *func, const char *file, PetscErrorCode n, PetscErrorType p, const char *mess, void *ctx)
{
  if (p == PETSC_ERROR_INITIAL && !LastError[0]) {
    const char *text = NULL;
    if (!mess || !mess[0] || !strcmp(mess, " ")) PetscErrorMessage(n, &text, NULL);
    snprintf(LastError, sizeof(LastError), "%s", mess && mess[0] && strcmp(mess, " ") ? mess : (text ? text : "unknown error"));
  }
  return n;
}

/* quiet: the tasks' lines on stdout are dropped, warnings and errors on stderr kept */
static PetscErrorCode QuietVFPrintf(FILE *fd, const char format[], va_list ap)
{
  if (fd == PETSC_STDOUT || fd == stdout) return 0;
  return (*SavedVFPrintf)(fd, format, ap);
}

int CSApiInitialize(void)
{
  static int   argc    = 2;
  static char  arg0[]  = "confsurf", arg1[] = "-no_signal_handler"; /* the caller's (Python's) signals stay its own */
  static char *args[]  = {arg0, arg1, NULL};
  static char **argv   = args;
  PetscErrorCode ierr;
  if (Started) return 0;
  if (!PetscInitializeCalled) CSSingletonDefaults(); /* as bin/confsurf: a serial run's Open MPI defaults (none under mpirun) */
  ierr = SlepcInitialize(&argc, &argv, NULL, NULL); /* PETSc too unless the caller (petsc4py) started it: then theirs to end */
  if (ierr) return (int)ierr;
  Started = PETSC_TRUE;
  ierr    = CSLimitThreads(PETSC_COMM_WORLD);
  if (!ierr) ierr = CSInitializePackage();
  return (int)ierr;
}

int CSApiFinalize(void)
{
  PetscErrorCode ierr = 0;
  if (!Started) return 0;
  ierr = CSApiRelease();
  if (!ierr) ierr = SlepcFinalize();
  Started = PETSC_FALSE;
  return (int)ierr;
}

int CSApiRank(void)
{
  PetscMPIInt rank = 0;
  if (PetscInitializeCalled) MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  return (int)rank;
}

int CSApiSize(void)
{
  PetscMPIInt size = 1;
  if (PetscInitializeCalled) MPI_Comm_size(PETSC_COMM_WORLD, &size);
  return (int)size;
}

const char *CSApiLastError(void)
{
  return LastError;
}

int CSApiLastErrorIsInput(void)
{
  return Refused;
}

int CSApiRelease(void)
{
  PetscErrorCode ierr = CSOutputCaptureReset(&Result);
  free(ResultFaces);
  ResultFaces = NULL;
  return (int)ierr;
}

/* The input of the call on rank 0 and what every rank must agree on: its kind (0: from the options, 1: a mesh,
   2: a curve) and a refusal message, both broadcast from rank 0. */
typedef struct {
  int         kind;
  int         hasrho; /* spin's rho as an array (broadcast) */
  PetscInt    nrho;
  PetscReal  *rho;
  char        refuse[1024];
  CSMeshData  md;
  CSCurveData cd;
} Input;

/* rank 0: the arrays copied into md (the validation of the mesh layer refuses NaN, bad indices and the rest) */
static PetscErrorCode MeshFromArrays(long nv, const double *V, long nf, const long *F, long nuv, const double *uv, const long *fuv, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCheck(nv >= 0 && nf >= 0 && nuv >= 0 && nv <= PETSC_MAX_INT / 3 && nf <= PETSC_MAX_INT / 3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "arrays V (%ld x 3), F (%ld x 3): sizes out of range", nv, nf);
  md->nv = (PetscInt)nv;
  md->nf = (PetscInt)nf;
  PetscCall(PetscSNPrintf(md->name, sizeof(md->name), "arrays (V %ld x 3, F %ld x 3)", nv, nf));
  PetscCall(PetscMalloc1(3 * nv, &md->x));
  PetscCall(PetscMalloc1(3 * nf, &md->f));
  for (long i = 0; i < 3 * nv; i++) md->x[i] = (PetscReal)V[i];
  for (long i = 0; i < 3 * nf; i++) md->f[i] = (F[i] < 0 || F[i] >= nv) ? -1 : (PetscInt)F[i]; /* -1: refused by the validation */
  if (nuv) {
    md->nuv = (PetscInt)nuv;
    PetscCall(PetscMalloc1(2 * nuv, &md->uv));
    PetscCall(PetscMalloc1(3 * nf, &md->fuv));
    for (long i = 0; i < 2 * nuv; i++) md->uv[i] = (PetscReal)uv[i];
    for (long i = 0; i < 3 * nf; i++) md->fuv[i] = (PetscInt)fuv[i];
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode CurveFromArray(long np, const double *P, int closed, CSCurveData *cd)
{
  PetscFunctionBeginUser;
  PetscCheck(np >= 0 && np <= PETSC_MAX_INT / 2, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "array P (%ld x 2): size out of range", np);
  cd->m      = (PetscInt)np;
  cd->closed = closed ? PETSC_TRUE : PETSC_FALSE;
  PetscCall(PetscSNPrintf(cd->name, sizeof(cd->name), "array (P %ld x 2)", np));
  PetscCall(PetscMalloc2(2 * np, &cd->x, np, &cd->line)); /* as the readers (CSCurveDataDestroy) */
  PetscCall(PetscArrayzero(cd->line, np));
  for (long i = 0; i < 2 * np; i++) cd->x[i] = (PetscReal)P[i];
  PetscFunctionReturn(0);
}

/* the options of the call: the caller's string (PETSc's reader: quotes, -options_file, -prefix_push), then -task */
static PetscErrorCode CallOptions(const char task[], const char options[], PetscOptions *db)
{
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsCreate(db));
  PetscCall(PetscOptionsInsertString(*db, options ? options : ""));
  PetscCall(PetscOptionsSetValue(*db, "-task", task));
  PetscFunctionReturn(0);
}

/* Options given and never read are an error (bin/confsurf: exit 2 after the run), named here as there: the tasks
   refuse most before the work (CSOptionsCheckUnused); what is left are PETSc's solver options read at the end. */
static PetscErrorCode CheckLeft(MPI_Comm comm, PetscOptions db)
{
  PetscInt n;
  char   **names, **values;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(db, &n, &names, &values));
  if (n) {
    char     name[256];
    PetscInt count = n; /* the restore zeroes n */
    PetscCall(PetscSNPrintf(name, sizeof(name), "-%s%s%s", names[0], values[0] ? " " : "", values[0] ? values[0] : ""));
    PetscCall(PetscOptionsLeftRestore(db, &n, &names, &values));
    SETERRQ(comm, PETSC_ERR_ARG_WRONG, "unknown or unused option %s (%" PetscInt_FMT " option(s) not used: misspelled, or not valid for this task)", name, count);
  }
  PetscCall(PetscOptionsLeftRestore(db, &n, &names, &values));
  PetscFunctionReturn(0);
}

/* the task on the pushed database, its input set and its results captured; everything undone on every path */
static PetscErrorCode RunInDatabase(MPI_Comm comm, PetscOptions db, const Input *in)
{
  PetscErrorCode ierr;
  static const CSMeshData  nomesh;  /* the other ranks' non-NULL source (rank 0's data is the input) */
  static const CSCurveData nocurve;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscOptionsPush(db));
  if (in->kind == 1) PetscCall(CSMeshDataSetArraySource(rank ? &nomesh : &in->md));
  if (in->kind == 2) PetscCall(CSCurveDataSetArraySource(rank ? &nocurve : &in->cd));
  if (in->hasrho) PetscCall(CSDriverSpinSetRhoArray(PETSC_TRUE, in->nrho, in->rho));
  PetscCall(CSOutputCaptureSet(&Result));
  ierr = CSDriverRun(comm);
  if (!ierr) ierr = CheckLeft(comm, db);
  PetscCall(CSOutputCaptureSet(NULL));
  PetscCall(CSDriverSpinSetRhoArray(PETSC_FALSE, 0, NULL));
  PetscCall(CSCurveDataSetArraySource(NULL));
  PetscCall(CSMeshDataSetArraySource(NULL));
  PetscCall(PetscOptionsPop());
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

static PetscErrorCode Run(const char task[], const char options[], Input *in)
{
  MPI_Comm       comm = PETSC_COMM_WORLD;
  PetscOptions   db   = NULL;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Bcast(&in->kind, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&in->hasrho, 1, MPI_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(in->refuse, (int)sizeof(in->refuse), MPI_CHAR, 0, comm));
  Refused = in->refuse[0] != 0;
  PetscCheck(!in->refuse[0], comm, PETSC_ERR_ARG_WRONG, "%s", in->refuse);
  ierr = CallOptions(task, options, &db);
  if (!ierr) ierr = RunInDatabase(comm, db, in);
  PetscCall(PetscOptionsDestroy(&db));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

/* Result.f as long for the caller (PetscInt may be 32 bits) */
static PetscErrorCode FacesToLong(void)
{
  PetscFunctionBeginUser;
  if (!Result.nf) PetscFunctionReturn(0);
  ResultFaces = (long *)malloc(sizeof(long) * 3 * (size_t)Result.nf);
  PetscCheck(ResultFaces, PETSC_COMM_SELF, PETSC_ERR_MEM, "no memory for the %" PetscInt_FMT " result faces", Result.nf);
  for (PetscInt i = 0; i < 3 * Result.nf; i++) ResultFaces[i] = (long)Result.f[i];
  PetscFunctionReturn(0);
}

int CSApiRun(const char *task, const char *options, int quiet, long nv, const double *V, long nf, const long *F, long nuv, const double *uv, const long *fuv, long nrho, const double *rho, long np, const double *P, int closed, const char *refuse)
{
  Input          in;
  PetscErrorCode ierr = 0, ierr2;
  PetscMPIInt    rank = 0;
  if (!Started) {
    snprintf(LastError, sizeof(LastError), "confsurf is not initialised (CSApiInitialize)");
    return PETSC_ERR_ORDER;
  }
  LastError[0] = 0;
  Refused      = 0;
  memset(&in, 0, sizeof(in));
  (void)CSApiRelease();
  MPI_Comm_rank(PETSC_COMM_WORLD, &rank);
  if (PetscPushErrorHandler(RecordError, NULL)) return PETSC_ERR_LIB;
  if (!rank) {
    if (refuse) snprintf(in.refuse, sizeof(in.refuse), "%s", refuse);
    in.kind   = nv || nf ? 1 : (np ? 2 : 0);
    in.hasrho = rho != NULL;
    in.nrho   = (PetscInt)nrho;
    in.rho    = (PetscReal *)rho; /* PetscReal is double here (a real build) */
    if (!refuse && in.kind == 1) ierr = MeshFromArrays(nv, V, nf, F, nuv, uv, fuv, &in.md);
    if (!refuse && in.kind == 2) ierr = CurveFromArray(np, P, closed, &in.cd);
    if (ierr) snprintf(in.refuse, sizeof(in.refuse), "%.1000s", LastError[0] ? LastError : "the input arrays cannot be used");
    LastError[0] = 0;
  }
  if (quiet) {
    SavedVFPrintf = PetscVFPrintf;
    PetscVFPrintf = QuietVFPrintf;
  }
  ierr = Run(task, options, &in);
  if (quiet) PetscVFPrintf = SavedVFPrintf;
  if (!ierr) ierr = FacesToLong();
  ierr2 = CSMeshDataDestroy(&in.md);
  if (!ierr2) ierr2 = CSCurveDataDestroy(&in.cd);
  PetscPopErrorHandler();
  if (ierr) (void)CSApiRelease();
  return (int)(ierr ? ierr : ierr2);
}

const char *CSApiResultSummary(void)
{
  return Result.summary;
}

const double *CSApiResultPositions(long *dim, long *n)
{
  *dim = (long)Result.dim;
  *n   = (long)Result.nv;
  return Result.x;
}

const long *CSApiResultFaces(long *nf)
{
  *nf = ResultFaces ? (long)Result.nf : 0;
  return ResultFaces;
}

const double *CSApiResultHistory(const char **header, long *rows, long *cols)
{
  *header = Result.history.header;
  *rows   = (long)Result.history.nrows;
  *cols   = (long)Result.history.ncol;
  return Result.history.rows;
}

long CSApiGlobalOptionsCount(void)
{
  char *all;
  long  n = 0;
  if (PetscOptionsGetAll(NULL, &all)) return -1;
  for (const char *c = all; *c; c++) n += (*c == '-' && (c == all || c[-1] == ' ') && c[1] && !(c[1] >= '0' && c[1] <= '9') && c[1] != '.');
  PetscFree(all);
  return n;
}

double CSApiPetscMemory(void)
{
  PetscLogDouble m = 0;
  PetscMallocGetCurrentUsage(&m);
  return (double)m;
}
