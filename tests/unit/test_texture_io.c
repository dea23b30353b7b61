/* Unit test of texture coordinates in the serial mesh-data layer (issue 38): the OBJ vt forms (tests/data/tetra_uv.obj),
   exact OBJ and PLY round trips of the UVs (per vertex: u v; per corner: texcoord), the refusals of validation (an
   index out of range, a NaN), unreferenced vertices dropped with fuv kept, an inward mesh's flip is not here (the
   mesh layer's), and the 1-to-4 split: each new corner's UV is the mean of its edge's corner UVs in that face, one
   new UV per edge and two on a seam edge.
   Prints "ok <check>" or "FAIL <check>: detail"; the exit code is the number of failures. Option: -data_dir DIR. */
#include "cs_meshdata.h"
#include "cs_test.h"
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define Check(...) CSTestCheckf(PETSC_COMM_WORLD, __VA_ARGS__) /* tests/unit/cs_test.h */

/* validation under the return handler: *ierr and PETSc's message of the first error */
static PetscErrorCode TryValidate(CSMeshData *md, PetscErrorCode *ierr, char msg[], size_t len)
{
  CSTopology  topo;
  const char *text     = NULL;
  char       *specific = NULL;

  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  *ierr = CSMeshDataValidate(md, &topo);
  PetscCall(PetscPopErrorHandler());
  msg[0] = 0;
  if (*ierr) {
    PetscCall(PetscErrorMessage(*ierr, &text, &specific));
    PetscCall(PetscStrncpy(msg, specific ? specific : (text ? text : "?"), len));
  }
  PetscFunctionReturn(0);
}

/* the UV of every face corner of a and b bitwise equal (the uv lists may differ: per vertex, per corner) */
static PetscBool SameCornerUV(const CSMeshData *a, const CSMeshData *b)
{
  if (!a->fuv || !b->fuv || a->nf != b->nf) return PETSC_FALSE;
  for (PetscInt h = 0; h < 3 * a->nf; h++)
    if (memcmp(a->uv + 2 * a->fuv[h], b->uv + 2 * b->fuv[h], 2 * sizeof(PetscReal))) return PETSC_FALSE;
  return PETSC_TRUE;
}

/* the same uv list and fuv, bitwise */
static PetscBool SameUV(const CSMeshData *a, const CSMeshData *b)
{
  return (PetscBool)(a->fuv && b->fuv && a->nuv == b->nuv && a->nf == b->nf && !memcmp(a->uv, b->uv, 2 * sizeof(PetscReal) * a->nuv) && !memcmp(a->fuv, b->fuv, 3 * sizeof(PetscInt) * a->nf));
}

static PetscErrorCode WriteRead(const CSMeshData *md, const char tmp[], const char file[], CSMeshData *out)
{
  char path[PETSC_MAX_PATH_LEN];
  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", tmp, file));
  PetscCall(CSMeshDataWrite(path, md));
  PetscCall(CSMeshDataRead(path, out));
  (void)remove(path);
  PetscFunctionReturn(0);
}

static PetscErrorCode TestRead(const char data[], const char tmp[])
{
  const PetscInt fuv[12] = {0, 2, 1, 0, 1, 3, 0, 3, 1, 1, 2, 3};
  CSMeshData     md, rt;
  char           path[PETSC_MAX_PATH_LEN];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/tetra_uv.obj", data));
  PetscCall(CSMeshDataRead(path, &md));
  PetscCall(Check((PetscBool)(md.nuv == 4 && md.fuv && !memcmp(md.fuv, fuv, sizeof(fuv)) && md.uv[6] == 0.5 && md.uv[7] == 0.25), "tetra_uv.obj: v/vt/vn, v/vt, relative vt, vt u v w", "nuv %" PetscInt_FMT, md.nuv));
  PetscCall(WriteRead(&md, tmp, "rt.obj", &rt));
  PetscCall(Check(SameUV(&md, &rt), "OBJ round trip: the vt list and fuv bitwise", ""));
  PetscCall(CSMeshDataDestroy(&rt));
  PetscCall(WriteRead(&md, tmp, "rt.ply", &rt));
  PetscCall(Check((PetscBool)(rt.nuv == 3 * md.nf && SameCornerUV(&md, &rt)), "PLY round trip (texcoord per corner): every corner's UV bitwise", "nuv %" PetscInt_FMT, rt.nuv));
  PetscCall(CSMeshDataDestroy(&rt));
  /* UVs per vertex (fuv = f, nuv = nv): written as u v, read back as they were */
  PetscCall(PetscArraycpy(md.fuv, md.f, 3 * md.nf));
  PetscCall(WriteRead(&md, tmp, "rtv.ply", &rt));
  PetscCall(Check(SameUV(&md, &rt), "PLY round trip (u v per vertex): uv and fuv = f bitwise", "nuv %" PetscInt_FMT, rt.nuv));
  PetscCall(CSMeshDataDestroy(&rt));
  PetscCall(CSMeshDataDestroy(&md));
  PetscFunctionReturn(0);
}

/* tetra_uv.obj with a fifth vertex no face uses: dropped, fuv and uv unchanged; then an index out of range and a NaN */
static PetscErrorCode TestValidate(const char data[])
{
  CSMeshData     md, bad;
  PetscErrorCode ierr;
  char           path[PETSC_MAX_PATH_LEN], msg[1024];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/tetra_uv.obj", data));
  PetscCall(CSMeshDataRead(path, &md));
  PetscCall(CSMeshDataDuplicate(&md, &bad));
  PetscCall(PetscFree(bad.x));
  PetscCall(PetscMalloc1(15, &bad.x));
  for (PetscInt i = 0; i < 12; i++) bad.x[i + 3] = md.x[i]; /* vertex 0 unreferenced: the faces' vertices + 1 */
  bad.x[0] = bad.x[1] = bad.x[2] = 9;
  bad.nv   = 5;
  for (PetscInt h = 0; h < 12; h++) bad.f[h]++;
  PetscCall(TryValidate(&bad, &ierr, msg, sizeof(msg)));
  PetscCall(Check((PetscBool)(!ierr && bad.nv == 4 && !memcmp(bad.f, md.f, 12 * sizeof(PetscInt)) && SameUV(&md, &bad)), "an unreferenced vertex dropped: f renumbered, fuv and uv kept", "%s", msg));
  PetscCall(CSMeshDataDestroy(&bad));
  PetscCall(CSMeshDataDuplicate(&md, &bad));
  bad.fuv[7] = bad.nuv;
  PetscCall(TryValidate(&bad, &ierr, msg, sizeof(msg)));
  PetscCall(Check((PetscBool)(ierr && strstr(msg, "face 2") && strstr(msg, "texture coordinate index 4 out of range")), "validate refuses a uv index out of range", "%s", msg));
  bad.fuv[7]   = 1;
  bad.uv[2 * 3] = (PetscReal)NAN;
  PetscCall(TryValidate(&bad, &ierr, msg, sizeof(msg)));
  PetscCall(Check((PetscBool)(ierr && strstr(msg, "texture coordinate 3") && strstr(msg, "NaN")), "validate refuses a NaN texture coordinate", "%s", msg));
  PetscCall(CSMeshDataDestroy(&bad));
  PetscCall(CSMeshDataDestroy(&md));
  PetscFunctionReturn(0);
}

/* one split of tetra_uv.obj (some of its edges are seams: their two faces give the edge's ends different uv indices,
   counted here by brute force): each new corner's UV = the mean of the two corner UVs of its edge in its face, bitwise
   (the same sum and halving); the old corners keep their uv indices; the new UVs: one per edge, two per seam edge */
static PetscErrorCode TestSplit(const char data[], PetscBool loop)
{
  CSMeshData md, r;
  char       path[PETSC_MAX_PATH_LEN], name[64];
  PetscInt   seams = 0, bad = 0;

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/tetra_uv.obj", data));
  PetscCall(CSMeshDataRead(path, &md));
  for (PetscInt h = 0; h < 12; h++) /* seam half-edges: its twin gives its ends other uv indices */
    for (PetscInt g = 0; g < 12; g++) {
      PetscInt hn = h % 3 == 2 ? h - 2 : h + 1, gn = g % 3 == 2 ? g - 2 : g + 1;
      if (md.f[h] == md.f[gn] && md.f[hn] == md.f[g] && h < g && !(md.fuv[h] == md.fuv[gn] && md.fuv[hn] == md.fuv[g])) seams++;
    }
  PetscCall(CSMeshDataDuplicate(&md, &r));
  PetscCall(CSMeshDataSplitOnce(&r, loop));
  for (PetscInt i = 0; i < md.nf; i++) { /* face 4i is (t0, m0, m2): m0 on corner 0 -> 1, m2 on corner 2 -> 0 */
    const PetscReal *t0 = md.uv + 2 * md.fuv[3 * i], *t1 = md.uv + 2 * md.fuv[3 * i + 1], *t2 = md.uv + 2 * md.fuv[3 * i + 2];
    const PetscReal *m0 = r.uv + 2 * r.fuv[12 * i + 1], *m2 = r.uv + 2 * r.fuv[12 * i + 2], *m1 = r.uv + 2 * r.fuv[12 * i + 5];
    for (int d = 0; d < 2; d++) bad += (m0[d] != 0.5 * (t0[d] + t1[d])) + (m1[d] != 0.5 * (t1[d] + t2[d])) + (m2[d] != 0.5 * (t2[d] + t0[d]));
    bad += (r.fuv[12 * i] != md.fuv[3 * i]) + (r.fuv[12 * i + 4] != md.fuv[3 * i + 1]) + (r.fuv[12 * i + 8] != md.fuv[3 * i + 2]);
  }
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s split: new corners at the UV midpoints", loop ? "loop" : "midpoint"));
  PetscCall(Check((PetscBool)(!bad), name, "%" PetscInt_FMT " wrong values", bad));
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s split: one new UV per edge, two per seam edge", loop ? "loop" : "midpoint"));
  PetscCall(Check((PetscBool)(seams > 0 && r.nuv == md.nuv + 6 + seams), name, "nuv %" PetscInt_FMT " -> %" PetscInt_FMT " with 6 edges, %" PetscInt_FMT " seams", md.nuv, r.nuv, seams));
  PetscCall(CSMeshDataDestroy(&r));
  PetscCall(CSMeshDataDestroy(&md));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  char data[PETSC_MAX_PATH_LEN] = "tests/data", tmp[] = "/tmp/cs_test_texture_io_XXXXXX";

  PetscCall(PetscInitialize(&argc, &argv, NULL, "Unit test of texture coordinates in the serial mesh-data layer"));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-data_dir", data, sizeof(data), NULL));
  PetscCheck(mkdtemp(tmp), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot create a temporary directory %s", tmp);
  PetscCall(TestRead(data, tmp));
  PetscCall(TestValidate(data));
  PetscCall(TestSplit(data, PETSC_FALSE));
  PetscCall(TestSplit(data, PETSC_TRUE));
  (void)rmdir(tmp);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%" PetscInt_FMT " failure%s\n", cs_test_failures, cs_test_failures == 1 ? "" : "s"));
  PetscCall(PetscFinalize());
  return (int)cs_test_failures;
}
