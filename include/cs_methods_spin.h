/* Spin transformations (crane2011): prescribe a change rho of mean curvature half-density, solve the
   eigenvalue problem (D - rho) lambda = gamma lambda for the smallest eigenpair (Sec. 5.5, Eq. 6 or 7; SLEPc
   EPS with prefix spin_, or inverse iteration with a kept factorisation, KSP prefix spin_inverse_), then the
   Poisson problem Delta f~ = div e~ for the new positions (Sec. 5.6, KSP prefix spin_poisson_).
   Boundary conditions of Sec. 5.7 (prescribed tangent directions) and the nearest spin transformation of an
   arbitrary deformation (Sec. 7.2). bin/confsurf -task spin and -task spectrum (Fig. 8, src/driver/task_spin.c, task_spectrum.c). */
#ifndef CS_METHODS_SPIN_H
#define CS_METHODS_SPIN_H
#include <slepceps.h>
#include <time.h>
#include "cs_operators_dirac.h"
#include "cs_cholmod.h"
#include "cs_quaternion_cholesky.h"

/* CPU seconds of this process, all threads (PetscGetCPUTime has a coarse resolution here) */
static inline PetscLogDouble CSSpinCPUTime(void)
{
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (PetscLogDouble)t.tv_sec + 1e-9 * (PetscLogDouble)t.tv_nsec;
}

/* crane2011 Eq. 8: e~_ij = 1/3 conj(l_i) e l_i + 1/6 conj(l_i) e l_j + 1/6 conj(l_j) e l_i + 1/3 conj(l_j) e l_j for the
   edge vector e = f_j - f_i. The two middle terms are q - conj(q) = 2 Im q with q = conj(l_i) e l_j, so e~ is
   imaginary. (The Poisson right-hand side, and the closing error of the conformal flow.) */
static inline void CSSpinTransformedEdge(const PetscReal li[4], const PetscReal lj[4], const PetscReal e[3], PetscReal out[3])
{
  PetscReal eq[4] = {0, e[0], e[1], e[2]}, ti[4], tj[4], a[4], b[4], c[4], d[4];
  CSQuatConjMul(li, eq, ti);
  CSQuatConjMul(lj, eq, tj);
  CSQuatMul(ti, li, a);
  CSQuatMul(ti, lj, b);
  CSQuatMul(tj, li, c);
  CSQuatMul(tj, lj, d);
  for (int k = 0; k < 3; k++) out[k] = a[k + 1] / 3 + b[k + 1] / 6 + c[k + 1] / 6 + d[k + 1] / 3;
}

typedef enum {
  CS_SPIN_BOUNDARY_NONE, /* natural (free) boundary; the default is KEEP on meshes with a boundary */
  CS_SPIN_BOUNDARY_KEEP, /* target tangents = current tangents */
  CS_SPIN_BOUNDARY_FILE, /* target tangents from -spin_boundary_file (3 values per vertex, file order) */
  CS_SPIN_BOUNDARY_TARGET /* target tangents = outgoing boundary edges of -target_mesh (Sec. 7.4) */
} CSSpinBoundary;

typedef struct _p_CSSpin *CSSpin;
struct _p_CSSpin {
  CSMesh mesh;
  DM     dm;  /* 4 dofs per vertex: lambda */
  DM     dmr; /* reduced space of Sec. 5.7 (2 dofs on boundary vertices), or NULL */

  /* options */
  PetscBool      generalized; /* Eq. 6 instead of Eq. 7 */
  PetscBool      shell;       /* matrix-free Dirac operator */
  PetscBool      inverse;     /* inverse iteration instead of EPS */
  PetscBool      scalar_pc;   /* EPS with STPRECOND and the scalar Laplacian preconditioner (spin_precond.c) */
  PetscBool      solver_set;  /* -spin_solver given */
  PetscBool      quat_factor; /* K - sigma is quaternionic and serial: csquat is the default factorisation */
  PetscInt       inverse_its;
  PetscBool      keep_factor; /* inverse iteration: keep the numeric factorisation across solves */
  PetscBool      pin;         /* Poisson: pin one vertex instead of mean-zero */
  CSSpinBoundary boundary;
  PetscReal      target;      /* shift toward 0 (dimensionless: in units of the unit sphere's spectrum) */
  PetscBool      target_set;

  /* state */
  Vec       mass;    /* dmV1: barycentric vertex areas M_V */
  Vec       v4;      /* dm: V = M_V^{-1/2} rescaled to mean 1 (Sec. 5.5), 4 entries per vertex */
  PetscReal vmean;   /* the mean of M_V^{-1/2} divided out */
  Vec       Ttarget; /* dmV3: target unit tangents on boundary vertices (Sec. 5.7), or NULL */
  Vec       Vcur;    /* dmV3: the directions V the boundary lambda maps to Ttarget (crane2013 Sec. 6.3.1), NULL: the tangents */
  Mat       P;       /* V U (dm x dmr) for Sec. 5.7, or NULL */
  Mat       X, K, Y; /* X = A^H M_F A; K = the operator of the standard problem; Y = B^H M_F A (Eq. 6) */
  EPS       eps;
  KSP       kinv;
  Mat       Kinv;    /* K - sigma I for the inverse iteration */
  Mat       Ks;      /* K - sigma I sharing K's structure, factored by shift-and-invert (serial Eq. 7), or NULL */
  PetscObjectId    ks_id; /* the K and nonzero state Ks was made from */
  PetscObjectState ks_nz;
  KSP       kpois;
  Mat       L;
  Mat       Ls;      /* L + c M (dmV1), the scalar preconditioner of spin_precond.c */
  KSP       klap;    /* its solver, prefix spin_lap_ */
  PetscInt  lap_its;
  PetscReal lap_shift; /* c in units of 4 pi / area */
  Vec       start;   /* initial vector of the eigensolver (reduced space), kept between solves */

  /* results */
  PetscReal gamma;    /* the eigenvalue, in the units of A^* A lambda = gamma M_V lambda (Eq. 7) or Eq. 6 */
  PetscReal residual; /* ||K x - gamma_K x|| / ||x|| of the scaled problem */
  PetscInt  eps_its, inner_its, poisson_its;
  PetscLogDouble t_setup, t_eigen, t_poisson;       /* wall clock */
  PetscLogDouble c_setup, c_eigen, c_poisson;       /* CPU time of this process (rank 0): robust to a loaded machine */
};

/* Sets pc to the scalar preconditioner V^-1 ((L + c M)^-1 (x) I_4) V^-1 of K (spin_precond.c). */
PETSC_EXTERN PetscErrorCode CSSpinSetUpScalarPC(CSSpin spin, Vec x, CSRhoLocation loc, Vec rho, PC pc);
/* PC type "csspinlap" (spin_precond.c): the scalar preconditioner of -spin_solver precond; registered by CSInitializePackage */
#define PCCSSPINLAP "csspinlap"
PETSC_EXTERN PetscErrorCode PCCreate_CSSpinLap(PC);
PETSC_EXTERN PetscErrorCode CSSpinCreate(CSMesh mesh, CSSpin *spin);
PETSC_EXTERN PetscErrorCode CSSpinSetFromOptions(CSSpin spin);
/* Boundary tangents (Sec. 5.7): Ttarget is a dmV3 global vector (read on boundary vertices), NULL for "keep". */
PETSC_EXTERN PetscErrorCode CSSpinSetBoundaryTangents(CSSpin spin, Vec x, Vec Ttarget);
/* crane2013 Sec. 6.3.1: boundary lambda = (cos th/2 - w sin th/2)(a - b V~) maps the unit direction V (dmV3, on
   boundary vertices) to V~ (Vt; NULL: V~ = V) instead of the tangent T to T~; V = NULL returns to the tangents. */
PETSC_EXTERN PetscErrorCode CSSpinSetBoundaryDirections(CSSpin spin, Vec V, Vec Vt);
/* The right-hand side b = -sum_j w_ij e~_ij of the Poisson problem L f~ = b (Sec. 5.6, Eq. 8), dmV3 */
PETSC_EXTERN PetscErrorCode CSSpinPoissonRHS(CSSpin spin, Vec x, Vec lambda, Vec b);
/* Smallest eigenpair for the surface x and rho; lambda is a global vector of spin->dm. */
PETSC_EXTERN PetscErrorCode CSSpinSolveEigen(CSSpin spin, Vec x, CSRhoLocation loc, Vec rho, Vec lambda);
/* The next CSSpinSolveEigen starts from lambda = 1 (the identity) instead of the last eigenvector (a flow on a
   new surface each step: crane2013 Sec. 6.1, rho^m = 0). */
PETSC_EXTERN PetscErrorCode CSSpinResetStart(CSSpin spin);
/* The nev smallest eigenvalues of Eq. 7 (rho = 0 unless given), ascending, unscaled (Fig. 8). */
PETSC_EXTERN PetscErrorCode CSSpinSpectrum(CSSpin spin, Vec x, CSRhoLocation loc, Vec rho, PetscInt nev, PetscReal eig[], PetscInt *nconv);
/* The signed spectrum of Eq. 6 with rho = 0 (Sec. 6.2, Fig. 8; spin_signed.c): the nev eigenvalues of smallest
   |gamma| (ties ascending), the kernel of A (gamma = 0) first; *nkernel its dimension. With nvec > 0 the first
   nvec eigenvectors are created in vecs[] (global on spin->dm; the caller destroys them). EPS prefixes
   spin_kernel_ and spin_signed_. */
PETSC_EXTERN PetscErrorCode CSSpinSpectrumSigned(CSSpin spin, Vec x, PetscInt nev, PetscReal eig[], PetscInt nvec, Vec vecs[], PetscInt *nkernel);
/* A Dirac sphere (Sec. 6.2, Fig. 9, 11): the surface of the eigenvector lambda (changed in place: its constant
   component removed unless it lies in the kernel, then normalised), scaled to the area of x. */
PETSC_EXTERN PetscErrorCode CSSpinDiracSphere(CSSpin spin, Vec x, Vec lambda, PetscBool kernel, Vec xnew);
/* lambda is determined up to a constant right factor c in H (a global similarity): choose c by least squares
   against mu (a dm vector), or with mu = NULL the rotation that best maps lambda to 1 and unit mean |lambda|^2;
   only a positive scale when rotation_too is false (prescribed boundary tangents must not turn). */
PETSC_EXTERN PetscErrorCode CSSpinNormalize(CSSpin spin, Vec lambda, Vec mu, PetscBool rotation_too);
/* New positions from Eq. 8 and the Poisson problem; the translation is fixed by matching the vertex mean of
   xcenter (or pinning one vertex at its position in xcenter with -spin_pin_vertex). */
PETSC_EXTERN PetscErrorCode CSSpinReconstruct(CSSpin spin, Vec x, Vec lambda, Vec xcenter, Vec xnew);
/* Scale xnew about its vertex mean to the area of xref (a painted rho fixes the shape, not its size). */
PETSC_EXTERN PetscErrorCode CSSpinRestoreArea(CSSpin spin, Vec xref, Vec xnew);
PETSC_EXTERN PetscErrorCode CSSpinDestroy(CSSpin *spin);

/* Inputs of rho (src/methods/spin/spin_rho.c): -rho FILE, -rho_location vertex|face, -rho_scale, -rho_bump_*,
   -rho_mean_curvature s, -target_mesh FILE (Sec. 7.2). On return *loc and *rho describe rho (NULL if zero), and
   with -target_mesh *xtarget holds the target positions and *mu the averaged best-fit similarities. */
PETSC_EXTERN PetscErrorCode CSSpinRhoFromOptions(CSSpin spin, Vec x, CSRhoLocation *loc, Vec *rho, Vec *xtarget, Vec *mu);
/* rho += (L g) / (2 M) for a normal displacement g (dmV1; Sec. 7.1, Fig. 20), and the heat filter
   (M + t L) rho~ = M rho of a per-vertex rho (Fig. 13; KSP prefix spin_smooth_). spin_rho_filters.c. */
PETSC_EXTERN PetscErrorCode CSSpinRhoFromDisplacement(CSSpin spin, Vec x, Vec g, Vec rho);
PETSC_EXTERN PetscErrorCode CSSpinRhoSmooth(CSSpin spin, Vec x, PetscReal t, Vec rho);
/* Sec. 7.2 / Fig. 21 (spin_interpolate.c): the surface f_t of the similarities lambda_t = exp(t log mu) between x
   (t = 0) and the deformation xt (t = 1, mu its best-fit similarities), with the reconstruction residuals of the
   ends r0, r1 (from CSSpinInterpolateSetUp) blended in so that both ends are reproduced exactly. */
PETSC_EXTERN PetscErrorCode CSSpinInterpolateSetUp(CSSpin spin, Vec x, Vec xt, Vec mu, Vec r0, Vec r1);
PETSC_EXTERN PetscErrorCode CSSpinInterpolate(CSSpin spin, Vec x, Vec mu, Vec r0, Vec r1, PetscReal t, Vec xs);
/* rho += s H with the signed vertex mean curvature H = (L f).N / (2 M) (spin_rho.c; s = -1: crane2011 Sec. 7.3). */
PETSC_EXTERN PetscErrorCode CSSpinRhoAddMeanCurvature(CSMesh mesh, Vec x, PetscReal s, Vec rho);
/* Target tangents for -spin_boundary file|target (-spin_boundary_file FILE); *Tt = NULL for none|keep. */
PETSC_EXTERN PetscErrorCode CSSpinBoundaryFromOptions(CSSpin spin, Vec xtarget, Vec *Tt);
/* Best-fit similarity per face averaged to vertices (Sec. 7.2), mu global on spin->dm. */
PETSC_EXTERN PetscErrorCode CSSpinBestFitSimilarities(CSSpin spin, Vec x, Vec xt, Vec mu);
/* Optimal per-face rho for mu (Sec. 7.2): rho_k = Re(conj(B mu)_k (D mu)_k) / |(B mu)_k|^2, dmF1 global. */
PETSC_EXTERN PetscErrorCode CSSpinOptimalRho(CSSpin spin, Vec x, Vec mu, Vec rho);

/* internal: log events of the Poisson step */
PETSC_EXTERN PetscErrorCode CSSpinLogPoissonBegin(void);
PETSC_EXTERN PetscErrorCode CSSpinLogPoissonEnd(void);
/* internal: x = ksp^{-1} b, an error naming the solve (what) and the KSP's options if it diverges; adds the
   Krylov iterations to *its */
PETSC_EXTERN PetscErrorCode CSSpinKSPSolve(CSSpin spin, KSP ksp, Vec b, Vec x, const char what[], PetscInt *its);

#endif
