/* Flat JSON summary object (numbers, integers, booleans, strings, number arrays), written by rank 0. */
#include "cs_util.h"

typedef struct {
  char *key;
  char *val; /* already formatted JSON value */
} CSJSONEntry;

struct _p_CSJSON {
  MPI_Comm     comm;
  PetscInt     n, cap;
  CSJSONEntry *e;
};

PetscErrorCode CSJSONCreate(MPI_Comm comm, CSJSON *js)
{
  PetscFunctionBeginUser;
  PetscCall(PetscNew(js));
  (*js)->comm = comm;
  PetscFunctionReturn(0);
}

/* Store a formatted value; a repeated key replaces the earlier value so later stages can refine a number. */
static PetscErrorCode CSJSONPut(CSJSON js, const char key[], const char val[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < js->n; i++) {
    PetscBool same;
    PetscCall(PetscStrcmp(js->e[i].key, key, &same));
    if (same) {
      PetscCall(PetscFree(js->e[i].val));
      PetscCall(PetscStrallocpy(val, &js->e[i].val));
      PetscFunctionReturn(0);
    }
  }
  PetscCall(CSArrayGrow(sizeof(CSJSONEntry), js->n, 16, &js->cap, (void **)&js->e));
  PetscCall(PetscStrallocpy(key, &js->e[js->n].key));
  PetscCall(PetscStrallocpy(val, &js->e[js->n].val));
  js->n++;
  PetscFunctionReturn(0);
}

/* JSON has no NaN/Inf: they are written as null so a reader fails loudly rather than silently. */
static PetscErrorCode FormatReal(PetscReal v, char buf[], size_t len)
{
  PetscFunctionBeginUser;
  if (PetscIsInfOrNanReal(v)) PetscCall(PetscSNPrintf(buf, len, "null"));
  else PetscCall(PetscSNPrintf(buf, len, "%.17g", (double)v));
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONAddReal(CSJSON js, const char key[], PetscReal v)
{
  char buf[64];
  PetscFunctionBeginUser;
  PetscCall(FormatReal(v, buf, sizeof(buf)));
  PetscCall(CSJSONPut(js, key, buf));
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONAddInt(CSJSON js, const char key[], PetscInt v)
{
  char buf[64];
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(buf, sizeof(buf), "%" PetscInt_FMT, v));
  PetscCall(CSJSONPut(js, key, buf));
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONAddBool(CSJSON js, const char key[], PetscBool v)
{
  PetscFunctionBeginUser;
  PetscCall(CSJSONPut(js, key, v ? "true" : "false"));
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONAddString(CSJSON js, const char key[], const char v[])
{
  size_t n, k = 0;
  char  *buf;
  PetscFunctionBeginUser;
  PetscCall(PetscStrlen(v, &n));
  PetscCall(PetscMalloc1(2 * n + 3, &buf));
  buf[k++] = '"';
  for (size_t i = 0; i < n; i++) {
    if (v[i] == '"' || v[i] == '\\') buf[k++] = '\\';
    buf[k++] = ((unsigned char)v[i] < 0x20 || v[i] == 0x7f) ? '?' : v[i]; /* control characters are not valid JSON */
  }
  buf[k++] = '"';
  buf[k]   = 0;
  PetscCall(CSJSONPut(js, key, buf));
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONAddRealArray(CSJSON js, const char key[], PetscInt n, const PetscReal v[])
{
  char  *buf;
  size_t len = 32 * (size_t)(n + 1), k = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(len, &buf));
  buf[k++] = '[';
  for (PetscInt i = 0; i < n; i++) {
    char   num[64];
    size_t l;
    PetscCall(FormatReal(v[i], num, sizeof(num)));
    PetscCall(PetscStrlen(num, &l));
    if (i) buf[k++] = ',';
    PetscCall(PetscMemcpy(buf + k, num, l));
    k += l;
  }
  buf[k++] = ']';
  buf[k]   = 0;
  PetscCall(CSJSONPut(js, key, buf));
  PetscCall(PetscFree(buf));
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONWrite(CSJSON js, const char path[])
{
  PetscMPIInt rank;
  CSFile      f;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(js->comm, &rank));
  PetscCall(CSFileOpen(js->comm, (PetscBool)!rank, "-summary", path, PETSC_FALSE, &f));
  if (f.fp) {
    fprintf(f.fp, "{\n");
    for (PetscInt i = 0; i < js->n; i++) fprintf(f.fp, "  \"%s\": %s%s\n", js->e[i].key, js->e[i].val, i + 1 < js->n ? "," : "");
    fprintf(f.fp, "}\n");
  }
  PetscCall(CSFileClose(js->comm, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONGetString(CSJSON js, char **text)
{
  size_t len = 4, k = 0;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < js->n; i++) len += strlen(js->e[i].key) + strlen(js->e[i].val) + 8;
  PetscCall(PetscMalloc1(len, text));
  k += (size_t)sprintf(*text + k, "{\n");
  for (PetscInt i = 0; i < js->n; i++) k += (size_t)sprintf(*text + k, "  \"%s\": %s%s\n", js->e[i].key, js->e[i].val, i + 1 < js->n ? "," : "");
  (void)sprintf(*text + k, "}\n");
  PetscFunctionReturn(0);
}

PetscErrorCode CSJSONDestroy(CSJSON *js)
{
  PetscFunctionBeginUser;
  if (!*js) PetscFunctionReturn(0);
  for (PetscInt i = 0; i < (*js)->n; i++) {
    PetscCall(PetscFree((*js)->e[i].key));
    PetscCall(PetscFree((*js)->e[i].val));
  }
  PetscCall(PetscFree((*js)->e));
  PetscCall(PetscFree(*js));
  PetscFunctionReturn(0);
}
