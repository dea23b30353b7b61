/* Discrete exterior calculus (DEC) on the distributed mesh and a basis of the harmonic 1-forms (docs/dec.md).

   Orientation convention (the same for every number of ranks, since it is the cone order of the serial
   interpolated DMPlex that the distribution keeps):
   - vertex i carries 0-forms (dmV1), edge e 1-forms (dmE1), face f 2-forms (dmF1);
   - edge e is oriented from mesh->edgeVert[2e] to mesh->edgeVert[2e+1] (its plex cone order);
   - face f is oriented counter-clockwise seen from outside, faceVert[3f] -> faceVert[3f+1] -> faceVert[3f+2].
   Then (d0 u)_e = u_{edgeVert[2e+1]} - u_{edgeVert[2e]}, and (d1 w)_f = sum over the three edges of f of
   s w_e with s = +1 where e points along the counter-clockwise boundary of f (side 0 in cs_mesh_adjacency.h)
   and -1 where it points against it. d1 d0 = 0 exactly (integer entries).
   Hodge stars (diagonal, as Vecs): *0 = barycentric vertex areas A_i (CSGeometryVertexAreas, the *0 of the
   rest of the code), *1 = cotan weights w_ij = (cot a + cot b)/2 (CSGeometryCotanWeights), *2 = 1/face area.
   With these, the cotan Laplacian of laplacian.c is L = d0^T *1 d0 and the codifferential of a 1-form is
   delta w = *0^{-1} d0^T *1 w (crane2013 App. C, soliman2021 App. D.1). */
#ifndef CS_OPERATORS_DEC_H
#define CS_OPERATORS_DEC_H
#include "cs_operators.h"
#include "cs_object.h"

/* d0: E x V AIJ (rows dmE1, columns dmV1), entries -1 at the edge's first and +1 at its second vertex. */
PETSC_EXTERN PetscErrorCode CSOperatorDECd0(CSMesh mesh, Mat *d0);
/* d1: F x E AIJ (rows dmF1, columns dmE1), entries +-1 as in the convention above. */
PETSC_EXTERN PetscErrorCode CSOperatorDECd1(CSMesh mesh, Mat *d1);
/* The diagonal Hodge stars at positions x (global dmV3): *0 into a dmV1 vector, *1 into dmE1, *2 into dmF1. */
PETSC_EXTERN PetscErrorCode CSOperatorHodgeStar0(CSMesh mesh, Vec x, Vec star0);
PETSC_EXTERN PetscErrorCode CSOperatorHodgeStar1(CSMesh mesh, Vec x, Vec star1);
PETSC_EXTERN PetscErrorCode CSOperatorHodgeStar2(CSMesh mesh, Vec x, Vec star2);

/* Genus g of a closed connected mesh from its Euler characteristic V - E + F = 2 - 2g. A mesh with boundary
   or with several components is refused with an error naming `caller` and the mesh (the harmonic forms of
   such meshes are not handled: relative cohomology / one constant per component). */
PETSC_EXTERN PetscErrorCode CSMeshGetClosedGenus(CSMesh mesh, const char caller[], PetscInt *g);

/* A *1-orthonormal basis omega_1..omega_2g of the harmonic 1-forms (d1 omega = 0, d0^T *1 omega = 0) of a
   closed connected mesh at positions x, by a parallel Hodge decomposition of 2g seeded random 1-forms
   (crane2013 App. C.1 steps I-IV; docs/dec.md), and the per-face vector fields v_i (crane2013 App. C.1 step
   IV): in face f the vector in the face's plane with <v, f_b - f_a> = omega_ab on its edges.

     CSHarmonicBasisCreate(mesh, x, &hb);         x: positions (global dmV3), copied
     CSHarmonicBasisSetOptionsPrefix(hb, "harmonic_");   (the default)
     CSHarmonicBasisSetFromOptions(hb);           -harmonic_seed N, and the solvers' -harmonic_vertex_ksp_*,
                                                  -harmonic_face_ksp_* (direct Cholesky by default)
     CSHarmonicBasisSetUp(hb);                    (the getters call it when needed)
     CSHarmonicBasisGetSize(hb, &n);              n = 2g
     CSHarmonicBasisGetForm(hb, i, &omega);       borrowed dmE1 global vector, 0 <= i < n
     CSHarmonicBasisGetFaceVectors(hb, i, &v);    borrowed, 3 entries per face (CSHarmonicBasisGetFaceDM)
     CSHarmonicBasisUpdate(hb, x);                new positions, same mesh: recomputes (keeps the solvers' symbolic work)
     CSHarmonicBasisUpdateFaceVectors(hb, x);     new positions, the same forms: only the face vectors
     CSHarmonicBasisDestroy(&hb);

   A mesh with boundary or several components is refused (CSMeshGetClosedGenus); genus 0 gives n = 0.
   On several ranks the default solver is the PC cssubchol: call CSInitializePackage first (the methods'
   Create functions do). */
typedef struct _p_CSHarmonicBasis *CSHarmonicBasis;
PETSC_EXTERN PetscErrorCode CSHarmonicBasisCreate(CSMesh mesh, Vec x, CSHarmonicBasis *hb);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisSetOptionsPrefix(CSHarmonicBasis hb, const char prefix[]);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisSetFromOptions(CSHarmonicBasis hb);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisSetSeed(CSHarmonicBasis hb, PetscInt seed);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisSetUp(CSHarmonicBasis hb);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisUpdate(CSHarmonicBasis hb, Vec x);
/* Keeps the forms and recomputes only the face vectors at positions x (O(F), no solve). Harmonic 1-forms depend
   only on the conformal structure (the Hodge star on 1-forms is conformally invariant), which a conformal flow
   keeps; the discrete *1 (cotans) changes a little under a discrete conformal map, so the kept forms are then
   closed exactly but co-closed only approximately at x: CSHarmonicBasisUpdate recomputes them. */
PETSC_EXTERN PetscErrorCode CSHarmonicBasisUpdateFaceVectors(CSHarmonicBasis hb, Vec x);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisGetSize(CSHarmonicBasis hb, PetscInt *n);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisGetForm(CSHarmonicBasis hb, PetscInt i, Vec *omega);
/* The DM of the face vectors: mesh->dm with 3 dofs per face; local face f of this rank is block f of the
   global vector's local array (overlap 0: every local face is owned). */
PETSC_EXTERN PetscErrorCode CSHarmonicBasisGetFaceDM(CSHarmonicBasis hb, DM *dmF3);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisGetFaceVectors(CSHarmonicBasis hb, PetscInt i, Vec *v);
/* c[i] = <<alpha, omega_i>> = alpha^T *1 omega_i for a 1-form alpha (dmE1), i < n (c has n entries). */
PETSC_EXTERN PetscErrorCode CSHarmonicBasisInner(CSHarmonicBasis hb, Vec alpha, PetscScalar c[]);
/* h = sum_i <<alpha, omega_i>> omega_i: the harmonic part of alpha in its Hodge decomposition (harmonic forms
   are *1-orthogonal to exact and co-exact ones), e.g. the closing error of crane2013 App. C. h may be alpha. */
PETSC_EXTERN PetscErrorCode CSHarmonicBasisProject(CSHarmonicBasis hb, Vec alpha, Vec h);
/* |harmonic part|_*1 of a vector-valued 1-form with bs components per edge (local entry bs*e + k = component k of
   owned edge e in dmE1 order, e.g. the R^3-valued beta = conj(lambda) df lambda of crane2013 App. C):
   sqrt(sum_k sum_i <<beta_k, omega_i>>^2), the closing error's size (0 for an exact beta). */
PETSC_EXTERN PetscErrorCode CSHarmonicBasisHarmonicNorm(CSHarmonicBasis hb, Vec beta, PetscInt bs, PetscReal *hnorm);
/* Residuals of the basis at the positions of its last SetUp/Update (for tests and reports; each may be NULL): max_i |d1 omega_i|_2 / |omega_i|_2,
   max_i |d0^T *1 omega_i|_2 / |*1 omega_i|_2 (co-closedness relative to the size of its terms), and
   max_ij |<<omega_i, omega_j>> - delta_ij|. */
PETSC_EXTERN PetscErrorCode CSHarmonicBasisGetResiduals(CSHarmonicBasis hb, PetscReal *closed, PetscReal *coclosed, PetscReal *orthonormal);
PETSC_EXTERN PetscErrorCode CSHarmonicBasisDestroy(CSHarmonicBasis *hb);

#endif
