/* OBJ: v x y z [w|r g b], vt u v [w], f a b c with a = i, i/t, i//n, i/t/n, 1-based or negative (relative to the
   v or vt lines before the face, as the OBJ format defines). Every other line (vn, o, g, s, usemtl, #...) is
   ignored. Texture coordinates (issue 38) are per face corner: a face's t indices, so a seam vertex takes a
   different vt in each face around it; every face has them or none does. A first pass counts, so nothing is
   reallocated and a forward positive index can be checked against the true count. */
#include "meshdata_reader.h"
#include <string.h>

static PetscBool ObjKeyword(const char *s, const char *key)
{
  size_t n = strlen(key);
  s        = CSReaderSkipBlank((char *)s);
  return (PetscBool)(!strncmp(s, key, n) && CSReaderIsBlank(s[n]));
}

/* The counts of v, vt and f lines and of lines; a file without vertices or faces is refused here. */
static void ObjCount(Reader *r, PetscInt *nvx, PetscInt *ntx, PetscInt *nfx)
{
  PetscInt nlines = 0;
  *nvx = *ntx = *nfx = 0;
  for (const char *p = r->buf, *end = r->buf + r->len; p < end;) {
    const char *e = (const char *)memchr(p, '\n', (size_t)(end - p));
    nlines++;
    if (ObjKeyword(p, "v")) (*nvx)++;
    else if (ObjKeyword(p, "vt")) (*ntx)++;
    else if (ObjKeyword(p, "f")) (*nfx)++;
    p = e ? e + 1 : end;
  }
  if (!*nvx && !*nfx) CSReaderFail(r, "%s:%" PetscInt_FMT ": empty file (no vertices and no faces)", r->path, PetscMax(nlines, 1));
  else if (!*nfx) CSReaderFail(r, "%s:%" PetscInt_FMT ": no faces (only %" PetscInt_FMT " vertices)", r->path, nlines, *nvx);
}

/* vt u v [w]: u and v kept (w, the depth of a 3D texture, ignored) */
static void ObjTexture(Reader *r, char *s, PetscInt line, PetscReal uv[2])
{
  char tok[40];
  for (int d = 0; d < 2 && !r->msg[0]; d++) {
    PetscReal v;
    int       st = CSReaderParseReal(&s, &v);
    if (st == 1) CSReaderLineFail(r, line, "vt with %d texture coordinates (u v expected)", d);
    else if (st == 2) CSReaderLineFail(r, line, "garbage '%s' where a texture coordinate was expected", CSReaderTokenText(s, tok));
    else if (PetscIsInfOrNanReal(v)) CSReaderLineFail(r, line, "non-finite texture coordinate (%s)", PetscIsNanReal(v) ? "NaN" : "Inf");
    else uv[d] = v;
  }
}

/* One corner i, i/t, i//n or i/t/n: 0 read, 1 none left on the line, 2 bad (the message recorded). */
static int ObjCorner(Reader *r, PetscInt line, char **s, long long *v, long long *t, PetscBool *has_t)
{
  char tok[40];
  int  st = CSReaderParseInt(s, v, "/");
  *has_t  = PETSC_FALSE;
  if (st == 1) return 1;
  if (st == 2) {
    CSReaderLineFail(r, line, "garbage '%s' where a vertex index was expected", CSReaderTokenText(*s, tok));
    return 2;
  }
  if (**s == '/' && (*s)[1] != '/') { /* i/t or i/t/n */
    char *p = *s + 1;
    if (CSReaderIsTokenEnd(*p) || CSReaderParseInt(&p, t, "/")) {
      CSReaderLineFail(r, line, "garbage '%s' where a texture (vt) index was expected", CSReaderTokenText(*s, tok));
      return 2;
    }
    *has_t = PETSC_TRUE;
    *s     = p;
  }
  *s = CSReaderSkipToken(*s); /* the /n part */
  return 0;
}

/* idx 1-based, or negative: relative to the `sofar` v (vt) lines before the face; the file has `total` */
static void ObjIndex(Reader *r, PetscInt line, const char *what, const char *plural, long long idx, PetscInt sofar, PetscInt total, PetscInt *out)
{
  if (idx > 0 && idx <= total) *out = (PetscInt)(idx - 1);
  else if (idx < 0 && idx >= -(long long)sofar) *out = (PetscInt)(sofar + idx);
  else if (idx == 0) CSReaderLineFail(r, line, "%s index 0 is invalid (OBJ indices start at 1)", what);
  else if (idx > 0) CSReaderLineFail(r, line, "%s index %lld out of range (the file has %" PetscInt_FMT " %s)", what, idx, total, plural);
  else CSReaderLineFail(r, line, "relative %s index %lld out of range (%" PetscInt_FMT " %s defined so far)", what, idx, sofar, plural);
}

typedef struct {
  PetscInt nvx, ntx, nv, nt, nf; /* the file's v and vt counts, those read so far, faces read so far */
  PetscInt tex_line;             /* the line of the first face: its corners with vt indices or without decide */
  PetscBool tex;
} ObjState;

/* f a b c: 3 corners, all with a vt index or none, as the first face */
static PetscErrorCode ObjFace(Reader *r, char *s, PetscInt line, ObjState *o)
{
  long long v[3], t[3];
  PetscBool has[3] = {PETSC_FALSE, PETSC_FALSE, PETSC_FALSE};
  PetscInt  cnt    = 0;

  PetscFunctionBeginUser;
  for (;;) {
    long long vi, ti = 0;
    PetscBool hi;
    int       st = ObjCorner(r, line, &s, &vi, &ti, &hi);
    if (st) break;
    if (cnt < 3) {
      v[cnt]   = vi;
      t[cnt]   = ti;
      has[cnt] = hi;
    }
    cnt++;
  }
  if (r->msg[0]) PetscFunctionReturn(0);
  if (cnt > 3) CSReaderLineFail(r, line, "polygon face with %" PetscInt_FMT " vertices (only triangles are supported)", cnt);
  else if (cnt < 3) CSReaderLineFail(r, line, "face with %" PetscInt_FMT " vertices (a triangle needs 3)", cnt);
  else if (has[0] != has[1] || has[1] != has[2]) CSReaderLineFail(r, line, "face mixes v and v/vt corners (give every corner its vt index, or none)");
  else if (!o->nf) {
    o->tex      = has[0];
    o->tex_line = line;
    if (o->tex) PetscCall(PetscMalloc1(3 * r->nf, &r->fuv));
  } else if (has[0] != o->tex) CSReaderLineFail(r, line, "face %s vt indices (%s) but the first face, on line %" PetscInt_FMT ", %s: give every face its vt indices, or none", has[0] ? "with" : "without", has[0] ? "v/vt" : "v or v//vn", o->tex_line, o->tex ? "has them" : "has none");
  for (int k = 0; k < 3 && !r->msg[0]; k++) {
    ObjIndex(r, line, "vertex", "vertices", v[k], o->nv, o->nvx, &r->f[3 * o->nf + k]);
    if (o->tex && !r->msg[0]) ObjIndex(r, line, "texture (vt)", "vt lines", t[k], o->nt, o->ntx, &r->fuv[3 * o->nf + k]);
  }
  o->nf++;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataReadOBJ(Reader *r)
{
  Lines    L = {r->buf, r->buf + r->len, 0};
  ObjState o;
  char    *s;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(&o, sizeof(o)));
  ObjCount(r, &o.nvx, &o.ntx, &r->nf);
  if (r->msg[0]) PetscFunctionReturn(0);
  PetscCall(PetscMalloc1(3 * o.nvx, &r->x));
  PetscCall(PetscMalloc1(3 * r->nf, &r->f));
  PetscCall(PetscMalloc1(2 * o.ntx, &r->uv));
  while ((s = CSReaderNextLine(&L)) && !r->msg[0]) {
    char *c = strchr(s, '#'); /* a trailing comment */
    if (c) *c = 0;
    if (ObjKeyword(s, "v")) {
      s = CSReaderSkipBlank(s) + 1;
      CSReaderParseVertex(r, &s, L.line, &r->x[3 * o.nv++]);
    } else if (ObjKeyword(s, "vt")) {
      ObjTexture(r, CSReaderSkipBlank(s) + 2, L.line, &r->uv[2 * o.nt++]);
    } else if (ObjKeyword(s, "f")) PetscCall(ObjFace(r, CSReaderSkipBlank(s) + 1, L.line, &o));
  }
  r->nv  = o.nvx;
  r->nuv = o.ntx;
  PetscFunctionReturn(0);
}

/* %.17g: strtod gives back the same double, so OBJ round trips are exact; with texture coordinates the vt list and
   every face's v/vt indices as read (the seams kept) */
PetscErrorCode CSMeshDataWriteOBJ(FILE *fp, const CSMeshData *md)
{
  const PetscInt *f = md->f, *t = md->fuv;

  PetscFunctionBeginUser;
  fprintf(fp, "# %s: %" PetscInt_FMT " vertices, %" PetscInt_FMT " faces", md->name, md->nv, md->nf);
  if (t) fprintf(fp, ", %" PetscInt_FMT " texture coordinates", md->nuv);
  fprintf(fp, " (written by confsurf)\n");
  for (PetscInt i = 0; i < md->nv; i++) fprintf(fp, "v %.17g %.17g %.17g\n", (double)md->x[3 * i], (double)md->x[3 * i + 1], (double)md->x[3 * i + 2]);
  if (t)
    for (PetscInt i = 0; i < md->nuv; i++) fprintf(fp, "vt %.17g %.17g\n", (double)md->uv[2 * i], (double)md->uv[2 * i + 1]);
  for (PetscInt i = 0; i < md->nf; i++) {
    if (t) fprintf(fp, "f %" PetscInt_FMT "/%" PetscInt_FMT " %" PetscInt_FMT "/%" PetscInt_FMT " %" PetscInt_FMT "/%" PetscInt_FMT "\n", f[3 * i] + 1, t[3 * i] + 1, f[3 * i + 1] + 1, t[3 * i + 1] + 1, f[3 * i + 2] + 1, t[3 * i + 2] + 1);
    else fprintf(fp, "f %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\n", f[3 * i] + 1, f[3 * i + 1] + 1, f[3 * i + 2] + 1);
  }
  PetscFunctionReturn(0);
}
