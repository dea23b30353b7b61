/* -flow_init smooth (issue 15, soliman2021 Fig. 16): the start omega = d(f + u) for a smooth random displacement u
   of the input's positions f, a sum of -flow_init_modes plane waves in the ambient space,
     u(p) = sum_j r_j sin(2 pi <k_j, p> / D + theta_j),   r_j in [-1, 1]^3, k_j a random unit vector,
   D the diagonal of the input's bounding box, scaled to max_v |u(p_v)| = -flow_init_amplitude times the mean edge
   length. Every number is hashed from the seed and j, and u is a function of the position only: the same field on
   any number of ranks. The start is integrable (an immersion's df) but not in the class c0, which stays the input's
   (or the lattice's): the flow's conformal rows take it there. Why not -flow_init random: an i.i.d. field on every
   halfedge is far from integrable and ends in pinch edges (docs/triangle_fields.md, "Random starts that reach it?"). */
#include "trianglefield_impl.h"
#include "cs_geometry.h"

/* Bounding-box diagonal D of the positions x (global Vec of dmV3). */
static PetscErrorCode BoxDiagonal(Vec x, PetscReal *D)
{
  PetscReal lo, hi, s = 0;
  PetscFunctionBeginUser;
  for (PetscInt c = 0; c < 3; c++) {
    PetscCall(VecStrideMin(x, c, NULL, &lo));
    PetscCall(VecStrideMax(x, c, NULL, &hi));
    s += PetscSqr(hi - lo);
  }
  *D = PetscSqrtReal(s);
  PetscFunctionReturn(0);
}

#define CS_MODE 8 /* the numbers of one plane wave */

/* The random numbers of mode j, hashed once: the wave vector k_j (0-2), the amplitude r_j (3-5), the phase theta_j
   (6) and |k_j| (7; 1 for a zero k_j). */
static void Mode(CSTriangleField *d, PetscReal (*hash)(PetscInt, PetscInt, PetscInt, PetscInt), PetscInt j, PetscReal m[CS_MODE])
{
  PetscReal nk = 0;
  for (int c = 0; c < 6; c++) m[c] = hash(d->seed, j, 4, c);
  for (int c = 0; c < 3; c++) nk += m[c] * m[c];
  m[6] = PETSC_PI * hash(d->seed, j, 4, 6);
  m[7] = nk > 0 ? PetscSqrtReal(nk) : 1;
}

/* u(p) at the owned positions of x into u (same layout); *umax = max_v |u(p_v)| over all ranks. */
static PetscErrorCode PlaneWaves(CSTriangleField *d, PetscReal (*hash)(PetscInt, PetscInt, PetscInt, PetscInt), Vec x, PetscReal D, Vec u, PetscReal *umax)
{
  const PetscScalar *p;
  PetscScalar       *w;
  PetscReal         *m;
  PetscInt           n;
  MPI_Comm           comm;
  PetscFunctionBeginUser;
  PetscCall(PetscObjectGetComm((PetscObject)x, &comm));
  PetscCall(PetscMalloc1(CS_MODE * d->modes, &m));
  for (PetscInt j = 0; j < d->modes; j++) Mode(d, hash, j, m + CS_MODE * j);
  PetscCall(VecGetLocalSize(x, &n));
  PetscCall(VecGetArrayRead(x, &p));
  PetscCall(VecGetArray(u, &w));
  *umax = 0;
  for (PetscInt v = 0; v < n / 3; v++) {
    PetscReal s[3] = {0, 0, 0};
    for (PetscInt j = 0; j < d->modes; j++) {
      const PetscReal *mj  = m + CS_MODE * j;
      PetscReal        arg = mj[6];
      for (int c = 0; c < 3; c++) arg += 2 * PETSC_PI * mj[c] / mj[7] * PetscRealPart(p[3 * v + c]) / D;
      for (int c = 0; c < 3; c++) s[c] += mj[3 + c] * PetscSinReal(arg);
    }
    for (int c = 0; c < 3; c++) w[3 * v + c] = s[c];
    *umax = PetscMax(*umax, PetscSqrtReal(s[0] * s[0] + s[1] * s[1] + s[2] * s[2]));
  }
  PetscCall(VecRestoreArray(u, &w));
  PetscCall(VecRestoreArrayRead(x, &p));
  PetscCall(PetscFree(m));
  PetscCall(MPIU_Allreduce(MPI_IN_PLACE, umax, 1, MPIU_REAL, MPIU_MAX, comm));
  PetscFunctionReturn(0);
}

/* F->x = d(f + u) with f = d->xpos0 (the input) and u the plane waves scaled to amp x the mean edge length. */
PetscErrorCode CSTFInitSmooth(CSWillmoreFlow F, CSTriangleField *d, PetscReal (*hash)(PetscInt, PetscInt, PetscInt, PetscInt))
{
  Vec       u;
  PetscReal D = 0, lbar = 0, umax = 0;
  PetscFunctionBeginUser;
  PetscCall(BoxDiagonal(d->xpos0, &D));
  PetscCall(CSGeometryMeanEdgeLength(F->mesh, d->xpos0, &lbar));
  PetscCall(VecDuplicate(d->xpos0, &u));
  PetscCall(PlaneWaves(d, hash, d->xpos0, D, u, &umax));
  if (!(umax > 0)) PetscCall(VecDestroy(&u)); /* nothing left behind by the error below */
  PetscCheck(umax > 0, F->hdr.comm, PETSC_ERR_ARG_OUTOFRANGE, "-%sinit smooth: the random displacement vanishes at every vertex (seed %" PetscInt_FMT "); use another -%sseed", F->hdr.prefix, d->seed, F->hdr.prefix);
  PetscCall(VecAYPX(u, d->amp * lbar / umax, d->xpos0));
  PetscCall(CSTriangleFieldFromPositions(F->mesh, u, d->dmH3, F->x));
  PetscCall(VecDestroy(&u));
  PetscFunctionReturn(0);
}
