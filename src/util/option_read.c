/* The project's option readers (cs_util.h): the raw value is checked before PETSc reads it, so a value that PETSc
   would wrap (integers), cut (strings) or drop (an empty value) is refused with one line naming the option. */
#include "cs_util.h"
#include <errno.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* The raw value of -<prefix><opt> (found: given at all; value NULL or "" when given without one) and its name for
   messages. */
static PetscErrorCode RawValue(PetscOptionItems *items, const char opt[], const char **value, PetscBool *found, char full[], size_t len)
{
  const char *pre = items->prefix ? items->prefix : "";
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsFindPair(items->options, items->prefix, opt, value, found));
  snprintf(full, len, "-%s%s", pre, opt[0] == '-' ? opt + 1 : opt);
  PetscCall(CSOptionsNoteRead(full)); /* a candidate of "did you mean" (option_unused.c) */
  PetscFunctionReturn(0);
}

static PetscBool Empty(const char *value)
{
  return (PetscBool)(!value || !value[0]);
}

/* An integer option takes a decimal integer that fits PetscInt (issue 36 item 9). Anything else is refused here,
   naming the option: PETSc's own reader names only the string ("Input string 1.5 has no integer value") and turns
   its words (DEFAULT, DECIDE, mouse) into negative sentinels that the options of this code do not mean. */
static PetscErrorCode CheckInteger(MPI_Comm comm, const char full[], const char value[])
{
  char     *end;
  long long v;
  PetscFunctionBeginUser;
  errno = 0;
  v     = strtoll(value, &end, 10);
  PetscCheck(end != value && !*end, comm, PETSC_ERR_ARG_WRONG, "%s %s: not an integer (a whole number in decimal digits)", full, value);
  PetscCheck(errno != ERANGE && v >= PETSC_MIN_INT && v <= PETSC_MAX_INT, comm, PETSC_ERR_ARG_OUTOFRANGE, "%s %s: out of range (an integer from %d to %d)", full, value, (int)PETSC_MIN_INT, (int)PETSC_MAX_INT);
  PetscFunctionReturn(0);
}

/* A real option takes a number strtod reads in full (nan and inf included: the callers' range checks name them);
   PETSc's reader would refuse 'abc' without naming the option. */
static PetscErrorCode CheckNumber(MPI_Comm comm, const char full[], const char value[])
{
  char *end;
  PetscFunctionBeginUser;
  (void)strtod(value, &end);
  PetscCheck(end != value && !*end, comm, PETSC_ERR_ARG_WRONG, "%s %s: not a number", full, value);
  PetscFunctionReturn(0);
}

/* The raw value of an option of the given kind: present with a value ("needs <what>"), an integer PetscInt holds
   (integer), no longer than len - 1 characters (len > 0: a string read into a buffer of len). */
typedef enum { RAW_NUMBER, RAW_INTEGER, RAW_TEXT } RawKind;
static PetscErrorCode CheckRaw(PetscOptionItems *items, const char opt[], RawKind kind, size_t len)
{
  const char *what[] = {"a number", "an integer value", "a value"};
  const char *value;
  PetscBool   found;
  char        full[256];
  PetscFunctionBeginUser;
  PetscCall(RawValue(items, opt, &value, &found, full, sizeof(full)));
  if (!found) PetscFunctionReturn(0);
  PetscCheck(!Empty(value), items->comm, PETSC_ERR_ARG_WRONG, "%s: needs %s", full, what[kind]);
  if (kind == RAW_INTEGER) PetscCall(CheckInteger(items->comm, full, value));
  if (kind == RAW_NUMBER) PetscCall(CheckNumber(items->comm, full, value));
  PetscCheck(!len || strlen(value) < len, items->comm, PETSC_ERR_ARG_SIZ, "%s: the value is %zu characters long, at most %zu are read (it would be cut)", full, strlen(value), len - 1);
  PetscFunctionReturn(0);
}

PetscErrorCode CSOptionsInt_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscInt cur, PetscInt *val, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckRaw(items, opt, RAW_INTEGER, 0));
  PetscCall(PetscOptionsInt_Private(items, opt, text, man, cur, val, set, PETSC_MIN_INT, PETSC_MAX_INT));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOptionsReal_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], PetscReal cur, PetscReal *val, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckRaw(items, opt, RAW_NUMBER, 0));
  PetscCall(PetscOptionsReal_Private(items, opt, text, man, cur, val, set));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOptionsString_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], const char cur[], char val[], size_t len, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckRaw(items, opt, RAW_TEXT, len));
  PetscCall(PetscOptionsString_Private(items, opt, text, man, cur, val, len, set));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOptionsEList_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], const char *const *list, PetscInt n, const char cur[], PetscInt *val, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckRaw(items, opt, RAW_TEXT, 0)); /* a choice given without a value (-gen '') is refused */
  PetscCall(PetscOptionsEList_Private(items, opt, text, man, list, n, cur, val, set));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOptionsEnum_Private(PetscOptionItems *items, const char opt[], const char text[], const char man[], const char *const *list, PetscEnum cur, PetscEnum *val, PetscBool *set)
{
  PetscFunctionBeginUser;
  PetscCall(CheckRaw(items, opt, RAW_TEXT, 0)); /* a choice given without a value (-gen '') is refused */
  PetscCall(PetscOptionsEnum_Private(items, opt, text, man, list, cur, val, set));
  PetscFunctionReturn(0);
}
