/* OBJ: v x y z [w|r g b], f a b c with a = i, i/t, i//n, i/t/n, 1-based or negative (relative). Every other
   line (vt, vn, o, g, s, usemtl, #...) is ignored. A first pass counts, so nothing is reallocated and a
   forward positive index can be checked against the true vertex count. */
#include "meshdata_reader.h"
#include <string.h>

static PetscBool ObjKeyword(const char *s, char key)
{
  s = CSReaderSkipBlank((char *)s);
  return (PetscBool)(s[0] == key && CSReaderIsBlank(s[1]));
}

PetscErrorCode CSMeshDataReadOBJ(Reader *r)
{
  Lines    L = {r->buf, r->buf + r->len, 0};
  PetscInt nvx = 0, nfx = 0, nlines = 0, nv = 0, nf = 0;
  char    *s, tok[40];

  PetscFunctionBeginUser;
  for (const char *p = r->buf, *end = r->buf + r->len; p < end;) {
    const char *e = (const char *)memchr(p, '\n', (size_t)(end - p));
    nlines++;
    if (ObjKeyword(p, 'v')) nvx++;
    else if (ObjKeyword(p, 'f')) nfx++;
    p = e ? e + 1 : end;
  }
  if (!nvx && !nfx) {
    CSReaderFail(r, "%s:%" PetscInt_FMT ": empty file (no vertices and no faces)", r->path, PetscMax(nlines, 1));
    PetscFunctionReturn(0);
  }
  if (!nfx) {
    CSReaderFail(r, "%s:%" PetscInt_FMT ": no faces (only %" PetscInt_FMT " vertices)", r->path, nlines, nvx);
    PetscFunctionReturn(0);
  }
  PetscCall(PetscMalloc1(3 * nvx, &r->x));
  PetscCall(PetscMalloc1(3 * nfx, &r->f));
  while ((s = CSReaderNextLine(&L)) && !r->msg[0]) {
    char *c = strchr(s, '#'); /* a trailing comment */
    if (c) *c = 0;
    if (ObjKeyword(s, 'v')) {
      s = CSReaderSkipBlank(s) + 1;
      CSReaderParseVertex(r, &s, L.line, &r->x[3 * nv]);
      nv++;
    } else if (ObjKeyword(s, 'f')) {
      long long idx[3];
      PetscInt  cnt = 0;
      s             = CSReaderSkipBlank(s) + 1;
      for (;;) {
        long long v;
        int       st = CSReaderParseInt(&s, &v, "/");
        if (st == 1) break;
        if (st == 2) {
          CSReaderLineFail(r, L.line, "garbage '%s' where a vertex index was expected", CSReaderTokenText(s, tok));
          break;
        }
        if (cnt < 3) idx[cnt] = v;
        cnt++;
        s = CSReaderSkipToken(s); /* the /vt/vn part */
      }
      if (r->msg[0]) break;
      if (cnt > 3) CSReaderLineFail(r, L.line, "polygon face with %" PetscInt_FMT " vertices (only triangles are supported)", cnt);
      else if (cnt < 3) CSReaderLineFail(r, L.line, "face with %" PetscInt_FMT " vertices (a triangle needs 3)", cnt);
      for (int k = 0; k < 3 && !r->msg[0]; k++) {
        if (idx[k] > 0 && idx[k] <= nvx) r->f[3 * nf + k] = (PetscInt)(idx[k] - 1);
        else if (idx[k] < 0 && idx[k] >= -(long long)nv) r->f[3 * nf + k] = (PetscInt)(nv + idx[k]);
        else if (idx[k] == 0) CSReaderLineFail(r, L.line, "vertex index 0 is invalid (OBJ indices start at 1)");
        else if (idx[k] > 0) CSReaderLineFail(r, L.line, "vertex index %lld out of range (the file has %" PetscInt_FMT " vertices)", idx[k], nvx);
        else CSReaderLineFail(r, L.line, "relative vertex index %lld out of range (%" PetscInt_FMT " vertices defined so far)", idx[k], nv);
      }
      nf++;
    }
  }
  r->nv = nvx;
  r->nf = nfx;
  PetscFunctionReturn(0);
}

/* %.17g: strtod gives back the same double, so OBJ round trips are exact */
PetscErrorCode CSMeshDataWriteOBJ(FILE *fp, const CSMeshData *md)
{
  PetscFunctionBeginUser;
  fprintf(fp, "# %s: %" PetscInt_FMT " vertices, %" PetscInt_FMT " faces (written by confsurf)\n", md->name, md->nv, md->nf);
  for (PetscInt i = 0; i < md->nv; i++) fprintf(fp, "v %.17g %.17g %.17g\n", (double)md->x[3 * i], (double)md->x[3 * i + 1], (double)md->x[3 * i + 2]);
  for (PetscInt i = 0; i < md->nf; i++) fprintf(fp, "f %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\n", md->f[3 * i] + 1, md->f[3 * i + 1] + 1, md->f[3 * i + 2] + 1);
  PetscFunctionReturn(0);
}
