/* The PetscLogEvents of confsurf (-log_view). Declared here, in the lowest layer, so that every layer can log
   them; registered once by CSInitializePackage (include/cs_package.h, docs/solvers.md "Package initialiser"). */
#ifndef CS_LOG_H
#define CS_LOG_H
#include <petsclog.h>

/* mesh, geometry, energies */
PETSC_EXTERN PetscLogEvent CS_EVENT_MeshRead, CS_EVENT_MeshDistribute, CS_EVENT_Geometry, CS_EVENT_Energy, CS_EVENT_Gradient, CS_EVENT_Assemble, CS_EVENT_ViewerWrite;
/* linalg: CHOLMOD's complex form (cholmod_factor.c), the quaternion Cholesky, the cssubchol PC */
PETSC_EXTERN PetscLogEvent CS_EVENT_CholmodSym, CS_EVENT_CholmodNum, CS_EVENT_CholmodSolve;
PETSC_EXTERN PetscLogEvent CS_EVENT_QuatCholSym, CS_EVENT_QuatCholNum, CS_EVENT_QuatCholSolve;
PETSC_EXTERN PetscLogEvent CS_EVENT_SubCholSym, CS_EVENT_SubCholNum, CS_EVENT_SubCholDense, CS_EVENT_SubCholSolve;
/* methods: the spin transformation's eigenproblem and Poisson problem */
PETSC_EXTERN PetscLogEvent CS_EVENT_SpinEigen, CS_EVENT_SpinPoisson;
/* methods: the curve flow's Poisson matrix and factorisation (once), its per-step Poisson solves */
PETSC_EXTERN PetscLogEvent CS_EVENT_CurvePoissonSetUp, CS_EVENT_CurvePoisson;
/* methods: one step and the whole solve of each flow (CSFlowLoop logs them for the flows on it; the Willmore and
   Bobenko-Schroeder flows in their own loops); nested: a Solve event holds its Step events */
PETSC_EXTERN PetscLogEvent CS_EVENT_WillmoreStep, CS_EVENT_WillmoreSolve, CS_EVENT_ConformalStep, CS_EVENT_ConformalSolve;
PETSC_EXTERN PetscLogEvent CS_EVENT_CurveStep, CS_EVENT_CurveSolve, CS_EVENT_BSStep, CS_EVENT_BSSolve;
/* operators: the harmonic 1-form basis (harmonic_basis.c): set-up / update */
PETSC_EXTERN PetscLogEvent CS_EVENT_HarmonicBasis;
#endif
