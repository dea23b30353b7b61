/* Unit checks of the triangle-field extensions of App. B (soliman2021 B.1, B.2; include/cs_constraints.h), serial
   and under mpirun, on a bumpy level-2 icosphere and a bumpy torus:
   - they are extensions: the volume V~(df) = V(f) and the relative points P~(df) = (f_v - f_v0) - (p_v - p_v0)
     equal the position constraints' values (CSConstraintCreateVolume / ...PointsFromFile) to 1e-12;
   - their rows are their gradients: a directional derivative against central differences <= 1e-6 (relative) at
     df and at a non-integrable field (every halfedge moved by up to 2 % of the field's size);
   - the point rows are the source/sink forms of B.1: co-closed (d0^T *1(x0)-weighted divergence of the row is
     delta_v - delta_v0 up to the grounding) is implied by the next check: <row, df> = f_v - f_v0 for every f, tested
     with a random f.
   - the Moebius balancing M~(omega) = m(R omega) (the vertex flow's rows on the input): M~(df) = m(f) to 1e-12 and
     its rows against central differences <= 1e-6 at df and at the non-integrable field;
   Option -points FILE: the points file (lines 'vertex x y z'; written by tests/cases/trianglefield_appb.sh).
   Exit status = number of failures. */
#include "cs_constraints.h"
#include "cs_geometry.h"
#include "cs_package.h"
#include "cs_test.h"

/* worst relative |row . dir - (c(w + h dir) - c(w - h dir)) / 2h| over the rows of g, at w */
static PetscErrorCode FDCheck(CSGlobalConstraint g, Vec w, PetscRandom rnd, PetscReal *worst)
{
  Vec       *rows, dir, wp;
  PetscReal *cp, *cm, *c0, h = 1e-6;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicateVecs(w, g->k, &rows));
  PetscCall(VecDuplicate(w, &dir));
  PetscCall(VecDuplicate(w, &wp));
  PetscCall(PetscMalloc3(g->k, &cp, g->k, &cm, g->k, &c0));
  PetscCall(VecSetRandom(dir, rnd));
  PetscCall(CSGlobalConstraintEvaluate(g, w, c0, rows));
  PetscCall(VecWAXPY(wp, h, dir, w));
  PetscCall(CSGlobalConstraintEvaluate(g, wp, cp, NULL));
  PetscCall(VecWAXPY(wp, -h, dir, w));
  PetscCall(CSGlobalConstraintEvaluate(g, wp, cm, NULL));
  *worst = 0;
  for (PetscInt j = 0; j < g->k; j++) {
    PetscScalar d;
    PetscReal   fd = (cp[j] - cm[j]) / (2 * h);
    PetscCall(VecDot(rows[j], dir, &d));
    *worst = PetscMax(*worst, PetscAbsReal(fd - PetscRealPart(d)) / PetscMax(PetscAbsReal(fd), 1e-3));
  }
  PetscCall(PetscFree3(cp, cm, c0));
  PetscCall(VecDestroyVecs(g->k, &rows));
  PetscCall(VecDestroy(&dir));
  PetscCall(VecDestroy(&wp));
  PetscFunctionReturn(0);
}

/* |g~(df) - c(f)| / max(1, |c(f)|), c the position constraint (for points: differences to the first point) */
static PetscErrorCode ExtensionCheck(CSGlobalConstraint gt, CSGlobalConstraint gp, Vec x, Vec omega, PetscBool relative, PetscReal *d)
{
  PetscReal *ct, *cp;
  PetscInt   off = relative ? 3 : 0;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc2(gt->k, &ct, gp->k, &cp));
  PetscCall(CSGlobalConstraintEvaluate(gt, omega, ct, NULL));
  PetscCall(CSGlobalConstraintEvaluate(gp, x, cp, NULL));
  PetscReal s = 1;
  *d = 0;
  for (PetscInt j = 0; j < gt->k; j++) {
    PetscReal v = cp[off + j] - (relative ? cp[j % 3] : 0);
    *d = PetscMax(*d, PetscAbsReal(ct[j] - v));
    s  = PetscMax(s, PetscAbsReal(v));
  }
  *d /= s; /* relative to max(1, |value|) */
  PetscCall(PetscFree2(ct, cp));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckMesh(CSMesh m, const char name[], const char points[])
{
  DM                     dmH1, dmH3;
  Vec                    omega, w, x;
  CSTriangleFieldPoisson P;
  CSGlobalConstraint     g[3], gp[3];
  PetscRandom            rnd;
  PetscReal              A, V, nrm, d = 0, worst = 0;
  char                   what[200];
  PetscFunctionBeginUser;
  PetscCall(CSLensCreateHalfedgeDM(m, 1, &dmH1));
  PetscCall(CSLensCreateHalfedgeDM(m, 3, &dmH3));
  PetscCall(DMCreateGlobalVector(dmH3, &omega));
  PetscCall(CSTriangleFieldFromPositions(m, m->x, dmH3, omega));
  PetscCall(CSTriangleFieldPoissonCreate(m, dmH1, dmH3, m->x, &P));
  PetscCall(CSGeometryAreaVolume(m, m->x, &A, &V));
  PetscCall(CSConstraintCreateTriangleFieldVolume(m, P, 0.9 * PetscAbsReal(V), &g[0]));
  PetscCall(CSConstraintCreateVolume(m, 0.9 * PetscAbsReal(V), &gp[0]));
  PetscCall(CSConstraintCreateTriangleFieldPoints(m, P, "-points", points, &g[1]));
  PetscCall(CSConstraintCreatePointsFromFile(m, "-points", points, &gp[1]));
  PetscCall(CSConstraintCreateTriangleFieldMobius(m, P, m->x, &g[2]));
  PetscCall(CSConstraintCreateMobiusBalance(m, m->x, &gp[2]));
  PetscCall(CSTriangleFieldPoissonDestroy(&P)); /* referenced by the constraints */
  PetscCall(CSTestRandom(m->comm, -1, 1, 23, &rnd));
  /* extensions at df, and at df of a random other f (same mesh): R d f = f - f_0 for every f */
  PetscCall(VecDuplicate(m->x, &x));
  PetscCall(VecDuplicate(omega, &w));
  for (int k = 0; k < 2; k++) {
    if (k) {
      PetscCall(VecSetRandom(x, rnd));
      PetscCall(VecAYPX(x, 10.0, m->x));
    } else PetscCall(VecCopy(m->x, x));
    PetscCall(CSTriangleFieldFromPositions(m, x, dmH3, w));
    for (int j = 0; j < 3; j++) {
      const char *cn = j == 0 ? "V" : (j == 1 ? "P" : "M");
      PetscCall(ExtensionCheck(g[j], gp[j], x, w, (PetscBool)(j == 1), &d));
      PetscCall(PetscSNPrintf(what, sizeof(what), "%s: %s~(df) = %s(f) (%s f)", name, cn, cn, k ? "a random" : "the input's"));
      PetscCall(CSTestCheck(m->comm, (PetscBool)(d < 1e-12), what, d, 1e-12));
    }
  }
  /* gradients at df and at a non-integrable field */
  PetscCall(VecCopy(omega, w));
  PetscCall(VecNorm(omega, NORM_INFINITY, &nrm));
  for (int k = 0; k < 2; k++) {
    if (k) {
      Vec r;
      PetscCall(VecDuplicate(w, &r));
      PetscCall(VecSetRandom(r, rnd));
      PetscCall(VecAXPY(w, 0.02 * nrm, r));
      PetscCall(VecDestroy(&r));
    }
    for (int j = 0; j < 3; j++) {
      PetscCall(FDCheck(g[j], w, rnd, &worst));
      PetscCall(PetscSNPrintf(what, sizeof(what), "%s: rows of %s~ vs central differences (%s)", name, j == 0 ? "V (B.2)" : (j == 1 ? "P (B.1)" : "M (Moebius balancing)"), k ? "non-integrable field" : "df"));
      PetscCall(CSTestCheck(m->comm, (PetscBool)(worst < 1e-6), what, worst, 1e-6));
    }
  }
  for (int j = 0; j < 3; j++) {
    PetscCall(CSGlobalConstraintDestroy(&g[j]));
    PetscCall(CSGlobalConstraintDestroy(&gp[j]));
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&w));
  PetscCall(VecDestroy(&omega));
  PetscCall(DMDestroy(&dmH1));
  PetscCall(DMDestroy(&dmH3));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm comm;
  CSMesh   m;
  char     points[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CSInitializePackage());
  PetscCall(PetscOptionsGetString(NULL, NULL, "-points", points, sizeof(points), NULL));
  PetscCheck(points[0], comm, PETSC_ERR_ARG_WRONG, "-points FILE: the points file is required");
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_ICOSPHERE, 2, 0, 0, 0}, 0.05, 3, &m));
  PetscCall(CheckMesh(m, "icosphere 2 bumpy", points));
  PetscCall(CSMeshDestroy(&m));
  PetscCall(CSTestMesh(comm, (CSTestMeshSpec){CS_TEST_TORUS, 12, 8, 3.0, 1.0}, 0.05, 5, &m));
  PetscCall(CheckMesh(m, "torus 12x8 bumpy", points));
  PetscCall(CSMeshDestroy(&m));
  return CSTestFinalize(comm, PetscFinalize);
}
