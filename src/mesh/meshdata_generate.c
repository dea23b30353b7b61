/* Generated test surfaces: icosphere, torus of revolution, flat (rectangular-class) torus, lattice torus (any class),
   open cylinder,
   flat disk. All are outward oriented (normals by the right-hand rule on counter-clockwise corners) and have
   no duplicate vertices. All but the icosphere carry their natural parameters as texture coordinates (issue 38). */
#include "meshdata_generate_impl.h"
#include "cs_util.h"
#include <stdio.h>

/* The sizes of a generated mesh, computed in 64 bits by the caller (issue 18, item 2: n*m in PetscInt overflowed),
   checked against PetscInt (3 indices per face) and against the memory a run needs: -task info measured about
   3.3 KB per vertex (icosphere levels 6 and 7: mesh, adjacency, operators), the flows more. */
#define CS_BYTES_PER_VERTEX 3300
static PetscErrorCode CheckSize(const char what[], double nv, double nf)
{
  char msg[256];
  PetscFunctionBeginUser;
  PetscCheck(3 * nf <= (double)PETSC_MAX_INT, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "%s: %.0f vertices, %.0f faces: the 3 x %.0f face indices exceed the largest PetscInt of this PETSc build (%" PetscInt_FMT ")", what, nv, nf, nf, (PetscInt)PETSC_MAX_INT);
  PetscCall(PetscSNPrintf(msg, sizeof(msg), "%s: %.0f vertices, %.0f faces, at about %d bytes per vertex for a run", what, nv, nf, CS_BYTES_PER_VERTEX));
  PetscCall(CSCheckAllocation(msg, (double)nv, CS_BYTES_PER_VERTEX));
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataAlloc(const char what[], double nv, double nf, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCall(CheckSize(what, nv, nf));
  PetscCall(PetscMemzero(md, sizeof(*md)));
  md->nv = (PetscInt)nv;
  md->nf = (PetscInt)nf;
  PetscCall(PetscMalloc1(3 * md->nv, &md->x));
  PetscCall(PetscMalloc1(3 * md->nf, &md->f));
  PetscFunctionReturn(0);
}

/* Two triangles (a b c), (a c d) for the quad a b c d, counter-clockwise. */
static inline void Quad(PetscInt *t, PetscInt a, PetscInt b, PetscInt c, PetscInt d)
{
  t[0] = a;
  t[1] = b;
  t[2] = c;
  t[3] = a;
  t[4] = c;
  t[5] = d;
}

/* Closed surfaces only: flip every face if the enclosed (signed) volume is negative. */
void CSMeshDataOrientOutward(CSMeshData *md)
{
  PetscReal vol = 0;
  for (PetscInt i = 0; i < md->nf; i++) {
    const PetscReal *a = md->x + 3 * md->f[3 * i], *b = md->x + 3 * md->f[3 * i + 1], *c = md->x + 3 * md->f[3 * i + 2];
    vol += a[0] * (b[1] * c[2] - b[2] * c[1]) + a[1] * (b[2] * c[0] - b[0] * c[2]) + a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  if (vol >= 0) return;
  for (PetscInt i = 0; i < md->nf; i++) {
    PetscInt t       = md->f[3 * i + 1];
    md->f[3 * i + 1] = md->f[3 * i + 2];
    md->f[3 * i + 2] = t;    if (md->len) { /* corners 1 and 2 swapped: so are the edges opposite them */
      PetscReal l        = md->len[3 * i + 1];
      md->len[3 * i + 1] = md->len[3 * i + 2];
      md->len[3 * i + 2] = l;
    }
  }
}

/* Grid offset of vertex b from vertex a along one periodic direction of k >= 3 segments: -1, 0 or 1. */
static inline PetscInt GridStep(PetscInt a, PetscInt b, PetscInt k)
{
  return (b - a + k + 1) % k - 1;
}

/* Texture coordinates of a quad grid (issue 38): face f lies in quad q = f/2 at (qi, qj), and each corner gets the
   UV of its grid point unwrapped from the quad's, (gi, gj) = (qi + di, qj + dj) with di, dj in {0, 1}, so a seam
   column gi = n (or row gj = m) repeats gi = 0 with u = 1: uv(gi, gj) = (gi/n + a gj, b gj) on an (n+1) x (m+1) list.
   Periodic in i (n around) and, unless cyl, in j; cyl: vertex j n + i and quad j n + i (-gen cylinder), else vertex
   i m + j and quad i m + j (the tori). Found from the vertices of the final faces, so any orientation flip is kept. */
PetscErrorCode CSMeshDataGridUVs(CSMeshData *md, PetscInt n, PetscInt m, PetscBool cyl, PetscReal a, PetscReal b)
{
  PetscFunctionBeginUser;
  md->nuv = (n + 1) * (m + 1);
  PetscCall(PetscMalloc1(2 * md->nuv, &md->uv));
  PetscCall(PetscMalloc1(3 * md->nf, &md->fuv));
  for (PetscInt gi = 0; gi <= n; gi++)
    for (PetscInt gj = 0; gj <= m; gj++) {
      md->uv[2 * (gi * (m + 1) + gj)]     = (PetscReal)gi / n + a * gj;
      md->uv[2 * (gi * (m + 1) + gj) + 1] = b * gj;
    }
  for (PetscInt f = 0; f < md->nf; f++) {
    PetscInt q = f / 2, qi = cyl ? q % n : q / m, qj = cyl ? q / n : q % m;
    for (int k = 0; k < 3; k++) {
      PetscInt w = md->f[3 * f + k], wi = cyl ? w % n : w / m, wj = cyl ? w / n : w % m;
      PetscInt gi = qi + GridStep(qi, wi, n), gj = cyl ? wj : qj + GridStep(qj, wj, m);
      md->fuv[3 * f + k] = gi * (m + 1) + gj;
    }
  }
  PetscFunctionReturn(0);
}

static void Project(PetscReal *p, PetscReal radius)
{
  PetscReal s = radius / PetscSqrtReal(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
  for (int d = 0; d < 3; d++) p[d] *= s;
}

/* One 1-to-4 split at the edge midpoints (CSMeshDataSplitOnce), the new vertices projected onto the sphere. */
static PetscErrorCode Subdivide(CSMeshData *md, PetscBool project, PetscReal radius)
{
  PetscInt nv = md->nv;

  PetscFunctionBeginUser;
  PetscCall(CSMeshDataSplitOnce(md, PETSC_FALSE));
  if (project)
    for (PetscInt v = nv; v < md->nv; v++) Project(md->x + 3 * v, radius);
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataIcosphere(PetscInt level, PetscReal radius, PetscBool project, CSMeshData *md)
{
  const PetscReal p      = (1 + PetscSqrtReal(5.0)) / 2;
  const PetscReal v[36]  = {-1, p, 0, 1, p, 0, -1, -p, 0, 1, -p, 0, 0, -1, p, 0, 1, p, 0, -1, -p, 0, 1, -p, p, 0, -1, p, 0, 1, -p, 0, -1, -p, 0, 1};
  const PetscInt  t[60]  = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4, 11, 10, 2, 10, 7, 6, 7, 1, 8, 3, 9, 4, 3, 4, 2, 3, 2, 6, 3, 6, 8, 3, 8, 9, 4, 9, 5, 2, 4, 11, 6, 2, 10, 8, 6, 7, 9, 8, 1};

  PetscFunctionBeginUser;
  /* level 9: 5.2M faces, about 9 GB for -task info; level 10 needs 35 GB */
  PetscCheck(level >= 0 && level <= 9, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_level %" PetscInt_FMT ": not in [0, 9] (level L has 20 4^L faces)", level);
  PetscCheck(radius > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "icosphere radius %g must be positive", (double)radius);
  PetscCall(CheckSize("-gen icosphere", 10 * PetscPowReal(4, level) + 2, 20 * PetscPowReal(4, level)));
  PetscCall(CSMeshDataAlloc("-gen icosphere", 12, 20, md));
  for (PetscInt i = 0; i < 12; i++) {
    PetscCall(PetscArraycpy(md->x + 3 * i, v + 3 * i, 3));
    Project(md->x + 3 * i, radius); /* circumradius = radius, projected or not */
  }
  PetscCall(PetscArraycpy(md->f, t, 60));
  CSMeshDataOrientOutward(md);
  for (PetscInt l = 0; l < level; l++) PetscCall(Subdivide(md, project, radius));
  snprintf(md->name, sizeof(md->name), "icosphere(level=%" PetscInt_FMT ",radius=%g,project=%s)", level, (double)radius, project ? "true" : "false");
  PetscFunctionReturn(0);
}

/* (u, v) grid on a closed n x m torus: vertex i*m + j, quads (i,j) (i+1,j) (i+1,j+1) (i,j+1). */
static void TorusGrid(PetscInt n, PetscInt m, PetscInt *f)
{
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < m; j++) {
      PetscInt i1 = (i + 1) % n, j1 = (j + 1) % m;
      Quad(f + 6 * (i * m + j), i * m + j, i1 * m + j, i1 * m + j1, i * m + j1);
    }
}

PetscErrorCode CSMeshDataTorus(PetscReal R, PetscReal r, PetscInt n, PetscInt m, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCheck(R > r && r > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "torus needs -gen_torus_R > -gen_tube_r > 0, got R = %g, r = %g", (double)R, (double)r);
  PetscCheck(n >= 3 && m >= 3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "torus needs n, m >= 3, got %" PetscInt_FMT ", %" PetscInt_FMT, n, m);
  PetscCall(CSMeshDataAlloc("-gen torus", (double)n * m, 2 * (double)n * m, md));
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < m; j++) {
      PetscReal u = 2 * PETSC_PI * i / n, v = 2 * PETSC_PI * j / m, rho = R + r * PetscCosReal(v);
      PetscReal *p = md->x + 3 * (i * m + j);
      p[0]         = rho * PetscCosReal(u);
      p[1]         = rho * PetscSinReal(u);
      p[2]         = r * PetscSinReal(v);
    }
  TorusGrid(n, m, md->f);
  CSMeshDataOrientOutward(md);
  PetscCall(CSMeshDataGridUVs(md, n, m, PETSC_FALSE, 0, 1.0 / m)); /* the angles u, v scaled to [0, 1]^2 */
  snprintf(md->name, sizeof(md->name), "torus(R=%g,r=%g,n=%" PetscInt_FMT ",m=%" PetscInt_FMT ")", (double)R, (double)r, n, m);
  PetscFunctionReturn(0);
}

/* Flat torus of conformal class tau = i*tau_im.
   In S^3 c C^2 the torus T = {(r1 e^{ia}, r2 e^{ib})}, r1^2 + r2^2 = 1, is intrinsically flat: (a, b) -> point is
   a local isometry from the rectangle [0, 2 pi r1) x [0, 2 pi r2) with opposite sides glued, so its conformal
   class is tau = i r2/r1; we take r2/r1 = tau_im (tau_im = 1 is the Clifford torus). Stereographic projection
   from N = (0,0,0,1), X -> (X1, X2, X3)/(1 - X4), is conformal and N is not on T (|X3 + i X4| = r2 < 1), so the
   image is a bounded torus of revolution about the x3 axis with the same conformal class (for tau_im = 1 it is
   the torus of revolution with R/r = sqrt 2). The n x m grid is uniform in (a, b): with m/n = tau_im the cells
   are squares of the flat metric, i.e. the mesh discretises this conformal class (its discrete class, the cross
   ratios, is that of the flat lattice i tau_im exactly only for n = m: see CSMeshDataLattice).
   A class with Re tau != 0 is a sheared lattice; its flat torus is not a product of two circles in S^3, so it
   has no realisation of this kind and is refused (-gen lattice gives its class as lengths). */
/* The stereographic image of {(r1 e^{ia}, r2 e^{ib})} c S^3 (r2/r1 = tau_im) on the n x m grid uniform in (a, b). */
static void FlatTorusPositions(PetscReal tau_im, PetscInt n, PetscInt m, PetscReal *x)
{
  PetscReal r1 = 1 / PetscSqrtReal(1 + tau_im * tau_im), r2 = tau_im * r1;
  for (PetscInt i = 0; i < n; i++)
    for (PetscInt j = 0; j < m; j++) {
      PetscReal a = 2 * PETSC_PI * i / n, b = 2 * PETSC_PI * j / m, s = 1 / (1 - r2 * PetscSinReal(b));
      PetscReal *p = x + 3 * (i * m + j);
      p[0]         = s * r1 * PetscCosReal(a);
      p[1]         = s * r1 * PetscSinReal(a);
      p[2]         = s * r2 * PetscCosReal(b);
    }
}

PetscErrorCode CSMeshDataFlatTorus(PetscReal tau_re, PetscReal tau_im, PetscInt n, PetscInt m, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCheck(tau_re == 0, PETSC_COMM_SELF, PETSC_ERR_SUP, "flat torus with tau = %g + %g i: only rectangular conformal classes (tau_re = 0) have a flat realisation as a product of circles in S^3 (use -gen lattice -gen_tau RE,IM)", (double)tau_re, (double)tau_im);
  PetscCheck(tau_im > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "flat torus needs tau_im > 0, got %g", (double)tau_im);
  PetscCheck(n >= 3 && m >= 3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "flat torus needs n, m >= 3, got %" PetscInt_FMT ", %" PetscInt_FMT, n, m);
  PetscCall(CSMeshDataAlloc("-gen flattorus", (double)n * m, 2 * (double)n * m, md));
  FlatTorusPositions(tau_im, n, m, md->x);
  TorusGrid(n, m, md->f);
  CSMeshDataOrientOutward(md);
  PetscCall(CSMeshDataGridUVs(md, n, m, PETSC_FALSE, 0, tau_im / m)); /* the flat rectangle [0, 1] x [0, tau_im]: conformal */
  snprintf(md->name, sizeof(md->name), "flattorus(tau=%g+%gi,n=%" PetscInt_FMT ",m=%" PetscInt_FMT ")", (double)tau_re, (double)tau_im, n, m);
  PetscFunctionReturn(0);
}

/* The flat torus C/(Z + tau Z) on the n x m grid of its fundamental domain: vertex (i, j) = i/n + j tau/m
   (soliman2021 Sec. 6.1.1: a lattice in the plane, triangulated; its discrete conformal class, the log length
   cross ratios of the flat triangles, is the target c0). Each grid cell is cut along its shorter diagonal
   (1/n + tau/m for Re tau <= 0, as -gen flattorus; tau/m - 1/n for Re tau > 0, so that no angle exceeds the
   cell's), and md->len holds the flat lengths |z_b - z_a| of every face's edges. The positions are only the
   start of a flow: the stereographic torus of the rectangular class i Im tau (-gen flattorus), same grid.
   For Re tau = 0 and n = m the positions already realise c0 exactly: cross ratios are Moebius invariant and
   the chordal lengths of the product of circles in R^4 are 2 r1 sin(pi/n), 2 r2 sin(pi/m) and the root of their
   squares' sum, a flat rectangular lattice of class i tau_im sinc(pi/m)/sinc(pi/n) (= i tau_im iff n = m). */
PetscErrorCode CSMeshDataLattice(PetscReal tau_re, PetscReal tau_im, PetscInt n, PetscInt m, CSMeshData *md)
{
  PetscFunctionBeginUser;
  if (!(tau_im > 0)) { /* PETSc's %g prints 0 as "0." (a trailing point that reads as the sentence's end): C's snprintf */
    char t[64];
    snprintf(t, sizeof(t), "%g,%g", (double)tau_re, (double)tau_im);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen_tau %s: the lattice tau must lie in the upper half-plane (Im tau > 0)", t);
  }
  PetscCheck(n >= 3 && m >= 3, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-gen lattice needs -gen_n, -gen_m >= 3, got %" PetscInt_FMT ", %" PetscInt_FMT, n, m);
  PetscCall(CSMeshDataAlloc("-gen lattice", (double)n * m, 2 * (double)n * m, md));
  FlatTorusPositions(tau_im, n, m, md->x);
  TorusGrid(n, m, md->f);
  if (tau_re > 0) /* quad a b c d = (i,j) (i+1,j) (i+1,j+1) (i,j+1): cut along b d instead of a c */
    for (PetscInt q = 0; q < n * m; q++) {
      PetscInt *t = md->f + 6 * q, b = t[1], c = t[2], d = t[5];
      t[2] = d;
      t[3] = b;
      t[4] = c;
      t[5] = d;
    }
  CSMeshDataOrientOutward(md);
  PetscCall(PetscMalloc1(3 * md->nf, &md->len));
  for (PetscInt f = 0; f < md->nf; f++) {
    const PetscInt *t = md->f + 3 * f;
    PetscReal       zr[3], zi[3];
    for (int k = 0; k < 3; k++) { /* unwrapped flat position of corner k, relative to corner 0 */
      PetscInt di = GridStep(t[0] / m, t[k] / m, n), dj = GridStep(t[0] % m, t[k] % m, m);
      zr[k] = (PetscReal)di / n + dj * tau_re / m;
      zi[k] = dj * tau_im / m;
    }
    for (int k = 0; k < 3; k++) md->len[3 * f + k] = PetscSqrtReal(PetscSqr(zr[(k + 2) % 3] - zr[(k + 1) % 3]) + PetscSqr(zi[(k + 2) % 3] - zi[(k + 1) % 3]));
  }
  PetscCall(CSMeshDataGridUVs(md, n, m, PETSC_FALSE, tau_re / m, tau_im / m)); /* the lattice positions i/n + j tau/m */
  snprintf(md->name, sizeof(md->name), "lattice(tau=%g%+gi,n=%" PetscInt_FMT ",m=%" PetscInt_FMT ")", (double)tau_re, (double)tau_im, n, m);
  PetscFunctionReturn(0);
}

/* Open cylinder about the z axis, z in [-height/2, height/2]: n around, m rows of quads, two boundary loops. */
PetscErrorCode CSMeshDataCylinder(PetscReal radius, PetscReal height, PetscInt n, PetscInt m, CSMeshData *md)
{
  PetscFunctionBeginUser;
  PetscCheck(radius > 0 && height > 0, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "cylinder needs radius, height > 0, got %g, %g", (double)radius, (double)height);
  PetscCheck(n >= 3 && m >= 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "cylinder needs n >= 3, m >= 1, got %" PetscInt_FMT ", %" PetscInt_FMT, n, m);
  PetscCall(CSMeshDataAlloc("-gen cylinder", (double)n * (m + 1), 2 * (double)n * m, md));
  for (PetscInt j = 0; j <= m; j++)
    for (PetscInt i = 0; i < n; i++) {
      PetscReal  u = 2 * PETSC_PI * i / n, *p = md->x + 3 * (j * n + i);
      p[0] = radius * PetscCosReal(u);
      p[1] = radius * PetscSinReal(u);
      p[2] = height * ((PetscReal)j / m - 0.5);
    }
  /* d/du x d/dz points away from the axis: (i,j) (i+1,j) (i+1,j+1) is counter-clockwise seen from outside */
  for (PetscInt j = 0; j < m; j++)
    for (PetscInt i = 0; i < n; i++) {
      PetscInt i1 = (i + 1) % n;
      Quad(md->f + 6 * (j * n + i), j * n + i, j * n + i1, (j + 1) * n + i1, (j + 1) * n + i);
    }
  /* u = angle / 2 pi, v = height / circumference: arc length over 2 pi radius, so the UV map is conformal */
  PetscCall(CSMeshDataGridUVs(md, n, m, PETSC_TRUE, 0, height / (2 * PETSC_PI * radius * m)));
  snprintf(md->name, sizeof(md->name), "cylinder(radius=%g,height=%g,n=%" PetscInt_FMT ",m=%" PetscInt_FMT ")", (double)radius, (double)height, n, m);
  PetscFunctionReturn(0);
}

/* Flat disk in the z = 0 plane, normal +z: the centre and rings k = 1..rings of 6k vertices at radius
   k/rings, all starting at angle 0. Consecutive rings are zipped by angle (exact integer comparison), which
   gives 12k - 6 triangles between rings k-1 and k: V = 1 + 3 rings (rings+1), F = 6 rings^2. */
PetscErrorCode CSMeshDataDisk(PetscReal radius, PetscInt rings, CSMeshData *md)
{
  PetscInt nf = 0;

  PetscFunctionBeginUser;
  PetscCheck(radius > 0 && rings >= 1, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "disk needs radius > 0 and rings >= 1, got %g, %" PetscInt_FMT, (double)radius, rings);
  PetscCall(CSMeshDataAlloc("-gen disk", 1 + 3 * (double)rings * (rings + 1), 6 * (double)rings * rings, md));
  md->x[0] = md->x[1] = md->x[2] = 0;
  for (PetscInt k = 1; k <= rings; k++) {
    PetscInt start = 1 + 3 * k * (k - 1);
    for (PetscInt t = 0; t < 6 * k; t++) {
      PetscReal a = 2 * PETSC_PI * t / (6 * k), *p = md->x + 3 * (start + t);
      p[0] = radius * k / rings * PetscCosReal(a);
      p[1] = radius * k / rings * PetscSinReal(a);
      p[2] = 0;
    }
  }
  for (PetscInt t = 0; t < 6; t++) {
    PetscInt tri[3] = {0, 1 + t, 1 + (t + 1) % 6};
    PetscCall(PetscArraycpy(md->f + 3 * nf++, tri, 3));
  }
  for (PetscInt k = 2; k <= rings; k++) {
    PetscInt A = 6 * (k - 1), B = 6 * k, in0 = 1 + 3 * (k - 1) * (k - 2), out0 = 1 + 3 * k * (k - 1), i = 0, o = 0;
    while (i < A || o < B) {
      PetscInt tri[3];
      /* advance on the ring whose next vertex comes first in angle: (i+1)/A < (o+1)/B */
      if (o == B || (i < A && (i + 1) * B < (o + 1) * A)) {
        tri[0] = in0 + i % A;
        tri[1] = out0 + o % B;
        tri[2] = in0 + (i + 1) % A;
        i++;
      } else {
        tri[0] = in0 + i % A;
        tri[1] = out0 + o % B;
        tri[2] = out0 + (o + 1) % B;
        o++;
      }
      PetscCall(PetscArraycpy(md->f + 3 * nf++, tri, 3));
    }
  }
  PetscCheck(nf == md->nf, PETSC_COMM_SELF, PETSC_ERR_PLIB, "disk: %" PetscInt_FMT " faces made, %" PetscInt_FMT " expected", nf, md->nf);
  /* the planar coordinates as UVs, scaled to [0, 1]^2 (one UV per vertex, no seam) */
  md->nuv = md->nv;
  PetscCall(PetscMalloc1(2 * md->nuv, &md->uv));
  PetscCall(PetscMalloc1(3 * md->nf, &md->fuv));
  for (PetscInt v = 0; v < md->nv; v++)
    for (int d = 0; d < 2; d++) md->uv[2 * v + d] = md->x[3 * v + d] / (2 * radius) + 0.5;
  PetscCall(PetscArraycpy(md->fuv, md->f, 3 * md->nf));
  snprintf(md->name, sizeof(md->name), "disk(radius=%g,rings=%" PetscInt_FMT ")", (double)radius, rings);
  PetscFunctionReturn(0);
}
