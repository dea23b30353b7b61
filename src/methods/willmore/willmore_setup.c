/* CSWillmoreFlowSetUp: positions, boundary, energy, constraints, work vectors, scaling and the saddle solver
   on the mesh the flow was given. */
#include "willmore_impl.h"
#include "cs_util.h"

/* Dirichlet vertices: the boundary of a surface with boundary unless -flow_boundary free. */
PetscErrorCode CSWFSetUpBoundary(CSWillmoreFlow F)
{
  CSMesh                 m = F->mesh;
  ISLocalToGlobalMapping l2g;
  PetscInt              *idx, n = 0;
  PetscFunctionBeginUser;
  if (F->boundary_set) PetscCheck(m->topo.boundary_loops > 0, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%sboundary %s: the mesh %s is closed (no boundary); boundary methods need a surface with boundary", F->hdr.prefix, CSFlowBoundaryTypes[F->boundary], m->name);
  if (m->topo.boundary_loops == 0) PetscFunctionReturn(0);
  F->normals = (PetscBool)(F->boundary == CS_FLOW_BOUNDARY_NORMALS); /* fixed positions and boundary-face normals (Fig. 2) */
  if (F->boundary == CS_FLOW_BOUNDARY_FREE) PetscFunctionReturn(0);
  PetscCall(PetscCalloc1(m->nv, &F->fixed));
  PetscCall(PetscMalloc1(3 * m->nv, &idx));
  for (PetscInt v = 0; v < m->nv; v++) {
    F->fixed[v] = m->vertBoundary[v];
    if (m->vertBoundary[v] && m->vertOwned[v])
      for (int d = 0; d < 3; d++) idx[n++] = 3 * v + d;
  }
  PetscCall(DMGetLocalToGlobalMapping(m->dmV3, &l2g));
  PetscCall(ISLocalToGlobalMappingApply(l2g, n, idx, idx));
  PetscCall(ISCreateGeneral(F->hdr.comm, n, idx, PETSC_OWN_POINTER, &F->fixedIS));
  PetscFunctionReturn(0);
}

/* The conformal constraint (target: the input's class, that of -flow_target_mesh, or the input's intrinsic
   lengths when it has them: -gen lattice) and the global ones: those of the options, then those added by name
   (willmore_constraints.c). */
PetscErrorCode CSWFSetUpConstraints(CSWillmoreFlow F)
{
  CSMesh             m = F->mesh;
  PetscReal          A, V;
  char               opt[96];
  CSGlobalConstraint g;
  PetscFunctionBeginUser;
  if (F->conformal) {
    Vec xt = F->x0;
    PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%starget_mesh", F->hdr.prefix));
    if (F->target[0]) PetscCall(CSMeshLoadCompatiblePositions(m, opt, F->target, &xt));
    PetscCall(CSConformalConstraintCreate(m, xt, (PetscBool)(m->topo.boundary_loops > 0), F->fixed, &F->cc));
    if (!F->target[0] && m->lt) PetscCall(CSConformalConstraintSetTargetLengths(&F->cc, m->lt));
    if (!F->target[0] && m->ct) PetscCall(VecCopy(m->ct, F->cc.c0)); /* -mesh_cross_ratios: c0 itself */
    if (F->target[0]) PetscCall(VecDestroy(&xt));
  }
  PetscCall(CSGeometryAreaVolume(m, F->x0, &A, &V));
  /* checked here too, so that the messages name this object's options */
  PetscCheck(!F->area_set || !F->area_given || F->area_target > 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sconstraint_area %g: the target area must be positive", F->hdr.prefix, (double)F->area_target);
  PetscCheck(!F->vol_set || m->topo.boundary_loops == 0, F->hdr.comm, PETSC_ERR_ARG_WRONG, "-%sconstraint_volume: the mesh %s has %" PetscInt_FMT " boundary loop(s); the enclosed volume is only defined for closed surfaces", F->hdr.prefix, m->name, m->topo.boundary_loops);
  PetscCheck(!F->vol_set || (F->vol_given ? F->vol_target : V) > 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sconstraint_volume %g: the target volume must be positive (outward-oriented surface)", F->hdr.prefix, (double)(F->vol_given ? F->vol_target : V));
  if (F->area_set) {
    PetscCall(CSConstraintCreateArea(m, F->area_given ? F->area_target : A, &g));
    PetscCall(CSWFAddConstraint(F, g));
  }
  if (F->vol_set) {
    PetscCall(CSConstraintCreateVolume(m, F->vol_given ? F->vol_target : V, &g));
    PetscCall(CSWFAddConstraint(F, g));
  }
  PetscCall(PetscSNPrintf(opt, sizeof(opt), "-%sconstraint_points", F->hdr.prefix));
  if (F->points[0]) {
    PetscCall(CSConstraintCreatePointsFromFile(m, opt, F->points, &g));
    PetscCall(CSWFPointsContinuationWrap(F, &g)); /* -points_stages: the targets moved in stages */
    PetscCall(CSWFAddConstraint(F, g));
  }
  /* Moebius balancing on request: not the default, its 3 dense rows cost 3 more solves per step
     (docs/willmore_flow.md), and soliman2021's method has no such rows */
  if (F->mobius) {
    PetscCheck(F->conformal, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%sconstraint_mobius fixes the Moebius gauge of the conformal constraint: it needs -%sconformal (cgd, pgd)", F->hdr.prefix, F->hdr.prefix);
    PetscCall(CSConstraintCreateMobiusBalance(m, F->x0, &g));
    PetscCall(CSWFAddConstraint(F, g));
  }
  if (F->rotation) {
    PetscCheck(F->conformal && F->mobius, F->hdr.comm, PETSC_ERR_ARG_INCOMP, "-%sconstraint_rotation fixes the rotations of the domain left free by the conformal constraint and the Moebius balancing: it needs -%sconformal and -%sconstraint_mobius", F->hdr.prefix, F->hdr.prefix, F->hdr.prefix);
    PetscCall(CSConstraintCreateRotationGauge(m, F->x0, &g));
    PetscCall(CSWFAddConstraint(F, g));
  }
  PetscCall(CSWFSetUpAddedConstraints(F));
  for (PetscInt j = 0; j < F->ng; j++) F->k += F->gc[j]->k;
  PetscFunctionReturn(0);
}

/* The multiplier layout with boundary-face normals: on each rank its owned edges, then 3 rows per local
   boundary face. */
static PetscErrorCode SetUpNormalLayout(CSWillmoreFlow F)
{
  PetscInt nE, nN, rs;
  PetscFunctionBeginUser;
  PetscCall(CSNormalConstraintCreate(F->mesh, F->x0, F->fixed, &F->nc));
  PetscCall(DMCreateGlobalVector(F->mesh->dmE1, &F->cE));
  PetscCall(VecDuplicate(F->cE, &F->iqE));
  PetscCall(VecDuplicate(F->nc.N0, &F->cN));
  PetscCall(VecDuplicate(F->nc.N0, &F->iqN));
  PetscCall(VecGetLocalSize(F->cE, &nE));
  PetscCall(VecGetLocalSize(F->cN, &nN));
  PetscCall(VecCreateMPI(F->hdr.comm, nE + nN, PETSC_DETERMINE, &F->c));
  PetscCall(VecGetOwnershipRange(F->c, &rs, NULL));
  PetscCall(ISCreateStride(F->hdr.comm, nE, rs, 1, &F->isM[0]));
  PetscCall(ISCreateStride(F->hdr.comm, nN, rs + nE, 1, &F->isM[1]));
  PetscFunctionReturn(0);
}

/* The primal work vectors (the layout of F->x: positions, or a kind's own variables). */
PetscErrorCode CSWFSetUpPrimalVectors(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->x, &F->g));
  PetscCall(VecDuplicate(F->x, &F->r));
  PetscCall(VecDuplicate(F->x, &F->df));
  PetscCall(VecDuplicate(F->x, &F->xt));
  PetscCall(VecDuplicate(F->x, &F->tmp));
  PetscFunctionReturn(0);
}

/* The multiplier block's vectors in the layout of F->c (created by the caller), mu = 0; and the k global rows'
   scalars (constraint values, multipliers, weights). */
PetscErrorCode CSWFSetUpMultiplierVectors(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  if (F->c) {
    PetscCall(VecDuplicate(F->c, &F->mu));
    PetscCall(VecDuplicate(F->c, &F->dmu));
    PetscCall(VecDuplicate(F->c, &F->iq));
    PetscCall(VecDuplicate(F->c, &F->ct));
    PetscCall(VecDuplicate(F->c, &F->mun));
    PetscCall(VecSet(F->mu, 0));
  }
  PetscCall(PetscCalloc6(F->k + 1, &F->cx, F->k + 1, &F->cxt, F->k + 1, &F->nu, F->k + 1, &F->dnu, F->k + 1, &F->gw, F->k + 1, &F->nun));
  PetscCall(PetscCalloc1(F->k + 1, &F->dnu2));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWFSetUpVectors(CSWillmoreFlow F)
{
  PetscFunctionBeginUser;
  PetscCall(CSWFSetUpPrimalVectors(F));
  if (F->conformal) {
    if (F->normals) PetscCall(SetUpNormalLayout(F));
    else PetscCall(DMCreateGlobalVector(F->mesh->dmE1, &F->c));
  }
  PetscCall(CSWFSetUpMultiplierVectors(F));
  if (F->k) PetscCall(VecDuplicateVecs(F->x, F->k, &F->rows));
  PetscFunctionReturn(0);
}

/* Size independence (see CSMetric): s^2 = area / 4pi; the metric's mass term gets 1/s^4 and the dual step
   t_mu (given for unit-size meshes) 1/s^2, since X^T I_Q^{-1} X is size-free while H ~ length^-2. */
PetscErrorCode CSWFSetUpScaling(CSWillmoreFlow F)
{
  PetscReal A, V, sc, E0;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryAreaVolume(F->mesh, F->x0, &A, &V));
  sc                    = A / (4 * PETSC_PI);
  F->metric.mass_weight = 1.0 / (sc * sc);
  /* an energy with its own metric term (the fairing energy's fidelity, soliman2021 Eq. 21: energy_fairing.c) */
  if (F->energy->metric) {
    PetscCheck(F->metric_type != CS_FLOW_METRIC_H1, F->hdr.comm, PETSC_ERR_SUP, "-%smetric h1 with -%senergy %s: not built (the energy's metric term is a weight on the H^2 metric's mass term)", F->hdr.prefix, F->hdr.prefix, F->energy_name);
    PetscCall(CSEnergyMetric(F->energy, &F->metric));
  }
  /* the ceiling of t_mu: with its own ramp 1e3 t_max; following t, none but tmu_ratio_max (each rejection
     raises t_mu / t twofold for good, up to 1e3 times its initial value, see the step control) */
  if (F->tmu_max <= 0) F->tmu_max = F->tmu_grow > 0 ? 1e3 * F->tmax : PETSC_MAX_REAL;
  F->tmu /= sc;
  if (F->tmu_max < PETSC_MAX_REAL) F->tmu_max /= sc;
  F->tmu_ratio_max = 1e3 * F->tmu / F->t;
  /* merit weight relative to the size of the energy (W ~ 4 pi and a fairing energy eps W differ by orders) */
  PetscCall(CSEnergyValue(F->energy, F->x0, &E0));
  F->rho *= PetscMax(PetscAbsReal(E0), PETSC_SMALL);
  if (F->ops.scale) PetscCall((*F->ops.scale)(F, sc, E0)); /* the kind's own parameters (CGD: its final dual step; ALM: its largest penalty) */
  PetscFunctionReturn(0);
}

static PetscErrorCode SetUpPositions(CSWillmoreFlow F)
{
  PetscScalar a0;
  PetscFunctionBeginUser;
  PetscCall(VecDuplicate(F->mesh->x, &F->x));
  PetscCall(VecCopy(F->mesh->x, F->x));
  PetscCall(VecDuplicate(F->x, &F->x0));
  PetscCall(VecCopy(F->x, F->x0));
  PetscCall(DMCreateGlobalVector(F->mesh->dmV1, &F->area0));
  PetscCall(VecDuplicate(F->area0, &F->areat));
  PetscCall(CSGeometryVertexAreas(F->mesh, F->x0, F->area0));
  PetscCall(VecSum(F->area0, &a0));
  F->area0_total = PetscRealPart(a0);
  PetscCall(CSGeometryAreaVolume(F->mesh, F->x0, NULL, &F->V0));
  if (F->fold_guard) PetscCall(VecDuplicate(F->x, &F->xgood));
  PetscFunctionReturn(0);
}

/* The memory a run of this kind needs, per vertex, against the memory available (issue 36, item 20): the peak RSS
   of one step, measured (docs/hardening.md "Memory per flow kind"): the vertex kinds about 30 KB per vertex (CGD:
   bunny_closed_cgal 926 MB / 37706, icosphere 5 292 MB / 10242); a kind with more unknowns says its own
   (ops.bytes_per_vertex: trianglefield.c). All ranks' vertices against one node's memory (the common single-machine
   run; an overestimate across nodes). Refused before anything is built, with the sizes, rather than killed mid-run. */
#define CS_FLOW_BYTES_PER_VERTEX 30000
static PetscErrorCode CheckMemory(CSWillmoreFlow F)
{
  char   what[256];
  size_t per = F->ops.bytes_per_vertex ? F->ops.bytes_per_vertex : CS_FLOW_BYTES_PER_VERTEX;
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(what, sizeof(what), "-%stype %s on %s: %" PetscInt_FMT " vertices at about %d KB per vertex for the run", F->hdr.prefix, F->type, F->mesh->name, F->mesh->Nv, (int)(per / 1000)));
  CSRootCall(F->hdr.comm, CSCheckAllocation(what, (PetscInt64)F->mesh->Nv, per));
  PetscFunctionReturn(0);
}

PetscErrorCode CSWillmoreFlowSetUp(CSWillmoreFlow F)
{
  char      prefix[80];
  PetscBool edges = F->conformal;
  PetscInt  k;
  PetscFunctionBeginUser;
  if (F->setupcalled) PetscFunctionReturn(0);
  PetscCall(PetscTime(&F->t0));
  PetscCall(CheckMemory(F));
  PetscCheck(!F->nadded || !CSWFOwnVariables(F), F->hdr.comm, PETSC_ERR_SUP, "CSWillmoreFlowAddConstraint(%s): the registered constraints act on vertex positions, not on the variables of -%stype %s", F->nadded ? F->added[0] : "", F->hdr.prefix, F->type);
  if (F->ops.setup_problem) { /* a kind with its own variables (trianglefield) */
    PetscCall((*F->ops.setup_problem)(F));
    F->setupcalled = PETSC_TRUE;
    PetscFunctionReturn(0);
  }
  PetscCall(SetUpPositions(F));
  PetscCall(CSWFSetUpBoundary(F));
  PetscCall(CSWFCreateEnergy(F));
  PetscCall(CSWFSetUpConstraints(F));
  PetscCall(CSWFSetUpVectors(F));
  PetscCall(CSMetricCreate(F->mesh, (PetscBool)(F->metric_type == CS_FLOW_METRIC_H2), &F->metric));
  F->metric.h1 = (PetscBool)(F->metric_type == CS_FLOW_METRIC_H1);
  PetscCall(CSWFSetUpScaling(F));
  PetscCall(PetscSNPrintf(prefix, sizeof(prefix), "%ssaddle_", F->hdr.prefix));
  k = F->k;
  if (F->ops.saddle_blocks) PetscCall((*F->ops.saddle_blocks)(F, &edges, &k)); /* ALM's plain metric: the metric solve alone */
  PetscCall(CSSaddleCreate(F->mesh, prefix, edges, (PetscBool)(F->metric_type == CS_FLOW_METRIC_H2), (PetscBool)(F->saddle_mat == CS_SADDLE_MAT_AIJ), F->reuse_its, k, &F->saddle));
  F->saddle.fixed = F->fixedIS;
  F->saddle.metric = &F->metric;
  F->setupcalled  = PETSC_TRUE;
  PetscFunctionReturn(0);
}
