/* Output of the Willmore flow (src/output/willmore_*.c): monitors for CSWillmoreFlowMonitorSet (the progress
   line, the -history_csv CSV, the checkpoint writer), resume from -resume, and the report at the end (final line,
   summary keys, ParaView output, mesh facts). */
#ifndef CS_OUTPUT_WILLMORE_H
#define CS_OUTPUT_WILLMORE_H
#include "cs_output.h"
#include "cs_methods_willmore.h"

/* Each Set function creates its context and registers the monitor (destroyed with the flow). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowMonitorProgressSet(CSWillmoreFlow flow);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowMonitorHistorySet(CSWillmoreFlow flow, CSOutput *out);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowMonitorCheckpointSet(CSWillmoreFlow flow, CSOutput *out);
/* The ParaView series of -viewer_dir: with every > 0 a step every `every` iterations (a monitor), and the
   final state (CSWillmoreFlowViewerFinish, after Solve); *wv = NULL without -viewer_dir. */
typedef struct _n_CSWillmoreViewer *CSWillmoreViewer;
PETSC_EXTERN PetscErrorCode CSWillmoreFlowMonitorViewerSet(CSWillmoreFlow flow, CSOutput *out, PetscInt every, CSWillmoreViewer *wv);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowViewerFinish(CSWillmoreFlow flow, CSWillmoreViewer *wv);
/* frees the context without writing (a run refused before its first step) */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowViewerDestroy(CSWillmoreViewer *wv);
/* After SetUp, before Solve: with -resume, the state of the checkpoint. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowResume(CSWillmoreFlow flow, CSOutput *out);
/* After Solve: the last accepted state's checkpoint (with -checkpoint), the final line, the summary keys,
   -o and -summary. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowReport(CSWillmoreFlow flow, CSOutput *out);

#endif
