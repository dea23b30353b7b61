/* -flow_type cgd (soliman2021 Sec. 4.2, Algorithm 1). The iteration lives in
   willmore_flow.c; this file is the registered entry point. */
#include "willmore_flow.h"

PetscErrorCode CSFlowCGD(MPI_Comm comm, CSOutput *out)
{
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowRun(comm, out, CS_FLOW_CGD));
  PetscFunctionReturn(0);
}
