/* Faces folded against a reference state: the area vector of the face in x points against the one in xref
   (a face turned over: the surface has passed through itself there, or the step was far too long). */
#include "cs_geometry.h"

PetscErrorCode CSGeometryFoldedFaces(CSMesh m, Vec xref, Vec x, PetscInt *nfolded)
{
  Vec              xl, rl;
  const PetscReal *p, *r;
  PetscInt         n = 0;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(CSMeshGetLocalPositions(m, xref, &rl, &r));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscReal *c0[3] = {r + 3 * F.v[0], r + 3 * F.v[1], r + 3 * F.v[2]};
    PetscReal        a[3], a0[3];
    CSTriangleAreaVector(F.c, a);
    CSTriangleAreaVector(c0, a0);
    if (!(CSVecDot(a, a0) > 0)) n++; /* faces are not ghosted (overlap 0): each counted once */
  }
  PetscCall(CSMeshRestoreLocalPositions(m, xref, &rl, &r));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MPIU_Allreduce(&n, nfolded, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscFunctionReturn(0);
}
