static const char help[] = "Checks of the foundation layer: energy gradients against finite differences, Willmore energy\n"
                           "convergence (4 pi, 2 pi^2) and invariances, cotan Laplacian identities. Prints one line per\n"
                           "check; the exit status is the number of failed checks.\n";

#include "cs_energy.h"
#include "cs_geometry.h"
#include "cs_util.h"
#include "cs_test.h"
#include <petscksp.h>

typedef enum { GEN_ICOSPHERE, GEN_TORUS, GEN_CYLINDER, GEN_DISK } Gen;

static PetscErrorCode MakeMesh(MPI_Comm comm, Gen g, PetscInt a, PetscInt b, PetscReal R, PetscReal r, PetscReal amp, CSMesh *mesh)
{
  const CSTestShape shapes[] = {CS_TEST_ICOSPHERE, CS_TEST_TORUS, CS_TEST_CYLINDER, CS_TEST_DISK};
  CSTestMeshSpec    spec     = {shapes[g], a, b, R, r};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, spec, amp, 7, mesh));
  PetscFunctionReturn(0);
}

/* Gradients of W, area and volume against central differences (relative error <= 1e-6). */
static PetscErrorCode CheckGradients(MPI_Comm comm, CSMesh mesh, const char label[])
{
  PetscErrorCode (*create[3])(CSMesh, CSEnergy *) = {CSEnergyCreateWillmore, CSEnergyCreateArea, CSEnergyCreateVolume};
  PetscFunctionBeginUser;
  for (int k = 0; k < 3; k++) {
    CSEnergy  e;
    PetscReal err;
    char      what[128];
    PetscCall(create[k](mesh, &e));
    PetscCall(CSEnergyCheckGradient(e, mesh->x, 1e-6, 4, &err));
    PetscCall(PetscSNPrintf(what, sizeof(what), "FD gradient of %s on %s", e->name, label));
    PetscCall(CSTestCheck(comm, (PetscBool)(err <= 1e-6), what, err, 1e-6));
    PetscCall(CSEnergyDestroy(&e));
  }
  PetscFunctionReturn(0);
}

/* W under x -> s Q x + t must not change (Willmore energy is scale, rotation and translation invariant). */
static PetscErrorCode CheckInvariance(MPI_Comm comm, CSMesh mesh, const char label[])
{
  CSEnergy           e;
  Vec                y;
  PetscReal          W0, W1;
  const PetscReal    c = PetscCosReal(0.7), s = PetscSinReal(0.7), scale = 3.7, t[3] = {1.5, -2.0, 0.25};
  const PetscScalar *xa;
  PetscScalar       *ya;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateWillmore(mesh, &e));
  PetscCall(CSEnergyValue(e, mesh->x, &W0));
  PetscCall(VecDuplicate(mesh->x, &y));
  PetscCall(VecGetLocalSize(y, &n));
  PetscCall(VecGetArrayRead(mesh->x, &xa));
  PetscCall(VecGetArray(y, &ya));
  for (PetscInt i = 0; i < n / 3; i++) {
    const PetscScalar *p = xa + 3 * i;
    /* rotation about (1,1,1)/sqrt3 by Rodrigues, then scale and shift */
    PetscReal k[3] = {1 / PetscSqrtReal(3), 1 / PetscSqrtReal(3), 1 / PetscSqrtReal(3)}, kx[3], kp = k[0] * p[0] + k[1] * p[1] + k[2] * p[2];
    kx[0] = k[1] * p[2] - k[2] * p[1];
    kx[1] = k[2] * p[0] - k[0] * p[2];
    kx[2] = k[0] * p[1] - k[1] * p[0];
    for (int d = 0; d < 3; d++) ya[3 * i + d] = scale * (p[d] * c + kx[d] * s + k[d] * kp * (1 - c)) + t[d];
  }
  PetscCall(VecRestoreArray(y, &ya));
  PetscCall(VecRestoreArrayRead(mesh->x, &xa));
  PetscCall(CSEnergyValue(e, y, &W1));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W1 - W0) <= 1e-12 * W0), "W invariant under rotation+scale+translation (rel. diff)", PetscAbsReal(W1 - W0) / W0, 1e-12));
  PetscCall(VecDestroy(&y));
  PetscCall(CSEnergyDestroy(&e));
  PetscFunctionReturn(0);
}

/* L 1 = 0, L symmetric, u^T L u >= 0 for random u (the test meshes are Delaunay), 1/2 <Lf, f> = area. */
static PetscErrorCode CheckLaplacian(MPI_Comm comm, CSMesh mesh, const char label[])
{
  Mat         L, L3;
  Vec         one, y, f3, y3;
  PetscReal   nrm, area, minq = PETSC_MAX_REAL;
  PetscBool   sym;
  PetscScalar half;
  PetscRandom rnd;
  char        what[128];
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLaplacian(mesh, mesh->x, MAT_INITIAL_MATRIX, &L));
  PetscCall(MatCreateVecs(L, &one, &y));
  PetscCall(VecSet(one, 1));
  PetscCall(MatMult(L, one, y));
  PetscCall(VecNorm(y, NORM_INFINITY, &nrm));
  PetscCall(PetscSNPrintf(what, sizeof(what), "|L 1|_inf on %s", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(nrm <= 1e-12), what, nrm, 1e-12));
  PetscCall(MatIsSymmetric(L, 1e-14, &sym));
  PetscCall(PetscSNPrintf(what, sizeof(what), "L symmetric on %s", label));
  PetscCall(CSTestCheck(comm, sym, what, sym ? 0 : 1, 0));
  PetscCall(PetscRandomCreate(comm, &rnd));
  PetscCall(PetscRandomSetFromOptions(rnd));
  for (int k = 0; k < 10; k++) {
    PetscScalar q, uu;
    PetscCall(VecSetRandom(one, rnd));
    PetscCall(MatMult(L, one, y));
    PetscCall(VecDot(one, y, &q));
    PetscCall(VecDot(one, one, &uu));
    minq = PetscMin(minq, PetscRealPart(q / uu));
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "min u^T L u / u^T u >= 0 (random u) on %s", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(minq >= 0), what, minq, 0));
  PetscCall(CSOperatorLaplacian3(mesh, mesh->x, MAT_INITIAL_MATRIX, &L3));
  PetscCall(MatCreateVecs(L3, &f3, &y3));
  PetscCall(VecCopy(mesh->x, f3));
  PetscCall(MatMult(L3, f3, y3));
  PetscCall(VecDot(y3, f3, &half));
  half *= 0.5;
  PetscCall(CSGeometryAreaVolume(mesh, mesh->x, &area, NULL));
  PetscCall(PetscSNPrintf(what, sizeof(what), "1/2 <Lf,f> = area on %s (rel. diff)", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(PetscRealPart(half) - area) <= 1e-12 * area), what, PetscAbsReal(PetscRealPart(half) - area) / area, 1e-12));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&one));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&f3));
  PetscCall(VecDestroy(&y3));
  PetscCall(MatDestroy(&L));
  PetscCall(MatDestroy(&L3));
  PetscFunctionReturn(0);
}

/* W -> 4 pi on refined icospheres and W -> 2 pi^2 on refined tori with R = sqrt 2, r = 1: the error must
   fall monotonically at second order (ratio ~4 per halving of h), and the Richardson extrapolation of the last
   two levels, W + (W - W_prev)/3, must match the exact value. */
static PetscErrorCode CheckSequence(MPI_Comm comm, Gen g, const char label[], PetscReal exact, PetscReal tol)
{
  PetscReal W = 0, Wprev = 0, err = 0, prev = PETSC_MAX_REAL, ratio = 0, rich;
  PetscBool mono = PETSC_TRUE;
  char      what[160];
  PetscFunctionBeginUser;
  for (PetscInt k = 0; k < 4; k++) {
    CSMesh   mesh;
    CSEnergy e;
    PetscInt n = 16 << k;
    if (g == GEN_ICOSPHERE) PetscCall(MakeMesh(comm, g, k + 2, 0, 0, 0, 0, &mesh));
    else PetscCall(MakeMesh(comm, g, n, n / 2, PetscSqrtReal(2), 1, 0, &mesh));
    PetscCall(CSEnergyCreateWillmore(mesh, &e));
    Wprev = W;
    PetscCall(CSEnergyValue(e, mesh->x, &W));
    err = PetscAbsReal(W - exact);
    PetscCall(PetscPrintf(comm, "     %s, %" PetscInt_FMT " faces: W = %.12f, |W - exact| = %.3e\n", label, mesh->Nf, (double)W, (double)err));
    if (err >= prev) mono = PETSC_FALSE;
    if (k) ratio = prev / err;
    prev = err;
    PetscCall(CSEnergyDestroy(&e));
    PetscCall(CSMeshDestroy(&mesh));
  }
  rich = W + (W - Wprev) / 3;
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: error falls monotonically at 2nd order (last ratio)", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(mono && ratio > 3.5 && ratio < 4.5), what, ratio, 4));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: Richardson-extrapolated W matches exact (rel. error)", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(rich - exact) <= tol * exact), what, PetscAbsReal(rich - exact) / exact, tol));
  PetscFunctionReturn(0);
}

/* Folds against smooth rotations (the fold guard of issue #19): mirroring the upper half of a torus (z -> -z for
   z > 0) folds it back onto the lower half, a crease of ~180 degrees along both equators (two rings of n edges at
   least); a rigid rotation by 170 degrees turns every face against its input direction but makes no crease; the
   mirrored state against itself has no new crease. */
static PetscErrorCode CheckCreases(MPI_Comm comm, CSMesh mesh, const char label[])
{
  Vec          y, z;
  PetscScalar *a;
  PetscInt     n, nmir, nrot, nself, nflip;
  char         what[160];
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(mesh->x, &y));
  PetscCall(VecDuplicate(mesh->x, &z));
  PetscCall(VecCopy(mesh->x, y));
  PetscCall(VecCopy(mesh->x, z));
  PetscCall(VecGetLocalSize(y, &n));
  PetscCall(VecGetArray(y, &a));
  for (PetscInt i = 0; i < n / 3; i++)
    if (PetscRealPart(a[3 * i + 2]) > 0) a[3 * i + 2] = -a[3 * i + 2];
  PetscCall(VecRestoreArray(y, &a));
  PetscCall(VecGetArray(z, &a));
  for (PetscInt i = 0; i < n / 3; i++) { /* about the x axis by 170 degrees */
    const PetscReal c = PetscCosReal(170 * PETSC_PI / 180), s = PetscSinReal(170 * PETSC_PI / 180);
    PetscReal       q1 = PetscRealPart(a[3 * i + 1]), q2 = PetscRealPart(a[3 * i + 2]);
    a[3 * i + 1] = c * q1 - s * q2;
    a[3 * i + 2] = s * q1 + c * q2;
  }
  PetscCall(VecRestoreArray(z, &a));
  PetscCall(CSGeometryCreasedEdges(mesh, mesh->x, y, 150, &nmir));
  PetscCall(CSGeometryCreasedEdges(mesh, mesh->x, z, 150, &nrot));
  PetscCall(CSGeometryCreasedEdges(mesh, y, y, 150, &nself));
  PetscCall(CSGeometryFoldedFaces(mesh, mesh->x, z, &nflip));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s mirrored onto its lower half: creases > 150 deg (at least 2 x 16)", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(nmir >= 32), what, (PetscReal)nmir, 32));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s rotated by 170 deg: no crease, while %" PetscInt_FMT " faces (over half) point against the input", label, nflip));
  PetscCall(CSTestCheck(comm, (PetscBool)(nrot == 0 && 2 * nflip > mesh->Nf), what, (PetscReal)nrot, 0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s mirrored, against itself: no new crease", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(nself == 0), what, (PetscReal)nself, 0));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&z));
  PetscFunctionReturn(0);
}

/* The checks that run on one mesh, in order, each on its own copy of the mesh (MakeMesh is deterministic). */
typedef struct {
  PetscErrorCode (*check)(MPI_Comm, CSMesh, const char[]);
  Gen         g;
  PetscInt    a, b;
  PetscReal   R, r, amp;
  const char *label;
} MeshCheck;

static const MeshCheck mesh_checks[] = {
  {CheckGradients,  GEN_ICOSPHERE, 2,  0, 0,   0,   0.03, "perturbed icosphere"               },
  {CheckInvariance, GEN_ICOSPHERE, 2,  0, 0,   0,   0.03, "perturbed icosphere"               },
  {CheckGradients,  GEN_TORUS,     16, 8, 2.0, 0.7, 0.03, "perturbed torus"                   },
  {CheckGradients,  GEN_CYLINDER,  16, 6, 0,   0,   0.03, "perturbed open cylinder (boundary)"},
  {CheckLaplacian,  GEN_ICOSPHERE, 3,  0, 0,   0,   0,    "icosphere"                         },
  {CheckLaplacian,  GEN_DISK,      6,  0, 0,   0,   0,    "disk (boundary)"                   },
  {CheckCreases,    GEN_TORUS,     16, 8, 2.0, 0.7, 0,    "torus 16 x 8"                      },
};

int main(int argc, char **argv)
{
  MPI_Comm comm;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  comm = PETSC_COMM_WORLD;

  for (size_t k = 0; k < sizeof(mesh_checks) / sizeof(mesh_checks[0]); k++) {
    const MeshCheck *c = &mesh_checks[k];
    CSMesh           mesh;
    PetscCall(MakeMesh(comm, c->g, c->a, c->b, c->R, c->r, c->amp, &mesh));
    PetscCall(c->check(comm, mesh, c->label));
    PetscCall(CSMeshDestroy(&mesh));
  }

  PetscCall(CheckSequence(comm, GEN_ICOSPHERE, "unit icosphere -> 4pi", 4 * PETSC_PI, 1e-5));
  PetscCall(CheckSequence(comm, GEN_TORUS, "torus R=sqrt2 r=1 -> 2pi^2", 2 * PETSC_PI * PETSC_PI, 1e-4));
  return CSTestFinalize(comm, PetscFinalize);
}
