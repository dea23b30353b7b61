/* New positions of a spin transformation (crane2011 Sec. 5.6): the transformed edge vectors e~ (Eq. 8), then
   the least-squares Poisson problem L f~ = div e~ with the cotan Laplacian, per coordinate, KSP prefix
   spin_poisson_ (CHOLMOD Cholesky serially, the substructured CHOLMOD factorisation cssubchol in parallel, by
   default). */
#include "spin_impl.h"

/* b = -sum_j w_ij e~_ij: the gradient of sum_edges w_ij |f_j - f_i - e~_ij|^2 is 2 (L f + sum_j w_ij e~_ij), with
   (L f)_i = sum_j w_ij (f_i - f_j) the positive cotan Laplacian (cs_operators.h). For e~_ij = f_j - f_i this is
   b = L f, so lambda = 1 reproduces the input exactly. */
PetscErrorCode CSSpinPoissonRHS(CSSpin s, Vec x, Vec lambda, Vec b)
{
  CSMesh             mesh = s->mesh;
  Vec                xl, ll;
  CSLocalSum         bs;
  const PetscReal   *p;
  const PetscScalar *l;
  PetscScalar       *ba;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &p));
  PetscCall(DMGetLocalVector(s->dm, &ll));
  PetscCall(DMGlobalToLocal(s->dm, lambda, INSERT_VALUES, ll));
  PetscCall(CSLocalSumBegin(mesh->dmV3, &bs));
  ba = bs.a;
  PetscCall(VecGetArrayRead(ll, &l));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, p, &F);) {
    const PetscInt *v = F.v;
    PetscReal       cot[3];
    CSTriangleCotans(F.c, cot);
    for (int k = 0; k < 3; k++) {
      PetscInt  i = v[(k + 1) % 3], j = v[(k + 2) % 3];
      PetscReal e[3], et[3], li[4], lj[4], w = 0.5 * cot[k];
      CSVecSub(p + 3 * j, p + 3 * i, e);
      for (int q = 0; q < 4; q++) {
        li[q] = PetscRealPart(l[4 * i + q]);
        lj[q] = PetscRealPart(l[4 * j + q]);
      }
      CSSpinTransformedEdge(li, lj, e, et);
      for (int d = 0; d < 3; d++) {
        ba[3 * i + d] -= w * et[d];
        ba[3 * j + d] += w * et[d];
      }
    }
  }
  PetscCall(VecRestoreArrayRead(ll, &l));
  PetscCall(CSLocalSumEnd(&bs, b));
  PetscCall(DMRestoreLocalVector(s->dm, &ll));
  PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &p));
  PetscFunctionReturn(0);
}

/* The KSP of the Poisson solves, prefix "<spin prefix>poisson_", made once and kept for the next solves */
static PetscErrorCode PoissonKSPCreate(CSSpin s)
{
  PC   pc;
  char prefix[256];
  PetscFunctionBeginUser;
  PetscCall(CSSpinSubPrefix(s, "poisson_", prefix, sizeof(prefix)));
  PetscCall(KSPCreate(s->mesh->comm, &s->kpois));
  PetscCall(KSPSetOptionsPrefix(s->kpois, prefix));
  PetscCall(KSPGetPC(s->kpois, &pc));
  /* a Cholesky factorisation (CHOLMOD; the substructured cssubchol on several ranks): serially 2-3x faster than
     CG + GAMG at 4k-38k vertices (runs/bench_spin.sh) */
  PetscCall(KSPSetType(s->kpois, KSPPREONLY));
  PetscCall(CSSetDefaultCholesky(pc));
  PetscCall(KSPSetTolerances(s->kpois, 1e-12, 1e-14, PETSC_DEFAULT, 1000));
  PetscCall(KSPSetFromOptions(s->kpois));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinReconstruct(CSSpin s, Vec x, Vec lambda, Vec xcenter, Vec xnew)
{
  CSMesh         mesh = s->mesh;
  Vec            b, b1, u1;
  PetscMPIInt    rank;
  PetscInt       row = 0;
  PetscReal      shift[3];
  PetscLogDouble t0, t1, c0, c1;
  PetscFunctionBeginUser;
  PetscCall(CSSpinLogPoissonBegin());
  PetscCall(PetscTime(&t0));
  c0 = CSSpinCPUTime();
  PetscCallMPI(MPI_Comm_rank(mesh->comm, &rank));
  PetscCall(DMCreateGlobalVector(mesh->dmV3, &b));
  PetscCall(CSSpinPoissonRHS(s, x, lambda, b));
  /* L has the constants in its kernel and b _|_ 1 (every edge adds +-w e~): the system is consistent. Solve it
     with the first global vertex pinned at 0 (row and column 0 replaced by the identity), which keeps every
     other equation and makes the matrix SPD for any solver (CG + AMG, or a Cholesky factorisation), then place
     the translation: vertex mean of xcenter (default) or vertex 0 at its xcenter position (-spin_pin_vertex). */
  PetscCall(CSOperatorLaplacian(mesh, x, s->L ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->L));
  PetscCall(MatZeroRowsColumns(s->L, rank ? 0 : 1, &row, 1.0, NULL, NULL));
  if (!s->kpois) PetscCall(PoissonKSPCreate(s));
  PetscCall(KSPSetOperators(s->kpois, s->L, s->L));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &b1));
  PetscCall(VecDuplicate(b1, &u1));
  s->poisson_its = 0;
  for (PetscInt d = 0; d < 3; d++) {
    KSPConvergedReason reason;
    PetscInt           its;
    PetscCall(VecStrideGather(b, d, b1, INSERT_VALUES));
    if (!rank) PetscCall(VecSetValue(b1, 0, 0.0, INSERT_VALUES));
    PetscCall(VecAssemblyBegin(b1));
    PetscCall(VecAssemblyEnd(b1));
    PetscCall(VecSet(u1, 0));
    PetscCall(KSPSolve(s->kpois, b1, u1));
    PetscCall(KSPGetConvergedReason(s->kpois, &reason));
    PetscCheck(reason > 0, mesh->comm, PETSC_ERR_NOT_CONVERGED, "spin: the Poisson solve (coordinate %" PetscInt_FMT ") did not converge (KSP reason %s; options -%spoisson_ksp_*, -%spoisson_pc_*). Nothing was written.", d, KSPConvergedReasons[reason], s->hdr.prefix, s->hdr.prefix);
    PetscCall(KSPGetIterationNumber(s->kpois, &its));
    s->poisson_its += its;
    PetscCall(VecStrideScatter(u1, d, xnew, INSERT_VALUES));
  }
  if (s->pin) {
    const PetscScalar *xc;
    PetscCall(VecGetArrayRead(xcenter, &xc));
    if (!rank)
      for (int d = 0; d < 3; d++) shift[d] = PetscRealPart(xc[d]);
    PetscCall(VecRestoreArrayRead(xcenter, &xc));
    PetscCallMPI(MPI_Bcast(shift, 3, MPIU_REAL, 0, mesh->comm));
  } else {
    for (PetscInt d = 0; d < 3; d++) {
      PetscScalar sc, sn;
      PetscCall(VecStrideSum(xcenter, d, &sc));
      PetscCall(VecStrideSum(xnew, d, &sn));
      shift[d] = PetscRealPart(sc - sn) / mesh->Nv;
    }
  }
  for (PetscInt d = 0; d < 3; d++) {
    PetscCall(VecStrideGather(xnew, d, u1, INSERT_VALUES));
    PetscCall(VecShift(u1, shift[d]));
    PetscCall(VecStrideScatter(u1, d, xnew, INSERT_VALUES));
  }
  PetscCall(VecDestroy(&b));
  PetscCall(VecDestroy(&b1));
  PetscCall(VecDestroy(&u1));
  PetscCall(PetscTime(&t1));
  c1           = CSSpinCPUTime();
  s->t_poisson = t1 - t0;
  s->c_poisson = c1 - c0;
  PetscCall(CSSpinLogPoissonEnd());
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinRestoreArea(CSSpin s, Vec xref, Vec xnew)
{
  PetscReal a0, a1, v, f;
  Vec       u;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryAreaVolume(s->mesh, xref, &a0, &v));
  PetscCall(CSGeometryAreaVolume(s->mesh, xnew, &a1, &v));
  PetscCheck(a1 > 0, s->mesh->comm, PETSC_ERR_NOT_CONVERGED, "spin: the new surface has zero area");
  f = PetscSqrtReal(a0 / a1);
  PetscCall(DMGetGlobalVector(s->mesh->dmV1, &u));
  for (PetscInt d = 0; d < 3; d++) {
    PetscScalar sn;
    PetscCall(VecStrideSum(xnew, d, &sn));
    PetscCall(VecStrideGather(xnew, d, u, INSERT_VALUES));
    PetscCall(VecShift(u, -sn / s->mesh->Nv));
    PetscCall(VecScale(u, f));
    PetscCall(VecShift(u, sn / s->mesh->Nv));
    PetscCall(VecStrideScatter(u, d, xnew, INSERT_VALUES));
  }
  PetscCall(DMRestoreGlobalVector(s->mesh->dmV1, &u));
  PetscFunctionReturn(0);
}
