/* The quaternionic Dirac operator of crane2011 Sec. 5 on the distributed mesh, stored as real matrices
   (one 4x4 block per quaternion, crane2011 Sec. 5.1, include/cs_quaternion.h).

   A field lambda in H^V lives on a DM with 4 dofs per vertex (dof 4v+c is component c = w,x,y,z of vertex v).
   rho, the change of mean curvature half-density, is either per face (crane2011 Sec. 5.3: R = P B) or per
   vertex (crane2013 App. G: R = B diag(rho)); in both cases row k of A = D - R in face k is
     a_j = -e_j / (2 A_k) - r_j / 3,      j a corner of face k,
   with e_j the edge opposite corner j oriented counter-clockwise (crane2011 Eq. 5) and r_j = rho_k (face)
   or rho_j (vertex). */
#ifndef CS_OPERATORS_DIRAC_H
#define CS_OPERATORS_DIRAC_H
#include "cs_operators.h"
#include "cs_quaternion.h"

typedef enum {
  CS_RHO_NONE,
  CS_RHO_VERTEX,
  CS_RHO_FACE
} CSRhoLocation;

/* A clone of mesh->dm with 4 dofs per vertex (or, with vdofs != NULL, vdofs[v] dofs on local vertex v: used
   for the reduced boundary space of crane2011 Sec. 5.7). */
PETSC_EXTERN PetscErrorCode CSDiracCreateDM(CSMesh mesh, const PetscInt vdofs[], DM *dm);

/* The V x V quaternionic matrix X = A^H M_F A = sum over faces of X_k, crane2013 App. G:
     (X_k)_ij = A_k conj(a_i) a_j = -e_i e_j/(4 A_k) + (r_i e_j - r_j e_i)/6 + A_k r_i r_j / 9.
   rho is a dmV1 (CS_RHO_VERTEX) or dmF1 (CS_RHO_FACE) global vector, or NULL (rho = 0).
   Assembled as AIJ with block size 4 on dm (from CSDiracCreateDM(mesh, NULL, ...)); real symmetric,
   positive semi-definite. MAT_REUSE_MATRIX refills *X. */
PETSC_EXTERN PetscErrorCode CSDiracAssemble(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, MatReuse reuse, Mat *X);
/* The same operator as a MATSHELL that applies the Hamilton products face by face (crane2011 Sec. 5.1,
   "a callback routine"): y_i += A_k conj(a_i) (sum_j a_j x_j). Supports MatMult, MatMultTranspose (= MatMult),
   MatGetDiagonal, and the shell's built-in MatShift/MatScale/MatDiagonalScale. Geometry is copied. */
PETSC_EXTERN PetscErrorCode CSDiracCreateShell(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, Mat *X);
/* Y = B^H M_F A, the right-hand side operator of the generalised problem crane2011 Eq. 6:
   (Y_k)_ij = (A_k / 3) a_j. Hermitian for rho per face; for rho per vertex it is not (then Eq. 6 is solved as
   a non-Hermitian problem). AIJ on dm. */
PETSC_EXTERN PetscErrorCode CSDiracAssembleBA(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, MatReuse reuse, Mat *Y);

/* The rectangular face operators of crane2011 Sec. 5.2-5.4 as real 4F x 4V AIJ matrices:
   D (Eq. 5: D_kj = -e_j/(2 A_k)), B (B_kj = 1/3), A = D - R, and the diagonal face mass M_F (a 4F vector of
   face areas). Rows: 4 per local face, in local face order (faces are owned); columns: dm's global dofs.
   Any output may be NULL. The adjoint of X is X^* = X^T M_F (Sec. 5.4, with M_V^-1 omitted on both sides),
   so X = A^T M_F A and Y = B^T M_F A. */
PETSC_EXTERN PetscErrorCode CSDiracCreateFaceOperators(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, Mat *D, Mat *B, Mat *A, Vec *MF);

/* Per-face quantities of a vertex field mu (global vector of dm): (D mu)_k and (B mu)_k, written to
   Dmu[4k..4k+3] and Bmu[4k..4k+3] (arrays of 4*nf, local faces). Used by crane2011 Sec. 7.2. */
PETSC_EXTERN PetscErrorCode CSDiracFaceApply(CSMesh mesh, DM dm, Vec x, Vec mu, PetscReal Dmu[], PetscReal Bmu[]);

/* A preallocated AIJ (or BAIJ) matrix with the vertex 1-ring pattern and bs dofs per vertex of dm (dm: CSDiracCreateDM,
   or mesh->dmV1 with bs = 1); local-to-global mapping set for MatSetValuesLocal. */

/* Helpers shared by the implementations: local (ghosted) rho values, and the coefficients a_j of one face. */
PETSC_EXTERN PetscErrorCode CSDiracGetRho(CSMesh mesh, CSRhoLocation loc, Vec rho, Vec *rl, const PetscScalar **r);
PETSC_EXTERN PetscErrorCode CSDiracRestoreRho(CSMesh mesh, CSRhoLocation loc, Vec rho, Vec *rl, const PetscScalar **r);
PETSC_EXTERN void           CSDiracFaceCoefficients(CSMesh mesh, const PetscReal *p, CSRhoLocation loc, const PetscScalar *r, PetscInt f, PetscReal a[3][4], PetscReal *area);

#endif
