/* -task spectrum (crane2011 Fig. 8): the smallest eigenvalues of Eq. 7 with rho = 0 (squared, the default), or
   with -spectrum_signed the signed eigenvalues of Eq. 6 (Sec. 6.2) and with -spectrum_reconstruct k[,k,...]
   the Dirac spheres of those eigenvectors (Fig. 9, 11), through the CSSpin object on the mesh the driver reads
   from the options. */
#include "cs_driver.h"
#include "cs_geometry.h"
#include "cs_methods_spin.h"
#include "cs_util.h"

static PetscErrorCode SpectrumReport(MPI_Comm comm, CSSpin spin, PetscInt nev, const PetscReal eig[], PetscReal root[], CSOutput *out)
{
  PetscInt eps_its;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetIterationNumbers(spin, &eps_its, NULL, NULL));
  for (PetscInt i = 0; i < nev; i++) root[i] = PetscSqrtReal(PetscMax(eig[i], 0));
  PetscCall(PetscPrintf(comm, "spectrum: %" PetscInt_FMT " smallest eigenvalues of (AV)^*(AV) (Eq. 7, rho = 0), eps its %" PetscInt_FMT "; sqrt:\n", nev, eps_its));
  for (PetscInt i = 0; i < nev; i++) PetscCall(PetscPrintf(comm, "%s%.6f", i % 8 ? " " : (i ? "\n  " : "  "), (double)root[i]));
  PetscCall(PetscPrintf(comm, "\n"));
  PetscCall(CSJSONAddRealArray(out->json, "eigenvalues", nev, eig));
  PetscCall(CSJSONAddRealArray(out->json, "eigenvalues_sqrt", nev, root));
  PetscCall(CSJSONAddInt(out->json, "eps_its", eps_its));
  PetscFunctionReturn(0);
}

static int CompareReal(const void *a, const void *b)
{
  PetscReal x = *(const PetscReal *)a, y = *(const PetscReal *)b;
  return x < y ? -1 : (x > y ? 1 : 0);
}

/* eig[] by |gamma| (as computed); the summary's eigenvalues ascending */
static PetscErrorCode SignedReport(MPI_Comm comm, CSSpin spin, PetscInt nev, const PetscReal eig[], PetscInt nker, CSOutput *out)
{
  PetscReal *asc;
  PetscInt   eps_its;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetIterationNumbers(spin, &eps_its, NULL, NULL));
  PetscCall(PetscMalloc1(nev, &asc));
  PetscCall(PetscArraycpy(asc, eig, nev));
  qsort(asc, (size_t)nev, sizeof(PetscReal), CompareReal);
  PetscCall(PetscPrintf(comm, "spectrum: %" PetscInt_FMT " eigenvalues of smallest |gamma| of A^*A lam = gamma B^*A lam (Eq. 6, rho = 0; kernel dimension %" PetscInt_FMT "), eps its %" PetscInt_FMT ":\n", nev, nker, eps_its));
  for (PetscInt i = 0; i < nev; i++) PetscCall(PetscPrintf(comm, "%s%+.5f", i % 8 ? " " : (i ? "\n  " : "  "), (double)eig[i]));
  PetscCall(PetscPrintf(comm, "\n"));
  PetscCall(CSJSONAddRealArray(out->json, "eigenvalues", nev, asc));
  PetscCall(CSJSONAddRealArray(out->json, "eigenvalues_by_magnitude", nev, eig));
  PetscCall(CSJSONAddInt(out->json, "kernel_dimension", nker));
  PetscCall(CSJSONAddInt(out->json, "eps_its", eps_its));
  PetscCall(PetscFree(asc));
  PetscFunctionReturn(0);
}

/* the Dirac sphere of eigenvector k[i] written to PREFIX_k.obj, with its q against the input */
static PetscErrorCode Reconstruct(CSSpin spin, CSMesh mesh, PetscInt nk, const PetscInt k[], Vec vecs[], PetscInt nker, const char prefix[], CSOutput *out)
{
  Vec        xnew;
  PetscReal *q;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(mesh->x, &xnew));
  PetscCall(PetscMalloc1(2 * nk, &q));
  for (PetscInt i = 0; i < nk; i++) {
    char path[PETSC_MAX_PATH_LEN];
    PetscCall(CSSpinDiracSphere(spin, mesh->x, vecs[k[i]], (PetscBool)(k[i] < nker), xnew));
    PetscCall(CSGeometryQuasiConformal(mesh, mesh->x, xnew, NULL, &q[i], &q[nk + i]));
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s_%" PetscInt_FMT ".obj", prefix, k[i]));
    PetscCall(CSMeshWrite(mesh, xnew, path));
    PetscCall(PetscPrintf(mesh->comm, "spectrum: Dirac sphere of eigenvector %" PetscInt_FMT ": %s, q_mean %.9f q_max %.9f against the input\n", k[i], path, (double)q[i], (double)q[nk + i]));
  }
  PetscCall(CSJSONAddRealArray(out->json, "reconstruct_q_mean", nk, q));
  PetscCall(CSJSONAddRealArray(out->json, "reconstruct_q_max", nk, q + nk));
  PetscCall(PetscFree(q));
  PetscCall(VecDestroy(&xnew));
  PetscFunctionReturn(0);
}

static PetscErrorCode Signed(CSSpin spin, CSMesh mesh, PetscInt nev, PetscInt nk, const PetscInt k[], const char prefix[], CSOutput *out)
{
  PetscReal *eig;
  Vec       *vecs;
  PetscInt   nvec = 0, nker;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < nk; i++) {
    PetscCheck(k[i] >= 0 && k[i] < nev, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-spectrum_reconstruct %" PetscInt_FMT ": eigenvectors 0..%" PetscInt_FMT " are computed (-spectrum_nev %" PetscInt_FMT ", numbered by |eigenvalue|, 0 = ground state)", k[i], nev - 1, nev);
    nvec = PetscMax(nvec, k[i] + 1);
  }
  PetscCall(PetscMalloc2(nev, &eig, nvec, &vecs));
  PetscCall(CSSpinSpectrumSigned(spin, mesh->x, nev, eig, nvec, vecs, &nker));
  PetscCall(SignedReport(mesh->comm, spin, nev, eig, nker, out));
  if (nk) PetscCall(Reconstruct(spin, mesh, nk, k, vecs, nker, prefix, out));
  for (PetscInt i = 0; i < nvec; i++) PetscCall(VecDestroy(&vecs[i]));
  PetscCall(PetscFree2(eig, vecs));
  PetscFunctionReturn(0);
}

/* The task's options against the mesh: -spectrum_nev in [1, 4V - 1], -spectrum_reconstruct with -spectrum_signed, the
   signed spectrum on a closed surface */
static PetscErrorCode CheckOptions(MPI_Comm comm, CSMesh mesh, PetscInt nev, PetscInt nk, PetscBool sgn)
{
  PetscFunctionBeginUser;
  PetscCheck(nev >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-spectrum_nev %" PetscInt_FMT ": need at least 1", nev);
  PetscCheck(nev < 4 * mesh->Nv, comm, PETSC_ERR_ARG_OUTOFRANGE, "-spectrum_nev %" PetscInt_FMT ": at most %" PetscInt_FMT " (the problem has %" PetscInt_FMT " eigenvalues and the eigensolver needs fewer)", nev, 4 * mesh->Nv - 1, 4 * mesh->Nv);
  PetscCheck(!nk || sgn, comm, PETSC_ERR_ARG_INCOMP, "-spectrum_reconstruct needs -spectrum_signed (eigenvectors of Eq. 6)");
  PetscCheck(!sgn || mesh->topo.boundary_loops == 0, comm, PETSC_ERR_ARG_WRONG, "-spectrum_signed: mesh %s has a boundary; the signed spectrum needs a closed surface", mesh->name);
  PetscFunctionReturn(0);
}

PetscErrorCode CSTaskSpectrum(MPI_Comm comm)
{
  CSOutput   out;
  CSMesh     mesh;
  PetscErrorCode ierr;
  CSSpin     spin = NULL;
  PetscInt   nev = 20, nconv, k[64], nk = 64;
  PetscReal *eig, *root;
  PetscBool  sgn = PETSC_FALSE, has_k;
  char       prefix[PETSC_MAX_PATH_LEN] = "dirac_sphere";
  PetscFunctionBeginUser;
  PetscCall(CSOutputFromOptions(comm, &out));
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  PetscOptionsBegin(comm, NULL, "Dirac spectrum (crane2011 Fig. 8)", NULL);
  PetscCall(CSOptionsInt("-spectrum_nev", "Number of smallest eigenvalues (of Eq. 7, or of |gamma| in Eq. 6 with -spectrum_signed)", NULL, nev, &nev, NULL));
  PetscCall(PetscOptionsBool("-spectrum_signed", "Signed eigenvalues of the generalised problem Eq. 6 (Sec. 6.2) instead of the squared Eq. 7", NULL, sgn, &sgn, NULL));
  PetscCall(PetscOptionsIntArray("-spectrum_reconstruct", "With -spectrum_signed: Dirac spheres (Fig. 9, 11) of these eigenvectors (0 = ground state, numbered by |eigenvalue|)", NULL, k, &nk, &has_k));
  PetscCall(CSOptionsString("-spectrum_reconstruct_prefix", "Dirac sphere k is written to PREFIX_k.obj", NULL, prefix, prefix, sizeof(prefix), NULL));
  PetscOptionsEnd();
  if (!has_k) nk = 0;
  ierr = CheckOptions(comm, mesh, nev, nk, sgn);
  if (!ierr) ierr = CSSpinCreate(mesh, &spin);
  if (!ierr) ierr = CSSpinSetFromOptions(spin);
  if (!ierr) ierr = CSOptionsCheckUnused(comm, "-task spectrum"); /* before the eigensolve; its EPS reads -spin_eps_* there */
  if (ierr) { /* refused: nothing written, and everything freed before the error returns (no leak under ASan) */
    PetscCall(CSSpinDestroy(&spin));
    PetscCall(CSMeshDestroy(&mesh));
    PetscCall(CSOutputDestroy(&out));
  }
  PetscCall(ierr);
  if (sgn) PetscCall(Signed(spin, mesh, nev, nk, k, prefix, &out));
  else {
    PetscCall(PetscMalloc2(nev, &eig, nev, &root));
    PetscCall(CSSpinSpectrum(spin, mesh->x, CS_RHO_NONE, NULL, nev, eig, &nconv));
    PetscCall(SpectrumReport(comm, spin, nev, eig, root, &out));
    PetscCall(PetscFree2(eig, root));
  }
  PetscCall(CSOutputAddMeshFacts(&out, mesh, mesh->x, NULL));
  PetscCall(CSOutputFinish(&out, mesh, mesh->x));
  PetscCall(CSSpinDestroy(&spin));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(CSOutputDestroy(&out));
  PetscFunctionReturn(0);
}
