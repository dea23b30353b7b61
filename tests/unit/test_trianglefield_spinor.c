/* Unit checks of the spinor variables of the triangle-field flow (-flow_type trianglefield -flow_variables spinor,
   soliman2021 App. C.2/C.3; src/methods/willmore/impls/trianglefield/trianglefield_spinor.c), serial and under mpirun, on the 6 x 6
   square lattice (tau = i) from a random start (random unit psi, uniform u), moved to a random u (|u| <= 0.1):
   - the energy W~(S_c(u, psi)) + w E_tau(psi) (w = 0.5) has the gradient J^T grad W~ + w grad E_tau: directional
     derivatives along random directions (u and psi parts together, and psi alone, and u alone) against central
     differences, relative error <= 1e-6 (the chain rule through the assembled Jacobian dS_c, its chart
     derivatives in u and the quaternion sandwich in psi).
   Prints a line per check; exit status = number of failures. */
#include "cs_methods_willmore.h"
#include "cs_energy.h"
#include "cs_package.h"
#include "cs_test.h"

/* relative |<g, dir> - (E(x + h dir) - E(x - h dir)) / 2h| */
static PetscErrorCode FDCheck(CSEnergy e, Vec x, Vec dir, PetscReal *err)
{
  Vec         g, xp;
  PetscReal   E0, Ep, Em, h = 1e-6, fd;
  PetscScalar d;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(x, &g));
  PetscCall(VecDuplicate(x, &xp));
  PetscCall(CSEnergyGradient(e, x, &E0, g));
  PetscCall(VecDot(g, dir, &d));
  PetscCall(VecWAXPY(xp, h, dir, x));
  PetscCall(CSEnergyValue(e, xp, &Ep));
  PetscCall(VecWAXPY(xp, -h, dir, x));
  PetscCall(CSEnergyValue(e, xp, &Em));
  fd   = (Ep - Em) / (2 * h);
  *err = PetscAbsReal(fd - PetscRealPart(d)) / PetscMax(PetscAbsReal(fd), 1e-8);
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)x), "  E %.10g  <g, dir> %.12g  central difference %.12g\n", (double)E0, (double)PetscRealPart(d), (double)fd));
  PetscCall(VecDestroy(&g));
  PetscCall(VecDestroy(&xp));
  PetscFunctionReturn(0);
}

/* dir restricted to its first n (mask 1), its rest (mask 2) or everything (0), per rank; n = the u part */
static PetscErrorCode Mask(Vec dir, PetscInt n, int mask)
{
  PetscScalar *a;
  PetscInt     N;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(dir, &N));
  PetscCall(VecGetArray(dir, &a));
  for (PetscInt i = 0; i < N; i++)
    if ((mask == 1 && i >= n) || (mask == 2 && i < n)) a[i] = 0;
  PetscCall(VecRestoreArray(dir, &a));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm       comm;
  CSMesh         m;
  CSWillmoreFlow flow;
  CSEnergy       e;
  Vec            x, dir, ug;
  PetscRandom    r;
  PetscInt       nu;
  const char    *what[3] = {"u and psi", "u only", "psi only"};
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CSInitializePackage());
  PetscCall(PetscOptionsInsertString(NULL, "-gen lattice -gen_tau 0,1 -gen_n 6 -gen_m 6 -flow_type trianglefield -flow_variables spinor -flow_init random -flow_seed 5 -flow_spin_weight 0.5"));
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &m));
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetFromOptions(flow));
  PetscCall(CSWillmoreFlowSetUp(flow));
  PetscCall(CSWillmoreFlowGetEnergy(flow, &e));
  PetscCall(CSWillmoreFlowGetVariables(flow, &x));
  PetscCall(DMCreateGlobalVector(m->dmV1, &ug));
  PetscCall(VecGetLocalSize(ug, &nu));
  PetscCall(VecDestroy(&ug));
  PetscCall(VecDuplicate(x, &dir));
  PetscCall(CSTestRandom(comm, -0.1, 0.1, 7, &r));
  PetscCall(VecSetRandom(dir, r));
  PetscCall(Mask(dir, nu, 1));
  PetscCall(VecAXPY(x, 1.0, dir)); /* a random conformal factor */
  for (int k = 0; k < 3; k++) {
    PetscReal err = 0;
    PetscCall(VecSetRandom(dir, r));
    PetscCall(Mask(dir, nu, k));
    PetscCall(FDCheck(e, x, dir, &err));
    {
      char msg[128];
      PetscCall(PetscSNPrintf(msg, sizeof(msg), "grad (W~ + w E_tau)(S_c(u, psi)) along %s vs central differences (relative)", what[k]));
      PetscCall(CSTestCheck(comm, (PetscBool)(err <= 1e-6), msg, err, 1e-6));
    }
  }
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(VecDestroy(&dir));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscCall(CSMeshDestroy(&m));
  return CSTestFinalize(comm, PetscFinalize);
}
