static const char help[] = "Checkpoint round trip: -mode write stores (it, scalars, positions, edge lengths) of a perturbed\n"
                           "icosphere; -mode read restores them, possibly on another number of ranks, and compares with\n"
                           "the values recomputed on this partition. Exit status = number of failures.\n";
#include "cs_geometry.h"

int main(int argc, char **argv)
{
  CSMesh    mesh;
  Vec       x, l, x2, l2;
  char      mode[16] = "write", path[PETSC_MAX_PATH_LEN] = "checkpoint.bin";
  PetscReal reals[2] = {0.125, -3.5}, r2[2], ex, el;
  PetscInt  it = 0, nfail = 0;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscOptionsBegin(PETSC_COMM_WORLD, NULL, "checkpoint test", NULL);
  PetscCall(PetscOptionsString("-mode", "write|read", NULL, mode, mode, sizeof(mode), NULL));
  PetscCall(PetscOptionsString("-path", "checkpoint file", NULL, path, path, sizeof(path), NULL));
  PetscOptionsEnd();
  PetscCall(CSMeshCreateFromOptions(PETSC_COMM_WORLD, NULL, &mesh));
  /* a state that is not just the input: scaled positions, and the edge lengths of the scaled mesh */
  PetscCall(VecDuplicate(mesh->x, &x));
  PetscCall(VecCopy(mesh->x, x));
  PetscCall(VecScale(x, 1.5));
  PetscCall(DMCreateGlobalVector(mesh->dmE1, &l));
  PetscCall(CSGeometryEdgeLengths(mesh, x, l));
  if (!strcmp(mode, "write")) {
    PetscCall(CSCheckpointWrite(mesh, path, 42, 2, reals, x, l));
  } else {
    PetscCall(VecDuplicate(x, &x2));
    PetscCall(VecDuplicate(l, &l2));
    PetscCall(CSCheckpointRead(mesh, path, &it, 2, r2, x2, l2));
    PetscCall(VecAXPY(x2, -1, x));
    PetscCall(VecAXPY(l2, -1, l));
    PetscCall(VecNorm(x2, NORM_INFINITY, &ex));
    PetscCall(VecNorm(l2, NORM_INFINITY, &el));
    nfail += (it != 42) + (r2[0] != reals[0] || r2[1] != reals[1]) + (ex != 0) + (el != 0);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s checkpoint restored: it %" PetscInt_FMT ", scalars %g %g, |dx| %g, |d edge| %g\n", nfail ? "FAIL" : "ok  ", it, (double)r2[0], (double)r2[1], (double)ex, (double)el));
    PetscCall(VecDestroy(&x2));
    PetscCall(VecDestroy(&l2));
  }
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&l));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(PetscFinalize());
  return (int)nfail;
}
