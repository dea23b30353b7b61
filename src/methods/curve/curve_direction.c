/* A state of the curve flow and its direction (crane2013 Sec. 4 and 5, Table 1 steps I-IV):
     I    kappa_i = phi_i / d_i, the turning angle over the dual length. With it the cumulative sums of
          Sec. 5.2 give back exactly the current edge angles, so a step with v = 0 changes nothing.
     II   v = -2 kappa, the L2 gradient of E = |kappa|^2_d = sum_i d_i kappa_i^2 (Eq. 1).
     (Sec. 4) optional spectral filter v <- v - (id + sigma A^k)^{-1} v.
     III  an orthonormal basis of {1, f^x, f^y} in <a,b>_d = sum_i d_i a_i b_i (modified Gram-Schmidt);
     IV   v <- v - sum_i <v, c_i> c_i (closed curves: <kappa', 1> keeps the total curvature 2 pi k, <kappa', f>
          closes the curve to first order, App. A).
   Discrete closure (App. A in the discrete setting, derived in docs/curve_flow.md): with theta_k = theta_0 +
   sum_{i=1..k} d_i kappa_i and edge k from f_k to f_{k+1}, the first variation of the gap sum_k l_k T_k is
   J sum_i d_i kappa'_i (f_0 - f_i); with <kappa', 1> = 0 it vanishes iff <kappa', f^x> = <kappa', f^y> = 0.
   So the paper's constraints are the exact linearisation of the discrete closure, and the gap is O(tau^2). */
#include "curve_flow_impl.h"
#include "cs_operators.h"

/* sum d kappa, sum d kappa^2, min and max kappa (interior vertices of an open curve) */
static PetscErrorCode KappaStats(CSCurveFlow F)
{
  CSCurve            c = F->curve;
  const PetscScalar *k, *d;
  PetscReal          s[2] = {0, 0}, mm[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, S[2], MM[2], mean;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(F->kappa, &k));
  PetscCall(VecGetArrayRead(F->d, &d));
  for (PetscInt i = 0; i < c->n; i++) {
    PetscInt gi = c->rstart + i;
    s[0] += d[i] * k[i];
    s[1] += d[i] * k[i] * k[i];
    if (!c->closed && (gi == 0 || gi == c->N - 1)) continue;
    mm[0] = PetscMin(mm[0], k[i]);
    mm[1] = PetscMin(mm[1], -k[i]);
  }
  PetscCall(VecRestoreArrayRead(F->d, &d));
  PetscCall(VecRestoreArrayRead(F->kappa, &k));
  PetscCallMPI(MPI_Allreduce(s, S, 2, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  PetscCallMPI(MPI_Allreduce(mm, MM, 2, MPIU_REAL, MPIU_MIN, F->hdr.comm));
  mean          = S[0] / F->length;
  F->s.turning  = S[0] / (2 * PETSC_PI); /* sum_i phi_i / 2 pi */
  F->s.energy   = S[1];
  F->s.spread   = c->closed ? -MM[1] - MM[0] : PetscMax(PetscAbsReal(MM[0]), PetscAbsReal(MM[1]));
  F->s.spread_rel = mean != 0 ? F->s.spread / PetscAbsReal(mean) : F->s.spread;
  PetscFunctionReturn(0);
}

/* max |l~/l - 1| of the current positions against the input lengths */
static PetscErrorCode Distortion(CSCurveFlow F)
{
  CSCurve            c = F->curve;
  const PetscScalar *l, *l0;
  PetscReal          dm = 0;
  PetscFunctionBeginUser;
  PetscCall(CSCurveEdgeLengths(c, F->x, F->lwork));
  PetscCall(VecGetArrayRead(F->lwork, &l));
  PetscCall(VecGetArrayRead(F->len, &l0));
  for (PetscInt i = 0; i < c->n; i++)
    if (l0[i] > 0) dm = PetscMax(dm, PetscAbsReal(l[i] / l0[i] - 1));
  PetscCall(VecRestoreArrayRead(F->len, &l0));
  PetscCall(VecRestoreArrayRead(F->lwork, &l));
  PetscCallMPI(MPI_Allreduce(&dm, &F->s.distortion, 1, MPIU_REAL, MPIU_MAX, F->hdr.comm));
  PetscFunctionReturn(0);
}

/* Sec. 4: v <- v - (id + sigma A^k)^{-1} v with A = M^{-1} L, i.e. (M + sigma L (M^{-1} L)^{k-1}) w = M v */
static PetscErrorCode Filter(CSCurveFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(VecPointwiseMult(F->rhs[0], F->d, F->v));
  PetscCall(KSPSolve(F->kspf, F->rhs[0], F->del[0]));
  PetscCall(CSOperatorSpectralFilterCheck(F->kspf, F->rhs[0], F->del[0], "curve flow", F->hdr.prefix));
  PetscCall(VecAXPY(F->v, -1, F->del[0]));
  PetscFunctionReturn(0);
}

/* Table 1 III-IV: Gram-Schmidt of {1, f^x, f^y} in <.,.>_d, then v minus its components along them */
static PetscErrorCode Project(CSCurveFlow F)
{
  PetscReal a;
  PetscFunctionBeginUser;
  PetscCall(VecSet(F->c[0], 1));
  PetscCall(VecStrideGather(F->x, 0, F->c[1], INSERT_VALUES));
  PetscCall(VecStrideGather(F->x, 1, F->c[2], INSERT_VALUES));
  for (int j = 0; j < 3; j++) {
    for (int i = 0; i < j; i++) {
      PetscCall(CSCurveDot(F->curve, F->d, F->c[j], F->c[i], &a));
      PetscCall(VecAXPY(F->c[j], -a, F->c[i]));
    }
    PetscCall(CSCurveDot(F->curve, F->d, F->c[j], F->c[j], &a));
    PetscCheck(a > 0, F->hdr.comm, PETSC_ERR_PLIB, "curve flow: the constraint functions 1, f^x, f^y are linearly dependent (a straight curve?)");
    PetscCall(VecScale(F->c[j], 1 / PetscSqrtReal(a)));
  }
  for (int i = 0; i < 3; i++) {
    PetscCall(CSCurveDot(F->curve, F->d, F->v, F->c[i], &a));
    PetscCall(VecAXPY(F->v, -a, F->c[i]));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowEvaluate(CSCurveFlow F)
{
  PetscReal vv;
  PetscFunctionBeginUser;
  PetscCall(CSCurveCurvature(F->curve, F->x, F->d, F->kappa)); /* I */
  PetscCall(KappaStats(F));
  PetscCall(Distortion(F));
  PetscCall(VecAXPBY(F->v, -2, 0, F->kappa)); /* II, Eq. 1 */
  if (F->filter) PetscCall(Filter(F));
  if (F->curve->closed) PetscCall(Project(F)); /* III, IV */
  PetscCall(CSCurveDot(F->curve, F->d, F->v, F->v, &vv));
  F->s.stationarity = PetscSqrtReal(vv * F->length) / (2 * PETSC_PI);
  PetscFunctionReturn(0);
}
