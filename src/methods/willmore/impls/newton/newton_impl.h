/* Private to impls/newton/: the constrained Newton step (newton_kkt.c) that newton.c uses with -flow_conformal. */
#ifndef CS_WILLMORE_NEWTON_IMPL_H
#define CS_WILLMORE_NEWTON_IMPL_H
#include "../../willmore_impl.h"

#define CS_NEWTON_KKT_MAXK 16 /* global rows of the KKT step (Moebius balance 3, rotation gauge 3, area, volume, ...) */

typedef struct _NewtonKKT NewtonKKT;
/* the KKT solver of F (set up: F->c, F->x, F->k exist); pc_t: t of the H^2 metric in its preconditioner */
PETSC_INTERN PetscErrorCode CSNewtonKKTCreate(CSWillmoreFlow F, PetscReal pc_t, NewtonKKT **d);
PETSC_INTERN PetscErrorCode CSNewtonKKTDestroy(NewtonKKT **d);
PETSC_INTERN PetscErrorCode CSNewtonKKTTrial(CSWillmoreFlow F, NewtonKKT *d, PetscBool *accept);
PETSC_INTERN PetscErrorCode CSNewtonKKTFilter(CSWillmoreFlow F, NewtonKKT *d, PetscBool *accept);
PETSC_INTERN PetscErrorCode CSNewtonKKTAccept(CSWillmoreFlow F);
PETSC_INTERN PetscInt       CSNewtonKKTIterations(NewtonKKT *d);
/* newton.c: the KKT solver of the flow's Newton data */
PETSC_INTERN NewtonKKT *CSNewtonGetKKT(CSWillmoreFlow F);
#endif
