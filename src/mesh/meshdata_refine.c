/* Regular 1-to-4 refinement of serial triangle data (-mesh_refine n, -mesh_refine_type midpoint|loop), applied on
   rank 0 to a validated input before it becomes a DMPlex. The refined mesh is a new discretisation, so its
   discrete conformal class (soliman2021 Eq. 4, the length cross ratios of the refined edges) is the constraint
   of a flow run on it, not the class of the coarse input (docs/real_meshes.md).
   midpoint: the new vertices at the edge midpoints, the old ones kept (the piecewise-flat shape is unchanged).
   loop: Loop subdivision (Loop 1987, Warren's weights): edge points 3/8 (a + b) + 1/8 (c + d), vertex points
   (1 - n beta) v + beta sum of neighbours with beta = 3/16 (n = 3), 3/(8n) (n > 3). Boundary edges get their
   midpoint and boundary vertices stay where they are (a Dirichlet boundary keeps its curve's vertices). */
#include "cs_meshdata.h"
#include <stdio.h>

/* Edge numbering by half-edge: mid[h] = nv + (index of the edge of half-edge h), one search in the bucket of
   the edge's smaller vertex (as the icosphere generator's split). nhe[e] counts the half-edges of edge e. */
static PetscErrorCode EdgeNumbers(const CSMeshData *md, PetscInt *mid, PetscInt *ne_out)
{
  PetscInt nv = md->nv, nh = 3 * md->nf, ne = 0, *off, *fill, *hi, *id;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc1(nv + 1, &off));
  PetscCall(PetscMalloc3(nv, &fill, nh, &hi, nh, &id));
  for (PetscInt h = 0; h < nh; h++) off[PetscMin(md->f[h], md->f[h % 3 == 2 ? h - 2 : h + 1]) + 1]++;
  for (PetscInt v = 0; v < nv; v++) off[v + 1] += off[v];
  PetscCall(PetscArraycpy(fill, off, nv));
  for (PetscInt h = 0; h < nh; h++) {
    PetscInt a = md->f[h], b = md->f[h % 3 == 2 ? h - 2 : h + 1], lo = PetscMin(a, b), s;
    for (s = off[lo]; s < fill[lo] && hi[s] != PetscMax(a, b); s++) {}
    if (s == fill[lo]) {
      hi[s] = PetscMax(a, b);
      id[s] = nv + ne++;
      fill[lo]++;
    }
    mid[h] = id[s];
  }
  PetscCall(PetscFree(off));
  PetscCall(PetscFree3(fill, hi, id));
  *ne_out = ne;
  PetscFunctionReturn(0);
}

/* Loop's positions, written into x (3*(nv+ne)) from the coarse md; cnt[v] counts half-edges per new index. */
static PetscErrorCode LoopPositions(const CSMeshData *md, const PetscInt *mid, PetscInt ne, PetscReal *x)
{
  PetscInt   nv = md->nv, nh = 3 * md->nf, *cnt, *val;
  PetscReal *nb;

  PetscFunctionBeginUser;
  PetscCall(PetscCalloc3(nv + ne, &cnt, nv, &val, 3 * nv, &nb));
  PetscCall(PetscArrayzero(x, 3 * (nv + ne)));
  for (PetscInt h = 0; h < nh; h++) {
    PetscInt a = md->f[h], b = md->f[h % 3 == 2 ? h - 2 : h + 1], c = md->f[h % 3 == 0 ? h + 2 : h - 1];
    cnt[mid[h]]++;
    val[a]++; /* outgoing half-edges: on a closed mesh one per neighbour */
    for (int d = 0; d < 3; d++) {
      x[3 * mid[h] + d] += 3.0 / 16 * (md->x[3 * a + d] + md->x[3 * b + d]) + 1.0 / 8 * md->x[3 * c + d];
      nb[3 * a + d] += md->x[3 * b + d];
    }
  }
  for (PetscInt h = 0; h < nh; h++) { /* a boundary edge (one half-edge): its midpoint; its vertices stay */
    PetscInt a = md->f[h], b = md->f[h % 3 == 2 ? h - 2 : h + 1];
    if (cnt[mid[h]] != 1) continue;
    for (int d = 0; d < 3; d++) x[3 * mid[h] + d] = 0.5 * (md->x[3 * a + d] + md->x[3 * b + d]);
    cnt[a] = cnt[b] = -1;
  }
  for (PetscInt v = 0; v < nv; v++) {
    PetscReal n = (PetscReal)val[v], beta = val[v] == 3 ? 3.0 / 16 : 3.0 / (8 * n);
    for (int d = 0; d < 3; d++) x[3 * v + d] = cnt[v] < 0 || val[v] == 0 ? md->x[3 * v + d] : (1 - n * beta) * md->x[3 * v + d] + beta * nb[3 * v + d];
  }
  PetscCall(PetscFree3(cnt, val, nb));
  PetscFunctionReturn(0);
}

/* One 1-to-4 split of md in place (also the icosphere generator's split, with its new vertices projected). */
PetscErrorCode CSMeshDataSplitOnce(CSMeshData *md, PetscBool loop)
{
  PetscInt   nv = md->nv, nf = md->nf, ne = 0, *mid, *f;
  PetscReal *x;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(3 * nf, &mid));
  PetscCall(EdgeNumbers(md, mid, &ne));
  PetscCall(PetscMalloc1(3 * (nv + ne), &x));
  PetscCall(PetscMalloc1(12 * nf, &f));
  if (loop) PetscCall(LoopPositions(md, mid, ne, x));
  else {
    PetscCall(PetscArraycpy(x, md->x, 3 * nv));
    for (PetscInt h = 0; h < 3 * nf; h++) {
      PetscInt a = md->f[h], b = md->f[h % 3 == 2 ? h - 2 : h + 1];
      for (int d = 0; d < 3; d++) x[3 * mid[h] + d] = 0.5 * (md->x[3 * a + d] + md->x[3 * b + d]);
    }
  }
  for (PetscInt i = 0; i < nf; i++) {
    const PetscInt *t = md->f + 3 * i, *m = mid + 3 * i; /* m[k] is the new vertex of t[k] t[k+1] */
    PetscInt        n[12] = {t[0], m[0], m[2], m[0], t[1], m[1], m[2], m[1], t[2], m[0], m[1], m[2]};
    PetscCall(PetscArraycpy(f + 12 * i, n, 12));
  }
  PetscCall(PetscFree(mid));
  PetscCall(PetscFree(md->x));
  PetscCall(PetscFree(md->f));
  md->x  = x;
  md->f  = f;
  md->nv = nv + ne;
  md->nf = 4 * nf;
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataRefine(CSMeshData *md, PetscInt levels, PetscBool loop)
{
  char name[PETSC_MAX_PATH_LEN + 32];

  PetscFunctionBeginUser;
  PetscCheck(levels >= 0 && levels <= 6, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_refine %" PetscInt_FMT ": not in [0, 6] (each level multiplies the faces by 4)", levels);
  PetscCheck((double)md->nf * PetscPowReal(4, levels) * 3 <= (double)PETSC_MAX_INT, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_refine %" PetscInt_FMT " of %s: %.0f faces exceed this PETSc build's PetscInt", levels, md->name, (double)md->nf * PetscPowReal(4, levels));
  for (PetscInt l = 0; l < levels; l++) PetscCall(CSMeshDataSplitOnce(md, loop));
  if (levels) {
    snprintf(name, sizeof(name), "%s(%s refined %" PetscInt_FMT "x)", md->name, loop ? "loop" : "midpoint", levels);
    PetscCall(PetscStrncpy(md->name, name, sizeof(md->name)));
  }
  PetscFunctionReturn(0);
}
