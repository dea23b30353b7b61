/* Interpolation between a surface and a deformation of it through their similarity fields (crane2011 Sec. 7.2,
   Fig. 21: "a tradeoff between approximation quality and conformality by interpolating between mu and lambda").
   The field of best-fit similarities mu (Sec. 7.2) is interpolated from the identity geometrically per vertex,
     lambda_t = exp(t log mu) = |mu|^t (cos(t phi) + u sin(t phi))     (mu = |mu| (cos phi + u sin phi)),
   i.e. the scale and the rotation angle of each similarity interpolated log-linearly, and each lambda_t gives a
   surface by Eq. 8 and the Poisson step. The reconstruction residuals of the two ends (r_0 = x - R(1), r_1 = xt -
   R(mu); R(1) = x up to rounding) are blended linearly, so that t = 0 and t = 1 give x and xt exactly:
     f_t = R(lambda_t) + (1 - t) r_0 + t r_1. */
#include "spin_impl.h"

/* lt = exp(t log mu) per vertex */
static PetscErrorCode PowerSimilarity(Vec mu, PetscReal t, Vec lt)
{
  const PetscScalar *m;
  PetscScalar       *l;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(mu, &n));
  PetscCall(VecGetArrayRead(mu, &m));
  PetscCall(VecGetArray(lt, &l));
  for (PetscInt i = 0; i < n / 4; i++) {
    PetscReal q[4], nq, nv, phi, s;
    for (int c = 0; c < 4; c++) q[c] = PetscRealPart(m[4 * i + c]);
    nv  = PetscSqrtReal(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
    nq  = PetscSqrtReal(q[0] * q[0] + nv * nv);
    phi = PetscAtan2Real(nv, q[0]);
    s   = PetscPowReal(nq, t);
    PetscCheck(nq > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "spin interpolation: a zero similarity (a face collapsed in the target)");
    l[4 * i] = s * PetscCosReal(t * phi);
    for (int c = 1; c < 4; c++) l[4 * i + c] = nv > 0 ? s * PetscSinReal(t * phi) * q[c] / nv : 0;
  }
  PetscCall(VecRestoreArray(lt, &l));
  PetscCall(VecRestoreArrayRead(mu, &m));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinInterpolateSetUp(CSSpin s, Vec x, Vec xt, Vec mu, Vec r0, Vec r1)
{
  Vec one, y;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(mu, &one));
  PetscCall(VecDuplicate(x, &y));
  PetscCall(PowerSimilarity(mu, 0, one)); /* the identity */
  PetscCall(CSSpinReconstruct(s, x, one, x, y));
  PetscCall(VecWAXPY(r0, -1, y, x));
  PetscCall(CSSpinReconstruct(s, x, mu, x, y));
  PetscCall(VecWAXPY(r1, -1, y, xt));
  PetscCall(VecDestroy(&one));
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinInterpolate(CSSpin s, Vec x, Vec mu, Vec r0, Vec r1, PetscReal t, Vec xs)
{
  Vec lt;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(mu, &lt));
  PetscCall(PowerSimilarity(mu, t, lt));
  PetscCall(CSSpinReconstruct(s, x, lt, x, xs));
  PetscCall(VecAXPBYPCZ(xs, 1 - t, t, 1, r0, r1));
  PetscCall(VecDestroy(&lt));
  PetscFunctionReturn(0);
}
