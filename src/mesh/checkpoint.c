/* Checkpoint/resume in natural order (independent of the number of ranks). The file (issue 18, item 9) is a text
   header of named fields, then the payload as little-endian float64 (the scalars, the positions 3 Nv, the edge
   field Ne):
     confsurf-checkpoint 2
     iteration 12
     scalars 5
     vertices 642
     edges 1920
     edge_field 1
     payload_bytes 61288
     checksum_fnv1a64 0123456789abcdef
     end_header
   Rank 0 writes it atomically (CSFile: unique temporary name, fsync, rename over a regular file only) and reads it
   whole; the header is checked against the mesh, the payload against its length and checksum, the values for
   range (a finite state, an iteration in [0, 1e9]), so a damaged file is refused naming the file and the field. */
#include "cs_mesh.h"
#include "cs_util.h"
#include <inttypes.h>
#include <stdio.h>
#include <stdlib.h>

#define CS_CHECKPOINT_VERSION 2
#define CS_CHECKPOINT_MAX_IT  1000000000

typedef struct {
  long long version, it, nreal, nv, ne, has_edge, bytes;
  uint64_t  sum;
} Header;

/* FNV-1a, 64 bits: a cheap checksum that notices any changed, lost or swapped byte with high probability */
static uint64_t Checksum(const unsigned char *p, size_t n)
{
  uint64_t h = 14695981039346656037ULL;
  for (size_t i = 0; i < n; i++) h = (h ^ p[i]) * 1099511628211ULL;
  return h;
}

/* rank 0: the payload [reals, positions, edge field] as doubles; n doubles */
static PetscErrorCode Payload(PetscInt nreal, const PetscReal reals[], Vec natx, Vec nate, double **pay, size_t *n)
{
  const PetscScalar *a;
  PetscInt           nx, ne = 0;
  PetscFunctionBeginUser;
  PetscCall(VecGetSize(natx, &nx));
  if (nate) PetscCall(VecGetSize(nate, &ne));
  *n = (size_t)(nreal + nx + ne);
  PetscCall(PetscMalloc1(*n, pay));
  for (PetscInt i = 0; i < nreal; i++) (*pay)[i] = (double)reals[i];
  PetscCall(VecGetArrayRead(natx, &a));
  for (PetscInt i = 0; i < nx; i++) (*pay)[nreal + i] = (double)PetscRealPart(a[i]);
  PetscCall(VecRestoreArrayRead(natx, &a));
  if (nate) {
    PetscCall(VecGetArrayRead(nate, &a));
    for (PetscInt i = 0; i < ne; i++) (*pay)[nreal + nx + i] = (double)PetscRealPart(a[i]);
    PetscCall(VecRestoreArrayRead(nate, &a));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSCheckpointWrite(CSMesh m, const char path[], PetscInt it, PetscInt nreal, const PetscReal reals[], Vec x, Vec edgeField)
{
  PetscMPIInt rank;
  Vec         natx, nate = NULL;
  CSFile      f;
  double     *pay = NULL;
  size_t      n   = 0;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(m->comm, &rank));
  PetscCall(CSMeshGather(&m->natV3, x, &natx));
  if (edgeField) PetscCall(CSMeshGather(&m->natE1, edgeField, &nate));
  PetscCall(CSFileOpen(m->comm, (PetscBool)!rank, "-checkpoint", path, PETSC_TRUE, &f));
  if (!rank) PetscCall(Payload(nreal, reals, natx, nate, &pay, &n));
  if (f.fp) {
    fprintf(f.fp, "confsurf-checkpoint %d\niteration %" PetscInt_FMT "\nscalars %" PetscInt_FMT "\nvertices %" PetscInt_FMT "\nedges %" PetscInt_FMT "\nedge_field %d\n", CS_CHECKPOINT_VERSION, it, nreal, m->Nv, m->Ne, edgeField ? 1 : 0);
    fprintf(f.fp, "payload_bytes %zu\nchecksum_fnv1a64 %016" PRIx64 "\nend_header\n", n * sizeof(double), Checksum((const unsigned char *)pay, n * sizeof(double)));
    (void)fwrite(pay, sizeof(double), n, f.fp); /* a short write sets the stream's error, reported by the close */
  }
  PetscCall(PetscFree(pay));
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
  PetscCheck(e, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: truncated header (no end_header line)", name);
  k = sscanf(buf, "confsurf-checkpoint %lld iteration %lld scalars %lld vertices %lld edges %lld edge_field %lld payload_bytes %lld checksum_fnv1a64 %" SCNx64, &h->version, &h->it, &h->nreal, &h->nv, &h->ne, &h->has_edge, &h->bytes, &h->sum);
  PetscCheck(k < 1 || h->version == CS_CHECKPOINT_VERSION, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: version %lld, this program reads version %d", name, h->version, CS_CHECKPOINT_VERSION);
  PetscCheck(k == 8, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: damaged header (field %d of 8 missing or not a number)", name, k + 1);
  *data = (size_t)(e - buf);
  PetscFunctionReturn(0);
}

/* the header against the mesh and the caller, the payload against its length, checksum and range */
static PetscErrorCode CheckContents(CSMesh m, const char name[], const Header *h, PetscInt nreal, PetscBool edge, const double *pay, size_t avail)
{
  long long n = h->nreal + 3 * h->nv + (h->has_edge ? h->ne : 0);
  PetscFunctionBeginUser;
  PetscCheck(h->it >= 0 && h->it <= CS_CHECKPOINT_MAX_IT, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: iteration %lld out of range [0, %d]", name, h->it, CS_CHECKPOINT_MAX_IT);
  PetscCheck(h->nv == m->Nv && h->ne == m->Ne, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: written for %lld vertices and %lld edges, the mesh has %" PetscInt_FMT " and %" PetscInt_FMT, name, h->nv, h->ne, m->Nv, m->Ne);
  PetscCheck(h->nreal == nreal, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: %lld scalars stored, %" PetscInt_FMT " expected (written by another method?)", name, h->nreal, nreal);
  PetscCheck(h->has_edge == (edge ? 1 : 0), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: the edge field is %s", name, h->has_edge ? "present but not expected" : "missing");
  PetscCheck(h->bytes == n * (long long)sizeof(double), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: payload_bytes %lld, the fields need %lld", name, h->bytes, n * (long long)sizeof(double));
  PetscCheck((size_t)h->bytes <= avail, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: truncated: %zu of %lld payload bytes", name, avail, h->bytes);
  PetscCheck(Checksum((const unsigned char *)pay, (size_t)h->bytes) == h->sum, PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: checksum mismatch: the payload is damaged", name);
  for (long long i = 0; i < n; i++) PetscCheck(isfinite(pay[i]), PETSC_COMM_SELF, PETSC_ERR_FILE_UNEXPECTED, "-resume %s: non-finite value at payload entry %lld", name, i);
  PetscFunctionReturn(0);
}

/* rank 0: the file into the natural vectors and reals; the iteration into *it */
static PetscErrorCode ReadRoot(CSMesh m, const char path[], PetscInt *it, PetscInt nreal, PetscReal reals[], PetscBool edge)
{
  char           name[PETSC_MAX_PATH_LEN], *buf;
  size_t         len, data = 0;
  Header         h;
  double        *pay = NULL;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(CSPathSanitize(path, name, sizeof(name)));
  PetscCall(CSFileLoad("-resume", path, &buf, &len));
  CSCaptureError(ierr, ParseHeader(name, buf, len, &h, &data));
  if (!ierr) { /* aligned copy of the payload */
    CSCaptureError(ierr, PetscMalloc1((len - data) / sizeof(double) + 1, &pay));
    if (!ierr) memcpy(pay, buf + data, len - data);
  }
  if (!ierr) CSCaptureError(ierr, CheckContents(m, name, &h, nreal, edge, pay, len - data));
  PetscCall(PetscFree(buf));
  if (!ierr) {
    PetscScalar *a;
    for (PetscInt i = 0; i < nreal; i++) reals[i] = (PetscReal)pay[i];
    PetscCall(VecGetArray(m->natV3.vec, &a));
    for (PetscInt i = 0; i < 3 * m->Nv; i++) a[i] = pay[nreal + i];
    PetscCall(VecRestoreArray(m->natV3.vec, &a));
    if (edge) {
      PetscCall(VecGetArray(m->natE1.vec, &a));
      for (PetscInt i = 0; i < m->Ne; i++) a[i] = pay[nreal + 3 * m->Nv + i];
      PetscCall(VecRestoreArray(m->natE1.vec, &a));
    }
    *it = (PetscInt)h.it;
  }
  PetscCall(PetscFree(pay));
  PetscCall(CSSyncError(PETSC_COMM_SELF, ierr));
  PetscFunctionReturn(0);
}

PetscErrorCode CSCheckpointRead(CSMesh m, const char path[], PetscInt *it, PetscInt nreal, PetscReal reals[], Vec x, Vec edgeField)
{
  PetscFunctionBeginUser;
  CSRootCall(m->comm, ReadRoot(m, path, it, nreal, reals, edgeField ? PETSC_TRUE : PETSC_FALSE));
  PetscCallMPI(MPI_Bcast(it, 1, MPIU_INT, 0, m->comm));
  if (nreal) PetscCallMPI(MPI_Bcast(reals, (PetscMPIInt)nreal, MPIU_REAL, 0, m->comm));
  PetscCall(CSMeshScatter(&m->natV3, m->natV3.vec, x));
  if (edgeField) PetscCall(CSMeshScatter(&m->natE1, m->natE1.vec, edgeField));
  PetscFunctionReturn(0);
}
