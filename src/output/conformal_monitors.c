/* Monitors and the report of the conformal curvature flow (include/cs_output_conformal.h). */
#include "cs_output_conformal.h"
#include "cs_energy_bs.h"

PetscErrorCode CSConformalFlowMonitorProgress(CSConformalFlow flow, const CSConformalMonitorInfo *s, void *ctx)
{
  CSMesh mesh;
  PetscFunctionBeginUser;
  if (s->event == CS_CONFORMAL_MONITOR_END) PetscFunctionReturn(0);
  PetscCall(CSConformalFlowGetMesh(flow, &mesh));
  PetscCall(PetscPrintf(mesh->comm, "conformal step %3" PetscInt_FMT "  W=%.10e  W/4pi=%.6f  gamma=%.3e  q_mean=%.4f  q_max=%.4f  |v|=%.3e  res=%.1e/%.1e/%.1e  closing=%.1e  nonexact=%.1e  q_step=%.4f  tau=%.3g  %.3f s\n", s->it, (double)s->W, (double)(s->W / (4 * PETSC_PI)), (double)s->gamma, (double)s->q_mean, (double)s->q_max, (double)s->vnorm, (double)s->res_total, (double)s->res_inversion, (double)s->res_exact, (double)s->closing, (double)s->nonexact, (double)s->q_step, (double)s->tau,
                        (double)(s->event == CS_CONFORMAL_MONITOR_STEP ? s->step_seconds : 0)));
  PetscFunctionReturn(0);
}

typedef struct {
  CSHistory hist;
  CSEnergy  bs; /* the Bobenko-Schroeder energy, column willmore_bs */
} HistoryCtx;

static PetscErrorCode MonitorHistory(CSConformalFlow flow, const CSConformalMonitorInfo *s, void *ctx)
{
  HistoryCtx *H = (HistoryCtx *)ctx;
  Vec         x;
  PetscReal   Wbs, row[22];
  PetscFunctionBeginUser;
  if (s->event == CS_CONFORMAL_MONITOR_END) PetscFunctionReturn(0);
  PetscCall(CSConformalFlowGetSolution(flow, &x));
  PetscCall(CSEnergyValue(H->bs, x, &Wbs));
  row[0]  = (PetscReal)s->it;
  row[1]  = s->W;
  row[2]  = Wbs;
  row[3]  = s->EH;
  row[4]  = s->gamma;
  row[5]  = s->q_mean;
  row[6]  = s->q_max;
  row[7]  = s->area;
  row[8]  = s->res_total;
  row[9]  = s->res_inversion;
  row[10] = s->res_exact;
  row[11] = s->closing;
  row[12] = s->log_area_spread;
  row[13] = s->vnorm;
  row[14] = s->tau;
  row[15] = s->event == CS_CONFORMAL_MONITOR_STEP ? s->step_seconds : 0;
  row[16] = s->seconds;
  row[17] = s->H_spread;
  row[18] = s->boundary_error;
  row[19] = s->nonexact;
  row[20] = (PetscReal)s->halvings;
  row[21] = s->it > 0 ? s->q_step : 1;
  PetscCall(CSHistoryAppend(H->hist, 22, row));
  PetscFunctionReturn(0);
}

static PetscErrorCode HistoryDestroy(void **ctx)
{
  HistoryCtx *H = (HistoryCtx *)*ctx;
  PetscFunctionBeginUser;
  PetscCall(CSHistoryDestroy(&H->hist));
  PetscCall(CSEnergyDestroy(&H->bs));
  PetscCall(PetscFree(*ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowMonitorSetHistory(CSConformalFlow flow, CSOutput *out)
{
  HistoryCtx *H;
  CSMesh      mesh;
  PetscFunctionBeginUser;
  if (!out->has_history && !CSHistoryCaptureActive()) PetscFunctionReturn(0); /* a library caller keeps it in memory (src/api) */
  PetscCall(CSConformalFlowGetMesh(flow, &mesh));
  PetscCall(PetscNew(&H));
  PetscCall(CSOutputHistoryCreate(out, mesh->comm, "it,willmore,willmore_bs,E_H,gamma,q_mean,q_max,area,res_total,res_inversion,res_exact,closing_error,log_area_spread,vnorm,tau,step_seconds,seconds,H_spread,boundary_error,nonexact,halvings,q_step", 0, &H->hist));
  PetscCall(CSEnergyCreateWillmoreBS(mesh, CS_BS_BOUNDARY_FIXED, 1e-6, &H->bs));
  PetscCall(CSConformalFlowMonitorSet(flow, MonitorHistory, H, HistoryDestroy));
  PetscFunctionReturn(0);
}

typedef struct {
  CSViewer v;
  Vec      q; /* per-face Q */
  PetscInt every;
} ViewerCtx;

/* every `every`-th step (0: none) and the final state (event END, unless that step was just written) */
static PetscErrorCode MonitorViewer(CSConformalFlow flow, const CSConformalMonitorInfo *s, void *ctx)
{
  ViewerCtx *V = (ViewerCtx *)ctx;
  Vec        x, H, rhodot;
  PetscBool  due = (PetscBool)(V->every > 0 && s->it % V->every == 0);
  PetscFunctionBeginUser;
  if (s->event == CS_CONFORMAL_MONITOR_END ? due : !due) PetscFunctionReturn(0);
  PetscCall(CSConformalFlowGetSolution(flow, &x));
  PetscCall(CSConformalFlowGetFields(flow, &H, &rhodot));
  PetscCall(CSConformalFlowGetQuasiConformal(flow, V->q));
  PetscCall(CSViewerAddVertexField(V->v, "rho_dot", rhodot));
  PetscCall(CSViewerAddVertexField(V->v, "H", H));
  PetscCall(CSViewerAddFaceField(V->v, "Q", V->q));
  PetscCall(CSViewerWriteStep(V->v, x, (PetscReal)s->it));
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewerDestroy(void **ctx)
{
  ViewerCtx *V = (ViewerCtx *)*ctx;
  PetscFunctionBeginUser;
  PetscCall(CSViewerDestroy(&V->v));
  PetscCall(VecDestroy(&V->q));
  PetscCall(PetscFree(*ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowMonitorSetViewer(CSConformalFlow flow, CSOutput *out, PetscInt every)
{
  ViewerCtx *V;
  CSMesh     mesh;
  PetscFunctionBeginUser;
  if (!out->has_viewer) PetscFunctionReturn(0);
  PetscCall(CSConformalFlowGetMesh(flow, &mesh));
  PetscCall(PetscNew(&V));
  V->every = every;
  PetscCall(CSViewerCreate(mesh, NULL, out->viewer_dir, &V->v));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &V->q));
  PetscCall(CSConformalFlowMonitorSet(flow, MonitorViewer, V, ViewerDestroy));
  PetscFunctionReturn(0);
}

PetscErrorCode CSConformalFlowReport(CSConformalFlow flow, CSOutput *out)
{
  CSConformalFlowConvergedReason reason;
  CSConformalFlowInfo            i;
  CSMesh                         mesh;
  Vec                            x, x0;
  PetscReal                      Wbs, sps;
  CSEnergy                       bs;
  PetscFunctionBeginUser;
  PetscCall(CSConformalFlowGetMesh(flow, &mesh));
  PetscCall(CSConformalFlowGetConvergedReason(flow, &reason));
  PetscCall(CSConformalFlowGetInfo(flow, &i));
  PetscCall(CSConformalFlowGetSolution(flow, &x));
  PetscCall(CSConformalFlowGetInitialSolution(flow, &x0));
  PetscCall(CSEnergyCreateWillmoreBS(mesh, CS_BS_BOUNDARY_FIXED, 1e-6, &bs));
  PetscCall(CSEnergyValue(bs, x, &Wbs));
  PetscCall(CSEnergyDestroy(&bs));
  sps = i.state.it ? (PetscReal)(i.step_seconds / i.state.it) : 0;
  PetscCall(PetscPrintf(mesh->comm, "conformal flow: %s (%s) after %" PetscInt_FMT " steps, W %.10g -> %.10g (W/4pi %.6f), q_mean %.6f q_max %.6f, %.4g s per step (set-up %.3g s)\n", reason > 0 ? "converged" : "NOT converged", CSConformalFlowConvergedReasons[reason], i.state.it, (double)i.W_initial, (double)i.state.W, (double)(i.state.W / (4 * PETSC_PI)), (double)i.state.q_mean,
                        (double)i.state.q_max, (double)sps, (double)i.setup_seconds));
  PetscCall(CSOutputAddMeshFacts(out, mesh, x, x0));
  PetscCall(CSJSONAddInt(out->json, "iterations", i.state.it));
  PetscCall(CSJSONAddBool(out->json, "converged", (PetscBool)(reason > 0)));
  PetscCall(CSJSONAddString(out->json, "stop_reason", CSConformalFlowConvergedReasons[reason]));
  PetscCall(CSJSONAddReal(out->json, "willmore_initial", i.W_initial));
  PetscCall(CSJSONAddReal(out->json, "willmore_bs", Wbs));
  PetscCall(CSJSONAddReal(out->json, "E_H", i.state.EH));
  PetscCall(CSJSONAddReal(out->json, "gamma", i.state.gamma));
  PetscCall(CSJSONAddReal(out->json, "res_total", i.state.res_total));
  PetscCall(CSJSONAddReal(out->json, "res_inversion", i.state.res_inversion));
  PetscCall(CSJSONAddReal(out->json, "res_exact", i.state.res_exact));
  PetscCall(CSJSONAddBool(out->json, "exactness", i.exactness));
  PetscCall(CSJSONAddReal(out->json, "log_area_spread", i.state.log_area_spread));
  PetscCall(CSJSONAddReal(out->json, "closing_error_max", i.closing_max));
  PetscCall(CSJSONAddReal(out->json, "q_step_max", i.q_step_max));
  PetscCall(CSJSONAddReal(out->json, "H_spread", i.state.H_spread));
  PetscCall(CSJSONAddReal(out->json, "boundary_error", i.state.boundary_error));
  PetscCall(CSJSONAddReal(out->json, "tau", i.tau));
  PetscCall(CSJSONAddReal(out->json, "filter_sigma", i.filter_sigma));
  PetscCall(CSJSONAddInt(out->json, "filter_k", i.filter_k));
  PetscCall(CSJSONAddBool(out->json, "mobius", i.mobius));
  PetscCall(CSJSONAddReal(out->json, "seconds_per_step", sps));
  PetscCall(CSJSONAddReal(out->json, "seconds_setup", (PetscReal)i.setup_seconds));
  PetscCall(CSOutputFinish(out, mesh, x));
  PetscFunctionReturn(0);
}
