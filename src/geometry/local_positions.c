/* Ghosted local positions: every face kernel reads its three corners from here; CSGeometryFaceSum runs a
   kernel over the faces and sums the shares into a global vector. */
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

PetscErrorCode CSGeometryFaceSum(CSMesh m, Vec x, DM dm, CSFaceAdd add, Vec g)
{
  Vec              xl;
  const PetscReal *p;
  CSLocalSum       s;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSLocalSumBegin(dm, &s));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) add(m, p, &F, s.a);
  PetscCall(CSLocalSumEnd(&s, g));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}
