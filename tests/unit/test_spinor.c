/* Unit checks of the discrete spinors of soliman2021 App. C (include/cs_operators_spinor.h), serial and under
   mpirun, on a bumpy icosphere and a bumpy torus, with the background metric l0 = the lengths of df:
   - the lift psi(df) is exact: S(l0, psi(df)) = df to 1e-12, and has no pinch edges (tau from df's spin structure);
   - flipping the spinor of one face makes exactly its 3 edges fail the pinch test |psi_jil - tau psi_ijk| < sqrt 2,
     but no vertex (CSSpinorPinchVertices: the flip is a gauge, each corner sees 2 of the 3 edges);
   - S_c(u, psi) is conformal by construction: C~ lambda(S_c(u, psi)) = C~ lambda0 to 1e-12 for random u and unit
     psi (C~ A~ = 0), and its faces close;
   - the gradient of the spin Dirichlet energy E_tau against central differences (<= 1e-6 relative).
   Prints a line per check; exit status = number of failures. */
#include "cs_operators_spinor.h"
#include "cs_package.h"
#include "cs_test.h"

static PetscErrorCode RandomUnitSpinors(CSMesh m, Vec psi, unsigned long seed)
{
  PetscRandom  r;
  PetscScalar *p;
  PetscFunctionBeginUser;
  PetscCall(CSTestRandom(m->comm, -1, 1, seed, &r));
  PetscCall(VecSetRandom(psi, r));
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(VecGetArray(psi, &p));
  for (PetscInt f = 0; f < m->nf; f++) {
    PetscReal n = 0;
    for (int c = 0; c < 4; c++) n += PetscSqr(PetscRealPart(p[4 * f + c]));
    for (int c = 0; c < 4; c++) p[4 * f + c] /= PetscSqrtReal(n);
  }
  PetscCall(VecRestoreArray(psi, &p));
  PetscFunctionReturn(0);
}

/* max |a - b| / max |b| */
static PetscErrorCode RelDiff(Vec a, Vec b, PetscReal *d)
{
  Vec       t;
  PetscReal nb;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(a, &t));
  PetscCall(VecWAXPY(t, -1.0, b, a));
  PetscCall(VecNorm(t, NORM_INFINITY, d));
  PetscCall(VecNorm(b, NORM_INFINITY, &nb));
  *d /= nb;
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckLiftAndPinch(CSMesh m, CSSpinorSpace sp, DM dmH3, Vec df, Vec psi, const char name[])
{
  Vec          om;
  PetscReal    d, dmax;
  PetscInt     np;
  PetscScalar *p;
  char         what[160];
  PetscFunctionBeginUser;
  PetscCall(CSSpinorFromTriangleField(sp, dmH3, df, NULL, psi));
  PetscCall(VecDuplicate(df, &om));
  PetscCall(CSSpinorTriangleField(sp, NULL, psi, dmH3, om));
  PetscCall(RelDiff(om, df, &d));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: S(l0, psi(df)) = df", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-12), what, d, 1e-12));
  PetscCall(CSSpinorPinchEdges(sp, psi, &np, &dmax));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: pinch edges of psi(df) = 0", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(np == 0), what, (PetscReal)np, 0));
  PetscCall(CSSpinorPinchVertices(sp, psi, &np));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: pinch vertices of psi(df) = 0", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(np == 0), what, (PetscReal)np, 0));
  /* smooth: psi_jil - tau psi_ijk is the half-angle rotation about the edge by the dihedral angle, small on a fine
     mesh whatever the signs (a wrong chart change r would leave O(1) defects on most edges) */
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: max |psi_jil - tau psi_ijk| of psi(df) is the dihedral half-angle (< 0.6)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(dmax < 0.6), what, dmax, 0.6));
  PetscCall(VecGetArray(psi, &p));
  for (PetscInt f = 0; f < m->nf; f++)
    if (m->faceNatural[f] == 0)
      for (int c = 0; c < 4; c++) p[4 * f + c] *= -1;
  PetscCall(VecRestoreArray(psi, &p));
  PetscCall(CSSpinorPinchEdges(sp, psi, &np, NULL));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: one face's spinor flipped: 3 pinch edges", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(np == 3), what, (PetscReal)np, 3));
  /* the flip is a change of gauge, not a pinch point: 2 of the 3 edges at each corner, the vertices' parity kept */
  PetscCall(CSSpinorPinchVertices(sp, psi, &np));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: one face's spinor flipped: 0 pinch vertices", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(np == 0), what, (PetscReal)np, 0));
  PetscCall(VecDestroy(&om));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckConformal(CSMesh m, CSSpinorSpace sp, DM dmH1, DM dmH3, Vec lambda0, Vec psi, const char name[])
{
  Mat         C, S;
  Vec         u, om, lam, c, c0;
  PetscRandom r;
  PetscReal   d, dc, nrm;
  char        what[160];
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(m->dmV1, &u));
  PetscCall(CSTestRandom(m->comm, -0.1, 0.1, 21, &r));
  PetscCall(VecSetRandom(u, r));
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(RandomUnitSpinors(m, psi, 22));
  PetscCall(DMCreateGlobalVector(dmH3, &om));
  PetscCall(CSSpinorTriangleField(sp, u, psi, dmH3, om));
  PetscCall(VecDuplicate(lambda0, &lam));
  PetscCall(VecDuplicate(lambda0, &c));
  PetscCall(VecDuplicate(lambda0, &c0));
  PetscCall(CSTriangleFieldLogLengths(m, dmH3, om, dmH1, lam));
  PetscCall(CSOperatorLensCrossRatio(m, dmH1, &C));
  PetscCall(MatMult(C, lam, c));
  PetscCall(MatMult(C, lambda0, c0));
  PetscCall(VecAXPY(c, -1.0, c0));
  PetscCall(VecNorm(c, NORM_INFINITY, &d));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: C~ lambda(S_c(u, psi)) = C~ lambda0 (|u| <= 0.1, random unit psi)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-12), what, d, 1e-12));
  PetscCall(CSOperatorLensFaceClosure(m, dmH1, &S));
  { /* closure per component */
    Vec comp, sc;
    PetscCall(VecDuplicate(lambda0, &comp));
    PetscCall(MatCreateVecs(S, NULL, &sc));
    dc = 0;
    for (PetscInt k = 0; k < 3; k++) {
      const PetscScalar *o;
      PetscScalar       *a;
      PetscInt           n;
      PetscCall(VecGetLocalSize(comp, &n));
      PetscCall(VecGetArrayRead(om, &o));
      PetscCall(VecGetArray(comp, &a));
      for (PetscInt h = 0; h < n; h++) a[h] = o[3 * h + k];
      PetscCall(VecRestoreArray(comp, &a));
      PetscCall(VecRestoreArrayRead(om, &o));
      PetscCall(MatMult(S, comp, sc));
      PetscCall(VecNorm(sc, NORM_INFINITY, &nrm));
      dc = PetscMax(dc, nrm);
    }
    PetscCall(VecDestroy(&comp));
    PetscCall(VecDestroy(&sc));
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: the faces of S_c(u, psi) close", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(dc < 1e-12), what, dc, 1e-12));
  PetscCall(MatDestroy(&C));
  PetscCall(MatDestroy(&S));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&om));
  PetscCall(VecDestroy(&lam));
  PetscCall(VecDestroy(&c));
  PetscCall(VecDestroy(&c0));
  PetscFunctionReturn(0);
}

/* <grad E, v> against (E(psi + h v) - E(psi - h v)) / 2h at a random (not unit) psi */
static PetscErrorCode CheckGradient(CSMesh m, CSSpinorSpace sp, Vec psi, const char name[])
{
  Vec         g, v, t;
  PetscRandom r;
  PetscReal   E, Ep, Em, h = 1e-5, fd, an, err;
  PetscScalar gv;
  char        what[160];
  PetscFunctionBeginUser;
  PetscCall(CSTestRandom(m->comm, -1, 1, 31, &r));
  PetscCall(VecSetRandom(psi, r));
  PetscCall(VecDuplicate(psi, &g));
  PetscCall(VecDuplicate(psi, &v));
  PetscCall(VecDuplicate(psi, &t));
  PetscCall(VecSetRandom(v, r));
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(CSSpinorDirichlet(sp, psi, &E, g));
  PetscCall(VecDot(g, v, &gv));
  an = PetscRealPart(gv);
  PetscCall(VecWAXPY(t, h, v, psi));
  PetscCall(CSSpinorDirichlet(sp, t, &Ep, NULL));
  PetscCall(VecWAXPY(t, -h, v, psi));
  PetscCall(CSSpinorDirichlet(sp, t, &Em, NULL));
  fd  = (Ep - Em) / (2 * h);
  err = PetscAbsReal(fd - an) / PetscAbsReal(an);
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: grad E_tau against central differences (E_tau = %.6g)", name, (double)E));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(err <= 1e-6), what, err, 1e-6));
  PetscCall(VecDestroy(&g));
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

/* d/domega E_tau(psi(omega)) against central differences at omega = df + noise (signs held by psi_prev) */
static PetscErrorCode CheckLiftGradient(CSMesh m, CSSpinorSpace sp, DM dmH3, Vec df, Vec psi, const char name[])
{
  Vec         om, g, v, t;
  PetscRandom r;
  PetscReal   E, Ep, Em, h = 1e-6, fd, an, err, nrm;
  PetscScalar gv;
  char        what[200];
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(df, &om));
  PetscCall(VecDuplicate(df, &g));
  PetscCall(VecDuplicate(df, &v));
  PetscCall(VecDuplicate(df, &t));
  PetscCall(CSTestRandom(m->comm, -1, 1, 41, &r));
  PetscCall(VecSetRandom(v, r));
  PetscCall(VecNorm(df, NORM_INFINITY, &nrm));
  PetscCall(VecWAXPY(om, 0.2 * nrm, v, df));
  PetscCall(VecSetRandom(v, r));
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(CSSpinorDirichletTriangleField(sp, dmH3, om, NULL, &E, g, psi));
  PetscCall(VecDot(g, v, &gv));
  an = PetscRealPart(gv);
  PetscCall(VecWAXPY(t, h, v, om));
  PetscCall(CSSpinorDirichletTriangleField(sp, dmH3, t, psi, &Ep, NULL, NULL));
  PetscCall(VecWAXPY(t, -h, v, om));
  PetscCall(CSSpinorDirichletTriangleField(sp, dmH3, t, psi, &Em, NULL, NULL));
  fd  = (Ep - Em) / (2 * h);
  err = PetscAbsReal(fd - an) / PetscAbsReal(an);
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: d/domega E_tau(psi(omega)) against central differences (omega = df + 20%% noise, E_tau = %.6g)", name, (double)E));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(err <= 1e-6), what, err, 1e-6));
  PetscCall(VecDestroy(&om));
  PetscCall(VecDestroy(&g));
  PetscCall(VecDestroy(&v));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckMesh(CSMesh m, const char name[])
{
  DM            dmH1, dmH3, dmF4;
  Vec           df, lambda0, psi;
  CSSpinorSpace sp;
  PetscFunctionBeginUser;
  PetscCall(CSLensCreateHalfedgeDM(m, 1, &dmH1));
  PetscCall(CSLensCreateHalfedgeDM(m, 3, &dmH3));
  PetscCall(DMCreateGlobalVector(dmH3, &df));
  PetscCall(DMCreateGlobalVector(dmH1, &lambda0));
  PetscCall(CSTriangleFieldFromPositions(m, m->x, dmH3, df));
  PetscCall(CSTriangleFieldLogLengths(m, dmH3, df, dmH1, lambda0));
  PetscCall(CSSpinorSpaceCreate(m, dmH1, lambda0, &sp));
  PetscCall(CSSpinorSpaceSetConnection(sp, dmH3, df));
  PetscCall(CSSpinorSpaceGetDM(sp, &dmF4));
  PetscCall(DMCreateGlobalVector(dmF4, &psi));
  PetscCall(CheckLiftAndPinch(m, sp, dmH3, df, psi, name));
  PetscCall(CheckConformal(m, sp, dmH1, dmH3, lambda0, psi, name));
  PetscCall(CheckGradient(m, sp, psi, name));
  PetscCall(CheckLiftGradient(m, sp, dmH3, df, psi, name));
  PetscCall(VecDestroy(&psi));
  PetscCall(VecDestroy(&df));
  PetscCall(VecDestroy(&lambda0));
  PetscCall(CSSpinorSpaceDestroy(&sp));
  PetscCall(DMDestroy(&dmH1));
  PetscCall(DMDestroy(&dmH3));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm comm;
  CSMesh   m;
  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CSInitializePackage());
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_ICOSPHERE, 2, 0, 0, 0}, 0.05, 3, &m));
  PetscCall(CheckMesh(m, "icosphere 2 bumpy"));
  PetscCall(CSMeshDestroy(&m));
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_TORUS, 12, 8, 2.0, 0.7}, 0.05, 3, &m));
  PetscCall(CheckMesh(m, "torus 12x8 bumpy"));
  PetscCall(CSMeshDestroy(&m));
  return CSTestFinalize(comm, PetscFinalize);
}
