/* -flow_type newton: Newton-Krylov minimisation of the energy (unconstrained) in normal coordinates.
   The iterate moves along the unit vertex normals n_i of the current state, x(phi) = x + N phi (N: 3V x V, column
   i = n_i at vertex i), as Surface Evolver's hessian_seek does with hessian_normal: the tangential part of the
   discrete gradient only slides vertices and is what degrades the mesh (docs/willmore_flow.md "Newton"). Each
   iteration solves
     (N^T H_E N) phi = -N^T g
   by CG (KSP prefix <flow prefix>newton_) without assembling H_E: its products are central differences of the
   analytic gradient (CSEnergyHessianMult), preconditioned by the H^2 metric restricted to normal motion (soliman2021
   Eq. 26) in csh2's factored form P = (s M + L_n) M^-1 (s M + L_n), L_n = N^T L N (FactoredApply), or by a
   Cholesky factorisation of N^T I_H2 N itself (-flow_newton_factored_pc false). Negative curvature: CG
   stops when p^T A p <= 0 (KSP_DIVERGED_INDEFINITE_MAT); the iterate it has reached is a descent direction
   (truncated CG, Steihaug) and is taken if it is not zero, otherwise (and whenever the direction is not a descent
   direction) the H^2 metric step phi = -P^{-1} N^T g, i.e. one Sobolev gradient step in normal
   coordinates. After an accepted step the vertices relax within their tangent planes toward the graph-harmonic
   distribution (Relax, -flow_newton_relax), or with -flow_newton_relax_scaled toward spacing in proportion to the
   local edge length (the smallest angle: docs/bench_evolver.md). Step length: t = 1 first, halved on rejection (energy increase, -flow_max_step, a face turned
   over), doubled after an accepted step up to -flow_t_max (default 1 here). Stopping: the normal residual
   ||N^T g||_2 < -flow_rtol (or -flow_energy_target). With -flow_conformal: Newton on
   the KKT system of the constrained problem instead (newton_kkt.c; soliman2021 Fig. 17). Otherwise constraints:
   none (no conformal, area, volume or point
   constraint; closed surfaces only): refused with a message. */
#include "../cgd/cgd_impl.h"
#include "newton_impl.h"
#include "cs_geometry.h"
#include "cs_util.h"

typedef struct {
  Mat       N, A, Mn; /* normals, the shell Hessian N^T H N, the metric N^T I_H2 N */
  KSP       ksp;
  Vec       nrm, u, hu, *work; /* dmV3 (work: 2) */
  Vec       gn, phi, b;          /* dmV1 */
  PetscReal eps;                 /* displacement of the Hessian's central difference */
  PetscInt  it_dir;              /* iteration whose direction phi holds (-1: none) */
  PetscInt  cg_its, fallbacks, truncated;
  PetscInt  reuse_its, last_its, setups; /* keep the factored metric while CG needs at most reuse_its */
  PetscBool factored;                    /* PC: (s M + L_n) M^-1 (s M + L_n) (default), else N^T I_H2 N itself */
  Mat       Ln;                          /* L_n = N^T L3 N + s M (V x V, 1-ring; L3: cotan Laplacian on dmV3) */
  Vec       m1, w1;                      /* vertex areas M, work (dmV1) */
  KSP       inner;                       /* factorisation of L_n + s M (prefix <flow prefix>newton_inner_) */
  PetscReal relax;                       /* tangential relaxation after an accepted step (Relax), 0: off */
  PetscInt  relax_sweeps;                /* solves of the relaxation per accepted step */
  PetscBool relax_scaled;                /* weights 1/sqrt(face area) (CSOperatorScaledGraphLaplacian3), else 1 */
  Mat       G1, G, PGP;                  /* graph Laplacian (dmV1), the same on each coordinate (MAIJ, dmV3), its tangential part (shell) */
  KSP       kspT;
  Vec       at, bt;
  NewtonKKT *kkt;                        /* -flow_conformal: Newton on the KKT system (newton_kkt.c) */
  PetscReal  kkt_pc_t;                   /* t of the H^2 metric in its preconditioner */
} Newton;

NewtonKKT *CSNewtonGetKKT(CSWillmoreFlow F)
{
  return ((Newton *)F->data)->kkt;
}

/* w = P v, P = I - n n^T at each vertex (w may be v). */
static PetscErrorCode ProjectTangentTo(Newton *d, Vec v, Vec w)
{
  PetscScalar       *a;
  const PetscScalar *n, *b;
  PetscInt           nl;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(v, &nl));
  PetscCall(VecGetArrayRead(d->nrm, &n));
  if (w == v) {
    PetscCall(VecGetArray(w, &a));
    b = a;
  } else {
    PetscCall(VecGetArrayRead(v, &b));
    PetscCall(VecGetArrayWrite(w, &a));
  }
  for (PetscInt i = 0; i < nl / 3; i++) {
    PetscReal un = b[3 * i] * n[3 * i] + b[3 * i + 1] * n[3 * i + 1] + b[3 * i + 2] * n[3 * i + 2];
    for (int c = 0; c < 3; c++) a[3 * i + c] = b[3 * i + c] - un * n[3 * i + c];
  }
  if (w == v) PetscCall(VecRestoreArray(w, &a));
  else {
    PetscCall(VecRestoreArrayRead(v, &b));
    PetscCall(VecRestoreArrayWrite(w, &a));
  }
  PetscCall(VecRestoreArrayRead(d->nrm, &n));
  PetscFunctionReturn(0);
}

static PetscErrorCode ProjectTangent(Newton *d, Vec v)
{
  PetscFunctionBeginUser;
  PetscCall(ProjectTangentTo(d, v, v));
  PetscFunctionReturn(0);
}

static PetscErrorCode PGPMult(Mat A, Vec v, Vec y)
{
  Newton *d;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &d));
  PetscCall(ProjectTangentTo(d, v, d->bt));
  PetscCall(MatMult(d->G, d->bt, y));
  PetscCall(ProjectTangent(d, y));
  PetscFunctionReturn(0);
}

static PetscErrorCode HessMult(Mat A, Vec v, Vec y)
{
  CSWillmoreFlow F;
  Newton        *d;
  PetscFunctionBeginUser;
  PetscCall(MatShellGetContext(A, &F));
  d = (Newton *)F->data;
  PetscCall(MatMult(d->N, v, d->u));
  PetscCall(CSEnergyHessianMult(F->energy, F->x, d->u, d->eps, d->work, d->hu));
  PetscCall(MatMultTranspose(d->N, d->hu, y));
  PetscFunctionReturn(0);
}

/* The factored form of the metric in normal coordinates, as the PC csh2 does on the full metric (h2_pc.c):
     P = (s M + L_n) M^{-1} (s M + L_n) = N^T I_H2 N + (2 s L_n - lower-order terms of N's variation),
   L_n = N^T L N, M = *0, s = sqrt(w): two solves with a 1-ring matrix instead of a factorisation of the 2-ring
   N^T I_H2 N. */
static PetscErrorCode FactoredApply(PC pc, Vec r, Vec y)
{
  Newton *d;
  PetscFunctionBeginUser;
  PetscCall(PCShellGetContext(pc, &d));
  PetscCall(KSPSolve(d->inner, r, d->w1));
  PetscCall(VecPointwiseMult(d->w1, d->w1, d->m1));
  PetscCall(KSPSolve(d->inner, d->w1, y));
  PetscFunctionReturn(0);
}

static PetscErrorCode CreateData(CSWillmoreFlow F)
{
  Newton  *d;
  PetscInt    n3, n1, N1;
  PetscMPIInt size;
  PC          pc;
  char        prefix[96];
  PetscFunctionBeginUser;
  d         = (Newton *)F->data; /* allocated by CSWillmoreFlowCreate_Newton with the options' defaults */
  d->it_dir = -1;
  PetscCall(VecDuplicate(F->x, &d->nrm));
  PetscCall(VecDuplicate(F->x, &d->u));
  PetscCall(VecDuplicate(F->x, &d->hu));
  PetscCall(VecDuplicateVecs(F->x, 2, &d->work));
  PetscCall(DMCreateGlobalVector(F->mesh->dmV1, &d->gn));
  PetscCall(VecDuplicate(d->gn, &d->phi));
  PetscCall(VecDuplicate(d->gn, &d->b));
  PetscCall(VecGetLocalSize(F->x, &n3));
  PetscCall(VecGetLocalSize(d->gn, &n1));
  PetscCall(VecGetSize(d->gn, &N1));
  PetscCall(MatCreateAIJ(F->hdr.comm, n3, n1, 3 * N1, N1, 1, NULL, 1, NULL, &d->N));
  PetscCall(MatSetOption(d->N, MAT_NEW_NONZERO_ALLOCATION_ERR, PETSC_TRUE));
  PetscCall(MatCreateShell(F->hdr.comm, n1, n1, N1, N1, F, &d->A));
  PetscCall(MatShellSetOperation(d->A, MATOP_MULT, (void (*)(void))HessMult));
  PetscCall(MatSetOption(d->A, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(KSPCreate(F->hdr.comm, &d->ksp));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%snewton_", F->hdr.prefix));
  PetscCall(KSPSetOptionsPrefix(d->ksp, prefix));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%snewton_inner_", F->hdr.prefix));
  PetscCall(KSPSetType(d->ksp, KSPCG));
  PetscCallMPI(MPI_Comm_size(F->hdr.comm, &size));
  if (d->factored) {
    PetscCall(KSPGetPC(d->ksp, &pc));
    PetscCall(PCSetType(pc, PCSHELL));
    PetscCall(PCShellSetContext(pc, d));
    PetscCall(PCShellSetApply(pc, FactoredApply));
    PetscCall(PCShellSetName(pc, "(s M + L_n) M^-1 (s M + L_n)"));
    PetscCall(DMCreateGlobalVector(F->mesh->dmV1, &d->m1));
    PetscCall(VecDuplicate(d->m1, &d->w1));
    PetscCall(KSPCreate(F->hdr.comm, &d->inner));
    PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%snewton_inner_", F->hdr.prefix));
    PetscCall(KSPSetOptionsPrefix(d->inner, prefix));
    PetscCall(KSPSetType(d->inner, KSPPREONLY));
    PetscCall(KSPGetPC(d->inner, &pc));
  } else PetscCall(KSPGetPC(d->ksp, &pc));
  if (size > 1) PetscCall(PCSetType(pc, "cssubchol")); /* as the saddle solver's Schur complement (docs/solvers.md) */
  else if (d->factored) { /* the 1-ring s M + L_n: PETSc's own Cholesky with nested dissection factors it 3-4x faster than
                             CHOLMOD (96 x 32 torus, under load: 5 ms against 20 ms per factorisation; docs/bench_evolver.md) */
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERPETSC));
    PetscCall(PCFactorSetMatOrderingType(pc, MATORDERINGND));
  } else {
    PetscCall(PCSetType(pc, PCCHOLESKY));
    PetscCall(PCFactorSetMatSolverType(pc, MATSOLVERCHOLMOD));
  }
  if (d->inner) PetscCall(KSPSetFromOptions(d->inner));
  PetscCall(KSPSetTolerances(d->ksp, 1e-2, PETSC_DEFAULT, PETSC_DEFAULT, 100)); /* inexact Newton */
  PetscCall(KSPSetFromOptions(d->ksp));
  PetscFunctionReturn(0);
}

/* N from the unit vertex normals at x (rows of owned vertices; dmV3 and dmV1 own the same vertices in order). */
static PetscErrorCode FillNormals(CSWillmoreFlow F, Newton *d)
{
  const PetscScalar *n;
  PetscInt           r3, r1, nl;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryVertexNormals(F->mesh, F->x, d->nrm));
  PetscCall(VecGetOwnershipRange(d->nrm, &r3, NULL));
  PetscCall(VecGetOwnershipRange(d->gn, &r1, NULL));
  PetscCall(VecGetLocalSize(d->gn, &nl));
  PetscCall(VecGetArrayRead(d->nrm, &n));
  for (PetscInt i = 0; i < nl; i++) {
    PetscInt col = r1 + i;
    for (PetscInt c = 0; c < 3; c++) {
      PetscInt row = r3 + 3 * i + c;
      PetscCall(MatSetValues(d->N, 1, &row, 1, &col, &n[3 * i + c], INSERT_VALUES));
    }
  }
  PetscCall(VecRestoreArrayRead(d->nrm, &n));
  PetscCall(MatAssemblyBegin(d->N, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(d->N, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* The stopping residual: ||N^T g||_2, the normal part of the gradient 2-form at x (the tangential part of the
   discrete gradient does not vanish at a discrete critical point of the normal motion). */
static PetscErrorCode NewtonResidual(CSWillmoreFlow F, PetscReal *el)
{
  Newton *d;
  PetscFunctionBeginUser;
  if (F->conformal) { /* the Lagrangian's gradient r = g + X^T mu + B nu (soliman2021 Eq. 7), as CGD's */
    PetscCall(CSWFResidual(F, el));
    PetscFunctionReturn(0);
  }
  d = (Newton *)F->data;
  if (!d->nrm) PetscCall(CreateData(F));
  PetscCall(FillNormals(F, d));
  PetscCall(MatMultTranspose(d->N, F->g, d->gn));
  PetscCall(VecNorm(d->gn, NORM_2, el));
  PetscFunctionReturn(0);
}

static PetscErrorCode FactoredSetUp(CSWillmoreFlow F, Newton *d)
{
  PetscReal s = PetscSqrtReal(F->metric.mass_weight);
  PetscFunctionBeginUser;
  PetscCall(CSOperatorNormalLaplacian(F->mesh, F->x, d->nrm, d->Ln ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, &d->Ln)); /* N^T L3 N, N from d->nrm (FillNormals) */
  PetscCall(CSOperatorMass(F->mesh, F->x, d->m1));
  PetscCall(VecScale(d->m1, s));
  PetscCall(MatDiagonalSet(d->Ln, d->m1, ADD_VALUES));
  PetscCall(VecScale(d->m1, 1.0 / s));
  PetscCall(MatSetOption(d->Ln, MAT_SYMMETRIC, PETSC_TRUE));
  PetscCall(KSPSetOperators(d->inner, d->Ln, d->Ln));
  PetscFunctionReturn(0);
}

/* phi = -P^{-1} N^T g: the H^2 gradient step in normal coordinates (the fallback). */
static PetscErrorCode MetricStep(Newton *d)
{
  PC pc;
  PetscFunctionBeginUser;
  PetscCall(KSPGetPC(d->ksp, &pc));
  PetscCall(PCApply(pc, d->b, d->phi));
  d->fallbacks++;
  PetscFunctionReturn(0);
}

/* The Newton direction phi at x (once per iteration; the rejections of the iteration only shorten t). */
static PetscErrorCode Direction(CSWillmoreFlow F, Newton *d)
{
  KSPConvergedReason reason;
  PetscInt           its;
  PetscScalar        slope;
  PetscReal          h;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryMeanEdgeLength(F->mesh, F->x, &h));
  d->eps = 1e-5 * h;
  if (d->setups == 0 || d->last_its > d->reuse_its) { /* the metric at x, restricted to normal motion, factored anew */
    if (d->factored) PetscCall(FactoredSetUp(F, d));
    else {
      PetscCall(CSMetricUpdate(&F->metric, F->x));
      PetscCall(MatPtAP(F->metric.H, d->N, d->Mn ? MAT_REUSE_MATRIX : MAT_INITIAL_MATRIX, 2.0, &d->Mn));
    }
    PetscCall(KSPSetOperators(d->ksp, d->A, d->factored ? d->A : d->Mn));
    PetscCall(KSPSetReusePreconditioner(d->ksp, PETSC_FALSE));
    d->setups++;
  } else PetscCall(KSPSetReusePreconditioner(d->ksp, PETSC_TRUE)); /* an earlier state's metric: still a good PC */
  PetscCall(VecCopy(d->gn, d->b));
  PetscCall(VecScale(d->b, -1.0));
  PetscCall(KSPSolve(d->ksp, d->b, d->phi));
  PetscCall(KSPGetConvergedReason(d->ksp, &reason));
  PetscCall(KSPGetIterationNumber(d->ksp, &its));
  F->kspits += its;
  d->cg_its += its;
  d->last_its = its;
  PetscCall(VecDot(d->phi, d->gn, &slope));
  if (reason < 0) d->truncated++;
  if (!(PetscRealPart(slope) < 0)) PetscCall(MetricStep(d)); /* zero (indefinite at once) or not a descent direction */
  if (reason < 0) PetscCall(PetscPrintf(F->hdr.comm, "     newton: CG stopped after %" PetscInt_FMT " iterations (%s): %s\n", its, KSPConvergedReasons[reason], PetscRealPart(slope) < 0 ? "the truncated CG iterate is taken" : "H^2 metric step"));
  d->it_dir = F->it;
  PetscFunctionReturn(0);
}

static PetscErrorCode TrialNewton(CSWillmoreFlow F, PetscBool *accept)
{
  Newton *d = (Newton *)F->data;
  PetscFunctionBeginUser;
  if (F->conformal) { /* the constrained problem: Newton on its first-order conditions (newton_kkt.c) */
    if (!d->kkt) PetscCall(CSNewtonKKTCreate(F, d->kkt_pc_t, &d->kkt));
    PetscCall(CSNewtonKKTTrial(F, d->kkt, accept));
    PetscFunctionReturn(0);
  }
  if (d->it_dir != F->it) PetscCall(Direction(F, d));
  PetscCall(MatMult(d->N, d->phi, F->df));
  PetscCall(VecScale(F->df, F->t));
  PetscCall(VecWAXPY(F->xt, 1.0, F->df, F->x));
  *accept = PETSC_TRUE;
  PetscFunctionReturn(0);
}

/* Tangential relaxation (-flow_newton_relax lambda): the vertices move within their tangent planes toward the
   minimiser of the graph Dirichlet energy sum_edges w_ij |x_i - x_j|^2 (CG on P G P a = -P G x), by lambda of the way,
   the largest move capped at -flow_max_step / 2 mean edge lengths; -flow_newton_relax_sweeps such solves, the
   weights recomputed before each. Weights 1 (the graph-harmonic distribution: about equal edge lengths) or, with
   -flow_newton_relax_scaled, 1/sqrt(area) of each face (CSOperatorScaledGraphLaplacian3: spacing in proportion to
   the local edge length across the mesh, which raises the smallest angle where a region has shrunk in one
   direction only, as the inner side of a torus does on its way to the Clifford torus; docs/bench_evolver.md). */
static PetscErrorCode RelaxSweep(CSWillmoreFlow F, Newton *d)
{
  PetscReal amax, h;
  PetscFunctionBeginUser;
  if (d->relax_scaled) PetscCall(CSOperatorScaledGraphLaplacian(F->mesh, F->x, MAT_REUSE_MATRIX, &d->G1)); /* G = G1 on each coordinate */
  else PetscCall(CSOperatorGraphLaplacian(F->mesh, F->x, MAT_REUSE_MATRIX, &d->G1));
  PetscCall(CSGeometryVertexNormals(F->mesh, F->x, d->nrm));
  PetscCall(KSPSetOperators(d->kspT, d->PGP, d->PGP));
  PetscCall(MatMult(d->G, F->x, d->u));
  PetscCall(ProjectTangent(d, d->u));
  PetscCall(VecScale(d->u, -1.0));
  PetscCall(KSPSolve(d->kspT, d->u, d->at));
  PetscCall(ProjectTangent(d, d->at));
  PetscCall(VecNorm(d->at, NORM_INFINITY, &amax));
  PetscCall(CSGeometryMeanEdgeLength(F->mesh, F->x, &h));
  PetscCall(VecAXPY(F->x, PetscMin(d->relax, 0.5 * F->max_step * h / PetscMax(amax, 1e-300)), d->at));
  PetscFunctionReturn(0);
}

static PetscErrorCode Relax(CSWillmoreFlow F, Newton *d)
{
  PetscInt n, N;
  PC       pc;
  char     prefix[96];
  PetscFunctionBeginUser;
  if (!(d->relax > 0)) PetscFunctionReturn(0);
  if (!d->PGP) {
    PetscCall(CSOperatorGraphLaplacian(F->mesh, F->x, MAT_INITIAL_MATRIX, &d->G1));
    PetscCall(MatCreateMAIJ(d->G1, 3, &d->G)); /* dmV3 interlaces the 3 coordinates of the vertices dmV1 owns, in order */
    PetscCall(VecGetLocalSize(F->x, &n));
    PetscCall(VecGetSize(F->x, &N));
    PetscCall(MatCreateShell(F->hdr.comm, n, n, N, N, d, &d->PGP));
    PetscCall(MatShellSetOperation(d->PGP, MATOP_MULT, (void (*)(void))PGPMult));
    PetscCall(VecDuplicate(F->x, &d->at));
    PetscCall(VecDuplicate(F->x, &d->bt));
    PetscCall(KSPCreate(F->hdr.comm, &d->kspT));
    PetscCall(KSPSetType(d->kspT, KSPCG));
    PetscCall(KSPSetTolerances(d->kspT, 1e-3, PETSC_DEFAULT, PETSC_DEFAULT, 200));
    PetscCall(KSPGetPC(d->kspT, &pc));
    PetscCall(PCSetType(pc, PCNONE));
    PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%snewton_relax_", F->hdr.prefix));
    PetscCall(KSPSetOptionsPrefix(d->kspT, prefix));
    PetscCall(KSPSetFromOptions(d->kspT));
  }
  for (PetscInt k = 0; k < d->relax_sweeps; k++) PetscCall(RelaxSweep(F, d));
  PetscFunctionReturn(0);
}

/* with the conformal rows the multipliers of the step, and no tangential relaxation (the rows fix the vertices' places) */
static PetscErrorCode AcceptNewton(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(CSNewtonKKTAccept(F));
  else PetscCall(Relax(F, (Newton *)F->data));
  PetscFunctionReturn(0);
}

static PetscErrorCode FilterNewton(CSWillmoreFlow F, PetscBool *accept)
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(CSNewtonKKTFilter(F, ((Newton *)F->data)->kkt, accept));
  else PetscCall(CSWFFilterEnergy(F, accept));
  PetscFunctionReturn(0);
}

static PetscErrorCode SetFromOptionsNewton(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject)
{
  Newton *d = (Newton *)F->data;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsBool("-newton_factored_pc", "Precondition CG with (s M + L_n) M^-1 (s M + L_n) (two 1-ring solves) instead of a factorisation of N^T I_H2 N", NULL, d->factored, &d->factored, NULL));
  PetscCall(CSOptionsReal("-newton_relax", "Tangential relaxation toward the graph-harmonic vertex distribution after each accepted step: fraction of the way (0: off)", NULL, d->relax, &d->relax, NULL));
  PetscCall(CSOptionsInt("-newton_relax_sweeps", "Solves of the tangential relaxation per accepted step (weights recomputed before each)", NULL, d->relax_sweeps, &d->relax_sweeps, NULL));
  PetscCall(PetscOptionsBool("-newton_relax_scaled", "Weight the relaxation's edges by 1/sqrt(face area) (spacing in proportion to the local edge length: raises the smallest angle) instead of 1", NULL, d->relax_scaled, &d->relax_scaled, NULL));
  PetscCall(CSOptionsReal("-newton_kkt_pc_t", "With -flow_conformal: t of the H^2 metric H / t that stands for the Hessian of the Lagrangian in the preconditioner of the KKT solve", NULL, d->kkt_pc_t, &d->kkt_pc_t, NULL));
  PetscCall(CSOptionsInt("-newton_reuse_its", "Keep the factored metric preconditioner of an earlier iteration while CG needed at most this many iterations (0: refactor every iteration)", NULL, d->reuse_its, &d->reuse_its, NULL));
  PetscFunctionReturn(0);
}

/* the options against each other and against the problem (after the flow's options block) */
static PetscErrorCode SetUpNewton(CSWillmoreFlow F)
{
  const char *p = F->hdr.prefix;
  Newton     *d = (Newton *)F->data;
  PetscFunctionBeginUser;
  PetscCheck(d->relax >= 0 && d->relax <= 1, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%snewton_relax %g: must lie in [0, 1]", p, (double)d->relax);
  PetscCheck(d->relax_sweeps >= 1, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%snewton_relax_sweeps %" PetscInt_FMT ": must be >= 1", p, d->relax_sweeps);
  PetscCheck(d->reuse_its >= 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%snewton_reuse_its %" PetscInt_FMT ": must be >= 0", p, d->reuse_its);
  PetscCheck(d->kkt_pc_t > 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%snewton_kkt_pc_t %g: must be > 0", p, (double)d->kkt_pc_t);
  PetscCheck(F->conformal || (!F->area_set && !F->vol_set && !F->points[0] && !F->mobius && !F->target[0]), F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype newton supports no constraints without -%sconformal (area, volume, points, Moebius, target mesh): add -%sconformal, or use gd or cgd", p, p, p);
  PetscCheck(!F->conformal || !F->normals, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype newton -%sconformal: the boundary normal rows are not supported (use cgd)", p, p);
  /* W and the class are scale invariant, r(s x) = r(x) / s: without a scale row the KKT step grows the surface (the
     48 x 24 torus of Fig. 17: area 22 -> 1069 in 15 iterations) */
  if (F->conformal && !F->area_set && !F->vol_set) PetscCall(PetscPrintf(F->hdr.comm, "Warning: -%stype newton -%sconformal without -%sconstraint_area (or _volume): W and the conformal class are scale invariant, and the Newton step may grow the surface without bound\n", p, p, p));
  PetscCheck(F->mesh->topo.boundary_loops == 0, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype newton: the mesh %s has %" PetscInt_FMT " boundary loop(s); newton supports closed surfaces only (use gd or cgd)", p, F->mesh->name, F->mesh->topo.boundary_loops);
  PetscFunctionReturn(0);
}

/* A constraint added by CSWillmoreFlowAddConstraint is counted in F->k only at the flow's set-up, after SetUpNewton
   (which refuses the option-made ones): the Newton step has no constraint rows and ran ignoring it (area violation 3.0
   after 3 iterations of a level-2 icosphere). A resume cannot add one: the checkpoint's size counts the rows. */
static PetscErrorCode StartNewton(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCheck(F->k == 0 || F->conformal, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%stype newton supports no constraints: the constraint %s added by CSWillmoreFlowAddConstraint is not supported (use gd or cgd)", F->hdr.prefix, F->nadded ? F->added[0] : "(global)");
  PetscFunctionReturn(0);
}

static PetscErrorCode DestroyNewton(CSWillmoreFlow F)
{
  Newton *d = (Newton *)F->data;
  PetscFunctionBeginUser;
  if (d->kkt) PetscCall(PetscInfo(NULL, "newton: %" PetscInt_FMT " FGMRES iterations of the KKT solves\n", CSNewtonKKTIterations(d->kkt)));
  PetscCall(CSNewtonKKTDestroy(&d->kkt));
  if (!d->nrm) {
    PetscCall(PetscFree(F->data));
    PetscFunctionReturn(0);
  }
  PetscCall(PetscInfo(NULL, "newton: %" PetscInt_FMT " CG iterations, %" PetscInt_FMT " truncated solves, %" PetscInt_FMT " metric steps, %" PetscInt_FMT " factorisations\n", d->cg_its, d->truncated, d->fallbacks, d->setups));
  PetscCall(MatDestroy(&d->N));
  PetscCall(MatDestroy(&d->A));
  PetscCall(MatDestroy(&d->Mn));
  PetscCall(MatDestroy(&d->Ln));
  PetscCall(VecDestroy(&d->m1));
  PetscCall(VecDestroy(&d->w1));
  PetscCall(KSPDestroy(&d->inner));
  PetscCall(MatDestroy(&d->G));
  PetscCall(MatDestroy(&d->G1));
  PetscCall(MatDestroy(&d->PGP));
  PetscCall(KSPDestroy(&d->kspT));
  PetscCall(VecDestroy(&d->at));
  PetscCall(VecDestroy(&d->bt));
  PetscCall(KSPDestroy(&d->ksp));
  PetscCall(VecDestroy(&d->nrm));
  PetscCall(VecDestroy(&d->u));
  PetscCall(VecDestroy(&d->hu));
  PetscCall(VecDestroyVecs(2, &d->work));
  PetscCall(VecDestroy(&d->gn));
  PetscCall(VecDestroy(&d->phi));
  PetscCall(VecDestroy(&d->b));
  PetscCall(PetscFree(F->data));
  PetscFunctionReturn(0);
}

static PetscErrorCode ViewNewton(CSWillmoreFlow F, PetscViewer viewer)
{
  Newton *d = (Newton *)F->data;
  PetscFunctionBeginUser;
  PetscCall(PetscViewerASCIIPrintf(viewer, "  newton: preconditioner %s, reuse while CG <= %" PetscInt_FMT " its, tangential relaxation %g (%" PetscInt_FMT " sweeps%s)\n", d->factored ? "(s M + L_n) M^-1 (s M + L_n)" : "N^T I_H2 N factored", d->reuse_its, (double)d->relax, d->relax_sweeps, d->relax_scaled ? ", scaled" : ""));
  PetscFunctionReturn(0);
}

/* CGD's step sizes without the -t_mu_final switch (no constraint rows) */
static PetscErrorCode GrowNewton(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFGrowDual(F, NULL));
  PetscFunctionReturn(0);
}

static PetscErrorCode ShrinkNewton(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFShrinkDual(F, NULL));
  PetscFunctionReturn(0);
}

/* the kind's strategy (willmore_impl.h), grouped: identity, the step, hooks, its own data and options */
static const struct _CSWillmoreFlowOps NewtonOps = {
  .id = 3, .conformal = PETSC_FALSE, .fold_guard = PETSC_TRUE, .own_metric = PETSC_TRUE,
  .max_step = 2, /* mean edge lengths per step (willmore_guards.c) */
  .trial = TrialNewton, .filter = FilterNewton, .accept = AcceptNewton, .grow = GrowNewton, .shrink = ShrinkNewton,
  .residual = NewtonResidual, .start = StartNewton,
  .setfromoptions = SetFromOptionsNewton, .setup = SetUpNewton, .view = ViewNewton, .destroy = DestroyNewton,
};

PetscErrorCode CSWillmoreFlowCreate_Newton(CSWillmoreFlow F)
{
  Newton *d;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(&d));
  d->factored           = PETSC_TRUE;
  d->relax              = 0.3; /* bumpy level-4 sphere: smallest angle 22 -> 49 degrees, q_max 2.8 -> 1.6; torus unchanged */
  d->relax_sweeps       = 1;
  d->kkt_pc_t           = 4; /* FGMRES its per KKT solve, 48 x 24 torus of Fig. 17: 200+ (t_pc 0.25), 52-67 (1), 20-24 (4), 20-25 (8), 22-31 (16) */
  d->reuse_its          = 0; /* refactor every iteration: kept factors change the inexact steps, and the final mesh quality moved both ways (docs/willmore_flow.md) */
  F->data               = d;
  F->ops                = NewtonOps;
  F->tmax               = 1; /* the full Newton step */
  PetscFunctionReturn(0);
}
