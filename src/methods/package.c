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

/* The events of each class, in the order they are registered (the ids and -log_view follow it). */
typedef struct {
  const char    *name;
  PetscLogEvent *event;
} EventName;

static const EventName mesh_events[] = {
  {"CSMeshRead",       &CS_EVENT_MeshRead      },
  {"CSMeshDistribute", &CS_EVENT_MeshDistribute},
  {"CSGeometry",       &CS_EVENT_Geometry      },
  {"CSEnergy",         &CS_EVENT_Energy        },
  {"CSGradient",       &CS_EVENT_Gradient      },
  {"CSAssemble",       &CS_EVENT_Assemble      },
  {"CSViewerWrite",    &CS_EVENT_ViewerWrite   },
  {"CSHarmonicBasis",  &CS_EVENT_HarmonicBasis },
};
static const EventName cholmod_events[] = {
  {"CSCholmodSym",   &CS_EVENT_CholmodSym  },
  {"CSCholmodNum",   &CS_EVENT_CholmodNum  },
  {"CSCholmodSolve", &CS_EVENT_CholmodSolve},
};
static const EventName quat_events[] = {
  {"CSQuatCholSym",   &CS_EVENT_QuatCholSym  },
  {"CSQuatCholNum",   &CS_EVENT_QuatCholNum  },
  {"CSQuatCholSolve", &CS_EVENT_QuatCholSolve},
};
static const EventName subchol_events[] = {
  {"CSSubCholSym",   &CS_EVENT_SubCholSym  },
  {"CSSubCholNum",   &CS_EVENT_SubCholNum  },
  {"CSSubCholDense", &CS_EVENT_SubCholDense},
  {"CSSubCholSolve", &CS_EVENT_SubCholSolve},
};
static const EventName spin_events[] = {
  {"CSSpinEigen",   &CS_EVENT_SpinEigen  },
  {"CSSpinPoisson", &CS_EVENT_SpinPoisson},
};
static const EventName curve_events[] = {
  {"CSCurvePoissonSet", &CS_EVENT_CurvePoissonSetUp},
  {"CSCurvePoisson",    &CS_EVENT_CurvePoisson     },
};
static const EventName flow_events[] = {
  {"CSWillmoreStep",   &CS_EVENT_WillmoreStep  },
  {"CSWillmoreSolve",  &CS_EVENT_WillmoreSolve },
  {"CSConformalStep",  &CS_EVENT_ConformalStep },
  {"CSConformalSolve", &CS_EVENT_ConformalSolve},
  {"CSCurveStep",      &CS_EVENT_CurveStep     },
  {"CSCurveSolve",     &CS_EVENT_CurveSolve    },
  {"CSBSStep",         &CS_EVENT_BSStep        },
  {"CSBSSolve",        &CS_EVENT_BSSolve       },
};

/* Registers the class (unless it is an existing one: name NULL) and its n events. */
static PetscErrorCode RegisterClassEvents(const char name[], PetscClassId classid, size_t n, const EventName events[])
{
  PetscFunctionBeginUser;
  if (name) PetscCall(PetscClassIdRegister(name, &classid));
  for (size_t i = 0; i < n; i++) PetscCall(PetscLogEventRegister(events[i].name, classid, events[i].event));
  PetscFunctionReturn(0);
}

static PetscErrorCode RegisterEvents(void)
{
  PetscFunctionBeginUser;
  PetscCall(RegisterClassEvents("confsurf", 0, PETSC_STATIC_ARRAY_LENGTH(mesh_events), mesh_events));
  PetscCall(RegisterClassEvents("confsurf CHOLMOD", 0, PETSC_STATIC_ARRAY_LENGTH(cholmod_events), cholmod_events));
  PetscCall(RegisterClassEvents("confsurf quaternion Cholesky", 0, PETSC_STATIC_ARRAY_LENGTH(quat_events), quat_events));
  PetscCall(RegisterClassEvents(NULL, PC_CLASSID, PETSC_STATIC_ARRAY_LENGTH(subchol_events), subchol_events));
  PetscCall(RegisterClassEvents("confsurf spin", 0, PETSC_STATIC_ARRAY_LENGTH(spin_events), spin_events));
  PetscCall(RegisterClassEvents("confsurf curve flow", 0, PETSC_STATIC_ARRAY_LENGTH(curve_events), curve_events));
  PetscCall(RegisterClassEvents("confsurf flow", 0, PETSC_STATIC_ARRAY_LENGTH(flow_events), flow_events));
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
