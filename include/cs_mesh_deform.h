/* Test inputs: a deformation of the input positions chosen by options, applied by CSMeshCreateFromOptions. */
#ifndef CS_MESH_DEFORM_H
#define CS_MESH_DEFORM_H
#include "cs_mesh.h"

/* f <- S (f (1 + a sin(k f_x) sin(k f_y) sin(k f_z))): -gen_deform_bump a, -gen_deform_bump_freq k (default 3),
   -gen_deform_stretch sx,sy,sz (after the bump); then -gen_deform_twist deg (rotation about z by deg (z - zmin) /
   (zmax - zmin)) and -gen_deform_invert cx,cy,cz (inversion in the unit sphere about c, then the mirror in x: a
   Moebius map, which keeps the length cross ratios). Pointwise (the twist takes the z range over all ranks), so the same on any number of ranks; a no-op
   without the options. */
PETSC_EXTERN PetscErrorCode CSMeshDeformFromOptions(CSMesh mesh, const char prefix[]);

#endif
