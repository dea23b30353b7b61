/* The end of -task spin's spin transformation (crane2011): its stdout lines, the summary keys (the golden suite
   compares them), the ParaView pair and -o. Everything is read through the CSSpin getters. */
#include "cs_output_spin.h"
#include "cs_geometry.h"
#include "cs_linalg.h"

/* What the summary and the stdout lines report of the solve, read once through the CSSpin getters. */
typedef struct {
  PetscReal      gamma, res;
  PetscInt       eps_its, inner_its, poisson_its;
  PetscLogDouble t[3], c[3];
  PetscBool      generalized, shell;
  CSSpinBoundary boundary;
  CSRhoLocation  loc;
} SpinFacts;

static PetscErrorCode GetFacts(CSSpin spin, SpinFacts *f)
{
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetEigenvalue(spin, &f->gamma, &f->res));
  PetscCall(CSSpinGetIterationNumbers(spin, &f->eps_its, &f->inner_its, &f->poisson_its));
  PetscCall(CSSpinGetTimes(spin, f->t, f->c));
  PetscCall(CSSpinGetProblem(spin, &f->generalized, &f->shell));
  PetscCall(CSSpinGetBoundaryType(spin, &f->boundary));
  PetscCall(CSSpinGetRhoLocation(spin, &f->loc));
  PetscFunctionReturn(0);
}

static PetscErrorCode SpinLines(const SpinFacts *f, MPI_Comm comm)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPrintf(comm, "spin: gamma=%.10g (%s problem, residual %.2e) eigensolver its=%" PetscInt_FMT " inner its=%" PetscInt_FMT "; poisson its=%" PetscInt_FMT "\n", (double)f->gamma, f->generalized ? "generalized Eq. 6" : "standard Eq. 7", (double)f->res, f->eps_its, f->inner_its, f->poisson_its));
  PetscCall(PetscPrintf(comm, "spin: seconds setup=%.4f eigen=%.4f poisson=%.4f (cpu %.4f %.4f %.4f)\n", f->t[0], f->t[1], f->t[2], f->c[0], f->c[1], f->c[2]));
  PetscFunctionReturn(0);
}

/* the keys in the order of the summaries written before spin_report.c existed */
static PetscErrorCode SolverKeys(const SpinFacts *f, CSJSON json)
{
  const char *bnames[] = {"none", "keep", "file", "target"};
  PetscFunctionBeginUser;
  PetscCall(CSJSONAddReal(json, "eigenvalue", f->gamma));
  PetscCall(CSJSONAddReal(json, "eigen_residual", f->res));
  PetscCall(CSJSONAddInt(json, "eps_its", f->eps_its));
  PetscCall(CSJSONAddInt(json, "inner_its", f->inner_its));
  PetscCall(CSJSONAddInt(json, "poisson_its", f->poisson_its));
  PetscCall(CSJSONAddReal(json, "seconds_setup", (PetscReal)f->t[0]));
  PetscCall(CSJSONAddReal(json, "seconds_eigen", (PetscReal)f->t[1]));
  PetscCall(CSJSONAddReal(json, "seconds_poisson", (PetscReal)f->t[2]));
  PetscCall(CSJSONAddReal(json, "cpu_seconds_setup", (PetscReal)f->c[0]));
  PetscCall(CSJSONAddReal(json, "cpu_seconds_eigen", (PetscReal)f->c[1]));
  PetscCall(CSJSONAddReal(json, "cpu_seconds_poisson", (PetscReal)f->c[2]));
  PetscCall(CSJSONAddString(json, "problem", f->generalized ? "generalized" : "standard"));
  PetscCall(CSJSONAddString(json, "dirac_type", f->shell ? "shell" : "aij"));
  PetscCall(CSJSONAddString(json, "boundary", bnames[f->boundary]));
  PetscCall(CSJSONAddString(json, "rho_location", f->loc == CS_RHO_NONE ? "none" : (f->loc == CS_RHO_VERTEX ? "vertex" : "face")));
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
static PetscErrorCode SpinView(CSSpin spin, CSMesh mesh, Vec x, CSRhoLocation loc, Vec rho, Vec xnew, const char dir[])
{
  CSViewer v;
  Vec      la, q, la0, lambda;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetSpinor(spin, &lambda));
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
  CSMesh    mesh;
  Vec       xnew;
  SpinFacts f;
  PetscFunctionBeginUser;
  PetscCall(CSSpinGetMesh(spin, &mesh));
  PetscCall(CSSpinGetSolution(spin, &xnew));
  PetscCall(GetFacts(spin, &f));
  PetscCall(SpinLines(&f, mesh->comm));
  PetscCall(SolverKeys(&f, out->json));
  PetscCall(InputKeys(mesh, rho, xt, xnew, out->json));
  PetscCall(CSOutputAddMeshFacts(out, mesh, xnew, x));
  if (out->has_viewer) PetscCall(SpinView(spin, mesh, x, f.loc, rho, xnew, out->viewer_dir));
  PetscCall(CSOutputFinish(out, mesh, xnew));
  PetscFunctionReturn(0);
}
