/* Constrained Willmore flow: soliman2021 Algorithm 1 (CGD), Sec. 4.1 (PGD with projection) and Eq. GD,
   in the H^2 metric (Eq. 26) or L2, with the conformal constraint (Sec. 3, App. D) and area / volume /
   point constraints (App. D "Constraints"), Dirichlet boundaries and C0 on surfaces with boundary.

   Step (CGD, Algorithm 1 line 11, whose block signs we follow; the displayed (CGD) equation of Sec. 4.2
   has -X and +I/t in its second row with right-hand side -c, i.e. X df - dmu/t = +c, which would push the
   constraint away from c = 0: a sign slip):
     [ H/t   X^T        ] [df ]   [ -g - X^T mu ]
     [ X    -I_Q/t_mu   ] [dmu] = [ -c          ]
   solved with the edge block first (CSSaddle). The primal step t and the dual step t_mu are separate:
   the second row reads X df = -c + I_Q dmu / t_mu, so with t_mu = t (the paper's single t) a small t also
   damps the Newton correction of the constraint; a large t_mu makes X df ~ -c (Gauss-Newton on c) while t
   still controls the energy descent.

   Step control: a trial step is rejected, t halved and the step recomputed (each rejection is reported),
   when it makes things worse; after an accepted step t grows by -flow_t_grow up to -flow_t_max.
     PGD:    worse = E increases (after the projection back onto the constraint set), or the projection fails.
     CGD/GD: a two-criteria filter on the Lagrangian with the updated multipliers
               L(f) = E(f) + <mu+dmu, c(f)> + <nu+dnu, xi(f)>   (+ rho/2 |c|^2 with -flow_merit_rho, default 0)
             and the violation v(f) = max(||c(f)||_inf, max_j |xi_j(f)|):
             worse = (L increases and (v increases or f was feasible, v(f) <= ctol)) or v exceeds
                     max(v(f), -flow_vmax): above the ceiling -flow_vmax the violation never grows (it used to
                     be allowed 10x per step, and on knot1_cgal it grew 1.7x per accepted step to 0.9).
             Before the test the trial point gets up to -flow_soc_max_it second-order corrections
             (SecondOrderCorrection), and a rejection halves t but not t_mu (see there); an accepted state
             stalled near the ceiling is projected back onto the constraints (Restore).
   Why not a single merit: along the CGD direction dL = -<H df, df>/t < 0 (first row of the system), but
   the change of v depends on t and t_mu: with an l1 or quadratic penalty of v the penalty's first-order
   term rho <c, X df> is O(t) of either sign once c != 0, and we saw every t rejected (torus of revolution,
   bunny). The filter accepts a step that improves either quantity without spoiling the other. Without
   constraints (GD) it is "E decreases".
   Stopping: el_residual = ||g + X^T mu + B^T nu||_2, the Euclidean norm of the residual 2-form of the
   Euler-Lagrange equations (soliman2021 Eq. 7 with the extra constraints; entries of fixed vertices
   excluded), below -flow_rtol, and the constraint violation max(||C lambda - c0||_inf, max_j |xi_j|)
   below -flow_ctol.
   Resolution guard (-flow_max_area_ratio): the discrete conformal constraint (length cross ratios) is
   invariant under Moebius transformations of R^3, and so is the smooth W, but the discrete W (Eq. 28) is
   not: it decreases when the vertex density is graded along a Moebius orbit (a boosted icosphere on the
   unit sphere keeps every cross ratio to 1e-13 and has W = 9.8 < 4 pi; an icosahedron has W = 9.57). The
   flow then lowers W by concentrating vertices instead of changing the shape, and W can end below the
   smooth lower bounds (4 pi, 2 pi^2). We stop when the spread max_i(A_i/A0_i) / min_i(A_i/A0_i) of the
   barycentric vertex areas relative to the input exceeds the limit, or when the total area has changed by more
   than that factor (a diverging run: a far-off volume target once grew |xi| 6x per step with the Lagrangian
   falling, which the step filter accepts) (0 disables; default 200: the vesicle of
   options/flow_vesicle.opts is still well resolved at a spread of 159 and W has dropped by 1.4 at 1740).
   The cure is -constraint_mobius (constraints_global.c, not the default), which fixes the three Moebius
   boosts: with it the vesicle keeps q_max 1.08 and W = 16.31 instead of sliding to W = 9.29. */
#include "willmore_flow.h"
#include "cs_util.h"

typedef struct {
  CSFlowKind            kind;
  MPI_Comm              comm;
  CSMesh                mesh;
  CSEnergy              energy;
  char                  energy_name[32];
  PetscBool             conformal;
  CSConformalConstraint cc;
  PetscBool             normals; /* boundary-face normal constraint: its rows follow the edge rows */
  CSNormalConstraint    nc;
  Mat                   Xn, Xext, Xc; /* nest [X; DN], its AIJ form, and the Jacobian in use (X or Xext) */
  IS                    isM[2];       /* edge / normal rows in the multiplier layout */
  Vec                   cE, cN, iqE, iqN;
  PetscInt              ng, k;
  CSGlobalConstraint    gc[4];
  PetscBool            *fixed; /* local vertices held fixed (Dirichlet), or NULL */
  IS                    fixedIS; /* global dmV3 dofs of owned fixed vertices */
  CSMetric              metric;
  CSSaddle              saddle;
  Vec                   x, x0, g, r, c, mu, dmu, df, iq, xt, ct, tmp;
  Vec                  *rows;
  PetscReal            *cx, *cxt, *nu, *dnu, *dnu2, *gw;
  PetscReal             t, tmu, tmax, grow, rtol, ctol, wmin, rho, vmax, vrestore, *nun;
  PetscBool             restore_stalled, restore_failed;
  Vec                   mun;
  Vec                   area0, areat; /* barycentric vertex areas of the input and of the current state */
  PetscReal             area0_total;  /* total area of the input */
  PetscReal             max_area_ratio;
  PetscInt              max_it, max_rej, proj_max_it, soc_max_it;
  PetscBool             step_control;
  PetscReal             proj_tmu;
  PetscReal             tmu_grow, tmu_max; /* own schedule of the dual step (0: t_mu follows t) */
  PetscReal             tmu_ratio_max;     /* following t: t_mu <= this * t (1e3 times the initial t_mu / t) */
} Flow;

/* ---------- options and setup ---------- */

/* "-constraint_area [value]": no value means the initial value. */
static PetscErrorCode OptionalTarget(const char name[], const char help[], PetscBool *set, PetscReal *value, PetscBool *given, PetscOptionItems *PetscOptionsObject)
{
  char s[128] = "";
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsString(name, help, NULL, s, s, sizeof(s), set));
  *given = PETSC_FALSE;
  if (*set && s[0]) {
    PetscCall(PetscOptionsStringToReal(s, value));
    *given = PETSC_TRUE;
  }
  PetscFunctionReturn(0);
}

/* Test inputs: f <- S (f (1 + a sin(k f_x) sin(k f_y) sin(k f_z))) applied to the initial positions
   (-flow_init_bump a, -flow_init_bump_freq k, -flow_init_stretch sx,sy,sz); pointwise, so the same on any
   number of ranks. */
static PetscErrorCode DeformInitial(Vec x, PetscReal a, PetscReal k, const PetscReal s[3])
{
  PetscInt     n;
  PetscScalar *p;
  PetscFunctionBeginUser;
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArray(x, &p));
  for (PetscInt i = 0; i < n / 3; i++) {
    PetscReal *q = (PetscReal *)p + 3 * i, b = 1 + a * PetscSinReal(k * q[0]) * PetscSinReal(k * q[1]) * PetscSinReal(k * q[2]);
    for (int d = 0; d < 3; d++) q[d] *= b * s[d];
  }
  PetscCall(VecRestoreArray(x, &p));
  PetscFunctionReturn(0);
}

static PetscErrorCode ZeroFixed(Flow *F, Vec v)
{
  PetscFunctionBeginUser;
  if (F->fixedIS) PetscCall(VecISSet(v, F->fixedIS, 0.0));
  PetscFunctionReturn(0);
}

static PetscErrorCode FlowSetUp(MPI_Comm comm, Flow *F, CSFlowKind kind, CSOutput *out)
{
  CSMesh    m;
  char      metric[16] = "h2", energy[32] = "willmore", target[PETSC_MAX_PATH_LEN] = "", points[PETSC_MAX_PATH_LEN] = "", boundary[32] = "";
  PetscBool conformal = (PetscBool)(kind != CS_FLOW_GD), conformal_set, has_target, has_points, has_boundary, area_set, area_given, vol_set, vol_given, h2, mobius = PETSC_FALSE;
  PetscReal area_target = 0, vol_target = 0, bump = 0, bump_k = 3, stretch[3] = {1, 1, 1}, eps = 1e-3;
  PetscInt  nstretch = 3;
  PetscBool stretch_set;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(F, sizeof(*F)));
  F->kind = kind;
  F->comm = comm;
  PetscCall(CSMeshCreateFromOptions(comm, NULL, &F->mesh));
  m            = F->mesh;
  F->t         = 1.0;
  F->tmu       = -1;
  F->tmax      = 2.0;
  F->grow      = 2.0;
  F->rtol      = 1e-6;
  F->ctol      = 1e-10;
  F->wmin      = 1e-2;
  F->max_it    = 100;
  F->max_rej   = 30;
  F->proj_max_it = 20;
  F->soc_max_it = 2;
  F->proj_tmu  = 1e6;
  F->step_control = PETSC_TRUE;
  F->rho       = 0.0;
  F->vmax      = 1e-2;
  F->vrestore  = 0; /* off by default: see Restore */
  F->restore_stalled = PETSC_TRUE;
  F->tmu_grow  = 0;
  F->tmu_max   = 0;
  F->max_area_ratio = 200;
  PetscOptionsBegin(comm, NULL, "Constrained Willmore flow (soliman2021)", NULL);
  PetscCall(PetscOptionsReal("-flow_t", "Initial primal step size t", NULL, F->t, &F->t, NULL));
  PetscCall(PetscOptionsReal("-flow_t_mu", "Dual step size t_mu of the multipliers (default 1e3 t)", NULL, F->tmu, &F->tmu, NULL));
  PetscCall(PetscOptionsReal("-flow_t_max", "Largest primal step", NULL, F->tmax, &F->tmax, NULL));
  PetscCall(PetscOptionsReal("-flow_t_mu_grow", "Grow t_mu by this factor after each accepted step, independently of t, up to -flow_t_mu_max (0: t_mu follows t)", NULL, F->tmu_grow, &F->tmu_grow, NULL));
  PetscCall(PetscOptionsReal("-flow_t_mu_max", "Largest t_mu (default: 1e3 t_max with -flow_t_mu_grow, else none; in the units of -flow_t_mu)", NULL, F->tmu_max, &F->tmu_max, NULL));
  PetscCall(PetscOptionsReal("-flow_t_grow", "Factor on t after an accepted step", NULL, F->grow, &F->grow, NULL));
  PetscCall(PetscOptionsBool("-flow_step_control", "Accept a step only if the merit function decreases (else halve t)", NULL, F->step_control, &F->step_control, NULL));
  PetscCall(PetscOptionsInt("-flow_max_rejections", "Consecutive rejected steps before giving up", NULL, F->max_rej, &F->max_rej, NULL));
  PetscCall(PetscOptionsReal("-flow_merit_rho", "Weight of the quadratic constraint penalty in the merit function, relative to |E(input)|", NULL, F->rho, &F->rho, NULL));
  PetscCall(PetscOptionsReal("-flow_vmax", "Step control: reject steps whose constraint violation exceeds max(v, this), v that of the current state", NULL, F->vmax, &F->vmax, NULL));
  PetscCall(PetscOptionsReal("-flow_restore_above", "CGD/GD: project an accepted state whose constraint violation exceeds this back onto the constraints (Gauss-Newton, as PGD's projection; 0: never)", NULL, F->vrestore, &F->vrestore, NULL));
  PetscCheck(F->vrestore >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_restore_above %g: use 0 (off) or a positive violation", (double)F->vrestore);
  PetscCall(PetscOptionsBool("-flow_restore_stalled", "CGD/GD: project an accepted state back onto the constraints when t has collapsed (t < 1e-3 t_max) with the violation above -flow_vmax / 10", NULL, F->restore_stalled, &F->restore_stalled, NULL));
  PetscCall(PetscOptionsReal("-flow_max_area_ratio", "Stop when max(A_i/A0_i)/min(A_i/A0_i) of the vertex areas, or the total area relative to the input, exceeds this (mesh resolution collapse, divergence; 0: off)", NULL, F->max_area_ratio, &F->max_area_ratio, NULL));
  PetscCheck(F->max_area_ratio == 0 || F->max_area_ratio > 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_max_area_ratio %g: use 0 (off) or a ratio above 1", (double)F->max_area_ratio);
  PetscCall(PetscOptionsReal("-flow_rtol", "Stop when ||g + X^T mu||_2 is below this", NULL, F->rtol, &F->rtol, NULL));
  PetscCall(PetscOptionsReal("-flow_ctol", "... and the constraint violation (inf-norm) below this", NULL, F->ctol, &F->ctol, NULL));
  PetscCall(PetscOptionsInt("-flow_max_it", "Maximum number of iterations", NULL, F->max_it, &F->max_it, NULL));
  PetscCall(PetscOptionsString("-flow_metric", "h2|l2: metric of the primal step (soliman2021 Eq. 26 or the mass)", NULL, metric, metric, sizeof(metric), NULL));
  PetscCall(PetscOptionsReal("-flow_iq_wmin", "Floor on cotan weights in I_Q (Eq. 25) for non-Delaunay edges", NULL, F->wmin, &F->wmin, NULL));
  PetscCall(PetscOptionsString("-energy", "willmore|area|fairing", NULL, energy, energy, sizeof(energy), NULL));
  PetscCall(PetscOptionsReal("-fairing_epsilon", "Weight of W in the fairing energy (soliman2021 Eq. 21)", NULL, eps, &eps, NULL));
  PetscCall(PetscOptionsBool("-flow_conformal", "Exact conformal constraint (default on for cgd and pgd)", NULL, conformal, &conformal, &conformal_set));
  PetscCall(PetscOptionsString("-target_mesh", "Mesh with the same connectivity whose conformal class is the target (soliman2021 Fig. 2)", NULL, target, target, sizeof(target), &has_target));
  PetscCall(OptionalTarget("-constraint_area", "Total area constraint [target value, default the initial area]", &area_set, &area_target, &area_given, PetscOptionsObject));
  PetscCall(OptionalTarget("-constraint_volume", "Enclosed volume constraint [target value, default the initial volume]", &vol_set, &vol_target, &vol_given, PetscOptionsObject));
  PetscCall(PetscOptionsString("-constraint_points", "File of point constraints: lines 'vertex_index x y z' (0-based)", NULL, points, points, sizeof(points), &has_points));
  PetscCall(PetscOptionsBool("-constraint_mobius", "Moebius balancing: fix the three Moebius boosts that the conformal constraint leaves free and along which the discrete W degrades the mesh (for the Willmore energy on closed surfaces; needs the conformal constraint)", NULL, mobius, &mobius, NULL));
  PetscCall(PetscOptionsString("-flow_boundary", "dirichlet|free|normals: boundary vertices fixed, free (C0 only), or fixed with fixed boundary-face normals (App. D)", NULL, boundary, boundary, sizeof(boundary), &has_boundary));
  PetscCall(PetscOptionsReal("-flow_init_bump", "Test input: radial bump amplitude applied to the initial positions", NULL, bump, &bump, NULL));
  PetscCall(PetscOptionsReal("-flow_init_bump_freq", "Test input: bump frequency k in sin(k x) sin(k y) sin(k z)", NULL, bump_k, &bump_k, NULL));
  PetscCall(PetscOptionsRealArray("-flow_init_stretch", "Test input: stretch factors sx,sy,sz applied after the bump", NULL, stretch, &nstretch, &stretch_set));
  PetscCall(PetscOptionsReal("-pgd_t_mu", "PGD: regularising dual step of the (singular) PGD system and of the projection", NULL, F->proj_tmu, &F->proj_tmu, NULL));
  PetscCall(PetscOptionsInt("-flow_soc_max_it", "CGD/GD: second-order corrections of each trial step toward the constraints (0: none)", NULL, F->soc_max_it, &F->soc_max_it, NULL));
  PetscCheck(F->soc_max_it >= 0, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_soc_max_it %" PetscInt_FMT ": use 0 (no corrections) or a positive count", F->soc_max_it);
  PetscCall(PetscOptionsInt("-pgd_projection_max_it", "PGD: Gauss-Newton iterations of the projection onto the constraint set", NULL, F->proj_max_it, &F->proj_max_it, NULL));
  PetscOptionsEnd();
  if (F->tmu <= 0) F->tmu = 1e3 * F->t;
  PetscCheck(F->t > 0 && F->tmu > 0 && F->grow >= 1 && F->tmax >= F->t, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_t %g, -flow_t_mu %g, -flow_t_grow %g, -flow_t_max %g: need t > 0, t_mu > 0, grow >= 1, t_max >= t", (double)F->t, (double)F->tmu, (double)F->grow, (double)F->tmax);
  PetscCheck(F->tmu_grow == 0 || F->tmu_grow >= 1, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_t_mu_grow %g: use 0 (t_mu follows t) or a factor >= 1", (double)F->tmu_grow);
  PetscCheck(kind != CS_FLOW_GD || !conformal, comm, PETSC_ERR_ARG_INCOMP, "-flow_type gd is unconstrained Sobolev gradient descent: -flow_conformal true is not allowed (use cgd or pgd)");
  F->conformal = conformal;
  PetscCheck(!has_target || conformal, comm, PETSC_ERR_ARG_INCOMP, "-target_mesh %s needs the conformal constraint (cgd, or pgd with -flow_conformal)", target);
  PetscCheck(!has_target || kind != CS_FLOW_PGD, comm, PETSC_ERR_ARG_INCOMP, "-target_mesh with -flow_type pgd: PGD keeps the class of its input and cannot move to another class (soliman2021 Sec. 4.2); use cgd");
  PetscCall(PetscStrcmp(metric, "h2", &h2));
  if (!h2) {
    PetscBool l2;
    PetscCall(PetscStrcmp(metric, "l2", &l2));
    PetscCheck(l2, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_metric %s: unknown (h2|l2)", metric);
  }
  PetscCall(PetscStrncpy(F->energy_name, energy, sizeof(F->energy_name)));
  (void)out;

  /* positions */
  PetscCall(VecDuplicate(m->x, &F->x));
  PetscCall(VecCopy(m->x, F->x));
  PetscCheck(!stretch_set || nstretch == 3, comm, PETSC_ERR_ARG_SIZ, "-flow_init_stretch needs three values sx,sy,sz");
  if (bump != 0 || stretch[0] != 1 || stretch[1] != 1 || stretch[2] != 1) PetscCall(DeformInitial(F->x, bump, bump_k, stretch));
  PetscCall(VecDuplicate(F->x, &F->x0));
  PetscCall(VecCopy(F->x, F->x0));
  PetscCall(DMCreateGlobalVector(m->dmV1, &F->area0));
  PetscCall(VecDuplicate(F->area0, &F->areat));
  PetscCall(CSGeometryVertexAreas(m, F->x0, F->area0));
  {
    PetscScalar a0;
    PetscCall(VecSum(F->area0, &a0));
    F->area0_total = PetscRealPart(a0);
  }

  /* boundary */
  if (has_boundary) PetscCheck(m->topo.boundary_loops > 0, comm, PETSC_ERR_ARG_INCOMP, "-flow_boundary %s: the mesh %s is closed (no boundary); boundary methods need a surface with boundary", boundary, m->name);
  if (m->topo.boundary_loops > 0) {
    PetscBool dir = PETSC_TRUE;
    if (has_boundary) {
      PetscBool isdir, isfree, isnormal;
      PetscCall(PetscStrcmp(boundary, "dirichlet", &isdir));
      PetscCall(PetscStrcmp(boundary, "free", &isfree));
      PetscCall(PetscStrcmp(boundary, "normals", &isnormal));
      PetscCheck(!isnormal || conformal, comm, PETSC_ERR_ARG_INCOMP, "-flow_boundary normals needs the conformal constraint (cgd or pgd)");
      PetscCheck(isdir || isfree || isnormal, comm, PETSC_ERR_ARG_OUTOFRANGE, "-flow_boundary %s: unknown (dirichlet|free|normals)", boundary);
      dir        = (PetscBool)(isdir || isnormal); /* normals = fixed positions and fixed boundary-face normals (Fig. 2) */
      F->normals = isnormal;
    }
    if (dir) {
      ISLocalToGlobalMapping l2g;
      PetscInt              *idx, n = 0;
      PetscCall(PetscCalloc1(m->nv, &F->fixed));
      PetscCall(PetscMalloc1(3 * m->nv, &idx));
      for (PetscInt v = 0; v < m->nv; v++) {
        F->fixed[v] = m->vertBoundary[v];
        if (m->vertBoundary[v] && m->vertOwned[v])
          for (int d = 0; d < 3; d++) idx[n++] = 3 * v + d;
      }
      PetscCall(DMGetLocalToGlobalMapping(m->dmV3, &l2g));
      PetscCall(ISLocalToGlobalMappingApply(l2g, n, idx, idx));
      PetscCall(ISCreateGeneral(comm, n, idx, PETSC_OWN_POINTER, &F->fixedIS));
    }
  }

  /* energy */
  {
    PetscBool isw, isa, isf;
    PetscCall(PetscStrcmp(energy, "willmore", &isw));
    PetscCall(PetscStrcmp(energy, "area", &isa));
    PetscCall(PetscStrcmp(energy, "fairing", &isf));
    if (isw) PetscCall(CSEnergyCreateWillmore(m, &F->energy));
    else if (isa) PetscCall(CSEnergyCreateArea(m, &F->energy));
    else if (isf) PetscCall(CSEnergyCreateFairing(m, F->x0, eps, &F->energy));
    else SETERRQ(comm, PETSC_ERR_ARG_OUTOFRANGE, "-energy %s: unknown (willmore|area|fairing)", energy);
  }

  /* conformal constraint: target = the initial class or the -target_mesh class */
  if (conformal) {
    Vec xt = F->x0;
    if (has_target) PetscCall(CSMeshLoadCompatiblePositions(m, "-target_mesh", target, &xt));
    PetscCall(CSConformalConstraintCreate(m, xt, (PetscBool)(m->topo.boundary_loops > 0), F->fixed, &F->cc));
    if (has_target) PetscCall(VecDestroy(&xt));
  }
  /* global constraints */
  if (area_set) {
    PetscReal A, V;
    PetscCall(CSGeometryAreaVolume(m, F->x0, &A, &V));
    PetscCall(CSConstraintCreateArea(m, area_given ? area_target : A, &F->gc[F->ng++]));
  }
  if (vol_set) {
    PetscReal A, V;
    PetscCall(CSGeometryAreaVolume(m, F->x0, &A, &V));
    PetscCall(CSConstraintCreateVolume(m, vol_given ? vol_target : V, &F->gc[F->ng++]));
  }
  if (has_points) PetscCall(CSConstraintCreatePointsFromFile(m, "-constraint_points", points, &F->gc[F->ng++]));
  /* Moebius balancing on request (-constraint_mobius): it matters where the Moebius orbit is free and W
     invariant along it (the Willmore energy on closed surfaces under the conformal constraint, without point
     constraints, which pin the gauge themselves), and the guard below stops runs that need it. Not the
     default: its 3 dense rows cost 3 more solves per step (bordering), 3.3x the time of a 200-step run at 20k
     faces once the factorisation is kept (159 vs 48 s), and soliman2021's method has no such rows. */
  if (mobius) {
    PetscCheck(conformal, comm, PETSC_ERR_ARG_INCOMP, "-constraint_mobius fixes the Moebius gauge of the conformal constraint: it needs -flow_conformal (cgd, pgd)");
    PetscCall(CSConstraintCreateMobiusBalance(m, F->x0, &F->gc[F->ng++]));
  }
  for (PetscInt j = 0; j < F->ng; j++) F->k += F->gc[j]->k;
  PetscCheck(F->conformal || F->k == 0 || kind != CS_FLOW_PGD, comm, PETSC_ERR_ARG_INCOMP, "pgd without the conformal constraint is not supported");

  /* work vectors */
  PetscCall(VecDuplicate(F->x, &F->g));
  PetscCall(VecDuplicate(F->x, &F->r));
  PetscCall(VecDuplicate(F->x, &F->df));
  PetscCall(VecDuplicate(F->x, &F->xt));
  PetscCall(VecDuplicate(F->x, &F->tmp));
  if (conformal) {
    if (F->normals) {
      /* multiplier layout: on each rank its owned edges, then 3 rows per local boundary face */
      PetscInt nE, nN, rs;
      Vec      v;
      PetscCall(CSNormalConstraintCreate(m, F->x0, F->fixed, &F->nc));
      PetscCall(DMCreateGlobalVector(m->dmE1, &F->cE));
      PetscCall(VecDuplicate(F->cE, &F->iqE));
      PetscCall(VecDuplicate(F->nc.N0, &F->cN));
      PetscCall(VecDuplicate(F->nc.N0, &F->iqN));
      PetscCall(VecGetLocalSize(F->cE, &nE));
      PetscCall(VecGetLocalSize(F->cN, &nN));
      PetscCall(VecCreateMPI(comm, nE + nN, PETSC_DETERMINE, &v));
      PetscCall(VecGetOwnershipRange(v, &rs, NULL));
      PetscCall(ISCreateStride(comm, nE, rs, 1, &F->isM[0]));
      PetscCall(ISCreateStride(comm, nN, rs + nE, 1, &F->isM[1]));
      F->c = v;
    } else PetscCall(DMCreateGlobalVector(m->dmE1, &F->c));
    PetscCall(VecDuplicate(F->c, &F->mu));
    PetscCall(VecDuplicate(F->c, &F->dmu));
    PetscCall(VecDuplicate(F->c, &F->iq));
    PetscCall(VecDuplicate(F->c, &F->ct));
    PetscCall(VecDuplicate(F->c, &F->mun));
    PetscCall(VecSet(F->mu, 0));
  }
  PetscCall(PetscCalloc6(F->k + 1, &F->cx, F->k + 1, &F->cxt, F->k + 1, &F->nu, F->k + 1, &F->dnu, F->k + 1, &F->gw, F->k + 1, &F->nun));
  PetscCall(PetscCalloc1(F->k + 1, &F->dnu2));
  if (F->k) PetscCall(VecDuplicateVecs(F->x, F->k, &F->rows));
  PetscCall(CSMetricCreate(m, h2, &F->metric));
  {
    /* size independence (see CSMetric): s^2 = area / 4pi; the metric's mass term gets 1/s^4 and the dual
       step t_mu (given for unit-size meshes) 1/s^2, since X^T I_Q^{-1} X is size-free while H ~ length^-2 */
    PetscReal A, V, sc, E0;
    PetscCall(CSGeometryAreaVolume(m, F->x0, &A, &V));
    sc                    = A / (4 * PETSC_PI);
    F->metric.mass_weight = 1.0 / (sc * sc);
    /* the ceiling of t_mu: with its own ramp 1e3 t_max; following t, none but tmu_ratio_max (each rejection
       raises t_mu / t twofold for good, up to 1e3 times its initial value, see the step control) */
    if (F->tmu_max <= 0) F->tmu_max = F->tmu_grow > 0 ? 1e3 * F->tmax : PETSC_MAX_REAL;
    F->tmu /= sc;
    if (F->tmu_max < PETSC_MAX_REAL) F->tmu_max /= sc;
    F->tmu_ratio_max = 1e3 * F->tmu / F->t;
    /* merit weight relative to the size of the energy (a Willmore energy ~ 4pi and a fairing energy
       eps W differ by orders of magnitude) */
    PetscCall(CSEnergyValue(F->energy, F->x0, &E0));
    F->rho *= PetscMax(PetscAbsReal(E0), PETSC_SMALL);
  }
  PetscCall(CSSaddleCreate(m, conformal, h2, F->k, &F->saddle));
  F->saddle.fixed = F->fixedIS;
  PetscFunctionReturn(0);
}

static PetscErrorCode FlowDestroy(Flow *F)
{
  PetscFunctionBeginUser;
  PetscCall(CSSaddleDestroy(&F->saddle));
  PetscCall(CSMetricDestroy(&F->metric));
  if (F->conformal) PetscCall(CSConformalConstraintDestroy(&F->cc));
  for (PetscInt j = 0; j < F->ng; j++) PetscCall(CSGlobalConstraintDestroy(&F->gc[j]));
  if (F->k) PetscCall(VecDestroyVecs(F->k, &F->rows));
  PetscCall(PetscFree(F->dnu2));
  PetscCall(PetscFree6(F->cx, F->cxt, F->nu, F->dnu, F->gw, F->nun));
  PetscCall(CSEnergyDestroy(&F->energy));
  PetscCall(VecDestroy(&F->x));
  PetscCall(VecDestroy(&F->x0));
  PetscCall(VecDestroy(&F->area0));
  PetscCall(VecDestroy(&F->areat));
  PetscCall(VecDestroy(&F->g));
  PetscCall(VecDestroy(&F->r));
  PetscCall(VecDestroy(&F->df));
  PetscCall(VecDestroy(&F->xt));
  PetscCall(VecDestroy(&F->tmp));
  PetscCall(VecDestroy(&F->c));
  if (F->normals) {
    PetscCall(CSNormalConstraintDestroy(&F->nc));
    PetscCall(VecDestroy(&F->cE));
    PetscCall(VecDestroy(&F->cN));
    PetscCall(VecDestroy(&F->iqE));
    PetscCall(VecDestroy(&F->iqN));
    PetscCall(MatDestroy(&F->Xn));
    PetscCall(MatDestroy(&F->Xext));
    PetscCall(ISDestroy(&F->isM[0]));
    PetscCall(ISDestroy(&F->isM[1]));
  }
  PetscCall(VecDestroy(&F->mu));
  PetscCall(VecDestroy(&F->dmu));
  PetscCall(VecDestroy(&F->iq));
  PetscCall(VecDestroy(&F->ct));
  PetscCall(VecDestroy(&F->mun));
  PetscCall(ISDestroy(&F->fixedIS));
  PetscCall(PetscFree(F->fixed));
  PetscCall(CSMeshDestroy(&F->mesh));
  PetscFunctionReturn(0);
}

/* ---------- evaluation ---------- */

/* Xext = [X; DN] in the multiplier layout (rows of X, then rows of DN, per rank), copied row by row
   (MatConvert of a MATNEST with MAT_REUSE_MATRIX fails in parallel in PETSc 3.18: "Reuse matrix has
   changed nonzero structure"). The pattern is fixed, so later calls only refill the values. */
static PetscErrorCode StackRows(Flow *F)
{
  Mat      B[2] = {F->cc.X, F->nc.DN};
  PetscInt rs, off = 0;
  PetscFunctionBeginUser;
  PetscCall(ISStrideGetInfo(F->isM[0], &rs, NULL));
  if (!F->Xext) {
    PetscInt n0, n1, nc, Nc, *dnz, *onz, cs, ce;
    PetscCall(MatGetLocalSize(B[0], &n0, &nc));
    PetscCall(MatGetLocalSize(B[1], &n1, NULL));
    PetscCall(MatGetSize(B[0], NULL, &Nc));
    PetscCall(MatGetOwnershipRangeColumn(B[0], &cs, &ce));
    PetscCall(PetscCalloc2(n0 + n1, &dnz, n0 + n1, &onz));
    for (int b = 0, r = 0; b < 2; b++) {
      PetscInt rstart, rend;
      PetscCall(MatGetOwnershipRange(B[b], &rstart, &rend));
      for (PetscInt i = rstart; i < rend; i++, r++) {
        PetscInt        ncols;
        const PetscInt *cols;
        PetscCall(MatGetRow(B[b], i, &ncols, &cols, NULL));
        for (PetscInt k = 0; k < ncols; k++) {
          if (cols[k] >= cs && cols[k] < ce) dnz[r]++;
          else onz[r]++;
        }
        PetscCall(MatRestoreRow(B[b], i, &ncols, &cols, NULL));
      }
    }
    PetscCall(MatCreateAIJ(F->comm, n0 + n1, nc, PETSC_DETERMINE, Nc, 0, dnz, 0, onz, &F->Xext));
    PetscCall(PetscFree2(dnz, onz));
  } else PetscCall(MatZeroEntries(F->Xext));
  for (int b = 0; b < 2; b++) {
    PetscInt rstart, rend;
    PetscCall(MatGetOwnershipRange(B[b], &rstart, &rend));
    for (PetscInt i = rstart; i < rend; i++, off++) {
      PetscInt           ncols, row = rs + off;
      const PetscInt    *cols;
      const PetscScalar *vals;
      PetscCall(MatGetRow(B[b], i, &ncols, &cols, &vals));
      PetscCall(MatSetValues(F->Xext, 1, &row, ncols, cols, vals, INSERT_VALUES));
      PetscCall(MatRestoreRow(B[b], i, &ncols, &cols, &vals));
    }
  }
  PetscCall(MatAssemblyBegin(F->Xext, MAT_FINAL_ASSEMBLY));
  PetscCall(MatAssemblyEnd(F->Xext, MAT_FINAL_ASSEMBLY));
  PetscFunctionReturn(0);
}

/* Constraint values at x (c and cx), with Jacobians (X in F->Xc, rows) if wantJ. */
static PetscErrorCode EvalConstraints(Flow *F, Vec x, Vec c, PetscReal cx[], PetscBool wantJ)
{
  PetscInt off = 0;
  PetscFunctionBeginUser;
  if (F->conformal && !F->normals) {
    PetscCall(CSConformalConstraintEvaluate(&F->cc, x, c, wantJ));
    F->Xc = F->cc.X;
  } else if (F->normals) {
    PetscCall(CSConformalConstraintEvaluate(&F->cc, x, F->cE, wantJ));
    PetscCall(CSNormalConstraintEvaluate(&F->nc, x, F->cN, wantJ));
    PetscCall(VecISCopy(c, F->isM[0], SCATTER_FORWARD, F->cE));
    PetscCall(VecISCopy(c, F->isM[1], SCATTER_FORWARD, F->cN));
    if (wantJ) {
      PetscCall(StackRows(F));
      F->Xc = F->Xext;
    }
  }
  for (PetscInt j = 0; j < F->ng; j++) {
    PetscCall(CSGlobalConstraintEvaluate(F->gc[j], x, cx + off, wantJ ? F->rows + off : NULL));
    off += F->gc[j]->k;
  }
  if (wantJ)
    for (PetscInt j = 0; j < F->k; j++) PetscCall(ZeroFixed(F, F->rows[j]));
  PetscFunctionReturn(0);
}

static PetscErrorCode Violation(Flow *F, Vec c, const PetscReal cx[], PetscReal *conf, PetscReal *glob)
{
  PetscReal v = 0;
  PetscFunctionBeginUser;
  *conf = 0;
  if (F->conformal) PetscCall(VecNorm(c, NORM_INFINITY, conf));
  for (PetscInt j = 0; j < F->k; j++) v = PetscMax(v, PetscAbsReal(cx[j]));
  *glob = v;
  PetscFunctionReturn(0);
}

/* The Lagrangian of the CGD/GD step control with multipliers F->mun, nun (plus the optional quadratic
   penalty -flow_merit_rho, default 0; see the top of the file). */
static PetscErrorCode Merit(Flow *F, PetscReal E, Vec c, const PetscReal cx[], const PetscReal nun[], PetscReal *phi)
{
  PetscReal s = E;
  PetscFunctionBeginUser;
  if (F->conformal) {
    PetscScalar d;
    PetscReal   n2;
    PetscCall(VecDot(F->mun, c, &d));
    PetscCall(VecNorm(c, NORM_2, &n2));
    s += PetscRealPart(d) + 0.5 * F->rho * n2 * n2;
  }
  for (PetscInt j = 0; j < F->k; j++) s += nun[j] * cx[j] + 0.5 * F->rho * cx[j] * cx[j] / F->gw[j];
  *phi = s;
  PetscFunctionReturn(0);
}

/* r = g + X^T mu + sum_j nu_j rows_j (the Euler-Lagrange residual), fixed entries zero. */
static PetscErrorCode Residual(Flow *F, PetscReal *el)
{
  PetscFunctionBeginUser;
  PetscCall(VecCopy(F->g, F->r));
  if (F->conformal) PetscCall(MatMultTransposeAdd(F->Xc, F->mu, F->r, F->r));
  for (PetscInt j = 0; j < F->k; j++) PetscCall(VecAXPY(F->r, F->nu[j], F->rows[j]));
  PetscCall(ZeroFixed(F, F->r));
  PetscCall(VecNorm(F->r, NORM_2, el));
  PetscFunctionReturn(0);
}

/* Metric weights of the global multipliers: g_j = |row_j|^2, so that the dual step acts alike on
   constraints of any unit (the paper leaves this metric open). */
static PetscErrorCode GlobalWeights(Flow *F)
{
  PetscFunctionBeginUser;
  for (PetscInt j = 0; j < F->k; j++) {
    PetscReal n;
    PetscCall(VecNorm(F->rows[j], NORM_2, &n));
    F->gw[j] = PetscMax(n * n, PETSC_SMALL);
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode SetOperators(Flow *F, PetscReal t, PetscReal tmu)
{
  PetscFunctionBeginUser;
  PetscCall(CSSaddleSetOperators(&F->saddle, F->metric.H, t, F->iq, tmu, F->conformal ? F->Xc : NULL, F->rows, F->gw));
  PetscFunctionReturn(0);
}

/* The metric of the multipliers at x: I_Q (Eq. 25) on the edge rows, 1/(2A) on normal rows. */
static PetscErrorCode QuadDiffMetric(Flow *F, Vec x, PetscInt *ng)
{
  PetscFunctionBeginUser;
  if (!F->conformal) PetscFunctionReturn(0);
  if (F->normals) {
    PetscCall(CSOperatorQuadDiffMetric(F->mesh, x, F->wmin, F->iqE, ng));
    PetscCall(CSNormalConstraintMetric(&F->nc, x, F->iqN));
    PetscCall(VecISCopy(F->iq, F->isM[0], SCATTER_FORWARD, F->iqE));
    PetscCall(VecISCopy(F->iq, F->isM[1], SCATTER_FORWARD, F->iqN));
  } else PetscCall(CSOperatorQuadDiffMetric(F->mesh, x, F->wmin, F->iq, ng));
  PetscFunctionReturn(0);
}

/* CSSaddleSolve, with a linear solve that did not converge reported in *ok (and printed) instead of raised:
   the step control then treats it as a rejected step (t halved, like the semi-implicit BS flow), and a run
   that keeps failing stops cleanly with its last accepted state. Other errors are raised. */
static PetscErrorCode TrySolve(Flow *F, Vec rE, Vec rV, const PetscReal rX[], Vec zE, Vec zV, PetscReal zX[], PetscInt *its, PetscBool *ok)
{
  PetscErrorCode ierr;
  char          *msg = NULL;
  PetscFunctionBeginUser;
  *its = 0;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  ierr = CSSaddleSolve(&F->saddle, rE, rV, rX, zE, zV, zX, its);
  PetscCall(PetscPopErrorHandler());
  *ok = (PetscBool)!ierr;
  if (!ierr) PetscFunctionReturn(0);
  PetscCall(PetscErrorMessage(ierr, NULL, &msg));
  PetscCheck(ierr == PETSC_ERR_NOT_CONVERGED, F->comm, ierr, "%s", msg ? msg : "CSSaddleSolve failed");
  PetscCall(PetscPrintf(F->comm, "     linear solve failed: %s\n", msg ? msg : "not converged"));
  PetscFunctionReturn(0);
}

/* One Gauss-Newton correction toward the constraints with the operator set last: the saddle system with
   right-hand side [-c; 0; -xi] for the c, xi held in F->ct, F->cxt (both overwritten); the position part in zV. */
static PetscErrorCode SolveCorrection(Flow *F, Vec zE, Vec zV, PetscInt *its, PetscBool *ok)
{
  PetscFunctionBeginUser;
  if (F->conformal) PetscCall(VecScale(F->ct, -1.0));
  for (PetscInt j = 0; j < F->k; j++) F->cxt[j] = -F->cxt[j];
  PetscCall(VecSet(F->tmp, 0));
  PetscCall(TrySolve(F, F->ct, F->tmp, F->cxt, zE, zV, F->dnu2, its, ok));
  PetscFunctionReturn(0);
}

/* PGD projection onto the constraint set (soliman2021 Sec. 4.1: the explicit step leaves the nonlinear
   constraint manifold): Gauss-Newton steps, each the minimal-H^2-norm correction dx with X dx = -c,
   solved as the saddle system with t = 1 and a huge t_mu (the -I_Q/t_mu block only regularises the
   rank deficiency of X, PETSC-NOTES). */
static PetscErrorCode Project(Flow *F, Vec x, PetscBool *ok, PetscInt *kspits)
{
  PetscReal conf, glob;
  Vec       pmu = NULL, pdf;
  PetscBool done = PETSC_FALSE;
  PetscFunctionBeginUser;
  *ok = PETSC_FALSE;
  /* the Newton corrections get their own vectors: F->dmu, F->df, F->dnu hold the step's solution, whose
     multipliers become PGD's mu and nu (overwriting them with the projection's left PGD with area/volume
     constraints at el_residual ~0.7 at the constrained minimum) */
  if (F->dmu) PetscCall(VecDuplicate(F->dmu, &pmu));
  PetscCall(VecDuplicate(F->df, &pdf));
  for (PetscInt it = 0; it < F->proj_max_it; it++) {
    PetscInt its;
    PetscCall(EvalConstraints(F, x, F->ct, F->cxt, PETSC_TRUE));
    PetscCall(Violation(F, F->ct, F->cxt, &conf, &glob));
    if (!(conf == conf) || !(glob == glob)) done = PETSC_TRUE;
    else if (PetscMax(conf, glob) < 0.1 * F->ctol) *ok = done = PETSC_TRUE;
    if (done) break;
    if (F->k) PetscCall(GlobalWeights(F));
    PetscCall(CSMetricUpdate(&F->metric, x));
    PetscCall(QuadDiffMetric(F, x, NULL));
    PetscCall(SetOperators(F, 1.0, F->proj_tmu));
    PetscCall(SolveCorrection(F, pmu, pdf, &its, ok));
    *kspits += its;
    if (!*ok) done = PETSC_TRUE;
    else PetscCall(VecAXPY(x, 1.0, pdf));
    *ok = PETSC_FALSE;
  }
  if (!done) { /* all Newton steps taken: feasible enough? */
    PetscCall(EvalConstraints(F, x, F->ct, F->cxt, PETSC_FALSE));
    PetscCall(Violation(F, F->ct, F->cxt, &conf, &glob));
    *ok = (PetscBool)(PetscMax(conf, glob) < F->ctol);
  }
  PetscCall(VecDestroy(&pmu));
  PetscCall(VecDestroy(&pdf));
  PetscFunctionReturn(0);
}

/* Second-order correction of a CGD/GD trial point (Nocedal & Wright, Numerical Optimization, Sec. 18.3):
   up to -flow_soc_max_it solves of the step's own system with right-hand side [-c(xt); 0; -xi(xt)] (the
   factorisation of the step is reused), each moving xt by the H-smallest correction of the linearised
   constraints at x. It removes the O(|df|^2) violation that the linearisation leaves, so the violation of an
   accepted step does not accumulate; at a fixed point c = 0 and the correction is zero. */
static PetscErrorCode SecondOrderCorrection(Flow *F, Vec xt, PetscInt *kspits, PetscBool *ok)
{
  Vec       dmu2 = NULL, df2;
  PetscReal conf, glob;
  PetscFunctionBeginUser;
  *ok = PETSC_TRUE;
  if (F->soc_max_it <= 0 || (!F->conformal && !F->k)) PetscFunctionReturn(0);
  if (F->dmu) PetscCall(VecDuplicate(F->dmu, &dmu2));
  PetscCall(VecDuplicate(F->df, &df2));
  for (PetscInt i = 0; i < F->soc_max_it; i++) {
    PetscInt its;
    PetscCall(EvalConstraints(F, xt, F->ct, F->cxt, PETSC_FALSE));
    PetscCall(Violation(F, F->ct, F->cxt, &conf, &glob));
    if (!(PetscMax(conf, glob) >= 0.1 * F->ctol)) break; /* feasible enough, or not a number (the filter rejects it) */
    PetscCall(SolveCorrection(F, dmu2, df2, &its, ok));
    *kspits += its;
    if (!*ok) break;
    PetscCall(VecAXPY(xt, 1.0, df2));
  }
  PetscCall(VecDestroy(&dmu2));
  PetscCall(VecDestroy(&df2));
  PetscFunctionReturn(0);
}

/* Restoration of an accepted CGD/GD state by PGD's Gauss-Newton projection (Project) onto the constraint set,
   with its own operator (t = 1, t_mu = -pgd_t_mu), whose restoring strength does not shrink with t as the
   step's does (the step's Schur complement H/t + t_mu X^T I_Q^{-1} X restores by a Levenberg-Marquardt step of
   parameter 1/(t t_mu)). Done when the state is stalled near the violation ceiling (-flow_restore_stalled, on:
   t < 1e-3 t_max and a violation above -flow_vmax / 10; a torus of revolution R = 2, bump 0.2, sat at |c| = 1e-2
   with t ~ 1e-14 for 300 iterations without it, and goes on with it), or, with -flow_restore_above V (off),
   whenever the violation exceeds V. The multipliers are kept; the next step factors its own operator. If the
   projection fails the state is left as it was and no restoration is tried again in the run (cow_cgal: it
   fails from |c| = 9e-3). -flow_restore_above 1e-3 helped nowhere (measured, docs/real_meshes.md): on the area +
   volume case of tests/cases/willmore_constraints.sh one restoration at iteration 0 sent the run past the
   critical point it converges to without. */
static PetscErrorCode Restore(Flow *F, PetscInt it, PetscInt *kspits)
{
  PetscReal conf, glob, v;
  PetscBool ok, stalled;
  Vec       keep;
  PetscFunctionBeginUser;
  stalled = (PetscBool)(F->restore_stalled && F->t < 1e-3 * F->tmax);
  if (F->restore_failed || (!stalled && !(F->vrestore > 0))) PetscFunctionReturn(0);
  PetscCall(EvalConstraints(F, F->x, F->ct, F->cxt, PETSC_FALSE));
  PetscCall(Violation(F, F->ct, F->cxt, &conf, &glob));
  v = PetscMax(conf, glob);
  if (!((F->vrestore > 0 && v > F->vrestore) || (stalled && v > 0.1 * F->vmax))) PetscFunctionReturn(0);
  PetscCall(VecDuplicate(F->x, &keep));
  PetscCall(VecCopy(F->x, keep));
  PetscCall(Project(F, F->x, &ok, kspits));
  F->saddle.wait = PetscMax(F->saddle.wait, 1); /* else the projection's factorisation preconditions the steps
                                                   in ~8 iterations, under the refactorisation threshold, for good */
  if (!ok) {
    PetscCall(VecCopy(keep, F->x));
    F->restore_failed = PETSC_TRUE; /* a failed projection costs -pgd_projection_max_it solves: not again in this run */
  }
  PetscCall(VecDestroy(&keep));
  PetscCall(PetscPrintf(F->comm, "     restoration after iteration %" PetscInt_FMT ": violation %.3e (t = %g): %s\n", it, (double)v, (double)F->t, ok ? "projected back onto the constraints" : "the projection failed; state kept, no more restorations in this run"));
  PetscFunctionReturn(0);
}

/* Checkpoint scalars: the loop state after `it` accepted steps besides the positions and mu (the edge
   field): [flow kind, t, t_mu, rejections, KSP its in total, KSP its of the last step, edges with guarded I_Q
   weight, seconds, nu_1..nu_k]. The rest (g, c, X, metric, residual) is recomputed from x at the top of the
   loop, so a resumed run continues exactly like the uninterrupted one. */
#define FLOW_CK_NREAL 8
typedef struct {
  PetscInt       rejections, kspits_total, kspits, nguard;
  PetscLogDouble t0;
} FlowCounters;

static PetscErrorCode FlowCheckpoint(Flow *F, CSOutput *out, PetscInt it, PetscBool force, const FlowCounters *n, PetscReal ck[])
{
  PetscLogDouble now;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&now));
  ck[0] = (PetscReal)F->kind;
  ck[1] = F->t;
  ck[2] = F->tmu;
  ck[3] = (PetscReal)n->rejections;
  ck[4] = (PetscReal)n->kspits_total;
  ck[5] = (PetscReal)n->kspits;
  ck[6] = (PetscReal)n->nguard;
  ck[7] = (PetscReal)(now - n->t0);
  for (PetscInt j = 0; j < F->k; j++) ck[FLOW_CK_NREAL + j] = F->nu[j];
  PetscCall(CSOutputCheckpoint(out, F->mesh, F->x0, it, force, FLOW_CK_NREAL + F->k, ck, F->x, F->conformal ? F->mu : NULL));
  PetscFunctionReturn(0);
}

/* What the resolution guard looks at, measured at every iteration (and written to the history): the total
   area relative to the input, the spread max_i(A_i/A0_i) / min_i(A_i/A0_i) of the barycentric vertex areas
   relative to the input (infinite if an area is not positive), and the largest quasi-conformal error of a
   face against the input (crane2011 Sec. 6.1; for an exactly discretely conformal state it measures how much
   the conformal factor changes across one triangle, i.e. whether the mesh still resolves it). */
typedef struct {
  PetscReal area_ratio, spread, qmax;
} FlowQuality;

static PetscErrorCode MeasureQuality(Flow *F, FlowQuality *q)
{
  PetscReal   amax, amin;
  PetscScalar atot;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryVertexAreas(F->mesh, F->x, F->areat));
  PetscCall(VecSum(F->areat, &atot));
  q->area_ratio = PetscRealPart(atot) / F->area0_total;
  PetscCall(VecPointwiseDivide(F->areat, F->areat, F->area0));
  PetscCall(VecMax(F->areat, NULL, &amax));
  PetscCall(VecMin(F->areat, NULL, &amin));
  q->spread = amin > 0 ? amax / amin : PETSC_INFINITY;
  PetscCall(CSGeometryQuasiConformal(F->mesh, F->x0, F->x, NULL, NULL, &q->qmax));
  PetscFunctionReturn(0);
}

/* The resolution guard (-flow_max_area_ratio, see the top of this file): sets *why to "diverged" when the total
   area has changed by more than the ratio, or to "mesh_degenerate" when the vertex areas relative to the input
   spread by more than it; leaves it alone otherwise. The message says what was measured and what it can mean:
   the guard cannot tell a Moebius slide (closed surfaces, the top of this file) from the discrete problem's own
   degeneration on coarse or far-from-minimiser inputs, a few vertices driven out into large flat triangles
   or a part of the surface squeezed into a few triangles (docs/real_meshes.md), and both happen with the
   constraints met; viol says whether they are. */
static PetscErrorCode CheckResolution(Flow *F, PetscInt it, const FlowQuality *q, PetscReal viol, const char **why)
{
  PetscFunctionBeginUser;
  if (!(q->area_ratio < F->max_area_ratio && q->area_ratio > 1 / F->max_area_ratio)) { /* e.g. a far-off volume target */
    PetscCall(PetscPrintf(F->comm, "flow: the flow diverges at iteration %" PetscInt_FMT ": the total area is %g times the input's, beyond -flow_max_area_ratio (%g). Stopping with this state; it is not a solution (try a smaller -flow_t_max, or a constraint target nearer the input)\n", it, (double)q->area_ratio, (double)F->max_area_ratio));
    *why = "diverged";
    PetscFunctionReturn(0);
  }
  if (!(q->spread <= F->max_area_ratio)) {
    PetscCall(PetscPrintf(F->comm, "flow: mesh resolution collapse at iteration %" PetscInt_FMT ": the vertex areas relative to the input spread by max(A/A0)/min(A/A0) = %g, beyond -flow_max_area_ratio (%g), with the constraints %s (violation %.2e) and the largest quasi-conformal error of a face %.3g. The discrete Willmore energy is being lowered by moving area between vertices, not only by changing the shape: either a slide along a Moebius orbit, to which the constraints are blind (-constraint_mobius fixes the Moebius gauge), or part of the surface blown up into a few large flat triangles or squeezed into a few small ones, where the mesh no longer resolves it (see docs/real_meshes.md). Stopping with this state; its energy is not trustworthy (-flow_max_area_ratio 0 disables this check)\n", it, (double)q->spread, (double)F->max_area_ratio, viol < 1e3 * F->ctol ? "met" : "NOT met", (double)viol, (double)q->qmax));
    *why = "mesh_degenerate";
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowRun(MPI_Comm comm, CSOutput *out, CSFlowKind kind)
{
  Flow           F;
  CSHistory      hist = NULL;
  PetscLogDouble tnow;
  PetscReal      E = 0, E0, el = 0, conf = 0, glob = 0, A, V, *ck;
  FlowQuality    quality;
  PetscInt       it, it0 = 0;
  FlowCounters   n = {0, 0, 0, 0, 0};
  PetscBool      converged = PETSC_FALSE, resumed, stop = PETSC_FALSE;
  const char    *names[] = {"cgd", "pgd", "gd"}, *stop_reason = "max_it";
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&n.t0));
  PetscCall(FlowSetUp(comm, &F, kind, out));
  /* -resume: positions, mu and the loop state; x0 (input, conformal target, q_mean) stays the input */
  PetscCheck(!F.normals || (!out->has_checkpoint && !out->has_resume), comm, PETSC_ERR_SUP, "-checkpoint/-resume with -flow_boundary normals: the multipliers of the normal constraint are not stored in checkpoints");
  PetscCall(PetscMalloc1(FLOW_CK_NREAL + F.k, &ck));
  PetscCall(CSOutputResume(out, F.mesh, F.x0, &it0, FLOW_CK_NREAL + F.k, ck, F.x, F.conformal ? F.mu : NULL, &resumed));
  if (resumed) {
    PetscBool same = (PetscBool)(ck[0] == (PetscReal)kind);
    if (!same) PetscCall(PetscFree(ck));
    PetscCheck(same, comm, PETSC_ERR_ARG_INCOMP, "-resume %s: written by another -flow_type (this run is %s)", out->resume, names[kind]);
    F.t            = ck[1];
    F.tmu          = ck[2];
    n.rejections   = (PetscInt)ck[3];
    n.kspits_total = (PetscInt)ck[4];
    n.kspits       = (PetscInt)ck[5];
    n.nguard       = (PetscInt)ck[6];
    n.t0          -= ck[7]; /* the seconds column of the history continues */
    for (PetscInt j = 0; j < F.k; j++) F.nu[j] = ck[FLOW_CK_NREAL + j];
  }
  /* a resumed run writes the row of iteration it0 again (from the same state) */
  PetscCall(CSOutputHistoryCreate(out, comm, "it,energy,area,volume,conformal_violation,constraint_violation,el_residual,t,ksp_its,rejections,seconds,area_spread,q_max", it0, &hist));
  PetscCall(PetscPrintf(comm, "flow %s: mesh %s V=%" PetscInt_FMT " E=%" PetscInt_FMT " F=%" PetscInt_FMT ", energy %s, metric %s, conformal %s, %" PetscInt_FMT " global constraint rows%s, t=%g t_mu=%g\n", names[kind], F.mesh->name, F.mesh->Nv, F.mesh->Ne, F.mesh->Nf, F.energy_name, F.metric.h2 ? "h2" : "l2", F.conformal ? "on" : "off", F.k, F.fixedIS ? ", Dirichlet boundary" : "", (double)F.t, (double)F.tmu));

  if (kind == CS_FLOW_PGD && !resumed) { /* PGD starts on the constraint set (a checkpoint is on it already) */
    PetscBool ok;
    PetscCall(Project(&F, F.x, &ok, &n.kspits_total));
    PetscCheck(ok, comm, PETSC_ERR_NOT_CONVERGED, "pgd: the initial projection onto the constraint set did not converge");
  }
  for (it = it0;; it++) {
    PetscCall(CSEnergyGradient(F.energy, F.x, &E, F.g));
    PetscCall(ZeroFixed(&F, F.g));
    PetscCall(EvalConstraints(&F, F.x, F.c, F.cx, PETSC_TRUE));
    PetscCall(Residual(&F, &el));
    PetscCall(Violation(&F, F.c, F.cx, &conf, &glob));
    PetscCall(CSGeometryAreaVolume(F.mesh, F.x, &A, &V));
    PetscCall(MeasureQuality(&F, &quality));
    PetscCall(PetscTime(&tnow));
    PetscCall(PetscPrintf(comm, "%4" PetscInt_FMT " E %.12g area %.8g vol %.8g |c|inf %.3e |xi| %.3e el %.3e t %.3g ksp %" PetscInt_FMT "\n", it, (double)E, (double)A, (double)V, (double)conf, (double)glob, (double)el, (double)F.t, n.kspits));
    if (hist) {
      PetscReal row[13] = {(PetscReal)it, E, A, V, conf, glob, el, F.t, (PetscReal)n.kspits, (PetscReal)n.rejections, tnow - n.t0, quality.spread, quality.qmax};
      PetscCall(CSHistoryAppend(hist, 13, row));
    }
    if (!(E == E) || !(el == el)) SETERRQ(comm, PETSC_ERR_FP, "flow: the energy or the residual is not a number at iteration %" PetscInt_FMT " (degenerate triangles?); try a smaller -flow_t", it);
    if (F.max_area_ratio > 0) {
      const char *why = NULL;
      PetscCall(CheckResolution(&F, it, &quality, PetscMax(conf, glob), &why));
      if (why) {
        stop_reason = why;
        break;
      }
    }
    if (el < F.rtol && PetscMax(conf, glob) < F.ctol) {
      converged   = PETSC_TRUE;
      stop_reason = "converged";
      break;
    }
    if (it >= F.max_it) break;

    /* operators at x */
    PetscCall(CSMetricUpdate(&F.metric, F.x));
    if (F.conformal) {
      PetscInt ng;
      PetscCall(QuadDiffMetric(&F, F.x, &ng));
      n.nguard = PetscMax(n.nguard, ng);
    }
    if (F.k) PetscCall(GlobalWeights(&F));
    n.kspits = 0;
    for (PetscInt rej = 0;; rej++) {
      PetscReal Et;
      PetscBool accept = PETSC_TRUE;
      PetscInt  its;
      Vec       dmu2, df2;

      if (rej > F.max_rej) {
        /* stop cleanly: F.x is the last accepted state, and E, el, c above belong to it */
        PetscCall(PetscPrintf(comm, "flow: %" PetscInt_FMT " consecutive steps rejected at iteration %" PetscInt_FMT " (t = %g, -flow_max_rejections): stopping with the last accepted state\n", rej, it, (double)F.t));
        stop        = PETSC_TRUE;
        stop_reason = "rejections";
        break;
      }
      PetscCall(SetOperators(&F, F.t, kind == CS_FLOW_PGD ? F.proj_tmu : F.tmu));
      /* right-hand side (Algorithm 1 line 11): [-c; -g - X^T mu - B^T nu; -xi] for CGD/GD, [0; -g; 0] for PGD */
      if (kind == CS_FLOW_PGD) {
        PetscCall(VecSet(F.ct, 0));
        PetscCall(VecCopy(F.g, F.tmp));
        PetscCall(VecScale(F.tmp, -1.0));
        for (PetscInt j = 0; j < F.k; j++) F.cxt[j] = 0;
      } else {
        if (F.conformal) {
          PetscCall(VecCopy(F.c, F.ct));
          PetscCall(VecScale(F.ct, -1.0));
        }
        PetscCall(VecCopy(F.r, F.tmp));
        PetscCall(VecScale(F.tmp, -1.0));
        for (PetscInt j = 0; j < F.k; j++) F.cxt[j] = -F.cx[j];
      }
      PetscCall(TrySolve(&F, F.ct, F.tmp, F.cxt, F.dmu, F.df, F.dnu, &its, &accept));
      n.kspits += its;
      if (!accept) PetscCall(PetscPrintf(comm, "     step rejected: linear solve failed with t = %g; halving t\n", (double)F.t));
      if (accept && kind == CS_FLOW_PGD) {
        /* The PGD matrix [[H/t, X^T], [X, 0]] is singular (dependent rows of X, PETSC-NOTES); we solve with
           -I_Q/pgd_t_mu in the (2,2) block and remove the regularisation error by iterative refinement
           against the unregularised system: only its second row differs, residual -X df (and -B^T df). */
        for (PetscInt ref = 0; ref < 3 && accept; ref++) {
          PetscCall(MatMult(F.Xc, F.df, F.ct));
          PetscCall(VecScale(F.ct, -1.0));
          for (PetscInt j = 0; j < F.k; j++) {
            PetscScalar v;
            PetscCall(VecDot(F.rows[j], F.df, &v));
            F.cxt[j] = -PetscRealPart(v);
          }
          PetscCall(VecSet(F.tmp, 0));
          PetscCall(VecDuplicate(F.dmu, &dmu2));
          PetscCall(VecDuplicate(F.df, &df2));
          PetscCall(TrySolve(&F, F.ct, F.tmp, F.cxt, dmu2, df2, F.dnu2, &its, &accept));
          n.kspits += its;
          if (!accept) PetscCall(PetscPrintf(comm, "     step rejected: linear solve failed with t = %g; halving t\n", (double)F.t));
          else {
            PetscCall(VecAXPY(F.dmu, 1.0, dmu2));
            PetscCall(VecAXPY(F.df, 1.0, df2));
            for (PetscInt j = 0; j < F.k; j++) F.dnu[j] += F.dnu2[j];
          }
          PetscCall(VecDestroy(&dmu2));
          PetscCall(VecDestroy(&df2));
        }
      }
      /* trial point */
      if (accept) PetscCall(VecWAXPY(F.xt, 1.0, F.df, F.x));
      if (accept && kind == CS_FLOW_PGD) {
        PetscBool ok;
        PetscCall(Project(&F, F.xt, &ok, &n.kspits));
        if (!ok) accept = PETSC_FALSE;
        if (!ok) PetscCall(PetscPrintf(comm, "     step rejected: the projection onto the constraint set failed with t = %g; halving t\n", (double)F.t));
      }
      if (accept && kind != CS_FLOW_PGD) {
        its = 0;
        PetscCall(SecondOrderCorrection(&F, F.xt, &its, &accept));
        n.kspits += its;
        if (!accept) PetscCall(PetscPrintf(comm, "     step rejected: the linear solve of the second-order correction failed with t = %g; halving t\n", (double)F.t));
      }
      if (accept && !F.step_control) {
        /* even without step control a non-finite state is never accepted: the last good state must survive */
        PetscCall(CSEnergyValue(F.energy, F.xt, &Et));
        if (PetscIsInfOrNanReal(Et)) accept = PETSC_FALSE;
        if (!accept) PetscCall(PetscPrintf(comm, "     step rejected: the energy is not finite with t = %g; halving t\n", (double)F.t));
      }
      if (accept && F.step_control) {
        if (kind == CS_FLOW_PGD) {
          PetscCall(CSEnergyValue(F.energy, F.xt, &Et));
          /* a relative slack of 1e-12 lets converged iterates (changes at round-off level) pass */
          if (!(Et == Et) || Et > E + 1e-12 * PetscAbsReal(E)) accept = PETSC_FALSE;
          if (!accept) PetscCall(PetscPrintf(comm, "     step rejected: energy %.15g -> %.15g with t = %g; halving t\n", (double)E, (double)Et, (double)F.t));
        } else {
          PetscReal v0, vt, ca, cb, L0, Lt;
          if (F.conformal) PetscCall(VecWAXPY(F.mun, 1.0, F.dmu, F.mu));
          for (PetscInt j = 0; j < F.k; j++) F.nun[j] = F.nu[j] + F.dnu[j];
          PetscCall(Merit(&F, E, F.c, F.cx, F.nun, &L0));
          PetscCall(Violation(&F, F.c, F.cx, &ca, &cb));
          v0 = PetscMax(ca, cb);
          PetscCall(CSEnergyValue(F.energy, F.xt, &Et));
          PetscCall(EvalConstraints(&F, F.xt, F.ct, F.cxt, PETSC_FALSE));
          PetscCall(Merit(&F, Et, F.ct, F.cxt, F.nun, &Lt));
          PetscCall(Violation(&F, F.ct, F.cxt, &ca, &cb));
          vt = PetscMax(ca, cb);
          /* the relative slack 1e-12 (and ctol on v) lets converged iterates, changing at round-off level, pass */
          if (!(Lt == Lt) || !(vt == vt) || (Lt > L0 + 1e-12 * PetscAbsReal(L0) && (vt > v0 + F.ctol || v0 <= F.ctol)) || vt > PetscMax(v0, F.vmax)) accept = PETSC_FALSE;
          if (!accept) PetscCall(PetscPrintf(comm, "     step rejected: Lagrangian %.15g -> %.15g, violation %.3e -> %.3e with t = %g; halving t\n", (double)L0, (double)Lt, (double)v0, (double)vt, (double)F.t));
        }
      }
      if (accept) break;
      n.rejections++;
      F.t *= 0.5;
      /* t_mu is left alone: it sets how strongly the step (and its second-order correction) restores the
         constraints, t t_mu X^T I_Q^{-1} X against H in the Schur complement, so halving it with t, as before,
         left a violated state unable to recover (knot1_cgal: |c| rose to 0.9, every t rejected). Since t_mu
         grows with t again after accepted steps, each rejection doubles t_mu / t for good: a step that had to
         be cut back weights the constraints more from then on (elephant_cgal: |c| 1e-2 and t -> 4e-16 with
         t_mu / t capped at its initial value, 2.6e-10 without the cap; docs/real_meshes.md). The ratio stays
         below tmu_ratio_max: without any bound, a run whose t stayed near 1e-35 doubled t_mu at every accepted
         step and its multipliers blew up (el_residual 7.7e23: a torus of revolution R = 2, bump 0.2) */
      if (kind != CS_FLOW_PGD && F.tmu_grow == 0) F.tmu = PetscMin(F.tmu, F.tmu_ratio_max * F.t);
    }
    if (stop) break;
    /* accept */
    PetscCall(VecCopy(F.xt, F.x));
    if (kind != CS_FLOW_PGD && (F.conformal || F.k)) PetscCall(Restore(&F, it, &n.kspits));
    if (kind == CS_FLOW_PGD) {
      /* PGD's multipliers are those of the last linearised problem */
      if (F.conformal) PetscCall(VecCopy(F.dmu, F.mu));
      for (PetscInt j = 0; j < F.k; j++) F.nu[j] = F.dnu[j];
    } else {
      if (F.conformal) PetscCall(VecAXPY(F.mu, 1.0, F.dmu));
      for (PetscInt j = 0; j < F.k; j++) F.nu[j] += F.dnu[j];
    }
    n.kspits_total += n.kspits;
    if (F.tmu_grow > 0 && kind != CS_FLOW_PGD) {
      /* a dual step ramped on its own (-flow_t_mu_grow): a large t_mu during the transient of a class change
         seeds an unstable mode (options/flow_class_change.opts) */
      if (F.t * F.grow <= F.tmax) F.t *= F.grow;
      F.tmu = PetscMin(F.tmu * F.tmu_grow, F.tmu_max);
    } else if (F.t * F.grow <= F.tmax) {
      F.t *= F.grow;
      if (kind != CS_FLOW_PGD) F.tmu = PetscMin(PetscMin(F.tmu * F.grow, F.tmu_max), F.tmu_ratio_max * F.t);
    }
    PetscCall(FlowCheckpoint(&F, out, it + 1, PETSC_FALSE, &n, ck)); /* it + 1 accepted steps */
  }
  PetscCall(FlowCheckpoint(&F, out, it, PETSC_TRUE, &n, ck)); /* the last accepted state, converged or not */
  PetscCall(PetscFree(ck));
  PetscCall(PetscTime(&tnow));
  PetscCall(PetscPrintf(comm, "flow %s: %s after %" PetscInt_FMT " iterations (%" PetscInt_FMT " rejected steps, %" PetscInt_FMT " KSP iterations, %" PetscInt_FMT " edges with guarded I_Q weight), %.3f s\n", names[kind], converged ? "converged" : "NOT converged", it, n.rejections, n.kspits_total, n.nguard, tnow - n.t0));
  PetscCall(CSJSONAddString(out->json, "flow_type", names[kind]));
  PetscCall(CSJSONAddString(out->json, "energy_name", F.energy_name));
  PetscCall(CSJSONAddInt(out->json, "iterations", it));
  PetscCall(CSJSONAddBool(out->json, "converged", converged));
  PetscCall(CSJSONAddString(out->json, "stop_reason", stop_reason));
  PetscCall(CSEnergyValue(F.energy, F.x0, &E0));
  PetscCall(CSJSONAddReal(out->json, "energy_initial", E0)); /* of the input (after -flow_init_*) */
  PetscCall(CSJSONAddReal(out->json, "energy", E));
  PetscCall(CSJSONAddReal(out->json, "area_spread", quality.spread));
  PetscCall(CSJSONAddReal(out->json, "conformal_violation", conf));
  PetscCall(CSJSONAddReal(out->json, "constraint_violation", glob));
  PetscCall(CSJSONAddReal(out->json, "el_residual", el));
  PetscCall(CSJSONAddInt(out->json, "rejections", n.rejections));
  PetscCall(CSJSONAddInt(out->json, "ksp_iterations", n.kspits_total));
  PetscCall(CSJSONAddInt(out->json, "pc_setups", F.saddle.setups)); /* preconditioner builds (factorisations) */
  PetscCall(CSJSONAddInt(out->json, "linear_solves", F.saddle.solves)); /* steps, second-order corrections, projections, bordering */
  PetscCall(CSJSONAddReal(out->json, "t_final", F.t));
  PetscCall(CSJSONAddReal(out->json, "seconds_per_iteration", it ? (tnow - n.t0) / it : 0));
  if (F.k) PetscCall(CSJSONAddRealArray(out->json, "constraint_values", F.k, F.cx));
  if (out->has_viewer) {
    CSViewer v;
    PetscCall(CSViewerCreate(F.mesh, out->viewer_dir, &v));
    PetscCall(CSViewerWriteStep(v, F.x, (PetscReal)it));
    PetscCall(CSViewerDestroy(&v));
  }
  PetscCall(CSOutputAddMeshFacts(out, F.mesh, F.x, F.x0));
  PetscCall(CSOutputFinish(out, F.mesh, F.x));
  if (hist) PetscCall(CSHistoryDestroy(&hist));
  PetscCall(FlowDestroy(&F));
  PetscFunctionReturn(0);
}
