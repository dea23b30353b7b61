/* Preallocated operator matrices: vertex-by-vertex (the 1-ring pattern) and point-by-point (edges x vertices,
   faces x edges, ...) with a fixed number of entries per row. */
#include "cs_operators.h"

/* A vertex-by-vertex matrix with bs dofs per vertex on dm (the 1-ring pattern), preallocated from the local
   edge counts summed over ranks: exact in serial, an over-estimate on partition cuts (an edge seen by two ranks
   counts twice). DMCreateMatrix's DMPlexPreallocate took ~0.5 s per matrix at 10k vertices; this is ~1 ms. */
PetscErrorCode CSOperatorCreateVertexMatrix(CSMesh mesh, DM dm, PetscInt bs, MatType type, Mat *A)
{
  Vec                    dg;
  CSLocalSum             s;
  const PetscScalar     *dga;
  PetscInt               n, N, *dnnz, *onnz;
  ISLocalToGlobalMapping ltog;
  PetscMPIInt            size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(mesh->comm, &size));
  PetscCall(DMGetGlobalVector(mesh->dmV1, &dg));
  PetscCall(CSLocalSumBegin(mesh->dmV1, &s));
  for (PetscInt e = 0; e < mesh->ne; e++) {
    s.a[mesh->edgeVert[2 * e]] += 1;
    s.a[mesh->edgeVert[2 * e + 1]] += 1;
  }
  PetscCall(CSLocalSumEnd(&s, dg));
  PetscCall(VecGetLocalSize(dg, &n));
  PetscCall(VecGetSize(dg, &N));
  PetscCall(PetscMalloc2(n, &dnnz, n, &onnz));
  PetscCall(VecGetArrayRead(dg, &dga));
  for (PetscInt i = 0; i < n; i++) {
    PetscInt deg = (PetscInt)PetscRealPart(dga[i]);
    dnnz[i]      = PetscMin(deg + 1, n);
    onnz[i]      = size > 1 ? PetscMin(deg, N - n) : 0;
  }
  PetscCall(VecRestoreArrayRead(dg, &dga));
  PetscCall(DMRestoreGlobalVector(mesh->dmV1, &dg));
  PetscCall(MatCreate(mesh->comm, A));
  PetscCall(MatSetSizes(*A, bs * n, bs * n, bs * N, bs * N));
  PetscCall(MatSetType(*A, type));
  PetscCall(MatSetBlockSize(*A, bs));
  PetscCall(MatXAIJSetPreallocation(*A, bs, dnnz, onnz, NULL, NULL));
  PetscCall(DMGetLocalToGlobalMapping(dm, &ltog));
  PetscCall(MatSetLocalToGlobalMapping(*A, ltog, ltog));
  PetscCall(PetscFree2(dnnz, onnz));
  PetscFunctionReturn(0);
}

/* An AIJ matrix with rows of dmRow and columns of dmCol (both per-point DMs of the mesh), nz per row. */
PetscErrorCode CSOperatorCreatePointMatrix(DM dmRow, DM dmCol, PetscInt nz, Mat *A)
{
  Vec                    r, c;
  PetscInt               nr, nc;
  ISLocalToGlobalMapping lr, lc;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(dmRow, &r));
  PetscCall(DMGetGlobalVector(dmCol, &c));
  PetscCall(VecGetLocalSize(r, &nr));
  PetscCall(VecGetLocalSize(c, &nc));
  PetscCall(DMRestoreGlobalVector(dmRow, &r));
  PetscCall(DMRestoreGlobalVector(dmCol, &c));
  PetscCall(MatCreateAIJ(PetscObjectComm((PetscObject)dmRow), nr, nc, PETSC_DETERMINE, PETSC_DETERMINE, nz, NULL, nz, NULL, A));
  PetscCall(DMGetLocalToGlobalMapping(dmRow, &lr));
  PetscCall(DMGetLocalToGlobalMapping(dmCol, &lc));
  PetscCall(MatSetLocalToGlobalMapping(*A, lr, lc));
  PetscCall(MatSetOption(*A, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscFunctionReturn(0);
}
