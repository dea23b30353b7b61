/* Monitors of the Bobenko-Schroeder flow (src/output/bs_monitors.c), set with CSBSFlowMonitorSet: the progress
   line, the -history_csv table (it,willmore_bs,willmore,area,dt,ksp_its,seconds), the ParaView series (vertex
   field W_i every `every` steps) and the checkpoint of the semi scheme; and the resume from -resume. */
#ifndef CS_OUTPUT_BS_H
#define CS_OUTPUT_BS_H
#include "cs_output.h"
#include "cs_methods_bs.h"

PETSC_EXTERN PetscErrorCode CSBSFlowMonitorProgress(CSBSFlow flow, const CSBSMonitorInfo *info, void *ctx);
/* Each Set creates its context (NULL and nothing set without -history_csv / -viewer_dir / -checkpoint). */
PETSC_EXTERN PetscErrorCode CSBSFlowMonitorSetHistory(CSBSFlow flow, CSOutput *out);
PETSC_EXTERN PetscErrorCode CSBSFlowMonitorSetViewer(CSBSFlow flow, CSOutput *out, PetscInt every);
PETSC_EXTERN PetscErrorCode CSBSFlowMonitorSetCheckpoint(CSBSFlow flow, CSOutput *out);
/* -resume for the semi scheme (after CSBSFlowSetUp, before the history monitor); the TAO scheme refuses
   -checkpoint/-resume. */
PETSC_EXTERN PetscErrorCode CSBSFlowResume(CSBSFlow flow, CSOutput *out);

#endif
