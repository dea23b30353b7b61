/* Per-iteration CSV history; flushed every row so a killed run keeps what it computed. The file is opened, flushed
   and closed collectively (CSFile): a folder that cannot hold it, or a full disk, stops every rank with a message. */
#include "cs_util.h"
#include <math.h>

struct _p_CSHistory {
  MPI_Comm  comm;
  CSFile    file;    /* open on rank 0 */
  PetscBool capture; /* rank 0 keeps the rows in Capture */
  PetscBool nofile;  /* path NULL: the capture only (the same on every rank) */
};

static CSHistoryCapture *Capture = NULL; /* the rows of this run for a caller of the library (src/api) */

PetscErrorCode CSHistoryCaptureSet(CSHistoryCapture *c)
{
  PetscFunctionBeginUser;
  Capture = c;
  PetscFunctionReturn(0);
}

PetscBool CSHistoryCaptureActive(void)
{
  return Capture ? PETSC_TRUE : PETSC_FALSE;
}

PetscErrorCode CSHistoryCaptureReset(CSHistoryCapture *c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->header));
  PetscCall(PetscFree(c->rows));
  PetscCall(PetscMemzero(c, sizeof(*c)));
  PetscFunctionReturn(0);
}

/* rank 0: a new history of this run replaces the rows captured before */
static PetscErrorCode CaptureStart(const char header[])
{
  PetscFunctionBeginUser;
  PetscCall(CSHistoryCaptureReset(Capture));
  PetscCall(PetscStrallocpy(header, &Capture->header));
  Capture->ncol = 1;
  for (const char *c = header; *c; c++) Capture->ncol += (*c == ',');
  PetscFunctionReturn(0);
}

static PetscErrorCode CaptureRow(PetscInt n, const PetscReal row[])
{
  PetscFunctionBeginUser;
  if (Capture->nrows == Capture->cap) {
    Capture->cap = 2 * Capture->cap + 64;
    PetscCall(PetscRealloc(sizeof(PetscReal) * Capture->cap * Capture->ncol, &Capture->rows));
  }
  for (PetscInt i = 0; i < Capture->ncol; i++) Capture->rows[Capture->nrows * Capture->ncol + i] = i < n ? row[i] : (PetscReal)NAN; /* a short row: NaN, as a CSV reader sees a missing value */
  Capture->nrows++;
  PetscFunctionReturn(0);
}

PetscErrorCode CSHistoryCreate(MPI_Comm comm, const char path[], const char header[], CSHistory *h)
{
  PetscMPIInt    rank;
  PetscErrorCode ierr = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(h));
  (*h)->comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank && Capture) {
    (*h)->capture = PETSC_TRUE;
    PetscCall(CaptureStart(header));
  }
  (*h)->nofile = (PetscBool)!path;
  if (!path) PetscFunctionReturn(0); /* the capture only */
  ierr = CSFileOpen(comm, (PetscBool)!rank, "-history_csv", path, PETSC_FALSE, &(*h)->file);
  if (!ierr && (*h)->file.fp) fprintf((*h)->file.fp, "%s\n", header);
  if (!ierr) ierr = CSFileFlush(comm, &(*h)->file);
  (*h)->file.keep = PETSC_TRUE; /* from here on a write error keeps the rows before it (issue 36, item 15) */
  if (ierr) PetscCall(CSHistoryDestroy(h)); /* the error is collective: every rank frees */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

/* Collective: row is read on rank 0 only */
PetscErrorCode CSHistoryAppend(CSHistory h, PetscInt n, const PetscReal row[])
{
  FILE *fp;
  PetscFunctionBeginUser;
  if (!h) PetscFunctionReturn(0);
  if (h->capture && Capture) PetscCall(CaptureRow(n, row));
  if (h->nofile) PetscFunctionReturn(0);
  if ((fp = h->file.fp)) {
    for (PetscInt i = 0; i < n; i++) fprintf(fp, i ? ",%.17g" : "%.17g", (double)row[i]);
    fprintf(fp, "\n");
  }
  PetscCall(CSFileFlush(h->comm, &h->file));
  h->file.records++;
  PetscFunctionReturn(0);
}

/* Not collective (a destroy may run on one rank's error path): the rows are flushed already */
PetscErrorCode CSHistoryDestroy(CSHistory *h)
{
  PetscFunctionBeginUser;
  if (!*h) PetscFunctionReturn(0);
  if ((*h)->file.fp) (void)fclose((*h)->file.fp);
  PetscCall(PetscFree(*h));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHistoryMonitorDestroy(void **ctx)
{
  CSHistory h = (CSHistory)*ctx;
  PetscFunctionBeginUser;
  PetscCall(CSHistoryDestroy(&h));
  *ctx = NULL;
  PetscFunctionReturn(0);
}
