/* A conformal class from a file of log length cross ratios (issue 15 item 6): md->cr, the flows' target c0
   (cgd: c0 = the file's values, soliman2021 Eq. 3; trianglefield: both halfedges of an edge, Eq. 14). Lines
   "i j c0", one per interior edge, i j the edge's vertices 1-based as in OBJ face lines (the order of the mesh's
   vertices), c0 = log(l_il l_jk / (l_lj l_ki)) for the faces ijk (traversing i -> j) and jil of the edge in the
   file's orientation (symmetric in i, j: cross_ratio.c). A c0 must lie in im C: C is skew (C_ijk of Eq. 24 is) and
   C A = 0 (Eq. 4) with rank |E| - |V| on a closed mesh, so im C = (ker C)^perp = ker A^T, A the vertex-to-edge map
   (A u)_ij = u_i + u_j. On a closed mesh c0 is projected onto ker A^T, c0 <- c0 - A (A^T A)^{-1} A^T c0 (A^T A is
   the signless graph Laplacian, SPD on a triangle mesh: the graph has odd cycles), and refused if the removed part
   exceeds tol in the max norm. Rank 0, serial arrays. */
#include "cs_meshdata.h"
#include "cs_util.h"
#include <math.h>

#define CS_CROSS_RATIO_MAX 700.0

typedef struct {
  PetscInt  ne, *a, *b; /* the interior edges (0-based vertices) */
  PetscReal *c;         /* their c0 */
} EdgeValues;

/* y = A^T A x: (y)_v = sum over the edges ab at v of x_a + x_b */
static void SignlessLaplacian(const EdgeValues *ev, PetscInt nv, const PetscReal *x, PetscReal *y)
{
  for (PetscInt v = 0; v < nv; v++) y[v] = 0;
  for (PetscInt e = 0; e < ev->ne; e++) {
    PetscReal s = x[ev->a[e]] + x[ev->b[e]];
    y[ev->a[e]] += s;
    y[ev->b[e]] += s;
  }
}

/* r = A (A^T A)^{-1} A^T c (conjugate gradients to 1e-14 relative), the part of c outside ker A^T = im C; on c
   scaled by the power of 2 above max |c|, so that the squared norms cannot overflow (issue 36: c ~ 1e154 made rr inf, no iteration) */
static PetscErrorCode OutsideImage(const EdgeValues *ev, PetscInt nv, PetscReal *r)
{
  PetscReal *x, *res, *p, *q, rr = 0, b2 = 0, cmax = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscCalloc4(nv, &x, nv, &res, nv, &p, nv, &q));
  for (PetscInt e = 0; e < ev->ne; e++) cmax = PetscMax(cmax, PetscAbsReal(ev->c[e]));
  if (cmax == 0) cmax = 1;
  else { /* a power of 2: the scaling is exact, the answers bit-identical to the unscaled ones */
    int ex;
    (void)frexp(cmax, &ex);
    cmax = ldexp(1.0, ex);
  }
  for (PetscInt e = 0; e < ev->ne; e++) {
    res[ev->a[e]] += ev->c[e] / cmax;
    res[ev->b[e]] += ev->c[e] / cmax;
  }
  for (PetscInt v = 0; v < nv; v++) p[v] = res[v], rr += res[v] * res[v];
  b2 = rr;
  for (PetscInt it = 0; it < 10 * nv + 100 && rr > 1e-28 * b2 && rr > 0; it++) {
    PetscReal pq = 0, alpha, rr1 = 0;
    SignlessLaplacian(ev, nv, p, q);
    for (PetscInt v = 0; v < nv; v++) pq += p[v] * q[v];
    alpha = rr / pq;
    for (PetscInt v = 0; v < nv; v++) x[v] += alpha * p[v], res[v] -= alpha * q[v], rr1 += res[v] * res[v];
    for (PetscInt v = 0; v < nv; v++) p[v] = res[v] + rr1 / rr * p[v];
    rr = rr1;
  }
  for (PetscInt e = 0; e < ev->ne; e++) r[e] = cmax * (x[ev->a[e]] + x[ev->b[e]]);
  PetscCall(PetscFree4(x, res, p, q));
  PetscFunctionReturn(0);
}

/* One line "i j c0" (values v[0..2] of line L): the slot range of its edge, or a one-line error. */
static PetscErrorCode ParseLine(const char option[], const char path[], const CSMeshData *md, const CSMeshDataEdges *E, const PetscReal v[3], PetscInt L, PetscInt *s)
{
  PetscInt k, ij[2];
  PetscFunctionBeginUser;
  for (int t = 0; t < 2; t++) {
    PetscCheck(v[t] == PetscFloorReal(v[t]) && v[t] >= 1 && v[t] <= md->nv, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": vertex %g is not an integer in [1, %" PetscInt_FMT "] (lines 'i j c0', vertices 1-based as in OBJ)", option, path, L, (double)v[t], md->nv);
    ij[t] = (PetscInt)v[t] - 1;
  }
  CSMeshDataEdgesFind(E, ij[0], ij[1], s, &k);
  PetscCheck(k > 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": (%" PetscInt_FMT ", %" PetscInt_FMT ") is not an edge of %s", option, path, L, ij[0] + 1, ij[1] + 1, md->name);
  PetscCheck(k == 2, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": (%" PetscInt_FMT ", %" PetscInt_FMT ") is a boundary edge (cross ratios are given on interior edges)", option, path, L, ij[0] + 1, ij[1] + 1);
  PetscFunctionReturn(0);
}

/* The lines into per-slot values (seen[s] = the line that gave the edge at slot s), then the count. */
static PetscErrorCode ReadEdges(const char option[], const char path[], const CSMeshData *md, const CSMeshDataEdges *E, PetscInt n, const PetscReal *v, const PetscInt *lines, PetscInt *seen, PetscReal *val)
{
  PetscInt nint = 0, s;
  PetscFunctionBeginUser;
  PetscCheck(n % 3 == 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": %" PetscInt_FMT " numbers in all, not a multiple of 3 (lines 'i j c0')", option, path, lines[n - 1], n);
  for (PetscInt t = 0; t < n; t += 3) {
    PetscCheck(lines[t] == lines[t + 2], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": expected 3 numbers 'i j c0' on the line", option, path, lines[t]);
    PetscCall(ParseLine(option, path, md, E, v + t, lines[t], &s));
    PetscCheck(!seen[s], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": the edge (%g, %g) is given twice (first on line %" PetscInt_FMT ")", option, path, lines[t], (double)v[t], (double)v[t + 1], seen[s]);
    /* a log cross ratio beyond 700 is a length ratio beyond e^700 = 1e304: no double metric has it (issue 36) */
    PetscCheck(PetscAbsReal(v[t + 2]) <= CS_CROSS_RATIO_MAX, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": the log cross ratio %g is not in [-%d, %d] (a length ratio beyond e^%d overflows a double)", option, path, lines[t], (double)v[t + 2], (int)CS_CROSS_RATIO_MAX, (int)CS_CROSS_RATIO_MAX, (int)CS_CROSS_RATIO_MAX);
    seen[s] = lines[t];
    val[s]  = v[t + 2];
  }
  for (PetscInt i = 0, e; i < E->nh; i = e) {
    e = CSMeshDataEdgesGroupEnd(E, md, i);
    if (e - i == 2) nint++;
  }
  PetscCheck(n / 3 == nint, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: %" PetscInt_FMT " lines, expected one per interior edge of %s: %" PetscInt_FMT, option, path, n / 3, md->name, nint);
  PetscFunctionReturn(0);
}

/* The interior edges and their values, projected onto im C on a closed mesh (refused above tol), into md->cr. */
static PetscErrorCode Store(const char option[], const char path[], PetscReal tol, const CSMeshDataEdges *E, const PetscInt *seen, const PetscReal *val, CSMeshData *md)
{
  EdgeValues ev;
  PetscReal *r, rmax = 0;
  PetscBool  closed = PETSC_TRUE;
  PetscInt   emax = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc4(E->nh, &ev.a, E->nh, &ev.b, E->nh, &ev.c, E->nh, &r));
  ev.ne = 0;
  for (PetscInt i = 0, e; i < E->nh; i = e) {
    e = CSMeshDataEdgesGroupEnd(E, md, i);
    if (e - i != 2) closed = PETSC_FALSE;
    if (!seen[i]) continue;
    ev.a[ev.ne] = PetscMin(md->f[E->he[i]], md->f[CSHalfedgeNext(E->he[i])]);
    ev.b[ev.ne] = E->key[i];
    ev.c[ev.ne++] = val[i];
  }
  if (closed) PetscCall(OutsideImage(&ev, md->nv, r));
  for (PetscInt e = 0; closed && e < ev.ne; e++)
    if (PetscAbsReal(r[e]) > rmax) rmax = PetscAbsReal(r[e]), emax = e;
  if (rmax > tol) {
    PetscInt a = ev.a[emax] + 1, b = ev.b[emax] + 1;
    PetscCall(PetscFree4(ev.a, ev.b, ev.c, r));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: the cross ratios are not those of any metric: their part outside im C (rank |E| - |V|) is %.3g at the edge (%" PetscInt_FMT ", %" PetscInt_FMT "), above -mesh_cross_ratios_tol %g", option, path, (double)rmax, a, b, (double)tol);
  }
  PetscCall(PetscMalloc1(3 * md->nf, &md->cr));
  for (PetscInt i = 0; i < 3 * md->nf; i++) md->cr[i] = 0; /* boundary edges: no row */
  for (PetscInt i = 0, e, n = 0; i < E->nh; i = e) {
    e = CSMeshDataEdgesGroupEnd(E, md, i);
    if (!seen[i]) continue;
    for (PetscInt j = i; j < e; j++) md->cr[3 * (E->he[j] / 3) + (E->he[j] % 3 + 2) % 3] = ev.c[n] - (closed ? r[n] : 0);
    n++;
  }
  PetscCall(PetscFree4(ev.a, ev.b, ev.c, r));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataReadCrossRatios(const char option[], const char path[], PetscReal tol, CSMeshData *md)
{
  PetscInt        n, *lines, *seen;
  PetscReal      *v, *val;
  CSMeshDataEdges E;
  PetscErrorCode  ierr;
  PetscFunctionBeginUser;
  PetscCheck(!md->len, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "%s %s: the mesh %s already carries an intrinsic metric (-gen lattice, -mesh_lengths)", option, path, md->name);
  PetscCall(CSReadNumberFile(option, path, &n, &v, &lines));
  if (!n) {
    PetscCall(PetscFree(v));
    PetscCall(PetscFree(lines));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: no numbers (lines 'i j c0', one per interior edge)", option, path);
  }
  PetscCall(CSMeshDataEdgesCreate(md, &E));
  PetscCall(PetscCalloc1(E.nh, &seen));
  PetscCall(PetscCalloc1(E.nh, &val));
  ierr = ReadEdges(option, path, md, &E, n, v, lines, seen, val);
  if (!ierr) ierr = Store(option, path, tol, &E, seen, val, md);
  PetscCall(PetscFree(seen));
  PetscCall(PetscFree(val));
  PetscCall(PetscFree(v));
  PetscCall(PetscFree(lines));
  PetscCall(CSMeshDataEdgesDestroy(&E));
  return ierr;
}
