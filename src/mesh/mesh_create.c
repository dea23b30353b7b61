/* From validated serial data on rank 0 to a distributed, interpolated DMPlex with its dof layouts and the
   local connectivity tables the kernels loop over. */
#include "cs_mesh_adjacency.h"
#include "cs_mesh_deform.h"
#include "cs_util.h"
#if defined(PETSC_HAVE_PTSCOTCH)
  #include <stdio.h>
  #include <scotch/ptscotch.h>
#endif

/* A clone of the plex with `dof` unknowns on every point of depth `depth` (0 vertices, 1 edges, 2 faces). */
PetscErrorCode CSMeshCreateFieldDM(DM dm, PetscInt depth, PetscInt dof, const char name[], DM *out)
{
  PetscSection s;
  PetscInt     pStart, pEnd, sStart, sEnd;
  PetscFunctionBeginUser;
  PetscCall(DMClone(dm, out));
  PetscCall(PetscObjectSetName((PetscObject)*out, name));
  PetscCall(DMPlexGetChart(dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(dm, depth, &sStart, &sEnd));
  PetscCall(PetscSectionCreate(PetscObjectComm((PetscObject)dm), &s));
  PetscCall(PetscSectionSetNumFields(s, 1)); /* the VTK/HDF5 viewers want a field */
  PetscCall(PetscSectionSetFieldComponents(s, 0, dof));
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  for (PetscInt p = sStart; p < sEnd; p++) {
    PetscCall(PetscSectionSetDof(s, p, dof));
    PetscCall(PetscSectionSetFieldDof(s, p, 0, dof));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(*out, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscFunctionReturn(0);
}

/* Natural (file-order) ids of vertices and faces survive distribution as ISs migrated with the points. */
static PetscErrorCode MigrateNaturalIds(DM serial, PetscSF sfMig, DM dist, PetscInt depth, PetscInt **ids)
{
  PetscSection sOld, sNew;
  IS           isOld, isNew;
  PetscInt     pStart, pEnd, sStart, sEnd, n, *v;
  const PetscInt *nv;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetChart(serial, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(serial, depth, &sStart, &sEnd));
  PetscCall(PetscSectionCreate(PETSC_COMM_SELF, &sOld));
  PetscCall(PetscSectionSetChart(sOld, pStart, pEnd));
  for (PetscInt p = sStart; p < sEnd; p++) PetscCall(PetscSectionSetDof(sOld, p, 1));
  PetscCall(PetscSectionSetUp(sOld));
  n = sEnd - sStart;
  PetscCall(PetscMalloc1(n, &v));
  /* DMPlexCreateFromCellList numbers cells and vertices in input order, and the section orders points
     by point number: entry i is the i-th cell/vertex of the file (for edges: of the serial interpolation) */
  for (PetscInt i = 0; i < n; i++) v[i] = i;
  PetscCall(ISCreateGeneral(PETSC_COMM_SELF, n, v, PETSC_OWN_POINTER, &isOld));
  if (sfMig) {
    PetscCall(PetscSectionCreate(PETSC_COMM_SELF, &sNew));
    PetscCall(DMPlexDistributeFieldIS(serial, sfMig, sOld, isOld, sNew, &isNew));
  } else {
    PetscCall(PetscObjectReference((PetscObject)sOld));
    PetscCall(PetscObjectReference((PetscObject)isOld));
    sNew  = sOld;
    isNew = isOld;
  }
  PetscCall(DMPlexGetDepthStratum(dist, depth, &sStart, &sEnd));
  PetscCall(PetscMalloc1(sEnd - sStart, ids));
  PetscCall(ISGetIndices(isNew, &nv));
  for (PetscInt p = sStart; p < sEnd; p++) {
    PetscInt off, dof;
    PetscCall(PetscSectionGetDof(sNew, p, &dof));
    PetscCheck(dof == 1, PETSC_COMM_SELF, PETSC_ERR_PLIB, "natural id of point %" PetscInt_FMT " lost in distribution", p);
    PetscCall(PetscSectionGetOffset(sNew, p, &off));
    (*ids)[p - sStart] = nv[off];
  }
  PetscCall(ISRestoreIndices(isNew, &nv));
  PetscCall(ISDestroy(&isOld));
  PetscCall(ISDestroy(&isNew));
  PetscCall(PetscSectionDestroy(&sOld));
  PetscCall(PetscSectionDestroy(&sNew));
  PetscFunctionReturn(0);
}

/* Oriented corners of every face, the edge opposite each corner, and the two vertices of every edge. */
static PetscErrorCode BuildLocalTables(CSMesh m)
{
  DM       dm = m->dm;
  PetscInt fS, fE, eS, eE, vS, vE;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetHeightStratum(dm, 0, &fS, &fE));
  PetscCall(DMPlexGetDepthStratum(dm, 1, &eS, &eE));
  PetscCall(DMPlexGetDepthStratum(dm, 0, &vS, &vE));
  m->nf = fE - fS;
  m->ne = eE - eS;
  m->nv = vE - vS;
  PetscCall(PetscMalloc3(3 * m->nf, &m->faceVert, 3 * m->nf, &m->faceEdge, 2 * m->ne, &m->edgeVert));
  for (PetscInt e = eS; e < eE; e++) {
    const PetscInt *cone;
    PetscCall(DMPlexGetCone(dm, e, &cone));
    m->edgeVert[2 * (e - eS)]     = cone[0] - vS;
    m->edgeVert[2 * (e - eS) + 1] = cone[1] - vS;
  }
  for (PetscInt f = fS; f < fE; f++) {
    PetscInt       *clos = NULL, nc, k = 0;
    const PetscInt *cone;
    /* the closure lists the vertices in the orientation of the cell, i.e. the order of the input triangle */
    PetscCall(DMPlexGetTransitiveClosure(dm, f, PETSC_TRUE, &nc, &clos));
    for (PetscInt c = 0; c < nc; c++) {
      PetscInt p = clos[2 * c];
      if (p >= vS && p < vE) {
        PetscCheck(k < 3, PETSC_COMM_SELF, PETSC_ERR_PLIB, "face %" PetscInt_FMT " is not a triangle", f);
        m->faceVert[3 * (f - fS) + k++] = p - vS;
      }
    }
    PetscCall(DMPlexRestoreTransitiveClosure(dm, f, PETSC_TRUE, &nc, &clos));
    PetscCheck(k == 3, PETSC_COMM_SELF, PETSC_ERR_PLIB, "face %" PetscInt_FMT " is not a triangle", f);
    PetscCall(DMPlexGetCone(dm, f, &cone));
    for (PetscInt a = 0; a < 3; a++) {
      PetscInt b = m->faceVert[3 * (f - fS) + (a + 1) % 3], c = m->faceVert[3 * (f - fS) + (a + 2) % 3], found = -1;
      for (PetscInt j = 0; j < 3; j++) {
        PetscInt e = cone[j] - eS, u = m->edgeVert[2 * e], w = m->edgeVert[2 * e + 1];
        if ((u == b && w == c) || (u == c && w == b)) found = e;
      }
      PetscCheck(found >= 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "face %" PetscInt_FMT ": no edge opposite corner %" PetscInt_FMT, f, a);
      m->faceEdge[3 * (f - fS) + a] = found;
    }
  }
  PetscFunctionReturn(0);
}

/* Ownership from the point SF, and boundary edges = edges with one face in the whole mesh (counted through
   an edge vector, since with overlap 0 a partition-cut edge has one face on each side). */
static PetscErrorCode BuildOwnershipAndBoundary(CSMesh m)
{
  PetscSF         sf;
  PetscInt        nleaves, vS, vE, eS, eE;
  const PetscInt *ilocal;
  CSLocalSum      c;
  PetscFunctionBeginUser;
  PetscCall(DMPlexGetDepthStratum(m->dm, 0, &vS, &vE));
  PetscCall(DMPlexGetDepthStratum(m->dm, 1, &eS, &eE));
  PetscCall(PetscMalloc4(m->nv, &m->vertOwned, m->ne, &m->edgeOwned, m->nv, &m->vertBoundary, m->ne, &m->edgeBoundary));
  for (PetscInt i = 0; i < m->nv; i++) m->vertOwned[i] = PETSC_TRUE;
  for (PetscInt i = 0; i < m->ne; i++) m->edgeOwned[i] = PETSC_TRUE;
  PetscCall(DMGetPointSF(m->dm, &sf));
  PetscCall(PetscSFGetGraph(sf, NULL, &nleaves, &ilocal, NULL));
  for (PetscInt l = 0; l < nleaves; l++) {
    PetscInt p = ilocal ? ilocal[l] : l;
    if (p >= vS && p < vE) m->vertOwned[p - vS] = PETSC_FALSE;
    if (p >= eS && p < eE) m->edgeOwned[p - eS] = PETSC_FALSE;
  }
  PetscCall(CSLocalSumBegin(m->dmE1, &c));
  for (PetscInt k = 0; k < 3 * m->nf; k++) c.a[m->faceEdge[k]] += 1;
  PetscCall(CSLocalSumShare(&c));
  for (PetscInt i = 0; i < m->nv; i++) m->vertBoundary[i] = PETSC_FALSE;
  for (PetscInt e = 0; e < m->ne; e++) {
    m->edgeBoundary[e] = (PetscBool)(PetscRealPart(c.a[e]) < 1.5);
    if (m->edgeBoundary[e]) m->vertBoundary[m->edgeVert[2 * e]] = m->vertBoundary[m->edgeVert[2 * e + 1]] = PETSC_TRUE;
  }
  PetscCall(CSLocalSumEnd(&c, NULL));
  PetscFunctionReturn(0);
}

/* Scatter between a natural vector (everything on rank 0, file order) and a global vector of dmX. */
PetscErrorCode CSMeshNaturalCreate(CSMesh m, DM dmX, PetscInt depth, PetscInt bs, CSMeshNatural *field)
{
  const PetscInt *natural = depth == 0 ? m->vertNatural : (depth == 1 ? m->edgeNatural : m->faceNatural);
  PetscInt        N       = depth == 0 ? m->Nv : (depth == 1 ? m->Ne : m->Nf);
  PetscSection    gs;
  PetscMPIInt     rank;
  PetscInt        sS, sE, n = 0, *from, *to;
  IS              isFrom, isTo;
  Vec             g;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  PetscCall(VecCreateMPI(m->comm, rank ? 0 : bs * N, bs * N, &field->vec));
  PetscCall(DMGetGlobalSection(dmX, &gs));
  PetscCall(DMPlexGetDepthStratum(dmX, depth, &sS, &sE));
  PetscCall(PetscMalloc2(sE - sS, &from, sE - sS, &to));
  for (PetscInt p = sS; p < sE; p++) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(gs, p, &off));
    if (off < 0) continue; /* not owned */
    from[n] = natural[p - sS];
    to[n++] = off / bs;
  }
  PetscCall(ISCreateBlock(m->comm, bs, n, from, PETSC_COPY_VALUES, &isFrom));
  PetscCall(ISCreateBlock(m->comm, bs, n, to, PETSC_COPY_VALUES, &isTo));
  PetscCall(DMGetGlobalVector(dmX, &g));
  PetscCall(VecScatterCreate(field->vec, isFrom, g, isTo, &field->sc));
  PetscCall(DMRestoreGlobalVector(dmX, &g));
  PetscCall(ISDestroy(&isFrom));
  PetscCall(ISDestroy(&isTo));
  PetscCall(PetscFree2(from, to));
  PetscFunctionReturn(0);
}

/* Copy the plex coordinates into the positions vector of dmV3. */
static PetscErrorCode PositionsFromCoordinates(CSMesh m)
{
  Vec                cl, xl;
  PetscSection       cs;
  const PetscScalar *c;
  PetscScalar       *x;
  PetscInt           vS, vE;
  PetscFunctionBeginUser;
  PetscCall(DMGetCoordinatesLocal(m->dm, &cl));
  PetscCall(DMGetCoordinateSection(m->dm, &cs));
  PetscCall(DMPlexGetDepthStratum(m->dm, 0, &vS, &vE));
  PetscCall(DMCreateGlobalVector(m->dmV3, &m->x));
  PetscCall(PetscObjectSetName((PetscObject)m->x, "positions"));
  PetscCall(DMGetLocalVector(m->dmV3, &xl));
  PetscCall(VecGetArrayRead(cl, &c));
  PetscCall(VecGetArray(xl, &x));
  for (PetscInt p = vS; p < vE; p++) {
    PetscInt off;
    PetscCall(PetscSectionGetOffset(cs, p, &off));
    for (PetscInt d = 0; d < 3; d++) x[3 * (p - vS) + d] = c[off + d];
  }
  PetscCall(VecRestoreArray(xl, &x));
  PetscCall(VecRestoreArrayRead(cl, &c));
  PetscCall(DMLocalToGlobal(m->dmV3, xl, INSERT_VALUES, m->x));
  PetscCall(DMRestoreLocalVector(m->dmV3, &xl));
  PetscFunctionReturn(0);
}

/* *out (dmE1) from rank 0's per-face-corner array v (3 per face, the edge opposite each corner; md->len, md->cr):
   each component as a natural face field, then every local face writes its three edges (both faces of an edge
   carry the same value). Nothing if v is NULL on rank 0. */
static PetscErrorCode EdgeFieldFromData(CSMesh m, const CSMeshData *md, const PetscReal *v, const char name[], Vec *out)
{
  PetscMPIInt rank;
  PetscInt    has;
  Vec         gF, lF, lE;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  has = (!rank && v) ? 1 : 0;
  PetscCallMPI(MPI_Bcast(&has, 1, MPIU_INT, 0, m->comm));
  if (!has) PetscFunctionReturn(0);
  PetscCall(DMCreateGlobalVector(m->dmE1, out));
  PetscCall(DMGetGlobalVector(m->dmF1, &gF));
  PetscCall(DMGetLocalVector(m->dmF1, &lF));
  PetscCall(DMGetLocalVector(m->dmE1, &lE));
  for (int a = 0; a < 3; a++) {
    PetscScalar       *n, *e;
    const PetscScalar *f;
    PetscCall(VecGetArray(m->natF1.vec, &n));
    if (!rank)
      for (PetscInt i = 0; i < md->nf; i++) n[i] = v[3 * i + a];
    PetscCall(VecRestoreArray(m->natF1.vec, &n));
    PetscCall(CSMeshScatter(&m->natF1, m->natF1.vec, gF));
    PetscCall(DMGlobalToLocal(m->dmF1, gF, INSERT_VALUES, lF));
    PetscCall(VecGetArrayRead(lF, &f));
    PetscCall(VecGetArray(lE, &e));
    for (PetscInt i = 0; i < m->nf; i++) e[m->faceEdge[3 * i + a]] = f[i];
    PetscCall(VecRestoreArray(lE, &e));
    PetscCall(VecRestoreArrayRead(lF, &f));
  }
  PetscCall(DMLocalToGlobal(m->dmE1, lE, INSERT_VALUES, *out));
  PetscCall(DMRestoreLocalVector(m->dmE1, &lE));
  PetscCall(DMRestoreLocalVector(m->dmF1, &lF));
  PetscCall(DMRestoreGlobalVector(m->dmF1, &gF));
  PetscCall(PetscObjectSetName((PetscObject)*out, name));
  PetscFunctionReturn(0);
}

/* PT-Scotch draws from one random generator per process, seeded once at load: a second mesh distributed in the same
   process (the Python interface's second call, a remesh) got another partition of the same input, so another order
   of the parallel sums, and the flows amplified that to 1e-11 in the positions. Resetting the generator before each
   partition makes the partition a function of the mesh alone (PETSc's own DMPlex tests and DOLFIN do the same); the
   first partition of a process is the one it always was. */
static PetscErrorCode ResetPartitionerRandom(PetscPartitioner part)
{
  PetscBool isScotch;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)part, PETSCPARTITIONERPTSCOTCH, &isScotch));
#if defined(PETSC_HAVE_PTSCOTCH)
  if (isScotch) SCOTCH_randomReset();
#endif
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshCreateFromData(MPI_Comm comm, CSMeshData *md, const CSTopology *topo, CSMesh *mesh)
{
  CSMesh           m;
  DM               serial, dist = NULL;
  PetscSF          sfMig = NULL;
  PetscPartitioner part;
  PetscMPIInt      rank;
  PetscInt         counts[2];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscNew(&m));
  m->comm = comm;
  m->topo = *topo;
  PetscCallMPI(MPI_Bcast(&m->topo, sizeof(CSTopology), MPI_BYTE, 0, comm));
  if (!rank) PetscCall(PetscStrncpy(m->name, md->name, sizeof(m->name)));
  PetscCallMPI(MPI_Bcast(m->name, sizeof(m->name), MPI_CHAR, 0, comm));

  PetscCall(PetscLogEventBegin(CS_EVENT_MeshDistribute, 0, 0, 0, 0));
  PetscCall(DMPlexCreateFromCellListPetsc(comm, 2, rank ? 0 : md->nf, rank ? 0 : md->nv, 3, PETSC_TRUE, rank ? NULL : md->f, 3, rank ? NULL : md->x, &serial));
  PetscCall(DMPlexGetPartitioner(serial, &part));
  PetscCall(PetscPartitionerSetType(part, PETSCPARTITIONERPTSCOTCH));
  PetscCall(PetscPartitionerSetFromOptions(part));
  PetscCall(ResetPartitionerRandom(part));
  PetscCall(DMPlexDistribute(serial, 0, &sfMig, &dist));
  m->dm = dist ? dist : serial;
  PetscCall(PetscObjectSetName((PetscObject)m->dm, "surface"));
  {
    PetscInt *vnat, *fnat, *enat;
    PetscCall(MigrateNaturalIds(serial, sfMig, m->dm, 0, &vnat));
    PetscCall(MigrateNaturalIds(serial, sfMig, m->dm, 2, &fnat));
    PetscCall(MigrateNaturalIds(serial, sfMig, m->dm, 1, &enat));
    m->vertNatural = vnat;
    m->faceNatural = fnat;
    m->edgeNatural = enat;
  }
  if (dist) PetscCall(DMDestroy(&serial));
  PetscCall(PetscSFDestroy(&sfMig));

  PetscCall(CSMeshCreateFieldDM(m->dm, 0, 3, "vertex3", &m->dmV3));
  PetscCall(CSMeshCreateFieldDM(m->dm, 0, 1, "vertex", &m->dmV1));
  PetscCall(CSMeshCreateFieldDM(m->dm, 1, 1, "edge", &m->dmE1));
  PetscCall(CSMeshCreateFieldDM(m->dm, 2, 1, "face", &m->dmF1));
  PetscCall(BuildLocalTables(m));
  PetscCall(BuildOwnershipAndBoundary(m));
  PetscCall(PositionsFromCoordinates(m));
  PetscCall(PetscLogEventEnd(CS_EVENT_MeshDistribute, 0, 0, 0, 0));

  {
    Vec g;
    PetscCall(DMGetGlobalVector(m->dmV1, &g));
    PetscCall(VecGetSize(g, &m->Nv));
    PetscCall(DMRestoreGlobalVector(m->dmV1, &g));
    PetscCall(DMGetGlobalVector(m->dmE1, &g));
    PetscCall(VecGetSize(g, &m->Ne));
    PetscCall(DMRestoreGlobalVector(m->dmE1, &g));
    PetscCall(MPIU_Allreduce(&m->nf, &m->Nf, 1, MPIU_INT, MPI_SUM, comm));
  }
  counts[0] = m->Nv;
  counts[1] = m->Nf;
  PetscCheck(counts[0] == m->topo.vertices && counts[1] == m->topo.faces, comm, PETSC_ERR_PLIB, "distributed mesh has %" PetscInt_FMT " vertices and %" PetscInt_FMT " faces, the input %" PetscInt_FMT " and %" PetscInt_FMT, counts[0], counts[1], m->topo.vertices, m->topo.faces);
  PetscCall(CSMeshNaturalCreate(m, m->dmV3, 0, 3, &m->natV3));
  PetscCall(CSMeshNaturalCreate(m, m->dmV1, 0, 1, &m->natV1));
  PetscCall(CSMeshNaturalCreate(m, m->dmF1, 2, 1, &m->natF1));
  PetscCall(CSMeshNaturalCreate(m, m->dmE1, 1, 1, &m->natE1));
  PetscCall(EdgeFieldFromData(m, md, md->len, "target_lengths", &m->lt));
  PetscCall(EdgeFieldFromData(m, md, md->cr, "target_cross_ratios", &m->ct));
  PetscCall(CSMeshTextureCreate(m, md));

  /* rank 0 keeps the connectivity for output; the coordinates now live in the distributed vector */
  m->serial = *md;
  PetscCall(PetscFree(m->serial.x));
  PetscCall(PetscFree(m->serial.len));
  PetscCall(PetscMemzero(md, sizeof(*md)));
  *mesh = m;
  PetscFunctionReturn(0);
}

/* A closed mesh whose faces all point inward (negative enclosed volume) is flipped to outward orientation:
   volume constraints, normals and the Dirac operator assume outward normals, and the connectivity stays the
   same as a set (a -reference/-target_mesh file is compared face by face as vertex sets). Open meshes have no
   inside, so they are left as they are. -mesh_keep_orientation turns this off. */
static PetscErrorCode OrientOutward(CSMeshData *md, const CSTopology *topo, PetscBool keep)
{
  PetscReal vol = 0;
  PetscFunctionBeginUser;
  if (topo->boundary_loops > 0 || !md->nf) PetscFunctionReturn(0);
  for (PetscInt f = 0; f < md->nf; f++) {
    const PetscReal *a = md->x + 3 * md->f[3 * f], *b = md->x + 3 * md->f[3 * f + 1], *c = md->x + 3 * md->f[3 * f + 2];
    vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  if (vol >= 0) PetscFunctionReturn(0);
  if (keep) {
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "Warning: %s: closed mesh oriented inward (volume %g < 0); kept as it is (-mesh_keep_orientation)\n", md->name, (double)vol));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "Note: %s: closed mesh oriented inward (volume %g < 0); flipped to outward orientation\n", md->name, (double)vol));
  for (PetscInt f = 0; f < md->nf; f++) {
    PetscInt t       = md->f[3 * f + 1];
    md->f[3 * f + 1] = md->f[3 * f + 2];
    md->f[3 * f + 2] = t;
    if (md->fuv) { /* the corners' UVs go with them */
      t                  = md->fuv[3 * f + 1];
      md->fuv[3 * f + 1] = md->fuv[3 * f + 2];
      md->fuv[3 * f + 2] = t;
    }
    if (md->len) { /* corners 1 and 2 swapped: so are the edges opposite them */
      PetscReal l        = md->len[3 * f + 1];
      md->len[3 * f + 1] = md->len[3 * f + 2];
      md->len[3 * f + 2] = l;
    }
    if (md->cr) { /* the same swap, and c0 changes sign with the orientation (the faces ijk and jil trade places) */
      PetscReal c       = md->cr[3 * f + 1];
      md->cr[3 * f + 1] = -md->cr[3 * f + 2];
      md->cr[3 * f + 2] = -c;
      md->cr[3 * f]     = -md->cr[3 * f];
    }
  }
  PetscFunctionReturn(0);
}

/* -o_input: the format by its extension, and the file writable, before any work (the checks of -o) */
static PetscErrorCode CheckInputOutput(MPI_Comm comm, const char path[])
{
  char        ext[16];
  CSFile      f;
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCheck(!strcmp(ext, "obj") || !strcmp(ext, "off") || !strcmp(ext, "ply"), comm, PETSC_ERR_ARG_WRONG, "-o_input %s: the input mesh is written as .obj, .off or .ply", path);
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(CSFileOpen(comm, (PetscBool)!rank, "-o_input", path, PETSC_TRUE, &f));
  PetscCall(CSFileDiscard(&f));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshCreateFromOptions(MPI_Comm comm, const char prefix[], CSMesh *mesh)
{
  CSMeshData  md;
  CSTopology  topo;
  PetscBool   keep = PETSC_FALSE, write_input = PETSC_FALSE;
  PetscMPIInt rank;
  char        input_out[PETSC_MAX_PATH_LEN] = "";
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(&md, sizeof(md)));
  PetscCall(PetscMemzero(&topo, sizeof(topo)));
  PetscOptionsBegin(comm, prefix, "Mesh orientation", NULL);
  PetscCall(PetscOptionsBool("-mesh_keep_orientation", "Keep an inward-oriented closed mesh as it is", NULL, keep, &keep, NULL));
  PetscCall(CSOptionsString("-o_input", "Write the input mesh as the task sees it (after -mesh_remesh, -mesh_refine, -mesh_deform_*) to this .obj/.off/.ply", NULL, input_out, input_out, sizeof(input_out), &write_input));
  PetscOptionsEnd();
  if (write_input) PetscCall(CheckInputOutput(comm, input_out));
  PetscCall(PetscLogEventBegin(CS_EVENT_MeshRead, 0, 0, 0, 0));
  PetscCall(CSMeshDataFromOptions(comm, prefix, &md, &topo));
  if (!rank) PetscCall(OrientOutward(&md, &topo, keep));
  PetscCall(PetscLogEventEnd(CS_EVENT_MeshRead, 0, 0, 0, 0));
  PetscCall(CSMeshCreateFromData(comm, &md, &topo, mesh));
  {
    PetscErrorCode ierr = CSMeshDeformFromOptions(*mesh, prefix); /* a refused -gen_deform_* value: no leak */
    if (ierr) PetscCall(CSMeshDestroy(mesh));
    PetscCall(ierr);
  }
  if (write_input) {
    PetscErrorCode ierr = CSMeshWrite(*mesh, (*mesh)->x, input_out);
    if (ierr) PetscCall(CSMeshDestroy(mesh)); /* no leak on the error path */
    PetscCall(ierr);
    PetscCall(PetscPrintf(comm, "wrote input mesh %s\n", input_out));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshNaturalDestroy(CSMeshNatural *field)
{
  PetscFunctionBeginUser;
  PetscCall(VecScatterDestroy(&field->sc));
  PetscCall(VecDestroy(&field->vec));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDestroy(CSMesh *mesh)
{
  CSMesh m = *mesh;
  PetscFunctionBeginUser;
  if (!m) PetscFunctionReturn(0);
  PetscCall(CSMeshAdjacencyDestroy(&m->adj));
  PetscCall(VecDestroy(&m->x));
  PetscCall(VecDestroy(&m->lt));
  PetscCall(VecDestroy(&m->ct));
  PetscCall(CSMeshNaturalDestroy(&m->natV3));
  PetscCall(CSMeshNaturalDestroy(&m->natV1));
  PetscCall(CSMeshNaturalDestroy(&m->natF1));
  PetscCall(CSMeshNaturalDestroy(&m->natE1));
  PetscCall(PetscFree(m->edgeNatural));
  PetscCall(PetscFree3(m->faceVert, m->faceEdge, m->edgeVert));
  PetscCall(PetscFree4(m->vertOwned, m->edgeOwned, m->vertBoundary, m->edgeBoundary));
  PetscCall(PetscFree(m->vertNatural));
  PetscCall(PetscFree(m->faceUV));
  PetscCall(PetscFree(m->faceNatural));
  PetscCall(CSMeshDataDestroy(&m->serial));
  PetscCall(DMDestroy(&m->dmV3));
  PetscCall(DMDestroy(&m->dmV1));
  PetscCall(DMDestroy(&m->dmE1));
  PetscCall(DMDestroy(&m->dmF1));
  PetscCall(DMDestroy(&m->dm));
  PetscCall(PetscFree(m));
  *mesh = NULL;
  PetscFunctionReturn(0);
}
