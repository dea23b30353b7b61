#include "cs_util.h"
#include <stdio.h>

/* Every numeric option is checked where it is read (issue 18: nan, inf or out-of-range values made do-nothing runs
   that exited 0): finite, and in the range the caller tests, or a one-line error naming the option. */
PetscErrorCode CSCheckOptionValue(MPI_Comm comm, const char prefix[], const char name[], PetscReal v, PetscBool ok, const char want[])
{
  char num[32];
  PetscFunctionBeginUser;
  snprintf(num, sizeof(num), "%g", (double)v); /* C's %g: PETSc's would print -1 as "-1." */
  PetscCheck(ok && !PetscIsInfOrNanReal(v), comm, PETSC_ERR_ARG_OUTOFRANGE, "-%s%s %s: %s", prefix ? prefix : "", name, num, want);
  PetscFunctionReturn(0);
}
