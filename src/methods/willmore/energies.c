/* The energies of the flow (-flow_energy), a PetscFunctionList of constructors: a new energy is one
   registration (CSWillmoreFlowEnergyRegister) of a function that creates it from the mesh, the input
   positions and the fairing weight. */
#include "willmore_impl.h"

static PetscFunctionList CSWillmoreFlowEnergies = NULL;

static PetscErrorCode CreateWillmore(CSMesh m, Vec x0, PetscReal eps, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateWillmore(m, e));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateArea(CSMesh m, Vec x0, PetscReal eps, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateArea(m, e));
  PetscFunctionReturn(0);
}

/* soliman2021 Eq. 21: 1/2 ||f - f0||^2 + eps W */
static PetscErrorCode CreateFairing(CSMesh m, Vec x0, PetscReal eps, CSEnergy *e)
{
  PetscFunctionBeginUser;
  PetscCall(CSEnergyCreateFairing(m, x0, eps, e));
  PetscFunctionReturn(0);
}

static PetscErrorCode EnergyListDestroy(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&CSWillmoreFlowEnergies));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowEnergyRegister(const char name[], PetscErrorCode (*create)(CSMesh, Vec, PetscReal, CSEnergy *))
{
  PetscFunctionBeginUser;
  if (!CSWillmoreFlowEnergies) PetscCall(PetscRegisterFinalize(EnergyListDestroy));
  PetscCall(PetscFunctionListAdd(&CSWillmoreFlowEnergies, name, create));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowEnergyList(PetscFunctionList *list)
{
  PetscFunctionBeginUser;
  if (!CSWillmoreFlowEnergies) {
    PetscCall(CSWillmoreFlowEnergyRegister("willmore", CreateWillmore));
    PetscCall(CSWillmoreFlowEnergyRegister("area", CreateArea));
    PetscCall(CSWillmoreFlowEnergyRegister("fairing", CreateFairing));
  }
  *list = CSWillmoreFlowEnergies;
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFCreateEnergy(CSWillmoreFlow F)
{
  PetscFunctionList list;
  PetscErrorCode (*create)(CSMesh, Vec, PetscReal, CSEnergy *);
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowEnergyList(&list));
  PetscCall(PetscFunctionListFind(list, F->energy_name, &create));
  PetscCheck(create, F->comm, PETSC_ERR_ARG_OUTOFRANGE, "-%senergy %s: unknown (willmore|area|fairing)", F->prefix, F->energy_name);
  PetscCall((*create)(F->mesh, F->x0, F->eps, &F->energy));
  PetscFunctionReturn(0);
}
