/* Monitors and report of the conformal curvature flow (src/output/conformal_monitors.c), set with
   CSConformalFlowMonitorSet: the progress line, the -history_csv table (it,willmore,willmore_bs,E_H,gamma,q_mean,
   q_max,area,res_total,res_inversion,res_exact,closing_error,log_area_spread,vnorm,tau,step_seconds,seconds), the ParaView series (-viewer_dir: vertex
   fields rho_dot, H, face field Q, every `every` steps and the final state), and the summary and -o of the end. */
#ifndef CS_OUTPUT_CONFORMAL_H
#define CS_OUTPUT_CONFORMAL_H
#include "cs_output.h"
#include "cs_methods_conformal.h"

PETSC_EXTERN PetscErrorCode CSConformalFlowMonitorProgress(CSConformalFlow flow, const CSConformalMonitorInfo *info, void *ctx);
/* Each Set creates its context (nothing set without -history_csv / -viewer_dir). */
PETSC_EXTERN PetscErrorCode CSConformalFlowMonitorSetHistory(CSConformalFlow flow, CSOutput *out);
PETSC_EXTERN PetscErrorCode CSConformalFlowMonitorSetViewer(CSConformalFlow flow, CSOutput *out, PetscInt every);
/* Summary keys iterations, converged, stop_reason, willmore (and the mesh facts), willmore_initial, willmore_bs,
   E_H, gamma, q_mean, q_max, res_total, res_inversion, res_exact, exactness, closing_error_max, q_step_max, log_area_spread, tau, filter_sigma, filter_k, seconds_per_step, seconds_setup;
   then -o and -summary. */
PETSC_EXTERN PetscErrorCode CSConformalFlowReport(CSConformalFlow flow, CSOutput *out);

#endif
