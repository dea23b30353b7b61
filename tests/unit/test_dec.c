/* Unit checks of the DEC operators and the harmonic basis (include/cs_operators_dec.h), serial and under mpirun,
   on an icosphere (g = 0), the generated torus and knot1_cgal.obj (g = 1), eight_cgal.obj (2), elephant_cgal.obj (3):
   - d1 d0 = 0 exactly, and d0^T *1 d0 is the cotan Laplacian of laplacian.c;
   - the basis has 2g forms, closed (|d1 w| / |w|) and co-closed (|d0^T *1 w| / |*1 w|) below 1e-12, *1-orthonormal
     to 1e-12; a basis from another seed spans the same space (the harmonic space is unique);
   - the projection is the identity on the basis and annihilates exact forms d0 u;
   - the face vectors lie in their faces' planes and reproduce the form on all three edges of every face;
   - the basis at the doubled positions (CSHarmonicBasisUpdate) is the same (the *1 of a surface is scale invariant);
   - on a clean torus of revolution d(phi) lies in the harmonic span, d(theta) does not;
   - a mesh with boundary is refused.
   Prints a line per check and the set-up time; exit status = number of failures. */
#include "cs_operators_dec.h"
#include "cs_mesh_adjacency.h"
#include "cs_package.h"
#include "cs_test.h"

/* A test mesh: a file (path not NULL) or a generated shape with noise amp */
typedef struct {
  const char    *path, *name;
  CSTestMeshSpec spec;
  PetscReal      amp;
  PetscInt       genus;
} Source;

static PetscErrorCode MakeMesh(MPI_Comm comm, const Source *src, CSMesh *mesh)
{
  CSMeshData  md;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  if (!src->path) {
    PetscCall(CSTestMesh(comm, src->spec, src->amp, 5, mesh));
    PetscFunctionReturn(0);
  }
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(&md, sizeof(md)));
  if (!rank) PetscCall(CSMeshDataRead(src->path, &md));
  PetscCall(CSTestDistribute(comm, &md, 0, 0, mesh));
  PetscFunctionReturn(0);
}

/* On several ranks: the forms in file (natural) edge order equal those of the same mesh on rank 0 alone
   (same random forms, same edge orientations), max |difference|. */
static PetscErrorCode CompareSerial(CSMesh m, CSHarmonicBasis hb, const Source *src, PetscReal *diff)
{
  PetscMPIInt size, rank;
  PetscInt    n;
  Vec        *nat;
  PetscReal   d = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(m->comm, &size));
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  *diff = 0;
  if (size == 1) PetscFunctionReturn(0);
  PetscCall(CSHarmonicBasisGetSize(hb, &n));
  PetscCall(PetscMalloc1(n, &nat));
  for (PetscInt i = 0; i < n; i++) {
    Vec w, g;
    PetscCall(CSHarmonicBasisGetForm(hb, i, &w));
    PetscCall(CSMeshGather(&m->natE1, w, &g));
    PetscCall(VecDuplicate(g, &nat[i]));
    PetscCall(VecCopy(g, nat[i]));
  }
  if (!rank) {
    CSMesh          ms;
    CSHarmonicBasis hs;
    PetscCall(MakeMesh(PETSC_COMM_SELF, src, &ms));
    PetscCall(CSHarmonicBasisCreate(ms, ms->x, &hs));
    for (PetscInt i = 0; i < n; i++) {
      Vec w, g;
      PetscCall(CSHarmonicBasisGetForm(hs, i, &w));
      const PetscScalar *a, *b;
      PetscInt           len;
      PetscCall(CSMeshGather(&ms->natE1, w, &g));
      PetscCall(VecGetLocalSize(g, &len));
      PetscCall(VecGetArrayRead(nat[i], &a)); /* the gathered vector lives on m->comm: no collective calls here */
      PetscCall(VecGetArrayRead(g, &b));
      for (PetscInt k = 0; k < len; k++) d = PetscMax(d, PetscAbsScalar(a[k] - b[k]));
      PetscCall(VecRestoreArrayRead(g, &b));
      PetscCall(VecRestoreArrayRead(nat[i], &a));
    }
    PetscCall(CSHarmonicBasisDestroy(&hs));
    PetscCall(CSMeshDestroy(&ms));
  }
  PetscCall(MPIU_Allreduce(&d, diff, 1, MPIU_REAL, MPIU_MAX, m->comm));
  for (PetscInt i = 0; i < n; i++) PetscCall(VecDestroy(&nat[i]));
  PetscCall(PetscFree(nat));
  PetscFunctionReturn(0);
}

/* |d1 d0|_F = 0 exactly; |d0^T *1 d0 - L|_F / |L|_F */
static PetscErrorCode CheckOperators(CSMesh m, const char name[])
{
  Mat       d0, d1, P, S, L;
  Vec       w;
  PetscReal nP, nL, nD;
  char      what[128];
  PetscFunctionBeginUser;
  PetscCall(CSOperatorDECd0(m, &d0));
  PetscCall(CSOperatorDECd1(m, &d1));
  PetscCall(MatMatMult(d1, d0, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &P));
  PetscCall(MatNorm(P, NORM_FROBENIUS, &nP));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: |d1 d0| = 0 exactly", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(nP == 0), what, nP, 0));
  PetscCall(DMCreateGlobalVector(m->dmE1, &w));
  PetscCall(CSOperatorHodgeStar1(m, m->x, w));
  PetscCall(MatDuplicate(d0, MAT_COPY_VALUES, &S));
  PetscCall(MatDiagonalScale(S, w, NULL));
  PetscCall(MatDestroy(&P));
  PetscCall(MatTransposeMatMult(d0, S, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &P));
  PetscCall(CSOperatorLaplacian(m, m->x, MAT_INITIAL_MATRIX, &L));
  PetscCall(MatNorm(L, NORM_FROBENIUS, &nL));
  PetscCall(MatAXPY(P, -1.0, L, DIFFERENT_NONZERO_PATTERN));
  PetscCall(MatNorm(P, NORM_FROBENIUS, &nD));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: |d0^T *1 d0 - L| / |L|", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(nD <= 1e-14 * nL), what, nD / nL, 1e-14));
  PetscCall(MatDestroy(&P));
  PetscCall(MatDestroy(&S));
  PetscCall(MatDestroy(&L));
  PetscCall(MatDestroy(&d0));
  PetscCall(MatDestroy(&d1));
  PetscCall(VecDestroy(&w));
  PetscFunctionReturn(0);
}

/* Face vectors: max |<v, N>| / |v| and max_f,a |<v, p_{a+2} - p_{a+1}> - s_a w_e| / max|w|. */
static PetscErrorCode CheckFaceVectors(CSMesh m, Vec x, CSHarmonicBasis hb, PetscInt i, PetscReal *tang, PetscReal *repro)
{
  Vec                om, ol, v, xl;
  DM                 dmF3;
  const PetscReal   *p;
  const PetscScalar *o, *va;
  PetscReal          wmax, t = 0, r = 0;
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisGetForm(hb, i, &om));
  PetscCall(CSHarmonicBasisGetFaceVectors(hb, i, &v));
  PetscCall(CSHarmonicBasisGetFaceDM(hb, &dmF3));
  PetscCall(VecNorm(om, NORM_INFINITY, &wmax));
  PetscCall(DMGetLocalVector(m->dmE1, &ol));
  PetscCall(DMGlobalToLocal(m->dmE1, om, INSERT_VALUES, ol));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  PetscCall(VecGetArrayRead(ol, &o));
  PetscCall(VecGetArrayRead(v, &va)); /* local face f is block f (overlap 0) */
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    PetscReal N[3], vf[3];
    for (int d = 0; d < 3; d++) vf[d] = PetscRealPart(va[3 * F.f + d]);
    CSTriangleNormal(F.c, N);
    if (CSVecNorm(vf) > 0) t = PetscMax(t, PetscAbsReal(CSVecDot(vf, N)) / CSVecNorm(vf));
    for (int a = 0; a < 3; a++) {
      PetscReal e[3], s = CSMeshEdgeSide(m, &F, a) == 0 ? 1 : -1;
      CSVecSub(F.c[(a + 2) % 3], F.c[(a + 1) % 3], e);
      r = PetscMax(r, PetscAbsReal(CSVecDot(vf, e) - s * PetscRealPart(o[F.e[a]])) / wmax);
    }
  }
  PetscCall(VecRestoreArrayRead(v, &va));
  PetscCall(VecRestoreArrayRead(ol, &o));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(DMRestoreLocalVector(m->dmE1, &ol));
  PetscCall(MPIU_Allreduce(&t, tang, 1, MPIU_REAL, MPIU_MAX, m->comm));
  PetscCall(MPIU_Allreduce(&r, repro, 1, MPIU_REAL, MPIU_MAX, m->comm));
  PetscFunctionReturn(0);
}

/* max_i |a_i - P_b a_i|_*1 (a: basis hb's forms, P_b: projection onto the span of other's) */
static PetscErrorCode SpanDistance(CSHarmonicBasis hb, CSHarmonicBasis other, Vec star1, PetscReal *dist)
{
  PetscInt n;
  Vec      h, t;
  PetscFunctionBeginUser;
  *dist = 0;
  PetscCall(CSHarmonicBasisGetSize(hb, &n));
  PetscCall(VecDuplicate(star1, &h));
  PetscCall(VecDuplicate(star1, &t));
  for (PetscInt i = 0; i < n; i++) {
    Vec         w;
    PetscScalar c;
    PetscCall(CSHarmonicBasisGetForm(hb, i, &w));
    PetscCall(CSHarmonicBasisProject(other, w, h));
    PetscCall(VecAYPX(h, -1.0, w));
    PetscCall(VecPointwiseMult(t, star1, h));
    PetscCall(VecDot(h, t, &c));
    *dist = PetscMax(*dist, PetscSqrtReal(PetscAbsReal(PetscRealPart(c))));
  }
  PetscCall(VecDestroy(&h));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

/* |P(d0 u)|_*1 / |d0 u|_*1 for a smooth-ish u (the x coordinate) */
static PetscErrorCode ExactProjection(CSMesh m, CSHarmonicBasis hb, Vec star1, PetscReal *rel)
{
  Mat         d0;
  Vec         u, du, h, t;
  PetscScalar a, b;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorDECd0(m, &d0));
  PetscCall(DMCreateGlobalVector(m->dmV1, &u));
  PetscCall(VecStrideGather(m->x, 0, u, INSERT_VALUES));
  PetscCall(VecDuplicate(star1, &du));
  PetscCall(VecDuplicate(star1, &h));
  PetscCall(VecDuplicate(star1, &t));
  PetscCall(MatMult(d0, u, du));
  PetscCall(CSHarmonicBasisProject(hb, du, h));
  PetscCall(VecPointwiseMult(t, star1, h));
  PetscCall(VecDot(h, t, &a));
  PetscCall(VecPointwiseMult(t, star1, du));
  PetscCall(VecDot(du, t, &b));
  *rel = PetscSqrtReal(PetscAbsReal(PetscRealPart(a) / PetscRealPart(b)));
  PetscCall(MatDestroy(&d0));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&du));
  PetscCall(VecDestroy(&h));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

/* beta = df (3 components per edge): harmonic norm 0; beta + omega_0 (1, 2, 3): sqrt(14). Returns the larger error. */
static PetscErrorCode CheckHarmonicNorm(CSMesh m, CSHarmonicBasis hb, PetscReal *err)
{
  Mat                d0;
  Vec                u, du, beta, w0;
  const PetscScalar *a, *o;
  PetscScalar       *b;
  PetscInt           n;
  PetscReal          h0, h1;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorDECd0(m, &d0));
  PetscCall(DMCreateGlobalVector(m->dmV1, &u));
  PetscCall(DMCreateGlobalVector(m->dmE1, &du));
  PetscCall(VecGetLocalSize(du, &n));
  PetscCall(VecCreateMPI(m->comm, 3 * n, PETSC_DETERMINE, &beta));
  for (PetscInt c = 0; c < 3; c++) {
    PetscCall(VecStrideGather(m->x, c, u, INSERT_VALUES));
    PetscCall(MatMult(d0, u, du));
    PetscCall(VecGetArrayRead(du, &a));
    PetscCall(VecGetArray(beta, &b));
    for (PetscInt e = 0; e < n; e++) b[3 * e + c] = a[e];
    PetscCall(VecRestoreArray(beta, &b));
    PetscCall(VecRestoreArrayRead(du, &a));
  }
  PetscCall(CSHarmonicBasisHarmonicNorm(hb, beta, 3, &h0));
  PetscCall(CSHarmonicBasisGetForm(hb, 0, &w0));
  PetscCall(VecGetArrayRead(w0, &o));
  PetscCall(VecGetArray(beta, &b));
  for (PetscInt e = 0; e < n; e++)
    for (PetscInt c = 0; c < 3; c++) b[3 * e + c] += (c + 1) * o[e];
  PetscCall(VecRestoreArray(beta, &b));
  PetscCall(VecRestoreArrayRead(w0, &o));
  PetscCall(CSHarmonicBasisHarmonicNorm(hb, beta, 3, &h1));
  *err = PetscMax(h0, PetscAbsReal(h1 - PetscSqrtReal(14.0)));
  PetscCall(MatDestroy(&d0));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&du));
  PetscCall(VecDestroy(&beta));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckResiduals(MPI_Comm comm, CSHarmonicBasis hb, const char name[], const char when[])
{
  PetscReal rc, rd, ro;
  char      what[160];
  PetscFunctionBeginUser;
  PetscCall(CSHarmonicBasisGetResiduals(hb, &rc, &rd, &ro));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s%s: closed |d1 w|/|w|", name, when));
  PetscCall(CSTestCheck(comm, (PetscBool)(rc < 1e-12), what, rc, 1e-12));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s%s: co-closed |d0^T *1 w|/|*1 w|", name, when));
  PetscCall(CSTestCheck(comm, (PetscBool)(rd < 1e-12), what, rd, 1e-12));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s%s: *1-orthonormal", name, when));
  PetscCall(CSTestCheck(comm, (PetscBool)(ro < 1e-12), what, ro, 1e-12));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckBasis(MPI_Comm comm, const Source *src)
{
  CSHarmonicBasis hb, hb2;
  CSMesh          m;
  const char     *name  = src->name;
  PetscInt        genus = src->genus, n, chi;
  PetscLogDouble  t0, t1;
  Vec             star1, x2;
  PetscReal       d, tang = 0, repro = 0;
  char            what[160];
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, src, &m));
  chi = m->Nv - m->Ne + m->Nf;
  PetscCall(CheckOperators(m, name));
  PetscCall(PetscTime(&t0));
  PetscCall(CSHarmonicBasisCreate(m, m->x, &hb));
  PetscCall(CSHarmonicBasisSetFromOptions(hb));
  PetscCall(CSHarmonicBasisSetUp(hb));
  PetscCall(PetscTime(&t1));
  PetscCall(CSHarmonicBasisGetSize(hb, &n));
  PetscCall(PetscPrintf(m->comm, "     %s: V %" PetscInt_FMT " E %" PetscInt_FMT " F %" PetscInt_FMT ", chi %" PetscInt_FMT ", %" PetscInt_FMT " harmonic forms, set-up %.3f s\n", name, m->Nv, m->Ne, m->Nf, chi, n, t1 - t0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: basis size = 2g = %" PetscInt_FMT, name, 2 * genus));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(n == 2 * genus), what, (PetscReal)n, (PetscReal)(2 * genus)));
  if (n) {
    PetscCall(CheckResiduals(m->comm, hb, name, ""));
    PetscCall(DMCreateGlobalVector(m->dmE1, &star1));
    PetscCall(CSOperatorHodgeStar1(m, m->x, star1));
    PetscCall(CSHarmonicBasisCreate(m, m->x, &hb2));
    PetscCall(CSHarmonicBasisSetSeed(hb2, 7));
    PetscCall(SpanDistance(hb, hb2, star1, &d));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: seeds 1 and 7 span the same space", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-11), what, d, 1e-11));
    PetscCall(SpanDistance(hb, hb, star1, &d));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: projection is the identity on the basis", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-12), what, d, 1e-12));
    PetscCall(CheckHarmonicNorm(m, hb, &d));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: HarmonicNorm(df + w_0 (1,2,3)) = sqrt(14), of df 0", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-12), what, d, 1e-12));
    PetscCall(ExactProjection(m, hb, star1, &d));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: projection of d0 x vanishes", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-12), what, d, 1e-12));
    for (PetscInt i = 0; i < n; i++) {
      PetscReal ti, ri;
      PetscCall(CheckFaceVectors(m, m->x, hb, i, &ti, &ri));
      tang  = PetscMax(tang, ti);
      repro = PetscMax(repro, ri);
    }
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: face vectors tangent |<v,N>|/|v|", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(tang < 1e-12), what, tang, 1e-12));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: face vectors reproduce w on every edge", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(repro < 1e-12), what, repro, 1e-12));
    /* doubled positions: the same *1, so the same basis */
    PetscCall(VecDuplicate(m->x, &x2));
    PetscCall(VecCopy(m->x, x2));
    PetscCall(VecScale(x2, 2.0));
    PetscCall(CSHarmonicBasisUpdate(hb2, x2));
    PetscCall(CheckResiduals(m->comm, hb2, name, " (Update, 2x)"));
    PetscCall(SpanDistance(hb, hb2, star1, &d));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: basis at 2x spans the same space", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-11), what, d, 1e-11));
    /* the same forms at 2x: face vectors halved, still reproducing the forms at 2x */
    PetscCall(CSHarmonicBasisUpdateFaceVectors(hb, x2));
    tang = repro = 0;
    for (PetscInt i = 0; i < n; i++) {
      PetscReal ti, ri;
      PetscCall(CheckFaceVectors(m, x2, hb, i, &ti, &ri));
      tang  = PetscMax(tang, ti);
      repro = PetscMax(repro, ri);
    }
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: UpdateFaceVectors(2x): tangent, reproducing w", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(tang < 1e-12 && repro < 1e-12), what, PetscMax(tang, repro), 1e-12));
    PetscCall(CSHarmonicBasisUpdateFaceVectors(hb, m->x));
    PetscCall(CompareSerial(m, hb, src, &d));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: the same forms (file order) as on one rank", name));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-11), what, d, 1e-11));
    PetscCall(VecDestroy(&x2));
    PetscCall(VecDestroy(&star1));
    PetscCall(CSHarmonicBasisDestroy(&hb2));
  }
  PetscCall(CSHarmonicBasisDestroy(&hb));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* On a torus of revolution about z (no noise) d(phi), phi = atan2(y, x), is harmonic (smooth setting), and its
   discrete version (wrapped angle differences, exactly closed) measures *1-distance 1e-15 from the span of the
   basis on the generated (rotationally symmetric) torus; the tube angle's d(theta) is closed but not co-closed
   (its harmonic representative is not d(theta)), so it stays far (0.23). */
static PetscErrorCode CheckTorusAngles(MPI_Comm comm, PetscInt n, PetscInt mm, PetscReal bound)
{
  CSMesh           m;
  CSHarmonicBasis  hb;
  Vec              al, a, h, t, star1, xl;
  const PetscReal *p;
  PetscReal        dist[2];
  char             what[160];
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_TORUS, n, mm, 3.0, 1.0}, 0, 0, &m));
  PetscCall(CSHarmonicBasisCreate(m, m->x, &hb));
  PetscCall(DMCreateGlobalVector(m->dmE1, &a));
  PetscCall(VecDuplicate(a, &h));
  PetscCall(VecDuplicate(a, &t));
  PetscCall(VecDuplicate(a, &star1));
  PetscCall(CSOperatorHodgeStar1(m, m->x, star1));
  PetscCall(CSMeshGetLocalPositions(m, m->x, &xl, &p));
  for (int k = 0; k < 2; k++) {
    PetscScalar *aa, c1, c2;
    PetscCall(DMGetLocalVector(m->dmE1, &al));
    PetscCall(VecGetArray(al, &aa));
    for (PetscInt e = 0; e < m->ne; e++) {
      const PetscReal *pi = p + 3 * m->edgeVert[2 * e], *pj = p + 3 * m->edgeVert[2 * e + 1];
      PetscReal        ai, aj, d;
      if (!k) {
        ai = PetscAtan2Real(pi[1], pi[0]);
        aj = PetscAtan2Real(pj[1], pj[0]);
      } else { /* tube angle about the core circle of radius 3 */
        ai = PetscAtan2Real(pi[2], PetscSqrtReal(pi[0] * pi[0] + pi[1] * pi[1]) - 3.0);
        aj = PetscAtan2Real(pj[2], PetscSqrtReal(pj[0] * pj[0] + pj[1] * pj[1]) - 3.0);
      }
      d     = aj - ai;
      aa[e] = d > PETSC_PI ? d - 2 * PETSC_PI : (d < -PETSC_PI ? d + 2 * PETSC_PI : d);
    }
    PetscCall(VecRestoreArray(al, &aa));
    PetscCall(DMLocalToGlobal(m->dmE1, al, INSERT_VALUES, a));
    PetscCall(DMRestoreLocalVector(m->dmE1, &al));
    PetscCall(CSHarmonicBasisProject(hb, a, h));
    PetscCall(VecAYPX(h, -1.0, a));
    PetscCall(VecPointwiseMult(t, star1, h));
    PetscCall(VecDot(h, t, &c1));
    PetscCall(VecPointwiseMult(t, star1, a));
    PetscCall(VecDot(a, t, &c2));
    dist[k] = PetscSqrtReal(PetscRealPart(c1) / PetscRealPart(c2));
  }
  PetscCall(CSMeshRestoreLocalPositions(m, m->x, &xl, &p));
  PetscCall(PetscSNPrintf(what, sizeof(what), "torus %" PetscInt_FMT "x%" PetscInt_FMT ": d(phi) within the harmonic span (d(theta): %.3f)", n, mm, (double)dist[1]));
  PetscCall(CSTestCheck(comm, (PetscBool)(dist[0] < bound && dist[1] > 0.1), what, dist[0], bound));
  PetscCall(VecDestroy(&a));
  PetscCall(VecDestroy(&h));
  PetscCall(VecDestroy(&t));
  PetscCall(VecDestroy(&star1));
  PetscCall(CSHarmonicBasisDestroy(&hb));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* A mesh with boundary: CSHarmonicBasisCreate fails (on every rank) with a message. */
static PetscErrorCode CheckBoundaryRefused(MPI_Comm comm)
{
  CSMesh          m;
  CSHarmonicBasis hb = NULL;
  PetscErrorCode  ierr;
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_CYLINDER, 12, 5, 0, 0}, 0, 0, &m));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = CSHarmonicBasisCreate(m, m->x, &hb);
  PetscCall(PetscPopErrorHandler());
  PetscCall(CSTestCheck(comm, (PetscBool)(ierr != 0 && !hb), "cylinder (boundary): CSHarmonicBasisCreate refuses", (PetscReal)ierr, 0));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm     comm;
  const Source src[] = {
    {NULL,                        "icosphere 3",       {CS_TEST_ICOSPHERE, 3, 0, 0, 0},     0,    0},
    {NULL,                        "torus 24x12 bumpy", {CS_TEST_TORUS, 24, 12, 3.0, 1.0}, 0.02, 1},
    {"meshes/knot1_cgal.obj",     "knot1_cgal",        {0},                                 0,    1},
    {"meshes/eight_cgal.obj",     "eight_cgal",        {0},                                 0,    2},
    {"meshes/elephant_cgal.obj",  "elephant_cgal",     {0},                                 0,    3},
  };
  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CSInitializePackage()); /* the PC cssubchol of the parallel solves */
  for (size_t k = 0; k < sizeof(src) / sizeof(src[0]); k++) PetscCall(CheckBasis(comm, &src[k]));
  PetscCall(CheckTorusAngles(comm, 24, 12, 1e-12));
  PetscCall(CheckBoundaryRefused(comm));
  return CSTestFinalize(comm, PetscFinalize);
}
