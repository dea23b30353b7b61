/* -task spectrum (crane2011 Fig. 8): the smallest eigenvalues of Eq. 7 with rho = 0, through the CSSpin
   object on the mesh the driver reads from the options. */
#include "cs_driver.h"
#include "cs_methods_spin.h"

static PetscErrorCode SpectrumReport(MPI_Comm comm, CSSpin spin, PetscInt nev, const PetscReal eig[], PetscReal root[], CSOutput *out)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < nev; i++) root[i] = PetscSqrtReal(PetscMax(eig[i], 0));
  PetscCall(PetscPrintf(comm, "spectrum: %" PetscInt_FMT " smallest eigenvalues of (AV)^*(AV) (Eq. 7, rho = 0), eps its %" PetscInt_FMT "; sqrt:\n", nev, spin->eps_its));
  for (PetscInt i = 0; i < nev; i++) PetscCall(PetscPrintf(comm, "%s%.6f", i % 8 ? " " : (i ? "\n  " : "  "), (double)root[i]));
  PetscCall(PetscPrintf(comm, "\n"));
  PetscCall(CSJSONAddRealArray(out->json, "eigenvalues", nev, eig));
  PetscCall(CSJSONAddRealArray(out->json, "eigenvalues_sqrt", nev, root));
  PetscCall(CSJSONAddInt(out->json, "eps_its", spin->eps_its));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTaskSpectrum(MPI_Comm comm)
{
  CSOutput   out;
  CSMesh     mesh;
  CSSpin     spin;
  PetscInt   nev = 20, nconv;
  PetscReal *eig, *root;
  PetscFunctionBeginUser;
  PetscCall(CSOutputFromOptions(comm, &out));
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  PetscOptionsBegin(comm, NULL, "Dirac spectrum (crane2011 Fig. 8)", NULL);
  PetscCall(PetscOptionsInt("-spectrum_nev", "Number of smallest eigenvalues of Eq. 7 with rho = 0", NULL, nev, &nev, NULL));
  PetscOptionsEnd();
  PetscCheck(nev >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-spectrum_nev %" PetscInt_FMT ": need at least 1", nev);
  PetscCheck(nev < 4 * mesh->Nv, comm, PETSC_ERR_ARG_OUTOFRANGE, "-spectrum_nev %" PetscInt_FMT ": the problem has only %" PetscInt_FMT " eigenvalues", nev, 4 * mesh->Nv);
  PetscCall(CSSpinCreate(mesh, &spin));
  PetscCall(CSSpinSetFromOptions(spin));
  PetscCall(PetscMalloc2(nev, &eig, nev, &root));
  PetscCall(CSSpinSpectrum(spin, mesh->x, CS_RHO_NONE, NULL, nev, eig, &nconv));
  PetscCall(SpectrumReport(comm, spin, nev, eig, root, &out));
  PetscCall(CSOutputAddMeshFacts(&out, mesh, mesh->x, NULL));
  PetscCall(CSOutputFinish(&out, mesh, mesh->x));
  PetscCall(PetscFree2(eig, root));
  PetscCall(CSSpinDestroy(&spin));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(CSOutputDestroy(&out));
  PetscFunctionReturn(0);
}
