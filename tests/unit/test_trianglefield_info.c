/* The triangle field's own state through its kind-specific getter (issue 37: kind state out of the public
   CSWillmoreFlowInfo; src/methods/willmore/impls/trianglefield/trianglefield.c), serial and under mpirun, on a
   bumped level-1 icosphere:
   - another kind (cgd): CSWillmoreFlowTriangleFieldGetInfo says so (is = false, every field -1, so the state is an
     immersion -o may write), and without the flag it is an error, as PETSc's PetscUseMethod getters;
   - -flow_type trianglefield, before the first evaluation: integrability_violation and pinch_edges -1;
   - after 2 iterations from omega_0 = df: the integrability violation is the flow's constraint violation (no App. B
     rows: glob = integ, trianglefield_eval.c), no pinch edges (the lift of df, App. C.1), E_tau >= 0, and
     -flow_immersion_tol read by the kind's options (1e-5 given here against the default 1e-6).
   Prints a line per check; exit status = number of failures. */
#include "cs_methods_willmore.h"
#include "cs_package.h"
#include "cs_util.h"
#include "cs_test.h"

static PetscErrorCode CheckOtherKind(MPI_Comm comm, CSMesh m)
{
  CSWillmoreFlow                  flow;
  CSWillmoreFlowTriangleFieldInfo tf;
  PetscBool                       is = PETSC_TRUE;
  PetscErrorCode                  ierr;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetType(flow, CSWILLMOREFLOWCGD));
  PetscCall(CSWillmoreFlowTriangleFieldGetInfo(flow, &tf, &is));
  PetscCall(CSTestCheck(comm, (PetscBool)!is, "cgd: not a triangle field (is)", (PetscReal)is, 0));
  PetscCall(CSTestCheck(comm, (PetscBool)(tf.integrability_violation == -1 && tf.pinch_edges == -1 && tf.spin_energy == -1 && tf.immersion_tol == -1), "cgd: every field -1", tf.integrability_violation, -1));
  PetscCall(CSTestCheck(comm, CSWillmoreFlowTriangleFieldInfoIsImmersion(&tf), "cgd: its state is an immersion (-o writes it)", 0, 0));
  CSCaptureError(ierr, CSWillmoreFlowTriangleFieldGetInfo(flow, &tf, NULL));
  PetscCall(CSTestCheck(comm, (PetscBool)(ierr == PETSC_ERR_ARG_WRONG), "cgd: the getter without the flag is an error (PETSC_ERR_ARG_WRONG)", (PetscReal)ierr, PETSC_ERR_ARG_WRONG));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckTriangleField(MPI_Comm comm, CSMesh m)
{
  CSWillmoreFlow                  flow;
  CSWillmoreFlowTriangleFieldInfo tf;
  CSWillmoreFlowInfo              info;
  PetscBool                       is = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowCreate(m, &flow));
  PetscCall(CSWillmoreFlowSetType(flow, CSWILLMOREFLOWTRIANGLEFIELD));
  PetscCall(CSWillmoreFlowSetTolerances(flow, PETSC_DEFAULT, PETSC_DEFAULT, 2));
  PetscCall(CSWillmoreFlowSetFromOptions(flow));
  PetscCall(CSWillmoreFlowSetUp(flow));
  PetscCall(CSWillmoreFlowTriangleFieldGetInfo(flow, &tf, NULL)); /* the kind: no flag needed */
  PetscCall(CSTestCheck(comm, (PetscBool)(tf.integrability_violation == -1 && tf.pinch_edges == -1), "trianglefield before the first evaluation: violation and pinch edges -1", tf.integrability_violation, -1));
  PetscCall(CSWillmoreFlowSolve(flow));
  PetscCall(CSWillmoreFlowGetInfo(flow, &info));
  PetscCall(CSWillmoreFlowTriangleFieldGetInfo(flow, &tf, &is));
  PetscCall(CSTestCheck(comm, is, "trianglefield: is", (PetscReal)is, 1));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.it == 2), "trianglefield: 2 iterations", (PetscReal)info.it, 2));
  PetscCall(CSTestCheck(comm, (PetscBool)(tf.integrability_violation >= 0 && tf.integrability_violation == info.constraint_violation), "trianglefield: integrability violation = the constraint violation (no App. B rows)", PetscAbsReal(tf.integrability_violation - info.constraint_violation), 0));
  PetscCall(CSTestCheck(comm, (PetscBool)(tf.pinch_edges == 0), "trianglefield from df: no pinch edges", (PetscReal)tf.pinch_edges, 0));
  PetscCall(CSTestCheck(comm, (PetscBool)(tf.spin_energy >= 0), "trianglefield: E_tau >= 0", tf.spin_energy, 0));
  PetscCall(CSTestCheck(comm, (PetscBool)(tf.immersion_tol == 1e-5), "trianglefield: -flow_immersion_tol 1e-5 read by the kind", tf.immersion_tol, 1e-5));
  PetscCall(CSTestCheck(comm, (PetscBool)(CSWillmoreFlowTriangleFieldInfoIsImmersion(&tf) == (tf.integrability_violation <= 1e-5)), "trianglefield: immersion iff violation <= tol", tf.integrability_violation, 1e-5));
  PetscCall(CSWillmoreFlowDestroy(&flow));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm       comm;
  CSMesh         m;
  CSTestMeshSpec s = {CS_TEST_ICOSPHERE, 1, 0, 1, 0};
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(CSInitializePackage());
  PetscCall(PetscOptionsInsertString(NULL, "-flow_immersion_tol 1e-5"));
  PetscCall(CSTestMesh(comm, s, 0.05, 3, &m));
  PetscCall(CheckOtherKind(comm, m));
  PetscCall(CheckTriangleField(comm, m));
  PetscCall(CSMeshDestroy(&m));
  return CSTestFinalize(comm, PetscFinalize);
}
