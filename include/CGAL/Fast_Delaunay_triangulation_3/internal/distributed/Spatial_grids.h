// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Two uniform grids over boxes, for the questions the ball exchange asks:
//   Rank_occupancy  which ranks own points in a grid cell of the global box: a ball is sent only to the ranks whose
//                   occupied cells it touches (one bit per cell and rank, gathered once after the partition);
//   Point_grid      which of a rank's own points lie in a ball: the answer to another rank's question.
// Both are conservative where it matters: a point is always counted in the cell its coordinates fall in, and a
// ball's box covers every cell it could touch (coordinates beyond the grid clamp to its border cells).

#ifndef CGAL_FDT3_INTERNAL_DISTRIBUTED_SPATIAL_GRIDS_H
#define CGAL_FDT3_INTERNAL_DISTRIBUTED_SPATIAL_GRIDS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/distributed/Circumball_bound.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/distributed/Mpi_exchange.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace distributed {

// cells[a] cells along axis a over [lo, hi]; a flat box gets one cell along its flat axes.
class Box_grid
{
public:
  Box_grid() = default;
  Box_grid(const double lo[3], const double hi[3], const std::uint32_t cells[3])
  {
    for(int a = 0; a < 3; ++a) {
      lo_[a] = lo[a];
      cells_[a] = std::max<std::uint32_t>(1, cells[a]);
      const double width = hi[a] - lo[a];
      // A zero or overflowing width maps every coordinate to cell 0 (inv 0), which stays conservative.
      inv_width_[a] = width > 0 && std::isfinite(width) ? double(cells_[a]) / width : 0;
    }
  }

  std::size_t number_of_cells() const { return std::size_t(cells_[0]) * cells_[1] * cells_[2]; }

  std::uint32_t cell_along(int a, double x) const
  {
    const double g = (x - lo_[a]) * inv_width_[a];
    if(!(g >= 0)) return 0;  // also NaN
    if(g >= double(cells_[a])) return cells_[a] - 1;
    return std::uint32_t(g);
  }
  std::size_t cell_of(const double p[3]) const
  {
    return index(cell_along(0, p[0]), cell_along(1, p[1]), cell_along(2, p[2]));
  }
  std::size_t index(std::uint32_t i, std::uint32_t j, std::uint32_t k) const
  {
    return (std::size_t(k) * cells_[1] + j) * cells_[0] + i;
  }

  // f(cell index) for every cell the axis box of `ball` meets.
  template <class F>
  void for_each_cell_meeting(const Ball_bound& ball, F f) const
  {
    std::uint32_t first[3], last[3];
    for(int a = 0; a < 3; ++a) {
      first[a] = cell_along(a, ball.center[a] - ball.radius);
      last[a] = cell_along(a, ball.center[a] + ball.radius);
      if(!std::isfinite(ball.radius) || !std::isfinite(ball.center[a])) {
        first[a] = 0;
        last[a] = cells_[a] - 1;
      }
    }
    for(std::uint32_t k = first[2]; k <= last[2]; ++k)
      for(std::uint32_t j = first[1]; j <= last[1]; ++j)
        for(std::uint32_t i = first[0]; i <= last[0]; ++i) f(index(i, j, k));
  }

private:
  double lo_[3] = {0, 0, 0};
  double inv_width_[3] = {0, 0, 0};
  std::uint32_t cells_[3] = {1, 1, 1};
};

// The ranks owning points in each cell of a grid over the global box, as lists (compressed rows).
class Rank_occupancy
{
public:
  // Collective. `points` are this rank's own points (3 doubles each); lo/hi the global box.
  Rank_occupancy(const Communicator& comm, const double lo[3], const double hi[3], std::size_t total_points,
                 const std::vector<double>& points, std::uint64_t* bytes_sent)
    : rank_(comm.rank()), stamp_(std::size_t(comm.size()), 0)
  {
    // About one cell per 4 points, at most 2^18 cells: 32 KiB of bits per rank, gathered by every rank.
    std::uint32_t per_axis = 1;
    while(per_axis < 64 && std::uint64_t(per_axis) * per_axis * per_axis * 4 < total_points) per_axis *= 2;
    const std::uint32_t cells[3] = {per_axis, per_axis, per_axis};
    grid_ = Box_grid(lo, hi, cells);
    const std::size_t words = (grid_.number_of_cells() + 63) / 64;
    std::vector<std::uint64_t> mine(words, 0);
    for(std::size_t i = 0; i < points.size() / 3; ++i) {
      const std::size_t c = grid_.cell_of(&points[3 * i]);
      mine[c / 64] |= std::uint64_t(1) << (c % 64);
    }
    const std::vector<std::uint64_t> all = comm.all_gather(mine, nullptr, bytes_sent);
    first_.assign(grid_.number_of_cells() + 1, 0);
    for(int r = 0; r < comm.size(); ++r)
      for(std::size_t c = 0; c < grid_.number_of_cells(); ++c)
        if(all[std::size_t(r) * words + c / 64] >> (c % 64) & 1) ++first_[c + 1];
    for(std::size_t c = 0; c < grid_.number_of_cells(); ++c) first_[c + 1] += first_[c];
    ranks_.resize(first_.back());
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for(int r = 0; r < comm.size(); ++r)
      for(std::size_t c = 0; c < grid_.number_of_cells(); ++c)
        if(all[std::size_t(r) * words + c / 64] >> (c % 64) & 1) ranks_[next[c]++] = r;
  }

  // The other ranks whose cells the ball's box meets, each once, appended to `out` (cleared first).
  void other_ranks_meeting(const Ball_bound& ball, std::vector<int>& out)
  {
    out.clear();
    ++current_;
    grid_.for_each_cell_meeting(ball, [&](std::size_t c) {
      for(std::size_t k = first_[c]; k < first_[c + 1]; ++k) {
        const int r = ranks_[k];
        if(r != rank_ && stamp_[std::size_t(r)] != current_) {
          stamp_[std::size_t(r)] = current_;
          out.push_back(r);
        }
      }
    });
  }

private:
  int rank_;
  Box_grid grid_;
  std::vector<std::size_t> first_;
  std::vector<int> ranks_;
  std::vector<std::uint64_t> stamp_;
  std::uint64_t current_ = 0;
};

// A rank's own points bucketed in a grid of about two points per cell over their box.
class Point_grid
{
public:
  explicit Point_grid(const std::vector<double>& points) : points_(points)
  {
    const std::size_t n = points.size() / 3;
    double lo[3], hi[3];
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::numeric_limits<double>::infinity();
      hi[a] = -lo[a];
    }
    for(std::size_t i = 0; i < n; ++i)
      for(int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], points[3 * i + a]);
        hi[a] = std::max(hi[a], points[3 * i + a]);
      }
    if(n == 0)
      for(int a = 0; a < 3; ++a) lo[a] = hi[a] = 0;
    const std::uint32_t per_axis = std::max<std::uint32_t>(1, std::uint32_t(std::cbrt(double(n) / 2)));
    const std::uint32_t cells[3] = {per_axis, per_axis, per_axis};
    grid_ = Box_grid(lo, hi, cells);
    first_.assign(grid_.number_of_cells() + 1, 0);
    for(std::size_t i = 0; i < n; ++i) ++first_[grid_.cell_of(&points[3 * i]) + 1];
    for(std::size_t c = 0; c < grid_.number_of_cells(); ++c) first_[c + 1] += first_[c];
    order_.resize(n);
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for(std::size_t i = 0; i < n; ++i) order_[next[grid_.cell_of(&points[3 * i])]++] = std::uint32_t(i);
  }

  // f(i) for each point i in the ball.
  template <class F>
  void for_each_point_in(const Ball_bound& ball, F f) const
  {
    grid_.for_each_cell_meeting(ball, [&](std::size_t c) {
      for(std::size_t k = first_[c]; k < first_[c + 1]; ++k)
        if(ball.contains(&points_[3 * std::size_t(order_[k])])) f(order_[k]);
    });
  }

private:
  const std::vector<double>& points_;
  Box_grid grid_;
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> order_;
};

} // namespace distributed
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_DISTRIBUTED_SPATIAL_GRIDS_H
