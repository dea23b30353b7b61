/* The ParaView series of a Willmore flow (-viewer_dir DIR, -flow_viewer_every N): one CSViewer for the run, so
   the steps written during the flow and the final state land in one DIR/series.pvd. With N = 0 (the default)
   only the final state is written, as before the flow had monitors. */
#include "cs_output_willmore.h"

struct _n_CSWillmoreViewer {
  CSViewer v;
  PetscInt every, last; /* last: the iteration of the last step written, -1 before any */
};

static PetscErrorCode WriteStep(CSWillmoreFlow flow, CSWillmoreViewer V, PetscInt it)
{
  Vec x;
  PetscFunctionBeginUser;
  PetscCall(CSWillmoreFlowGetSolution(flow, &x));
  PetscCall(CSViewerWriteStep(V->v, x, (PetscReal)it));
  V->last = it;
  PetscFunctionReturn(0);
}

static PetscErrorCode MonitorViewer(CSWillmoreFlow flow, PetscInt it, void *ctx)
{
  CSWillmoreViewer V = (CSWillmoreViewer)ctx;
  PetscFunctionBeginUser;
  if (it % V->every == 0 && it != V->last) PetscCall(WriteStep(flow, V, it));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowMonitorViewerSet(CSWillmoreFlow flow, CSOutput *out, PetscInt every, CSWillmoreViewer *wv)
{
  CSMesh mesh;
  PetscFunctionBeginUser;
  *wv = NULL;
  if (!out->has_viewer) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetMesh(flow, &mesh));
  PetscCall(PetscNew(wv));
  (*wv)->every = every;
  (*wv)->last  = -1;
  PetscCall(CSViewerCreate(mesh, out->viewer_dir, &(*wv)->v));
  /* the context belongs to the caller (CSWillmoreFlowViewerFinish writes the final state with it) */
  if (every > 0) PetscCall(CSWillmoreFlowMonitorSet(flow, MonitorViewer, *wv, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowViewerFinish(CSWillmoreFlow flow, CSWillmoreViewer *wv)
{
  CSWillmoreFlowInfo i;
  PetscFunctionBeginUser;
  if (!*wv) PetscFunctionReturn(0);
  PetscCall(CSWillmoreFlowGetInfo(flow, &i));
  if (i.it != (*wv)->last) PetscCall(WriteStep(flow, *wv, i.it));
  PetscCall(CSViewerDestroy(&(*wv)->v));
  PetscCall(PetscFree(*wv));
  PetscFunctionReturn(0);
}
