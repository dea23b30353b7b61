/* Collective propagation of an error raised on some ranks only (reading files happens on rank 0; a local
   factorisation can fail on one rank): every rank raises it, so no rank waits forever in a collective while the
   failing one is already gone. */
#include "cs_util.h"

PetscErrorCode CSSyncError(MPI_Comm comm, PetscErrorCode ierr)
{
  PetscMPIInt rank, size, mine, first;
  int         code = (int)ierr;
  char        msg[1024] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  mine = ierr ? rank : size; /* size: no error here */
  PetscCallMPI(MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm));
  if (first == size) PetscFunctionReturn(0);
  if (rank == first) {
    const char *text;
    char       *specific = NULL;
    PetscCall(PetscErrorMessage(code, &text, &specific));
    PetscCall(PetscStrncpy(msg, specific ? specific : (text ? text : "unknown error"), sizeof(msg)));
  }
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, first, comm));
  PetscCallMPI(MPI_Bcast(msg, (int)sizeof(msg), MPI_CHAR, first, comm));
  SETERRQ(comm, code, "%s", msg);
}
