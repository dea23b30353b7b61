static const char help[] = "The extension points of the Willmore flow (issue 37, point 3), through the public registration alone:\n"
                           "a toy energy E = W + w/2 |f - f0|^2 (its weight w read as -flow_toy_weight by its own SetFromOptions)\n"
                           "and a toy constraint |f|^2 / N = its input value are registered, a CGD flow runs 5 iterations with them,\n"
                           "and their gradient and rows pass central finite differences. Then every registered energy's gradient\n"
                           "and every registered constraint's rows are checked the same way, so a new one is tested by being\n"
                           "registered. Every registered flow kind must keep a constraint added by name or refuse it.\n"
                           "A kind with another's ops.id is refused at registration. Exit status = number of failed checks.\n";

#include "cs_methods_willmore.h"
#include "cs_package.h"
#include "cs_test.h"

/* ---- the toy energy: E = W(f) + w/2 |f - f0|^2 (a fidelity term on the plain vertex positions) ---- */
typedef struct {
  CSEnergy  W;
  Vec       x0, d;
  PetscReal w;
} ToyEnergy;

static PetscErrorCode ToyGradient(CSEnergy e, Vec x, PetscReal *E, Vec g)
{
  ToyEnergy *t = (ToyEnergy *)e->ctx;
  PetscReal  W, n;
  PetscFunctionBeginUser;
  if (g) PetscCall(CSEnergyGradient(t->W, x, &W, g));
  else PetscCall(CSEnergyValue(t->W, x, &W));
  PetscCall(VecWAXPY(t->d, -1.0, t->x0, x));
  if (E) {
    PetscCall(VecNorm(t->d, NORM_2, &n));
    *E = W + 0.5 * t->w * n * n;
  }
  if (g) PetscCall(VecAXPY(g, t->w, t->d));
  PetscFunctionReturn(0);
}

static PetscErrorCode ToyValue(CSEnergy e, Vec x, PetscReal *E)
{
  PetscFunctionBeginUser;
  PetscCall(ToyGradient(e, x, E, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode ToySetFromOptions(CSEnergy e)
{
  ToyEnergy *t = (ToyEnergy *)e->ctx;
  PetscFunctionBeginUser;
  PetscOptionsBegin(e->mesh->comm, e->prefix, "Toy energy of test_extension", NULL);
  PetscCall(PetscOptionsReal("-weight", "Weight w of the fidelity term", NULL, t->w, &t->w, NULL));
  PetscOptionsEnd();
  PetscFunctionReturn(0);
}

static PetscErrorCode ToyDestroy(CSEnergy e)
{
  ToyEnergy *t = (ToyEnergy *)e->ctx;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyDestroy(&t->W));
  PetscCall(VecDestroy(&t->x0));
  PetscCall(VecDestroy(&t->d));
  PetscCall(PetscFree(t));
  PetscFunctionReturn(0);
}

static PetscErrorCode ToyEnergyCreate(CSMesh m, Vec x0, CSEnergy *e)
{
  ToyEnergy *t;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&t));
  t->w = 1; /* the default of -<prefix>weight */
  PetscCall(CSEnergyCreateWillmore(m, &t->W));
  PetscCall(VecDuplicate(x0, &t->x0));
  PetscCall(VecCopy(x0, t->x0));
  PetscCall(VecDuplicate(x0, &t->d));
  PetscCall(CSEnergyCreateShell(m, "toy", e));
  (*e)->ctx            = t;
  (*e)->value          = ToyValue;
  (*e)->gradient       = ToyGradient;
  (*e)->setfromoptions = ToySetFromOptions;
  (*e)->destroy        = ToyDestroy;
  PetscFunctionReturn(0);
}

/* ---- the toy constraint: c = |f|^2 / N - r0^2 (one nonlinear row, 2 f / N; N the number of vertices) ---- */
typedef struct {
  PetscReal r2, N;
} ToyRadius;

static PetscErrorCode ToyRadiusEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[])
{
  ToyRadius *t = (ToyRadius *)g->ctx;
  PetscReal  n;
  PetscFunctionBeginUser;
  PetscCall(VecNorm(x, NORM_2, &n));
  c[0] = n * n / t->N - t->r2;
  if (rows) {
    PetscCall(VecCopy(x, rows[0]));
    PetscCall(VecScale(rows[0], 2.0 / t->N));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ToyRadiusDestroy(CSGlobalConstraint g)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(g->ctx));
  PetscFunctionReturn(0);
}

static PetscErrorCode ToyRadiusCreate(CSMesh m, Vec x0, const char prefix[], CSGlobalConstraint *g)
{
  ToyRadius *t;
  PetscReal  n;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&t));
  t->N = (PetscReal)m->Nv;
  PetscCall(VecNorm(x0, NORM_2, &n));
  t->r2 = n * n / t->N;
  PetscCall(CSGlobalConstraintCreateShell(m, "toy_radius", 1, g));
  (*g)->ctx      = t;
  (*g)->evaluate = ToyRadiusEvaluate;
  (*g)->destroy  = ToyRadiusDestroy;
  PetscFunctionReturn(0);
}

/* The test input: an icosphere of level 2 with seeded noise (the same on every process count). */
static PetscErrorCode MakeMesh(MPI_Comm comm, CSMesh *m)
{
  CSTestMeshSpec ico = {CS_TEST_ICOSPHERE, 2, 0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, ico, 0.02, 37, m));
  PetscFunctionReturn(0);
}

/* CGD with the toy energy (-flow_toy_weight 2) and the toy constraint added by name, 5 iterations. */
static PetscErrorCode CheckToyFlow(MPI_Comm comm)
{
  CSMesh             m;
  CSWillmoreFlow     flow;
  CSWillmoreFlowInfo info;
  CSEnergy           e;
  Vec                x;
  PetscReal          E0, err;
  PetscBool          prefixed;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, &m));
  PetscCall(PetscOptionsSetValue(NULL, "-flow_toy_weight", "2"));
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetType(flow, CSWILLMOREFLOWCGD));
  PetscCall(CSWillmoreFlowSetEnergyType(flow, "toy"));
  PetscCall(CSWillmoreFlowAddConstraint(flow, "toy_radius"));
  PetscCall(CSWillmoreFlowSetTolerances(flow, 1e-12, 1e-12, 5));
  PetscCall(CSWillmoreFlowSetFromOptions(flow));
  PetscCall(CSWillmoreFlowSetUp(flow));
  PetscCall(CSWillmoreFlowGetEnergy(flow, &e));
  PetscCall(PetscStrcmp(e->prefix, "flow_toy_", &prefixed));
  PetscCall(CSTestCheck(comm, prefixed, "the flow gave the toy energy the prefix flow_toy_", 0, 0));
  PetscCall(CSTestCheck(comm, (PetscBool)(((ToyEnergy *)e->ctx)->w == 2), "-flow_toy_weight 2 read by the energy's SetFromOptions (w)", ((ToyEnergy *)e->ctx)->w, 2));
  PetscCall(CSWillmoreFlowGetInitialEnergy(flow, &E0));
  PetscCall(CSWillmoreFlowSolve(flow));
  PetscCall(CSWillmoreFlowGetInfo(flow, &info));
  PetscCall(PetscPrintf(comm, "toy flow: %" PetscInt_FMT " iterations, %" PetscInt_FMT " rejections, E %.10g -> %.10g, constraint rows %" PetscInt_FMT ", global violation %.3e\n", info.it, info.rejections, (double)E0, (double)info.energy, info.k, (double)info.constraint_violation));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.it == 5), "5 iterations run", (PetscReal)info.it, 5));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.k == 1), "one global row: the toy constraint", (PetscReal)info.k, 1));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.energy < E0 - 1e-3 * E0), "the toy energy decreased (relative, E0 - E)", (E0 - info.energy) / E0, 1e-3));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.constraint_violation < 1e-6), "the toy constraint kept (violation of the global rows)", info.constraint_violation, 1e-6));
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(CSEnergyCheckGradient(e, x, 1e-6, 3, &err));
  PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-6), "toy energy: FD gradient at the flow's solution (relative)", err, 1e-6));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscCall(PetscOptionsClearValue(NULL, "-flow_toy_weight"));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* One registered energy (the toy one included): its gradient against central differences. */
static PetscErrorCode CheckEnergy(MPI_Comm comm, CSMesh m, Vec x0, const char name[], PetscVoidFunction fn)
{
  PetscErrorCode (*create)(CSMesh, Vec, CSEnergy *) = (PetscErrorCode(*)(CSMesh, Vec, CSEnergy *))fn;
  CSEnergy  e;
  PetscReal err;
  char      what[128];
  PetscFunctionBeginUser;
  PetscCall((*create)(m, x0, &e));
  PetscCall(CSEnergySetOptionsPrefix(e, "check_"));
  PetscCall(CSEnergySetFromOptions(e));
  PetscCall(CSEnergyCheckGradient(e, m->x, 1e-6, 3, &err));
  PetscCall(PetscSNPrintf(what, sizeof(what), "energy %s: FD gradient (relative)", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-6), what, err, 1e-6));
  PetscCall(CSEnergyDestroy(&e));
  PetscFunctionReturn(0);
}

/* One registered constraint (the toy one included): its rows against central differences. */
static PetscErrorCode CheckConstraint(MPI_Comm comm, CSMesh m, Vec x0, const char name[], PetscVoidFunction fn)
{
  PetscErrorCode (*create)(CSMesh, Vec, const char[], CSGlobalConstraint *) = (PetscErrorCode(*)(CSMesh, Vec, const char[], CSGlobalConstraint *))fn;
  CSGlobalConstraint g;
  PetscReal          err;
  char               what[128];
  PetscFunctionBeginUser;
  PetscCall((*create)(m, x0, "check_", &g));
  PetscCall(CSGlobalConstraintCheckRows(g, m->x, 1e-6, 3, &err));
  PetscCall(PetscSNPrintf(what, sizeof(what), "constraint %s: FD rows (%" PetscInt_FMT ", relative)", name, g->k));
  PetscCall(CSTestCheck(comm, (PetscBool)(err < 1e-6), what, err, 1e-6));
  PetscCall(CSGlobalConstraintDestroy(&g));
  PetscFunctionReturn(0);
}

/* check on every entry of a registry, in registration order */
static PetscErrorCode CheckEach(MPI_Comm comm, PetscFunctionList list, CSMesh m, Vec x0, PetscErrorCode (*check)(MPI_Comm, CSMesh, Vec, const char[], PetscVoidFunction))
{
  const char **names;
  int          n;
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListGet(list, &names, &n));
  for (int i = 0; i < n && names[i]; i++) { /* n counts a closing NULL */
    PetscVoidFunction fn;
    PetscCall(PetscFunctionListFind(list, names[i], &fn));
    PetscCall((*check)(comm, m, x0, names[i], fn));
  }
  PetscCall(PetscFree(names));
  PetscFunctionReturn(0);
}

/* The checks at x = the noisy icosphere, with targets and fidelities from a second noisy one (so that no
   term is at its minimum, where a wrong gradient could still vanish). */
static PetscErrorCode CheckRegistered(MPI_Comm comm)
{
  CSMesh            m;
  Vec               x0;
  PetscRandom       r;
  PetscFunctionList list;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, &m));
  PetscCall(VecDuplicate(m->x, &x0));
  PetscCall(CSTestRandom(comm, -0.02, 0.02, 11, &r));
  PetscCall(VecSetRandom(x0, r));
  PetscCall(VecAXPY(x0, 1.0, m->x));
  PetscCall(CSWillmoreFlowEnergyList(&list));
  PetscCall(CheckEach(comm, list, m, x0, CheckEnergy));
  PetscCall(CSWillmoreFlowConstraintList(&list));
  PetscCall(CheckEach(comm, list, m, x0, CheckConstraint));
  PetscCall(PetscRandomDestroy(&r));
  PetscCall(VecDestroy(&x0));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* One run of kind `name`, 2 iterations, with the toy constraint added after SetFromOptions (add) or without:
   *ierr the error of the set-up or the solve (0: it ran), *v = |toy_radius| at the solution. */
static PetscErrorCode RunKind(MPI_Comm comm, CSMesh m, const char name[], PetscBool add, PetscErrorCode *ierr, PetscReal *v)
{
  CSWillmoreFlow     flow;
  CSGlobalConstraint g;
  Vec                x;
  PetscReal          c;
  PetscFunctionBeginUser;
  *v = -1;
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetType(flow, name));
  PetscCall(CSWillmoreFlowSetTolerances(flow, 0, 1e-10, 2)); /* ctol the default: PGD projects to it */
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  *ierr = CSWillmoreFlowSetFromOptions(flow);
  if (!*ierr && add) *ierr = CSWillmoreFlowAddConstraint(flow, "toy_radius"); /* after the kind's option checks */
  if (!*ierr) *ierr = CSWillmoreFlowSetUp(flow);
  if (!*ierr) *ierr = CSWillmoreFlowSolve(flow);
  PetscCall(PetscPopErrorHandler());
  if (!*ierr) {
    PetscCall(CSWillmoreFlowGetSolution(flow, &x));
    PetscCall(ToyRadiusCreate(m, m->x, "check_", &g));
    PetscCall(CSGlobalConstraintEvaluate(g, x, &c, NULL));
    PetscCall(CSGlobalConstraintDestroy(&g));
    *v = PetscAbsReal(c);
  }
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscFunctionReturn(0);
}

/* Every registered kind honours a constraint added by name or refuses it: refused (ARG_INCOMP or SUP), or after 2
   iterations |toy_radius| < 1e-6 or under a tenth of what the kind reaches without it. newton and the fairing
   baselines refused only the option-made constraints and ran ignoring an added one (the kind recipe's walk-through). */
static PetscErrorCode CheckKindsHonourAdded(MPI_Comm comm)
{
  CSMesh            m;
  PetscFunctionList kinds;
  const char      **names;
  int               n;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, &m));
  PetscCall(CSWillmoreFlowGetTypeList(&kinds));
  PetscCall(PetscFunctionListGet(kinds, &names, &n));
  for (int i = 0; i < n && names[i]; i++) {
    PetscErrorCode ierr, ierr0 = 0;
    PetscReal      v, v0 = -1;
    PetscBool      ok;
    char           what[256];
    PetscCall(RunKind(comm, m, names[i], PETSC_TRUE, &ierr, &v));
    if (!ierr && v >= 1e-6) PetscCall(RunKind(comm, m, names[i], PETSC_FALSE, &ierr0, &v0));
    ok = (PetscBool)(ierr ? (ierr == PETSC_ERR_ARG_INCOMP || ierr == PETSC_ERR_SUP) : (v < 1e-6 || (!ierr0 && v < 0.1 * v0)));
    if (ierr) {
      char *msg = NULL;
      PetscCall(PetscErrorMessage(ierr, NULL, &msg));
      PetscCall(PetscSNPrintf(what, sizeof(what), "kind %s: an added constraint refused (error %d: %.90s)", names[i], (int)ierr, msg ? msg : ""));
    }
    else if (v0 < 0) PetscCall(PetscSNPrintf(what, sizeof(what), "kind %s ran with an added constraint: |c| %.2e", names[i], (double)v));
    else PetscCall(PetscSNPrintf(what, sizeof(what), "kind %s ran with an added constraint: |c| %.2e (without it %.2e)", names[i], (double)v, (double)v0));
    PetscCall(CSTestCheck(comm, ok, what, ierr ? (PetscReal)ierr : v, ierr ? 0 : 1e-6));
  }
  PetscCall(PetscFree(names));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* ---- a kind whose create sets no ops.id (0, cgd's): refused at registration, since the id is what a checkpoint
   stores to find the kind that wrote it (alm and newton once shared 3) ---- */
static PetscErrorCode ToyKindCreate(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  (void)F;
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckKindIds(MPI_Comm comm)
{
  PetscErrorCode    ierr;
  PetscFunctionList kinds;
  PetscVoidFunction fn = NULL;
  const char       *text;
  char             *specific = NULL;
  PetscBool         named;
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = CSWillmoreFlowRegister("toy_kind", ToyKindCreate);
  PetscCall(PetscPopErrorHandler());
  if (ierr) PetscCall(PetscErrorMessage(ierr, &text, &specific));
  named = (PetscBool)(specific && strstr(specific, "CSWillmoreFlowRegister(toy_kind): its ops.id 0 is that of the kind cgd"));
  PetscCall(CSTestCheck(comm, (PetscBool)(ierr && named), "a kind with cgd's ops.id refused at registration, naming both", 0, 0));
  PetscCall(CSWillmoreFlowGetTypeList(&kinds));
  PetscCall(PetscFunctionListFind(kinds, "toy_kind", &fn));
  PetscCall(CSTestCheck(comm, (PetscBool)!fn, "the refused kind is not in the list", 0, 0));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(CSInitializePackage());
  PetscCall(CSWillmoreFlowEnergyRegister("toy", ToyEnergyCreate));
  PetscCall(CSWillmoreFlowConstraintRegister("toy_radius", ToyRadiusCreate));
  PetscCall(CheckToyFlow(PETSC_COMM_WORLD));
  PetscCall(CheckRegistered(PETSC_COMM_WORLD));
  PetscCall(CheckKindsHonourAdded(PETSC_COMM_WORLD));
  PetscCall(CheckKindIds(PETSC_COMM_WORLD));
  return CSTestFinalize(PETSC_COMM_WORLD, PetscFinalize);
}
