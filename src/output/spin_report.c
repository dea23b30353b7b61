/* The end of -task spin's spin transformation (crane2011): its stdout lines, the summary keys (the golden suite
   compares them), the ParaView pair and -o. Everything is read through the CSSpin getters. */
#include "cs_output_spin.h"
#include "cs_geometry.h"
#include "cs_linalg.h"

static PetscErrorCode SpinLines(CSSpin spin, MPI_Comm comm)
{
  PetscReal      gamma, res;
  PetscInt       eps_its, inner_its, poisson_its;
  PetscLogDouble t[3], c[3];
  PetscBool      generalized;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetEigenvalue(spin, &gamma, &res));
  PetscCall(CSSpinGetIterationNumbers(spin, &eps_its, &inner_its, &poisson_its));
  PetscCall(CSSpinGetTimes(spin, t, c));
  PetscCall(CSSpinGetProblem(spin, &generalized, NULL));
  PetscCall(PetscPrintf(comm, "spin: gamma=%.10g (%s problem, residual %.2e) eigensolver its=%" PetscInt_FMT " inner its=%" PetscInt_FMT "; poisson its=%" PetscInt_FMT "\n", (double)gamma, generalized ? "generalized Eq. 6" : "standard Eq. 7", (double)res, eps_its, inner_its, poisson_its));
  PetscCall(PetscPrintf(comm, "spin: seconds setup=%.4f eigen=%.4f poisson=%.4f (cpu %.4f %.4f %.4f)\n", t[0], t[1], t[2], c[0], c[1], c[2]));
  PetscFunctionReturn(0);
}

/* the keys in the order of the summaries written before spin_report.c existed */
static PetscErrorCode SolverKeys(CSSpin spin, CSJSON json)
{
  const char    *bnames[] = {"none", "keep", "file", "target"};
  PetscReal      gamma, res;
  PetscInt       eps_its, inner_its, poisson_its;
  PetscLogDouble t[3], c[3];
  PetscBool      generalized, shell;
  CSSpinBoundary b;
  CSRhoLocation  loc;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetEigenvalue(spin, &gamma, &res));
  PetscCall(CSSpinGetIterationNumbers(spin, &eps_its, &inner_its, &poisson_its));
  PetscCall(CSSpinGetTimes(spin, t, c));
  PetscCall(CSSpinGetProblem(spin, &generalized, &shell));
  PetscCall(CSSpinGetBoundaryType(spin, &b));
  PetscCall(CSSpinGetRhoLocation(spin, &loc));
  PetscCall(CSJSONAddReal(json, "eigenvalue", gamma));
  PetscCall(CSJSONAddReal(json, "eigen_residual", res));
  PetscCall(CSJSONAddInt(json, "eps_its", eps_its));
  PetscCall(CSJSONAddInt(json, "inner_its", inner_its));
  PetscCall(CSJSONAddInt(json, "poisson_its", poisson_its));
  PetscCall(CSJSONAddReal(json, "seconds_setup", (PetscReal)t[0]));
  PetscCall(CSJSONAddReal(json, "seconds_eigen", (PetscReal)t[1]));
  PetscCall(CSJSONAddReal(json, "seconds_poisson", (PetscReal)t[2]));
  PetscCall(CSJSONAddReal(json, "cpu_seconds_setup", (PetscReal)c[0]));
  PetscCall(CSJSONAddReal(json, "cpu_seconds_eigen", (PetscReal)c[1]));
  PetscCall(CSJSONAddReal(json, "cpu_seconds_poisson", (PetscReal)c[2]));
  PetscCall(CSJSONAddString(json, "problem", generalized ? "generalized" : "standard"));
  PetscCall(CSJSONAddString(json, "dirac_type", shell ? "shell" : "aij"));
  PetscCall(CSJSONAddString(json, "boundary", bnames[b]));
  PetscCall(CSJSONAddString(json, "rho_location", loc == CS_RHO_NONE ? "none" : (loc == CS_RHO_VERTEX ? "vertex" : "face")));
  PetscFunctionReturn(0);
}

/* rho_min, rho_max; the distance to the target relative to the target's size (sqrt of its area) */
static PetscErrorCode InputKeys(CSMesh mesh, Vec rho, Vec xt, Vec xnew, CSJSON json)
{
  PetscFunctionBeginUser;
  if (rho) {
    PetscReal rmin, rmax;
    PetscCall(VecMin(rho, NULL, &rmin));
    PetscCall(VecMax(rho, NULL, &rmax));
    PetscCall(CSJSONAddReal(json, "rho_min", rmin));
    PetscCall(CSJSONAddReal(json, "rho_max", rmax));
  }
  if (xt) {
    Vec       d;
    PetscReal nd, area, vol;
    PetscCall(VecDuplicate(xnew, &d));
    PetscCall(VecWAXPY(d, -1, xt, xnew));
    PetscCall(VecNorm(d, NORM_INFINITY, &nd));
    PetscCall(CSGeometryAreaVolume(mesh, xt, &area, &vol));
    PetscCall(CSJSONAddReal(json, "target_distance_max", nd / PetscSqrtReal(area)));
    PetscCall(PetscPrintf(mesh->comm, "spin: max distance to -spin_target_mesh %.3e (relative to sqrt(area))\n", (double)(nd / PetscSqrtReal(area))));
    PetscCall(VecDestroy(&d));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewerAddRho(CSViewer v, CSRhoLocation loc, Vec rho)
{
  PetscFunctionBeginUser;
  if (rho && loc == CS_RHO_VERTEX) PetscCall(CSViewerAddVertexField(v, "rho", rho));
  if (rho && loc == CS_RHO_FACE) PetscCall(CSViewerAddFaceField(v, "rho", rho));
  PetscFunctionReturn(0);
}

/* step 0: the input with rho; step 1: the result with rho, |lambda| and Q */
static PetscErrorCode SpinView(CSSpin spin, CSMesh mesh, Vec x, Vec rho, Vec xnew, const char dir[])
{
  CSViewer      v;
  Vec           la, q, la0, lambda;
  CSRhoLocation loc;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetSpinor(spin, &lambda));
  PetscCall(CSSpinGetRhoLocation(spin, &loc));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &la));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &q));
  PetscCall(CSVecBlockNorms(lambda, 4, la)); /* |lambda| per vertex */
  PetscCall(CSGeometryQuasiConformal(mesh, x, xnew, q, NULL, NULL));
  PetscCall(CSViewerCreate(mesh, NULL, dir, &v));
  PetscCall(VecDuplicate(la, &la0));
  PetscCall(VecSet(la0, 1));
  PetscCall(ViewerAddRho(v, loc, rho));
  PetscCall(CSViewerAddVertexField(v, "lambda_abs", la0));
  PetscCall(CSViewerWriteStep(v, x, 0));
  PetscCall(ViewerAddRho(v, loc, rho));
  PetscCall(CSViewerAddVertexField(v, "lambda_abs", la));
  PetscCall(CSViewerAddFaceField(v, "Q", q));
  PetscCall(CSViewerWriteStep(v, xnew, 1));
  PetscCall(CSViewerDestroy(&v));
  PetscCall(VecDestroy(&la));
  PetscCall(VecDestroy(&la0));
  PetscCall(VecDestroy(&q));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinReport(CSSpin spin, Vec x, Vec rho, Vec xt, CSOutput *out)
{
  CSMesh mesh;
  Vec    xnew;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetMesh(spin, &mesh));
  PetscCall(CSSpinGetSolution(spin, &xnew));
  PetscCall(SpinLines(spin, mesh->comm));
  PetscCall(SolverKeys(spin, out->json));
  PetscCall(InputKeys(mesh, rho, xt, xnew, out->json));
  PetscCall(CSOutputAddMeshFacts(out, mesh, xnew, x));
  if (out->has_viewer) PetscCall(SpinView(spin, mesh, x, rho, xnew, out->viewer_dir));
  PetscCall(CSOutputFinish(out, mesh, xnew));
  PetscFunctionReturn(0);
}
