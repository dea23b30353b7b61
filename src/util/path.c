#include "cs_util.h"
#include <ctype.h>
#include <errno.h>
#include <sys/stat.h>

/* Extension of a file name, lower-case, without the dot ("" when there is none). */
PetscErrorCode CSPathExtension(const char path[], char ext[], size_t len)
{
  const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
  PetscFunctionBeginUser;
  ext[0] = 0;
  if (!dot || (slash && dot < slash)) PetscFunctionReturn(0);
  PetscCall(PetscStrncpy(ext, dot + 1, len));
  for (size_t i = 0; ext[i]; i++) ext[i] = (char)tolower((unsigned char)ext[i]);
  PetscFunctionReturn(0);
}

/* path with suffix put before its extension ("out/a.obj", "_last" -> "out/a_last.obj"; no extension: appended), the
   extension found as CSPathExtension finds it; an error naming the path when out cannot hold the name. */
PetscErrorCode CSPathInsertSuffix(const char path[], const char suffix[], char out[], size_t len)
{
  const char *dot = strrchr(path, '.'), *slash = strrchr(path, '/');
  size_t      stem;
  PetscFunctionBeginUser;
  if (!dot || (slash && dot < slash)) dot = NULL;
  stem = dot ? (size_t)(dot - path) : strlen(path);
  PetscCheck(snprintf(out, len, "%.*s%s%s", (int)stem, path, suffix, dot ? dot : "") < (int)len, PETSC_COMM_SELF, PETSC_ERR_ARG_SIZ, "%s: the name with %s inserted is too long", path, suffix);
  PetscFunctionReturn(0);
}

/* Creates a folder and the folders above it (as mkdir -p): output folders (-viewer_dir) and the folders of output
   files may be new, so an options file can send its results to out/... on a fresh checkout. A component that
   exists as a file is refused here, or by the open that follows. */
PetscErrorCode CSPathMakeDir(const char dir[])
{
  char d[PETSC_MAX_PATH_LEN], name[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(d, dir, sizeof(d)));
  for (char *s = d + 1;; s++) {
    char c = *s;
    if (c && c != '/') continue;
    *s = 0;
    if (mkdir(d, 0755) && errno != EEXIST) {
      int err = errno;
      PetscCall(CSPathSanitize(d, name, sizeof(name)));
      SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot create the folder %s (%s)", name, strerror(err));
    }
    *s = c;
    if (!c) break;
  }
  PetscFunctionReturn(0);
}

/* The folders above a file about to be written (CSPathMakeDir of its directory part). */
PetscErrorCode CSPathMakeParents(const char path[])
{
  char        dir[PETSC_MAX_PATH_LEN];
  const char *slash = strrchr(path, '/');
  PetscFunctionBeginUser;
  if (!slash || slash == path) PetscFunctionReturn(0);
  PetscCall(PetscStrncpy(dir, path, PetscMin(sizeof(dir), (size_t)(slash - path + 1))));
  PetscCall(CSPathMakeDir(dir));
  PetscFunctionReturn(0);
}

/* A path or name as it may be written into a file header or printed (issue 18, item 8): control characters
   (a newline would add a line to an OBJ header, a \r breaks the JSON summary, an escape sequence drives the
   terminal) become '?', and a very long one keeps its head and tail around "...", so a message naming it still
   fits and ends with its reason. */
PetscErrorCode CSPathSanitize(const char in[], char out[], size_t len)
{
  size_t n = strlen(in), k = 0, keep = len > 8 ? (len - 4) / 2 : 0, cap = PetscMin(len - 1, (size_t)CS_NAME_SHOWN);
  PetscFunctionBeginUser;
  if (n > cap) keep = (cap - 3) / 2;
  for (size_t i = 0; i < n && k + 1 < len; i++) {
    unsigned char c = (unsigned char)in[i];
    if (n > cap && i == keep) {
      for (int d = 0; d < 3; d++) out[k++] = '.';
      i = n - keep - 1;
      continue;
    }
    out[k++] = (char)((c < 0x20 || c == 0x7f) ? '?' : c);
  }
  out[k] = 0;
  PetscFunctionReturn(0);
}
