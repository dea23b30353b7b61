/* Storage of the event ids of include/cs_log.h; CSInitializePackage registers them. */
#include "cs_log.h"

PetscLogEvent CS_EVENT_MeshRead, CS_EVENT_MeshDistribute, CS_EVENT_Geometry, CS_EVENT_Energy, CS_EVENT_Gradient, CS_EVENT_Assemble, CS_EVENT_ViewerWrite;
PetscLogEvent CS_EVENT_CholmodSym, CS_EVENT_CholmodNum, CS_EVENT_CholmodSolve;
PetscLogEvent CS_EVENT_QuatCholSym, CS_EVENT_QuatCholNum, CS_EVENT_QuatCholSolve;
PetscLogEvent CS_EVENT_SubCholSym, CS_EVENT_SubCholNum, CS_EVENT_SubCholDense, CS_EVENT_SubCholSolve;
PetscLogEvent CS_EVENT_SpinEigen, CS_EVENT_SpinPoisson;
PetscLogEvent CS_EVENT_CurvePoissonSetUp, CS_EVENT_CurvePoisson;
PetscLogEvent CS_EVENT_WillmoreStep, CS_EVENT_WillmoreSolve, CS_EVENT_ConformalStep, CS_EVENT_ConformalSolve;
PetscLogEvent CS_EVENT_CurveStep, CS_EVENT_CurveSolve, CS_EVENT_BSStep, CS_EVENT_BSSolve;
PetscLogEvent CS_EVENT_HarmonicBasis;
