/* -flow_type gd (soliman2021 Sec. 4, Eq. GD: unconstrained Sobolev gradient descent). The iteration lives in
   willmore_flow.c; this file is the registered entry point. */
#include "willmore_flow.h"

PetscErrorCode CSFlowGD(MPI_Comm comm, CSOutput *out)
{
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowRun(comm, out, CS_FLOW_GD));
  PetscFunctionReturn(0);
}
