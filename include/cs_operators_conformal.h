/* Operators of the conformal constraint and the metrics of constrained Willmore flow (soliman2021 Sec. 3,
   App. D): log edge lengths, the cross-ratio map C (Eq. 24), the log-length derivative Dlambda, the metric
   I_Q on quadratic differentials (Eq. 25) and the Sobolev H^2 metric (Eq. 26), each a PETSc Mat/Vec on the
   distributed mesh. */
#ifndef CS_OPERATORS_CONFORMAL_H
#define CS_OPERATORS_CONFORMAL_H
#include "cs_operators.h"

/* lambda = log l (soliman2021 Sec. 3, "logarithmic coordinates"), a dmE1 vector. */
PETSC_EXTERN PetscErrorCode CSOperatorLogLengths(CSMesh mesh, Vec x, Vec lambda);

/* Cross-ratio map C: E x E AIJ on dmE1 summed from the per-face blocks of soliman2021 Eq. 24, so that
   (C lambda)_ij = lambda_il - lambda_lj + lambda_jk - lambda_ki = log c_ij. With interior_only the rows of
   boundary edges are left empty (the C_0 of App. D, "Boundary conditions"). */
PETSC_EXTERN PetscErrorCode CSOperatorCrossRatio(CSMesh mesh, PetscBool interior_only, Mat *C);

/* Dlambda: E x 3V AIJ with rows (f_j - f_i)^T / l_ij^2 at vertex j and the negative at vertex i
   (soliman2021 Eq. 5; the printed App. D text drops the 1/l^2). Columns of vertices with fixed[v] true are
   left out (Dirichlet boundary, App. D); fixed may be NULL. MAT_REUSE_MATRIX refills *D. */
PETSC_EXTERN PetscErrorCode CSOperatorLogLengthDerivative(CSMesh mesh, Vec x, const PetscBool fixed[], MatReuse reuse, Mat *D);

/* Diagonal of I_Q (soliman2021 Eq. 25): 1 / (w_ij l_ij^2), a dmE1 vector. Cotan weights w_ij <= wmin
   (non-Delaunay edges, where Eq. 25 would be negative or infinite) are replaced by wmin; *nguard returns
   the global number of such edges (may be NULL). Boundary edges get 1/(wmin l^2) if their w is small. */
PETSC_EXTERN PetscErrorCode CSOperatorQuadDiffMetric(CSMesh mesh, Vec x, PetscReal wmin, Vec iq, PetscInt *nguard);

/* The Sobolev H^2 metric I_H2 = *0 + L *0^{-1} L (soliman2021 Eq. 26), acting on each coordinate: 3V x 3V.
   CSH2Metric keeps L (3 comps), the mass and the assembled product (a two-ring AIJ made with MatMatMult,
   exact, used as the matrix and for preconditioning), and a shell Mat applying *0 f + L (*0^{-1} (L f))
   without the product. The L2 alternative (-flow_metric l2) is the diagonal mass *0. Eq. 26 adds terms of
   different units (*0 ~ length^2, L *0^{-1} L ~ length^-2): the paper's meshes have unit size. The flows set
   mass_weight = 1/s^4 with s = sqrt(area/4pi) of the input, so that w *0 + L *0^{-1} L scales as length^-2
   in both terms and the flow does not depend on the size of the input (s = 1: Eq. 26 as printed). */
typedef struct {
  CSMesh    mesh;
  PetscBool h2;        /* else L2, or H^1 if h1 */
  PetscBool h1;        /* H^1 = sqrt(w) *0 + L (set after Create; h2 false): the order of the area energy's Hessian */
  PetscReal mass_weight; /* w in w *0 + L *0^{-1} L (1 after Create; see CSMetricCreate) */
  PetscReal scale;       /* the metric is scale (w *0 + L *0^{-1} L) (1 after Create; the fairing energy: eps) */
  Mat       L3, Ls;    /* L and *0^{-1} L (rows scaled) */
  Mat       H;         /* assembled metric (AIJ, 3V x 3V) */
  Mat       shell;     /* matrix-free H^2 */
  Vec       m3, minv3; /* *0 repeated per component and its inverse */
  Vec       work;
} CSMetric;
PETSC_EXTERN PetscErrorCode CSMetricCreate(CSMesh mesh, PetscBool h2, CSMetric *m);
/* Recomputes everything at positions x. */
PETSC_EXTERN PetscErrorCode CSMetricUpdate(CSMetric *m, Vec x);
PETSC_EXTERN PetscErrorCode CSMetricDestroy(CSMetric *m);

/* PC type "csh2" (h2_pc.c): P^{-1} = (s *0 + L)^{-1} *0 (s *0 + L)^{-1}, s = sqrt(mass_weight), a spectrally
   equivalent (condition <= 2) preconditioner of the H^2 metric made of shifted-Laplacian solves. Register once
   (CSMetricCreate does); compose the metric on an operator op = scale * I_H2 (identity-like rows `fixed`, or
   NULL) so that -<prefix>pc_type csh2 can find it. */
PETSC_EXTERN PetscErrorCode CSH2PCRegister(void);
PETSC_EXTERN PetscErrorCode CSH2PCCompose(Mat op, CSMetric *metric, PetscReal scale, IS fixed);
/* the same metric as composed on src, for op = scale * src (no-op if src has none) */
PETSC_EXTERN PetscErrorCode CSH2PCComposeFrom(Mat src, Mat op, PetscReal scale, IS fixed);

#endif
