/* -task flow: -flow_type chooses a driver through a PetscFunctionList. cgd|pgd|gd (soliman2021): the mesh and
   the output from the options, a CSWillmoreFlow on that mesh with the output's monitors; bs
   (Bobenko-Schroeder): CSFlowBS (src/driver/task_flow_bs.c); conformal (crane2013): CSFlowConformal
   (src/driver/task_flow_conformal.c). */
#include "cs_driver.h"
#include "cs_output_willmore.h"
#include "cs_methods_bs.h"
#include "cs_geometry.h"

/* After an error: -o only for a state that is a finite immersion (a triangle field's reconstruction is one only when
   the field is integrable, willmore_report.c CheckImmersion); the summary is written either way. */
static PetscErrorCode KeepOnlyAnImmersion(CSWillmoreFlow flow, CSMesh mesh, CSOutput *out, Vec x)
{
  CSWillmoreFlowTriangleFieldInfo tf;
  PetscReal                       big;
  PetscBool                       finite, immersion, is;
  PetscFunctionBeginUser;
  if (!out->has_out) PetscFunctionReturn(0);
  PetscCall(VecNorm(x, NORM_INFINITY, &big));
  PetscCall(CSWillmoreFlowTriangleFieldGetInfo(flow, &tf, &is)); /* another kind: tf says immersion */
  finite    = (PetscBool)!PetscIsInfOrNanReal(big);
  immersion = CSWillmoreFlowTriangleFieldInfoIsImmersion(&tf);
  if (finite && immersion) PetscFunctionReturn(0);
  PetscCall(PetscPrintf(mesh->comm, "flow: -o %s is not written: the last state %s\n", out->out, finite ? "is a triangle field that is not integrable (-flow_immersion_tol)" : "is not finite"));
  out->has_out = PETSC_FALSE;
  PetscFunctionReturn(0);
}

/* the solve; after an error the last accepted state is written (CSOutputSaveAfterError), then the error raised */
static PetscErrorCode SolveOrSave(CSWillmoreFlow flow, CSWillmoreViewer *wv, CSOutput *out)
{
  PetscErrorCode     ierr;
  CSWillmoreFlowInfo info;
  CSMesh             mesh;
  Vec                x;
  char               msg[1024];
  PetscFunctionBeginUser;
  CSCaptureError(ierr, CSWillmoreFlowSolve(flow));
  if (!ierr) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetInfo(flow, &info));
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(CSWillmoreFlowViewerFinish(flow, wv));
  PetscCall(KeepOnlyAnImmersion(flow, mesh, out, x));
  PetscCall(CSOutputSaveAfterError(out, mesh, x, info.it, ierr, msg, sizeof(msg)));
  SETERRQ(mesh->comm, ierr, "%s", msg);
}

static PetscErrorCode SetMonitors(CSWillmoreFlow flow, CSOutput *out, CSWillmoreViewer *wv)
{
  PetscInt       every;
  const char    *prefix;
  CSMesh         mesh;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(CSWillmoreFlowGetOptionsPrefix(flow, &prefix));
  /* the viewer reads its options first: the last ones of the task, then the check, before any file is created */
  PetscCall(CSOutputViewerEvery(mesh->comm, prefix, "Willmore flow output", "With -viewer_dir: a ParaView step every this many iterations (0: the final state only)", PETSC_TRUE, &every));
  PetscCall(CSWillmoreFlowMonitorViewerSet(flow, out, every, wv));
  ierr = CSFlowCheckUnusedOptions(mesh->comm);
  if (ierr) PetscCall(CSWillmoreFlowViewerDestroy(wv)); /* nothing written, no leak */
  PetscCall(ierr);
  PetscCall(CSWillmoreFlowMonitorProgressSet(flow));
  PetscCall(CSWillmoreFlowMonitorHistorySet(flow, out));
  PetscCall(CSWillmoreFlowMonitorCheckpointSet(flow, out));
  PetscFunctionReturn(0);
}

static PetscErrorCode CSFlowWillmoreRun(CSMesh mesh, CSOutput *out)
{
  CSWillmoreFlow   flow;
  CSWillmoreViewer wv = NULL;
  PetscErrorCode   ierr;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowCreate(mesh, &flow));
  ierr = CSWillmoreFlowSetFromOptions(flow);
  if (!ierr) ierr = CSWillmoreFlowSetUp(flow);
  if (!ierr) ierr = CSWillmoreFlowResume(flow, out);
  if (!ierr) ierr = CSWillmoreFlowView(flow, NULL);
  if (!ierr) ierr = SetMonitors(flow, out, &wv);
  if (!ierr) ierr = SolveOrSave(flow, &wv, out);
  if (!ierr) ierr = CSWillmoreFlowViewerFinish(flow, &wv);
  if (!ierr) ierr = CSWillmoreFlowReport(flow, out);
  PetscCall(CSWillmoreFlowDestroy(&flow)); /* on every path: no leak after an error */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

/* cgd, pgd, gd: the flow reads its own -flow_type */
static PetscErrorCode CSFlowWillmore(MPI_Comm comm, CSOutput *out)
{
  CSMesh         mesh;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &mesh));
  ierr = CSMeshQualityCheck(mesh, NULL, mesh->x);
  if (!ierr) ierr = CSTriangleQualityWarnStall(mesh, mesh->x); /* issue 35: slivers stall the flow at its start */
  if (!ierr) ierr = CSFlowWillmoreRun(mesh, out);
  if (ierr) PetscCall(CSMeshDestroy(&mesh)); /* no leak on the error path */
  PetscCall(ierr);
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

static PetscFunctionList CSFlowList = NULL;
static char              CSFlowType[64] = "cgd"; /* -flow_type of this run, for the message of the options check */

/* Every option of the flow has been read (the mesh, the output, the flow and its monitors): one given and not used
   is refused before the first step (issue 36, item 18). */
PetscErrorCode CSFlowCheckUnusedOptions(MPI_Comm comm)
{
  char task[96];
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(task, sizeof(task), "-task flow -flow_type %s", CSFlowType));
  PetscCall(CSOptionsCheckUnused(comm, task));
  PetscFunctionReturn(0);
}

static PetscErrorCode FlowListDestroy(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFunctionListDestroy(&CSFlowList));
  PetscFunctionReturn(0);
}

static PetscErrorCode FlowRegisterAll(void)
{
  PetscFunctionBeginUser;
  if (CSFlowList) PetscFunctionReturn(0);
  { /* every kind of the Willmore flow (cgd, pgd, gd, newton, alm, the fairing baselines) is a flow type */
    PetscFunctionList kinds;
    const char      **names;
    int               n;
    PetscCall(CSWillmoreFlowGetTypeList(&kinds));
    PetscCall(PetscFunctionListGet(kinds, &names, &n));
    for (int i = 0; i < n; i++)
      if (names[i] && names[i][0]) PetscCall(PetscFunctionListAdd(&CSFlowList, names[i], CSFlowWillmore));
    PetscCall(PetscFree(names));
  }
  PetscCall(PetscFunctionListAdd(&CSFlowList, "bs", CSFlowBS));
  PetscCall(PetscFunctionListAdd(&CSFlowList, "conformal", CSFlowConformal));
  PetscCall(PetscRegisterFinalize(FlowListDestroy));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTaskFlow(MPI_Comm comm)
{
  char           type[64] = "cgd";
  CSOutput       out;
  PetscErrorCode (*run)(MPI_Comm, CSOutput *) = NULL;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(FlowRegisterAll());
  PetscOptionsBegin(comm, NULL, "confsurf flow", NULL);
  PetscCall(PetscOptionsFList("-flow_type", "Flow", NULL, CSFlowList, type, type, sizeof(type), NULL));
  PetscOptionsEnd();
  PetscCall(PetscFunctionListFind(CSFlowList, type, &run));
  PetscCall(PetscStrncpy(CSFlowType, type, sizeof(CSFlowType)));
  if (!run) {
    char known[256];
    PetscCall(CSFunctionListNames(CSFlowList, known, sizeof(known)));
    SETERRQ(comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_type %s: unknown flow (known: %s)", type, known);
  }
  PetscCall(CSOutputFromOptions(comm, &out));
  ierr = (*run)(comm, &out);
  if (ierr) PetscCall(CSOutputDestroy(&out)); /* no leak on the error path */
  PetscCall(ierr);
  PetscCall(CSOutputDestroy(&out));
  PetscFunctionReturn(0);
}
