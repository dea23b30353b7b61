/* ParaView output: each rank writes its own piece (its faces and their vertices, ghosts included) as a .vtu,
   rank 0 writes the .pvtu that joins the pieces and the .pvd series index. Nothing is gathered. */
#include "cs_mesh.h"
#include "cs_util.h"
#include "cs_log.h"
#include <zlib.h>

const char *const CSViewerFormats[] = {"ascii", "binary", "zlib", "CSViewerFormat", "CS_VIEWER_", NULL};

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
  CSViewerFormat format;
  PetscBool      single; /* -viewer_precision single: Float32 positions and fields */
  CSViewerField fields[CS_VIEWER_MAX_FIELDS];
  PetscReal    *times;
  PetscInt      ntimes_alloc;
};

PetscErrorCode CSViewerCreate(CSMesh mesh, const char prefix[], const char dir[], CSViewer *v)
{
  PetscFunctionBeginUser;
  CSRootCall(mesh->comm, CSPathMakeDir(dir)); /* before anything is allocated: no leak when it fails */
  PetscCall(PetscNew(v));
  (*v)->mesh = mesh;
  PetscCall(PetscStrncpy((*v)->dir, dir, sizeof((*v)->dir)));
  PetscCall(CSViewerFormatFromOptions(mesh->comm, prefix, &(*v)->format, &(*v)->single));
  PetscFunctionReturn(0);
}

PetscErrorCode CSViewerFormatFromOptions(MPI_Comm comm, const char prefix[], CSViewerFormat *format, PetscBool *single)
{
  const char *prec[] = {"double", "single"};
  PetscInt    ip     = 0;
  PetscFunctionBeginUser;
  *format = CS_VIEWER_BINARY;
  PetscOptionsBegin(comm, prefix, "ParaView output (-viewer_dir)", NULL);
  PetscCall(CSOptionsEnum("-viewer_format", "Data arrays of the .vtu pieces: appended raw binary, the same zlib-compressed, or ascii", "CSViewerSetFormat", CSViewerFormats, (PetscEnum)*format, (PetscEnum *)format, NULL));
  PetscCall(CSOptionsEList("-viewer_precision", "Positions and fields as Float64 (double) or Float32 (single: 7 digits, half the bytes)", "CSViewerSetFormat", prec, 2, prec[0], &ip, NULL));
  PetscOptionsEnd();
  *single = (PetscBool)(ip == 1);
  PetscFunctionReturn(0);
}

PetscErrorCode CSViewerSetFormat(CSViewer v, CSViewerFormat format, PetscBool single)
{
  PetscFunctionBeginUser;
  v->format = format;
  v->single = single;
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

/* One data array of a piece: its XML attributes and its values (Float64, the PetscInt type, or UInt8). */
typedef struct {
  char        name[64], type[8];
  PetscInt    ncomp;
  size_t      n, elsize; /* n values (tuples * ncomp) of elsize bytes */
  const void *data;
  void       *blob; /* zlib: the compressed blocks with their header */
  size_t      nblob;
} Array;

#define CS_VTU_BLOCK 65536

/* The bytes VTK reads for one appended array: binary, a UInt64 byte count then the data (written straight from
   the array); zlib, the header [nblocks, block size, last block's size, compressed size of each block] then the
   compressed blocks (level 1: the fastest; deflateBound of a block fits in compressBound). */
static PetscErrorCode EncodeArray(Array *a, CSViewerFormat format)
{
  size_t nbytes = a->n * a->elsize;
  PetscFunctionBeginUser;
  if (format == CS_VIEWER_BINARY) {
    a->nblob = sizeof(uint64_t) + nbytes;
  } else {
    size_t    nb = nbytes ? (nbytes + CS_VTU_BLOCK - 1) / CS_VTU_BLOCK : 0, pos;
    uint64_t *h;
    uLong     bound = compressBound(CS_VTU_BLOCK);
    PetscCall(PetscMalloc((3 + nb) * sizeof(uint64_t) + nb * bound, &a->blob));
    h    = (uint64_t *)a->blob;
    h[0] = nb;
    h[1] = CS_VTU_BLOCK;
    h[2] = nb ? nbytes - (nb - 1) * CS_VTU_BLOCK : 0;
    pos  = (3 + nb) * sizeof(uint64_t);
    /* one stream for every block (deflateReset): a deflateInit per block maps and faults in its state anew */
    z_stream z;
    int      ok = 1;
    memset(&z, 0, sizeof(z));
    /* floats: Huffman coding only (the LZ77 match search finds little in mantissas and doubles the time) */
    PetscCheck(deflateInit2(&z, 1, Z_DEFLATED, 15, 8, a->type[0] == 'F' ? Z_HUFFMAN_ONLY : Z_DEFAULT_STRATEGY) == Z_OK, PETSC_COMM_SELF, PETSC_ERR_LIB, "-viewer_format zlib: deflateInit2 failed");
    for (size_t b = 0; b < nb && ok; b++) {
      size_t in   = b + 1 < nb ? CS_VTU_BLOCK : h[2];
      z.next_in   = (Bytef *)a->data + b * CS_VTU_BLOCK;
      z.avail_in  = (uInt)in;
      z.next_out  = (Bytef *)a->blob + pos;
      z.avail_out = (uInt)bound;
      ok          = deflate(&z, Z_FINISH) == Z_STREAM_END;
      h[3 + b]    = z.total_out;
      pos += h[3 + b];
      if (ok) ok = deflateReset(&z) == Z_OK;
    }
    deflateEnd(&z);
    PetscCheck(ok, PETSC_COMM_SELF, PETSC_ERR_LIB, "-viewer_format zlib: compression failed");
    a->nblob = pos;
  }
  PetscFunctionReturn(0);
}

static void WriteArrayBytes(FILE *fp, const Array *a, CSViewerFormat format)
{
  if (format == CS_VIEWER_ZLIB) {
    fwrite(a->blob, 1, a->nblob, fp);
  } else {
    uint64_t h = a->n * a->elsize;
    fwrite(&h, sizeof(h), 1, fp);
    if (h) fwrite(a->data, 1, h, fp);
  }
}

static void WriteArrayHeader(FILE *fp, const Array *a, CSViewerFormat format, size_t *offset)
{
  fprintf(fp, "<DataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\" format=\"%s\"", a->type, a->name, (int)a->ncomp, format == CS_VIEWER_ASCII ? "ascii" : "appended");
  if (format == CS_VIEWER_ASCII) {
    fprintf(fp, ">\n");
    for (size_t i = 0; i < a->n; i++) {
      char sep = (i + 1) % a->ncomp ? ' ' : '\n';
      if (a->type[0] == 'F') fprintf(fp, "%.10g%c", a->elsize == 8 ? ((const double *)a->data)[i] : (double)((const float *)a->data)[i], sep);
      else if (a->type[0] == 'I') fprintf(fp, "%lld%c", a->elsize == 8 ? (long long)((const int64_t *)a->data)[i] : (long long)((const int32_t *)a->data)[i], sep);
      else fprintf(fp, "%d%c", (int)((const uint8_t *)a->data)[i], sep);
    }
    fprintf(fp, "</DataArray>\n");
  } else {
    fprintf(fp, " offset=\"%zu\"/>\n", *offset);
    *offset += a->nblob;
  }
}

static void SetArray(Array *a, const char name[], const char type[], PetscInt ncomp, size_t n, size_t elsize, const void *data)
{
  memset(a, 0, sizeof(*a));
  snprintf(a->name, sizeof(a->name), "%s", name);
  snprintf(a->type, sizeof(a->type), "%s", type);
  a->ncomp  = ncomp;
  a->n      = n;
  a->elsize = elsize;
  a->data   = data;
}

/* The values of a Vec as written: the array itself for Float64 in a real double build, else a copy as doubles or
   (single) floats, freed by the caller. */
static PetscErrorCode RealValues(const PetscScalar *a, PetscInt n, PetscBool single, const void **r, void **copy)
{
  PetscFunctionBeginUser;
  *copy = NULL;
  if (single) {
    float *f;
    PetscCall(PetscMalloc1(n, &f));
    for (PetscInt i = 0; i < n; i++) f[i] = (float)PetscRealPart(a[i]);
    *r = *copy = f;
    PetscFunctionReturn(0);
  }
#if defined(PETSC_USE_REAL_DOUBLE) && !defined(PETSC_USE_COMPLEX)
  *r = a;
#else
  {
    double *d;
    PetscCall(PetscMalloc1(n, &d));
    for (PetscInt i = 0; i < n; i++) d[i] = (double)PetscRealPart(a[i]);
    *r = *copy = d;
  }
#endif
  PetscFunctionReturn(0);
}

/* The piece's points: the local vertices, or with texture coordinates (mesh->faceUV, issue 38) one point per distinct
   (vertex, UV) pair, so a seam vertex is written once per side and ParaView's texture mapping sees each side's UV.
   vert[i]: the local vertex of point i (NULL: point i = vertex i), tc: 2 per point, conn: 3 per face. */
typedef struct {
  PetscInt         np;
  PetscInt        *vert, *conn;
  PetscScalar     *tc;
  const PetscInt  *c; /* conn, or the mesh's faceVert */
} CSViewerPoints;

static const PetscReal *cs_sort_uv; /* qsort has no context argument: the corners' UVs while sorting */
static const PetscInt  *cs_sort_vert;
static int CompareCorners(const void *a, const void *b)
{
  PetscInt i = *(const PetscInt *)a, j = *(const PetscInt *)b;
  if (cs_sort_vert[i] != cs_sort_vert[j]) return cs_sort_vert[i] < cs_sort_vert[j] ? -1 : 1;
  for (int d = 0; d < 2; d++)
    if (cs_sort_uv[2 * i + d] != cs_sort_uv[2 * j + d]) return cs_sort_uv[2 * i + d] < cs_sort_uv[2 * j + d] ? -1 : 1;
  return i < j ? -1 : (i > j);
}

static PetscErrorCode PointsCreate(CSMesh m, CSViewerPoints *P)
{
  PetscInt nc = 3 * m->nf, *order;
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(P, sizeof(*P)));
  P->np = m->nv;
  P->c  = m->faceVert;
  if (!m->faceUV) PetscFunctionReturn(0);
  PetscCall(PetscMalloc1(nc, &order));
  PetscCall(PetscMalloc3(nc, &P->vert, nc, &P->conn, 2 * nc, &P->tc));
  for (PetscInt k = 0; k < nc; k++) order[k] = k;
  cs_sort_uv   = m->faceUV;
  cs_sort_vert = m->faceVert;
  qsort(order, (size_t)nc, sizeof(PetscInt), CompareCorners);
  P->np = 0;
  for (PetscInt k = 0; k < nc; k++) {
    PetscInt i = order[k], j = k ? order[k - 1] : -1;
    if (j < 0 || m->faceVert[i] != m->faceVert[j] || m->faceUV[2 * i] != m->faceUV[2 * j] || m->faceUV[2 * i + 1] != m->faceUV[2 * j + 1]) {
      P->vert[P->np]       = m->faceVert[i];
      P->tc[2 * P->np]     = m->faceUV[2 * i];
      P->tc[2 * P->np + 1] = m->faceUV[2 * i + 1];
      P->np++;
    }
    P->conn[i] = P->np - 1;
  }
  P->c = P->conn;
  PetscCall(PetscFree(order));
  PetscFunctionReturn(0);
}

static PetscErrorCode PointsDestroy(CSViewerPoints *P)
{
  PetscFunctionBeginUser;
  if (P->vert) PetscCall(PetscFree3(P->vert, P->conn, P->tc));
  PetscFunctionReturn(0);
}

/* a per-vertex array (ncomp values each) at the piece's points: a itself, or a copy in *copy (freed by the caller) */
static PetscErrorCode PointValues(const CSViewerPoints *P, const PetscScalar *a, PetscInt ncomp, const PetscScalar **r, PetscScalar **copy)
{
  PetscFunctionBeginUser;
  *copy = NULL;
  *r    = a;
  if (!P->vert) PetscFunctionReturn(0);
  PetscCall(PetscMalloc1(ncomp * P->np, copy));
  for (PetscInt i = 0; i < P->np; i++)
    for (PetscInt c = 0; c < ncomp; c++) (*copy)[ncomp * i + c] = a[ncomp * P->vert[i] + c];
  *r = *copy;
  PetscFunctionReturn(0);
}

static PetscErrorCode WritePiece(CSViewer v, Vec x, const char path[])
{
  CSMesh             m = v->mesh;
  CSFile             file;
  FILE              *fp;
  Vec                xl;
  const PetscScalar *p, *fa[CS_VIEWER_MAX_FIELDS], *pp;
  Array              arr[5 + CS_VIEWER_MAX_FIELDS];
  void              *copy[2 + CS_VIEWER_MAX_FIELDS];
  PetscScalar       *expanded[1 + CS_VIEWER_MAX_FIELDS];
  CSViewerPoints     P;
  const void        *r;
  const char        *ftype  = v->single ? "Float32" : "Float64";
  size_t             fsize  = v->single ? sizeof(float) : sizeof(double);
  PetscInt          *offs;
  uint8_t           *types;
  PetscInt           na = 0, first_point = 0, first_cell = 0;
  size_t             offset = 0;
  const char        *itype = sizeof(PetscInt) == 8 ? "Int64" : "Int32";
  PetscFunctionBeginUser;
  PetscCall(CSFileOpen(m->comm, PETSC_TRUE, "-viewer_dir", path, PETSC_FALSE, &file)); /* every rank's piece */
  fp = file.fp;
  /* every array as it is written, straight from the Vecs and the mesh's tables where the types match */
  PetscCall(DMGetLocalVector(m->dmV3, &xl));
  PetscCall(DMGlobalToLocal(m->dmV3, x, INSERT_VALUES, xl));
  PetscCall(VecGetArrayRead(xl, &p));
  PetscCall(PointsCreate(m, &P));
  PetscCall(PetscMemzero(expanded, sizeof(expanded)));
  PetscCall(PointValues(&P, p, 3, &pp, &expanded[0]));
  PetscCall(RealValues(pp, 3 * P.np, v->single, &r, &copy[0]));
  SetArray(&arr[na++], "positions", ftype, 3, 3 * P.np, fsize, r);
  PetscCall(PetscMalloc2(m->nf, &offs, m->nf, &types));
  for (PetscInt f = 0; f < m->nf; f++) {
    offs[f]  = 3 * f + 3;
    types[f] = 5; /* VTK_TRIANGLE */
  }
  SetArray(&arr[na++], "connectivity", itype, 1, 3 * m->nf, sizeof(PetscInt), P.c);
  SetArray(&arr[na++], "offsets", itype, 1, m->nf, sizeof(PetscInt), offs);
  SetArray(&arr[na++], "types", "UInt8", 1, m->nf, sizeof(uint8_t), types);
  for (int pass = 0; pass < 2; pass++) { /* point data, then cell data */
    if (pass == 0) first_point = na;
    else first_cell = na;
    if (pass == 0 && P.vert) { /* the texture coordinates, ParaView's active TCoords */
      PetscCall(RealValues(P.tc, 2 * P.np, v->single, &r, &copy[na - 3]));
      SetArray(&arr[na++], "TCoords", ftype, 2, 2 * P.np, fsize, r);
    }
    for (PetscInt k = 0; k < v->nfields; k++) {
      PetscInt           n;
      const PetscScalar *fv;
      if (v->fields[k].face != (PetscBool)pass) continue;
      n = (pass ? m->nf : P.np) * v->fields[k].ncomp;
      PetscCall(VecGetArrayRead(v->fields[k].local, &fa[k]));
      fv = fa[k];
      if (!pass) PetscCall(PointValues(&P, fa[k], v->fields[k].ncomp, &fv, &expanded[1 + k]));
      PetscCall(RealValues(fv, n, v->single, &r, &copy[na - 3]));
      SetArray(&arr[na++], v->fields[k].name, ftype, v->fields[k].ncomp, (size_t)n, fsize, r);
    }
  }
  if (v->format != CS_VIEWER_ASCII)
    for (PetscInt k = 0; k < na; k++) PetscCall(EncodeArray(&arr[k], v->format));

  fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" header_type=\"UInt64\"%s>\n<UnstructuredGrid>\n", v->format == CS_VIEWER_ZLIB ? " compressor=\"vtkZLibDataCompressor\"" : "");
  fprintf(fp, "<Piece NumberOfPoints=\"%d\" NumberOfCells=\"%d\">\n<Points>\n", (int)P.np, (int)m->nf);
  WriteArrayHeader(fp, &arr[0], v->format, &offset);
  fprintf(fp, "</Points>\n<Cells>\n");
  for (PetscInt k = 1; k < 4; k++) WriteArrayHeader(fp, &arr[k], v->format, &offset);
  fprintf(fp, "</Cells>\n<PointData%s>\n", P.vert ? " TCoords=\"TCoords\"" : "");
  for (PetscInt k = first_point; k < first_cell; k++) WriteArrayHeader(fp, &arr[k], v->format, &offset);
  fprintf(fp, "</PointData>\n<CellData>\n");
  for (PetscInt k = first_cell; k < na; k++) WriteArrayHeader(fp, &arr[k], v->format, &offset);
  fprintf(fp, "</CellData>\n</Piece>\n</UnstructuredGrid>\n");
  if (v->format != CS_VIEWER_ASCII) {
    fprintf(fp, "<AppendedData encoding=\"raw\">\n_");
    for (PetscInt k = 0; k < na; k++) WriteArrayBytes(fp, &arr[k], v->format);
    fprintf(fp, "\n</AppendedData>\n");
  }
  fprintf(fp, "</VTKFile>\n");
  for (PetscInt k = 0; k < na; k++) PetscCall(PetscFree(arr[k].blob));
  PetscCall(PetscFree(copy[0]));
  for (PetscInt k = 4; k < na; k++) PetscCall(PetscFree(copy[k - 3]));
  for (PetscInt k = 0; k <= v->nfields; k++) PetscCall(PetscFree(expanded[k]));
  PetscCall(PointsDestroy(&P));
  for (PetscInt k = 0; k < v->nfields; k++) PetscCall(VecRestoreArrayRead(v->fields[k].local, &fa[k]));
  PetscCall(VecRestoreArrayRead(xl, &p));
  PetscCall(DMRestoreLocalVector(m->dmV3, &xl));
  PetscCall(PetscFree2(offs, types));
  PetscCall(CSFileClose(m->comm, &file));
  PetscFunctionReturn(0);
}

/* The .pvtu joining the pieces and the .pvd index of every step so far (rewritten each step, so a killed run
   leaves a readable series). */
static PetscErrorCode WriteIndex(CSViewer v, PetscMPIInt rank, PetscMPIInt size)
{
  char        path[PETSC_MAX_PATH_LEN];
  CSFile      file;
  FILE       *fp;
  const char *ftype = v->single ? "Float32" : "Float64";
  MPI_Comm    comm  = v->mesh->comm;
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/surface_%04d.pvtu", v->dir, (int)v->step));
  PetscCall(CSFileOpen(comm, (PetscBool)!rank, "-viewer_dir", path, PETSC_FALSE, &file));
  if ((fp = file.fp)) {
    fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n<PUnstructuredGrid GhostLevel=\"0\">\n");
    fprintf(fp, "<PPoints><PDataArray type=\"%s\" Name=\"positions\" NumberOfComponents=\"3\"/></PPoints>\n<PPointData%s>\n", ftype, v->mesh->faceUV ? " TCoords=\"TCoords\"" : "");
    if (v->mesh->faceUV) fprintf(fp, "<PDataArray type=\"%s\" Name=\"TCoords\" NumberOfComponents=\"2\"/>\n", ftype);
    for (PetscInt k = 0; k < v->nfields; k++)
      if (!v->fields[k].face) fprintf(fp, "<PDataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\"/>\n", ftype, v->fields[k].name, (int)v->fields[k].ncomp);
    fprintf(fp, "</PPointData>\n<PCellData>\n");
    for (PetscInt k = 0; k < v->nfields; k++)
      if (v->fields[k].face) fprintf(fp, "<PDataArray type=\"%s\" Name=\"%s\" NumberOfComponents=\"%d\"/>\n", ftype, v->fields[k].name, (int)v->fields[k].ncomp);
    fprintf(fp, "</PCellData>\n");
    for (PetscMPIInt r = 0; r < size; r++) fprintf(fp, "<Piece Source=\"surface_%04d_%d.vtu\"/>\n", (int)v->step, (int)r);
    fprintf(fp, "</PUnstructuredGrid>\n</VTKFile>\n");
  }
  PetscCall(CSFileClose(comm, &file));

  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/series.pvd", v->dir)); /* atomic: the last good index stays */
  PetscCall(CSFileOpen(comm, (PetscBool)!rank, "-viewer_dir", path, PETSC_TRUE, &file));
  if ((fp = file.fp)) {
    fprintf(fp, "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n<Collection>\n");
    for (PetscInt s = 0; s <= v->step; s++) fprintf(fp, "<DataSet timestep=\"%.17g\" file=\"surface_%04d.pvtu\"/>\n", (double)v->times[s], (int)s);
    fprintf(fp, "</Collection>\n</VTKFile>\n");
  }
  PetscCall(CSFileClose(comm, &file));
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
  PetscCall(PetscLogEventBegin(CS_EVENT_ViewerWrite, 0, 0, 0, 0));
  PetscCall(WritePiece(v, x, path));
  PetscCall(WriteIndex(v, rank, size));
  PetscCall(PetscLogEventEnd(CS_EVENT_ViewerWrite, 0, 0, 0, 0));
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
