/* One tokenizer for every value file (issue 18, item 3): the ρ file, the boundary-tangent file and the point
   constraints file. The file is read whole (CSFileLoad: no line length, no buffer edge to split a number at),
   tokens are separated by blanks, newlines or commas, and '#' starts a comment to the end of its line. Each token
   comes with its line, so a line-structured file (the points: "index x y z") can check its records. */
#include "cs_util.h"
#include <errno.h>
#include <stdlib.h>

PetscErrorCode CSTokensLoad(const char what[], const char path[], CSTokens *t)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(t, sizeof(*t)));
  PetscCall(CSFileLoad(what, path, &t->buf, &t->len));
  CSTokensInit(t, t->buf, t->len);
  PetscCall(CSPathSanitize(path, t->name, sizeof(t->name)));
  PetscFunctionReturn(0);
}

/* Not PETSc: also used by the fuzz target on a plain buffer (buf[len] must be 0) */
void CSTokensInit(CSTokens *t, char *buf, size_t len)
{
  t->p    = buf;
  t->end  = buf + len;
  t->line = 1;
}

static int IsSeparator(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\f' || c == '\v' || c == ',' || c == '#' || c == 0;
}

int CSTokensNext(CSTokens *t, const char **tok, size_t *len, PetscInt *line)
{
  while (t->p < t->end) {
    char c = *t->p;
    if (c == '\n') t->line++;
    if (c == '#')
      while (t->p < t->end && *t->p != '\n') t->p++;
    else if (IsSeparator(c)) t->p++;
    else break;
  }
  if (t->p >= t->end) return 0;
  *tok  = t->p;
  *line = t->line;
  while (t->p < t->end && !IsSeparator(*t->p)) t->p++;
  *len = (size_t)(t->p - *tok);
  return 1;
}

/* 0: a finite number; 1: not a number; 2: not finite */
int CSTokenReal(const char *tok, size_t len, double *v)
{
  char *e;
  *v = strtod(tok, &e);
  if (e != tok + len) return 1;
  return isfinite(*v) ? 0 : 2;
}

/* 0: an integer that fits a long long; 1: not an integer */
int CSTokenInt(const char *tok, size_t len, long long *v)
{
  char *e;
  errno = 0;
  *v    = strtoll(tok, &e, 10);
  return (e != tok + len || errno) ? 1 : 0;
}

/* a token for a message: at most 32 characters, control characters as '?' */
const char *CSTokenText(const char *tok, size_t len, char out[40])
{
  size_t n = PetscMin(len, (size_t)32);
  for (size_t i = 0; i < n; i++) out[i] = ((unsigned char)tok[i] < 0x20 || tok[i] == 0x7f) ? '?' : tok[i];
  out[n] = 0;
  return out;
}

PetscErrorCode CSTokensDestroy(CSTokens *t)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(t->buf));
  PetscFunctionReturn(0);
}

/* Every number of a value file, in order, with the line of each (the islands mask, -rho_from_displacement):
   errors name the option, the file and the line. */
PetscErrorCode CSReadNumberFile(const char option[], const char path[], PetscInt *n, PetscReal **values, PetscInt **lines)
{
  CSTokens    t;
  const char *tok;
  size_t      len;
  PetscInt    line, cap = 0;
  PetscFunctionBeginUser;
  *n = 0, *values = NULL, *lines = NULL;
  PetscCall(CSTokensLoad(option, path, &t));
  while (CSTokensNext(&t, &tok, &len, &line)) {
    double v;
    if (CSTokenReal(tok, len, &v)) {
      char shown[40];
      CSTokenText(tok, len, shown); /* before the buffer goes */
      PetscCall(PetscFree(*values));
      PetscCall(PetscFree(*lines));
      PetscCall(CSTokensDestroy(&t));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": not a finite number: '%s'", option, t.name, line, shown);
    }
    if (*n == cap) {
      PetscInt c2 = cap;
      PetscCall(CSArrayGrow(sizeof(PetscReal), *n, 64, &cap, (void **)values));
      PetscCall(CSArrayGrow(sizeof(PetscInt), *n, 64, &c2, (void **)lines));
    }
    (*values)[*n] = (PetscReal)v;
    (*lines)[(*n)++] = line;
  }
  PetscCall(CSTokensDestroy(&t));
  PetscFunctionReturn(0);
}
