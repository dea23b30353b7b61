static const char help[] = "Benchmark: read+validate, distribute, then -bench_repeat evaluations of the Willmore energy and\n"
                           "its gradient. Run with -log_view: events CSMeshRead, CSMeshDistribute, CSEnergy, CSGradient.\n";
#include "cs_energy.h"

int main(int argc, char **argv)
{
  CSMesh    mesh;
  CSEnergy  e;
  Vec       g;
  PetscInt  repeat = 10;
  PetscReal W;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "Energy benchmark", NULL);
  PetscCall(PetscOptionsInt("-bench_repeat", "Evaluations of W and its gradient", NULL, repeat, &repeat, NULL));
  PetscOptionsEnd();
  PetscCall(CSMeshCreateFromOptions(PETSC_COMM_WORLD, NULL, &mesh));
  PetscCall(CSEnergyCreateWillmore(mesh, &e));
  PetscCall(VecDuplicate(mesh->x, &g));
  for (PetscInt k = 0; k < repeat; k++) {
    PetscCall(CSEnergyValue(e, mesh->x, &W));
    PetscCall(CSEnergyGradient(e, mesh->x, NULL, g));
  }
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "faces %" PetscInt_FMT " W %.12g\n", mesh->Nf, (double)W));
  PetscCall(VecDestroy(&g));
  PetscCall(CSEnergyDestroy(&e));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(PetscFinalize());
  return 0;
}
