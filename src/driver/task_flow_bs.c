/* -task flow -flow_type bs: the Bobenko-Schroeder flow (bobenko-schroeder2005 Sec. 4) on the mesh of -mesh/-gen,
   with the monitors of src/output/bs_monitors.c. Summary keys: willmore_bs (the flow's energy, with the
   infinity terms for -bs_boundary free), iterations, converged, stop_reason, rejected, fixed_vertices,
   dt_final, seconds_per_step (stepping wall time over accepted + rejected steps), scheme, boundary, and the
   mesh facts (xref = the input positions). */
#include "cs_driver.h"
#include "cs_output_bs.h"

static PetscErrorCode SetMonitors(CSBSFlow flow, CSOutput *out)
{
  const char *prefix;
  PetscInt    every;
  CSMesh      mesh;
  PetscFunctionBeginUser;
  PetscCall(CSBSFlowGetMesh(flow, &mesh));
  PetscCall(CSBSFlowGetOptionsPrefix(flow, &prefix));
  PetscCall(CSOutputViewerEvery(mesh->comm, prefix, "Bobenko-Schroeder flow output", "Write a ParaView step every this many steps (with -viewer_dir)", PETSC_FALSE, &every));
  PetscCall(CSBSFlowMonitorSetViewer(flow, out, every));
  PetscCall(CSFlowCheckUnusedOptions(mesh->comm)); /* the last options read; before the history file is created */
  PetscCall(CSBSFlowMonitorSetHistory(flow, out));
  PetscCall(CSBSFlowMonitorSet(flow, CSBSFlowMonitorProgress, NULL, NULL));
  PetscCall(CSBSFlowMonitorSetCheckpoint(flow, out));
  PetscFunctionReturn(0);
}

static PetscErrorCode Report(CSBSFlow flow, CSMesh mesh, CSOutput *out)
{
  CSBSConvergedReason reason;
  CSBSFlowInfo        i;
  PetscLogDouble      t;
  const char         *scheme;
  Vec                 x;
  PetscFunctionBeginUser;
  PetscCall(CSBSFlowGetConvergedReason(flow, &reason));
  PetscCall(CSBSFlowGetInfo(flow, &i));
  PetscCall(CSBSFlowGetStepSeconds(flow, &t));
  PetscCall(CSBSFlowGetSchemeName(flow, &scheme));
  PetscCall(CSBSFlowGetSolution(flow, &x));
  PetscCall(PetscPrintf(mesh->comm, "bs flow: %s after %" PetscInt_FMT " steps (%s; %" PetscInt_FMT " rejected), willmore_bs=%.12g, %.3g s per step\n", reason > 0 ? "converged" : "NOT converged", i.it, CSBSConvergedReasons[reason], i.rejected, (double)i.W, (double)(i.it + i.rejected ? t / (i.it + i.rejected) : 0)));
  PetscCall(CSOutputAddMeshFacts(out, mesh, x, mesh->x));
  PetscCall(CSJSONAddReal(out->json, "willmore_bs", i.W));
  PetscCall(CSJSONAddInt(out->json, "iterations", i.it));
  PetscCall(CSJSONAddBool(out->json, "converged", (PetscBool)(reason > 0)));
  PetscCall(CSJSONAddString(out->json, "stop_reason", CSBSConvergedReasons[reason]));
  PetscCall(CSJSONAddInt(out->json, "rejected", i.rejected));
  PetscCall(CSJSONAddInt(out->json, "fixed_vertices", i.nfixed));
  PetscCall(CSJSONAddReal(out->json, "dt_final", i.dt));
  PetscCall(CSJSONAddReal(out->json, "seconds_per_step", i.it + i.rejected ? (PetscReal)t / (i.it + i.rejected) : 0));
  PetscCall(CSJSONAddString(out->json, "scheme", scheme));
  PetscCall(CSJSONAddString(out->json, "boundary", CSBSBoundaries[i.bc]));
  {
    CSEnergy  bs;
    Vec       wk;
    PetscReal wkmin;
    PetscInt  nneg;
    PetscCall(CSBSFlowGetEnergy(flow, &bs));
    PetscCall(DMCreateGlobalVector(mesh->dmV1, &wk));
    PetscCall(CSEnergyWillmoreBSGaussBound(bs, x, wk, &wkmin, &nneg)); /* Sec. 2: W_i + K_i >= 0 */
    PetscCall(CSJSONAddReal(out->json, "w_plus_k_min", wkmin));
    PetscCall(CSJSONAddInt(out->json, "w_plus_k_negative", nneg));
    PetscCall(VecDestroy(&wk));
  }
  PetscCall(CSOutputFinish(out, mesh, x));
  PetscFunctionReturn(0);
}

static PetscErrorCode RunFlow(CSMesh mesh, CSOutput *out)
{
  CSBSFlow       flow;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(CSBSFlowCreate(mesh, &flow));
  ierr = CSBSFlowSetFromOptions(flow);
  if (!ierr) ierr = CSBSFlowSetUp(flow);
  if (!ierr) ierr = CSBSFlowResume(flow, out); /* before the history, which continues a resumed run */
  if (!ierr) ierr = SetMonitors(flow, out);
  if (!ierr) {
    CSCaptureError(ierr, CSBSFlowSolve(flow));
    if (ierr) { /* the last accepted state to -o and -summary, then the error */
      CSBSFlowInfo i;
      Vec          x;
      char         msg[1024];
      PetscCall(CSBSFlowGetInfo(flow, &i));
      PetscCall(CSBSFlowGetSolution(flow, &x));
      PetscCall(CSOutputSaveAfterError(out, mesh, x, i.it, ierr, msg, sizeof(msg)));
      PetscCall(CSBSFlowDestroy(&flow));
      SETERRQ(mesh->comm, ierr, "%s", msg);
    }
  }
  if (!ierr) ierr = Report(flow, mesh, out);
  PetscCall(CSBSFlowDestroy(&flow)); /* on every path: no leak after an error */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode CSFlowBS(MPI_Comm comm, CSOutput *out)
{
  CSMesh         mesh;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(CSMeshDataRefuseTargetClass(comm, NULL, "-flow_type bs"));
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  ierr = CSMeshQualityCheck(mesh, NULL, mesh->x);
  if (!ierr) ierr = RunFlow(mesh, out);
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}
