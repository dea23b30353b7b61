/* The discrete Willmore energy of Bobenko-Schroeder (bobenko-schroeder2005, "Discrete Willmore Flow"):
   circle-intersection angles beta on the diamonds of the interior edges, W_i = sum_{edges at i} beta - 2 pi,
   W = sum_i W_i (Sec. 2), its gradient in the scalar form of Eq. 1, the |sin beta| < eps heuristic (Sec. 3.2),
   the n x n linearised Hessian K collecting Eq. 1's coefficients (Sec. 4), and the two boundary treatments
   of Sec. 3.3. Distributed: the diamond of an edge on a partition cut has its two faces on different ranks;
   the far opposite vertex is exchanged through an edge field (see bs_willmore.c).
   Measured facts (tests/unit/test_bs_energy.c): Eq. 1 as printed matches central differences (1.7e-9);
   K is symmetric (|K - K^T|/|K| ~ 1e-16, also with the free-boundary terms) but indefinite (a few small
   negative eigenvalues), constants are in its kernel, and grad W = K x exactly. On a curvature-line torus
   grid W = sum_i W_i tends to 2 int (H^2 - K) dA (68.95 vs 2 x 34.49), not to the smooth energy as Sec. 2's
   limit (R = 1 for curvature-line lattices) suggests: every beta is counted at both ends of its edge, and
   half of W, sum_e beta - pi |V|, is what matches. We keep the paper's W = sum_i W_i as the issue asks. */
#ifndef CS_ENERGY_BS_H
#define CS_ENERGY_BS_H
#include "cs_energy.h"
#include "cs_util.h"

/* Sec. 3.3. FIXED (G1): boundary vertices and their one-ring are fixed, W sums W_i over the non-boundary
   vertices (the only ones where W_i is defined). FREE: a vertex at infinity closes every boundary loop;
   W adds beta_2 (boundary edges, pi minus the opposite angle) and beta_3 (boundary vertices, the turning
   angle of the boundary polygon) and counts the infinity vertices in the -2 pi term. On a closed mesh the
   two agree. */
typedef enum {
  CS_BS_BOUNDARY_FIXED = 0,
  CS_BS_BOUNDARY_FREE  = 1
} CSBSBoundary;
PETSC_EXTERN const char *const CSBSBoundaries[]; /* "fixed", "free", then PetscOptionsEnum's trailer */

/* beta_eps: diamonds (and boundary angles) with |sin beta| < beta_eps contribute no gradient and no K
   (Sec. 3.2, paper value 1e-6). */
PETSC_EXTERN PetscErrorCode CSEnergyCreateWillmoreBS(CSMesh mesh, CSBSBoundary bc, PetscReal beta_eps, CSEnergy *e);

/* Per-vertex W_i (a dmV1 global vector; 0 on boundary vertices in FIXED mode) and the total. */
PETSC_EXTERN PetscErrorCode CSEnergyWillmoreBSVertex(CSEnergy e, Vec x, Vec Wv, PetscReal *W);

/* Fixed vertices (FIXED mode with a boundary): a local array over the mesh's nv local vertices (owned by e),
   and the global count. The gradient is exactly 0 there. */
PETSC_EXTERN PetscErrorCode CSEnergyWillmoreBSGetFixed(CSEnergy e, const PetscBool **fixed, PetscInt *nfixed);

/* Islands (Sec. 3.3: "one can fix some islands of internal vertices (or faces)"): the vertices with vmask > 0.5
   (a dmV1 global vector) are fixed with their one-ring, in either boundary mode, in addition to the boundary
   strip of FIXED mode. Collective; call before the first evaluation. */
PETSC_EXTERN PetscErrorCode CSEnergyWillmoreBSSetIslands(CSEnergy e, Vec vmask);

/* Sec. 2: W_i + K_i (>= 0) per vertex into wk (dmV1 global; 0 on boundary vertices, where W_i is not defined),
   its minimum over the interior vertices and the number below -1e-10 (src/energy/bs_gauss_bound.c). */
PETSC_EXTERN PetscErrorCode CSEnergyWillmoreBSGaussBound(CSEnergy e, Vec x, Vec wk, PetscReal *wkmin, PetscInt *nneg);

/* Sec. 3.2 "Gradient Singularity", the direction at a vertex where betas of its gradient's support vanish
   (|sin beta| < beta_eps). HEURISTIC: those diamonds contribute no gradient (the paper's practice). SINGLE: where
   exactly one vanishes, the paper's steepest descent (the regular negative gradient g split along the circle of
   the four co-circular points: g_p, plus g_o (1 - R/|g_o|) when the rate R of that beta is below |g_o|); vertices
   with several keep the heuristic. DELTA: at every vertex with one or more, the minimiser of the paper's delta
   (CSBSSingularDescent; for one it is SINGLE's closed form). Gradient only (K leaves those diamonds out either way). */
typedef enum {
  CS_BS_SINGULAR_HEURISTIC = 0,
  CS_BS_SINGULAR_SINGLE    = 1,
  CS_BS_SINGULAR_DELTA     = 2
} CSBSSingular;
PETSC_EXTERN const char *const CSBSSingularRules[]; /* "heuristic", "single", "delta", then PetscOptionsEnum's trailer */
PETSC_EXTERN PetscErrorCode    CSEnergyWillmoreBSSetSingularRule(CSEnergy e, CSBSSingular rule);

/* Sec. 3.2's delta minimisation at one vertex (src/energy/bs_singular_descent.c): g the regular negative gradient,
   n vanishing betas with unit circle tangents t (3n) and rates R (n, > 0); d the steepest descent direction
   (|d| = -delta; 0 when delta >= 0, i.e. |d| <= 1e-12 (|g| + sum R)), its the block-coordinate sweeps used (may
   be NULL). n <= CS_BS_SINGULAR_MAX. */
#define CS_BS_SINGULAR_MAX 24
PETSC_EXTERN PetscErrorCode CSBSSingularDescent(const PetscReal g[3], PetscInt n, const PetscReal t[], const PetscReal R[], PetscReal d[3], PetscInt *its);

/* The linearised Hessian K (Sec. 4): n x n scalar AIJ on dmV1's layout with grad W = K x per coordinate
   (K collects the Eq. 1 coefficients of every diamond; rows sum to zero). Rows and columns of fixed
   vertices are dropped and fixdiag put on their diagonal. MAT_INITIAL_MATRIX creates *K (preallocated for
   the 1-ring with flaps), MAT_REUSE_MATRIX refills it. Also returns the gradient g (dmV3, may be NULL) and W
   (may be NULL) from the same pass. K is not symmetric in general. */
PETSC_EXTERN PetscErrorCode CSEnergyWillmoreBSHessian(CSEnergy e, Vec x, PetscReal fixdiag, MatReuse reuse, Mat *K, PetscReal *W, Vec g);

/* Leave diamonds with sin beta < eps (>= beta_eps) out of K while keeping their gradient. Near beta = 0 the
   entries of Eq. 1's M grow like 1/sin beta although grad beta stays bounded (W has a kink there), which
   makes K a poor linearisation; this is our option (-bs_hessian_eps), not the paper's. */
PETSC_EXTERN PetscErrorCode CSEnergyWillmoreBSSetHessianEps(CSEnergy e, PetscReal eps);


/* Single-diamond kernel (exposed for the unit tests): P = {k, j, l, i} counter-clockwise around the diamond
   of edge ij (bobenko-schroeder2005 Fig. 1). Returns beta (atan2 of |Im Q|, -Re Q for the quaternion cross
   ratio Q = A B^-1 C D^-1) and M with grad_{P[r]} beta = sum_m M[r][m] P[m] (Eq. 1 and its cyclic
   permutations); *active = PETSC_FALSE (M = 0) when sin beta < eps. M may be NULL (value only). */
PETSC_EXTERN void CSBSDiamond(const PetscReal *const P[4], PetscReal eps, PetscReal *beta, PetscReal M[4][4], PetscBool *active);

#endif
