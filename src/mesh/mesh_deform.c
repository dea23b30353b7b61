/* Test-input deformation of a mesh's positions (-gen_deform_bump, -gen_deform_bump_freq, -gen_deform_stretch):
   a radial bump and a stretch, used by the flow tests and options/ to start away from a critical point. */
#include "cs_mesh_deform.h"

static PetscErrorCode Deform(Vec x, PetscReal a, PetscReal k, const PetscReal s[3])
{
  PetscInt     n;
  PetscScalar *p;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArray(x, &p));
  for (PetscInt i = 0; i < n / 3; i++) {
    PetscReal *q = (PetscReal *)p + 3 * i, b = 1 + a * PetscSinReal(k * q[0]) * PetscSinReal(k * q[1]) * PetscSinReal(k * q[2]);
    for (int d = 0; d < 3; d++) q[d] *= b * s[d];
  }
  PetscCall(VecRestoreArray(x, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDeformFromOptions(CSMesh mesh, const char prefix[])
{
  PetscReal bump = 0, freq = 3, stretch[3] = {1, 1, 1};
  PetscInt  nstretch = 3;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(mesh->comm, prefix, "Test-input deformation", NULL);
  PetscCall(PetscOptionsReal("-gen_deform_bump", "Radial bump amplitude a applied to the input positions", "CSMeshDeformFromOptions", bump, &bump, NULL));
  PetscCall(PetscOptionsReal("-gen_deform_bump_freq", "Bump frequency k in sin(k x) sin(k y) sin(k z)", "CSMeshDeformFromOptions", freq, &freq, NULL));
  PetscCall(PetscOptionsRealArray("-gen_deform_stretch", "Stretch factors sx,sy,sz applied after the bump", "CSMeshDeformFromOptions", stretch, &nstretch, &set));
  PetscOptionsEnd();
  PetscCheck(!set || nstretch == 3, mesh->comm, PETSC_ERR_ARG_SIZ, "-%sgen_deform_stretch needs three values sx,sy,sz", prefix ? prefix : "");
  if (bump != 0 || stretch[0] != 1 || stretch[1] != 1 || stretch[2] != 1) PetscCall(Deform(mesh->x, bump, freq, stretch));
  PetscFunctionReturn(0);
}
