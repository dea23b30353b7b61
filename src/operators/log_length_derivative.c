/* The derivative of the log edge lengths, Dlambda in R^{E x 3V} (soliman2021 Eq. 5). */
#include "cs_operators_conformal.h"

/* lambda_ij = log |f_j - f_i|, so d lambda_ij = <f_j - f_i, df_j - df_i> / l_ij^2 (Eq. 5). App. D prints
   (Dlambda)_{ij,j} = f_j - f_i, the derivative of l^2/2 rather than of log l: the 1/l^2 is needed for
   X = C Dlambda to be the derivative of the log cross ratios C lambda (checked by finite differences in
   tests/unit/test_willmore_operators.c). Rows are set by the rank owning the edge (both vertices of an
   edge are always in the local closure). */
PetscErrorCode CSOperatorLogLengthDerivative(CSMesh m, Vec x, const PetscBool fixed[], MatReuse reuse, Mat *D)
{
  Vec              xl;
  const PetscReal *p;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(CSOperatorCreatePointMatrix(m->dmE1, m->dmV3, 6, D));
  else PetscCall(MatZeroEntries(*D));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt    i = m->edgeVert[2 * e], j = m->edgeVert[2 * e + 1], cols[6], nc = 0;
    PetscScalar v[6];
    PetscReal   d[3], l2;
    if (!m->edgeOwned[e]) continue;
    CSVecSub(p + 3 * j, p + 3 * i, d);
    l2 = CSVecDot(d, d);
    for (int c = 0; c < 3; c++) {
      if (!fixed || !fixed[i]) {
        cols[nc] = 3 * i + c;
        v[nc++]  = -d[c] / l2;
      }
      if (!fixed || !fixed[j]) {
        cols[nc] = 3 * j + c;
        v[nc++]  = d[c] / l2;
      }
    }
    if (nc) PetscCall(MatSetValuesLocal(*D, 1, &e, nc, cols, v, INSERT_VALUES));
  }
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MatAssemblyBegin(*D, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*D, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
