/* The energies of the flow (-flow_energy), a PetscFunctionList of constructors: a new energy is one
   registration (CSWillmoreFlowEnergyRegister) of a function that creates it from the mesh and the input
   positions. The flow gives it the prefix "<flow prefix><name>_" and calls its SetFromOptions (the fairing
   energy's -flow_fairing_epsilon), and its metric op, if it has one, enters the step metric (willmore_setup.c). */
#include "willmore_impl.h"
#include "cs_util.h"

static PetscFunctionList CSWillmoreFlowEnergies           = NULL;
static PetscBool         CSWillmoreFlowEnergiesRegistered = PETSC_FALSE;

static PetscErrorCode CreateWillmore(CSMesh m, Vec x0, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateWillmore(m, e));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateArea(CSMesh m, Vec x0, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateArea(m, e));
  PetscFunctionReturn(0);
}

/* soliman2021 Eq. 21: 1/2 ||f - f0||^2 + eps W, eps = 1e-3 until its SetFromOptions reads -<prefix>epsilon */
static PetscErrorCode CreateFairing(CSMesh m, Vec x0, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateFairing(m, x0, 1e-3, e));
  PetscFunctionReturn(0);
}

static PetscErrorCode EnergyListDestroy(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&CSWillmoreFlowEnergies));
  CSWillmoreFlowEnergiesRegistered = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* The built-in energies first, whoever registers first (so that -help and the errors list them in this order). */
static PetscErrorCode EnergyRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (CSWillmoreFlowEnergiesRegistered) PetscFunctionReturn(0);
  CSWillmoreFlowEnergiesRegistered = PETSC_TRUE;
  PetscCall(PetscRegisterFinalize(EnergyListDestroy));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowEnergies, "willmore", CreateWillmore));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowEnergies, "area", CreateArea));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowEnergies, "fairing", CreateFairing));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowEnergyRegister(const char name[], PetscErrorCode (*create)(CSMesh, Vec, CSEnergy *))
{
  PetscFunctionBeginUser;
  PetscCall(EnergyRegisterAll());
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowEnergies, name, create));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowEnergyList(PetscFunctionList *list)
{
  PetscFunctionBeginUser;
  PetscCall(EnergyRegisterAll());
  *list = CSWillmoreFlowEnergies;
  PetscFunctionReturn(0);
}

/* The energy by its registered name (as -flow_energy; checked at SetUp, with the list in the error). */
PetscErrorCode CSWillmoreFlowSetEnergyType(CSWillmoreFlow F, const char name[])
{
  PetscFunctionBeginUser;
  PetscCheck(!F->setupcalled, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowSetEnergyType(%s): call it before CSWillmoreFlowSetUp", name);
  PetscCall(PetscStrncpy(F->energy_name, name, sizeof(F->energy_name)));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFCreateEnergy(CSWillmoreFlow F)
{
  PetscFunctionList list = NULL;
  char              names[256], prefix[128];
  PetscErrorCode (*create)(CSMesh, Vec, CSEnergy *);
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowEnergyList(&list));
  PetscCall(PetscFunctionListFind(list, F->energy_name, &create));
  if (!create) PetscCall(CSFunctionListJoin(list, "|", names, sizeof(names)));
  PetscCheck(create, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%senergy %s: unknown (%s)", F->hdr.prefix, F->energy_name, names);
  PetscCall((*create)(F->mesh, F->x0, &F->energy));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%s%s_", F->hdr.prefix, F->energy_name));
  PetscCall(CSEnergySetOptionsPrefix(F->energy, prefix));
  PetscCall(CSEnergySetFromOptions(F->energy));
  PetscFunctionReturn(0);
}
