/* Unit checks of the Bobenko-Schroeder energy (bobenko-schroeder2005): the diamond kernel against central
   differences (Eq. 1), W = 0 on an inscribed Delaunay mesh, W >= 0, Moebius invariance, the assembled
   gradient against finite differences (closed and free boundary), grad W = K x, and the fixed set.
   Prints a line per check; exit status = number of failures. Runs serial and under mpirun. */
#include "cs_energy_bs.h"
#include "cs_test.h"

/* kind 0: icosphere (projected), 1: disk, 2: linearly subdivided icosahedron */
static PetscErrorCode MakeMesh(MPI_Comm comm, int kind, PetscInt level, CSMesh *mesh)
{
  const CSTestShape shapes[] = {CS_TEST_ICOSPHERE, CS_TEST_DISK, CS_TEST_ICOSAHEDRON};
  CSTestMeshSpec    spec     = {shapes[kind], level, 0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, spec, 0, 0, mesh));
  PetscFunctionReturn(0);
}

/* Deterministic noise of amplitude amp, a hash of the vertex's file index: the same mesh for any number of
   ranks (VecSetRandom on the distributed vector would depend on the partition). */
static PetscErrorCode AddNoise(CSMesh mesh, PetscReal amp, unsigned long seed)
{
  Vec          nat;
  PetscInt     n;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGather(&mesh->natV3, mesh->x, &nat));
  PetscCall(VecGetLocalSize(nat, &n));
  PetscCall(VecGetArray(nat, &a));
  for (PetscInt k = 0; k < n; k++) {
    PetscReal t = PetscSinReal(12.9898 * (PetscReal)k + 78.233 * (PetscReal)seed) * 43758.5453;
    a[k] += amp * (2 * (t - PetscFloorReal(t)) - 1);
  }
  PetscCall(VecRestoreArray(nat, &a));
  PetscCall(CSMeshScatter(&mesh->natV3, nat, mesh->x));
  PetscFunctionReturn(0);
}

/* Diamond kernel: grad beta = M P against central differences of beta, for random diamonds. */
static PetscErrorCode CheckDiamond(MPI_Comm comm)
{
  PetscRandom r;
  PetscReal   worst = 0, worstsym = 0;
  PetscFunctionBeginUser;
  PetscCall(CSTestRandom(PETSC_COMM_SELF, -1, 1, 7, &r));
  for (int t = 0; t < 50; t++) {
    PetscReal        X[4][3], M[4][4], beta, h = 1e-6;
    const PetscReal *P[4] = {X[0], X[1], X[2], X[3]};
    PetscBool        act;
    for (int q = 0; q < 4; q++)
      for (int d = 0; d < 3; d++) PetscCall(PetscRandomGetValueReal(r, &X[q][d]));
    CSBSDiamond(P, 1e-6, &beta, M, &act);
    if (!act || PetscSinReal(beta) < 1e-2) continue; /* away from beta = 0 */
    for (int q = 0; q < 4; q++) {
      PetscReal an[3] = {0, 0, 0}, fd[3], num = 0, den = 0;
      for (int d = 0; d < 3; d++) {
        PetscReal       bp, bm, Mz[4][4], s = X[q][d];
        for (int m = 0; m < 4; m++) an[d] += M[q][m] * X[m][d];
        X[q][d] = s + h;
        CSBSDiamond(P, 1e-6, &bp, Mz, &act);
        X[q][d] = s - h;
        CSBSDiamond(P, 1e-6, &bm, Mz, &act);
        X[q][d] = s;
        fd[d]   = (bp - bm) / (2 * h);
      }
      for (int d = 0; d < 3; d++) {
        num += PetscSqr(an[d] - fd[d]);
        den += PetscSqr(fd[d]);
      }
      worst = PetscMax(worst, PetscSqrtReal(num / den));
    }
    /* beta is invariant under cyclic permutations and reflections of (k, j, l, i) (Sec. 3.1) */
    {
      const PetscReal *Q[4] = {X[1], X[2], X[3], X[0]}, *R[4] = {X[3], X[2], X[1], X[0]};
      PetscReal        b2, b3, Mz[4][4];
      CSBSDiamond(Q, 1e-6, &b2, Mz, &act);
      CSBSDiamond(R, 1e-6, &b3, Mz, &act);
      worstsym = PetscMax(worstsym, PetscMax(PetscAbsReal(b2 - beta), PetscAbsReal(b3 - beta)));
    }
  }
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(CSTestCheck(comm, (PetscBool)(worst < 1e-6), "diamond: Eq. 1 gradient vs central differences (rel)", worst, 1e-6));
  PetscCall(CSTestCheck(comm, (PetscBool)(worstsym < 1e-12), "diamond: beta invariant under rotation/reflection", worstsym, 1e-12));
  PetscFunctionReturn(0);
}

static PetscErrorCode MinOf(Vec v, PetscReal *mn)
{
  PetscFunctionBeginUser;
  PetscCall(VecMin(v, NULL, mn));
  PetscFunctionReturn(0);
}

/* y = sphere inversion of x (center c, radius rho), then scaled by s */
static PetscErrorCode InvertScale(Vec x, const PetscReal c[3], PetscReal rho, PetscReal s, Vec y)
{
  PetscInt           n;
  const PetscScalar *a;
  PetscScalar       *b;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &a));
  PetscCall(VecGetArray(y, &b));
  for (PetscInt i = 0; i < n / 3; i++) {
    PetscReal d[3], r2 = 0;
    for (int k = 0; k < 3; k++) {
      d[k] = PetscRealPart(a[3 * i + k]) - c[k];
      r2 += d[k] * d[k];
    }
    for (int k = 0; k < 3; k++) b[3 * i + k] = s * (c[k] + rho * rho * d[k] / r2);
  }
  PetscCall(VecRestoreArrayRead(x, &a));
  PetscCall(VecRestoreArray(y, &b));
  PetscFunctionReturn(0);
}

/* max over coordinates of |K x_d - g_d| / |g|, and |K - K^T|_F / |K|_F */
static PetscErrorCode CheckKx(CSEnergy e, Vec x, PetscReal *rel, PetscReal *asym)
{
  CSMesh    m = e->mesh;
  Mat       K;
  Vec       g, xd, yd, gd;
  PetscReal W, gn, worst = 0;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(x, &g));
  PetscCall(CSEnergyWillmoreBSHessian(e, x, 0, MAT_INITIAL_MATRIX, &K, &W, g));
  PetscCall(CSEnergyWillmoreBSHessian(e, x, 0, MAT_REUSE_MATRIX, &K, &W, g)); /* reuse path too */
  PetscCall(VecNorm(g, NORM_2, &gn));
  PetscCall(DMCreateGlobalVector(m->dmV1, &xd));
  PetscCall(VecDuplicate(xd, &yd));
  PetscCall(VecDuplicate(xd, &gd));
  for (PetscInt d = 0; d < 3; d++) {
    PetscReal err;
    PetscCall(VecStrideGather(x, d, xd, INSERT_VALUES));
    PetscCall(VecStrideGather(g, d, gd, INSERT_VALUES));
    PetscCall(MatMult(K, xd, yd));
    PetscCall(VecAXPY(yd, -1, gd));
    PetscCall(VecNorm(yd, NORM_2, &err));
    worst = PetscMax(worst, err / gn);
  }
  *rel = worst;
  {
    Mat       Kt;
    PetscReal nk, nd;
    PetscCall(MatTranspose(K, MAT_INITIAL_MATRIX, &Kt));
    PetscCall(MatNorm(K, NORM_FROBENIUS, &nk));
    PetscCall(MatAXPY(Kt, -1, K, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatNorm(Kt, NORM_FROBENIUS, &nd));
    *asym = nd / nk;
    PetscCall(MatDestroy(&Kt));
  }
  PetscCall(MatDestroy(&K));
  PetscCall(VecDestroy(&xd));
  PetscCall(VecDestroy(&yd));
  PetscCall(VecDestroy(&gd));
  PetscCall(VecDestroy(&g));
  PetscFunctionReturn(0);
}

/* The derivatives of e at x: the gradient against central differences, K x = grad W and K symmetric. */
static PetscErrorCode CheckDerivatives(MPI_Comm comm, CSEnergy e, Vec x, const char label[])
{
  PetscReal rel = 0, asym = 0;
  char      what[160];
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCheckGradient(e, x, 1e-6, 6, &rel));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: gradient vs central FD (rel)", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(rel < 1e-6), what, rel, 1e-6));
  PetscCall(CheckKx(e, x, &rel, &asym));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: K x = grad W (rel)", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(rel < 1e-12), what, rel, 1e-12));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: K symmetric |K-K^T|/|K|", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(asym < 1e-12), what, asym, 1e-12));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm  comm;
  CSMesh    sph, ico, disk;
  CSEnergy  e;
  Vec       Wv, y;
  PetscReal W, W2, mn;
  char      buf[128];

  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CheckDiamond(comm));

  /* inscribed Delaunay mesh: W = 0, every W_i = 0 */
  PetscCall(MakeMesh(comm, 0, 3, &sph));
  PetscCall(CSEnergyCreateWillmoreBS(sph, CS_BS_BOUNDARY_FIXED, 1e-6, &e));
  PetscCall(DMCreateGlobalVector(sph->dmV1, &Wv));
  PetscCall(CSEnergyWillmoreBSVertex(e, sph->x, Wv, &W));
  PetscCall(VecNorm(Wv, NORM_INFINITY, &mn));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W) < 1e-10), "icosphere level 3: |W|", PetscAbsReal(W), 1e-10));
  PetscCall(CSTestCheck(comm, (PetscBool)(mn < 1e-10), "icosphere level 3: max |W_i|", mn, 1e-10));
  PetscCall(CSEnergyValue(e, sph->x, &W2));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W - W2) < 1e-12), "value path = per-vertex path", PetscAbsReal(W - W2), 1e-12));
  {
    PetscReal s;
    PetscCall(VecSum(Wv, &s));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(s - W) < 1e-10), "sum of W_i = W (sphere)", PetscAbsReal(s - W), 1e-10));
  }
  /* noisy sphere: W > 0, every W_i >= 0, Moebius invariance, gradient, K x = g */
  PetscCall(AddNoise(sph, 0.02, 11));
  PetscCall(CSEnergyWillmoreBSVertex(e, sph->x, Wv, &W));
  PetscCall(MinOf(Wv, &mn));
  PetscCall(CSTestCheck(comm, (PetscBool)(W > 1e-3), "noisy icosphere: W > 0", W, 1e-3));
  PetscCall(CSTestCheck(comm, (PetscBool)(mn >= -1e-12), "noisy icosphere: min W_i >= 0", mn, -1e-12));
  {
    PetscReal s;
    PetscCall(VecSum(Wv, &s));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(s - W) < 1e-10 * W), "sum of W_i = W (noisy)", PetscAbsReal(s - W), 1e-10 * W));
  }
  PetscCall(VecDuplicate(sph->x, &y));
  {
    const PetscReal c1[3] = {0.3, -0.2, 0.1}, c2[3] = {2.5, 0.4, -1.0};
    PetscCall(InvertScale(sph->x, c1, 1.3, 1.0, y));
    PetscCall(CSEnergyValue(e, y, &W2));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W2 - W) < 1e-10 * W), "Moebius: inversion, center inside (rel)", PetscAbsReal(W2 - W) / W, 1e-10));
    PetscCall(InvertScale(sph->x, c2, 0.7, 1.0, y));
    PetscCall(CSEnergyValue(e, y, &W2));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W2 - W) < 1e-10 * W), "Moebius: inversion, center outside (rel)", PetscAbsReal(W2 - W) / W, 1e-10));
    PetscCall(VecCopy(sph->x, y));
    PetscCall(VecScale(y, 37.5));
    PetscCall(CSEnergyValue(e, y, &W2));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W2 - W) < 1e-10 * W), "Moebius: scaling by 37.5 (rel)", PetscAbsReal(W2 - W) / W, 1e-10));
    PetscCall(InvertScale(sph->x, c2, 0.7, 1e-3, y));
    PetscCall(CSEnergyValue(e, y, &W2));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W2 - W) < 1e-10 * W), "Moebius: inversion then scaling by 1e-3 (rel)", PetscAbsReal(W2 - W) / W, 1e-10));
  }
  PetscCall(CheckDerivatives(comm, e, sph->x, "noisy icosphere"));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&Wv));
  PetscCall(CSEnergyDestroy(&e));
  PetscCall(CSMeshDestroy(&sph));

  /* linearly subdivided icosahedron: W > 0; beta = 0 on the flat diamonds, the heuristic keeps g finite */
  PetscCall(MakeMesh(comm, 2, 2, &ico));
  PetscCall(CSEnergyCreateWillmoreBS(ico, CS_BS_BOUNDARY_FIXED, 1e-6, &e));
  {
    Vec       g;
    PetscReal gn;
    PetscCall(VecDuplicate(ico->x, &g));
    PetscCall(CSEnergyGradient(e, ico->x, &W, g));
    PetscCall(VecNorm(g, NORM_2, &gn));
    PetscCall(PetscSNPrintf(buf, sizeof(buf), "flat icosahedron level 2: W > 0 (W=%.6g), |g| finite", (double)W));
    PetscCall(CSTestCheck(comm, (PetscBool)(W > 1 && !PetscIsInfOrNanReal(gn)), buf, gn, 0));
    PetscCall(VecDestroy(&g));
  }
  PetscCall(CSEnergyDestroy(&e));
  PetscCall(CSMeshDestroy(&ico));

  /* disk: free boundary gradient, fixed boundary zero gradient on the fixed set */
  PetscCall(MakeMesh(comm, 1, 5, &disk));
  {
    Vec              g;
    PetscScalar     *a;
    PetscInt         n;
    const PetscBool *fixed;
    PetscInt         nfixed;
    PetscReal        gmax = 0, gfree = 0;
    /* lift the flat disk to a noisy cap so no beta is 0 */
    PetscCall(VecGetLocalSize(disk->x, &n));
    PetscCall(VecGetArray(disk->x, &a));
    for (PetscInt i = 0; i < n / 3; i++) a[3 * i + 2] = 0.3 * (a[3 * i] * a[3 * i] + 0.5 * a[3 * i + 1] * a[3 * i + 1]);
    PetscCall(VecRestoreArray(disk->x, &a));
    PetscCall(AddNoise(disk, 0.01, 5));
    PetscCall(CSEnergyCreateWillmoreBS(disk, CS_BS_BOUNDARY_FREE, 1e-6, &e));
    PetscCall(CSEnergyValue(e, disk->x, &W));
    PetscCall(CSTestCheck(comm, (PetscBool)(W > 0), "noisy cap, free boundary: W > 0", W, 0));
    PetscCall(CheckDerivatives(comm, e, disk->x, "noisy cap, free boundary"));
    PetscCall(VecDuplicate(disk->x, &y));
    /* The vertex at infinity is fixed by similarities only: the free-boundary energy is invariant under
       scaling and translation, not under an inversion (which moves infinity to the center). */
    PetscCall(VecCopy(disk->x, y));
    PetscCall(VecScale(y, 3.0));
    PetscCall(VecShift(y, 0.25));
    PetscCall(CSEnergyValue(e, y, &W2));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(W2 - W) < 1e-10 * W), "noisy cap, free: invariant under scaling+translation (rel)", PetscAbsReal(W2 - W) / W, 1e-10));
    PetscCall(VecDestroy(&y));
    PetscCall(CSEnergyDestroy(&e));
    PetscCall(CSEnergyCreateWillmoreBS(disk, CS_BS_BOUNDARY_FIXED, 1e-6, &e));
    PetscCall(CSEnergyWillmoreBSGetFixed(e, &fixed, &nfixed));
    PetscCall(VecDuplicate(disk->x, &g));
    PetscCall(CSEnergyGradient(e, disk->x, &W, g));
    PetscCall(VecGetArray(g, &a));
    {
      Vec          fl, fg;
      PetscScalar *fa;
      const PetscScalar *fr;
      PetscCall(DMGetLocalVector(disk->dmV1, &fl));
      PetscCall(DMGetGlobalVector(disk->dmV1, &fg));
      PetscCall(VecGetArray(fl, &fa));
      for (PetscInt v = 0; v < disk->nv; v++) fa[v] = fixed[v] ? 1 : 0;
      PetscCall(VecRestoreArray(fl, &fa));
      PetscCall(DMLocalToGlobal(disk->dmV1, fl, INSERT_VALUES, fg));
      PetscCall(VecGetArrayRead(fg, &fr));
      for (PetscInt i = 0; i < n / 3; i++)
        for (int d = 0; d < 3; d++) {
          if (PetscRealPart(fr[i]) > 0.5) gmax = PetscMax(gmax, PetscAbsScalar(a[3 * i + d]));
          else gfree = PetscMax(gfree, PetscAbsScalar(a[3 * i + d]));
        }
      PetscCall(VecRestoreArrayRead(fg, &fr));
      PetscCall(DMRestoreLocalVector(disk->dmV1, &fl));
      PetscCall(DMRestoreGlobalVector(disk->dmV1, &fg));
    }
    PetscCall(VecRestoreArray(g, &a));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &gmax, 1, MPIU_REAL, MPIU_MAX, comm));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &gfree, 1, MPIU_REAL, MPIU_MAX, comm));
    PetscCall(PetscSNPrintf(buf, sizeof(buf), "disk fixed boundary (%" PetscInt_FMT " fixed of %" PetscInt_FMT "): grad = 0 on fixed", nfixed, disk->Nv));
    PetscCall(CSTestCheck(comm, (PetscBool)(gmax == 0 && gfree > 0 && nfixed > 0 && nfixed < disk->Nv), buf, gmax, 0));
    PetscCall(VecDestroy(&g));
    PetscCall(CSEnergyDestroy(&e));
  }
  PetscCall(CSMeshDestroy(&disk));
  return CSTestFinalize(comm, PetscFinalize);
}
