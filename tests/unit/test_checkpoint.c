static const char help[] = "Checkpoint round trip: -mode write stores (it, scalars, positions, edge lengths) of a perturbed\n"
                           "icosphere and fields of several values per edge and face (from the natural numbers); -mode read restores them, possibly on another number of ranks, and compares with\n"
                           "the values recomputed on this partition. Exit status = number of failures.\n";
#include "cs_geometry.h"

/* a field with k values per point of depth (1 edges, 2 faces), value j of point p = (j + 1) * natural(p) + j */
static PetscErrorCode NaturalField(CSMesh mesh, PetscInt depth, PetscInt k, DM *dm, Vec *g)
{
  Vec          l;
  PetscScalar *a;
  PetscInt     n = depth == 1 ? mesh->ne : mesh->nf;
  PetscFunctionBeginUser;
  PetscCall(CSMeshCreateFieldDM(mesh->dm, depth, k, "test", dm));
  PetscCall(DMCreateGlobalVector(*dm, g));
  PetscCall(DMGetLocalVector(*dm, &l));
  PetscCall(VecGetArray(l, &a));
  for (PetscInt p = 0; p < n; p++)
    for (PetscInt j = 0; j < k; j++) a[k * p + j] = (j + 1) * (depth == 1 ? mesh->edgeNatural[p] : mesh->faceNatural[p]) + j;
  PetscCall(VecRestoreArray(l, &a));
  PetscCall(DMLocalToGlobal(*dm, l, INSERT_VALUES, *g));
  PetscCall(DMRestoreLocalVector(*dm, &l));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  CSMesh    mesh;
  Vec       x, l, x2, l2, e3, f2, e3b, f2b;
  DM        dmE3, dmF2;
  PetscReal ee, ef;
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
  PetscCall(NaturalField(mesh, 1, 3, &dmE3, &e3));
  PetscCall(NaturalField(mesh, 2, 2, &dmF2, &f2));
  if (!strcmp(mode, "write")) {
    CSCheckpointFields v = {x, l, NULL}, w = {NULL, e3, f2};
    char               p2[PETSC_MAX_PATH_LEN + 4];
    PetscCall(CSCheckpointWrite(mesh, path, 42, 2, reals, &v));
    PetscCall(PetscSNPrintf(p2, sizeof(p2), "%s.ef", path));
    PetscCall(CSCheckpointWrite(mesh, p2, 7, 2, reals, &w));
  } else if (!strcmp(mode, "read_ef")) { /* the per-edge and per-face fields of several values */
    CSCheckpointFields w;
    char               p2[PETSC_MAX_PATH_LEN + 4];
    PetscCall(VecDuplicate(e3, &e3b));
    PetscCall(VecDuplicate(f2, &f2b));
    w.x    = NULL;
    w.edge = e3b;
    w.face = f2b;
    PetscCall(PetscSNPrintf(p2, sizeof(p2), "%s.ef", path));
    PetscCall(CSCheckpointRead(mesh, p2, &it, 2, r2, &w));
    PetscCall(VecAXPY(e3b, -1, e3));
    PetscCall(VecAXPY(f2b, -1, f2));
    PetscCall(VecNorm(e3b, NORM_INFINITY, &ee));
    PetscCall(VecNorm(f2b, NORM_INFINITY, &ef));
    nfail += (it != 7) + (ee != 0) + (ef != 0);
    PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%s edge (3 per edge) and face (2 per face) fields restored: it %" PetscInt_FMT ", |d edge| %g, |d face| %g\n", nfail ? "FAIL" : "ok  ", it, (double)ee, (double)ef));
    PetscCall(VecDestroy(&e3b));
    PetscCall(VecDestroy(&f2b));
  } else {
    CSCheckpointFields v;
    PetscCall(VecDuplicate(x, &x2));
    PetscCall(VecDuplicate(l, &l2));
    v.x    = x2;
    v.edge = l2;
    v.face = NULL;
    PetscCall(CSCheckpointRead(mesh, path, &it, 2, r2, &v));
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
  PetscCall(VecDestroy(&e3));
  PetscCall(VecDestroy(&f2));
  PetscCall(DMDestroy(&dmE3));
  PetscCall(DMDestroy(&dmF2));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(PetscFinalize());
  return (int)nfail;
}
