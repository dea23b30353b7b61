/* Row stacking and block expansion of distributed AIJ matrices (include/cs_linalg.h). */
#include "cs_linalg.h"

/* Preallocation of the stacked matrix: per local row the entries in / outside the diagonal column block. */
static PetscErrorCode StackPrealloc(PetscInt n, Mat B[], PetscInt nloc, PetscInt **dnz, PetscInt **onz)
{
  PetscInt cs, ce, r = 0;
  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRangeColumn(B[0], &cs, &ce));
  PetscCall(PetscCalloc2(nloc, dnz, nloc, onz));
  for (PetscInt b = 0; b < n; b++) {
    PetscInt rstart, rend;
    PetscCall(MatGetOwnershipRange(B[b], &rstart, &rend));
    for (PetscInt i = rstart; i < rend; i++, r++) {
      PetscInt        ncols;
      const PetscInt *cols;
      PetscCall(MatGetRow(B[b], i, &ncols, &cols, NULL));
      for (PetscInt k = 0; k < ncols; k++) {
        if (cols[k] >= cs && cols[k] < ce) (*dnz)[r]++;
        else (*onz)[r]++;
      }
      PetscCall(MatRestoreRow(B[b], i, &ncols, &cols, NULL));
    }
  }
  PetscFunctionReturn(0);
}

/* X = [B_0; B_1; ...] with the rows of each rank in the order: its owned rows of B_0, then of B_1, ... (so a
   vector of X's row layout is the per-rank concatenation of the blocks' local parts). All B_b have the same
   column layout. MAT_REUSE_MATRIX refills *X (the blocks' patterns unchanged). */
PetscErrorCode CSMatStackRows(PetscInt n, Mat B[], MatReuse reuse, Mat *X)
{
  PetscInt nloc = 0, rs, off = 0;
  MPI_Comm comm;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)B[0], &comm));
  for (PetscInt b = 0; b < n; b++) {
    PetscInt m;
    PetscCall(MatGetLocalSize(B[b], &m, NULL));
    nloc += m;
  }
  if (reuse == MAT_INITIAL_MATRIX) {
    PetscInt *dnz, *onz, nc, Nc;
    PetscCall(StackPrealloc(n, B, nloc, &dnz, &onz));
    PetscCall(MatGetLocalSize(B[0], NULL, &nc));
    PetscCall(MatGetSize(B[0], NULL, &Nc));
    PetscCall(MatCreateAIJ(comm, nloc, nc, PETSC_DETERMINE, Nc, 0, dnz, 0, onz, X));
    PetscCall(PetscFree2(dnz, onz));
  } else PetscCall(MatZeroEntries(*X));
  PetscCall(MatGetOwnershipRange(*X, &rs, NULL));
  for (PetscInt b = 0; b < n; b++) {
    PetscInt rstart, rend;
    PetscCall(MatGetOwnershipRange(B[b], &rstart, &rend));
    for (PetscInt i = rstart; i < rend; i++, off++) {
      PetscInt           ncols, row = rs + off;
      const PetscInt    *cols;
      const PetscScalar *vals;
      PetscCall(MatGetRow(B[b], i, &ncols, &cols, &vals));
      PetscCall(MatSetValues(*X, 1, &row, ncols, cols, vals, INSERT_VALUES));
      PetscCall(MatRestoreRow(B[b], i, &ncols, &cols, &vals));
    }
  }
  PetscCall(MatAssemblyBegin(*X, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*X, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* B = A (x) I_bs on interlaced vectors: B(bs i + c, bs j + c) = A(i, j), an AIJ matrix (MatCreateMAIJ converted),
   rows and columns laid out like A's with bs entries per row / column. MAT_REUSE_MATRIX refills *B. */
PetscErrorCode CSMatKronIdentity(Mat A, PetscInt bs, MatReuse reuse, Mat *B)
{
  Mat M;
  PetscFunctionBeginUser;
  PetscCall(MatCreateMAIJ(A, bs, &M));
  if (reuse == MAT_INITIAL_MATRIX) PetscCall(MatConvert(M, MATAIJ, MAT_INITIAL_MATRIX, B));
  else {
    Mat T;
    PetscCall(MatConvert(M, MATAIJ, MAT_INITIAL_MATRIX, &T));
    PetscCall(MatCopy(T, *B, SAME_NONZERO_PATTERN));
    PetscCall(MatDestroy(&T));
  }
  PetscCall(MatDestroy(&M));
  PetscFunctionReturn(0);
}
