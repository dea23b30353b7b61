/* The package initialiser (include/cs_package.h). It lives in the methods layer, the lowest layer that sees every
   object it registers (the csh2 PC of operators/, the PC and solver types of linalg/, the spin method's csspinlap PC); the event ids live in
   util/ (include/cs_log.h) so that the lower layers can log without calling up. docs/solvers.md. */
#include <petscksp.h>
#include "cs_package.h"
#include "cs_linalg.h"
#include "cs_operators_conformal.h"
#include "cs_methods_spin.h"

static PetscBool CSPackageInitialized = PETSC_FALSE;

PetscErrorCode CSFinalizePackage(void)
{
  PetscFunctionBeginUser;
  CSPackageInitialized = PETSC_FALSE;
  PetscFunctionReturn(0);
}

static PetscErrorCode RegisterEvents(void)
{
  PetscClassId mesh, chol, quat, spin, curve;
  PetscFunctionBeginUser;
  PetscCall(PetscClassIdRegister("confsurf", &mesh));
  PetscCall(PetscLogEventRegister("CSMeshRead", mesh, &CS_EVENT_MeshRead));
  PetscCall(PetscLogEventRegister("CSMeshDistribute", mesh, &CS_EVENT_MeshDistribute));
  PetscCall(PetscLogEventRegister("CSGeometry", mesh, &CS_EVENT_Geometry));
  PetscCall(PetscLogEventRegister("CSEnergy", mesh, &CS_EVENT_Energy));
  PetscCall(PetscLogEventRegister("CSGradient", mesh, &CS_EVENT_Gradient));
  PetscCall(PetscLogEventRegister("CSAssemble", mesh, &CS_EVENT_Assemble));
  PetscCall(PetscClassIdRegister("confsurf CHOLMOD", &chol));
  PetscCall(PetscLogEventRegister("CSCholmodSym", chol, &CS_EVENT_CholmodSym));
  PetscCall(PetscLogEventRegister("CSCholmodNum", chol, &CS_EVENT_CholmodNum));
  PetscCall(PetscLogEventRegister("CSCholmodSolve", chol, &CS_EVENT_CholmodSolve));
  PetscCall(PetscClassIdRegister("confsurf quaternion Cholesky", &quat));
  PetscCall(PetscLogEventRegister("CSQuatCholSym", quat, &CS_EVENT_QuatCholSym));
  PetscCall(PetscLogEventRegister("CSQuatCholNum", quat, &CS_EVENT_QuatCholNum));
  PetscCall(PetscLogEventRegister("CSQuatCholSolve", quat, &CS_EVENT_QuatCholSolve));
  PetscCall(PetscLogEventRegister("CSSubCholSym", PC_CLASSID, &CS_EVENT_SubCholSym));
  PetscCall(PetscLogEventRegister("CSSubCholNum", PC_CLASSID, &CS_EVENT_SubCholNum));
  PetscCall(PetscLogEventRegister("CSSubCholDense", PC_CLASSID, &CS_EVENT_SubCholDense));
  PetscCall(PetscLogEventRegister("CSSubCholSolve", PC_CLASSID, &CS_EVENT_SubCholSolve));
  PetscCall(PetscClassIdRegister("confsurf spin", &spin));
  PetscCall(PetscLogEventRegister("CSSpinEigen", spin, &CS_EVENT_SpinEigen));
  PetscCall(PetscLogEventRegister("CSSpinPoisson", spin, &CS_EVENT_SpinPoisson));
  PetscCall(PetscClassIdRegister("confsurf curve flow", &curve));
  PetscCall(PetscLogEventRegister("CSCurvePoissonSet", curve, &CS_EVENT_CurvePoissonSetUp));
  PetscCall(PetscLogEventRegister("CSCurvePoisson", curve, &CS_EVENT_CurvePoisson));
  PetscFunctionReturn(0);
}

PetscErrorCode CSInitializePackage(void)
{
  PetscFunctionBeginUser;
  if (CSPackageInitialized) PetscFunctionReturn(0);
  CSPackageInitialized = PETSC_TRUE;
  /* PETSc's own solver types first: registering ours into an empty list would keep MatInitializePackage from
     registering PETSc's (cholmod, mumps, ...) later */
  PetscCall(MatInitializePackage());
  PetscCall(PCInitializePackage());
  PetscCall(RegisterEvents());
  PetscCall(PCRegister(PCCSSUBCHOL, PCCreate_CSSubChol));
  PetscCall(CSH2PCRegister());
  PetscCall(PCRegister(PCCSSPINLAP, PCCreate_CSSpinLap));
  PetscCall(MatSolverTypeRegister(MATSOLVERCSQUAT, MATSEQAIJ, MAT_FACTOR_CHOLESKY, MatGetFactor_SeqAIJ_CSQuat));
  PetscCall(MatSolverTypeRegister(MATSOLVERCSCHOLMOD, MATSEQAIJ, MAT_FACTOR_CHOLESKY, MatGetFactor_SeqAIJ_CSCholmod));
  PetscCall(PetscRegisterFinalize(CSFinalizePackage));
  PetscFunctionReturn(0);
}
