/* Energies of the surface behind one small interface: value, gradient (the gradient 2-form of
   soliman2021 Sec. 2: the plain partial derivatives dE/df), and, where an energy has one, an approximate
   Hessian for preconditioning. Constraints (vector-valued, with Jacobians) use the same pattern. */
#ifndef CS_ENERGY_H
#define CS_ENERGY_H
#include "cs_operators.h"
#include "cs_operators_conformal.h"

typedef struct _p_CSEnergy *CSEnergy;
struct _p_CSEnergy {
  char   name[64];
  char   prefix[128]; /* its options' prefix (CSEnergySetOptionsPrefix; a flow gives "<flow prefix><name>_") */
  CSMesh mesh;
  void  *ctx;
  PetscErrorCode (*value)(CSEnergy, Vec x, PetscReal *E);
  PetscErrorCode (*gradient)(CSEnergy, Vec x, PetscReal *E, Vec g); /* E may be NULL */
  PetscErrorCode (*setfromoptions)(CSEnergy); /* its parameters under prefix (NULL: none) */
  /* its Hessian's part of a flow's step metric (NULL: the flow's metric as it is): folds an approximation of its
     Hessian into the H^2/L2 metric w *0 + L *0^{-1} L (scale, mass weight), so the step sees its curvature */
  PetscErrorCode (*metric)(CSEnergy, CSMetric *);
  PetscErrorCode (*destroy)(CSEnergy);
};

PETSC_EXTERN PetscErrorCode CSEnergyValue(CSEnergy e, Vec x, PetscReal *E);
PETSC_EXTERN PetscErrorCode CSEnergyGradient(CSEnergy e, Vec x, PetscReal *E, Vec g);
PETSC_EXTERN PetscErrorCode CSEnergyDestroy(CSEnergy *e);
PETSC_EXTERN PetscErrorCode CSEnergySetOptionsPrefix(CSEnergy e, const char prefix[]);
PETSC_EXTERN PetscErrorCode CSEnergySetFromOptions(CSEnergy e);
/* The energy's part of a step metric m (its metric op; nothing without one). */
PETSC_EXTERN PetscErrorCode CSEnergyMetric(CSEnergy e, CSMetric *m);
/* y = H v, the Hessian of e at x applied to v, by a central difference of the gradient with the largest vertex
   displacement eps (energy.c); work: two vectors like x, or NULL. */
PETSC_EXTERN PetscErrorCode CSEnergyHessianMult(CSEnergy e, Vec x, Vec v, PetscReal eps, Vec work[2], Vec y);
/* For implementations: allocate an energy shell with a name. */
PETSC_EXTERN PetscErrorCode CSEnergyCreateShell(CSMesh mesh, const char name[], CSEnergy *e);

/* W = 1/4 <Lf, *0^{-1} Lf> (soliman2021 Eq. 28), gradient Lh + w (Eq. 29). */
PETSC_EXTERN PetscErrorCode CSEnergyCreateWillmore(CSMesh mesh, CSEnergy *e);
/* A = sum of face areas = 1/2 <Lf, f>, gradient Lf (soliman2021 Sec. 2). */
PETSC_EXTERN PetscErrorCode CSEnergyCreateArea(CSMesh mesh, CSEnergy *e);
/* V = 1/6 sum f_i.(f_j x f_k) (soliman2021 App. B.2), gradient Eq. 23. */
PETSC_EXTERN PetscErrorCode CSEnergyCreateVolume(CSMesh mesh, CSEnergy *e);

/* Central finite-difference check of e's gradient along n random directions (PetscRandom, seeded):
   returns the largest relative error |(E(x+hd)-E(x-hd))/2h - <g,d>| / max(|<g,d>|, tiny). Collective. */
PETSC_EXTERN PetscErrorCode CSEnergyCheckGradient(CSEnergy e, Vec x, PetscReal h, PetscInt n, PetscReal *relerr);

#endif
