/* Discrete operators as PETSc matrices on the distributed mesh. */
#ifndef CS_OPERATORS_H
#define CS_OPERATORS_H
#include <petscksp.h> /* petscmat.h, and KSP for CSOperatorSpectralFilterCheck */
#include "cs_geometry.h"

/* A vertex-by-vertex matrix with bs dofs per vertex of dm (mesh->dmV1, dmV3 or another vertex DM), with the
   1-ring nonzero pattern preallocated from vertex degrees and dm's local-to-global mapping set, so face kernels
   assemble with MatSetValuesLocal. Much cheaper than DMCreateMatrix (DMPlexPreallocate: ~0.5 s at 10k vertices). */
PETSC_EXTERN PetscErrorCode CSOperatorCreateVertexMatrix(CSMesh mesh, DM dm, PetscInt bs, MatType type, Mat *A);

/* An AIJ matrix with rows of dmRow and columns of dmCol (per-point DMs of the mesh, e.g. dmE1 x dmV3), nz entries per
   row preallocated in each block, both local-to-global mappings set (MatSetValuesLocal), new nonzeros an error. */
PETSC_EXTERN PetscErrorCode CSOperatorCreatePointMatrix(DM dmRow, DM dmCol, PetscInt nz, Mat *A);

/* Positive semi-definite cotan Laplacian L = -d*d (soliman2021 Sec. 2): (Lu)_i = sum_j w_ij (u_i - u_j).
   Scalar V x V AIJ on dmV1 (MAT_INITIAL_MATRIX creates *L, MAT_REUSE_MATRIX refills it). */
PETSC_EXTERN PetscErrorCode CSOperatorLaplacian(CSMesh mesh, Vec x, MatReuse reuse, Mat *L);
/* The same operator acting on R^3-valued vertex fields: 3V x 3V, block size 3, on dmV3. */
PETSC_EXTERN PetscErrorCode CSOperatorLaplacian3(CSMesh mesh, Vec x, MatReuse reuse, Mat *L3);
/* Vertex mass *0 = diag(barycentric dual areas) as a dmV1 vector (create with DMCreateGlobalVector). */
/* The graph (umbrella) Laplacian, weight 1 per interior edge, on each of 3 coordinates (dmV3). */
PETSC_EXTERN PetscErrorCode CSOperatorGraphLaplacian3(CSMesh mesh, Vec x, MatReuse reuse, Mat *A3);
/* The same with the weight 1/sqrt(face area) per face side (src/operators/laplacian.c). */
PETSC_EXTERN PetscErrorCode CSOperatorScaledGraphLaplacian3(CSMesh mesh, Vec x, MatReuse reuse, Mat *A3);
/* The scalar (dmV1) versions of the two graph Laplacians (apply to dmV3 vectors with MatCreateMAIJ(A, 3, ...)). */
PETSC_EXTERN PetscErrorCode CSOperatorGraphLaplacian(CSMesh mesh, Vec x, MatReuse reuse, Mat *A);
PETSC_EXTERN PetscErrorCode CSOperatorScaledGraphLaplacian(CSMesh mesh, Vec x, MatReuse reuse, Mat *A);
/* L_n = N^T L3 N (N: column i = the unit normal n_i of nrm, a dmV3 vector): (L_n)_ij = L_ij n_i . n_j, V x V on dmV1. */
PETSC_EXTERN PetscErrorCode CSOperatorNormalLaplacian(CSMesh mesh, Vec x, Vec nrm, MatReuse reuse, Mat *Ln);
PETSC_EXTERN PetscErrorCode CSOperatorMass(CSMesh mesh, Vec x, Vec mass);

/* The spectral filter matrix of crane2013 Sec. 4 (src/operators/spectral_filter.c): B = M + s L (M^-1 L)^(k-1)
   (k >= 1) or (1 + s) M (k = 0), a new SPD matrix, for (id + s A^k) w = v as B w = M v; L any AIJ Laplacian
   (positive semi-definite), mass its diagonal mass vector. */
PETSC_EXTERN PetscErrorCode CSOperatorSpectralFilter(Mat L, Vec mass, PetscReal s, PetscInt k, Mat *B);
/* after the filter solve B w = b by ksp: refuse a failed solve or a relative residual above CS_FILTER_RTOL, naming
   -<prefix>filter_k and -<prefix>filter_sigma (who: the flow, for the message) */
PETSC_EXTERN PetscErrorCode CSOperatorSpectralFilterCheck(KSP ksp, Vec b, Vec w, const char who[], const char prefix[]);
#define CS_FILTER_RTOL 1e-2 /* largest relative residual of a filter solve kept: w is the exact filter of a direction within 1 % of v */

#include "cs_linalg.h" /* CSMatAddFixedPattern (src/linalg/mat_add_fixed.c) */

#endif
