static const char help[] = "Checks of the texture coordinates (issue 38): the generators' UVs (no face across a seam, one\n"
                           "orientation), their distribution with the faces, and the texture distortion Q of\n"
                           "CSGeometryTextureQ on known maps. One line per check; the exit status is the number of failures.\n";

#include "cs_geometry.h"
#include "cs_test.h"

/* the k x k unit square in z = 0, each cell cut along its diagonal, with identity UVs (u, v) = (x, y) */
static PetscErrorCode Square(PetscInt k, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(md, sizeof(*md)));
  md->nv = md->nuv = (k + 1) * (k + 1);
  md->nf           = 2 * k * k;
  PetscCall(PetscMalloc1(3 * md->nv, &md->x));
  PetscCall(PetscMalloc1(2 * md->nuv, &md->uv));
  PetscCall(PetscMalloc1(3 * md->nf, &md->f));
  PetscCall(PetscMalloc1(3 * md->nf, &md->fuv));
  for (PetscInt j = 0; j <= k; j++)
    for (PetscInt i = 0; i <= k; i++) {
      PetscInt v        = j * (k + 1) + i;
      md->x[3 * v]      = md->uv[2 * v] = (PetscReal)i / k;
      md->x[3 * v + 1]  = md->uv[2 * v + 1] = (PetscReal)j / k;
      md->x[3 * v + 2]  = 0;
    }
  for (PetscInt j = 0; j < k; j++)
    for (PetscInt i = 0; i < k; i++) {
      PetscInt a = j * (k + 1) + i, b = a + 1, c = b + k + 1, d = a + k + 1, *t = md->f + 6 * (j * k + i);
      t[0] = a, t[1] = b, t[2] = c, t[3] = a, t[4] = c, t[5] = d;
    }
  PetscCall(PetscArraycpy(md->fuv, md->f, 3 * md->nf));
  PetscCall(PetscSNPrintf(md->name, sizeof(md->name), "square %" PetscInt_FMT, k));
  PetscFunctionReturn(0);
}

/* identity UVs: Q = 1; x stretched by s: the affine map is diag(s, 1) on every face, Q = s (mean and max) */
static PetscErrorCode CheckSquare(MPI_Comm comm)
{
  CSMeshData md;
  CSMesh     mesh;
  PetscReal  qm, qx, s = 2.5;
  PetscFunctionBeginUser;
  PetscCall(Square(12, &md));
  PetscCall(CSTestDistribute(comm, &md, 0, 0, &mesh));
  PetscCall(CSGeometryTextureQ(mesh, mesh->x, NULL, &qm, &qx));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(qm - 1) <= 1e-12 && PetscAbsReal(qx - 1) <= 1e-12), "square, identity UVs: |texture_q - 1| (mean, max)", PetscMax(PetscAbsReal(qm - 1), PetscAbsReal(qx - 1)), 1e-12));
  PetscCall(VecStrideScale(mesh->x, 0, s));
  PetscCall(CSGeometryTextureQ(mesh, mesh->x, NULL, &qm, &qx));
  PetscCall(CSTestCheck(comm, (PetscBool)(PetscAbsReal(qm - s) <= 1e-12 && PetscAbsReal(qx - s) <= 1e-12), "square stretched by 2.5 in x: |texture_q - 2.5| (mean, max)", PetscMax(PetscAbsReal(qm - s), PetscAbsReal(qx - s)), 1e-12));
  PetscCall(CSMeshDestroy(&mesh));
  PetscFunctionReturn(0);
}

/* rank 0: every UV triangle has the sign of the first (one orientation: no face folded over a seam) and no UV edge
   is longer than 0.5 (a face spanning a seam would have an edge of length about 1) */
static PetscErrorCode CheckSeams(const CSMeshData *md, PetscReal *bad)
{
  PetscReal s0 = 0;
  PetscFunctionBeginUser;
  *bad = 0;
  PetscCheck(md->fuv && md->uv, PETSC_COMM_SELF, PETSC_ERR_PLIB, "%s: no texture coordinates", md->name);
  for (PetscInt f = 0; f < md->nf; f++) {
    const PetscReal *a = md->uv + 2 * md->fuv[3 * f], *b = md->uv + 2 * md->fuv[3 * f + 1], *c = md->uv + 2 * md->fuv[3 * f + 2];
    PetscReal        s = (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
    if (f == 0) s0 = s;
    if (!(s * s0 > 0)) *bad += 1;
    for (int k = 0; k < 3; k++) {
      const PetscReal *p = md->uv + 2 * md->fuv[3 * f + k], *q = md->uv + 2 * md->fuv[3 * f + (k + 1) % 3];
      if (PetscSqrtReal(PetscSqr(p[0] - q[0]) + PetscSqr(p[1] - q[1])) > 0.5) *bad += 1;
    }
  }
  PetscFunctionReturn(0);
}

static PetscErrorCode CheckGenerators(MPI_Comm comm)
{
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  if (rank) PetscFunctionReturn(0);
  for (int g = 0; g < 8; g++) {
    CSMeshData md;
    PetscReal  bad;
    char       what[PETSC_MAX_PATH_LEN + 64];
    switch (g) {
    case 0: PetscCall(CSMeshDataTorus(2, 1, 12, 8, &md)); break;
    case 1: PetscCall(CSMeshDataFlatTorus(0, 1.3, 12, 9, &md)); break;
    case 2: PetscCall(CSMeshDataLattice(0.3, 1.1, 9, 8, &md)); break;
    case 3: PetscCall(CSMeshDataLattice(-0.4, 0.9, 9, 8, &md)); break;
    case 4: PetscCall(CSMeshDataCylinder(1, 2, 12, 5, &md)); break;
    case 5: PetscCall(CSMeshDataDisk(1, 4, &md)); break;
    case 6: PetscCall(CSMeshDataMorin(12, 8, 0.05, CS_MORIN_APERY, PETSC_FALSE, &md)); break;
    default: PetscCall(CSMeshDataMorin(12, 8, 0.05, CS_MORIN_KUSNER, PETSC_TRUE, &md)); break;
    }
    PetscCall(CheckSeams(&md, &bad));
    PetscCall(PetscSNPrintf(what, sizeof(what), "%s: UV faces of the wrong sign or across a seam", md.name));
    PetscCall(CSTestCheck(PETSC_COMM_SELF, (PetscBool)(bad == 0), what, bad, 0));
    PetscCall(CSMeshDataDestroy(&md));
  }
  PetscFunctionReturn(0);
}

/* -gen torus R = 2, r = 1 with the angles as UVs: the map (u, v) -> torus stretches by 2 pi (R + r cos v) and 2 pi r,
   so Q = (R + r cos v)/r, whose mean over v (UV-area weighted) is R/r = 2. The discrete error is O(h^2): it must
   shrink by about 4 when n = m doubles. Distributed: every corner must find its UV. */
static PetscErrorCode CheckTorus(MPI_Comm comm)
{
  PetscReal   err[2];
  PetscMPIInt rank;
  PetscFunctionBeginUser;
  PetscCallMPI(MPI_Comm_rank(comm, &rank));
  for (int k = 0; k < 2; k++) {
    CSMeshData md;
    CSMesh     mesh;
    PetscReal  qm, qx;
    PetscCall(PetscMemzero(&md, sizeof(md)));
    if (!rank) PetscCall(CSMeshDataTorus(2, 1, 24 << k, 24 << k, &md));
    PetscCall(CSTestDistribute(comm, &md, 0, 0, &mesh));
    PetscCall(CSGeometryTextureQ(mesh, mesh->x, NULL, &qm, &qx));
    err[k] = PetscAbsReal(qm - 2);
    PetscCall(CSTestCheck(comm, (PetscBool)(qx <= 3 * 1.01 && qx >= 3 * 0.99), "torus R=2 r=1: texture_q_max against (R + r)/r = 3", qx, 3));
    PetscCall(CSMeshDestroy(&mesh));
  }
  PetscCall(CSTestCheck(comm, (PetscBool)(err[0] < 0.05 && err[0] / err[1] > 3 && err[0] / err[1] < 5), "torus: |texture_q_mean - R/r| at n = 24 over that at n = 48 (O(h^2): about 4)", err[0] / err[1], 4));
  PetscFunctionReturn(0);
}

int main(int argc, char **argv)
{
  MPI_Comm comm;
  PetscCall(PetscInitialize(&argc, &argv, NULL, help));
  comm = PETSC_COMM_WORLD;
  PetscCall(CheckSquare(comm));
  PetscCall(CheckGenerators(comm));
  PetscCall(CheckTorus(comm));
  return CSTestFinalize(comm, PetscFinalize);
}
