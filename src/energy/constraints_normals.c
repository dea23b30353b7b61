/* Boundary-face normal constraint of soliman2021 App. D ("First-order boundary conditions"). */
#include "cs_constraints.h"

PetscErrorCode CSNormalConstraintCreate(CSMesh m, Vec x0, const PetscBool fixed[], CSNormalConstraint *nc)
{
  PetscInt nb = 0, *rows, rstart;
  ISLocalToGlobalMapping rmap, cmap;
  Vec      vV;
  PetscInt nV;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(nc, sizeof(*nc)));
  nc->mesh  = m;
  nc->fixed = fixed;
  PetscCall(PetscMalloc1(m->nf, &nc->faces));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);)
    if (m->edgeBoundary[F.e[0]] || m->edgeBoundary[F.e[1]] || m->edgeBoundary[F.e[2]]) nc->faces[nb++] = F.f;
  nc->nb = nb;
  PetscCall(VecCreateMPI(m->comm, 3 * nb, PETSC_DETERMINE, &nc->N0));
  PetscCall(VecSet(nc->N0, 0));
  {
    Vec t;
    PetscCall(VecDuplicate(nc->N0, &t));
    PetscCall(CSNormalConstraintEvaluate(nc, x0, t, PETSC_FALSE)); /* N(x0) - 0 */
    PetscCall(VecCopy(t, nc->N0));
    PetscCall(VecDestroy(&t));
  }
  PetscCall(DMGetGlobalVector(m->dmV3, &vV));
  PetscCall(VecGetLocalSize(vV, &nV));
  PetscCall(DMRestoreGlobalVector(m->dmV3, &vV));
  PetscCall(MatCreateAIJ(m->comm, 3 * nb, nV, PETSC_DETERMINE, PETSC_DETERMINE, 9, NULL, 9, NULL, &nc->DN));
  PetscCall(MatGetOwnershipRange(nc->DN, &rstart, NULL));
  PetscCall(PetscMalloc1(3 * nb, &rows));
  for (PetscInt i = 0; i < 3 * nb; i++) rows[i] = rstart + i;
  PetscCall(ISLocalToGlobalMappingCreate(m->comm, 1, 3 * nb, rows, PETSC_OWN_POINTER, &rmap));
  PetscCall(DMGetLocalToGlobalMapping(m->dmV3, &cmap));
  PetscCall(MatSetLocalToGlobalMapping(nc->DN, rmap, cmap));
  PetscCall(ISLocalToGlobalMappingDestroy(&rmap));
  PetscFunctionReturn(0);
}

PetscErrorCode CSNormalConstraintEvaluate(CSNormalConstraint *nc, Vec x, Vec c, PetscBool wantJ)
{
  CSMesh             m = nc->mesh;
  Vec                xl;
  const PetscReal   *p;
  PetscScalar       *ca;
  const PetscScalar *n0;
  PetscFunctionBeginUser;
  if (wantJ) PetscCall(MatZeroEntries(nc->DN));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(VecGetArray(c, &ca));
  PetscCall(VecGetArrayRead(nc->N0, &n0));
  for (PetscInt b = 0; b < nc->nb; b++) {
    const PetscInt  *v     = m->faceVert + 3 * nc->faces[b];
    const PetscReal *pc[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    PetscReal        N[3], A = CSTriangleNormal(pc, N);
    for (int d = 0; d < 3; d++) ca[3 * b + d] = N[d] - n0[3 * b + d];
    if (wantJ) {
      for (int i = 0; i < 3; i++) {
        PetscReal   e[3], w[3];
        PetscScalar blk[9];
        PetscInt    rows[3] = {3 * b, 3 * b + 1, 3 * b + 2}, cols[3] = {3 * v[i], 3 * v[i] + 1, 3 * v[i] + 2};
        if (nc->fixed && nc->fixed[v[i]]) continue;
        CSVecSub(pc[(i + 2) % 3], pc[(i + 1) % 3], e); /* e_jk = f_k - f_j, the edge opposite i */
        CSVecCross(N, e, w);
        for (int r = 0; r < 3; r++)
          for (int q = 0; q < 3; q++) blk[3 * r + q] = -w[r] * N[q] / (2 * A);
        PetscCall(MatSetValuesLocal(nc->DN, 3, rows, 3, cols, blk, INSERT_VALUES));
      }
    }
  }
  PetscCall(VecRestoreArrayRead(nc->N0, &n0));
  PetscCall(VecRestoreArray(c, &ca));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  if (wantJ) {
    PetscCall(MatAssemblyBegin(nc->DN, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(nc->DN, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSNormalConstraintMetric(CSNormalConstraint *nc, Vec x, Vec iq)
{
  CSMesh           m = nc->mesh;
  Vec              xl;
  const PetscReal *p;
  PetscScalar     *a;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(VecGetArray(iq, &a));
  for (PetscInt b = 0; b < nc->nb; b++) {
    const PetscInt  *v     = m->faceVert + 3 * nc->faces[b];
    const PetscReal *pc[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
    PetscReal        an[3];
    CSTriangleAreaVector(pc, an);
    for (int d = 0; d < 3; d++) a[3 * b + d] = 1.0 / (2 * CSVecNorm(an));
  }
  PetscCall(VecRestoreArray(iq, &a));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSNormalConstraintDestroy(CSNormalConstraint *nc)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(nc->faces));
  PetscCall(VecDestroy(&nc->N0));
  PetscCall(MatDestroy(&nc->DN));
  PetscFunctionReturn(0);
}
