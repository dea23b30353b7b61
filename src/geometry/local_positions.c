/* Ghosted local positions: every face kernel reads its three corners from here. */
#include "cs_geometry.h"

PetscErrorCode CSMeshGetLocalPositions(CSMesh m, Vec x, Vec *xl, const PetscReal **p)
{
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(m->dmV3, xl));
  PetscCall(DMGlobalToLocal(m->dmV3, x, INSERT_VALUES, *xl));
  PetscCall(VecGetArrayRead(*xl, (const PetscScalar **)p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshRestoreLocalPositions(CSMesh m, Vec x, Vec *xl, const PetscReal **p)
{
  PetscFunctionBeginUser;
  PetscCall(VecRestoreArrayRead(*xl, (const PetscScalar **)p));
  PetscCall(DMRestoreLocalVector(m->dmV3, xl));
  PetscFunctionReturn(0);
}
