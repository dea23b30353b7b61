/* Repeated solves with one CSSpin (the pattern of a flow, crane2013 Sec. 6.4.2): a second rho after a first
   one, with (a) EPS reusing its objects and (b) inverse iteration keeping the first factorisation as the
   preconditioner of the new operator (-spin_keep_inverse_factor) and starting from the previous eigenvector.
   Both must give the eigenvalue of a fresh solve. Exit status = number of failures.
   Run: build/tests/test_spin_reuse   (also under mpirun -n 2) */
#include <slepcsys.h>
#include "cs_methods_spin.h"
#include "cs_test.h"

static PetscInt nfail = 0;

/* gamma for rho = h1 bump then h2 bump with one CSSpin configured by the given options */
static PetscErrorCode TwoSolves(CSMesh mesh, const char opts[], PetscReal h1, PetscReal h2, PetscReal *g2)
{
  CSSpin spin;
  Vec    rho, lambda;
  DM     dm;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsInsertString(NULL, opts));
  PetscCall(CSSpinCreate(mesh, &spin));
  PetscCall(CSSpinSetFromOptions(spin));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &rho));
  PetscCall(CSSpinGetDM(spin, &dm));
  PetscCall(DMCreateGlobalVector(dm, &lambda));
  if (h1 != 0) {
    PetscCall(CSTestVertexField(mesh, CSTestBump, h1, rho));
    PetscCall(CSSpinSolveEigen(spin, mesh->x, CS_RHO_VERTEX, rho, lambda));
  }
  PetscCall(CSTestVertexField(mesh, CSTestBump, h2, rho));
  PetscCall(CSSpinSolveEigen(spin, mesh->x, CS_RHO_VERTEX, rho, lambda));
  PetscCall(CSSpinGetEigenvalue(spin, g2, NULL));
  PetscCall(VecDestroy(&rho));
  PetscCall(VecDestroy(&lambda));
  PetscCall(CSSpinDestroy(&spin));
  PetscCall(PetscOptionsClearValue(NULL, "-spin_solver"));
  PetscCall(PetscOptionsClearValue(NULL, "-spin_iterations"));
  PetscCall(PetscOptionsClearValue(NULL, "-spin_keep_inverse_factor"));
  PetscFunctionReturn(0);
}

static PetscErrorCode Check(MPI_Comm comm, const char what[], PetscReal a, PetscReal b, PetscReal tol)
{
  PetscReal err = PetscAbsReal(a - b) / PetscMax(PetscAbsReal(b), PETSC_SMALL);
  PetscFunctionBeginUser;
  if (!(err <= tol)) nfail++;
  PetscCall(PetscPrintf(comm, "%s %-58s %.12g vs %.12g (rel %.2e, tol %.0e)\n", err <= tol ? "ok  " : "BAD ", what, (double)a, (double)b, (double)err, (double)tol));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  CSMesh    mesh;
  PetscReal fresh, eps2, inv2;
  MPI_Comm  comm;
  PetscCall(SlepcInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(PetscOptionsSetValue(NULL, "-gen", "icosphere"));
  PetscCall(PetscOptionsSetValue(NULL, "-gen_level", "3"));
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  PetscCall(TwoSolves(mesh, "", 0, 2.2, &fresh));
  PetscCall(TwoSolves(mesh, "", 2.0, 2.2, &eps2));
  PetscCall(Check(comm, "EPS, second solve with the same objects", eps2, fresh, 1e-9));
  PetscCall(TwoSolves(mesh, "-spin_solver inverse -spin_iterations 4 -spin_keep_inverse_factor", 2.0, 2.2, &inv2));
  PetscCall(Check(comm, "inverse iteration with the kept factorisation", inv2, fresh, 1e-6));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(PetscPrintf(comm, "%" PetscInt_FMT " failure(s)\n", nfail));
  PetscCall(SlepcFinalize());
  return (int)nfail;
}
