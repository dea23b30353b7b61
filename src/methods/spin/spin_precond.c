/* A scalar preconditioner for the Dirac eigenproblem (crane2011 Eq. 7). The quaternionic operator X = A^* M_F A
   is a squared Dirac operator: up to lower-order terms it acts like the cotan Laplacian on each of the four
   real components (on the unit sphere X has the spectrum n^2 against M, the Laplacian l(l+1)). So
     K = V X V  ~  V ((L + c M) (x) I_4) V,    K^{-1} ~ V^{-1} ((L + c M)^{-1} (x) I_4) V^{-1},
   with c = 4 pi / area (one unit of the unit sphere's spectrum; -spin_lap_shift scales it) plus rho^2 (the zeroth-order part of (D - rho)^2).
   One V x V factorisation has the pattern of a single component of the 4V x 4V one, i.e. 1/16 of its
   nonzeros and about 1/64 of its flops; it is applied to the four components in turn. A preconditioned
   eigensolver (Generalised Davidson or LOBPCG, SLEPc's STPRECOND) then needs products with X instead of a
   factorisation of K; it never factors the 4V x 4V matrix (iteration counts and times: docs/solvers.md). Inner solver: KSP prefix spin_lap_ (Cholesky: CHOLMOD serially,
   MUMPS-AMD in parallel, by default). */
#include <petsc/private/pcimpl.h> /* a PC type of our own (PCRegister) */
#include "spin_impl.h"

/* Ls = L + M diag(c + rho_i^2) on dmV1 (rho per face: the area-weighted mean of the faces around i). */
static PetscErrorCode AssembleScalarOperator(CSSpin s, Vec x, CSRhoLocation loc, Vec rho)
{
  CSMesh    mesh = s->mesh;
  Vec       d;
  PetscReal area, shift;
  PetscFunctionBeginUser;
  PetscCall(CSOperatorLaplacian(mesh, x, s->Ls ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &s->Ls));
  PetscCall(VecSum(s->mass, &area));
  shift = s->lap_shift * 4 * PETSC_PI / area;
  PetscCall(DMGetGlobalVector(mesh->dmV1, &d));
  if (rho && loc == CS_RHO_VERTEX) PetscCall(VecPointwiseMult(d, rho, rho));
  else if (rho && loc == CS_RHO_FACE) { /* sum_f A_f rho_f^2 / 3 over the faces of i, divided by M_i */
    Vec                xl, rl;
    const PetscReal   *p;
    const PetscScalar *r;
    CSLocalSum         sum;
    PetscCall(CSMeshGetLocalPositions(mesh, x, &xl, &p));
    PetscCall(CSDiracGetRho(mesh, loc, rho, &rl, &r));
    PetscCall(CSLocalSumBegin(mesh->dmV1, &sum));
    for (CSFaceIter F = CS_FACE_ITER_INIT; CSMeshFaceNext(mesh, p, &F);) {
      PetscReal an[3], rf = PetscRealPart(r[F.f]), w;
      CSTriangleAreaVector(F.c, an);
      w = CSVecNorm(an) / 3 * rf * rf;
      for (int k = 0; k < 3; k++) sum.a[F.v[k]] += w;
    }
    PetscCall(CSLocalSumEnd(&sum, d));
    PetscCall(CSDiracRestoreRho(mesh, loc, rho, &rl, &r));
    PetscCall(CSMeshRestoreLocalPositions(mesh, x, &xl, &p));
    PetscCall(VecPointwiseDivide(d, d, s->mass));
  } else PetscCall(VecSet(d, 0));
  PetscCall(VecShift(d, shift));
  PetscCall(VecPointwiseMult(d, d, s->mass));
  PetscCall(MatDiagonalSet(s->Ls, d, ADD_VALUES));
  PetscCall(DMRestoreGlobalVector(mesh->dmV1, &d));
  PetscFunctionReturn(0);
}

/* y = V^{-1} (Ls^{-1} (x) I_4) V^{-1} x. The component loops are written out: the vectors SLEPc passes here
   carry no block size. */
static PetscErrorCode PCApply_CSSpinLap(PC pc, Vec x, Vec y)
{
  CSSpin             s = (CSSpin)pc->data;
  Vec                b, u;
  const PetscScalar *xa, *va, *ua;
  PetscScalar       *ya, *ba;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCheck(s && s->klap, PetscObjectComm((PetscObject)pc), PETSC_ERR_ARG_WRONGSTATE, "PC %s is the spin method's own (-spin_solver precond); it has no spin transformation to precondition here", PCCSSPINLAP);
  PetscCall(DMGetGlobalVector(s->mesh->dmV1, &b));
  PetscCall(DMGetGlobalVector(s->mesh->dmV1, &u));
  PetscCall(VecGetLocalSize(b, &n));
  PetscCall(VecGetArrayRead(s->v4, &va));
  for (PetscInt c = 0; c < 4; c++) {
    PetscCall(VecGetArrayRead(x, &xa));
    PetscCall(VecGetArray(b, &ba));
    for (PetscInt i = 0; i < n; i++) ba[i] = xa[4 * i + c] / va[4 * i + c];
    PetscCall(VecRestoreArray(b, &ba));
    PetscCall(VecRestoreArrayRead(x, &xa));
    PetscCall(CSSpinKSPSolve(s, s->klap, b, u, "the scalar preconditioner solve", &s->lap_its));
    PetscCall(VecGetArrayRead(u, &ua));
    PetscCall(VecGetArray(y, &ya));
    for (PetscInt i = 0; i < n; i++) ya[4 * i + c] = ua[i] / va[4 * i + c];
    PetscCall(VecRestoreArray(y, &ya));
    PetscCall(VecRestoreArrayRead(u, &ua));
  }
  PetscCall(VecRestoreArrayRead(s->v4, &va));
  PetscCall(DMRestoreGlobalVector(s->mesh->dmV1, &b));
  PetscCall(DMRestoreGlobalVector(s->mesh->dmV1, &u));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCView_CSSpinLap(PC pc, PetscViewer viewer)
{
  CSSpin      s      = (CSSpin)pc->data;
  const char *prefix = NULL;
  PetscBool   ascii;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectTypeCompare((PetscObject)viewer, PETSCVIEWERASCII, &ascii));
  if (s && s->klap) PetscCall(KSPGetOptionsPrefix(s->klap, &prefix));
  if (ascii) PetscCall(PetscViewerASCIIPrintf(viewer, "  scalar Laplacian (L + c M)^{-1} per quaternion component (KSP prefix %s)\n", prefix ? prefix : "spin_lap_"));
  PetscFunctionReturn(0);
}

static PetscErrorCode PCSetSpin_CSSpinLap(PC pc, CSSpin s)
{
  PetscFunctionBeginUser;
  pc->data = s; /* not owned */
  PetscFunctionReturn(0);
}

static PetscErrorCode PCDestroy_CSSpinLap(PC pc)
{
  PetscFunctionBeginUser;
  pc->data = NULL;
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "CSSpinLapSetSpin_C", NULL));
  PetscFunctionReturn(0);
}

/* PC type "csspinlap" (registered by CSInitializePackage) */
PetscErrorCode PCCreate_CSSpinLap(PC pc)
{
  PetscFunctionBeginUser;
  pc->data         = NULL;
  pc->ops->apply   = PCApply_CSSpinLap;
  pc->ops->view    = PCView_CSSpinLap;
  pc->ops->destroy = PCDestroy_CSSpinLap;
  PetscCall(PetscObjectComposeFunction((PetscObject)pc, "CSSpinLapSetSpin_C", PCSetSpin_CSSpinLap));
  PetscFunctionReturn(0);
}

/* Assembles L + c M and factors it; pc becomes (first call, before its SetFromOptions) or stays a csspinlap PC for s. */
PetscErrorCode CSSpinSetUpScalarPC(CSSpin s, Vec x, CSRhoLocation loc, Vec rho, PC pc)
{
  PetscBool first = (PetscBool)!s->klap;
  PetscFunctionBeginUser;
  PetscCall(AssembleScalarOperator(s, x, loc, rho));
  if (!s->klap) {
    PC   lpc;
    char prefix[256];
    PetscCall(CSSpinSubPrefix(s, "lap_", prefix, sizeof(prefix)));
    PetscCall(KSPCreate(s->mesh->comm, &s->klap));
    PetscCall(KSPSetOptionsPrefix(s->klap, prefix));
    PetscCall(KSPSetType(s->klap, KSPPREONLY));
    PetscCall(KSPGetPC(s->klap, &lpc));
    PetscCall(CSSetDefaultCholesky(lpc));
    PetscCall(KSPSetFromOptions(s->klap));
    PetscCall(CSMumpsDefaultOrdering(lpc, s->Ls));
  }
  PetscCall(KSPSetOperators(s->klap, s->Ls, s->Ls));
  PetscCall(KSPSetUp(s->klap));
  if (first) PetscCall(PCSetType(pc, PCCSSPINLAP)); /* the default, set before the PC's SetFromOptions */
  PetscTryMethod(pc, "CSSpinLapSetSpin_C", (PC, CSSpin), (pc, s));
  PetscFunctionReturn(0);
}
