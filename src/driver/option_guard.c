/* Checked option readers (issue 36, items 9-11). PETSc 3.18 reads an integer with strtol and a cast to int
   (PetscOptionsStringToInt: -flow_max_it 4294967298 gives 2, 99999999999999999999 gives -1), copies a string
   into the caller's buffer cut to its size (a 5000-character -summary path writes another file), and treats an
   option given without a value (-flow_t '') as not given at all (the default, silently). bin/confsurf defines
   PetscOptionsGetInt, PetscOptionsGetReal and PetscOptionsGetString itself: PETSc's option objects
   (PetscOptionsInt/Real/String/FList, also PETSc's own solvers') call them through the shared library's PLT, so
   these run first for every option, check the value and hand over to PETSc's (dlsym RTLD_NEXT). Every rank reads
   the options, so a refusal is raised on PETSC_COMM_WORLD: printed once, by rank 0. Only in the
   program (src/driver), not in the library the unit programs link. A static PETSc would fail to link: a loud
   failure, not a silent one. */
#define _GNU_SOURCE
#include <dlfcn.h>
#include <errno.h>
#include <limits.h>
#include <stdlib.h>
#include <petscsys.h>

typedef PetscErrorCode (*GetIntFn)(PetscOptions, const char[], const char[], PetscInt *, PetscBool *);
typedef PetscErrorCode (*GetRealFn)(PetscOptions, const char[], const char[], PetscReal *, PetscBool *);
typedef PetscErrorCode (*GetStringFn)(PetscOptions, const char[], const char[], char[], size_t, PetscBool *);

/* the option as the user wrote it, for messages: -<prefix><name without its dash> */
static void OptionName(const char pre[], const char name[], char out[], size_t len)
{
  snprintf(out, len, "-%s%s", pre ? pre : "", name[0] == '-' ? name + 1 : name);
}

static PetscBool Empty(const char *value)
{
  return (PetscBool)(!value || !value[0]);
}

/* confsurf's own string options, which need a value (PETSc's -history, -info, -log_trace ... may go without) */
static PetscBool NeedsValue(const char full[])
{
  const char *exact[] = {"-o", "-summary", "-history_csv", "-viewer_dir", "-checkpoint", "-resume", "-reference", "-task", "-energy", "-variables", "-islands", "-target_mesh", "-constraint_points"};
  const char *start[] = {"-gen", "-mesh", "-curve", "-flow_", "-spin_", "-bs_", "-rho", "-spectrum_"};
  for (size_t i = 0; i < sizeof(exact) / sizeof(exact[0]); i++)
    if (!strcmp(full, exact[i])) return PETSC_TRUE;
  for (size_t i = 0; i < sizeof(start) / sizeof(start[0]); i++)
    if (!strncmp(full, start[i], strlen(start[i]))) return PETSC_TRUE;
  return PETSC_FALSE;
}

/* An integer PetscInt holds, or PETSc's words for one (DEFAULT, DECIDE, mouse) */
static PetscErrorCode CheckInteger(const char full[], const char *value)
{
  const char *words[] = {"PETSC_DEFAULT", "DEFAULT", "PETSC_DECIDE", "DECIDE", "mouse"};
  char       *end;
  long long   v;
  PetscFunctionBegin;
  PetscCheck(!Empty(value), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: needs an integer value", full);
  for (size_t i = 0; i < sizeof(words) / sizeof(words[0]); i++)
    if (!strcasecmp(value, words[i])) PetscFunctionReturn(0);
  errno = 0;
  v     = strtoll(value, &end, 10);
  PetscCheck(end != value && !*end, PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s %s: not an integer", full, value);
  PetscCheck(errno != ERANGE && v <= PETSC_MAX_INT && v >= PETSC_MIN_INT, PETSC_COMM_WORLD, PETSC_ERR_ARG_OUTOFRANGE, "%s %s: out of range (an integer from %" PetscInt_FMT " to %" PetscInt_FMT ")", full, value, PETSC_MIN_INT, PETSC_MAX_INT);
  PetscFunctionReturn(0);
}

PetscErrorCode PetscOptionsGetInt(PetscOptions options, const char pre[], const char name[], PetscInt *ivalue, PetscBool *set)
{
  static GetIntFn next = NULL;
  const char     *value;
  PetscBool       found;
  char            full[256];
  PetscFunctionBegin;
  if (!next) next = (GetIntFn)dlsym(RTLD_NEXT, "PetscOptionsGetInt");
  PetscCheck(next, PETSC_COMM_SELF, PETSC_ERR_LIB, "PETSc's PetscOptionsGetInt not found (dlsym: %s)", dlerror());
  PetscCall(PetscOptionsFindPair(options, pre, name, &value, &found));
  OptionName(pre, name, full, sizeof(full));
  if (found) PetscCall(CheckInteger(full, value));
  PetscCall(next(options, pre, name, ivalue, set));
  PetscFunctionReturn(0);
}

PetscErrorCode PetscOptionsGetReal(PetscOptions options, const char pre[], const char name[], PetscReal *dvalue, PetscBool *set)
{
  static GetRealFn next = NULL;
  const char      *value;
  PetscBool        found;
  char             full[256];
  PetscFunctionBegin;
  if (!next) next = (GetRealFn)dlsym(RTLD_NEXT, "PetscOptionsGetReal");
  PetscCheck(next, PETSC_COMM_SELF, PETSC_ERR_LIB, "PETSc's PetscOptionsGetReal not found (dlsym: %s)", dlerror());
  PetscCall(PetscOptionsFindPair(options, pre, name, &value, &found));
  OptionName(pre, name, full, sizeof(full));
  PetscCheck(!found || !Empty(value), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: needs a number", full);
  PetscCall(next(options, pre, name, dvalue, set));
  PetscFunctionReturn(0);
}

PetscErrorCode PetscOptionsGetString(PetscOptions options, const char pre[], const char name[], char string[], size_t len, PetscBool *set)
{
  static GetStringFn next = NULL;
  const char        *value;
  PetscBool          found;
  char               full[256];
  PetscFunctionBegin;
  if (!next) next = (GetStringFn)dlsym(RTLD_NEXT, "PetscOptionsGetString");
  PetscCheck(next, PETSC_COMM_SELF, PETSC_ERR_LIB, "PETSc's PetscOptionsGetString not found (dlsym: %s)", dlerror());
  PetscCall(PetscOptionsFindPair(options, pre, name, &value, &found));
  OptionName(pre, name, full, sizeof(full));
  if (found) {
    PetscCheck(!Empty(value) || !NeedsValue(full), PETSC_COMM_WORLD, PETSC_ERR_ARG_WRONG, "%s: needs a value", full);
    PetscCheck(Empty(value) || !len || strlen(value) < len, PETSC_COMM_WORLD, PETSC_ERR_ARG_SIZ, "%s: the value is %zu characters long, at most %zu are read (it would be cut)", full, strlen(value), len - 1);
  }
  PetscCall(next(options, pre, name, string, len, set));
  PetscFunctionReturn(0);
}
