/* A state of the conformal flow and its direction (crane2013 Table 1 right column, steps I-IV; Sec. 4, 6.1, 6.2):
     I    H_i = (L f)_i . n_i / (2 A_i): CSGeometryVoronoiMeanCurvature (default; exactly 1/R on a mesh inscribed
          in a sphere with non-obtuse triangles, so the round sphere is a fixed point) or
          CSGeometrySignedMeanCurvature (-flow_curvature barycentric). On boundary vertices (Sec. 6.3) the mean
          over the interior neighbours (conformal_boundary.c).
     II   v = -2 H. The factor, derived: E_W(mu) = |mu|^2 with mu = H |df| (Sec. 6.1), so the L2 gradient flow is
          mu' = -2 mu (Eq. 1); a spin transformation with potential rho changes mu to mu + rho |df| (Sec. 6, with
          gamma the eigenvalue), so rho' = -2 H and the forward Euler step (Eq. 2) is rho = -2 tau H (rho^m = 0):
          mu -> (1 - 2 tau) mu, stable iff |1 - 2 tau| < 1, i.e. tau < 1 (Sec. 4). The paper's text is not
          consistent about the factor: Sec. 6.1 says rho' = -H and rho^{m+1} = rho^m - 2 tau H^m, then solves
          (D + tau H^m) lambda = gamma lambda, which is rho = -tau H, i.e. mu -> (1 - tau) mu, stable for tau < 2.
          We take -2 tau H (the step of Eq. 2 with the threshold tau < 1 the paper states and Fig. 18 shows);
          the check is the threshold itself (tests/cases/conformal_stability.sh: 0.95 stable, 1.05 not).
          (App. F's rho' = -H/2 is the scaling flow h' = -h, not the gradient.)
     (Sec. 4) the optional filter v <- v - (id + s A^k)^{-1} v (src/operators/spectral_filter.c).
     III  an orthonormal basis of {1, N^x, N^y, N^z} in <<a, b>> = sum_i A_i a_i b_i (modified Gram-Schmidt;
          App. B: total curvature; App. D: sphere inversions);
     IV   v <- v - sum_i <<v, c_i>> c_i; with Moebius balancing (App. E) v += w rho_a after the inversion
          constraint, then the remaining constraint (1) projected out again. */
#include "conformal_impl.h"
#include "cs_operators.h"

/* <<a, b>> = sum_i A_i a_i b_i over owned vertices */
static PetscErrorCode Dot(CSConformalFlow F, Vec a, Vec b, PetscReal *r)
{
  PetscFunctionBeginUser;
  PetscCall(VecPointwiseMult(F->work, F->area, a));
  PetscCall(VecDot(F->work, b, r));
  PetscFunctionReturn(0);
}

/* Raw functions c[0] = 1, c[1..3] = N^x,y,z (with the inversion constraint), then Z_i^x,y,z (exactness), made
   orthonormal in that order by modified Gram-Schmidt; nearly dependent ones (relative norm below 1e-10 after
   orthogonalisation) are dropped. nbefore counts the orthonormal ones from 1 and N. */
static PetscErrorCode ConstraintBasis(CSConformalFlow F)
{
  PetscInt nraw = F->inversion ? 4 : 1, nz;
  PetscFunctionBeginUser;
  PetscCall(VecSet(F->c[0], 1));
  for (PetscInt d = 1; d < nraw; d++) PetscCall(VecStrideGather(F->N, d - 1, F->c[d], INSERT_VALUES));
  F->nc = nraw;
  PetscCall(CSConformalFlowExactnessFunctions(F, &nz)); /* c[nraw..nraw+nz) */
  F->nc = 0;
  for (PetscInt j = 0; j < nraw + nz; j++) {
    Vec       c = F->c[j];
    PetscReal a, a0;
    if (j == nraw) F->nbefore = F->nc;
    PetscCall(Dot(F, c, c, &a0));
    for (PetscInt i = 0; i < F->nc; i++) {
      PetscCall(Dot(F, c, F->c[i], &a));
      PetscCall(VecAXPY(c, -a, F->c[i]));
    }
    PetscCall(Dot(F, c, c, &a));
    if (a <= 1e-20 * a0) continue;
    PetscCall(VecScale(c, 1 / PetscSqrtReal(a)));
    F->c[j]       = F->c[F->nc]; /* keep it at position nc (swap the vectors) */
    F->c[F->nc++] = c;
  }
  if (!nz) F->nbefore = F->nc;
  PetscFunctionReturn(0);
}

/* v <- v - sum_{i0 <= i < n} <<v, c_i>> c_i */
static PetscErrorCode Project(CSConformalFlow F, PetscInt i0, PetscInt n)
{
  PetscReal a;
  PetscFunctionBeginUser;
  for (PetscInt i = i0; i < n; i++) {
    PetscCall(Dot(F, F->v, F->c[i], &a));
    PetscCall(VecAXPY(F->v, -a, F->c[i]));
  }
  PetscFunctionReturn(0);
}

/* x = S^-1 b for the symmetric 3x3 S given by its upper triangle xx xy xz yy yz zz; returns the determinant */
static PetscReal Solve3(const PetscReal u[6], const PetscReal b[3], PetscReal x[3])
{
  const PetscReal S[9] = {u[0], u[1], u[2], u[1], u[3], u[4], u[2], u[4], u[5]};
  PetscReal       det  = S[0] * (S[4] * S[8] - S[5] * S[7]) - S[1] * (S[3] * S[8] - S[5] * S[6]) + S[2] * (S[3] * S[7] - S[4] * S[6]);
  if (det <= 0) return det;
  x[0] = (b[0] * (S[4] * S[8] - S[5] * S[7]) - S[1] * (b[1] * S[8] - S[5] * b[2]) + S[2] * (b[1] * S[7] - S[4] * b[2])) / det;
  x[1] = (S[0] * (b[1] * S[8] - S[5] * b[2]) - b[0] * (S[3] * S[8] - S[5] * S[6]) + S[2] * (S[3] * b[2] - b[1] * S[6])) / det;
  x[2] = (S[0] * (S[4] * b[2] - b[1] * S[7]) - S[1] * (S[3] * b[2] - b[1] * S[6]) + b[0] * (S[3] * S[7] - S[4] * S[6])) / det;
  return det;
}

/* App. E.1: u = 1/2 log(A_i / A*_i) against the input's vertex areas, u0 = u minus its area mean, b = sum A_i f_i u0_i.
   The inversion with centre velocity a changes the scale factors by u' = -2 <a, f> (App. E) and the curvature by
   rho' = -2 <a, N> (App. D). -flow_mobius_step paper: a = B^-1 b with B = 4 sum A_i N_i N_i^T, normalised to
   <B a, a> = 1 (E.1 steps IV-V; E's text adds "<a, N>", App. D's factor -2 belongs to the inversion that moves
   toward balance): a unit step whatever the imbalance, so with a fixed tau it overshoots and oscillates once the
   areas are nearly balanced (docs/conformal_flow.md). newton (default): the a whose u' removes the part of u0
   spanned by <a, f> in one step, the least-squares a = 1/2 C^-1 b with C = sum A_i (f_i - c)(f_i - c)^T (c the area
   centroid), applied over the step as rho = -2 <a, N> (v += rho / tau). Either way v += w rho. */
static PetscErrorCode MobiusBalance(CSConformalFlow F)
{
  const PetscScalar *A, *A0, *f, *N;
  PetscScalar       *v;
  PetscReal          loc[20] = {0}, g[20], b[3], C[6], a[3], nB = 0, scale;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(F->area, &n));
  PetscCall(VecGetArrayRead(F->area, &A));
  PetscCall(VecGetArrayRead(F->area0, &A0));
  PetscCall(VecGetArrayRead(F->x, &f));
  PetscCall(VecGetArrayRead(F->N, &N));
  for (PetscInt i = 0; i < n; i++) { /* sums of A, A u, A f, A f u, 4 A N N^T and A f f^T */
    PetscReal Ai = PetscRealPart(A[i]), u = 0.5 * PetscLogReal(Ai / PetscRealPart(A0[i]));
    loc[0] += Ai;
    loc[1] += Ai * u;
    for (int d = 0; d < 3; d++) {
      loc[2 + d] += Ai * PetscRealPart(f[3 * i + d]);
      loc[5 + d] += Ai * PetscRealPart(f[3 * i + d]) * u;
    }
    for (int d = 0, k = 0; d < 3; d++)
      for (int e = d; e < 3; e++, k++) {
        loc[8 + k] += 4 * Ai * PetscRealPart(N[3 * i + d] * N[3 * i + e]);
        loc[14 + k] += Ai * PetscRealPart(f[3 * i + d] * f[3 * i + e]);
      }
  }
  PetscCall(VecRestoreArrayRead(F->N, &N));
  PetscCall(VecRestoreArrayRead(F->x, &f));
  PetscCall(VecRestoreArrayRead(F->area0, &A0));
  PetscCall(VecRestoreArrayRead(F->area, &A));
  PetscCall(MPIU_Allreduce(loc, g, 20, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  for (int d = 0; d < 3; d++) b[d] = g[5 + d] - g[1] / g[0] * g[2 + d]; /* sum A f (u - mean u) */
  if (F->mobius_step == CS_CONFORMAL_MOBIUS_PAPER) {
    PetscCheck(Solve3(g + 8, b, a) > 0, F->hdr.comm, PETSC_ERR_PLIB, "conformal flow: Moebius balancing: B = 4 sum A N N^T is singular (a flat surface?)");
    for (int d = 0, k = 0; d < 3; d++)
      for (int e = d; e < 3; e++, k++) nB += (d == e ? 1 : 2) * a[d] * g[8 + k] * a[e];
    if (nB <= 0) PetscFunctionReturn(0); /* balanced already */
    scale = 1 / PetscSqrtReal(nB);
  } else {
    for (int d = 0, k = 0; d < 3; d++)
      for (int e = d; e < 3; e++, k++) C[k] = g[14 + k] - g[2 + d] * g[2 + e] / g[0];
    PetscCheck(Solve3(C, b, a) > 0, F->hdr.comm, PETSC_ERR_PLIB, "conformal flow: Moebius balancing: the second moment of the surface is singular (a flat surface?)");
    scale = 0.5 / F->tau;
  }
  PetscCall(VecGetArrayRead(F->N, &N));
  PetscCall(VecGetArray(F->v, &v));
  for (PetscInt i = 0; i < n; i++) v[i] += -2 * F->mobius_weight * scale * (a[0] * N[3 * i] + a[1] * N[3 * i + 1] + a[2] * N[3 * i + 2]);
  PetscCall(VecRestoreArray(F->v, &v));
  PetscCall(VecRestoreArrayRead(F->N, &N));
  PetscFunctionReturn(0);
}

/* the largest |<<v, c>>| / (|v| |c|) over c = 1 (res_total) and c = N^x,y,z (res_inversion) */
static PetscErrorCode Residuals(CSConformalFlow F)
{
  PetscReal vv, cc, vc;
  PetscFunctionBeginUser;
  PetscCall(Dot(F, F->v, F->v, &vv));
  F->s.vnorm         = PetscSqrtReal(vv);
  F->s.res_total     = 0;
  F->s.res_inversion = 0;
  F->s.res_exact     = 0;
  if (vv == 0) PetscFunctionReturn(0);
  for (PetscInt j = 0; j < 4; j++) {
    PetscReal r;
    if (j == 0) PetscCall(VecSet(F->rho, 1));
    else PetscCall(VecStrideGather(F->N, j - 1, F->rho, INSERT_VALUES));
    PetscCall(Dot(F, F->rho, F->rho, &cc));
    PetscCall(Dot(F, F->v, F->rho, &vc));
    r = PetscAbsReal(vc) / PetscSqrtReal(vv * cc);
    if (j == 0) F->s.res_total = r;
    else F->s.res_inversion = PetscMax(F->s.res_inversion, r);
  }
  F->s.res_exact = 0; /* against the orthonormalised Z functions (the same span) */
  for (PetscInt i = F->nbefore; i < F->nc; i++) {
    PetscCall(Dot(F, F->v, F->c[i], &vc));
    F->s.res_exact = PetscMax(F->s.res_exact, PetscAbsReal(vc) / PetscSqrtReal(vv));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowApplyFilter(CSConformalFlow F, Vec v)
{
  PetscReal A, vol, s;
  PetscFunctionBeginUser;
  PetscCheck(F->loop.setupcalled && F->sigma > 0, F->hdr.comm, PETSC_ERR_ORDER, "CSConformalFlowApplyFilter: needs SetUp and -%sfilter_sigma > 0", F->hdr.prefix);
  PetscCall(CSGeometryAreaVolume(F->mesh, F->x, &A, &vol));
  s = F->sigma * PetscPowReal(A / (4 * PETSC_PI), (PetscReal)F->fk); /* sigma is dimensionless: the unit sphere's */
  PetscCall(CSGeometryVertexAreas(F->mesh, F->x, F->area));
  PetscCall(CSOperatorLaplacian(F->mesh, F->x, F->L ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &F->L));
  PetscCall(MatDestroy(&F->B));
  PetscCall(CSOperatorSpectralFilter(F->L, F->area, s, F->fk, &F->B));
  if (!F->kspf) {
    PC pc;
    PetscCall(KSPCreate(F->hdr.comm, &F->kspf));
    PetscCall(KSPSetOptionsPrefix(F->kspf, F->hdr.prefix));
    PetscCall(KSPAppendOptionsPrefix(F->kspf, "filter_"));
    PetscCall(KSPSetType(F->kspf, KSPPREONLY));
    PetscCall(KSPGetPC(F->kspf, &pc));
    /* MUMPS, not CHOLMOD: for k = 3 on a distorted mesh B = M + s L (M^-1 L)^2 is SPD in exact arithmetic but spans
       so many orders of magnitude that CHOLMOD's supernodal Cholesky met a non-positive pivot (bunny_lowres_npm,
       k = 3, step 3). MUMPS factors it, but its solution is no better (relative residual 4 at sigma 1e-4): the
       residual check below refuses such solves (docs/conformal_flow.md, "The filter's conditioning") */
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERMUMPS));
    PetscCall(KSPSetFromOptions(F->kspf));
    PetscCall(CSMumpsDefaultOrdering(pc, F->B));
  }
  PetscCall(KSPSetOperators(F->kspf, F->B, F->B));
  PetscCall(VecPointwiseMult(F->work, F->area, v)); /* B w = M v */
  PetscCall(KSPSolve(F->kspf, F->work, F->rho));
  PetscCall(CSOperatorSpectralFilterCheck(F->kspf, F->work, F->rho, "conformal flow", F->hdr.prefix));
  PetscCall(VecAXPY(v, -1, F->rho));
  PetscFunctionReturn(0);
}

/* the area-weighted standard deviation of u = log(A_i / A0_i), the scale factors against the input (App. E) */
static PetscErrorCode AreaSpread(CSConformalFlow F)
{
  const PetscScalar *A, *A0;
  PetscReal          s[3] = {0, 0, 0}, g[3];
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(F->area, &n));
  PetscCall(VecGetArrayRead(F->area, &A));
  PetscCall(VecGetArrayRead(F->area0, &A0));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal u = PetscLogReal(PetscRealPart(A[i] / A0[i]));
    s[0] += PetscRealPart(A[i]);
    s[1] += PetscRealPart(A[i]) * u;
    s[2] += PetscRealPart(A[i]) * u * u;
  }
  PetscCall(VecRestoreArrayRead(F->area0, &A0));
  PetscCall(VecRestoreArrayRead(F->area, &A));
  PetscCall(MPIU_Allreduce(s, g, 3, MPIU_REAL, MPIU_SUM, F->hdr.comm));
  F->s.log_area_spread = PetscSqrtReal(PetscMax(0, g[2] / g[0] - PetscSqr(g[1] / g[0])));
  PetscFunctionReturn(0);
}

/* E_H = <<H, H>> = the paper's |mu|^2 with the signed H */
static PetscErrorCode Measures(CSConformalFlow F)
{
  PetscReal vol;
  PetscFunctionBeginUser;
  PetscCall(AreaSpread(F));
  PetscCall(CSEnergyValue(F->will, F->x, &F->s.W));
  PetscCall(Dot(F, F->H, F->H, &F->s.EH));
  PetscCall(CSGeometryAreaVolume(F->mesh, F->x, &F->s.area, &vol));
  PetscCall(CSGeometryQuasiConformal(F->mesh, F->x0, F->x, NULL, &F->s.q_mean, &F->s.q_max));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowEvaluate(CSConformalFlow F)
{
  PetscFunctionBeginUser;
  if (F->curvature == CS_CONFORMAL_CURVATURE_VORONOI) PetscCall(CSGeometryVoronoiMeanCurvature(F->mesh, F->x, F->H, F->N, F->area)); /* I */
  else PetscCall(CSGeometrySignedMeanCurvature(F->mesh, F->x, F->H, F->N, F->area));
  PetscCall(CSConformalFlowBoundaryCurvature(F)); /* Sec. 6.3: H on boundary vertices from the interior */
  PetscCall(Measures(F));
  PetscCall(CSConformalFlowBoundaryMeasures(F));
  PetscCall(VecAXPBY(F->v, -F->hfactor, 0, F->H)); /* II: rho' = -2 H (see above; -flow_curvature_factor) */
  if (F->sigma > 0) PetscCall(CSConformalFlowApplyFilter(F, F->v)); /* Sec. 4 */
  PetscCall(ConstraintBasis(F)); /* III */
  PetscCall(Project(F, 0, F->nc)); /* IV */
  if (F->mobius) { /* after the inversion constraint, before the remaining ones (Sec. 6.2) */
    PetscCall(MobiusBalance(F));
    PetscCall(Project(F, 0, 1));
    PetscCall(Project(F, F->nbefore, F->nc));
  }
  PetscCall(Residuals(F));
  PetscFunctionReturn(0);
}
