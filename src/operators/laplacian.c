/* Cotan Laplacian assembled face by face: each face adds the 3x3 block of its half-cotan edge weights. */
#include "cs_operators.h"

typedef enum {
  WEIGHT_COTAN,   /* half-cotan weights */
  WEIGHT_UNIFORM, /* 1 per face side */
  WEIGHT_SCALED   /* 1/sqrt(face area) per face side */
} Weight;

/* Adds the face blocks to A (dof block size bs: the same weight on each of the bs components). */
static PetscErrorCode AssembleCotanLaplacian(CSMesh m, Vec x, DM dmX, PetscInt bs, MatReuse reuse, Mat *A, Weight weight)
{
  Vec              xl;
  const PetscReal *p;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) {
    PetscCall(CSOperatorCreateVertexMatrix(m, dmX, bs, MATAIJ, A));
    PetscCall(MatSetOption(*A, MAT_SYMMETRIC, PETSC_TRUE));
  } else PetscCall(MatZeroEntries(*A));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscInt *v = F.v;
    PetscReal       cot[3];
    PetscScalar     K[9] = {0};
    if (weight == WEIGHT_UNIFORM) cot[0] = cot[1] = cot[2] = 1; /* each interior edge in two faces: weight 1 */
    else if (weight == WEIGHT_SCALED) {
      PetscReal an[3], A;
      CSTriangleAreaVector(F.c, an);
      A      = CSVecNorm(an);
      cot[0] = cot[1] = cot[2] = A > 0 ? 1 / PetscSqrtReal(A) : 0;
    } else CSTriangleCotans(F.c, cot);
    for (int k = 0; k < 3; k++) {
      int       i = (k + 1) % 3, j = (k + 2) % 3;
      PetscReal w = 0.5 * cot[k];
      K[3 * i + i] += w;
      K[3 * j + j] += w;
      K[3 * i + j] -= w;
      K[3 * j + i] -= w;
    }
    for (PetscInt d = 0; d < bs; d++) {
      PetscInt rows[3] = {bs * v[0] + d, bs * v[1] + d, bs * v[2] + d};
      PetscCall(MatSetValuesLocal(*A, 3, rows, 3, rows, K, ADD_VALUES));
    }
  }
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorLaplacian(CSMesh m, Vec x, MatReuse reuse, Mat *L)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV1, 1, reuse, L, WEIGHT_COTAN));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorLaplacian3(CSMesh m, Vec x, MatReuse reuse, Mat *L3)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV3, 3, reuse, L3, WEIGHT_COTAN));
  PetscFunctionReturn(0);
}

/* The graph (umbrella) Laplacian on each coordinate: weight 1 per interior edge (1/2 on boundary edges). */
PetscErrorCode CSOperatorGraphLaplacian3(CSMesh m, Vec x, MatReuse reuse, Mat *A3)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV3, 3, reuse, A3, WEIGHT_UNIFORM));
  PetscFunctionReturn(0);
}

/* The graph Laplacian with the weight 1/sqrt(A_f) per face side (face area A_f of x): the minimiser of
   sum_f A_f^-1/2 sum_{edges of f} |x_i - x_j|^2 over tangential moves, with the areas frozen and updated between
   solves, spaces the vertices in proportion to the local edge length across the mesh (on a torus of revolution:
   poloidal spacing ~ the distance to the axis, every grid cell the same shape; docs/bench_evolver.md). */
PetscErrorCode CSOperatorScaledGraphLaplacian3(CSMesh m, Vec x, MatReuse reuse, Mat *A3)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV3, 3, reuse, A3, WEIGHT_SCALED));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorMass(CSMesh m, Vec x, Vec mass)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryVertexAreas(m, x, mass));
  PetscFunctionReturn(0);
}
