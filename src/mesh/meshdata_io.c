/* Public entry points for serial triangle meshes: read and write by file extension (the formats live in
   meshdata_obj.c, meshdata_off.c, meshdata_ply.c), destroy, duplicate. */
#include "meshdata_reader.h"
#include "cs_util.h"
#include <string.h>

static PetscErrorCode ReadFormat(Reader *r, const char ext[])
{
  PetscFunctionBeginUser;
  if (!strcmp(ext, "obj")) PetscCall(CSMeshDataReadOBJ(r));
  else if (!strcmp(ext, "off")) PetscCall(CSMeshDataReadOFF(r));
  else PetscCall(CSMeshDataReadPLY(r));
  PetscFunctionReturn(0);
}

/* The file is read whole (CSFileLoad: a folder or FIFO refused, a UTF-8 byte-order mark skipped), then parsed; an
   error of the parser (out of memory included) names the file. */
PetscErrorCode CSMeshDataRead(const char path[], CSMeshData *md)
{
  Reader         r;
  char           ext[16], name[PETSC_MAX_PATH_LEN];
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(md, sizeof(*md)));
  PetscCall(PetscMemzero(&r, sizeof(r)));
  PetscCall(CSPathSanitize(path, name, sizeof(name)));
  r.path = name;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCall(CSFileLoad("mesh", path, &r.buf, &r.len)); /* first: a folder or FIFO is named as such, whatever its name */
  if (strcmp(ext, "obj") && strcmp(ext, "off") && strcmp(ext, "ply")) {
    PetscCall(PetscFree(r.buf));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: unknown mesh file extension '.%s' (expected .obj, .off or .ply)", name, ext);
  }
  CSCaptureError(ierr, ReadFormat(&r, ext));
  if (ierr && !r.msg[0]) {
    const char *text;
    char       *specific = NULL;
    PetscCall(PetscErrorMessage(ierr, &text, &specific));
    CSReaderFail(&r, "%s: %s", name, specific ? specific : text);
  }
  if (r.msg[0]) {
    PetscCall(CSReaderFree(&r));
    SETERRQ(PETSC_COMM_SELF, ierr ? ierr : PETSC_ERR_FILE_UNEXPECTED, "%s", r.msg);
  }
  PetscCall(PetscFree(r.buf));
  PetscCall(CSReaderTake(&r, md));
  PetscCall(PetscStrncpy(md->name, name, sizeof(md->name))); /* printed and written into headers: sanitised */
  PetscFunctionReturn(0);
}

/* Not collective (the caller's rank writes); the name goes into the header sanitised, a failed write or close
   removes the file (CSFile) */
PetscErrorCode CSMeshDataWrite(const char path[], const CSMeshData *md)
{
  char       ext[16];
  CSFile     f;
  PetscBool  ok = PETSC_TRUE;
  CSMeshData w  = *md;

  PetscFunctionBeginUser;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCheck(!strcmp(ext, "obj") || !strcmp(ext, "off") || !strcmp(ext, "ply"), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: unknown mesh file extension '.%s' (write .obj, .off or .ply)", path, ext);
  PetscCall(CSPathSanitize(md->name, w.name, sizeof(w.name))); /* a newline in it would add a line to the file */
  PetscCall(CSFileOpen(PETSC_COMM_SELF, PETSC_TRUE, "-o", path, PETSC_FALSE, &f));
  if (!strcmp(ext, "obj")) PetscCall(CSMeshDataWriteOBJ(f.fp, &w));
  else if (!strcmp(ext, "off")) PetscCall(CSMeshDataWriteOFF(f.fp, &w));
  else PetscCall(CSMeshDataWritePLY(f.fp, &w, &ok));
  if (!ok) PetscCall(CSFileDiscard(&f));
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-o %s: write error", path);
  PetscCall(CSFileClose(PETSC_COMM_SELF, &f));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataDestroy(CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(md->x));
  PetscCall(PetscFree(md->f));
  PetscCall(PetscFree(md->len));
  PetscCall(PetscFree(md->cr));
  PetscCall(PetscFree(md->uv));
  PetscCall(PetscFree(md->fuv));
  md->nuv     = 0;
  md->nv      = 0;
  md->nf      = 0;
  md->name[0] = 0;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataDuplicate(const CSMeshData *in, CSMeshData *out)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(out, sizeof(*out)));
  out->nv = in->nv;
  out->nf = in->nf;
  PetscCall(PetscMalloc1(3 * in->nv, &out->x));
  PetscCall(PetscMalloc1(3 * in->nf, &out->f));
  PetscCall(PetscArraycpy(out->x, in->x, 3 * in->nv));
  PetscCall(PetscArraycpy(out->f, in->f, 3 * in->nf));
  PetscCall(PetscStrncpy(out->name, in->name, sizeof(out->name)));
  if (in->len) {
    PetscCall(PetscMalloc1(3 * in->nf, &out->len));
    PetscCall(PetscArraycpy(out->len, in->len, 3 * in->nf));
  }
  if (in->cr) {
    PetscCall(PetscMalloc1(3 * in->nf, &out->cr));
    PetscCall(PetscArraycpy(out->cr, in->cr, 3 * in->nf));
  }
  if (in->fuv) { /* texture coordinates per face corner (issue 38) */
    out->nuv = in->nuv;
    PetscCall(PetscMalloc1(2 * in->nuv, &out->uv));
    PetscCall(PetscMalloc1(3 * in->nf, &out->fuv));
    PetscCall(PetscArraycpy(out->uv, in->uv, 2 * in->nuv));
    PetscCall(PetscArraycpy(out->fuv, in->fuv, 3 * in->nf));
  }
  PetscFunctionReturn(0);
}
