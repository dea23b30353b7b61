/* A - sigma I as a SeqAIJ matrix that shares A's row structure (include/cs_linalg.h): only the values are copied,
   the diagonal shifted in place. The matrix a shift-and-invert factorisation is built from, without the
   MatDuplicate + MatShift of SLEPc's ST_MATMODE_COPY (measurements: docs/solvers.md, csquat). */
#include "cs_linalg.h"

#define PARENT "CSMatShiftedParent"

/* the value array positions of A's diagonal entries; an error naming the first row without one */
static PetscErrorCode DiagonalPositions(PetscInt m, const PetscInt *ia, const PetscInt *ja, PetscInt *diag)
{
  PetscFunctionBeginUser;
  for (PetscInt r = 0; r < m; r++) {
    PetscInt lo = ia[r], hi = ia[r + 1];
    while (lo < hi) { /* columns ascend within a row */
      const PetscInt mid = lo + (hi - lo) / 2;
      if (ja[mid] < r) lo = mid + 1;
      else hi = mid;
    }
    PetscCheck(lo < ia[r + 1] && ja[lo] == r, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "CSMatShiftedShared: row %" PetscInt_FMT " stores no diagonal entry", r);
    diag[r] = lo;
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSMatShiftedShared(Mat A, PetscScalar shift, MatReuse reuse, Mat *S)
{
  const PetscInt    *ia, *ja;
  const PetscScalar *aa;
  PetscScalar       *sa;
  PetscInt           m, n, *diag;
  PetscBool          seq;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)A, MATSEQAIJ, &seq));
  PetscCheck(seq, PetscObjectComm((PetscObject)A), PETSC_ERR_SUP, "CSMatShiftedShared: SeqAIJ matrices only");
  PetscCall(MatGetSize(A, &m, &n));
  PetscCheck(m == n, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "CSMatShiftedShared: matrix of size %" PetscInt_FMT " x %" PetscInt_FMT " is not square", m, n);
  PetscCall(MatSeqAIJGetCSRAndMemType(A, &ia, &ja, NULL, NULL));
  PetscCall(MatSeqAIJGetArrayRead(A, &aa));
  if (reuse == MAT_INITIAL_MATRIX) {
    PetscContainer owner;
    PetscInt       bs;
    PetscCall(PetscMalloc1(ia[m], &sa));
    /* S uses A's i and j in place and never changes its pattern; A, composed on S, keeps them alive; the
       container frees S's values with S */
    PetscCall(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, m, n, (PetscInt *)ia, (PetscInt *)ja, sa, S));
    PetscCall(MatGetBlockSize(A, &bs));
    PetscCall(MatSetBlockSize(*S, bs));
    PetscCall(MatSetOption(*S, MAT_NEW_NONZERO_LOCATIONS, PETSC_FALSE));
    PetscCall(PetscObjectCompose((PetscObject)*S, PARENT, (PetscObject)A));
    PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &owner));
    PetscCall(PetscContainerSetPointer(owner, sa));
    PetscCall(PetscContainerSetUserDestroy(owner, PetscContainerUserDestroyDefault));
    PetscCall(PetscObjectCompose((PetscObject)*S, "CSMatShiftedValues", (PetscObject)owner));
    PetscCall(PetscContainerDestroy(&owner));
    PetscCall(MatPropagateSymmetryOptions(A, *S));
  } else {
    PetscObject parent;
    PetscCall(PetscObjectQuery((PetscObject)*S, PARENT, &parent));
    PetscCheck(parent == (PetscObject)A, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "CSMatShiftedShared: MAT_REUSE_MATRIX with a matrix made from another one");
  }
  PetscCall(MatSeqAIJGetArrayWrite(*S, &sa));
  PetscCall(PetscArraycpy(sa, aa, ia[m]));
  PetscCall(PetscMalloc1(m, &diag));
  PetscCall(DiagonalPositions(m, ia, ja, diag));
  for (PetscInt r = 0; r < m; r++) sa[diag[r]] += shift; /* as MatShift adds it */
  PetscCall(PetscFree(diag));
  PetscCall(MatSeqAIJRestoreArrayWrite(*S, &sa));
  PetscCall(MatSeqAIJRestoreArrayRead(A, &aa));
  PetscFunctionReturn(0);
}
