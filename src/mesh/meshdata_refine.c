/* Regular 1-to-4 refinement of serial triangle data (-mesh_refine n, -mesh_refine_type midpoint|loop), applied on
   rank 0 to a validated input before it becomes a DMPlex. The refined mesh is a new discretisation, so its
   discrete conformal class (soliman2021 Eq. 4, the length cross ratios of the refined edges) is the constraint
   of a flow run on it, not the class of the coarse input (docs/real_meshes.md).
   midpoint: the new vertices at the edge midpoints, the old ones kept (the piecewise-flat shape is unchanged).
   loop: Loop subdivision (Loop 1987, Warren's weights): edge points 3/8 (a + b) + 1/8 (c + d), vertex points
   (1 - n beta) v + beta sum of neighbours with beta = 3/16 (n = 3), 3/(8n) (n > 3). Boundary edges get their
   midpoint and boundary vertices stay where they are (a Dirichlet boundary keeps its curve's vertices).
   Texture coordinates (issue 38), both types: the midpoint of the edge's UVs in each face, the old corners' UVs
   kept. For Loop subdivision that is linear interpolation of the UVs, not Loop's rule: the texture map of the
   refined mesh is the coarse one's, piecewise linear on the coarse faces, which is what a texture means. */
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

/* The new UVs: midt[h] = index of the UV of half-edge h's new corner, numbered from md->nuv on. The two half-edges
   of an edge share it when they give the edge's ends the same uv indices (no seam there), else each has its own. */
static PetscErrorCode SplitUV(const CSMeshData *md, const PetscInt *mid, PetscInt ne, PetscInt *midt, PetscInt *nuv_out, PetscReal **uv_out)
{
  PetscInt   nh = 3 * md->nf, *first, n = md->nuv;
  PetscReal *uv;

  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(ne, &first));
  for (PetscInt e = 0; e < ne; e++) first[e] = -1;
  for (PetscInt h = 0; h < nh; h++) {
    PetscInt e = mid[h] - md->nv, g = first[e];
    if (g >= 0 && md->fuv[h] == md->fuv[CSHalfedgeNext(g)] && md->fuv[CSHalfedgeNext(h)] == md->fuv[g]) midt[h] = midt[g];
    else midt[h] = n++;
    if (g < 0) first[e] = h;
  }
  PetscCall(PetscFree(first));
  PetscCall(PetscMalloc1(2 * n, &uv));
  PetscCall(PetscArraycpy(uv, md->uv, 2 * md->nuv));
  for (PetscInt h = 0; h < nh; h++)
    for (int d = 0; d < 2; d++) uv[2 * midt[h] + d] = 0.5 * (md->uv[2 * md->fuv[h] + d] + md->uv[2 * md->fuv[CSHalfedgeNext(h)] + d]);
  *nuv_out = n;
  *uv_out  = uv;
  PetscFunctionReturn(0);
}

/* The 4 faces of each face (the corners, then the middle) from the corners t and the new corners m of each face
   (m[k] on the edge t[k] t[k+1]): the vertex indices with (t, m) = (f, mid), the uv indices with (fuv, midt) */
static void SplitFaces(PetscInt nf, const PetscInt *t, const PetscInt *m, PetscInt *out)
{
  for (PetscInt i = 0; i < nf; i++, t += 3, m += 3) {
    PetscInt n[12] = {t[0], m[0], m[2], m[0], t[1], m[1], m[2], m[1], t[2], m[0], m[1], m[2]};
    for (int k = 0; k < 12; k++) out[12 * i + k] = n[k];
  }
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
  SplitFaces(nf, md->f, mid, f);
  if (md->fuv) {
    PetscInt  *midt, *fuv, nuv = 0;
    PetscReal *uv = NULL;
    PetscCall(PetscMalloc1(3 * nf, &midt));
    PetscCall(PetscMalloc1(12 * nf, &fuv));
    PetscCall(SplitUV(md, mid, ne, midt, &nuv, &uv));
    SplitFaces(nf, md->fuv, midt, fuv);
    PetscCall(PetscFree(midt));
    PetscCall(PetscFree(md->uv));
    PetscCall(PetscFree(md->fuv));
    md->fuv = fuv;
    md->uv  = uv;
    md->nuv = nuv;
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
