/* Private to src/methods/spin: the CSSpin object (include/cs_methods_spin.h). Outside this folder the object is
   reached through its functions only. */
#ifndef CS_SPIN_IMPL_H
#define CS_SPIN_IMPL_H
#include <time.h>
#include "cs_methods_spin.h"
#include "cs_object.h"

/* CPU seconds of this process, all threads (PetscGetCPUTime has a coarse resolution here) */
static inline PetscLogDouble CSSpinCPUTime(void)
{
  struct timespec t;
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return (PetscLogDouble)t.tv_sec + 1e-9 * (PetscLogDouble)t.tv_nsec;
}

struct _p_CSSpin {
  CSObjectHeader hdr; /* comm (the mesh's), prefix (default "spin_"), monitors (CSSpinMonitorFn) */
  CSMesh         mesh;
  DM             dm;  /* 4 dofs per vertex: lambda */
  DM             dmr; /* reduced space of Sec. 5.7 (2 dofs on boundary vertices), or NULL */

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

  /* what CSSpinSolve transforms with (setters): where rho lives, the target of Sec. 7.2, the area rule */
  CSRhoLocation rho_loc;
  Vec           xtarget, mu; /* Sec. 7.2: the deformation and its best-fit similarities (references), or NULL */
  PetscBool     restore_area;

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
  PetscBool setupcalled;
  Vec       lambda, xnew; /* CSSpinSolve's eigenvector (dm) and transformed surface (dmV3) */

  /* results */
  PetscReal gamma;    /* the eigenvalue, in the units of A^* A lambda = gamma M_V lambda (Eq. 7) or Eq. 6 */
  PetscReal residual; /* ||K x - gamma_K x|| / ||x|| of the scaled problem */
  PetscInt  eps_its, inner_its, poisson_its;
  PetscLogDouble t_setup, t_eigen, t_poisson;       /* wall clock */
  PetscLogDouble c_setup, c_eigen, c_poisson;       /* CPU time of this process (rank 0): robust to a loaded machine */
};

/* the options prefix of a solver of the object: the object's prefix followed by suffix ("inverse_", "poisson_") */
PETSC_INTERN PetscErrorCode CSSpinSubPrefix(CSSpin spin, const char suffix[], char prefix[], size_t len);
/* Sets pc to the scalar preconditioner V^-1 ((L + c M)^-1 (x) I_4) V^-1 of K (spin_precond.c). */
PETSC_INTERN PetscErrorCode CSSpinSetUpScalarPC(CSSpin spin, Vec x, CSRhoLocation loc, Vec rho, PC pc);
/* log events of the Poisson step */
PETSC_INTERN PetscErrorCode CSSpinLogPoissonBegin(void);
PETSC_INTERN PetscErrorCode CSSpinLogPoissonEnd(void);
/* x = ksp^{-1} b, an error naming the solve (what) and the KSP's options if it diverges; adds the Krylov
   iterations to *its */
PETSC_INTERN PetscErrorCode CSSpinKSPSolve(CSSpin spin, KSP ksp, Vec b, Vec x, const char what[], PetscInt *its);

#endif
