/* S = diag(d) + sum_k A_k^T diag(w_k) A_k as an unassembled MATIS (issue #16, PCBDDC; docs/scaling.md).
   Rank p holds its share: diag(d)/mult on its local dofs (mult = how many ranks hold the dof) plus, for every A_k,
   the terms of its owned rows,
   A_k(R_p, C_p)^T diag(w_k(R_p)) A_k(R_p, C_p), on the local dofs C_p = the owned dofs and every column its rows
   touch. Each share is a sum of positive semidefinite rank-one terms (w_k >= 0, d >= 0): the local Neumann matrices
   PCBDDC needs, summing exactly to S. The diagonal is shared by every rank holding the dof (not given to the owner
   alone) so that with d > 0 every share is definite: a dof that only the terms of A_k reach (a ghost column of X)
   would otherwise leave the local matrix singular on the conformal deformations (ker X), and BDDC's local
   Neumann factorisation fails. For the flow's Schur complement S = H/t + t_mu X^T I_Q^-1 X with
   H = w *0 + L *0^-1 L (soliman2021 Eq. 26; L symmetric): A_1 = L (3 components), w_1 = *0^-1/t; A_2 = X,
   w_2 = t_mu/I_Q; d = w *0/t. With MAT_REUSE_MATRIX the local matrix of *S is replaced (same local dofs). */
#include "cs_linalg.h"

/* the sorted local dofs: the owned ones and the columns of the owned rows of every A_k */
static PetscErrorCode LocalDofs(Vec d, PetscInt n, Mat A[], PetscInt *nl, PetscInt **gidx)
{
  PetscInt rstart, rend, cnt = 0, cap;
  PetscFunctionBeginUser;
  PetscCall(VecGetOwnershipRange(d, &rstart, &rend));
  cap = rend - rstart;
  for (PetscInt k = 0; k < n; k++) {
    MatInfo info;
    PetscCall(MatGetInfo(A[k], MAT_LOCAL, &info));
    cap += (PetscInt)info.nz_used;
  }
  PetscCall(PetscMalloc1(cap, gidx));
  for (PetscInt i = rstart; i < rend; i++) (*gidx)[cnt++] = i;
  for (PetscInt k = 0; k < n; k++) {
    PetscInt as, ae;
    PetscCall(MatGetOwnershipRange(A[k], &as, &ae));
    for (PetscInt i = as; i < ae; i++) {
      PetscInt        nc;
      const PetscInt *cols;
      PetscCall(MatGetRow(A[k], i, &nc, &cols, NULL));
      PetscCheck(cnt + nc <= cap, PETSC_COMM_SELF, PETSC_ERR_PLIB, "CSMatISFromSquares: more entries than MatGetInfo reported");
      for (PetscInt j = 0; j < nc; j++) (*gidx)[cnt++] = cols[j];
      PetscCall(MatRestoreRow(A[k], i, &nc, &cols, NULL));
    }
  }
  PetscCall(PetscSortRemoveDupsInt(&cnt, *gidx));
  *nl = cnt;
  PetscFunctionReturn(0);
}

/* B = A_k(R_p, C_p) (local column numbers) and Bw = diag(w(R_p)) B, sequential */
static PetscErrorCode LocalRows(Mat A, Vec w, PetscInt nl, const PetscInt gidx[], Mat *B, Mat *Bw)
{
  PetscInt           as, ae, *nnz, *lc, maxnc = 0;
  const PetscScalar *wa;
  PetscFunctionBeginUser;
  PetscCall(MatGetOwnershipRange(A, &as, &ae));
  PetscCall(PetscMalloc1(ae - as + 1, &nnz));
  for (PetscInt i = as; i < ae; i++) {
    PetscInt nc;
    PetscCall(MatGetRow(A, i, &nc, NULL, NULL));
    nnz[i - as] = nc;
    maxnc       = PetscMax(maxnc, nc);
    PetscCall(MatRestoreRow(A, i, &nc, NULL, NULL));
  }
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, ae - as, nl, 0, nnz, B));
  PetscCall(PetscMalloc1(maxnc + 1, &lc));
  PetscCall(VecGetArrayRead(w, &wa));
  for (PetscInt i = as; i < ae; i++) {
    PetscInt           nc, r = i - as;
    const PetscInt    *cols;
    const PetscScalar *vals;
    PetscCall(MatGetRow(A, i, &nc, &cols, &vals));
    for (PetscInt j = 0; j < nc; j++) PetscCall(PetscFindInt(cols[j], nl, gidx, &lc[j]));
    PetscCall(MatSetValues(*B, 1, &r, nc, lc, vals, INSERT_VALUES));
    PetscCall(MatRestoreRow(A, i, &nc, &cols, &vals));
  }
  PetscCall(MatAssemblyBegin(*B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*B, MAT_FINAL_ASSEMBLY));
  PetscCall(MatDuplicate(*B, MAT_COPY_VALUES, Bw));
  {
    Vec wl;
    PetscCall(VecCreateSeqWithArray(PETSC_COMM_SELF, 1, ae - as, wa, &wl));
    PetscCall(MatDiagonalScale(*Bw, wl, NULL));
    PetscCall(VecDestroy(&wl));
  }
  PetscCall(VecRestoreArrayRead(w, &wa));
  PetscCall(PetscFree(lc));
  PetscCall(PetscFree(nnz));
  PetscFunctionReturn(0);
}

/* dl = (d / mult) at the local dofs, mult = the number of ranks holding each dof. Collective. */
static PetscErrorCode LocalDiagonal(Vec d, PetscInt nl, const PetscInt gidx[], Vec *dl)
{
  Vec         mult, dm;
  IS          is;
  VecScatter  sc;
  PetscScalar one = 1;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(d, &mult));
  PetscCall(VecSet(mult, 0));
  for (PetscInt l = 0; l < nl; l++) PetscCall(VecSetValues(mult, 1, &gidx[l], &one, ADD_VALUES));
  PetscCall(VecAssemblyBegin(mult));
  PetscCall(VecAssemblyEnd(mult));
  PetscCall(VecDuplicate(d, &dm));
  PetscCall(VecPointwiseDivide(dm, d, mult));
  PetscCall(VecCreateSeq(PETSC_COMM_SELF, nl, dl));
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, nl, gidx, PETSC_USE_POINTER, &is));
  PetscCall(VecScatterCreate(dm, is, *dl, NULL, &sc));
  PetscCall(VecScatterBegin(sc, dm, *dl, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, dm, *dl, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(ISDestroy(&is));
  PetscCall(VecDestroy(&dm));
  PetscCall(VecDestroy(&mult));
  PetscFunctionReturn(0);
}

/* the local share: diag(d / mult) (stored even where 0) + sum_k B_k^T Bw_k */
static PetscErrorCode LocalShare(Vec d, PetscInt n, Mat A[], Vec w[], PetscInt nl, const PetscInt gidx[], Mat *loc)
{
  Vec                dl;
  const PetscScalar *da;
  PetscFunctionBeginUser;
  PetscCall(LocalDiagonal(d, nl, gidx, &dl));
  PetscCall(MatCreateSeqAIJ(PETSC_COMM_SELF, nl, nl, 1, NULL, loc));
  PetscCall(VecGetArrayRead(dl, &da));
  for (PetscInt l = 0; l < nl; l++) PetscCall(MatSetValues(*loc, 1, &l, 1, &l, &da[l], INSERT_VALUES));
  PetscCall(VecRestoreArrayRead(dl, &da));
  PetscCall(VecDestroy(&dl));
  PetscCall(MatAssemblyBegin(*loc, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*loc, MAT_FINAL_ASSEMBLY));
  for (PetscInt k = 0; k < n; k++) {
    Mat B, Bw, C;
    PetscCall(LocalRows(A[k], w[k], nl, gidx, &B, &Bw));
    PetscCall(MatTransposeMatMult(B, Bw, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &C));
    PetscCall(MatAXPY(*loc, 1.0, C, DIFFERENT_NONZERO_PATTERN));
    PetscCall(MatDestroy(&C));
    PetscCall(MatDestroy(&B));
    PetscCall(MatDestroy(&Bw));
  }
  PetscCall(MatSetOption(*loc, MAT_SYMMETRIC, PETSC_TRUE));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMatISFromSquares(Vec d, PetscInt n, Mat A[], Vec w[], MatReuse reuse, Mat *S)
{
  PetscInt *gidx = NULL, nl = 0, m, M;
  Mat       loc;
  PetscFunctionBeginUser;
  PetscCall(LocalDofs(d, n, A, &nl, &gidx));
  PetscCall(LocalShare(d, n, A, w, nl, gidx, &loc));
  if (reuse == MAT_INITIAL_MATRIX) {
    ISLocalToGlobalMapping l2g;
    PetscCall(VecGetLocalSize(d, &m));
    PetscCall(VecGetSize(d, &M));
    PetscCall(ISLocalToGlobalMappingCreate(PetscObjectComm((PetscObject)d), 1, nl, gidx, PETSC_COPY_VALUES, &l2g));
    PetscCall(MatCreateIS(PetscObjectComm((PetscObject)d), 1, m, m, M, M, l2g, l2g, S));
    PetscCall(ISLocalToGlobalMappingDestroy(&l2g));
  }
  PetscCall(MatISSetLocalMat(*S, loc));
  PetscCall(MatDestroy(&loc));
  PetscCall(MatAssemblyBegin(*S, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*S, MAT_FINAL_ASSEMBLY));
  PetscCall(MatSetOption(*S, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(*S, MAT_SPD, PETSC_TRUE));
  PetscCall(PetscFree(gidx));
  PetscFunctionReturn(0);
}
