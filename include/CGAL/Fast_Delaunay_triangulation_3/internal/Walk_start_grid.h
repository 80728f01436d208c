// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the walk of a one-point insertion starts.  A bulk insertion sorts
// its points (BRIO + Moore curve), so each walk starts next to its point;
// insert(p) called in a loop gets the points in the caller's order, random
// in space for most callers, and a walk from the previous insertion crosses
// about n^(1/3) tetrahedra, one cache miss each.  This grid over the
// filters' box remembers, per grid cell, the vertex that the last insertion
// in that cell made; a walk starts at a tetrahedron of that vertex (or at
// the caller's hint when that is closer), a few steps from its point.
//
// The tetrahedron of a vertex comes from the caller, which keeps one per
// vertex up to date where it can and may be wrong elsewhere: an answer is
// used only if it is live and has the vertex.  (Remembering tetrahedra
// instead failed: their slots are soon reused by tetrahedra anywhere, and
// 58% of a loop's time went to walks from them.)  The grid is rebuilt from
// all vertices when they outnumber its cells eightfold or when the box has
// doubled along an axis (geometric growth: O(1) amortised per point);
// points beyond its box fall in its border cells meanwhile.  An empty cell
// borrows from one of its six neighbours.

#ifndef CGAL_FDT3_INTERNAL_WALK_START_GRID_H
#define CGAL_FDT3_INTERNAL_WALK_START_GRID_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

class Walk_start_grid
{
public:
  // About this many vertices per grid cell when the grid is (re)built.
  static constexpr std::size_t vertices_per_cell = 2;

  void clear()
  {
    starts_.clear();
    resolution_ = 0;
  }

  // The tetrahedron to start the walk to p from: one of the grid's vertex
  // for p's cell (tet_of(v): a tetrahedron that may have v), or `hint`,
  // whichever is nearer to p by its vertex 0.  `vertices` and the box
  // [lo, hi] are the triangulation's now; the grid is rebuilt if they
  // outgrew it.
  template <class Tet_of_vertex>
  Tet_id start(const Flat_storage& mesh, const double* p, Tet_id hint, std::size_t vertices, const double* lo,
               const double* hi, Tet_of_vertex tet_of)
  {
    fit(mesh, vertices, lo, hi);
    int k[3];
    cell_coordinates(p, k);
    Vertex_id v = starts_[index(k)];
    for(int neighbour = 0; v == no_vertex && neighbour < 6; ++neighbour) {
      int n[3] = {k[0], k[1], k[2]};
      n[neighbour / 2] += neighbour % 2 ? 1 : -1;
      if(n[neighbour / 2] >= 0 && n[neighbour / 2] < resolution_) v = starts_[index(n)];
    }
    if(v == no_vertex || v >= mesh.vertices.size()) return hint;
    const Tet_id t = tet_of(v);
    if(t >= mesh.number_of_slots() || !mesh.is_live(t) || index_of_vertex(mesh, t, v) < 0) return hint;
    return squared_distance(mesh.point(v), p) < squared_distance(mesh.point(mesh.vertex(hint, 0)), p) ? t : hint;
  }

  // The insertion of p made vertex v.
  void remember(const double* p, Vertex_id v)
  {
    if(resolution_ > 0) starts_[cell_of(p)] = v;
  }

private:
  static int index_of_vertex(const Flat_storage& mesh, Tet_id t, Vertex_id v)
  {
    for(int i = 0; i < 4; ++i)
      if(mesh.vertex(t, i) == v) return i;
    return -1;
  }

  static double squared_distance(const double* a, const double* b)
  {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
  }

  void fit(const Flat_storage& mesh, std::size_t vertices, const double* lo, const double* hi)
  {
    bool fits = resolution_ > 0 && vertices <= 8 * vertices_per_cell * starts_.size();
    for(int a = 0; a < 3 && fits; ++a) fits = hi[a] - lo[a] <= 2 * (hi_[a] - lo_[a]);
    if(fits) return;
    const double cells = std::max<double>(1.0, static_cast<double>(vertices) / vertices_per_cell);
    resolution_ = std::max(1, std::min(1024, static_cast<int>(std::cbrt(cells))));
    starts_.assign(static_cast<std::size_t>(resolution_) * resolution_ * resolution_, no_vertex);
    for(int a = 0; a < 3; ++a) {
      lo_[a] = lo[a];
      hi_[a] = hi[a];
      const double extent = hi[a] - lo[a];
      scale_[a] = extent > 0 ? resolution_ / extent : 0;
    }
    for(Vertex_id v = 0; v < mesh.vertices.size(); ++v)
      if(!mesh.is_dead(v)) starts_[cell_of(mesh.point(v))] = v;
  }

  void cell_coordinates(const double* p, int k[3]) const
  {
    // Points beyond the box (and on its far side) land in the border cells;
    // so does a NaN, from a box whose extent overflows (coordinates near
    // the largest double): it then has one cell along that axis, in effect.
    for(int a = 0; a < 3; ++a) {
      const double x = (p[a] - lo_[a]) * scale_[a];
      k[a] = x >= 0 ? (x < resolution_ ? static_cast<int>(x) : resolution_ - 1) : 0;
    }
  }
  std::size_t index(const int k[3]) const
  {
    return (static_cast<std::size_t>(k[0]) * resolution_ + static_cast<std::size_t>(k[1])) * resolution_ +
           static_cast<std::size_t>(k[2]);
  }
  std::size_t cell_of(const double* p) const
  {
    int k[3];
    cell_coordinates(p, k);
    return index(k);
  }

  static constexpr Vertex_id no_vertex = std::numeric_limits<Vertex_id>::max();
  std::vector<Vertex_id> starts_;
  int resolution_ = 0;
  double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0}, scale_[3] = {0, 0, 0};
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_WALK_START_GRID_H
