/* The common header of the method objects (src/util/object.c), as PETSc's _p_PetscObject is of its objects: the
   communicator, the options prefix, the monitor list and the destroy op, embedded as the first member `hdr` of a
   method object (CSBSFlow, CSConformalFlow, CSCurveFlow, CSWillmoreFlow, CSSpin, CSHarmonicBasis), which is created
   by CSObjectCreate and freed by CSObjectDestroy (as PetscHeaderCreate and PetscHeaderDestroy do).

   The skeleton every method object shares is written once, here: CS_OBJECT_DECLARE(Type, MonitorFn) in the
   object's public header declares, and CS_OBJECT_DEFINE(Type, MonitorFn) in its .c file defines,
     Type##SetOptionsPrefix(Type, const char prefix[])  (NULL: the empty prefix)
     Type##GetOptionsPrefix(Type, const char *prefix[]) (borrowed)
     Type##MonitorSet(Type, MonitorFn, void *ctx, PetscErrorCode (*destroy)(void **)) (up to CS_MAX_MONITORS,
                                                         called in the order set; destroy (may be NULL) frees ctx)
     Type##Destroy(Type *)                              (the monitors' contexts, hdr.destroy, the header)
   and CS_OBJECT_GETTER(Type, Name, T, member) defines a getter Type##Get##Name(Type, T *) of one member,
   CS_OBJECT_SETTER(Type, Name, T, member) a setter Type##Set##Name(Type, T) of one member. */
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

typedef struct _CSObjectHeader  CSObjectHeader;
typedef struct _CSObjectHeader *CSObject; /* an object whose first member is its header */
struct _CSObjectHeader {
  MPI_Comm      comm;
  char         *prefix; /* never NULL after CSObjectCreate */
  CSMonitorList monitors;
  PetscErrorCode (*destroy)(CSObject); /* frees the object's own members (NULL: it has none); given to CSObjectCreate */
};

/* *obj = a zeroed object of size bytes (its header first) with comm, the default prefix and the destroy op of its own
   members (NULL: none), no monitors, as PetscHeaderCreate takes the object's destroy; obj is the address of the
   object's pointer, e.g. CSObjectCreate(sizeof(*F), comm, "curve_", DestroyMembers, &F) */
PETSC_EXTERN PetscErrorCode CSObjectCreate(size_t size, MPI_Comm comm, const char prefix[], PetscErrorCode (*destroy)(CSObject), void *obj);
/* NULL sets the empty prefix */
PETSC_EXTERN PetscErrorCode CSObjectSetOptionsPrefix(CSObjectHeader *h, const char prefix[]);
PETSC_EXTERN PetscErrorCode CSObjectGetOptionsPrefix(CSObjectHeader *h, const char *prefix[]);
/* The whole Destroy of an object (nothing for *obj NULL): cancels its monitors (destroying their contexts), calls
   its destroy op, frees the prefix and the object, and sets *obj = NULL */
PETSC_EXTERN PetscErrorCode CSObjectDestroy(CSObject *obj);

/* caller names the public function in the error for a full list ("<caller>: at most 8 monitors") */
PETSC_EXTERN PetscErrorCode CSMonitorListAdd(CSMonitorList *l, MPI_Comm comm, const char caller[], PetscVoidFunction fn, void *ctx, PetscErrorCode (*destroy)(void **));
/* destroys every context (in the order added) and empties the list */
PETSC_EXTERN PetscErrorCode CSMonitorListCancel(CSMonitorList *l);

/* Calls every monitor of obj (whose header is obj->hdr) in the order set: fn(obj, info, ctx) with fn cast back
   to the object's monitor type MonitorFn. A statement, inside a function that began with PetscFunctionBeginUser. */
#define CS_OBJECT_MONITORS_CALL(obj, MonitorFn, info) \
  do { \
    for (PetscInt cs_i_ = 0; cs_i_ < (obj)->hdr.monitors.n; cs_i_++) PetscCall(((MonitorFn)(obj)->hdr.monitors.fn[cs_i_])((obj), (info), (obj)->hdr.monitors.ctx[cs_i_])); \
  } while (0)

/* the declarations of the shared skeleton (see the top of this file) */
#define CS_OBJECT_DECLARE(Type, MonitorFn) \
  PETSC_EXTERN PetscErrorCode Type##SetOptionsPrefix(Type, const char[]); \
  PETSC_EXTERN PetscErrorCode Type##GetOptionsPrefix(Type, const char *[]); \
  PETSC_EXTERN PetscErrorCode Type##MonitorSet(Type, MonitorFn, void *, PetscErrorCode (*)(void **)); \
  PETSC_EXTERN PetscErrorCode Type##Destroy(Type *)

/* the definitions of the shared skeleton: each a call of the header's function */
#define CS_OBJECT_DEFINE(Type, MonitorFn) \
  PetscErrorCode Type##SetOptionsPrefix(Type obj, const char prefix[]) \
  { \
    PetscFunctionBeginUser; \
    PetscCall(CSObjectSetOptionsPrefix(&obj->hdr, prefix)); \
    PetscFunctionReturn(0); \
  } \
  PetscErrorCode Type##GetOptionsPrefix(Type obj, const char *prefix[]) \
  { \
    PetscFunctionBeginUser; \
    PetscCall(CSObjectGetOptionsPrefix(&obj->hdr, prefix)); \
    PetscFunctionReturn(0); \
  } \
  PetscErrorCode Type##MonitorSet(Type obj, MonitorFn fn, void *ctx, PetscErrorCode (*destroy)(void **)) \
  { \
    PetscFunctionBeginUser; \
    PetscCall(CSMonitorListAdd(&obj->hdr.monitors, obj->hdr.comm, #Type "MonitorSet", (PetscVoidFunction)fn, ctx, destroy)); \
    PetscFunctionReturn(0); \
  } \
  PetscErrorCode Type##Destroy(Type *obj) \
  { \
    PetscFunctionBeginUser; \
    PetscCall(CSObjectDestroy((CSObject *)obj)); \
    PetscFunctionReturn(0); \
  }

/* PetscErrorCode Type##Get##Name(Type obj, T *value): *value = obj->member (borrowed; no cast, so a member of
   another type is a compile error, but an integer member may give an enum) */
#define CS_OBJECT_GETTER(Type, Name, T, member) \
  PetscErrorCode Type##Get##Name(Type obj, T *value) \
  { \
    PetscFunctionBeginUser; \
    *value = obj->member; \
    PetscFunctionReturn(0); \
  }

/* the same getter for a member that exists only once obj->ready is set: before, an ORDER error naming the call to
   make first (after) */
#define CS_OBJECT_GETTER_AFTER(Type, Name, T, member, ready, after) \
  PetscErrorCode Type##Get##Name(Type obj, T *value) \
  { \
    PetscFunctionBeginUser; \
    PetscCheck(obj->ready, obj->hdr.comm, PETSC_ERR_ORDER, #Type "Get" #Name " before " after); \
    *value = obj->member; \
    PetscFunctionReturn(0); \
  }
/* PetscErrorCode Type##Set##Name(Type obj, T value): obj->member = value (a plain value, no check) */
#define CS_OBJECT_SETTER(Type, Name, T, member) \
  PetscErrorCode Type##Set##Name(Type obj, T value) \
  { \
    PetscFunctionBeginUser; \
    obj->member = value; \
    PetscFunctionReturn(0); \
  }
#endif
