static const char help[] = "Benchmark of the harmonic 1-form basis (include/cs_operators_dec.h): mesh from -mesh/-gen, then\n"
                           "CSHarmonicBasisSetUp (first: topology + geometry) and -bench_repeat CSHarmonicBasisUpdate calls\n"
                           "(geometry only: refactor L, 2x2g solves, Gram-Schmidt, face vectors); prints seconds and residuals.\n";
#include "cs_operators_dec.h"
#include "cs_package.h"

int main(int argc, char **argv)
{
  CSMesh          mesh;
  CSHarmonicBasis hb;
  PetscInt        repeat = 3, n;
  PetscLogDouble  t0, t1, t2;
  PetscReal       rc, rd, ro;
  PetscMPIInt     size;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(CSInitializePackage());
  PetscCallMPI(MPI_Comm_size(PETSC_COMM_WORLD, &size));
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "Harmonic basis benchmark", NULL);
  PetscCall(PetscOptionsInt("-bench_repeat", "Updates at the same positions", NULL, repeat, &repeat, NULL));
  PetscOptionsEnd();
  PetscCall(CSMeshCreateFromOptions(PETSC_COMM_WORLD, NULL, &mesh));
  PetscCall(CSHarmonicBasisCreate(mesh, mesh->x, &hb));
  PetscCall(CSHarmonicBasisSetFromOptions(hb));
  PetscCall(PetscTime(&t0));
  PetscCall(CSHarmonicBasisSetUp(hb));
  PetscCall(PetscTime(&t1));
  for (PetscInt k = 0; k < repeat; k++) PetscCall(CSHarmonicBasisUpdate(hb, mesh->x));
  PetscCall(PetscTime(&t2));
  PetscCall(CSHarmonicBasisGetSize(hb, &n));
  PetscCall(CSHarmonicBasisGetResiduals(hb, &rc, &rd, &ro));
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "ranks %d faces %" PetscInt_FMT " forms %" PetscInt_FMT " setup_s %.4f update_s %.4f closed %.2e coclosed %.2e orthonormal %.2e\n", size, mesh->Nf, n, t1 - t0, repeat ? (t2 - t1) / repeat : 0.0, (double)rc, (double)rd, (double)ro));
  PetscCall(CSHarmonicBasisDestroy(&hb));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(PetscFinalize());
  return 0;
}
