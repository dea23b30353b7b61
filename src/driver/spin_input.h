/* Private to src/driver: the files and options of -task spin's inputs (spin_input.c). */
#ifndef CS_DRIVER_SPIN_INPUT_H
#define CS_DRIVER_SPIN_INPUT_H
#include "cs_methods_spin.h"

/* -rho FILE, -rho_location vertex|face, -rho_scale, -rho_bump_*, -rho_mean_curvature s, -rho_from_displacement FILE,
   -rho_smooth t, -spin_target_mesh FILE (Sec. 7.2). On return *loc and *rho describe rho (NULL if zero), and with
   -spin_target_mesh *xtarget holds the target positions and *mu the averaged best-fit similarities. */
PETSC_INTERN PetscErrorCode CSDriverSpinRhoFromOptions(CSSpin spin, Vec x, CSRhoLocation *loc, Vec *rho, Vec *xtarget, Vec *mu);
/* Target tangents for the object's boundary type file|target (-spin_boundary_file FILE); *Tt = NULL otherwise. */
PETSC_INTERN PetscErrorCode CSDriverSpinBoundaryFromOptions(CSSpin spin, Vec xtarget, Vec *Tt);

#endif
