/* -task curveflow: the isometric curve flow of crane2013 Sec. 5 on the curve of -curve FILE / -gen_curve SHAPE,
   with the monitors of src/output/curve_monitors.c (progress line, -history_csv, -viewer_dir: the curve of
   every -curve_viewer_every-th state as text with its curvature) and the report (-summary, -o .obj|.txt). */
#include "cs_driver.h"
#include "cs_output_curve.h"

/* -curve_viewer_every: read on every run (not only with -viewer_dir) so that the option is never "unused" */
static PetscErrorCode SetMonitors(CSCurveFlow flow, CSOutput *out)
{
  const char *prefix;
  PetscInt    every = 1;
  CSCurve     curve;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFlowGetCurve(flow, &curve));
  PetscCall(CSCurveFlowGetOptionsPrefix(flow, &prefix));
  PetscOptionsBegin(curve->comm, prefix, "Curve flow output", NULL);
  PetscCall(PetscOptionsInt("-viewer_every", "Write the curve of every this many states into -viewer_dir", NULL, every, &every, NULL));
  PetscOptionsEnd();
  PetscCheck(every >= 1, curve->comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sviewer_every %" PetscInt_FMT ": must be >= 1", prefix, every);
  PetscCall(CSCurveFlowMonitorSetHistory(flow, out));
  PetscCall(CSCurveFlowMonitorSetSteps(flow, out, every));
  PetscCall(CSCurveFlowMonitorSet(flow, CSCurveFlowMonitorProgress, NULL, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode RunFlow(CSCurve curve, CSOutput *out)
{
  CSCurveFlow    flow;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFlowCreate(curve, &flow));
  ierr = CSCurveFlowSetFromOptions(flow);
  if (!ierr) ierr = SetMonitors(flow, out);
  if (!ierr) ierr = CSCurveFlowSolve(flow);
  if (!ierr) ierr = CSCurveFlowReport(flow, out);
  PetscCall(CSCurveFlowDestroy(&flow)); /* on every path: no leak after an error */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode CSTaskCurveFlow(MPI_Comm comm)
{
  const char *const exts[] = {"obj", "txt", "xy", "dat", NULL};
  CSOutput          out;
  CSCurve           curve = NULL;
  PetscErrorCode    ierr;
  PetscFunctionBeginUser;
  PetscCall(CSOutputFromOptionsFormats(comm, exts, "the final curve is written as .obj or text (.txt .xy .dat)", &out));
  ierr = (out.has_checkpoint || out.has_resume || out.has_reference) ? PETSC_ERR_ARG_INCOMP : 0;
  if (ierr) PetscCall(CSOutputDestroy(&out));
  PetscCheck(!ierr, comm, PETSC_ERR_ARG_INCOMP, "-task curveflow: -checkpoint, -resume and -reference are not supported (a run takes milliseconds)");
  ierr = CSCurveCreateFromOptions(comm, &curve);
  if (!ierr) ierr = RunFlow(curve, &out);
  PetscCall(CSCurveDestroy(&curve));
  PetscCall(CSOutputDestroy(&out));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}
