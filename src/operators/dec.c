/* DEC exterior derivatives d0, d1 as AIJ matrices, the diagonal Hodge stars, and the genus of a closed mesh
   (conventions in include/cs_operators_dec.h and docs/dec.md). */
#include "cs_operators_dec.h"
#include "cs_mesh_adjacency.h"

/* (d0 u)_e = u_j - u_i for e = (i -> j) = (edgeVert[2e] -> edgeVert[2e+1]); rows set by the edge's owner. */
PetscErrorCode CSOperatorDECd0(CSMesh m, Mat *d0)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscCall(CSOperatorCreatePointMatrix(m->dmE1, m->dmV1, 2, d0));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscScalar v[2] = {-1.0, 1.0};
    if (!m->edgeOwned[e]) continue;
    PetscCall(MatSetValuesLocal(*d0, 1, &e, 2, m->edgeVert + 2 * e, v, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*d0, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*d0, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* (d1 w)_f = sum_a s_a w_{e_a}: the edge e_a opposite corner a runs v[a+1] -> v[a+2] counter-clockwise in f,
   s_a = +1 if that is its own orientation (side 0), else -1. Every local face is owned (overlap 0). */
PetscErrorCode CSOperatorDECd1(CSMesh m, Mat *d1)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscCall(CSOperatorCreatePointMatrix(m->dmF1, m->dmE1, 3, d1));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(m, NULL, &F);) {
    PetscScalar s[3];
    for (int a = 0; a < 3; a++) s[a] = CSMeshEdgeSide(m, &F, a) == 0 ? 1.0 : -1.0;
    PetscCall(MatSetValuesLocal(*d1, 1, &F.f, 3, F.e, s, INSERT_VALUES));
  }
  PetscCall(MatAssemblyBegin(*d1, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(*d1, MAT_FINAL_ASSEMBLY));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorHodgeStar0(CSMesh m, Vec x, Vec star0)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryVertexAreas(m, x, star0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorHodgeStar1(CSMesh m, Vec x, Vec star1)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryCotanWeights(m, x, star1));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOperatorHodgeStar2(CSMesh m, Vec x, Vec star2)
{
  PetscFunctionBeginUser;
  PetscCall(CSGeometryFaceAreas(m, x, star2));
  PetscCall(VecReciprocal(star2));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshGetClosedGenus(CSMesh m, const char caller[], PetscInt *g)
{
  PetscInt chi = m->Nv - m->Ne + m->Nf;
  PetscFunctionBeginUser;
  PetscCheck(!m->topo.boundary_edges, m->comm, PETSC_ERR_SUP, "%s: mesh %s has a boundary (%" PetscInt_FMT " boundary edges in %" PetscInt_FMT " loops); only closed meshes are handled", caller, m->name, m->topo.boundary_edges, m->topo.boundary_loops);
  PetscCheck(m->topo.components == 1, m->comm, PETSC_ERR_SUP, "%s: mesh %s has %" PetscInt_FMT " connected components; only connected meshes are handled", caller, m->name, m->topo.components);
  PetscCheck(chi <= 2 && chi % 2 == 0, m->comm, PETSC_ERR_PLIB, "%s: mesh %s has Euler characteristic %" PetscInt_FMT ", not 2 - 2g", caller, m->name, chi);
  *g = (2 - chi) / 2;
  PetscFunctionReturn(0);
}
