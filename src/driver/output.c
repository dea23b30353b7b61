/* Output options shared by every task, and the facts every summary carries. */
#include "cs_driver.h"
#include "cs_geometry.h"
#include "cs_energy_bs.h"

PetscErrorCode CSOutputFromOptions(MPI_Comm comm, CSOutput *o)
{
  PetscFunctionBeginUser;
  PetscCall(PetscMemzero(o, sizeof(*o)));
  PetscCall(PetscTime(&o->t0));
  PetscOptionsBegin(comm, NULL, "confsurf output", NULL);
  PetscCall(PetscOptionsString("-o", "Final mesh (.obj or .ply)", NULL, o->out, o->out, sizeof(o->out), &o->has_out));
  PetscCall(PetscOptionsString("-viewer_dir", "Directory for the ParaView series (series.pvd)", NULL, o->viewer_dir, o->viewer_dir, sizeof(o->viewer_dir), &o->has_viewer));
  PetscCall(PetscOptionsString("-summary", "JSON summary file", NULL, o->summary, o->summary, sizeof(o->summary), &o->has_summary));
  PetscCall(PetscOptionsString("-cs_history", "-history FILE.csv: per-iteration CSV history (main renames -history, which PETSc reserves)", NULL, o->history, o->history, sizeof(o->history), &o->has_history));
  PetscCall(PetscOptionsString("-reference", "Mesh with the same connectivity for the quasi-conformal error", NULL, o->reference, o->reference, sizeof(o->reference), &o->has_reference));
  PetscOptionsEnd();
  if (o->has_out) {
    char ext[16];
    PetscCall(CSPathExtension(o->out, ext, sizeof(ext)));
    PetscCheck(!strcmp(ext, "obj") || !strcmp(ext, "ply"), comm, PETSC_ERR_ARG_WRONG, "-o %s: the final mesh is written as .obj or .ply", o->out);
  }
  PetscCall(CSJSONCreate(comm, &o->json));
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputAddMeshFacts(CSOutput *o, CSMesh mesh, Vec x, Vec xref)
{
  PetscReal area, volume, W;
  CSEnergy  will;
  PetscFunctionBeginUser;
  PetscCall(CSGeometryAreaVolume(mesh, x, &area, &volume));
  PetscCall(CSEnergyCreateWillmore(mesh, &will));
  PetscCall(CSEnergyValue(will, x, &W));
  PetscCall(CSEnergyDestroy(&will));
  PetscCall(CSJSONAddString(o->json, "mesh", mesh->name));
  PetscCall(CSJSONAddInt(o->json, "vertices", mesh->Nv));
  PetscCall(CSJSONAddInt(o->json, "edges", mesh->Ne));
  PetscCall(CSJSONAddInt(o->json, "faces", mesh->Nf));
  PetscCall(CSJSONAddInt(o->json, "genus", mesh->topo.genus));
  PetscCall(CSJSONAddInt(o->json, "boundary_loops", mesh->topo.boundary_loops));
  PetscCall(CSJSONAddInt(o->json, "components", mesh->topo.components));
  PetscCall(CSJSONAddInt(o->json, "euler_characteristic", mesh->Nv - mesh->Ne + mesh->Nf));
  PetscCall(CSJSONAddReal(o->json, "area", area));
  PetscCall(CSJSONAddReal(o->json, "volume", volume));
  PetscCall(CSJSONAddReal(o->json, "willmore", W));
  PetscCall(CSEnergyWillmoreBSAddFact(mesh, x, o->json)); /* willmore_bs (bobenko-schroeder2005, issue 5) */
  PetscCall(PetscPrintf(mesh->comm, "mesh %s: V=%" PetscInt_FMT " E=%" PetscInt_FMT " F=%" PetscInt_FMT " genus=%" PetscInt_FMT " boundary_loops=%" PetscInt_FMT " components=%" PetscInt_FMT "\n", mesh->name, mesh->Nv, mesh->Ne, mesh->Nf, mesh->topo.genus, mesh->topo.boundary_loops, mesh->topo.components));
  PetscCall(PetscPrintf(mesh->comm, "area=%.12g volume=%.12g willmore=%.12g (4pi=%.12g)\n", (double)area, (double)volume, (double)W, (double)(4 * PETSC_PI)));
  if (xref || o->has_reference) {
    Vec       r = xref;
    PetscReal qmean, qmax;
    if (!r) PetscCall(CSMeshLoadCompatiblePositions(mesh, "-reference", o->reference, &r));
    PetscCall(CSGeometryQuasiConformal(mesh, r, x, NULL, &qmean, &qmax));
    PetscCall(CSJSONAddReal(o->json, "q_mean", qmean));
    PetscCall(CSJSONAddReal(o->json, "q_max", qmax));
    PetscCall(PetscPrintf(mesh->comm, "quasi-conformal error: q_mean=%.12g q_max=%.12g\n", (double)qmean, (double)qmax));
    if (!xref) PetscCall(VecDestroy(&r));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputFinish(CSOutput *o, CSMesh mesh, Vec x)
{
  PetscLogDouble t1;
  PetscFunctionBeginUser;
  PetscCall(PetscTime(&t1));
  PetscCall(CSJSONAddReal(o->json, "seconds", (PetscReal)(t1 - o->t0)));
  {
    PetscMPIInt size;
    PetscCallMPI(MPI_Comm_size(mesh->comm, &size));
    PetscCall(CSJSONAddInt(o->json, "ranks", (PetscInt)size));
  }
  if (o->has_out) {
    PetscCall(CSMeshWrite(mesh, x, o->out));
    PetscCall(PetscPrintf(mesh->comm, "wrote mesh %s\n", o->out));
  }
  if (o->has_summary) {
    PetscCall(CSJSONWrite(o->json, o->summary));
    PetscCall(PetscPrintf(mesh->comm, "wrote summary %s\n", o->summary));
  }
  PetscFunctionReturn(0);
}

PetscErrorCode CSOutputDestroy(CSOutput *o)
{
  PetscFunctionBeginUser;
  PetscCall(CSJSONDestroy(&o->json));
  PetscFunctionReturn(0);
}
