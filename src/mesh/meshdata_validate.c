/* Validation of serial triangle data and its topology (V, E, F, boundary loops, components, genus).
   Everything is O(n) or O(n log n): half-edges are bucketed by their smaller vertex (counting sort) and each
   bucket is sorted by the larger one, so the faces of an edge are adjacent. The first problem found is
   reported with md->name, the 0-based face or vertex and the reason; nothing is modified unless the mesh is
   accepted (then unreferenced vertices are dropped). Work arrays are freed before an error is raised. */
#include "cs_meshdata.h"
#include <stdarg.h>
#include <stdio.h>

typedef struct {
  CSMeshDataEdges E; /* half-edges grouped by edge (meshdata_edges.c) */
  PetscInt *twin; /* 3*nf opposite half-edge, -1 on the boundary */
  PetscInt *vout; /* 3*nf half-edges grouped by their start vertex */
  PetscInt *voff; /* nv+1 */
  PetscInt *aux;  /* max(nv, 3*nf)+1 scratch */
  char      msg[1024];
} Work;

static PetscErrorCode WorkFree(Work *w)
{
  PetscFunctionBeginUser;
  PetscCall(CSMeshDataEdgesDestroy(&w->E));
  PetscCall(PetscFree(w->twin));
  PetscCall(PetscFree(w->vout));
  PetscCall(PetscFree(w->voff));
  PetscCall(PetscFree(w->aux));
  PetscFunctionReturn(0);
}

static void Fail(Work *w, const char fmt[], ...)
{
  va_list ap;
  if (w->msg[0]) return;
  va_start(ap, fmt);
  vsnprintf(w->msg, sizeof(w->msg), fmt, ap);
  va_end(ap);
}

#define HeNext CSHalfedgeNext
#define HePrev CSHalfedgePrev

#define FACEFMT "face %" PetscInt_FMT " (vertices %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT ")"
#define FACEARG(md, i) (i), (md)->f[3 * (i)], (md)->f[3 * (i) + 1], (md)->f[3 * (i) + 2]

/* coordinates up to 1e100: squared lengths (1e200) and the products of the operators stay finite */
#define CS_MAX_COORDINATE 1e100

/* Per-face checks that need no adjacency. */
static void CheckFaces(const CSMeshData *md, Work *w)
{
  PetscReal lo[3] = {PETSC_MAX_REAL, PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[3] = {PETSC_MIN_REAL, PETSC_MIN_REAL, PETSC_MIN_REAL}, diag2 = 0, tol;

  for (PetscInt v = 0; v < md->nv && !w->msg[0]; v++)
    for (int d = 0; d < 3; d++)
      if (PetscIsInfOrNanReal(md->x[3 * v + d])) {
        Fail(w, "%s: vertex %" PetscInt_FMT " has a non-finite coordinate (%s)", md->name, v, PetscIsNanReal(md->x[3 * v + d]) ? "NaN" : "Inf");
        break;
      } else if (PetscAbsReal(md->x[3 * v + d]) > CS_MAX_COORDINATE) { /* 1e300 was called a zero-area face */
        Fail(w, "%s: vertex %" PetscInt_FMT " has the coordinate %g, beyond %g: areas and curvatures would overflow (rescale the mesh)", md->name, v, (double)md->x[3 * v + d], CS_MAX_COORDINATE);
        break;
      }
  for (PetscInt i = 0; i < md->nf && !w->msg[0]; i++) {
    const PetscInt *t = md->f + 3 * i;
    for (int k = 0; k < 3; k++)
      if (t[k] < 0 || t[k] >= md->nv) {
        Fail(w, "%s: " FACEFMT ": vertex index out of range [0, %" PetscInt_FMT ")", md->name, FACEARG(md, i), md->nv);
        break;
      }
    if (!w->msg[0] && (t[0] == t[1] || t[1] == t[2] || t[2] == t[0])) Fail(w, "%s: " FACEFMT ": repeated vertex (degenerate face)", md->name, FACEARG(md, i));
  }
  if (w->msg[0]) return;
  /* zero area relative to the size of the mesh (referenced vertices only) */
  for (PetscInt h = 0; h < 3 * md->nf; h++)
    for (int d = 0; d < 3; d++) {
      lo[d] = PetscMin(lo[d], md->x[3 * md->f[h] + d]);
      hi[d] = PetscMax(hi[d], md->x[3 * md->f[h] + d]);
    }
  for (int d = 0; d < 3; d++) diag2 += (hi[d] - lo[d]) * (hi[d] - lo[d]);
  tol = 1e-14 * diag2;
  for (PetscInt i = 0; i < md->nf; i++) {
    const PetscReal *a = md->x + 3 * md->f[3 * i], *b = md->x + 3 * md->f[3 * i + 1], *c = md->x + 3 * md->f[3 * i + 2];
    PetscReal        u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    PetscReal        n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    PetscReal        area = 0.5 * PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    if (area <= tol) {
      Fail(w, "%s: " FACEFMT ": zero-area face (area %g <= 1e-14 * bounding-box diagonal^2 = %g)", md->name, FACEARG(md, i), (double)area, (double)tol);
      return;
    }
  }
}

/* Texture coordinates (issue 38): finite, and every face corner's index into them in range. Unreferenced UVs
   are kept (the vt list is written back as it was read). */
static void CheckUV(const CSMeshData *md, Work *w)
{
  if (!md->fuv) return;
  for (PetscInt t = 0; t < 2 * md->nuv && !w->msg[0]; t++)
    if (PetscIsInfOrNanReal(md->uv[t])) Fail(w, "%s: texture coordinate %" PetscInt_FMT " has a non-finite %c (%s)", md->name, t / 2, "uv"[t % 2], PetscIsNanReal(md->uv[t]) ? "NaN" : "Inf");
  for (PetscInt h = 0; h < 3 * md->nf && !w->msg[0]; h++)
    if (md->fuv[h] < 0 || md->fuv[h] >= md->nuv) Fail(w, "%s: " FACEFMT ", corner %" PetscInt_FMT ": texture coordinate index %" PetscInt_FMT " out of range [0, %" PetscInt_FMT ")", md->name, FACEARG(md, h / 3), h % 3, md->fuv[h], md->nuv);
}

/* Groups the half-edges by undirected edge (CSMeshDataEdgesCreate), and the out-going half-edges per vertex. */
static PetscErrorCode BuildEdges(const CSMeshData *md, Work *w)
{
  PetscInt nh = 3 * md->nf, *cnt;

  PetscFunctionBeginUser;
  PetscCall(CSMeshDataEdgesCreate(md, &w->E));
  PetscCall(PetscMalloc1(nh, &w->twin));
  PetscCall(PetscMalloc1(nh, &w->vout));
  PetscCall(PetscCalloc1(md->nv + 1, &w->voff));
  PetscCall(PetscMalloc1(PetscMax(md->nv, nh) + 1, &w->aux));
  cnt = w->aux;
  /* out-going half-edges per vertex, for the fans */
  for (PetscInt h = 0; h < nh; h++) w->voff[md->f[h] + 1]++;
  for (PetscInt v = 0; v < md->nv; v++) w->voff[v + 1] += w->voff[v];
  for (PetscInt v = 0; v < md->nv; v++) cnt[v] = w->voff[v];
  for (PetscInt h = 0; h < nh; h++) w->vout[cnt[md->f[h]]++] = h;
  PetscFunctionReturn(0);
}

/* Runs over the edges in three passes so the most telling problem wins: duplicate faces (they also make
   their edges look non-manifold or misoriented), then non-manifold edges, then orientation. Sets twins. */
static void CheckEdges(const CSMeshData *md, Work *w, PetscInt *nedges, PetscInt *nbnd)
{
  *nedges = *nbnd = 0;
  for (int pass = 0; pass < 3 && !w->msg[0]; pass++) {
    for (PetscInt v = 0; v < md->nv && !w->msg[0]; v++) {
      for (PetscInt s = w->E.off[v], e; s < w->E.off[v + 1] && !w->msg[0]; s = e) {
        PetscInt k;
        for (e = s + 1; e < w->E.off[v + 1] && w->E.key[e] == w->E.key[s]; e++) {}
        k = e - s;
        if (pass == 0) {
          /* faces sharing this edge are the same triangle iff their third vertices agree; an edge with very many
             faces is non-manifold anyway, so the quadratic scan is capped */
          for (PetscInt i = s; i < e && i < s + 16 && !w->msg[0]; i++)
            for (PetscInt j = i + 1; j < e && j < s + 16; j++)
              if (md->f[HePrev(w->E.he[i])] == md->f[HePrev(w->E.he[j])]) {
                PetscInt fi = w->E.he[i] / 3, fj = w->E.he[j] / 3;
                Fail(w, "%s: " FACEFMT " and " FACEFMT ": duplicate faces (the same vertex set%s)", md->name, FACEARG(md, fi), FACEARG(md, fj), md->f[w->E.he[i]] == md->f[w->E.he[j]] ? "" : ", opposite orientation");
                break;
              }
        } else if (pass == 1) {
          if (k > 2) {
            char     list[256] = "";
            size_t   n         = 0;
            PetscInt a = md->f[w->E.he[s]], b = md->f[HeNext(w->E.he[s])];
            for (PetscInt i = s; i < e && i < s + 8 && n < sizeof(list); i++) n += (size_t)snprintf(list + n, sizeof(list) - n, "%s%" PetscInt_FMT, i > s ? ", " : "", w->E.he[i] / 3);
            Fail(w, "%s: non-manifold edge (%" PetscInt_FMT ", %" PetscInt_FMT ") shared by %" PetscInt_FMT " faces: %s%s", md->name, PetscMin(a, b), PetscMax(a, b), k, list, k > 8 ? ", ..." : "");
          }
        } else {
          (*nedges)++;
          if (k == 1) {
            w->twin[w->E.he[s]] = -1;
            (*nbnd)++;
          } else {
            PetscInt h0 = w->E.he[s], h1 = w->E.he[s + 1];
            if (md->f[h0] == md->f[h1]) {
              Fail(w, "%s: " FACEFMT " and " FACEFMT ": inconsistent orientation (both traverse the edge %" PetscInt_FMT " -> %" PetscInt_FMT " in the same direction)", md->name, FACEARG(md, h0 / 3), FACEARG(md, h1 / 3), md->f[h0], md->f[HeNext(h0)]);
            }
            w->twin[h0] = h1;
            w->twin[h1] = h0;
          }
        }
      }
    }
  }
}

/* With manifold, consistently oriented edges, the faces around a vertex form disjoint fans; rotating from one
   out-going half-edge across twins (both ways) must visit all of them, otherwise the vertex is pinched. */
static void CheckFans(const CSMeshData *md, Work *w)
{
  for (PetscInt v = 0; v < md->nv && !w->msg[0]; v++) {
    PetscInt deg = w->voff[v + 1] - w->voff[v], h0, h, seen = 1;
    if (!deg) continue;
    h0 = w->vout[w->voff[v]];
    for (h = w->twin[HePrev(h0)]; h >= 0 && h != h0 && seen <= deg; h = w->twin[HePrev(h)]) seen++;
    if (h < 0) /* an open fan: walk the other way from h0 too */
      for (h = h0; w->twin[h] >= 0 && seen <= deg; h = HeNext(w->twin[h])) seen++;
    if (seen != deg) Fail(w, "%s: pinched (non-manifold) vertex %" PetscInt_FMT ": its %" PetscInt_FMT " faces form more than one fan (one fan around it has %" PetscInt_FMT ")", md->name, v, deg, seen);
  }
}

/* Boundary loops (each boundary vertex has exactly one out-going boundary half-edge once fans are checked) and
   components of the face graph (union-find over interior edges). */
static void CountLoopsAndComponents(const CSMeshData *md, Work *w, PetscInt *loops, PetscInt *comps)
{
  PetscInt nh = 3 * md->nf, *bout = w->aux, *par = w->E.key; /* key is no longer needed */

  *loops = *comps = 0;
  for (PetscInt v = 0; v < md->nv; v++) bout[v] = -1;
  for (PetscInt h = 0; h < nh; h++)
    if (w->twin[h] < 0) bout[md->f[h]] = h;
  for (PetscInt h = 0; h < nh; h++) { /* twin of a visited boundary half-edge is set to -2 */
    if (w->twin[h] != -1) continue;
    (*loops)++;
    for (PetscInt g = h; w->twin[g] == -1; g = bout[md->f[HeNext(g)]]) w->twin[g] = -2;
  }
  for (PetscInt h = 0; h < nh; h++)
    if (w->twin[h] == -2) w->twin[h] = -1;
  for (PetscInt i = 0; i < md->nf; i++) par[i] = i;
  for (PetscInt h = 0; h < nh; h++) {
    PetscInt a = h / 3, b;
    if (w->twin[h] < 0) continue;
    b = w->twin[h] / 3;
    while (par[a] != a) a = par[a] = par[par[a]];
    while (par[b] != b) b = par[b] = par[par[b]];
    if (a != b) par[PetscMax(a, b)] = PetscMin(a, b);
  }
  for (PetscInt i = 0; i < md->nf; i++)
    if (par[i] == i) (*comps)++;
}

/* Drops vertices no face uses, keeping the order of the others. The texture coordinates are indexed per face
   corner, not per vertex: fuv and uv stay as they are. */
static PetscErrorCode DropUnreferenced(CSMeshData *md, PetscInt *dropped)
{
  PetscInt *map, n = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(md->nv, &map));
  for (PetscInt v = 0; v < md->nv; v++) map[v] = -1;
  for (PetscInt h = 0; h < 3 * md->nf; h++) map[md->f[h]] = 0;
  for (PetscInt v = 0; v < md->nv; v++)
    if (!map[v]) {
      map[v] = n;
      for (int d = 0; d < 3; d++) md->x[3 * n + d] = md->x[3 * v + d];
      n++;
    }
  *dropped = md->nv - n;
  if (*dropped) {
    for (PetscInt h = 0; h < 3 * md->nf; h++) md->f[h] = map[md->f[h]];
    md->nv = n;
    PetscCall(PetscPrintf(PETSC_COMM_SELF, "Warning: %s: dropped %" PetscInt_FMT " unreferenced vertices\n", md->name, *dropped));
  }
  PetscCall(PetscFree(map));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataValidate(CSMeshData *md, CSTopology *topo)
{
  Work     w;
  PetscInt E = 0, B = 0, loops = 0, comps = 0, V;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&w, sizeof(w)));
  PetscCall(PetscMemzero(topo, sizeof(*topo)));
  PetscCheck(md->nf > 0 && md->nv > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: no faces (%" PetscInt_FMT " vertices, %" PetscInt_FMT " faces)", md->name, md->nv, md->nf);
  CheckFaces(md, &w);
  CheckUV(md, &w);
  if (!w.msg[0]) {
    PetscCall(BuildEdges(md, &w));
    CheckEdges(md, &w, &E, &B);
  }
  if (!w.msg[0]) CheckFans(md, &w);
  if (w.msg[0]) {
    PetscCall(WorkFree(&w));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s", w.msg);
  }
  CountLoopsAndComponents(md, &w, &loops, &comps);
  PetscCall(WorkFree(&w));
  PetscCall(DropUnreferenced(md, &topo->dropped_vertices));
  V                    = md->nv;
  topo->vertices       = V;
  topo->edges          = E;
  topo->faces          = md->nf;
  topo->boundary_edges = B;
  topo->boundary_loops = loops;
  topo->components     = comps;
  topo->euler          = V - E + md->nf;
  topo->genus          = (2 * comps - loops - topo->euler) / 2;
  PetscFunctionReturn(0);
}
