/* Spin transformations (crane2011): prescribe a change rho of mean curvature half-density, solve the
   eigenvalue problem (D - rho) lambda = gamma lambda for the smallest eigenpair (Sec. 5.5, Eq. 6 or 7; SLEPc
   EPS with the object's prefix spin_, or inverse iteration with a kept factorisation, KSP prefix spin_inverse_),
   then the Poisson problem Delta f~ = div e~ for the new positions (Sec. 5.6, KSP prefix spin_poisson_).
   Boundary conditions of Sec. 5.7 (prescribed tangent directions) and the nearest spin transformation of an
   arbitrary deformation (Sec. 7.2). bin/confsurf -task spin and -task spectrum (Fig. 8, src/driver/task_spin.c, task_spectrum.c). */
#ifndef CS_METHODS_SPIN_H
#define CS_METHODS_SPIN_H
#include <slepceps.h>
#include "cs_operators_dirac.h"
#include "cs_cholmod.h"
#include "cs_quaternion_cholesky.h"
#include "cs_object.h"

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

/* The spin object (opaque; src/methods/spin/spin_impl.h). A spin transformation, as DESIGN.md's example:
     CSSpinCreate(mesh, &spin);            (options prefix "spin_": -spin_solver, -spin_problem, -spin_boundary, ...)
     CSSpinSetRhoLocation(spin, loc);      (and CSSpinSetTarget / CSSpinSetBoundaryTangents when wanted)
     CSSpinSetFromOptions(spin);
     CSSpinSolve(spin, x, rho);            (eigenproblem, global similarity, Eq. 8 + Poisson, area)
     CSSpinGetSolution(spin, &xnew);
     CSSpinDestroy(&spin);
   The factorisations (EPS/ST or the inverse iteration's KSP, the Poisson KSP) are made on the first solve and
   kept: later solves on the same mesh (a flow, crane2013 Sec. 6.4.2) refactor numerically only. The solver parts
   (CSSpinSolveEigen, CSSpinNormalize, CSSpinReconstruct, ...) stay public for the conformal flow, which takes the
   steps one by one. */
typedef struct _p_CSSpin *CSSpin;
/* called at the end of every CSSpinSolve */
typedef PetscErrorCode (*CSSpinMonitorFn)(CSSpin spin, void *ctx);

PETSC_EXTERN PetscErrorCode CSSpinCreate(CSMesh mesh, CSSpin *spin);
PETSC_EXTERN PetscErrorCode CSSpinSetFromOptions(CSSpin spin);
/* the work vectors of CSSpinSolve; called by CSSpinSolve when needed */
PETSC_EXTERN PetscErrorCode CSSpinSetUp(CSSpin spin);
/* A spin transformation of the surface x (dmV3) by rho (where CSSpinSetRhoLocation says; NULL: rho = 0):
   the smallest eigenpair (Sec. 5.5, 5.7), the global similarity (fit to the target's similarities, else the
   rotation closest to 1; only a scale with prescribed boundary tangents), the positions by Eq. 8 and the Poisson
   problem (Sec. 5.6; the translation of the target, else the vertex mean of x), then the area of x unless a
   target is set or CSSpinSetRestoreArea(spin, PETSC_FALSE). */
PETSC_EXTERN PetscErrorCode CSSpinSolve(CSSpin spin, Vec x, Vec rho);
/* the transformed surface of the last CSSpinSolve (dmV3, owned by the object) */
PETSC_EXTERN PetscErrorCode CSSpinGetSolution(CSSpin spin, Vec *xnew);
/* its eigenvector lambda (global on the object's DM, owned by the object) */
PETSC_EXTERN PetscErrorCode CSSpinGetSpinor(CSSpin spin, Vec *lambda);
/* CSSpinSetOptionsPrefix, GetOptionsPrefix, MonitorSet (up to 8 monitors, called once per Solve in the order set;
   destroy, may be NULL, frees ctx at Destroy) and Destroy: the skeleton of every method object (include/cs_object.h) */
CS_OBJECT_DECLARE(CSSpin, CSSpinMonitorFn);

/* Setters (before CSSpinSetFromOptions; the options given override those that are options) */
PETSC_EXTERN PetscErrorCode CSSpinSetRhoLocation(CSSpin spin, CSRhoLocation loc);
PETSC_EXTERN PetscErrorCode CSSpinGetRhoLocation(CSSpin spin, CSRhoLocation *loc);
/* Sec. 7.2: the deformation xtarget (dmV3) and its best-fit similarities mu (dm) that CSSpinSolve fits to;
   NULL, NULL: none. The object keeps references. */
PETSC_EXTERN PetscErrorCode CSSpinSetTarget(CSSpin spin, Vec xtarget, Vec mu);
PETSC_EXTERN PetscErrorCode CSSpinSetRestoreArea(CSSpin spin, PetscBool restore);
/* -spin_boundary (Sec. 5.7); the default is keep on meshes with a boundary */
PETSC_EXTERN PetscErrorCode CSSpinSetBoundaryType(CSSpin spin, CSSpinBoundary b);
PETSC_EXTERN PetscErrorCode CSSpinGetBoundaryType(CSSpin spin, CSSpinBoundary *b);
/* -spin_solver inverse with its steps (-spin_iterations), or back to the EPS default */
PETSC_EXTERN PetscErrorCode CSSpinSetInverseIteration(CSSpin spin, PetscBool inverse, PetscInt its);
PETSC_EXTERN PetscErrorCode CSSpinGetInverseIteration(CSSpin spin, PetscBool *inverse, PetscInt *its);

/* Getters */
/* 4 dofs per vertex: the space of lambda */
PETSC_EXTERN PetscErrorCode CSSpinGetDM(CSSpin spin, DM *dm);
PETSC_EXTERN PetscErrorCode CSSpinGetMesh(CSSpin spin, CSMesh *mesh);
/* -spin_shift: the shift toward 0, in units of the unit sphere's spectrum */
PETSC_EXTERN PetscErrorCode CSSpinGetShift(CSSpin spin, PetscReal *shift);
/* generalized: Eq. 6 (else Eq. 7); shell: the matrix-free Dirac operator (NULL: not wanted) */
PETSC_EXTERN PetscErrorCode CSSpinGetProblem(CSSpin spin, PetscBool *generalized, PetscBool *shell);
/* the last eigenvalue (units of Eq. 7 or Eq. 6) and ||K x - gamma x|| / ||x|| of the scaled problem */
PETSC_EXTERN PetscErrorCode CSSpinGetEigenvalue(CSSpin spin, PetscReal *gamma, PetscReal *residual);
/* eigensolver iterations, its inner (Krylov or preconditioner) solves, Poisson iterations of the last solves */
PETSC_EXTERN PetscErrorCode CSSpinGetIterationNumbers(CSSpin spin, PetscInt *eps_its, PetscInt *inner_its, PetscInt *poisson_its);
/* seconds of set-up, eigen solve and Poisson: wall clock and this process's CPU time (NULL: not wanted) */
PETSC_EXTERN PetscErrorCode CSSpinGetTimes(CSSpin spin, PetscLogDouble wall[3], PetscLogDouble cpu[3]);

/* The solver's steps, one by one (the conformal flow, crane2013 Sec. 6: its own rho, boundary directions and
   area rule each step; -task spectrum). The factorisations are kept in the object between calls. */
/* Boundary tangents (Sec. 5.7): Ttarget is a dmV3 global vector (read on boundary vertices), NULL for "keep". */
PETSC_EXTERN PetscErrorCode CSSpinSetBoundaryTangents(CSSpin spin, Vec Ttarget);
/* crane2013 Sec. 6.3.1: boundary lambda = (cos th/2 - w sin th/2)(a - b V~) maps the unit direction V (dmV3, on
   boundary vertices) to V~ (Vt; NULL: V~ = V) instead of the tangent T to T~; V = NULL returns to the tangents. */
PETSC_EXTERN PetscErrorCode CSSpinSetBoundaryDirections(CSSpin spin, Vec V, Vec Vt);
/* The right-hand side b = -sum_j w_ij e~_ij of the Poisson problem L f~ = b (Sec. 5.6, Eq. 8), dmV3 */
PETSC_EXTERN PetscErrorCode CSSpinPoissonRHS(CSSpin spin, Vec x, Vec lambda, Vec b);
/* Smallest eigenpair for the surface x and rho; lambda is a global vector of the object's DM. */
PETSC_EXTERN PetscErrorCode CSSpinSolveEigen(CSSpin spin, Vec x, CSRhoLocation loc, Vec rho, Vec lambda);
/* The next CSSpinSolveEigen starts from lambda = 1 (the identity) instead of the last eigenvector (a flow on a
   new surface each step: crane2013 Sec. 6.1, rho^m = 0). */
PETSC_EXTERN PetscErrorCode CSSpinResetStart(CSSpin spin);
/* The nev smallest eigenvalues of Eq. 7 (rho = 0 unless given), ascending, unscaled (Fig. 8). */
PETSC_EXTERN PetscErrorCode CSSpinSpectrum(CSSpin spin, Vec x, CSRhoLocation loc, Vec rho, PetscInt nev, PetscReal eig[], PetscInt *nconv);
/* The signed spectrum of Eq. 6 with rho = 0 (Sec. 6.2, Fig. 8; spin_signed.c): the nev eigenvalues of smallest
   |gamma| (ties ascending), the kernel of A (gamma = 0) first; *nkernel its dimension. With nvec > 0 the first
   nvec eigenvectors are created in vecs[] (global on the object's DM; the caller destroys them). EPS prefixes:
   the object's followed by kernel_ and signed_ (spin_kernel_, spin_signed_). */
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

/* rho and the deformations of crane2011 Sec. 7 (the driver's -rho_* and -spin_target_mesh inputs) */
/* rho += (L g) / (2 M) for a normal displacement g (dmV1; Sec. 7.1, Fig. 20), and the heat filter
   (M + t L) rho~ = M rho of a per-vertex rho (Fig. 13; KSP prefix: the object's followed by smooth_). spin_rho_filters.c. */
PETSC_EXTERN PetscErrorCode CSSpinRhoFromDisplacement(CSSpin spin, Vec x, Vec g, Vec rho);
PETSC_EXTERN PetscErrorCode CSSpinRhoSmooth(CSSpin spin, Vec x, PetscReal t, Vec rho);
/* Sec. 7.2 / Fig. 21 (spin_interpolate.c): the surface f_t of the similarities lambda_t = exp(t log mu) between x
   (t = 0) and the deformation xt (t = 1, mu its best-fit similarities), with the reconstruction residuals of the
   ends r0, r1 (from CSSpinInterpolateSetUp) blended in so that both ends are reproduced exactly. */
PETSC_EXTERN PetscErrorCode CSSpinInterpolateSetUp(CSSpin spin, Vec x, Vec xt, Vec mu, Vec r0, Vec r1);
PETSC_EXTERN PetscErrorCode CSSpinInterpolate(CSSpin spin, Vec x, Vec mu, Vec r0, Vec r1, PetscReal t, Vec xs);
/* rho += s H with the signed vertex mean curvature H = (L f).N / (2 M) (spin_rho.c; s = -1: crane2011 Sec. 7.3). */
PETSC_EXTERN PetscErrorCode CSSpinRhoAddMeanCurvature(CSMesh mesh, Vec x, PetscReal s, Vec rho);
/* Best-fit similarity per face averaged to vertices (Sec. 7.2), mu global on the object's DM. */
PETSC_EXTERN PetscErrorCode CSSpinBestFitSimilarities(CSSpin spin, Vec x, Vec xt, Vec mu);
/* Optimal per-face rho for mu (Sec. 7.2): rho_k = Re(conj(B mu)_k (D mu)_k) / |(B mu)_k|^2, dmF1 global. */
PETSC_EXTERN PetscErrorCode CSSpinOptimalRho(CSSpin spin, Vec x, Vec mu, Vec rho);

/* PC type "csspinlap" (spin_precond.c): the scalar preconditioner of -spin_solver precond; registered by
   CSInitializePackage */
#define PCCSSPINLAP "csspinlap"
PETSC_EXTERN PetscErrorCode PCCreate_CSSpinLap(PC);

#endif
