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

/* Creates the folders above a file about to be written (as mkdir -p), so that an options file can send its
   results to out/... on a fresh checkout. A component that exists as a file is left for the open to report. */
PetscErrorCode CSPathMakeParents(const char path[])
{
  char dir[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(PetscStrncpy(dir, path, sizeof(dir)));
  for (char *s = dir + 1; *s; s++) {
    if (*s != '/') continue;
    *s = 0;
    PetscCheck(!mkdir(dir, 0755) || errno == EEXIST, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s: cannot create the folder %s (%s)", path, dir, strerror(errno));
    *s = '/';
  }
  PetscFunctionReturn(0);
}
