/* The common header of the method objects and their monitor list (include/cs_object.h). */
#include "cs_object.h"

PetscErrorCode CSObjectCreate(size_t size, MPI_Comm comm, const char prefix[], PetscErrorCode (*destroy)(CSObject), void *obj)
{
  CSObject *h = (CSObject *)obj;
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc(size, h));
  (*h)->comm    = comm;
  (*h)->destroy = destroy;
  PetscCall(PetscStrallocpy(prefix ? prefix : "", &(*h)->prefix));
  PetscFunctionReturn(0);
}

PetscErrorCode CSObjectSetOptionsPrefix(CSObjectHeader *h, const char prefix[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(h->prefix));
  PetscCall(PetscStrallocpy(prefix ? prefix : "", &h->prefix));
  PetscFunctionReturn(0);
}

PetscErrorCode CSObjectGetOptionsPrefix(CSObjectHeader *h, const char *prefix[])
{
  PetscFunctionBeginUser;
  *prefix = h->prefix;
  PetscFunctionReturn(0);
}

PetscErrorCode CSObjectDestroy(CSObject *obj)
{
  PetscFunctionBeginUser;
  if (!*obj) PetscFunctionReturn(0);
  PetscCall(CSMonitorListCancel(&(*obj)->monitors)); /* before the members: a monitor's context may hold some */
  if ((*obj)->destroy) PetscCall((*(*obj)->destroy)(*obj));
  PetscCall(PetscFree((*obj)->prefix));
  PetscCall(PetscFree(*obj));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMonitorListAdd(CSMonitorList *l, MPI_Comm comm, const char caller[], PetscVoidFunction fn, void *ctx, PetscErrorCode (*destroy)(void **))
{
  PetscFunctionBeginUser;
  PetscCheck(l->n < CS_MAX_MONITORS, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: at most %d monitors", caller, CS_MAX_MONITORS);
  l->fn[l->n]      = fn;
  l->ctx[l->n]     = ctx;
  l->destroy[l->n] = destroy;
  l->n++;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMonitorListCancel(CSMonitorList *l)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < l->n; i++)
    if (l->destroy[i]) PetscCall((*l->destroy[i])(&l->ctx[i]));
  l->n = 0;
  PetscFunctionReturn(0);
}
