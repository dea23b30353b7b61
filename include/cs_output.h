/* Run output shared by every task and method: the fixed output options, the facts every summary carries,
   history and checkpoints. Sits between the energies and the methods, so methods report without knowing the
   driver. */
#ifndef CS_OUTPUT_H
#define CS_OUTPUT_H
#include "cs_energy.h"
#include "cs_util.h"

/* The fixed output interface of every task (README.md): -o, -viewer_dir, -summary, -history_csv, -reference,
   and for iterative tasks -checkpoint, -checkpoint_every, -resume. */
typedef struct {
  char      out[PETSC_MAX_PATH_LEN], viewer_dir[PETSC_MAX_PATH_LEN], summary[PETSC_MAX_PATH_LEN], history[PETSC_MAX_PATH_LEN], reference[PETSC_MAX_PATH_LEN];
  PetscBool has_out, has_viewer, has_summary, has_history, has_reference;
  char      checkpoint[PETSC_MAX_PATH_LEN], resume[PETSC_MAX_PATH_LEN];
  PetscBool has_checkpoint, has_resume;
  PetscInt  checkpoint_every;
  PetscBool resumed;          /* CSOutputResume restored a state: CSOutputHistoryCreate continues the history */
  PetscBool checkpoint_used;  /* the task called CSOutputResume (it supports -checkpoint/-resume) */
  PetscLogDouble t0;
  CSJSON    json;
} CSOutput;

PETSC_EXTERN PetscErrorCode CSOutputFromOptions(MPI_Comm comm, CSOutput *o);
/* the same with the -o extensions a task writes (NULL-terminated, lower case) and the message for others */
PETSC_EXTERN PetscErrorCode CSOutputFromOptionsFormats(MPI_Comm comm, const char *const exts[], const char what[], CSOutput *o);
/* -<prefix>viewer_every of a method (title: the options group, help: the option's text), read on every run and
   not only with -viewer_dir so that the option is never "unused". At least 1 (the default), or with zero_final
   at least 0 (the default; 0: the final state only). */
PETSC_EXTERN PetscErrorCode CSOutputViewerEvery(MPI_Comm comm, const char prefix[], const char title[], const char help[], PetscBool zero_final, PetscInt *every);
/* The keys every task reports: counts, topology, area, volume, willmore, (q_mean, q_max against
   -reference or the given xref); CSOutputFinish then writes -o and -summary (adding seconds). */
PETSC_EXTERN PetscErrorCode CSOutputAddMeshFacts(CSOutput *o, CSMesh mesh, Vec x, Vec xref);
/* Keys quality_min_angle_deg, quality_obtuse_share, quality_nondelaunay_share (fractions), quality_edge_ratio,
   quality_face_edge_ratio_max (CSGeometryTriangleQuality) and their printed line (-task info). */
PETSC_EXTERN PetscErrorCode CSOutputAddTriangleQuality(CSOutput *o, CSMesh mesh, Vec x);
/* Key willmore_bs: the circle-angle energy of bobenko-schroeder2005 with -bs_boundary fixed and beta_eps 1e-6
   (reported by -task info; the BS flow reports its own energy under the same key). */
PETSC_EXTERN PetscErrorCode CSOutputAddWillmoreBS(CSOutput *o, CSMesh mesh, Vec x);
PETSC_EXTERN PetscErrorCode CSOutputFinish(CSOutput *o, CSMesh mesh, Vec x);
/* CSOutputFinish's parts for a task without a CSMesh (the curve flow): the keys seconds and ranks; -summary */
PETSC_EXTERN PetscErrorCode CSOutputAddRunFacts(CSOutput *o, MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSOutputWriteSummary(CSOutput *o, MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSOutputDestroy(CSOutput *o);

/* Checkpoints of iterative tasks (CSCheckpointWrite/Read: natural order, any number of ranks). The task's loop
   state is it, nreal scalars and the fields v (positions, per-edge and per-face fields, cs_mesh.h); x0 (the input
   positions, or another vector fixed by the input, or NULL) is fingerprinted so that a resume with another input
   is refused. CSOutputResume: with -resume, overwrites it, reals, the vectors of v and sets *resumed; else a no-op.
   CSOutputCheckpoint: with -checkpoint, writes when force or it is a multiple of -checkpoint_every.
   CSOutputHistoryCreate: -history_csv (NULL without it); after a resume, the rows of the interrupted run with
   first column below next are kept, so the file continues as one run. */
PETSC_EXTERN PetscErrorCode CSOutputResume(CSOutput *o, CSMesh mesh, Vec x0, PetscInt *it, PetscInt nreal, PetscReal reals[], const CSCheckpointFields *v, PetscBool *resumed);
PETSC_EXTERN PetscErrorCode CSOutputCheckpoint(CSOutput *o, CSMesh mesh, Vec x0, PetscInt it, PetscBool force, PetscInt nreal, const PetscReal reals[], const CSCheckpointFields *v);
PETSC_EXTERN PetscErrorCode CSOutputHistoryCreate(CSOutput *o, MPI_Comm comm, const char header[], PetscInt next, CSHistory *h);

/* The results of one run in memory for a caller of the library (src/api; src/output/output_capture.c), set on
   every rank before the task runs: the summary (JSON text), the final positions x (dim 3: a mesh, the input's
   vertex order, with the faces f as -o writes them; dim 2: a curve) and the history rows, all on rank 0. Filled by
   CSOutputWriteSummary, CSOutputFinish, the curve report and the histories (made even without -history_csv). */
typedef struct {
  char            *summary;
  PetscInt         dim, nv, nf;
  PetscReal       *x;
  PetscInt        *f;
  CSHistoryCapture history;
} CSOutputCapture;
PETSC_EXTERN PetscErrorCode CSOutputCaptureSet(CSOutputCapture *c); /* NULL: off */
PETSC_EXTERN PetscBool      CSOutputCaptureActive(void);
PETSC_EXTERN PetscErrorCode CSOutputCaptureReset(CSOutputCapture *c); /* frees what was kept */
PETSC_EXTERN PetscErrorCode CSOutputCaptureSummary(CSJSON js, MPI_Comm comm);
PETSC_EXTERN PetscErrorCode CSOutputCaptureMesh(CSMesh mesh, Vec x);
struct _p_CSCurve; /* CSCurve (cs_curve.h) */
PETSC_EXTERN PetscErrorCode CSOutputCaptureCurve(struct _p_CSCurve *curve, Vec x);

/* after a solver error ierr: the last accepted state x (iteration it) to -o and -summary; ierr's message in msg */
PETSC_EXTERN PetscErrorCode CSOutputSaveAfterError(CSOutput *o, CSMesh mesh, Vec x, PetscInt it, PetscErrorCode ierr, char msg[], size_t len);

#endif
