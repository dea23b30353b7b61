#include "cs_util.h"
#include <stdio.h>

/* Every numeric option is checked where it is read (issue 18: nan, inf or out-of-range values made do-nothing runs
   that exited 0): finite, and in the range the caller tests, or a one-line error naming the option. The caller
   lists its options as a table of {name, value, in range, what is wanted}. */
PetscErrorCode CSCheckOptionValues(MPI_Comm comm, const char prefix[], size_t n, const CSOptionCheck checks[])
{
  PetscFunctionBeginUser;
  for (size_t i = 0; i < n; i++) {
    const CSOptionCheck *c = &checks[i];
    char                 num[32];
    snprintf(num, sizeof(num), "%g", (double)c->value); /* C's %g: PETSc's would print -1 as "-1." */
    PetscCheck(c->ok && !PetscIsInfOrNanReal(c->value), comm, PETSC_ERR_ARG_OUTOFRANGE, "-%s%s %s: %s", prefix ? prefix : "", c->name, num, c->want);
  }
  PetscFunctionReturn(0);
}
