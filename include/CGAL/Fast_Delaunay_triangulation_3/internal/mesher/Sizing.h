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
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Nearest_point.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedron_quality.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

inline double distance(const double* p, const double* q)
{
  return std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) + (p[2] - q[2]) * (p[2] - q[2]));
}

// For each of `queries` (vertices of m), the index of the nearest of
// `points`, the first in index order among the equally near ones, as a
// scan in that order finds it (with no points, std::size_t(-1)).  The scan
// costs queries times points distances; past a few million (when the
// recovery fell back to TetGen on a large surface, which may add thousands
// of Steiner points) a k-d tree of the points is built instead and asked
// for the eight nearest to each query, among which the scan's choice is
// made.  When the farthest of those is within rounding of the nearest
// (more may tie, and the tree ranks squared distances with its own
// roundings), it is asked for twice as many, until one is clearly
// farther or all are in: the answer is the scan's.  `use_tree`: 1 or 0
// forces one way (tests), -1 chooses.
inline std::vector<std::size_t> nearest_input_points(const std::vector<std::array<double, 3>>& points,
                                                     const Flat_storage& m, const std::vector<Vertex_id>& queries,
                                                     int use_tree = -1)
{
  std::vector<std::size_t> nearest(queries.size(), std::size_t(-1));
  if(points.empty() || queries.empty()) return nearest;
  const double scan_cost = double(points.size()) * double(queries.size());
  // The first nearest of the candidates, and the farthest distance among them.
  auto first_nearest = [&](const double* q, const std::size_t* candidates, std::size_t n, double& farthest) {
    double least = std::numeric_limits<double>::infinity();
    std::size_t chosen = candidates[0];
    farthest = 0;
    for(std::size_t c = 0; c < n; ++c) {
      const double d = distance(q, points[candidates[c]].data());
      farthest = std::max(farthest, d);
      if(d < least || (d == least && candidates[c] < chosen)) {
        least = d;
        chosen = candidates[c];
      }
    }
    return std::make_pair(chosen, least);
  };
  double farthest;
  if(use_tree == 1 || (use_tree < 0 && scan_cost > 4e6)) {
    const Nearest_point_index index(points);
    std::vector<std::size_t> candidates;
    for(std::size_t k = 0; k < queries.size(); ++k) {
      const double* q = m.point(queries[k]);
      for(std::size_t wanted = 8;; wanted *= 2) {
        index.nearest(q, wanted, candidates);
        const auto found = first_nearest(q, candidates.data(), candidates.size(), farthest);
        nearest[k] = found.first;
        if(candidates.size() < wanted || farthest > found.second * (1 + 1e-12)) break;
      }
    }
  } else {
    std::vector<std::size_t> all(points.size());
    for(std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    for(std::size_t k = 0; k < queries.size(); ++k)
      nearest[k] = first_nearest(m.point(queries[k]), all.data(), all.size(), farthest).first;
  }
  return nearest;
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
  std::vector<Vertex_id> steiner;
  for(Vertex_id v = 0; v < m.vertices.size(); ++v)
    if(cm.size[v] < 0) steiner.push_back(v);
  const std::vector<std::size_t> nearest = nearest_input_points(soup.points, m, steiner);
  for(std::size_t k = 0; k < steiner.size(); ++k) cm.size[steiner[k]] = cm.size[cm.vertex_of_input[nearest[k]]];
  // The user's function bounds these sizes too; a subdomain's cap does
  // not (a surface vertex is on the side of every subdomain it bounds, and
  // a cap inside one would otherwise refine its neighbours near the
  // surface): it bounds the sizes interpolated inside its subdomain.
  for(Vertex_id v = 0; v < m.vertices.size(); ++v) cm.size[v] = cm.size.bounded(cm.size[v], m.point(v), 0);
}

// Input triangles whose circumradius exceeds radius_ratio times h on one
// of their sides (the largest of the corners' sizes under that subdomain's
// caps), each counted once.  Refinement splits a tetrahedron whose
// circumradius is over radius_ratio h, but the surface is never split: the
// tetrahedra on such a triangle stay over the size, and those between it
// and the small ones inside come out flat, which the improvement then
// works on in vain (a unit tetrahedron meshed at h = 0.05: 2357 of its
// 7771 tetrahedra under gamma 0.3, and the improvement 140 times the
// refinement's time).  Called once the sizes are set.
inline std::size_t triangles_over_size(const Constrained_mesh& cm, double radius_ratio)
{
  const Flat_storage& m = cm.mesh;
  auto inside = [&](Tet_id t) { return !m.is_ghost(t) && cm.subdomain[t] >= 1; };
  // The corners' largest h under the caps of the subdomain of tetrahedron t.
  auto size_beside = [&](Tet_id t, const Vertex_id corner[3]) {
    double h = 0;
    for(int i = 0; i < 3; ++i) h = std::max(h, cm.size.capped(cm.size[corner[i]], cm.subdomain[t]));
    return h;
  };
  std::size_t count = 0;
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || !inside(t)) continue;
    for(int f = 0; f < 4; ++f) {
      if(!cm.is_constrained(t, f)) continue;
      const Tet_id other = m.neighbor(t, f);
      const bool both_sides = inside(other);
      if(both_sides && other < t) continue; // counted from `other`
      const Vertex_id* tv = m.vertex_ids(t);
      const Vertex_id corner[3] = {tv[(f + 1) & 3], tv[(f + 2) & 3], tv[(f + 3) & 3]};
      double h = size_beside(t, corner);
      if(both_sides) h = std::min(h, size_beside(other, corner));
      // R = |ab| |ac| |bc| / (2 |ab x ac|); the mesher's unit scale keeps
      // the products far from overflow.
      const double *a = m.point(corner[0]), *b = m.point(corner[1]), *c = m.point(corner[2]);
      double ab[3], ac[3], bc[3], normal[3];
      for(int k = 0; k < 3; ++k) {
        ab[k] = b[k] - a[k];
        ac[k] = c[k] - a[k];
        bc[k] = c[k] - b[k];
      }
      quality_detail::cross(ab, ac, normal);
      using quality_detail::norm;
      count += norm(ab) * norm(ac) * norm(bc) > 2 * radius_ratio * h * norm(normal) ? 1 : 0;
    }
  }
  return count;
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
