/* Every file confsurf writes goes through CSFileOpen/CSFileFlush/CSFileClose, collective on the communicator of the
   object that writes it (issue 18, items 1, 5, 9): the ranks that write (mine) open, flush and close their file,
   and the outcome of each step reaches every rank (CSSyncError), so a file that fails on one rank cannot leave the
   others waiting in the next collective. A failed write is caught through the stream's error indicator, the flush
   and the close, so a full disk is an error naming the file, not a silently short output. On any failure the file
   is removed: nothing half-written is left behind. An atomic file is written under a unique temporary name,
   synced to disk and renamed over the target, which must be a regular file (or absent). */
#include "cs_util.h"
#include <errno.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <unistd.h>

/* an existing target that is not a regular file (a folder, a device, a FIFO) is refused */
static PetscErrorCode CheckTarget(CSFile *f, PetscBool atomic)
{
  struct stat st;
  char        name[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  f->regular = PETSC_TRUE;
  if (lstat(f->path, &st)) PetscFunctionReturn(0);
  f->regular = (PetscBool)S_ISREG(st.st_mode); /* a device written to (-o /dev/stdout) is never removed */
  PetscCall(CSPathSanitize(f->path, name, sizeof(name)));
  PetscCheck(!S_ISDIR(st.st_mode), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: is a folder, cannot write a file there", f->what, name);
  PetscCheck(!atomic || S_ISREG(st.st_mode), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: exists and is not a regular file (a link, device or FIFO): refusing to replace it", f->what, name);
  PetscFunctionReturn(0);
}

static PetscErrorCode OpenLocal(CSFile *f, PetscBool atomic)
{
  char name[PETSC_MAX_PATH_LEN];
  int  fd = -1;
  PetscFunctionBeginUser;
  PetscCall(CSPathSanitize(f->path, name, sizeof(name)));
  PetscCall(CSPathMakeParents(f->path));
  PetscCall(CheckTarget(f, atomic));
  if (atomic) { /* unique: two runs writing the same checkpoint cannot collide */
    const char *slash = strrchr(f->path, '/'), *base = slash ? slash + 1 : f->path;
    /* the target's name with .XXXXXX, its name cut so that the whole stays within NAME_MAX (255) */
    PetscCall(PetscSNPrintf(f->tmp, sizeof(f->tmp), "%.*s%.*s.XXXXXX", (int)(base - f->path), f->path, (int)PetscMin(strlen(base), (size_t)(NAME_MAX - 7)), base));
    fd = mkstemp(f->tmp);
    PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot create a temporary file beside it (%s)", f->what, name, strerror(errno));
    {
      mode_t um = umask(0); /* mkstemp makes it 0600: the usual permissions instead */
      umask(um);
      (void)fchmod(fd, 0666 & ~um);
    }
    f->fp = fdopen(fd, "wb");
  } else { /* non-blocking open: a FIFO nobody reads is refused (ENXIO) instead of waiting for a reader */
    f->tmp[0] = 0;
    fd        = open(f->path, O_WRONLY | O_CREAT | O_TRUNC | O_NONBLOCK, 0666);
    PetscCheck(fd >= 0 || errno != ENXIO, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: a FIFO nobody reads (writing would block)", f->what, name);
    if (fd >= 0) {
      (void)fcntl(fd, F_SETFL, fcntl(fd, F_GETFL) & ~O_NONBLOCK);
      f->fp = fdopen(fd, "wb");
    }
  }
  if (!f->fp && fd >= 0) {
    close(fd);
    if (atomic) (void)remove(f->tmp);
  }
  PetscCheck(f->fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot open for writing (%s)", f->what, name, strerror(errno));
  f->created = (PetscBool)(atomic || f->regular);
  PetscFunctionReturn(0);
}

/* Removes what this rank has written so far (after a failure anywhere); a file of records (keep) is cut back to
   the records of the last flush that succeeded instead: a full disk must not cost the rows already written */
static void Discard(CSFile *f)
{
  if (f->keep && f->fp) {
    if (ftruncate(fileno(f->fp), f->good)) { /* a record half-written when the disk filled: cut it; if that fails, it stays */ }
    f->created = PETSC_FALSE;
  }
  if (f->fp) (void)fclose(f->fp);
  f->fp = NULL;
  if (f->created) (void)remove(f->tmp[0] ? f->tmp : f->path);
  f->created = PETSC_FALSE;
}

/* Every rank learns whether ierr is set anywhere; if so, each discards its file and raises the first error. */
static PetscErrorCode Settle(MPI_Comm comm, CSFile *f, PetscErrorCode ierr)
{
  int bad = ierr ? 1 : 0, any;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Allreduce(&bad, &any, 1, MPI_INT, MPI_MAX, comm));
  if (any && f->mine) Discard(f);
  PetscCall(CSSyncError(comm, ierr));
  PetscFunctionReturn(0);
}

PetscErrorCode CSFileOpen(MPI_Comm comm, PetscBool mine, const char what[], const char path[], PetscBool atomic, CSFile *f)
{
  PetscErrorCode ierr = 0;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(f, sizeof(*f)));
  f->mine   = mine;
  f->atomic = atomic;
  PetscCall(PetscStrncpy(f->what, what, sizeof(f->what)));
  PetscCall(PetscStrncpy(f->path, path, sizeof(f->path)));
  if (mine) CSCaptureError(ierr, OpenLocal(f, atomic));
  PetscCall(Settle(comm, f, ierr));
  PetscFunctionReturn(0);
}

/* the stream's error indicator and the flush: a write that failed since the last check */
static PetscErrorCode FlushLocal(CSFile *f, PetscBool sync)
{
  char name[PETSC_MAX_PATH_LEN];
  int  bad;
  PetscFunctionBeginUser;
  errno = 0;
  bad   = fflush(f->fp) || ferror(f->fp) || (sync && fsync(fileno(f->fp)));
  PetscCall(CSPathSanitize(f->path, name, sizeof(name)));
  PetscCheck(!bad || !f->keep, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s %s: write error (%s); kept the %" PetscInt_FMT " complete rows written before it", f->what, name, errno ? strerror(errno) : "stream error", f->records);
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s %s: write error (%s)", f->what, name, errno ? strerror(errno) : "stream error");
  if (f->keep) f->good = ftell(f->fp);
  PetscFunctionReturn(0);
}

PetscErrorCode CSFileFlush(MPI_Comm comm, CSFile *f)
{
  PetscErrorCode ierr = 0;
  PetscFunctionBeginUser;
  if (f->fp) CSCaptureError(ierr, FlushLocal(f, PETSC_FALSE));
  PetscCall(Settle(comm, f, ierr));
  PetscFunctionReturn(0);
}

static PetscErrorCode CloseLocal(CSFile *f)
{
  char name[PETSC_MAX_PATH_LEN];
  int  bad;
  PetscFunctionBeginUser;
  PetscCall(FlushLocal(f, f->atomic));
  PetscCall(CSPathSanitize(f->path, name, sizeof(name)));
  errno = 0;
  bad   = fclose(f->fp);
  f->fp = NULL;
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s %s: write error on close (%s)", f->what, name, strerror(errno));
  if (f->atomic) {
    PetscCall(CheckTarget(f, PETSC_TRUE)); /* it may have appeared since the open */
    PetscCheck(!rename(f->tmp, f->path), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s %s: cannot rename the temporary file to it (%s)", f->what, name, strerror(errno));
    f->tmp[0]  = 0;
    f->created = PETSC_FALSE; /* the target is replaced: nothing of ours to remove */
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSFileClose(MPI_Comm comm, CSFile *f)
{
  PetscErrorCode ierr = 0;
  PetscFunctionBeginUser;
  if (f->fp) CSCaptureError(ierr, CloseLocal(f));
  PetscCall(Settle(comm, f, ierr));
  PetscFunctionReturn(0);
}

/* Not collective: for the error paths of a writer (the file is removed) */
PetscErrorCode CSFileDiscard(CSFile *f)
{
  PetscFunctionBeginUser;
  Discard(f);
  PetscFunctionReturn(0);
}

/* Not collective: whether path can take an output, tested before any work (issue 36, item 13) and without touching
   an existing file: a folder, a FIFO nobody reads or a target that cannot be opened for writing (read-only file or
   file system, a parent that is a file) is refused; missing folders above it are created (as the writer would). */
PetscErrorCode CSFileCheckTarget(const char what[], const char path[])
{
  struct stat st;
  char        name[PETSC_MAX_PATH_LEN];
  int         fd;
  PetscFunctionBeginUser;
  PetscCall(CSPathSanitize(path, name, sizeof(name)));
  if (!stat(path, &st)) {
    PetscCheck(!S_ISDIR(st.st_mode), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: is a folder, cannot write a file there", what, name);
    fd = open(path, O_WRONLY | O_NONBLOCK); /* no O_TRUNC: the file stays as it is until the run writes it */
    PetscCheck(fd >= 0 || errno != ENXIO, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: a FIFO nobody reads (writing would block)", what, name);
    PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot write there (%s)", what, name, strerror(errno));
    close(fd);
    PetscFunctionReturn(0);
  }
  PetscCheck(errno == ENOENT, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot write there (%s)", what, name, strerror(errno));
  PetscCall(CSPathMakeParents(path));
  fd = open(path, O_WRONLY | O_CREAT | O_EXCL, 0666); /* a real test: access() passes for root on a read-only mount */
  PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot create it (%s)", what, name, strerror(errno));
  close(fd);
  (void)unlink(path);
  PetscFunctionReturn(0);
}

/* Not collective: a name for the file path is or would be, equal for two paths of the same file (through links,
   "./" or "..") so that two outputs to one file are caught; the path itself when its folder does not resolve. */
PetscErrorCode CSFileIdentity(const char path[], char id[], size_t len)
{
  char        dir[PETSC_MAX_PATH_LEN], real[PATH_MAX];
  const char *slash = strrchr(path, '/');
  PetscFunctionBeginUser;
  if (realpath(path, real)) PetscCall(PetscStrncpy(id, real, len));
  else {
    PetscCall(PetscSNPrintf(dir, sizeof(dir), "%.*s", slash ? (int)(slash - path + (slash == path)) : 1, slash ? path : "."));
    if (realpath(dir, real)) PetscCall(PetscSNPrintf(id, len, "%s/%s", real, slash ? slash + 1 : path));
    else PetscCall(PetscStrncpy(id, path, len));
  }
  PetscFunctionReturn(0);
}
