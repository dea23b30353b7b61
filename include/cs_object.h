/* The common header of the method objects (src/util/object.c), as PETSc's _p_PetscObject is of its objects: the
   communicator, the options prefix and the monitor list, embedded as the first member `hdr` of a method object
   (CSBSFlow, CSCurveFlow), which is created by CSObjectCreate and freed by CSObjectDestroy (as PetscHeaderCreate
   and PetscHeaderDestroy do) and whose public SetOptionsPrefix/GetOptionsPrefix/MonitorSet are one-line
   wrappers. */
#ifndef CS_OBJECT_H
#define CS_OBJECT_H
#include <petscsys.h>

#define CS_MAX_MONITORS 8

/* Monitors in the order added. fn is stored as PetscVoidFunction; the object casts it back to its own monitor
   type when it calls them (its monitors take its own state struct). destroy (may be NULL) frees ctx. */
typedef struct {
  PetscInt          n;
  PetscVoidFunction fn[CS_MAX_MONITORS];
  void             *ctx[CS_MAX_MONITORS];
  PetscErrorCode (*destroy[CS_MAX_MONITORS])(void **);
} CSMonitorList;

struct _CSObjectHeader {
  MPI_Comm      comm;
  char         *prefix; /* never NULL after CSObjectHeaderInit */
  CSMonitorList monitors;
};
typedef struct _CSObjectHeader CSObjectHeader;
typedef struct _CSObjectHeader *CSObject; /* an object whose first member is its header */

/* *obj = a zeroed object of size bytes (its header first) with comm and the default prefix, no monitors; obj is
   the address of the object's pointer, e.g. CSObjectCreate(sizeof(*F), comm, "curve_", &F) */
PETSC_EXTERN PetscErrorCode CSObjectCreate(size_t size, MPI_Comm comm, const char prefix[], void *obj);
/* NULL sets the empty prefix */
PETSC_EXTERN PetscErrorCode CSObjectSetOptionsPrefix(CSObjectHeader *h, const char prefix[]);
PETSC_EXTERN PetscErrorCode CSObjectGetOptionsPrefix(CSObjectHeader *h, const char *prefix[]);
/* the end of the object's Destroy: cancels any monitors left (destroying their contexts), frees the prefix and
   the object, and sets *obj = NULL */
PETSC_EXTERN PetscErrorCode CSObjectDestroy(CSObject *obj);

/* caller names the public function in the error for a full list ("<caller>: at most 8 monitors") */
PETSC_EXTERN PetscErrorCode CSMonitorListAdd(CSMonitorList *l, MPI_Comm comm, const char caller[], PetscVoidFunction fn, void *ctx, PetscErrorCode (*destroy)(void **));
/* destroys every context (in the order added) and empties the list */
PETSC_EXTERN PetscErrorCode CSMonitorListCancel(CSMonitorList *l);

#endif
