/* rho from the geometry: the mean curvature (rho = s H; crane2011 Sec. 7.3 uses rho = -H for minimal surfaces)
   and the nearest spin transformation of an arbitrary deformation (crane2011 Sec. 7.2: best-fit similarities,
   optimal rho). The files and options that choose rho are read by the driver (src/driver/spin_input.c). */
#include "spin_impl.h"
#include "cs_util.h"

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
