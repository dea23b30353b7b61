/* The iteration driver the stepping flows share (src/methods/flow_loop.c): set-up timing, the first evaluation,
   the step loop, the stopping tests common to all flows (-max_it, -max_seconds), the monitor events and the
   stepping time. A flow embeds a CSFlowLoop (member `loop`), fills its ops with its own parts and keeps only
   those: its evaluation, its step proper, its own stopping tests and the calls of its typed monitors. Used by
   the conformal flow (src/methods/conformal/), the curve flow (src/methods/curve/) and the Bobenko-Schroeder flow
   (src/methods/bs/: its schemes monitor their own steps, its TAO static scheme is one step that runs TaoSolve,
   its semi scheme limits the rejections itself, and a checkpoint resumes it through CSFlowLoopResume). Not (yet)
   by the Willmore flows: src/methods/willmore/willmore_solve.c evaluates and monitors a state at the start of a
   step, then runs its stopping tests and then a step with its own inner rejection loop; this loop monitors after
   the tests. The loop logs the flow's Step and Solve events. */
#ifndef CS_FLOW_LOOP_H
#define CS_FLOW_LOOP_H
#include <petscsys.h>

/* the same values as each flow's START/STEP/END monitor event */
typedef enum {
  CS_FLOW_EVENT_START,
  CS_FLOW_EVENT_STEP,
  CS_FLOW_EVENT_END
} CSFlowEvent;

/* Each op takes the flow object. reason values: 0 iterating (every flow's ITERATING is 0), < 0 diverged,
   > 0 converged. */
typedef struct {
  PetscErrorCode (*setup)(void *);                /* allocations and solvers (once) */
  PetscErrorCode (*start)(void *);                /* the input's state: evaluate it and record the initial measures */
  PetscErrorCode (*advance)(void *, PetscBool *); /* one step: the current positions <- the next; PETSC_FALSE when
                                                     the flow rejected the step and kept its state */
  PetscErrorCode (*evaluate)(void *);             /* the new state's measures and the next direction (NULL:
                                                     advance evaluates) */
  PetscErrorCode (*judge)(void *, PetscInt *);    /* the flow's own tests of the state, also after a rejected step
                                                     (0: none met, go on) */
  PetscErrorCode (*monitor)(void *, CSFlowEvent); /* call the flow's monitors (loop.it and the times are set) */
} CSFlowLoopOps;

typedef struct {
  CSFlowLoopOps  ops;
  MPI_Comm       comm;          /* the flow's: -max_seconds is decided on rank 0 */
  PetscInt       max_it;        /* -max_it: after this many steps stop with max_it_reason */
  PetscReal      max_seconds;   /* -max_seconds (0: no limit): stop with max_it_reason once this many seconds
                                   have passed since the set-up began */
  PetscInt       max_it_reason; /* the flow's DIVERGED_MAX_IT (0: no -max_it and -max_seconds tests, the flow
                                   counts itself) */
  PetscInt       it, reason;    /* steps taken; why the loop stopped (0 while iterating) */
  PetscInt       rejections;    /* steps the flow rejected (not counted in it, no STEP event) */
  PetscBool      own_rejection_limit; /* the flow's judge alone stops a run of rejections; else the rejected
                                         steps count toward -max_it too */
  PetscBool      step_taken;    /* the last advance was taken */
  PetscReal      seconds, step_seconds; /* since the set-up began, at the last monitor call; of the last step */
  PetscLogDouble t0, t_setup, t_steps;  /* set-up start; set-up time; the steps' total time */
  PetscBool      setupcalled, started;
  PetscLogEvent  event_step, event_solve; /* the flow's <Flow>Step (advance and evaluate) and <Flow>Solve events */
} CSFlowLoop;

/* ops, the communicator, the reason for -max_it/-max_seconds and the flow's Step and Solve events
   (include/cs_log.h); everything else zero */
PETSC_EXTERN PetscErrorCode CSFlowLoopInit(CSFlowLoop *, MPI_Comm, const CSFlowLoopOps *, PetscInt max_it_reason, PetscLogEvent event_step, PetscLogEvent event_solve);
/* ops.setup once, timed (t0, t_setup) */
PETSC_EXTERN PetscErrorCode CSFlowLoopSetUp(CSFlowLoop *, void *flow);
/* A run resumed from a checkpoint (after the set-up, before the first step): it steps taken, seconds since its
   set-up began (the seconds and -max_seconds continue from there) */
PETSC_EXTERN PetscErrorCode CSFlowLoopResume(CSFlowLoop *, PetscInt it, PetscReal seconds);
/* one step (after the set-up and the input's evaluation, when not yet done); nothing once stopped. A step the flow
   rejects is neither counted nor evaluated nor monitored; the flow's judge then decides whether to stop. */
PETSC_EXTERN PetscErrorCode CSFlowLoopStep(CSFlowLoop *, void *flow);
/* steps until a stopping test is met, then the END event */
PETSC_EXTERN PetscErrorCode CSFlowLoopSolve(CSFlowLoop *, void *flow);

/* The public SetUp, Step and Solve of a flow on the loop (its member `loop`), one call each of the loop's:
   CS_FLOW_LOOP_DEFINE(CSCurveFlow) defines CSCurveFlowSetUp, CSCurveFlowStep and CSCurveFlowSolve. */
#define CS_FLOW_LOOP_DEFINE(Type) \
  PetscErrorCode Type##SetUp(Type obj) \
  { \
    PetscFunctionBeginUser; \
    PetscCall(CSFlowLoopSetUp(&obj->loop, obj)); \
    PetscFunctionReturn(0); \
  } \
  PetscErrorCode Type##Step(Type obj) \
  { \
    PetscFunctionBeginUser; \
    PetscCall(CSFlowLoopStep(&obj->loop, obj)); \
    PetscFunctionReturn(0); \
  } \
  PetscErrorCode Type##Solve(Type obj) \
  { \
    PetscFunctionBeginUser; \
    PetscCall(CSFlowLoopSolve(&obj->loop, obj)); \
    PetscFunctionReturn(0); \
  }

#endif
