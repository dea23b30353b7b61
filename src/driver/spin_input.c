/* The inputs of -task spin read by the driver, not by the method (issue 37): rho from a file, painted bumps, the
   mean curvature, a normal displacement, the heat filter, or the nearest spin transformation of -spin_target_mesh
   (crane2011 Sec. 4.1, 7.1-7.3, Fig. 13); the target boundary tangents of Sec. 5.7 from -spin_boundary_file or
   the target mesh. Options without prefix (-rho*, -spin_target_mesh, -spin_boundary_file), as before. */
#include "spin_input.h"
#include "cs_util.h"

/* Rank 0: n*ncomp numbers from a value file (CSTokens: whitespace or comma separated, '#' comments) into a[]. */
static PetscErrorCode ReadValuesFile(const char option[], const char path[], PetscInt n, PetscInt ncomp, const char what[], PetscScalar a[])
{
  CSTokens    t;
  const char *tok;
  size_t      len;
  PetscInt    count = 0, want = n * ncomp, line;
  int         bad   = 0;
  double      v     = 0;
  PetscFunctionBeginUser;
  PetscCall(CSTokensLoad(option, path, &t));
  while (CSTokensNext(&t, &tok, &len, &line) && !(bad = CSTokenReal(tok, len, &v))) {
    if (PetscAbsReal(v) > 1e12) { /* rho beyond 1e12 swamps the Dirac operator (issue 36, item 16) */
      bad = 3;
      break;
    }
    if (count < want) a[count] = v;
    count++;
  }
  if (bad) {
    char text[40], msg[PETSC_MAX_PATH_LEN + 128];
    PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s %s: line %" PetscInt_FMT ": value %" PetscInt_FMT " '%s' is %s", option, t.name, line, count + 1, CSTokenText(tok, len, text), bad == 1 ? "not a number" : (bad == 3 ? "beyond 1e12 in absolute value" : "not finite")));
    PetscCall(CSTokensDestroy(&t));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s", msg);
  }
  PetscCall(CSTokensDestroy(&t));
  PetscCheck(count == want, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: %" PetscInt_FMT " values, expected %" PetscInt_FMT " (%s)", option, t.name, count, want, what);
  PetscFunctionReturn(0);
}

/* rho as an array of a caller of the library (src/api: the Python interface's spin(V, F, rho)), on rank 0, in
   place of -rho FILE while set (on every rank); read as the file would be, with the same checks. */
static const PetscReal *RhoArray = NULL;
static PetscInt         RhoArrayN = 0;

PetscErrorCode CSDriverSpinSetRhoArray(PetscBool set, PetscInt n, const PetscReal rho[])
{
  PetscFunctionBeginUser;
  RhoArray  = set ? (rho ? rho : (const PetscReal *)&RhoArrayN) : NULL; /* non-NULL on every rank while set */
  RhoArrayN = set ? n : 0;
  PetscFunctionReturn(0);
}

/* Rank 0: the array's values as ReadValuesFile reads a file's */
static PetscErrorCode CopyValues(PetscInt n, const char what[], PetscScalar a[])
{
  PetscFunctionBeginUser;
  PetscCheck(RhoArrayN == n, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "rho (array): %" PetscInt_FMT " values, expected %" PetscInt_FMT " (%s)", RhoArrayN, n, what);
  for (PetscInt i = 0; i < n; i++) {
    PetscCheck(!PetscIsInfOrNanReal(RhoArray[i]) && PetscAbsReal(RhoArray[i]) <= 1e12, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "rho (array): value %" PetscInt_FMT " is %g, %s", i, (double)RhoArray[i], PetscIsInfOrNanReal(RhoArray[i]) ? "not finite" : "beyond 1e12 in absolute value");
    a[i] = RhoArray[i];
  }
  PetscFunctionReturn(0);
}

/* Reads a per-vertex (ncomp 1 or 3) or per-face field in file order into the global vector g. */
static PetscErrorCode ReadField(CSMesh mesh, const char option[], const char path[], PetscInt depth, PetscInt ncomp, const char what[], Vec g)
{
  CSMeshNatural *field = depth == 2 ? &mesh->natF1 : (ncomp == 3 ? &mesh->natV3 : &mesh->natV1);
  PetscScalar   *a;
  PetscInt       n = depth == 2 ? mesh->Nf : mesh->Nv;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(field->vec, &a));
  if (RhoArray && !strcmp(option, "-rho")) CSRootCall(mesh->comm, CopyValues(n, what, a)); /* -rho's values as an array (src/api) */
  else CSRootCall(mesh->comm, ReadValuesFile(option, path, n, ncomp, what, a));
  PetscCall(VecRestoreArray(field->vec, &a));
  PetscCall(CSMeshScatter(field, field->vec, g));
  PetscFunctionReturn(0);
}

/* rho += height exp(-|f - c|^2 / radius^2) for each of the nb centres c (crane2011 Fig. 1: a painted rho) */
static PetscErrorCode PaintBumps(Vec x, PetscInt nb, const PetscReal centers[], PetscReal radius, PetscReal height, Vec rho)
{
  const PetscScalar *p;
  PetscScalar       *r;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(rho, &n));
  PetscCall(VecGetArrayRead(x, &p));
  PetscCall(VecGetArray(rho, &r));
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt b = 0; b < nb; b++) {
      PetscReal d2 = 0;
      for (int d = 0; d < 3; d++) d2 += PetscSqr(PetscRealPart(p[3 * i + d]) - centers[3 * b + d]);
      r[i] += height * PetscExpReal(-d2 / (radius * radius));
    }
  PetscCall(VecRestoreArray(rho, &r));
  PetscCall(VecRestoreArrayRead(x, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDriverSpinRhoFromOptions(CSSpin spin, Vec x, CSRhoLocation *loc, Vec *rho, Vec *xtarget, Vec *mu)
{
  CSMesh      mesh;
  DM          dm;
  char        file[PETSC_MAX_PATH_LEN] = "", target[PETSC_MAX_PATH_LEN] = "";
  const char *locs[]                   = {"vertex", "face"};
  PetscInt    iloc = 0, nc = 30;
  PetscReal   scale = 1, centers[30] = {0}, radius = 0.3, height = 1, hs = 0, smooth = 0;
  PetscBool   hasfile, hastarget, hasbump, hash, hasdisp, hassmooth;
  char        disp[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetMesh(spin, &mesh));
  PetscCall(CSSpinGetDM(spin, &dm));
  *loc     = CS_RHO_NONE;
  *rho     = NULL;
  *xtarget = NULL;
  *mu      = NULL;
  PetscOptionsBegin(mesh->comm, NULL, "Change of mean curvature half-density rho (crane2011 Sec. 4.1)", NULL);
  PetscCall(CSOptionsString("-rho", "File of rho values (one per vertex, or per face with -rho_location face), in file order", NULL, file, file, sizeof(file), &hasfile));
  PetscCall(CSOptionsEList("-rho_location", "Where -rho values live", NULL, locs, 2, locs[iloc], &iloc, NULL));
  PetscCall(CSOptionsReal("-rho_scale", "Multiply rho by this", NULL, scale, &scale, NULL));
  PetscCall(PetscOptionsRealArray("-rho_bump_center", "Bump centres x,y,z[,x,y,z...]: rho += height exp(-|f - c|^2 / radius^2)", NULL, centers, &nc, &hasbump));
  PetscCall(CSOptionsReal("-rho_bump_radius", "Bump radius", NULL, radius, &radius, NULL));
  PetscCall(CSOptionsReal("-rho_bump_height", "Bump height", NULL, height, &height, NULL));
  PetscCall(CSOptionsReal("-rho_mean_curvature", "rho += s H (s = -1: minimal surface, crane2011 Sec. 7.3)", NULL, hs, &hs, &hash));
  PetscCall(CSOptionsString("-rho_from_displacement", "rho += (L g)/(2 M) for a normal displacement g (file: one value per vertex in file order; crane2011 Sec. 7.1)", NULL, disp, disp, sizeof(disp), &hasdisp));
  PetscCall(CSOptionsReal("-rho_smooth", "Heat-diffusion filter of the per-vertex rho: (M + t L) rho~ = M rho, t in length^2 (crane2011 Fig. 13)", NULL, smooth, &smooth, &hassmooth));
  PetscCall(CSOptionsString("-spin_target_mesh", "Nearest spin transformation of this deformation (same connectivity; crane2011 Sec. 7.2)", NULL, target, target, sizeof(target), &hastarget));
  PetscOptionsEnd();
  if (!hasbump) nc = 0;
  PetscCheck(!RhoArray || !hasfile, mesh->comm, PETSC_ERR_ARG_INCOMP, "-rho %s: rho is given as an array", file);
  if (RhoArray) hasfile = PETSC_TRUE; /* the array takes -rho FILE's place */
  {
    /* finite and bounded (issue 36, item 16: inf or nan failed later inside the factorisation, naming nothing):
       rho beyond 1e12 swamps the Dirac operator's O(1/h) entries and the factorisation loses every digit */
    const CSOptionCheck checks[] = {
      {"rho_smooth", smooth, !hassmooth || (smooth > 0 && smooth <= 1e6), "must be a positive time (length^2) up to 1e6"},
      {"rho_scale", scale, PetscAbsReal(scale) <= 1e12, "must lie in [-1e12, 1e12]"},
      {"rho_bump_height", height, PetscAbsReal(height) <= 1e12, "must lie in [-1e12, 1e12]"},
      {"rho_bump_radius", radius, radius > 0 && radius <= 1e6, "must lie in (0, 1e6]"},
      {"rho_mean_curvature", hs, PetscAbsReal(hs) <= 1e6, "must lie in [-1e6, 1e6]"},
    };
    PetscCall(CSCheckOptionValues(mesh->comm, NULL, sizeof(checks) / sizeof(checks[0]), checks));
    for (PetscInt i = 0; i < nc; i++) PetscCheck(PetscAbsReal(centers[i]) <= 1e6, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-rho_bump_center: value %" PetscInt_FMT " is %g, not in [-1e6, 1e6]", i + 1, (double)centers[i]);
  }
  PetscCheck(!hasdisp || !(hastarget || (hasfile && iloc == 1)), mesh->comm, PETSC_ERR_ARG_INCOMP, "-rho_from_displacement gives a per-vertex rho: not with -spin_target_mesh or -rho_location face");
  PetscCheck(!hassmooth || !(hastarget || (hasfile && iloc == 1)), mesh->comm, PETSC_ERR_ARG_INCOMP, "-rho_smooth filters a per-vertex rho: not with -spin_target_mesh or -rho_location face");
  PetscCheck(nc % 3 == 0, mesh->comm, PETSC_ERR_ARG_WRONG, "-rho_bump_center: %" PetscInt_FMT " numbers; need x,y,z triples", nc);
  PetscCheck(radius > 0, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-rho_bump_radius %g: must be positive", (double)radius);
  PetscCheck(!(hastarget && (hasfile || nc || hash)), mesh->comm, PETSC_ERR_ARG_INCOMP, "-spin_target_mesh computes rho itself (crane2011 Sec. 7.2): do not combine it with -rho, -rho_bump_center or -rho_mean_curvature");
  PetscCheck(!(hasfile && iloc == 1 && (nc || hash)), mesh->comm, PETSC_ERR_ARG_INCOMP, "-rho_location face cannot be combined with the per-vertex -rho_bump_center/-rho_mean_curvature");
  if (hastarget) {
    PetscCall(CSMeshLoadCompatiblePositions(mesh, "-spin_target_mesh", target, xtarget));
    PetscCall(DMCreateGlobalVector(dm, mu));
    PetscCall(CSSpinBestFitSimilarities(spin, x, *xtarget, *mu));
    PetscCall(DMCreateGlobalVector(mesh->dmF1, rho));
    PetscCall(CSSpinOptimalRho(spin, x, *mu, *rho));
    *loc = CS_RHO_FACE;
  } else if (hasfile && iloc == 1) {
    PetscCall(DMCreateGlobalVector(mesh->dmF1, rho));
    PetscCall(ReadField(mesh, "-rho", file, 2, 1, "one per face in file order (-rho_location face)", *rho));
    *loc = CS_RHO_FACE;
  } else if (hasfile || nc || hash || hasdisp) {
    PetscCall(DMCreateGlobalVector(mesh->dmV1, rho));
    if (hasfile) PetscCall(ReadField(mesh, "-rho", file, 0, 1, "one per vertex in file order; -rho_location face for one per face", *rho));
    else PetscCall(VecSet(*rho, 0));
    if (nc) PetscCall(PaintBumps(x, nc / 3, centers, radius, height, *rho));
    if (hash) PetscCall(CSSpinRhoAddMeanCurvature(mesh, x, hs, *rho));
    if (hasdisp) {
      Vec g;
      PetscCall(VecDuplicate(*rho, &g));
      PetscCall(CSMeshReadVertexValues(mesh, "-rho_from_displacement", disp, g));
      PetscCall(CSSpinRhoFromDisplacement(spin, x, g, *rho));
      PetscCall(VecDestroy(&g));
    }
    if (hassmooth) PetscCall(CSSpinRhoSmooth(spin, x, smooth, *rho));
    *loc = CS_RHO_VERTEX;
  }
  if (*rho && scale != 1) PetscCall(VecScale(*rho, scale));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDriverSpinBoundaryFromOptions(CSSpin spin, Vec xtarget, Vec *Tt)
{
  CSMesh         mesh;
  CSSpinBoundary b;
  char           file[PETSC_MAX_PATH_LEN] = "";
  PetscBool      has;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetMesh(spin, &mesh));
  PetscCall(CSSpinGetBoundaryType(spin, &b));
  *Tt = NULL;
  PetscOptionsBegin(mesh->comm, NULL, "Spin boundary tangents (crane2011 Sec. 5.7)", NULL);
  PetscCall(CSOptionsString("-spin_boundary_file", "Target boundary tangents: 3 numbers per vertex in file order (read on boundary vertices)", NULL, file, file, sizeof(file), &has));
  PetscOptionsEnd();
  PetscCheck(!has || b == CS_SPIN_BOUNDARY_FILE, mesh->comm, PETSC_ERR_ARG_INCOMP, "-spin_boundary_file needs -spin_boundary file");
  switch (b) {
  case CS_SPIN_BOUNDARY_FILE:
    PetscCheck(has, mesh->comm, PETSC_ERR_ARG_WRONG, "-spin_boundary file needs -spin_boundary_file FILE");
    PetscCall(DMCreateGlobalVector(mesh->dmV3, Tt));
    PetscCall(ReadField(mesh, "-spin_boundary_file", file, 0, 3, "3 per vertex in file order", *Tt));
    break;
  case CS_SPIN_BOUNDARY_TARGET:
    PetscCheck(xtarget, mesh->comm, PETSC_ERR_ARG_WRONG, "-spin_boundary target needs -spin_target_mesh FILE");
    PetscCall(DMCreateGlobalVector(mesh->dmV3, Tt));
    PetscCall(CSGeometryBoundaryTangents(mesh, xtarget, *Tt));
    break;
  default:
    break;
  }
  PetscFunctionReturn(0);
}
