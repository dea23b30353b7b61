/* Private to src/mesh/meshdata_generate*.c: the pieces shared by the generators. */
#ifndef CS_MESHDATA_GENERATE_IMPL_H
#define CS_MESHDATA_GENERATE_IMPL_H
#include "cs_meshdata.h"

/* md with nv vertices and nf faces (sizes checked against PetscInt and memory; what names the generator) */
PETSC_INTERN PetscErrorCode CSMeshDataAlloc(const char what[], double nv, double nf, CSMeshData *md);
/* closed surfaces: flip every face if the signed enclosed volume is negative */
PETSC_INTERN void CSMeshDataOrientOutward(CSMeshData *md);
/* texture coordinates of a quad grid of n x m cells (meshdata_generate.c, CSMeshDataGridUVs) */
PETSC_INTERN PetscErrorCode CSMeshDataGridUVs(CSMeshData *md, PetscInt n, PetscInt m, PetscBool cyl, PetscReal a, PetscReal b);
#endif
