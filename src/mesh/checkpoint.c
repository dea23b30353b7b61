/* Checkpoint/resume in natural order (independent of the number of ranks). The file (issue 18, item 9) is a text
   header of named fields, then the payload as little-endian float64 (the scalars, then the fields in natural order:
   the positions, vertex_dofs = 3 per vertex, the edge field, edge_dofs per edge, the face field, face_dofs per face):
     confsurf-checkpoint 4
     iteration 12
     scalars 5
     vertices 642
     edges 1920
     faces 1280
     vertex_dofs 3
     edge_dofs 1
     face_dofs 0
     payload_bytes 61288
     checksum_fnv1a64 0123456789abcdef
     end_header
   (version 4: the checksum covers the header's lines before it too, so an edited iteration or size is damage;
   version 3 checksummed the payload only; version 2 had the positions always and at most one value per edge, which
   cannot hold a triangle field. Older versions are refused by the version line.) Rank 0 writes it atomically (CSFile: unique temporary name, fsync,
   rename over a regular file only) and reads it whole; the header is checked against the mesh and the caller's
   fields, the payload against its length and checksum, the values for range (a finite state, an iteration in
   [0, 1e9]), so a damaged file or one of another method is refused naming the file and the field. */
#include "cs_mesh.h"
#include "cs_util.h"
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

#define CS_CHECKPOINT_VERSION 4
#define CS_CHECKPOINT_MAX_IT  1000000000

typedef struct {
  long long version, it, nreal, nv, ne, nf, dof[3], bytes;
  uint64_t  sum;
  size_t    nhead; /* the header's bytes before its checksum line, covered by the checksum */
} Header;

/* The fields of a checkpoint by depth (0 positions, 1 edges, 2 faces): values per point, points, the natural
   scatter (the mesh's own for 3 per vertex and 1 per edge or face, else a temporary one on a field DM). */
typedef struct {
  Vec            vec[3];
  PetscInt       dof[3], npt[3];
  CSMeshNatural *nat[3];
  CSMeshNatural  own[3];
  DM             dm[3];
} Fields;

static PetscErrorCode FieldsCreate(CSMesh m, const CSCheckpointFields *v, Fields *f)
{
  CSMeshNatural *mine[3] = {&m->natV3, &m->natE1, &m->natF1};
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(f, sizeof(*f)));
  f->vec[0] = v->x;
  f->vec[1] = v->edge;
  f->vec[2] = v->face;
  f->npt[0] = m->Nv;
  f->npt[1] = m->Ne;
  f->npt[2] = m->Nf;
  for (PetscInt d = 0; d < 3; d++) {
    PetscInt n;
    if (!f->vec[d]) continue;
    PetscCall(VecGetSize(f->vec[d], &n));
    PetscCheck(f->npt[d] > 0 && n % f->npt[d] == 0 && (d || n == 3 * f->npt[d]), m->comm, PETSC_ERR_ARG_SIZ, "checkpoint field of depth %" PetscInt_FMT ": %" PetscInt_FMT " values for %" PetscInt_FMT " points", d, n, f->npt[d]);
    f->dof[d] = n / f->npt[d];
    if (f->dof[d] == (d ? 1 : 3)) f->nat[d] = mine[d];
    else {
      PetscCall(CSMeshCreateFieldDM(m->dm, d, f->dof[d], "checkpoint", &f->dm[d]));
      PetscCall(CSMeshNaturalCreate(m, f->dm[d], d, f->dof[d], &f->own[d]));
      f->nat[d] = &f->own[d];
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode FieldsDestroy(Fields *f)
{
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < 3; d++) {
    if (!f->dm[d]) continue;
    PetscCall(CSMeshNaturalDestroy(&f->own[d]));
    PetscCall(DMDestroy(&f->dm[d]));
  }
  PetscFunctionReturn(0);
}

/* FNV-1a, 64 bits: a cheap checksum that notices any changed, lost or swapped byte with high probability */
static uint64_t Checksum(uint64_t h, const unsigned char *p, size_t n)
{
  for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 1099511628211ULL;
  return h;
}
#define CS_FNV_BASIS 14695981039346656037ULL

/* the checksum of version 4: over the header's text before its checksum line (the iteration, the sizes: an edited
   "iteration 3" -> "4" is damage like any other), then over the payload (issue 36, item 8) */
static uint64_t ChecksumFile(const char *head, size_t nhead, const double *pay, size_t bytes)
{
  return Checksum(Checksum(CS_FNV_BASIS, (const unsigned char *)head, nhead), (const unsigned char *)pay, bytes);
}

/* rank 0: the payload [reals, positions, edge field, face field] (natural vectors) as doubles; n doubles */
static PetscErrorCode Payload(PetscInt nreal, const PetscReal reals[], const Fields *f, double **pay, size_t *n)
{
  size_t k = (size_t)nreal;
  PetscFunctionBeginUser;
  *n = k;
  for (PetscInt d = 0; d < 3; d++) *n += (size_t)(f->dof[d] * f->npt[d]);
  PetscCall(PetscMalloc1(*n, pay));
  for (PetscInt i = 0; i < nreal; i++) (*pay)[i] = (double)reals[i];
  for (PetscInt d = 0; d < 3; d++) {
    const PetscScalar *a;
    if (!f->nat[d]) continue;
    PetscCall(VecGetArrayRead(f->nat[d]->vec, &a));
    for (PetscInt i = 0; i < f->dof[d] * f->npt[d]; i++) (*pay)[k++] = (double)PetscRealPart(a[i]);
    PetscCall(VecRestoreArrayRead(f->nat[d]->vec, &a));
  }
  PetscFunctionReturn(0);
}

/* rank 0: the header and the payload into the open file */
static void WriteFile(FILE *fp, CSMesh m, PetscInt it, PetscInt nreal, const Fields *f, const double *pay, size_t n)
{
  char head[512];
  int  nh = snprintf(head, sizeof(head), "confsurf-checkpoint %d\niteration %" PetscInt_FMT "\nscalars %" PetscInt_FMT "\nvertices %" PetscInt_FMT "\nedges %" PetscInt_FMT "\nfaces %" PetscInt_FMT "\nvertex_dofs %" PetscInt_FMT "\nedge_dofs %" PetscInt_FMT "\nface_dofs %" PetscInt_FMT "\npayload_bytes %zu\n", CS_CHECKPOINT_VERSION, it, nreal, m->Nv, m->Ne, m->Nf, f->dof[0], f->dof[1], f->dof[2], n * sizeof(double));
  fputs(head, fp);
  fprintf(fp, "checksum_fnv1a64 %016" PRIx64 "\nend_header\n", ChecksumFile(head, (size_t)nh, pay, n * sizeof(double)));
  (void)fwrite(pay, sizeof(double), n, fp); /* a short write sets the stream's error, reported by the close */
}

PetscErrorCode CSCheckpointWrite(CSMesh m, const char path[], PetscInt it, PetscInt nreal, const PetscReal reals[], const CSCheckpointFields *v)
{
  PetscMPIInt rank;
  Fields      fl;
  CSFile      f;
  double     *pay = NULL;
  size_t      n   = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  PetscCall(FieldsCreate(m, v, &fl));
  for (PetscInt d = 0; d < 3; d++) {
    Vec nat;
    if (fl.nat[d]) PetscCall(CSMeshGather(fl.nat[d], fl.vec[d], &nat));
  }
  PetscCall(CSFileOpen(m->comm, (PetscBool)!rank, "-checkpoint", path, PETSC_TRUE, &f));
  if (!rank) PetscCall(Payload(nreal, reals, &fl, &pay, &n));
  if (f.fp) WriteFile(f.fp, m, it, nreal, &fl, pay, n);
  PetscCall(PetscFree(pay));
  PetscCall(FieldsDestroy(&fl));
  PetscCall(CSFileClose(m->comm, &f));
  PetscFunctionReturn(0);
}

/* the header's named fields, in order; *data is where the payload starts */
static PetscErrorCode ParseHeader(const char name[], const char *buf, size_t len, Header *h, size_t *data)
{
  const char *e = NULL;
  int         k = 0;
  PetscFunctionBeginUser;
  for (size_t i = 0; i + 11 <= len && !e; i++)
    if (!memcmp(buf + i, "end_header\n", 11)) e = buf + i + 11;
  PetscCheck(len >= 20 && !memcmp(buf, "confsurf-checkpoint ", 20), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: not a confsurf checkpoint (or one of an older version)", name);
  if (!e) { /* a text transfer turned the line ends into CRLF: say so, not "truncated" */
    for (size_t i = 0; i + 12 <= len && !e; i++)
      if (!memcmp(buf + i, "end_header\r\n", 12)) e = buf + i;
    PetscCheck(!e, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: the header has CRLF line ends (copied as text?): a checkpoint is binary, copy it unchanged", name);
  }
  PetscCheck(e, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: truncated header (no end_header line)", name);
  k = sscanf(buf, "confsurf-checkpoint %lld iteration %lld scalars %lld vertices %lld edges %lld faces %lld vertex_dofs %lld edge_dofs %lld face_dofs %lld payload_bytes %lld checksum_fnv1a64 %" SCNx64, &h->version, &h->it, &h->nreal, &h->nv, &h->ne, &h->nf, &h->dof[0], &h->dof[1], &h->dof[2], &h->bytes, &h->sum);
  PetscCheck(k < 1 || h->version == CS_CHECKPOINT_VERSION, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: version %lld, this program reads version %d", name, h->version, CS_CHECKPOINT_VERSION);
  PetscCheck(k == 11, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: damaged header (field %d of 11 missing or not a number)", name, k + 1);
  {
    const char *c = strstr(buf, "\nchecksum_fnv1a64 "); /* sscanf found it, before end_header */
    h->nhead = (size_t)(c - buf) + 1;
  }
  *data = (size_t)(e - buf);
  PetscFunctionReturn(0);
}

/* the header against the mesh and the caller's fields (sizes; the values are checked by CheckPayload) */
static PetscErrorCode CheckHeader(CSMesh m, const char name[], const Header *h, PetscInt nreal, const Fields *f)
{
  PetscFunctionBeginUser;
  PetscCheck(h->it >= 0 && h->it <= CS_CHECKPOINT_MAX_IT, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: iteration %lld out of range [0, %d]", name, h->it, CS_CHECKPOINT_MAX_IT);
  PetscCheck(h->nv == m->Nv && h->ne == m->Ne && h->nf == m->Nf, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: written for %lld vertices, %lld edges and %lld faces, the mesh has %" PetscInt_FMT ", %" PetscInt_FMT " and %" PetscInt_FMT, name, h->nv, h->ne, h->nf, m->Nv, m->Ne, m->Nf);
  PetscCheck(h->dof[0] == f->dof[0] && h->dof[1] == f->dof[1] && h->dof[2] == f->dof[2], PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: stores %lld values per vertex, %lld per edge and %lld per face, this run %" PetscInt_FMT ", %" PetscInt_FMT " and %" PetscInt_FMT " (written by another method or flow type?)", name, h->dof[0], h->dof[1], h->dof[2], f->dof[0], f->dof[1], f->dof[2]);
  PetscCheck(h->nreal == nreal, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: %lld scalars stored, %" PetscInt_FMT " expected (written by another method?)", name, h->nreal, nreal);
  PetscFunctionReturn(0);
}

/* the payload against its length, checksum and range; n doubles expected */
static PetscErrorCode CheckPayload(const char name[], const char *head, const Header *h, long long n, const double *pay, size_t avail)
{
  PetscFunctionBeginUser;
  PetscCheck(h->bytes == n * (long long)sizeof(double), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: payload_bytes %lld, the fields need %lld", name, h->bytes, n * (long long)sizeof(double));
  PetscCheck((size_t)h->bytes <= avail, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: truncated: %zu of %lld payload bytes", name, avail, h->bytes);
  PetscCheck(ChecksumFile(head, h->nhead, pay, (size_t)h->bytes) == h->sum, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: checksum mismatch: the header or the payload is damaged", name);
  for (long long i = 0; i < n; i++) PetscCheck(isfinite(pay[i]), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: non-finite value at payload entry %lld", name, i);
  PetscFunctionReturn(0);
}

/* rank 0: the checked payload into the reals and the natural vectors */
static PetscErrorCode Unpack(PetscInt nreal, PetscReal reals[], const Fields *f, const double *pay)
{
  size_t k = (size_t)nreal;
  PetscFunctionBeginUser;
  for (PetscInt i = 0; i < nreal; i++) reals[i] = (PetscReal)pay[i];
  for (PetscInt d = 0; d < 3; d++) {
    PetscScalar *a;
    if (!f->nat[d]) continue;
    PetscCall(VecGetArray(f->nat[d]->vec, &a));
    for (PetscInt i = 0; i < f->dof[d] * f->npt[d]; i++) a[i] = pay[k++];
    PetscCall(VecRestoreArray(f->nat[d]->vec, &a));
  }
  PetscFunctionReturn(0);
}

/* rank 0: the file into the natural vectors and reals; the iteration into *it */
static PetscErrorCode ReadRoot(CSMesh m, const char path[], PetscInt *it, PetscInt nreal, PetscReal reals[], const Fields *f)
{
  char           name[PETSC_MAX_PATH_LEN], *buf;
  size_t         len, data = 0;
  Header         h;
  double        *pay = NULL;
  long long      n   = nreal;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  for (PetscInt d = 0; d < 3; d++) n += (long long)(f->dof[d] * f->npt[d]);
  PetscCall(CSPathSanitize(path, name, sizeof(name)));
  PetscCall(CSFileLoad("-resume", path, &buf, &len));
  CSCaptureError(ierr, ParseHeader(name, buf, len, &h, &data));
  if (!ierr) CSCaptureError(ierr, CheckHeader(m, name, &h, nreal, f));
  if (!ierr) { /* aligned copy of the payload */
    CSCaptureError(ierr, PetscMalloc1((len - data) / sizeof(double) + 1, &pay));
    if (!ierr) memcpy(pay, buf + data, len - data);
  }
  if (!ierr) CSCaptureError(ierr, CheckPayload(name, buf, &h, n, pay, len - data));
  PetscCall(PetscFree(buf));
  if (!ierr) {
    PetscCall(Unpack(nreal, reals, f, pay));
    *it = (PetscInt)h.it;
  }
  PetscCall(PetscFree(pay));
  PetscCall(CSSyncError(PETSC_COMM_SELF, ierr));
  PetscFunctionReturn(0);
}

/* rank 0 reads; a refused file is refused on every rank (CSRootCall) */
static PetscErrorCode ReadFields(CSMesh m, const char path[], PetscInt *it, PetscInt nreal, PetscReal reals[], const Fields *f)
{
  PetscFunctionBeginUser;
  CSRootCall(m->comm, ReadRoot(m, path, it, nreal, reals, f));
  PetscCallMPI(MPI_Bcast(it, 1, MPIU_INT, 0, m->comm));
  if (nreal) PetscCallMPI(MPI_Bcast(reals, (PetscMPIInt)nreal, MPIU_REAL, 0, m->comm));
  for (PetscInt d = 0; d < 3; d++)
    if (f->nat[d]) PetscCall(CSMeshScatter(f->nat[d], f->nat[d]->vec, f->vec[d]));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCheckpointRead(CSMesh m, const char path[], PetscInt *it, PetscInt nreal, PetscReal reals[], const CSCheckpointFields *v)
{
  Fields         f;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(FieldsCreate(m, v, &f));
  ierr = ReadFields(m, path, it, nreal, reals, &f);
  PetscCall(FieldsDestroy(&f)); /* on the error path too */
  PetscCall(ierr);
  PetscFunctionReturn(0);
}
