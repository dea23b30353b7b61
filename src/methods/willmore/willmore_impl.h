/* Private to src/methods/willmore/: the flow object, its kind strategy and its saddle solver.
   The method (soliman2021 Algorithm 1, step control, guards) is described in docs/willmore_flow.md. */
#ifndef CS_WILLMORE_IMPL_H
#define CS_WILLMORE_IMPL_H
#include "cs_methods_willmore.h"
#include "cs_object.h"

/* ---- the linear solver of every step (willmore_saddle.c) ----
   Solves, with the KSP of prefix "<flow prefix>saddle_",
     [ A00  X    0  ] [zE]   [rE]      A00 = -I_Q / t_mu   (multipliers of the conformal constraint, FIRST:
     [ X^T  H/t  B  ] [zV] = [rV]                            then selfp is the exact Schur complement)
     [ 0    B^T  -G ] [zX]   [rX]      H = metric (3V x 3V), X = C Dlambda (E x 3V),
   B = the k dense Jacobian rows of the global constraints (area, volume, points), G = diag(g_j)/t_mu. The
   sparse part is a MATNEST [[A00, X], [X^T, H/t]] (or its AIJ conversion with -flow_matrix_type aij, for
   monolithic direct solvers); the k dense rows are appended by bordering (block elimination: k+1 solves
   with the same operator, then a k x k system), so no dense row ever enters a factorisation. Without the
   conformal constraint the edge block is absent and the KSP solves with H/t alone. */
typedef struct {
  CSMesh      mesh;
  KSP         ksp;
  char        prefix[64]; /* of the KSP */
  PetscBool   edges;      /* conformal block present */
  PetscBool   h2;         /* metric H^2 (else L2): chooses the default solver without the edge block */
  PetscBool   monolithic; /* aij */
  Mat         A00, Xt, H11, K, Kaij;
  Mat         XtD, XtDX, S; /* the exact Schur complement S = H/t + X^T (t_mu I_Q^{-1}) X, assembled with a fixed
                               pattern (for the fieldsplit's schur_precondition user) */
  CSMatAddMap add_xtdx, add_h11; /* S refilled from its two terms (fixed patterns) */
  IS          is[2];
  Vec         b, z;
  IS          fixed;      /* Dirichlet dofs of H (identity rows/cols), may be NULL */
  PetscInt    k;
  Vec        *B, *W;      /* k rows, k solutions (each an (E+3V) or 3V vector) */
  Vec        *WE, *WV;    /* a resumed run's W (parts), until the first step creates W (CSSaddleSetGuess) */
  PetscReal  *G;
  PetscInt    reuse_its;  /* keep the preconditioner while the last solve took <= this many its */
  PetscBool   reuse_set;  /* reuse_its given by the user (-flow_factor_reuse_its), not the default */
  PetscInt    last_its;   /* Krylov iterations of the last solve */
  PetscInt    setups;     /* preconditioner (factorisation) builds so far */
  PetscInt    solves;     /* linear solves (right-hand sides) so far */
  PetscInt    max_it;     /* the KSP's own iteration limit */
  PetscBool   reusing;    /* this step keeps an earlier preconditioner */
  PetscBool   krylov;     /* the KSP iterates (not preonly): kept preconditioners and initial guesses allowed */
  PetscInt    backoff, wait; /* fresh steps to take before the next reuse attempt, after failed attempts */
  Vec         iq;         /* this step's I_Q, t_mu and X (borrowed), to rebuild S when a kept one fails */
  PetscReal   tmu;
  Mat         X;
  PetscBool   have_pc;
  PetscBool   reuse_borders; /* -<prefix>reuse_borders: keep W = K^{-1} B for the later solves with the same operators */
  PetscBool   w_valid;    /* W holds K^{-1} B for the operators set last */
  CSSchurSolveType schur; /* -<prefix>schur_solver: direct (default) or an iterative Schur solve (docs/scaling.md) */
  PetscReal   schur_rtol; /* -<prefix>schur_rtol of the iterative Schur solve */
  CSMetric   *metric;     /* the flow's (borrowed): its terms build the unassembled S for bddc */
  PetscReal   t;          /* this step's t */
  PetscReal   t_pc, tmu_pc; /* the t and t_mu of the preconditioner (factorisation) in use */
  Mat         Sis;        /* bddc: S unassembled (MATIS), the user Schur preconditioner */
} CSSaddle;

/* prefix: of the KSP; reuse_its < 0: the default (10 with the edge block, else 0) */
PETSC_INTERN PetscErrorCode CSSaddleCreate(CSMesh mesh, const char prefix[], PetscBool edges, PetscBool h2, PetscBool monolithic, PetscInt reuse_its, PetscInt k, CSSaddle *s);
/* H (3V x 3V) scaled by 1/t; iq, tmu, X ignored without the edge block; rows/g only if k > 0. */
PETSC_INTERN PetscErrorCode CSSaddleSetOperators(CSSaddle *s, Mat H, PetscReal t, Vec iq, PetscReal tmu, Mat X, Vec rows[], const PetscReal g[]);
/* rE/zE may be NULL without the edge block; rX/zX without k. *its = KSP iterations (sum over the k+1
   bordering solves); *reason = the KSP's reason of the first solve that failed, or of the last one. A solve
   that did not converge is not an error: the flow decides (a rejected step). */
PETSC_INTERN PetscErrorCode CSSaddleSolve(CSSaddle *s, Vec rE, Vec rV, const PetscReal rX[], Vec zE, Vec zV, PetscReal zX[], PetscInt *its, KSPConvergedReason *reason);
PETSC_INTERN PetscErrorCode CSSaddleDestroy(CSSaddle *s);
/* checkpoints: the bordering solves' initial guesses W_j (the last solutions), by parts (E NULL without the edge block) */
PETSC_INTERN PetscErrorCode CSSaddleGetGuess(CSSaddle *s, PetscInt j, Vec E, Vec V);
PETSC_INTERN PetscErrorCode CSSaddleSetGuess(CSSaddle *s, PetscInt j, Vec E, Vec V);

/* ---- the step size model (willmore_step_model.c) ---- */
typedef enum { CS_WF_STEP_PREDICTIVE, CS_WF_STEP_HALVING } CSWFStepModel;
PETSC_INTERN const char *const CSWFStepModels[];
#define CS_WF_REJECT_CEILING    1 /* the filter's criteria that rejected a trial */
#define CS_WF_REJECT_LAGRANGIAN 2
typedef struct {
  PetscInt  it, n;       /* the iteration of the trials recorded, and how many so far */
  PetscInt  why;         /* CS_WF_REJECT_* bits of the last trial (0: accepted) */
  PetscReal t, v0, vt;   /* its step, the violation of x and of the trial point (after the corrections) */
  PetscReal dL, slope;   /* L(t) - L0 and the slope <df, H df>/t (Lagrangian rejections only) */
  PetscReal t1, d1;      /* the trial before it at this x: step and v(t1) - v0 */
  PetscReal q;           /* the violation left by the step's first second-order correction, relative (willmore_step.c): the
                            part (1 - t t_mu s^2 / (lambda_H + t t_mu s^2)) of a violation the step's operator leaves */
} CSWFTrialRecord;

/* ---- the flow kind: a strategy struct (impls/<kind>/: cgd, pgd, gd, newton, alm, fairing, trianglefield) ----
   Its data live in F->data (created by CSWillmoreFlowCreate_<Kind>, freed by ops.destroy); no shared file tests a
   kind's name: what differs between kinds is one of these slots (NULL: the shared default named beside it). */
struct _CSWillmoreFlowOps {
  PetscInt  id;             /* stored in checkpoints (a resume must use the same kind) */
  PetscBool conformal;      /* default of -flow_conformal */
  PetscBool step_halving;   /* default of -flow_step_model is halving (trianglefield: the model fell behind, docs/willmore_flow.md) */
  PetscReal tmu_ratio;      /* default of -flow_t_mu as a multiple of t (0: 1e3; cgd 1e5, docs/studies.md "The dual step") */
  PetscErrorCode (*setup)(CSWillmoreFlow);               /* checks of the options against the kind */
  PetscErrorCode (*start)(CSWillmoreFlow);               /* before the first iteration (not after a resume) */
  PetscErrorCode (*trial)(CSWillmoreFlow, PetscBool *);  /* the trial point xt of step t (false: rejected) */
  PetscErrorCode (*filter)(CSWillmoreFlow, PetscBool *); /* acceptance of xt */
  PetscErrorCode (*accept)(CSWillmoreFlow);              /* x = xt done: multipliers, restoration */
  PetscErrorCode (*grow)(CSWillmoreFlow);                /* step sizes after an accepted step */
  PetscErrorCode (*shrink)(CSWillmoreFlow);              /* step sizes after a rejected step */
  PetscErrorCode (*dual)(CSWillmoreFlow);                /* before the step, after its operators: a multiplier estimate (NULL: none) */
  PetscErrorCode (*residual)(CSWillmoreFlow, PetscReal *); /* the stopping residual at x (NULL: CSWFResidual, el_residual) */
  PetscErrorCode (*multipliers)(CSWillmoreFlow, Vec *);  /* the conformal multiplier reported at x (NULL: mu; ALM: its estimate) */
  PetscErrorCode (*weights)(CSWillmoreFlow);             /* the metric of the conformal rows at x (NULL: I_Q, CSWFQuadDiffMetric) */
  PetscErrorCode (*scale)(CSWillmoreFlow, PetscReal sc, PetscReal E0); /* size scaling of the kind's parameters (s^2 = sc, |E(input)| = E0) */
  PetscErrorCode (*saddle_blocks)(CSWillmoreFlow, PetscBool *edges, PetscInt *k); /* blocks of the saddle solver
                                                         (NULL: the conformal rows if on, and the k global rows) */
  PetscErrorCode (*storable)(CSWillmoreFlow);            /* refuses -checkpoint/-resume when its state is not stored (NULL: stored) */
  PetscErrorCode (*get_switch)(CSWillmoreFlow, PetscBool *); /* the kind's one stored switch, ck[8] of a checkpoint */
  PetscErrorCode (*set_switch)(CSWillmoreFlow, PetscBool);   /* (CGD: -t_mu_final fired; NULL: none, 0 stored) */
  PetscErrorCode (*destroy)(CSWillmoreFlow);             /* the kind's own data (NULL: none) */
  PetscErrorCode (*setfromoptions)(CSWillmoreFlow, PetscOptionItems *); /* the kind's own options, read inside the
                                                         flow's options block after the shared ones (NULL: none) */
  PetscErrorCode (*view)(CSWillmoreFlow, PetscViewer);   /* the kind's own lines of CSWillmoreFlowView (NULL: none) */
  PetscReal max_step;       /* default of -flow_max_step (0: off) */
  PetscBool fold_guard;     /* default of -flow_fold_guard */
  PetscBool own_metric;     /* the kind updates the metric itself, when it needs it (newton) */
  size_t    bytes_per_vertex; /* memory of a run per vertex, measured (0: the vertex kinds', willmore_setup.c CheckMemory) */
  /* A kind with its own variables (trianglefield: x is a triangle field, not positions) replaces the positions'
     pipeline: its set-up (variables, energy, constraints, vectors, saddle), the evaluation at x (E, g, c, X, r,
     violations), the step's operators (metric, I_Q, weights), the constraints (for the filter and the
     corrections) and the surface of a state (positions for the output). NULL: the positions' own. */
  PetscErrorCode (*setup_problem)(CSWillmoreFlow);
  PetscErrorCode (*evaluate)(CSWillmoreFlow);
  PetscErrorCode (*operators)(CSWillmoreFlow);
  PetscErrorCode (*constraints)(CSWillmoreFlow, Vec x, Vec c, PetscReal cx[], PetscBool wantJ);
  PetscErrorCode (*positions)(CSWillmoreFlow, PetscBool initial, Vec *x);
  /* Checkpoints of such a kind (willmore_state.c; NULL: refused): state_nreal scalars of its own after the flow's, the
     fields packed in natural-order-ready form (get_state; ck NULL: the fields only) and their inverse after a
     resume overwrote the fields and the scalars (set_state). */
  PetscInt state_nreal;
  PetscErrorCode (*get_state)(CSWillmoreFlow, PetscReal ck[], CSCheckpointFields *v);
  PetscErrorCode (*set_state)(CSWillmoreFlow, const PetscReal ck[]);
};

/* the continuation of the point targets (willmore_points_continuation.c, -flow_points_stages) */
typedef struct {
  PetscInt   stages;     /* -points_stages K (0: off) */
  PetscReal  rtol, ctol; /* a stage ends when el_residual_scaled < rtol and the violation < ctol ... */
  PetscInt   max_it;     /* ... or after this many iterations (0: no limit) */
  PetscInt   stage, it0; /* the stage k in 1..K (targets k/K of the way from the input) and its first iteration */
  PetscReal *c0;         /* the point rows at the input, c(x0) (the staged constraint's) */
  PetscInt   k, off;     /* their count and place among the global rows */
} CSWFPointsContinuation;
static inline PetscBool CSWFPointsFinal(const CSWFPointsContinuation *pc)
{
  return (PetscBool)(pc->stage >= pc->stages);
}
static inline PetscReal CSWFPointsFraction(const CSWFPointsContinuation *pc)
{
  return pc->stages ? (PetscReal)pc->stage / (PetscReal)pc->stages : 1;
}
#define CS_WF_STAT_MAX                64 /* largest -flow_stationary_window (its values are stored in checkpoints) */
#define CS_WF_STAT_NREAL              (6 + 2 * (CS_WF_STAT_MAX + 1)) /* checkpoint scalars of the window and of the drift test */

struct _p_CSWillmoreFlow {
  CSObjectHeader        hdr;  /* comm (the mesh's), prefix (default "flow_"), monitors (CSWillmoreFlowMonitorFn), destroy */
  CSMesh                mesh; /* given, referenced by the caller; not destroyed here */
  char                  type[16];
  struct _CSWillmoreFlowOps ops;
  PetscBool             setupcalled;
  CSWillmoreFlowConvergedReason reason;

  /* options */
  char                  energy_name[32];
  CSFlowMetricType      metric_type;
  CSFlowBoundaryType    boundary;
  PetscBool             boundary_set, conformal_set, mobius, rotation;
  char                  target[PETSC_MAX_PATH_LEN], points[PETSC_MAX_PATH_LEN];
  PetscBool             area_set, area_given, vol_set, vol_given;
  PetscReal             area_target, vol_target;
  CSSaddleMatType       saddle_mat;
  PetscInt              reuse_its;

  /* problem */
  CSEnergy              energy;
  PetscBool             conformal;
  CSConformalConstraint cc;
  PetscBool             normals; /* boundary-face normal constraint: its rows follow the edge rows */
  CSNormalConstraint    nc;
  Mat                   Xext, Xc; /* [X; DN] stacked by rows (AIJ), and the Jacobian in use (X or Xext) */
  IS                    isM[2];       /* edge / normal rows in the multiplier layout */
  Vec                   cE, cN, iqE, iqN;
  PetscInt              ng, ngmax, k; /* global constraints (ng of ngmax slots), their rows */
  CSGlobalConstraint   *gc;    /* area, volume, points, Moebius balance, rotation gauge, added ones (grows) */
  char                **added; /* names of the registered constraints added (CSWillmoreFlowAddConstraint) */
  PetscInt              nadded, naddedmax;
  PetscFunctionList     constraint_list; /* the registry they were found in (borrowed) */
  PetscBool            *fixed;   /* local vertices held fixed (Dirichlet), or NULL */
  IS                    fixedIS; /* global dmV3 dofs of owned fixed vertices */
  CSMetric              metric;
  CSSaddle              saddle;
  Vec                   x, x0, g, r, c, mu, dmu, df, iq, xt, ct, tmp;
  Vec                   xstart; /* NULL (x0), or the kind's start variables: fingerprinted by checkpoints (borrowed) */
  Vec                  *rows;
  PetscReal            *cx, *cxt, *nu, *dnu, *dnu2, *gw, *nun;
  PetscReal             t, tmu, tmax, grow, rtol, ctol, wmin, rho, vmax, vrestore;
  PetscBool             restore_stalled, restore_failed;
  Vec                   mun;
  Vec                   area0, areat; /* barycentric vertex areas of the input and of the current state */
  PetscReal             area0_total;  /* total area of the input */
  PetscReal             max_area_ratio;
  PetscBool             max_area_ratio_set; /* given as an option (a kind may default to 0 otherwise: trianglefield) */
  PetscBool             project_at_stop; /* project the state the guard stopped at onto the constraints */
  PetscReal             fin_q;        /* q_max above which the guard reports fins rather than a smooth concentration */
  CSWillmoreFlowDegeneration degeneration;
  PetscInt              max_it, max_rej, proj_max_it, soc_max_it;
  PetscReal             max_seconds; /* wall-time budget (0: none); its stop is reported as DIVERGED_MAX_IT */
  PetscBool             step_control;
  CSWFStepModel         step_model;        /* -step_model: the predictive t or halving (willmore_step_model.c) */
  CSWFTrialRecord       trial;             /* the filter's measurements of the trials (willmore_step_model.c) */
  PetscReal             step_tacc, step_dacc; /* the step model: t and the violation added by the last accepted step (checkpointed) */
  PetscReal             proj_tmu;
  PetscReal             tmu_grow, tmu_max; /* own schedule of the dual step (0: t_mu follows t) */
  PetscReal             tmu_ratio_max;     /* following t: t_mu <= this * t (1e3 times the initial t_mu / t) */

  /* geometric step control and guards (gd, newton: docs/willmore_flow.md "Unconstrained descent") */
  PetscReal             max_step;      /* reject a trial step moving a vertex by more than this times the mean edge length */
  PetscBool             max_step_set, fold_guard, fold_guard_set;
  PetscReal             t_min;         /* t below this: stalled */
  PetscReal             energy_target; /* stop when E <= this */
  PetscBool             energy_target_set;
  Vec                   xgood;         /* the last state that passed the fold guard */
  PetscBool             good_set;      /* xgood holds a state (else the guard compares against the input) */
  PetscReal             V0;            /* enclosed volume of the input */
  void                 *data;          /* the kind's own data */

  /* loop state */
  PetscInt              it, rejections, kspits_total, kspits, nguard;
  PetscBool             resumed, started;
  PetscLogDouble        t0;
  PetscReal             E, el, conf, glob, A, V, area_ratio, spread, qmax; /* at x, from the last evaluation */
  PetscReal             viol_max; /* the largest max(conf, glob) of any evaluated state (before a projection at the stop) */
  PetscReal             viol_min; /* the smallest max(conf, glob) of any evaluated state (-1: none yet) */
  PetscInt              viol_min_it, viol_max_it; /* the iterations of viol_min, viol_max */
  PetscBool             path_set; /* willmore_path.c: the EL residual along the run (since the set-up or the resume) */
  PetscReal             el_first, el_min, E_el_min;
  PetscInt              it_el_min;

  /* the stopping rule (willmore_stop.c, docs/willmore_flow.md "Stopping") */
  CSFlowELNormType      el_norm;   /* -flow_el_norm: what -flow_rtol tests */
  PetscBool             el_norm_set;
  PetscReal             els;       /* el_residual_scaled at x: el sqrt(A) / max(|E|, 1e-3 |E0|) */
  PetscReal             E0;        /* |E| of the input (the floor of the scaling; < 0: not computed yet) */
  PetscInt              stat_window;          /* -flow_stationary_window K (0: off) */
  PetscReal             stat_rtol, stat_xtol; /* -flow_stationary_rtol (W), -flow_stationary_xtol (x, mean edge lengths) */
  PetscInt              stat_n, stat_it;      /* values in the window; the iteration recorded last (-1: none) */
  PetscReal             stat_W[CS_WF_STAT_MAX + 1], stat_d[CS_WF_STAT_MAX + 1]; /* W and the step's displacement, newest last */
  Vec                   stat_x;               /* the positions recorded last */
  PetscInt              drift_window;         /* -flow_drift_window (0: off; the W values of the window above) */
  PetscReal             drift_wtol, drift_rise; /* -flow_drift_wtol (largest relative W change per step), -flow_drift_rise */
  PetscInt              drift_rise_steps;     /* -flow_drift_rise_steps: the rise must have lasted this many accepted steps */
  PetscInt              drift_risen;          /* accepted steps in a row with el_residual_scaled >= drift_rise x els_min */
  PetscReal             drift_risen_els;      /* el_residual_scaled at the first of them */
  PetscReal             els_min;              /* the smallest el_residual_scaled of the run (< 0: none yet) */
  PetscInt              els_min_it;           /* and its iteration */
  CSFlowKeepBestType    keep_best;            /* -flow_keep_best */
  Vec                   best_x, best_mu;      /* the kept state: variables and multipliers */
  PetscReal            *best_nu;
  PetscInt              best_it;              /* -1: none */
  PetscReal             best_els, best_E, last_E, last_els;
  PetscInt              last_it;
  PetscBool             best_used;
  Vec                   last_x;               /* the last state's variables once the best replaced them (written beside -o) */
  CSWFPointsContinuation pcont;               /* -points_stages (willmore_points_continuation.c) */
};

/* A kind with its own variables (ops.setup_problem: trianglefield's triangle field), not vertex positions: the shared
   code asks this capability, never the kind's name. */
static inline PetscBool CSWFOwnVariables(CSWillmoreFlow F)
{
  return F->ops.setup_problem ? PETSC_TRUE : PETSC_FALSE;
}

/* the residual -flow_rtol tests (-flow_el_norm) */
static inline PetscReal CSWFStopResidual(CSWillmoreFlow F)
{
  return F->el_norm == CS_FLOW_EL_NORM_SCALED ? F->els : F->el;
}

/* willmore_evaluate.c */
PETSC_INTERN PetscErrorCode CSWFZeroFixed(CSWillmoreFlow F, Vec v);
PETSC_INTERN PetscErrorCode CSWFEvalConstraints(CSWillmoreFlow F, Vec x, Vec c, PetscReal cx[], PetscBool wantJ);
PETSC_INTERN PetscErrorCode CSWFViolation(CSWillmoreFlow F, Vec c, const PetscReal cx[], PetscReal *conf, PetscReal *glob);
PETSC_INTERN PetscErrorCode CSWFMerit(CSWillmoreFlow F, PetscReal E, Vec c, const PetscReal cx[], const PetscReal nun[], PetscReal *phi);
PETSC_INTERN PetscErrorCode CSWFResidual(CSWillmoreFlow F, PetscReal *el);
PETSC_INTERN PetscErrorCode CSWFResidualWith(CSWillmoreFlow F, Vec mu, const PetscReal nu[], PetscReal *el);
PETSC_INTERN PetscErrorCode CSWFGlobalWeights(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFQuadDiffMetric(CSWillmoreFlow F, Vec x, PetscInt *ng);
/* willmore_step.c */
PETSC_INTERN PetscErrorCode CSWFSetOperators(CSWillmoreFlow F, PetscReal t, PetscReal tmu);
PETSC_INTERN PetscErrorCode CSWFTrySolve(CSWillmoreFlow F, Vec rE, Vec rV, const PetscReal rX[], Vec zE, Vec zV, PetscReal zX[], PetscInt *its, PetscBool *ok);
PETSC_INTERN PetscErrorCode CSWFSolveCorrection(CSWillmoreFlow F, Vec zE, Vec zV, PetscInt *its, PetscBool *ok);
PETSC_INTERN PetscErrorCode CSWFRejected(CSWillmoreFlow F, const char what[]);
/* willmore_filter.c */
PETSC_INTERN PetscErrorCode CSWFFilterLagrangian(CSWillmoreFlow F, PetscBool *accept);
PETSC_INTERN PetscErrorCode CSWFFilterEnergy(CSWillmoreFlow F, PetscBool *accept);
PETSC_INTERN PetscErrorCode CSWFCheckFinite(CSWillmoreFlow F, PetscBool *accept);
/* willmore_step_model.c */
PETSC_INTERN PetscErrorCode CSWFStepModelRecord(CSWillmoreFlow F, PetscReal v0, PetscReal vt, PetscReal dL, PetscInt why);
PETSC_INTERN PetscReal      CSWFStepModelShrink(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFStepModelGrow(CSWillmoreFlow F, PetscReal *factor);
/* willmore_projection.c */
PETSC_INTERN PetscErrorCode CSWFProject(CSWillmoreFlow F, Vec x, PetscBool *ok, PetscInt *kspits);
PETSC_INTERN PetscErrorCode CSWFProjectTo(CSWillmoreFlow F, Vec x, PetscReal vtarget, PetscBool *ok, PetscInt *kspits);
PETSC_INTERN PetscErrorCode CSWFRestore(CSWillmoreFlow F, PetscInt *kspits);
PETSC_INTERN PetscErrorCode CSWFRestoreTo(CSWillmoreFlow F, PetscReal v, PetscReal vtarget, PetscInt *kspits);
/* willmore_guards.c */
PETSC_INTERN PetscErrorCode CSWFMeasureQuality(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFMeasureQualityOf(CSWillmoreFlow F, Vec x0, Vec x);
PETSC_INTERN PetscErrorCode CSWFTrackPath(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFCheckResolution(CSWillmoreFlow F, CSWillmoreFlowConvergedReason *reason);
PETSC_INTERN PetscErrorCode CSWFCheckFolds(CSWillmoreFlow F, PetscBool *folded);
PETSC_INTERN PetscErrorCode CSWFCheckStepGeometry(CSWillmoreFlow F, PetscBool *accept);
/* willmore_stop.c */
PETSC_INTERN PetscErrorCode CSWFStopOptions(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSWFScaledResidual(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFTrackStationarity(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFCheckStationary(CSWillmoreFlow F, CSWillmoreFlowConvergedReason *reason);
PETSC_INTERN PetscErrorCode CSWFCheckDrift(CSWillmoreFlow F, CSWillmoreFlowConvergedReason *reason);
PETSC_INTERN PetscErrorCode CSWFTrackBest(CSWillmoreFlow F);
PETSC_INTERN void           CSWFStationaryGetState(CSWillmoreFlow F, PetscReal ck[]);
PETSC_INTERN void           CSWFStationarySetState(CSWillmoreFlow F, const PetscReal ck[]);
PETSC_INTERN PetscErrorCode CSWFStopDestroy(CSWillmoreFlow F);
/* willmore_setup.c */
PETSC_INTERN PetscErrorCode CSWFSetUpBoundary(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFSetUpConstraints(CSWillmoreFlow F);
/* willmore_points_continuation.c */
#define CS_WF_POINTS_NREAL 3 /* checkpoint scalars of the point stages */
PETSC_INTERN PetscErrorCode CSWFPointsContinuationOptions(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSWFPointsContinuationCheck(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFPointsContinuationWrap(CSWillmoreFlow F, CSGlobalConstraint *g);
PETSC_INTERN PetscErrorCode CSWFPointsContinuationAdvance(CSWillmoreFlow F, PetscBool *moved);
PETSC_INTERN PetscErrorCode CSWFPointsContinuationReport(CSWillmoreFlow F);
PETSC_INTERN void           CSWFPointsContinuationGetState(CSWillmoreFlow F, PetscReal ck[]);
PETSC_INTERN PetscErrorCode CSWFPointsContinuationSetState(CSWillmoreFlow F, PetscInt it, const PetscReal ck[]);
/* willmore_constraints.c */
PETSC_INTERN PetscErrorCode CSWFAddConstraint(CSWillmoreFlow F, CSGlobalConstraint g);
PETSC_INTERN PetscErrorCode CSWFSetUpAddedConstraints(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFConstraintsDestroy(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFSetUpPrimalVectors(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFSetUpMultiplierVectors(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFSetUpVectors(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFSetUpScaling(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFCreateEnergy(CSWillmoreFlow F);
/* kinds */
PETSC_INTERN PetscErrorCode CSWFDestroyData(CSWillmoreFlow F); /* ops.destroy of a kind whose F->data holds no objects */
PETSC_INTERN PetscErrorCode CSWillmoreFlowCreate_CGD(CSWillmoreFlow);
PETSC_INTERN PetscErrorCode CSWillmoreFlowCreate_PGD(CSWillmoreFlow);
PETSC_INTERN PetscErrorCode CSWillmoreFlowCreate_GD(CSWillmoreFlow);
PETSC_INTERN PetscErrorCode CSWillmoreFlowCreate_Newton(CSWillmoreFlow);
PETSC_INTERN PetscErrorCode CSWillmoreFlowCreate_ALM(CSWillmoreFlow);
PETSC_INTERN PetscErrorCode CSWillmoreFlowCreate_Fairing(CSWillmoreFlow); /* the kind named by F->type */
PETSC_INTERN PetscErrorCode CSWillmoreFlowCreate_TriangleField(CSWillmoreFlow);
/* step sizes shared by the kinds (impls/pgd/pgd.c, impls/cgd/cgd.c) */
PETSC_INTERN PetscErrorCode CSWFGrowStep(CSWillmoreFlow F, PetscReal *r);
PETSC_INTERN PetscErrorCode CSWFGrowPrimal(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSWFShrinkPrimal(CSWillmoreFlow F);

#endif
