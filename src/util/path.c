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

/* Creates a folder and the folders above it (as mkdir -p): output folders (-viewer_dir) and the folders of output
   files may be new, so an options file can send its results to out/... on a fresh checkout. A component that
   exists as a file is refused here, or by the open that follows. */
PetscErrorCode CSPathMakeDir(const char dir[])
{
  char d[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(d, dir, sizeof(d)));
  for (char *s = d + 1;; s++) {
    char c = *s;
    if (c && c != '/') continue;
    *s = 0;
    PetscCheck(!mkdir(d, 0755) || errno == EEXIST, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s: cannot create the folder %s (%s)", dir, d, strerror(errno));
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
