/* The exactness constraint of crane2013 App. C, C.1 for genus g >= 1: with the 2g harmonic 1-forms omega_i of the
   current surface and their face vector fields v_i (CSHarmonicBasis, src/operators/harmonic_basis.c: steps I-IV),
   step V solves D Z_i = v_i in the least-squares sense, X Z_i = D^* M_F v_i with X = D^* M_F D (App. G, rho = 0;
   D^* = the real transpose of the 4x4-block form, crane2011 Sec. 5.4), and rho' must be orthogonal to the three
   imaginary components Z_i^x,y,z (App. C: <<rho', <Z_i, a>>> = 0 for all a in R^3).
   X is singular (the constants, 4-fold); the right-hand side is orthogonal to them (D 1 = 0), so we factor the
   definite X + s M (s and M the shift of the spin's inverse iteration) once per step: one solve (the linearisation
   of the single inverse-iteration step) or refined to X^+ (SolveZ).
   The closing error: the harmonic part of beta = conj(lambda) df lambda (App. C), per edge the transformed edge
   vector of crane2011 Eq. 8, measured as |P_H beta|_*1 / |beta|_*1 over the three coordinates. */
#include "conformal_impl.h"
#include "cs_linalg.h"

PetscErrorCode CSConformalFlowExactnessSetUp(CSConformalFlow F)
{
  CSMesh      m = F->mesh;
  PetscMPIInt size;
  PC          pc;
  DM          dm4;
  PetscFunctionBeginUser;
  if (m->topo.genus == 0) PetscFunctionReturn(0);
  PetscCall(CSHarmonicBasisCreate(m, F->x, &F->hb));
  PetscCall(CSHarmonicBasisSetFromOptions(F->hb));
  PetscCall(CSHarmonicBasisGetSize(F->hb, &F->ng));
  if (!F->exactness) PetscFunctionReturn(0); /* the basis still measures the closing error */
  PetscCall(PetscMalloc1(F->ng, &F->Z));
  PetscCall(CSSpinGetDM(F->spin, &dm4));
  for (PetscInt i = 0; i < F->ng; i++) PetscCall(DMCreateGlobalVector(dm4, &F->Z[i]));
  PetscCall(DMCreateGlobalVector(dm4, &F->zr));
  PetscCall(VecDuplicate(F->zr, &F->zt));
  PetscCall(VecDuplicate(F->zr, &F->zb));
  PetscCall(VecDuplicate(F->zr, &F->M4));
  PetscCall(KSPCreate(m->comm, &F->kz));
  PetscCall(KSPSetOptionsPrefix(F->kz, F->hdr.prefix));
  PetscCall(KSPAppendOptionsPrefix(F->kz, "exactness_"));
  PetscCall(KSPSetType(F->kz, KSPPREONLY));
  PetscCall(KSPGetPC(F->kz, &pc));
  PetscCallMPI(MPI_Comm_size(m->comm, &size));
  if (size == 1) { /* the quaternion Cholesky, as the spin method's default (docs/solvers.md) */
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERCSQUAT));
  } else PetscCall(CSSetDefaultCholesky(pc));
  PetscCall(KSPSetFromOptions(F->kz));
  PetscFunctionReturn(0);
}

/* X0 = D^* M_F D, Xs = X0 + s M (same pattern), the face operator D and the face areas M_F on the current surface.
   s and M are exactly the shift of CSSpin's inverse iteration (s = target 4 pi / area, M the barycentric vertex
   areas: (K - sigma) with K = V X V, sigma = -target 4 pi / area / vmean^2, V^-2 = vmean^2 M), so that one solve
   with Xs is the linearisation of the step the flow takes (SolveZ). */
static PetscErrorCode Operators(CSConformalFlow F)
{
  PetscReal          A, s, shift;
  const PetscScalar *a;
  PetscScalar       *m4;
  PetscInt           n;
  DM                 dm4;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetDM(F->spin, &dm4));
  PetscCall(CSSpinGetShift(F->spin, &shift)); /* -spin_shift, in units of 4 pi / area */
  PetscCall(CSDiracAssemble(F->mesh, dm4, F->x, CS_RHO_NONE, NULL, F->X0 ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &F->X0));
  PetscCall(MatDestroy(&F->Dface));
  PetscCall(VecDestroy(&F->MF));
  PetscCall(CSDiracCreateFaceOperators(F->mesh, dm4, F->x, CS_RHO_NONE, NULL, &F->Dface, NULL, NULL, &F->MF));
  PetscCall(CSGeometryVertexAreas(F->mesh, F->x, F->work)); /* the spin's mass: barycentric areas (so is F->area, in both -curvature modes) */
  PetscCall(VecSum(F->work, &A));
  s   = shift * 4 * PETSC_PI / A;
  PetscCall(VecGetLocalSize(F->work, &n));
  PetscCall(VecGetArrayRead(F->work, &a));
  PetscCall(VecGetArray(F->M4, &m4));
  for (PetscInt i = 0; i < 4 * n; i++) m4[i] = s * a[i / 4];
  PetscCall(VecRestoreArray(F->M4, &m4));
  PetscCall(VecRestoreArrayRead(F->work, &a));
  if (!F->Xs) PetscCall(MatDuplicate(F->X0, MAT_COPY_VALUES, &F->Xs));
  else PetscCall(MatCopy(F->X0, F->Xs, SAME_NONZERO_PATTERN));
  PetscCall(MatDiagonalSet(F->Xs, F->M4, ADD_VALUES));
  PetscCall(MatSetOption(F->Xs, MAT_SPD, PETSC_TRUE));
  PetscCall(KSPSetOperators(F->kz, F->Xs, F->Xs));
  PetscFunctionReturn(0);
}

/* b = D^T (M_F w), w = (0, v) per face */
static PetscErrorCode RightHandSide(CSConformalFlow F, Vec vf, Vec b)
{
  Vec                w;
  const PetscScalar *v, *mf;
  PetscScalar       *wa;
  PetscInt           nf4;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->MF, &w));
  PetscCall(VecGetLocalSize(w, &nf4));
  PetscCall(VecGetArrayRead(vf, &v));
  PetscCall(VecGetArrayRead(F->MF, &mf));
  PetscCall(VecGetArray(w, &wa));
  for (PetscInt k = 0; k < nf4 / 4; k++) {
    wa[4 * k] = 0;
    for (int d = 0; d < 3; d++) wa[4 * k + 1 + d] = mf[4 * k + 1 + d] * v[3 * k + d];
  }
  PetscCall(VecRestoreArray(w, &wa));
  PetscCall(VecRestoreArrayRead(F->MF, &mf));
  PetscCall(VecRestoreArrayRead(vf, &v));
  PetscCall(MatMultTranspose(F->Dface, w, b));
  PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

/* Z = X^+ b for the eigenproblem's linearisation (App. G; -flow_eigensolver eps): refined Z <- Z + Xs^{-1} (b - X0 Z)
   until |b - X0 Z| <= 1e-10 |b| (each pass gains s / (s + gamma_1): ~1e-2 on a round torus, only ~0.4 on the thin
   tube of knot1_cgal, where X0's smallest nonzero eigenvalue gamma_1 is ~1.5 s). With the default single
   inverse-iteration step (Sec. 6.4.2) the step taken is lambda = (X + s M)^{-1} M 1, whose first-order response to
   rho is (X0 + s M)^{-1} D^T M_F B rho' (not X0^+ ...): then Z = Xs^{-1} b, one solve, is the exact linearisation
   (docs/conformal_flow.md "knot1": with X0^+ the closing error stays first order in tau on knot1). */
static PetscErrorCode SolveZ(CSConformalFlow F, Vec b, Vec Z)
{
  KSPConvergedReason r;
  PetscBool          shifted, inverse;
  PetscInt           its;
  PetscReal          nb, nr;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetInverseIteration(F->spin, &inverse, &its));
  shifted = (PetscBool)(inverse && its == 1 && !F->exactness_paper);
  PetscCall(VecSet(Z, 0));
  PetscCall(VecCopy(b, F->zr));
  PetscCall(VecNorm(b, NORM_2, &nb));
  for (int pass = 0; pass < (shifted ? 1 : 200); pass++) { /* Z <- Z + Xs^{-1} (b - X0 Z) */
    PetscCall(KSPSolve(F->kz, F->zr, F->zt));
    PetscCall(KSPGetConvergedReason(F->kz, &r));
    PetscCheck(r >= 0, F->hdr.comm, PETSC_ERR_NOT_CONVERGED, "conformal flow: the exactness solve X Z = D^* v (-%sexactness_ksp_*) failed: %s", F->hdr.prefix, KSPConvergedReasons[r]);
    PetscCall(VecAXPY(Z, 1, F->zt));
    PetscCall(MatMult(F->X0, Z, F->zr));
    PetscCall(VecAYPX(F->zr, -1, b));
    PetscCall(VecNorm(F->zr, NORM_2, &nr));
    if (nr <= 1e-10 * nb) break;
  }
  PetscFunctionReturn(0);
}

/* The discrete linearisation (default; docs/conformal_flow.md "Exactness"): with lambda = 1 + t l, edge ij's transformed
   vector (crane2011 Eq. 8) changes by 2 Re(l_m) e + 2 e x Im(l_m), l_m = (l_i + l_j)/2, so the harmonic part
   <<beta', omega_i>>_*1 . e_d is the linear functional g . l with, per vertex v and edge e = (v, w) of omega's
   orientation, s_e = *1_e omega_i(e): Re g_v += s_e e_d . e, Im g_v += s_e e_d x e. Owned edges only (each once). */
static PetscErrorCode FunctionalGradient(CSConformalFlow F, Vec omega, Vec star1, PetscInt d, Vec g)
{
  CSMesh             m = F->mesh;
  Vec                xl, wl, sl;
  const PetscReal   *p;
  const PetscScalar *w, *st;
  CSLocalSum         ls;
  DM                 dm4;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, F->x, &xl, &p));
  PetscCall(DMGetLocalVector(m->dmE1, &wl));
  PetscCall(DMGetLocalVector(m->dmE1, &sl));
  PetscCall(DMGlobalToLocal(m->dmE1, omega, INSERT_VALUES, wl));
  PetscCall(DMGlobalToLocal(m->dmE1, star1, INSERT_VALUES, sl));
  PetscCall(VecGetArrayRead(wl, &w));
  PetscCall(VecGetArrayRead(sl, &st));
  PetscCall(CSSpinGetDM(F->spin, &dm4));
  PetscCall(CSLocalSumBegin(dm4, &ls));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt  v[2] = {m->edgeVert[2 * e], m->edgeVert[2 * e + 1]};
    PetscReal ev[3], ed[3] = {0, 0, 0}, cr[3], se = PetscRealPart(st[e] * w[e]);
    if (!m->edgeOwned[e]) continue;
    CSVecSub(p + 3 * v[1], p + 3 * v[0], ev);
    ed[d] = 1;
    CSVecCross(ed, ev, cr);
    for (int k = 0; k < 2; k++) {
      ls.a[4 * v[k]] += se * ev[d];
      for (int q = 0; q < 3; q++) ls.a[4 * v[k] + 1 + q] += se * cr[q];
    }
  }
  PetscCall(CSLocalSumEnd(&ls, g));
  PetscCall(VecRestoreArrayRead(sl, &st));
  PetscCall(VecRestoreArrayRead(wl, &w));
  PetscCall(DMRestoreLocalVector(m->dmE1, &sl));
  PetscCall(DMRestoreLocalVector(m->dmE1, &wl));
  PetscCall(CSMeshRestoreLocalPositions(m, F->x, &xl, &p));
  PetscFunctionReturn(0);
}

/* The linearised eigenproblem X l = D^T M_F (B rho') + gamma' M 1 (App. G with rho = t rho', D 1 = 0) gives
   g . l = (D X^+ g)^T M_F B rho', so rho' must be <<.,.>>-orthogonal to c = M^{-1} B^T M_F Re(D Z), Z = X^+ g. */
static PetscErrorCode DiscreteFunction(CSConformalFlow F, Vec Z, Vec c)
{
  CSMesh             m = F->mesh;
  Vec                y;
  const PetscScalar *ya, *mf;
  CSLocalSum         ls;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->MF, &y));
  PetscCall(MatMult(F->Dface, Z, y));
  PetscCall(VecGetArrayRead(y, &ya));
  PetscCall(VecGetArrayRead(F->MF, &mf));
  PetscCall(CSLocalSumBegin(m->dmV1, &ls));
  for (CSFaceIter f = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &f);)
    for (int k = 0; k < 3; k++) ls.a[f.v[k]] += PetscRealPart(mf[4 * f.f] * ya[4 * f.f]) / 3;
  PetscCall(CSLocalSumEnd(&ls, c));
  PetscCall(VecRestoreArrayRead(F->MF, &mf));
  PetscCall(VecRestoreArrayRead(y, &ya));
  PetscCall(VecPointwiseDivide(c, c, F->area));
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

/* the paper's functions (App. C.1, -flow_exactness_paper): c_d = Im_d Z_i with X Z_i = D^T M_F v_i */
static PetscErrorCode PaperFunctions(CSConformalFlow F, PetscInt i, Vec c[3])
{
  Vec                vf;
  const PetscScalar *z;
  PetscInt           nl;
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisGetFaceVectors(F->hb, i, &vf));
  PetscCall(RightHandSide(F, vf, F->zb));
  PetscCall(SolveZ(F, F->zb, F->Z[i]));
  PetscCall(VecGetLocalSize(F->area, &nl));
  PetscCall(VecGetArrayRead(F->Z[i], &z));
  for (int d = 0; d < 3; d++) {
    PetscScalar *ca;
    PetscCall(VecGetArray(c[d], &ca));
    for (PetscInt j = 0; j < nl; j++) ca[j] = z[4 * j + 1 + d];
    PetscCall(VecRestoreArray(c[d], &ca));
  }
  PetscCall(VecRestoreArrayRead(F->Z[i], &z));
  PetscFunctionReturn(0);
}

/* c[nc + 3i + d] = Z_i^{x,y,z}; *n = 3 * 2g */
PetscErrorCode CSConformalFlowExactnessFunctions(CSConformalFlow F, PetscInt *n)
{
  Vec star1 = NULL;
  PetscFunctionBeginUser;
  *n = 0;
  if (!F->exactness || !F->ng) PetscFunctionReturn(0);
  PetscCall(CSHarmonicBasisUpdate(F->hb, F->x));
  PetscCall(Operators(F));
  if (!F->exactness_paper) {
    PetscCall(DMCreateGlobalVector(F->mesh->dmE1, &star1));
    PetscCall(CSOperatorHodgeStar1(F->mesh, F->x, star1));
  }
  for (PetscInt i = 0; i < F->ng; i++) {
    Vec *c = F->c + F->nc + 3 * i;
    if (F->exactness_paper) PetscCall(PaperFunctions(F, i, c));
    else {
      Vec omega;
      PetscCall(CSHarmonicBasisGetForm(F->hb, i, &omega));
      for (PetscInt d = 0; d < 3; d++) {
        PetscCall(FunctionalGradient(F, omega, star1, d, F->zb));
        PetscCall(SolveZ(F, F->zb, F->Z[i]));
        PetscCall(DiscreteFunction(F, F->Z[i], c[d]));
      }
    }
  }
  *n = 3 * F->ng;
  PetscCall(VecDestroy(&star1));
  PetscFunctionReturn(0);
}

/* beta_d on every local edge (edgeVert[2e] -> edgeVert[2e+1]) from the local positions and lambda */
static PetscErrorCode TransformedEdges(CSConformalFlow F, Vec beta[3])
{
  CSMesh             m = F->mesh;
  Vec                xl, ll, bl[3];
  const PetscReal   *p;
  const PetscScalar *l;
  PetscScalar       *b[3];
  DM                 dm4;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, F->x, &xl, &p));
  PetscCall(CSSpinGetDM(F->spin, &dm4));
  PetscCall(DMGetLocalVector(dm4, &ll));
  PetscCall(DMGlobalToLocal(dm4, F->lambda, INSERT_VALUES, ll));
  PetscCall(VecGetArrayRead(ll, &l));
  for (int d = 0; d < 3; d++) {
    PetscCall(DMGetLocalVector(m->dmE1, &bl[d]));
    PetscCall(VecGetArray(bl[d], &b[d]));
  }
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt  i = m->edgeVert[2 * e], j = m->edgeVert[2 * e + 1];
    PetscReal li[4], lj[4], ed[3], et[3];
    for (int q = 0; q < 4; q++) {
      li[q] = PetscRealPart(l[4 * i + q]);
      lj[q] = PetscRealPart(l[4 * j + q]);
    }
    CSVecSub(p + 3 * j, p + 3 * i, ed);
    CSSpinTransformedEdge(li, lj, ed, et);
    for (int d = 0; d < 3; d++) b[d][e] = et[d];
  }
  for (int d = 0; d < 3; d++) {
    PetscCall(VecRestoreArray(bl[d], &b[d]));
    PetscCall(DMLocalToGlobal(m->dmE1, bl[d], INSERT_VALUES, beta[d]));
    PetscCall(DMRestoreLocalVector(m->dmE1, &bl[d]));
  }
  PetscCall(VecRestoreArrayRead(ll, &l));
  PetscCall(DMRestoreLocalVector(dm4, &ll));
  PetscCall(CSMeshRestoreLocalPositions(m, F->x, &xl, &p));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowClosingError(CSConformalFlow F, PetscReal *err)
{
  Vec          beta[3], star1, t;
  PetscScalar *c;
  PetscReal    num = 0, den = 0;
  PetscFunctionBeginUser;
  *err = 0;
  if (!F->ng) PetscFunctionReturn(0);
  if (!F->exactness) PetscCall(CSHarmonicBasisUpdate(F->hb, F->x)); /* else updated by the constraint step */
  PetscCall(PetscMalloc1(F->ng, &c));
  PetscCall(DMCreateGlobalVector(F->mesh->dmE1, &star1));
  PetscCall(VecDuplicate(star1, &t));
  for (int d = 0; d < 3; d++) PetscCall(VecDuplicate(star1, &beta[d]));
  PetscCall(CSOperatorHodgeStar1(F->mesh, F->x, star1));
  PetscCall(VecAbs(star1)); /* the denominator a norm also with non-Delaunay edges (negative cotan weights) */
  PetscCall(TransformedEdges(F, beta));
  for (int d = 0; d < 3; d++) {
    PetscScalar bb;
    PetscCall(CSHarmonicBasisInner(F->hb, beta[d], c));
    for (PetscInt i = 0; i < F->ng; i++) num += PetscRealPart(c[i] * c[i]);
    PetscCall(VecPointwiseMult(t, star1, beta[d]));
    PetscCall(VecDot(t, beta[d], &bb));
    den += PetscRealPart(bb);
  }
  *err = den > 0 ? PetscSqrtReal(num / den) : 0;
  for (int d = 0; d < 3; d++) PetscCall(VecDestroy(&beta[d]));
  PetscCall(VecDestroy(&t));
  PetscCall(VecDestroy(&star1));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowExactnessDestroy(CSConformalFlow F)
{
  PetscFunctionBeginUser;
  if (F->Z)
    for (PetscInt i = 0; i < F->ng; i++) PetscCall(VecDestroy(&F->Z[i]));
  PetscCall(PetscFree(F->Z));
  {
    Vec *vs[] = {&F->zr, &F->zt, &F->zb, &F->M4, &F->MF};
    for (size_t k = 0; k < sizeof(vs) / sizeof(vs[0]); k++) PetscCall(VecDestroy(vs[k]));
  }
  PetscCall(MatDestroy(&F->X0));
  PetscCall(MatDestroy(&F->Xs));
  PetscCall(MatDestroy(&F->Dface));
  PetscCall(KSPDestroy(&F->kz));
  PetscCall(CSHarmonicBasisDestroy(&F->hb));
  PetscFunctionReturn(0);
}
