/* ParaView output: each rank writes its own piece (its faces and their vertices, ghosts included) as a .vtu,
   rank 0 writes the .pvtu that joins the pieces and the .pvd series index. Nothing is gathered. */
#include "cs_mesh.h"
#include "cs_util.h"
#include <sys/stat.h>
#include <errno.h>

#define CS_VIEWER_MAX_FIELDS 16

typedef struct {
  char      name[64];
  PetscBool face;
  PetscInt  ncomp;
  Vec       local; /* ghosted copy (vertex fields) or a copy of the face field */
} CSViewerField;

struct _p_CSViewer {
  CSMesh        mesh;
  char          dir[PETSC_MAX_PATH_LEN];
  PetscInt      nfields, step;
  CSViewerField fields[CS_VIEWER_MAX_FIELDS];
  PetscReal    *times;
  PetscInt      ntimes_alloc;
};

PetscErrorCode CSViewerCreate(CSMesh mesh, const char dir[], CSViewer *v)
{
  PetscMPIInt rank;
  int         ok = 1;
  PetscFunctionBeginUser;
  PetscCall(PetscNew(v));
  (*v)->mesh = mesh;
  PetscCall(PetscStrncpy((*v)->dir, dir, sizeof((*v)->dir)));
  PetscCallMPI(MPI_Comm_rank(mesh->comm, &rank));
  if (!rank && mkdir(dir, 0755) && errno != EEXIST) ok = 0;
  PetscCallMPI(MPI_Bcast(&ok, 1, MPI_INT, 0, mesh->comm));
  PetscCheck(ok, mesh->comm, PETSC_ERR_FILE_OPEN, "-viewer_dir %s: cannot create the directory", dir);
  PetscFunctionReturn(0);
}

static PetscErrorCode AddField(CSViewer v, const char name[], Vec g, PetscBool face)
{
  CSViewerField *f;
  DM             dm;
  PetscInt       N;
  PetscFunctionBeginUser;
  PetscCheck(v->nfields < CS_VIEWER_MAX_FIELDS, v->mesh->comm, PETSC_ERR_ARG_OUTOFRANGE, "too many ParaView fields (at most %d)", CS_VIEWER_MAX_FIELDS);
  f = &v->fields[v->nfields++];
  PetscCall(PetscStrncpy(f->name, name, sizeof(f->name)));
  f->face = face;
  PetscCall(VecGetSize(g, &N));
  if (face) {
    f->ncomp = N / v->mesh->Nf;
    PetscCall(VecDuplicate(g, &f->local));
    PetscCall(VecCopy(g, f->local));
  } else {
    f->ncomp = N / v->mesh->Nv;
    PetscCheck(f->ncomp == 1 || f->ncomp == 3, v->mesh->comm, PETSC_ERR_ARG_WRONG, "vertex field %s: %" PetscInt_FMT " components (1 or 3 supported)", name, f->ncomp);
    dm = f->ncomp == 3 ? v->mesh->dmV3 : v->mesh->dmV1;
    PetscCall(DMCreateLocalVector(dm, &f->local));
    PetscCall(DMGlobalToLocal(dm, g, INSERT_VALUES, f->local));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSViewerAddVertexField(CSViewer v, const char name[], Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(AddField(v, name, g, PETSC_FALSE));
  PetscFunctionReturn(0);
}

PetscErrorCode CSViewerAddFaceField(CSViewer v, const char name[], Vec g)
{
  PetscFunctionBeginUser;
  PetscCall(AddField(v, name, g, PETSC_TRUE));
  PetscFunctionReturn(0);
}

static void WriteArray(FILE *fp, const char name[], PetscInt ncomp, PetscInt n, const PetscScalar *a)
{
  fprintf(fp, "<DataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"ascii\">\n", name, (int)ncomp);
  for (PetscInt i = 0; i < n * ncomp; i++) fprintf(fp, "%.10g%c", (double)PetscRealPart(a[i]), (i + 1) % ncomp ? ' ' : '\n');
  fprintf(fp, "</DataArray>\n");
}

static PetscErrorCode WritePiece(CSViewer v, Vec x, const char path[])
{
  CSMesh             m = v->mesh;
  FILE              *fp;
  Vec                xl;
  const PetscScalar *p;
  PetscFunctionBeginUser;
  fp = fopen(path, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-viewer_dir: cannot write %s", path);
  PetscCall(DMGetLocalVector(m->dmV3, &xl));
  PetscCall(DMGlobalToLocal(m->dmV3, x, INSERT_VALUES, xl));
  PetscCall(VecGetArrayRead(xl, &p));
  fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<UnstructuredGrid>\n");
  fprintf(fp, "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n<Points>\n", (int)m->nv, (int)m->nf);
  WriteArray(fp, "positions", 3, m->nv, p);
  fprintf(fp, "</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n");
  for (PetscInt f = 0; f < m->nf; f++) fprintf(fp, "%d %d %d\n", (int)m->faceVert[3 * f], (int)m->faceVert[3 * f + 1], (int)m->faceVert[3 * f + 2]);
  fprintf(fp, "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n");
  for (PetscInt f = 0; f < m->nf; f++) fprintf(fp, "%d\n", (int)(3 * f + 3));
  fprintf(fp, "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n");
  for (PetscInt f = 0; f < m->nf; f++) fprintf(fp, "5\n");
  fprintf(fp, "</DataArray>\n</Cells>\n<PointData>\n");
  PetscCall(VecRestoreArrayRead(xl, &p));
  PetscCall(DMRestoreLocalVector(m->dmV3, &xl));
  for (PetscInt k = 0; k < v->nfields; k++) {
    const PetscScalar *a;
    if (v->fields[k].face) continue;
    PetscCall(VecGetArrayRead(v->fields[k].local, &a));
    WriteArray(fp, v->fields[k].name, v->fields[k].ncomp, m->nv, a);
    PetscCall(VecRestoreArrayRead(v->fields[k].local, &a));
  }
  fprintf(fp, "</PointData>\n<CellData>\n");
  for (PetscInt k = 0; k < v->nfields; k++) {
    const PetscScalar *a;
    if (!v->fields[k].face) continue;
    PetscCall(VecGetArrayRead(v->fields[k].local, &a));
    WriteArray(fp, v->fields[k].name, v->fields[k].ncomp, m->nf, a);
    PetscCall(VecRestoreArrayRead(v->fields[k].local, &a));
  }
  fprintf(fp, "</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  PetscCheck(!fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-viewer_dir: error writing %s", path);
  PetscFunctionReturn(0);
}

/* The .pvtu joining the pieces and the .pvd index of every step so far (rewritten each step, so a killed run
   leaves a readable series). */
static PetscErrorCode WriteIndex(CSViewer v, PetscMPIInt size)
{
  char  path[PETSC_MAX_PATH_LEN];
  FILE *fp;
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/surface_%04d.pvtu", v->dir, (int)v->step));
  fp = fopen(path, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-viewer_dir: cannot write %s", path);
  fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PUnstructuredGrid GhostLevel=\"0\">\n");
  fprintf(fp, "<PPoints><PDataArray type=\"Float64\" Name=\"positions\" NumberOfComponents=\"3\"/></PPoints>\n<PPointData>\n");
  for (PetscInt k = 0; k < v->nfields; k++)
    if (!v->fields[k].face) fprintf(fp, "<PDataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"%d\"/>\n", v->fields[k].name, (int)v->fields[k].ncomp);
  fprintf(fp, "</PPointData>\n<PCellData>\n");
  for (PetscInt k = 0; k < v->nfields; k++)
    if (v->fields[k].face) fprintf(fp, "<PDataArray type=\"Float64\" Name=\"%s\" NumberOfComponents=\"%d\"/>\n", v->fields[k].name, (int)v->fields[k].ncomp);
  fprintf(fp, "</PCellData>\n");
  for (PetscMPIInt r = 0; r < size; r++) fprintf(fp, "<Piece Source=\"surface_%04d_%d.vtu\"/>\n", (int)v->step, (int)r);
  fprintf(fp, "</PUnstructuredGrid>\n</VTKFile>\n");
  PetscCheck(!fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-viewer_dir: error writing %s", path);

  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/series.pvd", v->dir));
  fp = fopen(path, "w");
  PetscCheck(fp, PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "-viewer_dir: cannot write %s", path);
  fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n");
  for (PetscInt s = 0; s <= v->step; s++) fprintf(fp, "<DataSet timestep=\"%.17g\" file=\"surface_%04d.pvtu\"/>\n", (double)v->times[s], (int)s);
  fprintf(fp, "</Collection>\n</VTKFile>\n");
  PetscCheck(!fclose(fp), PETSC_COMM_SELF, PETSC_ERR_FILE_WRITE, "-viewer_dir: error writing %s", path);
  PetscFunctionReturn(0);
}

PetscErrorCode CSViewerWriteStep(CSViewer v, Vec x, PetscReal time)
{
  char        path[PETSC_MAX_PATH_LEN];
  PetscMPIInt rank, size;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(v->mesh->comm, &rank));
  PetscCallMPI(MPI_Comm_size(v->mesh->comm, &size));
  PetscCall(CSArrayGrow(sizeof(PetscReal), v->step, 64, &v->ntimes_alloc, (void **)&v->times));
  v->times[v->step] = time;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/surface_%04d_%d.vtu", v->dir, (int)v->step, (int)rank));
  PetscCall(WritePiece(v, x, path));
  if (!rank) PetscCall(WriteIndex(v, size));
  for (PetscInt k = 0; k < v->nfields; k++) PetscCall(VecDestroy(&v->fields[k].local));
  v->nfields = 0;
  v->step++;
  PetscCallMPI(MPI_Barrier(v->mesh->comm));
  PetscFunctionReturn(0);
}

PetscErrorCode CSViewerDestroy(CSViewer *v)
{
  PetscFunctionBeginUser;
  if (!*v) PetscFunctionReturn(0);
  for (PetscInt k = 0; k < (*v)->nfields; k++) PetscCall(VecDestroy(&(*v)->fields[k].local));
  PetscCall(PetscFree((*v)->times));
  PetscCall(PetscFree(*v));
  PetscFunctionReturn(0);
}
