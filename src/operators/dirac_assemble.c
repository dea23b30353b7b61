/* The quaternionic Dirac operator assembled face by face (crane2011 Sec. 5.2-5.4, crane2013 App. G) into real
   AIJ matrices with 4x4 blocks (crane2011 Sec. 5.1). See include/cs_operators_dirac.h for the conventions. */
#include "cs_operators_dirac.h"

PetscErrorCode CSDiracCreateDM(CSMesh mesh, const PetscInt vdofs[], DM *dm)
{
  PetscSection s;
  PetscInt     pStart, pEnd, vS, vE;
  PetscFunctionBeginUser;
  PetscCall(DMClone(mesh->dm, dm));
  PetscCall(PetscObjectSetName((PetscObject)*dm, vdofs ? "quaternion_reduced" : "quaternion"));
  PetscCall(DMPlexGetChart(mesh->dm, &pStart, &pEnd));
  PetscCall(DMPlexGetDepthStratum(mesh->dm, 0, &vS, &vE));
  PetscCall(PetscSectionCreate(mesh->comm, &s));
  if (!vdofs) {
    PetscCall(PetscSectionSetNumFields(s, 1));
    PetscCall(PetscSectionSetFieldComponents(s, 0, 4));
  }
  PetscCall(PetscSectionSetChart(s, pStart, pEnd));
  for (PetscInt p = vS; p < vE; p++) {
    PetscInt dof = vdofs ? vdofs[p - vS] : 4;
    PetscCall(PetscSectionSetDof(s, p, dof));
    if (!vdofs) PetscCall(PetscSectionSetFieldDof(s, p, 0, dof));
  }
  PetscCall(PetscSectionSetUp(s));
  PetscCall(DMSetLocalSection(*dm, s));
  PetscCall(PetscSectionDestroy(&s));
  PetscCall(DMSetMatType(*dm, MATAIJ));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDiracGetRho(CSMesh mesh, CSRhoLocation loc, Vec rho, Vec *rl, const PetscScalar **r)
{
  PetscFunctionBeginUser;
  *rl = NULL;
  *r  = NULL;
  if (!rho || loc == CS_RHO_NONE) PetscFunctionReturn(0);
  if (loc == CS_RHO_VERTEX) {
    PetscCall(DMGetLocalVector(mesh->dmV1, rl));
    PetscCall(DMGlobalToLocal(mesh->dmV1, rho, INSERT_VALUES, *rl));
    PetscCall(VecGetArrayRead(*rl, r));
  } else {
    PetscInt n;
    PetscCall(VecGetLocalSize(rho, &n));
    PetscCheck(n == mesh->nf, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "per-face rho has %" PetscInt_FMT " local entries, the mesh %" PetscInt_FMT " local faces", n, mesh->nf);
    PetscCall(VecGetArrayRead(rho, r));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSDiracRestoreRho(CSMesh mesh, CSRhoLocation loc, Vec rho, Vec *rl, const PetscScalar **r)
{
  PetscFunctionBeginUser;
  if (!rho || loc == CS_RHO_NONE) PetscFunctionReturn(0);
  if (loc == CS_RHO_VERTEX) {
    PetscCall(VecRestoreArrayRead(*rl, r));
    PetscCall(DMRestoreLocalVector(mesh->dmV1, rl));
  } else PetscCall(VecRestoreArrayRead(rho, r));
  PetscFunctionReturn(0);
}

/* One face: the three coefficients a_j of row k of A = D - R and the area. */
void CSDiracFaceCoefficients(CSMesh mesh, const PetscReal *p, CSRhoLocation loc, const PetscScalar *r, PetscInt f, PetscReal a[3][4], PetscReal *area)
{
  const PetscInt  *v    = mesh->faceVert + 3 * f;
  const PetscReal *c[3] = {p + 3 * v[0], p + 3 * v[1], p + 3 * v[2]};
  PetscReal        an[3], A;
  CSTriangleAreaVector(c, an);
  A = CSVecNorm(an);
  for (int j = 0; j < 3; j++) {
    PetscReal e[3], rj = 0;
    /* crane2011 Eq. 5: e_j is the edge opposite corner j, counter-clockwise: from corner j+1 to corner j+2 */
    CSVecSub(c[(j + 2) % 3], c[(j + 1) % 3], e);
    if (r) rj = PetscRealPart(loc == CS_RHO_VERTEX ? r[v[j]] : r[f]);
    a[j][0] = -rj / 3; /* -R_kj, crane2011 Sec. 5.3 (B_kj = 1/3) */
    for (int d = 0; d < 3; d++) a[j][d + 1] = -e[d] / (2 * A);
  }
  *area = A;
}

/* Block (vertex) local-to-global mapping of dm: block v -> global dof(4v) / 4. */
static PetscErrorCode BlockMapping(CSMesh mesh, DM dm, ISLocalToGlobalMapping *bmap)
{
  ISLocalToGlobalMapping ltog;
  PetscInt              *b;
  PetscFunctionBeginUser;
  PetscCall(DMGetLocalToGlobalMapping(dm, &ltog));
  PetscCall(PetscMalloc1(mesh->nv, &b));
  for (PetscInt v = 0; v < mesh->nv; v++) b[v] = 4 * v;
  PetscCall(ISLocalToGlobalMappingApply(ltog, mesh->nv, b, b));
  for (PetscInt v = 0; v < mesh->nv; v++) b[v] /= 4;
  PetscCall(ISLocalToGlobalMappingCreate(mesh->comm, 4, mesh->nv, b, PETSC_OWN_POINTER, bmap));
  PetscFunctionReturn(0);
}

typedef struct {
  PetscInt    *ii, *jj;
  PetscScalar *xa;
} CSRArrays;

static PetscErrorCode FreeCSR(void *ctx)
{
  CSRArrays *c = (CSRArrays *)ctx;
  PetscFunctionBeginUser;
  PetscCall(PetscFree3(c->ii, c->jj, c->xa));
  PetscCall(PetscFree(c));
  PetscFunctionReturn(0);
}

/* BAIJ -> AIJ. In serial directly from the block CSR (SeqBAIJ stores each block column-major; the AIJ rows
   4i+s list the blocks of row i in order, so the columns stay sorted) -- MatConvert took 0.25 s for the 75k-face
   bunny, this ~10 ms, and MAT_REUSE_MATRIX just overwrites the values. In parallel MatConvert. */
static PetscErrorCode BAIJToAIJ(Mat Xb, MatReuse reuse, Mat *X)
{
  PetscMPIInt     size;
  const PetscInt *ia, *ja;
  PetscInt        nb;
  PetscBool       done;
  PetscScalar    *aa, *xa;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(PetscObjectComm((PetscObject)Xb), &size));
  if (size > 1) {
    PetscCall(MatConvert(Xb, MATAIJ, reuse, X));
    PetscFunctionReturn(0);
  }
  /* inodecompressed = TRUE: the block (vertex) structure of a BAIJ matrix */
  PetscCall(MatGetRowIJ(Xb, 0, PETSC_FALSE, PETSC_TRUE, &nb, &ia, &ja, &done));
  PetscCheck(done, PETSC_COMM_SELF, PETSC_ERR_PLIB, "MatGetRowIJ failed");
  PetscCall(MatSeqBAIJGetArray(Xb, &aa));
  if (reuse == MAT_INITIAL_MATRIX) {
    PetscInt *ii, *jj, n = 0;
    PetscCall(PetscMalloc3(4 * nb + 1, &ii, 16 * ia[nb], &jj, 16 * ia[nb], &xa));
    ii[0] = 0;
    for (PetscInt i = 0; i < nb; i++)
      for (PetscInt s = 0; s < 4; s++) {
        for (PetscInt k = ia[i]; k < ia[i + 1]; k++)
          for (PetscInt t = 0; t < 4; t++) {
            jj[n]   = 4 * ja[k] + t;
            xa[n++] = aa[16 * k + 4 * t + s];
          }
        ii[4 * i + s + 1] = n;
      }
    PetscContainer owner;
    CSRArrays     *csr;
    /* the matrix uses the arrays in place (MatSeqAIJSetPreallocationCSR copied them entry by entry: 50 ms at
       14k vertices); the container frees them with the matrix */
    PetscCall(MatCreateSeqAIJWithArrays(PETSC_COMM_SELF, 4 * nb, 4 * nb, ii, jj, xa, X));
    PetscCall(MatSetBlockSize(*X, 4));
    PetscCall(PetscContainerCreate(PETSC_COMM_SELF, &owner));
    PetscCall(PetscNew(&csr));
    csr->ii = ii;
    csr->jj = jj;
    csr->xa = xa;
    PetscCall(PetscContainerSetPointer(owner, csr));
    PetscCall(PetscContainerSetUserDestroy(owner, FreeCSR));
    PetscCall(PetscObjectCompose((PetscObject)*X, "CSDiracCSR", (PetscObject)owner));
    PetscCall(PetscContainerDestroy(&owner));
  } else {
    PetscInt n = 0;
    PetscCall(MatSeqAIJGetArray(*X, &xa));
    for (PetscInt i = 0; i < nb; i++)
      for (PetscInt s = 0; s < 4; s++)
        for (PetscInt k = ia[i]; k < ia[i + 1]; k++)
          for (PetscInt t = 0; t < 4; t++) xa[n++] = aa[16 * k + 4 * t + s];
    PetscCall(MatSeqAIJRestoreArray(*X, &xa));
  }
  PetscCall(MatSeqBAIJRestoreArray(Xb, &aa));
  PetscCall(MatRestoreRowIJ(Xb, 0, PETSC_FALSE, PETSC_TRUE, &nb, &ia, &ja, &done));
  PetscFunctionReturn(0);
}

/* Shared assembly of X (kind 0: A_k conj(a_i) a_j) and Y (kind 1: A_k/3 a_j). The 4x4 blocks are added to a
   BAIJ matrix (one insertion per block instead of 16: 4-8x faster) that is then converted to the AIJ matrix
   the factorisations (CHOLMOD, MUMPS Cholesky) need. The BAIJ work matrix is kept on *X for MAT_REUSE_MATRIX. */
static PetscErrorCode AssembleBlocks(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, PetscInt kind, MatReuse reuse, Mat *X)
{
  Vec                xl, rl;
  const PetscReal   *p;
  const PetscScalar *r;
  Mat                Xb;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_Assemble, 0, 0, 0, 0));
  if (reuse == MAT_INITIAL_MATRIX) {
    ISLocalToGlobalMapping bmap;
    PetscCall(CSOperatorCreateVertexMatrix(mesh, dm, 4, MATBAIJ, &Xb));
    PetscCall(BlockMapping(mesh, dm, &bmap));
    PetscCall(MatSetLocalToGlobalMapping(Xb, bmap, bmap));
    PetscCall(ISLocalToGlobalMappingDestroy(&bmap));
  } else {
    PetscCall(PetscObjectQuery((PetscObject)*X, "CSDiracBAIJ", (PetscObject *)&Xb));
    PetscCheck(Xb, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "MAT_REUSE_MATRIX needs a matrix made by CSDiracAssemble");
    PetscCall(PetscObjectReference((PetscObject)Xb));
    PetscCall(MatZeroEntries(Xb));
  }
  PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &p));
  PetscCall(CSDiracGetRho(mesh, loc, rho, &rl, &r));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, NULL, &F);) {
    const PetscInt  f = F.f, *v = F.v;
    PetscReal       a[3][4], A;
    PetscScalar     K[144];
    CSDiracFaceCoefficients(mesh, p, loc, r, f, a, &A);
    for (int i = 0; i < 3; i++) {
      for (int j = 0; j < 3; j++) {
        PetscReal   q[4];
        PetscScalar blk[16];
        if (kind == 0) {
          CSQuatConjMul(a[i], a[j], q); /* crane2013 App. G: X_ij = A conj(a_i) a_j */
          for (int c = 0; c < 4; c++) q[c] *= A;
        } else {
          for (int c = 0; c < 4; c++) q[c] = A / 3 * a[j][c]; /* (B^H M_F A)_ij */
        }
        CSQuatBlock(q, blk);
        for (int s = 0; s < 4; s++)
          for (int t = 0; t < 4; t++) K[(4 * i + s) * 12 + 4 * j + t] = blk[4 * s + t];
      }
    }
    PetscCall(MatSetValuesBlockedLocal(Xb, 3, v, 3, v, K, ADD_VALUES));
  }
  PetscCall(CSDiracRestoreRho(mesh, loc, rho, &rl, &r));
  PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &p));
  PetscCall(MatAssemblyBegin(Xb, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(Xb, MAT_FINAL_ASSEMBLY));
  PetscCall(BAIJToAIJ(Xb, reuse, X));
  if (reuse == MAT_INITIAL_MATRIX) {
    ISLocalToGlobalMapping ltog;
    PetscCall(DMGetLocalToGlobalMapping(dm, &ltog));
    PetscCall(MatSetLocalToGlobalMapping(*X, ltog, ltog));
    PetscCall(PetscObjectCompose((PetscObject)*X, "CSDiracBAIJ", (PetscObject)Xb));
    if (kind == 0) PetscCall(MatSetOption(*X, MAT_SYMMETRIC, PETSC_TRUE));
    if (kind == 0) PetscCall(MatSetOption(*X, MAT_SYMMETRY_ETERNAL, PETSC_TRUE));
  }
  PetscCall(MatDestroy(&Xb));
  PetscCall(PetscLogEventEnd(CS_EVENT_Assemble, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDiracAssemble(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, MatReuse reuse, Mat *X)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleBlocks(mesh, dm, x, loc, rho, 0, reuse, X));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDiracAssembleBA(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, MatReuse reuse, Mat *Y)
{
  PetscFunctionBeginUser;
  PetscCall(AssembleBlocks(mesh, dm, x, loc, rho, 1, reuse, Y));
  PetscFunctionReturn(0);
}

PetscErrorCode CSDiracCreateFaceOperators(CSMesh mesh, DM dm, Vec x, CSRhoLocation loc, Vec rho, Mat *Dm, Mat *Bm, Mat *Am, Vec *MF)
{
  ISLocalToGlobalMapping ltog;
  Vec                    xl, rl, g;
  const PetscReal       *p;
  const PetscScalar     *r;
  PetscInt               fstart = 0, ncol, nf = mesh->nf;
  Mat                    M[3] = {NULL, NULL, NULL};
  PetscScalar           *mf   = NULL;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Exscan(&nf, &fstart, 1, MPIU_INT, MPI_SUM, mesh->comm));
  {
    PetscMPIInt rank;
    PetscCallMPI(MPI_Comm_rank(mesh->comm, &rank));
    if (!rank) fstart = 0;
  }
  PetscCall(DMGetLocalToGlobalMapping(dm, &ltog));
  PetscCall(DMGetGlobalVector(dm, &g));
  PetscCall(VecGetLocalSize(g, &ncol));
  PetscCall(DMRestoreGlobalVector(dm, &g));
  for (int m = 0; m < 3; m++) {
    if ((m == 0 && !Dm) || (m == 1 && !Bm) || (m == 2 && !Am)) continue;
    PetscCall(MatCreateAIJ(mesh->comm, 4 * nf, ncol, PETSC_DETERMINE, PETSC_DETERMINE, 12, NULL, 12, NULL, &M[m]));
    PetscCall(MatSetBlockSizes(M[m], 4, 4));
  }
  if (MF) {
    PetscCall(VecCreateMPI(mesh->comm, 4 * nf, PETSC_DETERMINE, MF));
    PetscCall(VecGetArray(*MF, &mf));
  }
  PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &p));
  PetscCall(CSDiracGetRho(mesh, loc, rho, &rl, &r));
  for (PetscInt f = 0; f < nf; f++) {
    const PetscInt *v = mesh->faceVert + 3 * f;
    PetscReal       a[3][4], A;
    PetscInt        rows[4], cols[12];
    CSDiracFaceCoefficients(mesh, p, loc, r, f, a, &A);
    for (int s = 0; s < 4; s++) rows[s] = 4 * (fstart + f) + s;
    for (int j = 0; j < 3; j++)
      for (int s = 0; s < 4; s++) cols[4 * j + s] = 4 * v[j] + s;
    PetscCall(ISLocalToGlobalMappingApply(ltog, 12, cols, cols));
    for (int m = 0; m < 3; m++) {
      PetscScalar K[48];
      if (!M[m]) continue;
      for (int j = 0; j < 3; j++) {
        PetscReal   q[4];
        PetscScalar blk[16];
        if (m == 0) { /* D_kj = -e_j/(2A) */
          q[0] = 0;
          for (int c = 1; c < 4; c++) q[c] = a[j][c];
        } else if (m == 1) { /* B_kj = 1/3 */
          q[0] = 1.0 / 3;
          q[1] = q[2] = q[3] = 0;
        } else
          for (int c = 0; c < 4; c++) q[c] = a[j][c];
        CSQuatBlock(q, blk);
        for (int s = 0; s < 4; s++)
          for (int t = 0; t < 4; t++) K[12 * s + 4 * j + t] = blk[4 * s + t];
      }
      PetscCall(MatSetValues(M[m], 4, rows, 12, cols, K, INSERT_VALUES));
    }
    if (mf)
      for (int s = 0; s < 4; s++) mf[4 * f + s] = A;
  }
  PetscCall(CSDiracRestoreRho(mesh, loc, rho, &rl, &r));
  PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &p));
  if (MF) PetscCall(VecRestoreArray(*MF, &mf));
  for (int m = 0; m < 3; m++) {
    if (!M[m]) continue;
    PetscCall(MatAssemblyBegin(M[m], MAT_FINAL_ASSEMBLY));
    PetscCall(MatAssemblyEnd(M[m], MAT_FINAL_ASSEMBLY));
  }
  if (Dm) *Dm = M[0];
  if (Bm) *Bm = M[1];
  if (Am) *Am = M[2];
  PetscFunctionReturn(0);
}

PetscErrorCode CSDiracFaceApply(CSMesh mesh, DM dm, Vec x, Vec mu, PetscReal Dmu[], PetscReal Bmu[])
{
  Vec                xl, ml;
  const PetscReal   *p;
  const PetscScalar *m;
  PetscFunctionBeginUser;
  PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &p));
  PetscCall(DMGetLocalVector(dm, &ml));
  PetscCall(DMGlobalToLocal(dm, mu, INSERT_VALUES, ml));
  PetscCall(VecGetArrayRead(ml, &m));
  for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, NULL, &F);) {
    const PetscInt  f = F.f, *v = F.v;
    PetscReal       a[3][4], A;
    CSDiracFaceCoefficients(mesh, p, CS_RHO_NONE, NULL, f, a, &A);
    for (int c = 0; c < 4; c++) Dmu[4 * f + c] = Bmu[4 * f + c] = 0;
    for (int j = 0; j < 3; j++) {
      PetscReal q[4], t[4];
      for (int c = 0; c < 4; c++) q[c] = PetscRealPart(m[4 * v[j] + c]);
      CSQuatMul(a[j], q, t); /* crane2011 Eq. 5: (D mu)_k = sum_j -e_j/(2A) mu_j */
      CSQuatAXPY(1, t, Dmu + 4 * f);
      CSQuatAXPY(1.0 / 3, q, Bmu + 4 * f);
    }
  }
  PetscCall(VecRestoreArrayRead(ml, &m));
  PetscCall(DMRestoreLocalVector(dm, &ml));
  PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &p));
  PetscFunctionReturn(0);
}
