/* Serial triangle-mesh data: what a file or a generator gives, before it becomes a DMPlex.
   Lives on rank 0 only (the one global array the design allows: the file as read). */
#ifndef CS_MESHDATA_H
#define CS_MESHDATA_H
#include <petscsys.h>

typedef struct {
  PetscInt   nv, nf;                  /* vertices, triangles */
  PetscReal *x;                       /* 3*nv coordinates */
  PetscInt  *f;                       /* 3*nf vertex indices, 0-based, counter-clockwise = outward */
  char       name[PETSC_MAX_PATH_LEN]; /* file name or generator description, used in messages */
  PetscReal *len;                     /* NULL, or 3*nf: an intrinsic metric, len[3f+a] = length of the edge opposite
                                         corner a of face f (-gen lattice: the flat lattice; the flows' target class) */
  PetscReal *cr;                      /* NULL, or 3*nf: log length cross ratios c0 (soliman2021 Eq. 3/14), cr[3f+a] =
                                         c0 of the edge opposite corner a of face f, in f's orientation (the flows'
                                         target class, -mesh_cross_ratios); both faces of an edge hold the same value */
  PetscInt   nuv;                     /* texture coordinates (issue 38): 0 when the input has none */
  PetscReal *uv;                      /* NULL, or 2*nuv: (u, v) pairs, in the order the file lists them */
  PetscInt  *fuv;                     /* NULL, or 3*nf: fuv[3f+a] = index into uv of corner a of face f; per face
                                         corner, so a seam vertex carries different UVs in different faces. Every
                                         method keeps the connectivity, so the input's UVs are the result's. */
} CSMeshData;

/* The edges of serial triangle data as groups of half-edges (meshdata_edges.c): half-edge h = 3f + c runs from
   f[h] to f[CSHalfedgeNext(h)]; he[off[v]..off[v+1]) are the half-edges whose smaller vertex is v, sorted by the
   larger one (key), so the half-edges of one edge are adjacent (2 on an interior edge, 1 on the boundary). */
typedef struct {
  PetscInt  nv, nh;
  PetscInt *he, *key, *off;
} CSMeshDataEdges;

static inline PetscInt CSHalfedgeNext(PetscInt h)
{
  return h % 3 == 2 ? h - 2 : h + 1;
}
static inline PetscInt CSHalfedgePrev(PetscInt h)
{
  return h % 3 == 0 ? h + 2 : h - 1;
}

/* Facts found by validation (Euler characteristic chi = V - E + F = 2*components - 2*genus - boundary_loops). */
typedef struct {
  PetscInt vertices, edges, faces;
  PetscInt boundary_edges, boundary_loops, components;
  PetscInt euler, genus; /* genus summed over components */
  PetscInt dropped_vertices; /* unreferenced vertices removed */
} CSTopology;

/* Readers/writers by extension: .obj, .off, .ply (ascii and binary_little_endian). Errors name the
   file, the line (or element) and the reason. Serial, PETSC_COMM_SELF. */
PETSC_EXTERN PetscErrorCode CSMeshDataRead(const char path[], CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataWrite(const char path[], const CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataDestroy(CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataDuplicate(const CSMeshData *in, CSMeshData *out);

/* Refuses (with md->name, element and reason): NaN/Inf coordinates, indices out of range, repeated-vertex
   or zero-area faces, duplicate faces, non-manifold edges, pinched vertices, inconsistent orientation,
   non-finite texture coordinates or a face corner's uv index out of range. Drops unreferenced vertices with a
   warning (renumbering f; fuv and uv unchanged). Fills topo. */
PETSC_EXTERN PetscErrorCode CSMeshDataValidate(CSMeshData *md, CSTopology *topo);

/* Generators (all outward-oriented). */
PETSC_EXTERN PetscErrorCode CSMeshDataIcosphere(PetscInt level, PetscReal radius, PetscBool project, CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataTorus(PetscReal R, PetscReal r, PetscInt n, PetscInt m, CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataLattice(PetscReal tau_re, PetscReal tau_im, PetscInt n, PetscInt m, CSMeshData *md);
/* soliman2021 Fig. 8: the level-L icosphere with 12 spikes of height h and angular width w; round: md->len = the
   round icosphere's edge lengths (the target class of the flows) (meshdata_shapes.c). */
PETSC_EXTERN PetscErrorCode CSMeshDataSpikySphere(PetscInt level, PetscReal height, PetscReal width, PetscBool round, CSMeshData *md);
/* soliman2021 Fig. 15: a Morin surface (an immersed sphere, fourfold symmetric) on n x (m - 1) rings and two poles,
   plus a symmetry-breaking perturbation of size eps: Apery's parametrisation (not conformal) or Kusner's Willmore
   halfway model (W = 16 pi, conformally parametrised by the round sphere); round: md->len = the round UV sphere's
   edge lengths on the same grid (the flows' target class) (meshdata_shapes.c). */
typedef enum {
  CS_MORIN_APERY,
  CS_MORIN_KUSNER
} CSMorinKind;
PETSC_EXTERN const char *const CSMorinKinds[];
PETSC_EXTERN PetscErrorCode    CSMeshDataMorin(PetscInt n, PetscInt m, PetscReal eps, CSMorinKind kind, PetscBool round, CSMeshData *md);
/* md->len from a file of 3 |F| edge lengths (per face, opposite corners 0, 1, 2): the conformal class that the
   flows' conformal rows then target (-mesh_lengths FILE). One-line errors: wrong count, not a triangle, an edge
   given two lengths. Rank 0 (meshdata_lengths.c). */
PETSC_EXTERN PetscErrorCode CSMeshDataReadLengths(const char option[], const char path[], CSMeshData *md);
/* md->cr from a file of lines "i j c0", one per interior edge, vertices 1-based as in OBJ face lines (the mesh's
   vertex order), c0 the log length cross ratio of the edge (soliman2021 Eq. 3, the C of cross_ratio.c) in the
   file's face orientation. One-line errors naming the file and line: a count other than the interior edges, a pair
   that is not an edge or is a boundary edge, a duplicate, a non-number; on a closed mesh c0 is projected onto
   im C = ker A^T (rank |E| - |V|) and refused if the removed part exceeds tol (meshdata_cross_ratios.c). Rank 0. */
PETSC_EXTERN PetscErrorCode CSMeshDataReadCrossRatios(const char option[], const char path[], PetscReal tol, CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataEdgesCreate(const CSMeshData *md, CSMeshDataEdges *E);
PETSC_EXTERN PetscErrorCode CSMeshDataEdgesDestroy(CSMeshDataEdges *E);
PETSC_EXTERN void           CSMeshDataEdgesFind(const CSMeshDataEdges *E, PetscInt a, PetscInt b, PetscInt *s, PetscInt *k);
PETSC_EXTERN PetscInt       CSMeshDataEdgesGroupEnd(const CSMeshDataEdges *E, const CSMeshData *md, PetscInt s);
PETSC_EXTERN PetscErrorCode CSMeshDataFlatTorus(PetscReal tau_re, PetscReal tau_im, PetscInt n, PetscInt m, CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataCylinder(PetscReal radius, PetscReal height, PetscInt n, PetscInt m, CSMeshData *md);
PETSC_EXTERN PetscErrorCode CSMeshDataDisk(PetscReal radius, PetscInt rings, CSMeshData *md);

/* levels regular 1-to-4 splits in place (loop: Loop subdivision, boundary vertices kept; else midpoints);
   md->name gets the suffix "(loop refined 2x)". Serial (rank 0 data). */
PETSC_EXTERN PetscErrorCode CSMeshDataRefine(CSMeshData *md, PetscInt levels, PetscBool loop);
/* One such split: the new vertex of edge e is nv + e, in the order the faces first meet the edges; face i becomes
   faces 4i..4i+3 (the corners, then the middle). Texture coordinates: a new corner gets the mean of its edge's two
   corner UVs, one new UV per edge, or two on a seam edge (its faces give its ends different uv indices), appended
   to uv in the order the half-edges first meet them. */
PETSC_EXTERN PetscErrorCode CSMeshDataSplitOnce(CSMeshData *md, PetscBool loop);

/* Isotropic remeshing in place (CGAL Polygon_mesh_processing::isotropic_remeshing, src/mesh/meshdata_remesh.c) to
   `faces` faces (> 0: target edge length h = sqrt(4 A / (sqrt(3) faces)), equilateral faces tiling the area A) or
   else to the target edge length h, with `iterations` CGAL iterations; a boundary is kept (its edges split to at
   most h and protected). Refuses a result whose components, boundary loops or genus differ from topo's, warns when
   it intersects itself; topo is replaced by the result's. md->name gets "(remeshed 6012f)". Rank 0. A build
   without CGAL refuses with a one-line error naming `make deps`. */
#define CS_REMESH_MIN_FACES 20
#define CS_REMESH_MAX_FACES 1e7 /* CGAL's halfedge structure and AABB tree: ~1 kB a face (10 GB) */
PETSC_EXTERN PetscErrorCode CSMeshDataRemesh(CSMeshData *md, CSTopology *topo, PetscInt faces, PetscReal h, PetscInt iterations);

/* Builds md from the options database: -mesh FILE, or -gen icosphere|torus|flattorus|lattice|cylinder|disk with
   -gen_tau RE,IM (lattice), -gen_level, -gen_radius, -gen_torus_R, -gen_tube_r (PETSc option names ignore case), -gen_n, -gen_m, -gen_tau_re, -gen_tau_im, -gen_height, -gen_rings,
   -mesh_remesh N | -mesh_remesh_edge_length h with -mesh_remesh_iterations k (after validation), then
   -mesh_refine n and -mesh_refine_type loop|midpoint (so a remeshed mesh can be refined),
   then validates it (topo filled on rank 0). Collective on comm: options are read on every rank, the data is
   loaded on rank 0 only (other ranks get an empty md); an error on rank 0 is raised on every rank (no hang). */
PETSC_EXTERN PetscErrorCode CSMeshDataFromOptions(MPI_Comm comm, const char prefix[], CSMeshData *md, CSTopology *topo);
/* The mesh of a caller of the library (src/api: the Python interface's arrays V, F), used by CSMeshDataFromOptions
   instead of -mesh/-gen (which it then refuses) while set; md is read on rank 0 (the other ranks pass any non-NULL
   md), copied, and validated as a file is. NULL: off. Set and cleared on every rank. */
PETSC_EXTERN PetscErrorCode CSMeshDataSetArraySource(const CSMeshData *md);
/* A task that takes its conformal class from the positions (the conformal flow, spin transformations, the
   Bobenko-Schroeder flow) refuses -mesh_lengths and -mesh_cross_ratios with one line naming the option and the task,
   rather than ignoring them (issue 36, item 12). Collective on comm. */
PETSC_EXTERN PetscErrorCode CSMeshDataRefuseTargetClass(MPI_Comm comm, const char prefix[], const char task[]);

#endif
