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

/* |B w - b| / |b| of a filter solve B w = b */
static PetscErrorCode RelativeResidual(Mat B, Vec b, Vec w, PetscReal *rel)
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

/* After the filter solve B w = b by ksp (B its operator): a failed KSP, or a relative residual above CS_FILTER_RTOL,
   stops the flow with one line naming <prefix>filter_k and <prefix>filter_sigma. A direct factorisation is backward
   stable, so at that bound w is the exact filter of a direction within 1 % of v. But B's condition grows like
   s lambda_max(A)^k (~ sigma (N / pi)^(2k) on a curve of N vertices): for k = 3, 4 on fine inputs it passes 1e16 and
   the solution has no correct digit (a 2000-vertex star: relative residual 15 for k = 3 serially; 2 ranks' CG
   stopped indefinite for k = 4; the bunny, k = 3: 4.0 at sigma 1e-4). Shared by the curve and conformal flows. */
PetscErrorCode CSOperatorSpectralFilterCheck(KSP ksp, Vec b, Vec w, const char who[], const char prefix[])
{
  KSPConvergedReason kr;
  PetscReal          rel;
  Mat                B;
  PetscFunctionBeginUser;
  PetscCall(KSPGetConvergedReason(ksp, &kr));
  PetscCall(KSPGetOperators(ksp, &B, NULL));
  PetscCall(RelativeResidual(B, b, w, &rel));
  PetscCheck(kr >= 0 && rel <= CS_FILTER_RTOL, PetscObjectComm((PetscObject)ksp), PETSC_ERR_NOT_CONVERGED, "%s: the spectral filter solve failed (%s, relative residual %.1e > %g): the filter matrix M + s L (M^-1 L)^(k-1) is too ill-conditioned on this input; use a smaller -%sfilter_k or -%sfilter_sigma", who, KSPConvergedReasons[kr], (double)rel, (double)CS_FILTER_RTOL, prefix ? prefix : "", prefix ? prefix : "");
  PetscFunctionReturn(0);
}
