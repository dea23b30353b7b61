/* bin/confsurf -task spin (crane2011: paint rho / nearest spin transformation / boundary edit) and
   -task spectrum (the smallest eigenvalues of Eq. 7 with rho = 0, Fig. 8). */
#include "cs_methods_spin.h"
#include "cs_output.h"

/* |lambda| per vertex (dmV1), for the viewer */
static PetscErrorCode LambdaAbs(CSSpin s, Vec lambda, Vec a)
{
  const PetscScalar *l;
  PetscScalar       *r;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(a, &n));
  PetscCall(VecGetArrayRead(lambda, &l));
  PetscCall(VecGetArray(a, &r));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal q[4];
    for (int c = 0; c < 4; c++) q[c] = PetscRealPart(l[4 * i + c]);
    r[i] = PetscSqrtReal(CSQuatNorm2(q));
  }
  PetscCall(VecRestoreArray(a, &r));
  PetscCall(VecRestoreArrayRead(lambda, &l));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTaskSpin(MPI_Comm comm)
{
  CSOutput      out;
  CSMesh        mesh;
  CSSpin        spin;
  CSRhoLocation loc;
  Vec           rho, xt, mu, Tt, lambda, xnew;
  const char   *bnames[] = {"none", "keep", "file", "target"};
  PetscFunctionBeginUser;
  PetscCall(CSOutputFromOptions(comm, &out));
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  PetscCall(CSSpinCreate(mesh, &spin));
  PetscCall(CSSpinSetFromOptions(spin));
  PetscCall(CSSpinRhoFromOptions(spin, mesh->x, &loc, &rho, &xt, &mu));
  PetscCall(CSSpinBoundaryFromOptions(spin, xt, &Tt));
  if (spin->boundary != CS_SPIN_BOUNDARY_NONE) PetscCall(CSSpinSetBoundaryTangents(spin, mesh->x, Tt));
  PetscCall(DMCreateGlobalVector(spin->dm, &lambda));
  PetscCall(CSSpinSolveEigen(spin, mesh->x, loc, rho, lambda));
  /* the global similarity: fit mu (Sec. 7.2) or the identity; with prescribed boundary tangents only a scale,
     since a rotation would turn the prescribed tangents */
  PetscCall(CSSpinNormalize(spin, lambda, mu, (PetscBool)(spin->boundary == CS_SPIN_BOUNDARY_NONE)));
  PetscCall(VecDuplicate(mesh->x, &xnew));
  PetscCall(CSSpinReconstruct(spin, mesh->x, lambda, xt ? xt : mesh->x, xnew));
  if (!xt) PetscCall(CSSpinRestoreArea(spin, mesh->x, xnew));
  PetscCall(PetscPrintf(comm, "spin: gamma=%.10g (%s problem, residual %.2e) eigensolver its=%" PetscInt_FMT " inner its=%" PetscInt_FMT "; poisson its=%" PetscInt_FMT "\n", (double)spin->gamma, spin->generalized ? "generalized Eq. 6" : "standard Eq. 7", (double)spin->residual, spin->eps_its, spin->inner_its, spin->poisson_its));
  PetscCall(PetscPrintf(comm, "spin: seconds setup=%.4f eigen=%.4f poisson=%.4f (cpu %.4f %.4f %.4f)\n", spin->t_setup, spin->t_eigen, spin->t_poisson, spin->c_setup, spin->c_eigen, spin->c_poisson));
  PetscCall(CSJSONAddReal(out.json, "eigenvalue", spin->gamma));
  PetscCall(CSJSONAddReal(out.json, "eigen_residual", spin->residual));
  PetscCall(CSJSONAddInt(out.json, "eps_its", spin->eps_its));
  PetscCall(CSJSONAddInt(out.json, "inner_its", spin->inner_its));
  PetscCall(CSJSONAddInt(out.json, "poisson_its", spin->poisson_its));
  PetscCall(CSJSONAddReal(out.json, "seconds_setup", (PetscReal)spin->t_setup));
  PetscCall(CSJSONAddReal(out.json, "seconds_eigen", (PetscReal)spin->t_eigen));
  PetscCall(CSJSONAddReal(out.json, "seconds_poisson", (PetscReal)spin->t_poisson));
  PetscCall(CSJSONAddReal(out.json, "cpu_seconds_setup", (PetscReal)spin->c_setup));
  PetscCall(CSJSONAddReal(out.json, "cpu_seconds_eigen", (PetscReal)spin->c_eigen));
  PetscCall(CSJSONAddReal(out.json, "cpu_seconds_poisson", (PetscReal)spin->c_poisson));
  PetscCall(CSJSONAddString(out.json, "problem", spin->generalized ? "generalized" : "standard"));
  PetscCall(CSJSONAddString(out.json, "dirac_type", spin->shell ? "shell" : "aij"));
  PetscCall(CSJSONAddString(out.json, "boundary", bnames[spin->boundary]));
  PetscCall(CSJSONAddString(out.json, "rho_location", loc == CS_RHO_NONE ? "none" : (loc == CS_RHO_VERTEX ? "vertex" : "face")));
  if (rho) {
    PetscReal rmin, rmax;
    PetscCall(VecMin(rho, NULL, &rmin));
    PetscCall(VecMax(rho, NULL, &rmax));
    PetscCall(CSJSONAddReal(out.json, "rho_min", rmin));
    PetscCall(CSJSONAddReal(out.json, "rho_max", rmax));
  }
  if (xt) {
    /* distance to the target, relative to the target's size (sqrt of its area) */
    Vec       d;
    PetscReal nd, area, vol;
    PetscCall(VecDuplicate(xnew, &d));
    PetscCall(VecWAXPY(d, -1, xt, xnew));
    PetscCall(VecNorm(d, NORM_INFINITY, &nd));
    PetscCall(CSGeometryAreaVolume(mesh, xt, &area, &vol));
    PetscCall(CSJSONAddReal(out.json, "target_distance_max", nd / PetscSqrtReal(area)));
    PetscCall(PetscPrintf(comm, "spin: max distance to -target_mesh %.3e (relative to sqrt(area))\n", (double)(nd / PetscSqrtReal(area))));
    PetscCall(VecDestroy(&d));
  }
  PetscCall(CSOutputAddMeshFacts(&out, mesh, xnew, mesh->x));
  if (out.has_viewer) {
    CSViewer v;
    Vec      la, q, la0;
    PetscCall(DMCreateGlobalVector(mesh->dmV1, &la));
    PetscCall(DMCreateGlobalVector(mesh->dmF1, &q));
    PetscCall(LambdaAbs(spin, lambda, la));
    PetscCall(CSGeometryQuasiConformal(mesh, mesh->x, xnew, q, NULL, NULL));
    PetscCall(CSViewerCreate(mesh, out.viewer_dir, &v));
    /* step 0: the input with rho; step 1: the result with rho, |lambda| and Q */
    PetscCall(VecDuplicate(la, &la0));
    PetscCall(VecSet(la0, 1));
    if (rho && loc == CS_RHO_VERTEX) PetscCall(CSViewerAddVertexField(v, "rho", rho));
    if (rho && loc == CS_RHO_FACE) PetscCall(CSViewerAddFaceField(v, "rho", rho));
    PetscCall(CSViewerAddVertexField(v, "lambda_abs", la0));
    PetscCall(CSViewerWriteStep(v, mesh->x, 0));
    if (rho && loc == CS_RHO_VERTEX) PetscCall(CSViewerAddVertexField(v, "rho", rho));
    if (rho && loc == CS_RHO_FACE) PetscCall(CSViewerAddFaceField(v, "rho", rho));
    PetscCall(CSViewerAddVertexField(v, "lambda_abs", la));
    PetscCall(CSViewerAddFaceField(v, "Q", q));
    PetscCall(CSViewerWriteStep(v, xnew, 1));
    PetscCall(CSViewerDestroy(&v));
    PetscCall(VecDestroy(&la));
    PetscCall(VecDestroy(&la0));
    PetscCall(VecDestroy(&q));
  }
  PetscCall(CSOutputFinish(&out, mesh, xnew));
  PetscCall(VecDestroy(&xnew));
  PetscCall(VecDestroy(&lambda));
  PetscCall(VecDestroy(&rho));
  PetscCall(VecDestroy(&xt));
  PetscCall(VecDestroy(&mu));
  PetscCall(VecDestroy(&Tt));
  PetscCall(CSSpinDestroy(&spin));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(CSOutputDestroy(&out));
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
  for (PetscInt i = 0; i < nev; i++) root[i] = PetscSqrtReal(PetscMax(eig[i], 0));
  PetscCall(PetscPrintf(comm, "spectrum: %" PetscInt_FMT " smallest eigenvalues of (AV)^*(AV) (Eq. 7, rho = 0), eps its %" PetscInt_FMT "; sqrt:\n", nev, spin->eps_its));
  for (PetscInt i = 0; i < nev; i++) PetscCall(PetscPrintf(comm, "%s%.6f", i % 8 ? " " : (i ? "\n  " : "  "), (double)root[i]));
  PetscCall(PetscPrintf(comm, "\n"));
  PetscCall(CSJSONAddRealArray(out.json, "eigenvalues", nev, eig));
  PetscCall(CSJSONAddRealArray(out.json, "eigenvalues_sqrt", nev, root));
  PetscCall(CSJSONAddInt(out.json, "eps_its", spin->eps_its));
  PetscCall(CSOutputAddMeshFacts(&out, mesh, mesh->x, NULL));
  PetscCall(CSOutputFinish(&out, mesh, mesh->x));
  PetscCall(PetscFree2(eig, root));
  PetscCall(CSSpinDestroy(&spin));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(CSOutputDestroy(&out));
  PetscFunctionReturn(0);
}
