/* The lens complex of soliman2021 Sec. 5 / App. A as halfedge fields on the edges (include/cs_operators_lens.h):
   the averaging map A~, the length multi-ratio map C~ and the lens integrability d1. */
#include "cs_operators_lens.h"
#include "cs_mesh_adjacency.h"

PetscErrorCode CSLensCreateHalfedgeDM(CSMesh m, PetscInt dof, DM *dmH)
{
  PetscFunctionBeginUser;
  PetscCall(CSMeshCreateFieldDM(m->dm, 1, 2 * dof, dof == 1 ? "halfedge" : "halfedge_vector", dmH));
  PetscFunctionReturn(0);
}

/* (A~ u)_(e,s) = (u_i + u_j)/2 for both halfedges of every owned edge. */
PetscErrorCode CSOperatorLensAverage(CSMesh m, DM dmH, Mat *A)
{
  PetscFunctionBeginUser;
  PetscCall(CSOperatorCreatePointMatrix(dmH, m->dmV1, 2, A));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscScalar v[2] = {0.5, 0.5};
    if (!m->edgeOwned[e]) continue;
    for (PetscInt s = 0; s < 2; s++) {
      PetscInt row = 2 * e + s;
      PetscCall(MatSetValuesLocal(*A, 1, &row, 2, m->edgeVert + 2 * e, v, INSERT_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* (C~ lambda)_ij = (lambda_jk - lambda_ki) + (lambda_il - lambda_lj) + (lambda_ji - lambda_ij): the first bracket
   is next minus previous of ij in its face ijk, the second next minus previous of ji in its face jil. So each
   face adds, for each of its halfedges h with next n and previous p, +1 at n and -1 at p to the rows of h and of
   twin(h); every owned edge adds the last bracket to its two rows.
   The printed per-face matrix Eq. 30 has rows jk and ki of Eq. 24 (0 on the diagonal) and only row ij changed to
   (-1, 1, -1): that is not invariant under relabelling the face (ij -> jk -> ki) and does not give Eq. 14's
   log m, whose halfedge term lambda_ji - lambda_ij couples the two faces of an edge. We assemble Eq. 14 as
   written; tests/unit/test_lens.c checks C~ A~ = 0 and rank C~ = |H| - |V| (Lemma A.1). */
PetscErrorCode CSOperatorLensCrossRatio(CSMesh m, DM dmH, Mat *C)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscCall(CSOperatorCreatePointMatrix(dmH, dmH, 6, C));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscInt h[3];
    for (int a = 0; a < 3; a++) h[a] = 2 * F.e[a] + CSMeshEdgeSide(m, &F, a);
    for (int a = 0; a < 3; a++) {
      PetscInt    rows[2] = {h[a], h[a] ^ 1}, cols[2] = {h[(a + 1) % 3], h[(a + 2) % 3]}; /* h ^ 1: the twin */
      PetscScalar v[4]    = {1.0, -1.0, 1.0, -1.0};
      PetscCall(MatSetValuesLocal(*C, 2, rows, 2, cols, v, ADD_VALUES));
    }
  }
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt    rc[2] = {2 * e, 2 * e + 1};
    PetscScalar v[4]  = {-1.0, 1.0, 1.0, -1.0};
    if (!m->edgeOwned[e]) continue;
    PetscCall(MatSetValuesLocal(*C, 2, rc, 2, rc, v, ADD_VALUES));
  }
  PetscCall(MatAssemblyBegin(*C, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*C, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* (d1 omega)_e = -(omega_(e,0) + omega_(e,1)) (Sec. 5.1; Eq. 31's +-1 with the lens oriented so). */
PetscErrorCode CSOperatorLensD1(CSMesh m, DM dmH, Mat *d1)
{
  PetscFunctionBeginUser;
  PetscCall(CSOperatorCreatePointMatrix(m->dmE1, dmH, 2, d1));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt    cols[2] = {2 * e, 2 * e + 1};
    PetscScalar v[2]    = {-1.0, -1.0};
    if (!m->edgeOwned[e]) continue;
    PetscCall(MatSetValuesLocal(*d1, 1, &e, 2, cols, v, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*d1, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*d1, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* The harmonic dual 1-form Y of an edge 1-form eta on halfedges (soliman2021 Eq. 13, Algorithm 2 step 2):
   y_h = 1/2 cot(theta_h) eta(h), theta_h the angle opposite h in its face at positions x and eta(h) = +-eta_e
   by the halfedge's direction, so that <<Y|omega>> = sum_h y_h omega_h is the L2 product of Sec. 5.1 (the
   cotan formula per face, polarised) and, for omega = df, sum_e w_e eta_e (df)_e = <<eta, df>>. */
static void AddHalfCotanDual(CSMesh m, const PetscReal *p, const CSFaceIter *F, PetscScalar *a)
{
  PetscReal cot[3];
  CSTriangleCotans(F->c, cot);
  for (int k = 0; k < 3; k++) a[2 * F->e[k] + CSMeshEdgeSide(m, F, k)] += 0.5 * cot[k];
}

PetscErrorCode CSLensHarmonicDual(CSMesh m, Vec x, Vec eta, DM dmH1, Vec y)
{
  Vec                el, yl;
  const PetscScalar *e;
  PetscScalar       *a;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryFaceSum(m, x, dmH1, AddHalfCotanDual, y));
  PetscCall(DMGetLocalVector(m->dmE1, &el));
  PetscCall(DMGlobalToLocal(m->dmE1, eta, INSERT_VALUES, el));
  PetscCall(DMGetLocalVector(dmH1, &yl));
  PetscCall(DMGlobalToLocal(dmH1, y, INSERT_VALUES, yl));
  PetscCall(VecGetArrayRead(el, &e));
  PetscCall(VecGetArray(yl, &a));
  for (PetscInt k = 0; k < m->ne; k++) {
    a[2 * k] *= e[k];
    a[2 * k + 1] *= -e[k];
  }
  PetscCall(VecRestoreArray(yl, &a));
  PetscCall(VecRestoreArrayRead(el, &e));
  PetscCall(DMLocalToGlobal(dmH1, yl, INSERT_VALUES, y));
  PetscCall(DMRestoreLocalVector(dmH1, &yl));
  PetscCall(DMRestoreLocalVector(m->dmE1, &el));
  PetscFunctionReturn(0);
}

/* The lens d0 (H x V): (d0 u)_h = u_head - u_tail, i.e. (e, 0): u_j - u_i and (e, 1): u_i - u_j for
   e = (i -> j); d0 of the positions per component is the triangle field df. */
PetscErrorCode CSOperatorLensD0(CSMesh m, DM dmH, Mat *d0)
{
  PetscFunctionBeginUser;
  PetscCall(CSOperatorCreatePointMatrix(dmH, m->dmV1, 2, d0));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscScalar v[2][2] = {{-1.0, 1.0}, {1.0, -1.0}};
    if (!m->edgeOwned[e]) continue;
    for (PetscInt s = 0; s < 2; s++) {
      PetscInt row = 2 * e + s;
      PetscCall(MatSetValuesLocal(*d0, 1, &row, 2, m->edgeVert + 2 * e, v[s], INSERT_VALUES));
    }
  }
  PetscCall(MatAssemblyBegin(*d0, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*d0, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* I_H1 = *1 + *1 d0 *0^{-1} d0^T *1 (soliman2021 Eq. 32) on halfedges, scalar (H x H), from the stars of
   CSTriangleFieldStars: B = *1 d0 (rows scaled), H1 = B *0^{-1} B^T + diag(*1). As *1 itself it is indefinite
   where a triangle has an obtuse angle opposite a halfedge whose other side does not compensate (cot < 0). */
PetscErrorCode CSOperatorLensH1Metric(CSMesh m, DM dmH, Vec star1, Vec star0, Mat *H1)
{
  Mat B, Bs;
  Vec s0i;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscCall(CSOperatorLensD0(m, dmH, &B));
  PetscCall(MatDiagonalScale(B, star1, NULL));
  PetscCall(MatDuplicate(B, MAT_COPY_VALUES, &Bs));
  PetscCall(VecDuplicate(star0, &s0i));
  PetscCall(VecCopy(star0, s0i));
  PetscCall(VecReciprocal(s0i));
  PetscCall(MatDiagonalScale(Bs, NULL, s0i));
  PetscCall(MatMatTransposeMult(Bs, B, MAT_INITIAL_MATRIX, PETSC_DEFAULT, H1));
  PetscCall(MatDiagonalSet(*H1, star1, ADD_VALUES));
  PetscCall(MatDestroy(&B));
  PetscCall(MatDestroy(&Bs));
  PetscCall(VecDestroy(&s0i));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Dlambda on halfedges (soliman2021 Sec. 5.2): lambda-dot_h = <omega_h, omega-dot_h> / |omega_h|^2, H x 3H (rows
   dmH1, columns dmH3). Rows set by the edge's owner; MAT_REUSE_MATRIX refills *D. */
PetscErrorCode CSOperatorLensLogLengthDerivative(CSMesh m, DM dmH1, DM dmH3, Vec omega, MatReuse reuse, Mat *D)
{
  Vec                ol;
  const PetscScalar *o;
  PetscFunctionBeginUser;
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(CSOperatorCreatePointMatrix(dmH1, dmH3, 3, D));
  else PetscCall(MatZeroEntries(*D));
  PetscCall(DMGetLocalVector(dmH3, &ol));
  PetscCall(DMGlobalToLocal(dmH3, omega, INSERT_VALUES, ol));
  PetscCall(VecGetArrayRead(ol, &o));
  for (PetscInt e = 0; e < m->ne; e++) {
    if (!m->edgeOwned[e]) continue;
    for (PetscInt h = 2 * e; h < 2 * e + 2; h++) {
      PetscReal   w[3] = {PetscRealPart(o[3 * h]), PetscRealPart(o[3 * h + 1]), PetscRealPart(o[3 * h + 2])}, l2 = CSVecDot(w, w);
      PetscInt    cols[3] = {3 * h, 3 * h + 1, 3 * h + 2};
      PetscScalar v[3]    = {w[0] / l2, w[1] / l2, w[2] / l2};
      PetscCall(MatSetValuesLocal(*D, 1, &h, 3, cols, v, INSERT_VALUES));
    }
  }
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(DMRestoreLocalVector(dmH3, &ol));
  PetscCall(MatAssemblyBegin(*D, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*D, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* Face closure (Sec. 5.1: the three halfedge vectors of a triangle sum to zero): F x H, (S omega)_f = sum of the
   face's three halfedges, scalar (per component of a triangle field). Every local face is owned (overlap 0). */
PetscErrorCode CSOperatorLensFaceClosure(CSMesh m, DM dmH, Mat *S)
{
  PetscFunctionBeginUser;
  PetscCall(CSOperatorCreatePointMatrix(m->dmF1, dmH, 3, S));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscInt    h[3];
    PetscScalar v[3] = {1.0, 1.0, 1.0};
    for (int a = 0; a < 3; a++) h[a] = 2 * F.e[a] + CSMeshEdgeSide(m, &F, a);
    PetscCall(MatSetValuesLocal(*S, 1, &F.f, 3, h, v, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*S, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*S, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}
