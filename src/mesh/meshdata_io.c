/* Readers and writers of serial triangle meshes: OBJ, OFF, PLY (ascii and binary_little_endian).
   A file is read whole into memory and parsed in place. Parse errors are not raised where they are found:
   the first one is recorded as a message, everything allocated is freed, and only then the error is raised,
   so a bad file leaks nothing even when the caller catches the error (PetscReturnErrorHandler). */
#include "cs_meshdata.h"
#include "cs_util.h"
#include <ctype.h>
#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define CS_MSG_LEN 1024

typedef struct {
  const char *path;
  char       *buf; /* the whole file, NUL-terminated */
  size_t      len;
  PetscInt    nv, nf;
  PetscReal  *x;
  PetscInt   *f;
  char        msg[CS_MSG_LEN]; /* the first error, empty while the file is fine */
} Reader;

/* Records the first error only: later ones are consequences. */
static void ReaderFail(Reader *r, const char fmt[], ...)
{
  va_list ap;
  if (r->msg[0]) return;
  va_start(ap, fmt);
  vsnprintf(r->msg, sizeof(r->msg), fmt, ap);
  va_end(ap);
}

static PetscErrorCode ReaderFree(Reader *r)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(r->buf));
  PetscCall(PetscFree(r->x));
  PetscCall(PetscFree(r->f));
  PetscFunctionReturn(0);
}

/* Whole file into r->buf; on failure r->msg says why and *code which error class to raise. */
static PetscErrorCode ReaderLoad(Reader *r, PetscErrorCode *code)
{
  FILE *fp;
  long  size;
  PetscFunctionBeginUser;
  *code = 0;
  fp    = fopen(r->path, "rb");
  if (!fp) {
    ReaderFail(r, "%s: cannot open for reading (%s)", r->path, strerror(errno));
    *code = PETSC_ERR_FILE_OPEN;
    PetscFunctionReturn(0);
  }
  if (fseek(fp, 0, SEEK_END) || (size = ftell(fp)) < 0 || fseek(fp, 0, SEEK_SET)) {
    ReaderFail(r, "%s: cannot determine the file size (%s)", r->path, strerror(errno));
    *code = PETSC_ERR_FILE_READ;
    (void)fclose(fp);
    PetscFunctionReturn(0);
  }
  PetscCall(PetscMalloc1((size_t)size + 1, &r->buf));
  r->len = fread(r->buf, 1, (size_t)size, fp);
  if (r->len != (size_t)size || ferror(fp)) {
    ReaderFail(r, "%s: read error (%s)", r->path, strerror(errno));
    *code = PETSC_ERR_FILE_READ;
  }
  r->buf[r->len] = 0;
  (void)fclose(fp);
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------------
   Line and token helpers (text formats). Lines are cut in place; '\r' counts as blank (CRLF files). */
typedef struct {
  char    *p, *end;
  PetscInt line; /* 1-based number of the line last returned */
} Lines;

static char *NextLine(Lines *L)
{
  char *s = L->p, *e;
  if (s >= L->end) return NULL;
  e = (char *)memchr(s, '\n', (size_t)(L->end - s));
  if (e) {
    *e   = 0;
    L->p = e + 1;
  } else L->p = L->end;
  L->line++;
  return s;
}

static int IsBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
static int IsTokenEnd(char c)
{
  return c == 0 || isspace((unsigned char)c);
}
static char *SkipBlank(char *s)
{
  while (IsBlank(*s)) s++;
  return s;
}
static char *SkipToken(char *s)
{
  while (!IsTokenEnd(*s)) s++;
  return s;
}
/* length of the token at s (bounded so a binary blob does not flood a message) */
static int TokenLen(const char *s)
{
  int n = 0;
  while (!IsTokenEnd(s[n]) && n < 32) n++;
  return n;
}
/* the token at s for a message: bounded, unprintable bytes shown as '?' */
static const char *TokenText(const char *s, char out[40])
{
  int n = TokenLen(s);
  for (int i = 0; i < n; i++) out[i] = isprint((unsigned char)s[i]) ? s[i] : '?';
  out[n] = 0;
  return out;
}

/* Real number token: 0 ok, 1 no token left on the line, 2 garbage. */
static int ParseReal(char **s, PetscReal *v)
{
  char *e;
  *s = SkipBlank(*s);
  if (!**s) return 1;
  *v = (PetscReal)strtod(*s, &e);
  if (e == *s || !IsTokenEnd(*e)) return 2;
  *s = e;
  return 0;
}

/* Integer token, with the characters allowed right after the digits ('/' for OBJ's v/vt/vn). */
static int ParseInt(char **s, long long *v, const char *after)
{
  char *e;
  *s = SkipBlank(*s);
  if (!**s) return 1;
  errno = 0;
  *v    = strtoll(*s, &e, 10);
  if (e == *s || errno || (!IsTokenEnd(*e) && !(after && strchr(after, *e)))) return 2;
  *s = e;
  return 0;
}

/* "file:line: reason" */
static void LineFail(Reader *r, PetscInt line, const char fmt[], ...)
{
  char    reason[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(reason, sizeof(reason), fmt, ap);
  va_end(ap);
  ReaderFail(r, "%s:%" PetscInt_FMT ": %s", r->path, line, reason);
}

static PetscBool CoordBad(Reader *r, PetscReal v, PetscInt line)
{
  if (!PetscIsInfOrNanReal(v)) return PETSC_FALSE;
  LineFail(r, line, "non-finite coordinate (%s)", PetscIsNanReal(v) ? "NaN" : "Inf");
  return PETSC_TRUE;
}

static PetscBool BufferIsBlank(const Reader *r)
{
  for (size_t i = 0; i < r->len; i++)
    if (!isspace((unsigned char)r->buf[i])) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* ---------------------------------------------------------------------------------------------------------
   OBJ: v x y z [w|r g b], f a b c with a = i, i/t, i//n, i/t/n, 1-based or negative (relative). Every other
   line (vt, vn, o, g, s, usemtl, #...) is ignored. A first pass counts, so nothing is reallocated and a
   forward positive index can be checked against the true vertex count. */
static PetscBool ObjKeyword(const char *s, char key)
{
  s = SkipBlank((char *)s);
  return (PetscBool)(s[0] == key && IsBlank(s[1]));
}

static PetscErrorCode ReadOBJ(Reader *r)
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
    ReaderFail(r, "%s:%" PetscInt_FMT ": empty file (no vertices and no faces)", r->path, PetscMax(nlines, 1));
    PetscFunctionReturn(0);
  }
  if (!nfx) {
    ReaderFail(r, "%s:%" PetscInt_FMT ": no faces (only %" PetscInt_FMT " vertices)", r->path, nlines, nvx);
    PetscFunctionReturn(0);
  }
  PetscCall(PetscMalloc1(3 * nvx, &r->x));
  PetscCall(PetscMalloc1(3 * nfx, &r->f));
  while ((s = NextLine(&L)) && !r->msg[0]) {
    char *c = strchr(s, '#'); /* a trailing comment */
    if (c) *c = 0;
    if (ObjKeyword(s, 'v')) {
      s = SkipBlank(s) + 1;
      for (int d = 0; d < 3 && !r->msg[0]; d++) {
        PetscReal v;
        int       st = ParseReal(&s, &v);
        if (st == 1) LineFail(r, L.line, "vertex with %d coordinates (3 expected)", d);
        else if (st == 2) LineFail(r, L.line, "garbage '%s' where a coordinate was expected", TokenText(s, tok));
        else if (!CoordBad(r, v, L.line)) r->x[3 * nv + d] = v;
      }
      nv++;
    } else if (ObjKeyword(s, 'f')) {
      long long idx[3];
      PetscInt  cnt = 0;
      s             = SkipBlank(s) + 1;
      for (;;) {
        long long v;
        int       st = ParseInt(&s, &v, "/");
        if (st == 1) break;
        if (st == 2) {
          LineFail(r, L.line, "garbage '%s' where a vertex index was expected", TokenText(s, tok));
          break;
        }
        if (cnt < 3) idx[cnt] = v;
        cnt++;
        s = SkipToken(s); /* the /vt/vn part */
      }
      if (r->msg[0]) break;
      if (cnt > 3) LineFail(r, L.line, "polygon face with %" PetscInt_FMT " vertices (only triangles are supported)", cnt);
      else if (cnt < 3) LineFail(r, L.line, "face with %" PetscInt_FMT " vertices (a triangle needs 3)", cnt);
      for (int k = 0; k < 3 && !r->msg[0]; k++) {
        if (idx[k] > 0 && idx[k] <= nvx) r->f[3 * nf + k] = (PetscInt)(idx[k] - 1);
        else if (idx[k] < 0 && -idx[k] <= nv) r->f[3 * nf + k] = (PetscInt)(nv + idx[k]);
        else if (idx[k] == 0) LineFail(r, L.line, "vertex index 0 is invalid (OBJ indices start at 1)");
        else if (idx[k] > 0) LineFail(r, L.line, "vertex index %lld out of range (the file has %" PetscInt_FMT " vertices)", idx[k], nvx);
        else LineFail(r, L.line, "relative vertex index %lld out of range (%" PetscInt_FMT " vertices defined so far)", idx[k], nv);
      }
      nf++;
    }
  }
  r->nv = nvx;
  r->nf = nfx;
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------------
   OFF: header OFF (or COFF/NOFF/...: extra per-vertex values are ignored), then nv nf ne (possibly on the
   header line), nv vertex lines, nf face lines "3 a b c [colour]" with 0-based indices. '#' starts a comment. */
static char *NextDataLine(Lines *L)
{
  char *s;
  while ((s = NextLine(L))) {
    char *c = strchr(s, '#');
    if (c) *c = 0;
    s = SkipBlank(s);
    if (*s) return s;
  }
  return NULL;
}

static PetscErrorCode ReadOFF(Reader *r)
{
  Lines     L = {r->buf, r->buf + r->len, 0};
  char     *s, *t, tok[40];
  long long cnt[3] = {0, 0, 0};
  int       ncnt   = 0, tl, st = 0;

  PetscFunctionBeginUser;
  if (!(s = NextDataLine(&L))) {
    ReaderFail(r, "%s:%" PetscInt_FMT ": empty file (no OFF header)", r->path, PetscMax(L.line, 1));
    PetscFunctionReturn(0);
  }
  tl = TokenLen(s);
  for (t = s; t < s + tl - 3 && strchr("STCN", *t); t++) {}
  if (tl < 3 || t != s + tl - 3 || strncmp(t, "OFF", 3)) {
    ReaderFail(r, "%s:%" PetscInt_FMT ": not an OFF file (header '%s', expected OFF)", r->path, L.line, TokenText(s, tok));
    PetscFunctionReturn(0);
  }
  s = SkipToken(s);
  for (;;) {
    while (ncnt < 3 && !(st = ParseInt(&s, &cnt[ncnt], NULL))) ncnt++;
    if (ncnt < 3 && st == 2) {
      ReaderFail(r, "%s:%" PetscInt_FMT ": garbage '%s' where the vertex/face counts were expected", r->path, L.line, TokenText(s, tok));
      PetscFunctionReturn(0);
    }
    if (ncnt >= 2) break; /* the edge count is optional */
    if (!(s = NextDataLine(&L))) {
      ReaderFail(r, "%s:%" PetscInt_FMT ": truncated: no vertex and face counts after the OFF header", r->path, L.line);
      PetscFunctionReturn(0);
    }
  }
  if (cnt[0] < 0 || cnt[1] < 0 || cnt[0] > PETSC_MAX_INT / 3 || cnt[1] > PETSC_MAX_INT / 3) {
    ReaderFail(r, "%s:%" PetscInt_FMT ": invalid counts %lld vertices, %lld faces", r->path, L.line, cnt[0], cnt[1]);
    PetscFunctionReturn(0);
  }
  if (!cnt[1]) {
    ReaderFail(r, "%s:%" PetscInt_FMT ": no faces (the header says 0)", r->path, L.line);
    PetscFunctionReturn(0);
  }
  r->nv = (PetscInt)cnt[0];
  r->nf = (PetscInt)cnt[1];
  PetscCall(PetscMalloc1(3 * r->nv, &r->x));
  PetscCall(PetscMalloc1(3 * r->nf, &r->f));
  for (PetscInt i = 0; i < r->nv && !r->msg[0]; i++) {
    if (!(s = NextDataLine(&L))) {
      ReaderFail(r, "%s:%" PetscInt_FMT ": truncated: the header says %" PetscInt_FMT " vertices, the file ends after %" PetscInt_FMT, r->path, L.line, r->nv, i);
      break;
    }
    for (int d = 0; d < 3 && !r->msg[0]; d++) {
      PetscReal v;
      int       st = ParseReal(&s, &v);
      if (st == 1) LineFail(r, L.line, "vertex with %d coordinates (3 expected)", d);
      else if (st == 2) LineFail(r, L.line, "garbage '%s' where a coordinate was expected", TokenText(s, tok));
      else if (!CoordBad(r, v, L.line)) r->x[3 * i + d] = v;
    }
  }
  for (PetscInt i = 0; i < r->nf && !r->msg[0]; i++) {
    long long n, v;
    int       st;
    if (!(s = NextDataLine(&L))) {
      ReaderFail(r, "%s:%" PetscInt_FMT ": truncated: the header says %" PetscInt_FMT " faces, the file ends after %" PetscInt_FMT, r->path, L.line, r->nf, i);
      break;
    }
    if ((st = ParseInt(&s, &n, NULL))) {
      LineFail(r, L.line, "garbage '%s' where the face size was expected", TokenText(s, tok));
      break;
    }
    if (n != 3) {
      LineFail(r, L.line, "face with %lld vertices (only triangles are supported)", n);
      break;
    }
    for (int k = 0; k < 3 && !r->msg[0]; k++) {
      st = ParseInt(&s, &v, NULL);
      if (st == 1) LineFail(r, L.line, "face with %d of its 3 vertex indices", k);
      else if (st == 2) LineFail(r, L.line, "garbage '%s' where a vertex index was expected", TokenText(s, tok));
      else if (v < 0 || v >= r->nv) LineFail(r, L.line, "vertex index %lld out of range [0, %" PetscInt_FMT ")", v, r->nv);
      else r->f[3 * i + k] = (PetscInt)v;
    }
  }
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------------
   PLY: ascii or binary_little_endian. The header describes every element; the vertex element's x y z and the
   face element's vertex_indices (or vertex_index) list are kept, every other property and element is read
   and skipped according to its declared type. */
typedef enum {
  PLY_NONE,
  PLY_INT8,
  PLY_UINT8,
  PLY_INT16,
  PLY_UINT16,
  PLY_INT32,
  PLY_UINT32,
  PLY_FLOAT32,
  PLY_FLOAT64
} PlyType;

static const struct {
  const char *name;
  PlyType     type;
} PlyTypeNames[] = {
  {"char",    PLY_INT8   },
  {"int8",    PLY_INT8   },
  {"uchar",   PLY_UINT8  },
  {"uint8",   PLY_UINT8  },
  {"short",   PLY_INT16  },
  {"int16",   PLY_INT16  },
  {"ushort",  PLY_UINT16 },
  {"uint16",  PLY_UINT16 },
  {"int",     PLY_INT32  },
  {"int32",   PLY_INT32  },
  {"uint",    PLY_UINT32 },
  {"uint32",  PLY_UINT32 },
  {"float",   PLY_FLOAT32},
  {"float32", PLY_FLOAT32},
  {"double",  PLY_FLOAT64},
  {"float64", PLY_FLOAT64}
};
static const int PlyTypeSize[] = {0, 1, 1, 2, 2, 4, 4, 4, 8};

#define PLY_MAX_ELEMS 16
#define PLY_MAX_PROPS 64

typedef struct {
  char    name[64];
  PlyType type, count_type; /* count_type != PLY_NONE: a list */
  int     role;             /* 0,1,2 = x,y,z of the vertex element; 3 = face vertex list; -1 skipped */
} PlyProp;

typedef struct {
  char     name[64];
  PetscInt count, nprops;
  PlyProp  props[PLY_MAX_PROPS];
} PlyElem;

typedef struct {
  PetscInt  nelem;
  PlyElem   elem[PLY_MAX_ELEMS];
  PetscBool binary, has_format;
} PlyHeader;

/* Where the data is read from: binary bytes or ascii tokens, and the current element for messages. */
typedef struct {
  Reader              *r;
  PetscBool            binary;
  const unsigned char *p, *end; /* binary */
  Lines                L;       /* ascii: L.p is the cursor, L.line the current line */
  const char          *ename;
  PetscInt             k, count; /* current entry of the element and the number announced */
} PlySource;

static PlyType PlyTypeFromName(const char *s, int len)
{
  for (size_t i = 0; i < sizeof(PlyTypeNames) / sizeof(PlyTypeNames[0]); i++)
    if ((int)strlen(PlyTypeNames[i].name) == len && !strncmp(PlyTypeNames[i].name, s, (size_t)len)) return PlyTypeNames[i].type;
  return PLY_NONE;
}

static PetscBool PlyIsInteger(PlyType t)
{
  return (PetscBool)(t != PLY_NONE && t != PLY_FLOAT32 && t != PLY_FLOAT64);
}

/* "where" prefix of a data error: file:line for ascii, file: element k (name) for binary */
static void PlyWhere(const PlySource *src, char *where, size_t len)
{
  if (src->binary) snprintf(where, len, "%s: element %" PetscInt_FMT " (%s) :", src->r->path, src->k, src->ename);
  else snprintf(where, len, "%s:%" PetscInt_FMT ":", src->r->path, src->L.line);
}

static void PlyFail(PlySource *src, const char fmt[], ...)
{
  char    where[PETSC_MAX_PATH_LEN + 96], reason[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(reason, sizeof(reason), fmt, ap);
  va_end(ap);
  PlyWhere(src, where, sizeof(where));
  ReaderFail(src->r, "%s %s", where, reason);
}

static uint64_t LoadLE(const unsigned char *p, int n)
{
  uint64_t u = 0;
  for (int i = n - 1; i >= 0; i--) u = (u << 8) | p[i];
  return u;
}

/* One value of type t as a double and (integer types) as a long long. Returns 0, or 1 after recording an
   error (truncated data or a garbage token). */
static int PlyRead(PlySource *src, PlyType t, double *dv, long long *iv)
{
  if (src->binary) {
    int      n = PlyTypeSize[t];
    uint64_t u;
    if (src->end - src->p < n) {
      PlyFail(src, "truncated: the data ends before the %" PetscInt_FMT " %s elements the header announces", src->count, src->ename);
      return 1;
    }
    u = LoadLE(src->p, n);
    src->p += n;
    switch (t) {
    case PLY_INT8: *iv = (int8_t)u; break;
    case PLY_UINT8: *iv = (uint8_t)u; break;
    case PLY_INT16: *iv = (int16_t)u; break;
    case PLY_UINT16: *iv = (uint16_t)u; break;
    case PLY_INT32: *iv = (int32_t)u; break;
    case PLY_UINT32: *iv = (uint32_t)u; break;
    case PLY_FLOAT32: {
      uint32_t w = (uint32_t)u;
      float    fl;
      memcpy(&fl, &w, sizeof(fl));
      *dv = fl;
      return 0;
    }
    case PLY_FLOAT64: memcpy(dv, &u, sizeof(*dv)); return 0;
    default: break;
    }
    *dv = (double)*iv;
    return 0;
  } else {
    char *s = src->L.p, *e;
    /* skip blanks and newlines, counting lines */
    while (s < src->L.end && isspace((unsigned char)*s)) {
      if (*s == '\n') src->L.line++;
      s++;
    }
    if (s >= src->L.end || !*s) {
      src->L.p = s;
      PlyFail(src, "truncated: the data ends before the %" PetscInt_FMT " %s elements the header announces", src->count, src->ename);
      return 1;
    }
    errno = 0;
    if (PlyIsInteger(t)) {
      *iv = strtoll(s, &e, 10);
      *dv = (double)*iv;
    } else {
      *dv = strtod(s, &e);
      *iv = 0;
    }
    if (e == s || (PlyIsInteger(t) && errno == ERANGE) || !IsTokenEnd(*e)) {
      char tok[40];
      src->L.p = s;
      PlyFail(src, "garbage '%s' where a number was expected", TokenText(s, tok));
      return 1;
    }
    src->L.p = e;
    return 0;
  }
}

static PetscErrorCode PlyParseHeader(Reader *r, PlyHeader *h, Lines *L, char **data)
{
  char    *s;
  PlyElem *cur = NULL;

  PetscFunctionBeginUser;
  *data = NULL;
  s     = NextLine(L);
  if (!s || strncmp(SkipBlank(s), "ply", 3) || !IsTokenEnd(SkipBlank(s)[3])) {
    ReaderFail(r, "%s:1: %s", r->path, BufferIsBlank(r) ? "empty file" : "not a PLY file (the first line is not 'ply')");
    PetscFunctionReturn(0);
  }
  while ((s = NextLine(L))) {
    char *kw = SkipBlank(s), *a, *b, *c;
    int   kl = TokenLen(kw), al, bl, cl;
    char  where[PETSC_MAX_PATH_LEN + 32], tok[40];
    snprintf(where, sizeof(where), "%s:%" PetscInt_FMT ":", r->path, L->line);
    a  = SkipBlank(SkipToken(kw));
    al = TokenLen(a);
    b  = SkipBlank(SkipToken(a));
    bl = TokenLen(b);
    c  = SkipBlank(SkipToken(b));
    cl = TokenLen(c);
    if (!kl || (kl == 7 && !strncmp(kw, "comment", 7)) || (kl == 8 && !strncmp(kw, "obj_info", 8))) continue;
    if (kl == 10 && !strncmp(kw, "end_header", 10)) {
      *data = L->p;
      break;
    }
    if (kl == 6 && !strncmp(kw, "format", 6)) {
      h->has_format = PETSC_TRUE;
      if (al == 5 && !strncmp(a, "ascii", 5)) h->binary = PETSC_FALSE;
      else if (al == 20 && !strncmp(a, "binary_little_endian", 20)) h->binary = PETSC_TRUE;
      else {
        ReaderFail(r, "%s unsupported PLY format '%s' (only ascii and binary_little_endian are read)", where, TokenText(a, tok));
        PetscFunctionReturn(0);
      }
    } else if (kl == 7 && !strncmp(kw, "element", 7)) {
      long long n;
      char     *t = b;
      if (h->nelem == PLY_MAX_ELEMS) {
        ReaderFail(r, "%s more than %d elements", where, PLY_MAX_ELEMS);
        PetscFunctionReturn(0);
      }
      if (!al || ParseInt(&t, &n, NULL) || n < 0 || n > PETSC_MAX_INT / 3 || *SkipBlank(t)) {
        ReaderFail(r, "%s malformed element line (expected 'element NAME COUNT')", where);
        PetscFunctionReturn(0);
      }
      cur = &h->elem[h->nelem++];
      snprintf(cur->name, sizeof(cur->name), "%.*s", al, a);
      cur->count  = (PetscInt)n;
      cur->nprops = 0;
    } else if (kl == 8 && !strncmp(kw, "property", 8)) {
      PlyProp *p;
      if (!cur) {
        ReaderFail(r, "%s property before any element", where);
        PetscFunctionReturn(0);
      }
      if (cur->nprops == PLY_MAX_PROPS) {
        ReaderFail(r, "%s more than %d properties in element %s", where, PLY_MAX_PROPS, cur->name);
        PetscFunctionReturn(0);
      }
      p             = &cur->props[cur->nprops++];
      p->count_type = PLY_NONE;
      p->role       = -1;
      if (al == 4 && !strncmp(a, "list", 4)) {
        char *d  = SkipBlank(SkipToken(c));
        int   dl = TokenLen(d);
        p->count_type = PlyTypeFromName(b, bl);
        p->type       = PlyTypeFromName(c, cl);
        if (!PlyIsInteger(p->count_type) || p->type == PLY_NONE || !dl) {
          ReaderFail(r, "%s malformed list property (expected 'property list COUNTTYPE ITEMTYPE NAME' with an integer COUNTTYPE)", where);
          PetscFunctionReturn(0);
        }
        snprintf(p->name, sizeof(p->name), "%.*s", dl, d);
      } else {
        p->type = PlyTypeFromName(a, al);
        if (p->type == PLY_NONE || !bl) {
          ReaderFail(r, "%s malformed property (unknown type '%s')", where, TokenText(a, tok));
          PetscFunctionReturn(0);
        }
        snprintf(p->name, sizeof(p->name), "%.*s", bl, b);
      }
    } else {
      ReaderFail(r, "%s unknown PLY header line '%s'", where, TokenText(kw, tok));
      PetscFunctionReturn(0);
    }
  }
  if (!*data) ReaderFail(r, "%s:%" PetscInt_FMT ": truncated header (no end_header)", r->path, L->line);
  else if (!h->has_format) ReaderFail(r, "%s:%" PetscInt_FMT ": no format line in the header", r->path, L->line);
  PetscFunctionReturn(0);
}

/* Marks the properties kept (roles) and checks the header has what a triangle mesh needs. */
static void PlyAssignRoles(Reader *r, PlyHeader *h, PetscInt line, PlyElem **ev, PlyElem **ef)
{
  *ev = *ef = NULL;
  for (PetscInt e = 0; e < h->nelem; e++) {
    PlyElem *el = &h->elem[e];
    if (!*ev && !strcmp(el->name, "vertex")) {
      int found[3] = {0, 0, 0};
      *ev          = el;
      for (PetscInt q = 0; q < el->nprops; q++) {
        PlyProp *p = &el->props[q];
        for (int d = 0; d < 3; d++)
          if (p->count_type == PLY_NONE && !found[d] && p->name[0] == "xyz"[d] && !p->name[1]) {
            p->role  = d;
            found[d] = 1;
          }
      }
      if (!found[0] || !found[1] || !found[2]) ReaderFail(r, "%s:%" PetscInt_FMT ": the vertex element lacks a scalar x, y or z property", r->path, line);
    } else if (!*ef && !strcmp(el->name, "face")) {
      *ef = el;
      for (PetscInt q = 0; q < el->nprops; q++) {
        PlyProp *p = &el->props[q];
        if (p->count_type != PLY_NONE && (!strcmp(p->name, "vertex_indices") || !strcmp(p->name, "vertex_index"))) {
          if (!PlyIsInteger(p->type)) ReaderFail(r, "%s:%" PetscInt_FMT ": the face list %s has a non-integer item type", r->path, line, p->name);
          p->role = 3;
          break;
        }
      }
      if (!r->msg[0]) {
        PetscBool ok = PETSC_FALSE;
        for (PetscInt q = 0; q < el->nprops; q++) ok = (PetscBool)(ok || el->props[q].role == 3);
        if (!ok) ReaderFail(r, "%s:%" PetscInt_FMT ": the face element has no vertex_indices list", r->path, line);
      }
    }
  }
  if (!*ev) ReaderFail(r, "%s:%" PetscInt_FMT ": no vertex element", r->path, line);
  else if (!*ef) ReaderFail(r, "%s:%" PetscInt_FMT ": no face element", r->path, line);
  else if (!(*ef)->count) ReaderFail(r, "%s:%" PetscInt_FMT ": no faces (the header says 0)", r->path, line);
}

static PetscErrorCode ReadPLY(Reader *r)
{
  Lines     L = {r->buf, r->buf + r->len, 0};
  PlyHeader *h;
  PlyElem   *ev = NULL, *ef = NULL;
  PlySource  src;
  char      *data;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &h));
  PetscCall(PlyParseHeader(r, h, &L, &data));
  if (!r->msg[0]) PlyAssignRoles(r, h, L.line, &ev, &ef);
  if (r->msg[0]) {
    PetscCall(PetscFree(h));
    PetscFunctionReturn(0);
  }
  r->nv = ev->count;
  r->nf = ef->count;
  PetscCall(PetscMalloc1(3 * r->nv, &r->x));
  PetscCall(PetscMalloc1(3 * r->nf, &r->f));
  PetscCall(PetscMemzero(&src, sizeof(src)));
  src.r      = r;
  src.binary = h->binary;
  src.p      = (const unsigned char *)data;
  src.end    = (const unsigned char *)(r->buf + r->len);
  src.L      = L;
  src.L.line = L.line + 1; /* the data starts on the line after end_header */
  for (PetscInt e = 0; e < h->nelem && !r->msg[0]; e++) {
    PlyElem *el = &h->elem[e];
    src.ename   = el->name;
    src.count   = el->count;
    for (PetscInt k = 0; k < el->count && !r->msg[0]; k++) {
      src.k = k;
      for (PetscInt q = 0; q < el->nprops && !r->msg[0]; q++) {
        const PlyProp *p = &el->props[q];
        double         dv;
        long long      iv, n;
        if (p->count_type == PLY_NONE) {
          if (PlyRead(&src, p->type, &dv, &iv)) break;
          if (el == ev && p->role >= 0) {
            if (PetscIsInfOrNanReal((PetscReal)dv)) PlyFail(&src, "non-finite coordinate (%s)", PetscIsNanReal((PetscReal)dv) ? "NaN" : "Inf");
            else r->x[3 * k + p->role] = (PetscReal)dv;
          }
          continue;
        }
        if (PlyRead(&src, p->count_type, &dv, &n)) break;
        if (n < 0) {
          PlyFail(&src, "negative length of the list %s", p->name);
          break;
        }
        if (el == ef && p->role == 3 && n != 3) {
          PlyFail(&src, "face with %lld vertices (only triangles are supported)", n);
          break;
        }
        for (long long i = 0; i < n && !r->msg[0]; i++) {
          if (PlyRead(&src, p->type, &dv, &iv)) break;
          if (el == ef && p->role == 3) {
            if (iv < 0 || iv >= r->nv) PlyFail(&src, "vertex index %lld out of range [0, %" PetscInt_FMT ")", iv, r->nv);
            else r->f[3 * k + i] = (PetscInt)iv;
          }
        }
      }
    }
  }
  PetscCall(PetscFree(h));
  PetscFunctionReturn(0);
}

/* ---------------------------------------------------------------------------------------------------------
   Public: read, write, destroy, duplicate. */
PetscErrorCode CSMeshDataRead(const char path[], CSMeshData *md)
{
  Reader         r;
  char           ext[16];
  PetscErrorCode code;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(md, sizeof(*md)));
  PetscCall(PetscMemzero(&r, sizeof(r)));
  r.path = path;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCheck(!strcmp(ext, "obj") || !strcmp(ext, "off") || !strcmp(ext, "ply"), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: unknown mesh file extension '.%s' (expected .obj, .off or .ply)", path, ext);
  PetscCall(ReaderLoad(&r, &code));
  if (r.msg[0]) {
    PetscCall(ReaderFree(&r));
    SETERRQ(PETSC_COMM_SELF, code, "%s", r.msg);
  }
  if (!strcmp(ext, "obj")) PetscCall(ReadOBJ(&r));
  else if (!strcmp(ext, "off")) PetscCall(ReadOFF(&r));
  else PetscCall(ReadPLY(&r));
  if (r.msg[0]) {
    PetscCall(ReaderFree(&r));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s", r.msg);
  }
  PetscCall(PetscFree(r.buf));
  md->nv = r.nv;
  md->nf = r.nf;
  md->x  = r.x;
  md->f  = r.f;
  PetscCall(PetscStrncpy(md->name, path, sizeof(md->name)));
  PetscFunctionReturn(0);
}

static void StoreLE(unsigned char *p, uint64_t u, int n)
{
  for (int i = 0; i < n; i++, u >>= 8) p[i] = (unsigned char)(u & 0xff);
}

/* %.17g: strtod gives back the same double, so OBJ round trips are exact */
static PetscErrorCode WriteOBJ(FILE *fp, const CSMeshData *md)
{
  PetscFunctionBeginUser;
  fprintf(fp, "# %s: %" PetscInt_FMT " vertices, %" PetscInt_FMT " faces (written by confsurf)\n", md->name, md->nv, md->nf);
  for (PetscInt i = 0; i < md->nv; i++) fprintf(fp, "v %.17g %.17g %.17g\n", (double)md->x[3 * i], (double)md->x[3 * i + 1], (double)md->x[3 * i + 2]);
  for (PetscInt i = 0; i < md->nf; i++) fprintf(fp, "f %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\n", md->f[3 * i] + 1, md->f[3 * i + 1] + 1, md->f[3 * i + 2] + 1);
  PetscFunctionReturn(0);
}

static PetscErrorCode WriteOFF(FILE *fp, const CSMeshData *md)
{
  PetscFunctionBeginUser;
  fprintf(fp, "OFF\n# %s (written by confsurf)\n%" PetscInt_FMT " %" PetscInt_FMT " 0\n", md->name, md->nv, md->nf);
  for (PetscInt i = 0; i < md->nv; i++) fprintf(fp, "%.17g %.17g %.17g\n", (double)md->x[3 * i], (double)md->x[3 * i + 1], (double)md->x[3 * i + 2]);
  for (PetscInt i = 0; i < md->nf; i++) fprintf(fp, "3 %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "\n", md->f[3 * i], md->f[3 * i + 1], md->f[3 * i + 2]);
  PetscFunctionReturn(0);
}

/* binary_little_endian, double x y z, list uchar int vertex_indices: exact and compact */
static PetscErrorCode WritePLY(FILE *fp, const CSMeshData *md, PetscBool *ok)
{
  unsigned char *b, *p;
  size_t         n = (size_t)md->nv * 24 + (size_t)md->nf * 13;

  PetscFunctionBeginUser;
  fprintf(fp, "ply\nformat binary_little_endian 1.0\ncomment %s (written by confsurf)\n", md->name);
  fprintf(fp, "element vertex %" PetscInt_FMT "\nproperty double x\nproperty double y\nproperty double z\n", md->nv);
  fprintf(fp, "element face %" PetscInt_FMT "\nproperty list uchar int vertex_indices\nend_header\n", md->nf);
  PetscCall(PetscMalloc1(n, &b));
  p = b;
  for (PetscInt i = 0; i < 3 * md->nv; i++, p += 8) {
    double   d = (double)md->x[i];
    uint64_t u;
    memcpy(&u, &d, sizeof(u));
    StoreLE(p, u, 8);
  }
  for (PetscInt i = 0; i < md->nf; i++) {
    *p++ = 3;
    for (int k = 0; k < 3; k++, p += 4) StoreLE(p, (uint64_t)(uint32_t)(int32_t)md->f[3 * i + k], 4);
  }
  *ok = (PetscBool)(fwrite(b, 1, n, fp) == n);
  PetscCall(PetscFree(b));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataWrite(const char path[], const CSMeshData *md)
{
  char      ext[16];
  FILE     *fp;
  PetscBool ok = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCheck(!strcmp(ext, "obj") || !strcmp(ext, "off") || !strcmp(ext, "ply"), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: unknown mesh file extension '.%s' (write .obj, .off or .ply)", path, ext);
  fp = fopen(path, "wb");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s: cannot open for writing (%s)", path, strerror(errno));
  if (!strcmp(ext, "obj")) PetscCall(WriteOBJ(fp, md));
  else if (!strcmp(ext, "off")) PetscCall(WriteOFF(fp, md));
  else PetscCall(WritePLY(fp, md, &ok));
  ok = (PetscBool)(ok && !ferror(fp));
  ok = (PetscBool)(!fclose(fp) && ok);
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s: write error (%s)", path, strerror(errno));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataDestroy(CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(md->x));
  PetscCall(PetscFree(md->f));
  md->nv      = 0;
  md->nf      = 0;
  md->name[0] = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataDuplicate(const CSMeshData *in, CSMeshData *out)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(out, sizeof(*out)));
  out->nv = in->nv;
  out->nf = in->nf;
  PetscCall(PetscMalloc1(3 * in->nv, &out->x));
  PetscCall(PetscMalloc1(3 * in->nf, &out->f));
  PetscCall(PetscArraycpy(out->x, in->x, 3 * in->nv));
  PetscCall(PetscArraycpy(out->f, in->f, 3 * in->nf));
  PetscCall(PetscStrncpy(out->name, in->name, sizeof(out->name)));
  PetscFunctionReturn(0);
}
