/* -task info: read, validate, distribute, and report the facts of a mesh (and write it back, if asked). */
#include "cs_driver.h"
#include "cs_geometry.h"
#include "cs_linalg.h"

/* ParaView fields of a mesh at rest: mean curvature vector h and |h|, vertex area, face area. */
static PetscErrorCode WriteInfoFields(CSMesh mesh, const char dir[])
{
  CSViewer       v = NULL;
  Vec            h, hn, area, farea;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(DMCreateGlobalVector(mesh->dmV3, &h));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &hn));
  PetscCall(DMCreateGlobalVector(mesh->dmV1, &area));
  PetscCall(DMCreateGlobalVector(mesh->dmF1, &farea));
  PetscCall(CSGeometryMeanCurvature(mesh, mesh->x, h));
  PetscCall(CSGeometryVertexAreas(mesh, mesh->x, area));
  PetscCall(CSGeometryFaceAreas(mesh, mesh->x, farea));
  PetscCall(CSVecBlockNorms(h, 3, hn));
  ierr = CSViewerCreate(mesh, NULL, dir, &v);
  if (!ierr) ierr = CSViewerAddVertexField(v, "mean_curvature_vector", h);
  if (!ierr) ierr = CSViewerAddVertexField(v, "mean_curvature", hn);
  if (!ierr) ierr = CSViewerAddVertexField(v, "vertex_area", area);
  if (!ierr) ierr = CSViewerAddFaceField(v, "face_area", farea);
  if (!ierr) ierr = CSViewerWriteStep(v, mesh->x, 0);
  PetscCall(CSViewerDestroy(&v)); /* on every path: a folder that cannot be written leaks nothing */
  PetscCall(VecDestroy(&h));
  PetscCall(VecDestroy(&hn));
  PetscCall(VecDestroy(&area));
  PetscCall(VecDestroy(&farea));
  PetscCall(ierr);
  PetscCall(PetscPrintf(mesh->comm, "wrote ParaView series %s/series.pvd\n", dir));
  PetscFunctionReturn(0);
}

PetscErrorCode CSTaskInfo(MPI_Comm comm)
{
  CSMesh         mesh;
  CSOutput       out;
  PetscErrorCode ierr;
  PetscFunctionBeginUser;
  PetscCall(CSOutputFromOptions(comm, &out));
  ierr = CSMeshCreateFromOptions(comm, NULL, &mesh);
  if (ierr) PetscCall(CSOutputDestroy(&out)); /* no leak on the error path */
  PetscCall(ierr);
  ierr = CSOptionsCheckUnused(comm, "-task info"); /* every option is read: the mesh's and the outputs' */
  if (!ierr) ierr = CSOutputAddMeshFacts(&out, mesh, mesh->x, NULL);
  if (!ierr) ierr = CSOutputAddTriangleQuality(&out, mesh, mesh->x);
  if (!ierr) ierr = CSOutputAddWillmoreBS(&out, mesh, mesh->x);
  if (!ierr && out.has_viewer) ierr = WriteInfoFields(mesh, out.viewer_dir);
  if (!ierr) ierr = CSOutputFinish(&out, mesh, mesh->x);
  /* clean up on every path, so a bad -reference or an unwritable output leaks nothing */
  PetscCall(CSMeshDestroy(&mesh));
  PetscCall(CSOutputDestroy(&out));
  PetscCall(ierr);
  PetscFunctionReturn(0);
}
