/* Setters and getters of the CSSpin object (include/cs_methods_spin.h): what a caller sets before a solve (where
   rho lives, the target of Sec. 7.2, the boundary condition of Sec. 5.7, the inverse iteration of crane2013
   Sec. 6.4.2) and what a summary reads after it (the eigenvalue, its residual, iterations, times). */
#include "spin_impl.h"

CS_OBJECT_GETTER(CSSpin, RhoLocation, CSRhoLocation, rho_loc)
CS_OBJECT_GETTER(CSSpin, BoundaryType, CSSpinBoundary, boundary)
CS_OBJECT_GETTER(CSSpin, DM, DM, dm)
CS_OBJECT_GETTER(CSSpin, Mesh, CSMesh, mesh)
CS_OBJECT_GETTER(CSSpin, Shift, PetscReal, target)

PetscErrorCode CSSpinSetRhoLocation(CSSpin s, CSRhoLocation loc)
{
  PetscFunctionBeginUser;
  s->rho_loc = loc;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetTarget(CSSpin s, Vec xtarget, Vec mu)
{
  PetscFunctionBeginUser;
  PetscCheck(!xtarget == !mu, s->hdr.comm, PETSC_ERR_ARG_WRONG, "CSSpinSetTarget: give both the target positions and their similarities, or neither");
  if (xtarget) PetscCall(PetscObjectReference((PetscObject)xtarget));
  if (mu) PetscCall(PetscObjectReference((PetscObject)mu));
  PetscCall(VecDestroy(&s->xtarget));
  PetscCall(VecDestroy(&s->mu));
  s->xtarget = xtarget;
  s->mu      = mu;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetRestoreArea(CSSpin s, PetscBool restore)
{
  PetscFunctionBeginUser;
  s->restore_area = restore;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetBoundaryType(CSSpin s, CSSpinBoundary b)
{
  PetscFunctionBeginUser;
  s->boundary = b;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetInverseIteration(CSSpin s, PetscBool inverse, PetscInt its)
{
  PetscFunctionBeginUser;
  PetscCheck(its >= 1, s->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "CSSpinSetInverseIteration: %" PetscInt_FMT " steps; need at least 1", its);
  s->inverse     = inverse;
  s->inverse_its = its;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinGetInverseIteration(CSSpin s, PetscBool *inverse, PetscInt *its)
{
  PetscFunctionBeginUser;
  if (inverse) *inverse = s->inverse;
  if (its) *its = s->inverse_its;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinGetProblem(CSSpin s, PetscBool *generalized, PetscBool *shell)
{
  PetscFunctionBeginUser;
  if (generalized) *generalized = s->generalized;
  if (shell) *shell = s->shell;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinGetEigenvalue(CSSpin s, PetscReal *gamma, PetscReal *residual)
{
  PetscFunctionBeginUser;
  if (gamma) *gamma = s->gamma;
  if (residual) *residual = s->residual;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinGetIterationNumbers(CSSpin s, PetscInt *eps_its, PetscInt *inner_its, PetscInt *poisson_its)
{
  PetscFunctionBeginUser;
  if (eps_its) *eps_its = s->eps_its;
  if (inner_its) *inner_its = s->inner_its;
  if (poisson_its) *poisson_its = s->poisson_its;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinGetTimes(CSSpin s, PetscLogDouble wall[3], PetscLogDouble cpu[3])
{
  PetscFunctionBeginUser;
  if (wall) {
    wall[0] = s->t_setup;
    wall[1] = s->t_eigen;
    wall[2] = s->t_poisson;
  }
  if (cpu) {
    cpu[0] = s->c_setup;
    cpu[1] = s->c_eigen;
    cpu[2] = s->c_poisson;
  }
  PetscFunctionReturn(0);
}
