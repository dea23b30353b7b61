/* -task spin (crane2011): paint rho / nearest spin transformation / boundary edit. The driver reads the mesh
   and the output from the options and hands the mesh to the CSSpin object. */
#include "cs_driver.h"
#include "cs_geometry.h"
#include "cs_methods_spin.h"
#include "cs_linalg.h"

/* Inputs and results of one spin transformation. */
typedef struct {
  CSRhoLocation loc;
  Vec           rho, xt, mu, Tt, lambda, xnew;
} SpinRun;

/* rho (Sec. 5.5), boundary tangents (Sec. 5.7), the eigenproblem, the similarity and Eq. 8 + Poisson. */
static PetscErrorCode SpinSolve(CSSpin spin, CSMesh mesh, SpinRun *r)
{
  PetscFunctionBeginUser;
  PetscCall(CSSpinRhoFromOptions(spin, mesh->x, &r->loc, &r->rho, &r->xt, &r->mu));
  PetscCall(CSSpinBoundaryFromOptions(spin, r->xt, &r->Tt));
  if (spin->boundary != CS_SPIN_BOUNDARY_NONE) PetscCall(CSSpinSetBoundaryTangents(spin, mesh->x, r->Tt));
  PetscCall(DMCreateGlobalVector(spin->dm, &r->lambda));
  PetscCall(CSSpinSolveEigen(spin, mesh->x, r->loc, r->rho, r->lambda));
  /* the global similarity: fit mu (Sec. 7.2) or the identity; with prescribed boundary tangents only a scale,
     since a rotation would turn the prescribed tangents */
  PetscCall(CSSpinNormalize(spin, r->lambda, r->mu, (PetscBool)(spin->boundary == CS_SPIN_BOUNDARY_NONE)));
  PetscCall(VecDuplicate(mesh->x, &r->xnew));
  PetscCall(CSSpinReconstruct(spin, mesh->x, r->lambda, r->xt ? r->xt : mesh->x, r->xnew));
  if (!r->xt) PetscCall(CSSpinRestoreArea(spin, mesh->x, r->xnew));
  PetscFunctionReturn(0);
}

static PetscErrorCode SpinReport(CSSpin spin, CSMesh mesh, const SpinRun *r, CSOutput *out)
{
  const char *bnames[] = {"none", "keep", "file", "target"};
  MPI_Comm    comm     = mesh->comm;
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "spin: gamma=%.10g (%s problem, residual %.2e) eigensolver its=%" PetscInt_FMT " inner its=%" PetscInt_FMT "; poisson its=%" PetscInt_FMT "\n", (double)spin->gamma, spin->generalized ? "generalized Eq. 6" : "standard Eq. 7", (double)spin->residual, spin->eps_its, spin->inner_its, spin->poisson_its));
  PetscCall(PetscPrintf(comm, "spin: seconds setup=%.4f eigen=%.4f poisson=%.4f (cpu %.4f %.4f %.4f)\n", spin->t_setup, spin->t_eigen, spin->t_poisson, spin->c_setup, spin->c_eigen, spin->c_poisson));
  PetscCall(CSJSONAddReal(out->json, "eigenvalue", spin->gamma));
  PetscCall(CSJSONAddReal(out->json, "eigen_residual", spin->residual));
  PetscCall(CSJSONAddInt(out->json, "eps_its", spin->eps_its));
  PetscCall(CSJSONAddInt(out->json, "inner_its", spin->inner_its));
  PetscCall(CSJSONAddInt(out->json, "poisson_its", spin->poisson_its));
  PetscCall(CSJSONAddReal(out->json, "seconds_setup", (PetscReal)spin->t_setup));
  PetscCall(CSJSONAddReal(out->json, "seconds_eigen", (PetscReal)spin->t_eigen));
  PetscCall(CSJSONAddReal(out->json, "seconds_poisson", (PetscReal)spin->t_poisson));
  PetscCall(CSJSONAddReal(out->json, "cpu_seconds_setup", (PetscReal)spin->c_setup));
  PetscCall(CSJSONAddReal(out->json, "cpu_seconds_eigen", (PetscReal)spin->c_eigen));
  PetscCall(CSJSONAddReal(out->json, "cpu_seconds_poisson", (PetscReal)spin->c_poisson));
  PetscCall(CSJSONAddString(out->json, "problem", spin->generalized ? "generalized" : "standard"));
  PetscCall(CSJSONAddString(out->json, "dirac_type", spin->shell ? "shell" : "aij"));
  PetscCall(CSJSONAddString(out->json, "boundary", bnames[spin->boundary]));
  PetscCall(CSJSONAddString(out->json, "rho_location", r->loc == CS_RHO_NONE ? "none" : (r->loc == CS_RHO_VERTEX ? "vertex" : "face")));
  if (r->rho) {
    PetscReal rmin, rmax;
    PetscCall(VecMin(r->rho, NULL, &rmin));
    PetscCall(VecMax(r->rho, NULL, &rmax));
    PetscCall(CSJSONAddReal(out->json, "rho_min", rmin));
    PetscCall(CSJSONAddReal(out->json, "rho_max", rmax));
  }
  if (r->xt) { /* distance to the target, relative to the target's size (sqrt of its area) */
    Vec       d;
    PetscReal nd, area, vol;
    PetscCall(VecDuplicate(r->xnew, &d));
    PetscCall(VecWAXPY(d, -1, r->xt, r->xnew));
    PetscCall(VecNorm(d, NORM_INFINITY, &nd));
    PetscCall(CSGeometryAreaVolume(mesh, r->xt, &area, &vol));
    PetscCall(CSJSONAddReal(out->json, "target_distance_max", nd / PetscSqrtReal(area)));
    PetscCall(PetscPrintf(comm, "spin: max distance to -spin_target_mesh %.3e (relative to sqrt(area))\n", (double)(nd / PetscSqrtReal(area))));
    PetscCall(VecDestroy(&d));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewerAddRho(CSViewer v, const SpinRun *r)
{
  PetscFunctionBeginUser;
  if (r->rho && r->loc == CS_RHO_VERTEX) PetscCall(CSViewerAddVertexField(v, "rho", r->rho));
  if (r->rho && r->loc == CS_RHO_FACE) PetscCall(CSViewerAddFaceField(v, "rho", r->rho));
  PetscFunctionReturn(0);
}

/* step 0: the input with rho; step 1: the result with rho, |lambda| and Q */
static PetscErrorCode SpinView(CSSpin spin, CSMesh mesh, const SpinRun *r, const char dir[])
{
  CSViewer v;
  Vec      la, q, la0;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &la));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &q));
  PetscCall(CSVecBlockNorms(r->lambda, 4, la)); /* |lambda| per vertex */
  PetscCall(CSGeometryQuasiConformal(mesh, mesh->x, r->xnew, q, NULL, NULL));
  PetscCall(CSViewerCreate(mesh, dir, &v));
  PetscCall(VecDuplicate(la, &la0));
  PetscCall(VecSet(la0, 1));
  PetscCall(ViewerAddRho(v, r));
  PetscCall(CSViewerAddVertexField(v, "lambda_abs", la0));
  PetscCall(CSViewerWriteStep(v, mesh->x, 0));
  PetscCall(ViewerAddRho(v, r));
  PetscCall(CSViewerAddVertexField(v, "lambda_abs", la));
  PetscCall(CSViewerAddFaceField(v, "Q", q));
  PetscCall(CSViewerWriteStep(v, r->xnew, 1));
  PetscCall(CSViewerDestroy(&v));
  PetscCall(VecDestroy(&la));
  PetscCall(VecDestroy(&la0));
  PetscCall(VecDestroy(&q));
  PetscFunctionReturn(0);
}

static PetscErrorCode RunSpin(CSSpin spin, CSMesh mesh, SpinRun *r, CSOutput *out)
{
  PetscFunctionBeginUser;
  PetscCall(CSSpinSetFromOptions(spin));
  PetscCall(SpinSolve(spin, mesh, r));
  PetscCall(SpinReport(spin, mesh, r, out));
  PetscCall(CSOutputAddMeshFacts(out, mesh, r->xnew, mesh->x));
  if (out->has_viewer) PetscCall(SpinView(spin, mesh, r, out->viewer_dir));
  PetscCall(CSOutputFinish(out, mesh, r->xnew));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTaskSpin(MPI_Comm comm)
{
  CSOutput       out;
  CSMesh         mesh = NULL;
  CSSpin         spin = NULL;
  SpinRun        r;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&r, sizeof(r)));
  PetscCall(CSOutputFromOptions(comm, &out));
  ierr = CSMeshCreateFromOptions(comm, NULL, &mesh);
  if (!ierr) ierr = CSSpinCreate(mesh, &spin);
  if (!ierr) ierr = RunSpin(spin, mesh, &r, &out);
  /* on every path: no leak after an error (a bad -rho file) */
  PetscCall(VecDestroy(&r.xnew));
  PetscCall(VecDestroy(&r.lambda));
  PetscCall(VecDestroy(&r.rho));
  PetscCall(VecDestroy(&r.xt));
  PetscCall(VecDestroy(&r.mu));
  PetscCall(VecDestroy(&r.Tt));
  PetscCall(CSSpinDestroy(&spin));
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(CSOutputDestroy(&out));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}
