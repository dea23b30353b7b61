/* PC type "cssubchol": direct solve of a distributed sparse SPD matrix S by substructuring, with CHOLMOD on
   every rank and one dense Schur complement on the interface.

   Why: the 2-rank MUMPS factorisation of the flow's Schur complement (PORD ordering: Debian's MUMPS has no
   METIS/SCOTCH) is no faster than serial CHOLMOD with METIS, so 2 ranks gained nothing (issue 3). Splitting the
   unknowns by the mesh partition lets each rank factor its own half with CHOLMOD + METIS at full speed.

   The split. Each dof belongs to the rank that owns its row. The interface Gamma is the set of dofs that are
   coupled (S_ij stored in row i or in row j) to a dof of a higher rank (or, whichever makes the largest local
   matrix smaller, of a lower rank); what remains on rank p, its interior I_p, is coupled only to I_p and Gamma,
   never to another rank's interior. Rank p factors its local matrix
       A_p = [ S(I_p, I_p)  S(I_p, G_p) ]      G_p = the interface dofs coupled to I_p, and its own,
             [ S(G_p, I_p)  S(G_p, G_p) ]
   (a principal submatrix of S, hence SPD) with G_p ordered after I_p (METIS on I_p). Its interface block is the
   local Schur complement T_p = S(G_p,G_p) - C_p, C_p = S(G_p,I_p) S(I_p,I_p)^{-1} S(I_p,G_p): CHOLMOD factors the
   whole local matrix, and T_p = L_GG L_GG^T is multiplied back from the factor's interface block (LAPACK dlauum).
   The Schur complement of S on the interface is
       S_Gamma = S(Gamma, Gamma) - sum_p C_p,
   a dense matrix of the interface size, summed over ranks (MPI_Allreduce) and factored redundantly (LAPACK).
   The local factor's interface block is then set to the identity, L = [L_II 0; L_GI I], so a solve S x = b is:
   y_p = L^{-1} [b_I; 0] on each rank (its interface part is -L_GI y_I = -S(G,I) S(I,I)^{-1} b_I),
   x_Gamma = S_Gamma^{-1} (b_Gamma + sum_p y_G), and x_I = L^{-T} [y_I; x_G] on each rank.
   All interface couplings stay correct under CHOLMOD's postordering: G_p is closed upwards in the elimination
   tree (it is ordered last), so L(I,G) = 0 even where the postorder puts an interface column before interior ones.
   Errors: a failure on one rank (CHOLMOD, a matrix that is not positive definite) is agreed on by all ranks before
   the next collective call (CSSyncError), so every rank raises the error or reports PC_FACTOR_NUMERIC_ZEROPIVOT
   together.

   Cost and measurements (the interface size, flops, the cost of multiplying T_p back): docs/solvers.md. The
   interface is redundant on every rank, so this is meant for a few ranks; on one rank it is a plain CHOLMOD
   factorisation. The symbolic phase (split, METIS, CHOLMOD analysis) is kept while the nonzero pattern stays. */
#include <petsc/private/pcimpl.h> /* a PC type of our own (PCRegister) */
#include <petscblaslapack.h>
#include <suitesparse/cholmod.h>
#include "cs_substructured_cholesky.h"
#include "cs_cholmod.h"
#include "cs_util.h"
#include "cs_linalg.h"

/* LAPACK: U U^T of an upper triangular U (not wrapped by PETSc) */
extern void dlauum_(const char *, const PetscBLASInt *, PetscScalar *, const PetscBLASInt *, PetscBLASInt *);

enum { ORDER_METIS, ORDER_AMD, ORDER_NESDIS };
static const char *const OrderingNames[] = {"metis", "amd", "nesdis"};
enum { SIDE_AUTO, SIDE_LOWER, SIDE_UPPER };
static const char *const SideNames[] = {"auto", "lower", "upper"};

typedef struct {
  PetscInt        ordering; /* of the interior: ORDER_* */
  cholmod_common  c;
  PetscBool       started;
  cholmod_sparse *A; /* local matrix, upper part used (stype 1) */
  cholmod_factor *L;
  cholmod_dense  *v, *t1, *t2, *Yw, *Ew; /* solve vectors and cholmod_solve2 workspace, kept */
  Mat            *sub;   /* the local matrix as SeqAIJ (MatCreateSubMatrices) */
  IS              isloc; /* global indices of the local dofs, ascending */
  PetscInt        m;     /* local dofs */
  PetscLogDouble  fl, lnz; /* CHOLMOD's flop count of the local factorisation and nonzeros of L (for -log_view) */
  PetscInt        own_off; /* the owned dofs are local dofs own_off, own_off + 1, ... */
  PetscInt        side;    /* the interface is on the lower (0) or upper (1) side of each cut */
  PetscInt        side_opt; /* SIDE_* (-pc_cssubchol_interface) */
  PetscInt        G;     /* interface dofs, all ranks */
  PetscInt       *gidx;  /* their global indices, ascending */
  PetscInt        gp;    /* interface dofs of the local matrix */
  PetscInt       *gpos;  /* their positions in the factor's (permuted) order, ascending */
  PetscInt       *gglob; /* their interface numbers (0..G-1), in that order */
  PetscInt       *gloc;  /* their local numbers (0..m-1), in that order */
  PetscInt        nfact; /* numeric factorisations, for -ksp_view */
  PetscScalar    *SG;    /* G x G: Cholesky factor of S_Gamma */
  PetscScalar    *pack;  /* G (G + 1) / 2: the lower triangle of S_Gamma, for the reduction */
  PetscScalar    *rG;    /* G: interface vector */
  PetscInt        nown;    /* owned rows */
  PetscInt       *own_loc; /* for each: local number, or -1 - (interface number) on the interface */
  VecScatter      scat;    /* global -> local dofs */
  Vec             bloc;
  PetscReal       max_ratio; /* -pc_cssubchol_max_interface_ratio: dense interface / largest local factor, in bytes */
  PetscReal       fits_mb;   /* -pc_cssubchol_fits_mb: a dense interface of at most this many MB per rank always fits */
  PC              fallback;  /* MUMPS Cholesky, where the dense interface does not fit (ChooseEngine) */
  PetscInt        Gseen, gpmax; /* the interface (all ranks, and the largest local part) of the last split */
  PetscLogDouble  dense_mb, factor_mb; /* its dense storage per rank, the largest local sparse factor */
} PC_SubChol;

static PetscErrorCode CholCheck(cholmod_common *c, const char *what)
{
  PetscFunctionBeginUser;
  PetscCheck(c->status >= CHOLMOD_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "cssubchol: CHOLMOD %s failed (status %d)", what, c->status);
  PetscFunctionReturn(0);
}

static PetscErrorCode ResetSymbolic(PC_SubChol *s)
{
  PetscFunctionBeginUser;
  if (s->started) {
    cholmod_free_sparse(&s->A, &s->c);
    cholmod_free_factor(&s->L, &s->c);
    cholmod_free_dense(&s->v, &s->c);
    cholmod_free_dense(&s->t1, &s->c);
    cholmod_free_dense(&s->t2, &s->c);
    cholmod_free_dense(&s->Yw, &s->c);
    cholmod_free_dense(&s->Ew, &s->c);
  }
  if (s->sub) PetscCall(MatDestroySubMatrices(1, &s->sub));
  PetscCall(ISDestroy(&s->isloc));
  PetscCall(PetscFree(s->gidx));
  PetscCall(PetscFree3(s->gpos, s->gglob, s->gloc));
  PetscCall(PetscFree(s->SG));
  PetscCall(PetscFree(s->pack));
  PetscCall(PetscFree(s->rG));
  PetscCall(PetscFree(s->own_loc));
  PetscCall(VecScatterDestroy(&s->scat));
  PetscCall(VecDestroy(&s->bloc));
  s->m = s->G = s->gp = s->nown = s->own_off = 0;
  PetscFunctionReturn(0);
}

/* Collective: the split (interface from the pattern), the local dofs, the local matrix and the scatter. */
static PetscErrorCode SetUpSplit(PC pc, PC_SubChol *s)
{
  Mat         S = pc->pmat;
  MPI_Comm    comm;
  PetscMPIInt size;
  PetscInt    rstart, rend, nown, *mine, nmine = 0, *extra, nextra = 0, n, cn;
  PetscBool   *isgam, aij;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)S, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  { /* AIJ with equal row and column layouts (every rank decides the same) */
    PetscMPIInt bad = 0, anybad;
    PetscCall(PetscObjectBaseTypeCompareAny((PetscObject)S, &aij, MATSEQAIJ, MATMPIAIJ, ""));
    PetscCall(MatGetLocalSize(S, &n, &cn));
    bad = (!aij || n != cn) ? 1 : 0;
    PetscCallMPI(MPI_Allreduce(&bad, &anybad, 1, MPI_INT, MPI_MAX, comm));
    PetscCheck(!anybad, comm, PETSC_ERR_SUP, "cssubchol: the matrix must be AIJ (Seq or MPI) with the same row and column layout");
  }
  PetscCall(MatGetOwnershipRange(S, &rstart, &rend));
  nown = rend - rstart;
  /* Two valid splits: the interface on the lower side of each cut (dofs coupled to a higher rank) or on the upper
     side (coupled to a lower rank). A coupling counts when stored in either row (one-sided patterns), hence the
     marks sent to the owners through vectors. The split with the smaller largest local matrix is taken: the
     interface adds its dofs to both sides of a cut, and the largest local factorisation sets the pace (level 6:
     3.08e10 vs 3.42e10 flops on the two ranks with the lower side). */
  {
    PetscBool *gam[2];
    PetscInt   next[2] = {0, 0}, *ext[2], caps[2] = {16, 16};
    Vec        f[2];
    PetscInt   mloc[2], mmax[2];
    PetscScalar one = 1;
    for (int side = 0; side < 2; side++) {
      PetscCall(PetscCalloc1(nown, &gam[side]));
      PetscCall(PetscMalloc1(caps[side], &ext[side]));
      PetscCall(MatCreateVecs(S, &f[side], NULL));
    }
    for (PetscInt i = rstart; i < rend; i++) { /* side 0: coupled to a higher rank; side 1: to a lower one */
      PetscInt        nc;
      const PetscInt *cols;
      PetscCall(MatGetRow(S, i, &nc, &cols, NULL));
      for (PetscInt k = 0; k < nc; k++) {
        if (cols[k] >= rend) {
          gam[0][i - rstart] = PETSC_TRUE;
          PetscCall(VecSetValues(f[1], 1, &cols[k], &one, ADD_VALUES));
        }
        if (cols[k] < rstart) {
          gam[1][i - rstart] = PETSC_TRUE;
          PetscCall(VecSetValues(f[0], 1, &cols[k], &one, ADD_VALUES));
        }
      }
      PetscCall(MatRestoreRow(S, i, &nc, &cols, NULL));
    }
    for (int side = 0; side < 2; side++) {
      const PetscScalar *fa;
      PetscCall(VecAssemblyBegin(f[side]));
      PetscCall(VecAssemblyEnd(f[side]));
      PetscCall(VecGetArrayRead(f[side], &fa));
      for (PetscInt i = 0; i < nown; i++)
        if (fa[i] != 0) gam[side][i] = PETSC_TRUE;
      PetscCall(VecRestoreArrayRead(f[side], &fa));
      PetscCall(VecDestroy(&f[side]));
    }
    /* the other ranks' dofs (all on the interface) coupled to interior rows */
    for (int side = 0; side < 2; side++) {
      for (PetscInt i = rstart; i < rend; i++) {
        PetscInt        nc;
        const PetscInt *cols;
        if (gam[side][i - rstart]) continue;
        PetscCall(MatGetRow(S, i, &nc, &cols, NULL));
        for (PetscInt k = 0; k < nc; k++) {
          if (cols[k] >= rstart && cols[k] < rend) continue;
          if (next[side] == caps[side]) {
            PetscInt *t;
            PetscCall(PetscMalloc1(2 * caps[side], &t));
            PetscCall(PetscArraycpy(t, ext[side], next[side]));
            PetscCall(PetscFree(ext[side]));
            ext[side] = t;
            caps[side] *= 2;
          }
          ext[side][next[side]++] = cols[k];
        }
        PetscCall(MatRestoreRow(S, i, &nc, &cols, NULL));
      }
      PetscCall(PetscSortRemoveDupsInt(&next[side], ext[side]));
      mloc[side] = nown + next[side];
    }
    PetscCallMPI(MPI_Allreduce(mloc, mmax, 2, MPIU_INT, MPI_MAX, comm));
    s->side = mmax[1] < mmax[0] ? 1 : 0;
    if (s->side_opt != SIDE_AUTO) s->side = s->side_opt == SIDE_UPPER ? 1 : 0;
    isgam   = gam[s->side];
    extra   = ext[s->side];
    nextra  = next[s->side];
    PetscCall(PetscFree(gam[1 - s->side]));
    PetscCall(PetscFree(ext[1 - s->side]));
  }
  /* the global interface list on every rank */
  {
    PetscMPIInt *counts, *displs, nm;
    PetscInt     G = 0;
    for (PetscInt i = 0; i < nown; i++) G += isgam[i];
    PetscCall(PetscMalloc1(G, &mine));
    for (PetscInt i = 0; i < nown; i++)
      if (isgam[i]) mine[nmine++] = rstart + i;
    PetscCall(PetscMPIIntCast(nmine, &nm));
    PetscCall(PetscMalloc2(size, &counts, size, &displs));
    PetscCallMPI(MPI_Allgather(&nm, 1, MPI_INT, counts, 1, MPI_INT, comm));
    G = 0;
    for (PetscMPIInt r = 0; r < size; r++) {
      PetscCall(PetscMPIIntCast(G, &displs[r]));
      G += counts[r];
    }
    s->G = G;
    PetscCall(PetscMalloc1(G, &s->gidx));
    PetscCallMPI(MPI_Allgatherv(mine, nm, MPIU_INT, s->gidx, counts, displs, MPIU_INT, comm));
    PetscCall(PetscFree2(counts, displs));
    PetscCall(PetscFree(mine));
  }
  /* local dofs, ascending: the other ranks' interface dofs of the interior rows and the owned ones */
  {
    PetscInt *loc, below = 0;
    s->m    = nown + nextra;
    s->nown = nown;
    PetscCall(PetscMalloc1(s->m, &loc));
    for (PetscInt k = 0; k < nextra; k++) below += extra[k] < rstart;
    for (PetscInt k = 0; k < below; k++) loc[k] = extra[k];
    for (PetscInt i = 0; i < nown; i++) loc[below + i] = rstart + i;
    for (PetscInt k = below; k < nextra; k++) loc[nown + k] = extra[k];
    s->own_off = below;
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, s->m, loc, PETSC_OWN_POINTER, &s->isloc));
    PetscCall(ISSetInfo(s->isloc, IS_SORTED, IS_LOCAL, PETSC_TRUE, PETSC_TRUE));
  }
  PetscCall(PetscFree(isgam));
  PetscCall(PetscFree(extra));
  PetscCall(MatCreateSubMatrices(S, 1, &s->isloc, &s->isloc, MAT_INITIAL_MATRIX, &s->sub));
  {
    Vec g;
    PetscCall(MatCreateVecs(S, &g, NULL));
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, s->m, &s->bloc));
    PetscCall(VecScatterCreate(g, s->isloc, s->bloc, NULL, &s->scat));
    PetscCall(VecDestroy(&g));
  }
  PetscFunctionReturn(0);
}

/* Rank-local: the local matrix in CHOLMOD form, the ordering (interior by METIS/AMD/NESDIS, interface last) and
   CHOLMOD's analysis, the interface columns in the factor's order, the owned rows' places. */
static PetscErrorCode SetUpAnalysis(PC_SubChol *s)
{
  PetscInt        mi = 0, q = 0, *pos;
  int            *perm, *sub = NULL, *pi = NULL;
  const PetscInt *loc;
  PetscFunctionBeginUser;
  PetscCheck(s->m < 2147483647, PETSC_COMM_SELF, PETSC_ERR_SUP, "cssubchol: %" PetscInt_FMT " local dofs: too many for CHOLMOD's int interface", s->m);
  { /* CSR of a symmetric matrix = its CSC, upper part used */
    const PetscInt *ia, *ja;
    PetscInt        n;
    PetscBool       done;
    int            *cp, *ci;
    PetscCall(MatGetRowIJ(s->sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
    PetscCheck(done && n == s->m, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cssubchol: no row structure of the local matrix");
    s->A = cholmod_allocate_sparse((size_t)n, (size_t)n, (size_t)ia[n], 1, 1, 1, CHOLMOD_REAL, &s->c);
    PetscCall(CholCheck(&s->c, "allocate"));
    cp = (int *)s->A->p;
    ci = (int *)s->A->i;
    for (PetscInt k = 0; k <= n; k++) cp[k] = (int)ia[k];
    for (PetscInt k = 0; k < ia[n]; k++) ci[k] = (int)ja[k];
    PetscCall(MatRestoreRowIJ(s->sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
  }
  PetscCall(ISGetIndices(s->isloc, &loc));
  PetscCall(PetscMalloc1(s->m, &pos));
  for (PetscInt k = 0; k < s->m; k++) {
    PetscInt g;
    PetscCall(PetscFindInt(loc[k], s->G, s->gidx, &g));
    pos[k] = g; /* interface number or < 0 */
    if (g < 0) mi++;
  }
  PetscCall(ISRestoreIndices(s->isloc, &loc));
  PetscCall(PetscMalloc1(PetscMax(s->m, 1), &perm)); /* CHOLMOD_GIVEN needs a pointer even for m = 0 */
  if (mi > 0) {
    cholmod_sparse *Au, *Ai;
    PetscCall(PetscMalloc2(mi, &sub, mi, &pi));
    for (PetscInt k = 0; k < s->m; k++)
      if (pos[k] < 0) sub[q++] = (int)k;
    Au = cholmod_copy(s->A, 0, 0, &s->c); /* both triangles (cholmod_submatrix needs them), pattern only */
    PetscCall(CholCheck(&s->c, "copy"));
    Ai = cholmod_submatrix(Au, sub, (long)mi, sub, (long)mi, 0, 1, &s->c);
    cholmod_free_sparse(&Au, &s->c);
    PetscCall(CholCheck(&s->c, "submatrix"));
    Ai->stype = 1;
    if (s->ordering == ORDER_AMD) cholmod_amd(Ai, NULL, 0, pi, &s->c);
    else if (s->ordering == ORDER_NESDIS) {
      int *cpar, *cm;
      PetscCall(PetscMalloc2(mi, &cpar, mi, &cm));
      cholmod_nested_dissection(Ai, NULL, 0, pi, cpar, cm, &s->c);
      PetscCall(PetscFree2(cpar, cm));
    } else cholmod_metis(Ai, NULL, 0, 1, pi, &s->c);
    cholmod_free_sparse(&Ai, &s->c);
    PetscCall(CholCheck(&s->c, "interior ordering"));
    for (PetscInt k = 0; k < mi; k++) perm[k] = sub[pi[k]];
    PetscCall(PetscFree2(sub, pi));
  }
  q = mi;
  for (PetscInt k = 0; k < s->m; k++)
    if (pos[k] >= 0) perm[q++] = (int)k;
  s->c.nmethods           = 1;
  s->c.method[0].ordering = CHOLMOD_GIVEN;
  s->L                    = cholmod_analyze_p(s->A, perm, NULL, 0, &s->c);
  PetscCall(PetscFree(perm));
  PetscCall(CholCheck(&s->c, "analysis"));
  s->fl  = s->c.fl;
  s->lnz = s->c.lnz;
  s->gp  = s->m - mi;
  PetscCall(PetscMalloc3(s->gp, &s->gpos, s->gp, &s->gglob, s->gp, &s->gloc));
  {
    const int *P = (const int *)s->L->Perm;
    PetscInt   l = 0;
    for (PetscInt k = 0; k < s->m; k++)
      if (pos[P[k]] >= 0) {
        s->gpos[l]  = k;
        s->gglob[l] = pos[P[k]];
        s->gloc[l]  = P[k];
        l++;
      }
  }
  PetscCall(PetscMalloc1(s->nown, &s->own_loc));
  for (PetscInt i = 0; i < s->nown; i++) s->own_loc[i] = pos[s->own_off + i] >= 0 ? -1 - pos[s->own_off + i] : s->own_off + i;
  PetscCall(PetscFree(pos));
  PetscCall(PetscMalloc1((size_t)s->G * s->G, &s->SG));
  PetscCall(PetscMalloc1((size_t)s->G * (s->G + 1) / 2, &s->pack));
  PetscCall(PetscMalloc1(s->G, &s->rG));
  s->v = cholmod_zeros((size_t)s->m, 1, CHOLMOD_REAL, &s->c);
  PetscCall(CholCheck(&s->c, "allocate"));
  PetscFunctionReturn(0);
}

/* Rank-local: new values into the local matrix, factorisation. *notpd: not positive definite. */
static PetscErrorCode LocalFactor(PC_SubChol *s, PetscBool *notpd)
{
  const PetscScalar *a;
  PetscFunctionBeginUser;
  PetscCall(MatSeqAIJGetArrayRead(s->sub[0], &a));
  PetscCall(PetscArraycpy((PetscScalar *)s->A->x, a, ((int *)s->A->p)[s->m]));
  PetscCall(MatSeqAIJRestoreArrayRead(s->sub[0], &a));
  cholmod_factorize(s->A, s->L, &s->c);
  PetscCall(CholCheck(&s->c, "factorisation"));
  s->nfact++;
  PetscCall(PetscLogFlops(s->fl));
  *notpd = (PetscBool)(s->c.status == CHOLMOD_NOT_POSDEF);
  PetscFunctionReturn(0);
}

/* Rank-local: this rank's part of S_Gamma (lower triangle, packed): T_p - S(G_p, G_p), with T_p = the local Schur
   complement on the interface, plus S(Gamma, Gamma) on the owned interface rows. T_p = L_GG L_GG^T from the
   factor's interface block. Then L(G,G) is set
   to the identity: the solves need only L_II and L_GI (ApplyForward, PCApply). */
static PetscErrorCode LocalInterface(Mat S, PC_SubChol *s)
{
  PetscInt     gp = s->gp, G = s->G, rstart;
  PetscBLASInt bgp, info;
  PetscFunctionBeginUser;
#define PACK(i, j) ((size_t)(j) * (2 * (size_t)G - (j) + 1) / 2 + ((i) - (j))) /* lower triangle, column-major, i >= j */
  PetscCall(PetscArrayzero(s->pack, (size_t)G * (G + 1) / 2));
  if (gp) {
    const int *super = (const int *)s->L->super, *lpi = (const int *)s->L->pi, *lpx = (const int *)s->L->px, *ls = (const int *)s->L->s;
    double    *lx    = (double *)s->L->x;
    PetscInt  *inv;
    PetscScalar *U; /* gp x gp: the interface block of L, reversed (upper triangular), column-major */
    PetscCheck(s->L->is_super, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cssubchol: CHOLMOD returned a simplicial factor");
    PetscCall(PetscMalloc1(s->m, &inv));
    PetscCall(PetscCalloc1((size_t)gp * gp, &U));
    for (PetscInt k = 0; k < s->m; k++) inv[k] = -1;
    for (PetscInt l = 0; l < gp; l++) inv[s->gpos[l]] = l;
    /* the interface columns (all their rows are interface rows: Gamma is closed upwards in the elimination tree) */
    for (size_t sn = 0; sn < s->L->nsuper; sn++) {
      PetscInt k1 = super[sn], k2 = super[sn + 1], nsrow = lpi[sn + 1] - lpi[sn];
      for (PetscInt jj = 0; jj < k2 - k1; jj++) {
        PetscInt c = inv[k1 + jj];
        if (c < 0) continue;
        for (PetscInt ii = jj; ii < nsrow; ii++) {
          PetscInt r = inv[ls[lpi[sn] + ii]];
          if (r < 0) continue;
          U[(gp - 1 - r) + (size_t)gp * (gp - 1 - c)] = lx[lpx[sn] + ii + (size_t)jj * nsrow];
          lx[lpx[sn] + ii + (size_t)jj * nsrow] = r == c ? 1 : 0;
        }
      }
    }
    { /* T_p = L_GG L_GG^T by LAPACK's U U^T on the reversed L_GG: a third of the flops of a product */
      PetscCall(PetscBLASIntCast(gp, &bgp));
      dlauum_("U", &bgp, U, &bgp, &info);
      PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "cssubchol: LAPACK dlauum info %d", (int)info);
      PetscCall(PetscLogFlops((PetscLogDouble)gp * gp * gp / 3));
    }
    for (PetscInt j = 0; j < gp; j++) /* T(i,j) = U(gp-1-i, gp-1-j), i >= j */
      for (PetscInt i = j; i < gp; i++) {
        PetscInt gi = PetscMax(s->gglob[i], s->gglob[j]), gj = PetscMin(s->gglob[i], s->gglob[j]);
        s->pack[PACK(gi, gj)] += U[(gp - 1 - i) + (size_t)gp * (gp - 1 - j)];
      }
    PetscCall(PetscFree(U));
    /* - S(G_p, G_p), from the local matrix (both triangles stored: take each pair once) */
    {
      const PetscInt    *ia, *ja;
      const PetscScalar *a;
      PetscInt           n;
      PetscBool          done;
      for (PetscInt k = 0; k < s->m; k++) inv[k] = -1;
      for (PetscInt l = 0; l < gp; l++) inv[s->gloc[l]] = s->gglob[l];
      PetscCall(MatGetRowIJ(s->sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
      PetscCall(MatSeqAIJGetArrayRead(s->sub[0], &a));
      for (PetscInt r = 0; r < n; r++) {
        if (inv[r] < 0) continue;
        for (PetscInt k = ia[r]; k < ia[r + 1]; k++)
          if (inv[ja[k]] >= 0 && inv[ja[k]] <= inv[r]) s->pack[PACK(inv[r], inv[ja[k]])] -= a[k];
      }
      PetscCall(MatSeqAIJRestoreArrayRead(s->sub[0], &a));
      PetscCall(MatRestoreRowIJ(s->sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
    }
    PetscCall(PetscFree(inv));
  }
  /* + S(Gamma, Gamma): the owner of each interface row adds its lower part once */
  PetscCall(MatGetOwnershipRange(S, &rstart, NULL));
  for (PetscInt i = 0; i < s->nown && G; i++) {
    PetscInt           nc, gi = -1 - s->own_loc[i];
    const PetscInt    *cols;
    const PetscScalar *vals;
    if (s->own_loc[i] >= 0) continue;
    PetscCall(MatGetRow(S, rstart + i, &nc, &cols, &vals));
    for (PetscInt k = 0; k < nc; k++) {
      PetscInt gj;
      PetscCall(PetscFindInt(cols[k], G, s->gidx, &gj));
      if (gj >= 0 && gj <= gi) s->pack[PACK(gi, gj)] += vals[k];
    }
    PetscCall(MatRestoreRow(S, rstart + i, &nc, &cols, &vals));
  }
  PetscFunctionReturn(0);
}

/* The local factorisation, its interface block, and the factored S_Gamma. Collective. */
static PetscErrorCode SetUpNumeric(PC pc, PC_SubChol *s)
{
  Mat            S = pc->pmat;
  PetscInt       G = s->G;
  MPI_Comm       comm;
  PetscMPIInt    size;
  PetscErrorCode ierr;
  PetscBool      notpd = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)S, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(MatCreateSubMatrices(S, 1, &s->isloc, &s->isloc, MAT_REUSE_MATRIX, &s->sub));
  CSCaptureError(ierr, LocalFactor(s, &notpd));
  PetscCall(CSSyncError(comm, ierr)); /* a failure on one rank: raised on every rank */
  { /* a matrix that is not positive definite on some rank: decided by all ranks together and reported the PETSc
       way (the KSP stops with DIVERGED_PC_FAILED; the flow halves its step) */
    PetscMPIInt bad = notpd ? 1 : 0, worst;
    if (notpd) PetscCall(PetscInfo(pc, "the local matrix is not positive definite (CHOLMOD stopped at column %d of %" PetscInt_FMT ")\n", (int)s->L->minor, s->m));
    PetscCallMPI(MPI_Allreduce(&bad, &worst, 1, MPI_INT, MPI_MAX, comm));
    if (worst) {
      PetscCheck(!pc->erroriffailure, comm, PETSC_ERR_MAT_CH_ZRPVT, "cssubchol: the matrix is not positive definite");
      PetscCall(PCSetFailedReason(pc, PC_FACTOR_NUMERIC_ZEROPIVOT));
      PetscFunctionReturn(0);
    }
  }
  PetscCall(PetscLogEventBegin(CS_EVENT_SubCholDense, pc, 0, 0, 0));
  CSCaptureError(ierr, LocalInterface(S, s));
  PetscCall(CSSyncError(comm, ierr));
  if (size > 1) {
    PetscMPIInt n;
    PetscCall(PetscMPIIntCast((PetscInt)((size_t)G * (G + 1) / 2), &n));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s->pack, n, MPIU_SCALAR, MPIU_SUM, comm));
  }
  if (G) {
    PetscBLASInt bG, info;
    PetscMPIInt  bad, anybad;
    for (PetscInt j = 0; j < G; j++)
      for (PetscInt i = j; i < G; i++) s->SG[i + (size_t)G * j] = s->pack[PACK(i, j)];
    PetscCall(PetscBLASIntCast(G, &bG));
    LAPACKpotrf_("L", &bG, s->SG, &bG, &info); /* the same data on every rank: decided together all the same */
    PetscCall(PetscLogFlops((PetscLogDouble)G * G * G / 3));
    bad = info ? 1 : 0;
    PetscCallMPI(MPI_Allreduce(&bad, &anybad, 1, MPI_INT, MPI_MAX, comm));
    if (anybad) {
      PetscCall(PetscInfo(pc, "the interface Schur complement (%" PetscInt_FMT " dofs) is not positive definite (LAPACK potrf info %d)\n", G, (int)info));
      PetscCheck(!pc->erroriffailure, comm, PETSC_ERR_MAT_CH_ZRPVT, "cssubchol: the interface Schur complement is not positive definite");
      PetscCall(PCSetFailedReason(pc, PC_FACTOR_NUMERIC_ZEROPIVOT));
    }
  }
#undef PACK
  PetscCall(PetscLogEventEnd(CS_EVENT_SubCholDense, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Collective, after the split and the analysis: does the dense interface fit? Every rank stores S_Gamma twice
   (its Cholesky factor, G^2 entries, and the packed lower triangle for the reduction, G (G + 1) / 2), 12 G^2 bytes,
   redundantly; its sparse local factor takes about 12 lnz bytes (value and row index). The interface grows with the
   ranks (2D cuts: G ~ sqrt(P N), so 12 G^2 ~ P N) while the local factors shrink (~ N / P): past some rank count
   the redundant dense block dominates the memory per rank. It fits while 12 G^2 <= max_ratio x the largest local
   factor or it takes at most fits_mb MB (small problems: the redundancy costs nothing measurable); else
   *use_fallback (docs/scaling.md, "Several ranks"). */
static PetscErrorCode ChooseEngine(PC pc, PC_SubChol *s, PetscBool *use_fallback)
{
  PetscLogDouble lnz = s->lnz, lnzmax;
  PetscInt       gpmax;
  MPI_Comm       comm = PetscObjectComm((PetscObject)pc);
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&lnz, &lnzmax, 1, MPI_DOUBLE, MPI_MAX, comm));
  PetscCallMPI(MPI_Allreduce(&s->gp, &gpmax, 1, MPIU_INT, MPI_MAX, comm));
  s->Gseen     = s->G;
  s->gpmax     = gpmax;
  s->dense_mb  = 8.0 * ((PetscLogDouble)s->G * s->G + (PetscLogDouble)s->G * (s->G + 1) / 2) / 1048576.0;
  s->factor_mb = 12.0 * lnzmax / 1048576.0;
  *use_fallback = (PetscBool)(s->G > 0 && s->dense_mb > PetscMax(s->max_ratio * s->factor_mb, s->fits_mb));
  PetscCall(PetscInfo(pc, "interface %" PetscInt_FMT " dofs (up to %" PetscInt_FMT " per rank), dense %.3g MB per rank, largest local factor %.3g MB: %s\n", s->G, gpmax, s->dense_mb, s->factor_mb, *use_fallback ? "MUMPS" : "substructured"));
  PetscFunctionReturn(0);
}

/* The MUMPS Cholesky that replaces the substructuring (options prefix <prefix>cssubchol_fallback_; AMD ordering by
   default, the best Debian's MUMPS has), with a note on the output. */
static PetscErrorCode SetUpFallback(PC pc, PC_SubChol *s)
{
  const char *prefix;
  PetscFunctionBeginUser;
  PetscCall(PCGetOptionsPrefix(pc, &prefix));
  PetscCall(PetscPrintf(PetscObjectComm((PetscObject)pc), "cssubchol (%s): the interface has %" PetscInt_FMT " dofs (up to %" PetscInt_FMT " per rank), %.3g MB dense on every rank > %g x the largest local factor (%.3g MB) and > %g MB: MUMPS Cholesky instead (-%spc_cssubchol_max_interface_ratio, -%spc_cssubchol_fits_mb)\n", prefix ? prefix : "", s->Gseen, s->gpmax, s->dense_mb, (double)s->max_ratio, s->factor_mb, (double)s->fits_mb, prefix ? prefix : "", prefix ? prefix : ""));
  PetscCall(PCCreate(PetscObjectComm((PetscObject)pc), &s->fallback));
  PetscCall(PCSetOptionsPrefix(s->fallback, prefix));
  PetscCall(PCAppendOptionsPrefix(s->fallback, "cssubchol_fallback_"));
  PetscCall(PCSetOperators(s->fallback, pc->mat, pc->pmat));
  PetscCall(PCSetType(s->fallback, PCCHOLESKY));
  PetscCall(PCFactorSetMatSolverType(s->fallback, MATSOLVERMUMPS));
  PetscCall(PCSetFromOptions(s->fallback));
  PetscCall(CSMumpsDefaultOrdering(s->fallback, pc->pmat));
  PetscFunctionReturn(0);
}

/* The fallback's factorisation; a failure (not positive definite, MUMPS out of workspace) is this PC's */
static PetscErrorCode SetUpNumericFallback(PC pc, PC_SubChol *s)
{
  PCFailedReason reason;
  PetscFunctionBeginUser;
  PetscCall(PCSetUp(s->fallback));
  PetscCall(PCGetFailedReasonRank(s->fallback, &reason));
  {
    PetscMPIInt r = (PetscMPIInt)reason, worst;
    PetscCallMPI(MPI_Allreduce(&r, &worst, 1, MPI_INT, MPI_MAX, PetscObjectComm((PetscObject)pc)));
    if (worst) PetscCall(PCSetFailedReason(pc, (PCFailedReason)worst));
  }
  s->nfact++;
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetUp_SubChol(PC pc)
{
  PC_SubChol    *s = (PC_SubChol *)pc->data;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  if (!s->started) {
    PetscCall(CSCholmodStartCommon("auto", &s->c));
    s->c.print = 0; /* silent: a matrix that is not positive definite is reported through the PC, errors by status */
    s->started = PETSC_TRUE;
  }
  if (!pc->setupcalled || pc->flag == DIFFERENT_NONZERO_PATTERN || !(s->L || s->fallback)) {
    PetscBool use_fallback;
    PetscCall(PetscLogEventBegin(CS_EVENT_SubCholSym, pc, 0, 0, 0));
    PetscCall(ResetSymbolic(s));
    PetscCall(PCDestroy(&s->fallback));
    PetscCall(SetUpSplit(pc, s));
    CSCaptureError(ierr, SetUpAnalysis(s));
    if (ierr) PetscCall(ResetSymbolic(s)); /* free what a half-done analysis left */
    PetscCall(CSSyncError(PetscObjectComm((PetscObject)pc), ierr));
    PetscCall(ChooseEngine(pc, s, &use_fallback));
    if (use_fallback) {
      PetscCall(ResetSymbolic(s));
      PetscCall(SetUpFallback(pc, s));
    }
    PetscCall(PetscLogEventEnd(CS_EVENT_SubCholSym, pc, 0, 0, 0));
  }
  PetscCall(PCSetFailedReason(pc, PC_NOERROR));
  if (s->fallback) {
    PetscCall(SetUpNumericFallback(pc, s));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventBegin(CS_EVENT_SubCholNum, pc, 0, 0, 0));
  PetscCall(SetUpNumeric(pc, s));
  PetscCall(PetscLogEventEnd(CS_EVENT_SubCholNum, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* Rank-local: y = L^{-1} P [b_I; 0] with L(G,G) = I; its interface part y_G = -L_GI y_I = -S(G,I) S(I,I)^{-1} b_I
   is added into rG; owned interface entries of b into rG too. */
static PetscErrorCode ApplyForward(PC_SubChol *s, Vec b)
{
  const PetscScalar *bl, *ba;
  const PetscScalar *ya;
  PetscFunctionBeginUser;
  PetscCall(VecGetArrayRead(s->bloc, &bl));
  PetscCall(PetscArraycpy((PetscScalar *)s->v->x, bl, s->m));
  PetscCall(VecRestoreArrayRead(s->bloc, &bl));
  for (PetscInt l = 0; l < s->gp; l++) ((PetscScalar *)s->v->x)[s->gloc[l]] = 0;
  cholmod_solve2(CHOLMOD_P, s->L, s->v, NULL, &s->t1, NULL, &s->Yw, &s->Ew, &s->c);
  cholmod_solve2(CHOLMOD_L, s->L, s->t1, NULL, &s->t2, NULL, &s->Yw, &s->Ew, &s->c);
  PetscCall(CholCheck(&s->c, "forward solve"));
  PetscCall(PetscArrayzero(s->rG, s->G));
  ya = (const PetscScalar *)s->t2->x;
  for (PetscInt l = 0; l < s->gp; l++) s->rG[s->gglob[l]] += ya[s->gpos[l]];
  PetscCall(VecGetArrayRead(b, &ba));
  for (PetscInt i = 0; i < s->nown; i++)
    if (s->own_loc[i] < 0) s->rG[-1 - s->own_loc[i]] += ba[i];
  PetscCall(VecRestoreArrayRead(b, &ba));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCApply_SubChol(PC pc, Vec b, Vec x)
{
  PC_SubChol    *s = (PC_SubChol *)pc->data;
  PetscScalar   *xa, *ya;
  PetscInt       G = s->G;
  PetscBLASInt   bG, one = 1, info;
  MPI_Comm       comm;
  PetscMPIInt    size;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  if (pc->failedreason) { /* PETSc's convention after a failed factorisation */
    PetscCall(VecSetInf(x));
    PetscFunctionReturn(0);
  }
  if (s->fallback) {
    PetscCall(PCApply(s->fallback, b, x));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventBegin(CS_EVENT_SubCholSolve, pc, b, x, 0));
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCall(VecScatterBegin(s->scat, b, s->bloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s->scat, b, s->bloc, INSERT_VALUES, SCATTER_FORWARD));
  CSCaptureError(ierr, ApplyForward(s, b));
  PetscCall(CSSyncError(comm, ierr));
  if (G && size > 1) { /* r_Gamma = b_Gamma + sum_p y_G */
    PetscMPIInt n;
    PetscCall(PetscMPIIntCast(G, &n));
    PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, s->rG, n, MPIU_SCALAR, MPIU_SUM, comm));
  }
  if (G) {
    PetscCall(PetscBLASIntCast(G, &bG));
    LAPACKpotrs_("L", &bG, &one, s->SG, &bG, s->rG, &bG, &info); /* rG = x_Gamma */
    PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "cssubchol: LAPACK potrs info %d", (int)info);
    ya = (PetscScalar *)s->t2->x; /* backward data: y_G = x_G (L(G,G) = I) */
    for (PetscInt l = 0; l < s->gp; l++) ya[s->gpos[l]] = s->rG[s->gglob[l]];
  }
  /* backward: x_loc = P^T L^{-T} y */
  cholmod_solve2(CHOLMOD_Lt, s->L, s->t2, NULL, &s->t1, NULL, &s->Yw, &s->Ew, &s->c);
  cholmod_solve2(CHOLMOD_Pt, s->L, s->t1, NULL, &s->t2, NULL, &s->Yw, &s->Ew, &s->c);
  PetscCall(CholCheck(&s->c, "backward solve"));
  PetscCall(PetscLogFlops(4 * s->lnz + 2.0 * G * G)); /* two triangular solves with L, potrs */
  PetscCall(VecGetArray(x, &xa));
  for (PetscInt i = 0; i < s->nown; i++) xa[i] = s->own_loc[i] >= 0 ? ((PetscScalar *)s->t2->x)[s->own_loc[i]] : s->rG[-1 - s->own_loc[i]];
  PetscCall(VecRestoreArray(x, &xa));
  PetscCall(PetscLogEventEnd(CS_EVENT_SubCholSolve, pc, b, x, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCReset_SubChol(PC pc)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscFunctionBeginUser;
  PetscCall(ResetSymbolic(s));
  PetscCall(PCDestroy(&s->fallback));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCDestroy_SubChol(PC pc)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscFunctionBeginUser;
  PetscCall(ResetSymbolic(s));
  PetscCall(PCDestroy(&s->fallback));
  if (s->started) cholmod_finish(&s->c);
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "CSSubCholGetInfo_C", NULL));
  PetscCall(PetscFree(pc->data));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetFromOptions_SubChol(PC pc, PetscOptionItems *PetscOptionsObject)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Substructured CHOLMOD Cholesky (cssubchol)");
  PetscCall(CSOptionsEList("-pc_cssubchol_ordering", "Ordering of each rank's interior", NULL, OrderingNames, 3, OrderingNames[s->ordering], &s->ordering, NULL));
  PetscCall(CSOptionsEList("-pc_cssubchol_interface", "Side of each cut that holds the interface (auto: the smaller largest local matrix)", NULL, SideNames, 3, SideNames[s->side_opt], &s->side_opt, NULL));
  PetscCall(CSOptionsReal("-pc_cssubchol_max_interface_ratio", "Substructure while the dense interface per rank takes at most this times the memory of the largest local factor, else MUMPS", NULL, s->max_ratio, &s->max_ratio, NULL));
  PetscCall(CSOptionsReal("-pc_cssubchol_fits_mb", "A dense interface of at most this many MB per rank is always substructured", NULL, s->fits_mb, &s->fits_mb, NULL));
  PetscOptionsHeadEnd();
  PetscCheck(s->fits_mb >= 0, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "-%spc_cssubchol_fits_mb %g: must be >= 0", ((PetscObject)pc)->prefix ? ((PetscObject)pc)->prefix : "", (double)s->fits_mb);
  PetscCheck(s->max_ratio >= 0, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "-%spc_cssubchol_max_interface_ratio %g: must be >= 0", ((PetscObject)pc)->prefix ? ((PetscObject)pc)->prefix : "", (double)s->max_ratio);
  PetscFunctionReturn(0);
}

static PetscErrorCode PCView_SubChol(PC pc, PetscViewer viewer)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscBool   ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii && s->fallback) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "  MUMPS Cholesky instead of the substructuring: interface %" PetscInt_FMT " dofs (up to %" PetscInt_FMT " per rank), %.3g MB dense per rank > %g x the largest local factor (%.3g MB)\n", s->Gseen, s->gpmax, s->dense_mb, (double)s->max_ratio, s->factor_mb));
    PetscCall(PetscViewerASCIIPushTab(viewer));
    PetscCall(PCView(s->fallback, viewer));
    PetscCall(PetscViewerASCIIPopTab(viewer));
  } else if (ascii) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "  substructured CHOLMOD Cholesky: interior ordering %s, interface %" PetscInt_FMT " dofs (dense, redundant), on the %s side of each cut\n", OrderingNames[s->ordering], s->G, s->side ? "upper" : "lower"));
    PetscCall(PetscViewerASCIIPrintf(viewer, "    dense interface %.3g MB per rank (up to %" PetscInt_FMT " interface dofs per local matrix), largest local factor %.3g MB: fits (<= %g x, or <= %g MB)\n", s->dense_mb, s->gpmax, s->factor_mb, (double)s->max_ratio, (double)s->fits_mb));
    PetscCall(PetscViewerASCIIPushSynchronized(viewer));
    if (s->L) PetscCall(PetscViewerASCIISynchronizedPrintf(viewer, "    [local] %" PetscInt_FMT " dofs, %" PetscInt_FMT " on the interface, factor %.3g entries, %.3g flops; %" PetscInt_FMT " factorisations\n", s->m, s->gp, s->lnz, s->fl, s->nfact));
    PetscCall(PetscViewerFlush(viewer));
    PetscCall(PetscViewerASCIIPopSynchronized(viewer));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode GetInfo_SubChol(PC pc, PetscInt *G, PetscInt *factorisations)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscFunctionBeginUser;
  if (G) *G = s->fallback ? s->Gseen : s->G;
  if (factorisations) *factorisations = s->nfact;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSubCholGetInfo(PC pc, PetscInt *G, PetscInt *factorisations)
{
  PetscFunctionBeginUser;
  PetscValidHeaderSpecific(pc, PC_CLASSID, 1);
  if (G) *G = 0;
  if (factorisations) *factorisations = 0;
  PetscTryMethod(pc, "CSSubCholGetInfo_C", (PC, PetscInt *, PetscInt *), (pc, G, factorisations));
  PetscFunctionReturn(0);
}

PetscErrorCode PCCreate_CSSubChol(PC pc)
{
  PC_SubChol *s;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  s->max_ratio             = 1.0; /* docs/scaling.md, "Several ranks" */
  s->fits_mb               = 16.0;
  pc->data                 = s;
  pc->ops->setup           = PCSetUp_SubChol;
  pc->ops->apply           = PCApply_SubChol;
  pc->ops->applytranspose  = PCApply_SubChol; /* S is symmetric */
  pc->ops->reset           = PCReset_SubChol;
  pc->ops->destroy         = PCDestroy_SubChol;
  pc->ops->setfromoptions  = PCSetFromOptions_SubChol;
  pc->ops->view            = PCView_SubChol;
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "CSSubCholGetInfo_C", GetInfo_SubChol));
  PetscFunctionReturn(0);
}
