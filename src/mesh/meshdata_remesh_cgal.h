/* The C interface of the CGAL remesher (meshdata_remesh_cgal.cc, compiled only when the build finds CGAL: then
   CS_HAVE_CGAL is defined). Plain C types only, so the C++ translation unit needs no PETSc header. */
#ifndef CS_MESHDATA_REMESH_CGAL_H
#define CS_MESHDATA_REMESH_CGAL_H
#include <stddef.h>
#ifdef __cplusplus
extern "C" {
#endif
/* Isotropic remeshing (CGAL::Polygon_mesh_processing::isotropic_remeshing, boundary edges split to at most h and
   then protected) of the oriented triangle mesh (nv vertices x, nf faces f, 0-based) to target edge length h with
   the given number of iterations. On success returns 0 with the result in malloc'ed *x_out (3 *nv_out) and
   *f_out (3 *nf_out), to be freed with free(), and self_intersects[0], [1]: 1 where the input, the result
   intersects itself (PMP::does_self_intersect); on
   failure returns 1 with a one-line reason in msg (nothing to free). */
int CSRemeshCGAL(long nv, const double *x, long nf, const long *f, double h, int iterations, long *nv_out, double **x_out, long *nf_out, long **f_out, int self_intersects[2], char *msg, size_t msglen);
#ifdef __cplusplus
}
#endif
#endif
