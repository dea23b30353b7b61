/* Discrete Willmore flow of Bobenko-Schroeder (bobenko-schroeder2005 Sec. 4) as an object on a mesh it is
   given, PETSc style (like KSP/TS):
     CSBSFlowCreate(mesh, &flow); CSBSFlowSetOptionsPrefix(flow, "bs_") (the default); CSBSFlowSetFromOptions;
     CSBSFlowMonitorSet(...) (progress line, history, ParaView, checkpoint: src/output/bs_monitors.c);
     CSBSFlowSetUp; CSBSFlowSolve (or CSBSFlowStep until the reason is not CS_BS_ITERATING);
     CSBSFlowGetConvergedReason; CSBSFlowGetSolution; CSBSFlowDestroy.
   The flow works on its own copy of mesh->x; the mesh is not changed.
   Schemes (-bs_scheme, a small strategy: src/methods/bs/bs_semi.c, bs_tao.c):
     semi  semi-implicit steps (1/dt I + K) dx = -grad W, one n x n solve per coordinate with the KSP of
           prefix "<prefix>semi_" (K: the linearised Hessian of Eq. 1; default MUMPS LDL^T, see docs/bs_flow.md).
           A failed solve or an energy increase rejects the step and divides dt by 4 (at most
           -bs_max_rejections in a row); accepted steps grow dt by -bs_dt_grow up to -bs_dt_max;
     tao   TAO of prefix "<prefix>" (-bs_tao_type ...; objective/gradient = W, Hessian = K on each coordinate as
           a 3V x 3V AIJ with block size 3, plus I/dt: K alone gives the Newton step -x, a homothety):
           -bs_problem static minimises W in one TaoSolve (dt grows by -bs_dt_grow per Hessian),
           -bs_problem euler does backward Euler steps min W(x) + |x - x_n|^2 / (2 dt).
   Boundaries (-bs_boundary fixed|free, Sec. 3.3), heuristic threshold -bs_beta_eps (Sec. 3.2), -bs_perturb f
   (random move of the free vertices by f mean edge lengths first), -bs_hessian_eps s (diamonds with
   sin beta < s left out of K), -bs_monotone false (accept steps that increase W: the paper's plain stepping).
   Stopping: W < -bs_atol, or a relative decrease below -bs_rtol, or -bs_max_it steps; semi also stops as stalled
   when dt falls below -bs_dt_min (default 1e-6 dt0), at -bs_energy_target, and by the guard -bs_max_area_ratio
   (the total area, or the spread of the vertex areas relative to the input, beyond it: the last good state). dt has units of
   length^2; the default -bs_dt_rel 1 takes dt = (mean edge length)^2. */
#ifndef CS_METHODS_BS_H
#define CS_METHODS_BS_H
#include <petscksp.h>
#include "cs_energy_bs.h"
#include "cs_object.h"

typedef struct _p_CSBSFlow *CSBSFlow;

typedef enum {
  CS_BS_SCHEME_SEMI,
  CS_BS_SCHEME_TAO
} CSBSScheme;
PETSC_EXTERN const char *const CSBSSchemes[];
typedef enum {
  CS_BS_PROBLEM_STATIC,
  CS_BS_PROBLEM_EULER
} CSBSProblem;
PETSC_EXTERN const char *const CSBSProblems[];
/* -bs_islands_type: what the -bs_islands file lists (Sec. 3.3, "islands of internal vertices (or faces)") */
typedef enum {
  CS_BS_ISLANDS_VERTEX,
  CS_BS_ISLANDS_FACE
} CSBSIslandsType;
PETSC_EXTERN const char *const CSBSIslandsTypes[];

/* Why the flow stopped; CSBSConvergedReasons[reason] is the summary's stop_reason. */
typedef enum {
  CS_BS_STALLED             = -5, /* semi: dt fell below -bs_dt_min (rejected steps): no progress, not converged */
  CS_BS_DIVERGED_GUARD      = -4, /* semi: the total area or the vertex-area spread beyond -bs_max_area_ratio:
                                     stopped with the last good state */
  CS_BS_DIVERGED_TAO        = -3, /* tao: TAO did not converge, or -bs_max_it backward Euler steps */
  CS_BS_DIVERGED_REJECTIONS = -2, /* semi: more than -bs_max_rejections consecutive rejected steps */
  CS_BS_DIVERGED_MAX_IT     = -1, /* semi: -bs_max_it accepted steps */
  CS_BS_ITERATING           = 0,
  CS_BS_CONVERGED           = 1, /* W < atol or relative decrease < rtol (tao static: TAO's own tests too) */
  CS_BS_CONVERGED_ENERGY_TARGET = 2 /* semi: W reached -bs_energy_target */
} CSBSConvergedReason;
PETSC_EXTERN const char *const *CSBSConvergedReasons;

/* What a monitor is called for: the state before the first step (START; with resumed set it is already in
   the history), every accepted step (semi, tao euler) or TAO iteration (tao static), and the end. */
typedef enum {
  CS_BS_MONITOR_START,
  CS_BS_MONITOR_STEP,
  CS_BS_MONITOR_END
} CSBSMonitorEvent;
typedef struct {
  CSBSMonitorEvent event;
  PetscInt         it;           /* accepted steps (semi, euler) or TAO iterations (static) */
  PetscInt         row;          /* history row / ParaView step of this state */
  PetscReal        W;            /* energy of the current state */
  PetscReal        dt;           /* time step of the step just taken (0 for tao static) */
  PetscInt         inner_its;    /* linear iterations (semi) or TAO iterations (euler) of the step */
  PetscReal        gnorm;        /* tao static: |grad W| */
  const char      *inner_reason; /* tao euler: TAO's reason for the step */
  PetscBool        resumed;      /* START of a resumed run */
  PetscReal        seconds;      /* wall time since the start (continued across a resume) */
} CSBSMonitorInfo;
typedef PetscErrorCode (*CSBSFlowMonitorFn)(CSBSFlow, const CSBSMonitorInfo *, void *);

PETSC_EXTERN PetscErrorCode CSBSFlowCreate(CSMesh mesh, CSBSFlow *flow);
PETSC_EXTERN PetscErrorCode CSBSFlowSetFromOptions(CSBSFlow flow);
PETSC_EXTERN PetscErrorCode CSBSFlowSetUp(CSBSFlow flow);
PETSC_EXTERN PetscErrorCode CSBSFlowStep(CSBSFlow flow);
PETSC_EXTERN PetscErrorCode CSBSFlowSolve(CSBSFlow flow);
/* CSBSFlowSetOptionsPrefix, GetOptionsPrefix, MonitorSet (up to 8 monitors, called in the order set; destroy,
   may be NULL, frees ctx at Destroy) and Destroy: the skeleton of every method object (include/cs_object.h) */
CS_OBJECT_DECLARE(CSBSFlow, CSBSFlowMonitorFn);

PETSC_EXTERN PetscErrorCode CSBSFlowGetConvergedReason(CSBSFlow flow, CSBSConvergedReason *reason);
PETSC_EXTERN PetscErrorCode CSBSFlowGetSolution(CSBSFlow flow, Vec *x); /* the current state (borrowed) */
PETSC_EXTERN PetscErrorCode CSBSFlowGetInitialSolution(CSBSFlow flow, Vec *x0); /* before -bs_perturb */
PETSC_EXTERN PetscErrorCode CSBSFlowGetMesh(CSBSFlow flow, CSMesh *mesh);
PETSC_EXTERN PetscErrorCode CSBSFlowGetEnergy(CSBSFlow flow, CSEnergy *bs); /* the circle-angle energy */
/* The state of the run: accepted steps, consecutive rejections, W, the current time step, the boundary
   condition and its number of fixed vertices. */
typedef struct {
  PetscInt     it, rejected;
  PetscReal    W, dt;
  CSBSBoundary bc;
  PetscInt     nfixed;
} CSBSFlowInfo;
PETSC_EXTERN PetscErrorCode CSBSFlowGetInfo(CSBSFlow flow, CSBSFlowInfo *info);
/* "semi", "tao_static" or "tao_euler" */
PETSC_EXTERN PetscErrorCode CSBSFlowGetSchemeName(CSBSFlow flow, const char *name[]);
/* Wall time of the stepping (with the first assembly of K and grad W), continued across a resume. */
PETSC_EXTERN PetscErrorCode CSBSFlowGetStepSeconds(CSBSFlow flow, PetscLogDouble *seconds);

/* Checkpoint state of the semi scheme after `it` accepted steps: x and [dt, rejected, seconds of the history
   clock, seconds of stepping]; W, grad W and K are recomputed from x, so a resumed run continues exactly like
   the uninterrupted one. SetCheckpointState (after SetUp, before the first step) restores it. */
#define CS_BS_CHECKPOINT_NREAL 4
PETSC_EXTERN PetscErrorCode CSBSFlowGetCheckpointState(CSBSFlow flow, PetscReal r[CS_BS_CHECKPOINT_NREAL]);
PETSC_EXTERN PetscErrorCode CSBSFlowSetCheckpointState(CSBSFlow flow, PetscInt it, const PetscReal r[CS_BS_CHECKPOINT_NREAL]);

#endif
