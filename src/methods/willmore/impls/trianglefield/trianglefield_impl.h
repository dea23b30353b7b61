/* Private to trianglefield*.c: the data of the triangle-field kind (soliman2021 Algorithm 2). */
#ifndef CS_TRIANGLEFIELD_IMPL_H
#define CS_TRIANGLEFIELD_IMPL_H
#include "../cgd/cgd_impl.h"
#include "cs_operators_lens.h"
#include "cs_operators_spinor.h"
#include "cs_linalg.h"

typedef enum { CS_TF_INIT_DF, CS_TF_INIT_RANDOM, CS_TF_INIT_RANDOM_SPINOR, CS_TF_INIT_SMOOTH } CSTriangleFieldInit;
PETSC_INTERN const char *const CSTriangleFieldInits[];

typedef struct {
  CSWFDualStep ds;          /* first: CGD's dual step (-t_mu_final), found there by CGD's grow/shrink (cgd_impl.h) */
  CSTriangleFieldInit init; /* -flow_init df | random | random_spinor | smooth */
  PetscInt  modes;         /* -flow_init_modes: plane waves of -flow_init smooth */
  PetscInt  seed;          /* -flow_seed */
  PetscReal amp;           /* -flow_init_amplitude */
  DM        dmH1, dmH3;    /* halfedge scalars, halfedge vectors (the variables omega) */
  Mat       C;             /* C~ (Eq. 14), H x H */
  Mat       D, CD;         /* Dlambda at omega (H x 3H) and X_conf = C~ Dlambda */
  Mat       Klin;          /* [d1; S] (x) I_3: lens integrability (Eq. 31) and face closure, constant */
  Mat       X;             /* [X_conf; Klin] stacked per rank: the Jacobian of the constraint rows */
  Vec       lambda, c0;    /* log halfedge lengths, the target C~ lambda(omega_0) (dmH1) */
  Vec       star1, star0;  /* the triangle field's *1 (dmH1) and *0 (dmV1) at x */
  Vec       iqH;           /* I_Q on halfedges (dmH1) */
  Vec       clin;          /* Klin omega */
  PetscInt  nH, nL;        /* local rows: conformal (owned halfedges), linear (3 (owned edges + faces)) */
  Vec       xpos0, xpos;   /* positions of the input, and the reconstruction of the current omega (dmV3) */
  CSTriangleFieldReconstruction recon; /* the Poisson solver of xpos, kept across evaluations */
  PetscReal sc;            /* area / 4 pi of the input (size scaling of the metric and of t_mu) */
  PetscInt  nforms;        /* harmonic forms (2g): 3 nforms rows <<Y_i|omega>> */
  PetscReal wint;          /* -flow_integrability_weight: multiplier metric of the integrability rows */
  PetscInt  nD1;           /* local rows of d1 (the first 3 nD1 linear rows are the lens rows d1 omega) */
  PetscInt  istart;        /* -flow_integrability_start (trianglefield_schedule.c) */
  PetscReal wrelax;        /* -flow_integrability_relaxed_weight */
  PetscReal vmax0;         /* -flow_vmax, lifted while the rows are relaxed */
  PetscReal restore_near;  /* -flow_restore_near_ceiling: restore omega when v > this * vmax (trianglefield_restore.c) */
  PetscBool noconf;        /* -flow_conformal false: no C~ rows (nH = 0), X = Klin */
  CSSpinorSpace sp;        /* charts of the target metric, spin connection of the input (App. C) */
  Vec       psi, psit;     /* the face spinors of the accepted omega (signs followed along the flow), a work copy */
  PetscReal wspin;         /* -flow_spin_weight: the energy is W~ + wspin E_tau(psi(omega)) (App. C.3) */
  Vec       gspin;         /* grad_omega E_tau(psi(omega)) (dmH3), created at the first weighted gradient */
  /* -flow_variables spinor (trianglefield_spinor.c): x = (u, psi), omega = S_c(u, psi) (App. C.2) */
  PetscBool spinor;
  CSWillmoreFlow flow;     /* the flow (for the energy's evaluations) */
  PetscInt  nVo, xstart;   /* owned vertices (the u part of x), first global index of x on this rank */
  Vec       ug, pg, gpsi;  /* u (dmV1), psi (dmF4) of the last split x, grad E_tau (dmF4) */
  Vec       omega, omt, gom; /* S_c of the accepted x, of the last evaluated x, grad W~ (dmH3) */
  Vec       lamt;          /* log lengths of omega (dmH1): the measured class C~ lambda - c0 */
  Mat       J, P, KJ, Hom; /* dS_c, the sphere rows' Jacobian, Kd1 J, the triangle fields' metric I_H1 */
  PetscReal wgauge;        /* -flow_scale_gauge_weight: multiplier metric of the gauge row (relative to |row|^2) */
  PetscReal mshift;        /* -flow_spinor_metric_shift: + mshift a I on the pulled-back metric (0: none) */
  PetscReal ubar0;         /* the scale gauge: mean(u) of the start */
  Vec      *rowsOm;        /* the <<Y_i|.>> rows on triangle fields (F->rows holds J^T of them) */
  PetscReal wdecay, wspin_min;      /* continuation in wspin (trianglefield_continuation.c) */
  PetscReal stage_rtol, stage_ctol; /* a stage ends at el < stage_rtol, rows < stage_ctol */
  PetscInt  stage_maxit, stage_it0, nstages;
  DM        dmCkE, dmCkF;  /* checkpoints (trianglefield_state.c): the packed per-edge and per-face fields */
  Vec       ckE, ckF;
  Vec       start;         /* the start omega's reconstruction (dmV3): fingerprinted by checkpoints (another -flow_init is refused) */
  /* at x, from the last evaluation (trianglefield_eval.c): CSWillmoreFlowTriangleFieldGetInfo */
  PetscReal integ;         /* integrability violation: max of |d1 omega|, face closure, |<<Y_i|omega>>| (-1: none yet) */
  PetscReal espin;         /* E_tau(psi(omega)) (App. C.3), whatever its weight */
  PetscInt  pinch;         /* edges failing the spinor pinch test (App. C.1; -1: none yet) */
  PetscInt  pinchv;        /* pinch points: vertices with an odd number of those edges (sign-independent; -1: none yet) */
  PetscReal immersion_tol; /* -flow_immersion_tol: the largest integ at which -o writes the reconstruction */
  /* the step cap that learns from a sawtooth (trianglefield_stepcap.c) */
  PetscInt  cap_rises;     /* -flow_t_max_rises: consecutive rises at the cap that halve it (0: off) */
  PetscReal cap_wtol;      /* -flow_t_max_rises_wtol: W flat over a step (relative) */
  PetscInt  cap_n, cap_it, cap_lowered; /* the current count, the iteration of the record, the halvings so far */
  PetscReal cap_E, cap_el, cap_t;       /* the record: W, el_residual of state cap_it and the step accepted from it */
  PetscInt  cap_rejects;   /* -flow_t_max_rejects: consecutive iterations whose trial at the cap was rejected that halve it (0: off) */
  PetscInt  cap_nrej, cap_rej0; /* the current count of such iterations, the run's rejections at the last observation */
  PetscReal cap_tnext;     /* t after the last growth: the first trial of the next iteration */
} CSTriangleField;
PETSC_INTERN const char *const CSTriangleFieldVariables[];

PETSC_INTERN PetscErrorCode CSTFConstraints(CSWillmoreFlow F, Vec x, Vec c, PetscReal cx[], PetscBool wantJ);
PETSC_INTERN PetscErrorCode CSTFEvaluate(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSTFOperators(CSWillmoreFlow F);
/* trianglefield_appb.c: the App. B constraints (volume, points) in F->gc, rows after the 3 nforms period rows */
PETSC_INTERN PetscErrorCode CSTFAppBSetUp(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN PetscErrorCode CSTFAppBEvaluate(CSWillmoreFlow F, Vec x, PetscReal cx[], Vec rows[], PetscBool wantJ);
PETSC_INTERN PetscInt       CSTFAppBRows(CSWillmoreFlow F);
/* trianglefield_options.c: the kind's options (ops.setfromoptions), their checks (ops.setup) and ops.view */
PETSC_INTERN PetscErrorCode CSTFSetFromOptions(CSWillmoreFlow F, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSTFCheckOptions(CSWillmoreFlow F);
PETSC_INTERN PetscErrorCode CSTFView(CSWillmoreFlow F, PetscViewer viewer);
/* trianglefield_schedule.c: integrability enforced from an iteration on (Fig. 8) */
PETSC_INTERN PetscErrorCode CSTFScheduleSetFromOptions(CSWillmoreFlow F, CSTriangleField *d, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSTFScheduleCheck(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN PetscReal      CSTFIntegrabilityWeight(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN void           CSTFScheduleApply(CSWillmoreFlow F, CSTriangleField *d);
/* trianglefield_spinor.c: the spinor variables (App. C.2, C.3) */
PETSC_INTERN PetscErrorCode CSTFSpinorSetUp(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN PetscErrorCode CSTFSpinorStart(CSWillmoreFlow F, CSTriangleField *d, PetscReal (*hash)(PetscInt, PetscInt, PetscInt, PetscInt));
PETSC_INTERN PetscErrorCode CSTFSpinorOmega(CSTriangleField *d, Vec x, Vec omega);
PETSC_INTERN PetscErrorCode CSTFSpinorJacobian(CSWillmoreFlow F, CSTriangleField *d, Vec x);
PETSC_INTERN PetscErrorCode CSTFSpinorEnergy(CSWillmoreFlow F, CSTriangleField *d, Vec x, PetscReal *E, Vec g);
PETSC_INTERN PetscErrorCode CSTFSpinorConstraints(CSWillmoreFlow F, Vec x, Vec c, PetscReal cx[], PetscBool wantJ);
PETSC_INTERN PetscErrorCode CSTFSpinorMetric(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN PetscErrorCode CSTFSpinorNormalize(CSWillmoreFlow F, CSTriangleField *d, Vec x);
PETSC_INTERN PetscErrorCode CSTFSpinorDestroy(CSTriangleField *d);
/* trianglefield_init.c: -flow_init smooth, d(f + u) for a smooth random displacement u (Fig. 16) */
PETSC_INTERN PetscErrorCode CSTFInitSmooth(CSWillmoreFlow F, CSTriangleField *d, PetscReal (*hash)(PetscInt, PetscInt, PetscInt, PetscInt));
/* trianglefield_restore.c: Gauss-Newton restoration of an accepted omega onto the rows (issue 15) */
PETSC_INTERN PetscErrorCode CSTFRestore(CSWillmoreFlow F);
/* trianglefield_state.c: checkpoints (the hooks of willmore_state.c), at the end of the set-up */
PETSC_INTERN PetscErrorCode CSTFStateSetUp(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN PetscErrorCode CSTFStateDestroy(CSTriangleField *d);
/* trianglefield_continuation.c: w <- w * decay each time a stage converges, then 0 (App. C.3) */
PETSC_INTERN PetscErrorCode CSTFContinuationSetFromOptions(CSWillmoreFlow F, CSTriangleField *d, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSTFContinuationCheck(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN PetscErrorCode CSTFContinuationAdvance(CSWillmoreFlow F, CSTriangleField *d, PetscBool *next);
/* trianglefield_stepcap.c: -flow_t_max halved after a sawtooth at the cap (issue 39, Fig. 15); the kind's ops.grow */
PETSC_INTERN PetscErrorCode CSTFStepCapSetFromOptions(CSWillmoreFlow F, CSTriangleField *d, PetscOptionItems *PetscOptionsObject);
PETSC_INTERN PetscErrorCode CSTFStepCapCheck(CSWillmoreFlow F, CSTriangleField *d);
PETSC_INTERN PetscErrorCode CSTFGrow(CSWillmoreFlow F);
#endif
