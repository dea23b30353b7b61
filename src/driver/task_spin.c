/* -task spin (crane2011): paint rho / nearest spin transformation / boundary edit. The driver reads the mesh,
   the inputs (rho, the target, the boundary tangents: spin_input.c) and the output from the options, hands them
   to the CSSpin object, solves and reports (src/output/spin_report.c). */
#include "cs_driver.h"
#include "cs_geometry.h"
#include "cs_output_spin.h"
#include "cs_util.h"
#include "spin_input.h"

/* The inputs of one spin transformation, read by spin_input.c. */
typedef struct {
  CSRhoLocation loc;
  Vec           rho, xt, mu, Tt;
  Vec           xlsq; /* the positions of -spin_least_squares */
} SpinRun;

/* A spin transformation (crane2011 Sec. 5): the inputs handed to the object, its Solve, the report */
static PetscErrorCode SpinTransform(CSSpin spin, CSMesh mesh, const SpinRun *r, CSOutput *out)
{
  CSSpinBoundary b;
  PetscFunctionBeginUser;
  PetscCall(CSSpinSetRhoLocation(spin, r->loc));
  PetscCall(CSSpinSetTarget(spin, r->xt, r->mu));
  PetscCall(CSSpinGetBoundaryType(spin, &b));
  if (b != CS_SPIN_BOUNDARY_NONE) PetscCall(CSSpinSetBoundaryTangents(spin, r->Tt));
  PetscCall(CSSpinSolve(spin, mesh->x, r->rho));
  PetscCall(CSSpinReport(spin, mesh->x, r->rho, r->xt, out));
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
  PetscCall(VecDuplicate(mesh->x, &r->xlsq));
  PetscCall(CSSpinReconstruct(spin, mesh->x, r->mu, r->xt, r->xlsq));
  PetscCall(VecDuplicate(r->xlsq, &d));
  PetscCall(VecWAXPY(d, -1, r->xt, r->xlsq));
  PetscCall(VecNorm(d, NORM_INFINITY, &nd));
  PetscCall(CSGeometryAreaVolume(mesh, r->xt, &area, &vol));
  PetscCall(CSJSONAddReal(out->json, "target_distance_max", nd / PetscSqrtReal(area)));
  PetscCall(CSJSONAddString(out->json, "method", "least_squares"));
  PetscCall(PetscPrintf(mesh->comm, "least squares from mu (Fig. 22): max distance to -spin_target_mesh %.3e (relative to sqrt(area))\n", (double)(nd / PetscSqrtReal(area))));
  PetscCall(CSOutputAddMeshFacts(out, mesh, r->xlsq, mesh->x));
  PetscCall(CSOutputFinish(out, mesh, r->xlsq));
  PetscCall(VecDestroy(&d));
  PetscFunctionReturn(0);
}

/* -spin_flow_steps N (crane2011 Sec. 7.3, Fig. 16, 17): the conformal Willmore flow on a disk, rho(t) = -t H,
   taken as N steps of rho = -tau H of the current surface, each a spin transformation with the boundary
   condition of Sec. 5.7 (-spin_boundary, default keep). History per step: area, boundary length, the ratio
   area / length^2 (1/(4 pi) for a flat disk bounded by a circle), q_mean against the input. */
static PetscErrorCode SpinFlow(CSSpin spin, CSMesh mesh, PetscInt N, PetscReal tau, CSOutput *out)
{
  Vec       x, rho, xnew;
  CSHistory hist = NULL;
  PetscReal area, vol, len, qmean = 1, qmax;
  PetscFunctionBeginUser;
  PetscCheck(mesh->topo.boundary_loops > 0, mesh->comm, PETSC_ERR_ARG_WRONG, "-spin_flow_steps: mesh %s has no boundary (the flow rho = -t H is the closed form on disks, Sec. 7.3)", mesh->name);
  PetscCall(VecDuplicate(mesh->x, &x));
  PetscCall(VecCopy(mesh->x, x));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &rho));
  PetscCall(CSSpinSetRhoLocation(spin, CS_RHO_VERTEX));
  PetscCall(CSSpinSetRestoreArea(spin, PETSC_FALSE)); /* the area changes: area / length^2 is the result */
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
    PetscCall(CSSpinSolve(spin, x, rho));
    PetscCall(CSSpinGetSolution(spin, &xnew));
    PetscCall(VecCopy(xnew, x));
  }
  PetscCall(CSJSONAddReal(out->json, "flow_area_over_length2", area / (len * len)));
  PetscCall(CSJSONAddInt(out->json, "flow_steps", N));
  PetscCall(CSOutputAddMeshFacts(out, mesh, x, mesh->x));
  PetscCall(CSOutputFinish(out, mesh, x));
  PetscCall(CSHistoryDestroy(&hist));
  PetscCall(VecDestroy(&x));
  PetscCall(VecDestroy(&rho));
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
  if (!flow) PetscCall(CSDriverSpinRhoFromOptions(spin, mesh->x, &r->loc, &r->rho, &r->xt, &r->mu));
  if (!interp && !flow && !lsq) PetscCall(CSDriverSpinBoundaryFromOptions(spin, r->xt, &r->Tt));
  PetscCall(CSOptionsCheckUnused(comm, "-task spin"));
  if (interp) PetscCall(SpinInterpolate(spin, mesh, ninterp, iprefix, r, out));
  else if (flow) PetscCall(SpinFlow(spin, mesh, nflow, tau, out));
  else if (lsq) PetscCall(SpinLeastSquares(spin, mesh, r, out));
  else PetscCall(SpinTransform(spin, mesh, r, out));
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
  PetscCall(VecDestroy(&r.xlsq));
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
