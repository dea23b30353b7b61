/* Reading a whole file, for the mesh readers and the value files (issue 18, items 3, 6, 11): a folder, a FIFO or a
   device is refused before anything blocks on it, a UTF-8 byte-order mark (editors on Windows write one) is
   dropped rather than glued to the first keyword, the size is known before any count from a header is believed,
   and running out of memory names the file. */
#include "cs_util.h"
#include <errno.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

static PetscErrorCode ReadAll(int fd, const char what[], const char name[], size_t size, char *buf, size_t *len)
{
  PetscFunctionBeginUser;
  *len = 0;
  while (*len < size) {
    ssize_t got = read(fd, buf + *len, size - *len);
    if (got < 0 && errno == EINTR) continue;
    PetscCheck(got >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_READ, "%s %s: read error (%s)", what, name, strerror(errno));
    if (!got) break; /* shrank while reading */
    *len += (size_t)got;
  }
  buf[*len] = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSFileLoad(const char what[], const char path[], char **buf, size_t *len)
{
  char           name[PETSC_MAX_PATH_LEN];
  struct stat    st;
  int            fd;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  *buf = NULL;
  *len = 0;
  PetscCall(CSPathSanitize(path, name, sizeof(name)));
  fd = open(path, O_RDONLY | O_NONBLOCK); /* O_NONBLOCK: opening a FIFO with no writer must not wait */
  PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot open for reading (%s)", what, name, strerror(errno));
  if (fstat(fd, &st)) st.st_mode = 0;
  if (!S_ISREG(st.st_mode)) {
    int isdir = S_ISDIR(st.st_mode);
    close(fd);
    PetscCheck(!isdir, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: is a folder, not a file", what, name);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: not a regular file (a FIFO, socket or device cannot be read)", what, name);
  }
  CSCaptureError(ierr, CSCheckAllocation(name, (PetscInt64)st.st_size + 1, 1));
  if (!ierr) CSCaptureError(ierr, PetscMalloc1((size_t)st.st_size + 1, buf));
  if (!ierr) CSCaptureError(ierr, ReadAll(fd, what, name, (size_t)st.st_size, *buf, len));
  close(fd);
  if (!ierr && *len >= 3 && !memcmp(*buf, "\xEF\xBB\xBF", 3)) { /* a UTF-8 byte-order mark is not content (item 4) */
    memmove(*buf, *buf + 3, *len - 3 + 1);
    *len -= 3;
  }
  if (ierr) {
    const char *text;
    char       *specific = NULL;
    PetscCall(PetscFree(*buf));
    PetscCall(PetscErrorMessage(ierr, &text, &specific));
    SETERRQ(PETSC_COMM_SELF, ierr, "%s", specific ? specific : text);
  }
  PetscFunctionReturn(0);
}
