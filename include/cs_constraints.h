/* Constraints of constrained Willmore flow (soliman2021 Sec. 3 and App. D, "Constraints"): vector-valued
   maps xi(f) = 0 with value c and Jacobian rows X. Two kinds:
   - the conformal constraint c = C lambda(f) - c0 (one row per edge, sparse Jacobian X = C Dlambda as a Mat);
   - "global" constraints with few rows (total area, enclosed volume, point positions): values c[k] and the
     Jacobian rows as k dmV3 vectors (dense rows; the saddle solver appends them by bordering).
   Also the fairing energy of soliman2021 Eq. 21 (it needs the initial positions). */
#ifndef CS_CONSTRAINTS_H
#define CS_CONSTRAINTS_H
#include "cs_operators_conformal.h"
#include "cs_energy.h"
#include "cs_operators_lens.h"

typedef struct {
  CSMesh    mesh;
  PetscBool interior_only; /* C0 of App. D: only interior edges (surfaces with boundary) */
  const PetscBool *fixed;  /* Dirichlet vertices (columns dropped from X), may be NULL; not owned */
  Mat       C, D, X;       /* cross-ratio map, Dlambda, X = C Dlambda */
  Vec       c0, lambda;    /* target log cross ratios, work */
} CSConformalConstraint;

/* Target = the log cross ratios of positions xt (the initial mesh or a -target_mesh). */
PETSC_EXTERN PetscErrorCode CSConformalConstraintCreate(CSMesh mesh, Vec xt, PetscBool interior_only, const PetscBool fixed[], CSConformalConstraint *cc);
/* c0 = C log(l) for intrinsic edge lengths l (dmE1), e.g. mesh->lt of -gen lattice, instead of the positions' */
PETSC_EXTERN PetscErrorCode CSConformalConstraintSetTargetLengths(CSConformalConstraint *cc, Vec l);
/* c = C lambda(x) - c0 (dmE1 vector; zero on boundary edges with interior_only); if wantX, X at x. */
PETSC_EXTERN PetscErrorCode CSConformalConstraintEvaluate(CSConformalConstraint *cc, Vec x, Vec c, PetscBool wantX);
PETSC_EXTERN PetscErrorCode CSConformalConstraintDestroy(CSConformalConstraint *cc);

/* Boundary-face normal constraint (soliman2021 App. D, "first-order boundary conditions"): N_f(x) = N_f(x0)
   for every face with a boundary edge, 3 rows per face, rows owned by the face's rank (a plain MPI layout of
   3 * local boundary faces). DN has the 3x3 blocks dN_f/df_i = -(N x e_jk) N^T / (2 A_f), e_jk = f_k - f_j
   the edge opposite i (App. D prints 1/A_ijk: with A the triangle area the factor is 1/(2A), checked by
   finite differences in tests/unit/test_willmore_operators.c). Columns of fixed vertices are dropped. */
typedef struct {
  CSMesh           mesh;
  const PetscBool *fixed;
  PetscInt         nb;    /* local boundary faces */
  PetscInt        *faces; /* their local face indices */
  Vec              N0;    /* target normals, 3 nb local entries */
  Mat              DN;
} CSNormalConstraint;
PETSC_EXTERN PetscErrorCode CSNormalConstraintCreate(CSMesh mesh, Vec x0, const PetscBool fixed[], CSNormalConstraint *nc);
/* c = N(x) - N0 (a vector like N0); DN at x if wantJ. */
PETSC_EXTERN PetscErrorCode CSNormalConstraintEvaluate(CSNormalConstraint *nc, Vec x, Vec c, PetscBool wantJ);
/* Metric of the normal multipliers (the analogue of I_Q: 1 / (2 A_f)), a vector like N0. */
PETSC_EXTERN PetscErrorCode CSNormalConstraintMetric(CSNormalConstraint *nc, Vec x, Vec iq);
PETSC_EXTERN PetscErrorCode CSNormalConstraintDestroy(CSNormalConstraint *nc);

/* Global constraints. evaluate fills c[0..k) and, if rows != NULL, rows[0..k) (dmV3 global vectors). */
typedef struct _p_CSGlobalConstraint *CSGlobalConstraint;
struct _p_CSGlobalConstraint {
  char     name[64];
  CSMesh   mesh;
  PetscInt k;
  void    *ctx;
  PetscErrorCode (*evaluate)(CSGlobalConstraint, Vec x, PetscReal c[], Vec rows[]);
  PetscErrorCode (*destroy)(CSGlobalConstraint);
};
PETSC_EXTERN PetscErrorCode CSGlobalConstraintEvaluate(CSGlobalConstraint g, Vec x, PetscReal c[], Vec rows[]);
PETSC_EXTERN PetscErrorCode CSGlobalConstraintDestroy(CSGlobalConstraint *g);
/* For implementations: a constraint of k rows with a name; set ctx, evaluate and destroy. */
PETSC_EXTERN PetscErrorCode CSGlobalConstraintCreateShell(CSMesh mesh, const char name[], PetscInt k, CSGlobalConstraint *g);
/* Central finite-difference check of the rows (as CSEnergyCheckGradient): the largest error of the slopes of c
   along n seeded random directions, relative to the largest row's slope. Collective. */
PETSC_EXTERN PetscErrorCode CSGlobalConstraintCheckRows(CSGlobalConstraint g, Vec x, PetscReal h, PetscInt n, PetscReal *relerr);
/* Total area A(f) = target (soliman2021 Sec. 2; gradient Lf). */
PETSC_EXTERN PetscErrorCode CSConstraintCreateArea(CSMesh mesh, PetscReal target, CSGlobalConstraint *g);
/* Enclosed volume V(f) = target (App. B.2; gradient Eq. 23). Refused on surfaces with boundary. */
PETSC_EXTERN PetscErrorCode CSConstraintCreateVolume(CSMesh mesh, PetscReal target, CSGlobalConstraint *g);
/* Point constraints f_v = p_v read from a file of lines "vertex_index x y z" (0-based file-order vertex
   indices; '#' starts a comment). Clear errors for an unreadable file, a bad line, an index out of range or
   a repeated vertex. 3 rows per point. */
PETSC_EXTERN PetscErrorCode CSConstraintCreatePointsFromFile(CSMesh mesh, const char option[], const char path[], CSGlobalConstraint *g);

/* Triangle-field extensions (soliman2021 App. B) of translation-invariant global constraints: c~(omega) =
   c(R omega) with R the frozen-metric Poisson reconstruction (CSTriangleFieldPoissonCreate), rows R^T rows(R
   omega) on dmH3 vectors. The volume (B.2): V(R omega) = target. The points (B.1), from the file of
   CSConstraintCreatePointsFromFile: a triangle field fixes positions only up to translation, so the first point
   of the file anchors the others, f_v - f_v0 = p_v - p_v0 (3 (n - 1) rows, linear: <<omega, dp>> with L0 p =
   delta_v - delta_v0, the source/sink form of B.1); fewer than 2 points is refused. P is referenced. */
PETSC_EXTERN PetscErrorCode CSConstraintCreateTriangleFieldVolume(CSMesh mesh, CSTriangleFieldPoisson P, PetscReal target, CSGlobalConstraint *g);
PETSC_EXTERN PetscErrorCode CSConstraintCreateTriangleFieldPoints(CSMesh mesh, CSTriangleFieldPoisson P, const char option[], const char path[], CSGlobalConstraint *g);
/* The Moebius balancing (CSConstraintCreateMobiusBalance on the input positions x0) of R omega: 3 rows fixing the
   Moebius gauge of the triangle-field flow (-flow_constraint_mobius with -flow_type trianglefield). */
PETSC_EXTERN PetscErrorCode CSConstraintCreateTriangleFieldMobius(CSMesh mesh, CSTriangleFieldPoisson P, Vec x0, CSGlobalConstraint *g);

/* Moebius balancing (gauge of the Moebius orbit left free by the conformal constraint, along which the
   discrete Willmore energy is not invariant): the 3 rows sum_i A_i(f) (f0_i - c0) = 0, normalised by
   A(f0)^(3/2); see constraints_global.c. */
PETSC_EXTERN PetscErrorCode CSConstraintCreateMobiusBalance(CSMesh mesh, Vec x0, CSGlobalConstraint *g);
/* Rotation gauge of the domain (the rotations of the Moebius group the balancing leaves free): the 3 off-diagonal
   second moments sum_i A_i(f) (y_i - ybar) of the area distribution on the input's vertices; constraints_global.c. */
PETSC_EXTERN PetscErrorCode CSConstraintCreateRotationGauge(CSMesh mesh, Vec x0, CSGlobalConstraint *g);

/* Fairing energy E = 1/2 ||f - f0||^2_{L2} + eps W(f) (soliman2021 Eq. 21), with the L2 norm of the input
   mesh (mass *0(f0), fixed), so grad E = *0(f0) (f - f0) + eps grad W. */
PETSC_EXTERN PetscErrorCode CSEnergyCreateFairing(CSMesh mesh, Vec x0, PetscReal eps, CSEnergy *e);

#endif
