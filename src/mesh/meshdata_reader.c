/* What the OBJ, OFF and PLY readers share: loading the file, recording the first error, line and token parsing. */
#include "meshdata_reader.h"
#include <errno.h>
#include <stdarg.h>
#include <stdlib.h>
#include <string.h>

void CSReaderFail(Reader *r, const char fmt[], ...)
{
  va_list ap;
  if (r->msg[0]) return;
  va_start(ap, fmt);
  vsnprintf(r->msg, sizeof(r->msg), fmt, ap);
  va_end(ap);
}

PetscErrorCode CSReaderFree(Reader *r)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(r->buf));
  PetscCall(PetscFree(r->x));
  PetscCall(PetscFree(r->f));
  PetscCall(PetscFree(r->uv));
  PetscCall(PetscFree(r->fuv));
  PetscFunctionReturn(0);
}

PetscErrorCode CSReaderTake(Reader *r, CSMeshData *md)
{
  PetscFunctionBeginUser;
  md->nv  = r->nv;
  md->nf  = r->nf;
  md->x   = r->x;
  md->f   = r->f;
  md->nuv = r->fuv ? r->nuv : 0;
  md->uv  = r->fuv ? r->uv : NULL;
  md->fuv = r->fuv;
  if (!r->fuv) PetscCall(PetscFree(r->uv)); /* texture coordinates no face refers to are no texture */
  r->x = r->uv = NULL;
  r->f = r->fuv = NULL;
  r->nuv        = 0;
  PetscFunctionReturn(0);
}

char *CSReaderNextLine(Lines *L)
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

/* length of the token at s (bounded so a binary blob does not flood a message) */
int CSReaderTokenLen(const char *s)
{
  int n = 0;
  while (!CSReaderIsTokenEnd(s[n]) && n < 32) n++;
  return n;
}
/* the token at s for a message: bounded, unprintable bytes shown as '?' */
const char *CSReaderTokenText(const char *s, char out[40])
{
  int n = CSReaderTokenLen(s);
  for (int i = 0; i < n; i++) out[i] = isprint((unsigned char)s[i]) ? s[i] : '?';
  out[n] = 0;
  return out;
}

/* Real number token: 0 ok, 1 no token left on the line, 2 garbage. */
int CSReaderParseReal(char **s, PetscReal *v)
{
  char *e;
  *s = CSReaderSkipBlank(*s);
  if (!**s) return 1;
  *v = (PetscReal)strtod(*s, &e);
  if (e == *s || !CSReaderIsTokenEnd(*e)) return 2;
  *s = e;
  return 0;
}

/* Integer token, with the characters allowed right after the digits ('/' for OBJ's v/vt/vn). */
int CSReaderParseInt(char **s, long long *v, const char *after)
{
  char *e;
  *s = CSReaderSkipBlank(*s);
  if (!**s) return 1;
  errno = 0;
  *v    = strtoll(*s, &e, 10);
  if (e == *s || errno || (!CSReaderIsTokenEnd(*e) && !(after && strchr(after, *e)))) return 2;
  *s = e;
  return 0;
}

/* "file:line: reason" */
void CSReaderLineFail(Reader *r, PetscInt line, const char fmt[], ...)
{
  char    reason[512];
  va_list ap;
  va_start(ap, fmt);
  vsnprintf(reason, sizeof(reason), fmt, ap);
  va_end(ap);
  CSReaderFail(r, "%s:%" PetscInt_FMT ": %s", r->path, line, reason);
}

PetscBool CSReaderCoordBad(Reader *r, PetscReal v, PetscInt line)
{
  if (!PetscIsInfOrNanReal(v)) return PETSC_FALSE;
  CSReaderLineFail(r, line, "non-finite coordinate (%s)", PetscIsNanReal(v) ? "NaN" : "Inf");
  return PETSC_TRUE;
}

/* The x y z of a text vertex line into x[0..2] (OBJ and OFF); what follows them (w, colours) is ignored. */
void CSReaderParseVertex(Reader *r, char **s, PetscInt line, PetscReal x[3])
{
  char tok[40];
  for (int d = 0; d < 3 && !r->msg[0]; d++) {
    PetscReal v;
    int       st = CSReaderParseReal(s, &v);
    if (st == 1) CSReaderLineFail(r, line, "vertex with %d coordinates (3 expected)", d);
    else if (st == 2) CSReaderLineFail(r, line, "garbage '%s' where a coordinate was expected", CSReaderTokenText(*s, tok));
    else if (!CSReaderCoordBad(r, v, line)) x[d] = v;
  }
}
