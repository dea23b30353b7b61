/* Private to src/methods/bs/: the Bobenko-Schroeder flow object and its scheme strategy. */
#ifndef CS_BS_FLOW_IMPL_H
#define CS_BS_FLOW_IMPL_H
#include "cs_methods_bs.h"
#include "cs_geometry.h"
#include "cs_object.h"
#include "cs_flow_loop.h"

/* A scheme: setup after the flow's SetUp, start before the first step (after a resume), one step, destroy. */
typedef struct {
  PetscErrorCode (*setup)(CSBSFlow);
  PetscErrorCode (*start)(CSBSFlow);
  PetscErrorCode (*step)(CSBSFlow);
  PetscErrorCode (*destroy)(CSBSFlow);
  CSBSConvergedReason max_it_reason; /* the reason after -bs_max_it steps (ITERATING: the scheme counts) */
} CSBSSchemeOps;

/* semi (bs_semi.c); tao (bs_tao.c: backward Euler, switched to CSBSSchemeTaoStatic in its setup for the static
   problem) */
PETSC_INTERN const CSBSSchemeOps CSBSSchemeSemi, CSBSSchemeTao, CSBSSchemeTaoStatic;

struct _p_CSBSFlow {
  CSObjectHeader hdr; /* comm (the mesh's), prefix, monitors (CSBSFlowMonitorFn) */
  CSMesh         mesh;

  /* options */
  CSBSScheme   scheme;
  CSBSProblem  problem;
  CSBSBoundary bc;
  PetscReal    beta_eps, hessian_eps, dt_opt, dt_rel, dt_grow, dt_max_opt, atol, rtol, perturb;
  PetscReal    dt_min_rel, dt_min, dt0, max_area_ratio, energy_target;
  PetscBool    energy_target_set;
  PetscBool    hessian_eps_set, dt_set, monotone;
  PetscInt     max_rej;
  char         islands[PETSC_MAX_PATH_LEN]; /* -bs_islands FILE (Sec. 3.3), "" for none */
  CSBSIslandsType islands_type;             /* -bs_islands_type: the file lists vertices or faces */
  CSBSSingular    singular;                 /* -bs_singular (Sec. 3.2) */

  /* state */
  CSEnergy         bs;
  const PetscBool *fixed;
  PetscInt         nfixed;
  Vec              x, x0;  /* the iterate; the input positions (fixed vertices are reset to them) */
  Vec              area0, areat; /* vertex areas of the input and of a trial state (the guard) */
  Vec              xmon;   /* the state the monitors see (x, or TAO's iterate with fixed vertices reset) */
  PetscReal        h, dt, dt_max, W;
  PetscInt         it, rejected, row; /* it: the scheme's count (loop.it, but TAO static: its iterations) */
  PetscLogDouble   tstart, tsteps0;
  CSBSConvergedReason reason;       /* the scheme's verdict of its last step (the loop's reason adds max_it) */
  PetscBool        finished, resumed;
  CSFlowLoop       loop;            /* -max_it, the set-up time and t0, the stop reason (src/methods/flow_loop.c) */

  const CSBSSchemeOps *ops;
  void                *data;
};

PETSC_INTERN PetscErrorCode CSBSFlowResetFixed(CSBSFlow, Vec);
/* The divergence guard (-bs_max_area_ratio): *ok false (and a message) when x's total area or vertex-area spread
   relative to the input is beyond the ratio. */
PETSC_INTERN PetscErrorCode CSBSFlowCheckGuard(CSBSFlow, Vec x, PetscBool *ok);
/* Calls the monitors on flow->xmon; START and STEP advance the history row (START only when not resumed). */
PETSC_INTERN PetscErrorCode CSBSFlowMonitor(CSBSFlow, CSBSMonitorInfo *);

#endif
