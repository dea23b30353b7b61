/* OFF: header OFF (or COFF/NOFF/...: extra per-vertex values are ignored), then nv nf ne (possibly on the
   header line), nv vertex lines, nf face lines "3 a b c [colour]" with 0-based indices. '#' starts a comment. */
#include "meshdata_reader.h"
#include <string.h>

static char *NextDataLine(Lines *L)
{
  char *s;
  while ((s = CSReaderNextLine(L))) {
    char *c = strchr(s, '#');
    if (c) *c = 0;
    s = CSReaderSkipBlank(s);
    if (*s) return s;
  }
  return NULL;
}

PetscErrorCode CSMeshDataReadOFF(Reader *r)
{
  Lines     L = {r->buf, r->buf + r->len, 0};
  char     *s, *t, tok[40];
  long long cnt[3] = {0, 0, 0};
  int       ncnt   = 0, tl, st = 0;

  PetscFunctionBeginUser;
  if (!(s = NextDataLine(&L))) {
    CSReaderFail(r, "%s:%" PetscInt_FMT ": empty file (no OFF header)", r->path, PetscMax(L.line, 1));
    PetscFunctionReturn(0);
  }
  tl = CSReaderTokenLen(s);
  for (t = s; t < s + tl - 3 && strchr("STCN", *t); t++) {}
  if (tl < 3 || t != s + tl - 3 || strncmp(t, "OFF", 3)) {
    CSReaderFail(r, "%s:%" PetscInt_FMT ": not an OFF file (header '%s', expected OFF)", r->path, L.line, CSReaderTokenText(s, tok));
    PetscFunctionReturn(0);
  }
  s = CSReaderSkipToken(s);
  for (;;) {
    while (ncnt < 3 && !(st = CSReaderParseInt(&s, &cnt[ncnt], NULL))) ncnt++;
    if (ncnt < 3 && st == 2) {
      CSReaderFail(r, "%s:%" PetscInt_FMT ": garbage '%s' where the vertex/face counts were expected", r->path, L.line, CSReaderTokenText(s, tok));
      PetscFunctionReturn(0);
    }
    if (ncnt >= 2) break; /* the edge count is optional */
    if (!(s = NextDataLine(&L))) {
      CSReaderFail(r, "%s:%" PetscInt_FMT ": truncated: no vertex and face counts after the OFF header", r->path, L.line);
      PetscFunctionReturn(0);
    }
  }
  if (cnt[0] < 0 || cnt[1] < 0 || cnt[0] > PETSC_MAX_INT / 3 || cnt[1] > PETSC_MAX_INT / 3) {
    CSReaderFail(r, "%s:%" PetscInt_FMT ": invalid counts %lld vertices, %lld faces", r->path, L.line, cnt[0], cnt[1]);
    PetscFunctionReturn(0);
  }
  if (!cnt[1]) {
    CSReaderFail(r, "%s:%" PetscInt_FMT ": no faces (the header says 0)", r->path, L.line);
    PetscFunctionReturn(0);
  }
  if (6.0 * (double)cnt[0] + 8.0 * (double)cnt[1] - 1 > (double)(L.end - L.p)) { /* "x y z\n", "3 a b c\n" at least */
    CSReaderFail(r, "%s:%" PetscInt_FMT ": truncated: the header claims %lld vertices and %lld faces, the %zu bytes after it cannot hold them", r->path, L.line, cnt[0], cnt[1], (size_t)(L.end - L.p));
    PetscFunctionReturn(0);
  }
  r->nv = (PetscInt)cnt[0];
  r->nf = (PetscInt)cnt[1];
  PetscCall(PetscMalloc1(3 * r->nv, &r->x));
  PetscCall(PetscMalloc1(3 * r->nf, &r->f));
  for (PetscInt i = 0; i < r->nv && !r->msg[0]; i++) {
    if (!(s = NextDataLine(&L))) {
      CSReaderFail(r, "%s:%" PetscInt_FMT ": truncated: the header says %" PetscInt_FMT " vertices, the file ends after %" PetscInt_FMT, r->path, L.line, r->nv, i);
      break;
    }
    CSReaderParseVertex(r, &s, L.line, &r->x[3 * i]);
  }
  for (PetscInt i = 0; i < r->nf && !r->msg[0]; i++) {
    long long n, v;
    int       st;
    if (!(s = NextDataLine(&L))) {
      CSReaderFail(r, "%s:%" PetscInt_FMT ": truncated: the header says %" PetscInt_FMT " faces, the file ends after %" PetscInt_FMT, r->path, L.line, r->nf, i);
      break;
    }
    if ((st = CSReaderParseInt(&s, &n, NULL))) {
      CSReaderLineFail(r, L.line, "garbage '%s' where the face size was expected", CSReaderTokenText(s, tok));
      break;
    }
    if (n != 3) {
      CSReaderLineFail(r, L.line, "face with %lld vertices (only triangles are supported)", n);
      break;
    }
    for (int k = 0; k < 3 && !r->msg[0]; k++) {
      st = CSReaderParseInt(&s, &v, NULL);
      if (st == 1) CSReaderLineFail(r, L.line, "face with %d of its 3 vertex indices", k);
      else if (st == 2) CSReaderLineFail(r, L.line, "garbage '%s' where a vertex index was expected", CSReaderTokenText(s, tok));
      else if (v < 0 || v >= r->nv) CSReaderLineFail(r, L.line, "vertex index %lld out of range [0, %" PetscInt_FMT ")", v, r->nv);
      else r->f[3 * i + k] = (PetscInt)v;
    }
  }
  PetscFunctionReturn(0);
}

/* OFF has no texture coordinates: a textured mesh is written without them, with a warning (not refused: -o_input
   of a textured mesh to .off is a plain geometry export) */
PetscErrorCode CSMeshDataWriteOFF(FILE *fp, const CSMeshData *md)
{
  PetscFunctionBeginUser;
  if (md->fuv) PetscCall(PetscPrintf(PETSC_COMM_SELF, "Warning: %s: OFF has no texture coordinates: its %" PetscInt_FMT " UVs are not written (write .obj or .ply to keep them)\n", md->name, md->nuv));
  fprintf(fp, "OFF\n# %s (written by confsurf)\n%" PetscInt_FMT " %" PetscInt_FMT " 0\n", md->name, md->nv, md->nf);
  for (PetscInt i = 0; i < md->nv; i++) fprintf(fp, "%.17g %.17g %.17g\n", (double)md->x[3 * i], (double)md->x[3 * i + 1], (double)md->x[3 * i + 2]);
  for (PetscInt i = 0; i < md->nf; i++) fprintf(fp, "3 %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\n", md->f[3 * i], md->f[3 * i + 1], md->f[3 * i + 2]);
  PetscFunctionReturn(0);
}
