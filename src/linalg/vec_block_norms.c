/* Per-block 2-norms of a vector: |h| of the mean curvature vectors, |lambda| of the quaternion fields. */
#include "cs_linalg.h"

PetscErrorCode CSVecBlockNorms(Vec x, PetscInt bs, Vec norms)
{
  const PetscScalar *a;
  PetscScalar       *r;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(norms, &n));
  PetscCall(VecGetArrayRead(x, &a));
  PetscCall(VecGetArray(norms, &r));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal s = 0;
    for (PetscInt c = 0; c < bs; c++) s += PetscSqr(PetscRealPart(a[bs * i + c]));
    r[i] = PetscSqrtReal(s);
  }
  PetscCall(VecRestoreArray(norms, &r));
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscFunctionReturn(0);
}
