/* Table 1 steps V-VI and the right-hand side of VII (crane2013 Eq. 2, Sec. 5.1, 5.2):
     kappa~ = kappa + tau v                                   (Eq. 2 with the constrained direction v)
     theta_k = theta_0 + sum_{i=1..k} d_i kappa~_i            (Sec. 5.2; across ranks with MPI_Exscan)
     T~_k = l_k (cos theta_k, sin theta_k)                    (edge k from vertex k to k+1, l the input lengths)
     b_i = T~_{i-1}/l_{i-1} - T~_i/l_i                        (Sec. 5.2, as printed: the divergence of T~)
   theta_0 is the current angle of edge 0; the rotation this leaves is removed after the Poisson step.
   The Poisson problem is solved for the correction delta = f~ - f (curve_poisson.c), whose right-hand side
   is b - L f = g_{i-1} - g_i with g_k = T~_k/l_k - (f_{k+1} - f_k)/l_k: for a step with v = 0 (a circle) g is
   at round-off level and so is the change of the positions. */
#include "curve_flow_impl.h"

/* theta <- the edge angles theta_k of Sec. 5.2 */
static PetscErrorCode Angles(CSCurveFlow F)
{
  CSCurve            c = F->curve;
  const PetscScalar *k, *v, *d;
  PetscScalar       *t;
  PetscReal          theta0, local = 0, before = 0;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFirstEdgeAngle(c, F->x, &theta0));
  PetscCall(VecGetArrayRead(F->kappa, &k));
  PetscCall(VecGetArrayRead(F->v, &v));
  PetscCall(VecGetArrayRead(F->d, &d));
  PetscCall(VecGetArray(F->theta, &t));
  for (PetscInt i = 0; i < c->n; i++) {
    if (c->rstart + i > 0) local += d[i] * (k[i] + F->tau * v[i]); /* d_i kappa~_i, i >= 1 */
    t[i] = local;
  }
  PetscCallMPI(MPI_Exscan(&local, &before, 1, MPIU_REAL, MPIU_SUM, c->comm));
  if (!c->rstart) before = 0; /* MPI_Exscan leaves rank 0's result undefined */
  for (PetscInt i = 0; i < c->n; i++) t[i] += theta0 + before;
  PetscCall(VecRestoreArray(F->theta, &t));
  PetscCall(VecRestoreArrayRead(F->d, &d));
  PetscCall(VecRestoreArrayRead(F->v, &v));
  PetscCall(VecRestoreArrayRead(F->kappa, &k));
  PetscFunctionReturn(0);
}

/* w <- g_k = (cos theta_k, sin theta_k) - (f_{k+1} - f_k)/l_k; the gap |sum_k T~_k| / length */
static PetscErrorCode EdgeResiduals(CSCurveFlow F)
{
  CSCurve            c = F->curve;
  const PetscScalar *a, *t, *l;
  PetscScalar       *g;
  PetscReal          lr[4], sum[2] = {0, 0}, S[2];
  PetscFunctionBeginUser;
  PetscCall(CSCurveGhosts(c, F->x, lr));
  PetscCall(VecGetArrayRead(F->x, &a));
  PetscCall(VecGetArrayRead(F->theta, &t));
  PetscCall(VecGetArrayRead(F->len, &l));
  PetscCall(VecGetArray(F->w, &g));
  for (PetscInt i = 0; i < c->n; i++) {
    const PetscReal *q = i + 1 < c->n ? a + 2 * i + 2 : lr + 2;
    PetscReal        u[2] = {PetscCosReal(t[i]), PetscSinReal(t[i])};
    if (l[i] == 0) { /* the end of an open curve: no edge */
      g[2 * i] = g[2 * i + 1] = 0;
      continue;
    }
    for (int k = 0; k < 2; k++) {
      g[2 * i + k] = u[k] - (q[k] - a[2 * i + k]) / l[i];
      sum[k] += l[i] * u[k];
    }
  }
  PetscCall(VecRestoreArray(F->w, &g));
  PetscCall(VecRestoreArrayRead(F->len, &l));
  PetscCall(VecRestoreArrayRead(F->theta, &t));
  PetscCall(VecRestoreArrayRead(F->x, &a));
  PetscCallMPI(MPI_Allreduce(sum, S, 2, MPIU_REAL, MPIU_SUM, c->comm));
  F->s.gap = c->closed ? PetscSqrtReal(S[0] * S[0] + S[1] * S[1]) / F->length : 0;
  PetscFunctionReturn(0);
}

/* rhs[k]_i = g_{i-1,k} - g_{i,k} (g_{-1} = 0 at the start of an open curve) */
static PetscErrorCode RightHandSides(CSCurveFlow F)
{
  CSCurve            c = F->curve;
  const PetscScalar *g;
  PetscScalar       *r[2];
  PetscReal          lr[4];
  PetscFunctionBeginUser;
  PetscCall(CSCurveGhosts(c, F->w, lr));
  PetscCall(VecGetArrayRead(F->w, &g));
  for (int k = 0; k < 2; k++) PetscCall(VecGetArray(F->rhs[k], &r[k]));
  for (PetscInt i = 0; i < c->n; i++)
    for (int k = 0; k < 2; k++) r[k][i] = (i ? g[2 * (i - 1) + k] : lr[k]) - g[2 * i + k];
  for (int k = 0; k < 2; k++) PetscCall(VecRestoreArray(F->rhs[k], &r[k]));
  PetscCall(VecRestoreArrayRead(F->w, &g));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowIntegrate(CSCurveFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(Angles(F));
  PetscCall(EdgeResiduals(F));
  PetscCall(RightHandSides(F));
  PetscFunctionReturn(0);
}
