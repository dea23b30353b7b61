/* Willmore-regularised fairing energy (soliman2021 Eq. 21). */
#include "cs_constraints.h"
#include "cs_util.h"

typedef struct {
  CSEnergy  W;
  Vec       x0, m0, d; /* input positions, their mass *0(f0) per component, work */
  PetscReal eps;
} FairingCtx;

/* E = 1/2 sum_i A_i(f0) |f_i - f0_i|^2 + eps W(f). Eq. 21 leaves open which mass defines ||.||_L2; we take
   the input mesh's, so the fidelity term is a fixed quadratic with gradient *0(f0) (f - f0). */
static PetscErrorCode FairingGradient(CSEnergy e, Vec x, PetscReal *E, Vec g)
{
  FairingCtx *c = (FairingCtx *)e->ctx;
  PetscReal   W;
  PetscScalar q;
  PetscFunctionBeginUser;
  if (g) PetscCall(CSEnergyGradient(c->W, x, &W, g));
  else PetscCall(CSEnergyValue(c->W, x, &W));
  PetscCall(VecWAXPY(c->d, -1.0, c->x0, x));
  PetscCall(VecPointwiseMult(c->d, c->m0, c->d));
  if (E) {
    Vec diff;
    PetscCall(VecDuplicate(x, &diff));
    PetscCall(VecWAXPY(diff, -1.0, c->x0, x));
    PetscCall(VecDot(c->d, diff, &q));
    PetscCall(VecDestroy(&diff));
    *E = 0.5 * PetscRealPart(q) + c->eps * W;
  }
  if (g) {
    PetscCall(VecScale(g, c->eps));
    PetscCall(VecAXPY(g, 1.0, c->d));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode FairingValue(CSEnergy e, Vec x, PetscReal *E)
{
  PetscFunctionBeginUser;
  PetscCall(FairingGradient(e, x, E, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode FairingDestroy(CSEnergy e)
{
  FairingCtx *c = (FairingCtx *)e->ctx;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyDestroy(&c->W));
  PetscCall(VecDestroy(&c->x0));
  PetscCall(VecDestroy(&c->m0));
  PetscCall(VecDestroy(&c->d));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

/* -<prefix>epsilon (a flow's: -flow_fairing_epsilon), the weight of W. */
static PetscErrorCode FairingSetFromOptions(CSEnergy e)
{
  FairingCtx *c = (FairingCtx *)e->ctx;
  PetscFunctionBeginUser;
  PetscOptionsBegin(e->mesh->comm, e->prefix, "Fairing energy (soliman2021 Eq. 21)", NULL);
  PetscCall(CSOptionsReal("-epsilon", "Weight of W in the fairing energy (soliman2021 Eq. 21)", NULL, c->eps, &c->eps, NULL));
  PetscOptionsEnd();
  {
    const CSOptionCheck check[] = {{"epsilon", c->eps, c->eps > 0, "must be > 0"}};
    PetscCall(CSCheckOptionValues(e->mesh->comm, e->prefix, 1, check));
  }
  PetscFunctionReturn(0);
}

/* The fidelity term is a fixed quadratic with Hessian *0, which the metric of W alone (w *0 + L *0^{-1} L,
   w = 1/s^4) does not see: along the low modes (translations, scalings) the step was t/w times the fidelity
   gradient, 300 t on the low-res bunny, and the flow oscillated (the volume 194 -> 198 -> 191 -> 197 in the first
   steps at eps 0.1) and then drifted (60 iterations: E 13.6 -> 1.6e7). The metric of the sum,
   eps (w *0 + L *0^{-1} L) + *0 = eps ((w + 1/eps) *0 + L *0^{-1} L), is a Newton step on the fidelity and the W
   metric on the rest (with the current mass *0(f) for *0(f0)). */
static PetscErrorCode FairingMetric(CSEnergy e, CSMetric *m)
{
  FairingCtx *c = (FairingCtx *)e->ctx;
  PetscFunctionBeginUser;
  m->scale = c->eps;
  m->mass_weight += 1.0 / c->eps;
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyCreateFairing(CSMesh mesh, Vec x0, PetscReal eps, CSEnergy *e)
{
  FairingCtx        *c;
  Vec                a;
  const PetscScalar *aa;
  PetscScalar       *m;
  PetscInt           n;
  PetscFunctionBeginUser;
  /* the argument, not an option: the energy has no prefix yet (its option -<prefix>epsilon is checked in its SetFromOptions) */
  PetscCheck(eps > 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "CSEnergyCreateFairing: eps %g, the weight of W (soliman2021 Eq. 21), must be > 0", (double)eps);
  PetscCall(CSEnergyCreateShell(mesh, "fairing", e));
  PetscCall(PetscNew(&c));
  c->eps = eps;
  PetscCall(CSEnergyCreateWillmore(mesh, &c->W));
  PetscCall(VecDuplicate(x0, &c->x0));
  PetscCall(VecCopy(x0, c->x0));
  PetscCall(VecDuplicate(x0, &c->m0));
  PetscCall(VecDuplicate(x0, &c->d));
  PetscCall(DMGetGlobalVector(mesh->dmV1, &a));
  PetscCall(CSOperatorMass(mesh, x0, a));
  PetscCall(VecGetLocalSize(a, &n));
  PetscCall(VecGetArrayRead(a, &aa));
  PetscCall(VecGetArray(c->m0, &m));
  for (PetscInt i = 0; i < n; i++)
    for (int d = 0; d < 3; d++) m[3 * i + d] = aa[i];
  PetscCall(VecRestoreArray(c->m0, &m));
  PetscCall(VecRestoreArrayRead(a, &aa));
  PetscCall(DMRestoreGlobalVector(mesh->dmV1, &a));
  (*e)->ctx      = c;
  (*e)->value    = FairingValue;
  (*e)->gradient = FairingGradient;
  (*e)->destroy  = FairingDestroy;
  (*e)->setfromoptions = FairingSetFromOptions;
  (*e)->metric         = FairingMetric;
  PetscFunctionReturn(0);
}
