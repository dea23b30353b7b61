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
    PetscCall(PetscSNPrintf(f->tmp, sizeof(f->tmp), "%s.XXXXXX", f->path));
    fd = mkstemp(f->tmp);
    PetscCheck(fd >= 0, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot create a temporary file beside it (%s)", f->what, name, strerror(errno));
    {
      mode_t um = umask(0); /* mkstemp makes it 0600: the usual permissions instead */
      umask(um);
      (void)fchmod(fd, 0666 & ~um);
    }
    f->fp = fdopen(fd, "wb");
  } else {
    f->tmp[0] = 0;
    f->fp     = fopen(f->path, "wb");
  }
  if (!f->fp && fd >= 0) {
    close(fd);
    (void)remove(f->tmp);
  }
  PetscCheck(f->fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s %s: cannot open for writing (%s)", f->what, name, strerror(errno));
  f->created = (PetscBool)(atomic || f->regular);
  PetscFunctionReturn(0);
}

/* Removes what this rank has written so far (after a failure anywhere) */
static void Discard(CSFile *f)
{
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
  PetscCheck(!bad, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s %s: write error (%s)", f->what, name, errno ? strerror(errno) : "stream error");
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
