/* A *1-orthonormal basis of the harmonic 1-forms by a parallel Hodge decomposition (crane2013 App. C.1 steps
   I-III; docs/dec.md), no spanning tree:
     I.   2g random 1-forms alpha_i (a hash of the seed, i and the edge's natural number: the same forms on
          every number of ranks);
     IIa. closed part: alpha <- alpha - d1^T (d1 d1^T)^{-1} d1 alpha. Any metric on the 1-forms gives a closed
          form in the same cohomology class; we take the combinatorial one (d1 d1^T, the dual graph Laplacian)
          instead of Desbrun et al. 2008's d1 *1^{-1} d1^T, which is indefinite or undefined (w_ij <= 0) on
          non-Delaunay edges. It depends on the connectivity only, so it is done once per mesh;
     IIb. co-closed: omega = alpha - d0 L^{-1} d0^T *1 alpha with L = d0^T *1 d0 the cotan Laplacian
          (laplacian.c), positive semi-definite on any mesh. d1 d0 = 0 keeps omega closed, and d0^T *1 omega = 0.
          Then both steps once more on the result (the round-off of the first solves is relative to the large
          exact and co-exact parts of a random form; the second pass makes it relative to the small harmonic
          rest: at 65k faces |d1 w|/|w| 7.7e-13 -> see docs/dec.md);
     III. modified Gram-Schmidt, twice, in <<a, b>> = a^T *1 b, positive definite on closed forms (per face
          it is A_f |v_f|^2, the cotan formula);
     IV.  the face vectors of crane2013 App. C.1.
   Both Laplacians are singular (constants); vertex 0 / face 0 is grounded (its row and column replaced by the
   identity): the right-hand sides sum to zero, so the grounded solution solves the singular system exactly. */
#include "cs_operators_dec.h"
#include "cs_mesh_adjacency.h"
#include "cs_cholmod.h"
#include "cs_util.h"
#include <stdint.h>

struct _p_CSHarmonicBasis {
  CSObjectHeader hdr;
  CSMesh         mesh;
  Vec            x;
  PetscInt       g, n, seed;
  PetscBool      setup, from_options;
  Mat            d0, d1, L, Lf; /* Lf = d1 d1^T; L and Lf grounded */
  KSP            kv, kf;        /* vertex (L) and face (Lf) solves */
  Vec            star1, wE, wV, wF;
  Vec           *closed, *omega, *v; /* n each: closed random forms, harmonic basis, face vectors */
  DM             dmF3;
};

/* splitmix64 of (a, b) mapped to [-1, 1) */
static PetscReal HashUniform(uint64_t a, uint64_t b)
{
  uint64_t z = a * 0x9E3779B97F4A7C15ULL + b + 0x632BE59BD9B4E019ULL;
  z          = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
  z          = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
  z ^= z >> 31;
  return (PetscReal)(z >> 11) * 0x1.0p-52 - 1.0;
}

PetscErrorCode CSHarmonicBasisCreate(CSMesh mesh, Vec x, CSHarmonicBasis *hb)
{
  CSHarmonicBasis h;
  PetscInt        g;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetClosedGenus(mesh, "CSHarmonicBasisCreate", &g));
  PetscCall(CSObjectCreate(sizeof(*h), mesh->comm, "harmonic_", NULL, &h));
  h->mesh = mesh;
  h->seed = 1;
  h->g    = g;
  h->n = 2 * h->g;
  PetscCall(VecDuplicate(x, &h->x));
  PetscCall(VecCopy(x, h->x));
  *hb = h;
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisSetOptionsPrefix(CSHarmonicBasis hb, const char prefix[])
{
  PetscFunctionBeginUser;
  PetscCall(CSObjectSetOptionsPrefix(&hb->hdr, prefix));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisSetSeed(CSHarmonicBasis hb, PetscInt seed)
{
  PetscFunctionBeginUser;
  /* the random closed forms are drawn once, in the first set-up (SetUpTopology) */
  PetscCheck(!hb->d0 || seed == hb->seed, hb->hdr.comm, PETSC_ERR_ORDER, "CSHarmonicBasisSetSeed: the seed is fixed at the first CSHarmonicBasisSetUp");
  hb->seed  = seed;
  hb->setup = PETSC_FALSE;
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisSetFromOptions(CSHarmonicBasis hb)
{
  PetscInt seed0 = hb->seed;
  PetscFunctionBeginUser;
  PetscOptionsBegin(hb->hdr.comm, hb->hdr.prefix, "Harmonic 1-form basis (crane2013 App. C.1)", NULL);
  PetscCall(CSOptionsInt("-seed", "Seed of the random 1-forms whose harmonic parts span the basis", NULL, hb->seed, &hb->seed, NULL));
  PetscOptionsEnd();
  {
    const CSOptionCheck checks[] = {
      {"seed", (PetscReal)hb->seed, hb->seed >= 0, "must be >= 0"}
    };
    PetscCall(CSCheckOptionValues(hb->hdr.comm, hb->hdr.prefix, 1, checks));
  }
  PetscCheck(!hb->d0 || hb->seed == seed0, hb->hdr.comm, PETSC_ERR_ORDER, "-%sseed: the seed is fixed at the first set-up of the harmonic basis", hb->hdr.prefix ? hb->hdr.prefix : "");
  hb->from_options = PETSC_TRUE;
  hb->setup        = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* Replaces global row and column 0 of A by the identity (grounding a Laplacian with the constants as kernel). */
static PetscErrorCode Ground(Mat A)
{
  PetscMPIInt rank;
  PetscInt    row = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PetscObjectComm((PetscObject)A), &rank));
  PetscCall(MatZeroRowsColumns(A, rank ? 0 : 1, &row, 1.0, NULL, NULL));
  PetscCall(MatSetOption(A, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(A, MAT_SPD, PETSC_TRUE));
  PetscFunctionReturn(0);
}

/* The right-hand side of a grounded system: entry 0 set to 0 (the grounded unknown). */
static PetscErrorCode GroundRHS(Vec b)
{
  PetscInt lo, hi;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(b, &lo, &hi));
  if (lo == 0 && hi > 0) PetscCall(VecSetValue(b, 0, 0.0, INSERT_VALUES));
  PetscCall(VecAssemblyBegin(b));
  PetscCall(VecAssemblyEnd(b));
  PetscFunctionReturn(0);
}

/* A direct Cholesky solver for the grounded SPD A: CHOLMOD serially, the substructured CHOLMOD cssubchol in
   parallel (CSSetDefaultCholesky); options -<prefix><suffix>ksp_type, _pc_type etc. override. */
static PetscErrorCode CreateDirectKSP(CSHarmonicBasis hb, Mat A, const char suffix[], KSP *ksp)
{
  PC   pc;
  char prefix[256];
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%s%s", hb->hdr.prefix, suffix));
  PetscCall(KSPCreate(hb->hdr.comm, ksp));
  PetscCall(KSPSetOptionsPrefix(*ksp, prefix));
  PetscCall(KSPSetOperators(*ksp, A, A));
  PetscCall(KSPSetType(*ksp, KSPPREONLY));
  PetscCall(KSPGetPC(*ksp, &pc));
  PetscCall(CSSetDefaultCholesky(pc));
  if (hb->from_options) PetscCall(KSPSetFromOptions(*ksp));
  PetscFunctionReturn(0);
}

/* a failed factorisation under preonly returns Inf without an error; it would surface later as "dependent forms" */
static PetscErrorCode CheckSolve(KSP ksp)
{
  KSPConvergedReason r;
  const char        *prefix;
  PetscFunctionBeginUser;
  PetscCall(KSPGetConvergedReason(ksp, &r));
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  PetscCheck(r >= 0, PetscObjectComm((PetscObject)ksp), PETSC_ERR_NOT_CONVERGED, "harmonic basis: the solve -%sksp_type ... failed: %s", prefix ? prefix : "", KSPConvergedReasons[r]);
  PetscFunctionReturn(0);
}

/* alpha <- alpha - d1^T Lf^{-1} d1 alpha (step IIa) */
static PetscErrorCode RemoveCoexact(CSHarmonicBasis hb, Vec alpha)
{
  Vec y;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(hb->wF, &y));
  PetscCall(MatMult(hb->d1, alpha, hb->wF));
  PetscCall(GroundRHS(hb->wF));
  PetscCall(KSPSolve(hb->kf, hb->wF, y));
  PetscCall(CheckSolve(hb->kf));
  PetscCall(MatMultTranspose(hb->d1, y, hb->wE));
  PetscCall(VecAXPY(alpha, -1.0, hb->wE));
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

/* alpha <- alpha - d0 L^{-1} d0^T *1 alpha (step IIb) */
static PetscErrorCode RemoveExact(CSHarmonicBasis hb, Vec alpha)
{
  Vec u;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(hb->wV, &u));
  PetscCall(VecPointwiseMult(hb->wE, hb->star1, alpha));
  PetscCall(MatMultTranspose(hb->d0, hb->wE, hb->wV));
  PetscCall(GroundRHS(hb->wV));
  PetscCall(KSPSolve(hb->kv, hb->wV, u));
  PetscCall(CheckSolve(hb->kv));
  PetscCall(MatMult(hb->d0, u, hb->wE));
  PetscCall(VecAXPY(alpha, -1.0, hb->wE));
  PetscCall(VecDestroy(&u));
  PetscFunctionReturn(0);
}

/* <<a, b>> = a^T *1 b */
static PetscErrorCode Inner(CSHarmonicBasis hb, Vec a, Vec b, PetscScalar *c)
{
  PetscFunctionBeginUser;
  PetscCall(VecPointwiseMult(hb->wE, hb->star1, b));
  PetscCall(VecDot(a, hb->wE, c));
  PetscFunctionReturn(0);
}

/* Steps I and IIa, once per mesh: the operators, the face solver and the closed random forms. */
static PetscErrorCode SetUpTopology(CSHarmonicBasis hb)
{
  CSMesh m = hb->mesh;
  Mat    d1t;
  Vec    al;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorDECd0(m, &hb->d0));
  PetscCall(CSOperatorDECd1(m, &hb->d1));
  PetscCall(MatTranspose(hb->d1, MAT_INITIAL_MATRIX, &d1t));
  PetscCall(MatMatMult(hb->d1, d1t, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &hb->Lf));
  PetscCall(MatDestroy(&d1t));
  PetscCall(Ground(hb->Lf));
  PetscCall(CreateDirectKSP(hb, hb->Lf, "face_", &hb->kf));
  PetscCall(DMCreateGlobalVector(m->dmE1, &hb->star1));
  PetscCall(VecDuplicate(hb->star1, &hb->wE));
  PetscCall(DMCreateGlobalVector(m->dmV1, &hb->wV));
  PetscCall(DMCreateGlobalVector(m->dmF1, &hb->wF));
  PetscCall(VecDuplicateVecs(hb->star1, hb->n, &hb->closed));
  PetscCall(VecDuplicateVecs(hb->star1, hb->n, &hb->omega));
  PetscCall(DMGetLocalVector(m->dmE1, &al));
  for (PetscInt i = 0; i < hb->n; i++) {
    PetscScalar *a;
    PetscCall(VecGetArray(al, &a));
    for (PetscInt e = 0; e < m->ne; e++) a[e] = HashUniform((uint64_t)hb->seed * 4099 + (uint64_t)i, (uint64_t)m->edgeNatural[e]);
    PetscCall(VecRestoreArray(al, &a));
    PetscCall(DMLocalToGlobal(m->dmE1, al, INSERT_VALUES, hb->closed[i]));
    PetscCall(RemoveCoexact(hb, hb->closed[i]));
  }
  PetscCall(DMRestoreLocalVector(m->dmE1, &al));
  PetscFunctionReturn(0);
}

/* Step III: modified Gram-Schmidt in <<., .>>, twice. */
static PetscErrorCode Orthonormalise(CSHarmonicBasis hb)
{
  PetscFunctionBeginUser;
  for (int pass = 0; pass < 2; pass++)
    for (PetscInt i = 0; i < hb->n; i++) {
      PetscScalar c;
      for (PetscInt j = 0; j < i; j++) {
        PetscCall(Inner(hb, hb->omega[j], hb->omega[i], &c));
        PetscCall(VecAXPY(hb->omega[i], -c, hb->omega[j]));
      }
      PetscCall(Inner(hb, hb->omega[i], hb->omega[i], &c));
      PetscCheck(PetscRealPart(c) > 0, hb->hdr.comm, PETSC_ERR_PLIB, "harmonic basis of %s: form %" PetscInt_FMT " has <<w, w>> = %g after Gram-Schmidt (dependent random forms?)", hb->mesh->name, i, (double)PetscRealPart(c));
      PetscCall(VecScale(hb->omega[i], 1.0 / PetscSqrtReal(PetscRealPart(c))));
    }
  PetscFunctionReturn(0);
}

/* Step IV (crane2013 App. C.1): in each face, v = a1 e1 + a2 e2 with e1 = p1 - p0, e2 = p2 - p0 and
   [|e1|^2 <e1,e2>; <e1,e2> |e2|^2] [a1; a2] = [omega(p0 -> p1); omega(p0 -> p2)]. The edge opposite corner a runs
   v[a+1] -> v[a+2] counter-clockwise, so omega(p0 -> p1) = s_2 omega_{e[2]} and omega(p0 -> p2) = -s_1 omega_{e[1]}. */
static PetscErrorCode FaceVectors(CSHarmonicBasis hb, Vec omega, Vec v)
{
  CSMesh             m = hb->mesh;
  Vec                xl, ol, vl;
  const PetscReal   *p;
  const PetscScalar *o;
  PetscScalar       *va;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, hb->x, &xl, &p));
  PetscCall(DMGetLocalVector(m->dmE1, &ol));
  PetscCall(DMGlobalToLocal(m->dmE1, omega, INSERT_VALUES, ol));
  PetscCall(DMGetLocalVector(hb->dmF3, &vl));
  PetscCall(VecGetArrayRead(ol, &o));
  PetscCall(VecGetArray(vl, &va));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal e1[3], e2[3], g11, g12, g22, det, w1, w2, a1, a2;
    CSVecSub(F.c[1], F.c[0], e1);
    CSVecSub(F.c[2], F.c[0], e2);
    g11 = CSVecDot(e1, e1);
    g12 = CSVecDot(e1, e2);
    g22 = CSVecDot(e2, e2);
    det = g11 * g22 - g12 * g12;
    w1  = (CSMeshEdgeSide(m, &F, 2) == 0 ? 1 : -1) * PetscRealPart(o[F.e[2]]);
    w2  = -(CSMeshEdgeSide(m, &F, 1) == 0 ? 1 : -1) * PetscRealPart(o[F.e[1]]);
    a1  = (g22 * w1 - g12 * w2) / det;
    a2  = (g11 * w2 - g12 * w1) / det;
    for (int d = 0; d < 3; d++) va[3 * F.f + d] = a1 * e1[d] + a2 * e2[d];
  }
  PetscCall(VecRestoreArray(vl, &va));
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(DMLocalToGlobal(hb->dmF3, vl, INSERT_VALUES, v));
  PetscCall(DMRestoreLocalVector(hb->dmF3, &vl));
  PetscCall(DMRestoreLocalVector(m->dmE1, &ol));
  PetscCall(CSMeshRestoreLocalPositions(m, hb->x, &xl, &p));
  PetscFunctionReturn(0);
}

/* Steps IIb-IV at the current positions. */
static PetscErrorCode SetUpGeometry(CSHarmonicBasis hb)
{
  PetscFunctionBeginUser;
  PetscCall(CSOperatorHodgeStar1(hb->mesh, hb->x, hb->star1));
  PetscCall(CSOperatorLaplacian(hb->mesh, hb->x, hb->L ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &hb->L));
  PetscCall(Ground(hb->L));
  if (!hb->kv) PetscCall(CreateDirectKSP(hb, hb->L, "vertex_", &hb->kv));
  else PetscCall(KSPSetOperators(hb->kv, hb->L, hb->L));
  for (PetscInt i = 0; i < hb->n; i++) {
    /* exact part out, then both again on the (small, mostly harmonic) rest: the round-off of the first solves
       is relative to the large exact part of the random form, the second pass makes it relative to omega */
    PetscCall(VecCopy(hb->closed[i], hb->omega[i]));
    PetscCall(RemoveExact(hb, hb->omega[i]));
    PetscCall(RemoveCoexact(hb, hb->omega[i]));
    PetscCall(RemoveExact(hb, hb->omega[i]));
  }
  PetscCall(Orthonormalise(hb));
  if (!hb->v) {
    Vec t;
    PetscCall(DMCreateGlobalVector(hb->dmF3, &t));
    PetscCall(VecDuplicateVecs(t, hb->n, &hb->v));
    PetscCall(VecDestroy(&t));
  }
  for (PetscInt i = 0; i < hb->n; i++) PetscCall(FaceVectors(hb, hb->omega[i], hb->v[i]));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisSetUp(CSHarmonicBasis hb)
{
  PetscFunctionBeginUser;
  if (hb->setup) PetscFunctionReturn(0);
  PetscCall(PetscLogEventBegin(CS_EVENT_HarmonicBasis, 0, 0, 0, 0));
  if (!hb->dmF3) PetscCall(CSMeshCreateFieldDM(hb->mesh->dm, 2, 3, "face3", &hb->dmF3));
  if (hb->n) { /* genus 0: nothing to compute */
    if (!hb->d0) PetscCall(SetUpTopology(hb));
    PetscCall(SetUpGeometry(hb));
  }
  PetscCall(PetscLogEventEnd(CS_EVENT_HarmonicBasis, 0, 0, 0, 0));
  hb->setup = PETSC_TRUE;
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisUpdate(CSHarmonicBasis hb, Vec x)
{
  PetscFunctionBeginUser;
  PetscCall(VecCopy(x, hb->x));
  hb->setup = PETSC_FALSE;
  PetscCall(CSHarmonicBasisSetUp(hb));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisUpdateFaceVectors(CSHarmonicBasis hb, Vec x)
{
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisSetUp(hb));
  PetscCall(VecCopy(x, hb->x));
  for (PetscInt i = 0; i < hb->n; i++) PetscCall(FaceVectors(hb, hb->omega[i], hb->v[i]));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisGetSize(CSHarmonicBasis hb, PetscInt *n)
{
  PetscFunctionBeginUser;
  *n = hb->n;
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckIndex(CSHarmonicBasis hb, PetscInt i, const char caller[])
{
  PetscFunctionBeginUser;
  PetscCheck(i >= 0 && i < hb->n, hb->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "%s: index %" PetscInt_FMT " out of range: the basis of %s (genus %" PetscInt_FMT ") has %" PetscInt_FMT " forms", caller, i, hb->mesh->name, hb->g, hb->n);
  PetscCall(CSHarmonicBasisSetUp(hb));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisGetForm(CSHarmonicBasis hb, PetscInt i, Vec *omega)
{
  PetscFunctionBeginUser;
  PetscCall(CheckIndex(hb, i, "CSHarmonicBasisGetForm"));
  *omega = hb->omega[i];
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisGetFaceDM(CSHarmonicBasis hb, DM *dmF3)
{
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisSetUp(hb));
  *dmF3 = hb->dmF3;
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisGetFaceVectors(CSHarmonicBasis hb, PetscInt i, Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(CheckIndex(hb, i, "CSHarmonicBasisGetFaceVectors"));
  *v = hb->v[i];
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisInner(CSHarmonicBasis hb, Vec alpha, PetscScalar c[])
{
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisSetUp(hb));
  PetscCall(VecPointwiseMult(hb->wE, hb->star1, alpha));
  if (hb->n) PetscCall(VecMDot(hb->wE, hb->n, hb->omega, c));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisProject(CSHarmonicBasis hb, Vec alpha, Vec h)
{
  PetscScalar c[64];
  PetscFunctionBeginUser;
  PetscCheck(hb->n <= 64, hb->hdr.comm, PETSC_ERR_SUP, "CSHarmonicBasisProject: genus %" PetscInt_FMT " > 32", hb->g);
  PetscCall(CSHarmonicBasisInner(hb, alpha, c));
  PetscCall(VecSet(h, 0.0));
  if (hb->n) PetscCall(VecMAXPY(h, hb->n, c, hb->omega));
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisHarmonicNorm(CSHarmonicBasis hb, Vec beta, PetscInt bs, PetscReal *hnorm)
{
  const PetscScalar *b;
  PetscScalar       *c, *w;
  PetscInt           n;
  PetscReal          s = 0;
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisSetUp(hb));
  PetscCall(PetscMalloc1(hb->n + 1, &c));
  PetscCall(VecGetLocalSize(hb->wE, &n));
  for (PetscInt k = 0; k < bs; k++) {
    PetscCall(VecGetArrayRead(beta, &b));
    PetscCall(VecGetArray(hb->wE, &w));
    for (PetscInt e = 0; e < n; e++) w[e] = b[bs * e + k];
    PetscCall(VecRestoreArray(hb->wE, &w));
    PetscCall(VecRestoreArrayRead(beta, &b));
    PetscCall(VecPointwiseMult(hb->wE, hb->star1, hb->wE));
    if (hb->n) PetscCall(VecMDot(hb->wE, hb->n, hb->omega, c));
    for (PetscInt i = 0; i < hb->n; i++) s += PetscRealPart(c[i] * PetscConj(c[i]));
  }
  PetscCall(PetscFree(c));
  *hnorm = PetscSqrtReal(s);
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisGetResiduals(CSHarmonicBasis hb, PetscReal *closed, PetscReal *coclosed, PetscReal *orthonormal)
{
  PetscReal rc = 0, rd = 0, ro = 0;
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisSetUp(hb));
  for (PetscInt i = 0; i < hb->n; i++) {
    PetscReal a, b;
    PetscCall(MatMult(hb->d1, hb->omega[i], hb->wF));
    PetscCall(VecNorm(hb->wF, NORM_2, &a));
    PetscCall(VecNorm(hb->omega[i], NORM_2, &b));
    rc = PetscMax(rc, a / b);
    PetscCall(VecPointwiseMult(hb->wE, hb->star1, hb->omega[i]));
    PetscCall(VecNorm(hb->wE, NORM_2, &b));
    PetscCall(MatMultTranspose(hb->d0, hb->wE, hb->wV));
    PetscCall(VecNorm(hb->wV, NORM_2, &a));
    rd = PetscMax(rd, a / b);
    for (PetscInt j = 0; j < hb->n; j++) {
      PetscScalar c;
      PetscCall(Inner(hb, hb->omega[i], hb->omega[j], &c));
      ro = PetscMax(ro, PetscAbsReal(PetscRealPart(c) - (i == j ? 1.0 : 0.0)));
    }
  }
  if (closed) *closed = rc;
  if (coclosed) *coclosed = rd;
  if (orthonormal) *orthonormal = ro;
  PetscFunctionReturn(0);
}

PetscErrorCode CSHarmonicBasisDestroy(CSHarmonicBasis *hb)
{
  CSHarmonicBasis h = *hb;
  PetscFunctionBeginUser;
  if (!h) PetscFunctionReturn(0);
  PetscCall(MatDestroy(&h->d0));
  PetscCall(MatDestroy(&h->d1));
  PetscCall(MatDestroy(&h->L));
  PetscCall(MatDestroy(&h->Lf));
  PetscCall(KSPDestroy(&h->kv));
  PetscCall(KSPDestroy(&h->kf));
  PetscCall(VecDestroy(&h->x));
  PetscCall(VecDestroy(&h->star1));
  PetscCall(VecDestroy(&h->wE));
  PetscCall(VecDestroy(&h->wV));
  PetscCall(VecDestroy(&h->wF));
  if (h->closed) PetscCall(VecDestroyVecs(h->n, &h->closed));
  if (h->omega) PetscCall(VecDestroyVecs(h->n, &h->omega));
  if (h->v) PetscCall(VecDestroyVecs(h->n, &h->v));
  PetscCall(DMDestroy(&h->dmF3));
  PetscCall(CSObjectDestroy((CSObject *)hb));
  PetscFunctionReturn(0);
}
