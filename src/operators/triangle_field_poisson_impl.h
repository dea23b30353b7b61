/* Private to src/operators/triangle_field_*.c: the pieces of the Poisson problem L f = d*omega shared by the
   reconstruction (triangle_field_poisson.c) and the fixed-metric extension of App. B (triangle_field_extension.c). */
#ifndef CS_TRIANGLE_FIELD_POISSON_IMPL_H
#define CS_TRIANGLE_FIELD_POISSON_IMPL_H
#include "cs_operators_lens.h"

/* L = d0^T *1 d0 with vertex 0 grounded (identity row and column), B = *1 d0 (H x V) */
PETSC_INTERN PetscErrorCode CSTriangleFieldPoissonOperator(CSMesh m, DM dmH1, Vec star1, Mat *L, Mat *B);
/* component c of a 3-dof vector (dmH3 / dmV3) to (gather) or from a 1-dof one on the same points */
PETSC_INTERN PetscErrorCode CSTriangleFieldComponent(Vec v3, PetscInt c, Vec v1, PetscBool gather);
#endif
