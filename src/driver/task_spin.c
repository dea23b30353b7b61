/* -task spin (crane2011): paint rho / nearest spin transformation / boundary edit. The driver reads the mesh
   and the output from the options and hands the mesh to the CSSpin object. */
#include "cs_driver.h"
#include "cs_geometry.h"
#include "cs_methods_spin.h"
#include "cs_linalg.h"
#include "cs_util.h"

/* Inputs and results of one spin transformation. */
typedef struct {
  CSRhoLocation loc;
  Vec           rho, xt, mu, Tt, lambda, xnew;
} SpinRun;

/* With rho (Sec. 5.5) and the boundary tangents (Sec. 5.7) read: the eigenproblem, the similarity and Eq. 8 +
   Poisson. */
static PetscErrorCode SpinSolve(CSSpin spin, CSMesh mesh, SpinRun *r)
{
  PetscFunctionBeginUser;
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
  PetscCall(CSViewerCreate(mesh, NULL, dir, &v));
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

/* -spin_interpolate N (Sec. 7.2, Fig. 21): meshes PREFIX_k.obj, k = 0..N, of the similarity interpolation from the
   input (k = 0) to -spin_target_mesh (k = N); q_mean against the input of each and of the linear interpolation
   (1 - t) x + t xt of the positions, and the distance of the ends to the input and the target. */
static PetscErrorCode SpinInterpolate(CSSpin spin, CSMesh mesh, PetscInt N, const char prefix[], const SpinRun *rr, CSOutput *out)
{
  SpinRun    r = *rr;
  Vec        r0, r1, xs, xl;
  PetscReal *q, end[2];
  PetscFunctionBeginUser;
  PetscCheck(r.xt, mesh->comm, PETSC_ERR_ARG_WRONG, "-spin_interpolate needs -spin_target_mesh FILE (the other end, same connectivity)");
  PetscCall(VecDuplicate(mesh->x, &r0));
  PetscCall(VecDuplicate(mesh->x, &r1));
  PetscCall(VecDuplicate(mesh->x, &xs));
  PetscCall(VecDuplicate(mesh->x, &xl));
  PetscCall(PetscMalloc1(2 * (N + 1), &q));
  PetscCall(CSSpinInterpolateSetUp(spin, mesh->x, r.xt, r.mu, r0, r1));
  for (PetscInt k = 0; k <= N; k++) {
    char      path[PETSC_MAX_PATH_LEN];
    PetscReal t = (PetscReal)k / N, qmax;
    PetscCall(CSSpinInterpolate(spin, mesh->x, r.mu, r0, r1, t, xs));
    PetscCall(VecCopy(mesh->x, xl)); /* xl = (1 - t) x + t xt */
    PetscCall(VecScale(xl, 1 - t));
    PetscCall(VecAXPY(xl, t, r.xt));
    PetscCall(CSGeometryQuasiConformal(mesh, mesh->x, xs, NULL, &q[k], &qmax));
    PetscCall(CSGeometryQuasiConformal(mesh, mesh->x, xl, NULL, &q[N + 1 + k], &qmax));
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s_%" PetscInt_FMT ".obj", prefix, k));
    PetscCall(CSMeshWrite(mesh, xs, path));
    PetscCall(PetscPrintf(mesh->comm, "spin interpolation t=%.3f: %s, q_mean %.6f (linear interpolation %.6f)\n", (double)t, path, (double)q[k], (double)q[N + 1 + k]));
    if (k == 0 || k == N) {
      PetscCall(VecAXPY(xs, -1, k ? r.xt : mesh->x));
      PetscCall(VecNorm(xs, NORM_INFINITY, &end[k ? 1 : 0]));
    }
  }
  PetscCall(CSJSONAddRealArray(out->json, "interpolation_q_mean", N + 1, q));
  PetscCall(CSJSONAddRealArray(out->json, "linear_q_mean", N + 1, q + N + 1));
  PetscCall(CSJSONAddReal(out->json, "interpolation_start_error", end[0]));
  PetscCall(CSJSONAddReal(out->json, "interpolation_end_error", end[1]));
  PetscCall(CSOutputAddMeshFacts(out, mesh, mesh->x, NULL)); /* -o writes the input (the meshes are PREFIX_k.obj) */
  PetscCall(CSOutputFinish(out, mesh, mesh->x));
  PetscCall(PetscFree(q));
  PetscCall(VecDestroy(&r0));
  PetscCall(VecDestroy(&r1));
  PetscCall(VecDestroy(&xs));
  PetscCall(VecDestroy(&xl));
  PetscFunctionReturn(0);
}

/* -spin_least_squares (crane2011 Fig. 22, the baseline the paper compares with): positions straight from the
   best-fit similarities mu of -spin_target_mesh by Eq. 8 and the least-squares Poisson step, without the
   eigenproblem (mu is not integrable, so the result is not a spin transformation). Summary: q_mean, q_max against
   the input and target_distance_max, as for the spin result. */
static PetscErrorCode SpinLeastSquares(CSSpin spin, CSMesh mesh, SpinRun *r, CSOutput *out)
{
  Vec       d;
  PetscReal nd, area, vol;
  PetscFunctionBeginUser;
  PetscCheck(r->xt, mesh->comm, PETSC_ERR_ARG_WRONG, "-spin_least_squares needs -spin_target_mesh FILE");
  PetscCall(VecDuplicate(mesh->x, &r->xnew));
  PetscCall(CSSpinReconstruct(spin, mesh->x, r->mu, r->xt, r->xnew));
  PetscCall(VecDuplicate(r->xnew, &d));
  PetscCall(VecWAXPY(d, -1, r->xt, r->xnew));
  PetscCall(VecNorm(d, NORM_INFINITY, &nd));
  PetscCall(CSGeometryAreaVolume(mesh, r->xt, &area, &vol));
  PetscCall(CSJSONAddReal(out->json, "target_distance_max", nd / PetscSqrtReal(area)));
  PetscCall(CSJSONAddString(out->json, "method", "least_squares"));
  PetscCall(PetscPrintf(mesh->comm, "least squares from mu (Fig. 22): max distance to -spin_target_mesh %.3e (relative to sqrt(area))\n", (double)(nd / PetscSqrtReal(area))));
  PetscCall(CSOutputAddMeshFacts(out, mesh, r->xnew, mesh->x));
  PetscCall(CSOutputFinish(out, mesh, r->xnew));
  PetscCall(VecDestroy(&d));
  PetscFunctionReturn(0);
}

/* -spin_flow_steps N (crane2011 Sec. 7.3, Fig. 16, 17): the conformal Willmore flow on a disk, rho(t) = -t H,
   taken as N steps of rho = -tau H of the current surface, each a spin transformation with the boundary
   condition of Sec. 5.7 (-spin_boundary, default keep). History per step: area, boundary length, the ratio
   area / length^2 (1/(4 pi) for a flat disk bounded by a circle), q_mean against the input. */
static PetscErrorCode SpinFlow(CSSpin spin, CSMesh mesh, PetscInt N, PetscReal tau, CSOutput *out)
{
  Vec       x, rho, lambda, xnew;
  CSHistory hist = NULL;
  PetscReal area, vol, len, qmean = 1, qmax;
  PetscFunctionBeginUser;
  PetscCheck(mesh->topo.boundary_loops > 0, mesh->comm, PETSC_ERR_ARG_WRONG, "-spin_flow_steps: mesh %s has no boundary (the flow rho = -t H is the closed form on disks, Sec. 7.3)", mesh->name);
  PetscCall(VecDuplicate(mesh->x, &x));
  PetscCall(VecDuplicate(mesh->x, &xnew));
  PetscCall(VecCopy(mesh->x, x));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &rho));
  PetscCall(DMCreateGlobalVector(spin->dm, &lambda));
  PetscCall(CSOutputHistoryCreate(out, mesh->comm, "it,area,boundary_length,area_over_length2,q_mean", 0, &hist));
  for (PetscInt k = 0; k <= N; k++) {
    PetscReal row[5];
    PetscCall(CSGeometryAreaVolume(mesh, x, &area, &vol));
    PetscCall(CSGeometryBoundaryLength(mesh, x, &len));
    if (k) PetscCall(CSGeometryQuasiConformal(mesh, mesh->x, x, NULL, &qmean, &qmax));
    row[0] = k; row[1] = area; row[2] = len; row[3] = area / (len * len); row[4] = qmean;
    if (hist) PetscCall(CSHistoryAppend(hist, 5, row));
    PetscCall(PetscPrintf(mesh->comm, "spin flow %3" PetscInt_FMT ": area %.6f boundary length %.6f area/length^2 %.6f q_mean %.6f\n", k, (double)area, (double)len, (double)row[3], (double)qmean));
    if (k == N) break;
    PetscCall(VecSet(rho, 0));
    PetscCall(CSSpinRhoAddMeanCurvature(mesh, x, -tau, rho));
    PetscCall(CSSpinSolveEigen(spin, x, CS_RHO_VERTEX, rho, lambda));
    PetscCall(CSSpinNormalize(spin, lambda, NULL, (PetscBool)(spin->boundary == CS_SPIN_BOUNDARY_NONE)));
    PetscCall(CSSpinReconstruct(spin, x, lambda, x, xnew));
    PetscCall(VecCopy(xnew, x));
  }
  PetscCall(CSJSONAddReal(out->json, "flow_area_over_length2", area / (len * len)));
  PetscCall(CSJSONAddInt(out->json, "flow_steps", N));
  PetscCall(CSOutputAddMeshFacts(out, mesh, x, mesh->x));
  PetscCall(CSOutputFinish(out, mesh, x));
  PetscCall(CSHistoryDestroy(&hist));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&xnew));
  PetscCall(VecDestroy(&rho));
  PetscCall(VecDestroy(&lambda));
  PetscFunctionReturn(0);
}

/* The spin task proper, after the mesh and the method exist: one of -spin_interpolate, -spin_flow_steps,
   -spin_least_squares, or a spin transformation (the default). */
static PetscErrorCode RunSpin(CSSpin spin, CSMesh mesh, SpinRun *r, CSOutput *out)
{
  MPI_Comm  comm    = mesh->comm;
  PetscInt  ninterp = 8, nflow = 10;
  PetscBool interp  = PETSC_FALSE, flow = PETSC_FALSE, lsq = PETSC_FALSE;
  PetscReal tau     = 0.1;
  char      iprefix[PETSC_MAX_PATH_LEN] = "spin_interpolate";
  PetscFunctionBeginUser;
  PetscCall(CSSpinSetFromOptions(spin));
  PetscOptionsBegin(comm, NULL, "Similarity interpolation (crane2011 Sec. 7.2, Fig. 21)", NULL);
  PetscCall(CSOptionsInt("-spin_interpolate", "Meshes 0..N of the similarity interpolation from the input to -spin_target_mesh instead of a spin transformation", NULL, ninterp, &ninterp, &interp));
  PetscCall(CSOptionsInt("-spin_flow_steps", "Conformal Willmore flow on a disk (Sec. 7.3): this many spin transformations with rho = -tau H of the current surface", NULL, nflow, &nflow, &flow));
  PetscCall(CSOptionsReal("-spin_flow_tau", "Step of -spin_flow_steps (tau = 1: the minimal surface in one step)", NULL, tau, &tau, NULL));
  PetscCall(PetscOptionsBool("-spin_least_squares", "Positions from the best-fit similarities of -spin_target_mesh by least squares, without the eigenproblem (the baseline of Fig. 22)", NULL, lsq, &lsq, NULL));
  PetscCall(CSOptionsString("-spin_interpolate_prefix", "Interpolated mesh k is written to PREFIX_k.obj", NULL, iprefix, iprefix, sizeof(iprefix), NULL));
  PetscOptionsEnd();
  {
    const CSOptionCheck checks[] = {{"spin_interpolate", (PetscReal)ninterp, ninterp >= 1, "need at least 1 step"}, {"spin_flow_steps", (PetscReal)nflow, nflow >= 1, "must be >= 1"}, {"spin_flow_tau", tau, tau > 0, "must be > 0"}};
    PetscCall(CSCheckOptionValues(comm, NULL, 3, checks));
  }
  /* before anything is allocated: a refused size names it */
  if (interp) PetscCall(CSCheckAllocation("-spin_interpolate: q_mean of N + 1 meshes, twice", 2 * ((PetscInt64)ninterp + 1), sizeof(PetscReal)));
  /* rho and the boundary tangents are read (and rho made) before the check of unused options, the eigensolves after */
  if (!flow) PetscCall(CSSpinRhoFromOptions(spin, mesh->x, &r->loc, &r->rho, &r->xt, &r->mu));
  if (!interp && !flow && !lsq) PetscCall(CSSpinBoundaryFromOptions(spin, r->xt, &r->Tt));
  PetscCall(CSOptionsCheckUnused(comm, "-task spin"));
  if (interp) PetscCall(SpinInterpolate(spin, mesh, ninterp, iprefix, r, out));
  else if (flow) PetscCall(SpinFlow(spin, mesh, nflow, tau, out));
  else if (lsq) PetscCall(SpinLeastSquares(spin, mesh, r, out));
  else {
    PetscCall(SpinSolve(spin, mesh, r));
    PetscCall(SpinReport(spin, mesh, r, out));
    PetscCall(CSOutputAddMeshFacts(out, mesh, r->xnew, mesh->x));
    if (out->has_viewer) PetscCall(SpinView(spin, mesh, r, out->viewer_dir));
    PetscCall(CSOutputFinish(out, mesh, r->xnew));
  }
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
  ierr = CSMeshDataRefuseTargetClass(comm, NULL, "-task spin");
  if (!ierr) ierr = CSMeshCreateFromOptions(comm, NULL, &mesh);
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
