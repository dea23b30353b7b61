/* The eigenvalue problem of spin transformations (crane2011 Sec. 5.5, 5.7): the smallest eigenpair of
     (AV)^* (AV) lam^ = gamma lam^          (Eq. 7, standard; V = M_V^{-1/2} rescaled to mean 1), or
     A^* A lam = gamma B^* A lam            (Eq. 6, generalised, -spin_problem generalized),
   optionally restricted to lam = V U lam^ with the boundary parametrisation U of Sec. 5.7.
   Solved with SLEPc EPS (prefix spin_: shift-and-invert toward a small negative target with a Cholesky
   factorisation by default; every part selectable by -spin_eps_*, -spin_st_*, the factorisation by
   -spin_st_pc_factor_mat_solver_type csquat|cscholmod|cholmod|mumps) or by inverse iteration with a kept
   factorisation (-spin_solver inverse, KSP prefix spin_inverse_; crane2013 Sec. 6.4.2). The default solvers and
   why: docs/solvers.md. */
#include "spin_impl.h"
#include "cs_linalg.h"
#include "cs_package.h"
#include "cs_util.h"

/* M_V and V = M_V^{-1/2} divided by its mean (Sec. 5.5: "improved numerics if the entries of V are rescaled to
   have mean value 1"). */
static PetscErrorCode ComputeScaling(CSSpin s, Vec x)
{
  const PetscScalar *m;
  PetscScalar       *v;
  PetscInt           n;
  PetscReal          sum = 0;
  PetscFunctionBeginUser;
  if (!s->mass) PetscCall(DMCreateGlobalVector(s->mesh->dmV1, &s->mass));
  if (!s->v4) PetscCall(DMCreateGlobalVector(s->dm, &s->v4));
  PetscCall(CSGeometryVertexAreas(s->mesh, x, s->mass));
  PetscCall(VecGetLocalSize(s->mass, &n));
  PetscCall(VecGetArrayRead(s->mass, &m));
  for (PetscInt i = 0; i < n; i++) {
    PetscCheck(PetscRealPart(m[i]) > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "vertex with zero area");
    sum += 1 / PetscSqrtReal(PetscRealPart(m[i]));
  }
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, &sum, 1, MPIU_REAL, MPIU_SUM, s->mesh->comm));
  s->vmean = sum / s->mesh->Nv;
  PetscCall(VecGetArray(s->v4, &v));
  for (PetscInt i = 0; i < n; i++)
    for (int c = 0; c < 4; c++) v[4 * i + c] = 1 / PetscSqrtReal(PetscRealPart(m[i])) / s->vmean;
  PetscCall(VecRestoreArray(s->v4, &v));
  PetscCall(VecRestoreArrayRead(s->mass, &m));
  PetscFunctionReturn(0);
}

/* P = V U (crane2011 Sec. 5.7): on interior vertices V_i I_4; on boundary vertex i the 4x2 block
   V_i [W_i | W_i T~_i], lam_i = W_i (a + b T~_i). W_i rotates the current tangent T_i into T~_i under the
   similarity lam -> conj(lam) v lam: W_i = cos(theta/2) - sin(theta/2) w with w = T x T~ / sin(theta).
   NOTE: the paper writes cos(theta/2) + w sin(theta/2); with its own convention d f~ = conj(lam) df lam (Eq. 1)
   conj(W) T W is T rotated by -theta about w, away from T~, so the sign of the sine term is flipped here
   (the sign check: docs/solvers.md, "Spin boundary rotation"). */
static PetscErrorCode BuildBoundaryMap(CSSpin s, Vec x)
{
  CSMesh                 mesh = s->mesh;
  PetscInt              *vdofs, vS, vE, nrow, ncol;
  PetscSection           sr;
  ISLocalToGlobalMapping l4, lr;
  Vec                    T, Tl, Ttl, g, v4l = NULL;
  const PetscScalar     *t, *tt, *v = NULL;
  PetscFunctionBeginUser;
  if (!s->dmr) {
    PetscCall(PetscMalloc1(mesh->nv, &vdofs));
    for (PetscInt i = 0; i < mesh->nv; i++) vdofs[i] = mesh->vertBoundary[i] ? 2 : 4;
    PetscCall(CSDiracCreateDM(mesh, vdofs, &s->dmr));
    PetscCall(PetscFree(vdofs));
  }
  PetscCall(MatDestroy(&s->P));
  PetscCall(DMPlexGetDepthStratum(mesh->dm, 0, &vS, &vE));
  PetscCall(DMGetLocalSection(s->dmr, &sr));
  PetscCall(DMGetLocalToGlobalMapping(s->dm, &l4));
  PetscCall(DMGetLocalToGlobalMapping(s->dmr, &lr));
  PetscCall(DMGetGlobalVector(s->dm, &g));
  PetscCall(VecGetLocalSize(g, &nrow));
  PetscCall(DMRestoreGlobalVector(s->dm, &g));
  PetscCall(DMGetGlobalVector(s->dmr, &g));
  PetscCall(VecGetLocalSize(g, &ncol));
  PetscCall(DMRestoreGlobalVector(s->dmr, &g));
  PetscCall(MatCreateAIJ(mesh->comm, nrow, ncol, PETSC_DETERMINE, PETSC_DETERMINE, 4, NULL, 0, NULL, &s->P));
  PetscCall(DMCreateGlobalVector(mesh->dmV3, &T));
  if (s->Vcur) PetscCall(VecCopy(s->Vcur, T)); /* crane2013 Sec. 6.3.1: any direction V, not only T */
  else PetscCall(CSGeometryBoundaryTangents(mesh, x, T));
  PetscCall(DMGetLocalVector(mesh->dmV3, &Tl));
  PetscCall(DMGetLocalVector(mesh->dmV3, &Ttl));
  PetscCall(DMGlobalToLocal(mesh->dmV3, T, INSERT_VALUES, Tl));
  PetscCall(DMGlobalToLocal(mesh->dmV3, s->Ttarget ? s->Ttarget : T, INSERT_VALUES, Ttl));
  if (!s->generalized) {
    PetscCall(DMGetLocalVector(s->dm, &v4l));
    PetscCall(DMGlobalToLocal(s->dm, s->v4, INSERT_VALUES, v4l));
    PetscCall(VecGetArrayRead(v4l, &v));
  }
  PetscCall(VecGetArrayRead(Tl, &t));
  PetscCall(VecGetArrayRead(Ttl, &tt));
  for (PetscInt i = 0; i < mesh->nv; i++) {
    PetscInt    rows[4], cols[4], off, nc;
    PetscScalar K[16];
    PetscReal   Vi = v ? PetscRealPart(v[4 * i]) : 1;
    if (!mesh->vertOwned[i]) continue;
    PetscCall(PetscSectionGetOffset(sr, vS + i, &off));
    for (int c = 0; c < 4; c++) rows[c] = 4 * i + c;
    PetscCall(ISLocalToGlobalMappingApply(l4, 4, rows, rows));
    if (!mesh->vertBoundary[i]) {
      nc = 4;
      for (int c = 0; c < 16; c++) K[c] = (c % 5 == 0) ? Vi : 0;
    } else {
      PetscReal T0[3], T1[3], w[3], sn, cs, nt0, nt1, W[4], Tq[4], WT[4];
      for (int d = 0; d < 3; d++) {
        T0[d] = PetscRealPart(t[3 * i + d]);
        T1[d] = PetscRealPart(tt[3 * i + d]);
      }
      nt0 = CSVecNorm(T0);
      nt1 = CSVecNorm(T1);
      PetscCheck(nt0 > 0, PETSC_COMM_SELF, PETSC_ERR_PLIB, "boundary vertex %" PetscInt_FMT " without outgoing boundary edge", mesh->vertNatural[i]);
      PetscCheck(nt1 > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "-%sboundary: zero target tangent at boundary vertex %" PetscInt_FMT " (file order)", s->hdr.prefix, mesh->vertNatural[i]);
      for (int d = 0; d < 3; d++) {
        T0[d] /= nt0;
        T1[d] /= nt1;
      }
      CSVecCross(T0, T1, w);
      sn = CSVecNorm(w);
      cs = CSVecDot(T0, T1);
      if (sn < 1e-12) { /* T~ = +-T: any axis orthogonal to T */
        PetscReal e[3] = {1, 0, 0};
        if (PetscAbsReal(T0[0]) > 0.9) {
          e[0] = 0;
          e[1] = 1;
        }
        CSVecCross(T0, e, w);
        sn = CSVecNorm(w);
        for (int d = 0; d < 3; d++) w[d] /= sn;
        sn = 0;
      } else
        for (int d = 0; d < 3; d++) w[d] /= sn;
      {
        PetscReal th = PetscAtan2Real(sn, cs);
        W[0]         = PetscCosReal(th / 2);
        for (int d = 0; d < 3; d++) W[d + 1] = -PetscSinReal(th / 2) * w[d];
      }
      Tq[0] = 0;
      for (int d = 0; d < 3; d++) Tq[d + 1] = T1[d];
      CSQuatMul(W, Tq, WT);
      nc = 2;
      for (int c = 0; c < 4; c++) {
        K[2 * c]     = Vi * W[c];
        K[2 * c + 1] = Vi * WT[c];
      }
    }
    for (int c = 0; c < nc; c++) cols[c] = off + c;
    PetscCall(ISLocalToGlobalMappingApply(lr, nc, cols, cols));
    PetscCall(MatSetValues(s->P, 4, rows, nc, cols, K, INSERT_VALUES));
  }
  PetscCall(VecRestoreArrayRead(Tl, &t));
  PetscCall(VecRestoreArrayRead(Ttl, &tt));
  if (v4l) {
    PetscCall(VecRestoreArrayRead(v4l, &v));
    PetscCall(DMRestoreLocalVector(s->dm, &v4l));
  }
  PetscCall(DMRestoreLocalVector(mesh->dmV3, &Tl));
  PetscCall(DMRestoreLocalVector(mesh->dmV3, &Ttl));
  PetscCall(VecDestroy(&T));
  PetscCall(MatAssemblyBegin(s->P, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(s->P, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetBoundaryDirections(CSSpin s, Vec V, Vec Vt)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&s->Vcur));
  if (V) {
    PetscCall(VecDuplicate(V, &s->Vcur));
    PetscCall(VecCopy(V, s->Vcur));
  }
  PetscCall(CSSpinSetBoundaryTangents(s, Vt ? Vt : V));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSetBoundaryTangents(CSSpin s, Vec Ttarget)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&s->Ttarget));
  if (Ttarget) {
    PetscCall(VecDuplicate(Ttarget, &s->Ttarget));
    PetscCall(VecCopy(Ttarget, s->Ttarget));
  }
  PetscFunctionReturn(0);
}

/* The operators of the problem for (x, rho): K (and Y for Eq. 6), in the reduced space when P is set. */
static PetscErrorCode BuildOperators(CSSpin s, Vec x, CSRhoLocation loc, Vec rho)
{
  PetscFunctionBeginUser;
  PetscCall(ComputeScaling(s, x));
  if (s->boundary != CS_SPIN_BOUNDARY_NONE) PetscCall(BuildBoundaryMap(s, x));
  if (s->shell) {
    PetscCall(MatDestroy(&s->K));
    PetscCall(CSDiracCreateShell(s->mesh, s->dm, x, loc, rho, &s->K));
    PetscCall(MatDiagonalScale(s->K, s->v4, s->v4));
    /* the assembled copy only preconditions the inner solve (set up in SetupEPS) */
    PetscCall(CSDiracAssemble(s->mesh, s->dm, x, loc, rho, s->X ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->X));
    PetscCall(MatDiagonalScale(s->X, s->v4, s->v4));
    PetscFunctionReturn(0);
  }
  PetscCall(CSDiracAssemble(s->mesh, s->dm, x, loc, rho, s->X ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->X));
  if (s->generalized) {
    if (s->P) {
      Mat Yfull;
      PetscCall(CSDiracAssembleBA(s->mesh, s->dm, x, loc, rho, MAT_INITIAL_MATRIX, &Yfull));
      PetscCall(MatDestroy(&s->K));
      PetscCall(MatDestroy(&s->Y));
      PetscCall(MatPtAP(s->X, s->P, MAT_INITIAL_MATRIX, 2.0, &s->K));
      PetscCall(MatPtAP(Yfull, s->P, MAT_INITIAL_MATRIX, 2.0, &s->Y));
      PetscCall(MatDestroy(&Yfull));
    } else {
      PetscCall(CSDiracAssembleBA(s->mesh, s->dm, x, loc, rho, s->Y ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->Y));
      PetscCall(PetscObjectReference((PetscObject)s->X));
      PetscCall(MatDestroy(&s->K));
      s->K = s->X;
    }
  } else if (s->P) {
    PetscCall(MatDestroy(&s->K));
    PetscCall(MatPtAP(s->X, s->P, MAT_INITIAL_MATRIX, 2.0, &s->K));
    PetscCall(MatSetOption(s->K, MAT_SYMMETRIC, PETSC_TRUE));
  } else {
    PetscCall(MatDiagonalScale(s->X, s->v4, s->v4)); /* K = V X V in place */
    PetscCall(PetscObjectReference((PetscObject)s->X));
    PetscCall(MatDestroy(&s->K));
    s->K = s->X;
  }
  PetscFunctionReturn(0);
}

/* The target sigma in the units of K: the spectrum of Eq. 7 on a unit sphere is n^2, so a dimensionless
   shift tau corresponds to gamma = tau 4 pi / area; K = V X V has eigenvalues gamma / vmean^2. For Eq. 6
   (eigenvalues ~ n, unscaled) sigma = -tau sqrt(4 pi / area). */
static PetscErrorCode DefaultTarget(CSSpin s, PetscReal *sigma)
{
  PetscReal area;
  PetscFunctionBeginUser;
  PetscCall(VecSum(s->mass, &area));
  if (s->generalized) *sigma = -s->target * PetscSqrtReal(4 * PETSC_PI / area);
  else *sigma = -s->target * 4 * PETSC_PI / area / (s->vmean * s->vmean);
  PetscFunctionReturn(0);
}

/* Default factorisation of K - sigma, set on pc before its SetFromOptions: LU for Eq. 6 (PETSc's serially, MUMPS in
   parallel); else the quaternion Cholesky (csquat) where it applies and quat_ok, or the project's default Cholesky
   (CSSetDefaultCholesky). docs/solvers.md. */
static PetscErrorCode SetDefaultFactor(CSSpin s, PC pc, PetscBool lu, PetscBool quat_ok)
{
  PetscMPIInt size;
  PetscFunctionBeginUser;
  if (lu) {
    PetscCallMPI(MPI_Comm_size(s->mesh->comm, &size));
    PetscCall(PCSetType(pc, PCLU));
    PetscCall(PCFactorSetMatSolverType(pc, size == 1 ? MATSOLVERPETSC : MATSOLVERMUMPS));
  } else if (quat_ok && s->quat_factor) {
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERCSQUAT));
  } else PetscCall(CSSetDefaultCholesky(pc));
  PetscFunctionReturn(0);
}

/* Serial Eq. 7 on the full space: the ST gets ST_MATMODE_SHELL and a preconditioner matrix instead of forming
   K - sigma I by MatDuplicate + MatShift (ST_MATMODE_COPY): K itself when the factor is csquat or cscholmod, told
   the shift (MatCSQuatFactorSetShift: subtracted as the entries are read, as the former PCSHELL did), else
   K - sigma I from CSMatShiftedShared (K's row structure, own values). Same values, same factorisation, no copy
   (docs/solvers.md, csquat). */
static PetscErrorCode UseShiftedPmat(CSSpin s, PetscBool *use)
{
  PetscMPIInt size;
  PetscBool   seq;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(s->mesh->comm, &size));
  PetscCall(PetscObjectBaseTypeCompare((PetscObject)s->K, MATSEQAIJ, &seq));
  *use = (PetscBool)(size == 1 && seq && !s->generalized && !s->P && !s->shell);
  PetscFunctionReturn(0);
}

/* after EPSSetFromOptions (the target and the solver type are final); again for every new K when Ks is used */
static PetscErrorCode SetShiftedPmat(CSSpin s, ST st, PC pc)
{
  PetscReal        tgt;
  PetscObjectId    id;
  PetscObjectState nz;
  MatSolverType    type = NULL;
  PetscBool        chol, ours = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(EPSGetTarget(s->eps, &tgt));
  PetscCall(PetscObjectTypeCompare((PetscObject)pc, PCCHOLESKY, &chol));
  if (chol) PetscCall(PCFactorGetMatSolverType(pc, &type));
  if (type) ours = (PetscBool)(!strcmp(type, MATSOLVERCSQUAT) || !strcmp(type, MATSOLVERCSCHOLMOD));
  if (ours && !s->Ks) {
    Mat       F;
    PetscBool has_op;
    PetscCall(PCGetOperatorsSet(pc, NULL, &has_op));
    if (!has_op) PetscCall(PCSetOperators(pc, s->K, s->K));
    PetscCall(PCFactorSetUpMatSolverType(pc));
    PetscCall(PCFactorGetMatrix(pc, &F));
    PetscCall(MatCSQuatFactorSetShift(F, tgt));
    PetscCall(STSetPreconditionerMat(st, s->K)); /* K = X for the spin object's life (BuildOperators) */
    PetscFunctionReturn(0);
  }
  PetscCall(PetscObjectGetId((PetscObject)s->K, &id));
  PetscCall(MatGetNonzeroState(s->K, &nz));
  if (s->Ks && (id != s->ks_id || nz != s->ks_nz)) PetscCall(MatDestroy(&s->Ks)); /* a new K */
  PetscCall(CSMatShiftedShared(s->K, -tgt, s->Ks ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->Ks));
  s->ks_id = id;
  s->ks_nz = nz;
  PetscCall(STSetPreconditionerMat(st, s->Ks));
  PetscFunctionReturn(0);
}

/* precond: Generalised Davidson (any -spin_eps_type that works with STPRECOND, e.g. lobpcg) with the scalar preconditioner of
   spin_precond.c; else Krylov-Schur with shift-and-invert toward sigma and a factorisation of K - sigma. */
static PetscErrorCode SetupEPS(CSSpin s, Vec x, CSRhoLocation loc, Vec rho, PetscInt nev, PetscBool precond)
{
  ST        st;
  KSP       ksp;
  PC        pc;
  PetscReal sigma;
  PetscBool shifted = PETSC_FALSE;
  PetscFunctionBeginUser;
  PetscCall(DefaultTarget(s, &sigma));
  if (!s->eps) {
    PetscCall(EPSCreate(s->mesh->comm, &s->eps));
    PetscCall(EPSSetOptionsPrefix(s->eps, s->hdr.prefix));
    PetscCall(EPSGetST(s->eps, &st));
    PetscCall(STGetKSP(st, &ksp));
    PetscCall(KSPGetPC(ksp, &pc));
    if (precond) {
      /* Generalised Davidson: fewer and cheaper iterations than LOBPCG (docs/solvers.md) */
      PetscCall(EPSSetType(s->eps, EPSGD));
      PetscCall(STSetType(st, STPRECOND));
      PetscCall(KSPSetType(ksp, KSPPREONLY));
      PetscCall(EPSSetWhichEigenpairs(s->eps, EPS_SMALLEST_REAL));
      PetscCall(EPSSetDimensions(s->eps, nev, PETSC_DEFAULT, PETSC_DEFAULT));
    } else {
      PetscCall(STSetType(st, STSINVERT));
      if (s->shell) {
        /* the shell cannot be factored: Krylov inner solve preconditioned by the factored assembled copy */
        PetscCall(STSetMatMode(st, ST_MATMODE_SHELL));
        PetscCall(KSPSetType(ksp, KSPGMRES));
        PetscCall(KSPSetTolerances(ksp, 1e-12, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
      } else {
        PetscCall(UseShiftedPmat(s, &shifted));
        if (shifted) PetscCall(STSetMatMode(st, ST_MATMODE_SHELL)); /* K - sigma I: SetShiftedPmat */
        PetscCall(KSPSetType(ksp, KSPPREONLY));
      }
      PetscCall(SetDefaultFactor(s, pc, s->generalized, (PetscBool)!s->shell));
      PetscCall(EPSSetWhichEigenpairs(s->eps, EPS_TARGET_MAGNITUDE));
      PetscCall(EPSSetTarget(s->eps, sigma));
      /* nev = 1: 6 basis vectors, enough to converge without restart (docs/solvers.md) */
      PetscCall(EPSSetDimensions(s->eps, nev, nev == 1 ? 6 : PETSC_DEFAULT, PETSC_DEFAULT));
    }
    PetscCall(EPSSetProblemType(s->eps, s->generalized ? EPS_GNHEP : EPS_HEP));
    PetscCall(EPSSetTolerances(s->eps, 1e-10, PETSC_DEFAULT));
    PetscCall(EPSSetOperators(s->eps, s->K, s->generalized ? s->Y : NULL));
    if (precond) PetscCall(CSSpinSetUpScalarPC(s, x, loc, rho, pc));
    PetscCall(EPSSetFromOptions(s->eps));
    PetscCall(KSPGetPC(ksp, &pc));
    if (shifted) PetscCall(SetShiftedPmat(s, st, pc));
    PetscCall(CSMumpsDefaultOrdering(pc, s->shell ? s->X : (s->Ks ? s->Ks : s->K))); /* the shell's PC factors a copy of X */
  } else {
    PetscCall(EPSSetOperators(s->eps, s->K, s->generalized ? s->Y : NULL));
    PetscCall(EPSGetST(s->eps, &st));
    if (!precond && s->Ks) {
      PetscCall(STGetKSP(st, &ksp));
      PetscCall(KSPGetPC(ksp, &pc));
      PetscCall(SetShiftedPmat(s, st, pc));
    }
    if (precond) {
      PetscCall(STGetKSP(st, &ksp));
      PetscCall(KSPGetPC(ksp, &pc));
      PetscCall(CSSpinSetUpScalarPC(s, x, loc, rho, pc));
    }
  }
  if (s->shell && !precond) {
    Mat       Pm;
    PetscReal tgt;
    PetscCall(EPSGetTarget(s->eps, &tgt));
    PetscCall(MatDuplicate(s->X, MAT_COPY_VALUES, &Pm));
    PetscCall(MatShift(Pm, -tgt));
    PetscCall(STSetPreconditionerMat(st, Pm));
    PetscCall(MatDestroy(&Pm));
  }
  PetscFunctionReturn(0);
}

/* The starting vector: lam = 1 (the identity), i.e. lam^ = V^{-1} 1, or P^T e_0 in the reduced space. */
static PetscErrorCode DefaultStart(CSSpin s, Vec start)
{
  Vec          one;
  PetscScalar *a;
  PetscInt     n;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(s->dm, &one));
  PetscCall(VecGetLocalSize(one, &n));
  PetscCall(VecGetArray(one, &a));
  for (PetscInt i = 0; i < n; i++) a[i] = (i % 4 == 0) ? 1 : 0;
  PetscCall(VecRestoreArray(one, &a));
  /* the reduced coordinates of lambda = 1: P's columns are V_i times orthonormal ones, so u = P^T (1 / V^2) */
  if (s->P && !s->generalized) {
    PetscCall(VecPointwiseDivide(one, one, s->v4));
    PetscCall(VecPointwiseDivide(one, one, s->v4));
  }
  if (s->P) PetscCall(MatMultTranspose(s->P, one, start));
  else if (!s->generalized) PetscCall(VecPointwiseDivide(start, one, s->v4));
  else PetscCall(VecCopy(one, start));
  PetscCall(VecDestroy(&one));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinResetStart(CSSpin s)
{
  PetscFunctionBeginUser;
  PetscCall(VecDestroy(&s->start));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinKSPSolve(CSSpin s, KSP ksp, Vec b, Vec x, const char what[], PetscInt *its)
{
  KSPConvergedReason reason;
  const char        *prefix;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(KSPSolve(ksp, b, x));
  PetscCall(KSPGetConvergedReason(ksp, &reason));
  PetscCall(KSPGetOptionsPrefix(ksp, &prefix));
  PetscCheck(reason >= 0, s->mesh->comm, PETSC_ERR_NOT_CONVERGED, "spin: %s failed (KSP reason %s; options -%sksp_*, -%spc_*)", what, KSPConvergedReasons[reason], prefix, prefix);
  PetscCall(KSPGetIterationNumber(ksp, &n));
  *its += n;
  PetscFunctionReturn(0);
}

static PetscErrorCode InverseIteration(CSSpin s, Vec xr, PetscReal *kr)
{
  PetscReal sigma, nrm, xKx;
  Vec       y;
  PetscFunctionBeginUser;
  PetscCheck(!s->generalized, s->mesh->comm, PETSC_ERR_SUP, "-%ssolver inverse supports -%sproblem standard only", s->hdr.prefix, s->hdr.prefix);
  PetscCall(DefaultTarget(s, &sigma));
  if (!s->kinv) {
    PC   pc;
    char prefix[256];
    PetscCall(CSSpinSubPrefix(s, "inverse_", prefix, sizeof(prefix)));
    PetscCall(KSPCreate(s->mesh->comm, &s->kinv));
    PetscCall(KSPSetOptionsPrefix(s->kinv, prefix));
    PetscCall(KSPSetType(s->kinv, s->keep_factor ? KSPGMRES : KSPPREONLY));
    PetscCall(KSPSetTolerances(s->kinv, 1e-12, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
    PetscCall(KSPGetPC(s->kinv, &pc));
    PetscCall(SetDefaultFactor(s, pc, PETSC_FALSE, PETSC_TRUE));
    PetscCall(KSPSetFromOptions(s->kinv));
    PetscCall(CSMumpsDefaultOrdering(pc, s->K));
    PetscCall(MatDuplicate(s->K, MAT_COPY_VALUES, &s->Kinv));
  } else {
    PetscCall(MatCopy(s->K, s->Kinv, SAME_NONZERO_PATTERN));
    /* crane2013 Sec. 6.4.2: consecutive problems are close, so the old factorisation preconditions the new one */
    if (s->keep_factor) PetscCall(KSPSetReusePreconditioner(s->kinv, PETSC_TRUE));
  }
  PetscCall(MatShift(s->Kinv, -sigma));
  PetscCall(KSPSetOperators(s->kinv, s->Kinv, s->Kinv));
  PetscCall(VecDuplicate(xr, &y));
  PetscCall(VecCopy(s->start, xr));
  PetscCall(VecNormalize(xr, NULL));
  s->inner_its = 0;
  for (PetscInt it = 0; it < s->inverse_its; it++) {
    PetscCall(CSSpinKSPSolve(s, s->kinv, xr, y, "inverse iteration solve", &s->inner_its));
    PetscCall(VecNormalize(y, &nrm));
    PetscCall(VecCopy(y, xr));
  }
  PetscCall(MatMult(s->K, xr, y));
  PetscCall(VecDot(xr, y, &xKx));
  *kr        = xKx;
  s->eps_its = s->inverse_its;
  PetscCall(VecDestroy(&y));
  PetscFunctionReturn(0);
}

/* ||K x - k x|| / ||x|| (or ||K x - k Y x|| for Eq. 6) */
static PetscErrorCode Residual(CSSpin s, Vec xr, PetscReal k, PetscReal *res)
{
  Vec       r, t;
  PetscReal nx;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(xr, &r));
  PetscCall(VecDuplicate(xr, &t));
  PetscCall(MatMult(s->K, xr, r));
  if (s->generalized) PetscCall(MatMult(s->Y, xr, t));
  else PetscCall(VecCopy(xr, t));
  PetscCall(VecAXPY(r, -k, t));
  PetscCall(VecNorm(r, NORM_2, res));
  PetscCall(VecNorm(xr, NORM_2, &nx));
  *res /= nx;
  PetscCall(VecDestroy(&r));
  PetscCall(VecDestroy(&t));
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckEPSConverged(CSSpin s, PetscInt need, PetscInt *nconv)
{
  EPSConvergedReason reason;
  EPSType            type;
  ST                 st;
  STType             sttype;
  PetscInt           its, maxit;
  PetscReal          tol;
  PetscFunctionBeginUser;
  PetscCall(EPSGetConverged(s->eps, nconv));
  PetscCall(EPSGetConvergedReason(s->eps, &reason));
  PetscCall(EPSGetIterationNumber(s->eps, &its));
  PetscCall(EPSGetType(s->eps, &type));
  PetscCall(EPSGetST(s->eps, &st));
  PetscCall(STGetType(st, &sttype));
  PetscCall(EPSGetTolerances(s->eps, &tol, &maxit));
  PetscCheck(*nconv >= need, s->mesh->comm, PETSC_ERR_NOT_CONVERGED,
             "spin: the eigensolver did not converge: %" PetscInt_FMT " of %" PetscInt_FMT " eigenpairs after %" PetscInt_FMT " iterations (reason %s; -%seps_type %s -%sst_type %s -%seps_max_it %" PetscInt_FMT " -%seps_tol %g). Nothing was written.",
             *nconv, need, its, EPSConvergedReasons[reason], s->hdr.prefix, type, s->hdr.prefix, sttype, s->hdr.prefix, maxit, s->hdr.prefix, (double)tol);
  s->eps_its = its;
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinSolveEigen(CSSpin s, Vec x, CSRhoLocation loc, Vec rho, Vec lambda)
{
  Vec            xr;
  PetscReal      kr;
  PetscLogDouble t0, t1, t2, c0, c1, c2;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_SpinEigen, 0, 0, 0, 0));
  PetscCall(PetscTime(&t0));
  c0 = CSSpinCPUTime();
  PetscCall(BuildOperators(s, x, loc, rho));
  PetscCall(MatCreateVecs(s->K, &xr, NULL));
  if (!s->start) {
    PetscCall(VecDuplicate(xr, &s->start));
    PetscCall(DefaultStart(s, s->start));
  }
  PetscCall(PetscTime(&t1));
  c1 = CSSpinCPUTime();
  if (s->inverse) PetscCall(InverseIteration(s, xr, &kr));
  else {
    PetscScalar ki;
    PetscInt    nconv;
    ST          st;
    KSP         ksp;
    PetscCall(SetupEPS(s, x, loc, rho, 1, s->scalar_pc));
    PetscCall(EPSSetInitialSpace(s->eps, 1, &s->start));
    s->lap_its = 0;
    PetscCall(EPSSolve(s->eps));
    {
      PetscErrorCode ierr = CheckEPSConverged(s, 1, &nconv);
      if (ierr) PetscCall(VecDestroy(&xr)); /* no leak when the eigensolver did not converge */
      PetscCall(ierr);
    }
    PetscCall(EPSGetEigenpair(s->eps, 0, &kr, &ki, xr, NULL));
    if (PetscAbsScalar(ki) > 1e-8 * PetscAbsReal(kr)) PetscCall(PetscPrintf(s->mesh->comm, "Warning: spin: eigenvalue %g has imaginary part %g; using the real part\n", (double)kr, (double)PetscRealPart(ki)));
    PetscCall(EPSGetST(s->eps, &st));
    PetscCall(STGetKSP(st, &ksp));
    PetscCall(KSPGetTotalIterations(ksp, &s->inner_its));
    if (s->scalar_pc) s->inner_its = s->lap_its; /* scalar preconditioner solves (4 per application) */
  }
  PetscCall(Residual(s, xr, kr, &s->residual));
  PetscCall(VecCopy(xr, s->start)); /* the next solve (a flow step) starts here */
  s->gamma = s->generalized ? kr : kr * s->vmean * s->vmean;
  if (s->P) PetscCall(MatMult(s->P, xr, lambda));
  else if (!s->generalized) PetscCall(VecPointwiseMult(lambda, xr, s->v4));
  else PetscCall(VecCopy(xr, lambda));
  PetscCall(VecDestroy(&xr));
  PetscCall(PetscTime(&t2));
  c2 = CSSpinCPUTime();
  s->t_setup = t1 - t0;
  s->t_eigen = t2 - t1;
  s->c_setup = c1 - c0;
  s->c_eigen = c2 - c1;
  PetscCall(PetscLogEventEnd(CS_EVENT_SpinEigen, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}

static int CompareReal(const void *a, const void *b)
{
  PetscReal x = *(const PetscReal *)a, y = *(const PetscReal *)b;
  return x < y ? -1 : (x > y ? 1 : 0);
}

PetscErrorCode CSSpinSpectrum(CSSpin s, Vec x, CSRhoLocation loc, Vec rho, PetscInt nev, PetscReal eig[], PetscInt *nout)
{
  PetscInt   nconv;
  PetscReal *all;
  PetscFunctionBeginUser;
  PetscCheck(!s->generalized && !s->inverse, s->mesh->comm, PETSC_ERR_SUP, "-task spectrum solves the standard problem (Eq. 7) with EPS: drop -%sproblem/-%ssolver", s->hdr.prefix, s->hdr.prefix);
  PetscCall(BuildOperators(s, x, loc, rho));
  /* Krylov methods can miss copies of a multiple eigenvalue at the end of the wanted range (every eigenvalue
     is at least 4-fold here): ask for a margin more and keep the nev smallest */
  PetscCall(SetupEPS(s, x, loc, rho, PetscMin(nev + PetscMax(8, nev / 4), 4 * s->mesh->Nv - 1), (PetscBool)(s->scalar_pc && s->solver_set)));
  PetscCall(EPSSolve(s->eps));
  PetscCall(CheckEPSConverged(s, nev, &nconv));
  PetscCall(PetscMalloc1(nconv, &all));
  for (PetscInt i = 0; i < nconv; i++) {
    PetscScalar kr, ki;
    PetscCall(EPSGetEigenvalue(s->eps, i, &kr, &ki));
    all[i] = PetscRealPart(kr) * s->vmean * s->vmean;
  }
  qsort(all, (size_t)nconv, sizeof(PetscReal), CompareReal);
  for (PetscInt i = 0; i < nev; i++) eig[i] = all[i];
  *nout = nev;
  PetscCall(PetscFree(all));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinNormalize(CSSpin s, Vec lambda, Vec mu, PetscBool rotation_too)
{
  const PetscScalar *l, *m, *u = NULL;
  PetscScalar       *lw;
  PetscReal          num[4] = {0, 0, 0, 0}, den = 0, mu2 = 0, c[4], buf[6];
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(s->mass, &n));
  PetscCall(VecGetArrayRead(lambda, &l));
  PetscCall(VecGetArrayRead(s->mass, &m));
  if (mu) PetscCall(VecGetArrayRead(mu, &u));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal li[4], ui[4] = {1, 0, 0, 0}, t[4], Mi = PetscRealPart(m[i]);
    for (int k = 0; k < 4; k++) li[k] = PetscRealPart(l[4 * i + k]);
    if (u)
      for (int k = 0; k < 4; k++) ui[k] = PetscRealPart(u[4 * i + k]);
    CSQuatConjMul(li, ui, t); /* least squares min sum M_i |lam_i c - mu_i|^2: c = sum M conj(lam) mu / sum M |lam|^2 */
    CSQuatAXPY(Mi, t, num);
    den += Mi * CSQuatNorm2(li);
    mu2 += Mi * CSQuatNorm2(ui);
  }
  PetscCall(VecRestoreArrayRead(lambda, &l));
  PetscCall(VecRestoreArrayRead(s->mass, &m));
  if (mu) PetscCall(VecRestoreArrayRead(mu, &u));
  for (int k = 0; k < 4; k++) buf[k] = num[k];
  buf[4] = den;
  buf[5] = mu2;
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, buf, 6, MPIU_REAL, MPIU_SUM, s->mesh->comm));
  PetscCheck(buf[4] > 0, s->mesh->comm, PETSC_ERR_PLIB, "spin: eigenvector is zero");
  if (rotation_too && mu && CSQuatNorm2(buf) > 1e-24 * buf[4] * buf[5]) {
    for (int k = 0; k < 4; k++) c[k] = buf[k] / buf[4];
  } else if (rotation_too && !mu && CSQuatNorm2(buf) > 1e-24 * buf[4] * buf[5]) {
    /* no target: only the rotation of the fit to 1 (where lambda turns a lot, sum M conj(lambda) nearly cancels
       and the least-squares factor would shrink everything); unit mean |lambda|^2, the task then restores the
       area */
    PetscReal nb = PetscSqrtReal(CSQuatNorm2(buf));
    for (int k = 0; k < 4; k++) c[k] = buf[k] / nb * PetscSqrtReal(buf[5] / buf[4]);
  } else {
    c[0] = PetscSqrtReal(buf[5] / buf[4]);
    c[1] = c[2] = c[3] = 0;
  }
  /* |lambda c|^2 would be ~0: the eigenvector is (nearly) orthogonal to the target similarities mu */
  PetscCheck(CSQuatNorm2(c) * buf[4] > 1e-8 * buf[5], s->mesh->comm, PETSC_ERR_NOT_CONVERGED,
             "spin: the eigenvector found does not resemble the target similarities (|fit| = %g); it is not the wanted mode (with -%sproblem generalized try -%sproblem standard). Nothing was written.", (double)PetscSqrtReal(CSQuatNorm2(c) * buf[4] / buf[5]), s->hdr.prefix, s->hdr.prefix);
  PetscCall(VecGetArray(lambda, &lw));
  for (PetscInt i = 0; i < n; i++) {
    PetscReal li[4], t[4];
    for (int k = 0; k < 4; k++) li[k] = PetscRealPart(lw[4 * i + k]);
    CSQuatMul(li, c, t); /* right factor: (D - rho)(lam c) = ((D - rho) lam) c */
    for (int k = 0; k < 4; k++) lw[4 * i + k] = t[k];
  }
  PetscCall(VecRestoreArray(lambda, &lw));
  PetscFunctionReturn(0);
}

PetscErrorCode CSSpinLogPoissonBegin(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_SpinPoisson, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
PetscErrorCode CSSpinLogPoissonEnd(void)
{
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventEnd(CS_EVENT_SpinPoisson, 0, 0, 0, 0));
  PetscFunctionReturn(0);
}
