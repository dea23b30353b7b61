/* The driver: common output options and the tasks of bin/confsurf. */
#ifndef CS_DRIVER_H
#define CS_DRIVER_H
#include "cs_energy.h"
#include "cs_util.h"

/* The fixed output interface of every task (DEVELOPERS.md): -o, -viewer_dir, -summary, -history, -reference. */
typedef struct {
  char      out[PETSC_MAX_PATH_LEN], viewer_dir[PETSC_MAX_PATH_LEN], summary[PETSC_MAX_PATH_LEN], history[PETSC_MAX_PATH_LEN], reference[PETSC_MAX_PATH_LEN];
  PetscBool has_out, has_viewer, has_summary, has_history, has_reference;
  PetscLogDouble t0;
  CSJSON    json;
} CSOutput;

PETSC_EXTERN PetscErrorCode CSOutputFromOptions(MPI_Comm comm, CSOutput *o);
/* The keys every task reports: counts, topology, area, volume, willmore, (q_mean, q_max against
   -reference or the given xref), then writes -o and -summary (adding seconds). */
PETSC_EXTERN PetscErrorCode CSOutputAddMeshFacts(CSOutput *o, CSMesh mesh, Vec x, Vec xref);
PETSC_EXTERN PetscErrorCode CSOutputFinish(CSOutput *o, CSMesh mesh, Vec x);
PETSC_EXTERN PetscErrorCode CSOutputDestroy(CSOutput *o);

PETSC_EXTERN PetscErrorCode CSTaskInfo(MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSTaskFlow(MPI_Comm comm);

#endif
