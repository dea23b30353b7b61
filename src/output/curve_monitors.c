/* Monitors and the report of the curve flow (include/cs_output_curve.h). */
#include "cs_output_curve.h"

PetscErrorCode CSCurveFlowMonitorProgress(CSCurveFlow flow, const CSCurveMonitorInfo *s, void *ctx)
{
  CSCurve curve;
  PetscFunctionBeginUser;
  if (s->event == CS_CURVE_MONITOR_END) PetscFunctionReturn(0);
  PetscCall(CSCurveFlowGetCurve(flow, &curve));
  PetscCall(PetscPrintf(curve->comm, "curve step %3" PetscInt_FMT "  E=%.12e  turning=%.15g  gap=%.2e  distortion=%.2e  kappa_spread=%.2e (rel %.2e)  stationarity=%.2e  change=%.2e\n", s->it, (double)s->energy, (double)s->turning, (double)s->gap, (double)s->distortion, (double)s->spread, (double)s->spread_rel, (double)s->stationarity, (double)s->change));
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorHistory(CSCurveFlow flow, const CSCurveMonitorInfo *s, void *ctx)
{
  CSHistory h = (CSHistory)ctx;
  PetscReal row[11];
  PetscFunctionBeginUser;
  if (s->event == CS_CURVE_MONITOR_END) PetscFunctionReturn(0);
  row[0] = (PetscReal)s->it;
  row[1] = s->energy;
  row[2] = s->turning;
  row[3] = s->gap;
  row[4] = s->distortion;
  row[5] = s->spread;
  row[6] = s->spread_rel;
  row[7] = s->stationarity;
  row[8] = s->change;
  row[9] = s->event == CS_CURVE_MONITOR_STEP ? s->step_seconds : 0;
  row[10] = s->seconds;
  PetscCall(CSHistoryAppend(h, 11, row));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowMonitorSetHistory(CSCurveFlow flow, CSOutput *out)
{
  CSCurve   curve;
  CSHistory h;
  PetscFunctionBeginUser;
  if (!out->has_history && !CSHistoryCaptureActive()) PetscFunctionReturn(0); /* a library caller keeps it in memory (src/api) */
  PetscCall(CSCurveFlowGetCurve(flow, &curve));
  PetscCall(CSOutputHistoryCreate(out, curve->comm, "it,energy,turning_number,closure_gap,length_distortion,kappa_spread,kappa_spread_rel,stationarity,change,step_seconds,seconds", 0, &h));
  PetscCall(CSCurveFlowMonitorSet(flow, MonitorHistory, h, CSHistoryMonitorDestroy));
  PetscFunctionReturn(0);
}

typedef struct {
  char     dir[PETSC_MAX_PATH_LEN];
  PetscInt every;
} StepsCtx;

static PetscErrorCode MonitorSteps(CSCurveFlow flow, const CSCurveMonitorInfo *s, void *ctx)
{
  StepsCtx *S = (StepsCtx *)ctx;
  CSCurve   curve;
  Vec       x, kappa;
  char      path[PETSC_MAX_PATH_LEN + 32];
  PetscFunctionBeginUser;
  if (s->event == CS_CURVE_MONITOR_END || s->it % S->every) PetscFunctionReturn(0);
  PetscCall(CSCurveFlowGetCurve(flow, &curve));
  PetscCall(CSCurveFlowGetSolution(flow, &x));
  PetscCall(CSCurveFlowGetCurvature(flow, &kappa));
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/curve_%05" PetscInt_FMT ".txt", S->dir, s->it));
  PetscCall(CSCurveWrite(curve, x, kappa, path));
  PetscFunctionReturn(0);
}

static PetscErrorCode StepsDestroy(void **ctx)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(*ctx));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowMonitorSetSteps(CSCurveFlow flow, CSOutput *out, PetscInt every)
{
  StepsCtx *S;
  CSCurve   curve;
  PetscFunctionBeginUser;
  if (!out->has_viewer) PetscFunctionReturn(0);
  PetscCall(CSCurveFlowGetCurve(flow, &curve));
  CSRootCall(curve->comm, CSPathMakeDir(out->viewer_dir));
  PetscCall(PetscNew(&S));
  PetscCall(PetscStrncpy(S->dir, out->viewer_dir, sizeof(S->dir)));
  S->every = every;
  PetscCall(CSCurveFlowMonitorSet(flow, MonitorSteps, S, StepsDestroy));
  PetscFunctionReturn(0);
}

static PetscErrorCode ReportState(CSJSON js, const CSCurveFlowInfo *i)
{
  PetscFunctionBeginUser;
  PetscCall(CSJSONAddInt(js, "iterations", i->state.it));
  PetscCall(CSJSONAddReal(js, "energy", i->state.energy));
  PetscCall(CSJSONAddReal(js, "energy_initial", i->energy_initial));
  PetscCall(CSJSONAddReal(js, "turning_number", i->state.turning));
  PetscCall(CSJSONAddInt(js, "turning_number_initial", i->turning_initial));
  PetscCall(CSJSONAddReal(js, "closure_gap_max", i->gap_max));
  PetscCall(CSJSONAddReal(js, "max_length_distortion", i->distortion_max));
  PetscCall(CSJSONAddReal(js, "length_distortion", i->state.distortion));
  PetscCall(CSJSONAddReal(js, "kappa_spread", i->state.spread));
  PetscCall(CSJSONAddReal(js, "kappa_spread_rel", i->state.spread_rel));
  PetscCall(CSJSONAddReal(js, "stationarity", i->state.stationarity));
  PetscCall(CSJSONAddReal(js, "seconds_per_step", i->state.it ? (PetscReal)(i->step_seconds / i->state.it) : 0));
  PetscCall(CSJSONAddReal(js, "seconds_setup", (PetscReal)i->setup_seconds));
  PetscCall(CSJSONAddReal(js, "length", i->length));
  PetscCall(CSJSONAddReal(js, "tau", i->tau));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveFlowReport(CSCurveFlow flow, CSOutput *out)
{
  CSCurveFlowConvergedReason reason;
  CSCurveFlowInfo            i;
  CSCurve                    curve;
  Vec                        x;
  PetscFunctionBeginUser;
  PetscCall(CSCurveFlowGetCurve(flow, &curve));
  PetscCall(CSCurveFlowGetConvergedReason(flow, &reason));
  PetscCall(CSCurveFlowGetInfo(flow, &i));
  PetscCall(CSCurveFlowGetSolution(flow, &x));
  PetscCall(PetscPrintf(curve->comm, "curve flow: %s (%s) after %" PetscInt_FMT " steps, E=%.12g, turning number %.15g, max length distortion %.3e, %.3g ms per step (set-up %.3g ms)\n", reason > 0 ? "converged" : "NOT converged", CSCurveFlowConvergedReasons[reason], i.state.it, (double)i.state.energy, (double)i.state.turning, (double)i.distortion_max,
                        i.state.it ? 1e3 * (double)i.step_seconds / (double)i.state.it : 0.0, 1e3 * (double)i.setup_seconds));
  PetscCall(CSJSONAddString(out->json, "curve", curve->name));
  PetscCall(CSJSONAddInt(out->json, "vertices", curve->N));
  PetscCall(CSJSONAddBool(out->json, "closed", curve->closed));
  PetscCall(CSJSONAddBool(out->json, "converged", (PetscBool)(reason > 0)));
  PetscCall(CSJSONAddString(out->json, "stop_reason", CSCurveFlowConvergedReasons[reason]));
  PetscCall(ReportState(out->json, &i));
  PetscCall(CSOutputAddRunFacts(out, curve->comm));
  if (out->has_out) {
    PetscCall(CSCurveWrite(curve, x, NULL, out->out));
    PetscCall(PetscPrintf(curve->comm, "wrote curve %s\n", out->out));
  }
  PetscCall(CSOutputCaptureCurve(curve, x));
  PetscCall(CSOutputWriteSummary(out, curve->comm));
  PetscFunctionReturn(0);
}
