/* Mesh adjacency built once per CSMesh: the faces on the two sides of every edge, the vertex opposite the
   edge on each side (the diamond (k, j, l, i) of bobenko-schroeder2005 Fig. 1) and the boundary neighbours of
   every boundary vertex, in local and global numbering. The mesh has overlap 0, so the two faces of an edge
   on a partition cut live on two ranks; the far side is exchanged once through the point SF of the edges
   (and of the vertices for the boundary), so the tables are the same whatever the number of ranks.

   Sides: side 0 of local edge e is the face traversing edgeVert[2e] -> edgeVert[2e+1], side 1 the face
   traversing it backwards (in bobenko-schroeder2005's notation with i = edgeVert[2e], j = edgeVert[2e+1]:
   side 0 is t_ijl, side 1 is t_jik). Boundary: next(v) is the vertex after v along the boundary half-edge
   v -> next(v) of its only face (counter-clockwise order of that face), prev(v) the one before. */
#ifndef CS_MESH_ADJACENCY_H
#define CS_MESH_ADJACENCY_H
#include "cs_mesh.h"

struct _p_CSMeshAdjacency {
  PetscInt       *edgeFace;       /* 2*ne: local face on side s, -1 if that face is on another rank or absent */
  PetscInt       *edgeOpp;        /* 2*ne: local number of the opposite vertex, -1 if not on this rank or absent */
  PetscInt       *edgeFaceGlobal; /* 2*ne: global face number (dmF1), -1 on the missing side of a boundary edge */
  PetscInt       *edgeOppGlobal;  /* 2*ne: global vertex number (dmV1) of the opposite vertex, -1 likewise */
  PetscInt       *edgeNFaces;     /* ne: faces of the edge in the whole mesh (1 on the boundary, else 2) */
  PetscInt       *bdPrev, *bdNext;             /* nv: local numbers, -1 if not on this rank or v interior */
  PetscInt       *bdPrevGlobal, *bdNextGlobal; /* nv: global numbers, -1 for an interior vertex */
  PetscBool       bdManifold;     /* every boundary vertex has one incoming and one outgoing boundary edge (else
                                     the prev/next of the others are -1); the same on every rank */
  const PetscInt *vertGlobal;     /* nv: global vertex numbers of the local vertices (dmV1) */
  const PetscInt *faceGlobal;     /* nf: global face numbers (dmF1) */
  /* private: the exchange of per-edge-side / per-vertex pairs */
  DM                     dmE2, dmV2;
  ISLocalToGlobalMapping vmap, fmap;
};

/* Side of the edge F->e[a] (opposite corner a of the face F) that F lies on. */
static inline int CSMeshEdgeSide(CSMesh mesh, const CSFaceIter *F, int a)
{
  return F->v[(a + 1) % 3] == mesh->edgeVert[2 * F->e[a]] ? 0 : 1;
}

/* The adjacency of mesh, built on the first call (collective then) and freed by CSMeshDestroy. */
PETSC_EXTERN PetscErrorCode CSMeshGetAdjacency(CSMesh mesh, CSMeshAdjacency *adj);
PETSC_EXTERN PetscErrorCode CSMeshAdjacencyDestroy(CSMeshAdjacency *adj);
/* out[2e+s] = vdata[opposite vertex of side s of edge e] for every local edge, also where that vertex lives on
   another rank; `none` where the side has no face. vdata is indexed by local vertex. Collective. */
PETSC_EXTERN PetscErrorCode CSMeshAdjacencyGatherOpposite(CSMesh mesh, const PetscInt vdata[], PetscInt none, PetscInt out[]);

#endif
