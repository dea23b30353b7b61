/* Isotropic remeshing of the validated input on rank 0 (-mesh_remesh N, -mesh_remesh_edge_length h,
   -mesh_remesh_iterations k), before any refinement and before the DMPlex is made, so every task and flow gets it.
   Issue 35: meshes with slivers (min angle 0.08-2.8 deg) stall the constrained Willmore flow at its first
   iterations; remeshed, the same shapes move. The remeshed mesh is a new discretisation: its own discrete conformal
   class (soliman2021 Eq. 4) is a flow's constraint (soliman2021 Fig. 14: a better approximation of the smooth
   shape's class than a mesh of slivers). The work is CGAL's (meshdata_remesh_cgal.cc); here the target edge length,
   the checks of what must be kept (closedness, boundary loops, components, genus) and the messages. */
#include "cs_meshdata.h"
#include "meshdata_remesh_cgal.h"
#include <stdio.h>

#if !defined(CS_HAVE_CGAL)
PetscErrorCode CSMeshDataRemesh(CSMeshData *md, CSTopology *topo, PetscInt faces, PetscReal h, PetscInt iterations)
{
  PetscFunctionBeginUser;
  SETERRQ(PETSC_COMM_SELF, PETSC_ERR_SUP, "-mesh_remesh: this build has no CGAL (run 'make deps' to install libcgal-dev, then 'make')");
}
#else
/* the total area of md */
static PetscReal Area(const CSMeshData *md)
{
  PetscReal A = 0;
  for (PetscInt i = 0; i < md->nf; i++) {
    const PetscReal *a = md->x + 3 * md->f[3 * i], *b = md->x + 3 * md->f[3 * i + 1], *c = md->x + 3 * md->f[3 * i + 2];
    PetscReal        u[3] = {b[0] - a[0], b[1] - a[1], b[2] - a[2]}, v[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
    PetscReal        n[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
    A += 0.5 * PetscSqrtReal(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
  }
  return A;
}

/* equilateral faces of edge h have area sqrt(3)/4 h^2: the number of them that tile area A, and back */
static PetscReal FacesOfEdge(PetscReal A, PetscReal h)
{
  return A / (PetscSqrtReal(3.0) / 4 * h * h);
}
static PetscReal EdgeOfFaces(PetscReal A, PetscReal n)
{
  return PetscSqrtReal(4 * A / (PetscSqrtReal(3.0) * n));
}

/* CGAL's remesh of in into out (PetscInt arrays; out->name is in's), freeing CGAL's malloc'ed arrays */
static PetscErrorCode RunCGAL(const CSMeshData *in, PetscReal h, PetscInt iterations, CSMeshData *out, int si[2])
{
  long   *f, nv, nf, *fo = NULL;
  double *xo = NULL;
  int     err;
  char    msg[256];
  PetscFunctionBeginUser;
  PetscCall(PetscMalloc1(3 * in->nf, &f));
  for (PetscInt i = 0; i < 3 * in->nf; i++) f[i] = (long)in->f[i];
  err = CSRemeshCGAL((long)in->nv, in->x, (long)in->nf, f, (double)h, (int)iterations, &nv, &xo, &nf, &fo, si, msg, sizeof(msg));
  PetscCall(PetscFree(f));
  PetscCheck(!err, PETSC_COMM_SELF, PETSC_ERR_LIB, "-mesh_remesh of %s: %s", in->name, msg);
  if (3 * (double)nf > (double)PETSC_MAX_INT) {
    free(xo);
    free(fo);
    SETERRQ(PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_remesh of %s: %ld faces exceed this PETSc build's PetscInt", in->name, nf);
  }
  PetscCall(PetscMemzero(out, sizeof(*out)));
  PetscCall(PetscMalloc1(3 * nv, &out->x));
  PetscCall(PetscMalloc1(3 * nf, &out->f));
  for (long i = 0; i < 3 * nv; i++) out->x[i] = (PetscReal)xo[i];
  for (long i = 0; i < 3 * nf; i++) out->f[i] = (PetscInt)fo[i];
  out->nv = (PetscInt)nv;
  out->nf = (PetscInt)nf;
  PetscCall(PetscStrncpy(out->name, in->name, sizeof(out->name)));
  free(xo);
  free(fo);
  PetscFunctionReturn(0);
}

/* -mesh_remesh N: CGAL's faces are ~11-15 % more than the equilateral count (its edges lie in [4/5 h, 4/3 h],
   measured on cow, triceratops, man, knot1 at N = 6000); a result off by more than 5 % is remeshed once more from
   the input with h scaled by sqrt(faces / N) */
static PetscErrorCode Remesh(CSMeshData *md, PetscInt faces, PetscReal *h, PetscInt iterations, int si[2])
{
  CSMeshData out;
  PetscFunctionBeginUser;
  PetscCall(RunCGAL(md, *h, iterations, &out, si));
  if (faces > 0 && PetscAbsReal((PetscReal)out.nf / (PetscReal)faces - 1) > 0.05) {
    *h *= PetscSqrtReal((PetscReal)out.nf / (PetscReal)faces);
    PetscCall(CSMeshDataDestroy(&out));
    PetscCall(RunCGAL(md, *h, iterations, &out, si));
  }
  PetscCall(CSMeshDataDestroy(md));
  *md = out;
  PetscFunctionReturn(0);
}

/* what remeshing must keep: the same closed/open surface, its components and genus (Euler characteristic) */
static PetscErrorCode CheckKept(const char name[], const CSTopology *in, const CSTopology *out)
{
  PetscFunctionBeginUser;
  PetscCheck(out->components == in->components && out->boundary_loops == in->boundary_loops && out->genus == in->genus && out->euler == in->euler, PETSC_COMM_SELF, PETSC_ERR_PLIB,
             "-mesh_remesh of %s changed the topology (components %" PetscInt_FMT " -> %" PetscInt_FMT ", boundary loops %" PetscInt_FMT " -> %" PetscInt_FMT ", genus %" PetscInt_FMT " -> %" PetscInt_FMT "): try a smaller -mesh_remesh_edge_length (more faces)", name,
             in->components, out->components, in->boundary_loops, out->boundary_loops, in->genus, out->genus);
  PetscFunctionReturn(0);
}

PetscErrorCode CSMeshDataRemesh(CSMeshData *md, CSTopology *topo, PetscInt faces, PetscReal h, PetscInt iterations)
{
  PetscReal      A = Area(md), est;
  PetscLogDouble t0, t1;
  int            si[2] = {0, 0};
  CSTopology     in = *topo;
  PetscInt       nf0 = md->nf;
  char           name[PETSC_MAX_PATH_LEN + 64];

  PetscFunctionBeginUser;
  PetscCheck(!md->fuv, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "-mesh_remesh of %s: the input has texture coordinates (%" PetscInt_FMT " UVs), and CGAL's isotropic remeshing makes new vertices and faces that no UV transfer here would give UVs: not remeshed (remesh a copy without vt/texcoord, or use -mesh_refine, which interpolates them)", md->name, md->nuv);
  PetscCheck(!md->len && !md->cr, PETSC_COMM_SELF, PETSC_ERR_ARG_INCOMP, "-mesh_remesh of %s: the input carries a target class given for its own edges (-mesh_lengths, -mesh_cross_ratios, -gen lattice, -gen_spike_round_class): not remeshed", md->name);
  if (faces > 0) h = EdgeOfFaces(A, (PetscReal)faces);
  est = FacesOfEdge(A, h);
  PetscCheck(est >= CS_REMESH_MIN_FACES && est <= CS_REMESH_MAX_FACES, PETSC_COMM_SELF, PETSC_ERR_ARG_OUTOFRANGE, "-mesh_remesh_edge_length %g: gives about %.3g faces on %s (area %g): want %d to %.0e", (double)h, (double)est, md->name, (double)A, CS_REMESH_MIN_FACES, (double)CS_REMESH_MAX_FACES);
  PetscCall(PetscTime(&t0));
  PetscCall(Remesh(md, faces, &h, iterations, si));
  PetscCall(PetscTime(&t1));
  PetscCall(CSMeshDataValidate(md, topo));
  PetscCall(CheckKept(md->name, &in, topo));
  PetscCall(PetscPrintf(PETSC_COMM_SELF, "mesh_remesh: %s: %" PetscInt_FMT " -> %" PetscInt_FMT " faces (target edge length %.4g, %" PetscInt_FMT " iterations, %.2f s)\n", md->name, nf0, md->nf, (double)h, iterations, (double)(t1 - t0)));
  if (si[1]) PetscCall(PetscPrintf(PETSC_COMM_SELF, "Warning: -mesh_remesh: the remeshed %s intersects itself (CGAL does_self_intersect; %s)\n", md->name, si[0] ? "so does the input" : "the input does not: try more faces"));
  snprintf(name, sizeof(name), "%s(remeshed %" PetscInt_FMT "f)", md->name, md->nf);
  PetscCall(PetscStrncpy(md->name, name, sizeof(md->name)));
  PetscFunctionReturn(0);
}
#endif
