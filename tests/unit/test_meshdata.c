/* Unit test of the serial mesh-data layer: generators and their topology, readers/writers (exact round trips,
   agreement of OBJ/OFF/PLY), the flat torus' conformal class, refusal of every bad input in tests/data with
   the expected message, and the real meshes of the shared collection (counts, genus, boundary loops).
   Prints "ok <check>" or "FAIL <check>: detail" per check; the exit code is the number of failures.
   Options: -data_dir DIR (tests/data), -meshes_dir DIR (meshes), -shared_meshes DIR (../shared/meshes). */
#include "cs_meshdata.h"
#include "cs_test.h"
#include <petsctime.h>
#include <math.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#define Check(...) CSTestCheckf(PETSC_COMM_WORLD, __VA_ARGS__) /* tests/unit/cs_test.h */

/* Errors are returned, not printed; msg gets PETSc's message of the first error ("" on success). */
static PetscErrorCode ErrorText(PetscErrorCode ierr, char msg[], size_t len)
{
  const char *text     = NULL;
  char       *specific = NULL;

  PetscFunctionBeginUser;
  msg[0] = 0;
  if (!ierr) PetscFunctionReturn(0);
  PetscCall(PetscErrorMessage(ierr, &text, &specific));
  PetscCall(PetscStrncpy(msg, specific ? specific : (text ? text : "?"), len));
  PetscFunctionReturn(0);
}

static PetscErrorCode TryLoad(const char path[], CSMeshData *md, CSTopology *topo, PetscErrorCode *ierr, char msg[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  *ierr = CSMeshDataRead(path, md);
  if (!*ierr) {
    *ierr = CSMeshDataValidate(md, topo);
    if (*ierr) PetscCall(CSMeshDataDestroy(md)); /* does not touch the recorded message */
  }
  PetscCall(PetscPopErrorHandler());
  PetscCall(ErrorText(*ierr, msg, len));
  PetscFunctionReturn(0);
}

static PetscErrorCode TryValidate(CSMeshData *md, CSTopology *topo, PetscErrorCode *ierr, char msg[], size_t len)
{
  PetscFunctionBeginUser;
  PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
  *ierr = CSMeshDataValidate(md, topo);
  PetscCall(PetscPopErrorHandler());
  PetscCall(ErrorText(*ierr, msg, len));
  PetscFunctionReturn(0);
}

static PetscReal SignedVolume(const CSMeshData *md)
{
  PetscReal vol = 0;
  for (PetscInt i = 0; i < md->nf; i++) {
    const PetscReal *a = md->x + 3 * md->f[3 * i], *b = md->x + 3 * md->f[3 * i + 1], *c = md->x + 3 * md->f[3 * i + 2];
    vol += (a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  return vol;
}

static void FaceNormal(const CSMeshData *md, PetscInt i, PetscReal n[3], PetscReal c[3])
{
  const PetscReal *a = md->x + 3 * md->f[3 * i], *b = md->x + 3 * md->f[3 * i + 1], *e = md->x + 3 * md->f[3 * i + 2];
  PetscReal        u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {e[0] - a[0], e[1] - a[1], e[2] - a[2]};
  n[0] = u[1] * v[2] - u[2] * v[1];
  n[1] = u[2] * v[0] - u[0] * v[2];
  n[2] = u[0] * v[1] - u[1] * v[0];
  for (int d = 0; d < 3; d++) c[d] = (a[d] + b[d] + e[d]) / 3;
}

static PetscBool SameData(const CSMeshData *a, const CSMeshData *b)
{
  if (a->nv != b->nv || a->nf != b->nf) return PETSC_FALSE;
  return (PetscBool)(!memcmp(a->x, b->x, sizeof(PetscReal) * 3 * a->nv) && !memcmp(a->f, b->f, sizeof(PetscInt) * 3 * a->nf));
}

/* Validates generated data and compares its topology with the expected one. */
static PetscErrorCode CheckTopology(CSMeshData *md, PetscInt V, PetscInt F, PetscInt genus, PetscInt loops, PetscInt euler)
{
  CSTopology     topo;
  PetscErrorCode ierr;
  char           msg[1024], name[PETSC_MAX_PATH_LEN + 16];

  PetscFunctionBeginUser;
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s", md->name));
  PetscCall(Check((PetscBool)(md->nv == V && md->nf == F), name, "V=%" PetscInt_FMT " F=%" PetscInt_FMT " (expected %" PetscInt_FMT " %" PetscInt_FMT ")", md->nv, md->nf, V, F));
  PetscCall(TryValidate(md, &topo, &ierr, msg, sizeof(msg)));
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s validate", md->name));
  if (ierr) PetscCall(Check(PETSC_FALSE, name, "refused: %s", msg));
  else
    PetscCall(Check((PetscBool)(topo.genus == genus && topo.boundary_loops == loops && topo.components == 1 && topo.euler == euler && topo.vertices == V && topo.faces == F && topo.edges == V + F - euler && !topo.dropped_vertices), name,
                    "genus %" PetscInt_FMT " loops %" PetscInt_FMT " components %" PetscInt_FMT " euler %" PetscInt_FMT " E %" PetscInt_FMT " (expected genus %" PetscInt_FMT " loops %" PetscInt_FMT " components 1 euler %" PetscInt_FMT ")", topo.genus, topo.boundary_loops, topo.components, topo.euler, topo.edges, genus, loops, euler));
  PetscFunctionReturn(0);
}

static PetscErrorCode TestGenerators(void)
{
  CSMeshData md;
  char       name[256];

  PetscFunctionBeginUser;
  for (PetscInt L = 0, p = 1; L <= 6; L++, p *= 4) {
    PetscReal err = 0;
    PetscCall(CSMeshDataIcosphere(L, 1.0, PETSC_TRUE, &md));
    PetscCall(CheckTopology(&md, 10 * p + 2, 20 * p, 0, 0, 2));
    for (PetscInt v = 0; v < md.nv; v++) err = PetscMax(err, PetscAbsReal(PetscSqrtReal(md.x[3 * v] * md.x[3 * v] + md.x[3 * v + 1] * md.x[3 * v + 1] + md.x[3 * v + 2] * md.x[3 * v + 2]) - 1));
    PetscCall(PetscSNPrintf(name, sizeof(name), "%s on the sphere, outward", md.name));
    PetscCall(Check((PetscBool)(err < 1e-14 && SignedVolume(&md) > 0), name, "max | |x| - 1 | = %.2e, volume %.6f", (double)err, (double)SignedVolume(&md)));
    PetscCall(CSMeshDataDestroy(&md));
  }
  {
    PetscReal rmin = PETSC_MAX_REAL, rmax = 0, planar = 0;
    CSMeshData ico0;
    PetscCall(CSMeshDataIcosphere(0, 2.0, PETSC_FALSE, &ico0));
    PetscCall(CSMeshDataIcosphere(2, 2.0, PETSC_FALSE, &md));
    PetscCall(CheckTopology(&md, 162, 320, 0, 0, 2));
    for (PetscInt v = 0; v < md.nv; v++) {
      PetscReal r = PetscSqrtReal(md.x[3 * v] * md.x[3 * v] + md.x[3 * v + 1] * md.x[3 * v + 1] + md.x[3 * v + 2] * md.x[3 * v + 2]);
      rmin        = PetscMin(rmin, r);
      rmax        = PetscMax(rmax, r);
    }
    /* every vertex of the linear subdivision lies in the plane of one icosahedron face: the volume is unchanged */
    planar = PetscAbsReal(SignedVolume(&md) - SignedVolume(&ico0)) / SignedVolume(&ico0);
    PetscCall(Check((PetscBool)(PetscAbsReal(rmax - 2) < 1e-14 && rmin < 1.8 && planar < 1e-13 && SignedVolume(&md) > 0), "icosphere unprojected (linear subdivision)", "radius in [%.4f, %.4f], relative volume change %.1e", (double)rmin, (double)rmax, (double)planar));
    PetscCall(CSMeshDataDestroy(&md));
    PetscCall(CSMeshDataDestroy(&ico0));
  }
  {
    PetscReal vol, exact = 2 * PETSC_PI * PETSC_PI * PetscSqrtReal(2.0);
    PetscCall(CSMeshDataTorus(PetscSqrtReal(2.0), 1, 32, 16, &md));
    PetscCall(CheckTopology(&md, 512, 1024, 1, 0, 0));
    vol = SignedVolume(&md);
    PetscCall(Check((PetscBool)(vol > 0 && PetscAbsReal(vol - exact) < 0.05 * exact), "torus outward", "volume %.4f (smooth 2 pi^2 R r^2 = %.4f)", (double)vol, (double)exact));
    PetscCall(CSMeshDataDestroy(&md));
  }
  PetscCall(CSMeshDataFlatTorus(0, 1, 32, 32, &md));
  PetscCall(CheckTopology(&md, 1024, 2048, 1, 0, 0));
  PetscCall(Check((PetscBool)(SignedVolume(&md) > 0), "flattorus outward", "volume %.4f", (double)SignedVolume(&md)));
  PetscCall(CSMeshDataDestroy(&md));
  PetscCall(CSMeshDataFlatTorus(0, 2, 16, 32, &md));
  PetscCall(CheckTopology(&md, 512, 1024, 1, 0, 0));
  PetscCall(Check((PetscBool)(SignedVolume(&md) > 0), "flattorus(tau_im=2) outward", "volume %.4f", (double)SignedVolume(&md)));
  PetscCall(CSMeshDataDestroy(&md));
  {
    PetscBool out = PETSC_TRUE;
    PetscCall(CSMeshDataCylinder(1, 2, 24, 8, &md));
    PetscCall(CheckTopology(&md, 24 * 9, 2 * 24 * 8, 0, 2, 0));
    for (PetscInt i = 0; i < md.nf; i++) {
      PetscReal n[3], c[3];
      FaceNormal(&md, i, n, c);
      if (n[0] * c[0] + n[1] * c[1] <= 0) out = PETSC_FALSE;
    }
    PetscCall(Check(out, "cylinder outward", "every face normal points away from the axis"));
    PetscCall(CSMeshDataDestroy(&md));
  }
  {
    PetscBool up = PETSC_TRUE;
    PetscReal rmax = 0;
    PetscCall(CSMeshDataDisk(1, 8, &md));
    PetscCall(CheckTopology(&md, 1 + 3 * 8 * 9, 6 * 64, 0, 1, 1));
    for (PetscInt i = 0; i < md.nf; i++) {
      PetscReal n[3], c[3];
      FaceNormal(&md, i, n, c);
      if (n[2] <= 0) up = PETSC_FALSE;
    }
    for (PetscInt v = 0; v < md.nv; v++) rmax = PetscMax(rmax, PetscSqrtReal(md.x[3 * v] * md.x[3 * v] + md.x[3 * v + 1] * md.x[3 * v + 1]));
    PetscCall(Check((PetscBool)(up && PetscAbsReal(rmax - 1) < 1e-14), "disk normals +z, radius 1", "radius %.15f", (double)rmax));
    PetscCall(CSMeshDataDestroy(&md));
  }
  {
    PetscErrorCode ierr;
    char           msg[1024];
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CSMeshDataFlatTorus(0.5, 1, 16, 16, &md);
    PetscCall(PetscPopErrorHandler());
    PetscCall(ErrorText(ierr, msg, sizeof(msg)));
    PetscCall(Check((PetscBool)(ierr && strstr(msg, "rectangular")), "flattorus tau_re != 0 refused", "%s", msg));
  }
  PetscFunctionReturn(0);
}

/* The flat torus' conformal class, checked three ways:
   1. exactly (to rounding): every vertex, mapped back to S^3 by inverse stereographic projection, lies on the
      product of circles |z1| = r1, |z2| = r2 with r2/r1 = tau_im, and the two generating loops (regular n-gons
      on those circles when n = m) have length ratio exactly tau_im: the mesh samples the flat torus whose
      lattice is the rectangle 2 pi r1 x 2 pi r2, i.e. modulus tau = i tau_im;
   2. for tau_im = 1 the image is exactly the torus of revolution R = sqrt 2, r = 1 (the default -gen_R/-gen_r);
   3. in R^3, conformality of the map: at every vertex the central differences along the two grid directions
      are orthogonal and of length ratio tau_im n/m, up to O(h^2): with m = tau_im n the grid cells become
      squares in the limit. The defect must fall by about 4 when n doubles. */
static PetscErrorCode ConformalDefect(PetscReal tau_im, PetscInt n, PetscInt m, PetscReal *defect)
{
  CSMeshData md;

  PetscFunctionBeginUser;
  *defect = 0;
  PetscCall(CSMeshDataFlatTorus(0, tau_im, n, m, &md));
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < m; j++) {
      const PetscReal *pa = md.x + 3 * (((i + 1) % n) * m + j), *pb = md.x + 3 * (((i + n - 1) % n) * m + j);
      const PetscReal *qa = md.x + 3 * (i * m + (j + 1) % m), *qb = md.x + 3 * (i * m + (j + m - 1) % m);
      PetscReal        du[3], dv[3], nu = 0, nv = 0, dot = 0;
      for (int d = 0; d < 3; d++) {
        du[d] = pa[d] - pb[d];
        dv[d] = qa[d] - qb[d];
        nu += du[d] * du[d];
        nv += dv[d] * dv[d];
        dot += du[d] * dv[d];
      }
      nu      = PetscSqrtReal(nu);
      nv      = PetscSqrtReal(nv);
      *defect = PetscMax(*defect, PetscAbsReal(nv / nu * m / (tau_im * n) - 1) + PetscAbsReal(dot / (nu * nv)));
    }
  PetscCall(CSMeshDataDestroy(&md));
  PetscFunctionReturn(0);
}

static PetscErrorCode TestFlatTorus(void)
{
  CSMeshData md;

  PetscFunctionBeginUser;
  for (PetscReal tau = 1; tau <= 2; tau += 1) {
    PetscInt  n = 24, m = 24;
    PetscReal r1 = 1 / PetscSqrtReal(1 + tau * tau), r2 = tau * r1, err = 0, la = 0, lb = 0, (*X)[4];
    char      name[64];
    PetscCall(CSMeshDataFlatTorus(0, tau, n, m, &md));
    PetscCall(PetscMalloc1(md.nv, &X));
    for (PetscInt v = 0; v < md.nv; v++) {
      const PetscReal *p = md.x + 3 * v;
      PetscReal        s = p[0] * p[0] + p[1] * p[1] + p[2] * p[2];
      for (int d = 0; d < 3; d++) X[v][d] = 2 * p[d] / (s + 1);
      X[v][3] = (s - 1) / (s + 1);
      err     = PetscMax(err, PetscAbsReal(PetscSqrtReal(X[v][0] * X[v][0] + X[v][1] * X[v][1]) - r1));
      err     = PetscMax(err, PetscAbsReal(PetscSqrtReal(X[v][2] * X[v][2] + X[v][3] * X[v][3]) - r2));
    }
    for (PetscInt k = 0; k < n; k++) { /* loop a: j = 0, i = 0..n-1; loop b: i = 0, j = 0..m-1 */
      PetscReal da = 0, db = 0;
      for (int d = 0; d < 4; d++) {
        da += PetscSqr(X[((k + 1) % n) * m][d] - X[k * m][d]);
        db += PetscSqr(X[(k + 1) % m][d] - X[k][d]);
      }
      la += PetscSqrtReal(da);
      lb += PetscSqrtReal(db);
    }
    PetscCall(PetscSNPrintf(name, sizeof(name), "flattorus(tau_im=%g) modulus", (double)tau));
    PetscCall(Check((PetscBool)(err < 1e-12 && PetscAbsReal(lb / la - tau) < 1e-12), name, "on |z1|=r1, |z2|=r2 to %.1e in S^3; loop length ratio %.15f (expected %g)", (double)err, (double)(lb / la), (double)tau));
    PetscCall(PetscFree(X));
    if (tau == 1) {
      PetscReal e = 0;
      for (PetscInt v = 0; v < md.nv; v++) {
        const PetscReal *p = md.x + 3 * v;
        e = PetscMax(e, PetscAbsReal(PetscSqr(PetscSqrtReal(p[0] * p[0] + p[1] * p[1]) - PetscSqrtReal(2.0)) + p[2] * p[2] - 1));
      }
      PetscCall(Check((PetscBool)(e < 1e-12), "flattorus(tau_im=1) is the torus of revolution R=sqrt2, r=1", "max defect %.1e", (double)e));
    }
    PetscCall(CSMeshDataDestroy(&md));
  }
  for (PetscReal tau = 1; tau <= 2; tau += 1) {
    PetscReal d1, d2;
    char      name[64];
    PetscCall(ConformalDefect(tau, 32, (PetscInt)(32 * tau), &d1));
    PetscCall(ConformalDefect(tau, 64, (PetscInt)(64 * tau), &d2));
    PetscCall(PetscSNPrintf(name, sizeof(name), "flattorus(tau_im=%g) square cells in the limit", (double)tau));
    PetscCall(Check((PetscBool)(d2 < 2e-2 && d1 / d2 > 3.5), name, "conformality defect %.2e (n=32), %.2e (n=64), ratio %.2f (O(h^2): 4)", (double)d1, (double)d2, (double)(d1 / d2)));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode RoundTrip(CSMeshData *md, const char dir[])
{
  const char *ext[] = {"obj", "ply", "off", "obj"};
  CSMeshData  cur, next;
  char        path[PETSC_MAX_PATH_LEN], name[PETSC_MAX_PATH_LEN + 64];

  PetscFunctionBeginUser;
  PetscCall(CSMeshDataDuplicate(md, &cur));
  PetscCall(PetscSNPrintf(name, sizeof(name), "%s duplicate", md->name));
  PetscCall(Check((PetscBool)(SameData(md, &cur) && !strcmp(md->name, cur.name)), name, ""));
  for (int k = 0; k < 4; k++) { /* OBJ -> PLY -> OFF -> OBJ, each compared with the original, bit for bit */
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/rt%d.%s", dir, k, ext[k]));
    PetscCall(CSMeshDataWrite(path, &cur));
    PetscCall(CSMeshDataRead(path, &next));
    PetscCall(PetscSNPrintf(name, sizeof(name), "%s round trip %s", md->name, ext[k]));
    PetscCall(Check(SameData(md, &next), name, "bitwise equal coordinates and faces"));
    PetscCall(CSMeshDataDestroy(&cur));
    cur = next;
    (void)remove(path);
  }
  PetscCall(CSMeshDataDestroy(&cur));
  PetscFunctionReturn(0);
}

static PetscErrorCode TestIO(const char data[], const char tmp[])
{
  CSMeshData md, other;
  CSTopology topo;
  char       path[PETSC_MAX_PATH_LEN], msg[1024];
  const char *same[] = {"tetra.off", "tetra_ascii.ply", "tetra_binary.ply"};
  PetscErrorCode ierr;

  PetscFunctionBeginUser;
  PetscCall(CSMeshDataTorus(PetscSqrtReal(2.0), 1, 32, 16, &md));
  PetscCall(RoundTrip(&md, tmp));
  PetscCall(CSMeshDataDestroy(&md));
  PetscCall(CSMeshDataIcosphere(3, 1.0, PETSC_TRUE, &md));
  PetscCall(RoundTrip(&md, tmp));
  PetscCall(CSMeshDataDestroy(&md));

  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/tetra.obj", data));
  PetscCall(TryLoad(path, &md, &topo, &ierr, msg, sizeof(msg)));
  if (ierr) {
    PetscCall(Check(PETSC_FALSE, "tetra.obj", "%s (run from the repository root or pass -data_dir)", msg));
    PetscFunctionReturn(0);
  }
  PetscCall(Check((PetscBool)(md.nv == 4 && md.nf == 4 && topo.genus == 0 && topo.euler == 2 && md.x[3] == 1.25 && md.x[11] == 0.75 && md.f[6] == 0 && md.f[7] == 3 && md.f[8] == 2 && SignedVolume(&md) > 0), "tetra.obj (slash forms, negative indices, ignored lines)", "V=%" PetscInt_FMT " F=%" PetscInt_FMT ", volume %g", md.nv, md.nf, (double)SignedVolume(&md)));
  for (size_t k = 0; k < sizeof(same) / sizeof(same[0]); k++) {
    char name[128];
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", data, same[k]));
    PetscCall(TryLoad(path, &other, &topo, &ierr, msg, sizeof(msg)));
    PetscCall(PetscSNPrintf(name, sizeof(name), "%s equals tetra.obj", same[k]));
    PetscCall(Check((PetscBool)(!ierr && SameData(&md, &other)), name, "%s", ierr ? msg : "bitwise equal"));
    PetscCall(CSMeshDataDestroy(&other));
  }
  PetscCall(CSMeshDataDestroy(&md));

  PetscCall(PetscSNPrintf(path, sizeof(path), "%s/unreferenced_vertex.obj", data));
  PetscCall(TryLoad(path, &md, &topo, &ierr, msg, sizeof(msg)));
  PetscCall(Check((PetscBool)(!ierr && md.nv == 4 && topo.vertices == 4 && topo.dropped_vertices == 1 && topo.genus == 0 && md.x[6] == 0 && md.x[7] == 1 && md.f[0] == 0 && md.f[1] == 2 && md.f[2] == 1), "unreferenced_vertex.obj accepted, vertex dropped and faces renumbered", "%s", msg));
  PetscCall(CSMeshDataDestroy(&md));
  PetscFunctionReturn(0);
}

/* Bad inputs: each must be refused, with the file (and line or element) and a telling word in the message. */
static PetscErrorCode TestBadFiles(const char data[])
{
  const struct {
    const char *file, *where, *word;
  } bad[] = {
    {"empty.obj",                    "empty.obj:1:",                     "empty"                       },
    {"truncated.off",                "truncated.off:2:",                 "truncated"                   },
    {"truncated_binary.ply",         "truncated_binary.ply:18:", "truncated"            },
    {"garbage.obj",                  "garbage.obj:4:",                   "garbage 'abc'"               },
    {"index_out_of_range.obj",       "index_out_of_range.obj:5:",        "out of range"                },
    {"nan.obj",                      "nan.obj:2:",                       "NaN"                         },
    {"inf.ply",                      "inf.ply:12:",                      "Inf"                         },
    {"quad_face.obj",                "quad_face.obj:5:",                 "polygon face with 4 vertices"},
    {"bigendian.ply",                "bigendian.ply:2:",                 "unsupported PLY format"      },
    {"no_such_file.obj",             "no_such_file.obj:",                "cannot open"                 },
    {"repeated_vertex.obj",          "face 1 (vertices 0 2 2)",          "repeated vertex"             },
    {"zero_area.obj",                "face 1 (vertices 0 3 1)",          "zero-area"                   },
    {"duplicate_face.obj",           "face 0 (vertices 0 2 1)",          "duplicate"                   },
    {"nonmanifold_edge.obj",         "edge (0, 1) shared by 3 faces",    "non-manifold"                },
    {"pinched_vertex.obj",           "vertex 0",                         "pinched"                     },
    {"inconsistent_orientation.obj", "and face",                            "orientation"                 },
  };

  PetscFunctionBeginUser;
  for (size_t k = 0; k < sizeof(bad) / sizeof(bad[0]); k++) {
    CSMeshData     md;
    CSTopology     topo;
    PetscErrorCode ierr;
    char           path[PETSC_MAX_PATH_LEN], msg[1024], name[128];
    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", data, bad[k].file));
    PetscCall(TryLoad(path, &md, &topo, &ierr, msg, sizeof(msg)));
    if (!ierr) PetscCall(CSMeshDataDestroy(&md));
    PetscCall(PetscSNPrintf(name, sizeof(name), "%s refused", bad[k].file));
    PetscCall(Check((PetscBool)(ierr && strstr(msg, path) && strstr(msg, bad[k].where) && strstr(msg, bad[k].word)), name, "%s", ierr ? msg : "accepted"));
  }
  /* what the readers cannot produce but callers can: validation catches it in memory */
  {
    CSMeshData     md, bad;
    CSTopology     topo;
    PetscErrorCode ierr;
    char           msg[1024];
    PetscCall(CSMeshDataIcosphere(1, 1.0, PETSC_TRUE, &md));
    PetscCall(CSMeshDataDuplicate(&md, &bad));
    bad.x[3 * 5 + 1] = (PetscReal)NAN;
    PetscCall(TryValidate(&bad, &topo, &ierr, msg, sizeof(msg)));
    PetscCall(Check((PetscBool)(ierr && strstr(msg, "vertex 5") && strstr(msg, "NaN")), "validate refuses NaN in memory", "%s", msg));
    bad.x[3 * 5 + 1] = (PetscReal)INFINITY;
    PetscCall(TryValidate(&bad, &topo, &ierr, msg, sizeof(msg)));
    PetscCall(Check((PetscBool)(ierr && strstr(msg, "Inf")), "validate refuses Inf in memory", "%s", msg));
    PetscCall(CSMeshDataDestroy(&bad));
    PetscCall(CSMeshDataDuplicate(&md, &bad));
    bad.f[3 * 7 + 2] = bad.nv;
    PetscCall(TryValidate(&bad, &topo, &ierr, msg, sizeof(msg)));
    PetscCall(Check((PetscBool)(ierr && strstr(msg, "face 7") && strstr(msg, "out of range")), "validate refuses an index out of range in memory", "%s", msg));
    PetscCall(CSMeshDataDestroy(&bad));
    /* a closed mesh oriented inward is not refused here (the mesh layer reports/flips it) */
    PetscCall(CSMeshDataDuplicate(&md, &bad));
    for (PetscInt i = 0; i < bad.nf; i++) {
      PetscInt t       = bad.f[3 * i + 1];
      bad.f[3 * i + 1] = bad.f[3 * i + 2];
      bad.f[3 * i + 2] = t;
    }
    PetscCall(TryValidate(&bad, &topo, &ierr, msg, sizeof(msg)));
    PetscCall(Check((PetscBool)(!ierr && topo.genus == 0 && SignedVolume(&bad) < 0), "validate accepts an inward-oriented closed mesh", "%s", msg));
    PetscCall(CSMeshDataDestroy(&bad));
    PetscCall(CSMeshDataDestroy(&md));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode TestOptions(const char data[])
{
  CSMeshData     md;
  CSTopology     topo;
  PetscMPIInt    rank;
  PetscErrorCode ierr;
  char           path[PETSC_MAX_PATH_LEN], msg[1024];
  const struct {
    const char *prefix, *opts, *word; /* word == NULL: must succeed */
    PetscInt    nv;
  } cases[] = {
    {"t1_", "-t1_gen icosphere -t1_gen_level 2",                     NULL,          162 },
    {"t2_", "-t2_gen disk -t2_gen_rings 3",                          NULL,          37  },
    {"t3_", "-t3_gen flattorus -t3_gen_n 8 -t3_gen_m 16 -t3_gen_tau_im 2", NULL,    128 },
    {"t4_", "-t4_gen torus",                                         NULL,          512 },
    {"t5_", "-t5_gen cylinder -t5_gen_n 6 -t5_gen_m 2",              NULL,          18  },
    {"t6_", "",                                                      "neither",     0   },
    {"t7_", "-t7_gen torus -t7_mesh x.obj",                          "both",        0   },
    {"t8_", "-t8_gen flattorus -t8_gen_tau_re 0.5",                  "rectangular", 0   },
    {"t9_", "-t9_mesh %s/pinched_vertex.obj",                        "pinched",     0   },
    {"ta_", "-ta_mesh %s/tetra_binary.ply",                          NULL,          4   },
  };

  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(PETSC_COMM_WORLD, &rank));
  for (size_t k = 0; k < sizeof(cases) / sizeof(cases[0]); k++) {
    char name[256];
    PetscCall(PetscSNPrintf(path, sizeof(path), cases[k].opts, data));
    PetscCall(PetscOptionsInsertString(NULL, path));
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CSMeshDataFromOptions(PETSC_COMM_WORLD, cases[k].prefix, &md, &topo);
    PetscCall(PetscPopErrorHandler());
    PetscCall(ErrorText(ierr, msg, sizeof(msg)));
    PetscCall(PetscSNPrintf(name, sizeof(name), "options '%s'", path));
    if (cases[k].word) PetscCall(Check((PetscBool)(ierr && strstr(msg, cases[k].word)), name, "%s", ierr ? msg : "accepted"));
    else PetscCall(Check((PetscBool)(!ierr && md.nv == (rank ? 0 : cases[k].nv) && (rank || topo.vertices == cases[k].nv) && (!rank || (!md.x && !md.f))), name, "%s V=%" PetscInt_FMT " (%s)", ierr ? msg : "", md.nv, md.name));
    if (!ierr) PetscCall(CSMeshDataDestroy(&md));
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode DirExists(const char dir[], PetscBool *flg)
{
  PetscFunctionBeginUser;
  PetscCall(PetscTestDirectory(dir, 'r', flg));
  PetscFunctionReturn(0);
}

/* The real meshes (facts from the README of the shared collection). */
static PetscErrorCode TestRealMeshes(const char dir[], const char label[], PetscBool onlyPresent)
{
  const struct {
    const char *file;
    PetscInt    V, F, genus, loops; /* genus < 0: bad input, must be refused */
  } real[] = {
    {"bunny_closed_cgal.obj",           37706, 75408, 0,  0 },
    {"armadillo_cgal.obj",              26002, 52000, 0,  0 },
    {"cow_cgal.obj",                    2904,  5804,  0,  0 },
    {"bunny_lowres_npm.obj",            1839,  3674,  0,  0 },
    {"man_cgal.obj",                    17495, 34986, 0,  0 },
    {"triceratops_cgal.obj",            2832,  5660,  0,  0 },
    {"knot1_cgal.obj",                  3200,  6400,  1,  0 },
    {"eight_cgal.obj",                  315,   634,   2,  0 },
    {"elephant_cgal.obj",               2775,  5558,  3,  0 },
    {"nefertiti_cgal.obj",              299,   562,   0,  1 },
    {"lion_head_cgal.obj",              8356,  16674, 0,  1 },
    {"cylinder_cgal.obj",               1200,  2262,  0,  1 },
    {"mushroom_open_cgal.obj",          2337,  4608,  0,  1 },
    {"pig_stl_nonmanifold_cgal.obj",    8642,  16848, -1, 5 },
    {"dragon_res3_nonmanifold_npm.obj", 22998, 47794, -1, -1},
  };
  PetscBool flg;

  PetscFunctionBeginUser;
  PetscCall(DirExists(dir, &flg));
  if (!flg) {
    PetscCall(Check(PETSC_TRUE, label, "skipped (no directory %s)", dir));
    PetscFunctionReturn(0);
  }
  for (size_t k = 0; k < sizeof(real) / sizeof(real[0]); k++) {
    CSMeshData     md;
    CSTopology     topo;
    PetscErrorCode ierr;
    PetscLogDouble t0, t1, t2;
    char           path[PETSC_MAX_PATH_LEN], msg[1024], name[PETSC_MAX_PATH_LEN + 64];

    PetscCall(PetscSNPrintf(path, sizeof(path), "%s/%s", dir, real[k].file));
    PetscCall(PetscTestFile(path, 'r', &flg));
    if (!flg && onlyPresent) continue;
    PetscCall(PetscSNPrintf(name, sizeof(name), "%s %s", label, real[k].file));
    PetscCall(PetscTime(&t0));
    PetscCall(PetscPushErrorHandler(PetscReturnErrorHandler, NULL));
    ierr = CSMeshDataRead(path, &md);
    PetscCall(PetscTime(&t1));
    if (!ierr) {
      ierr = CSMeshDataValidate(&md, &topo);
      if (ierr) PetscCall(CSMeshDataDestroy(&md));
    }
    PetscCall(PetscTime(&t2));
    PetscCall(PetscPopErrorHandler());
    PetscCall(ErrorText(ierr, msg, sizeof(msg)));
    if (real[k].genus < 0) {
      PetscCall(Check((PetscBool)(ierr && (strstr(msg, "non-manifold") || strstr(msg, "pinched") || strstr(msg, "duplicate"))), name, "refused: %s", ierr ? msg : "accepted"));
      if (!ierr) PetscCall(CSMeshDataDestroy(&md));
      continue;
    }
    if (ierr) {
      PetscCall(Check(PETSC_FALSE, name, "%s", msg));
      continue;
    }
    PetscCall(Check((PetscBool)(md.nv == real[k].V && md.nf == real[k].F && topo.genus == real[k].genus && topo.boundary_loops == real[k].loops && topo.components == 1 && (real[k].loops || SignedVolume(&md) > 0)), name,
                    "V=%" PetscInt_FMT " F=%" PetscInt_FMT " genus %" PetscInt_FMT " loops %" PetscInt_FMT " components %" PetscInt_FMT " (README: %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT " %" PetscInt_FMT "); read %.3f s, validate %.3f s", md.nv, md.nf, topo.genus, topo.boundary_loops, topo.components, real[k].V, real[k].F, real[k].genus, real[k].loops, t1 - t0, t2 - t1));
    PetscCall(CSMeshDataDestroy(&md));
  }
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  char      data[PETSC_MAX_PATH_LEN] = "tests/data", meshes[PETSC_MAX_PATH_LEN] = "meshes", shared[PETSC_MAX_PATH_LEN] = "../shared/meshes";
  char      tmp[] = "/tmp/cs_test_meshdata_XXXXXX";
  PetscBool flg;

  PetscCall(PetscInitialize(&argc, &argv, NULL, "Unit test of the serial mesh-data layer"));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-data_dir", data, sizeof(data), NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-meshes_dir", meshes, sizeof(meshes), NULL));
  PetscCall(PetscOptionsGetString(NULL, NULL, "-shared_meshes", shared, sizeof(shared), NULL));
  PetscCheck(mkdtemp(tmp), PETSC_COMM_SELF, PETSC_ERR_FILE_OPEN, "cannot create a temporary directory %s", tmp);
  PetscCall(DirExists(data, &flg));
  if (!flg) PetscCall(Check(PETSC_FALSE, "test data", "no directory %s (run from the repository root or pass -data_dir)", data));

  PetscCall(TestGenerators());
  PetscCall(TestFlatTorus());
  PetscCall(TestIO(data, tmp));
  PetscCall(TestBadFiles(data));
  PetscCall(TestOptions(data));
  PetscCall(TestRealMeshes(meshes, "meshes/", PETSC_TRUE));
  PetscCall(TestRealMeshes(shared, "shared", PETSC_FALSE));

  (void)rmdir(tmp);
  PetscCall(PetscPrintf(PETSC_COMM_WORLD, "%" PetscInt_FMT " failure%s\n", cs_test_failures, cs_test_failures == 1 ? "" : "s"));
  PetscCall(PetscFinalize());
  return (int)cs_test_failures;
}
