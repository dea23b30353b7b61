/* Small utilities shared by every layer: collective error propagation, JSON summary, CSV history. */
#ifndef CS_UTIL_H
#define CS_UTIL_H
#include <petscsys.h>

/* Some ranks did work that may have failed with ierr (run under CSCaptureError, so nothing was printed). Every
   rank then raises the error of the lowest failing rank, with its message, or all return 0. Collective. */
PETSC_EXTERN PetscErrorCode CSSyncError(MPI_Comm comm, PetscErrorCode ierr);
/* Threads per process: OpenMP loops (CHOLMOD's) bounded by OMP_NUM_THREADS, default 1; one OpenBLAS thread per
   rank when several ranks run, unless OPENBLAS_NUM_THREADS is set (src/util/threads.c). */
PETSC_EXTERN PetscErrorCode CSLimitThreads(MPI_Comm comm);
/* the resulting OpenMP and OpenBLAS thread counts of this process (1 where the library is absent) */
PETSC_EXTERN PetscErrorCode CSGetThreadCounts(PetscInt *omp_threads, PetscInt *blas_threads);

/* ierr = expr, with PETSc's error printing off (PetscReturnErrorHandler): for CSSyncError */
#define CSCaptureError(ierr, expr) \
  do { \
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL)); \
    (ierr) = (expr); \
    PetscCall(PetscPopErrorHandler()); \
  } while (0)

/* Call expr on rank 0 only, every rank raising its error (CSSyncError). Use:
     CSRootCall(comm, CSMeshDataRead(path, &md)); */
#define CSRootCall(comm, expr) \
  do { \
    PetscMPIInt    _rank; \
    PetscErrorCode _ierr = 0; \
    PetscCallMPI(MPI_Comm_rank((comm), &_rank)); \
    if (!_rank) CSCaptureError(_ierr, (expr)); \
    PetscCall(CSSyncError((comm), _ierr)); \
  } while (0)

/* JSON summary: a flat object of numbers, integers, strings and number arrays, written by rank 0. */
typedef struct _p_CSJSON *CSJSON;
PETSC_EXTERN PetscErrorCode CSJSONCreate(MPI_Comm comm, CSJSON *js);
PETSC_EXTERN PetscErrorCode CSJSONAddReal(CSJSON js, const char key[], PetscReal v);
PETSC_EXTERN PetscErrorCode CSJSONAddInt(CSJSON js, const char key[], PetscInt v);
PETSC_EXTERN PetscErrorCode CSJSONAddBool(CSJSON js, const char key[], PetscBool v);
PETSC_EXTERN PetscErrorCode CSJSONAddString(CSJSON js, const char key[], const char v[]);
PETSC_EXTERN PetscErrorCode CSJSONAddRealArray(CSJSON js, const char key[], PetscInt n, const PetscReal v[]);
PETSC_EXTERN PetscErrorCode CSJSONWrite(CSJSON js, const char path[]);
/* the object as CSJSONWrite writes it, in a PetscMalloc'd string (the Python interface's summary, src/api) */
PETSC_EXTERN PetscErrorCode CSJSONGetString(CSJSON js, char **text);
PETSC_EXTERN PetscErrorCode CSJSONDestroy(CSJSON *js);

/* CSV history: header fixed at creation, one row of reals per call; rank 0 writes, flushed per row. path NULL: no
   file, the rows only go to the capture (below). */
typedef struct _p_CSHistory *CSHistory;
/* The rows of the histories of one run kept in memory on rank 0 for a caller of the library (src/api): while a
   capture is set, every history created starts it afresh (header, ncol) and each row appended is kept. */
typedef struct {
  char      *header;
  PetscInt   ncol, nrows, cap;
  PetscReal *rows; /* nrows x ncol, row-major */
} CSHistoryCapture;
PETSC_EXTERN PetscErrorCode CSHistoryCaptureSet(CSHistoryCapture *c); /* NULL: off */
PETSC_EXTERN PetscBool      CSHistoryCaptureActive(void);
PETSC_EXTERN PetscErrorCode CSHistoryCaptureReset(CSHistoryCapture *c);  /* frees the rows and the header */
PETSC_EXTERN PetscErrorCode CSHistoryCreate(MPI_Comm comm, const char path[], const char header[], CSHistory *h);
PETSC_EXTERN PetscErrorCode CSHistoryAppend(CSHistory h, PetscInt n, const PetscReal row[]);
PETSC_EXTERN PetscErrorCode CSHistoryDestroy(CSHistory *h);
/* the destroy callback of a monitor whose context is a CSHistory (MonitorSet(flow, fn, h, CSHistoryMonitorDestroy)) */
PETSC_EXTERN PetscErrorCode CSHistoryMonitorDestroy(void **ctx);

/* Rank-local: every number of a text file (white space or commas, '#' comments; no line length limit) into
   *values (PetscMalloc'd, *n of them) with the line of each in *lines (src/util/values.c, on CSTokens). Errors name
   option, path and line. */
PETSC_EXTERN PetscErrorCode CSReadNumberFile(const char option[], const char path[], PetscInt *n, PetscReal **values, PetscInt **lines);
/* Path helpers */
/* Room for one more element in a growing array *a of n elements of size bytes, capacity *cap: when full, the
   capacity doubles (first = initial) and the n elements move to the new storage. */
PETSC_EXTERN PetscErrorCode CSArrayGrow(size_t size, PetscInt n, PetscInt initial, PetscInt *cap, void **a);
PETSC_EXTERN PetscErrorCode CSPathExtension(const char path[], char ext[], size_t len); /* lower-case, without dot */
PETSC_EXTERN PetscErrorCode CSPathMakeDir(const char dir[]);       /* mkdir -p of a folder */
PETSC_EXTERN PetscErrorCode CSPathInsertSuffix(const char path[], const char suffix[], char out[], size_t len); /* a.obj, _last -> a_last.obj */
PETSC_EXTERN PetscErrorCode CSFunctionListNames(PetscFunctionList list, char *buf, size_t len); /* "a b c": the registered names */
PETSC_EXTERN PetscErrorCode CSFunctionListJoin(PetscFunctionList list, const char sep[], char *buf, size_t len); /* "a|b|c" with sep "|" */
PETSC_EXTERN PetscErrorCode CSPathMakeParents(const char path[]); /* mkdir -p of the folders above a file to write */
/* a path or name fit to print or write into a header: control characters '?', at most CS_NAME_SHOWN characters */
#define CS_NAME_SHOWN 300
PETSC_EXTERN PetscErrorCode CSPathSanitize(const char in[], char out[], size_t len);

/* Files written collectively (src/util/file.c): the ranks with mine write, every step's outcome reaches every
   rank, a failed write (full disk) or close is an error naming the file, and a failure removes the file. atomic:
   written under a unique temporary name, fsync'ed, renamed over the target (which must be a regular file). */
typedef struct {
  FILE     *fp; /* open on the ranks with mine, after CSFileOpen */
  PetscBool mine, atomic, regular, created; /* created: ours to remove on failure */
  PetscBool keep;    /* set by a writer of records (the history): on failure keep the records flushed before it */
  long      good;    /* with keep: the file's length after the last flush that succeeded */
  PetscInt  records; /* with keep: the records in it (the writer counts them) */
  char      what[64]; /* the option, for messages */
  char      path[PETSC_MAX_PATH_LEN], tmp[PETSC_MAX_PATH_LEN];
} CSFile;
PETSC_EXTERN PetscErrorCode CSFileOpen(MPI_Comm comm, PetscBool mine, const char what[], const char path[], PetscBool atomic, CSFile *f);
PETSC_EXTERN PetscErrorCode CSFileFlush(MPI_Comm comm, CSFile *f); /* collective: errors of the writes so far */
PETSC_EXTERN PetscErrorCode CSFileClose(MPI_Comm comm, CSFile *f);
PETSC_EXTERN PetscErrorCode CSFileDiscard(CSFile *f); /* not collective: close and remove (error paths) */
/* Not collective: path can take an output (checked before any work; missing folders are created), and a name of
   the file it is or would be (the same for two paths of one file) */
PETSC_EXTERN PetscErrorCode CSFileCheckTarget(const char what[], const char path[]);
PETSC_EXTERN PetscErrorCode CSFileIdentity(const char path[], char id[], size_t len);
/* Not collective: the whole of a regular file into *buf (NUL-terminated, PetscFree it); a folder, FIFO or device
   is refused without blocking; what names the option in messages. */
PETSC_EXTERN PetscErrorCode CSFileLoad(const char what[], const char path[], char **buf, size_t *len);
/* Value files (src/util/values.c): the whole file, tokens separated by blanks, newlines or commas, '#' comments;
   each token with its line. CSTokensNext returns 0 at the end; the token is not NUL-terminated. */
typedef struct {
  char    *buf, *p, *end;
  size_t   len;
  PetscInt line;
  char     name[PETSC_MAX_PATH_LEN]; /* the path, sanitised for messages */
} CSTokens;
PETSC_EXTERN PetscErrorCode CSTokensLoad(const char what[], const char path[], CSTokens *t);
PETSC_EXTERN void           CSTokensInit(CSTokens *t, char *buf, size_t len);
PETSC_EXTERN int            CSTokensNext(CSTokens *t, const char **tok, size_t *len, PetscInt *line);
PETSC_EXTERN int            CSTokenReal(const char *tok, size_t len, double *v); /* 0 ok, 1 not a number, 2 not finite */
PETSC_EXTERN int            CSTokenInt(const char *tok, size_t len, long long *v); /* 0 ok, 1 not an integer */
PETSC_EXTERN const char    *CSTokenText(const char *tok, size_t len, char out[40]);
PETSC_EXTERN PetscErrorCode CSTokensDestroy(CSTokens *t);
/* n elements of size bytes each: an error naming what and the sizes when n*size exceeds PetscInt or the memory */
PETSC_EXTERN PetscErrorCode CSCheckAllocation(const char what[], PetscInt64 n, size_t size);

/* Numeric options: each value finite and ok (the caller's range test), else an error "-<prefix><name> <v>: <want>". */
typedef struct {
  const char *name;
  PetscReal   value;
  PetscBool   ok;
  const char *want;
} CSOptionCheck;
PETSC_EXTERN PetscErrorCode CSCheckOptionValues(MPI_Comm comm, const char prefix[], size_t n, const CSOptionCheck checks[]);

/* The project's option readers (issue 36, items 9-11): PETSc 3.18 reads an integer with strtoll and a cast to int
   (-flow_max_it 4294967298 gave 2 iterations), copies a string cut to the caller's buffer (a long -summary path
   wrote another file) and takes an option given without a value as not given (-flow_t '' ran with the default).
   These check the raw value first (an integer PetscInt holds, a string that fits, a value present) and then read
   it with PETSc's reader; use them in place of PetscOptionsInt/Real/String inside PetscOptionsBegin/End. */
PETSC_EXTERN PetscErrorCode CSOptionsInt_Private(PetscOptionItems *, const char[], const char[], const char[], PetscInt, PetscInt *, PetscBool *);
PETSC_EXTERN PetscErrorCode CSOptionsReal_Private(PetscOptionItems *, const char[], const char[], const char[], PetscReal, PetscReal *, PetscBool *);
PETSC_EXTERN PetscErrorCode CSOptionsString_Private(PetscOptionItems *, const char[], const char[], const char[], const char[], char[], size_t, PetscBool *);
PETSC_EXTERN PetscErrorCode CSOptionsEList_Private(PetscOptionItems *, const char[], const char[], const char[], const char *const *, PetscInt, const char[], PetscInt *, PetscBool *);
PETSC_EXTERN PetscErrorCode CSOptionsEnum_Private(PetscOptionItems *, const char[], const char[], const char[], const char *const *, PetscEnum, PetscEnum *, PetscBool *);
#define CSOptionsEList(opt, text, man, list, n, cur, val, set) CSOptionsEList_Private(PetscOptionsObject, opt, text, man, list, n, cur, val, set)
#define CSOptionsEnum(opt, text, man, list, cur, val, set)     CSOptionsEnum_Private(PetscOptionsObject, opt, text, man, list, cur, val, set)
#define CSOptionsInt(opt, text, man, cur, val, set)         CSOptionsInt_Private(PetscOptionsObject, opt, text, man, cur, val, set)
#define CSOptionsReal(opt, text, man, cur, val, set)        CSOptionsReal_Private(PetscOptionsObject, opt, text, man, cur, val, set)
#define CSOptionsString(opt, text, man, cur, val, len, set) CSOptionsString_Private(PetscOptionsObject, opt, text, man, cur, val, len, set)

/* Options given and not used, before the work (issue 36, item 18; src/util/option_unused.c): called by the driver
   once every object of the task has read its options; a one-line error naming them (with the closest name read,
   "did you mean -flow_max_it?") on every rank. PETSc's solver options (-<prefix>ksp_..., pc_, mat_, eps_, st_, ...)
   are read lazily by PETSc and left to the end-of-run check. CSOptionsNoteRead records a name the project's
   readers looked up (the candidates of the suggestion). */
PETSC_EXTERN PetscErrorCode CSOptionsCheckUnused(MPI_Comm comm, const char task[]);
PETSC_EXTERN PetscErrorCode CSOptionsNoteRead(const char full[]);

#endif
