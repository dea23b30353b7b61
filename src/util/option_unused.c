/* Options given and not used, checked before the work starts (issue 36, item 18): a misspelled option
   (-flow_maxit 3) was reported only after the whole run with the defaults. The driver calls CSOptionsCheckUnused
   once every object of the task has read its options (after SetFromOptions/SetUp, before the first iteration,
   solve or output); the check at the end of the run (src/driver/main.c) stays for what is read later. */
#include "cs_util.h"
#include <ctype.h>
#include <stdlib.h>
#include <string.h>
#include <strings.h>

/* The names the project's readers looked up (option_read.c), given or not: the candidates of "did you mean". */
static char   **ReadNames = NULL;
static PetscInt NRead = 0, NReadAlloc = 0;

static PetscErrorCode ReadNamesDestroy(void)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < NRead; i++) PetscCall(PetscFree(ReadNames[i]));
  PetscCall(PetscFree(ReadNames));
  NRead = NReadAlloc = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSOptionsNoteRead(const char full[])
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < NRead; i++)
    if (!strcasecmp(ReadNames[i], full)) PetscFunctionReturn(0);
  if (!NReadAlloc) PetscCall(PetscRegisterFinalize(ReadNamesDestroy));
  PetscCall(CSArrayGrow(sizeof(char *), NRead, 64, &NReadAlloc, (void **)&ReadNames));
  PetscCall(PetscStrallocpy(full, &ReadNames[NRead++]));
  PetscFunctionReturn(0);
}

/* Options of PETSc's and SLEPc's solver objects: -<prefix><family>_..., e.g. -flow_saddle_ksp_rtol,
   -flow_saddle_fieldsplit_1_pc_cssubchol_ordering, -bs_semi_mat_mumps_icntl_7, -spin_st_ksp_type. They are not
   checked early: PETSc reads them when the solver is set up, which is lazy (a PCFIELDSPLIT makes its inner KSPs at
   its first PCSetUp, MUMPS reads -mat_mumps_* at the factorisation, the EPS of -task spin is made at the solve), so
   before the work they are legitimately unused. A misspelled one is still refused by the check at the end of the
   run. The families: KSP, PC (with the PCs' inner solvers fieldsplit_, sub_, mg_, redundant_, the project's csh2
   h2_), Mat (factor packages), SNES, TS, TAO, SLEPc's EPS, ST, BV, DS, RG, FN, and the objects PETSc views or sets
   up from the options when they are used (-vec_view at an assembly, -dm_*, -is_*, -sf_* at a scatter's set-up,
   -draw_*, -random_*). No option of the project's own has a component of these names (checked against every name
   its readers use; -viewer_* is the project's). */
static const char *const SolverFamilies[] = {"ksp_", "pc_", "mat_", "snes_", "ts_", "tao_", "eps_", "st_", "bv_", "ds_", "rg_", "fn_", "fieldsplit_", "sub_", "mg_", "redundant_", "h2_", "vec_", "dm_", "is_", "sf_", "draw_", "random_"};

static PetscBool IsSolverOption(const char name[])
{
  for (const char *p = name; *p; p++) {
    if (p != name && p[-1] != '_') continue; /* a family starts the name or follows an '_' */
    for (size_t i = 0; i < sizeof(SolverFamilies) / sizeof(SolverFamilies[0]); i++)
      if (!strncasecmp(p, SolverFamilies[i], strlen(SolverFamilies[i]))) return PETSC_TRUE;
  }
  return PETSC_FALSE;
}

/* PETSc's own options read after the check: -options_left in PetscFinalize (main.c marks it used before its own
   end-of-run check). */
static PetscBool IsReadLate(const char name[])
{
  return (PetscBool)!strcasecmp(name, "options_left");
}

/* Edit distance (insertions, deletions, substitutions, transpositions of neighbours), case-insensitive, capped at
   cap + 1: a name further away is no suggestion. */
static int Distance(const char *a, const char *b, int cap)
{
  int la = (int)strlen(a), lb = (int)strlen(b), d[3][128];
  if (la > 126 || lb > 126 || abs(la - lb) > cap) return cap + 1;
  for (int j = 0; j <= lb; j++) d[0][j] = j;
  for (int i = 1; i <= la; i++) {
    int *cur = d[i % 3], *prev = d[(i - 1) % 3], *prev2 = d[(i + 1) % 3], best;
    cur[0] = best = i;
    for (int j = 1; j <= lb; j++) {
      int sub = tolower((unsigned char)a[i - 1]) != tolower((unsigned char)b[j - 1]);
      cur[j] = PetscMin(PetscMin(prev[j] + 1, cur[j - 1] + 1), prev[j - 1] + sub);
      if (i > 1 && j > 1 && tolower((unsigned char)a[i - 1]) == tolower((unsigned char)b[j - 2]) && tolower((unsigned char)a[i - 2]) == tolower((unsigned char)b[j - 1])) cur[j] = PetscMin(cur[j], prev2[j - 2] + 1);
      best = PetscMin(best, cur[j]);
    }
    if (best > cap) return cap + 1;
  }
  return d[la % 3][lb];
}

/* The closest name the program looked up or used (within 2 edits, at most a third of the name), or NULL. */
static PetscErrorCode Suggest(const char name[], const char *const used[], PetscInt nused, const char **best)
{
  char dashed[256];
  int  cap = PetscMin(2, (int)strlen(name) / 3), bestd = cap + 1;
  PetscFunctionBeginUser;
  *best = NULL;
  PetscCall(PetscSNPrintf(dashed, sizeof(dashed), "-%s", name));
  for (PetscInt i = 0; i < NRead; i++) {
    int d = Distance(dashed, ReadNames[i], cap);
    if (d && d < bestd) bestd = d, *best = ReadNames[i];
  }
  for (PetscInt i = 0; i < nused; i++) {
    int d = Distance(dashed, used[i], cap);
    if (d && d < bestd) bestd = d, *best = used[i];
  }
  PetscFunctionReturn(0);
}

/* The given options that were used, "-name" each (the other candidates of a suggestion), from PETSc's list of
   all options ("-name value -name ..."; a token that starts with '-' and a letter is a name). */
static PetscErrorCode UsedNames(PetscInt *n, char ***names)
{
  char     *all, *s, *tok;
  PetscInt  N = 0, cap;
  PetscBool used;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsGetAll(NULL, &all));
  cap = (PetscInt)strlen(all) / 2 + 1;
  PetscCall(PetscMalloc1(cap, names));
  for (s = all; (tok = strtok(s, " ")); s = NULL) {
    if (tok[0] != '-' || !isalpha((unsigned char)tok[1])) continue;
    PetscCall(PetscOptionsUsed(NULL, tok + 1, &used));
    if (used && N < cap) PetscCall(PetscStrallocpy(tok, &(*names)[N++]));
  }
  PetscCall(PetscFree(all));
  *n = N;
  PetscFunctionReturn(0);
}

static PetscErrorCode NamesDestroy(PetscInt n, char ***names)
{
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < n; i++) PetscCall(PetscFree((*names)[i]));
  PetscCall(PetscFree(*names));
  PetscFunctionReturn(0);
}

/* " -name value (did you mean -other?)" appended to msg */
static PetscErrorCode Describe(const char name[], const char *const used[], PetscInt nused, char msg[], size_t len)
{
  const char *best, *value;
  char        dashed[256];
  size_t      at = strlen(msg);
  PetscBool   found;
  PetscFunctionBeginUser;
  PetscCall(Suggest(name, used, nused, &best));
  PetscCall(PetscSNPrintf(dashed, sizeof(dashed), "-%s", name));
  PetscCall(PetscOptionsFindPair(NULL, NULL, dashed, &value, &found));
  if (value && !value[0]) value = NULL;
  PetscCall(PetscSNPrintf(msg + at, len - at, "%s-%s%s%s%s%s%s", at ? ", " : "", name, value ? " " : "", value ? value : "", best ? " (did you mean " : "", best ? best : "", best ? "?)" : ""));
  PetscFunctionReturn(0);
}

/* The options unused on this rank that are checked early, "name\n" each. */
static PetscErrorCode CheckedUnused(char **list)
{
  PetscInt n;
  char   **names, **values;
  size_t   len = 1;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsLeftGet(NULL, &n, &names, &values));
  for (PetscInt i = 0; i < n; i++)
    if (!IsSolverOption(names[i]) && !IsReadLate(names[i])) len += strlen(names[i]) + 1;
  PetscCall(PetscMalloc1(len, list));
  (*list)[0] = 0;
  for (PetscInt i = 0; i < n; i++)
    if (!IsSolverOption(names[i]) && !IsReadLate(names[i])) strcat(strcat(*list, names[i]), "\n");
  PetscCall(PetscOptionsLeftRestore(NULL, &n, &names, &values));
  PetscFunctionReturn(0);
}

/* Rank 0's unused options, kept only if no rank used them (an option read on one rank only is not a typo): every
   rank reaches the same verdict, so the error is raised on all of them. */
static PetscErrorCode UnusedEverywhere(MPI_Comm comm, char **list, PetscInt *n, int **unused)
{
  PetscMPIInt rank;
  PetscInt64  len = 0;
  char       *s;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (!rank) {
    PetscCall(CheckedUnused(list));
    len = (PetscInt64)strlen(*list) + 1;
  }
  PetscCallMPI(MPI_Bcast(&len, 1, MPIU_INT64, 0, comm));
  if (rank) PetscCall(PetscMalloc1(len, list));
  PetscCallMPI(MPI_Bcast(*list, (PetscMPIInt)len, MPI_CHAR, 0, comm));
  *n = 0;
  for (s = *list; *s; s++) *n += (*s == '\n');
  PetscCall(PetscMalloc1(*n + 1, unused));
  s = *list;
  for (PetscInt i = 0; i < *n; i++) {
    char     *nl = strchr(s, '\n');
    PetscBool used;
    *nl = 0; /* the names stay separated by '\0' from here on */
    PetscCall(PetscOptionsUsed(NULL, s, &used));
    (*unused)[i] = !used;
    s = nl + 1;
  }
  PetscCallMPI(MPI_Allreduce(MPI_IN_PLACE, *unused, (PetscMPIInt)*n, MPI_INT, MPI_LAND, comm));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOptionsCheckUnused(MPI_Comm comm, const char task[])
{
  PetscInt    n, nbad = 0, nused;
  char       *list, **used, msg[2048] = "";
  const char *name;
  int        *unused;
  PetscBool   help;
  PetscFunctionBeginUser;
  PetscCall(PetscOptionsHasHelp(NULL, &help));
  if (help) PetscFunctionReturn(0); /* -task X -help sets the max_it options of every task (main.c) */
  PetscCall(UnusedEverywhere(comm, &list, &n, &unused));
  PetscCall(UsedNames(&nused, &used));
  name = list;
  for (PetscInt i = 0; i < n; name += strlen(name) + 1, i++)
    if (unused[i] && nbad++ < 8) PetscCall(Describe(name, (const char *const *)used, nused, msg, sizeof(msg)));
  PetscCall(NamesDestroy(nused, &used));
  PetscCall(PetscFree(unused));
  PetscCall(PetscFree(list));
  PetscCheck(!nbad, comm, PETSC_ERR_ARG_WRONG, "unknown option%s %s%s: not read by %s; nothing was run (a task's options: -task NAME -help)", nbad > 1 ? "s" : "", msg, nbad > 8 ? ", ..." : "", task);
  PetscFunctionReturn(0);
}
