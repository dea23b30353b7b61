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
