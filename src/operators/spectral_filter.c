/* The matrix of crane2013 Sec. 4's spectral filter v <- v - (id + s A^k)^{-1} v, A = M^{-1} L >= 0 (L the
   positive semi-definite Laplacian, M the diagonal mass): (id + s A^k) w = v is, multiplied by M,
     B w = M v,   B = M + s L (M^{-1} L)^{k-1}   (k >= 1),   B = (1 + s) M   (k = 0),
   symmetric positive definite for s > 0 and every k (the paper writes id - sigma Delta^k: with Delta = -A <= 0
   that is definite only for odd k; with A it is for all k, and the gain on an eigenfunction A phi = w phi is
   s w^k / (1 + s w^k) for every k). Shared by the curve flow and the conformal surface flow. */
#include "cs_operators.h"

PetscErrorCode CSOperatorSpectralFilter(Mat L, Vec mass, PetscReal s, PetscInt k, Mat *B)
{
  Mat T, P;
  Vec minv, d;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(mass, &minv));
  PetscCall(VecCopy(mass, minv));
  PetscCall(VecReciprocal(minv));
  if (k == 0) {
    PetscCall(MatDuplicate(L, MAT_DO_NOT_COPY_VALUES, &P));
    PetscCall(MatZeroEntries(P));
  } else {
    PetscCall(MatDuplicate(L, MAT_COPY_VALUES, &P));
    for (PetscInt j = 1; j < k; j++) { /* P <- L M^{-1} P */
      PetscCall(MatDuplicate(P, MAT_COPY_VALUES, &T));
      PetscCall(MatDiagonalScale(T, minv, NULL));
      PetscCall(MatDestroy(&P));
      PetscCall(MatMatMult(L, T, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &P));
      PetscCall(MatDestroy(&T));
    }
    PetscCall(MatScale(P, s));
  }
  PetscCall(VecDuplicate(mass, &d));
  PetscCall(VecCopy(mass, d));
  if (k == 0) PetscCall(VecScale(d, 1 + s));
  PetscCall(MatDiagonalSet(P, d, ADD_VALUES));
  PetscCall(MatSetOption(P, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(MatSetOption(P, MAT_SPD, PETSC_TRUE));
  *B = P;
  PetscCall(VecDestroy(&d));
  PetscCall(VecDestroy(&minv));
  PetscFunctionReturn(0);
}

/* |B w - b| / |b| of a filter solve B w = b. A direct factorisation is backward stable, but B's condition grows like
   s lambda_max(A)^k (~ sigma (N / pi)^(2k) on a curve of N vertices): for k = 3, 4 on fine inputs it passes 1e16, and the
   solution then has no correct digit in the low frequencies the filter must keep (a 2000-vertex star: relative
   residual 15 for k = 3 serially, and 2 ranks' CG stopped indefinite for k = 4). The callers refuse such solves. */
PetscErrorCode CSOperatorSpectralFilterResidual(Mat B, Vec b, Vec w, PetscReal *rel)
{
  Vec       r;
  PetscReal nb;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(b, &r));
  PetscCall(MatMult(B, w, r));
  PetscCall(VecAXPY(r, -1, b));
  PetscCall(VecNorm(r, NORM_2, rel));
  PetscCall(VecNorm(b, NORM_2, &nb));
  *rel = nb > 0 ? *rel / nb : 0;
  PetscCall(VecDestroy(&r));
  PetscFunctionReturn(0);
}
