/* Y += a X with fixed nonzero patterns (include/cs_linalg.h): the flow's Schur complement
   S = H/t + X^T D X is refilled from its two terms at every refactorisation. */
#include "cs_linalg.h"

struct _p_CSMatAddMap {
  PetscObjectId    yid, xid;      /* the matrices' ids (not their addresses, which a new matrix may reuse) */
  PetscObjectState ystate, xstate; /* nonzero states at creation */
  PetscInt         nblk;          /* 1 (Seq) or 2 (MPI: diagonal and off-diagonal blocks) */
  PetscInt         nz[2];
  PetscInt        *pos[2];        /* for each entry of X's block b, its index in Y's block b value array */
};

/* the blocks of an AIJ matrix and, for the off-diagonal one, its local-to-global column map */
static PetscErrorCode GetBlocks(Mat A, PetscInt *nblk, Mat blk[2], const PetscInt *garray[2])
{
  PetscBool mpi;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)A, MATMPIAIJ, &mpi));
  if (mpi) {
    PetscCall(MatMPIAIJGetSeqAIJ(A, &blk[0], &blk[1], &garray[1]));
    garray[0] = NULL;
    *nblk     = 2;
  } else {
    PetscBool seq;
    MatType   type;
    PetscCall(PetscObjectBaseTypeCompare((PetscObject)A, MATSEQAIJ, &seq));
    PetscCall(MatGetType(A, &type));
    PetscCheck(seq, PetscObjectComm((PetscObject)A), PETSC_ERR_SUP, "CSMatAddFixedPattern: AIJ matrices only, not %s", type);
    blk[0]    = A;
    garray[0] = NULL;
    *nblk     = 1;
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode BuildBlockMap(Mat Yb, const PetscInt *yg, Mat Xb, const PetscInt *xg, PetscInt *nz, PetscInt **pos)
{
  const PetscInt *yi, *yj, *xi, *xj;
  PetscInt        ny, nx;
  PetscBool       done;
  PetscFunctionBeginUser;
  PetscCall(MatGetRowIJ(Yb, 0, PETSC_FALSE, PETSC_FALSE, &ny, &yi, &yj, &done));
  PetscCall(MatGetRowIJ(Xb, 0, PETSC_FALSE, PETSC_FALSE, &nx, &xi, &xj, &done));
  PetscCheck(nx == ny, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "CSMatAddFixedPattern: %" PetscInt_FMT " vs %" PetscInt_FMT " local rows", nx, ny);
  *nz = xi[nx];
  PetscCall(PetscMalloc1(*nz, pos));
  for (PetscInt r = 0; r < nx; r++) {
    for (PetscInt k = xi[r]; k < xi[r + 1]; k++) {
      PetscInt c = xg ? xg[xj[k]] : xj[k], lo = yi[r], hi = yi[r + 1] - 1, found = -1;
      while (lo <= hi) { /* the columns of a row are ascending; so are garray's global numbers */
        PetscInt mid = (lo + hi) / 2, cm = yg ? yg[yj[mid]] : yj[mid];
        if (cm == c) {
          found = mid;
          break;
        }
        if (cm < c) lo = mid + 1;
        else hi = mid - 1;
      }
      PetscCheck(found >= 0, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "CSMatAddFixedPattern: X has entry (%" PetscInt_FMT ", global column %" PetscInt_FMT ") outside Y's pattern", r, c);
      (*pos)[k] = found;
    }
  }
  PetscCall(MatRestoreRowIJ(Yb, 0, PETSC_FALSE, PETSC_FALSE, &ny, &yi, &yj, &done));
  PetscCall(MatRestoreRowIJ(Xb, 0, PETSC_FALSE, PETSC_FALSE, &nx, &xi, &xj, &done));
  PetscFunctionReturn(0);
}

/* The values were written into Y's blocks, whose states rose; Y's own state must rise too, or a PC built on Y
   would not see the new values (PCSetUp compares the state). A final assembly does it with public calls: the pattern
   is unchanged, so AIJ's assembly returns at once on each block and Y's nonzero state stays; it forgets the
   symmetry/SPD flags the caller set, which are restored. */
static PetscErrorCode BumpState(Mat Y)
{
  PetscBool sym_set, sym, spd_set, spd;
  PetscFunctionBeginUser;
  PetscCall(MatIsSymmetricKnown(Y, &sym_set, &sym));
  PetscCall(MatIsSPDKnown(Y, &spd_set, &spd));
  PetscCall(MatAssemblyBegin(Y, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(Y, MAT_FINAL_ASSEMBLY));
  if (sym_set) PetscCall(MatSetOption(Y, MAT_SYMMETRIC, sym));
  if (spd_set) PetscCall(MatSetOption(Y, MAT_SPD, spd));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMatAddFixedPattern(Mat Y, PetscScalar a, Mat X, CSMatAddMap *map)
{
  Mat              yb[2], xb[2];
  const PetscInt  *yg[2], *xg[2];
  PetscInt         ny, nx;
  PetscObjectState ys, xs;
  PetscObjectId    yid, xid;
  CSMatAddMap      m = *map;
  PetscFunctionBeginUser;
  PetscCall(GetBlocks(Y, &ny, yb, yg));
  PetscCall(GetBlocks(X, &nx, xb, xg));
  PetscCheck(nx == ny, PetscObjectComm((PetscObject)Y), PETSC_ERR_ARG_INCOMP, "CSMatAddFixedPattern: matrices of different types");
  PetscCall(MatGetNonzeroState(Y, &ys));
  PetscCall(MatGetNonzeroState(X, &xs));
  PetscCall(PetscObjectGetId((PetscObject)Y, &yid));
  PetscCall(PetscObjectGetId((PetscObject)X, &xid));
  if (m && (m->yid != yid || m->xid != xid || m->ystate != ys || m->xstate != xs)) PetscCall(CSMatAddMapDestroy(map)); /* a new pattern */
  m = *map;
  if (!m) {
    PetscCall(PetscNew(&m));
    m->yid    = yid;
    m->xid    = xid;
    m->ystate = ys;
    m->xstate = xs;
    m->nblk   = ny;
    for (PetscInt b = 0; b < ny; b++) PetscCall(BuildBlockMap(yb[b], yg[b], xb[b], xg[b], &m->nz[b], &m->pos[b]));
    *map = m;
  }
  for (PetscInt b = 0; b < m->nblk; b++) {
    PetscScalar       *ya;
    const PetscScalar *xa;
    PetscCall(MatSeqAIJGetArray(yb[b], &ya));
    PetscCall(MatSeqAIJGetArrayRead(xb[b], &xa));
    for (PetscInt k = 0; k < m->nz[b]; k++) ya[m->pos[b][k]] += a * xa[k];
    PetscCall(MatSeqAIJRestoreArrayRead(xb[b], &xa));
    PetscCall(MatSeqAIJRestoreArray(yb[b], &ya));
  }
  PetscCall(BumpState(Y));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMatAddMapDestroy(CSMatAddMap *map)
{
  PetscFunctionBeginUser;
  if (!*map) PetscFunctionReturn(0);
  for (PetscInt b = 0; b < (*map)->nblk; b++) PetscCall(PetscFree((*map)->pos[b]));
  PetscCall(PetscFree(*map));
  PetscFunctionReturn(0);
}
