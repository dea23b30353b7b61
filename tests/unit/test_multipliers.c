static const char help[] = "The conformal Lagrange multiplier made visible (soliman2021 Sec. 3, Eq. 6-8): after 30 CGD steps\n"
                           "of a perturbed sphere and at a few ALM steps, q = quadratic differential sums to zero around every\n"
                           "vertex (Eq. 6), |grad W + force| equals the reported EL residual; on the conformally constrained minimal\n"
                           "cylinder (Fig. 6 right) the force balances -Lf at the interior vertices to the solver tolerance.\n"
                           "Exit status = number of failed checks.\n";

#include "cs_methods_willmore.h"
#include "cs_geometry.h"
#include "cs_package.h"
#include "cs_test.h"

/* max_i |sum_j q_ij| and max |q| */
static PetscErrorCode VertexSums(CSMesh m, Vec q, PetscReal *smax, PetscReal *qmax)
{
  Vec s;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(m->dmV1, &s));
  PetscCall(CSGeometryEdgeSumAtVertices(m, q, s));
  PetscCall(VecNorm(s, NORM_INFINITY, smax));
  PetscCall(VecNorm(q, NORM_INFINITY, qmax));
  PetscCall(VecDestroy(&s));
  PetscFunctionReturn(0);
}

/* Eq. 6 and |grad W + force| = EL residual at the flow's current state. */
static PetscErrorCode CheckIdentities(CSWillmoreFlow flow, const char what[])
{
  CSMesh             m;
  CSEnergy           W;
  CSWillmoreFlowInfo info;
  Vec                q, force, g, x;
  PetscReal          E, smax, qmax, el;
  char               s[128];
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetMesh(flow, &m));
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(CSWillmoreFlowGetInfo(flow, &info));
  PetscCall(DMCreateGlobalVector(m->dmE1, &q));
  PetscCall(DMCreateGlobalVector(m->dmV3, &force));
  PetscCall(VecDuplicate(force, &g));
  PetscCall(CSWillmoreFlowGetConformalMultiplier(flow, q, force));
  PetscCall(VertexSums(m, q, &smax, &qmax));
  PetscCall(PetscSNPrintf(s, sizeof(s), "%s: max_i |sum_j q_ij| (Eq. 6; max |q| = %.3e)", what, (double)qmax));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(smax < 1e-12 && qmax > 1e-6), s, smax, 1e-12));
  PetscCall(CSEnergyCreateWillmore(m, &W));
  PetscCall(CSEnergyGradient(W, x, &E, g));
  PetscCall(VecAXPY(g, 1.0, force));
  PetscCall(VecNorm(g, NORM_2, &el));
  PetscCall(PetscSNPrintf(s, sizeof(s), "%s: | |grad W + force| - EL residual | (EL %.3e)", what, (double)info.el_residual));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(PetscAbsReal(el - info.el_residual) <= 1e-12 * PetscMax(1, info.el_residual)), s, PetscAbsReal(el - info.el_residual), 1e-12));
  PetscCall(CSEnergyDestroy(&W));
  PetscCall(VecDestroy(&q));
  PetscCall(VecDestroy(&force));
  PetscCall(VecDestroy(&g));
  PetscFunctionReturn(0);
}

/* A perturbed icosphere (level 2): 30 CGD steps, then 5 ALM steps (Gauss-Newton metric). */
static PetscErrorCode CheckSphere(MPI_Comm comm, CSWillmoreFlowType type, const char prefix[], PetscInt max_it)
{
  CSMesh                        m;
  CSWillmoreFlow                flow;
  CSWillmoreFlowConvergedReason reason;
  CSTestMeshSpec                ico = {CS_TEST_ICOSPHERE, 2, 0, 0, 0};
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, ico, 0.01, 11, &m));
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetType(flow, type));
  PetscCall(CSWillmoreFlowSetOptionsPrefix(flow, prefix));
  PetscCall(CSWillmoreFlowSetTolerances(flow, 1e-6, 1e-10, max_it));
  PetscCall(CSWillmoreFlowSetFromOptions(flow));
  PetscCall(CSWillmoreFlowSolve(flow));
  PetscCall(CSWillmoreFlowGetConvergedReason(flow, &reason));
  PetscCall(PetscPrintf(comm, "%s: %s\n", type, CSWillmoreFlowConvergedReasons[reason]));
  PetscCall(CheckIdentities(flow, type));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

/* The conformally constrained minimal cylinder (area energy, Dirichlet boundary): force = -Lf inside. */
static PetscErrorCode CheckCylinder(MPI_Comm comm)
{
  CSMesh                        m;
  CSWillmoreFlow                flow;
  CSWillmoreFlowConvergedReason reason;
  CSWillmoreFlowInfo            info;
  CSTestMeshSpec                cyl = {CS_TEST_CYLINDER, 24, 12, 0, 0};
  Vec                           x, force, Lf, q;
  PetscReal                     d, n, smax, qmax;
  PetscScalar                  *a;
  PetscInt                      nv;
  PetscFunctionBeginUser;
  PetscCall(CSTestMesh(comm, cyl, 0, 3, &m));
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetOptionsPrefix(flow, "cyl_")); /* tests/cases/willmore_multipliers.sh: -cyl_energy area */
  PetscCall(CSWillmoreFlowSetTolerances(flow, 1e-6, 1e-10, 300));
  PetscCall(CSWillmoreFlowSetFromOptions(flow));
  PetscCall(CSWillmoreFlowSolve(flow));
  PetscCall(CSWillmoreFlowGetConvergedReason(flow, &reason));
  PetscCall(CSWillmoreFlowGetInfo(flow, &info));
  PetscCall(PetscPrintf(comm, "cylinder: %s after %" PetscInt_FMT " iterations, EL %.3e\n", CSWillmoreFlowConvergedReasons[reason], info.it, (double)info.el_residual));
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(DMCreateGlobalVector(m->dmV3, &force));
  PetscCall(DMCreateGlobalVector(m->dmE1, &q));
  PetscCall(VecDuplicate(force, &Lf));
  PetscCall(CSWillmoreFlowGetConformalMultiplier(flow, q, force));
  PetscCall(CSGeometryLaplacianPositions(m, x, Lf, NULL)); /* grad Area = Lf (soliman2021 Sec. 2) */
  PetscCall(VecAXPY(Lf, 1.0, force));                      /* force + Lf, zeroed at the boundary below */
  PetscCall(VecGetLocalSize(Lf, &nv));
  PetscCall(VecGetArray(Lf, &a));
  {
    PetscInt rs, k = 0;
    PetscCall(VecGetOwnershipRange(Lf, &rs, NULL));
    for (PetscInt v = 0; v < m->nv; v++) /* owned vertices come first in the local numbering of dmV3 */
      if (m->vertOwned[v]) {
        if (m->vertBoundary[v])
          for (int c = 0; c < 3; c++) a[3 * k + c] = 0;
        k++;
      }
    PetscCheck(3 * k == nv, comm, PETSC_ERR_PLIB, "owned vertex count");
  }
  PetscCall(VecRestoreArray(Lf, &a));
  PetscCall(VecNorm(Lf, NORM_2, &d));
  PetscCall(VecNorm(force, NORM_2, &n));
  PetscCall(CSTestCheck(comm, (PetscBool)(reason == CS_WILLMORE_FLOW_CONVERGED_RTOL), "cylinder: converged (reason)", (PetscReal)reason, CS_WILLMORE_FLOW_CONVERGED_RTOL));
  PetscCall(CSTestCheck(comm, (PetscBool)(d <= 1e-6 && n > 1e-2), "cylinder: |force + Lf| over interior vertices (the solver tolerance rtol = 1e-6)", d, 1e-6));
  PetscCall(PetscPrintf(comm, "cylinder: |force| = %.6e, |force + Lf| / |force| = %.3e\n", (double)n, (double)(d / n)));
  PetscCall(VertexSums(m, q, &smax, &qmax));
  PetscCall(PetscPrintf(comm, "cylinder: max |sum_j q_ij| %.3e over all vertices (Eq. 6 is for interior vertices of C0's rows), max |q| %.3e\n", (double)smax, (double)qmax));
  PetscCall(VecDestroy(&force));
  PetscCall(VecDestroy(&Lf));
  PetscCall(VecDestroy(&q));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  PetscCall(CSInitializePackage());
  PetscCall(CheckSphere(PETSC_COMM_WORLD, CSWILLMOREFLOWCGD, "cgd_", 30));
  PetscCall(CheckSphere(PETSC_COMM_WORLD, CSWILLMOREFLOWALM, "alm_", 5)); /* -alm_alm_metric gauss_newton */
  PetscCall(CheckCylinder(PETSC_COMM_WORLD));
  return CSTestFinalize(PETSC_COMM_WORLD, PetscFinalize);
}
