/* Boundary conditions of the conformal flow (crane2013 Sec. 6.3), -flow_boundary none|vector|fixed:
     vector (6.3.1): per boundary vertex the frame N, T, B := T x N (T the unit boundary tangent, the outgoing
       boundary edge; N the vertex normal made orthogonal to T); V = cN N + cT T + cB B (-flow_boundary_frame,
       default B); the boundary lambda is restricted to lambda_theta = (cos th/2 - w sin th/2)(a - b V~) with
       w = V x V~ / |V x V~|, the two real unknowns a, b per boundary vertex (crane2011 Sec. 5.7's reduced space in
       CSSpin, generalised from T to V). V~ = V of -flow_target_mesh, or V~ = V (the current directions kept).
       V = +-N is refused: Eq. 5 is not elliptic there (Bohle and Pinkall 2013, quoted in Sec. 6.3.1).
     fixed (6.3.2): target boundary positions (-flow_target_mesh, or the input's); the boundary lambda maps the
       current tangents T to the target's T~ (the same reduced space with V = T), and the Poisson problem for
       f~ takes the target positions as Dirichlet values on the boundary vertices.
   Where we differ from the paper: Sec. 6.3.2 fixes lambda on the boundary completely (T -> T~ and N parallel to N~,
   moved to the right-hand side of a least-squares problem); we fix only T -> T~ and leave the rotation about T~ and
   the scale (a, b) to the eigenproblem; the positions are met exactly either way (the Dirichlet values).
   The cotan H of a boundary vertex is not a curvature (its Lf holds the boundary's geodesic curvature term); the
   flow uses there the mean of H over its interior neighbours. */
#include "conformal_impl.h"
#include "cs_operators.h"

const char *const CSConformalBoundaries[] = {"none", "vector", "fixed", "CSConformalBoundary", "CS_CONFORMAL_BOUNDARY_", NULL};

/* flag = 1 on boundary vertices, 0 elsewhere (dmV1 global) */
static PetscErrorCode BoundaryFlag(CSConformalFlow F, Vec flag)
{
  CSMesh     m = F->mesh;
  CSLocalSum fs;
  PetscFunctionBeginUser;
  PetscCall(CSLocalSumBegin(m->dmV1, &fs));
  for (CSFaceIter f = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &f);)
    for (int k = 0; k < 3; k++)
      if (m->vertBoundary[f.v[k]]) fs.a[f.v[k]] += 1;
  PetscCall(CSLocalSumEnd(&fs, flag));
  {
    PetscScalar *a;
    PetscInt     n;
    PetscCall(VecGetLocalSize(flag, &n));
    PetscCall(VecGetArray(flag, &a));
    for (PetscInt i = 0; i < n; i++) a[i] = PetscRealPart(a[i]) > 0 ? 1 : 0;
    PetscCall(VecRestoreArray(flag, &a));
  }
  PetscFunctionReturn(0);
}

/* the options' checks against the mesh, the target positions and the boundary flag */
PetscErrorCode CSConformalFlowBoundarySetUp(CSConformalFlow F)
{
  CSMesh      m = F->mesh;
  const char *p = F->hdr.prefix;
  char        opt[96];
  PetscFunctionBeginUser;
  PetscCheck(m->topo.boundary_loops == 0 || F->bmode != CS_CONFORMAL_BOUNDARY_NONE, m->comm, PETSC_ERR_ARG_WRONG, "-flow_type conformal: mesh %s has %" PetscInt_FMT " boundary loop(s): choose a boundary condition of crane2013 Sec. 6.3 with -%sboundary vector|fixed", m->name, m->topo.boundary_loops, p);
  PetscCheck(m->topo.boundary_loops > 0 || F->bmode == CS_CONFORMAL_BOUNDARY_NONE, m->comm, PETSC_ERR_ARG_WRONG, "-%sboundary %s: mesh %s has no boundary", p, CSConformalBoundaries[F->bmode], m->name);
  PetscCheck(!F->target[0] || F->bmode != CS_CONFORMAL_BOUNDARY_NONE, m->comm, PETSC_ERR_ARG_INCOMP, "-%starget_mesh %s needs -%sboundary vector|fixed (it gives the boundary targets)", p, F->target, p);
  PetscCheck(F->bmode != CS_CONFORMAL_BOUNDARY_VECTOR || PetscAbsReal(F->frame[1]) + PetscAbsReal(F->frame[2]) > 0, m->comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sboundary_frame %g,%g,%g: V = +-N is not allowed (Eq. 5 is not elliptic there, crane2013 Sec. 6.3.1); give V a T or B component", p, (double)F->frame[0], (double)F->frame[1], (double)F->frame[2]);
  if (F->bmode == CS_CONFORMAL_BOUNDARY_NONE) PetscFunctionReturn(0);
  PetscCheck(m->topo.genus == 0, m->comm, PETSC_ERR_SUP, "-%sboundary %s: mesh %s has genus %" PetscInt_FMT "; boundary conditions are implemented for genus 0 (the exactness constraint of App. C is for closed surfaces)", p, CSConformalBoundaries[F->bmode], m->name, m->topo.genus);
  if (F->target[0]) {
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%starget_mesh", p));
    PetscCall(CSMeshLoadCompatiblePositions(m, opt, F->target, &F->xt));
  } else if (F->bmode == CS_CONFORMAL_BOUNDARY_FIXED) {
    PetscCall(VecDuplicate(F->x0, &F->xt));
    PetscCall(VecCopy(F->x0, F->xt));
  }
  PetscCall(DMCreateGlobalVector(m->dmV1, &F->bflag));
  PetscCall(BoundaryFlag(F, F->bflag));
  F->inversion = PETSC_FALSE; /* App. D's inversions move the boundary: not a symmetry of the boundary problem */
  /* the balancing adds an inversion direction rho = -2 <a, N> (App. E): the same reason */
  PetscCheck(!F->mobius, m->comm, PETSC_ERR_ARG_INCOMP, "-%smobius with -%sboundary %s: Moebius balancing moves the boundary (it adds an inversion), so it is for closed surfaces only", p, p, CSConformalBoundaries[F->bmode]);
  PetscCall(CSSpinSetBoundaryType(F->spin, CS_SPIN_BOUNDARY_KEEP));
  PetscFunctionReturn(0);
}

/* V = cN N + cT T + cB B (normalised) on the boundary vertices of x, 0 elsewhere (dmV3 global) */
static PetscErrorCode BoundaryDirections(CSConformalFlow F, Vec x, const PetscReal c[3], Vec V)
{
  Vec                N;
  const PetscScalar *n;
  PetscScalar       *t;
  PetscInt           nl;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(F->mesh->dmV3, &N));
  PetscCall(CSGeometryVertexNormals(F->mesh, x, N));
  PetscCall(CSGeometryBoundaryTangents(F->mesh, x, V)); /* 0 on interior vertices */
  PetscCall(VecGetLocalSize(V, &nl));
  PetscCall(VecGetArrayRead(N, &n));
  PetscCall(VecGetArray(V, &t));
  for (PetscInt i = 0; i < nl / 3; i++) {
    PetscReal T[3], Nv[3], B[3], v[3], s, l;
    for (int d = 0; d < 3; d++) {
      T[d]  = PetscRealPart(t[3 * i + d]);
      Nv[d] = PetscRealPart(n[3 * i + d]);
    }
    if (CSVecNorm(T) == 0) continue; /* interior */
    s = CSVecDot(Nv, T);
    for (int d = 0; d < 3; d++) Nv[d] -= s * T[d];
    l = CSVecNorm(Nv);
    for (int d = 0; d < 3; d++) Nv[d] /= l;
    CSVecCross(T, Nv, B); /* B := T x N (Sec. 6.3.1) */
    for (int d = 0; d < 3; d++) v[d] = c[0] * Nv[d] + c[1] * T[d] + c[2] * B[d];
    l = CSVecNorm(v);
    for (int d = 0; d < 3; d++) t[3 * i + d] = v[d] / l;
  }
  PetscCall(VecRestoreArray(V, &t));
  PetscCall(VecRestoreArrayRead(N, &n));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmV3, &N));
  PetscFunctionReturn(0);
}

/* Before each eigen solve: V on the current surface, V~ on the target (or V~ = V), handed to CSSpin */
PetscErrorCode CSConformalFlowBoundaryPrepare(CSConformalFlow F)
{
  const PetscReal tangent[3] = {0, 1, 0};
  const PetscReal *c = F->bmode == CS_CONFORMAL_BOUNDARY_FIXED ? tangent : F->frame;
  Vec              V, Vt = NULL;
  PetscFunctionBeginUser;
  if (F->bmode == CS_CONFORMAL_BOUNDARY_NONE) PetscFunctionReturn(0);
  PetscCall(DMGetGlobalVector(F->mesh->dmV3, &V));
  PetscCall(BoundaryDirections(F, F->x, c, V));
  if (F->xt) {
    PetscCall(DMGetGlobalVector(F->mesh->dmV3, &Vt));
    PetscCall(BoundaryDirections(F, F->xt, c, Vt));
  }
  PetscCall(CSSpinSetBoundaryDirections(F->spin, V, Vt));
  if (Vt) PetscCall(DMRestoreGlobalVector(F->mesh->dmV3, &Vt));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmV3, &V));
  PetscFunctionReturn(0);
}

/* H on boundary vertices <- the mean of H over their interior neighbours (each neighbour once per shared face) */
PetscErrorCode CSConformalFlowBoundaryCurvature(CSConformalFlow F)
{
  CSMesh             m = F->mesh;
  Vec                Hl, S, C;
  CSLocalSum         ss, cs;
  const PetscScalar *h, *s, *c, *b;
  PetscScalar       *H;
  PetscInt           n;
  PetscFunctionBeginUser;
  if (F->bmode == CS_CONFORMAL_BOUNDARY_NONE) PetscFunctionReturn(0);
  PetscCall(DMGetLocalVector(m->dmV1, &Hl));
  PetscCall(DMGlobalToLocal(m->dmV1, F->H, INSERT_VALUES, Hl));
  PetscCall(DMGetGlobalVector(m->dmV1, &S));
  PetscCall(DMGetGlobalVector(m->dmV1, &C));
  PetscCall(CSLocalSumBegin(m->dmV1, &ss));
  PetscCall(CSLocalSumBegin(m->dmV1, &cs));
  PetscCall(VecGetArrayRead(Hl, &h));
  for (CSFaceIter f = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &f);)
    for (int k = 0; k < 3; k++)
      for (int j = 0; j < 3; j++)
        if (j != k && m->vertBoundary[f.v[k]] && !m->vertBoundary[f.v[j]]) {
          ss.a[f.v[k]] += h[f.v[j]];
          cs.a[f.v[k]] += 1;
        }
  PetscCall(VecRestoreArrayRead(Hl, &h));
  PetscCall(CSLocalSumEnd(&ss, S));
  PetscCall(CSLocalSumEnd(&cs, C));
  PetscCall(VecGetLocalSize(F->H, &n));
  PetscCall(VecGetArray(F->H, &H));
  PetscCall(VecGetArrayRead(S, &s));
  PetscCall(VecGetArrayRead(C, &c));
  PetscCall(VecGetArrayRead(F->bflag, &b));
  for (PetscInt i = 0; i < n; i++)
    if (PetscRealPart(b[i]) > 0 && PetscRealPart(c[i]) > 0) H[i] = s[i] / c[i];
  PetscCall(VecRestoreArrayRead(F->bflag, &b));
  PetscCall(VecRestoreArrayRead(C, &c));
  PetscCall(VecRestoreArrayRead(S, &s));
  PetscCall(VecRestoreArray(F->H, &H));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &C));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &S));
  PetscCall(DMRestoreLocalVector(m->dmV1, &Hl));
  PetscFunctionReturn(0);
}

/* Ld (the current L) -> the Dirichlet Laplacian (boundary rows and columns replaced by the identity) and its solver */
static PetscErrorCode DirichletOperator(CSConformalFlow F)
{
  const PetscScalar *b;
  PetscInt           n, lo, nb = 0, *rows;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(F->bflag, &n));
  PetscCall(VecGetOwnershipRange(F->bflag, &lo, NULL));
  PetscCall(PetscMalloc1(n, &rows));
  PetscCall(VecGetArrayRead(F->bflag, &b));
  for (PetscInt i = 0; i < n; i++)
    if (PetscRealPart(b[i]) > 0) rows[nb++] = lo + i;
  PetscCall(VecRestoreArrayRead(F->bflag, &b));
  PetscCall(MatZeroRowsColumns(F->Ld, nb, rows, 1.0, NULL, NULL));
  PetscCall(PetscFree(rows));
  if (!F->kd) {
    PC pc;
    PetscCall(KSPCreate(F->hdr.comm, &F->kd));
    PetscCall(KSPSetOptionsPrefix(F->kd, F->hdr.prefix));
    PetscCall(KSPAppendOptionsPrefix(F->kd, "boundary_poisson_"));
    PetscCall(KSPSetType(F->kd, KSPPREONLY));
    PetscCall(KSPGetPC(F->kd, &pc));
    PetscCall(CSSetDefaultCholesky(pc));
    PetscCall(KSPSetFromOptions(F->kd));
  }
  PetscCall(KSPSetOperators(F->kd, F->Ld, F->Ld));
  PetscFunctionReturn(0);
}

/* Sec. 6.3.2: min |df~ - conj(lambda) df lambda|^2 with f~ = the target on the boundary: L f~ = b on interior
   vertices with the boundary values moved to the right-hand side (b - L_IB f~_B), f~_B = the target there */
PetscErrorCode CSConformalFlowReconstructFixed(CSConformalFlow F)
{
  Vec                b, b1, xb, t, u;
  KSPConvergedReason kr;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(F->mesh->dmV3, &b));
  PetscCall(CSSpinPoissonRHS(F->spin, F->x, F->lambda, b));
  PetscCall(CSOperatorLaplacian(F->mesh, F->x, F->Ld ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &F->Ld)); /* L itself first */
  PetscCall(VecDuplicate(F->bflag, &b1));
  PetscCall(VecDuplicate(F->bflag, &xb));
  PetscCall(VecDuplicate(F->bflag, &t));
  PetscCall(VecDuplicate(F->bflag, &u));
  for (PetscInt d = 0; d < 3; d++) { /* right-hand sides b - L f~_B (into the stride of b) */
    PetscCall(VecStrideGather(b, d, b1, INSERT_VALUES));
    PetscCall(VecStrideGather(F->xt, d, xb, INSERT_VALUES));
    PetscCall(VecPointwiseMult(xb, xb, F->bflag));
    PetscCall(MatMult(F->Ld, xb, t));
    PetscCall(VecAXPY(b1, -1, t));
    PetscCall(VecPointwiseMult(t, b1, F->bflag)); /* boundary rows: the target value */
    PetscCall(VecAXPY(b1, -1, t));
    PetscCall(VecAXPY(b1, 1, xb));
    PetscCall(VecStrideScatter(b1, d, b, INSERT_VALUES));
  }
  PetscCall(DirichletOperator(F));
  for (PetscInt d = 0; d < 3; d++) {
    PetscCall(VecStrideGather(b, d, b1, INSERT_VALUES));
    PetscCall(KSPSolve(F->kd, b1, u));
    PetscCall(KSPGetConvergedReason(F->kd, &kr));
    PetscCheck(kr > 0, F->hdr.comm, PETSC_ERR_NOT_CONVERGED, "conformal flow: the Dirichlet Poisson solve (-%sboundary_poisson_ksp_*) failed: %s", F->hdr.prefix, KSPConvergedReasons[kr]);
    PetscCall(VecStrideScatter(u, d, F->xnew, INSERT_VALUES));
  }
  PetscCall(VecDestroy(&b1));
  PetscCall(VecDestroy(&xb));
  PetscCall(VecDestroy(&t));
  PetscCall(VecDestroy(&u));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmV3, &b));
  PetscFunctionReturn(0);
}

/* max over boundary vertices of |f - f~| / sqrt(area) (fixed boundary), the area-weighted std(H) / |mean H| over
   interior vertices */
PetscErrorCode CSConformalFlowBoundaryMeasures(CSConformalFlow F)
{
  const PetscScalar *x, *xt = NULL, *b = NULL, *H, *A;
  PetscReal          loc[3] = {0, 0, 0}, g[3], e = 0, eg;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(F->H, &n));
  PetscCall(VecGetArrayRead(F->H, &H));
  PetscCall(VecGetArrayRead(F->area, &A));
  PetscCall(VecGetArrayRead(F->x, &x));
  if (F->bflag) PetscCall(VecGetArrayRead(F->bflag, &b));
  if (F->xt && F->bmode == CS_CONFORMAL_BOUNDARY_FIXED) PetscCall(VecGetArrayRead(F->xt, &xt));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal a = PetscRealPart(A[i]), h = PetscRealPart(H[i]);
    if (b && PetscRealPart(b[i]) > 0) {
      if (xt) e = PetscMax(e, PetscSqrtReal(PetscSqr(PetscRealPart(x[3 * i] - xt[3 * i])) + PetscSqr(PetscRealPart(x[3 * i + 1] - xt[3 * i + 1])) + PetscSqr(PetscRealPart(x[3 * i + 2] - xt[3 * i + 2]))));
      continue;
    }
    loc[0] += a;
    loc[1] += a * h;
    loc[2] += a * h * h;
  }
  if (xt) PetscCall(VecRestoreArrayRead(F->xt, &xt));
  if (b) PetscCall(VecRestoreArrayRead(F->bflag, &b));
  PetscCall(VecRestoreArrayRead(F->x, &x));
  PetscCall(VecRestoreArrayRead(F->area, &A));
  PetscCall(VecRestoreArrayRead(F->H, &H));
  PetscCall(MPIU_Allreduce(loc, g, 3, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  PetscCall(MPIU_Allreduce(&e, &eg, 1, MPIU_REAL, MPIU_MAX, F->hdr.comm));
  F->s.H_spread       = PetscSqrtReal(PetscMax(0, g[2] / g[0] - PetscSqr(g[1] / g[0]))) / PetscAbsReal(g[1] / g[0]);
  F->s.boundary_error = eg / PetscSqrtReal(F->area_initial);
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowBoundaryDestroy(CSConformalFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&F->xt));
  PetscCall(VecDestroy(&F->bflag));
  PetscCall(MatDestroy(&F->Ld));
  PetscCall(KSPDestroy(&F->kd));
  PetscFunctionReturn(0);
}
