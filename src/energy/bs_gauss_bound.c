/* bobenko-schroeder2005 Sec. 2: W_i + K_i = sum_j beta_j^i - sum alpha^i >= 0 at every vertex where W_i is defined
   ("reflecting the fact that H^2 dA is always non-negative"), with K_i = 2 pi - (sum of the corner angles). */
#include "cs_energy_bs.h"
#include "cs_geometry.h"

PetscErrorCode CSEnergyWillmoreBSGaussBound(CSEnergy e, Vec x, Vec wk, PetscReal *wkmin, PetscInt *nneg)
{
  CSMesh             m = e->mesh;
  Vec                Wv;
  const PetscScalar *w;
  PetscScalar       *a;
  PetscReal          mn = PETSC_MAX_REAL;
  PetscInt           n, k = 0, neg = 0;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(wk, &Wv));
  PetscCall(CSEnergyWillmoreBSVertex(e, x, Wv, NULL));
  PetscCall(CSGeometryAngleSums(m, x, wk));
  PetscCall(VecGetLocalSize(wk, &n));
  PetscCall(VecGetArrayRead(Wv, &w));
  PetscCall(VecGetArray(wk, &a));
  for (PetscInt v = 0; v < m->nv; v++) {
    if (!m->vertOwned[v]) continue;
    /* W_i (and K_i) are defined at interior vertices only; boundary vertices get 0 */
    a[k] = m->vertBoundary[v] ? 0 : w[k] + 2 * PETSC_PI - a[k];
    if (!m->vertBoundary[v]) {
      mn = PetscMin(mn, PetscRealPart(a[k]));
      if (PetscRealPart(a[k]) < -1e-10) neg++;
    }
    k++;
  }
  PetscCheck(k == n, PETSC_COMM_SELF, PETSC_ERR_PLIB, "owned vertices %" PetscInt_FMT " != local size %" PetscInt_FMT, k, n);
  PetscCall(VecRestoreArray(wk, &a));
  PetscCall(VecRestoreArrayRead(Wv, &w));
  PetscCall(MPIU_Allreduce(&mn, wkmin, 1, MPIU_REAL, MPIU_MIN, m->comm));
  PetscCall(MPIU_Allreduce(&neg, nneg, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscCall(VecDestroy(&Wv));
  PetscFunctionReturn(0);
}
