/* -task flow -flow_type conformal: the conformal curvature flow of crane2013 (Sec. 6) on the mesh of -mesh/-gen,
   with the monitors of src/output/conformal_monitors.c (progress line, -history_csv, -viewer_dir with
   -flow_viewer_every N) and the report (-summary, -o). -checkpoint/-resume are not supported (a run takes a few
   steps). */
#include "cs_driver.h"
#include "cs_output_conformal.h"

static PetscErrorCode SetMonitors(CSConformalFlow flow, CSOutput *out)
{
  const char *prefix;
  PetscInt    every;
  CSMesh      mesh;
  PetscFunctionBeginUser;
  PetscCall(CSConformalFlowGetMesh(flow, &mesh));
  PetscCall(CSConformalFlowGetOptionsPrefix(flow, &prefix));
  PetscCall(CSOutputViewerEvery(mesh->comm, prefix, "Conformal flow output", "With -viewer_dir: a ParaView step every this many steps (0: the final state only)", PETSC_TRUE, &every));
  PetscCall(CSConformalFlowMonitorSetViewer(flow, out, every));
  PetscCall(CSFlowCheckUnusedOptions(mesh->comm)); /* the last options read; before the history file is created */
  PetscCall(CSConformalFlowMonitorSetHistory(flow, out));
  PetscCall(CSConformalFlowMonitorSet(flow, CSConformalFlowMonitorProgress, NULL, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode RunFlow(CSMesh mesh, CSOutput *out)
{
  CSConformalFlow flow;
  PetscErrorCode  ierr;
  PetscFunctionBeginUser;
  PetscCall(CSConformalFlowCreate(mesh, &flow));
  ierr = CSConformalFlowSetFromOptions(flow);
  if (!ierr) ierr = CSConformalFlowSetUp(flow);
  if (!ierr) ierr = SetMonitors(flow, out);
  if (!ierr) ierr = CSConformalFlowSolve(flow);
  if (!ierr) ierr = CSConformalFlowReport(flow, out);
  PetscCall(CSConformalFlowDestroy(&flow)); /* on every path: no leak after an error */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode CSFlowConformal(MPI_Comm comm, CSOutput *out)
{
  CSMesh         mesh;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCheck(!out->has_checkpoint && !out->has_resume, comm, PETSC_ERR_ARG_INCOMP, "-flow_type conformal: -checkpoint and -resume are not supported");
  PetscCall(CSMeshDataRefuseTargetClass(comm, NULL, "-flow_type conformal"));
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  ierr = RunFlow(mesh, out);
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}
