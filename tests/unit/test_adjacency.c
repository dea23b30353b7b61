/* Unit checks of the mesh adjacency (cs_mesh_adjacency.h) on closed meshes (icosphere, torus) and meshes with
   boundary (disk, cylinder), serial and under mpirun:
   - every interior edge has two faces, every boundary edge one; the sum of the face counts over the edges
     is 3F, and V - E + F = 2 - 2g - b with that F;
   - the two opposite vertices of an interior edge are distinct and not on the edge, and each opposite vertex
     is a corner of its side's face, with the face on that side traversing the edge in the stated direction;
   - every copy of an edge or a vertex on any rank holds the same global entries, and in file numbering the
     tables equal those of the serial mesh built on rank 0;
   - next(prev(v)) = v on the boundary, the next-cycles visit boundary vertices only, there are as many as
     boundary loops and their lengths add up to the number of boundary edges;
   - CSMeshAdjacencyGatherOpposite of the global vertex numbers is edgeOppGlobal.
   Prints a line per check; exit status = number of failures. */
#include "cs_mesh_adjacency.h"
#include "cs_test.h"

/* kind 0: icosphere, 1: torus, 2: disk, 3: cylinder (rank 0 only; empty elsewhere) */
static PetscErrorCode MakeData(MPI_Comm comm, int kind, CSMeshData *md)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMemzero(md, sizeof(*md)));
  if (rank) PetscFunctionReturn(0);
  if (kind == 0) PetscCall(CSMeshDataIcosphere(2, 1.0, PETSC_TRUE, md));
  else if (kind == 1) PetscCall(CSMeshDataTorus(2.0, 0.7, 16, 9, md));
  else if (kind == 2) PetscCall(CSMeshDataDisk(1.0, 5, md));
  else PetscCall(CSMeshDataCylinder(1.0, 2.0, 12, 5, md));
  PetscFunctionReturn(0);
}

/* allnat[g] = file index of the vertex with global number g (on every rank). */
static PetscErrorCode GlobalToNatural(CSMesh m, PetscInt **allnat)
{
  Vec                g, all;
  VecScatter         sc;
  CSLocalSum         s;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(CSLocalSumBegin(m->dmV1, &s));
  for (PetscInt v = 0; v < m->nv; v++)
    if (m->vertOwned[v]) s.a[v] = (PetscScalar)m->vertNatural[v];
  PetscCall(DMCreateGlobalVector(m->dmV1, &g));
  PetscCall(CSLocalSumEnd(&s, g));
  PetscCall(VecScatterCreateToAll(g, &sc, &all));
  PetscCall(VecScatterBegin(sc, g, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(sc, g, all, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(PetscMalloc1(m->Nv, allnat));
  PetscCall(VecGetArrayRead(all, &a));
  for (PetscInt i = 0; i < m->Nv; i++) (*allnat)[i] = (PetscInt)PetscRealPart(a[i]);
  PetscCall(VecRestoreArrayRead(all, &a));
  PetscCall(VecScatterDestroy(&sc));
  PetscCall(VecDestroy(&all));
  PetscCall(VecDestroy(&g));
  PetscFunctionReturn(0);
}

/* Per local edge, in file numbering: the vertex opposite the face traversing the edge from its lower to its
   higher file index (t[2e]) and the other one (t[2e+1], -1 if none); per local vertex: prev, next (t[2v..]). */
static PetscErrorCode NaturalTables(CSMesh m, CSMeshAdjacency a, const PetscInt allnat[], PetscInt te[], PetscInt tv[])
{
  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt  i = m->vertNatural[m->edgeVert[2 * e]], j = m->vertNatural[m->edgeVert[2 * e + 1]];
    PetscInt  o[2];
    for (int s = 0; s < 2; s++) o[s] = a->edgeOppGlobal[2 * e + s] >= 0 ? allnat[a->edgeOppGlobal[2 * e + s]] : -1;
    te[2 * e]     = i < j ? o[0] : o[1];
    te[2 * e + 1] = i < j ? o[1] : o[0];
  }
  for (PetscInt v = 0; v < m->nv; v++) {
    tv[2 * v]     = a->bdPrevGlobal[v] >= 0 ? allnat[a->bdPrevGlobal[v]] : -1;
    tv[2 * v + 1] = a->bdNextGlobal[v] >= 0 ? allnat[a->bdNextGlobal[v]] : -1;
  }
  PetscFunctionReturn(0);
}

/* Counts, Euler characteristic, diamonds well formed, opposite vertices on their faces, GatherOpposite. */
static PetscErrorCode CheckLocal(CSMesh m, CSMeshAdjacency a, const char name[])
{
  PetscInt  bad[4] = {0, 0, 0, 0}, sums[2] = {0, 0}, *go;
  char      what[128];
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(2 * m->ne, &go));
  PetscCall(CSMeshAdjacencyGatherOpposite(m, a->vertGlobal, -1, go));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt i = a->vertGlobal[m->edgeVert[2 * e]], j = a->vertGlobal[m->edgeVert[2 * e + 1]];
    PetscInt o0 = a->edgeOppGlobal[2 * e], o1 = a->edgeOppGlobal[2 * e + 1];
    if (m->edgeOwned[e]) {
      sums[0]++;
      sums[1] += a->edgeNFaces[e];
    }
    if (a->edgeNFaces[e] != (m->edgeBoundary[e] ? 1 : 2)) bad[0]++;
    if (!m->edgeBoundary[e] && (o0 < 0 || o1 < 0 || o0 == o1 || o0 == i || o0 == j || o1 == i || o1 == j)) bad[1]++;
    if (m->edgeBoundary[e] && (o0 >= 0) == (o1 >= 0)) bad[1]++;
    for (int s = 0; s < 2; s++) {
      PetscInt f = a->edgeFace[2 * e + s];
      if (go[2 * e + s] != a->edgeOppGlobal[2 * e + s]) bad[3]++;
      if (f < 0) continue;
      /* the face on side s contains the opposite vertex and traverses the edge forwards (s = 0) or back */
      for (int k = 0; k < 3; k++) {
        const PetscInt *v = m->faceVert + 3 * f;
        if (m->faceEdge[3 * f + k] != e) continue;
        if (v[k] != a->edgeOpp[2 * e + s] || (v[(k + 1) % 3] == m->edgeVert[2 * e]) != (s == 0)) bad[2]++;
      }
    }
  }
  PetscCall(PetscFree(go));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, bad, 4, MPIU_INT, MPI_SUM, m->comm));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, sums, 2, MPIU_INT, MPI_SUM, m->comm));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: faces per edge (1 on the boundary, else 2)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(bad[0] == 0), what, (PetscReal)bad[0], 0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: diamonds (opposite vertices distinct, off the edge)", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(bad[1] == 0), what, (PetscReal)bad[1], 0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: opposite vertex and side of every local face", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(bad[2] == 0), what, (PetscReal)bad[2], 0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: GatherOpposite(global numbers) = edgeOppGlobal", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(bad[3] == 0), what, (PetscReal)bad[3], 0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: sum of faces per edge = 3F, E = Ne", name));
  PetscCall(CSTestCheck(m->comm, (PetscBool)(sums[1] == 3 * m->Nf && sums[0] == m->Ne), what, (PetscReal)(sums[1] - 3 * m->Nf), 0));
  {
    PetscInt chi = m->Nv - sums[0] + sums[1] / 3, want = 2 * m->topo.components - 2 * m->topo.genus - m->topo.boundary_loops;
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: V - E + F = 2 - 2g - b (%" PetscInt_FMT ")", name, want));
    PetscCall(CSTestCheck(m->comm, (PetscBool)(chi == want), what, (PetscReal)(chi - want), 0));
  }
  PetscFunctionReturn(0);
}

/* Every copy of an edge (vertex) agrees with the owner's copy: local -> global (INSERT, owners) -> local. */
static PetscErrorCode CopiesAgree(DM dm, PetscInt n, PetscInt bs, const PetscInt t[], PetscInt *bad)
{
  Vec          l, g;
  PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalVector(dm, &l));
  PetscCall(DMGetGlobalVector(dm, &g));
  PetscCall(VecGetArray(l, &a));
  for (PetscInt k = 0; k < n * bs; k++) a[k] = (PetscScalar)t[k];
  PetscCall(VecRestoreArray(l, &a));
  PetscCall(DMLocalToGlobal(dm, l, INSERT_VALUES, g));
  PetscCall(DMGlobalToLocal(dm, g, INSERT_VALUES, l));
  PetscCall(VecGetArray(l, &a));
  for (PetscInt k = 0; k < n * bs; k++)
    if ((PetscInt)PetscRealPart(a[k]) != t[k]) (*bad)++;
  PetscCall(VecRestoreArray(l, &a));
  PetscCall(DMRestoreGlobalVector(dm, &g));
  PetscCall(DMRestoreLocalVector(dm, &l));
  PetscFunctionReturn(0);
}

/* Gathers a local per-point pair table into file order on rank 0 (natural index: nat[]), owned copies only. */
static PetscErrorCode GatherNatural(MPI_Comm comm, PetscInt n, const PetscBool owned[], const PetscInt nat[], const PetscInt t[], PetscInt N, PetscInt out[])
{
  PetscInt   *buf, cnt = 0, tot;
  PetscMPIInt size, rank, c, *counts, *displs;
  PetscInt   *all = NULL;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(PetscMalloc1(3 * n, &buf));
  for (PetscInt i = 0; i < n; i++)
    if (owned[i]) {
      buf[3 * cnt]     = nat[i];
      buf[3 * cnt + 1] = t[2 * i];
      buf[3 * cnt + 2] = t[2 * i + 1];
      cnt++;
    }
  c = (PetscMPIInt)(3 * cnt);
  PetscCall(PetscMalloc2(size, &counts, size, &displs));
  PetscCallMPI(MPI_Gather(&c, 1, MPI_INT, counts, 1, MPI_INT, 0, comm));
  tot = 0;
  if (!rank) {
    for (PetscMPIInt r = 0; r < size; r++) {
      displs[r] = (PetscMPIInt)tot;
      tot += counts[r];
    }
    PetscCheck(tot == 3 * N, PETSC_COMM_SELF, PETSC_ERR_PLIB, "owned points %" PetscInt_FMT ", expected %" PetscInt_FMT, tot / 3, N);
    PetscCall(PetscMalloc1(tot, &all));
  }
  PetscCallMPI(MPI_Gatherv(buf, c, MPIU_INT, all, counts, displs, MPIU_INT, 0, comm));
  if (!rank)
    for (PetscInt k = 0; k < N; k++) {
      out[2 * all[3 * k]]     = all[3 * k + 1];
      out[2 * all[3 * k] + 1] = all[3 * k + 2];
    }
  PetscCall(PetscFree(all));
  PetscCall(PetscFree2(counts, displs));
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(0);
}

/* Boundary cycles on the file-order table nb (prev, next per vertex) of rank 0. */
static PetscErrorCode CheckCycles(MPI_Comm comm, CSMesh m, const PetscInt nb[], const char name[])
{
  PetscMPIInt rank;
  PetscInt    bad = 0, loops = 0, len = 0, nbe = 0;
  PetscBool  *seen;
  char        what[128];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (PetscInt e = 0; e < m->ne; e++)
    if (m->edgeOwned[e] && m->edgeBoundary[e]) nbe++;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &nbe, 1, MPIU_INT, MPI_SUM, comm));
  if (!rank) {
    PetscCall(PetscCalloc1(m->Nv, &seen));
    for (PetscInt v = 0; v < m->Nv; v++) {
      PetscInt w = v, steps = 0;
      if (nb[2 * v + 1] < 0 || seen[v]) continue;
      if (nb[2 * nb[2 * v + 1]] != v) bad++; /* prev(next(v)) = v */
      do {
        seen[w] = PETSC_TRUE;
        w       = nb[2 * w + 1];
        steps++;
      } while (w >= 0 && w != v && steps <= m->Nv);
      if (w != v) bad++;
      loops++;
      len += steps;
    }
    PetscCall(PetscFree(seen));
  }
  PetscCallMPI(MPI_Bcast(&bad, 1, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&loops, 1, MPIU_INT, 0, comm));
  PetscCallMPI(MPI_Bcast(&len, 1, MPIU_INT, 0, comm));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: %" PetscInt_FMT " boundary cycle(s) closed, prev(next(v)) = v", name, loops));
  PetscCall(CSTestCheck(comm, (PetscBool)(bad == 0 && loops == m->topo.boundary_loops), what, (PetscReal)bad, 0));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: cycle lengths add up to the %" PetscInt_FMT " boundary edges", name, nbe));
  PetscCall(CSTestCheck(comm, (PetscBool)(len == nbe), what, (PetscReal)(len - nbe), 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckMesh(MPI_Comm comm, int kind, const char name[])
{
  CSMeshData      md, mds;
  CSMesh          m, ms = NULL;
  CSMeshAdjacency a, as;
  PetscMPIInt     rank;
  PetscInt       *allnat, *te, *tv, *ge, *gv, bad = 0, badref = 0;
  char            what[128];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(MakeData(comm, kind, &md));
  PetscCall(PetscMemzero(&mds, sizeof(mds)));
  if (!rank) PetscCall(CSMeshDataDuplicate(&md, &mds));
  PetscCall(CSTestDistribute(comm, &md, 0, 0, &m));
  PetscCall(CSMeshGetAdjacency(m, &a));
  PetscCall(CSMeshGetAdjacency(m, &as));
  PetscCall(CSTestCheck(comm, (PetscBool)(a == as && a == m->adj), "built once per mesh", 0, 0));
  PetscCall(CheckLocal(m, a, name));

  /* the same entries on every copy, and file-numbered tables equal to the serial mesh's */
  PetscCall(GlobalToNatural(m, &allnat));
  PetscCall(PetscMalloc2(2 * m->ne, &te, 2 * m->nv, &tv));
  PetscCall(NaturalTables(m, a, allnat, te, tv));
  PetscCall(CopiesAgree(a->dmE2, m->ne, 2, a->edgeOppGlobal, &bad));
  PetscCall(CopiesAgree(a->dmE2, m->ne, 2, a->edgeFaceGlobal, &bad));
  PetscCall(CopiesAgree(a->dmV2, m->nv, 2, tv, &bad));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &bad, 1, MPIU_INT, MPI_SUM, comm));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: every copy holds the owner's global entries", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(bad == 0), what, (PetscReal)bad, 0));
  PetscCall(PetscMalloc2(rank ? 0 : 2 * m->Ne, &ge, rank ? 0 : 2 * m->Nv, &gv));
  PetscCall(GatherNatural(comm, m->ne, m->edgeOwned, m->edgeNatural, te, m->Ne, ge));
  PetscCall(GatherNatural(comm, m->nv, m->vertOwned, m->vertNatural, tv, m->Nv, gv));
  if (!rank) {
    PetscInt *sallnat, *ste, *stv;
    PetscCall(CSTestDistribute(PETSC_COMM_SELF, &mds, 0, 0, &ms));
    PetscCall(CSMeshGetAdjacency(ms, &as));
    PetscCall(GlobalToNatural(ms, &sallnat));
    PetscCall(PetscMalloc2(2 * ms->ne, &ste, 2 * ms->nv, &stv));
    PetscCall(NaturalTables(ms, as, sallnat, ste, stv));
    for (PetscInt e = 0; e < ms->ne; e++)
      for (int s = 0; s < 2; s++) badref += ge[2 * ms->edgeNatural[e] + s] != ste[2 * e + s];
    for (PetscInt v = 0; v < ms->nv; v++)
      for (int s = 0; s < 2; s++) badref += gv[2 * ms->vertNatural[v] + s] != stv[2 * v + s];
    PetscCall(PetscFree2(ste, stv));
    PetscCall(PetscFree(sallnat));
    PetscCall(CSMeshDestroy(&ms));
  }
  PetscCallMPI(MPI_Bcast(&badref, 1, MPIU_INT, 0, comm));
  PetscCall(PetscSNPrintf(what, sizeof(what), "%s: tables in file numbering = the serial mesh's", name));
  PetscCall(CSTestCheck(comm, (PetscBool)(badref == 0), what, (PetscReal)badref, 0));
  PetscCall(CheckCycles(comm, m, gv, name));
  PetscCall(PetscFree2(ge, gv));
  PetscCall(PetscFree2(te, tv));
  PetscCall(PetscFree(allnat));
  PetscCall(CSMeshDestroy(&m));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  const char *names[] = {"icosphere", "torus", "disk", "cylinder"};
  PetscCall(PetscInitialize(&argc, &argv, NULL, NULL));
  for (int k = 0; k < 4; k++) PetscCall(CheckMesh(PETSC_COMM_WORLD, k, names[k]));
  PetscCall(PetscFinalize());
  return (int)cs_test_failures;
}
