// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The size field h (paper §4.1: "mesh size inside the domain is simply
// interpolated from the surface mesh").  A surface vertex gets the average
// length of its surface edges; a Steiner point of the recovery gets the size
// of the nearest surface vertex; a refinement point gets the linear
// interpolation, inside the tetrahedron that contains it, of the sizes of
// that tetrahedron's vertices, so that h stays the piecewise linear
// interpolation over the initial mesh.  Every size is clipped where it is
// made to the bounds the user set in the field (Size_field.h): a global
// cap, a cap per subdomain, a function of the position.

#ifndef CGAL_FDT3_INTERNAL_MESHER_SIZING_H
#define CGAL_FDT3_INTERNAL_MESHER_SIZING_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

inline double distance(const double* p, const double* q)
{
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// Fills cm.size for the vertices of the recovered, coloured mesh; its
// bounds are set.
inline void surface_sizes(const Surface_soup& soup, Constrained_mesh& cm)
{
  const double maximum_size = cm.size.cap();
  std::vector<double> sum(soup.points.size(), 0.0);
  std::vector<int> count(soup.points.size(), 0);
  // Each edge is used by two triangles: counting it from both keeps the average.
  for(const auto& t : soup.triangles)
    for(int i = 0; i < 3; ++i) {
      const std::uint32_t a = t[i], b = t[(i + 1) % 3];
      const double l = distance(soup.points[a].data(), soup.points[b].data());
      sum[a] += l; ++count[a];
      sum[b] += l; ++count[b];
    }
  const Flat_storage& m = cm.mesh;
  cm.size.assign(m.vertices.size(), -1.0);
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    cm.size[cm.vertex_of_input[i]] = std::min(maximum_size, sum[i] / count[i]);
  for(Vertex_id v = 0; v < m.vertices.size(); ++v) {
    if(cm.size[v] >= 0) continue;
    double nearest = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < soup.points.size(); ++i) {
      const double d = distance(m.point(v), soup.points[i].data());
      if(d < nearest) {
        nearest = d;
        cm.size[v] = cm.size[cm.vertex_of_input[i]];
      }
    }
  }
  // The user's function bounds these sizes too; a subdomain's cap does
  // not (a surface vertex is on the side of every subdomain it bounds, and
  // a cap inside one would otherwise refine its neighbours near the
  // surface): it bounds the sizes interpolated inside its subdomain.
  for(Vertex_id v = 0; v < m.vertices.size(); ++v) cm.size[v] = cm.size.bounded(cm.size[v], m.point(v), 0);
}

// The piecewise linear h at p, inside (or on) finite tetrahedron t.
inline double linear_size(const Constrained_mesh& cm, Tet_id t, const double* p)
{
  const Flat_storage& m = cm.mesh;
  const Vertex_id* tv = m.vertex_ids(t);
  const double* w[4] = {m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])};
  const double total = orientation_determinant(w[0], w[1], w[2], w[3]);
  double h = 0, weight_sum = 0;
  for(int i = 0; i < 4; ++i) {
    const double* q[4] = {w[0], w[1], w[2], w[3]};
    q[i] = p;
    const double weight = std::max(0.0, orientation_determinant(q[0], q[1], q[2], q[3]) / total);
    h += weight * cm.size[tv[i]];
    weight_sum += weight;
  }
  if(!(weight_sum > 0)) return (cm.size[tv[0]] + cm.size[tv[1]] + cm.size[tv[2]] + cm.size[tv[3]]) / 4;
  return h / weight_sum;
}

// h at p, inside (or on) finite tetrahedron t: barycentric interpolation,
// clipped to the bounds in t's subdomain.
inline double interpolated_size(const Constrained_mesh& cm, Tet_id t, const double* p)
{
  return cm.size.bounded(linear_size(cm, t, p), p, cm.subdomain[t]);
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_SIZING_H
