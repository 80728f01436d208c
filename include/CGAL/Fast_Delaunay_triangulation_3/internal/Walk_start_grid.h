// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Where the walk of a one-point insertion starts.  A bulk insertion sorts
// its points (BRIO + Moore curve), so each walk starts next to its point;
// insert(p) called in a loop gets the points in the caller's order, random
// in space for most callers, and a walk from the previous insertion crosses
// about n^(1/3) tetrahedra, one cache miss each.  This grid over the
// filters' box remembers, per grid cell, a tetrahedron that the last
// insertion in that cell made; a walk starts there (or at the caller's hint
// when that is closer), a few steps from its point.
//
// Any live tetrahedron is a correct start (the walk is exact from anywhere),
// so an entry whose tetrahedron was deleted, or whose slot now holds another
// tetrahedron, costs steps, never correctness.  The grid is rebuilt empty
// when the box grows or when the vertices outnumber its cells eightfold
// (geometric growth: O(1) amortised per point); it refills as points come.

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

  // The tetrahedron to start the walk to p from: the grid's entry for p's
  // cell, or `hint`, whichever has its vertex 0 nearer to p (the grid's only
  // if it is live).  `vertices` and the box [lo, hi] are the triangulation's
  // now; the grid is rebuilt if they outgrew it.
  Tet_id start(const Flat_storage& mesh, const double* p, Tet_id hint, std::size_t vertices, const double* lo,
               const double* hi)
  {
    fit(mesh, vertices, lo, hi);
    const Tet_id remembered = starts_[cell_of(p)];
    if(remembered >= mesh.number_of_slots() || !mesh.is_live(remembered)) return hint;
    return squared_distance(mesh.point(mesh.vertex(remembered, 0)), p) <
                   squared_distance(mesh.point(mesh.vertex(hint, 0)), p)
               ? remembered
               : hint;
  }

  // The insertion of p made tetrahedron t (one of its ball).
  void remember(const double* p, Tet_id t)
  {
    if(resolution_ > 0) starts_[cell_of(p)] = t;
  }

private:
  static double squared_distance(const double* a, const double* b)
  {
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return dx * dx + dy * dy + dz * dz;
  }

  // A rebuilt grid takes over the old one's live entries, each in the cell
  // of its tetrahedron's vertex 0, so that the walks stay short after the
  // box grows.
  void fit(const Flat_storage& mesh, std::size_t vertices, const double* lo, const double* hi)
  {
    const bool same_box = resolution_ > 0 && std::equal(lo, lo + 3, lo_) && std::equal(hi, hi + 3, hi_);
    if(same_box && vertices <= 8 * vertices_per_cell * starts_.size()) return;
    const double cells = std::max<double>(1.0, static_cast<double>(vertices) / vertices_per_cell);
    const int old_resolution = resolution_;
    resolution_ = std::max(1, std::min(1024, static_cast<int>(std::cbrt(cells))));
    std::vector<Tet_id> old_starts;
    if(old_resolution > 0) old_starts.swap(starts_);
    starts_.assign(static_cast<std::size_t>(resolution_) * resolution_ * resolution_, no_start);
    for(int a = 0; a < 3; ++a) {
      lo_[a] = lo[a];
      hi_[a] = hi[a];
      const double extent = hi[a] - lo[a];
      scale_[a] = extent > 0 ? resolution_ / extent : 0;
    }
    for(Tet_id t : old_starts)
      if(t < mesh.number_of_slots() && mesh.is_live(t)) starts_[cell_of(mesh.point(mesh.vertex(t, 0)))] = t;
  }

  std::size_t cell_of(const double* p) const
  {
    std::size_t index = 0;
    for(int a = 0; a < 3; ++a) {
      // Points on the box's far side (and rounding) land in the last cell.
      const int k = std::min(resolution_ - 1, std::max(0, static_cast<int>((p[a] - lo_[a]) * scale_[a])));
      index = index * static_cast<std::size_t>(resolution_) + static_cast<std::size_t>(k);
    }
    return index;
  }

  static constexpr Tet_id no_start = std::numeric_limits<Tet_id>::max();
  std::vector<Tet_id> starts_;
  int resolution_ = 0;
  double lo_[3] = {0, 0, 0}, hi_[3] = {0, 0, 0}, scale_[3] = {0, 0, 0};
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_WALK_START_GRID_H
