/* Per-iteration CSV history; flushed every row so a killed run keeps what it computed. The file is opened, flushed
   and closed collectively (CSFile): a folder that cannot hold it, or a full disk, stops every rank with a message. */
#include "cs_util.h"

struct _p_CSHistory {
  MPI_Comm comm;
  CSFile   file; /* open on rank 0 */
};

PetscErrorCode CSHistoryCreate(MPI_Comm comm, const char path[], const char header[], CSHistory *h)
{
  PetscMPIInt    rank;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(h));
  (*h)->comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
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
