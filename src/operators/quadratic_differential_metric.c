/* The metric I_Q on discrete quadratic differentials (soliman2021 Eq. 9 and Eq. 25). */
#include "cs_operators_conformal.h"

/* (I_Q)_ij = 1 / (w_ij l_ij^2) = 1 / (l_ij l*_ij) (Eq. 9, 25): the L2 norm of the conformal tension. On a
   non-Delaunay edge w_ij <= 0 (the two opposite angles sum to >= pi) and Eq. 25 is negative or infinite,
   which would make the (2,2) block of the CGD system indefinite/singular. We guard by using
   max(w_ij, wmin): a positive floor keeps I_Q a metric; the only effect is a smaller dual step on those
   edges (the multiplier there still converges, the fixed point of the flow is unchanged since I_Q only
   enters the step, not the Euler-Lagrange equations). */
PetscErrorCode CSOperatorQuadDiffMetric(CSMesh m, Vec x, PetscReal wmin, Vec iq, PetscInt *nguard)
{
  Vec          l;
  PetscInt     n, ng = 0;
  PetscScalar *a;
  const PetscScalar *la;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(iq, &l));
  PetscCall(CSGeometryEdgeLengths(m, x, l));
  PetscCall(CSGeometryCotanWeights(m, x, iq));
  PetscCall(VecGetLocalSize(iq, &n));
  PetscCall(VecGetArray(iq, &a));
  PetscCall(VecGetArrayRead(l, &la));
  for (PetscInt e = 0; e < n; e++) {
    PetscReal w = PetscRealPart(a[e]);
    if (w < wmin) {
      w = wmin;
      ng++;
    }
    a[e] = 1.0 / (w * la[e] * la[e]);
  }
  PetscCall(VecRestoreArrayRead(l, &la));
  PetscCall(VecRestoreArray(iq, &a));
  PetscCall(VecDestroy(&l));
  if (nguard) PetscCall(MPIU_Allreduce(&ng, nguard, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscFunctionReturn(0);
}
