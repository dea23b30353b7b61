/* PC type "cssubchol": direct solve of a distributed sparse SPD matrix S by substructuring, with CHOLMOD on
   every rank and one dense Schur complement on the interface.

   Why: the 2-rank MUMPS factorisation of the flow's Schur complement (PORD ordering: Debian's MUMPS has no
   METIS/SCOTCH) is no faster than serial CHOLMOD with METIS, so 2 ranks gained nothing (issue 3). Splitting the
   unknowns by the mesh partition lets each rank factor its own half with CHOLMOD + METIS at full speed.

   The split. Each dof belongs to the rank that owns its row. The interface Gamma is the set of dofs that are
   coupled (nonzero S_ij) to a dof of a higher rank; what remains on rank p, its interior I_p, is coupled only to
   I_p and Gamma, never to another rank's interior. Rank p factors its local matrix
       A_p = [ S(I_p, I_p)  S(I_p, G_p) ]      G_p = the interface dofs coupled to I_p, and its own,
             [ S(G_p, I_p)  S(G_p, G_p) ]
   (a principal submatrix of S, hence SPD) with G_p ordered after I_p (METIS on I_p). The last block of its
   Cholesky factor then holds L_GG with L_GG L_GG^T = S(G_p,G_p) - C_p, C_p = S(G_p,I_p) S(I_p,I_p)^{-1} S(I_p,G_p),
   and the Schur complement of S on the whole interface is
       S_Gamma = S(Gamma, Gamma) - sum_p C_p,
   a dense matrix of the interface size, summed over ranks (MPI_Allreduce) and factored redundantly (LAPACK).
   A solve S x = b then is: y_p = L^{-1} [b_I; 0] on each rank (its interface part gives S(G,I)S(I,I)^{-1} b_I
   as -L_GG y_G), x_Gamma = S_Gamma^{-1} (b_Gamma - sum), and x_I = L^{-T} [y_I; L_GG^T x_G] on each rank.
   All interface couplings stay correct under CHOLMOD's postordering: G_p is closed upwards in the elimination
   tree (it is ordered last), so no interior column is eliminated after an interface column it touches.

   Cost: the interface has about two rows of mesh vertices along the cut (S couples two-rings); its dense
   factorisation is small next to the two halves (level 6: 2.1k interface dofs, 3.3e10 flops per rank against
   5.7e10 serially). The interface is redundant on every rank, so this is meant for a few ranks (memory
   8 G^2 bytes per rank); on one rank it is a plain CHOLMOD factorisation. The symbolic phase (split, METIS,
   CHOLMOD analysis) is kept while the nonzero pattern stays. */
#include <petsc/private/pcimpl.h> /* a PC type of our own (PCRegister) */
#include <petscblaslapack.h>
#include <suitesparse/cholmod.h>
#include "cs_substructured_cholesky.h"
#include "cs_cholmod.h"

/* LAPACK: U U^T of an upper triangular U (not wrapped by PETSc) */
extern void dlauum_(const char *, const PetscBLASInt *, PetscScalar *, const PetscBLASInt *, PetscBLASInt *);

static PetscLogEvent EV_Sym = 0, EV_Num = 0, EV_Dense = 0, EV_Solve = 0;

typedef struct {
  char            ordering[16]; /* of the interior: metis | amd | nesdis */
  cholmod_common  c;
  PetscBool       started;
  cholmod_sparse *A; /* local matrix, upper part used (stype 1) */
  cholmod_factor *L;
  Mat            *sub; /* the local matrix as SeqAIJ (MatCreateSubMatrices) */
  IS              isloc; /* global indices of the local dofs, ascending */
  PetscInt        m;     /* local dofs */
  PetscInt        G;     /* interface dofs, all ranks */
  PetscInt       *gidx;  /* their global indices, ascending */
  PetscInt        gp;    /* interface dofs of the local matrix */
  PetscInt       *gpos;  /* their positions in the factor's (permuted) order, ascending */
  PetscInt       *gglob; /* their interface numbers (0..G-1), in that order */
  PetscInt       *gloc;  /* their local numbers (0..m-1), in that order */
  PetscScalar    *LG;    /* gp x gp: L restricted to them (lower triangular, column-major) */
  PetscScalar    *SG;    /* G x G: Cholesky factor of S_Gamma */
  PetscScalar    *work;  /* max(gp, G) */
  PetscScalar    *rG;    /* G */
  PetscInt        nown;    /* owned rows */
  PetscInt       *own_loc; /* for each: local number, or -1 - (interface number) on the interface */
  VecScatter      scat;    /* global -> local dofs */
  Vec             bloc;
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
  }
  if (s->sub) PetscCall(MatDestroySubMatrices(1, &s->sub));
  PetscCall(ISDestroy(&s->isloc));
  PetscCall(PetscFree(s->gidx));
  PetscCall(PetscFree3(s->gpos, s->gglob, s->gloc));
  PetscCall(PetscFree(s->LG));
  PetscCall(PetscFree(s->SG));
  PetscCall(PetscFree2(s->work, s->rG));
  PetscCall(PetscFree(s->own_loc));
  PetscCall(VecScatterDestroy(&s->scat));
  PetscCall(VecDestroy(&s->bloc));
  s->m = s->G = s->gp = s->nown = 0;
  PetscFunctionReturn(0);
}

/* The split and the local matrix's pattern, ordering and CHOLMOD analysis. */
static PetscErrorCode SetUpSymbolic(PC pc, PC_SubChol *s)
{
  Mat             S = pc->pmat;
  MPI_Comm        comm;
  PetscMPIInt     size, rank;
  const PetscInt *ranges;
  PetscInt        rstart, rend, nown, *mine, nmine = 0, *extra, nextra = 0, cap = 16;
  PetscBool      *isgam;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)S, &comm));
  PetscCallMPI(MPI_Comm_size(comm, &size));
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  PetscCall(MatGetOwnershipRange(S, &rstart, &rend));
  PetscCall(MatGetOwnershipRanges(S, &ranges));
  nown = rend - rstart;
  /* interface rows: coupled to a higher rank (columns >= rend); the pattern is symmetric, so a column below
     rstart in any row is another rank's interface dof */
  PetscCall(PetscCalloc1(nown, &isgam));
  PetscCall(PetscMalloc1(cap, &extra));
  for (PetscInt i = rstart; i < rend; i++) {
    PetscInt        nc;
    const PetscInt *cols;
    PetscCall(MatGetRow(S, i, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc; k++)
      if (cols[k] >= rend) isgam[i - rstart] = PETSC_TRUE;
    PetscCall(MatRestoreRow(S, i, &nc, &cols, NULL));
  }
  for (PetscInt i = rstart; i < rend; i++) {
    PetscInt        nc;
    const PetscInt *cols;
    if (isgam[i - rstart]) continue; /* the lower-rank dofs coupled to interior rows only */
    PetscCall(MatGetRow(S, i, &nc, &cols, NULL));
    for (PetscInt k = 0; k < nc && cols[k] < rstart; k++) {
      if (nextra == cap) {
        PetscInt *t;
        PetscCall(PetscMalloc1(2 * cap, &t));
        PetscCall(PetscArraycpy(t, extra, nextra));
        PetscCall(PetscFree(extra));
        extra = t;
        cap *= 2;
      }
      extra[nextra++] = cols[k];
    }
    PetscCall(MatRestoreRow(S, i, &nc, &cols, NULL));
  }
  PetscCall(PetscSortRemoveDupsInt(&nextra, extra));
  /* the global interface list on every rank */
  {
    PetscMPIInt *counts, *displs, n;
    PetscInt     G = 0;
    for (PetscInt i = 0; i < nown; i++) G += isgam[i];
    PetscCall(PetscMalloc1(G, &mine));
    for (PetscInt i = 0; i < nown; i++)
      if (isgam[i]) mine[nmine++] = rstart + i;
    PetscCall(PetscMPIIntCast(nmine, &n));
    PetscCall(PetscMalloc2(size, &counts, size, &displs));
    PetscCallMPI(MPI_Allgather(&n, 1, MPI_INT, counts, 1, MPI_INT, comm));
    G = 0;
    for (PetscMPIInt r = 0; r < size; r++) {
      displs[r] = (PetscMPIInt)G;
      G += counts[r];
    }
    s->G = G;
    PetscCall(PetscMalloc1(G, &s->gidx));
    PetscCallMPI(MPI_Allgatherv(mine, n, MPIU_INT, s->gidx, counts, displs, MPIU_INT, comm));
    PetscCall(PetscFree2(counts, displs));
  }
  /* local dofs: owned ones (interior and interface) and the lower-rank interface dofs of the interior rows */
  {
    PetscInt *loc;
    s->m = nown + nextra;
    PetscCall(PetscMalloc1(s->m, &loc));
    for (PetscInt k = 0; k < nextra; k++) loc[k] = extra[k];
    for (PetscInt i = 0; i < nown; i++) loc[nextra + i] = rstart + i; /* ascending: extra < rstart */
    PetscCall(ISCreateGeneral(PETSC_COMM_SELF, s->m, loc, PETSC_OWN_POINTER, &s->isloc));
    PetscCall(ISSetInfo(s->isloc, IS_SORTED, IS_LOCAL, PETSC_TRUE, PETSC_TRUE));
  }
  PetscCheck(s->m < PETSC_MAX_INT / 2 && s->m < 2147483647, PETSC_COMM_SELF, PETSC_ERR_SUP, "cssubchol: %" PetscInt_FMT " local dofs: too many for CHOLMOD's int interface", s->m);
  PetscCall(MatCreateSubMatrices(S, 1, &s->isloc, &s->isloc, MAT_INITIAL_MATRIX, &s->sub));
  /* the local matrix in CHOLMOD form: CSR of a symmetric matrix = its CSC, upper part used */
  {
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
  /* ordering: the interior by METIS (or AMD/NESDIS), then the interface */
  {
    PetscInt        mi = 0, q = 0, *pos;
    int            *perm, *sub = NULL, *pi = NULL;
    const PetscInt *loc;
    PetscCall(ISGetIndices(s->isloc, &loc));
    PetscCall(PetscMalloc1(s->m, &pos));
    for (PetscInt k = 0; k < s->m; k++) {
      PetscInt g;
      PetscCall(PetscFindInt(loc[k], s->G, s->gidx, &g));
      pos[k] = g; /* interface number or < 0 */
      if (g < 0) mi++;
    }
    PetscCall(PetscMalloc1(s->m, &perm));
    if (mi > 0) {
      cholmod_sparse *Au, *Ai;
      PetscBool       amd, nesdis;
      PetscCall(PetscMalloc2(mi, &sub, mi, &pi));
      for (PetscInt k = 0; k < s->m; k++)
        if (pos[k] < 0) sub[q++] = (int)k;
      Au = cholmod_copy(s->A, 0, 1, &s->c); /* cholmod_submatrix needs both triangles */
      PetscCall(CholCheck(&s->c, "copy"));
      Ai = cholmod_submatrix(Au, sub, (long)mi, sub, (long)mi, 1, 1, &s->c);
      cholmod_free_sparse(&Au, &s->c);
      PetscCall(CholCheck(&s->c, "submatrix"));
      Ai->stype = 1;
      PetscCall(PetscStrcmp(s->ordering, "amd", &amd));
      PetscCall(PetscStrcmp(s->ordering, "nesdis", &nesdis));
      if (amd) cholmod_amd(Ai, NULL, 0, pi, &s->c);
      else if (nesdis) {
        int *cp, *cm;
        PetscCall(PetscMalloc2(mi, &cp, mi, &cm));
        cholmod_nested_dissection(Ai, NULL, 0, pi, cp, cm, &s->c);
        PetscCall(PetscFree2(cp, cm));
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
    PetscCall(CholCheck(&s->c, "analysis"));
    PetscCall(PetscFree(perm));
    /* the interface columns in the factor's order */
    s->gp = s->m - mi;
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
    /* owned rows: local number or interface number */
    s->nown = nown;
    PetscCall(PetscMalloc1(nown, &s->own_loc));
    for (PetscInt i = 0; i < nown; i++) s->own_loc[i] = pos[nextra + i] >= 0 ? -1 - pos[nextra + i] : nextra + i;
    PetscCall(PetscFree(pos));
    PetscCall(ISRestoreIndices(s->isloc, &loc));
  }
  PetscCall(PetscMalloc1((size_t)s->gp * s->gp, &s->LG));
  PetscCall(PetscMalloc1((size_t)s->G * s->G, &s->SG));
  PetscCall(PetscMalloc2(PetscMax(s->gp, s->G), &s->work, s->G, &s->rG));
  {
    Vec g;
    PetscCall(MatCreateVecs(S, &g, NULL));
    PetscCall(VecCreateSeq(PETSC_COMM_SELF, s->m, &s->bloc));
    PetscCall(VecScatterCreate(g, s->isloc, s->bloc, NULL, &s->scat));
    PetscCall(VecDestroy(&g));
  }
  PetscCall(PetscFree(isgam));
  PetscCall(PetscFree(mine));
  PetscCall(PetscFree(extra));
  PetscFunctionReturn(0);
}

/* The local factorisation, its interface block, and the factored S_Gamma. */
static PetscErrorCode SetUpNumeric(PC pc, PC_SubChol *s)
{
  Mat          S = pc->pmat;
  PetscInt     rstart, rend, gp = s->gp, G = s->G;
  PetscBLASInt bgp, bG, info;
  MPI_Comm     comm;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)S, &comm));
  PetscCall(MatCreateSubMatrices(S, 1, &s->isloc, &s->isloc, MAT_REUSE_MATRIX, &s->sub));
  {
    const PetscScalar *a;
    PetscInt           nz;
    PetscCall(MatSeqAIJGetArrayRead(s->sub[0], &a));
    nz = ((int *)s->A->p)[s->m];
    PetscCall(PetscArraycpy((PetscScalar *)s->A->x, a, nz));
    PetscCall(MatSeqAIJRestoreArrayRead(s->sub[0], &a));
  }
  cholmod_factorize(s->A, s->L, &s->c);
  PetscCall(CholCheck(&s->c, "factorisation"));
  { /* a matrix that is not positive definite fails on some ranks only: decide together, and report it the PETSc
       way (the KSP then stops with DIVERGED_PC_FAILED; the flow halves its step) */
    PetscMPIInt bad = s->c.status == CHOLMOD_NOT_POSDEF, anybad;
    if (bad) PetscCall(PetscInfo(pc, "cssubchol: the local matrix is not positive definite (CHOLMOD stopped at column %d of %" PetscInt_FMT ")\n", (int)s->L->minor, s->m));
    PetscCallMPI(MPI_Allreduce(&bad, &anybad, 1, MPI_INT, MPI_MAX, comm));
    if (anybad) {
      PetscCall(PCSetFailedReason(pc, PC_FACTOR_NUMERIC_ZEROPIVOT));
      PetscFunctionReturn(0);
    }
  }
  PetscCheck(s->L->is_super, PETSC_COMM_SELF, PETSC_ERR_PLIB, "cssubchol: CHOLMOD returned a simplicial factor");
  PetscCall(PetscLogEventBegin(EV_Dense, pc, 0, 0, 0));
  /* LG = L(interface, interface) of the local factor, in the factor's order */
  PetscCall(PetscArrayzero(s->LG, (size_t)gp * gp));
  if (gp) {
    const int    *super = (const int *)s->L->super, *lpi = (const int *)s->L->pi, *lpx = (const int *)s->L->px, *ls = (const int *)s->L->s;
    const double *lx    = (const double *)s->L->x;
    PetscInt     *inv;
    PetscCall(PetscMalloc1(s->m, &inv));
    for (PetscInt k = 0; k < s->m; k++) inv[k] = -1;
    for (PetscInt l = 0; l < gp; l++) inv[s->gpos[l]] = l;
    for (size_t sn = 0; sn < s->L->nsuper; sn++) {
      PetscInt k1 = super[sn], k2 = super[sn + 1], nsrow = lpi[sn + 1] - lpi[sn];
      for (PetscInt jj = 0; jj < k2 - k1; jj++) {
        PetscInt c = inv[k1 + jj];
        if (c < 0) continue;
        for (PetscInt ii = jj; ii < nsrow; ii++) {
          PetscInt r = inv[ls[lpi[sn] + ii]];
          if (r >= 0) s->LG[r + (size_t)gp * c] = lx[lpx[sn] + ii + (size_t)jj * nsrow];
        }
      }
    }
    PetscCall(PetscFree(inv));
  }
  /* S_Gamma = S(Gamma,Gamma) - sum_p C_p with C_p = S(G_p,G_p) - L_GG L_GG^T. L_GG L_GG^T by LAPACK's U U^T on the
     reversed (upper triangular) L_GG: a third of the flops of a general product. */
  PetscCall(PetscArrayzero(s->SG, (size_t)G * G));
  if (gp) {
    PetscScalar *U;
    PetscCall(PetscMalloc1((size_t)gp * gp, &U));
    for (PetscInt j = 0; j < gp; j++)
      for (PetscInt i = 0; i < gp; i++) U[(gp - 1 - i) + (size_t)gp * (gp - 1 - j)] = s->LG[i + (size_t)gp * j];
    PetscCall(PetscBLASIntCast(gp, &bgp));
    dlauum_("U", &bgp, U, &bgp, &info);
    PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "cssubchol: LAPACK dlauum info %d", (int)info);
    /* SG(lower) += T_p - S(G_p, G_p): T(i,j) = (U U^T)(gp-1-i, gp-1-j), i >= j */
    for (PetscInt j = 0; j < gp; j++)
      for (PetscInt i = j; i < gp; i++) {
        PetscInt gi = s->gglob[i], gj = s->gglob[j];
        PetscScalar t = U[(gp - 1 - i) + (size_t)gp * (gp - 1 - j)];
        if (gi < gj) {
          PetscInt tmp = gi;
          gi           = gj;
          gj           = tmp;
        }
        s->SG[gi + (size_t)G * gj] += t;
      }
    PetscCall(PetscFree(U));
    {
      const PetscInt    *ia, *ja;
      const PetscScalar *a;
      PetscInt           n;
      PetscBool          done;
      PetscInt          *inv; /* local number -> interface number */
      PetscCall(PetscMalloc1(s->m, &inv));
      for (PetscInt k = 0; k < s->m; k++) inv[k] = -1;
      for (PetscInt l = 0; l < gp; l++) inv[s->gloc[l]] = s->gglob[l];
      PetscCall(MatGetRowIJ(s->sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
      PetscCall(MatSeqAIJGetArrayRead(s->sub[0], &a));
      for (PetscInt r = 0; r < n; r++) {
        if (inv[r] < 0) continue;
        for (PetscInt k = ia[r]; k < ia[r + 1]; k++)
          if (inv[ja[k]] >= 0 && inv[ja[k]] <= inv[r]) s->SG[inv[r] + (size_t)G * inv[ja[k]]] -= a[k];
      }
      PetscCall(MatSeqAIJRestoreArrayRead(s->sub[0], &a));
      PetscCall(MatRestoreRowIJ(s->sub[0], 0, PETSC_FALSE, PETSC_FALSE, &n, &ia, &ja, &done));
      PetscCall(PetscFree(inv));
    }
  }
  if (G) {
    /* + S(Gamma, Gamma): the owner of each interface row adds it once */
    PetscCall(MatGetOwnershipRange(S, &rstart, &rend));
    for (PetscInt i = 0; i < s->nown; i++) {
      PetscInt           nc, gi = -1 - s->own_loc[i];
      const PetscInt    *cols;
      const PetscScalar *vals;
      if (s->own_loc[i] >= 0) continue;
      PetscCall(MatGetRow(S, rstart + i, &nc, &cols, &vals));
      for (PetscInt k = 0; k < nc; k++) {
        PetscInt gj;
        PetscCall(PetscFindInt(cols[k], G, s->gidx, &gj));
        if (gj >= 0 && gj <= gi) s->SG[gi + (size_t)G * gj] += vals[k];
      }
      PetscCall(MatRestoreRow(S, rstart + i, &nc, &cols, &vals));
    }
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s->SG, (PetscMPIInt)((size_t)G * G), MPIU_SCALAR, MPIU_SUM, comm));
    PetscCall(PetscBLASIntCast(G, &bG));
    LAPACKpotrf_("L", &bG, s->SG, &bG, &info); /* the same data and result on every rank */
    if (info) {
      PetscCall(PetscInfo(pc, "cssubchol: the interface Schur complement (%" PetscInt_FMT " dofs) is not positive definite (LAPACK potrf info %d)\n", G, (int)info));
      PetscCall(PCSetFailedReason(pc, PC_FACTOR_NUMERIC_ZEROPIVOT));
    }
  }
  PetscCall(PetscLogEventEnd(EV_Dense, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetUp_SubChol(PC pc)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscFunctionBeginUser;
  if (!s->started) {
    PetscCall(CSCholmodStartCommon("auto", &s->c));
    s->c.print   = 0; /* silent: a matrix that is not positive definite is reported through the PC, errors by status */
    s->started = PETSC_TRUE;
  }
  if (!pc->setupcalled || pc->flag == DIFFERENT_NONZERO_PATTERN || !s->L) {
    PetscCall(PetscLogEventBegin(EV_Sym, pc, 0, 0, 0));
    PetscCall(ResetSymbolic(s));
    PetscCall(SetUpSymbolic(pc, s));
    PetscCall(PetscLogEventEnd(EV_Sym, pc, 0, 0, 0));
  }
  PetscCall(PCSetFailedReason(pc, PC_NOERROR));
  PetscCall(PetscLogEventBegin(EV_Num, pc, 0, 0, 0));
  PetscCall(SetUpNumeric(pc, s));
  PetscCall(PetscLogEventEnd(EV_Num, pc, 0, 0, 0));
  PetscFunctionReturn(0);
}

/* b -> local dense CHOLMOD vector with the interface entries zeroed */
static PetscErrorCode PCApply_SubChol(PC pc, Vec b, Vec x)
{
  PC_SubChol        *s = (PC_SubChol *)pc->data;
  cholmod_dense     *v, *y, *u, *z;
  const PetscScalar *bl;
  PetscScalar       *xa, *ya;
  PetscInt           gp = s->gp, G = s->G, rstart;
  PetscBLASInt       bgp, bG, one = 1, info;
  const PetscScalar *ba;
  MPI_Comm           comm;
  PetscFunctionBeginUser;
  if (pc->failedreason) { /* PETSc's convention after a failed factorisation */
    PetscCall(VecSetInf(x));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscLogEventBegin(EV_Solve, pc, b, x, 0));
  PetscCall(PetscObjectGetComm((PetscObject)pc, &comm));
  PetscCall(VecScatterBegin(s->scat, b, s->bloc, INSERT_VALUES, SCATTER_FORWARD));
  PetscCall(VecScatterEnd(s->scat, b, s->bloc, INSERT_VALUES, SCATTER_FORWARD));
  v = cholmod_allocate_dense((size_t)s->m, 1, (size_t)s->m, CHOLMOD_REAL, &s->c);
  PetscCall(CholCheck(&s->c, "allocate"));
  PetscCall(VecGetArrayRead(s->bloc, &bl));
  PetscCall(PetscArraycpy((PetscScalar *)v->x, bl, s->m));
  PetscCall(VecRestoreArrayRead(s->bloc, &bl));
  for (PetscInt l = 0; l < gp; l++) ((PetscScalar *)v->x)[s->gloc[l]] = 0;
  /* forward: y = L^{-1} P [b_I; 0] */
  u = cholmod_solve(CHOLMOD_P, s->L, v, &s->c);
  y = cholmod_solve(CHOLMOD_L, s->L, u, &s->c);
  cholmod_free_dense(&u, &s->c);
  cholmod_free_dense(&v, &s->c);
  PetscCall(CholCheck(&s->c, "forward solve"));
  ya = (PetscScalar *)y->x;
  /* r_Gamma = b_Gamma + sum_p L_GG y_G  (L_GG y_G = -S(G,I) S(I,I)^{-1} b_I) */
  if (G) {
    PetscCall(PetscArrayzero(s->rG, G));
    if (gp) {
      for (PetscInt l = 0; l < gp; l++) s->work[l] = ya[s->gpos[l]];
      PetscCall(PetscBLASIntCast(gp, &bgp));
      BLAStrmv_("L", "N", "N", &bgp, s->LG, &bgp, s->work, &one);
      for (PetscInt l = 0; l < gp; l++) s->rG[s->gglob[l]] += s->work[l];
    }
    PetscCall(VecGetArrayRead(b, &ba));
    for (PetscInt i = 0; i < s->nown; i++)
      if (s->own_loc[i] < 0) s->rG[-1 - s->own_loc[i]] += ba[i];
    PetscCall(VecRestoreArrayRead(b, &ba));
    PetscCall(MPIU_Allreduce(MPI_IN_PLACE, s->rG, (PetscMPIInt)G, MPIU_SCALAR, MPIU_SUM, comm));
    PetscCall(PetscBLASIntCast(G, &bG));
    LAPACKpotrs_("L", &bG, &one, s->SG, &bG, s->rG, &bG, &info); /* rG = x_Gamma */
    PetscCheck(!info, PETSC_COMM_SELF, PETSC_ERR_LIB, "cssubchol: LAPACK potrs info %d", (int)info);
    /* backward data: y_G = L_GG^T x_G */
    if (gp) {
      for (PetscInt l = 0; l < gp; l++) s->work[l] = s->rG[s->gglob[l]];
      BLAStrmv_("L", "T", "N", &bgp, s->LG, &bgp, s->work, &one);
      for (PetscInt l = 0; l < gp; l++) ya[s->gpos[l]] = s->work[l];
    }
  }
  /* backward: x_loc = P^T L^{-T} y */
  u = cholmod_solve(CHOLMOD_Lt, s->L, y, &s->c);
  z = cholmod_solve(CHOLMOD_Pt, s->L, u, &s->c);
  cholmod_free_dense(&u, &s->c);
  cholmod_free_dense(&y, &s->c);
  PetscCall(CholCheck(&s->c, "backward solve"));
  PetscCall(VecGetOwnershipRange(x, &rstart, NULL));
  PetscCall(VecGetArray(x, &xa));
  for (PetscInt i = 0; i < s->nown; i++) xa[i] = s->own_loc[i] >= 0 ? ((PetscScalar *)z->x)[s->own_loc[i]] : s->rG[-1 - s->own_loc[i]];
  PetscCall(VecRestoreArray(x, &xa));
  cholmod_free_dense(&z, &s->c);
  PetscCall(PetscLogEventEnd(EV_Solve, pc, b, x, 0));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCReset_SubChol(PC pc)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscFunctionBeginUser;
  PetscCall(ResetSymbolic(s));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCDestroy_SubChol(PC pc)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscFunctionBeginUser;
  PetscCall(ResetSymbolic(s));
  if (s->started) cholmod_finish(&s->c);
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "CSSubCholGetInterfaceSize_C", NULL));
  PetscCall(PetscFree(pc->data));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetFromOptions_SubChol(PC pc, PetscOptionItems *PetscOptionsObject)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscBool   ok, a, b, c;
  PetscFunctionBeginUser;
  PetscOptionsHeadBegin(PetscOptionsObject, "Substructured CHOLMOD Cholesky (cssubchol)");
  PetscCall(PetscOptionsString("-pc_cssubchol_ordering", "Ordering of each rank's interior: metis|amd|nesdis", NULL, s->ordering, s->ordering, sizeof(s->ordering), NULL));
  PetscOptionsHeadEnd();
  PetscCall(PetscStrcmp(s->ordering, "metis", &a));
  PetscCall(PetscStrcmp(s->ordering, "amd", &b));
  PetscCall(PetscStrcmp(s->ordering, "nesdis", &c));
  ok = (PetscBool)(a || b || c);
  PetscCheck(ok, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_OUTOFRANGE, "-%spc_cssubchol_ordering %s: use metis, amd or nesdis", ((PetscObject)pc)->prefix ? ((PetscObject)pc)->prefix : "", s->ordering);
  PetscFunctionReturn(0);
}

static PetscErrorCode PCView_SubChol(PC pc, PetscViewer viewer)
{
  PC_SubChol *s = (PC_SubChol *)pc->data;
  PetscBool   ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (ascii) {
    PetscCall(PetscViewerASCIIPrintf(viewer, "  substructured CHOLMOD Cholesky: interior ordering %s, interface %" PetscInt_FMT " dofs (dense, redundant)\n", s->ordering, s->G));
    PetscCall(PetscViewerASCIIPushSynchronized(viewer));
    if (s->L) PetscCall(PetscViewerASCIISynchronizedPrintf(viewer, "    [local] %" PetscInt_FMT " dofs, %" PetscInt_FMT " on the interface, factor %.3g entries, %.3g flops\n", s->m, s->gp, s->c.lnz, s->c.fl));
    PetscCall(PetscViewerFlush(viewer));
    PetscCall(PetscViewerASCIIPopSynchronized(viewer));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode GetInterfaceSize_SubChol(PC pc, PetscInt *G)
{
  PetscFunctionBeginUser;
  *G = ((PC_SubChol *)pc->data)->G;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSubCholGetInterfaceSize(PC pc, PetscInt *G)
{
  PetscFunctionBeginUser;
  *G = 0;
  PetscTryMethod(pc, "CSSubCholGetInterfaceSize_C", (PC, PetscInt *), (pc, G));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCCreate_SubChol(PC pc)
{
  PC_SubChol *s;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&s));
  PetscCall(PetscStrncpy(s->ordering, "metis", sizeof(s->ordering)));
  pc->data                 = s;
  pc->ops->setup           = PCSetUp_SubChol;
  pc->ops->apply           = PCApply_SubChol;
  pc->ops->reset           = PCReset_SubChol;
  pc->ops->destroy         = PCDestroy_SubChol;
  pc->ops->setfromoptions  = PCSetFromOptions_SubChol;
  pc->ops->view            = PCView_SubChol;
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "CSSubCholGetInterfaceSize_C", GetInterfaceSize_SubChol));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSubCholRegister(void)
{
  static PetscBool done = PETSC_FALSE;
  PetscFunctionBeginUser;
  if (done) PetscFunctionReturn(0);
  PetscCall(PCRegister("cssubchol", PCCreate_SubChol));
  PetscCall(PetscLogEventRegister("CSSubCholSym", PC_CLASSID, &EV_Sym));
  PetscCall(PetscLogEventRegister("CSSubCholNum", PC_CLASSID, &EV_Num));
  PetscCall(PetscLogEventRegister("CSSubCholDense", PC_CLASSID, &EV_Dense));
  PetscCall(PetscLogEventRegister("CSSubCholSolve", PC_CLASSID, &EV_Solve));
  done = PETSC_TRUE;
  PetscFunctionReturn(0);
}
