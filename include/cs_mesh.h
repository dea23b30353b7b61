/* The distributed surface mesh: an interpolated DMPlex (faces = cells, edges, vertices) distributed with
   PT-Scotch, the dof layouts for per-vertex and per-edge fields, and the local connectivity tables that the
   geometry kernels loop over. Everything here is collective on the mesh communicator. */
#ifndef CS_MESH_H
#define CS_MESH_H
#include <petscdmplex.h>
#include <petscsf.h>
#include "cs_meshdata.h"

typedef struct _p_CSMesh *CSMesh;
typedef struct _p_CSMeshAdjacency *CSMeshAdjacency; /* cs_mesh_adjacency.h */

/* A field in the natural (file) order: the scatter to the global vector and the natural vector itself, all
   entries on rank 0 (length 0 elsewhere). */
typedef struct {
  VecScatter sc;
  Vec        vec;
} CSMeshNatural;

struct _p_CSMesh {
  MPI_Comm comm;
  DM       dm;   /* interpolated, distributed DMPlex; overlap 0, so every local face is owned here */
  DM       dmV3; /* clone of dm: 3 dofs per vertex (positions, vertex vector fields) */
  DM       dmV1; /* clone of dm: 1 dof per vertex (areas, scalar vertex fields, the scalar Laplacian) */
  DM       dmE1; /* clone of dm: 1 dof per edge (cross ratios, Lagrange multipliers) */
  DM       dmF1; /* clone of dm: 1 dof per face (per-face fields) */

  /* Local tables (local numbering = plex point minus stratum start; ghost vertices/edges included). */
  PetscInt  nf, nv, ne;        /* local faces, vertices, edges */
  PetscInt *faceVert;          /* 3*nf: oriented corners (counter-clockwise seen from outside) */
  PetscInt *faceEdge;          /* 3*nf: faceEdge[3f+a] is the edge opposite corner a */
  PetscInt *edgeVert;          /* 2*ne: the edge's two vertices (plex cone order) */
  PetscBool *vertOwned;        /* nv: owned by this rank (global sums run over owned vertices) */
  PetscBool *edgeOwned;        /* ne */
  PetscBool *vertBoundary;     /* nv: on the mesh boundary */
  PetscBool *edgeBoundary;     /* ne: has only one face */
  PetscInt *vertNatural;       /* nv: vertex index in the input file (after dropping unreferenced ones) */
  PetscInt *faceNatural;       /* nf: face index in the input file */
  PetscInt *edgeNatural;       /* ne: edge number of the serial interpolated mesh (independent of the ranks) */

  /* Global facts. */
  PetscInt   Nv, Ne, Nf;
  CSTopology topo; /* from validation; identical on every rank */
  char       name[PETSC_MAX_PATH_LEN];

  Vec x;  /* positions, global vector of dmV3 */
  Vec lt; /* NULL, or the input's intrinsic edge lengths (CSMeshData len, dmE1): the target class of the flows */
  Vec ct; /* NULL, or the input's target log length cross ratios c0 (CSMeshData cr, dmE1; -mesh_cross_ratios) */
  PetscReal *faceUV; /* NULL, or 6*nf: the input's texture coordinates (u, v) of each local face's corners in faceVert
                        order (CSMeshData uv, fuv; issue 38); every rank has them or none does */

  /* Natural-order fields (rank 0 holds the whole field in file order) for I/O of vertex/face/edge fields. */
  CSMeshNatural natV3, natV1, natF1, natE1;

  CSMeshData serial; /* rank 0: the validated input (faces kept for output); empty elsewhere */

  CSMeshAdjacency adj; /* edge sides, diamonds, boundary neighbours: built by the first CSMeshGetAdjacency */
};

/* Face iterator: for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, p, &F);) visits every local face
   F.f with its corners F.v[0..2] (counter-clockwise), the edges F.e[a] opposite them, and (p not NULL: the local
   positions array of dmV3) the corner positions F.c[a]. */
typedef struct {
  PetscInt         f;
  const PetscInt  *v, *e;
  const PetscReal *c[3];
} CSFaceIter;
#define CS_FACE_ITER_INIT {-1, NULL, NULL, {NULL, NULL, NULL}}
static inline PetscBool CSMeshFaceNext(CSMesh mesh, const PetscReal *p, CSFaceIter *F)
{
  if (++F->f >= mesh->nf) return PETSC_FALSE;
  F->v = mesh->faceVert + 3 * F->f;
  F->e = mesh->faceEdge + 3 * F->f;
  if (p)
    for (int a = 0; a < 3; a++) F->c[a] = p + 3 * F->v[a];
  return PETSC_TRUE;
}

/* The local scatter-add of element-by-element assembly. CSLocalSumBegin gives a zeroed local vector of dm
   (array s->a, ghosts included) to accumulate into; CSLocalSumEnd adds the copies of every point over the
   ranks into the global g (g = the sum; g may be NULL) and gives the local vector back. CSLocalSumShare, in
   between, gives every local copy the summed value (s->a stays readable; still end with CSLocalSumEnd). */
typedef struct {
  DM           dm;
  Vec          l;
  PetscScalar *a;
} CSLocalSum;
PETSC_EXTERN PetscErrorCode CSLocalSumBegin(DM dm, CSLocalSum *s);
PETSC_EXTERN PetscErrorCode CSLocalSumShare(CSLocalSum *s);
PETSC_EXTERN PetscErrorCode CSLocalSumEnd(CSLocalSum *s, Vec g);

/* Reads the mesh source from the options (see CSMeshDataFromOptions), validates, distributes. */
PETSC_EXTERN PetscErrorCode CSMeshCreateFromOptions(MPI_Comm comm, const char prefix[], CSMesh *mesh);
/* Distributes md (significant on rank 0 only; consumed: md is emptied). */
PETSC_EXTERN PetscErrorCode CSMeshCreateFromData(MPI_Comm comm, CSMeshData *md, const CSTopology *topo, CSMesh *mesh);
PETSC_EXTERN PetscErrorCode CSMeshDestroy(CSMesh *mesh);
/* mesh->faceUV from rank 0's md->uv, md->fuv (nothing when md has none): a per-face field scattered from the file
   order, each UV matched to its corner by vertex number (src/mesh/mesh_texture.c). Collective. */
PETSC_EXTERN PetscErrorCode CSMeshTextureCreate(CSMesh mesh, const CSMeshData *md);
/* A clone of mesh->dm with dof unknowns on every point of the given depth (0 vertices, 1 edges, 2 faces),
   e.g. 4 per vertex for quaternion fields. Local dof block v of its local vectors is local vertex v. */
PETSC_EXTERN PetscErrorCode CSMeshCreateFieldDM(DM dm, PetscInt depth, PetscInt dof, const char name[], DM *out);

/* Vector fields in the natural (file) order, gathered on / scattered from rank 0, for one of the mesh's
   natural fields (&mesh->natV3, natV1, natF1 or natE1). A natural vector is a sequential Vec on rank 0
   (3*Nv, Nv, Nf or Ne long) and empty elsewhere; the gathered one is field->vec, owned by the mesh. */
PETSC_EXTERN PetscErrorCode CSMeshGather(CSMeshNatural *field, Vec g, Vec *nat);
PETSC_EXTERN PetscErrorCode CSMeshScatter(CSMeshNatural *field, Vec nat, Vec g);
/* The natural field of a DM with bs dofs on every point of the given depth (0 vertices, 1 edges, 2 faces), e.g. a
   clone of CSMeshCreateFieldDM; destroy with CSMeshNaturalDestroy (the mesh's own are destroyed with the mesh). */
PETSC_EXTERN PetscErrorCode CSMeshNaturalCreate(CSMesh mesh, DM dmX, PetscInt depth, PetscInt bs, CSMeshNatural *field);
PETSC_EXTERN PetscErrorCode CSMeshNaturalDestroy(CSMeshNatural *field);

/* The fields of a checkpoint, each NULL or a global vector: the positions (dmV3), a per-edge and a per-face field
   with k values per point in the global layout of CSMeshCreateFieldDM(mesh->dm, 1 or 2, k) (k = size / Ne or Nf;
   k = 1: dmE1, dmF1), e.g. the edge multipliers of the conformal flows, or a triangle field's halfedge data. */
typedef struct {
  Vec x, edge, face;
} CSCheckpointFields;

/* Checkpoints for long runs: iteration number, a few scalars and the fields, all in natural order, so a run
   resumes on any number of ranks (src/mesh/checkpoint.c: a text header, float64 payload, checksum); written
   atomically (temporary file, then rename) so a killed run keeps the last one. Read refuses a file whose sizes
   (mesh, scalars, values per vertex / edge / face) differ from the mesh's and v's, naming the file. */
PETSC_EXTERN PetscErrorCode CSCheckpointWrite(CSMesh mesh, const char path[], PetscInt it, PetscInt nreal, const PetscReal reals[], const CSCheckpointFields *v);
PETSC_EXTERN PetscErrorCode CSCheckpointRead(CSMesh mesh, const char path[], PetscInt *it, PetscInt nreal, PetscReal reals[], const CSCheckpointFields *v);

/* A second set of positions with the same connectivity (a -reference or -target_mesh file), read on rank 0,
   checked face by face against the mesh (clear error naming the option and the first differing face), and
   scattered into a new global positions vector. */
PETSC_EXTERN PetscErrorCode CSMeshLoadCompatiblePositions(CSMesh mesh, const char option[], const char path[], Vec *x);

/* A mask of vertices (faces = false) or faces from a file of 0-based indices in file order (read on rank 0 by
   CSReadNumberFile; indices out of range or not integers are refused naming the option, file and line), as the
   dmV1 global vector vmask: 1 on the masked vertices, or on the vertices of the masked faces (src/mesh/mesh_mask.c). */
PETSC_EXTERN PetscErrorCode CSMeshReadIndexMask(CSMesh mesh, const char option[], const char path[], PetscBool faces, Vec vmask);

/* One number per vertex in file order from a text file (CSReadNumberFile on rank 0) into the dmV1 global vector g;
   a wrong count is refused naming the option and file (src/mesh/mesh_values.c). */
PETSC_EXTERN PetscErrorCode CSMeshReadVertexValues(CSMesh mesh, const char option[], const char path[], Vec g);

/* Writes the mesh with positions x (global, dmV3) to .obj/.ply (by extension), in file order, from rank 0. */
PETSC_EXTERN PetscErrorCode CSMeshWrite(CSMesh mesh, Vec x, const char path[]);
/* Before a flow: faces with a relative area below -mesh_quality_min_area (1e-8) or an angle below
   -mesh_quality_min_angle (1e-5 degrees) are reported (the worst, in file numbering) and the run refused, or warned
   about with -mesh_quality_action warn (off: no check). The options under the caller's prefix (the tasks: none).
   Collective. */
PETSC_EXTERN PetscErrorCode CSMeshQualityCheck(CSMesh mesh, const char prefix[], Vec x);

/* ParaView output: one .pvtu per step (a piece per rank, with named per-vertex and per-face fields) plus a
   .pvd series index in dir. Fields are global Vecs of dmV1/dmV3 (vertex) or dmF1 (face). The pieces' data arrays
   are written as -viewer_format binary (default: VTK XML appended raw data, UInt64 block headers), zlib (the
   same, zlib-compressed in 64 KiB blocks) or ascii, with -viewer_precision double (default) or single (Float32);
   CSViewerCreate reads the options (docs/output.md). */
typedef struct _p_CSViewer *CSViewer;
typedef enum {
  CS_VIEWER_ASCII,
  CS_VIEWER_BINARY,
  CS_VIEWER_ZLIB
} CSViewerFormat;
PETSC_EXTERN const char *const CSViewerFormats[];
/* -<prefix>viewer_format and -<prefix>viewer_precision are read under the caller's prefix (the tasks' output: none) */
PETSC_EXTERN PetscErrorCode    CSViewerCreate(CSMesh mesh, const char prefix[], const char dir[], CSViewer *v);
PETSC_EXTERN PetscErrorCode    CSViewerSetFormat(CSViewer v, CSViewerFormat format, PetscBool single);
/* -<prefix>viewer_format and -<prefix>viewer_precision alone (CSViewerCreate reads them this way; the output reads
   them with -viewer_dir before the work, so the check of unused options finds them read) */
PETSC_EXTERN PetscErrorCode    CSViewerFormatFromOptions(MPI_Comm comm, const char prefix[], CSViewerFormat *format, PetscBool *single);
PETSC_EXTERN PetscErrorCode CSViewerAddVertexField(CSViewer v, const char name[], Vec g);
PETSC_EXTERN PetscErrorCode CSViewerAddFaceField(CSViewer v, const char name[], Vec g);
PETSC_EXTERN PetscErrorCode CSViewerWriteStep(CSViewer v, Vec x, PetscReal time); /* writes and clears the fields */
PETSC_EXTERN PetscErrorCode CSViewerDestroy(CSViewer *v);

/* Logging: the event ids, registered by CSInitializePackage */
#include "cs_log.h"

#endif
