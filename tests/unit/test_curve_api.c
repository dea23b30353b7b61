/* The isometric curve flow (crane2013 Sec. 5) through the library API alone, no bin/confsurf:
   1. a 5-petal star generated on rank 0, handed to CSCurveCreate and CSCurveFlowCreate (tau 0.5 and the
      tolerances set in code, then SetFromOptions), stepped with CSCurveFlowStep until the reason is not
      ITERATING, with a monitor counting the states: converged in <= 10 steps, kappa spread < 1e-6 of its mean,
      turning number 1 to 1e-12, the lengths kept (distortion of the final state < 1e-10);
   2. with -bad_dir DIR: the curve reader and validation on every bad file the shell test wrote there
      (tests/cases/curve_api.sh), in one process: each must fail with a message naming FILE:LINE and the
      reason. Exit status = number of failures. Run: build/tests/test_curve_api [-bad_dir DIR] (also mpirun -n 2) */
#include <petscsys.h>
#include <string.h>
#include "cs_methods_curve.h"
#include "cs_test.h"
#include "cs_util.h"

static PetscErrorCode CountStates(CSCurveFlow flow, const CSCurveMonitorInfo *info, void *ctx)
{
  PetscFunctionBeginUser;
  if (info->event != CS_CURVE_MONITOR_END) (*(PetscInt *)ctx)++;
  PetscFunctionReturn(0);
}

static PetscErrorCode FlowStar(MPI_Comm comm)
{
  CSCurveData                cd;
  CSCurveGenParams           p = {.n = 2000, .petals = 5, .seed = 1, .r = 1, .a = 2, .b = 1, .amplitude = 0.3, .noise = 0};
  CSCurve                    curve;
  CSCurveFlow                flow;
  CSCurveFlowConvergedReason reason = CS_CURVE_ITERATING;
  CSCurveFlowInfo            info;
  PetscInt                   states = 0;
  PetscMPIInt                rank;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&cd, sizeof(cd)));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) PetscCall(CSCurveDataGenerate("star", &p, &cd));
  PetscCall(CSCurveCreate(comm, &cd, &curve));
  PetscCall(CSCurveDataDestroy(&cd));
  PetscCall(CSCurveFlowCreate(curve, &flow));
  PetscCall(CSCurveFlowSetOptionsPrefix(flow, "test_"));
  PetscCall(CSCurveFlowSetTimeStep(flow, 0.5));
  PetscCall(CSCurveFlowSetTolerances(flow, 1e-9, 10));
  PetscCall(CSCurveFlowMonitorSet(flow, CountStates, &states, NULL));
  PetscCall(CSCurveFlowSetFromOptions(flow));
  PetscCall(CSCurveFlowSetUp(flow));
  while (reason == CS_CURVE_ITERATING) {
    PetscCall(CSCurveFlowStep(flow));
    PetscCall(CSCurveFlowGetConvergedReason(flow, &reason));
  }
  PetscCall(CSCurveFlowGetInfo(flow, &info));
  PetscCall(CSTestCheck(comm, (PetscBool)(reason == CS_CURVE_CONVERGED_RTOL && info.state.it <= 10), "star 2000: converged (steps)", (PetscReal)info.state.it, 10));
  PetscCall(CSTestCheck(comm, (PetscBool)(states == info.state.it + 1), "monitor saw every state (states - steps - 1)", (PetscReal)(states - info.state.it - 1), 0));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.state.spread_rel < 1e-6), "star 2000: kappa spread / mean", info.state.spread_rel, 1e-6));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(2 * PETSC_PI * (info.state.turning - 1)) < 1e-12), "star 2000: |total curvature - 2 pi|", PetscAbsReal(2 * PETSC_PI * (info.state.turning - 1)), 1e-12));
  PetscCall(CSTestCheck(comm, (PetscBool)(info.state.distortion < 1e-10), "star 2000: final length distortion", info.state.distortion, 1e-10));
  PetscCall(CSCurveFlowDestroy(&flow));
  PetscCall(CSCurveDestroy(&curve));
  PetscFunctionReturn(0);
}

/* read + validate (rank 0, as CSCurveCreateFromOptions does); the message must contain FILE[:LINE] and key */
static PetscErrorCode BadFile(MPI_Comm comm, const char dir[], const char name[], PetscInt line, const char key[])
{
  char           path[PETSC_MAX_PATH_LEN], where[PETSC_MAX_PATH_LEN + 16], msg[1024] = "";
  CSCurveData    cd;
  PetscErrorCode ierr = 0;
  PetscBool      ok;
  PetscMPIInt    rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(0);
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", dir, name));
  if (line) PetscCall(PetscSNPrintf(where, sizeof(where), "%s:%" PetscInt_FMT ":", path, line));
  else PetscCall(PetscSNPrintf(where, sizeof(where), "%s", path));
  CSCaptureError(ierr, CSCurveDataRead(path, &cd));
  if (!ierr) {
    CSCaptureError(ierr, CSCurveDataValidate(&cd, PETSC_FALSE));
    PetscCall(CSCurveDataDestroy(&cd));
  }
  if (ierr) {
    const char *text;
    char       *specific = NULL;
    PetscCall(PetscErrorMessage(ierr, &text, &specific));
    PetscCall(PetscStrncpy(msg, specific ? specific : "", sizeof(msg)));
  }
  ok = (PetscBool)(ierr && strstr(msg, where) && strstr(msg, key));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "%s %s: %s\n", ok ? "ok  " : "FAIL", name, ierr ? msg : "accepted"));
  if (!ok) cs_test_failures++;
  PetscFunctionReturn(0);
}

static PetscErrorCode BadFiles(MPI_Comm comm, const char dir[])
{
  PetscFunctionBeginUser;
  PetscCall(BadFile(comm, dir, "two_vertices.obj", 3, "at least 3"));
  PetscCall(BadFile(comm, dir, "repeated_point.txt", 3, "repeated consecutive points"));
  PetscCall(BadFile(comm, dir, "zero_length_edge.obj", 5, "zero-length edge"));
  PetscCall(BadFile(comm, dir, "nan.txt", 3, "NaN"));
  PetscCall(BadFile(comm, dir, "z_not_constant.obj", 3, "z coordinate"));
  PetscCall(BadFile(comm, dir, "two_lines.obj", 6, "second l element"));
  PetscCall(BadFile(comm, dir, "open_line.obj", 5, "open line"));
  PetscCall(BadFile(comm, dir, "open_line.txt", 1, "open line"));
  PetscCall(BadFile(comm, dir, "index_out_of_range.obj", 4, "out of range"));
  PetscCall(BadFile(comm, dir, "no_line.obj", 3, "no l element"));
  PetscCall(BadFile(comm, dir, "garbage.txt", 2, "garbage"));
  PetscCall(BadFile(comm, dir, "face.obj", 4, "face"));
  PetscCall(BadFile(comm, dir, "empty.txt", 0, "empty"));
  PetscCall(BadFile(comm, dir, "does_not_exist.txt", 0, "cannot open"));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm  comm;
  char      dir[PETSC_MAX_PATH_LEN];
  PetscBool has_dir;
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  comm = PETSC_COMM_WORLD;
  PetscCall(PetscOptionsGetString(NULL, NULL, "-bad_dir", dir, sizeof(dir), &has_dir));
  PetscCall(FlowStar(comm));
  if (has_dir) PetscCall(BadFiles(comm, dir));
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, &cs_test_failures, 1, MPIU_INT, MPI_SUM, comm)); /* the bad files are read on rank 0 */
  return CSTestFinalize(comm, PetscFinalize);
}
