/* The path of a run: its smallest Euler-Lagrange residual (soliman2021 Thm. 3.2; the stopping measure of Sec. 6.1.2,
   EL < 1e-6) and where it was. A run that does not converge either never came near a critical point or passed
   nearest one at some iteration and moved away from it while the energy kept falling: knot1_cgal's CGD reaches
   EL 2.48 (from 101) at iteration 10 and leaves it, EL 13.8 at the guard's stop at 29 (docs/real_meshes.md 0b). */
#include "willmore_impl.h"

/* After each evaluation: record the first residual and the smallest so far with its iteration and energy (NaN
   states are not recorded). A resumed run starts the record at the checkpoint. */
PetscErrorCode CSWFTrackPath(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (PetscIsInfOrNanReal(F->el) || PetscIsInfOrNanReal(F->E)) PetscFunctionReturn(0);
  if (!F->path_set) {
    F->path_set = PETSC_TRUE;
    F->el_first = F->el;
    F->el_min   = PETSC_MAX_REAL;
  }
  if (F->el < F->el_min) {
    F->el_min    = F->el;
    F->E_el_min  = F->E;
    F->it_el_min = F->it;
  }
  PetscFunctionReturn(0);
}
