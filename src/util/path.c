#include "cs_util.h"
#include <ctype.h>

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
