/* Isotropic remeshing of serial triangle data with CGAL 5.5 Polygon_mesh_processing (Botsch-Kobbelt 2004 as
   implemented by CGAL: split edges above 4/3 h, collapse below 4/5 h, flip towards valence 6, tangential
   relaxation, projection to the input surface), the one C++ translation unit of confsurf, behind the plain C
   interface of meshdata_remesh_cgal.h (no PETSc types cross it). A boundary is kept: its edges are split to at
   most h and then protected (neither split nor collapsed), as in CGAL's isotropic_remeshing_example.cpp, so the
   boundary curve and its vertices stay where they are. */
#include "meshdata_remesh_cgal.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>
#include <boost/iterator/function_output_iterator.hpp>

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <vector>

namespace PMP = CGAL::Polygon_mesh_processing;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3>                      Mesh;
typedef Mesh::Vertex_index                                  VI;
typedef Mesh::Edge_index                                    EI;

/* the input as a Surface_mesh; 0, or 1 when CGAL refuses a face (non-manifold input: validation prevents it) */
static int Build(long nv, const double *x, long nf, const long *f, Mesh &m)
{
  std::vector<VI> v((size_t)nv);
  for (long i = 0; i < nv; i++) v[(size_t)i] = m.add_vertex(K::Point_3(x[3 * i], x[3 * i + 1], x[3 * i + 2]));
  for (long i = 0; i < nf; i++)
    if (m.add_face(v[(size_t)f[3 * i]], v[(size_t)f[3 * i + 1]], v[(size_t)f[3 * i + 2]]) == Mesh::null_face()) return 1;
  return 0;
}

/* the result into malloc'ed arrays (the caller frees them) */
static int Export(Mesh &m, long *nv, double **x, long *nf, long **f)
{
  m.collect_garbage();
  *nv = (long)m.number_of_vertices();
  *nf = (long)m.number_of_faces();
  *x  = (double *)malloc(sizeof(double) * 3 * (size_t)*nv);
  *f  = (long *)malloc(sizeof(long) * 3 * (size_t)*nf);
  if (!*x || !*f) return 1;
  for (VI v : m.vertices()) {
    const K::Point_3 &p = m.point(v);
    for (int d = 0; d < 3; d++) (*x)[3 * (size_t)v + d] = p[d];
  }
  size_t k = 0;
  for (Mesh::Face_index fc : m.faces())
    for (VI v : m.vertices_around_face(m.halfedge(fc))) (*f)[k++] = (long)(size_t)v;
  return 0;
}

extern "C" int CSRemeshCGAL(long nv, const double *x, long nf, const long *f, double h, int iterations, long *nv_out, double **x_out, long *nf_out, long **f_out, int self_intersects[2], char *msg, size_t msglen)
{
  *x_out = NULL;
  *f_out = NULL;
  try {
    Mesh            m;
    std::vector<EI> border;
    if (Build(nv, x, nf, f, m)) {
      snprintf(msg, msglen, "CGAL refused a face of the input (not an oriented 2-manifold)");
      return 1;
    }
    self_intersects[0] = PMP::does_self_intersect(m) ? 1 : 0;
    PMP::border_halfedges(faces(m), m, boost::make_function_output_iterator([&](Mesh::Halfedge_index h) { border.push_back(m.edge(h)); }));
    PMP::split_long_edges(border, h, m); /* protected edges must be shorter than 4/3 h (CGAL's precondition) */
    PMP::isotropic_remeshing(faces(m), h, m, CGAL::parameters::number_of_iterations((unsigned)iterations).protect_constraints(true));
    self_intersects[1] = PMP::does_self_intersect(m) ? 1 : 0;
    if (Export(m, nv_out, x_out, nf_out, f_out)) {
      snprintf(msg, msglen, "out of memory for the remeshed mesh");
      return 1;
    }
  } catch (const std::exception &e) { /* CGAL's failed preconditions, std::bad_alloc */
    snprintf(msg, msglen, "CGAL failed: %s", e.what());
    return 1;
  }
  return 0;
}
