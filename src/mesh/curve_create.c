/* The distributed curve (include/cs_curve.h): contiguous blocks of vertices, ghost gathers of the two
   neighbour vertices, creation from options, gathered output. */
#include "cs_curve.h"
#include "cs_util.h"
#include "cs_log.h"

/* scatter of the neighbour vertices rstart-1 and rstart+n (mod N) of a block-size-bs Vec into a Seq Vec */
static PetscErrorCode CreateGhostScatter(CSCurve c, PetscInt bs, VecScatter *sc, Vec *g)
{
  Vec      t;
  IS       is;
  PetscInt idx[2] = {c->gl < 0 ? 0 : c->gl, c->gr < 0 ? 0 : c->gr};
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(c->comm, bs * c->n, bs * c->N, &t));
  PetscCall(VecSetBlockSize(t, bs));
  PetscCall(ISCreateBlock(PETSC_COMM_SELF, bs, 2, idx, PETSC_COPY_VALUES, &is));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, 2 * bs, g));
  PetscCall(VecScatterCreate(t, is, *g, NULL, sc));
  PetscCall(ISDestroy(&is));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

static PetscErrorCode Distribute(CSCurve c, const CSCurveData *cd)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_MeshDistribute, 0, 0, 0, 0));
  PetscCallMPI(MPI_Comm_rank(c->comm, &rank));
  PetscCall(VecCreateMPI(c->comm, 2 * c->n, 2 * c->N, &c->x));
  PetscCall(VecSetBlockSize(c->x, 2));
  if (!rank) {
    PetscInt *idx;
    PetscCall(PetscMalloc1(2 * c->N, &idx));
    for (PetscInt i = 0; i < 2 * c->N; i++) idx[i] = i;
    PetscCall(VecSetValues(c->x, 2 * c->N, idx, cd->x, INSERT_VALUES));
    PetscCall(PetscFree(idx));
  }
  PetscCall(VecAssemblyBegin(c->x));
  PetscCall(VecAssemblyEnd(c->x));
  PetscCall(PetscLogEventEnd(CS_EVENT_MeshDistribute, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveCreate(MPI_Comm comm, const CSCurveData *cd, CSCurve *curve)
{
  CSCurve     c;
  PetscMPIInt rank, size;
  PetscInt    info[2] = {0, 0};
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(PetscNew(&c));
  c->comm = comm;
  if (!rank) {
    info[0] = cd->m;
    info[1] = cd->closed;
    PetscCall(PetscStrncpy(c->name, cd->name, sizeof(c->name)));
  }
  PetscCallMPI(MPI_Bcast(info, 2, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(c->name, (int)sizeof(c->name), MPI_CHAR, 0, comm));
  c->N      = info[0];
  c->closed = (PetscBool)info[1];
  PetscCheck(c->N >= size, comm, PETSC_ERR_ARG_SIZ, "%s: %" PetscInt_FMT " vertices on %d ranks (at least one vertex per rank)", c->name, c->N, (int)size);
  c->n = PETSC_DECIDE;
  PetscCall(PetscSplitOwnership(comm, &c->n, &c->N));
  PetscCallMPI(MPI_Scan(&c->n, &c->rstart, 1, MPIU_INT, MPI_SUM, comm));
  c->rstart -= c->n;
  c->gl = c->rstart > 0 ? c->rstart - 1 : (c->closed ? c->N - 1 : -1);
  c->gr = c->rstart + c->n < c->N ? c->rstart + c->n : (c->closed ? 0 : -1);
  PetscCall(Distribute(c, cd));
  for (PetscInt b = 0; b < 2; b++) PetscCall(CreateGhostScatter(c, b + 1, &c->sc[b], &c->g[b]));
  *curve = c;
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveGhosts(CSCurve c, Vec v, PetscReal lr[4])
{
  PetscInt           bs;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(VecGetBlockSize(v, &bs));
  PetscCheck(bs == 1 || bs == 2, c->comm, PETSC_ERR_ARG_WRONG, "CSCurveGhosts: block size %" PetscInt_FMT " (1 or 2)", bs);
  PetscCall(VecScatterBegin(c->sc[bs - 1], v, c->g[bs - 1], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(c->sc[bs - 1], v, c->g[bs - 1], INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecGetArrayRead(c->g[bs - 1], &a));
  for (PetscInt k = 0; k < 2 * bs; k++) lr[k] = PetscRealPart(a[k]);
  PetscCall(VecRestoreArrayRead(c->g[bs - 1], &a));
  for (PetscInt k = 0; k < bs; k++) {
    if (c->gl < 0) lr[k] = 0;
    if (c->gr < 0) lr[bs + k] = 0;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveCreateScalarVec(CSCurve c, Vec *v)
{
  PetscFunctionBeginUser;
  PetscCall(VecCreateMPI(c->comm, c->n, c->N, v));
  PetscFunctionReturn(0);
}

/* rank 0's copy of v (the whole vector there, empty elsewhere); destroy with VecDestroy */
static PetscErrorCode ToZero(Vec v, Vec *v0)
{
  VecScatter sc;
  PetscFunctionBeginUser;
  PetscCall(VecScatterCreateToZero(v, &sc, v0));
  PetscCall(VecScatterBegin(sc, v, *v0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, v, *v0, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterDestroy(&sc));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveWrite(CSCurve c, Vec x, Vec kappa, const char path[])
{
  Vec                x0, k0 = NULL;
  const PetscScalar *a, *k = NULL;
  PetscFunctionBeginUser;
  PetscCall(ToZero(x, &x0));
  if (kappa) PetscCall(ToZero(kappa, &k0));
  PetscCall(VecGetArrayRead(x0, &a));
  if (k0) PetscCall(VecGetArrayRead(k0, &k));
  CSRootCall(c->comm, CSCurveDataWrite(path, c->N, (const PetscReal *)a, (const PetscReal *)k, c->closed));
  if (k0) PetscCall(VecRestoreArrayRead(k0, &k));
  PetscCall(VecRestoreArrayRead(x0, &a));
  PetscCall(VecDestroy(&x0));
  PetscCall(VecDestroy(&k0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveDestroy(CSCurve *curve)
{
  CSCurve c = *curve;
  PetscFunctionBeginUser;
  if (!c) PetscFunctionReturn(0);
  PetscCall(VecDestroy(&c->x));
  for (int b = 0; b < 2; b++) {
    PetscCall(VecScatterDestroy(&c->sc[b]));
    PetscCall(VecDestroy(&c->g[b]));
  }
  PetscCall(PetscFree(c));
  *curve = NULL;
  PetscFunctionReturn(0);
}
