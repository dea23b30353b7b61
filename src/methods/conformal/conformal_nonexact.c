/* How integrable a step's transformed edge vectors are (crane2011 Sec. 5.6; crane2013 Table 1 VII): the Poisson
   step finds f~ minimising sum_e *1_e |f~_j - f~_i - beta_e|^2, beta_e = conj(lambda) e lambda per edge (crane2011
   Eq. 8), so its least-squares residual r_e = (f~_j - f~_i) - beta_e is exactly the part of beta that is not
   exact (its coexact and harmonic parts in the *1 inner product). The relative non-exact residual
       eta = |r|_*1 / |beta|_*1   (over the three coordinates)
   measures how far the discrete spin transformation is from an integrable one: the distortion the Poisson step
   has to spread over the surface. Its harmonic part is the closing error (conformal_exactness.c).
   -flow_max_nonexact eta_max (> 0) rejects a step whose eta exceeds eta_max and retries it with tau halved (at
   most -flow_max_halvings times): a safeguard, not the paper's method (docs/conformal_flow.md "knot1"). */
#include "conformal_impl.h"

/* eta from the sums over owned edges of *1_e |beta_e|^2 and *1_e |df~_e - beta_e|^2 (xnew before any rescaling) */
PetscErrorCode CSConformalFlowNonExactResidual(CSConformalFlow F, Vec xnew, PetscReal *eta)
{
  CSMesh             m = F->mesh;
  Vec                xl, nl, ll, st;
  const PetscReal   *p, *pn;
  const PetscScalar *l;
  PetscReal          loc[2] = {0, 0}, glob[2];
  DM                 dm4;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetDM(F->spin, &dm4));
  PetscCall(DMCreateGlobalVector(m->dmE1, &st));
  PetscCall(CSOperatorHodgeStar1(m, F->x, st));
  PetscCall(CSMeshGetLocalPositions(m, F->x, &xl, &p));
  PetscCall(CSMeshGetLocalPositions(m, xnew, &nl, &pn));
  PetscCall(DMGetLocalVector(dm4, &ll));
  PetscCall(DMGlobalToLocal(dm4, F->lambda, INSERT_VALUES, ll));
  PetscCall(VecGetArrayRead(ll, &l));
  {
    Vec                sl;
    const PetscScalar *sa;
    PetscCall(DMGetLocalVector(m->dmE1, &sl));
    PetscCall(DMGlobalToLocal(m->dmE1, st, INSERT_VALUES, sl));
    PetscCall(VecGetArrayRead(sl, &sa));
    for (PetscInt e = 0; e < m->ne; e++) {
      PetscInt  i = m->edgeVert[2 * e], j = m->edgeVert[2 * e + 1];
      /* |w|: the cotan weight is negative on a non-Delaunay edge, and sum w |r|^2 is then no norm (review 2026-12-05) */
      PetscReal li[4], lj[4], ed[3], et[3], dn[3], w = PetscAbsReal(PetscRealPart(sa[e]));
      if (!m->edgeOwned[e]) continue;
      for (int q = 0; q < 4; q++) {
        li[q] = PetscRealPart(l[4 * i + q]);
        lj[q] = PetscRealPart(l[4 * j + q]);
      }
      CSVecSub(p + 3 * j, p + 3 * i, ed);
      CSSpinTransformedEdge(li, lj, ed, et);
      CSVecSub(pn + 3 * j, pn + 3 * i, dn);
      for (int d = 0; d < 3; d++) {
        loc[0] += w * et[d] * et[d];
        loc[1] += w * (dn[d] - et[d]) * (dn[d] - et[d]);
      }
    }
    PetscCall(VecRestoreArrayRead(sl, &sa));
    PetscCall(DMRestoreLocalVector(m->dmE1, &sl));
  }
  PetscCall(VecRestoreArrayRead(ll, &l));
  PetscCall(DMRestoreLocalVector(dm4, &ll));
  PetscCall(CSMeshRestoreLocalPositions(m, xnew, &nl, &pn));
  PetscCall(CSMeshRestoreLocalPositions(m, F->x, &xl, &p));
  PetscCall(MPIU_Allreduce(loc, glob, 2, MPIU_REAL, MPIU_SUM, m->comm));
  *eta = glob[0] > 0 ? PetscSqrtReal(glob[1] / glob[0]) : 0;
  PetscCall(VecDestroy(&st));
  PetscFunctionReturn(0);
}
