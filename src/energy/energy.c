/* The energy interface and a finite-difference check every energy must pass. */
#include "cs_energy.h"

PetscErrorCode CSEnergyCreateShell(CSMesh mesh, const char name[], CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(PetscNew(e));
  (*e)->mesh = mesh;
  PetscCall(PetscStrncpy((*e)->name, name, sizeof((*e)->name)));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyValue(CSEnergy e, Vec x, PetscReal *E)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Energy, 0, 0, 0, 0));
  PetscCall(e->value(e, x, E));
  PetscCall(PetscLogEventEnd(CS_EVENT_Energy, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyGradient(CSEnergy e, Vec x, PetscReal *E, Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Gradient, 0, 0, 0, 0));
  PetscCall(e->gradient(e, x, E, g));
  PetscCall(PetscLogEventEnd(CS_EVENT_Gradient, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyDestroy(CSEnergy *e)
{
  PetscFunctionBeginUser;
  if (!*e) PetscFunctionReturn(0);
  if ((*e)->destroy) PetscCall((*e)->destroy(*e));
  PetscCall(PetscFree(*e));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergySetOptionsPrefix(CSEnergy e, const char prefix[])
{
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(e->prefix, prefix ? prefix : "", sizeof(e->prefix)));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergySetFromOptions(CSEnergy e)
{
  PetscFunctionBeginUser;
  if (e->setfromoptions) PetscCall((*e->setfromoptions)(e));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyMetric(CSEnergy e, CSMetric *m)
{
  PetscFunctionBeginUser;
  if (e->metric) PetscCall((*e->metric)(e, m));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyCheckGradient(CSEnergy e, Vec x, PetscReal h, PetscInt n, PetscReal *relerr)
{
  Vec         g, d, xp;
  PetscRandom rnd;
  PetscReal   worst = 0;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(x, &g));
  PetscCall(VecDuplicate(x, &d));
  PetscCall(VecDuplicate(x, &xp));
  PetscCall(CSEnergyGradient(e, x, NULL, g));
  PetscCall(PetscRandomCreate(e->mesh->comm, &rnd));
  PetscCall(PetscRandomSetInterval(rnd, -1, 1));
  PetscCall(PetscRandomSetSeed(rnd, 20210811));
  PetscCall(PetscRandomSeed(rnd));
  for (PetscInt k = 0; k < n; k++) {
    PetscReal   Ep, Em, fd, an;
    PetscScalar gd;
    PetscCall(VecSetRandom(d, rnd));
    PetscCall(VecDot(g, d, &gd));
    an = PetscRealPart(gd);
    PetscCall(VecWAXPY(xp, h, d, x));
    PetscCall(CSEnergyValue(e, xp, &Ep));
    PetscCall(VecWAXPY(xp, -h, d, x));
    PetscCall(CSEnergyValue(e, xp, &Em));
    fd    = (Ep - Em) / (2 * h);
    worst = PetscMax(worst, PetscAbsReal(fd - an) / PetscMax(PetscAbsReal(an), 1e-300));
  }
  *relerr = worst;
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&g));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&xp));
  PetscFunctionReturn(0);
}

/* Hessian-vector product by a central difference of the analytic gradient,
     H v ~ (g(x + e v) - g(x - e v)) / (2 e),   e = eps / max_i |v_i|  (eps: an absolute displacement),
   exact for quadratics and O(e^2) otherwise; rounding adds O(u |g| / e). eps ~ 1e-5 times the mean edge length
   balances the two for W (u^(1/3) relative: test_newton_hessian checks it against second differences of E).
   work: two vectors like x (NULL: allocated here). */
PetscErrorCode CSEnergyHessianMult(CSEnergy e, Vec x, Vec v, PetscReal eps, Vec work[2], Vec y)
{
  Vec       w[2] = {NULL, NULL};
  PetscReal vmax, s;
  PetscFunctionBeginUser;
  if (work) {
    w[0] = work[0];
    w[1] = work[1];
  } else {
    PetscCall(VecDuplicate(x, &w[0]));
    PetscCall(VecDuplicate(x, &w[1]));
  }
  PetscCall(VecNorm(v, NORM_INFINITY, &vmax));
  if (vmax == 0) {
    PetscCall(VecSet(y, 0));
  } else {
    s = eps / vmax;
    PetscCall(VecWAXPY(w[0], s, v, x));
    PetscCall(CSEnergyGradient(e, w[0], NULL, y));
    PetscCall(VecWAXPY(w[0], -s, v, x));
    PetscCall(CSEnergyGradient(e, w[0], NULL, w[1]));
    PetscCall(VecAXPY(y, -1.0, w[1]));
    PetscCall(VecScale(y, 1.0 / (2 * s)));
  }
  if (!work) {
    PetscCall(VecDestroy(&w[0]));
    PetscCall(VecDestroy(&w[1]));
  }
  PetscFunctionReturn(0);
}
