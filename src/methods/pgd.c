/* -flow_type pgd (soliman2021 Sec. 4.1, Eq. PGD, with projection). The iteration lives in
   willmore_flow.c; this file is the registered entry point. */
#include "willmore_flow.h"

PetscErrorCode CSFlowPGD(MPI_Comm comm, CSOutput *out)
{
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowRun(comm, out, CS_FLOW_PGD));
  PetscFunctionReturn(0);
}
