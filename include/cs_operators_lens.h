/* Triangle fields and the lens complex of soliman2021 Sec. 5.1, 5.2, App. A, D.1 (docs/dec.md, "Lens complex").

   Index maps. The lens complex has V~ = V, E~ = H (halfedges), F~ = E u F (a lens per edge, the triangles).
   A halfedge is an edge with a side: h = (e, s), s = 0 the halfedge running along e's orientation
   (edgeVert[2e] -> edgeVert[2e+1]) in the face on side 0 (cs_mesh_adjacency.h), s = 1 the opposite one in the
   face on side 1; twin(e, s) = (e, 1 - s). Halfedge fields live on the edges: a scalar per halfedge is dof s of
   edge e (local index 2e + s, CSLensCreateHalfedgeDM with dof 1), a vector (a triangle field omega_ij in R^3) is
   dofs 3s..3s+2 (local index 6e + 3s + c, dof 3). So twin, next and previous halfedges of a face are always in the
   local closure, on any number of ranks. In face f the halfedge opposite corner a (running v[a+1] -> v[a+2]) is
   (faceEdge[3f+a], CSMeshEdgeSide(mesh, F, a)); its next is the one opposite corner a+1, its previous the one
   opposite corner a+2. Lenses are edges (dmE1), triangles faces (dmF1). */
#ifndef CS_OPERATORS_LENS_H
#define CS_OPERATORS_LENS_H
#include "cs_operators_dec.h"

/* mesh->dm with 2*dof unknowns per edge: dof per halfedge (1: scalar, e.g. log lengths; 3: triangle fields). */
PETSC_EXTERN PetscErrorCode CSLensCreateHalfedgeDM(CSMesh mesh, PetscInt dof, DM *dmH);

/* A~ (soliman2021 Eq. 14): H x V, (A~ u)_ij = (u_i + u_j)/2. Rows of dmH (dof 1), columns dmV1. */
PETSC_EXTERN PetscErrorCode CSOperatorLensAverage(CSMesh mesh, DM dmH, Mat *A);
/* C~ (soliman2021 Eq. 14, per face Eq. 30): H x H, (C~ lambda)_ij = log m(l)_ij
     = (lambda_il - lambda_lj + lambda_jk - lambda_ki) + (lambda_ji - lambda_ij),
   ijk the face of ij, jil the face of ji. C~ A~ = 0 and rank C~ = |H| - |V| (Lemma A.1). */
PETSC_EXTERN PetscErrorCode CSOperatorLensCrossRatio(CSMesh mesh, DM dmH, Mat *C);
/* The lens integrability d1 (soliman2021 Eq. 31, Sec. 5.1): E x H, (d1 omega)_e = -(omega_(e,0) + omega_(e,1)),
   scalar (apply it per component of a triangle field). */
PETSC_EXTERN PetscErrorCode CSOperatorLensD1(CSMesh mesh, DM dmH, Mat *d1);

/* The harmonic dual 1-form Y of an edge 1-form eta (e.g. a CSHarmonicBasis form) on halfedges (dmH1 global
   vector y), with the cotans at positions x: <<Y|omega>> = sum_h y_h omega_h, per component of a triangle field,
   is the constraint row of soliman2021 Eq. 13 / Algorithm 2; for omega = df it is <<eta, df>> = 0 for harmonic eta. */
PETSC_EXTERN PetscErrorCode CSLensHarmonicDual(CSMesh mesh, Vec x, Vec eta, DM dmH1, Vec y);

/* The lens d0 (H x V): (d0 u)_h = u_head - u_tail; per component of the positions it gives df. */
PETSC_EXTERN PetscErrorCode CSOperatorLensD0(CSMesh mesh, DM dmH, Mat *d0);
/* Dlambda on halfedges (soliman2021 Sec. 5.2, cf. Eq. 5): (Dlambda omega-dot)_h = <omega_h, omega-dot_h>/|omega_h|^2,
   H x 3H (rows dmH1, columns dmH3), at the triangle field omega. */
PETSC_EXTERN PetscErrorCode CSOperatorLensLogLengthDerivative(CSMesh mesh, DM dmH1, DM dmH3, Vec omega, MatReuse reuse, Mat *D);
/* The triangle field's metric (Sec. 5.1): star1_h = 1/2 cot theta_h (dmH1) with theta_h the angle opposite h in
   omega's own triangle, star0_i = a third of the incident triangle field areas (dmV1). */
PETSC_EXTERN PetscErrorCode CSTriangleFieldStars(CSMesh mesh, DM dmH3, Vec omega, DM dmH1, Vec star1, Vec star0);
/* I_H1 = *1 + *1 d0 *0^{-1} d0^T *1 (soliman2021 Eq. 32) on halfedges, scalar H x H (per component of a
   triangle field), from the stars of CSTriangleFieldStars; d0^T I_H1 d0 = L + L *0^{-1} L for omega = df. */
PETSC_EXTERN PetscErrorCode CSOperatorLensH1Metric(CSMesh mesh, DM dmH, Vec star1, Vec star0, Mat *H1);

/* I_Q on halfedges (Eq. 25 for triangle fields): (I_Q)_h = 1/(w_h |omega_h|^2), w_h = 1/2 cot theta_h of omega's
   triangle floored at wmin (*nguard floored halfedges, may be NULL); dmH1 global vector iq. For omega = df the two
   halfedges of an edge in series give Eq. 25's 1/(w_ij l_ij^2). */
PETSC_EXTERN PetscErrorCode CSTriangleFieldQuadDiffMetric(CSMesh mesh, DM dmH3, Vec omega, DM dmH1, PetscReal wmin, Vec iq, PetscInt *nguard);

/* omega = df: omega_(e,s) = f_head - f_tail of the halfedge (dmH with dof 3, global vector). */
PETSC_EXTERN PetscErrorCode CSTriangleFieldFromPositions(CSMesh mesh, Vec x, DM dmH3, Vec omega);
/* Log halfedge lengths lambda_h = log |omega_h| (dmH3 -> dmH1 global vectors). */
PETSC_EXTERN PetscErrorCode CSTriangleFieldLogLengths(CSMesh mesh, DM dmH3, Vec omega, DM dmH1, Vec lambda);
/* lambda (dmH1) = log l_e on both halfedges of every edge, for intrinsic edge lengths l (dmE1, e.g. mesh->lt) */
PETSC_EXTERN PetscErrorCode CSTriangleFieldLogLengthsFromEdges(CSMesh mesh, Vec l, DM dmH1, Vec lambda);
/* ch = an edge field c (dmE1, e.g. mesh->ct of -mesh_cross_ratios) on both halfedges of each edge (dmH1): on exact
   fields C~ lambda(df) = C lambda(f) on both halfedges of an edge, so this is the halfedge target of a class c0 */
PETSC_EXTERN PetscErrorCode CSTriangleFieldHalfedgesFromEdges(CSMesh mesh, Vec c, DM dmH1, Vec ch);
/* The triangle-field Willmore energy (soliman2021 App. D.1) W~(omega) = 1/4 <d*omega, d*omega>
   = 1/4 sum_i |sum_ij w_ij omega_ij|^2 / A_i with the cotans and areas of the triangle field's own triangles;
   W~(df) = W(f). grad (may be NULL; W may be NULL): the partial derivatives with respect to the stored halfedge
   vectors (dmH3), of W~ as computed from them (per face: the cotans from the two halfedges at each corner, the
   area from |omega_2 x omega_1|; on face-closed fields every such formula agrees, off them this is the extension
   differentiated). */
PETSC_EXTERN PetscErrorCode CSTriangleFieldWillmore(CSMesh mesh, DM dmH3, Vec omega, PetscReal *W, Vec grad);

/* Face closure (Sec. 5.1): F x H, (S omega)_f = the sum of the face's three halfedges (per component). */
PETSC_EXTERN PetscErrorCode CSOperatorLensFaceClosure(CSMesh mesh, DM dmH, Mat *S);
/* Positions from a triangle field by the Poisson problem L f = d*omega (soliman2021 Algorithm 2), i.e.
   d0^T *1 d0 f = d0^T *1 omega per component with omega's own *1: the *1-least-squares f, exact (up to a
   translation) for omega = df. The translation puts f's vertex centroid at that of xref (dmV3). KSP prefix
   -trianglefield_poisson_ (default a direct Cholesky). */
PETSC_EXTERN PetscErrorCode CSTriangleFieldReconstruct(CSMesh mesh, DM dmH1, DM dmH3, Vec omega, Vec xref, Vec x);
/* The same reconstruction kept alive across calls (the flow measures its surface at every evaluation): the KSP, d0,
   L, B and the work vectors are made at the first set-up; a new (or changed) omega refills L and B in place (same
   nonzero pattern: one numeric factorisation, the symbolic one kept), an omega equal to the last one (value for
   value, kept as a copy) reuses everything. Solve sets up at omega itself; its answer is CSTriangleFieldReconstruct's. */
typedef struct _p_CSTriangleFieldReconstruction *CSTriangleFieldReconstruction;
PETSC_EXTERN PetscErrorCode CSTriangleFieldReconstructionCreate(CSMesh mesh, DM dmH1, DM dmH3, CSTriangleFieldReconstruction *R);
PETSC_EXTERN PetscErrorCode CSTriangleFieldReconstructionSetUp(CSTriangleFieldReconstruction R, Vec omega);
PETSC_EXTERN PetscErrorCode CSTriangleFieldReconstructionSolve(CSTriangleFieldReconstruction R, Vec omega, Vec xref, Vec x);
PETSC_EXTERN PetscErrorCode CSTriangleFieldReconstructionDestroy(CSTriangleFieldReconstruction *R);
/* The halfedge vectors opposite corner a (0, 1, 2) of every local face: a new vector of 3 entries per face (the
   viewer's face vector layout), the face's own triangle of the field, not glued to its neighbours. */
PETSC_EXTERN PetscErrorCode CSTriangleFieldFaceVectors(CSMesh mesh, DM dmH3, Vec omega, PetscInt a, Vec *w);

/* The linear Poisson reconstruction of App. B (soliman2021 Eq. 22) with the metric frozen at the input x0:
   R omega = f with L0 f = d0^T *1(x0) omega, vertex 0 grounded (f_0 = 0), per component. For every integrable
   omega = df, R omega = f - f_0, so F(R omega) is a triangle-field extension of any translation-invariant F(f)
   (App. B), and its gradient R^T grad F(R omega) = *1(x0) d0 L0^{-1} grad F is exact for every omega (the paper's
   d varphi of Eq. 22: the Poisson problem is linear only for a fixed L). KSP prefix -trianglefield_extension_
   (default a direct Cholesky, factored once). Reference counted (shared by the App. B constraints). */
typedef struct _p_CSTriangleFieldPoisson *CSTriangleFieldPoisson;
PETSC_EXTERN PetscErrorCode CSTriangleFieldPoissonCreate(CSMesh mesh, DM dmH1, DM dmH3, Vec x0, CSTriangleFieldPoisson *P);
PETSC_EXTERN PetscErrorCode CSTriangleFieldPoissonReference(CSTriangleFieldPoisson P);
/* f (dmV3) = R omega (dmH3) */
PETSC_EXTERN PetscErrorCode CSTriangleFieldPoissonApply(CSTriangleFieldPoisson P, Vec omega, Vec f);
/* w (dmH3) = R^T v (dmV3): the triangle-field gradient of F(R omega) from grad F = v */
PETSC_EXTERN PetscErrorCode CSTriangleFieldPoissonApplyTranspose(CSTriangleFieldPoisson P, Vec v, Vec w);
PETSC_EXTERN PetscErrorCode CSTriangleFieldPoissonDestroy(CSTriangleFieldPoisson *P);

#endif
