/* Discrete Willmore energy of bobenko-schroeder2005 (Secs. 2, 3.1-3.3, 4): value, per-vertex W_i, gradient
   in the scalar form of Eq. 1 and the linearised Hessian K.

   Notation (paper Fig. 1): interior edge e_ij with faces t_ijl (traversed i -> j) and t_jik (j -> i); the
   diamond is (k, j, l, i) counter-clockwise, a = v_j - v_k, b = v_l - v_j, c = v_i - v_l, d = v_k - v_i and
   A, B, C, D their unit vectors. cos beta = <A,C><B,D> - <A,B><C,D> - <B,C><D,A> = -Re(A B^-1 C D^-1)
   (Sec. 3.1). Each edge contributes beta to W_i and W_j (beta^i_j = beta^j_i), so W = 2 sum_e beta - 2 pi V;
   W is nevertheless summed vertex by vertex (W_i small near a minimum, no 2 pi V cancellation: |W| = 8e-14
   instead of 9e-12 on the level-3 icosphere). beta = atan2(|Im Q|, -Re Q) keeps digits near 0 and pi.

   Eq. 1 (checked against central differences, see tests/unit/test_bs_energy.c: the printed signs are right):
     -sin(beta) beta_,k = (cos b/|a|^2 - <B,C>/(|a||d|)) a + (<A,C>/(|b||d|) + <C,D>/(|b||a|)) b
                          - (<A,B>/(|c||d|) + <B,D>/(|c||a|)) c - (cos b/|d|^2 - <B,C>/(|a||d|)) d.
   The other three vertex gradients are the same function with cyclically permuted arguments (Sec. 3.1:
   beta_,j = f1(j,l,i,k) etc.). Since a..d are differences of positions, grad beta = M p with a scalar 4x4 M
   per diamond whose rows sum to zero; K = sum over diamonds of (edge weight) M is the n x n "linearised
   Hessian" of Sec. 4, and grad W = K x holds exactly at the current positions (per coordinate).

   Distribution (CSMesh has overlap 0): the two faces of an edge on a partition cut live on different ranks,
   so the far opposite vertex of a diamond may not be local. The mesh adjacency (cs_mesh_adjacency.h) gives
   the diamond's vertices in global numbering on every rank holding the edge (side 0: t_ijl with
   i = edgeVert[0], side 1: t_jik); per evaluation each face writes the position of its opposite vertex into
   its side's slot of a per-edge field, and LocalToGlobal(ADD) + GlobalToLocal gives every such rank the
   whole diamond. Every rank then evaluates its local diamonds; the edge owner adds the value and the rows of
   i and j, the rank of each face adds the row of that face's opposite vertex (each face is on one rank only),
   so every term is added exactly once. K rows/columns use global vertex numbers (from the adjacency). The free boundary's beta_3 needs both boundary neighbours of a boundary
   vertex: exchanged the same way through a per-vertex field. */
#include "cs_energy_bs.h"
#include "cs_mesh_adjacency.h"
#include "cs_quaternion.h"

const char *const CSBSBoundaries[]    = {"fixed", "free", "CSBSBoundary", "CS_BS_BOUNDARY_", NULL};
const char *const CSBSSingularRules[] = {"heuristic", "single", "delta", "CSBSSingular", "CS_BS_SINGULAR_", NULL};

typedef struct {
  CSBSBoundary bc;
  PetscReal    eps;
  PetscReal    epsK;     /* diamonds with sin beta below this are left out of K (default eps, see header) */
  PetscBool    freebd;   /* FREE and the mesh has a boundary */
  DM           dmE6;     /* 6 dofs per edge: opposite vertex position per side */
  DM           dmV6;     /* 6 dofs per vertex: previous/next boundary neighbour position (FREE) */
  CSMeshAdjacency adj;   /* the mesh's: edge sides (diamonds) and boundary neighbours, global and local */
  PetscInt    *oppFixed; /* 2*ne: the opposite vertex per side is fixed */
  const PetscInt *gid;   /* nv: global vertex numbers (dmV1 local-to-global) */
  PetscBool   *fixed;    /* nv */
  PetscInt     nfixed;
  PetscBool   *islands;  /* nv, or NULL: user-fixed vertices (Sec. 3.3 "islands"), fixed with their one-ring */
  CSBSSingular rule;     /* Sec. 3.2: the eps heuristic, the rule for a single vanishing beta, or delta */
  PetscReal   *wEdge;    /* ne: multiplicity of beta(e) in W */
  Vec          Wg;       /* dmV1 work vector: per-vertex W_i when the caller does not want them */
  PetscReal   *gkl;      /* 6*ne scratch: weighted gradient rows of l (side 0) and k (side 1) */
  PetscReal   *Mkl;      /* 8*ne scratch: weighted K rows of l and k (zeros for inactive diamonds: K's nonzero
                            pattern must not depend on which diamonds pass the |sin beta| test, or a later
                            reassembly would need new nonzeros after the first assembly compressed K) */
  PetscBool   *act;      /* ne scratch */
  PetscBool   *both;     /* ne: both faces of the edge are on this rank (then it is owned here and the whole
                            diamond is added in one block by the edge loop) */
  PetscInt    *nnz;      /* owned rows: preallocation bound 1 + 2 * valence */
} BSCtx;

/* ---------------------------------------------------------------- kernels */
void CSBSDiamond(const PetscReal *const P[4], PetscReal eps, PetscReal *beta, PetscReal M[4][4], PetscBool *active)
{
  PetscReal E[4][3], U[4][4], len[4], G[4][4], q1[4], q2[4], q[4], cb, sb;
  for (int r = 0; r < 4; r++) {
    CSVecSub(P[(r + 1) % 4], P[r], E[r]); /* E0 = a = j - k, E1 = b = l - j, E2 = c = i - l, E3 = d = k - i */
    len[r]  = CSVecNorm(E[r]);
    U[r][0] = 0;
    for (int t = 0; t < 3; t++) U[r][t + 1] = E[r][t] / len[r];
  }
  for (int r = 0; r < 4; r++)
    for (int s = 0; s < 4; s++) G[r][s] = U[r][1] * U[s][1] + U[r][2] * U[s][2] + U[r][3] * U[s][3];
  /* Q = A B^-1 C D^-1 = A B C D (X^-1 = -X for unit imaginary X); cos beta = -Re Q, sin beta = |Im Q| >= 0.
     atan2 keeps beta accurate near 0 and pi where acos(cos) loses half the digits. */
  CSQuatMul(U[0], U[1], q1);
  CSQuatMul(q1, U[2], q2);
  CSQuatMul(q2, U[3], q);
  cb    = -q[0];
  sb    = PetscSqrtReal(q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  *beta = PetscAtan2Real(sb, cb);
  *active = (PetscBool)(sb >= eps);
  if (!M) return; /* value only */
  for (int r = 0; r < 4; r++)
    for (int m = 0; m < 4; m++) M[r][m] = 0;
  if (!*active) return;
  /* The paper's cos beta uses exactly these dot products; use it (not -Re Q, equal up to rounding). */
  cb = G[0][2] * G[1][3] - G[0][1] * G[2][3] - G[1][2] * G[3][0];
  for (int r = 0; r < 4; r++) {
    const int a = r, b = (r + 1) % 4, c = (r + 2) % 4, d = (r + 3) % 4;
    const PetscReal la = len[a], lb = len[b], lc = len[c], ld = len[d];
    /* Eq. 1 for f1(P[r], P[r+1], P[r+2], P[r+3]) */
    const PetscReal aa = cb / (la * la) - G[b][c] / (la * ld);
    const PetscReal ab = G[a][c] / (lb * ld) + G[c][d] / (lb * la);
    const PetscReal ac = G[a][b] / (lc * ld) + G[b][d] / (lc * la);
    const PetscReal ad = cb / (ld * ld) - G[b][c] / (la * ld);
    /* -sin b grad = aa (P1 - P0) + ab (P2 - P1) - ac (P3 - P2) - ad (P0 - P3) */
    M[r][a] = (aa + ad) / sb;
    M[r][b] = (ab - aa) / sb;
    M[r][c] = -(ab + ac) / sb;
    M[r][d] = (ac - ad) / sb;
  }
}

/* Angle theta at P[0] between P[1] - P[0] and P[2] - P[0], with grad_{P[r]} theta = sum_m M[r][m] P[m]
   (the edge-angle gradient of [DMA02] App. B the paper refers to, in the same scalar form as Eq. 1:
   grad_{P1} theta = -(1/sin)(v/(|u||v|) - cos u/|u|^2), u = P1 - P0, v = P2 - P0). */
static void BSAngle(const PetscReal *const P[3], PetscReal eps, PetscReal *theta, PetscReal M[3][3], PetscBool *active)
{
  PetscReal u[3], v[3], w[3], lu, lv, cs, sn;
  CSVecSub(P[1], P[0], u);
  CSVecSub(P[2], P[0], v);
  CSVecCross(u, v, w);
  lu     = CSVecNorm(u);
  lv     = CSVecNorm(v);
  cs     = CSVecDot(u, v) / (lu * lv);
  sn     = CSVecNorm(w) / (lu * lv);
  *theta = PetscAtan2Real(sn, cs);
  *active = (PetscBool)(sn >= eps);
  for (int r = 0; r < 3; r++)
    for (int m = 0; m < 3; m++) M[r][m] = 0;
  if (!*active) return;
  M[1][1] = cs / (sn * lu * lu);
  M[1][2] = -1 / (sn * lu * lv);
  M[1][0] = -(M[1][1] + M[1][2]);
  M[2][2] = cs / (sn * lv * lv);
  M[2][1] = -1 / (sn * lu * lv);
  M[2][0] = -(M[2][1] + M[2][2]);
  for (int m = 0; m < 3; m++) M[0][m] = -(M[1][m] + M[2][m]); /* translation invariance */
}

/* ---------------------------------------------------------------- setup */

/* Fixed vertices (FIXED mode): the boundary and its one-ring (Sec. 3.3), on every copy; the global counts. */
static PetscErrorCode BSFixedSet(CSEnergy en)
{
  BSCtx     *c = (BSCtx *)en->ctx;
  CSMesh     m = en->mesh;
  CSLocalSum s;
  PetscInt   nint = 0, nbdv = 0, N[3], Nsum[3];
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->fixed));
  PetscCall(PetscCalloc1(m->nv, &c->fixed));
  PetscCall(CSLocalSumBegin(m->dmV1, &s));
  /* seeds: the boundary (FIXED mode) and the islands, known on every copy of a vertex; then their one-ring */
  for (PetscInt v = 0; v < m->nv; v++) c->fixed[v] = (PetscBool)((c->bc == CS_BS_BOUNDARY_FIXED && m->vertBoundary[v]) || (c->islands && c->islands[v]));
  for (PetscInt v = 0; v < m->nv; v++)
    if (c->fixed[v]) s.a[v] = 1;
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt i = m->edgeVert[2 * e], j = m->edgeVert[2 * e + 1];
    if (c->fixed[i]) s.a[j] = 1;
    if (c->fixed[j]) s.a[i] = 1;
  }
  PetscCall(CSLocalSumShare(&s));
  N[0] = 0;
  for (PetscInt v = 0; v < m->nv; v++) {
    c->fixed[v] = (PetscBool)(PetscRealPart(s.a[v]) > 0.5);
    if (m->vertOwned[v] && c->fixed[v]) N[0]++;
    if (m->vertOwned[v] && !m->vertBoundary[v]) nint++;
    if (m->vertOwned[v] && m->vertBoundary[v]) nbdv++;
  }
  PetscCall(CSLocalSumEnd(&s, NULL));
  N[1] = nint;
  N[2] = nbdv;
  PetscCall(MPIU_Allreduce(N, Nsum, 3, MPIU_INT, MPI_SUM, m->comm));
  c->nfixed = Nsum[0];
  c->freebd = (PetscBool)(c->bc == CS_BS_BOUNDARY_FREE && Nsum[2] > 0);
  PetscFunctionReturn(0);
}

/* the far vertices' fixed flags (their positions travel per evaluation through dmE6) */
static PetscErrorCode BSOppositeFixed(CSEnergy en)
{
  BSCtx    *c = (BSCtx *)en->ctx;
  CSMesh    m = en->mesh;
  PetscInt *fx;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->oppFixed));
  PetscCall(PetscMalloc1(m->nv, &fx));
  PetscCall(PetscMalloc1(2 * m->ne, &c->oppFixed));
  for (PetscInt v = 0; v < m->nv; v++) fx[v] = c->fixed[v] ? 1 : 0;
  PetscCall(CSMeshAdjacencyGatherOpposite(m, fx, 0, c->oppFixed));
  PetscCall(PetscFree(fx));
  PetscFunctionReturn(0);
}

/* Preallocation bound of K: 1 + 2 valence (the 1-ring with flaps, Sec. 4: 13 for valence 6) per owned row. */
static PetscErrorCode BSPreallocation(CSEnergy en)
{
  BSCtx     *c = (BSCtx *)en->ctx;
  CSMesh     m = en->mesh;
  CSLocalSum s;
  Vec        g;
  PetscInt   nown = 0, rstart;
  PetscFunctionBeginUser;
  PetscCall(CSLocalSumBegin(m->dmV1, &s));
  for (PetscInt e = 0; e < m->ne; e++)
    if (m->edgeOwned[e]) {
      s.a[m->edgeVert[2 * e]] += 1;
      s.a[m->edgeVert[2 * e + 1]] += 1;
    }
  PetscCall(CSLocalSumShare(&s));
  for (PetscInt v = 0; v < m->nv; v++)
    if (m->vertOwned[v]) nown++;
  PetscCall(PetscMalloc1(nown, &c->nnz));
  PetscCall(DMGetGlobalVector(m->dmV1, &g));
  PetscCall(VecGetOwnershipRange(g, &rstart, NULL));
  PetscCall(DMRestoreGlobalVector(m->dmV1, &g));
  for (PetscInt v = 0; v < m->nv; v++)
    if (m->vertOwned[v]) {
      PetscInt r = c->gid[v] - rstart;
      PetscCheck(r >= 0 && r < nown, PETSC_COMM_SELF, PETSC_ERR_PLIB, "bs_willmore: owned vertex %" PetscInt_FMT " has global number %" PetscInt_FMT " outside the local range", v, c->gid[v]);
      /* FREE: beta_3 at a boundary neighbour couples v to the next-but-one boundary vertex on each side */
      c->nnz[r] = PetscMin(1 + 2 * (PetscInt)PetscRealPart(s.a[v]) + (c->freebd && m->vertBoundary[v] ? 2 : 0), m->Nv);
    }
  PetscCall(CSLocalSumEnd(&s, NULL));
  PetscFunctionReturn(0);
}

/* Fixed set, edge weights, the diamonds' far vertices from the mesh adjacency (global numbers, fixed flags),
   boundary neighbours (FREE), preallocation of K. Collective. */
static PetscErrorCode BSSetUp(CSEnergy en)
{
  BSCtx   *c = (BSCtx *)en->ctx;
  CSMesh   m = en->mesh;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetAdjacency(m, &c->adj));
  c->gid = c->adj->vertGlobal;
  PetscCall(BSFixedSet(en));
  /* W = sum of W_i over the vertices that carry one: all of them (+ one infinity vertex per boundary loop)
     in FREE mode, the non-boundary ones in FIXED mode */
  PetscCall(DMCreateGlobalVector(m->dmV1, &c->Wg));

  /* edge multiplicities */
  PetscCall(PetscMalloc1(m->ne, &c->wEdge));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt i = m->edgeVert[2 * e], j = m->edgeVert[2 * e + 1];
    if (c->bc == CS_BS_BOUNDARY_FREE) c->wEdge[e] = 2;
    else c->wEdge[e] = (PetscReal)(!m->vertBoundary[i]) + (PetscReal)(!m->vertBoundary[j]);
  }

  PetscCall(CSMeshCreateFieldDM(m->dm, 1, 6, "bs_edge6", &c->dmE6));
  PetscCall(BSOppositeFixed(en));

  if (c->freebd) {
    PetscCheck(c->adj->bdManifold, m->comm, PETSC_ERR_PLIB, "bs_willmore: some boundary vertices do not have one incoming and one outgoing boundary edge");
    PetscCall(CSMeshCreateFieldDM(m->dm, 0, 6, "bs_vert6", &c->dmV6));
  }
  PetscCall(BSPreallocation(en));
  PetscCall(PetscMalloc3(6 * m->ne, &c->gkl, 8 * m->ne, &c->Mkl, m->ne, &c->act));
  PetscCall(PetscMalloc1(m->ne, &c->both));
  for (PetscInt e = 0; e < m->ne; e++) c->both[e] = (PetscBool)(c->adj->edgeFace[2 * e] >= 0 && c->adj->edgeFace[2 * e + 1] >= 0 && m->edgeOwned[e]);
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------- evaluation */
/* Per-evaluation arrays: local positions, the far diamond vertices per edge side (dmE6) and the boundary
   neighbours (dmV6, FREE), the local gradient (NULL: not wanted) and W_i; K may be NULL. */
typedef struct {
  const PetscReal *p;
  PetscScalar     *ea, *va, *ga, *wa;
  Mat              K;
  PetscReal        Winf; /* W of the vertices at infinity (FREE), this rank's part */
} BSEval;

/* Interior edges: beta_1 of Sec. 3.1; the edge owner adds the value and the rows of i and j (and of k and l
   when both faces are here); otherwise the rows of k and l wait in gkl/Mkl for BSOppositeRows. */
static PetscErrorCode BSInteriorEdges(BSCtx *c, CSMesh m, BSEval *E)
{
  const PetscReal *p = E->p;
  PetscScalar     *ea = E->ea, *ga = E->ga, *wa = E->wa;
  Mat              K = E->K;
  PetscFunctionBeginUser;
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt         i = m->edgeVert[2 * e], j = m->edgeVert[2 * e + 1];
    const PetscReal *P[4];
    PetscReal        beta, M[4][4], w = c->wEdge[e];
    PetscBool        active;
    c->act[e] = PETSC_FALSE;
    if (m->edgeBoundary[e]) continue;
    P[0] = ea + 6 * e + 3; /* k: opposite in t_jik (side 1) */
    P[1] = p + 3 * j;
    P[2] = ea + 6 * e; /* l: opposite in t_ijl (side 0) */
    P[3] = p + 3 * i;
    CSBSDiamond(P, c->eps, &beta, (ga || K) ? M : NULL, &active);
    if (m->edgeOwned[e]) {
      wa[i] += beta;
      wa[j] += beta;
    }
    c->act[e] = active;
    if (w == 0) continue;
    if (ga && active) {
      for (int d = 0; d < 3; d++) {
        PetscReal gr[4] = {0, 0, 0, 0};
        for (int r = 0; r < 4; r++)
          for (int q = 0; q < 4; q++) gr[r] += M[r][q] * P[q][d];
        if (m->edgeOwned[e]) {
          if (!c->fixed[i]) ga[3 * i + d] += w * gr[3];
          if (!c->fixed[j]) ga[3 * j + d] += w * gr[1];
        }
        if (c->both[e]) { /* k and l are local: add their rows here */
          PetscInt vk = c->adj->edgeOpp[2 * e + 1], vl = c->adj->edgeOpp[2 * e];
          if (!c->fixed[vl]) ga[3 * vl + d] += w * gr[2];
          if (!c->fixed[vk]) ga[3 * vk + d] += w * gr[0];
        } else {
          c->gkl[6 * e + d]     = w * gr[2]; /* side 0: l */
          c->gkl[6 * e + 3 + d] = w * gr[0]; /* side 1: k */
        }
      }
    }
    if (K && active && PetscSinReal(beta) < c->epsK) /* near-kink diamond: keep its gradient, drop it from K */
      for (int r = 0; r < 4; r++)
        for (int q = 0; q < 4; q++) M[r][q] = 0;
    if (K) {
      PetscInt    cols[4] = {c->adj->edgeOppGlobal[2 * e + 1], c->gid[j], c->adj->edgeOppGlobal[2 * e], c->gid[i]};
      PetscBool   cfix[4] = {(PetscBool)c->oppFixed[2 * e + 1], c->fixed[j], (PetscBool)c->oppFixed[2 * e], c->fixed[i]};
      PetscScalar vals[4];
      for (int q = 0; q < 4; q++) {
        c->Mkl[8 * e + q]     = cfix[q] ? 0 : w * M[2][q];
        c->Mkl[8 * e + 4 + q] = cfix[q] ? 0 : w * M[0][q];
      }
      if (c->both[e]) { /* the whole 4 x 4 block at once (fixed rows get zeros: entries inside the 1-ring with flaps) */
        PetscScalar blk[16];
        for (int r = 0; r < 4; r++)
          for (int q = 0; q < 4; q++) blk[4 * r + q] = (cfix[r] || cfix[q]) ? 0 : w * M[r][q];
        PetscCall(MatSetValues(K, 4, cols, 4, cols, blk, ADD_VALUES));
      } else if (m->edgeOwned[e]) {
        const int rows[2] = {3, 1};
        for (int r = 0; r < 2; r++) {
          if (cfix[rows[r]]) continue;
          for (int q = 0; q < 4; q++) vals[q] = cfix[q] ? 0 : w * M[rows[r]][q];
          PetscCall(MatSetValues(K, 1, &cols[rows[r]], 4, cols, vals, ADD_VALUES));
        }
      }
    }
  }
  PetscFunctionReturn(0);
}

/* The rows of the opposite vertices k, l of diamonds split over two ranks: added by the rank of their face. */
static PetscErrorCode BSOppositeRows(BSCtx *c, CSMesh m, BSEval *E)
{
  PetscScalar     *ga = E->ga;
  Mat              K = E->K;
  PetscFunctionBeginUser;
  CSFaceIter F = CS_FACE_ITER_INIT;
  while (CSMeshFaceNext(m, NULL, &F))
    for (int k = 0; k < 3; k++) {
      PetscInt e = F.e[k], o = F.v[k];
      int      s = CSMeshEdgeSide(m, &F, k);
      if (m->edgeBoundary[e] || c->both[e] || c->fixed[o] || c->wEdge[e] == 0) continue;
      if (ga && c->act[e])
        for (int d = 0; d < 3; d++) ga[3 * o + d] += c->gkl[6 * e + 3 * s + d];
      if (K) {
        PetscInt    cols[4] = {c->adj->edgeOppGlobal[2 * e + 1], c->gid[m->edgeVert[2 * e + 1]], c->adj->edgeOppGlobal[2 * e], c->gid[m->edgeVert[2 * e]]};
        PetscScalar vals[4];
        for (int q = 0; q < 4; q++) vals[q] = c->Mkl[8 * e + 4 * s + q];
        PetscCall(MatSetValues(K, 1, &c->gid[o], 4, cols, vals, ADD_VALUES));
      }
    }
  PetscFunctionReturn(0);
}

  /* free boundary (Sec. 3.3): beta_2 = pi - (angle opposite the boundary edge), beta_3 = pi - (angle of the
     boundary polygon at v_b) = the intersection angle of the two boundary lines through v_b and infinity.
     Both are limits of the diamond formula with one vertex sent to infinity (cos beta -> <D,A> resp. <C,D>).
     Each appears at two vertices of the closed surface (for beta_3: v_b and infinity), hence weight 2.
   This rank adds beta_2 of the boundary edges of its faces and the rows of beta_3 at their ends. */
static PetscErrorCode BSFreeBoundaryFaces(BSCtx *c, CSMesh m, BSEval *E)
{
  const PetscReal *p = E->p;
  PetscScalar     *va = E->va, *ga = E->ga, *wa = E->wa;
  Mat              K = E->K;
  PetscFunctionBeginUser;
  CSFaceIter F = CS_FACE_ITER_INIT;
  while (CSMeshFaceNext(m, NULL, &F))
    for (int k = 0; k < 3; k++) {
      PetscInt         vk = F.v[k], i = F.v[(k + 1) % 3], j = F.v[(k + 2) % 3];
      const PetscReal *P[3];
      PetscReal        th, M[3][3];
      PetscBool        active;
      if (!m->edgeBoundary[F.e[k]]) continue;
      /* beta_2 of edge i -> j (the boundary edge is local on this rank only, and owned here) */
      P[0] = p + 3 * vk;
      P[1] = p + 3 * i;
      P[2] = p + 3 * j;
      BSAngle(P, c->eps, &th, M, &active);
      wa[i] += PETSC_PI - th;
      wa[j] += PETSC_PI - th;
      {
        PetscInt idx[3] = {vk, i, j};
        if (ga && active)
          for (int r = 0; r < 3; r++)
            for (int d = 0; d < 3; d++)
              for (int q = 0; q < 3; q++) ga[3 * idx[r] + d] -= 2 * M[r][q] * P[q][d];
        if (K) {
          PetscInt    cols[3] = {c->gid[vk], c->gid[i], c->gid[j]};
          PetscScalar vals[9];
          for (int r = 0; r < 3; r++)
            for (int q = 0; q < 3; q++) vals[3 * r + q] = -2 * M[r][q];
          PetscCall(MatSetValues(K, 3, cols, 3, cols, vals, ADD_VALUES));
        }
      }
      /* beta_3 at i (prev(i), i, j): this rank adds the row of j; at j (i, j, next(j)): the row of i */
      for (int t = 0; t < 2; t++) {
        PetscInt         b = t ? j : i, other = t ? i : j;
        PetscInt         cols[3];
        const PetscReal *Q[3];
        PetscScalar      vals[3];
        int              ro = 0;
        Q[0]    = p + 3 * b;
        cols[0] = c->gid[b];
        if (!t) { /* b = i: prev(i) (slot 0), next = j */
          Q[1]    = va + 6 * i;
          cols[1] = c->adj->bdPrevGlobal[i];
          Q[2]    = p + 3 * j;
          cols[2] = c->gid[j];
          ro      = 2;
        } else { /* b = j: prev = i, next(j) (slot 1) */
          Q[1]    = p + 3 * i;
          cols[1] = c->gid[i];
          Q[2]    = va + 6 * j + 3;
          cols[2] = c->adj->bdNextGlobal[j];
          ro      = 1;
        }
        BSAngle(Q, c->eps, &th, M, &active);
        if (ga && active)
          for (int d = 0; d < 3; d++)
            for (int q = 0; q < 3; q++) ga[3 * other + d] -= 2 * M[ro][q] * Q[q][d];
        if (K) {
          for (int q = 0; q < 3; q++) vals[q] = -2 * M[ro][q];
          PetscCall(MatSetValues(K, 1, &cols[ro], 3, cols, vals, ADD_VALUES));
        }
      }
    }
  PetscFunctionReturn(0);
}

/* beta_3 value and the row of v_b itself: the owner of v_b. */
static PetscErrorCode BSFreeBoundaryVertices(BSCtx *c, CSMesh m, BSEval *E)
{
  const PetscReal *p = E->p;
  PetscScalar     *va = E->va, *ga = E->ga, *wa = E->wa;
  Mat              K = E->K;
  PetscFunctionBeginUser;
  for (PetscInt b = 0; b < m->nv; b++) {
    const PetscReal *Q[3];
    PetscReal        th, M[3][3];
    PetscBool        active;
    if (!m->vertBoundary[b] || !m->vertOwned[b]) continue;
    Q[0] = p + 3 * b;
    Q[1] = va + 6 * b;
    Q[2] = va + 6 * b + 3;
    BSAngle(Q, c->eps, &th, M, &active);
    wa[b] += PETSC_PI - th;
    E->Winf += PETSC_PI - th; /* W of the vertex at infinity: sum of its beta_3 - 2 pi per loop */
    if (ga && active)
      for (int d = 0; d < 3; d++)
        for (int q = 0; q < 3; q++) ga[3 * b + d] -= 2 * M[0][q] * Q[q][d];
    if (K) {
      PetscInt    cols[3] = {c->gid[b], c->adj->bdPrevGlobal[b], c->adj->bdNextGlobal[b]};
      PetscScalar vals[3];
      for (int q = 0; q < 3; q++) vals[q] = -2 * M[0][q];
      PetscCall(MatSetValues(K, 1, &cols[0], 3, cols, vals, ADD_VALUES));
    }
  }
  PetscFunctionReturn(0);
}

/* Sec. 3.2, one vanishing beta: tangent t at P[r] of the circle through the diamond (P[r] and its diamond
   neighbours P[r+1], P[r+3]) and the rate R at which beta grows for a unit move orthogonal to it (equal in all
   orthogonal directions; measured along the normal of the circle's plane, beta(h)/h with h = 1e-4 |edge|). */
static void SingularData(const PetscReal *const P[4], int r, PetscReal h, PetscReal t[3], PetscReal *R)
{
  PetscReal a[3], b[3], n[3], u[3], v[3], o[3], q[3], beta, nn;
  const PetscReal *Q[4] = {P[0], P[1], P[2], P[3]};
  PetscBool active;
  CSVecSub(P[(r + 1) % 4], P[r], a);
  CSVecSub(P[(r + 3) % 4], P[r], b);
  CSVecCross(a, b, n);
  nn = CSVecNorm(n);
  for (int d = 0; d < 3; d++) {
    u[d] = CSVecDot(a, a) * b[d] - CSVecDot(b, b) * a[d];
    n[d] /= nn;
  }
  CSVecCross(u, n, v); /* (|a|^2 b - |b|^2 a) x (a x b) / (2 |a x b|^2): the centre - P[r] */
  for (int d = 0; d < 3; d++) o[d] = v[d] / (2 * nn);
  CSVecCross(n, o, t);
  nn = CSVecNorm(t);
  for (int d = 0; d < 3; d++) {
    t[d] /= nn;
    q[d] = P[r][d] + h * n[d];
  }
  Q[r] = q;
  CSBSDiamond(Q, 0, &beta, NULL, &active);
  *R = beta / h;
}

/* The vanishing betas of the gradient's support per vertex, as lists (Sec. 3.2): each local vertex gets a block
   [count, (t_n, w R_n) x CS_BS_SINGULAR_MAX] of the diamonds this rank counts (i, j: the edge owner; k, l: the
   rank of their face), so every (diamond, vertex) pair is in exactly one block. */
static PetscErrorCode BSSingularLists(BSCtx *c, CSMesh m, const PetscReal *p, const PetscScalar *ea, PetscReal *L)
{
  const PetscInt unit = 1 + 4 * CS_BS_SINGULAR_MAX;
  PetscFunctionBeginUser;
  PetscCall(PetscArrayzero(L, unit * m->nv));
  for (PetscInt e = 0; e < m->ne; e++) {
    PetscInt         i = m->edgeVert[2 * e], j = m->edgeVert[2 * e + 1], vtx[4];
    PetscBool        mine[4];
    const PetscReal *P[4];
    PetscReal        h, dij[3];
    if (m->edgeBoundary[e] || c->act[e] || c->wEdge[e] == 0) continue;
    P[0] = ea + 6 * e + 3; P[1] = p + 3 * j; P[2] = ea + 6 * e; P[3] = p + 3 * i;
    vtx[0] = c->adj->edgeOpp[2 * e + 1]; vtx[1] = j; vtx[2] = c->adj->edgeOpp[2 * e]; vtx[3] = i;
    mine[0] = (PetscBool)(c->adj->edgeFace[2 * e + 1] >= 0); mine[2] = (PetscBool)(c->adj->edgeFace[2 * e] >= 0);
    mine[1] = mine[3] = m->edgeOwned[e];
    CSVecSub(P[1], P[3], dij);
    h = 1e-4 * CSVecNorm(dij);
    for (int r = 0; r < 4; r++) {
      PetscReal *b = L + unit * vtx[r], R;
      PetscInt   n = (PetscInt)b[0];
      if (!mine[r] || c->fixed[vtx[r]]) continue;
      PetscCheck(n < CS_BS_SINGULAR_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "bs -singular: more than %d vanishing betas at one vertex", CS_BS_SINGULAR_MAX);
      SingularData(P, r, h, b + 1 + 4 * n, &R);
      b[1 + 4 * n + 3] = c->wEdge[e] * R;
      b[0] += 1;
    }
  }
  PetscFunctionReturn(0);
}

/* Sec. 3.2 at one vertex from its n vanishing betas (t, w R in blocks of 4); dn the regular negative gradient,
   replaced by the direction of the rule (see cs_energy_bs.h). */
static PetscErrorCode BSSingularVertex(CSBSSingular rule, PetscInt n, const PetscReal *tr, PetscReal dn[3])
{
  PetscReal t[3 * CS_BS_SINGULAR_MAX], R[CS_BS_SINGULAR_MAX], d[3];
  PetscFunctionBeginUser;
  if (n == 0 || (rule == CS_BS_SINGULAR_SINGLE && n > 1)) PetscFunctionReturn(0); /* the heuristic's direction */
  for (PetscInt k = 0; k < n; k++) {
    for (int q = 0; q < 3; q++) t[3 * k + q] = tr[4 * k + q];
    R[k] = tr[4 * k + 3];
  }
  if (rule == CS_BS_SINGULAR_SINGLE) { /* the paper's closed form for one: g_p if R > |g_o|, else g_p + g_o (1 - R/|g_o|) */
    PetscReal dp = CSVecDot(dn, t), dO[3], no, f;
    for (int q = 0; q < 3; q++) dO[q] = dn[q] - dp * t[q];
    no = CSVecNorm(dO);
    f  = no > R[0] ? 1 - R[0] / no : 0;
    for (int q = 0; q < 3; q++) d[q] = dp * t[q] + f * dO[q];
  } else PetscCall(CSBSSingularDescent(dn, n, t, R, d, NULL));
  for (int q = 0; q < 3; q++) dn[q] = d[q];
  PetscFunctionReturn(0);
}

/* Sec. 3.2 "Gradient Singularity" (rules single and delta): the lists of every copy of a vertex are gathered on its
   owner through the dmV1 section SF (one block per copy), then the vertex's direction replaces its gradient. */
static PetscErrorCode BSSingularRule(BSCtx *c, CSMesh m, const PetscReal *p, const PetscScalar *ea, Vec g)
{
  const PetscInt unit = 1 + 4 * CS_BS_SINGULAR_MAX;
  PetscSF        sf;
  MPI_Datatype   blk;
  const PetscInt *deg;
  PetscInt       nroots, nmulti = 0, off = 0, k = 0, cnt[3] = {0, 0, 0}; /* vertices with one, several, d = 0 */
  PetscReal     *L, *G;
  PetscScalar   *ga;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(unit * m->nv, &L));
  PetscCall(BSSingularLists(c, m, p, ea, L));
  PetscCall(DMGetSectionSF(m->dmV1, &sf));
  PetscCall(PetscSFGetGraph(sf, &nroots, NULL, NULL, NULL));
  PetscCall(PetscSFComputeDegreeBegin(sf, &deg));
  PetscCall(PetscSFComputeDegreeEnd(sf, &deg));
  for (PetscInt r = 0; r < nroots; r++) nmulti += deg[r];
  PetscCall(PetscMalloc1(unit * PetscMax(nmulti, 1), &G));
  PetscCallMPI(MPI_Type_contiguous((PetscMPIInt)unit, MPIU_REAL, &blk));
  PetscCallMPI(MPI_Type_commit(&blk));
  PetscCall(PetscSFGatherBegin(sf, blk, L, G));
  PetscCall(PetscSFGatherEnd(sf, blk, L, G));
  PetscCallMPI(MPI_Type_free(&blk));
  PetscCall(VecGetArray(g, &ga));
  for (PetscInt r = 0; r < nroots; r++, k++) {
    PetscReal tr[4 * CS_BS_SINGULAR_MAX], dn[3];
    PetscInt  n = 0;
    for (PetscInt b = 0; b < deg[r]; b++, off++) { /* the copies' lists, one after the other */
      const PetscReal *B = G + unit * off;
      PetscCheck(n + (PetscInt)B[0] <= CS_BS_SINGULAR_MAX, PETSC_COMM_SELF, PETSC_ERR_SUP, "bs -singular: more than %d vanishing betas at one vertex", CS_BS_SINGULAR_MAX);
      PetscCall(PetscArraycpy(tr + 4 * n, B + 1, 4 * (PetscInt)B[0]));
      n += (PetscInt)B[0];
    }
    for (int q = 0; q < 3; q++) dn[q] = -PetscRealPart(ga[3 * k + q]); /* the regular negative gradient */
    PetscCall(BSSingularVertex(c->rule, n, tr, dn));
    for (int q = 0; q < 3; q++) ga[3 * k + q] = -dn[q];
    if (n) cnt[n > 1]++;
    if (n && CSVecNorm(dn) == 0) cnt[2]++;
  }
  PetscCall(PetscInfo(NULL, "bs -singular %s: owned vertices with one vanishing beta %" PetscInt_FMT ", several %" PetscInt_FMT ", zero direction %" PetscInt_FMT "\n", CSBSSingularRules[c->rule], cnt[0], cnt[1], cnt[2]));
  PetscCall(VecRestoreArray(g, &ga));
  PetscCall(PetscFree(G));
  PetscCall(PetscFree(L));
  PetscFunctionReturn(0);
}

/* One pass: W (always), per-vertex W_i (Wv, dmV1 global, may be NULL), gradient (g, dmV3 global, may be
   NULL), K (may be NULL, already zeroed and preallocated; assembled here with fixdiag on fixed rows). */
static PetscErrorCode BSEvaluate(CSEnergy en, Vec x, PetscReal *Wout, Vec Wv, Vec g, Mat K, PetscReal fixdiag)
{
  BSCtx             *c = (BSCtx *)en->ctx;
  CSMesh             m = en->mesh;
  Vec                xl;
  CSLocalSum         es, vs = {NULL, NULL, NULL}, gs = {NULL, NULL, NULL}, ws;
  const PetscReal   *p;
  BSEval             E = {NULL, NULL, NULL, NULL, NULL, K, 0};
  PetscReal          Wloc = 0, Wsum;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(m, x, &xl, &p));
  /* diamonds: opposite positions per edge side, written by the rank of that side's face */
  PetscCall(CSLocalSumBegin(c->dmE6, &es));
  for (PetscInt k = 0; k < 2 * m->ne; k++)
    if (c->adj->edgeFace[k] >= 0)
      for (int d = 0; d < 3; d++) es.a[3 * k + d] = p[3 * c->adj->edgeOpp[k] + d];
  PetscCall(CSLocalSumShare(&es));
  E.ea = es.a;
  if (c->freebd) { /* boundary neighbours' positions, written by the rank of the boundary edge's face */
    CSFaceIter F = CS_FACE_ITER_INIT;
    PetscCall(CSLocalSumBegin(c->dmV6, &vs));
    while (CSMeshFaceNext(m, NULL, &F))
      for (int k = 0; k < 3; k++) {
        PetscInt i = F.v[(k + 1) % 3], j = F.v[(k + 2) % 3];
        if (!m->edgeBoundary[F.e[k]]) continue;
        for (int d = 0; d < 3; d++) {
          vs.a[6 * i + 3 + d] = p[3 * j + d];
          vs.a[6 * j + d]     = p[3 * i + d];
        }
      }
    PetscCall(CSLocalSumShare(&vs));
    E.va = vs.a;
  }
  if (g) {
    PetscCall(CSLocalSumBegin(m->dmV3, &gs));
    E.ga = gs.a;
  }
  /* W is summed as sum_i W_i (each W_i = sum beta - 2 pi is small near a minimum), not as 2 sum_e beta - 2 pi V,
     whose cancellation loses ~1e-11 on a few thousand vertices */
  PetscCall(CSLocalSumBegin(m->dmV1, &ws));
  E.wa = ws.a;
  E.p  = p;
  PetscCall(BSInteriorEdges(c, m, &E));
  if (E.ga || K) PetscCall(BSOppositeRows(c, m, &E));
  if (c->freebd) {
    PetscCall(BSFreeBoundaryFaces(c, m, &E));
    PetscCall(BSFreeBoundaryVertices(c, m, &E));
    PetscCall(CSLocalSumEnd(&vs, NULL));
  }
  if (g) PetscCall(CSLocalSumEnd(&gs, g));
  if (g && c->rule != CS_BS_SINGULAR_HEURISTIC) PetscCall(BSSingularRule(c, m, p, es.a, g));
  PetscCall(CSLocalSumEnd(&es, NULL));
  PetscCall(CSMeshRestoreLocalPositions(m, x, &xl, &p));
  {
    PetscScalar *w;
    PetscInt     n = 0;
    Vec          Wg = Wv ? Wv : c->Wg;
    PetscCall(CSLocalSumEnd(&ws, Wg));
    PetscCall(VecGetArray(Wg, &w));
    for (PetscInt v = 0; v < m->nv; v++) {
      if (!m->vertOwned[v]) continue;
      if (c->bc == CS_BS_BOUNDARY_FIXED && m->vertBoundary[v]) w[n] = 0; /* W_i undefined there (Sec. 3.3) */
      else w[n] -= 2 * PETSC_PI;
      Wloc += PetscRealPart(w[n]);
      n++;
    }
    PetscCall(VecRestoreArray(Wg, &w));
    Wloc += E.Winf;
    PetscCall(MPIU_Allreduce(&Wloc, &Wsum, 1, MPIU_REAL, MPIU_SUM, m->comm));
    if (Wout) *Wout = Wsum - (c->freebd ? 2 * PETSC_PI * (PetscReal)m->topo.boundary_loops : 0);
  }
  if (K) {
    for (PetscInt v = 0; v < m->nv; v++)
      if (m->vertOwned[v] && c->fixed[v]) PetscCall(MatSetValue(K, c->gid[v], c->gid[v], fixdiag, ADD_VALUES));
    PetscCall(MatAssemblyBegin(K, MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(K, MAT_FINAL_ASSEMBLY));
  }
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------- interface */
static PetscErrorCode BSValue(CSEnergy e, Vec x, PetscReal *W)
{
  PetscFunctionBeginUser;
  PetscCall(BSEvaluate(e, x, W, NULL, NULL, NULL, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode BSGradient(CSEnergy e, Vec x, PetscReal *W, Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(BSEvaluate(e, x, W, NULL, g, NULL, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode BSDestroy(CSEnergy e)
{
  BSCtx *c = (BSCtx *)e->ctx;
  PetscFunctionBeginUser;
  PetscCall(DMDestroy(&c->dmE6));
  PetscCall(VecDestroy(&c->Wg));
  PetscCall(DMDestroy(&c->dmV6));
  PetscCall(PetscFree(c->oppFixed));
  PetscCall(PetscFree(c->fixed));
  PetscCall(PetscFree(c->islands));
  PetscCall(PetscFree(c->wEdge));
  PetscCall(PetscFree(c->nnz));
  PetscCall(PetscFree3(c->gkl, c->Mkl, c->act));
  PetscCall(PetscFree(c->both));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyCreateWillmoreBS(CSMesh mesh, CSBSBoundary bc, PetscReal beta_eps, CSEnergy *e)
{
  BSCtx *c;
  PetscFunctionBeginUser;
  PetscCheck(beta_eps >= 0 && beta_eps < 1, mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "-bs_beta_eps %g: must lie in [0, 1)", (double)beta_eps);
  PetscCall(CSEnergyCreateShell(mesh, "willmore_bs", e));
  PetscCall(PetscNew(&c));
  c->bc          = bc;
  c->eps         = beta_eps;
  c->epsK        = beta_eps;
  (*e)->ctx      = c;
  (*e)->value    = BSValue;
  (*e)->gradient = BSGradient;
  (*e)->destroy  = BSDestroy;
  PetscCall(BSSetUp(*e));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyWillmoreBSVertex(CSEnergy e, Vec x, Vec Wv, PetscReal *W)
{
  PetscReal Wt;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Energy, 0, 0, 0, 0));
  PetscCall(BSEvaluate(e, x, &Wt, Wv, NULL, NULL, 0));
  PetscCall(PetscLogEventEnd(CS_EVENT_Energy, 0, 0, 0, 0));
  if (W) *W = Wt;
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyWillmoreBSSetIslands(CSEnergy e, Vec vmask)
{
  BSCtx             *c = (BSCtx *)e->ctx;
  CSMesh             m = e->mesh;
  Vec                l;
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(PetscFree(c->islands));
  PetscCall(PetscCalloc1(m->nv, &c->islands));
  PetscCall(DMGetLocalVector(m->dmV1, &l));
  PetscCall(DMGlobalToLocal(m->dmV1, vmask, INSERT_VALUES, l)); /* ghost copies too: their rings cross the cut */
  PetscCall(VecGetArrayRead(l, &a));
  for (PetscInt v = 0; v < m->nv; v++) c->islands[v] = (PetscBool)(PetscRealPart(a[v]) > 0.5);
  PetscCall(VecRestoreArrayRead(l, &a));
  PetscCall(DMRestoreLocalVector(m->dmV1, &l));
  PetscCall(BSFixedSet(e));
  PetscCall(BSOppositeFixed(e));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyWillmoreBSSetSingularRule(CSEnergy e, CSBSSingular rule)
{
  PetscFunctionBeginUser;
  ((BSCtx *)e->ctx)->rule = rule;
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyWillmoreBSGetFixed(CSEnergy e, const PetscBool **fixed, PetscInt *nfixed)
{
  BSCtx *c = (BSCtx *)e->ctx;
  PetscFunctionBeginUser;
  if (fixed) *fixed = c->fixed;
  if (nfixed) *nfixed = c->nfixed;
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyWillmoreBSHessian(CSEnergy e, Vec x, PetscReal fixdiag, MatReuse reuse, Mat *K, PetscReal *W, Vec g)
{
  BSCtx   *c = (BSCtx *)e->ctx;
  CSMesh   m = e->mesh;
  PetscReal Wt;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) {
    Vec      v;
    PetscInt n;
    PetscCall(DMGetGlobalVector(m->dmV1, &v));
    PetscCall(VecGetLocalSize(v, &n));
    PetscCall(DMRestoreGlobalVector(m->dmV1, &v));
    PetscCall(MatCreate(m->comm, K));
    PetscCall(MatSetSizes(*K, n, n, m->Nv, m->Nv));
    PetscCall(MatSetType(*K, MATAIJ));
    PetscCall(MatSeqAIJSetPreallocation(*K, 0, c->nnz));
    PetscCall(MatMPIAIJSetPreallocation(*K, 0, c->nnz, 0, c->nnz));
    PetscCall(MatSetOption(*K, MAT_IGNORE_ZERO_ENTRIES, PETSC_FALSE));
  } else PetscCall(MatZeroEntries(*K));
  PetscCall(BSEvaluate(e, x, &Wt, NULL, g, *K, fixdiag));
  if (W) *W = Wt;
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSEnergyWillmoreBSSetHessianEps(CSEnergy e, PetscReal eps)
{
  BSCtx *c = (BSCtx *)e->ctx;
  PetscFunctionBeginUser;
  c->epsK = eps;
  PetscFunctionReturn(0);
}
