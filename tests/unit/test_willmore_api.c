static const char help[] = "The constrained Willmore flow through the library API alone (issue 23): a CGD flow created on a\n"
                           "mesh generated here, stepped with CSWillmoreFlowStep and solved with CSWillmoreFlowSolve, with a\n"
                           "monitor. Checks: W decreases, the conformal violation stays small (below 1e-10 at convergence), the mesh given to the\n"
                           "flow keeps its positions, the iteration limit gives DIVERGED_MAX_IT, a coarse torus converges\n"
                           "(CONVERGED_RTOL). Exit status = number of failed checks.\n";

#include "cs_methods_willmore.h"
#include "cs_package.h"
#include "cs_test.h"

/* The test input of the flow tests: f <- f (1 + a sin(3 f_x) sin(3 f_y) sin(3 f_z)) (as -gen_deform_bump a). */
static PetscErrorCode Bump(Vec x, PetscReal a)
{
  PetscInt     n;
  PetscScalar *p;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArray(x, &p));
  for (PetscInt i = 0; i < n; i += 3) {
    PetscReal b = 1 + a * PetscSinReal(3 * PetscRealPart(p[i])) * PetscSinReal(3 * PetscRealPart(p[i + 1])) * PetscSinReal(3 * PetscRealPart(p[i + 2]));
    for (int d = 0; d < 3; d++) p[i + d] *= b;
  }
  PetscCall(VecRestoreArray(x, &p));
  PetscFunctionReturn(0);
}

/* a bumped icosphere of level 2, or a coarse torus of revolution R = 3, r = 1 */
static PetscErrorCode MakeMesh(MPI_Comm comm, PetscBool torus, CSMesh *mesh)
{
  CSTestMeshSpec ico = {CS_TEST_ICOSPHERE, 2, 0, 0, 0}, tor = {CS_TEST_TORUS, 16, 8, 3, 1};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, torus ? tor : ico, 0, 7, mesh));
  if (!torus) PetscCall(Bump((*mesh)->x, 0.1));
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt  calls;
  PetscReal W0, Wlast, vmax; /* the energy of the first and last call, the largest conformal violation */
  PetscBool decreasing;
} Record;

static PetscErrorCode RecordMonitor(CSWillmoreFlow flow, PetscInt it, void *ctx)
{
  Record            *r = (Record *)ctx;
  CSWillmoreFlowInfo i;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  if (!r->calls) r->W0 = i.energy;
  else if (!(i.energy <= r->Wlast)) r->decreasing = PETSC_FALSE;
  r->Wlast = i.energy;
  r->vmax  = PetscMax(r->vmax, i.conformal_violation);
  r->calls++;
  PetscFunctionReturn(0);
}

/* A bumped icosphere, 6 CGD iterations: 3 by Step, the rest by Solve. */
static PetscErrorCode CheckSteps(MPI_Comm comm)
{
  CSMesh                        m;
  CSWillmoreFlow                flow;
  CSWillmoreFlowConvergedReason reason;
  Record                        rec = {0, 0, 0, 0, PETSC_TRUE};
  Vec                           x, x0;
  PetscReal                     d, n0;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, PETSC_FALSE, &m));
  PetscCall(VecDuplicate(m->x, &x0));
  PetscCall(VecCopy(m->x, x0));
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetType(flow, CSWILLMOREFLOWCGD));
  PetscCall(CSWillmoreFlowSetTolerances(flow, 1e-6, 1e-10, 6));
  PetscCall(CSWillmoreFlowSetFromOptions(flow));
  PetscCall(CSWillmoreFlowMonitorSet(flow, RecordMonitor, &rec, NULL));
  PetscCall(CSWillmoreFlowSetUp(flow));
  for (PetscInt i = 0; i < 3; i++) PetscCall(CSWillmoreFlowStep(flow, &reason));
  PetscCall(CSTestCheck(comm, (PetscBool)(reason == CS_WILLMORE_FLOW_ITERATING), "steps 1-3: still iterating (reason)", (PetscReal)reason, 0));
  PetscCall(CSWillmoreFlowSolve(flow));
  PetscCall(CSWillmoreFlowGetConvergedReason(flow, &reason));
  PetscCall(PetscPrintf(comm, "reason %s\n", CSWillmoreFlowConvergedReasons[reason]));
  PetscCall(CSTestCheck(comm, (PetscBool)(reason == CS_WILLMORE_FLOW_DIVERGED_MAX_IT), "6 iterations: DIVERGED_MAX_IT (reason)", (PetscReal)reason, CS_WILLMORE_FLOW_DIVERGED_MAX_IT));
  PetscCall(CSTestCheck(comm, (PetscBool)(rec.calls == 7), "monitor called at iterations 0..6 (calls)", (PetscReal)rec.calls, 7));
  PetscCall(CSTestCheck(comm, (PetscBool)(rec.decreasing && rec.Wlast < rec.W0 - 1e-3), "W decreases at every step (W0 - W6)", rec.W0 - rec.Wlast, 1e-3));
  PetscCall(CSTestCheck(comm, (PetscBool)(rec.vmax < 1e-5), "conformal violation at every iteration (first steps: linearisation error)", rec.vmax, 1e-5));
  /* the flow works on its own copy: the mesh it was given keeps the input positions */
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(VecNorm(x0, NORM_2, &n0));
  PetscCall(VecAXPY(x0, -1.0, m->x));
  PetscCall(VecNorm(x0, NORM_2, &d));
  PetscCall(CSTestCheck(comm, (PetscBool)(d == 0), "mesh positions unchanged by the flow", d, 0));
  PetscCall(VecAXPY(x0, 1.0, m->x));
  PetscCall(VecAXPY(x0, -1.0, x));
  PetscCall(VecNorm(x0, NORM_2, &d));
  PetscCall(CSTestCheck(comm, (PetscBool)(d > 1e-3 * n0), "the solution moved (|x - x0| / |x0|)", d / n0, 1e-3));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscCall(VecDestroy(&x0));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* A coarse torus of revolution flows to a constrained critical point: CONVERGED_RTOL. */
static PetscErrorCode CheckConverges(MPI_Comm comm)
{
  CSMesh                        m;
  CSWillmoreFlow                flow;
  CSWillmoreFlowConvergedReason reason;
  CSWillmoreFlowInfo            info;
  PetscFunctionBeginUser;
  PetscCall(MakeMesh(comm, PETSC_TRUE, &m));
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetTolerances(flow, 1e-6, 1e-10, 200));
  PetscCall(CSWillmoreFlowSetFromOptions(flow));
  PetscCall(CSWillmoreFlowSolve(flow));
  PetscCall(CSWillmoreFlowGetConvergedReason(flow, &reason));
  PetscCall(CSWillmoreFlowGetInfo(flow, &info));
  PetscCall(PetscPrintf(comm, "reason %s after %" PetscInt_FMT " iterations, W %.10g\n", CSWillmoreFlowConvergedReasons[reason], info.it, (double)info.energy));
  PetscCall(CSTestCheck(comm, (PetscBool)(reason == CS_WILLMORE_FLOW_CONVERGED_RTOL), "torus: CONVERGED_RTOL (reason)", (PetscReal)reason, CS_WILLMORE_FLOW_CONVERGED_RTOL));
  /* -flow_rtol tests the scale-free el_residual_scaled (docs/willmore_flow.md "Stopping") */
  PetscCall(CSTestCheck(comm, (PetscBool)(info.el_residual_scaled < 1e-6), "torus: scaled EL residual at convergence", info.el_residual_scaled, 1e-6));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.conformal_violation < 1e-10), "torus: conformal violation at convergence", info.conformal_violation, 1e-10));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(CSInitializePackage());
  PetscCall(CheckSteps(PETSC_COMM_WORLD));
  PetscCall(CheckConverges(PETSC_COMM_WORLD));
  return CSTestFinalize(PETSC_COMM_WORLD, PetscFinalize);
}
