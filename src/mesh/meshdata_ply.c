/* PLY: ascii or binary_little_endian. The header describes every element; the vertex element's x y z and the
   face element's vertex_indices (or vertex_index) list are kept, every other property and element is read
   and skipped according to its declared type. Texture coordinates (issue 38): per vertex, the first pair of
   u v, s t or texture_u texture_v (then fuv = f); per face corner, the face list texcoord of 6 values u0 v0 u1 v1
   u2 v2 (then uv has 3 nf pairs and fuv[h] = h), which wins when a file has both. */
#include "meshdata_reader.h"
#include <errno.h>
#include <stdarg.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

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

enum {
  PLY_ROLE_X = 0, /* 0, 1, 2: x, y, z of the vertex element */
  PLY_ROLE_FACE = 3, /* the face's vertex list */
  PLY_ROLE_U = 4, /* 4, 5: u, v of the vertex element */
  PLY_ROLE_TEXCOORD = 6 /* the face's list of 6 texture coordinates */
};

#define PLY_MAX_ELEMS 16
#define PLY_MAX_PROPS 64

typedef struct {
  char    name[64];
  PlyType type, count_type; /* count_type != PLY_NONE: a list */
  int     role;             /* PLY_ROLE_*: what the property is kept as; -1 skipped */
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
  CSReaderFail(src->r, "%s %s", where, reason);
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
    if (e == s || (PlyIsInteger(t) && errno == ERANGE) || !CSReaderIsTokenEnd(*e)) {
      char tok[40];
      src->L.p = s;
      PlyFail(src, "garbage '%s' where a number was expected", CSReaderTokenText(s, tok));
      return 1;
    }
    src->L.p = e;
    return 0;
  }
}

static PetscBool BufferIsBlank(const Reader *r)
{
  for (size_t i = 0; i < r->len; i++)
    if (!isspace((unsigned char)r->buf[i])) return PETSC_FALSE;
  return PETSC_TRUE;
}

static PetscErrorCode PlyParseHeader(Reader *r, PlyHeader *h, Lines *L, char **data)
{
  char    *s;
  PlyElem *cur = NULL;

  PetscFunctionBeginUser;
  *data = NULL;
  s     = CSReaderNextLine(L);
  if (!s || strncmp(CSReaderSkipBlank(s), "ply", 3) || !CSReaderIsTokenEnd(CSReaderSkipBlank(s)[3])) {
    CSReaderFail(r, "%s:1: %s", r->path, BufferIsBlank(r) ? "empty file" : "not a PLY file (the first line is not 'ply')");
    PetscFunctionReturn(0);
  }
  while ((s = CSReaderNextLine(L))) {
    char *kw = CSReaderSkipBlank(s), *a, *b, *c;
    int   kl = CSReaderTokenLen(kw), al, bl, cl;
    char  where[PETSC_MAX_PATH_LEN + 32], tok[40];
    snprintf(where, sizeof(where), "%s:%" PetscInt_FMT ":", r->path, L->line);
    a  = CSReaderSkipBlank(CSReaderSkipToken(kw));
    al = CSReaderTokenLen(a);
    b  = CSReaderSkipBlank(CSReaderSkipToken(a));
    bl = CSReaderTokenLen(b);
    c  = CSReaderSkipBlank(CSReaderSkipToken(b));
    cl = CSReaderTokenLen(c);
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
        CSReaderFail(r, "%s unsupported PLY format '%s' (only ascii and binary_little_endian are read)", where, CSReaderTokenText(a, tok));
        PetscFunctionReturn(0);
      }
    } else if (kl == 7 && !strncmp(kw, "element", 7)) {
      long long n;
      char     *t = b;
      if (h->nelem == PLY_MAX_ELEMS) {
        CSReaderFail(r, "%s more than %d elements", where, PLY_MAX_ELEMS);
        PetscFunctionReturn(0);
      }
      if (!al || CSReaderParseInt(&t, &n, NULL) || n < 0 || n > PETSC_MAX_INT / 3 || *CSReaderSkipBlank(t)) {
        CSReaderFail(r, "%s malformed element line (expected 'element NAME COUNT')", where);
        PetscFunctionReturn(0);
      }
      cur = &h->elem[h->nelem++];
      snprintf(cur->name, sizeof(cur->name), "%.*s", al, a);
      (void)CSPathSanitize(cur->name, cur->name, sizeof(cur->name)); /* printed in messages: no escape sequences */
      cur->count  = (PetscInt)n;
      cur->nprops = 0;
    } else if (kl == 8 && !strncmp(kw, "property", 8)) {
      PlyProp *p;
      if (!cur) {
        CSReaderFail(r, "%s property before any element", where);
        PetscFunctionReturn(0);
      }
      if (cur->nprops == PLY_MAX_PROPS) {
        CSReaderFail(r, "%s more than %d properties in element %s", where, PLY_MAX_PROPS, cur->name);
        PetscFunctionReturn(0);
      }
      p             = &cur->props[cur->nprops++];
      p->count_type = PLY_NONE;
      p->role       = -1;
      if (al == 4 && !strncmp(a, "list", 4)) {
        char *d  = CSReaderSkipBlank(CSReaderSkipToken(c));
        int   dl = CSReaderTokenLen(d);
        p->count_type = PlyTypeFromName(b, bl);
        p->type       = PlyTypeFromName(c, cl);
        if (!PlyIsInteger(p->count_type) || p->type == PLY_NONE || !dl) {
          CSReaderFail(r, "%s malformed list property (expected 'property list COUNTTYPE ITEMTYPE NAME' with an integer COUNTTYPE)", where);
          PetscFunctionReturn(0);
        }
        snprintf(p->name, sizeof(p->name), "%.*s", dl, d);
        (void)CSPathSanitize(p->name, p->name, sizeof(p->name));
      } else {
        p->type = PlyTypeFromName(a, al);
        if (p->type == PLY_NONE || !bl) {
          CSReaderFail(r, "%s malformed property (unknown type '%s')", where, CSReaderTokenText(a, tok));
          PetscFunctionReturn(0);
        }
        snprintf(p->name, sizeof(p->name), "%.*s", bl, b);
        (void)CSPathSanitize(p->name, p->name, sizeof(p->name));
      }
    } else {
      CSReaderFail(r, "%s unknown PLY header line '%s'", where, CSReaderTokenText(kw, tok));
      PetscFunctionReturn(0);
    }
  }
  if (!*data) CSReaderFail(r, "%s:%" PetscInt_FMT ": truncated header (no end_header)", r->path, L->line);
  else if (!h->has_format) CSReaderFail(r, "%s:%" PetscInt_FMT ": no format line in the header", r->path, L->line);
  PetscFunctionReturn(0);
}

/* The fewest bytes the data of the header's elements can take (binary: the scalars and list counts; ascii: a
   digit and a separator each), so counts the file cannot hold are refused before anything is allocated */
static double PlyMinimumBytes(const PlyHeader *h)
{
  double total = 0;
  for (PetscInt e = 0; e < h->nelem; e++) {
    double per = 0;
    for (PetscInt q = 0; q < h->elem[e].nprops; q++) {
      const PlyProp *p = &h->elem[e].props[q];
      per += h->binary ? PlyTypeSize[p->count_type != PLY_NONE ? p->count_type : p->type] : 2;
    }
    total += per * (double)h->elem[e].count;
  }
  return h->binary ? total : total - 1; /* the last ascii value may end the file */
}

/* the vertex element's first pair of scalar texture coordinate properties (u v, s t, texture_u texture_v) gets the
   roles PLY_ROLE_U, PLY_ROLE_U + 1 */
static void PlyVertexUV(PlyElem *el)
{
  static const char *const pairs[][2] = {
    {"u",         "v"        },
    {"s",         "t"        },
    {"texture_u", "texture_v"}
  };
  for (size_t k = 0; k < sizeof(pairs) / sizeof(pairs[0]); k++) {
    PlyProp *found[2] = {NULL, NULL};
    for (PetscInt q = 0; q < el->nprops; q++)
      for (int d = 0; d < 2; d++)
        if (el->props[q].count_type == PLY_NONE && !found[d] && !strcmp(el->props[q].name, pairs[k][d])) found[d] = &el->props[q];
    if (found[0] && found[1]) {
      found[0]->role = PLY_ROLE_U;
      found[1]->role = PLY_ROLE_U + 1;
      return;
    }
  }
}

static void PlyVertexRoles(Reader *r, PlyElem *el, PetscInt line)
{
  int found[3] = {0, 0, 0};
  for (PetscInt q = 0; q < el->nprops; q++) {
    PlyProp *p = &el->props[q];
    for (int d = 0; d < 3; d++)
      if (p->count_type == PLY_NONE && !found[d] && p->name[0] == "xyz"[d] && !p->name[1]) {
        p->role  = PLY_ROLE_X + d;
        found[d] = 1;
      }
  }
  if (!found[0] || !found[1] || !found[2]) CSReaderFail(r, "%s:%" PetscInt_FMT ": the vertex element lacks a scalar x, y or z property", r->path, line);
  PlyVertexUV(el);
}

/* the vertex list (vertex_indices or vertex_index) and the texcoord list; *texcoord says whether there is one */
static void PlyFaceRoles(Reader *r, PlyElem *el, PetscInt line, PetscBool *texcoord)
{
  PetscBool ok = PETSC_FALSE;
  *texcoord    = PETSC_FALSE;
  for (PetscInt q = 0; q < el->nprops && !r->msg[0]; q++) {
    PlyProp *p = &el->props[q];
    if (p->count_type == PLY_NONE) continue;
    if (!ok && (!strcmp(p->name, "vertex_indices") || !strcmp(p->name, "vertex_index"))) {
      if (!PlyIsInteger(p->type)) CSReaderFail(r, "%s:%" PetscInt_FMT ": the face list %s has a non-integer item type", r->path, line, p->name);
      p->role = PLY_ROLE_FACE;
      ok      = PETSC_TRUE;
    } else if (!*texcoord && !strcmp(p->name, "texcoord")) {
      p->role   = PLY_ROLE_TEXCOORD;
      *texcoord = PETSC_TRUE;
    }
  }
  if (!ok) CSReaderFail(r, "%s:%" PetscInt_FMT ": the face element has no vertex_indices list", r->path, line);
}

/* Marks the properties kept (roles) and checks the header has what a triangle mesh needs. */
static void PlyAssignRoles(Reader *r, PlyHeader *h, PetscInt line, PlyElem **ev, PlyElem **ef)
{
  PetscBool texcoord = PETSC_FALSE;
  *ev = *ef = NULL;
  for (PetscInt e = 0; e < h->nelem && !r->msg[0]; e++) {
    PlyElem *el = &h->elem[e];
    if (!*ev && !strcmp(el->name, "vertex")) {
      *ev = el;
      PlyVertexRoles(r, el, line);
    } else if (!*ef && !strcmp(el->name, "face")) {
      *ef = el;
      PlyFaceRoles(r, el, line, &texcoord);
    }
  }
  if (r->msg[0]) return;
  if (!*ev) CSReaderFail(r, "%s:%" PetscInt_FMT ": no vertex element", r->path, line);
  else if (!*ef) CSReaderFail(r, "%s:%" PetscInt_FMT ": no face element", r->path, line);
  else if (!(*ef)->count) CSReaderFail(r, "%s:%" PetscInt_FMT ": no faces (the header says 0)", r->path, line);
  else if (texcoord) /* per corner wins over per vertex */
    for (PetscInt q = 0; q < (*ev)->nprops; q++)
      if ((*ev)->props[q].role >= PLY_ROLE_U) (*ev)->props[q].role = -1;
}

/* The arrays of the kept data; UVs when the header has them (per vertex: nuv = nv; per corner: nuv = 3 nf) */
static PetscErrorCode PlyAllocate(Reader *r, const PlyElem *ev, const PlyElem *ef, PetscBool *vuv)
{
  PetscBool fuv = PETSC_FALSE;
  PetscFunctionBeginUser;
  *vuv  = PETSC_FALSE;
  r->nv = ev->count;
  r->nf = ef->count;
  PetscCall(PetscMalloc1(3 * r->nv, &r->x));
  PetscCall(PetscMalloc1(3 * r->nf, &r->f));
  for (PetscInt q = 0; q < ev->nprops; q++) *vuv = (PetscBool)(*vuv || ev->props[q].role == PLY_ROLE_U);
  for (PetscInt q = 0; q < ef->nprops; q++) fuv = (PetscBool)(fuv || ef->props[q].role == PLY_ROLE_TEXCOORD);
  if (!*vuv && !fuv) PetscFunctionReturn(0);
  r->nuv = fuv ? 3 * r->nf : r->nv;
  PetscCall(PetscMalloc1(2 * r->nuv, &r->uv));
  PetscCall(PetscMalloc1(3 * r->nf, &r->fuv));
  if (fuv)
    for (PetscInt h = 0; h < 3 * r->nf; h++) r->fuv[h] = h;
  PetscFunctionReturn(0);
}

/* a scalar of entry k of the vertex element: a coordinate or a texture coordinate */
static void PlyKeepScalar(PlySource *src, const PlyProp *p, PetscInt k, double dv)
{
  Reader *r = src->r;
  if (p->role < 0) return;
  if (PetscIsInfOrNanReal((PetscReal)dv)) PlyFail(src, "non-finite %s (%s)", p->role >= PLY_ROLE_U ? "texture coordinate" : "coordinate", PetscIsNanReal((PetscReal)dv) ? "NaN" : "Inf");
  else if (p->role >= PLY_ROLE_U) r->uv[2 * k + p->role - PLY_ROLE_U] = (PetscReal)dv;
  else r->x[3 * k + p->role] = (PetscReal)dv;
}

/* the length n of a list: not negative; 3 vertices, 6 texture coordinates when kept; 1 after recording an error */
static int PlyListLength(PlySource *src, const PlyProp *p, long long n)
{
  if (n < 0) PlyFail(src, "negative length of the list %s", p->name);
  else if (p->role == PLY_ROLE_FACE && n != 3) PlyFail(src, "face with %lld vertices (only triangles are supported)", n);
  else if (p->role == PLY_ROLE_TEXCOORD && n != 6) PlyFail(src, "texcoord list with %lld values (6 expected: u v of each corner of a triangle)", n);
  return src->r->msg[0] ? 1 : 0;
}

/* item i of a kept list of face k */
static void PlyKeepItem(PlySource *src, const PlyProp *p, PetscInt k, long long i, double dv, long long iv)
{
  Reader *r = src->r;
  if (p->role == PLY_ROLE_FACE) {
    if (iv < 0 || iv >= r->nv) PlyFail(src, "vertex index %lld out of range [0, %" PetscInt_FMT ")", iv, r->nv);
    else r->f[3 * k + i] = (PetscInt)iv;
  } else if (p->role == PLY_ROLE_TEXCOORD) {
    if (PetscIsInfOrNanReal((PetscReal)dv)) PlyFail(src, "non-finite texture coordinate (%s)", PetscIsNanReal((PetscReal)dv) ? "NaN" : "Inf");
    else r->uv[6 * k + i] = (PetscReal)dv;
  }
}

/* every entry of element el: its kept values stored, the others read and skipped */
static void PlyReadElement(PlySource *src, const PlyElem *el)
{
  Reader *r   = src->r;
  src->ename  = el->name;
  src->count  = el->count;
  for (PetscInt k = 0; k < el->count && el->nprops && !r->msg[0]; k++) { /* an element without properties has no data */
    src->k = k;
    for (PetscInt q = 0; q < el->nprops && !r->msg[0]; q++) {
      const PlyProp *p = &el->props[q];
      double         dv;
      long long      iv, n;
      if (p->count_type == PLY_NONE) {
        if (!PlyRead(src, p->type, &dv, &iv)) PlyKeepScalar(src, p, k, dv);
        continue;
      }
      if (PlyRead(src, p->count_type, &dv, &n)) break;
      if (PlyListLength(src, p, n)) break;
      for (long long i = 0; i < n && !r->msg[0]; i++) {
        if (PlyRead(src, p->type, &dv, &iv)) break;
        PlyKeepItem(src, p, k, i, dv, iv);
      }
    }
  }
}

PetscErrorCode CSMeshDataReadPLY(Reader *r)
{
  Lines     L = {r->buf, r->buf + r->len, 0};
  PlyHeader *h;
  PlyElem   *ev = NULL, *ef = NULL;
  PlySource  src;
  char      *data;
  PetscBool  vuv;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(1, &h));
  PetscCall(PlyParseHeader(r, h, &L, &data));
  if (!r->msg[0]) PlyAssignRoles(r, h, L.line, &ev, &ef);
  if (!r->msg[0] && PlyMinimumBytes(h) > (double)(r->buf + r->len - data)) CSReaderFail(r, "%s:%" PetscInt_FMT ": truncated: the header's element counts need at least %.0f bytes of data, the file has %zu after the header", r->path, L.line, PlyMinimumBytes(h), (size_t)(r->buf + r->len - data));
  if (r->msg[0]) {
    PetscCall(PetscFree(h));
    PetscFunctionReturn(0);
  }
  PetscCall(PlyAllocate(r, ev, ef, &vuv));
  PetscCall(PetscMemzero(&src, sizeof(src)));
  src.r      = r;
  src.binary = h->binary;
  src.p      = (const unsigned char *)data;
  src.end    = (const unsigned char *)(r->buf + r->len);
  src.L      = L;
  src.L.line = L.line + 1; /* the data starts on the line after end_header */
  for (PetscInt e = 0; e < h->nelem && !r->msg[0]; e++) PlyReadElement(&src, &h->elem[e]);
  if (!r->msg[0] && vuv) PetscCall(PetscArraycpy(r->fuv, r->f, 3 * r->nf)); /* UVs per vertex */
  PetscCall(PetscFree(h));
  PetscFunctionReturn(0);
}

static void StoreLE(unsigned char *p, uint64_t u, int n)
{
  for (int i = 0; i < n; i++, u >>= 8) p[i] = (unsigned char)(u & 0xff);
}

static void StoreDouble(unsigned char *p, PetscReal v)
{
  double   d = (double)v;
  uint64_t u;
  memcpy(&u, &d, sizeof(u));
  StoreLE(p, u, 8);
}

/* UVs per vertex: one per vertex and each face corner takes its vertex's */
static PetscBool UVPerVertex(const CSMeshData *md)
{
  if (!md->fuv || md->nuv != md->nv) return PETSC_FALSE;
  for (PetscInt h = 0; h < 3 * md->nf; h++)
    if (md->fuv[h] != md->f[h]) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* binary_little_endian, double x y z, list uchar int vertex_indices: exact and compact. Texture coordinates as
   doubles: per vertex (double u v) when each vertex has one, else per face corner (list uchar double texcoord) */
PetscErrorCode CSMeshDataWritePLY(FILE *fp, const CSMeshData *md, PetscBool *ok)
{
  unsigned char *b, *p;
  PetscBool      vuv = UVPerVertex(md), fuv = (PetscBool)(md->fuv && !vuv);
  size_t         vb = vuv ? 40 : 24, fb = fuv ? 13 + 49 : 13, n = (size_t)md->nv * vb + (size_t)md->nf * fb;

  PetscFunctionBeginUser;
  fprintf(fp, "ply\nformat binary_little_endian 1.0\ncomment %s (written by confsurf)\n", md->name);
  fprintf(fp, "element vertex %" PetscInt_FMT "\nproperty double x\nproperty double y\nproperty double z\n", md->nv);
  if (vuv) fprintf(fp, "property double u\nproperty double v\n");
  fprintf(fp, "element face %" PetscInt_FMT "\nproperty list uchar int vertex_indices\n", md->nf);
  if (fuv) fprintf(fp, "property list uchar double texcoord\n");
  fprintf(fp, "end_header\n");
  PetscCall(PetscMalloc1(n, &b));
  p = b;
  for (PetscInt i = 0; i < md->nv; i++) {
    for (int d = 0; d < 3; d++, p += 8) StoreDouble(p, md->x[3 * i + d]);
    if (vuv)
      for (int d = 0; d < 2; d++, p += 8) StoreDouble(p, md->uv[2 * i + d]);
  }
  for (PetscInt i = 0; i < md->nf; i++) {
    *p++ = 3;
    for (int k = 0; k < 3; k++, p += 4) StoreLE(p, (uint64_t)(uint32_t)(int32_t)md->f[3 * i + k], 4);
    if (!fuv) continue;
    *p++ = 6;
    for (int k = 0; k < 3; k++)
      for (int d = 0; d < 2; d++, p += 8) StoreDouble(p, md->uv[2 * md->fuv[3 * i + k] + d]);
  }
  *ok = (PetscBool)(fwrite(b, 1, n, fp) == n);
  PetscCall(PetscFree(b));
  PetscFunctionReturn(0);
}
