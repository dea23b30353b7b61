/* Collective propagation of an error raised on rank 0 only (reading files happens there): every rank raises
   it, so no rank waits forever in a collective while rank 0 is already gone. */
#include "cs_util.h"

PetscErrorCode CSSyncRootError(MPI_Comm comm, PetscErrorCode ierr)
{
  PetscMPIInt rank;
  int         code = (int)ierr;
  char        msg[1024] = "";

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Bcast(&code, 1, MPI_INT, 0, comm));
  if (!code) PetscFunctionReturn(0);
  if (!rank) {
    const char *text;
    char       *specific = NULL;
    PetscCall(PetscErrorMessage(code, &text, &specific));
    PetscCall(PetscStrncpy(msg, specific ? specific : (text ? text : "unknown error"), sizeof(msg)));
  }
  PetscCallMPI(MPI_Bcast(msg, (int)sizeof(msg), MPI_CHAR, 0, comm));
  SETERRQ(comm, code, "%s", msg);
}
