/* Growing arrays (the JSON entries, the viewer's time steps). */
#include "cs_util.h"

PetscErrorCode CSArrayGrow(size_t size, PetscInt n, PetscInt initial, PetscInt *cap, void **a)
{
  void    *b;
  PetscInt c = *cap ? 2 * *cap : initial;
  PetscFunctionBeginUser;
  if (n < *cap) PetscFunctionReturn(0);
  PetscCall(PetscMalloc(size * (size_t)c, &b));
  if (n) PetscCall(PetscMemcpy(b, *a, size * (size_t)n));
  PetscCall(PetscFree(*a));
  *a   = b;
  *cap = c;
  PetscFunctionReturn(0);
}
