/* Per-iteration CSV history; flushed every row so a killed run keeps what it computed. */
#include "cs_util.h"

struct _p_CSHistory {
  MPI_Comm comm;
  FILE    *fp; /* rank 0 only */
};

PetscErrorCode CSHistoryCreate(MPI_Comm comm, const char path[], const char header[], CSHistory *h)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(h));
  (*h)->comm = comm;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    PetscCall(CSPathMakeParents(path));
    (*h)->fp = fopen(path, "w");
    PetscCheck((*h)->fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-history_csv: cannot open %s for writing", path);
    fprintf((*h)->fp, "%s\n", header);
    fflush((*h)->fp);
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSHistoryAppend(CSHistory h, PetscInt n, const PetscReal row[])
{
  PetscFunctionBeginUser;
  if (!h || !h->fp) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < n; i++) fprintf(h->fp, i ? ",%.17g" : "%.17g", (double)row[i]);
  fprintf(h->fp, "\n");
  fflush(h->fp);
  PetscFunctionReturn(0);
}

PetscErrorCode CSHistoryDestroy(CSHistory *h)
{
  PetscFunctionBeginUser;
  if (!*h) PetscFunctionReturn(0);
  if ((*h)->fp) fclose((*h)->fp);
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
