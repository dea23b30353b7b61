/* The conformal Lagrange multiplier made visible (soliman2021 Sec. 3.2): the quadratic differential q per edge
   and the conformal tension force per vertex. With the flow's convention r = g + X^T mu (X = C Dlambda) the
   paper's q (Eq. 7: grad E + sum_j q_ij df_ij / |df_ij|^2 = 0, q_ij > 0 compressive) is q = -C^T mu, since
   (Dlambda^T q)_i = -sum_j q_ij df_ij / |df_ij|^2 (Sec. 3.1); the force sum_j q_ij df_ij / |df_ij|^2 (Eq. 8 summed
   around i, d tau) is then X^T mu, so grad E + force is the Euler-Lagrange residual the flow reports (without
   global constraints; their forces nu_j row_j are not included). With -flow_boundary normals the force includes
   the normal constraint's rows. A kind may report another multiplier (ops.multipliers; ALM: its first-order estimate
   mu + rho c, impls/alm/alm.c). */
#include "willmore_impl.h"

PetscErrorCode CSWillmoreFlowGetConformalMultiplier(CSWillmoreFlow F, Vec q, Vec force)
{
  Vec mu = F->mu, muE;
  PetscFunctionBeginUser;
  PetscCheck(F->setupcalled && F->started, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowGetConformalMultiplier before the first CSWillmoreFlowStep");
  PetscCheck(!CSWFOwnVariables(F), F->hdr.comm, PETSC_ERR_SUP, "-%stype %s: the multipliers live on halfedges; the vertex force and edge q are not defined", F->hdr.prefix, F->type);
  if (!F->conformal) {
    if (q) PetscCall(VecSet(q, 0));
    if (force) PetscCall(VecSet(force, 0));
    PetscFunctionReturn(0);
  }
  if (F->ops.multipliers) PetscCall((*F->ops.multipliers)(F, &mu)); /* ALM: its estimate */
  if (force) {
    PetscCall(MatMultTranspose(F->Xc, mu, force));
    PetscCall(CSWFZeroFixed(F, force));
  }
  if (q) {
    if (F->normals) PetscCall(VecGetSubVector(mu, F->isM[0], &muE));
    else muE = mu;
    PetscCall(MatMultTranspose(F->cc.C, muE, q));
    PetscCall(VecScale(q, -1.0));
    if (F->normals) PetscCall(VecRestoreSubVector(mu, F->isM[0], &muE));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowGetResidual(CSWillmoreFlow F, Vec *r)
{
  PetscFunctionBeginUser;
  PetscCheck(F->setupcalled && F->started, F->hdr.comm, PETSC_ERR_ORDER, "CSWillmoreFlowGetResidual before the first CSWillmoreFlowStep");
  PetscCheck(!CSWFOwnVariables(F), F->hdr.comm, PETSC_ERR_SUP, "-%stype %s: the residual lives on halfedges, not vertices", F->hdr.prefix, F->type);
  *r = F->r;
  PetscFunctionReturn(0);
}
