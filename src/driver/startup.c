/* What bin/confsurf does before MPI starts: the start-up defaults of a serial run (an MPI singleton) and the
   private folder Open MPI's session tree goes into (issue 36, item 2). */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <fcntl.h>
#include <ftw.h>
#include <sys/stat.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "cs_driver.h"

static char SessionBase[4096]; /* the private folder, removed at exit; "" when none */

static int RemoveEntry(const char *path, const struct stat *st, int flag, struct FTW *ftw)
{
  (void)st;
  (void)flag;
  (void)ftw;
  (void)remove(path);
  return 0;
}

/* atexit: after MPI_Finalize (which empties its own tree) and on every exit() path, also MPI_Abort's */
static void SessionBaseRemove(void)
{
  if (!SessionBase[0]) return;
  (void)nftw(SessionBase, RemoveEntry, 16, FTW_DEPTH | FTW_PHYS);
  SessionBase[0] = 0;
}

/* Open MPI 4.1's isolated singleton (ess_singleton_isolated, opal/mca/pmix/isolated) names every process [[0,1],0],
   so all serial runs of a user share one session tree, $TMPDIR/ompi.<host>.<uid>/jf.0/1/0 (orte/util/session_dir.c).
   A run that finalizes removes that tree (proc, job, job-family and top folders) while another one that starts is
   creating it one folder at a time (opal_os_dirpath_create): its mkdir fails with ENOENT and MPI_Init aborts
   (3 of 400 runs of 8 concurrent `-task info`, runs/startup_race.sh). Each run gets its own tree instead: Open MPI's
   orte_tmpdir_base points at a fresh mkdtemp folder under $TMPDIR (or /tmp), removed at exit. Not when the user
   chose a tmpdir base (any of Open MPI's three parameters), and not when the folder cannot be made (then the shared
   tree, as before). A run killed by a signal Open MPI does not catch (SIGKILL) leaves its folder behind: a few empty
   folders, /tmp/confsurf-mpi.XXXXXX/ompi.<host>.<uid>/jf.0/1/0, as Open MPI itself leaves its tree then. */
static void PrivateSessionTree(void)
{
  const char *tmp = getenv("TMPDIR");
  if (getenv("OMPI_MCA_orte_tmpdir_base") || getenv("OMPI_MCA_orte_local_tmpdir_base") || getenv("OMPI_MCA_orte_remote_tmpdir_base")) return;
  if (!tmp || !tmp[0]) tmp = "/tmp";
  if (snprintf(SessionBase, sizeof(SessionBase), "%s/confsurf-mpi.XXXXXX", tmp) >= (int)sizeof(SessionBase) || !mkdtemp(SessionBase)) {
    SessionBase[0] = 0;
    return;
  }
  if (atexit(SessionBaseRemove)) {
    (void)rmdir(SessionBase);
    SessionBase[0] = 0;
    return;
  }
  setenv("OMPI_MCA_orte_tmpdir_base", SessionBase, 1);
}

/* Start-up of a serial run (an MPI singleton, not started by mpirun): Open MPI's defaults spawn a helper daemon
   (ess singleton), open UCX and every transport (pml, btl) and let hwloc load its GL/OpenCL/PCI/libxml plugins (X11,
   libicu) and opens nine collective components; for one process none of that is used. Measured (docs/output.md):
   MPI_Init 384 ms -> 46 ms, the tiny -task info run 0.60 s -> 0.14 s wall. Set only
   what the user did not set; CS_MPI_DEFAULTS=0 turns it off (and the private session tree with it). */
void CSSingletonDefaults(void)
{
  const char *off = getenv("CS_MPI_DEFAULTS");
  if (off && !strcmp(off, "0")) return;
  if (getenv("OMPI_COMM_WORLD_SIZE") || getenv("PMIX_RANK") || getenv("PMI_RANK")) return; /* under a launcher */
  setenv("OMPI_MCA_ess_singleton_isolated", "1", 0);
  setenv("OMPI_MCA_pml", "ob1", 0);
  setenv("OMPI_MCA_btl", "self", 0);
  setenv("OMPI_MCA_coll", "self,basic,libnbc", 0);
  setenv("HWLOC_PLUGINS_BLACKLIST", "hwloc_gl,hwloc_opencl,hwloc_pci,hwloc_xml_libxml", 0);
  PrivateSessionTree();
}

/* The files PetscInitialize opens itself, before any error handler of ours (issue 18, item 1; issue 36, items 1, 4,
   19), checked before MPI starts in every source PETSc reads them from (the command line, PETSC_OPTIONS, the
   options files, ~/.petscrc, .petscrc, petscrc; not the YAML ones): PETSc's -history FILE is opened with
   fopen(FILE, "a") by rank 0 and its failure is not caught (PetscOpenHistoryFile checks the pointer to the FILE *,
   then writes through NULL: SIGSEGV, or the other ranks hang); a FIFO nobody writes blocks PETSc's read of an options
   file, a FIFO nobody reads its open of -history; a folder as -options_file printed PETSc's whole error block. Every
   rank comes to the same conclusion on the same file system; rank 0 prints the line. */
#define CS_OPTIONS_DEPTH 8

static void StartupError(const char *fmt, const char *opt, const char *path, const char *why)
{
  const char *rank = getenv("OMPI_COMM_WORLD_RANK");
  if (rank && strcmp(rank, "0")) return;
  fprintf(stderr, fmt, opt, path, why);
  fflush(stderr);
}

/* PETSc's -history target: appended to, never replaced */
/* 1: usable, 0: refused (said), -1: another process of this run (a rank of the same mpirun, all checking the same
   path at once) created or removed the file between the stat and the open: look again */
static int HistoryUsableOnce(const char *path)
{
  struct stat st;
  int         fd;
  const char *fmt = "confsurf: error: %s %s: cannot write there (%s); PETSc's -history logs the options, the flows' table is -history_csv\n";
  if (!stat(path, &st)) {
    if (S_ISDIR(st.st_mode)) return StartupError(fmt, "-history", path, "is a folder"), 0;
    if (!S_ISREG(st.st_mode) && !S_ISCHR(st.st_mode)) { /* a FIFO: usable only when something reads it */
      if ((fd = open(path, O_WRONLY | O_NONBLOCK)) < 0) return StartupError(fmt, "-history", path, errno == ENXIO ? "a FIFO nobody reads (it would block)" : strerror(errno)), 0;
      close(fd);
      return 1;
    }
    if ((fd = open(path, O_WRONLY | O_APPEND | O_NONBLOCK)) < 0) return errno == ENOENT ? -1 : (StartupError(fmt, "-history", path, strerror(errno)), 0);
    close(fd);
    return 1;
  }
  if (errno != ENOENT) return StartupError(fmt, "-history", path, strerror(errno)), 0;
  /* created and removed again: a permission test (access) passes for root where the file system refuses */
  if ((fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0666)) < 0) {
    char why[256];
    if (errno == EEXIST) return -1;
    snprintf(why, sizeof(why), "cannot create it: %s", strerror(errno));
    return StartupError(fmt, "-history", path, why), 0;
  }
  close(fd);
  (void)unlink(path);
  return 1;
}

/* -history's file can be written. Every rank of an mpirun checks before MPI exists, so two ranks can race on the
   probe file (one's O_EXCL create fails with "File exists" while the other holds it: make test failed at random on 2
   ranks); a race is looked at again, a bounded number of times. */
static int HistoryUsable(const char *path)
{
  for (int k = 0; k < 100; k++) {
    int r = HistoryUsableOnce(path);
    if (r >= 0) return r;
  }
  return StartupError("confsurf: error: %s %s: cannot write there (%s); PETSc's -history logs the options, the flows' table is -history_csv\n", "-history", path, "it keeps appearing and disappearing"), 0;
}

/* an options file: a regular file that can be read (a folder, FIFO or device is refused without opening it) */
static int OptionsFileUsable(const char *opt, const char *path, int required)
{
  struct stat st;
  const char *fmt = "confsurf: error: %s %s: cannot read it (%s)\n";
  if (stat(path, &st)) return (!required && errno == ENOENT) ? 1 : (StartupError(fmt, opt, path, strerror(errno)), 0);
  if (S_ISDIR(st.st_mode)) return StartupError(fmt, opt, path, "is a folder, not an options file"), 0;
  if (!S_ISREG(st.st_mode)) return StartupError(fmt, opt, path, "is not a regular file (a FIFO or device would block the read)"), 0;
  if (access(path, R_OK)) return StartupError(fmt, opt, path, strerror(errno)), 0;
  return 1;
}

static int ScanFile(const char *path, int depth);

/* one option and its value (NULL when none): the checks of -history and -options_file */
static int ScanOption(const char *key, const char *value, int depth)
{
  if (!strcmp(key, "-history")) {
    char        home[4096];
    const char *h = getenv("HOME");
    if (value) return HistoryUsable(value);
    snprintf(home, sizeof(home), "%s/.petschistory", h ? h : "");
    return HistoryUsable(home); /* PETSc's default history file */
  }
  if (!strcmp(key, "-options_file")) {
    if (!value) return StartupError("confsurf: error: %s%s%s: needs a file name\n", key, "", ""), 0;
    if (depth >= CS_OPTIONS_DEPTH) return StartupError("confsurf: error: %s %s: %s\n", key, value, "options files nested more than 8 deep (a file that names itself?)"), 0;
    return OptionsFileUsable(key, value, 1) && ScanFile(value, depth + 1);
  }
  return 1;
}

/* the next blank-separated token of *s, "..." quoted as PETSc's PetscToken reads it; NULL at the end */
static char *NextToken(char **s)
{
  char *p = *s, *t;
  while (*p == ' ' || *p == '\t' || *p == '\n' || *p == '\r') p++;
  if (!*p) return NULL;
  if (*p == '"') {
    t = ++p;
    while (*p && *p != '"') p++;
  } else {
    t = p;
    while (*p && *p != ' ' && *p != '\t' && *p != '\n' && *p != '\r') p++;
  }
  if (*p) *p++ = 0;
  *s = p;
  return t;
}

/* a value is any token that is not an option name (a negative number is a value) */
static int IsKey(const char *t)
{
  return t && t[0] == '-' && t[1] && !(t[1] >= '0' && t[1] <= '9') && t[1] != '.';
}

static int ScanTokens(char **tok, int n, int depth)
{
  for (int i = 0; i < n; i++) {
    if (!IsKey(tok[i])) continue;
    if (!ScanOption(tok[i], i + 1 < n && !IsKey(tok[i + 1]) && tok[i + 1][0] ? tok[i + 1] : NULL, depth)) return 0;
  }
  return 1;
}

static int ScanString(char *s, int depth)
{
  char **tok = malloc((strlen(s) / 2 + 1) * sizeof(char *)), *t; /* at most one token per two characters */
  int    n   = 0, ok;
  if (!tok) return 1; /* no memory for the check: PETSc reads the string itself */
  while ((t = NextToken(&s))) tok[n++] = t;
  ok = ScanTokens(tok, n, depth);
  free(tok);
  return ok;
}

/* an options file as PETSc reads it: one option (and its value) per line, '#' starts a comment */
static int ScanFile(const char *path, int depth)
{
  FILE  *fp = fopen(path, "r");
  char  *line = NULL;
  size_t cap  = 0;
  int    ok   = 1;
  if (!fp) return 1; /* not there (an optional petscrc): PETSc reports the required ones */
  while (ok && getline(&line, &cap, fp) > 0) {
    char *hash = strchr(line, '#'), *s = line, *tok[2];
    int   n    = 0;
    if (hash) *hash = 0;
    while (n < 2 && (tok[n] = NextToken(&s))) n++;
    ok = ScanTokens(tok, n, depth);
  }
  free(line);
  fclose(fp);
  return ok;
}

int CSStartupFilesUsable(int argc, char **argv)
{
  const char *env = getenv("PETSC_OPTIONS"), *home = getenv("HOME");
  char        rc[4096];
  int         ok = 1;
  if (home) {
    snprintf(rc, sizeof(rc), "%s/.petscrc", home);
    ok = OptionsFileUsable("~/.petscrc", rc, 0) && ScanFile(rc, 1);
  }
  ok = ok && OptionsFileUsable(".petscrc", ".petscrc", 0) && ScanFile(".petscrc", 1);
  ok = ok && OptionsFileUsable("petscrc", "petscrc", 0) && ScanFile("petscrc", 1);
  if (ok && env) {
    char *copy = strdup(env);
    ok         = copy && ScanString(copy, 0);
    free(copy);
  }
  ok = ok && ScanTokens(argv + 1, argc - 1, 0);
  if (!ok && getenv("OMPI_COMM_WORLD_RANK") && strcmp(getenv("OMPI_COMM_WORLD_RANK"), "0")) sleep(2); /* mpirun ends the job at the first failed rank: let rank 0 print first */
  return ok;
}
