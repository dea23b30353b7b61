/* Baseline fairing flows for the comparison of crane2013 Sec. 6.4.2 (Fig. 17), as small flow kinds of the Willmore
   flow object (so they share its history, summary, ParaView output, wall-time budget and W as the measure). They
   are baselines, deliberately plain: position-based, one linear operator per step, a fixed step tau.
     emcf    explicit mean curvature flow (Brakke 1992):      f <- f - tau M^-1 L f
     ebilap  explicit bi-Laplacian flow (Taubin 1995):         f <- f - tau (M^-1 L)^2 f
     imcf    implicit mean curvature flow (Desbrun 1999):      (M + tau L) f' = M f
     ibilap  implicit bi-Laplacian flow (backward Euler):      (M + tau L M^-1 L) f' = M f
     cmcf    conformalized MCF (Kazhdan et al. 2012):          (M + tau L_0) f' = M f, L_0 of the input
     vmcf    volume-controlled MCF (Eckstein et al. 2007):     (M + tau L) f' = M f + tau lambda grad V(f), lambda
             (the multiplier of the volume, the mean of H) solved by Newton so that V(f') = V(input) to round-off
     isobend Willmore flow of the isometric bending model (Wardetzky et al. 2007): (M_0 + tau K_0) f' = M_0 f,
             K_0 = L_0 M_0^-1 L_0, the Hessian of W under isometric deformations, constant: factored once
             (the isometry is the model's assumption, not a constraint of the flow: all edge lengths kept would leave
             a generic closed mesh only rigid motions, Gluck 1975; the flow leaves the model's range and W, not
             E_b, rises again after a while: the iterates tend to K_0's lowest eigenvector in every coordinate)
   after each step f' is recentred and rescaled to the input's area (as Kazhdan et al. do for cmcf); vmcf is only
   recentred (its volume is the constraint; a translation keeps it).
   L = the positive cotan Laplacian, M = the barycentric vertex areas, both at the current f (L_0, M_0 at the input).
   tau = -flow_t h^2 (MCF kinds) or -flow_t h^4 (bi-Laplacian kinds), h the mean edge length of the input, so that
   -flow_t is in units of the explicit stability scale; the step is fixed (a non-finite step is halved). Linear
   solves: KSP prefix <flow prefix>fair_, default Cholesky (CHOLMOD) on one rank, CG + hypre on several. */
#include "../../willmore_impl.h"
#include "cs_operators.h"

typedef enum { FAIR_EMCF, FAIR_EBILAP, FAIR_IMCF, FAIR_IBILAP, FAIR_CMCF, FAIR_VMCF, FAIR_ISOBEND } FairKind;

typedef struct {
  FairKind  kind;
  Mat       L, L0, A, ML; /* L (3V), the input's L (cmcf), the implicit matrix, M^-1 L (bi-Laplacian) */
  Vec       m, y, b;      /* vertex areas on the 3 components, work */
  Vec       gV;           /* the volume's gradient (vmcf) */
  CSEnergy  vol;          /* the enclosed volume (vmcf) */
  KSP       ksp;
  PetscReal h, A0, V0;    /* mean edge length, area and volume of the input */
  PetscReal c0[3];        /* centroid of the input (cmcf) */
  PetscReal tauA;         /* the tau of the implicit matrix A (isobend rebuilds it only when tau changes) */
} Fair;

/* m (3V) = the barycentric vertex areas of x, repeated on the 3 components (dmV1 and dmV3 order their owned
   vertices alike) */
static PetscErrorCode Mass3(CSWillmoreFlow F, Vec x, Vec m)
{
  Vec                a;
  const PetscScalar *aa;
  PetscScalar       *ma;
  PetscInt           n;
  PetscFunctionBeginUser;
  PetscCall(DMGetGlobalVector(F->mesh->dmV1, &a));
  PetscCall(CSOperatorMass(F->mesh, x, a));
  PetscCall(VecGetLocalSize(a, &n));
  PetscCall(VecGetArrayRead(a, &aa));
  PetscCall(VecGetArray(m, &ma));
  for (PetscInt i = 0; i < n; i++)
    for (int d = 0; d < 3; d++) ma[3 * i + d] = aa[i];
  PetscCall(VecRestoreArray(m, &ma));
  PetscCall(VecRestoreArrayRead(a, &aa));
  PetscCall(DMRestoreGlobalVector(F->mesh->dmV1, &a));
  PetscFunctionReturn(0);
}

static PetscErrorCode Centroid(CSWillmoreFlow F, Vec x, PetscReal c[3])
{
  PetscFunctionBeginUser;
  for (int d = 0; d < 3; d++) {
    PetscScalar s;
    PetscInt    N;
    PetscCall(VecStrideSum(x, d, &s));
    PetscCall(VecGetSize(x, &N));
    c[d] = PetscRealPart(s) / (N / 3);
  }
  PetscFunctionReturn(0);
}

/* The default solver of the implicit kinds (before the user's options). */
static PetscErrorCode NewKSP(CSWillmoreFlow F, Fair *fa)
{
  PC          pc;
  PetscMPIInt size;
  char        prefix[80];
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_size(F->hdr.comm, &size));
  PetscCall(KSPCreate(F->hdr.comm, &fa->ksp));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%sfair_", F->hdr.prefix));
  PetscCall(KSPSetOptionsPrefix(fa->ksp, prefix));
  PetscCall(KSPGetPC(fa->ksp, &pc));
  if (size == 1) {
    PetscCall(KSPSetType(fa->ksp, KSPPREONLY));
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERCHOLMOD));
  } else {
    PetscCall(KSPSetType(fa->ksp, KSPCG));
    PetscCall(PCSetType(pc, PCHYPRE));
    /* isobend: 1e-12, K_0 = L_0 M_0^-1 L_0 is the worst conditioned; at 1e-10 W at step 6 differed from the
       serial Cholesky run's in the 10th digit (willmore_fairing_resume) */
    PetscCall(KSPSetTolerances(fa->ksp, fa->kind == FAIR_ISOBEND ? 1e-12 : 1e-10, PETSC_DEFAULT, PETSC_DEFAULT, PETSC_DEFAULT));
  }
  PetscCall(KSPSetFromOptions(fa->ksp));
  PetscFunctionReturn(0);
}

/* The kind's data, from the input x0, at the first trial: also after a -resume, which skips ops.start (the data
   were built there and a resumed run crashed on the missing Laplacian). An added constraint (CSWillmoreFlowAddConstraint,
   counted in F->k only at the flow's set-up) is refused here: the option-made ones are refused by SetUpFair. */
static PetscErrorCode SetUpFairData(CSWillmoreFlow F)
{
  Fair *fa = (Fair *)F->data;
  PetscFunctionBeginUser;
  if (fa->m) PetscFunctionReturn(0);
  PetscCheck(F->k == 0, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype %s is an unconstrained baseline fairing flow: the constraint %s added by CSWillmoreFlowAddConstraint is not supported", F->hdr.prefix, F->type, F->nadded ? F->added[0] : "(global)");
  PetscCall(CSGeometryMeanEdgeLength(F->mesh, F->x0, &fa->h));
  PetscCall(CSGeometryAreaVolume(F->mesh, F->x0, &fa->A0, &fa->V0));
  PetscCall(Centroid(F, F->x0, fa->c0));
  PetscCall(VecDuplicate(F->x, &fa->m));
  PetscCall(VecDuplicate(F->x, &fa->y));
  PetscCall(VecDuplicate(F->x, &fa->b));
  PetscCall(CSOperatorLaplacian3(F->mesh, F->x0, MAT_INITIAL_MATRIX, &fa->L));
  if (fa->kind == FAIR_CMCF) PetscCall(MatDuplicate(fa->L, MAT_COPY_VALUES, &fa->L0));
  if (fa->kind == FAIR_ISOBEND) PetscCall(Mass3(F, F->x0, fa->m)); /* M_0: L and m stay the input's */
  if (fa->kind == FAIR_VMCF) {
    PetscCheck(F->mesh->topo.boundary_edges == 0 && fa->V0 != 0, F->hdr.comm, PETSC_ERR_ARG_WRONG, "-%stype vmcf keeps the enclosed volume: it needs a closed mesh enclosing a volume (this one: volume %g)", F->hdr.prefix, (double)fa->V0);
    PetscCall(CSEnergyCreateVolume(F->mesh, &fa->vol));
    PetscCall(VecDuplicate(F->x, &fa->gV));
  }
  if (fa->kind >= FAIR_IMCF) PetscCall(NewKSP(F, fa));
  PetscFunctionReturn(0);
}

/* The implicit matrix A = M + tau K with K = L, L M^-1 L or L_0 (fixed pattern after the first step); isobend's
   M_0 + tau L_0 M_0^-1 L_0 is built once per tau, so its factorisation is kept across the steps. */
static PetscErrorCode ImplicitMatrix(CSWillmoreFlow F, Fair *fa, PetscReal tau)
{
  Mat       K = fa->kind == FAIR_CMCF ? fa->L0 : fa->L;
  PetscBool first = fa->A ? PETSC_FALSE : PETSC_TRUE;
  PetscFunctionBeginUser;
  if (fa->kind == FAIR_ISOBEND && fa->A && fa->tauA == tau) PetscFunctionReturn(0);
  fa->tauA = tau;
  if (fa->kind == FAIR_IBILAP || fa->kind == FAIR_ISOBEND) {
    PetscCall(VecCopy(fa->m, fa->y));
    PetscCall(VecReciprocal(fa->y));
    if (!fa->ML) PetscCall(MatDuplicate(fa->L, MAT_COPY_VALUES, &fa->ML));
    else PetscCall(MatCopy(fa->L, fa->ML, SAME_NONZERO_PATTERN));
    PetscCall(MatDiagonalScale(fa->ML, fa->y, NULL));
    PetscCall(MatDestroy(&fa->A));
    PetscCall(MatMatMult(fa->L, fa->ML, MAT_INITIAL_MATRIX, PETSC_DEFAULT, &fa->A));
    first = PETSC_TRUE;
  } else if (first) PetscCall(MatDuplicate(K, MAT_COPY_VALUES, &fa->A));
  else PetscCall(MatCopy(K, fa->A, SAME_NONZERO_PATTERN));
  PetscCall(MatScale(fa->A, tau));
  PetscCall(MatDiagonalSet(fa->A, fa->m, ADD_VALUES));
  PetscCall(MatSetOption(fa->A, MAT_SPD, PETSC_TRUE));
  if (first) PetscCall(KSPSetOperators(fa->ksp, fa->A, fa->A));
  F->saddle.setups++; /* a new operator: its factorisation (preconditioner) is built at the next solve */
  PetscFunctionReturn(0);
}

/* Back to the input's centroid and area after every step (Kazhdan et al. 2012 normalise cmcf so): MCF would
   shrink a sphere to a point in finite time; W is scale-invariant, so this changes no measure of the study.
   vmcf is only recentred. */
static PetscErrorCode Normalise(CSWillmoreFlow F, Fair *fa, Vec x)
{
  PetscReal    c[3], A, V, s;
  PetscScalar *xa;
  PetscInt     n;
  PetscFunctionBeginUser;
  PetscCall(Centroid(F, x, c));
  PetscCall(CSGeometryAreaVolume(F->mesh, x, &A, &V));
  s = fa->kind == FAIR_VMCF ? 1 : PetscSqrtReal(fa->A0 / A); /* vmcf: the volume is kept, not the area */
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArray(x, &xa));
  for (PetscInt i = 0; i < n; i++) xa[i] = fa->c0[i % 3] + s * (xa[i] - c[i % 3]); /* x, y, z interleaved */
  PetscCall(VecRestoreArray(x, &xa));
  PetscFunctionReturn(0);
}

static PetscBool BiLaplacian(FairKind k)
{
  return (PetscBool)(k == FAIR_EBILAP || k == FAIR_IBILAP || k == FAIR_ISOBEND);
}

/* One solve with the implicit matrix A (z = A^-1 r), counted in the flow's linear solves and KSP iterations. */
static PetscErrorCode SolveFair(CSWillmoreFlow F, Fair *fa, Vec r, Vec z, PetscBool *ok)
{
  KSPConvergedReason reason;
  PetscInt           its;
  PetscFunctionBeginUser;
  PetscCall(KSPSolve(fa->ksp, r, z));
  PetscCall(KSPGetConvergedReason(fa->ksp, &reason));
  PetscCall(KSPGetIterationNumber(fa->ksp, &its));
  F->saddle.solves++;
  F->kspits += its;
  *ok = (PetscBool)(reason > 0);
  PetscFunctionReturn(0);
}

/* vmcf (Eckstein et al. 2007): f' = f_a + lambda f_b with (M + tau L) f_a = M f (in F->xt) and (M + tau L) f_b =
   tau grad V(f) (in fa->y); lambda by Newton on the cubic V(f_a + lambda f_b) = V_0, dV/dlambda = grad V(f') . f_b,
   to 1e-14 V_0 (a few iterations: lambda ~ tau times the mean of H). Not met in 30: *ok false (the step is halved). */
static PetscErrorCode VolumeControl(CSWillmoreFlow F, Fair *fa, PetscReal tau, PetscBool *ok)
{
  PetscReal   V, A, lambda = 0;
  PetscScalar dV;
  PetscFunctionBeginUser;
  PetscCall(CSEnergyGradient(fa->vol, F->x, NULL, fa->gV));
  PetscCall(VecScale(fa->gV, tau));
  PetscCall(SolveFair(F, fa, fa->gV, fa->y, ok));
  if (!*ok) PetscFunctionReturn(0);
  *ok = PETSC_FALSE;
  for (PetscInt it = 0; it < 30 && !*ok; it++) {
    PetscCall(CSGeometryAreaVolume(F->mesh, F->xt, &A, &V));
    if (PetscAbsReal(V - fa->V0) <= 1e-14 * PetscAbsReal(fa->V0)) *ok = PETSC_TRUE;
    else {
      PetscCall(CSEnergyGradient(fa->vol, F->xt, NULL, fa->gV));
      PetscCall(VecDot(fa->gV, fa->y, &dV));
      if (PetscRealPart(dV) == 0) break;
      lambda = -(V - fa->V0) / PetscRealPart(dV);
      PetscCall(VecAXPY(F->xt, lambda, fa->y));
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode TrialFair(CSWillmoreFlow F, PetscBool *accept)
{
  Fair     *fa = (Fair *)F->data;
  PetscReal tau;
  PetscFunctionBeginUser;
  PetscCall(SetUpFairData(F));
  tau     = F->t * PetscPowReal(fa->h, BiLaplacian(fa->kind) ? 4 : 2);
  *accept = PETSC_TRUE;
  if (fa->kind != FAIR_ISOBEND) { /* isobend keeps the input's L_0 and M_0 */
    PetscCall(CSOperatorLaplacian3(F->mesh, F->x, MAT_REUSE_MATRIX, &fa->L));
    PetscCall(Mass3(F, F->x, fa->m));
  }
  if (fa->kind == FAIR_EMCF || fa->kind == FAIR_EBILAP) {
    PetscCall(MatMult(fa->L, F->x, fa->y));
    PetscCall(VecPointwiseDivide(fa->y, fa->y, fa->m));
    if (fa->kind == FAIR_EBILAP) {
      PetscCall(MatMult(fa->L, fa->y, fa->b));
      PetscCall(VecPointwiseDivide(fa->y, fa->b, fa->m));
    }
    PetscCall(VecWAXPY(F->xt, -tau, fa->y, F->x));
  } else {
    PetscCall(ImplicitMatrix(F, fa, tau));
    PetscCall(VecPointwiseMult(fa->b, fa->m, F->x));
    PetscCall(VecCopy(F->x, F->xt));
    PetscCall(SolveFair(F, fa, fa->b, F->xt, accept));
    if (*accept && fa->kind == FAIR_VMCF) PetscCall(VolumeControl(F, fa, tau, accept));
  }
  if (*accept) PetscCall(Normalise(F, fa, F->xt));
  PetscFunctionReturn(0);
}

static PetscErrorCode NoOp(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscFunctionReturn(0);
}

static PetscErrorCode DestroyFair(CSWillmoreFlow F)
{
  Fair *fa = (Fair *)F->data;
  PetscFunctionBeginUser;
  if (!fa) PetscFunctionReturn(0);
  PetscCall(MatDestroy(&fa->L));
  PetscCall(MatDestroy(&fa->L0));
  PetscCall(MatDestroy(&fa->A));
  PetscCall(MatDestroy(&fa->ML));
  PetscCall(VecDestroy(&fa->m));
  PetscCall(VecDestroy(&fa->y));
  PetscCall(VecDestroy(&fa->b));
  PetscCall(VecDestroy(&fa->gV));
  PetscCall(CSEnergyDestroy(&fa->vol));
  PetscCall(KSPDestroy(&fa->ksp));
  PetscCall(PetscFree(F->data));
  PetscFunctionReturn(0);
}

static PetscErrorCode SetUpFair(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(!F->conformal && !F->area_set && !F->vol_set && !F->points[0] && !F->mobius, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype %s is an unconstrained baseline fairing flow: no constraints", F->hdr.prefix, F->type);
  F->step_control = PETSC_FALSE; /* a fixed step; only a non-finite state is rejected */
  F->grow         = 1;
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewFair(CSWillmoreFlow F, PetscViewer viewer)
{
  Fair     *fa    = (Fair *)F->data;
  PetscBool bilap = BiLaplacian(fa->kind);
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  baseline fairing flow %s: fixed step tau = t h^%d (h the input's mean edge length), linear solves with KSP prefix -%sfair_\n", F->type, bilap ? 4 : 2, F->hdr.prefix));
  PetscFunctionReturn(0);
}

/* The kind named by F->type (set before the create function is called), with its id in checkpoints and its
   default step (in units of h^2 or h^4; the largest stable ones found by runs/study_fairing.sh are larger or
   smaller, per mesh). */
PetscErrorCode CSWillmoreFlowCreate_Fairing(CSWillmoreFlow F)
{
  static const struct {
    const char *name;
    FairKind    kind;
    PetscReal   t;
  } kinds[] = {{"emcf", FAIR_EMCF, 0.02}, {"ebilap", FAIR_EBILAP, 0.01}, {"imcf", FAIR_IMCF, 1}, {"ibilap", FAIR_IBILAP, 100}, {"cmcf", FAIR_CMCF, 100}, {"vmcf", FAIR_VMCF, 1}, {"isobend", FAIR_ISOBEND, 100}};
  Fair     *fa;
  PetscBool match = PETSC_FALSE;
  PetscInt  k;
  PetscFunctionBeginUser;
  for (k = 0; k < (PetscInt)PETSC_STATIC_ARRAY_LENGTH(kinds) && !match; k++) PetscCall(PetscStrcmp(F->type, kinds[k].name, &match));
  PetscCheck(match, F->hdr.comm, PETSC_ERR_PLIB, "fairing baseline %s not in the table", F->type);
  k--;
  PetscCall(PetscNew(&fa));
  fa->kind         = kinds[k].kind;
  F->data          = fa;
  F->ops.id        = 10 + k;
  F->ops.conformal = PETSC_FALSE;
  F->ops.setup     = SetUpFair;
  F->ops.trial     = TrialFair;
  F->ops.filter    = CSWFCheckFinite;
  F->ops.accept    = NoOp;
  F->ops.grow      = NoOp;
  F->ops.shrink    = CSWFShrinkPrimal;
  F->ops.destroy   = DestroyFair;
  F->ops.view      = ViewFair;
  F->t             = kinds[k].t;
  F->tmax          = 1e8; /* the step never grows (grow is a no-op): no cap, the largest -flow_t_max the checks admit */
  PetscFunctionReturn(0);
}
