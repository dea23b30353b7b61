/* Test-input deformation of a mesh's positions (-gen_deform_bump, -gen_deform_bump_freq, -gen_deform_stretch,
   -gen_deform_twist, -gen_deform_invert, -gen_deform_nfold): a radial bump and a stretch, used by the flow tests and
   options/ to start away from a critical point; a twist about the z axis (a cylinder with rotated boundary,
   soliman2021 Fig. 2, 21); a Moebius map (another representative of the same discrete conformal class, Fig. 4); an
   n-fold wave about the z axis (a symmetric start, Fig. 17). */
#include "cs_mesh_deform.h"
#include "cs_util.h"

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

/* Rotation about the z axis by the angle deg * (z - zmin) / (zmax - zmin) (degrees; z range over all ranks):
   the bottom stays, the top turns by deg, linearly in between. */
static PetscErrorCode Twist(MPI_Comm comm, Vec x, PetscReal deg)
{
  PetscInt     n;
  PetscScalar *p;
  PetscReal    lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, g[2]; /* zmin, -zmax */
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArray(x, &p));
  for (PetscInt i = 0; i < n / 3; i++) {
    lo[0] = PetscMin(lo[0], PetscRealPart(p[3 * i + 2]));
    lo[1] = PetscMin(lo[1], -PetscRealPart(p[3 * i + 2]));
  }
  PetscCall(MPIU_Allreduce(lo, g, 2, MPIU_REAL, MPIU_MIN, comm));
  for (PetscInt i = 0; i < n / 3 && -g[1] > g[0]; i++) {
    PetscReal *q = (PetscReal *)p + 3 * i, a = deg * PETSC_PI / 180 * (q[2] - g[0]) / (-g[1] - g[0]);
    PetscReal  c = PetscCosReal(a), s = PetscSinReal(a), x0 = q[0];
    q[0] = c * x0 - s * q[1];
    q[1] = s * x0 + c * q[1];
  }
  PetscCall(VecRestoreArray(x, &p));
  PetscFunctionReturn(0);
}

/* An orientation-preserving Moebius map: the inversion in the unit sphere about c, then the mirror x -> 2 c_x - x.
   Length cross ratios are Moebius invariant (soliman2021 Sec. 3), so the image lies in the input's discrete
   conformal class (to rounding). A vertex at c has no image: refused. */
static PetscErrorCode Invert(MPI_Comm comm, Vec x, const PetscReal c[3], const char *prefix)
{
  PetscInt     n;
  PetscScalar *p;
  PetscBool    bad = PETSC_FALSE, gbad;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArray(x, &p));
  for (PetscInt i = 0; i < n / 3; i++) {
    PetscReal *q = (PetscReal *)p + 3 * i, r2 = 0;
    for (int d = 0; d < 3; d++) r2 += (q[d] - c[d]) * (q[d] - c[d]);
    if (!(r2 > 1e-24)) { bad = PETSC_TRUE; continue; }
    for (int d = 0; d < 3; d++) q[d] = c[d] + (q[d] - c[d]) / r2;
    q[0] = 2 * c[0] - q[0];
  }
  PetscCall(VecRestoreArray(x, &p));
  PetscCall(MPIU_Allreduce(&bad, &gbad, 1, MPIU_BOOL, MPI_LOR, comm));
  PetscCheck(!gbad, comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sgen_deform_invert %g,%g,%g: a vertex lies at the centre of the inversion (choose a centre off the surface)", prefix, (double)c[0], (double)c[1], (double)c[2]);
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDeformFromOptions(CSMesh mesh, const char prefix[])
{
  PetscReal bump = 0, freq = 3, stretch[3] = {1, 1, 1}, twist = 0, centre[3] = {0, 0, 0};
  PetscReal nfold[2] = {0, 0};
  PetscInt  nstretch = 3, ncentre = 3, nn = 2;
  PetscBool set, inv, nset = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscOptionsBegin(mesh->comm, prefix, "Test-input deformation", NULL);
  PetscCall(CSOptionsReal("-gen_deform_bump", "Radial bump amplitude a applied to the input positions", "CSMeshDeformFromOptions", bump, &bump, NULL));
  PetscCall(CSOptionsReal("-gen_deform_bump_freq", "Bump frequency k in sin(k x) sin(k y) sin(k z)", "CSMeshDeformFromOptions", freq, &freq, NULL));
  PetscCall(PetscOptionsRealArray("-gen_deform_stretch", "Stretch factors sx,sy,sz applied after the bump", "CSMeshDeformFromOptions", stretch, &nstretch, &set));
  PetscCall(CSOptionsReal("-gen_deform_twist", "Twist about the z axis: the top turns by this angle (degrees), linearly in z, after the stretch", "CSMeshDeformFromOptions", twist, &twist, NULL));
  PetscCall(PetscOptionsRealArray("-gen_deform_invert", "Moebius map applied last: inversion in the unit sphere about cx,cy,cz and the mirror in x (the same discrete conformal class)", "CSMeshDeformFromOptions", centre, &ncentre, &inv));
  PetscCall(PetscOptionsRealArray("-gen_deform_nfold", "N,A: the distance from the z axis times 1 + A cos(N phi) (an N-fold symmetric start), applied first", "CSMeshDeformFromOptions", nfold, &nn, &nset));
  PetscOptionsEnd();
  PetscCheck(!nset || nn == 2, mesh->comm, PETSC_ERR_ARG_WRONG, "-%sgen_deform_nfold N,A: give two numbers (got %" PetscInt_FMT ")", prefix ? prefix : "", nn);
  PetscCheck(!nset || (nfold[0] == PetscFloorReal(nfold[0]) && nfold[0] >= 0 && nfold[0] <= 1e3), mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sgen_deform_nfold N,A = %g,%g: N must be an integer in [0, 1000]", prefix ? prefix : "", (double)nfold[0], (double)nfold[1]);
  PetscCheck(!nset || PetscAbsReal(nfold[1]) < 1, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sgen_deform_nfold N,A = %g,%g: A must lie in (-1, 1) (the factor 1 + A cos(N phi) must stay positive)", prefix ? prefix : "", (double)nfold[0], (double)nfold[1]);
  {
    /* issue 36, item 5: nan or 1e300 used to be written as a mesh of nan coordinates */
    const CSOptionCheck checks[] = {
      {"gen_deform_bump", bump, PetscAbsReal(bump) <= 10, "must lie in [-10, 10] (the radial factor 1 + a sin sin sin)"},
      {"gen_deform_bump_freq", freq, PetscAbsReal(freq) <= 1e3, "must lie in [-1e3, 1e3] (a frequency beyond any mesh's resolution otherwise)"},
      {"gen_deform_stretch (sx)", stretch[0], stretch[0] >= 1e-6 && stretch[0] <= 1e6, "must lie in [1e-6, 1e6]"},
      {"gen_deform_stretch (sy)", stretch[1], stretch[1] >= 1e-6 && stretch[1] <= 1e6, "must lie in [1e-6, 1e6]"},
      {"gen_deform_stretch (sz)", stretch[2], stretch[2] >= 1e-6 && stretch[2] <= 1e6, "must lie in [1e-6, 1e6]"},
      {"gen_deform_twist", twist, PetscAbsReal(twist) <= 1e4, "must lie in [-1e4, 1e4] degrees"},
      {"gen_deform_invert (cx)", centre[0], PetscAbsReal(centre[0]) <= 1e6, "must lie in [-1e6, 1e6]"},
      {"gen_deform_invert (cy)", centre[1], PetscAbsReal(centre[1]) <= 1e6, "must lie in [-1e6, 1e6]"},
      {"gen_deform_invert (cz)", centre[2], PetscAbsReal(centre[2]) <= 1e6, "must lie in [-1e6, 1e6]"},
    };
    PetscCall(CSCheckOptionValues(mesh->comm, prefix, sizeof(checks) / sizeof(checks[0]), checks));
  }
  if (nfold[0] > 0 && nfold[1] != 0) PetscCall(NFold(mesh->x, (PetscInt)nfold[0], nfold[1]));
  PetscCheck(!set || nstretch == 3, mesh->comm, PETSC_ERR_ARG_SIZ, "-%sgen_deform_stretch needs three values sx,sy,sz", prefix ? prefix : "");
  PetscCheck(!inv || ncentre == 3, mesh->comm, PETSC_ERR_ARG_SIZ, "-%sgen_deform_invert needs three values cx,cy,cz", prefix ? prefix : "");
  if (bump != 0 || stretch[0] != 1 || stretch[1] != 1 || stretch[2] != 1) PetscCall(Deform(mesh->x, bump, freq, stretch));
  if (twist != 0) PetscCall(Twist(mesh->comm, mesh->x, twist));
  if (inv) PetscCall(Invert(mesh->comm, mesh->x, centre, prefix ? prefix : ""));
  PetscFunctionReturn(0);
}
