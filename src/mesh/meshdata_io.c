/* Public entry points for serial triangle meshes: read and write by file extension (the formats live in
   meshdata_obj.c, meshdata_off.c, meshdata_ply.c), destroy, duplicate. */
#include "meshdata_reader.h"
#include "cs_util.h"
#include <errno.h>
#include <string.h>

PetscErrorCode CSMeshDataRead(const char path[], CSMeshData *md)
{
  Reader         r;
  char           ext[16];
  PetscErrorCode code;

  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(md, sizeof(*md)));
  PetscCall(PetscMemzero(&r, sizeof(r)));
  r.path = path;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCheck(!strcmp(ext, "obj") || !strcmp(ext, "off") || !strcmp(ext, "ply"), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s: unknown mesh file extension '.%s' (expected .obj, .off or .ply)", path, ext);
  PetscCall(CSReaderLoad(&r, &code));
  if (r.msg[0]) {
    PetscCall(CSReaderFree(&r));
    SETERRQ(PETSC_COMM_SELF, code, "%s", r.msg);
  }
  if (!strcmp(ext, "obj")) PetscCall(CSMeshDataReadOBJ(&r));
  else if (!strcmp(ext, "off")) PetscCall(CSMeshDataReadOFF(&r));
  else PetscCall(CSMeshDataReadPLY(&r));
  if (r.msg[0]) {
    PetscCall(CSReaderFree(&r));
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "%s", r.msg);
  }
  PetscCall(PetscFree(r.buf));
  md->nv = r.nv;
  md->nf = r.nf;
  md->x  = r.x;
  md->f  = r.f;
  PetscCall(PetscStrncpy(md->name, path, sizeof(md->name)));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataWrite(const char path[], const CSMeshData *md)
{
  char      ext[16];
  FILE     *fp;
  PetscBool ok = PETSC_TRUE;

  PetscFunctionBeginUser;
  PetscCall(CSPathExtension(path, ext, sizeof(ext)));
  PetscCheck(!strcmp(ext, "obj") || !strcmp(ext, "off") || !strcmp(ext, "ply"), PETSC_COMM_SELF, PETSC_ERR_ARG_WRONG, "%s: unknown mesh file extension '.%s' (write .obj, .off or .ply)", path, ext);
  PetscCall(CSPathMakeParents(path));
  fp = fopen(path, "wb");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "%s: cannot open for writing (%s)", path, strerror(errno));
  if (!strcmp(ext, "obj")) PetscCall(CSMeshDataWriteOBJ(fp, md));
  else if (!strcmp(ext, "off")) PetscCall(CSMeshDataWriteOFF(fp, md));
  else PetscCall(CSMeshDataWritePLY(fp, md, &ok));
  ok = (PetscBool)(ok && !ferror(fp));
  ok = (PetscBool)(!fclose(fp) && ok);
  PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "%s: write error (%s)", path, strerror(errno));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataDestroy(CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCall(PetscFree(md->x));
  PetscCall(PetscFree(md->f));
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
  PetscFunctionReturn(0);
}
