/* A per-vertex scalar field from a file of Nv numbers in file order (CSReadNumberFile: no line length limit). */
#include "cs_mesh.h"
#include "cs_util.h"

static PetscErrorCode ReadValues(const char option[], const char path[], PetscInt N, PetscScalar nat[])
{
  PetscInt   n, *line;
  PetscReal *v;
  PetscFunctionBeginUser;
  PetscCall(CSReadNumberFile(option, path, &n, &v, &line));
  for (PetscInt i = 0; i < PetscMin(n, N); i++) nat[i] = v[i];
  PetscCall(PetscFree(v));
  PetscCall(PetscFree(line));
  PetscCheck(n == N, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: %" PetscInt_FMT " values, expected %" PetscInt_FMT " (one per vertex in file order)", option, path, n, N);
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshReadVertexValues(CSMesh mesh, const char option[], const char path[], Vec g)
{
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(mesh->natV1.vec, &a));
  CSRootCall(mesh->comm, ReadValues(option, path, mesh->Nv, a));
  PetscCall(VecRestoreArray(mesh->natV1.vec, &a));
  PetscCall(CSMeshScatter(&mesh->natV1, mesh->natV1.vec, g));
  PetscFunctionReturn(0);
}
