/* The Hessian-vector product of W used by -flow_type newton (CSEnergyHessianMult: central difference of the
   analytic gradient, src/energy/energy.c) against finite differences of the energy alone:
     w^T H v  vs  (W(x+hv+hw) - W(x+hv-hw) - W(x-hv+hw) + W(x-hv-hw)) / (4 h^2)   (mixed second difference),
   its symmetry w^T H v = v^T H w, and H x = -g. Scale invariance: W(s x) = W(x) gives g(s x) s = g(x), differentiated in s at 1: H x + g = 0, i.e. H x = -g. */
#include "cs_energy.h"
#include "cs_test.h"

static PetscErrorCode MixedSecondDifference(CSEnergy e, Vec x, Vec v, Vec w, PetscReal h, PetscReal *d2)
{
  Vec       y;
  PetscReal s[4];
  const PetscReal a[4] = {1, 1, -1, -1}, b[4] = {1, -1, 1, -1};
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(x, &y));
  for (int k = 0; k < 4; k++) {
    PetscCall(VecCopy(x, y));
    PetscCall(VecAXPBYPCZ(y, a[k] * h, b[k] * h, 1.0, v, w));
    PetscCall(CSEnergyValue(e, y, &s[k]));
  }
  *d2 = (s[0] - s[1] - s[2] + s[3]) / (4 * h * h);
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckMesh(MPI_Comm comm, CSTestMeshSpec spec, const char *name)
{
  CSMesh      mesh;
  CSEnergy    e;
  Vec         v, w, Hv, Hw, g;
  PetscRandom rnd;
  PetscReal   h, worst = 0, sym, d2 = 0, vHw, wHv, scale, err;
  PetscScalar dot;
  char        what[128];
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, spec, 0.02, 7, &mesh));
  PetscCall(CSEnergyCreateWillmore(mesh, &e));
  PetscCall(CSGeometryMeanEdgeLength(mesh, mesh->x, &h));
  PetscCall(VecDuplicate(mesh->x, &v));
  PetscCall(VecDuplicate(mesh->x, &w));
  PetscCall(VecDuplicate(mesh->x, &Hv));
  PetscCall(VecDuplicate(mesh->x, &Hw));
  PetscCall(VecDuplicate(mesh->x, &g));
  PetscCall(CSTestRandom(comm, -1, 1, 19, &rnd));
  for (int k = 0; k < 3; k++) {
    PetscCall(VecSetRandom(v, rnd));
    PetscCall(VecSetRandom(w, rnd));
    PetscCall(CSEnergyHessianMult(e, mesh->x, v, 1e-5 * h, NULL, Hv));
    PetscCall(CSEnergyHessianMult(e, mesh->x, w, 1e-5 * h, NULL, Hw));
    PetscCall(VecDot(w, Hv, &dot));
    wHv = PetscRealPart(dot);
    PetscCall(VecDot(v, Hw, &dot));
    vHw = PetscRealPart(dot);
    /* step 2e-4 edge lengths: truncation O(h^2) (1.6e-4 relative at 1e-3 on the torus, 6e-6 here) above rounding */
    PetscCall(MixedSecondDifference(e, mesh->x, v, w, 2e-4 * h, &d2));
    scale = PetscMax(PetscAbsReal(d2), 1e-8);
    worst = PetscMax(worst, PetscAbsReal(wHv - d2) / scale);
    sym   = PetscAbsReal(wHv - vHw) / scale;
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: symmetry |w^T H v - v^T H w| / |w^T H v| (pair %d)", name, k));
    PetscCall(CSTestCheck(comm, (PetscBool)(sym < 1e-5), what, sym, 1e-5));
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: w^T H v against the mixed second difference of W, relative", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(worst < 1e-4), what, worst, 1e-4));
  /* H x = -g (scale invariance) */
  PetscCall(CSEnergyGradient(e, mesh->x, NULL, g));
  PetscCall(CSEnergyHessianMult(e, mesh->x, mesh->x, 1e-5 * h, NULL, Hv));
  PetscCall(VecAXPY(Hv, 1.0, g));
  PetscCall(VecNorm(Hv, NORM_2, &err));
  PetscCall(VecNorm(g, NORM_2, &scale));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: |H x + g| / |g| (W is scale invariant)", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(err / scale < 1e-6), what, err / scale, 1e-6));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&Hv));
  PetscCall(VecDestroy(&Hw));
  PetscCall(VecDestroy(&g));
  PetscCall(CSEnergyDestroy(&e));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  CSTestMeshSpec ico   = {CS_TEST_ICOSPHERE, 2, 0, 0, 0};
  CSTestMeshSpec torus = {CS_TEST_TORUS, 24, 12, 3, 1};
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  PetscCall(CheckMesh(PETSC_COMM_WORLD, ico, "icosphere 2 (noisy)"));
  PetscCall(CheckMesh(PETSC_COMM_WORLD, torus, "torus 24x12 R=3 r=1 (noisy)"));
  return CSTestFinalize(PETSC_COMM_WORLD, PetscFinalize);
}
