/* Shared by the unit programs (header only: each program is one translation unit): one line per check with a
   failure count for the exit status, and a distributed mesh made from data generated on rank 0. */
#ifndef CS_TEST_H
#define CS_TEST_H
#include "cs_mesh.h"
#include <stdarg.h>
#include <stdio.h>

PETSC_UNUSED static PetscInt cs_test_failures = 0;

PETSC_UNUSED static PetscErrorCode CSTestCheck(MPI_Comm comm, PetscBool ok, const char what[], PetscReal value, PetscReal bound)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "%s %s: %.3e (bound %.1e)\n", ok ? "ok  " : "FAIL", what, (double)value, (double)bound));
  if (!ok) cs_test_failures++;
  PetscFunctionReturn(0);
}

/* One check with a printf-style detail: "ok NAME detail" or "FAIL NAME: detail" on comm's rank 0. */
PETSC_UNUSED static PetscErrorCode CSTestCheckf(MPI_Comm comm, PetscBool ok, const char name[], const char fmt[], ...)
{
  char    detail[1024] = "";
  va_list ap;

  PetscFunctionBeginUser;
  va_start(ap, fmt);
  vsnprintf(detail, sizeof(detail), fmt, ap);
  va_end(ap);
  if (ok) PetscCall(PetscPrintf(comm, "ok %s%s%s\n", name, detail[0] ? " " : "", detail));
  else {
    cs_test_failures++;
    PetscCall(PetscPrintf(comm, "FAIL %s: %s\n", name, detail));
  }
  PetscFunctionReturn(0);
}

/* The end of a unit program: the failure count on one line, finalize (PetscFinalize or SlepcFinalize), and the
   count as the exit status. Use: return CSTestFinalize(comm, PetscFinalize); */
PETSC_UNUSED static int CSTestFinalize(MPI_Comm comm, PetscErrorCode (*finalize)(void))
{
  PetscCall(PetscPrintf(comm, "%" PetscInt_FMT " failed\n", cs_test_failures));
  PetscCall(finalize());
  return (int)cs_test_failures;
}

/* A PetscRandom on comm, uniform in [lo, hi), seeded: the same numbers in every run (PetscRandomCreate's own
   interval is [0, 1)). */
PETSC_UNUSED static PetscErrorCode CSTestRandom(MPI_Comm comm, PetscReal lo, PetscReal hi, unsigned long seed, PetscRandom *r)
{
  PetscFunctionBeginUser;
  PetscCall(PetscRandomCreate(comm, r));
  PetscCall(PetscRandomSetInterval(*r, lo, hi));
  PetscCall(PetscRandomSetSeed(*r, seed));
  PetscCall(PetscRandomSeed(*r));
  PetscFunctionReturn(0);
}

/* md was generated on rank 0 (empty elsewhere). amp > 0 adds uniform noise in [-amp, amp] from a seeded
   PetscRandom on rank 0, in file order, so every process count sees the same mesh. Then validate and
   distribute; md is consumed. */
PETSC_UNUSED static PetscErrorCode CSTestDistribute(MPI_Comm comm, CSMeshData *md, PetscReal amp, unsigned long seed, CSMesh *mesh)
{
  CSTopology  topo;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(&topo, sizeof(topo)));
  if (!rank) {
    if (amp > 0) {
      PetscRandom r;
      PetscCall(CSTestRandom(PETSC_COMM_SELF, -amp, amp, seed, &r));
      for (PetscInt i = 0; i < 3 * md->nv; i++) {
        PetscReal d;
        PetscCall(PetscRandomGetValueReal(r, &d));
        md->x[i] += d;
      }
      PetscCall(PetscRandomDestroy(&r));
    }
    PetscCall(CSMeshDataValidate(md, &topo));
  }
  PetscCall(CSMeshCreateFromData(comm, md, &topo, mesh));
  PetscCall(CSMeshDataDestroy(md));
  PetscFunctionReturn(0);
}

/* The meshes of the unit tests: generated on rank 0 (a = level, n or rings; b = m), then CSTestDistribute. */
typedef enum { CS_TEST_ICOSPHERE, CS_TEST_ICOSAHEDRON, CS_TEST_TORUS, CS_TEST_CYLINDER, CS_TEST_DISK } CSTestShape;
typedef struct {
  CSTestShape shape;
  PetscInt    a, b;
  PetscReal   R, r;
} CSTestMeshSpec;

PETSC_UNUSED static PetscErrorCode CSTestMesh(MPI_Comm comm, CSTestMeshSpec s, PetscReal amp, unsigned long seed, CSMesh *mesh)
{
  CSMeshData  md;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(&md, sizeof(md)));
  if (!rank) {
    if (s.shape == CS_TEST_ICOSPHERE || s.shape == CS_TEST_ICOSAHEDRON) PetscCall(CSMeshDataIcosphere(s.a, 1.0, (PetscBool)(s.shape == CS_TEST_ICOSPHERE), &md));
    else if (s.shape == CS_TEST_TORUS) PetscCall(CSMeshDataTorus(s.R, s.r, s.a, s.b, &md));
    else if (s.shape == CS_TEST_CYLINDER) PetscCall(CSMeshDataCylinder(1.0, 2.0, s.a, s.b, &md));
    else PetscCall(CSMeshDataDisk(1.0, s.a, &md));
  }
  PetscCall(CSTestDistribute(comm, &md, amp, seed, mesh));
  PetscFunctionReturn(0);
}

/* v_i = fn(f_i, a) at every owned vertex i of mesh (v on the vertex dofs, one per vertex): a test field from positions */
typedef PetscReal (*CSTestPointFn)(const PetscReal f[3], PetscReal a);
PETSC_UNUSED static PetscErrorCode CSTestVertexField(CSMesh mesh, CSTestPointFn fn, PetscReal a, Vec v)
{
  const PetscScalar *x;
  PetscScalar       *r;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &n));
  PetscCall(VecGetArrayRead(mesh->x, &x));
  PetscCall(VecGetArray(v, &r));
  for (PetscInt i = 0; i < n; i++) {
    const PetscReal f[3] = {PetscRealPart(x[3 * i]), PetscRealPart(x[3 * i + 1]), PetscRealPart(x[3 * i + 2])};
    r[i]                 = fn(f, a);
  }
  PetscCall(VecRestoreArray(v, &r));
  PetscCall(VecRestoreArrayRead(mesh->x, &x));
  PetscFunctionReturn(0);
}

/* h exp(-|f - (0,0,1)|^2 / 0.25): a painted bump on the unit sphere's north pole (crane2011 Fig. 1), the spin tests'
   curvature change rho */
PETSC_UNUSED static PetscReal CSTestBump(const PetscReal f[3], PetscReal h)
{
  return h * PetscExpReal(-(PetscSqr(f[0]) + PetscSqr(f[1]) + PetscSqr(f[2] - 1)) / 0.25);
}
#endif