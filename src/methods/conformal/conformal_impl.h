/* Private to src/methods/conformal: the CSConformalFlow object (include/cs_methods_conformal.h). */
#ifndef CS_CONFORMAL_IMPL_H
#define CS_CONFORMAL_IMPL_H
#include "cs_methods_conformal.h"
#include "cs_methods_spin.h"
#include "cs_energy.h"
#include "cs_object.h"

#define CS_CONFORMAL_MAX_BASIS 4 /* {1, N^x, N^y, N^z} */

struct _p_CSConformalFlow {
  CSObjectHeader hdr; /* comm (the mesh's), prefix, monitors (CSConformalFlowMonitorFn) */
  CSMesh         mesh;
  /* options */
  PetscReal              tau, atol, rtol, egrow, sigma, mobius_weight, hfactor;
  PetscInt               max_it, fk;
  PetscBool              inversion, mobius, keep_area;
  CSConformalEigensolver eigensolver;
  /* state: positions (current, input, next), per-vertex areas of the input, the step's fields */
  Vec       x, x0, xnew, area0;
  Vec       area, N, H, v, rho, work, c[CS_CONFORMAL_MAX_BASIS], lambda;
  PetscInt  nc;            /* constraint functions in c */
  CSSpin    spin;          /* Eq. 5 and 6: the Dirac eigenproblem and the Poisson problem */
  CSEnergy  will;          /* W of soliman2021 Eq. 28 */
  Mat       L, B;          /* the filter: L on the current surface, B = M + s L (M^-1 L)^(k-1) */
  KSP       kspf;
  PetscReal area_initial;
  /* progress */
  CSConformalMonitorInfo         s;
  CSConformalFlowConvergedReason reason;
  PetscReal                      W0, Wprev;
  PetscLogDouble                 t0, t_setup, t_steps;
  PetscBool                      setupcalled, started;
};

/* conformal_direction.c: H, W, the filtered and projected direction v and the measures of the state */
PETSC_INTERN PetscErrorCode CSConformalFlowEvaluate(CSConformalFlow F);
/* conformal_integrate.c: rho = tau v, the eigenproblem, the Poisson problem, x <- the new positions */
PETSC_INTERN PetscErrorCode CSConformalFlowIntegrate(CSConformalFlow F);

#endif
