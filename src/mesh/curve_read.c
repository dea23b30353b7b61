/* Reading polylines (include/cs_curve.h): OBJ (`v x y [z]`, one `l` element) and plain text (`x y [z]` per
   line). As for meshes (meshdata_reader.h), the first parse error is recorded, everything is freed, and only
   then the error is raised: a bad file leaks nothing. */
#include "cs_curve.h"
#include "meshdata_reader.h"
#include "cs_util.h"
#include <string.h>

typedef struct {
  Reader     r;         /* path, buffer, first error */
  PetscInt   nv, cap;   /* points read */
  PetscReal *p;         /* 3 per point (z = 0 when absent) */
  PetscInt  *pline;     /* line of each point */
  PetscInt  *idx, ni;   /* OBJ: the `l` indices (0-based) */
  PetscInt   nvlines;   /* OBJ: the number of `v` lines (room for the `l` indices) */
  PetscInt   lline;
  PetscInt   zline;     /* first line whose z differs from the first point's */
} CurveReader;

static PetscBool Keyword(const char *s, const char *key)
{
  size_t k = strlen(key);
  s        = CSReaderSkipBlank((char *)s);
  return (PetscBool)(!strncmp(s, key, k) && CSReaderIsTokenEnd(s[k]));
}

/* two or three coordinates: x y [z]; anything after them is an error */
static void ParsePoint(CurveReader *c, char *s, PetscInt line)
{
  PetscReal v[3] = {0, 0, 0};
  char      tok[40];
  int       d;
  for (d = 0; d < 4 && !c->r.msg[0]; d++) {
    PetscReal t;
    int       st = CSReaderParseReal(&s, &t);
    if (st == 1) break;
    if (st == 2) CSReaderLineFail(&c->r, line, "garbage '%s' where a coordinate was expected", CSReaderTokenText(s, tok));
    else if (d == 3) CSReaderLineFail(&c->r, line, "more than 3 coordinates (a point is x y [z])");
    else if (!CSReaderCoordBad(&c->r, t, line)) v[d] = t;
  }
  if (c->r.msg[0]) return;
  if (d < 2) {
    CSReaderLineFail(&c->r, line, "point with %d coordinate%s (x y [z] expected)", d, d == 1 ? "" : "s");
    return;
  }
  if (c->nv && v[2] != c->p[2] && !c->zline) c->zline = line;
  for (int k = 0; k < 3; k++) c->p[3 * c->nv + k] = v[k];
  c->pline[c->nv++] = line;
}

static PetscErrorCode Alloc(CurveReader *c, PetscInt cap)
{
  PetscFunctionBeginUser;
  c->cap = PetscMax(cap, 1);
  PetscCall(PetscMalloc2(3 * c->cap, &c->p, c->cap, &c->pline));
  PetscFunctionReturn(0);
}

/* the indices of one `l` element: 1-based, or negative (relative to the vertices read so far) */
static PetscErrorCode ParseLine(CurveReader *c, char *s, PetscInt line, PetscInt maxidx)
{
  char tok[40];
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(maxidx + 1, &c->idx));
  for (;;) {
    long long v;
    int       st = CSReaderParseInt(&s, &v, "/");
    if (st == 1) break;
    if (st == 2) {
      CSReaderLineFail(&c->r, line, "garbage '%s' where a vertex index was expected", CSReaderTokenText(s, tok));
      break;
    }
    s = CSReaderSkipToken(s);
    if (v < 0) v += c->nv + 1;
    if (v < 1 || v > c->nv) {
      CSReaderLineFail(&c->r, line, "vertex index %lld out of range (1..%" PetscInt_FMT ")", v, c->nv);
      break;
    }
    if (c->ni > maxidx) {
      CSReaderLineFail(&c->r, line, "the line element visits a vertex more than once");
      break;
    }
    c->idx[c->ni++] = (PetscInt)(v - 1);
  }
  PetscFunctionReturn(0);
}

/* every line of the file with its # comment cut off, handed to parse until the first error; *nlines (if
   not NULL): the number of lines read */
static PetscErrorCode ReadLines(CurveReader *c, PetscErrorCode (*parse)(CurveReader *, char *, PetscInt), PetscInt *nlines)
{
  Lines L = {c->r.buf, c->r.buf + c->r.len, 0};
  char *s;
  PetscFunctionBeginUser;
  while ((s = CSReaderNextLine(&L)) && !c->r.msg[0]) {
    char *h = strchr(s, '#');
    if (h) *h = 0;
    PetscCall(parse(c, s, L.line));
  }
  if (nlines) *nlines = L.line;
  PetscFunctionReturn(0);
}

/* an OBJ line: a `v` point or the one `l` element; a face is an error, any other line is ignored */
static PetscErrorCode ParseOBJLine(CurveReader *c, char *s, PetscInt line)
{
  PetscFunctionBeginUser;
  if (Keyword(s, "v")) ParsePoint(c, CSReaderSkipBlank(s) + 1, line);
  else if (Keyword(s, "f")) CSReaderLineFail(&c->r, line, "a face in a curve file (only v and one l element)");
  else if (Keyword(s, "l")) {
    if (c->lline) CSReaderLineFail(&c->r, line, "a second l element (the first is on line %" PetscInt_FMT "; one closed polyline per file)", c->lline);
    else {
      c->lline = line;
      PetscCall(ParseLine(c, CSReaderSkipBlank(s) + 1, line, c->nvlines));
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ReadOBJ(CurveReader *c)
{
  PetscInt nlines;
  PetscFunctionBeginUser;
  for (const char *p = c->r.buf, *end = c->r.buf + c->r.len; p < end;) {
    const char *e = (const char *)memchr(p, '\n', (size_t)(end - p));
    if (Keyword(p, "v")) c->nvlines++;
    p = e ? e + 1 : end;
  }
  PetscCall(Alloc(c, c->nvlines));
  PetscCall(ReadLines(c, ParseOBJLine, &nlines));
  if (!c->r.msg[0] && !c->lline) CSReaderFail(&c->r, "%s:%" PetscInt_FMT ": no l element (the polyline `l 1 2 ... n 1`)", c->r.path, PetscMax(nlines, 1));
  PetscFunctionReturn(0);
}

/* a text line: a point, or nothing */
static PetscErrorCode ParseTextLine(CurveReader *c, char *s, PetscInt line)
{
  PetscFunctionBeginUser;
  if (*CSReaderSkipBlank(s)) ParsePoint(c, s, line);
  PetscFunctionReturn(0);
}

static PetscErrorCode ReadText(CurveReader *c)
{
  PetscInt nl = 1;
  PetscFunctionBeginUser;
  for (size_t i = 0; i < c->r.len; i++) nl += c->r.buf[i] == '\n';
  PetscCall(Alloc(c, nl));
  PetscCall(ReadLines(c, ParseTextLine, NULL));
  PetscFunctionReturn(0);
}

/* cd from the parsed points: OBJ in the order of the `l` element, text in file order; a repeated first
   point closes the curve. */
static PetscErrorCode Assemble(CurveReader *c, PetscBool obj, CSCurveData *cd)
{
  PetscInt m = obj ? c->ni : c->nv;
  PetscFunctionBeginUser;
  if (m >= 2 && (obj ? c->idx[m - 1] == c->idx[0] : (c->p[3 * (m - 1)] == c->p[0] && c->p[3 * (m - 1) + 1] == c->p[1]))) {
    cd->closed = PETSC_TRUE;
    m--;
  }
  cd->m     = m;
  cd->lline = c->lline;
  PetscCall(PetscMalloc2(2 * PetscMax(m, 1), &cd->x, PetscMax(m, 1), &cd->line));
  for (PetscInt i = 0; i < m; i++) {
    PetscInt k  = obj ? c->idx[i] : i;
    cd->x[2 * i]     = c->p[3 * k];
    cd->x[2 * i + 1] = c->p[3 * k + 1];
    cd->line[i]      = c->pline[k];
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode ReaderFree(CurveReader *c)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree2(c->p, c->pline));
  PetscCall(PetscFree(c->idx));
  PetscCall(PetscFree(c->r.buf));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCurveDataRead(const char path[], CSCurveData *cd)
{
  CurveReader    c;
  char           ext[16];
  PetscBool      obj;
  char           name[PETSC_MAX_PATH_LEN];
  PetscErrorCode code = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(cd, sizeof(*cd)));
  PetscCall(PetscMemzero(&c, sizeof(c)));
  PetscCall(CSPathSanitize(path, name, sizeof(name)));
  c.r.path = name;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  obj = (PetscBool)!strcmp(ext, "obj");
  PetscCall(CSFileLoad("curve", path, &c.r.buf, &c.r.len));
  PetscCall(obj ? ReadOBJ(&c) : ReadText(&c));
  if (!c.r.msg[0] && c.zline) CSReaderLineFail(&c.r, c.zline, "z coordinate differs from the first point's (the curve must be planar, z constant)");
  if (!c.r.msg[0] && !c.nv) CSReaderFail(&c.r, "%s: empty file (no points)", name);
  if (c.r.msg[0]) {
    PetscCall(ReaderFree(&c));
    SETERRQ(PETSC_COMM_SELF, code ? code : PETSC_ERR_FILE_UNEXPECTED, "%s", c.r.msg);
  }
  PetscCall(Assemble(&c, obj, cd));
  PetscCall(ReaderFree(&c));
  PetscCall(PetscStrncpy(cd->name, name, sizeof(cd->name)));
  PetscFunctionReturn(0);
}
