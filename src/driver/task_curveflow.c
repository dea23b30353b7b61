/* -task curveflow: the isometric curve flow of crane2013 Sec. 5 on the curve of -curve FILE / -gen_curve SHAPE,
   with the monitors of src/output/curve_monitors.c (progress line, -history_csv, -viewer_dir: the curve of
   every -curve_viewer_every-th state as text with its curvature) and the report (-summary, -o .obj|.txt). */
#include "cs_driver.h"
#include "cs_output_curve.h"

static PetscErrorCode SetMonitors(CSCurveFlow flow, CSOutput *out)
{
  const char *prefix;
  PetscInt    every;
  CSCurve     curve;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFlowGetCurve(flow, &curve));
  PetscCall(CSCurveFlowGetOptionsPrefix(flow, &prefix));
  PetscCall(CSOutputViewerEvery(curve->comm, prefix, "Curve flow output", "Write the curve of every this many states into -viewer_dir", PETSC_FALSE, &every));
  PetscCall(CSCurveFlowMonitorSetSteps(flow, out, every));
  PetscCall(CSOptionsCheckUnused(curve->comm, "-task curveflow")); /* the last options read; before the history file is created */
  PetscCall(CSCurveFlowMonitorSetHistory(flow, out));
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
