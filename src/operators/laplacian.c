/* Cotan Laplacian assembled face by face: each face adds the 3x3 block of its half-cotan edge weights. */
#include "cs_operators.h"

typedef enum {
  WEIGHT_COTAN,   /* half-cotan weights */
  WEIGHT_UNIFORM, /* 1 per face side */
  WEIGHT_SCALED   /* 1/sqrt(face area) per face side */
} Weight;

/* The 3x3 block of face F (corners 0, 1, 2) with the edge weights of `weight`; with nq (the unit normals' local
   array) entry (i, j) is multiplied by n_i . n_j (the Laplacian of each coordinate restricted to normal motion). */
static void FaceBlock(const CSFaceIter *F, Weight weight, const PetscReal *nq, PetscScalar K[9])
{
  PetscReal cot[3];
  if (weight == WEIGHT_UNIFORM) cot[0] = cot[1] = cot[2] = 1; /* each interior edge in two faces: weight 1 */
  else if (weight == WEIGHT_SCALED) {
    PetscReal an[3], A;
    CSTriangleAreaVector(F->c, an);
    A      = CSVecNorm(an);
    cot[0] = cot[1] = cot[2] = A > 0 ? 1 / PetscSqrtReal(A) : 0;
  } else CSTriangleCotans(F->c, cot);
  for (int k = 0; k < 9; k++) K[k] = 0;
  for (int k = 0; k < 3; k++) {
    int       i = (k + 1) % 3, j = (k + 2) % 3;
    PetscReal w = 0.5 * cot[k];
    K[3 * i + i] += w;
    K[3 * j + j] += w;
    K[3 * i + j] -= w;
    K[3 * j + i] -= w;
  }
  if (nq)
    for (int i = 0; i < 3; i++)
      for (int j = 0; j < 3; j++) {
        const PetscReal *ni = nq + 3 * F->v[i], *nj = nq + 3 * F->v[j];
        K[3 * i + j] *= ni[0] * nj[0] + ni[1] * nj[1] + ni[2] * nj[2];
      }
}

/* Adds the face blocks to A (dof block size bs: the same weight on each of the bs components; nrm: see FaceBlock). */
static PetscErrorCode AssembleCotanLaplacian(CSMesh m, Vec x, DM dmX, PetscInt bs, MatReuse reuse, Mat *A, Weight weight, Vec nrm)
{
  Vec              xl, nl = NULL;
  const PetscReal *p, *nq = NULL;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) {
    PetscCall(CSOperatorCreateVertexMatrix(m, dmX, bs, MATAIJ, A));
    PetscCall(MatSetOption(*A, MAT_SYMMETRIC, PETSC_TRUE));
  } else PetscCall(MatZeroEntries(*A));
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  if (nrm) PetscCall(CSMeshGetLocalPositions(m, nrm, &nl, &nq));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, p, &F);) {
    const PetscInt *v = F.v;
    PetscScalar     K[9];
    FaceBlock(&F, weight, nq, K);
    for (PetscInt d = 0; d < bs; d++) {
      PetscInt rows[3] = {bs * v[0] + d, bs * v[1] + d, bs * v[2] + d};
      PetscCall(MatSetValuesLocal(*A, 3, rows, 3, rows, K, ADD_VALUES));
    }
  }
  if (nrm) PetscCall(CSMeshRestoreLocalPositions(m, nrm, &nl, &nq));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  PetscCall(MatAssemblyBegin(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*A, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorLaplacian(CSMesh m, Vec x, MatReuse reuse, Mat *L)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV1, 1, reuse, L, WEIGHT_COTAN, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorLaplacian3(CSMesh m, Vec x, MatReuse reuse, Mat *L3)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV3, 3, reuse, L3, WEIGHT_COTAN, NULL));
  PetscFunctionReturn(0);
}

/* The graph (umbrella) Laplacian on each coordinate: weight 1 per interior edge (1/2 on boundary edges). */
PetscErrorCode CSOperatorGraphLaplacian3(CSMesh m, Vec x, MatReuse reuse, Mat *A3)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV3, 3, reuse, A3, WEIGHT_UNIFORM, NULL));
  PetscFunctionReturn(0);
}

/* The graph Laplacian with the weight 1/sqrt(A_f) per face side (face area A_f of x): the minimiser of
   sum_f A_f^-1/2 sum_{edges of f} |x_i - x_j|^2 over tangential moves, with the areas frozen and updated between
   solves, spaces the vertices in proportion to the local edge length across the mesh (on a torus of revolution:
   poloidal spacing ~ the distance to the axis, every grid cell the same shape; docs/bench_evolver.md). */
PetscErrorCode CSOperatorScaledGraphLaplacian3(CSMesh m, Vec x, MatReuse reuse, Mat *A3)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV3, 3, reuse, A3, WEIGHT_SCALED, NULL));
  PetscFunctionReturn(0);
}

/* L_n = N^T L3 N, the cotan Laplacian restricted to normal motion (N: 3V x V, column i = n_i): (L_n)_ij = L_ij n_i . n_j
   (L3 = L on each coordinate), assembled on dmV1 from the faces' blocks directly (the same sums as MatPtAP(L3, N)
   without assembling L3; nrm: the unit vertex normals, a dmV3 vector). */
PetscErrorCode CSOperatorNormalLaplacian(CSMesh m, Vec x, Vec nrm, MatReuse reuse, Mat *Ln)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV1, 1, reuse, Ln, WEIGHT_COTAN, nrm));
  PetscFunctionReturn(0);
}

/* The scalar (dmV1) graph Laplacians: CSOperatorGraphLaplacian3 and CSOperatorScaledGraphLaplacian3 are these on
   each coordinate (MatCreateMAIJ(A, 3) applies them to dmV3 vectors without assembling three copies). */
PetscErrorCode CSOperatorGraphLaplacian(CSMesh m, Vec x, MatReuse reuse, Mat *A)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV1, 1, reuse, A, WEIGHT_UNIFORM, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorScaledGraphLaplacian(CSMesh m, Vec x, MatReuse reuse, Mat *A)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleCotanLaplacian(m, x, m->dmV1, 1, reuse, A, WEIGHT_SCALED, NULL));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorMass(CSMesh m, Vec x, Vec mass)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryVertexAreas(m, x, mass));
  PetscFunctionReturn(0);
}
