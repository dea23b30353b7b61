/* The global constraints of the triangle-field flow (soliman2021 App. B): -flow_constraint_volume (B.2),
   -flow_constraint_points (B.1) and -flow_constraint_mobius (the balancing gauge) as extensions through the frozen-metric Poisson reconstruction
   (src/energy/constraints_trianglefield.c). Their rows follow the 3 * 2g period rows <<Y_i|omega>> in F->rows,
   are evaluated by CSTFConstraints and weighted like the vertex flow's global rows (|row|^2, CSWFGlobalWeights). */
#include "trianglefield_impl.h"
#include "cs_constraints.h"

PetscErrorCode CSTFAppBSetUp(CSWillmoreFlow F, CSTriangleField *d)
{
  CSMesh                 m = F->mesh;
  CSTriangleFieldPoisson P;
  CSGlobalConstraint     g;
  char                   opt[96];
  PetscErrorCode         ierr = 0;
  PetscFunctionBeginUser;
  if (!F->vol_set && !F->points[0] && !F->mobius) PetscFunctionReturn(0);
  PetscCall(CSTriangleFieldPoissonCreate(m, d->dmH1, d->dmH3, d->xpos0, &P));
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sconstraint_points", F->hdr.prefix));
  if (F->vol_set) {
    PetscReal A, V;
    PetscCall(CSGeometryAreaVolume(m, d->xpos0, &A, &V));
    ierr = CSConstraintCreateTriangleFieldVolume(m, P, F->vol_given ? F->vol_target : V, &g);
    if (!ierr) ierr = CSWFAddConstraint(F, g);
  }
  if (!ierr && F->points[0]) {
    ierr = CSConstraintCreateTriangleFieldPoints(m, P, opt, F->points, &g);
    if (!ierr) ierr = CSWFAddConstraint(F, g);
  }
  if (!ierr && F->mobius) {
    ierr = CSConstraintCreateTriangleFieldMobius(m, P, d->xpos0, &g);
    if (!ierr) ierr = CSWFAddConstraint(F, g);
  }
  PetscCall(CSTriangleFieldPoissonDestroy(&P)); /* the constraints hold references; on an error nothing leaks */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

/* cx[0..) and, with wantJ, rows[0..) of the App. B constraints at omega = x. */
PetscErrorCode CSTFAppBEvaluate(CSWillmoreFlow F, Vec x, PetscReal cx[], Vec rows[], PetscBool wantJ)
{
  PetscInt off = 0;
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < F->ng; j++) {
    PetscCall(CSGlobalConstraintEvaluate(F->gc[j], x, cx + off, wantJ ? rows + off : NULL));
    off += F->gc[j]->k;
  }
  PetscFunctionReturn(0);
}

/* The number of App. B rows. */
PetscInt CSTFAppBRows(CSWillmoreFlow F)
{
  PetscInt k = 0;
  for (PetscInt j = 0; j < F->ng; j++) k += F->gc[j]->k;
  return k;
}
