/* Private to src/methods: the common driver of the cgd / pgd / gd flows. */
#ifndef CS_WILLMORE_FLOW_H
#define CS_WILLMORE_FLOW_H
#include "cs_methods_willmore.h"

typedef enum { CS_FLOW_CGD, CS_FLOW_PGD, CS_FLOW_GD } CSFlowKind;
PETSC_INTERN PetscErrorCode CSWillmoreFlowRun(MPI_Comm comm, CSOutput *out, CSFlowKind kind);

#endif
