/* Constrained Willmore flow (soliman2021 Sec. 4, Algorithm 1) as a library object on a mesh it is given:
   competitive gradient descent (cgd), projected gradient descent (pgd) and Sobolev gradient descent (gd) in the
   H^2 (or L2) metric, with the exact discrete conformal constraint and area / volume / point constraints, on
   closed surfaces and on surfaces with boundary. PETSc object style:
     CSWillmoreFlowCreate(mesh, &flow); CSWillmoreFlowSetType(flow, CSWILLMOREFLOWCGD);
     CSWillmoreFlowSetFromOptions(flow); CSWillmoreFlowSetUp(flow); CSWillmoreFlowSolve(flow);
     CSWillmoreFlowGetConvergedReason(flow, &reason); CSWillmoreFlowGetSolution(flow, &x);
     CSWillmoreFlowDestroy(&flow);
   Options are read under the prefix "flow_" (CSWillmoreFlowSetOptionsPrefix); the saddle solve's KSP under
   "<prefix>saddle_". The flow reads no mesh and writes no output: monitors (src/output/) do. */
#ifndef CS_METHODS_WILLMORE_H
#define CS_METHODS_WILLMORE_H
#include "cs_constraints.h"
#include "cs_object.h"
#include <petscksp.h>

typedef struct _p_CSWillmoreFlow *CSWillmoreFlow;

typedef const char *CSWillmoreFlowType;
#define CSWILLMOREFLOWCGD "cgd"
#define CSWILLMOREFLOWPGD "pgd"
#define CSWILLMOREFLOWGD  "gd"
#define CSWILLMOREFLOWNEWTON "newton"
#define CSWILLMOREFLOWALM "alm"
#define CSWILLMOREFLOWTRIANGLEFIELD "trianglefield" /* soliman2021 Algorithm 2 over triangle fields (trianglefield.c) */

/* Why Solve stopped; CSWillmoreFlowConvergedReasons[reason] names it, CSWillmoreFlowStopReasons[reason] is the
   summary's stop_reason. */
typedef enum {
  CS_WILLMORE_FLOW_ITERATING = 0,
  CS_WILLMORE_FLOW_CONVERGED_RTOL,           /* el_residual < rtol and violation < ctol */
  CS_WILLMORE_FLOW_DIVERGED_MAX_IT,          /* -flow_max_it reached */
  CS_WILLMORE_FLOW_DIVERGED_REJECTIONS,      /* -flow_max_rejections consecutive rejected steps */
  CS_WILLMORE_FLOW_DIVERGED_AREA,            /* total area beyond -flow_max_area_ratio */
  CS_WILLMORE_FLOW_DIVERGED_MESH_DEGENERATE, /* vertex-area spread beyond -flow_max_area_ratio */
  CS_WILLMORE_FLOW_STALLED,                  /* the step size t fell below -flow_t_min: no progress, not converged */
  CS_WILLMORE_FLOW_CONVERGED_ENERGY_TARGET,  /* the energy reached -flow_energy_target */
  CS_WILLMORE_FLOW_DIVERGED_FOLDED,          /* the enclosed volume changed sign or faces turned over against the
                                                input (-flow_fold_guard): stopped at the last good state */
  CS_WILLMORE_FLOW_CONVERGED_STATIONARY,     /* W and x stationary over -flow_stationary_window accepted steps, the
                                                violation below ctol (a fixed point of the iteration above rtol) */
  CS_WILLMORE_FLOW_DIVERGED_DRIFT            /* W stationary over -flow_drift_window steps while the residual rose
                                                -flow_drift_rise-fold from its smallest value: sliding along a
                                                direction of nearly constant W (a saddle; docs/real_meshes.md) */
} CSWillmoreFlowConvergedReason;
/* Whether a reason is a convergence (rtol, the energy target, or a stationary iteration). */
#define CSWillmoreFlowReasonConverged(r) ((r) == CS_WILLMORE_FLOW_CONVERGED_RTOL || (r) == CS_WILLMORE_FLOW_CONVERGED_ENERGY_TARGET || (r) == CS_WILLMORE_FLOW_CONVERGED_STATIONARY)
PETSC_EXTERN const char *const CSWillmoreFlowConvergedReasons[];
PETSC_EXTERN const char *const CSWillmoreFlowStopReasons[];

/* What the resolution guard measured when it stopped the flow (docs/real_meshes.md); CSWillmoreFlowDegenerations[]
   names it (the summary's "degeneration"). FINS: a face's quasi-conformal error beyond -flow_fin_q, i.e. the
   conformal factor jumps across faces (vertex stars blown out into large flat triangles); SQUEEZE: every face kept
   its shape with the Moebius gauge fixed (-flow_constraint_mobius), so the area moved smoothly along a path the
   Moebius group does not explain; SMOOTH: every face kept its shape without the gauge fixed (a Moebius slide or a
   squeeze). */
typedef enum { CS_WILLMORE_FLOW_DEGENERATION_NONE, CS_WILLMORE_FLOW_DEGENERATION_FINS, CS_WILLMORE_FLOW_DEGENERATION_SQUEEZE, CS_WILLMORE_FLOW_DEGENERATION_SMOOTH } CSWillmoreFlowDegeneration;
PETSC_EXTERN const char *const CSWillmoreFlowDegenerations[];

/* Enumerated options (PetscOptionsEnum tables: values, then the enum name, the prefix, NULL). */
typedef enum { CS_FLOW_METRIC_H2, CS_FLOW_METRIC_L2, CS_FLOW_METRIC_H1 } CSFlowMetricType;
typedef enum { CS_FLOW_BOUNDARY_DIRICHLET, CS_FLOW_BOUNDARY_FREE, CS_FLOW_BOUNDARY_NORMALS } CSFlowBoundaryType;
typedef enum { CS_SADDLE_MAT_NEST, CS_SADDLE_MAT_AIJ } CSSaddleMatType;
typedef enum { CS_ALM_METRIC_PLAIN, CS_ALM_METRIC_GAUSS_NEWTON } CSALMMetricType;
/* -flow_el_norm: what -flow_rtol tests, the scale-free residual el_residual_scaled (default) or el_residual itself */
typedef enum { CS_FLOW_EL_NORM_SCALED, CS_FLOW_EL_NORM_ABSOLUTE } CSFlowELNormType;
/* -flow_keep_best: at which non-converged stops the flow returns the kept best state instead of the last one */
typedef enum { CS_FLOW_KEEP_BEST_NONE, CS_FLOW_KEEP_BEST_GUARD, CS_FLOW_KEEP_BEST_ALL } CSFlowKeepBestType;
PETSC_EXTERN const char *const CSFlowELNormTypes[];
PETSC_EXTERN const char *const CSFlowKeepBestTypes[];
PETSC_EXTERN const char *const CSALMMetricTypes[];
PETSC_EXTERN const char *const CSFlowMetricTypes[];
PETSC_EXTERN const char *const CSFlowBoundaryTypes[];
PETSC_EXTERN const char *const CSSaddleMatTypes[];

/* The state after the last evaluation, for monitors and reports. */
typedef struct {
  PetscInt         it;                  /* accepted steps so far */
  PetscReal        energy, area, volume, conformal_violation, constraint_violation, el_residual, t;
  PetscReal        el_residual_scaled;  /* el_residual sqrt(area) / max(|energy|, 1e-3 |energy of the input|): scale-free */
  PetscInt         ksp_its;             /* Krylov iterations of the last step */
  PetscInt         ksp_its_total, rejections, nguard, pc_setups, linear_solves;
  PetscReal        area_spread, q_max, seconds;
  PetscReal        violation_max;       /* the largest constraint violation (conformal or global) of any iterate */
  PetscReal        violation_min;       /* the smallest of any iterate */
  PetscInt         violation_max_it, violation_min_it; /* their iterations */
  PetscBool        violation_grew;      /* the last state's violation is above ctol and 10x violation_min */
  PetscReal        el_first, el_min, energy_el_min; /* the EL residual of the first state, the smallest of the run and W there */
  PetscInt         it_el_min;           /* ... at this iteration (how near a critical point the path passed) */
  CSWillmoreFlowDegeneration degeneration; /* set when the resolution guard stopped the flow */
  PetscInt         k;                   /* global constraint values */
  const PetscReal *constraint_values;
  /* -flow_keep_best: the state of smallest el_residual_scaled with the violation <= ctol seen in the run (best_it -1:
     none yet); best_used: the flow returned it at its stop (CSWillmoreFlowUseBest), so the fields above describe it */
  PetscInt         best_it;
  PetscReal        best_el_residual_scaled, best_energy;
  PetscBool        best_used;
  PetscInt         last_it;             /* the iteration of the last state (== it unless best_used) */
  PetscReal        last_energy, last_el_residual_scaled;
} CSWillmoreFlowInfo;

/* The triangle field's own state (-flow_type trianglefield, soliman2021 Algorithm 2), after the last evaluation:
   the kind's part of CSWillmoreFlowInfo. */
typedef struct {
  PetscReal integrability_violation; /* max of |d1 omega|, face closure, |<<Y_i|omega>>| (-1: not evaluated yet) */
  PetscReal immersion_tol;           /* -flow_immersion_tol: -o writes the reconstruction only at a violation <= this */
  PetscReal spin_energy;             /* E_tau(psi(omega)) (App. C.3), unweighted */
  PetscInt  pinch_edges;             /* edges with |psi_jil - tau_ij psi_ijk| >= sqrt 2 (App. C.1; -1: not evaluated yet),
                                        in the signs the run's lifts followed: a sign flip on the way moves it */
  PetscInt  pinch_vertices;          /* pinch points: interior vertices with an odd number of such edges (sign-independent) */
} CSWillmoreFlowTriangleFieldInfo;
/* As KSPGMRESGetRestart, for the trianglefield kind only: with is NULL, another kind is an error; else *is says
   whether flow is of this kind (info is then filled, else set to -1 throughout). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowTriangleFieldGetInfo(CSWillmoreFlow flow, CSWillmoreFlowTriangleFieldInfo *info, PetscBool *is);
/* Whether the state -o would write is an immersion: the Poisson reconstruction of a triangle field integrable to
   -flow_immersion_tol (an immersion of it only then), or positions (the info of another kind: every field -1). */
static inline PetscBool CSWillmoreFlowTriangleFieldInfoIsImmersion(const CSWillmoreFlowTriangleFieldInfo *i)
{
  return (PetscBool)(i->integrability_violation < 0 || i->integrability_violation <= i->immersion_tol);
}

PETSC_EXTERN PetscErrorCode CSWillmoreFlowCreate(CSMesh mesh, CSWillmoreFlow *flow);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowSetType(CSWillmoreFlow flow, CSWillmoreFlowType type);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetType(CSWillmoreFlow flow, CSWillmoreFlowType *type);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowSetTolerances(CSWillmoreFlow flow, PetscReal rtol, PetscReal ctol, PetscInt max_it);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowSetFromOptions(CSWillmoreFlow flow);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowSetUp(CSWillmoreFlow flow);
/* One outer iteration (a step with its rejections); *reason is ITERATING unless the flow stopped. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowStep(CSWillmoreFlow flow, CSWillmoreFlowConvergedReason *reason);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowSolve(CSWillmoreFlow flow);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetConvergedReason(CSWillmoreFlow flow, CSWillmoreFlowConvergedReason *reason);
/* After a stop: make the kept best state (-flow_keep_best) the flow's state when the stop reason calls for it
   (*used); Solve leaves the last state, so a final checkpoint can store it first (the driver calls this after). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowUseBest(CSWillmoreFlow flow, PetscBool *used);
/* The positions of the current / initial state (dmV3, borrowed); for trianglefield the surface reconstructed from
   the triangle field (CSTriangleFieldReconstruct), whose own vector CSWillmoreFlowGetVariables gives. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetSolution(CSWillmoreFlow flow, Vec *x);   /* borrowed */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetInitial(CSWillmoreFlow flow, Vec *x0);   /* borrowed */
/* The positions of the last state when CSWillmoreFlowUseBest replaced it by the kept best (borrowed), else NULL. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetLastSolution(CSWillmoreFlow flow, Vec *x);
/* The flow's own variables (positions, or the triangle field omega on halfedges; borrowed). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetVariables(CSWillmoreFlow flow, Vec *x);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetMesh(CSWillmoreFlow flow, CSMesh *mesh);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetInfo(CSWillmoreFlow flow, CSWillmoreFlowInfo *info);
/* The flow's energy on its own variables (borrowed; after SetUp): for tests of its gradient. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetEnergy(CSWillmoreFlow flow, CSEnergy *e);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetEnergyName(CSWillmoreFlow flow, const char **name);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetInitialEnergy(CSWillmoreFlow flow, PetscReal *E0);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowView(CSWillmoreFlow flow, PetscViewer viewer); /* NULL: stdout */

/* The conformal Lagrange multiplier at the current state (soliman2021 Sec. 3.2): q (dmE1, or NULL) the
   quadratic differential in the paper's sign (Eq. 7), force (dmV3, or NULL) the conformal tension force
   sum_j q_ij df_ij / |df_ij|^2 per vertex, so that grad E + force is the Euler-Lagrange residual (without global
   constraints). Zero without the conformal constraint. After the first CSWillmoreFlowStep (e.g. in a monitor). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetConformalMultiplier(CSWillmoreFlow flow, Vec q, Vec force);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetConformal(CSWillmoreFlow flow, PetscBool *conformal);
/* The Euler-Lagrange residual r = g + X^T mu + sum_j nu_j row_j at the current state (dmV3, borrowed; its norm is
   the reported el_residual). After the first CSWillmoreFlowStep. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetResidual(CSWillmoreFlow flow, Vec *r);

/* Monitors, called after the evaluation at the top of every iteration (it = accepted steps so far). */
typedef PetscErrorCode (*CSWillmoreFlowMonitorFn)(CSWillmoreFlow flow, PetscInt it, void *ctx);
/* CSWillmoreFlowSetOptionsPrefix, GetOptionsPrefix, MonitorSet (up to 8 monitors, called in the order set; destroy,
   may be NULL, frees ctx at Destroy) and Destroy: the skeleton of every method object (include/cs_object.h) */
CS_OBJECT_DECLARE(CSWillmoreFlow, CSWillmoreFlowMonitorFn);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowMonitorCancel(CSWillmoreFlow flow);

/* Checkpoint state (after SetUp): the loop scalars and the fields a checkpoint stores (borrowed; may be
   overwritten before Solve to resume), and the inverse. Vertex flows: the positions x and the edge multipliers mu
   (NULL without the conformal constraint); -flow_type trianglefield: no positions, per edge its two halfedges'
   omega and multipliers, per face its closure multipliers and spinor (trianglefield_state.c). reals NULL: the
   fields only. CSWillmoreFlowSetState checks that the scalars were written by the same flow type and unpacks. */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetStateSize(CSWillmoreFlow flow, PetscInt *nreal);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetState(CSWillmoreFlow flow, PetscReal reals[], CSCheckpointFields *v);
PETSC_EXTERN PetscErrorCode CSWillmoreFlowSetState(CSWillmoreFlow flow, PetscInt it, const PetscReal reals[]);
/* The start the checkpoints fingerprint (borrowed; positions): the input positions, or the reconstruction of the
   start omega of -flow_type trianglefield (fixed by the input and -flow_init_*, -flow_seed). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetStart(CSWillmoreFlow flow, Vec *x);

/* Flow kinds: each in its folder src/methods/willmore/impls/<kind>/ (cgd, pgd, gd, newton, alm, trianglefield, and
   the fairing baselines), registered by name. */
typedef struct _CSWillmoreFlowOps *CSWillmoreFlowOps;
PETSC_EXTERN PetscErrorCode CSWillmoreFlowRegister(const char name[], PetscErrorCode (*create)(CSWillmoreFlow));
PETSC_EXTERN PetscErrorCode CSWillmoreFlowGetTypeList(PetscFunctionList *list); /* the registered kinds (not to be freed) */
/* Energies of the flow (-flow_energy), registered by name: willmore, area, fairing. create(mesh, x0, e) builds
   one at the input positions x0 with its defaults; the flow then gives it the options prefix "<flow prefix><name>_"
   and calls CSEnergySetFromOptions (willmore_energies.c). A new energy is tested by being registered
   (tests/unit/test_extension.c checks the gradient of every registered energy). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowEnergyRegister(const char name[], PetscErrorCode (*create)(CSMesh, Vec x0, CSEnergy *));
PETSC_EXTERN PetscErrorCode CSWillmoreFlowEnergyList(PetscFunctionList *list); /* the registered energies (not to be freed) */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowSetEnergyType(CSWillmoreFlow flow, const char name[]); /* as -flow_energy */
/* Global constraints registered by name (willmore_constraints.c): area, volume, mobius, rotation (targets: the input's
   values) and any registered later. create(mesh, x0, prefix, g) builds one at the input positions x0, reading
   its options, if any, under prefix ("<flow prefix>constraint_<name>_"). AddConstraint appends one to a flow's
   constraints (before SetUp; after the ones of the -flow_constraint_* options); the vertex kinds only. A new
   constraint is tested by being registered (tests/unit/test_extension.c checks the rows of every one). */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowConstraintRegister(const char name[], PetscErrorCode (*create)(CSMesh, Vec x0, const char prefix[], CSGlobalConstraint *));
PETSC_EXTERN PetscErrorCode CSWillmoreFlowConstraintList(PetscFunctionList *list); /* the registered constraints (not to be freed) */
PETSC_EXTERN PetscErrorCode CSWillmoreFlowAddConstraint(CSWillmoreFlow flow, const char name[]);

#endif
