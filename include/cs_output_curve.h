/* Monitors and report of the curve flow (src/output/curve_monitors.c), set with CSCurveFlowMonitorSet: the
   progress line, the -history_csv table (it,energy,turning_number,closure_gap,length_distortion,kappa_spread,
   kappa_spread_rel,stationarity,change,step_seconds,seconds), the curve of every `every`-th state as
   DIR/curve_NNNNN.txt (x y kappa; -viewer_dir DIR), and the summary and -o of the end. */
#ifndef CS_OUTPUT_CURVE_H
#define CS_OUTPUT_CURVE_H
#include "cs_output.h"
#include "cs_methods_curve.h"

PETSC_EXTERN PetscErrorCode CSCurveFlowMonitorProgress(CSCurveFlow flow, const CSCurveMonitorInfo *info, void *ctx);
/* Each Set creates its context (nothing set without -history_csv / -viewer_dir). */
PETSC_EXTERN PetscErrorCode CSCurveFlowMonitorSetHistory(CSCurveFlow flow, CSOutput *out);
PETSC_EXTERN PetscErrorCode CSCurveFlowMonitorSetSteps(CSCurveFlow flow, CSOutput *out, PetscInt every);
/* Summary keys (iterations, converged, stop_reason, energy, energy_initial, turning_number, closure_gap_max,
   max_length_distortion, kappa_spread, kappa_spread_rel, stationarity, seconds_per_step, seconds_setup,
   vertices, closed, length, tau, ranks, seconds), then -o (.obj or text) and -summary. */
PETSC_EXTERN PetscErrorCode CSCurveFlowReport(CSCurveFlow flow, CSOutput *out);

#endif
