/* CSCurveCreateFromOptions: -curve FILE or -gen_curve SHAPE, read/generated and validated on rank 0, errors
   raised on every rank (include/cs_curve.h). */
#include "cs_curve.h"
#include "cs_util.h"
#include "cs_log.h"

typedef struct {
  char             file[PETSC_MAX_PATH_LEN], shape[32];
  PetscBool        has_file, has_gen, open, close;
  PetscBool        arrays; /* the points of CSCurveDataSetArraySource (src/api) */
  CSCurveGenParams p;
} CurveOptions;

/* The points of a caller of the library (src/api: the Python interface's P), on rank 0, while set. */
static const CSCurveData *ArraySource = NULL;

PetscErrorCode CSCurveDataSetArraySource(const CSCurveData *cd)
{
  PetscFunctionBeginUser;
  ArraySource = cd;
  PetscFunctionReturn(0);
}

static PetscErrorCode CopyArrays(CSCurveData *cd)
{
  const CSCurveData *a = ArraySource;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(cd, sizeof(*cd)));
  cd->m      = a->m;
  cd->closed = a->closed;
  PetscCall(PetscStrncpy(cd->name, a->name, sizeof(cd->name)));
  PetscCall(PetscMalloc2(2 * a->m, &cd->x, a->m, &cd->line)); /* as the readers (CSCurveDataDestroy) */
  PetscCall(PetscArraycpy(cd->x, a->x, 2 * a->m));
  PetscCall(PetscArrayzero(cd->line, a->m)); /* line 0: no file line in the messages */
  PetscFunctionReturn(0);
}

static PetscErrorCode ReadOptions(MPI_Comm comm, CurveOptions *o)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(o, sizeof(*o)));
  o->p.n         = 200;
  o->p.r         = 1;
  o->p.a         = 2;
  o->p.b         = 1;
  o->p.amplitude = 0.3;
  o->p.petals    = 5;
  o->p.noise     = 0.05;
  o->p.seed      = 1;
  PetscOptionsBegin(comm, NULL, "confsurf curve input", NULL);
  PetscCall(CSOptionsString("-curve", "Closed planar polyline: .obj (v x y [z], one l element) or text (x y per line)", NULL, o->file, o->file, sizeof(o->file), &o->has_file));
  PetscCall(CSOptionsString("-gen_curve", "Generated curve: circle|ellipse|star|noisy|limacon", NULL, o->shape, o->shape, sizeof(o->shape), &o->has_gen));
  PetscCall(CSOptionsInt("-gen_curve_n", "Vertices of the generated curve", NULL, o->p.n, &o->p.n, NULL));
  PetscCall(CSOptionsReal("-gen_curve_radius", "Radius (circle, star, noisy)", NULL, o->p.r, &o->p.r, NULL));
  PetscCall(CSOptionsReal("-gen_curve_a", "Ellipse semi-axis a; limacon r = b + a cos t", NULL, o->p.a, &o->p.a, NULL));
  PetscCall(CSOptionsReal("-gen_curve_b", "Ellipse semi-axis b; limacon r = b + a cos t", NULL, o->p.b, &o->p.b, NULL));
  PetscCall(CSOptionsReal("-gen_curve_amplitude", "Star: r (1 + amplitude cos(petals t))", NULL, o->p.amplitude, &o->p.amplitude, NULL));
  PetscCall(CSOptionsInt("-gen_curve_petals", "Star: number of petals", NULL, o->p.petals, &o->p.petals, NULL));
  PetscCall(CSOptionsReal("-gen_curve_noise", "Noisy circle: relative radial noise amplitude", NULL, o->p.noise, &o->p.noise, NULL));
  PetscCall(CSOptionsInt("-gen_curve_seed", "Noisy circle: random seed", NULL, o->p.seed, &o->p.seed, NULL));
  PetscCall(PetscOptionsBool("-curve_open", "Treat the input as an open curve (no closure constraints)", NULL, o->open, &o->open, NULL));
  PetscCall(PetscOptionsBool("-curve_close", "Close an open input line with the edge last -> first", NULL, o->close, &o->close, NULL));
  PetscOptionsEnd();
  o->arrays = (PetscBool)(ArraySource != NULL); /* set on every rank */
  PetscCheck(!o->arrays || (!o->has_file && !o->has_gen), comm, PETSC_ERR_ARG_WRONG, "-%s: the curve is given as an array (P); -curve and -gen_curve are for the command line", o->has_file ? "curve" : "gen_curve");
  PetscCheck(o->arrays || o->has_file != o->has_gen, comm, PETSC_ERR_ARG_WRONG, "give exactly one of -curve FILE and -gen_curve circle|ellipse|star|noisy|limacon");
  PetscCheck(!(o->open && o->close), comm, PETSC_ERR_ARG_INCOMP, "-curve_open and -curve_close exclude each other");
  PetscFunctionReturn(0);
}

/* rank 0: read or generate, apply -curve_open/-curve_close, validate */
static PetscErrorCode Load(const CurveOptions *o, CSCurveData *cd)
{
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(PetscLogEventBegin(CS_EVENT_MeshRead, 0, 0, 0, 0));
  if (o->arrays) PetscCall(CopyArrays(cd));
  else if (o->has_file) PetscCall(CSCurveDataRead(o->file, cd));
  else PetscCall(CSCurveDataGenerate(o->shape, &o->p, cd));
  if (o->close) cd->closed = PETSC_TRUE;
  if (o->open) cd->closed = PETSC_FALSE;
  ierr = CSCurveDataValidate(cd, o->open);
  if (ierr) PetscCall(CSCurveDataDestroy(cd));
  PetscCall(PetscLogEventEnd(CS_EVENT_MeshRead, 0, 0, 0, 0));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveCreateFromOptions(MPI_Comm comm, CSCurve *curve)
{
  CurveOptions o;
  CSCurveData  cd;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&cd, sizeof(cd)));
  PetscCall(ReadOptions(comm, &o));
  CSRootCall(comm, Load(&o, &cd));
  PetscCall(CSCurveCreate(comm, &cd, curve));
  PetscCall(CSCurveDataDestroy(&cd));
  PetscFunctionReturn(0);
}
