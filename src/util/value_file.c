/* One reader for files of numbers (a value or an index per entry): tokens separated by white space or commas,
   '#' comments to the end of the line. Read character by character, so no line length limit; a single token
   longer than 63 characters is refused. Kept small and in one place so it can be replaced. */
#include "cs_util.h"
#include <stdio.h>
#include <stdlib.h>

/* the next token into tok[64]; *line counts newlines; returns 0 at the end of the file */
static int NextToken(FILE *fp, char tok[64], PetscInt *line, PetscBool *toolong)
{
  int c, n = 0;
  *toolong = PETSC_FALSE;
  while ((c = fgetc(fp)) != EOF) {
    if (c == '#') {
      while ((c = fgetc(fp)) != EOF && c != '\n') {}
      if (c == EOF) break;
    }
    if (c == '\n') (*line)++;
    if (c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == ',') continue;
    break;
  }
  if (c == EOF) return 0;
  do {
    if (n < 63) tok[n++] = (char)c;
    else *toolong = PETSC_TRUE;
    c = fgetc(fp);
  } while (c != EOF && c != ' ' && c != '\t' && c != '\r' && c != '\n' && c != ',' && c != '#');
  if (c != EOF) ungetc(c, fp);
  tok[n] = 0;
  return 1;
}

PetscErrorCode CSReadNumberFile(const char option[], const char path[], PetscInt *n, PetscReal **values, PetscInt **lines)
{
  FILE     *fp;
  char      tok[64];
  PetscInt  cap = 0, line = 1;
  PetscBool toolong;
  PetscFunctionBeginUser;
  *n      = 0;
  *values = NULL;
  *lines  = NULL;
  fp      = fopen(path, "r");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot open the file", option, path);
  while (NextToken(fp, tok, &line, &toolong)) {
    char  *end;
    double v = strtod(tok, &end);
    if (toolong || end == tok || *end || PetscIsInfOrNanReal((PetscReal)v)) {
      fclose(fp);
      PetscCall(PetscFree(*values));
      PetscCall(PetscFree(*lines));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s %s: line %" PetscInt_FMT ": not a finite number: '%.20s%s'", option, path, line, tok, toolong ? "..." : "");
    }
    if (*n == cap) {
      PetscInt c2 = cap;
      PetscCall(CSArrayGrow(sizeof(PetscReal), *n, 64, &cap, (void **)values));
      PetscCall(CSArrayGrow(sizeof(PetscInt), *n, 64, &c2, (void **)lines));
    }
    (*values)[*n]  = (PetscReal)v;
    (*lines)[*n]   = line;
    (*n)++;
  }
  fclose(fp);
  PetscFunctionReturn(0);
}
