/* The names in a PetscFunctionList, for error messages that list the known types (tasks, flow types) without a
   hand-kept copy that goes stale when a type is registered. */
#include "cs_util.h"

PetscErrorCode CSFunctionListNames(PetscFunctionList list, char *buf, size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(CSFunctionListJoin(list, " ", buf, len));
  PetscFunctionReturn(0);
}

/* The names in registration order, separated by sep ("|": the form of "-flow_energy NAME: unknown (a|b|c)"). */
PetscErrorCode CSFunctionListJoin(PetscFunctionList list, const char sep[], char *buf, size_t len)
{
  const char **names;
  int          n;

  PetscFunctionBeginUser;
  PetscCheck(len > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "CSFunctionListJoin: empty buffer");
  buf[0] = 0;
  PetscCall(PetscFunctionListGet(list, &names, &n));
  for (int i = 0; i < n; i++) { /* the array ends with an empty name */
    if (!names[i] || !names[i][0]) continue;
    if (buf[0]) PetscCall(PetscStrlcat(buf, sep, len));
    PetscCall(PetscStrlcat(buf, names[i], len));
  }
  PetscCall(PetscFree(names));
  PetscFunctionReturn(0);
}
