/* A spin transformation through the library API alone (crane2011), no bin/confsurf: generate a mesh, hand it
   to CSSpinCreate, solve the eigenproblem of Eq. 7 with rho = 0, fix the global similarity and reconstruct
   (Eq. 8 + Poisson). With rho = 0 the constant quaternions are an exact kernel of the Dirac operator on every
   closed mesh (the edges of each face sum to zero), so the smallest eigenvalue is 0 and the reconstructed
   mesh is the input up to a similarity: after CSSpinNormalize (best rotation to 1, unit mean |lambda|^2) and
   CSSpinRestoreArea it must equal the input. Checked on the round icosphere, on a randomly perturbed one (no
   symmetry to help) and on a torus; and the sphere's known spectrum (Fig. 8). Exit status = number of failures.
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

/* rho = 0: eigenpair, similarity, reconstruction; returns gamma and max |xnew - x| / sqrt(area). */
static PetscErrorCode Transform(CSMesh mesh, PetscReal *gamma, PetscReal *dist)
{
  CSSpin    spin;
  Vec       lambda, xnew;
  PetscReal area, vol;
  PetscFunctionBeginUser;
  PetscCall(CSSpinCreate(mesh, &spin));
  PetscCall(CSSpinSetFromOptions(spin));
  PetscCall(DMCreateGlobalVector(spin->dm, &lambda));
  PetscCall(CSSpinSolveEigen(spin, mesh->x, CS_RHO_NONE, NULL, lambda));
  PetscCall(CSSpinNormalize(spin, lambda, NULL, PETSC_TRUE));
  PetscCall(VecDuplicate(mesh->x, &xnew));
  PetscCall(CSSpinReconstruct(spin, mesh->x, lambda, mesh->x, xnew));
  PetscCall(CSSpinRestoreArea(spin, mesh->x, xnew));
  *gamma = spin->gamma;
  PetscCall(VecAXPY(xnew, -1, mesh->x));
  PetscCall(VecNorm(xnew, NORM_INFINITY, dist));
  PetscCall(CSGeometryAreaVolume(mesh, mesh->x, &area, &vol));
  *dist /= PetscSqrtReal(area);
  PetscCall(VecDestroy(&xnew));
  PetscCall(VecDestroy(&lambda));
  PetscCall(CSSpinDestroy(&spin));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckSurface(MPI_Comm comm, const char name[], Surface s, PetscReal noise)
{
  CSMesh    mesh;
  PetscReal gamma = PETSC_MAX_REAL, dist = PETSC_MAX_REAL;
  char      what[128];
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, s, noise, &mesh));
  PetscCall(Transform(mesh, &gamma, &dist));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: smallest eigenvalue of Eq. 7 with rho = 0 is 0", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(gamma) <= 1e-8), what, PetscAbsReal(gamma), 1e-8));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: reconstruction = input, max |x' - x| / sqrt(area)", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(dist <= 1e-8), what, dist, 1e-8));
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
  PetscCall(CheckSphereSpectrum(comm));
  return CSTestFinalize(comm, SlepcFinalize);
}
