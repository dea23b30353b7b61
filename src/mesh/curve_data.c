/* CSCurveData (include/cs_curve.h): validation, generators, writer. Serial, rank 0. */
#include "cs_curve.h"
#include "cs_util.h"
#include <string.h>

/* "FILE:LINE" of vertex i (the `l` element's line for an OBJ, where the order is set), or "NAME vertex i" */
static void Where(const CSCurveData *cd, PetscInt i, char buf[], size_t len)
{
  PetscInt line = cd->lline ? cd->lline : (cd->line ? cd->line[i] : 0);
  if (line) snprintf(buf, len, "%s:%" PetscInt_FMT, cd->name, line);
  else snprintf(buf, len, "%s", cd->name);
}

PetscErrorCode CSCurveDataValidate(const CSCurveData *cd, PetscBool allow_open)
{
  char      w[PETSC_MAX_PATH_LEN + 32];
  PetscReal lo[2] = {PETSC_MAX_REAL, PETSC_MAX_REAL}, hi[2] = {-PETSC_MAX_REAL, -PETSC_MAX_REAL}, diam;
  PetscInt  m = cd->m, ne;
  PetscFunctionBeginUser;
  Where(cd, 0, w, sizeof(w));
  PetscCheck(m >= 3, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: %" PetscInt_FMT " vertices (a curve needs at least 3)", w, m);
  PetscCheck(cd->closed || allow_open, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: open line (the last point does not repeat the first); a closed curve is required: repeat the first %s, or use -curve_close (add the closing edge) or -curve_open (flow an open curve)", w, cd->lline ? "index" : "point");
  for (PetscInt i = 0; i < m; i++) {
    for (int d = 0; d < 2; d++) {
      Where(cd, i, w, sizeof(w));
      PetscCheck(!PetscIsInfOrNanReal(cd->x[2 * i + d]), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: non-finite coordinate of vertex %" PetscInt_FMT, w, i + 1);
      lo[d] = PetscMin(lo[d], cd->x[2 * i + d]);
      hi[d] = PetscMax(hi[d], cd->x[2 * i + d]);
    }
  }
  diam = PetscSqrtReal(PetscSqr(hi[0] - lo[0]) + PetscSqr(hi[1] - lo[1]));
  ne   = cd->closed ? m : m - 1;
  for (PetscInt i = 0; i < ne; i++) {
    PetscInt  j  = (i + 1) % m;
    PetscReal dx = cd->x[2 * j] - cd->x[2 * i], dy = cd->x[2 * j + 1] - cd->x[2 * i + 1];
    Where(cd, j, w, sizeof(w));
    PetscCheck(dx != 0 || dy != 0, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: repeated consecutive points (vertices %" PetscInt_FMT " and %" PetscInt_FMT " of the polyline are equal)", w, i + 1, j + 1);
    PetscCheck(PetscSqrtReal(dx * dx + dy * dy) > 1e-12 * diam, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: zero-length edge between vertices %" PetscInt_FMT " and %" PetscInt_FMT " (length %.3g, curve size %.3g)", w, i + 1, j + 1, (double)PetscSqrtReal(dx * dx + dy * dy), (double)diam);
  }
  PetscFunctionReturn(0);
}

/* a small deterministic generator (the same curve on any number of ranks and machines) */
static PetscReal Uniform(unsigned long long *s)
{
  *s = *s * 6364136223846793005ULL + 1442695040888963407ULL;
  return (PetscReal)((*s >> 11) * (1.0 / 9007199254740992.0)) * 2 - 1;
}

/* radius r(t) and the point of the polar curve at parameter t */
static void Point(const char shape[], const CSCurveGenParams *p, PetscReal t, PetscReal noise, PetscReal xy[2])
{
  PetscReal r = p->r;
  if (!strcmp(shape, "ellipse")) {
    xy[0] = p->a * PetscCosReal(t);
    xy[1] = p->b * PetscSinReal(t);
    return;
  }
  if (!strcmp(shape, "star")) r = p->r * (1 + p->amplitude * PetscCosReal(p->petals * t));
  else if (!strcmp(shape, "noisy")) r = p->r * (1 + noise);
  else if (!strcmp(shape, "limacon")) r = p->b + p->a * PetscCosReal(t);
  xy[0] = r * PetscCosReal(t);
  xy[1] = r * PetscSinReal(t);
}

PetscErrorCode CSCurveDataGenerate(const char shape[], const CSCurveGenParams *p, CSCurveData *cd)
{
  const char        *known[] = {"circle", "ellipse", "star", "noisy", "limacon"};
  PetscBool          ok      = PETSC_FALSE;
  unsigned long long s       = 0x9E3779B97F4A7C15ULL ^ (unsigned long long)p->seed;
  PetscFunctionBeginUser;
  for (int k = 0; k < 5; k++) ok = (PetscBool)(ok || !strcmp(shape, known[k]));
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_ARG_UNKNOWN_TYPE, "-gen_curve %s: unknown curve (circle, ellipse, star, noisy, limacon)", shape);
  PetscCheck(p->n >= 3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_curve_n %" PetscInt_FMT ": at least 3 vertices", p->n);
  PetscCheck(p->r >= 1e-6 && p->r <= 1e6, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_curve_radius %g: must lie in [1e-6, 1e6] (a length)", (double)p->r);
  PetscCheck(p->a >= 1e-6 && p->a <= 1e6, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_curve_a %g: must lie in [1e-6, 1e6] (a length)", (double)p->a);
  PetscCheck(p->b >= 1e-6 && p->b <= 1e6, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_curve_b %g: must lie in [1e-6, 1e6] (a length)", (double)p->b);
  /* a run needs about 1 KB per curve vertex (measured 300 B at 2e5 vertices): the size named, not "out of memory" */
  PetscCall(CSCheckAllocation("-gen_curve_n: vertices of the generated curve, at about 1000 bytes each for a run", p->n, 1000));
  PetscCheck(strcmp(shape, "limacon") || p->a != p->b, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_curve limacon: -gen_curve_a must differ from -gen_curve_b (a cusp otherwise)");
  PetscCheck(strcmp(shape, "star") || PetscAbsReal(p->amplitude) < 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_curve_amplitude %g: must lie in (-1, 1)", (double)p->amplitude);
  PetscCheck(strcmp(shape, "noisy") || (p->noise >= 0 && p->noise < 1), PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_curve_noise %g: must lie in [0, 1)", (double)p->noise);
  PetscCall(PetscMemzero(cd, sizeof(*cd)));
  cd->m      = p->n;
  cd->closed = PETSC_TRUE;
  PetscCall(PetscMalloc2(2 * p->n, &cd->x, p->n, &cd->line));
  for (PetscInt i = 0; i < p->n; i++) {
    PetscReal t = 2 * PETSC_PI * (PetscReal)i / (PetscReal)p->n;
    Point(shape, p, t, p->noise * Uniform(&s), &cd->x[2 * i]);
    cd->line[i] = 0;
  }
  PetscCall(PetscSNPrintf(cd->name, sizeof(cd->name), "-gen_curve %s", shape));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveDataWrite(const char path[], PetscInt m, const PetscReal x[], const PetscReal kappa[], PetscBool closed)
{
  char   ext[16];
  CSFile f;
  FILE  *fp;
  PetscFunctionBeginUser;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCall(CSFileOpen(PETSC_COMM_SELF, PETSC_TRUE, "curve file", path, PETSC_FALSE, &f));
  fp = f.fp;
  if (!strcmp(ext, "obj")) {
    fprintf(fp, "# confsurf curve, %" PetscInt_FMT " vertices, %s\n", m, closed ? "closed" : "open");
    for (PetscInt i = 0; i < m; i++) fprintf(fp, "v %.17g %.17g 0\n", (double)x[2 * i], (double)x[2 * i + 1]);
    fprintf(fp, "l");
    for (PetscInt i = 0; i < m; i++) fprintf(fp, " %" PetscInt_FMT, i + 1);
    fprintf(fp, closed ? " 1\n" : "\n");
  } else {
    fprintf(fp, "# confsurf curve, %" PetscInt_FMT " vertices, %s; columns x y%s\n", m, closed ? "closed (first point repeated)" : "open", kappa ? " kappa" : "");
    for (PetscInt i = 0; i < m + (closed ? 1 : 0); i++) {
      PetscInt k = i % m;
      if (kappa) fprintf(fp, "%.17g %.17g %.17g\n", (double)x[2 * k], (double)x[2 * k + 1], (double)kappa[k]);
      else fprintf(fp, "%.17g %.17g\n", (double)x[2 * k], (double)x[2 * k + 1]);
    }
  }
  PetscCall(CSFileClose(PETSC_COMM_SELF, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveDataDestroy(CSCurveData *cd)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(cd->x, cd->line));
  PetscCall(PetscMemzero(cd, sizeof(*cd)));
  PetscFunctionReturn(0);
}
