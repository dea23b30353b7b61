static const char help[] = "Checks of the conformal-constraint operators of soliman2021 (issue 3): X = C Dlambda against\n"
                           "finite differences of C lambda, the identities C A u = 0 (cross ratios are invariant under\n"
                           "vertex scaling, Eq. 4), X f = 0 (global scaling), X t = 0 and X (w x f) = 0 (translations,\n"
                           "rotations), the vertex-star relation sum_j (C lambda)_ij = 0 (why PGD's matrix is singular),\n"
                           "the shell H^2 metric against the assembled one, H 1 = *0 1, I_Q > 0, the fairing gradient, the\n"
                           "Moebius-balancing rows (finite differences, similarity invariance, the boost rate).\n"
                           "Exit status = number of failed checks.\n";

#include "cs_constraints.h"
#include "cs_util.h"
#include "cs_test.h"
#include "cs_package.h"

static PetscErrorCode MakeMesh(MPI_Comm comm, PetscBool torus, PetscReal amp, CSMesh *mesh)
{
  CSTestMeshSpec ico = {CS_TEST_ICOSPHERE, 2, 0, 0, 0}, tor = {CS_TEST_TORUS, 16, 8, 3, 1};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, torus ? tor : ico, amp, 11, mesh));
  PetscFunctionReturn(0);
}

/* v_i = a (constant) or w x f_i (rotation) or f_i (scaling) */
static PetscErrorCode FillVertexField(Vec x, Vec v, int kind)
{
  PetscInt           n;
  const PetscScalar *p;
  PetscScalar       *a;
  const PetscReal    w[3] = {0.3, -0.7, 0.5}, t[3] = {1.0, -2.0, 0.5};
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &p));
  PetscCall(VecGetArray(v, &a));
  for (PetscInt i = 0; i < n / 3; i++) {
    const PetscReal *f = (const PetscReal *)p + 3 * i;
    PetscReal        c[3];
    CSVecCross(w, f, c);
    for (int d = 0; d < 3; d++) a[3 * i + d] = kind == 0 ? t[d] : (kind == 1 ? c[d] : f[d]);
  }
  PetscCall(VecRestoreArray(v, &a));
  PetscCall(VecRestoreArrayRead(x, &p));
  PetscFunctionReturn(0);
}

/* The fairing energy's errors name what the caller gave: the eps argument of CSEnergyCreateFairing, and the option
   -<prefix>epsilon under the energy's own prefix (here "my_fairing_", not the flow's "flow_fairing_"). */
static PetscErrorCode CheckFairingErrors(MPI_Comm comm, CSMesh m, Vec x0, const char label[])
{
  CSEnergy       e = NULL;
  PetscErrorCode ierr;
  const char    *text;
  char          *specific = NULL, what[160];
  PetscBool      named, flow;
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = CSEnergyCreateFairing(m, x0, -1.0, &e);
  PetscCall(PetscPopErrorHandler());
  if (ierr) PetscCall(PetscErrorMessage(ierr, &text, &specific));
  named = (PetscBool)(specific && strstr(specific, "CSEnergyCreateFairing: eps -1"));
  flow  = (PetscBool)(specific && strstr(specific, "-flow_"));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: fairing eps -1 refused naming the argument, no -flow_ option (%s)", label, specific ? specific : "no error"));
  PetscCall(CSTestCheck(comm, (PetscBool)(ierr && named && !flow), what, 0, 0));
  PetscCall(CSEnergyCreateFairing(m, x0, 0.1, &e));
  PetscCall(CSEnergySetOptionsPrefix(e, "my_fairing_"));
  PetscCall(PetscOptionsSetValue(NULL, "-my_fairing_epsilon", "-2"));
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = CSEnergySetFromOptions(e);
  PetscCall(PetscPopErrorHandler());
  PetscCall(PetscOptionsClearValue(NULL, "-my_fairing_epsilon"));
  specific = NULL;
  if (ierr) PetscCall(PetscErrorMessage(ierr, &text, &specific));
  named = (PetscBool)(specific && strstr(specific, "-my_fairing_epsilon -2"));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: -my_fairing_epsilon -2 refused naming the energy's prefix (%s)", label, specific ? specific : "no error"));
  PetscCall(CSTestCheck(comm, (PetscBool)(ierr && named), what, 0, 0));
  PetscCall(CSEnergyDestroy(&e));
  PetscFunctionReturn(0);
}

static PetscErrorCode RunChecks(MPI_Comm comm, PetscBool torus)
{
  CSMesh                m;
  CSConformalConstraint cc;
  Vec                   x, d, xp, cp, cm, fd, Xd, v, y, lam, u, Au, iq;
  PetscRandom           rnd;
  PetscReal             err, nrm, mn;
  const char           *label = torus ? "torus" : "icosphere";
  char                  what[256];
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, torus, 0.02, &m));
  x = m->x;
  PetscCall(CSConformalConstraintCreate(m, x, PETSC_FALSE, NULL, &cc));
  PetscCall(DMCreateGlobalVector(m->dmE1, &cp));
  PetscCall(VecDuplicate(cp, &cm));
  PetscCall(VecDuplicate(cp, &fd));
  PetscCall(VecDuplicate(cp, &Xd));
  PetscCall(VecDuplicate(cp, &y));
  PetscCall(VecDuplicate(cp, &lam));
  PetscCall(VecDuplicate(cp, &Au));
  PetscCall(VecDuplicate(cp, &iq));
  PetscCall(VecDuplicate(x, &d));
  PetscCall(VecDuplicate(x, &xp));
  PetscCall(VecDuplicate(x, &v));
  PetscCall(CSTestRandom(comm, -1, 1, 2021, &rnd));

  /* c(x) = 0 at the target, and X = C Dlambda against central differences of c */
  PetscCall(CSConformalConstraintEvaluate(&cc, x, cp, PETSC_TRUE));
  PetscCall(VecNorm(cp, NORM_INFINITY, &err));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: C lambda(x) - c0 = 0 at the target", label));
  PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-13), what, err, 1e-13));
  PetscCall(VecSetRandom(d, rnd));
  PetscCall(MatMult(cc.X, d, Xd));
  {
    const PetscReal h = 1e-6;
    Mat             Xs;
    PetscCall(MatDuplicate(cc.X, MAT_COPY_VALUES, &Xs));
    PetscCall(VecWAXPY(xp, h, d, x));
    PetscCall(CSConformalConstraintEvaluate(&cc, xp, cp, PETSC_FALSE));
    PetscCall(VecWAXPY(xp, -h, d, x));
    PetscCall(CSConformalConstraintEvaluate(&cc, xp, cm, PETSC_FALSE));
    PetscCall(VecWAXPY(fd, -1.0, cm, cp));
    PetscCall(VecScale(fd, 1.0 / (2 * h)));
    PetscCall(VecAXPY(fd, -1.0, Xd));
    PetscCall(VecNorm(fd, NORM_INFINITY, &err));
    PetscCall(VecNorm(Xd, NORM_INFINITY, &nrm));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: X d vs central differences of C lambda (relative)", label));
    PetscCall(CSTestCheck(comm, (PetscBool)(err / nrm < 1e-6), what, err / nrm, 1e-6));
    PetscCall(MatDestroy(&Xs));
  }
  /* X f = 0, X t = 0, X (w x f) = 0 */
  for (int k = 0; k < 3; k++) {
    const char *nm[3] = {"translation", "rotation", "scaling (X f)"};
    PetscCall(FillVertexField(x, v, k));
    PetscCall(MatMult(cc.X, v, Xd));
    PetscCall(VecNorm(Xd, NORM_INFINITY, &err));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: X applied to a %s", label, nm[k]));
    PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-11), what, err, 1e-11));
  }
  /* C A u = 0 for random vertex scale factors u (Eq. 4: im A = ker C) */
  {
    Vec          ul, Aul;
    PetscScalar *a;
    const PetscScalar *ua;
    PetscCall(DMCreateGlobalVector(m->dmV1, &u));
    PetscCall(VecSetRandom(u, rnd));
    PetscCall(DMGetLocalVector(m->dmV1, &ul));
    PetscCall(DMGlobalToLocal(m->dmV1, u, INSERT_VALUES, ul));
    PetscCall(DMGetLocalVector(m->dmE1, &Aul));
    PetscCall(VecGetArrayRead(ul, &ua));
    PetscCall(VecGetArray(Aul, &a));
    for (PetscInt e = 0; e < m->ne; e++) a[e] = 0.5 * (ua[m->edgeVert[2 * e]] + ua[m->edgeVert[2 * e + 1]]);
    PetscCall(VecRestoreArray(Aul, &a));
    PetscCall(VecRestoreArrayRead(ul, &ua));
    PetscCall(DMLocalToGlobal(m->dmE1, Aul, INSERT_VALUES, Au));
    PetscCall(DMRestoreLocalVector(m->dmE1, &Aul));
    PetscCall(DMRestoreLocalVector(m->dmV1, &ul));
    PetscCall(MatMult(cc.C, Au, y));
    PetscCall(VecNorm(y, NORM_INFINITY, &err));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: C A u = 0 for random u (scale invariance of cross ratios)", label));
    PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-13), what, err, 1e-13));
  }
  /* vertex-star sums of C lambda vanish for any lambda: rows of C (and X) are dependent */
  {
    Vec              sl, s;
    Vec              yl;
    PetscScalar     *sa;
    const PetscScalar *ya;
    PetscCall(VecSetRandom(lam, rnd));
    PetscCall(MatMult(cc.C, lam, y));
    PetscCall(DMGetLocalVector(m->dmE1, &yl));
    PetscCall(DMGlobalToLocal(m->dmE1, y, INSERT_VALUES, yl));
    PetscCall(DMGetLocalVector(m->dmV1, &sl));
    PetscCall(VecSet(sl, 0));
    PetscCall(VecGetArrayRead(yl, &ya));
    PetscCall(VecGetArray(sl, &sa));
    for (PetscInt e = 0; e < m->ne; e++)
      if (m->edgeOwned[e]) {
        sa[m->edgeVert[2 * e]] += ya[e];
        sa[m->edgeVert[2 * e + 1]] += ya[e];
      }
    PetscCall(VecRestoreArray(sl, &sa));
    PetscCall(VecRestoreArrayRead(yl, &ya));
    PetscCall(DMCreateGlobalVector(m->dmV1, &s));
    PetscCall(VecSet(s, 0));
    PetscCall(DMLocalToGlobal(m->dmV1, sl, ADD_VALUES, s));
    PetscCall(VecNorm(s, NORM_INFINITY, &err));
    PetscCall(VecNorm(y, NORM_INFINITY, &nrm));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: vertex-star sums of C lambda (random lambda, |C lambda| = %.2g)", label, (double)nrm));
    PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-12 && nrm > 0.1), what, err, 1e-12));
    PetscCall(VecDestroy(&s));
    PetscCall(DMRestoreLocalVector(m->dmV1, &sl));
    PetscCall(DMRestoreLocalVector(m->dmE1, &yl));
  }
  /* H^2 metric: shell = assembled, H 1 = *0 1 (L 1 = 0), symmetric positive */
  {
    CSMetric    H;
    Vec         h1, h2;
    PetscScalar q;
    PetscCall(CSMetricCreate(m, PETSC_TRUE, &H));
    PetscCall(CSMetricUpdate(&H, x));
    PetscCall(VecDuplicate(x, &h1));
    PetscCall(VecDuplicate(x, &h2));
    PetscCall(VecSetRandom(d, rnd));
    PetscCall(MatMult(H.H, d, h1));
    PetscCall(MatMult(H.shell, d, h2));
    PetscCall(VecAXPY(h2, -1.0, h1));
    PetscCall(VecNorm(h2, NORM_INFINITY, &err));
    PetscCall(VecNorm(h1, NORM_INFINITY, &nrm));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: H^2 shell vs assembled *0 + L *0^-1 L (relative)", label));
    PetscCall(CSTestCheck(comm, (PetscBool)(err / nrm < 1e-12), what, err / nrm, 1e-12));
    PetscCall(VecDot(h1, d, &q));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: <H d, d> > 0", label));
    PetscCall(CSTestCheck(comm, (PetscBool)(PetscRealPart(q) > 0), what, PetscRealPart(q), 0));
    PetscCall(VecSet(d, 1.0));
    PetscCall(MatMult(H.H, d, h1));
    PetscCall(VecAXPY(h1, -1.0, H.m3));
    PetscCall(VecNorm(h1, NORM_INFINITY, &err));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: H 1 = *0 1", label));
    PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-12), what, err, 1e-12));
    PetscCall(VecDestroy(&h1));
    PetscCall(VecDestroy(&h2));
    PetscCall(CSMetricDestroy(&H));
  }
  /* I_Q > 0 with the guard */
  {
    PetscInt ng;
    PetscCall(CSOperatorQuadDiffMetric(m, x, 1e-2, iq, &ng));
    PetscCall(VecMin(iq, NULL, &mn));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: min I_Q > 0 (%" PetscInt_FMT " guarded edges)", label, ng));
    PetscCall(CSTestCheck(comm, (PetscBool)(mn > 0), what, mn, 0));
  }
  /* fairing gradient (Eq. 21) against finite differences */
  {
    CSEnergy e;
    Vec      x0;
    PetscCall(VecDuplicate(x, &x0));
    PetscCall(VecCopy(x, x0));
    PetscCall(VecShift(x0, 0.01));
    PetscCall(CSEnergyCreateFairing(m, x0, 0.1, &e));
    PetscCall(CSEnergyCheckGradient(e, x, 1e-6, 3, &err));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: FD gradient of the fairing energy", label));
    PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-6), what, err, 1e-6));
    PetscCall(CSEnergyDestroy(&e));
    PetscCall(CheckFairingErrors(comm, m, x0, label));
    PetscCall(VecDestroy(&x0));
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&cp));
  PetscCall(VecDestroy(&cm));
  PetscCall(VecDestroy(&fd));
  PetscCall(VecDestroy(&Xd));
  PetscCall(VecDestroy(&y));
  PetscCall(VecDestroy(&lam));
  PetscCall(VecDestroy(&Au));
  PetscCall(VecDestroy(&iq));
  PetscCall(VecDestroy(&u));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&xp));
  PetscCall(VecDestroy(&v));
  PetscCall(CSConformalConstraintDestroy(&cc));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* DN (boundary-face normals, App. D) against central differences of N on a perturbed cylinder. */
static PetscErrorCode CheckNormals(MPI_Comm comm)
{
  CSMeshData         md;
  CSTopology         topo;
  CSMesh             m;
  CSNormalConstraint nc;
  PetscMPIInt        rank;
  Vec                d, xp, cp, cm, Jd;
  PetscRandom        rnd;
  PetscReal          err, nrm, h = 1e-6;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(&md, sizeof(md)));
  PetscCall(PetscMemzero(&topo, sizeof(topo)));
  if (!rank) {
    PetscCall(CSMeshDataCylinder(1.0, 2.0, 12, 6, &md));
    for (PetscInt i = 0; i < 3 * md.nv; i++) md.x[i] += 0.01 * PetscSinReal(7.0 * i);
    PetscCall(CSMeshDataValidate(&md, &topo));
  }
  PetscCall(CSMeshCreateFromData(comm, &md, &topo, &m));
  PetscCall(CSNormalConstraintCreate(m, m->x, NULL, &nc));
  PetscCall(VecDuplicate(nc.N0, &cp));
  PetscCall(VecDuplicate(nc.N0, &cm));
  PetscCall(VecDuplicate(nc.N0, &Jd));
  PetscCall(VecDuplicate(m->x, &d));
  PetscCall(VecDuplicate(m->x, &xp));
  PetscCall(CSNormalConstraintEvaluate(&nc, m->x, cp, PETSC_TRUE));
  PetscCall(VecNorm(cp, NORM_INFINITY, &err));
  PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-14), "cylinder: N(x) - N0 = 0 at the input", err, 1e-14));
  PetscCall(CSTestRandom(comm, 0, 1, 5, &rnd));
  PetscCall(VecSetRandom(d, rnd));
  PetscCall(MatMult(nc.DN, d, Jd));
  PetscCall(VecWAXPY(xp, h, d, m->x));
  PetscCall(CSNormalConstraintEvaluate(&nc, xp, cp, PETSC_FALSE));
  PetscCall(VecWAXPY(xp, -h, d, m->x));
  PetscCall(CSNormalConstraintEvaluate(&nc, xp, cm, PETSC_FALSE));
  PetscCall(VecAXPY(cp, -1.0, cm));
  PetscCall(VecScale(cp, 1.0 / (2 * h)));
  PetscCall(VecAXPY(cp, -1.0, Jd));
  PetscCall(VecNorm(cp, NORM_INFINITY, &err));
  PetscCall(VecNorm(Jd, NORM_INFINITY, &nrm));
  PetscCall(CSTestCheck(comm, (PetscBool)(err / nrm < 1e-6), "cylinder: DN d vs central differences of the boundary-face normals (relative)", err / nrm, 1e-6));
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroy(&cp));
  PetscCall(VecDestroy(&cm));
  PetscCall(VecDestroy(&Jd));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&xp));
  PetscCall(CSNormalConstraintDestroy(&nc));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* Moebius balancing rows (constraints_global.c), and the same checks but the boost for the rotation gauge: m(f0) = 0; rows against central differences of m; m = 0 after
   a similarity of f0 (scaling, rotation and translation stay free); and the infinitesimal Moebius boost of the
   unit sphere v(x) = b - (b.x) x (area change dA = -2 (b.x) A) moves m at the rate of the smooth identity
   dm = -2 (sum_i A_i x_i x_i^T) b / A^(3/2) = -(2/3) b / sqrt(4 pi): the rows do fix the boosts. */
static PetscErrorCode CheckMoments(MPI_Comm comm, PetscBool rotation)
{
  CSMesh             m;
  CSGlobalConstraint g;
  Vec               *rows, d, xp;
  PetscRandom        rnd;
  PetscReal          c[3], cp[3], cm[3], err = 0, nrm = 0, h = 1e-6, expect;
  const PetscReal    b[3] = {0.3, -0.5, 0.2}, w[3] = {0.2, 0.9, -0.4};
  PetscScalar        jd[3];
  char               what[128];
  const char        *nm = rotation ? "rotation gauge" : "mobius";
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, PETSC_FALSE, 0.0, &m)); /* level-2 icosphere, vertices on the unit sphere */
  if (rotation) PetscCall(CSConstraintCreateRotationGauge(m, m->x, &g));
  else PetscCall(CSConstraintCreateMobiusBalance(m, m->x, &g));
  PetscCall(VecDuplicateVecs(m->x, 3, &rows));
  PetscCall(VecDuplicate(m->x, &d));
  PetscCall(VecDuplicate(m->x, &xp));
  PetscCall(CSGlobalConstraintEvaluate(g, m->x, c, rows));
  err = PetscMax(PetscAbsReal(c[0]), PetscMax(PetscAbsReal(c[1]), PetscAbsReal(c[2])));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: m(f0) = 0", nm));
  PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-15), what, err, 1e-15));
  /* rows vs central differences along a random direction */
  PetscCall(CSTestRandom(comm, 0, 1, 7, &rnd));
  PetscCall(VecSetRandom(d, rnd));
  PetscCall(VecMDot(d, 3, rows, jd));
  PetscCall(VecWAXPY(xp, h, d, m->x));
  PetscCall(CSGlobalConstraintEvaluate(g, xp, cp, NULL));
  PetscCall(VecWAXPY(xp, -h, d, m->x));
  PetscCall(CSGlobalConstraintEvaluate(g, xp, cm, NULL));
  err = 0;
  for (int k = 0; k < 3; k++) {
    err = PetscMax(err, PetscAbsReal((cp[k] - cm[k]) / (2 * h) - PetscRealPart(jd[k])));
    nrm = PetscMax(nrm, PetscAbsReal(PetscRealPart(jd[k])));
  }
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: rows vs central differences (relative)", nm));
  PetscCall(CSTestCheck(comm, (PetscBool)(err / nrm < 1e-6), what, err / nrm, 1e-6));
  /* a similarity: x -> 1.7 R x + t, R the rotation exp([w]x) to first order made exact by Rodrigues */
  {
    PetscInt           nl;
    const PetscScalar *x;
    PetscScalar       *y;
    PetscReal          th = CSVecNorm(w), k[3], t[3] = {0.4, -1.1, 2.0};
    for (int e = 0; e < 3; e++) k[e] = w[e] / th;
    PetscCall(VecGetLocalSize(m->x, &nl));
    PetscCall(VecGetArrayRead(m->x, &x));
    PetscCall(VecGetArray(xp, &y));
    for (PetscInt i = 0; i < nl / 3; i++) {
      const PetscReal *v = (const PetscReal *)x + 3 * i;
      PetscReal        kv[3], kd = CSVecDot(k, v);
      CSVecCross(k, v, kv);
      for (int e = 0; e < 3; e++) y[3 * i + e] = 1.7 * (v[e] * PetscCosReal(th) + kv[e] * PetscSinReal(th) + k[e] * kd * (1 - PetscCosReal(th))) + t[e];
    }
    PetscCall(VecRestoreArrayRead(m->x, &x));
    PetscCall(VecRestoreArray(xp, &y));
    PetscCall(CSGlobalConstraintEvaluate(g, xp, cp, NULL));
    err = PetscMax(PetscAbsReal(cp[0]), PetscMax(PetscAbsReal(cp[1]), PetscAbsReal(cp[2])));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: zero after a similarity of f0 in space (scaling, rotation, translation free)", nm));
    PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-13), what, err, 1e-13));
  }
  /* the boost field (the balancing's own job) */
  if (!rotation) {
    PetscInt           nl;
    const PetscScalar *x;
    PetscScalar       *v;
    PetscCall(VecGetLocalSize(m->x, &nl));
    PetscCall(VecGetArrayRead(m->x, &x));
    PetscCall(VecGetArray(d, &v));
    for (PetscInt i = 0; i < nl / 3; i++) {
      const PetscReal *f  = (const PetscReal *)x + 3 * i;
      PetscReal        bx = CSVecDot(b, f);
      for (int e = 0; e < 3; e++) v[3 * i + e] = b[e] - bx * f[e];
    }
    PetscCall(VecRestoreArrayRead(m->x, &x));
    PetscCall(VecRestoreArray(d, &v));
    PetscCall(VecMDot(d, 3, rows, jd));
    expect = -2.0 / (3.0 * PetscSqrtReal(4 * PETSC_PI));
    err    = 0;
    for (int k = 0; k < 3; k++) err = PetscMax(err, PetscAbsReal(PetscRealPart(jd[k]) - expect * b[k]) / (PetscAbsReal(expect) * CSVecNorm(b)));
    PetscCall(CSTestCheck(comm, (PetscBool)(err < 0.05), "mobius: rows . boost field = -(2/3) b / sqrt(4 pi) (smooth identity, relative, level-2 icosphere)", err, 0.05));
  }
  PetscCall(PetscRandomDestroy(&rnd));
  PetscCall(VecDestroyVecs(3, &rows));
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&xp));
  PetscCall(CSGlobalConstraintDestroy(&g));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(CSInitializePackage());
  PetscCall(RunChecks(PETSC_COMM_WORLD, PETSC_FALSE));
  PetscCall(RunChecks(PETSC_COMM_WORLD, PETSC_TRUE));
  PetscCall(CheckNormals(PETSC_COMM_WORLD));
  PetscCall(CheckMoments(PETSC_COMM_WORLD, PETSC_FALSE));
  PetscCall(CheckMoments(PETSC_COMM_WORLD, PETSC_TRUE)); /* the rotation gauge of the domain (docs/vesicle.md) */
  return CSTestFinalize(PETSC_COMM_WORLD, PetscFinalize);
}
