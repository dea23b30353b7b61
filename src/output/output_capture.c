/* The results of one run kept in memory for a caller of the library (src/api, the Python interface): the summary
   as the JSON text -summary would hold, the final positions in the input's order (with the faces) as -o would
   write them, and the history rows of -history_csv. The tasks fill it through the calls they make anyway
   (CSOutputFinish, CSOutputWriteSummary, CSOutputHistoryCreate, the curve report), so the binary and the
   library share one path; without a capture set these are no-ops. */
#include "cs_output.h"
#include "cs_curve.h"

static CSOutputCapture *Capture = NULL;

PetscErrorCode CSOutputCaptureSet(CSOutputCapture *c)
{
  PetscFunctionBeginUser;
  Capture = c;
  PetscCall(CSHistoryCaptureSet(c ? &c->history : NULL));
  PetscFunctionReturn(0);
}

PetscBool CSOutputCaptureActive(void)
{
  return Capture ? PETSC_TRUE : PETSC_FALSE;
}

PetscErrorCode CSOutputCaptureReset(CSOutputCapture *c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->summary));
  PetscCall(PetscFree(c->x));
  PetscCall(PetscFree(c->f));
  PetscCall(CSHistoryCaptureReset(&c->history));
  PetscCall(PetscMemzero(c, sizeof(*c)));
  PetscFunctionReturn(0);
}

/* rank 0: the summary as it stands (a later call replaces it: the last summary of the run is the result) */
PetscErrorCode CSOutputCaptureSummary(CSJSON js, MPI_Comm comm)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  if (!Capture) PetscFunctionReturn(0);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(0);
  PetscCall(PetscFree(Capture->summary));
  PetscCall(CSJSONGetString(js, &Capture->summary));
  PetscFunctionReturn(0);
}

/* rank 0: n points of dim coordinates from a (natural order), and nf faces f (NULL: none) */
static PetscErrorCode KeepPositions(PetscInt dim, PetscInt n, const PetscScalar *a, PetscInt nf, const PetscInt *f)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(Capture->x));
  PetscCall(PetscFree(Capture->f));
  Capture->dim = dim;
  Capture->nv  = n;
  Capture->nf  = nf;
  PetscCall(PetscMalloc1(dim * n, &Capture->x));
  for (PetscInt i = 0; i < dim * n; i++) Capture->x[i] = PetscRealPart(a[i]);
  if (nf) {
    PetscCall(PetscMalloc1(3 * nf, &Capture->f));
    PetscCall(PetscArraycpy(Capture->f, f, 3 * nf));
  }
  PetscFunctionReturn(0);
}

/* Collective: x gathered into the input's vertex order, with the faces -o writes (mesh->serial, rank 0) */
PetscErrorCode CSOutputCaptureMesh(CSMesh mesh, Vec x)
{
  Vec                nat;
  const PetscScalar *a;
  PetscMPIInt        rank;
  PetscFunctionBeginUser;
  if (!Capture) PetscFunctionReturn(0);
  PetscCall(CSMeshGather(&mesh->natV3, x, &nat));
  PetscCallMPI(MPI_Comm_rank(mesh->comm, &rank));
  if (rank) PetscFunctionReturn(0);
  PetscCall(VecGetArrayRead(nat, &a));
  PetscCall(KeepPositions(3, mesh->serial.nv, a, mesh->serial.nf, mesh->serial.f));
  PetscCall(VecRestoreArrayRead(nat, &a));
  PetscFunctionReturn(0);
}

/* Collective: the curve's points on rank 0 */
PetscErrorCode CSOutputCaptureCurve(CSCurve curve, Vec x)
{
  VecScatter         sc;
  Vec                x0;
  const PetscScalar *a;
  PetscMPIInt        rank;
  PetscFunctionBeginUser;
  if (!Capture) PetscFunctionReturn(0);
  PetscCall(VecScatterCreateToZero(x, &sc, &x0));
  PetscCall(VecScatterBegin(sc, x, x0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, x, x0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterDestroy(&sc));
  PetscCallMPI(MPI_Comm_rank(curve->comm, &rank));
  if (!rank) {
    PetscCall(VecGetArrayRead(x0, &a));
    PetscCall(KeepPositions(2, curve->N, a, 0, NULL));
    PetscCall(VecRestoreArrayRead(x0, &a));
  }
  PetscCall(VecDestroy(&x0));
  PetscFunctionReturn(0);
}
