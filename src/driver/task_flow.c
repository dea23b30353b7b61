/* -task flow: dispatch on -flow_type to the flow methods (each registers one line below). */
#include "cs_driver.h"
#include "cs_methods_willmore.h"
#include "cs_methods_bs.h"

typedef struct {
  const char *name;
  PetscErrorCode (*run)(MPI_Comm, CSOutput *);
} CSFlowType;

/* cgd|pgd|gd (soliman2021, issue 3) and bs (Bobenko-Schroeder, issue 5) register here. */
static const CSFlowType flows[] = {
  {"cgd", CSFlowCGD}, {"pgd", CSFlowPGD}, {"gd", CSFlowGD},
  {"bs", CSFlowBS},
  {NULL, NULL},
};

PetscErrorCode CSTaskFlow(MPI_Comm comm)
{
  char      type[64] = "cgd", known[256] = "";
  PetscBool found    = PETSC_FALSE;
  CSOutput  out;
  PetscFunctionBeginUser;
  PetscOptionsBegin(comm, NULL, "confsurf flow", NULL);
  PetscCall(PetscOptionsString("-flow_type", "cgd|pgd|gd|bs", NULL, type, type, sizeof(type), NULL));
  PetscOptionsEnd();
  PetscCall(CSOutputFromOptions(comm, &out));
  for (size_t i = 0; i < sizeof(flows) / sizeof(flows[0]); i++) {
    PetscBool same;
    if (!flows[i].name) continue;
    PetscCall(PetscStrlcat(known, " ", sizeof(known)));
    PetscCall(PetscStrlcat(known, flows[i].name, sizeof(known)));
    PetscCall(PetscStrcmp(type, flows[i].name, &same));
    if (same && !found) {
      PetscErrorCode ierr;
      found = PETSC_TRUE;
      ierr  = flows[i].run(comm, &out);
      if (ierr) PetscCall(CSOutputDestroy(&out)); /* no leak on the error path */
      PetscCall(ierr);
    }
  }
  PetscCall(CSOutputDestroy(&out));
  PetscCheck(found, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_type %s: unknown flow (known:%s)", type, known);
  PetscFunctionReturn(0);
}
