/* The edges of serial triangle data as groups of half-edges (the one edge-twin builder of the mesh layer, used by
   validation, -mesh_lengths and -mesh_cross_ratios): half-edge h = 3 f + c runs from f[h] to f[next(h)] (it is the
   edge opposite corner c + 2 of face f); half-edges are bucketed by their smaller vertex (counting sort) and each
   bucket is sorted by the larger one, so the half-edges of one undirected edge are adjacent. O(n log n). */
#include "cs_meshdata.h"

PetscErrorCode CSMeshDataEdgesCreate(const CSMeshData *md, CSMeshDataEdges *E)
{
  PetscInt nh = 3 * md->nf, *cnt;
  PetscFunctionBeginUser;
  E->nv = md->nv;
  E->nh = nh;
  PetscCall(PetscMalloc1(nh, &E->he));
  PetscCall(PetscMalloc1(nh, &E->key));
  PetscCall(PetscCalloc1(md->nv + 1, &E->off));
  PetscCall(PetscMalloc1(md->nv + 1, &cnt));
  for (PetscInt h = 0; h < nh; h++) E->off[PetscMin(md->f[h], md->f[CSHalfedgeNext(h)]) + 1]++;
  for (PetscInt v = 0; v < md->nv; v++) E->off[v + 1] += E->off[v];
  for (PetscInt v = 0; v < md->nv; v++) cnt[v] = E->off[v];
  for (PetscInt h = 0; h < nh; h++) {
    PetscInt a = md->f[h], b = md->f[CSHalfedgeNext(h)], s = cnt[PetscMin(a, b)]++;
    E->he[s]  = h;
    E->key[s] = PetscMax(a, b);
  }
  PetscCall(PetscFree(cnt));
  for (PetscInt v = 0; v < md->nv; v++)
    if (E->off[v + 1] - E->off[v] > 1) PetscCall(PetscSortIntWithArray(E->off[v + 1] - E->off[v], E->key + E->off[v], E->he + E->off[v]));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataEdgesDestroy(CSMeshDataEdges *E)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(E->he));
  PetscCall(PetscFree(E->key));
  PetscCall(PetscFree(E->off));
  PetscFunctionReturn(0);
}

/* The slots [*s, *s + *k) of E->he holding the half-edges of the edge {a, b}; *k = 0 if it is not an edge. */
void CSMeshDataEdgesFind(const CSMeshDataEdges *E, PetscInt a, PetscInt b, PetscInt *s, PetscInt *k)
{
  PetscInt lo = 0, hi = 0, u = PetscMin(a, b), w = PetscMax(a, b);
  *s = *k = 0;
  if (u < 0 || w >= E->nv) return;
  lo = E->off[u];
  hi = E->off[u + 1];
  while (lo < hi) { /* first slot with key >= w */
    PetscInt mid = (lo + hi) / 2;
    if (E->key[mid] < w) lo = mid + 1;
    else hi = mid;
  }
  *s = lo;
  while (lo < E->off[u + 1] && E->key[lo] == w) lo++;
  *k = lo - *s;
}

/* The next edge group after slot s (its end), for loops over the edges: for (s = 0; s < nh; s = e) e = ...End(s). */
PetscInt CSMeshDataEdgesGroupEnd(const CSMeshDataEdges *E, const CSMeshData *md, PetscInt s)
{
  PetscInt e = s + 1, u = PetscMin(md->f[E->he[s]], md->f[CSHalfedgeNext(E->he[s])]);
  while (e < E->off[u + 1] && E->key[e] == E->key[s]) e++;
  return e;
}
