/* A spin transformation through the library API alone (crane2011), no bin/confsurf, exactly as docs/DESIGN.md
   shows it: generate a mesh, CSSpinCreate, SetOptionsPrefix, MonitorSet, SetFromOptions, CSSpinSolve (the
   eigenproblem of Eq. 7 with rho = 0, the global similarity, Eq. 8 + Poisson, the area), GetSolution, Destroy.
   With rho = 0 the constant quaternions are an exact kernel of the Dirac operator on every closed mesh (the
   edges of each face sum to zero), so the smallest eigenvalue is 0 and the reconstructed mesh is the input up
   to a similarity: after the global similarity (best rotation to 1, unit mean |lambda|^2) and the area it must
   equal the input. Checked on the round icosphere, on a randomly perturbed one (no symmetry to help) and on a
   torus; a second solve on one object (factor once, solve many); the object's options prefix; and the
   sphere's known spectrum (Fig. 8). Exit status = number of failures.
   Run: build/tests/test_spin_api   (also under mpirun -n 2) */
#include <slepcsys.h>
#include "cs_methods_spin.h"
#include "cs_geometry.h"
#include "cs_test.h"

typedef enum {
  SURF_ICOSPHERE,
  SURF_TORUS
} Surface;

static PetscErrorCode MakeMesh(MPI_Comm comm, Surface s, PetscReal noise, CSMesh *mesh)
{
  CSMeshData  md;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&md, sizeof(md)));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank && s == SURF_ICOSPHERE) PetscCall(CSMeshDataIcosphere(3, 1.0, PETSC_TRUE, &md));
  if (!rank && s == SURF_TORUS) PetscCall(CSMeshDataTorus(1.0, 0.4, 24, 12, &md));
  PetscCall(CSTestDistribute(comm, &md, noise, 20111, mesh));
  PetscFunctionReturn(0);
}

static PetscErrorCode CountSolves(CSSpin spin, void *ctx)
{
  PetscFunctionBeginUser;
  (*(PetscInt *)ctx)++;
  PetscFunctionReturn(0);
}

/* rho = 0: a spin transformation through the object exactly as docs/DESIGN.md shows it (eigenpair, similarity,
   reconstruction, area); returns gamma, max |xnew - x| / sqrt(area) and the monitor's count of solves. */
static PetscErrorCode Transform(CSMesh mesh, PetscReal *gamma, PetscReal *dist, PetscInt *nsolves)
{
  CSSpin    spin;
  Vec       xnew, d;
  PetscReal area, vol;
  PetscFunctionBeginUser;
  *nsolves = 0;
  PetscCall(CSSpinCreate(mesh, &spin));
  PetscCall(CSSpinSetOptionsPrefix(spin, "spin_")); /* the default */
  PetscCall(CSSpinSetRhoLocation(spin, CS_RHO_VERTEX)); /* where a rho would live; rho = NULL here */
  PetscCall(CSSpinMonitorSet(spin, CountSolves, nsolves, NULL));
  PetscCall(CSSpinSetFromOptions(spin));
  PetscCall(CSSpinSolve(spin, mesh->x, NULL));
  PetscCall(CSSpinGetSolution(spin, &xnew));
  PetscCall(CSSpinGetEigenvalue(spin, gamma, NULL));
  PetscCall(VecDuplicate(xnew, &d));
  PetscCall(VecWAXPY(d, -1, mesh->x, xnew));
  PetscCall(VecNorm(d, NORM_INFINITY, dist));
  PetscCall(CSGeometryAreaVolume(mesh, mesh->x, &area, &vol));
  *dist /= PetscSqrtReal(area);
  PetscCall(VecDestroy(&d));
  PetscCall(CSSpinDestroy(&spin));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckSurface(MPI_Comm comm, const char name[], Surface s, PetscReal noise)
{
  CSMesh    mesh;
  PetscReal gamma = PETSC_MAX_REAL, dist = PETSC_MAX_REAL;
  PetscInt  nsolves = 0;
  char      what[128];
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, s, noise, &mesh));
  PetscCall(Transform(mesh, &gamma, &dist, &nsolves));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: the monitor is called once per CSSpinSolve", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(nsolves == 1), what, (PetscReal)nsolves, 1));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: smallest eigenvalue of Eq. 7 with rho = 0 is 0", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(gamma) <= 1e-8), what, PetscAbsReal(gamma), 1e-8));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: reconstruction = input, max |x' - x| / sqrt(area)", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(dist <= 1e-8), what, dist, 1e-8));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

/* Factor once, solve many: a second CSSpinSolve on one object (its operators rebuilt, its factorisations and
   start vector kept) gives the surface a fresh object gives for the same rho. A stale operator or start would
   leave an O(h) difference. */
static PetscErrorCode CheckSolveMany(MPI_Comm comm)
{
  CSMesh    mesh;
  CSSpin    a, b;
  Vec       rho, xa, xb, d;
  PetscReal dist, area, vol, ga, gb;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, SURF_ICOSPHERE, 0, &mesh));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &rho));
  PetscCall(CSSpinCreate(mesh, &a));
  PetscCall(CSSpinCreate(mesh, &b));
  PetscCall(CSSpinSetRhoLocation(a, CS_RHO_VERTEX));
  PetscCall(CSSpinSetRhoLocation(b, CS_RHO_VERTEX));
  PetscCall(CSSpinSetFromOptions(a));
  PetscCall(CSSpinSetFromOptions(b));
  PetscCall(CSTestVertexField(mesh, CSTestBump, 1, rho));
  PetscCall(CSSpinSolve(a, mesh->x, rho));
  PetscCall(CSTestVertexField(mesh, CSTestBump, 2, rho));
  PetscCall(CSSpinSolve(a, mesh->x, rho));
  PetscCall(CSSpinSolve(b, mesh->x, rho));
  PetscCall(CSSpinGetSolution(a, &xa));
  PetscCall(CSSpinGetSolution(b, &xb));
  PetscCall(CSSpinGetEigenvalue(a, &ga, NULL));
  PetscCall(CSSpinGetEigenvalue(b, &gb, NULL));
  PetscCall(VecDuplicate(xa, &d));
  PetscCall(VecWAXPY(d, -1, xb, xa));
  PetscCall(VecNorm(d, NORM_INFINITY, &dist));
  PetscCall(CSGeometryAreaVolume(mesh, mesh->x, &area, &vol));
  PetscCall(CSTestCheck(comm, (PetscBool)(dist / PetscSqrtReal(area) <= 1e-6), "second CSSpinSolve on one object = a fresh object's, max |x_a - x_b| / sqrt(area)", dist / PetscSqrtReal(area), 1e-6));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(ga - gb) <= 1e-6 * PetscAbsReal(gb)), "second CSSpinSolve on one object = a fresh object's, |gamma_a - gamma_b|", PetscAbsReal(ga - gb), 1e-6 * PetscAbsReal(gb)));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&rho));
  PetscCall(CSSpinDestroy(&a));
  PetscCall(CSSpinDestroy(&b));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

/* The object reads its options with its own prefix: -myspin_solver inverse -myspin_iterations 3 reach an object
   with prefix myspin_ and not one with the default spin_. */
static PetscErrorCode CheckPrefix(MPI_Comm comm)
{
  CSMesh      mesh;
  CSSpin      a, b;
  PetscBool   inva, invb;
  PetscInt    itsa, itsb;
  const char *prefix;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, SURF_ICOSPHERE, 0, &mesh));
  PetscCall(PetscOptionsSetValue(NULL, "-myspin_solver", "inverse"));
  PetscCall(PetscOptionsSetValue(NULL, "-myspin_iterations", "3"));
  PetscCall(CSSpinCreate(mesh, &a));
  PetscCall(CSSpinCreate(mesh, &b));
  PetscCall(CSSpinSetOptionsPrefix(a, "myspin_"));
  PetscCall(CSSpinGetOptionsPrefix(a, &prefix));
  PetscCall(CSTestCheck(comm, (PetscBool)!strcmp(prefix, "myspin_"), "CSSpinGetOptionsPrefix returns the prefix set", 0, 0));
  PetscCall(CSSpinSetFromOptions(a));
  PetscCall(CSSpinSetFromOptions(b));
  PetscCall(CSSpinGetInverseIteration(a, &inva, &itsa));
  PetscCall(CSSpinGetInverseIteration(b, &invb, &itsb));
  PetscCall(CSTestCheck(comm, (PetscBool)(inva && itsa == 3), "prefix myspin_: -myspin_solver inverse -myspin_iterations 3 read", (PetscReal)itsa, 3));
  PetscCall(CSTestCheck(comm, (PetscBool)(!invb && itsb == 1), "prefix spin_: the myspin_ options not read", (PetscReal)itsb, 1));
  PetscCall(PetscOptionsClearValue(NULL, "-myspin_solver"));
  PetscCall(PetscOptionsClearValue(NULL, "-myspin_iterations"));
  PetscCall(CSSpinDestroy(&a));
  PetscCall(CSSpinDestroy(&b));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

/* The known Dirac spectrum of the round unit sphere (crane2011 Fig. 8): sqrt of the eigenvalues of Eq. 7 with
   rho = 0 are 0 (4 times: the quaternionic constants) and then 1 (8 times); 4e-6 off at level 3. */
static PetscErrorCode CheckSphereSpectrum(MPI_Comm comm)
{
  CSMesh    mesh;
  CSSpin    spin;
  PetscInt  nconv;
  PetscReal eig[12], e0 = 0, e1 = 0;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, SURF_ICOSPHERE, 0, &mesh));
  PetscCall(CSSpinCreate(mesh, &spin));
  PetscCall(CSSpinSetFromOptions(spin));
  PetscCall(CSSpinSpectrum(spin, mesh->x, CS_RHO_NONE, NULL, 12, eig, &nconv));
  for (PetscInt i = 0; i < 4; i++) e0 = PetscMax(e0, PetscAbsReal(eig[i]));
  for (PetscInt i = 4; i < 12; i++) e1 = PetscMax(e1, PetscAbsReal(PetscSqrtReal(PetscMax(eig[i], 0)) - 1));
  PetscCall(CSTestCheck(comm, (PetscBool)(e0 <= 1e-8), "unit sphere spectrum: eigenvalues 1-4 are 0", e0, 1e-8));
  PetscCall(CSTestCheck(comm, (PetscBool)(e1 <= 1e-4), "unit sphere spectrum: sqrt of eigenvalues 5-12 are 1", e1, 1e-4));
  PetscCall(CSSpinDestroy(&spin));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm comm;
  PetscCall(SlepcInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CheckSurface(comm, "icosphere level 3", SURF_ICOSPHERE, 0));
  PetscCall(CheckSurface(comm, "perturbed icosphere", SURF_ICOSPHERE, 0.02));
  PetscCall(CheckSurface(comm, "torus 24 x 12", SURF_TORUS, 0));
  PetscCall(CheckSolveMany(comm));
  PetscCall(CheckPrefix(comm));
  PetscCall(CheckSphereSpectrum(comm));
  return CSTestFinalize(comm, SlepcFinalize);
}
