/* Constrained Willmore flow (soliman2021 Sec. 4, Algorithm 1): competitive gradient descent (cgd),
   projected gradient descent (pgd) and Sobolev gradient descent (gd) in the H^2 (or L2) metric, with the
   exact discrete conformal constraint and area / volume / point constraints, on closed surfaces and on
   surfaces with boundary (-task flow -flow_type cgd|pgd|gd). */
#ifndef CS_METHODS_WILLMORE_H
#define CS_METHODS_WILLMORE_H
#include "cs_constraints.h"
#include "cs_output.h"
#include <petscksp.h>

PETSC_EXTERN PetscErrorCode CSFlowCGD(MPI_Comm comm, CSOutput *out);
PETSC_EXTERN PetscErrorCode CSFlowPGD(MPI_Comm comm, CSOutput *out);
PETSC_EXTERN PetscErrorCode CSFlowGD(MPI_Comm comm, CSOutput *out);

/* ---- the linear solver of every step (src/methods/saddle_solver.c) ----
   Solves, with the KSP of prefix "flow_",
     [ A00  X    0  ] [zE]   [rE]      A00 = -I_Q / t_mu   (multipliers of the conformal constraint, FIRST:
     [ X^T  H/t  B  ] [zV] = [rV]                            then selfp is the exact Schur complement)
     [ 0    B^T  -G ] [zX]   [rX]      H = metric (3V x 3V), X = C Dlambda (E x 3V),
   B = the k dense Jacobian rows of the global constraints (area, volume, points), G = diag(g_j)/t_mu. The
   sparse part is a MATNEST [[A00, X], [X^T, H/t]] (or its AIJ conversion with -flow_saddle_mat aij, for
   monolithic direct solvers); the k dense rows are appended by bordering (block elimination: k+1 solves
   with the same operator, then a k x k system), so no dense row ever enters a factorisation. Without the
   conformal constraint the edge block is absent and the KSP solves with H/t alone. */
typedef struct {
  CSMesh    mesh;
  KSP       ksp;
  PetscBool edges;      /* conformal block present */
  PetscBool monolithic; /* -flow_saddle_mat aij */
  Mat       A00, Xt, H11, K, Kaij;
  Mat       XtD, XtDX, S; /* the exact Schur complement S = H/t + X^T (t_mu I_Q^{-1}) X, assembled with a fixed
                             pattern (for -flow_pc_fieldsplit_schur_precondition user) */
  CSMatAddMap add_xtdx, add_h11; /* S refilled from its two terms (fixed patterns) */
  IS        is[2];
  Vec       b, z;
  IS        fixed;      /* Dirichlet dofs of H (identity rows/cols), may be NULL */
  PetscInt  k;
  Vec      *B, *W;      /* k rows, k solutions (each an (E+3V) or 3V vector) */
  PetscReal *G;
  PetscInt  reuse_its;  /* keep the preconditioner while the last solve took <= this many its */
  PetscInt  last_its;   /* Krylov iterations of the last solve */
  PetscInt  setups;     /* preconditioner (factorisation) builds so far */
  PetscInt  solves;     /* linear solves (right-hand sides) so far */
  PetscInt  max_it;     /* the KSP's own iteration limit */
  PetscBool reusing;    /* this step keeps an earlier preconditioner */
  PetscBool krylov;     /* the KSP iterates (not preonly): kept preconditioners and initial guesses allowed */
  PetscInt  backoff, wait; /* fresh steps to take before the next reuse attempt, after failed attempts */
  Vec       iq;         /* this step's I_Q, t_mu and X (borrowed), to rebuild S when a kept one fails */
  PetscReal tmu;
  Mat       X;
  PetscBool have_pc;
  char     **preset;    /* option names inserted as defaults (cleared after the first setup) */
  PetscInt  npreset;
} CSSaddle;

PETSC_EXTERN PetscErrorCode CSSaddleCreate(CSMesh mesh, PetscBool edges, PetscBool h2, PetscInt k, CSSaddle *s);
/* H (3V x 3V) scaled by 1/t; iq, tmu, X ignored without the edge block; rows/g only if k > 0. */
PETSC_EXTERN PetscErrorCode CSSaddleSetOperators(CSSaddle *s, Mat H, PetscReal t, Vec iq, PetscReal tmu, Mat X, Vec rows[], const PetscReal g[]);
/* rE/zE may be NULL without the edge block; rX/zX without k. *its = KSP iterations (sum over the k+1
   bordering solves). */
PETSC_EXTERN PetscErrorCode CSSaddleSolve(CSSaddle *s, Vec rE, Vec rV, const PetscReal rX[], Vec zE, Vec zV, PetscReal zX[], PetscInt *its);
PETSC_EXTERN PetscErrorCode CSSaddleDestroy(CSSaddle *s);

#endif
