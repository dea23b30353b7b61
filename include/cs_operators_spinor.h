/* Discrete spinors on triangle fields (soliman2021 App. C, after Chern et al. 2018; docs/triangle_fields.md,
   "Spinors").

   Conventions. Quaternions as in cs_quaternion.h; the complex numbers are span{1, i} of H and a complex
   coordinate z = x + iy of a face is placed in Im H as z j = x j + y k (so the face plane is span{j, k}, normal i).
   A face spinor psi_f in H defines the triangle field omega_psi = conj(psi) dz j psi in that face (App. C.1's
   conj(psi) dz psi with dz read as dz j, which makes it imaginary): a rotation of the flat triangle dz into R^3,
   scaled by |psi|^2. If two charts of neighbouring faces differ by dz' = e^{i theta} dz, then
   conj(psi') dz' j psi' = conj(psi) dz j psi iff psi' = +-e^{i theta/2} psi (j e^{i a} = e^{-i a} j), so the
   spin connection is tau_ij = +-sqrt(e^{i theta}) in span{1, i}, acting by left multiplication, and
   psi_jil = tau_ij psi_ijk for a smooth spinor field (ijk the face on side 0 of the edge, jil the one on side 1).

   Charts. Face f with halfedge lengths l_a (a = 0, 1, 2, the halfedge opposite corner a, running
   v[a+1] -> v[a+2]) gets the canonical isometric chart z(v1) = 0, z(v2) = l_0, z(v0) in the upper half plane:
   dz_0 = l_0 > 0, dz_1 = z(v0) - l_0, dz_2 = -z(v0). The background metric l0 (the target class) fixes the
   charts, the connection's rotations e^{i theta}, and the cotan weights w_ij of E_tau.

   The spin structure (the sign of each tau_ij) is the one of a reference immersion: psi_ref = the face rotations
   of a reference triangle field (df of the input) against the charts, tau_ij = the root with
   <psi_ref,jil, tau_ij psi_ref,ijk> >= 0. For an immersed reference every edge then passes the pinch test. */
#ifndef CS_OPERATORS_SPINOR_H
#define CS_OPERATORS_SPINOR_H
#include "cs_operators_lens.h"

typedef struct _p_CSSpinorSpace *CSSpinorSpace;

/* The charts and the weights w_ij = (cot alpha + cot beta)/2 of the background metric: lambda0 = log halfedge
   lengths (dmH1 global vector, e.g. CSTriangleFieldLogLengthsFromEdges of mesh->lt, or of df). */
PETSC_EXTERN PetscErrorCode CSSpinorSpaceCreate(CSMesh mesh, DM dmH1, Vec lambda0, CSSpinorSpace *sp);
PETSC_EXTERN PetscErrorCode CSSpinorSpaceDestroy(CSSpinorSpace *sp);
/* The background halfedge lengths l0 per local face (3 per face, opposite corners 0, 1, 2), borrowed. */
PETSC_EXTERN PetscErrorCode CSSpinorSpaceGetLengths(CSSpinorSpace sp, const PetscReal **l0);
/* The spinor DM: 4 reals per face (dmF4). */
PETSC_EXTERN PetscErrorCode CSSpinorSpaceGetDM(CSSpinorSpace sp, DM *dmF4);
/* The spin connection tau (App. C.1) from the charts and the spin structure of the reference field omega_ref (dmH3). */
PETSC_EXTERN PetscErrorCode CSSpinorSpaceSetConnection(CSSpinorSpace sp, DM dmH3, Vec omega_ref);
/* tau_e (Re, Im) and w_e of the local edge e (after SetConnection); for tests and output. */
PETSC_EXTERN PetscErrorCode CSSpinorSpaceGetEdge(CSSpinorSpace sp, PetscInt e, PetscReal tau[2], PetscReal *w);

/* psi (dmF4) = the unit face spinors of a triangle field omega (dmH3): per face the rotation of the conformal part
   of the real-linear map A with A(dz_a) = omega_a (a = 0, 1), i.e. r1 = (A(1) - n x A(i))/|.|, n = A(1) x A(i)/|.|,
   psi with conj(psi) j psi = r1, conj(psi) i psi = n. Exact (up to sign) for omega = S(l, psi) of a unit psi.
   The sign of each face: the one nearer to psi_prev (dmF4, may be NULL: w >= 0). */
PETSC_EXTERN PetscErrorCode CSSpinorFromTriangleField(CSSpinorSpace sp, DM dmH3, Vec omega, Vec psi_prev, Vec psi);
/* omega = S_c(u, psi) = S(e^u l0, psi) (App. C.2): per face conj(psi) dz j psi in the canonical chart of the
   lengths l_ij = e^{(u_i + u_j)/2} l0_ij. u (dmV1) may be NULL (u = 0: S(l0, psi)). Conformal by construction:
   log l = lambda0 + A~ u, so C~ lambda(omega) = C~ lambda0 for unit psi (C~ A~ = 0, Lemma A.1), as long as
   the lengths e^u l0 satisfy the triangle inequalities (a violating face is flattened, and the identity fails). */
PETSC_EXTERN PetscErrorCode CSSpinorTriangleField(CSSpinorSpace sp, Vec u, Vec psi, DM dmH3, Vec omega);
/* The spin Dirichlet energy (App. C.3) E_tau(psi) = 1/2 sum_ij w_ij |psi_jil - tau_ij psi_ijk|^2 and its gradient
   (dmF4, may be NULL). */
PETSC_EXTERN PetscErrorCode CSSpinorDirichlet(CSSpinorSpace sp, Vec psi, PetscReal *E, Vec grad);
/* The pinch-point test (App. C.1): the number of edges with |psi_jil - tau_ij psi_ijk| >= sqrt(2) (global), and
   the largest |psi_jil - tau_ij psi_ijk| (dmax may be NULL). */
PETSC_EXTERN PetscErrorCode CSSpinorPinchEdges(CSSpinorSpace sp, Vec psi, PetscInt *npinch, PetscReal *dmax);
/* The pinch points (App. C.1) independent of the spinors' signs: the interior vertices at which an odd number of
   edges fail the edge test above (global count). The edge count depends on the signs the lifts followed; this not. */
PETSC_EXTERN PetscErrorCode CSSpinorPinchVertices(CSSpinorSpace sp, Vec psi, PetscInt *npinch);
/* The regulariser on triangle fields: E_tau(psi(omega)) for the lift psi(omega) of CSSpinorFromTriangleField
   (signs nearer to psi_prev, may be NULL), its gradient with respect to omega (dmH3, may be NULL: the adjoint of
   the lift, exact for the lift as defined, whose rotation depends on omega_0, omega_1 of each face), and the lift
   itself in psi (dmF4, may be NULL). */
PETSC_EXTERN PetscErrorCode CSSpinorDirichletTriangleField(CSSpinorSpace sp, DM dmH3, Vec omega, Vec psi_prev, PetscReal *E, Vec grad, Vec psi);

#endif
