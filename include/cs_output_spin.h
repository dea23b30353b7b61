/* The report of a spin transformation (src/output/spin_report.c): the two lines on stdout, the summary keys,
   the ParaView pair (-viewer_dir: step 0 the input with rho, step 1 the result with rho, |lambda| and Q), -o. */
#ifndef CS_OUTPUT_SPIN_H
#define CS_OUTPUT_SPIN_H
#include "cs_output.h"
#include "cs_methods_spin.h"

/* After CSSpinSolve(spin, x, rho) (xt: the -spin_target_mesh positions, or NULL). Summary keys eigenvalue,
   eigen_residual, eps_its, inner_its, poisson_its, seconds_{setup,eigen,poisson}, cpu_seconds_{setup,eigen,poisson},
   problem, dirac_type, boundary, rho_location, rho_min, rho_max (with rho), target_distance_max (with xt), the mesh
   facts; then -viewer_dir, -o and -summary. */
PETSC_EXTERN PetscErrorCode CSSpinReport(CSSpin spin, Vec x, Vec rho, Vec xt, CSOutput *out);

#endif
