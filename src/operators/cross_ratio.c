/* Log edge lengths and the cross-ratio map C of soliman2021 Sec. 3 / App. D. */
#include "cs_operators_conformal.h"

PetscErrorCode CSOperatorLogLengths(CSMesh m, Vec x, Vec lambda)
{
  PetscInt     n;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryEdgeLengths(m, x, lambda));
  PetscCall(VecGetLocalSize(lambda, &n));
  PetscCall(VecGetArray(lambda, &a));
  for (PetscInt e = 0; e < n; e++) a[e] = PetscLogReal(a[e]);
  PetscCall(VecRestoreArray(lambda, &a));
  PetscFunctionReturn(0);
}

/* Each face ijk (counter-clockwise) adds, by soliman2021 Eq. 24, to the row of its edge ij the terms
   +lambda_jk - lambda_ki. The face jil on the other side adds +lambda_il - lambda_lj, so
     (C lambda)_ij = lambda_jk - lambda_ki + lambda_il - lambda_lj = log (l_il l_jk / (l_lj l_ki)).
   The printed Eq. 3 has l_ij in the denominator where l_lj belongs (a typo: with l_ij the map would not
   vanish on Au, i.e. not be scale invariant; with l_lj every lambda_ab appears once with + and once with -
   in each row, so C A u = 0, Eq. 4). In our tables faceEdge[3f+k] is the edge opposite corner k, i.e. the
   edge (k+1, k+2); its "next" edge (k+2, k) is opposite corner k+1 and its "previous" edge (k, k+1) is
   opposite corner k+2: row e_k gets +1 at e_{k+1} and -1 at e_{k+2}. */
PetscErrorCode CSOperatorCrossRatio(CSMesh m, PetscBool interior_only, Mat *C)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscCall(DMCreateMatrix(m->dmE1, C));
  PetscCall(MatSetOption(*C, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    const PetscInt *fe = F.e;
    for (int k = 0; k < 3; k++) {
      PetscInt    row = fe[k], cols[2] = {fe[(k + 1) % 3], fe[(k + 2) % 3]};
      PetscScalar v[2] = {1.0, -1.0};
      if (interior_only && m->edgeBoundary[row]) continue;
      PetscCall(MatSetValuesLocal(*C, 1, &row, 2, cols, v, ADD_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(*C, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*C, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
