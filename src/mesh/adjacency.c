/* Edge sides (faces and opposite vertices, i.e. the diamonds of bobenko-schroeder2005 Fig. 1) and boundary
   neighbours, exchanged once over the ranks through the section SFs of per-edge and per-vertex integer pairs:
   each side of an edge is written by the one rank holding its face, reduced onto the edge's owner and
   broadcast back to every copy. */
#include "cs_mesh_adjacency.h"

/* Every copy of a point gets the reduction (op) over all copies of its two integers (local layout of dm2). */
static PetscErrorCode ReduceShare(DM dm2, MPI_Op op, PetscInt init, PetscInt leaf[])
{
  PetscSF   sf;
  PetscInt  nroots, *root;
  PetscFunctionBeginUser;
  PetscCall(DMGetSectionSF(dm2, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, NULL, NULL, NULL));
  PetscCall(PetscMalloc1(nroots, &root));
  for (PetscInt r = 0; r < nroots; r++) root[r] = init;
  PetscCall(PetscSFReduceBegin(sf, MPIU_INT, leaf, root, op));
  PetscCall(PetscSFReduceEnd(sf, MPIU_INT, leaf, root, op));
  PetscCall(PetscSFBcastBegin(sf, MPIU_INT, root, leaf, MPI_REPLACE));
  PetscCall(PetscSFBcastEnd(sf, MPIU_INT, root, leaf, MPI_REPLACE));
  PetscCall(PetscFree(root));
  PetscFunctionReturn(0);
}

/* Local numbers of global vertices (-1 where absent here or g < 0). */
static PetscErrorCode GlobalToLocal(CSMeshAdjacency a, PetscInt n, const PetscInt g[], PetscInt l[])
{
  PetscFunctionBeginUser;
  PetscCall(ISGlobalToLocalMappingApply(a->vmap, IS_GTOLM_MASK, n, g, NULL, l));
  for (PetscInt i = 0; i < n; i++)
    if (g[i] < 0) l[i] = -1;
  PetscFunctionReturn(0);
}

/* Faces and opposite vertices per edge side; checks one face per side of every interior edge and one face on
   one side of every boundary edge (fails on an inconsistent orientation or cone order across ranks). */
static PetscErrorCode BuildEdgeSides(CSMesh m, CSMeshAdjacency a)
{
  PetscInt  *cnt, bad = 0;
  CSFaceIter F = CS_FACE_ITER_INIT;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc5(2 * m->ne, &a->edgeFace, 2 * m->ne, &a->edgeOpp, 2 * m->ne, &a->edgeFaceGlobal, 2 * m->ne, &a->edgeOppGlobal, m->ne, &a->edgeNFaces));
  PetscCall(PetscCalloc1(2 * m->ne, &cnt));
  for (PetscInt k = 0; k < 2 * m->ne; k++) a->edgeFace[k] = a->edgeOpp[k] = a->edgeFaceGlobal[k] = a->edgeOppGlobal[k] = -1;
  while (CSMeshFaceNext(m, NULL, &F))
    for (int k = 0; k < 3; k++) {
      PetscInt es = 2 * F.e[k] + CSMeshEdgeSide(m, &F, k);
      a->edgeFace[es]       = F.f;
      a->edgeOpp[es]        = F.v[k];
      a->edgeFaceGlobal[es] = a->faceGlobal[F.f];
      a->edgeOppGlobal[es]  = a->vertGlobal[F.v[k]];
      cnt[es]++;
    }
  PetscCall(ReduceShare(a->dmE2, MPI_SUM, 0, cnt));
  PetscCall(ReduceShare(a->dmE2, MPI_MAX, -1, a->edgeFaceGlobal));
  PetscCall(ReduceShare(a->dmE2, MPI_MAX, -1, a->edgeOppGlobal));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt c0 = cnt[2 * e], c1 = cnt[2 * e + 1];
    a->edgeNFaces[e] = c0 + c1;
    if (c0 > 1 || c1 > 1 || (m->edgeBoundary[e] ? c0 + c1 != 1 : c0 + c1 != 2)) bad++;
  }
  PetscCall(PetscFree(cnt));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, m->comm));
  PetscCheck(!bad, m->comm, PETSC_ERR_PLIB, "mesh adjacency: %" PetscInt_FMT " edges do not have one face per side (inconsistent orientation, or edge cone order differs across ranks)", bad);
  PetscCall(GlobalToLocal(a, 2 * m->ne, a->edgeOppGlobal, a->edgeOpp));
  PetscFunctionReturn(0);
}

/* Previous/next boundary neighbour from the boundary half-edges i -> j of the (single) faces of boundary
   edges. A vertex where boundary loops touch has several; its entries are then -1 (see bdManifold). */
static PetscErrorCode BuildBoundary(CSMesh m, CSMeshAdjacency a)
{
  PetscInt  *nb, *cnt, bad = 0;
  CSFaceIter F = CS_FACE_ITER_INIT;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc4(m->nv, &a->bdPrev, m->nv, &a->bdNext, m->nv, &a->bdPrevGlobal, m->nv, &a->bdNextGlobal));
  PetscCall(PetscMalloc1(2 * m->nv, &nb));
  PetscCall(PetscCalloc1(2 * m->nv, &cnt));
  for (PetscInt k = 0; k < 2 * m->nv; k++) nb[k] = -1;
  while (CSMeshFaceNext(m, NULL, &F))
    for (int k = 0; k < 3; k++) {
      PetscInt i = F.v[(k + 1) % 3], j = F.v[(k + 2) % 3];
      if (!m->edgeBoundary[F.e[k]]) continue;
      nb[2 * i + 1] = a->vertGlobal[j]; /* next of i */
      cnt[2 * i + 1]++;
      nb[2 * j] = a->vertGlobal[i]; /* prev of j */
      cnt[2 * j]++;
    }
  PetscCall(ReduceShare(a->dmV2, MPI_SUM, 0, cnt));
  PetscCall(ReduceShare(a->dmV2, MPI_MAX, -1, nb));
  for (PetscInt v = 0; v < m->nv; v++) {
    PetscBool one = (PetscBool)(cnt[2 * v] == 1 && cnt[2 * v + 1] == 1);
    if (m->vertBoundary[v] && !one) bad++;
    a->bdPrevGlobal[v] = one ? nb[2 * v] : -1;
    a->bdNextGlobal[v] = one ? nb[2 * v + 1] : -1;
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, m->comm));
  a->bdManifold = (PetscBool)!bad;
  PetscCall(GlobalToLocal(a, m->nv, a->bdPrevGlobal, a->bdPrev));
  PetscCall(GlobalToLocal(a, m->nv, a->bdNextGlobal, a->bdNext));
  PetscCall(PetscFree(nb));
  PetscCall(PetscFree(cnt));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshGetAdjacency(CSMesh m, CSMeshAdjacency *adj)
{
  CSMeshAdjacency a;
  PetscFunctionBeginUser;
  if (!m->adj) {
    PetscCall(PetscNew(&a));
    PetscCall(DMGetLocalToGlobalMapping(m->dmV1, &a->vmap));
    PetscCall(DMGetLocalToGlobalMapping(m->dmF1, &a->fmap));
    PetscCall(PetscObjectReference((PetscObject)a->vmap));
    PetscCall(PetscObjectReference((PetscObject)a->fmap));
    PetscCall(ISLocalToGlobalMappingGetIndices(a->vmap, &a->vertGlobal));
    PetscCall(ISLocalToGlobalMappingGetIndices(a->fmap, &a->faceGlobal));
    PetscCall(CSMeshCreateFieldDM(m->dm, 1, 2, "adjacency_edge2", &a->dmE2));
    PetscCall(CSMeshCreateFieldDM(m->dm, 0, 2, "adjacency_vertex2", &a->dmV2));
    PetscCall(BuildEdgeSides(m, a));
    PetscCall(BuildBoundary(m, a));
    m->adj = a;
  }
  *adj = m->adj;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshAdjacencyGatherOpposite(CSMesh m, const PetscInt vdata[], PetscInt none, PetscInt out[])
{
  CSMeshAdjacency a;
  PetscInt        lo;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetAdjacency(m, &a));
  /* every side is written on exactly one rank; MPI_MAX over `lo` (below every value) keeps that one */
  lo = none;
  for (PetscInt v = 0; v < m->nv; v++) lo = PetscMin(lo, vdata[v]);
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &lo, 1, MPIU_INT, MPI_MIN, m->comm));
  for (PetscInt k = 0; k < 2 * m->ne; k++) out[k] = a->edgeFace[k] >= 0 ? vdata[a->edgeOpp[k]] : lo;
  PetscCall(ReduceShare(a->dmE2, MPI_MAX, lo, out));
  for (PetscInt k = 0; k < 2 * m->ne; k++)
    if (a->edgeOppGlobal[k] < 0) out[k] = none;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshAdjacencyDestroy(CSMeshAdjacency *adj)
{
  CSMeshAdjacency a = *adj;
  PetscFunctionBeginUser;
  if (!a) PetscFunctionReturn(0);
  PetscCall(PetscFree5(a->edgeFace, a->edgeOpp, a->edgeFaceGlobal, a->edgeOppGlobal, a->edgeNFaces));
  PetscCall(PetscFree4(a->bdPrev, a->bdNext, a->bdPrevGlobal, a->bdNextGlobal));
  PetscCall(ISLocalToGlobalMappingRestoreIndices(a->vmap, &a->vertGlobal));
  PetscCall(ISLocalToGlobalMappingRestoreIndices(a->fmap, &a->faceGlobal));
  PetscCall(ISLocalToGlobalMappingDestroy(&a->vmap));
  PetscCall(ISLocalToGlobalMappingDestroy(&a->fmap));
  PetscCall(DMDestroy(&a->dmE2));
  PetscCall(DMDestroy(&a->dmV2));
  PetscCall(PetscFree(a));
  *adj = NULL;
  PetscFunctionReturn(0);
}
