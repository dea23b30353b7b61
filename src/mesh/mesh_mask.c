/* A user mask of vertices or faces from a file of 0-based indices in file order (bobenko-schroeder2005
   Sec. 3.3: "islands" of vertices or faces held fixed), as a vertex field. */
#include "cs_mesh.h"
#include "cs_util.h"
#include <stdio.h>

/* rank 0: the natural vector nat (Nv or Nf entries) gets 1 at every index of the file */
static PetscErrorCode MarkIndices(const char option[], const char path[], PetscInt N, const char what[], PetscScalar nat[])
{
  PetscInt   n, *line;
  PetscReal *v;
  PetscFunctionBeginUser;
  PetscCall(CSReadNumberFile(option, path, &n, &v, &line));
  for (PetscInt i = 0; i < n; i++) {
    PetscBool ok = (PetscBool)(v[i] >= 0 && v[i] < N && v[i] == PetscFloorReal(v[i]));
    if (!ok) {
      char     num[32];
      PetscInt l = line[i];
      snprintf(num, sizeof(num), "%g", (double)v[i]); /* C's %g: PETSc's prints 162 as "162." */
      PetscCall(PetscFree(v));
      PetscCall(PetscFree(line));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": %s is not a %s index in 0..%" PetscInt_FMT, option, path, l, num, what, N - 1);
    }
    nat[(PetscInt)v[i]] = 1;
  }
  PetscCall(PetscFree(v));
  PetscCall(PetscFree(line));
  PetscCheck(n > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: no indices", option, path);
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshReadIndexMask(CSMesh mesh, const char option[], const char path[], PetscBool faces, Vec vmask)
{
  CSMeshNatural *field = faces ? &mesh->natF1 : &mesh->natV1;
  PetscScalar   *a;
  PetscFunctionBeginUser;
  PetscCall(VecSet(field->vec, 0));
  PetscCall(VecGetArray(field->vec, &a));
  CSRootCall(mesh->comm, MarkIndices(option, path, faces ? mesh->Nf : mesh->Nv, faces ? "face" : "vertex", a));
  PetscCall(VecRestoreArray(field->vec, &a));
  if (!faces) PetscCall(CSMeshScatter(field, field->vec, vmask));
  else {
    Vec                fm;
    const PetscScalar *f;
    CSLocalSum         s;
    PetscCall(DMCreateGlobalVector(mesh->dmF1, &fm));
    PetscCall(CSMeshScatter(field, field->vec, fm));
    PetscCall(VecGetArrayRead(fm, &f)); /* faces are owned by the rank that has them (local face order) */
    PetscCall(CSLocalSumBegin(mesh->dmV1, &s));
    for (PetscInt k = 0; k < mesh->nf; k++)
      if (PetscRealPart(f[k]) > 0.5)
        for (int c = 0; c < 3; c++) s.a[mesh->faceVert[3 * k + c]] = 1;
    PetscCall(VecRestoreArrayRead(fm, &f));
    PetscCall(CSLocalSumEnd(&s, vmask));
    PetscCall(VecDestroy(&fm));
  }
  PetscFunctionReturn(0);
}
