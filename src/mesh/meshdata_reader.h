/* Private to src/mesh: what the OBJ, OFF and PLY readers share, and the per-format readers and writers
   behind CSMeshDataRead/CSMeshDataWrite.
   A file is read whole into memory and parsed in place. Parse errors are not raised where they are found:
   the first one is recorded as a message, everything allocated is freed, and only then the error is raised,
   so a bad file leaks nothing even when the caller catches the error (PetscReturnErrorHandler). */
#ifndef CS_MESHDATA_READER_H
#define CS_MESHDATA_READER_H
#include "cs_meshdata.h"
#include "cs_util.h"
#include <ctype.h>
#include <stdio.h>

#define CS_MSG_LEN 2048 /* a long path (shortened to CS_NAME_SHOWN) and the reason */

typedef struct {
  const char *path;
  char       *buf; /* the whole file, NUL-terminated */
  size_t      len;
  PetscInt    nv, nf;
  PetscReal  *x;
  PetscInt   *f;
  PetscInt    nuv;  /* texture coordinates (issue 38): 0 when the file has none */
  PetscReal  *uv;   /* 2*nuv */
  PetscInt   *fuv;  /* 3*nf, per face corner */
  char        msg[CS_MSG_LEN]; /* the first error, empty while the file is fine */
} Reader;

/* Records the first error only: later ones are consequences. */
PETSC_INTERN void           CSReaderFail(Reader *r, const char fmt[], ...);
PETSC_INTERN PetscErrorCode CSReaderFree(Reader *r);
/* Moves what a successful parse read (positions, faces, UVs) into md, leaving r without them. */
PETSC_INTERN PetscErrorCode CSReaderTake(Reader *r, CSMeshData *md);

/* Line and token helpers (text formats). Lines are cut in place; '\r' counts as blank (CRLF files). */
typedef struct {
  char    *p, *end;
  PetscInt line; /* 1-based number of the line last returned */
} Lines;

PETSC_INTERN char *CSReaderNextLine(Lines *L);

static inline int CSReaderIsBlank(char c)
{
  return c == ' ' || c == '\t' || c == '\r' || c == '\f' || c == '\v';
}
static inline int CSReaderIsTokenEnd(char c)
{
  return c == 0 || isspace((unsigned char)c);
}
static inline char *CSReaderSkipBlank(char *s)
{
  while (CSReaderIsBlank(*s)) s++;
  return s;
}
static inline char *CSReaderSkipToken(char *s)
{
  while (!CSReaderIsTokenEnd(*s)) s++;
  return s;
}

PETSC_INTERN int         CSReaderTokenLen(const char *s);
PETSC_INTERN const char *CSReaderTokenText(const char *s, char out[40]);
PETSC_INTERN int         CSReaderParseReal(char **s, PetscReal *v);
PETSC_INTERN int         CSReaderParseInt(char **s, long long *v, const char *after);
PETSC_INTERN void        CSReaderLineFail(Reader *r, PetscInt line, const char fmt[], ...);
PETSC_INTERN PetscBool   CSReaderCoordBad(Reader *r, PetscReal v, PetscInt line);
PETSC_INTERN void        CSReaderParseVertex(Reader *r, char **s, PetscInt line, PetscReal x[3]);

/* One reader and one writer per format; a reader leaves r->msg set on a parse error. */
PETSC_INTERN PetscErrorCode CSMeshDataReadOBJ(Reader *r);
PETSC_INTERN PetscErrorCode CSMeshDataReadOFF(Reader *r);
PETSC_INTERN PetscErrorCode CSMeshDataReadPLY(Reader *r);
PETSC_INTERN PetscErrorCode CSMeshDataWriteOBJ(FILE *fp, const CSMeshData *md);
PETSC_INTERN PetscErrorCode CSMeshDataWriteOFF(FILE *fp, const CSMeshData *md);
PETSC_INTERN PetscErrorCode CSMeshDataWritePLY(FILE *fp, const CSMeshData *md, PetscBool *ok);

#endif
