/* Where rho comes from: a file (one value per vertex or per face, in file order), a painted bump, the mean
   curvature (rho = s H; crane2011 Sec. 7.3 uses rho = -H for minimal surfaces), or the nearest spin
   transformation of an arbitrary deformation (crane2011 Sec. 7.2). */
#include "cs_methods_spin.h"
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

/* Reads a per-vertex (ncomp 1 or 3) or per-face field in file order into the global vector g. */
static PetscErrorCode ReadField(CSMesh mesh, const char option[], const char path[], PetscInt depth, PetscInt ncomp, const char what[], Vec g)
{
  CSMeshNatural *field = depth == 2 ? &mesh->natF1 : (ncomp == 3 ? &mesh->natV3 : &mesh->natV1);
  PetscScalar   *a;
  PetscInt       n = depth == 2 ? mesh->Nf : mesh->Nv;
  PetscFunctionBeginUser;
  PetscCall(VecGetArray(field->vec, &a));
  CSRootCall(mesh->comm, ReadValuesFile(option, path, n, ncomp, what, a));
  PetscCall(VecRestoreArray(field->vec, &a));
  PetscCall(CSMeshScatter(field, field->vec, g));
  PetscFunctionReturn(0);
}

/* rho += s H with the signed pointwise mean curvature H_i = (L f)_i . N_i / (2 M_i) (positive on a sphere with
   outward normals; (L f)_i ~ 2 H N M_i for the positive cotan Laplacian). crane2011 Sec. 7.3 takes |HN| = |Lf|,
   which loses the sign on saddle-shaped regions; the projection on the vertex normal keeps it. */
PetscErrorCode CSSpinRhoAddMeanCurvature(CSMesh mesh, Vec x, PetscReal s, Vec rho)
{
  Vec H;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(mesh->dmV1, &H));
  PetscCall(CSGeometrySignedMeanCurvature(mesh, x, H, NULL, NULL));
  PetscCall(VecAXPY(rho, s, H));
  PetscCall(DMRestoreGlobalVector(mesh->dmV1, &H));
  PetscFunctionReturn(0);
}

/* crane2011 Sec. 7.2: per face the best-fit similarity S = sqrt(det Y) A2^{-1} R A1 (B = R Y the polar
   decomposition of the planar map), as a quaternion l with conj(l) v l = S v, averaged to vertices with the
   source face areas. The sign of l is chosen with l_w >= 0 (rotation angles <= pi), so that neighbouring faces
   agree unless the deformation rotates them by about pi. */
PetscErrorCode CSSpinBestFitSimilarities(CSSpin spin, Vec x, Vec xt, Vec mu)
{
  CSMesh             mesh = spin->mesh;
  Vec                xl, tl, w;
  CSLocalSum         ms, ws;
  const PetscReal   *pa, *qa;
  const PetscScalar *wg;
  PetscScalar       *mg;
  PetscInt           n, nflip = 0;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &pa));
  PetscCall(CSMeshGetLocalPositions(mesh, xt, &tl, &qa));
  PetscCall(CSLocalSumBegin(spin->dm, &ms));
  PetscCall(CSLocalSumBegin(mesh->dmV1, &ws));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, pa, &F);) {
    const PetscInt  *v    = F.v;
    const PetscReal *d[3] = {qa + 3 * v[0], qa + 3 * v[1], qa + 3 * v[2]};
    PetscReal        A1[9], A2[9], s[4], t[4], B[4], detS, detB, phi, R2[9], R3[9], q[4], l[4], scale, an[3], area;
    CSTriangleFrame(F.c, A1, s);
    CSTriangleFrame(d, A2, t);
    /* B [s1 s2] = [t1 t2] */
    detS = s[0] * s[3] - s[2] * s[1];
    B[0] = (t[0] * s[3] - t[2] * s[1]) / detS;
    B[1] = (-t[0] * s[2] + t[2] * s[0]) / detS;
    B[2] = (t[1] * s[3] - t[3] * s[1]) / detS;
    B[3] = (-t[1] * s[2] + t[3] * s[0]) / detS;
    detB = B[0] * B[3] - B[1] * B[2];
    if (detB <= 0) nflip++;
    /* rotation of the polar decomposition of a 2x2 map with det > 0 */
    phi   = PetscAtan2Real(B[2] - B[1], B[0] + B[3]);
    scale = PetscSqrtReal(PetscAbsReal(detB)); /* sqrt(det Y): geometric mean of the principal stretches */
    for (int k = 0; k < 9; k++) R2[k] = 0;
    R2[0] = PetscCosReal(phi);
    R2[1] = -PetscSinReal(phi);
    R2[3] = PetscSinReal(phi);
    R2[4] = PetscCosReal(phi);
    R2[8] = 1;
    /* R3 = A2^T R2 A1 */
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        PetscReal sum = 0;
        for (int k = 0; k < 3; k++)
          for (int m = 0; m < 3; m++) sum += A2[3 * k + i] * R2[3 * k + m] * A1[3 * m + j];
        R3[3 * i + j] = sum;
      }
    CSQuatFromRotation(R3, q); /* q v conj(q) = R3 v, so l = sqrt(scale) conj(q) gives conj(l) v l = scale R3 v */
    CSQuatConj(q, l);
    if (l[0] < 0)
      for (int k = 0; k < 4; k++) l[k] = -l[k];
    CSTriangleAreaVector(F.c, an);
    area = CSVecNorm(an);
    for (int k = 0; k < 3; k++) {
      for (int m = 0; m < 4; m++) ms.a[4 * v[k] + m] += area * PetscSqrtReal(scale) * l[m];
      ws.a[v[k]] += area;
    }
  }
  PetscCall(CSMeshRestoreLocalPositions(mesh, xt, &tl, &qa));
  PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &pa));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &w));
  PetscCall(CSLocalSumEnd(&ms, mu));
  PetscCall(CSLocalSumEnd(&ws, w));
  PetscCall(VecGetLocalSize(w, &n));
  PetscCall(VecGetArrayRead(w, &wg));
  PetscCall(VecGetArray(mu, &mg));
  for (PetscInt i = 0; i < n; i++)
    for (int m = 0; m < 4; m++) mg[4 * i + m] /= wg[i];
  PetscCall(VecRestoreArray(mu, &mg));
  PetscCall(VecRestoreArrayRead(w, &wg));
  PetscCall(VecDestroy(&w));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &nflip, 1, MPIU_INT, MPI_SUM, mesh->comm));
  if (nflip) PetscCall(PetscPrintf(mesh->comm, "Warning: -spin_target_mesh: %" PetscInt_FMT " face(s) are flipped (orientation-reversing map); their similarity uses |det|\n", nflip));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinOptimalRho(CSSpin spin, Vec x, Vec mu, Vec rho)
{
  CSMesh       mesh = spin->mesh;
  PetscReal   *Dmu, *Bmu;
  PetscScalar *r;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(4 * mesh->nf, &Dmu, 4 * mesh->nf, &Bmu));
  PetscCall(CSDiracFaceApply(mesh, spin->dm, x, mu, Dmu, Bmu));
  PetscCall(VecGetArray(rho, &r));
  for (PetscInt f = 0; f < mesh->nf; f++) {
    /* argmin_rho |(D mu)_k - rho (B mu)_k|^2 = Re(conj(B mu) D mu) / |B mu|^2, and Re(conj(p) q) = p . q */
    PetscReal num = 0, den = 0;
    for (int c = 0; c < 4; c++) {
      num += Bmu[4 * f + c] * Dmu[4 * f + c];
      den += Bmu[4 * f + c] * Bmu[4 * f + c];
    }
    r[f] = den > 0 ? num / den : 0;
  }
  PetscCall(VecRestoreArray(rho, &r));
  PetscCall(PetscFree2(Dmu, Bmu));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinRhoFromOptions(CSSpin spin, Vec x, CSRhoLocation *loc, Vec *rho, Vec *xtarget, Vec *mu)
{
  CSMesh      mesh = spin->mesh;
  char        file[PETSC_MAX_PATH_LEN] = "", target[PETSC_MAX_PATH_LEN] = "";
  const char *locs[]                   = {"vertex", "face"};
  PetscInt    iloc = 0, nc = 30;
  PetscReal   scale = 1, centers[30], radius = 0.3, height = 1, hs = 0, smooth = 0;
  PetscBool   hasfile, hastarget, hasbump, hash, hasdisp, hassmooth;
  char        disp[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
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
    PetscCall(DMCreateGlobalVector(spin->dm, mu));
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
    if (nc) {
      const PetscScalar *p;
      PetscScalar       *r;
      PetscInt           n;
      PetscCall(VecGetLocalSize(*rho, &n));
      PetscCall(VecGetArrayRead(x, &p));
      PetscCall(VecGetArray(*rho, &r));
      for (PetscInt i = 0; i < n; i++)
        for (PetscInt b = 0; b < nc / 3; b++) {
          PetscReal d2 = 0;
          for (int d = 0; d < 3; d++) d2 += PetscSqr(PetscRealPart(p[3 * i + d]) - centers[3 * b + d]);
          r[i] += height * PetscExpReal(-d2 / (radius * radius));
        }
      PetscCall(VecRestoreArray(*rho, &r));
      PetscCall(VecRestoreArrayRead(x, &p));
    }
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

PetscErrorCode CSSpinBoundaryFromOptions(CSSpin spin, Vec xtarget, Vec *Tt)
{
  CSMesh    mesh                     = spin->mesh;
  char      file[PETSC_MAX_PATH_LEN] = "";
  PetscBool has;
  PetscFunctionBeginUser;
  *Tt = NULL;
  PetscOptionsBegin(mesh->comm, NULL, "Spin boundary tangents (crane2011 Sec. 5.7)", NULL);
  PetscCall(CSOptionsString("-spin_boundary_file", "Target boundary tangents: 3 numbers per vertex in file order (read on boundary vertices)", NULL, file, file, sizeof(file), &has));
  PetscOptionsEnd();
  PetscCheck(!has || spin->boundary == CS_SPIN_BOUNDARY_FILE, mesh->comm, PETSC_ERR_ARG_INCOMP, "-spin_boundary_file needs -spin_boundary file");
  switch (spin->boundary) {
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
