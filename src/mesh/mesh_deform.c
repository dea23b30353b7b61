/* Test-input deformation of a mesh's positions (-gen_deform_bump, -gen_deform_bump_freq, -gen_deform_stretch,
   -gen_deform_nfold): a radial bump, a stretch and an n-fold wave about the z axis, used by the flow tests and
   options/ to start away from a critical point (or, n-fold, at a symmetric start: soliman2021 Fig. 17). */
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

/* the distance from the z axis times 1 + a cos(n phi), phi the angle about z: n-fold rotational symmetry */
static PetscErrorCode NFold(Vec x, PetscInt n, PetscReal a)
{
  PetscInt     m;
  PetscScalar *p;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &m));
  PetscCall(VecGetArray(x, &p));
  for (PetscInt i = 0; i < m / 3; i++) {
    PetscReal *q = (PetscReal *)p + 3 * i, b = 1 + a * PetscCosReal(n * PetscAtan2Real(q[1], q[0]));
    q[0] *= b;
    q[1] *= b;
  }
  PetscCall(VecRestoreArray(x, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDeformFromOptions(CSMesh mesh, const char prefix[])
{
  PetscReal bump = 0, freq = 3, stretch[3] = {1, 1, 1};
  PetscInt  nstretch = 3, nn = 2;
  PetscReal nfold[2] = {0, 0};
  PetscBool nset     = PETSC_FALSE;
  PetscBool set;
  PetscFunctionBeginUser;
  PetscOptionsBegin(mesh->comm, prefix, "Test-input deformation", NULL);
  PetscCall(PetscOptionsReal("-gen_deform_bump", "Radial bump amplitude a applied to the input positions", "CSMeshDeformFromOptions", bump, &bump, NULL));
  PetscCall(PetscOptionsReal("-gen_deform_bump_freq", "Bump frequency k in sin(k x) sin(k y) sin(k z)", "CSMeshDeformFromOptions", freq, &freq, NULL));
  PetscCall(PetscOptionsRealArray("-gen_deform_stretch", "Stretch factors sx,sy,sz applied after the bump", "CSMeshDeformFromOptions", stretch, &nstretch, &set));
  PetscCall(PetscOptionsRealArray("-gen_deform_nfold", "N,A: the distance from the z axis times 1 + A cos(N phi) (an N-fold symmetric start)", "CSMeshDeformFromOptions", nfold, &nn, &nset));
  PetscOptionsEnd();
  PetscCheck(!nset || (nn == 2 && nfold[0] == (PetscInt)nfold[0] && nfold[0] >= 0 && PetscAbsReal(nfold[1]) < 1), mesh->comm, PETSC_ERR_ARG_WRONG, "-%sgen_deform_nfold N,A: N a non-negative integer, |A| < 1 (got %" PetscInt_FMT " values)", prefix ? prefix : "", nn);
  if (nfold[0] > 0 && nfold[1] != 0) PetscCall(NFold(mesh->x, (PetscInt)nfold[0], nfold[1]));
  PetscCheck(!set || nstretch == 3, mesh->comm, PETSC_ERR_ARG_SIZ, "-%sgen_deform_stretch needs three values sx,sy,sz", prefix ? prefix : "");
  if (bump != 0 || stretch[0] != 1 || stretch[1] != 1 || stretch[2] != 1) PetscCall(Deform(mesh->x, bump, freq, stretch));
  PetscFunctionReturn(0);
}
