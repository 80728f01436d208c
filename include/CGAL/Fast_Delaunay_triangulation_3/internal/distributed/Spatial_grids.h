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
#include <cstdlib>
#include <limits>
#include <utility>
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

  // The range of cells, per axis, that the axis box of `ball` meets.
  template <class Index>
  void box_of(const Ball_bound& ball, Index first[3], Index last[3]) const
  {
    for(int a = 0; a < 3; ++a) {
      first[a] = Index(cell_along(a, ball.center[a] - ball.radius));
      last[a] = Index(cell_along(a, ball.center[a] + ball.radius));
      if(!std::isfinite(ball.radius) || !std::isfinite(ball.center[a])) {
        first[a] = 0;
        last[a] = Index(cells_[a] - 1);
      }
    }
  }

  // The squared distance from x to the slab of cells `i` along axis a, widened by a hundredth of a cell on each
  // side: a point on a cell's border may have been counted in the neighbouring cell by cell_along's rounding.
  double distance2_to_slab(int a, std::uint32_t i, double x) const
  {
    if(inv_width_[a] == 0) return 0;
    const double lo = lo_[a] + (double(i) - 0.01) / inv_width_[a], hi = lo_[a] + (double(i) + 1.01) / inv_width_[a];
    const double d = x < lo ? lo - x : (x > hi ? x - hi : 0);
    return d * d;
  }
  bool cell_meets(const Ball_bound& ball, std::uint32_t i, std::uint32_t j, std::uint32_t k) const
  {
    if(!ball.is_finite()) return true;
    return distance2_to_slab(0, i, ball.center[0]) + distance2_to_slab(1, j, ball.center[1]) +
               distance2_to_slab(2, k, ball.center[2]) <=
           ball.radius * ball.radius * (1 + 1e-12);
  }

  // f(cell index) for every cell that may hold a point of the ball, until f returns false: slab by slab and row by
  // row, each cut to the ball's extent there, so a thin cap of a huge ball costs its own cells.
  template <class F>
  void for_each_cell_meeting(const Ball_bound& ball, F f) const
  {
    std::uint32_t first[3], last[3];
    box_of(ball, first, last);
    const double r2 = ball.radius * ball.radius * (1 + 1e-12);
    // The cells along axis a of the points with |x - centre| <= half: cell_along is monotone, so the cells of the
    // two ends bracket them (the relative 1e-12 covers the rounding of the square root and of the subtraction).
    auto extent = [&](int a, double left, std::uint32_t& from, std::uint32_t& to) {
      const double half = std::sqrt(left) * (1 + 1e-12);
      from = std::max(first[a], cell_along(a, ball.center[a] - half));
      to = std::min(last[a], cell_along(a, ball.center[a] + half));
    };
    for(std::uint32_t k = first[2]; k <= last[2]; ++k) {
      std::uint32_t j0 = first[1], j1 = last[1];
      const double after_z = r2 - distance2_to_slab(2, k, ball.center[2]);
      if(ball.is_finite()) {
        if(after_z < 0) continue;
        extent(1, after_z, j0, j1);
      }
      for(std::uint32_t j = j0; j <= j1; ++j) {
        std::uint32_t i0 = first[0], i1 = last[0];
        if(ball.is_finite()) {
          const double after_y = after_z - distance2_to_slab(1, j, ball.center[1]);
          if(after_y < 0) continue;
          extent(0, after_y, i0, i1);
        }
        for(std::uint32_t i = i0; i <= i1; ++i)
          if(!f(index(i, j, k))) return;
      }
    }
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

    // Summed-volume table of the cells where another rank owns points: most balls are those of cells deep inside
    // this rank's region, and 8 lookups tell that no other rank is near their box.
    side_ = per_axis + 1;
    foreign_before_.assign(std::size_t(side_) * side_ * side_, 0);
    for(std::uint32_t k = 0; k < per_axis; ++k)
      for(std::uint32_t j = 0; j < per_axis; ++j)
        for(std::uint32_t i = 0; i < per_axis; ++i) {
          const std::size_t c = grid_.index(i, j, k);
          std::uint32_t foreign = 0;
          for(std::size_t m = first_[c]; m < first_[c + 1]; ++m) foreign |= ranks_[m] != rank_;
          foreign_before_[table(i + 1, j + 1, k + 1)] =
              foreign + foreign_before_[table(i, j + 1, k + 1)] + foreign_before_[table(i + 1, j, k + 1)] +
              foreign_before_[table(i + 1, j + 1, k)] - foreign_before_[table(i, j, k + 1)] -
              foreign_before_[table(i, j + 1, k)] - foreign_before_[table(i + 1, j, k)] + foreign_before_[table(i, j, k)];
        }
  }

  // The other ranks whose cells the ball's box meets, each once, appended to `out` (cleared first).
  void other_ranks_meeting(const Ball_bound& ball, std::vector<int>& out)
  {
    out.clear();
    std::uint32_t first[3], last[3];
    grid_.box_of(ball, first, last);
    const std::uint32_t i0 = first[0], j0 = first[1], k0 = first[2], i1 = last[0] + 1, j1 = last[1] + 1, k1 = last[2] + 1;
    const std::int64_t foreign =
        std::int64_t(foreign_before_[table(i1, j1, k1)]) - foreign_before_[table(i0, j1, k1)] -
        foreign_before_[table(i1, j0, k1)] - foreign_before_[table(i1, j1, k0)] + foreign_before_[table(i0, j0, k1)] +
        foreign_before_[table(i0, j1, k0)] + foreign_before_[table(i1, j0, k0)] - foreign_before_[table(i0, j0, k0)];
    if(foreign == 0) return;
    ++current_;
    const std::size_t others = stamp_.size() - 1;
    grid_.for_each_cell_meeting(ball, [&](std::size_t c) {
      for(std::size_t k = first_[c]; k < first_[c + 1]; ++k) {
        const int r = ranks_[k];
        if(r != rank_ && stamp_[std::size_t(r)] != current_) {
          stamp_[std::size_t(r)] = current_;
          out.push_back(r);
        }
      }
      return out.size() < others;
    });
  }

private:
  std::size_t table(std::uint32_t i, std::uint32_t j, std::uint32_t k) const
  {
    return (std::size_t(k) * side_ + j) * side_ + i;
  }

  int rank_;
  Box_grid grid_;
  std::uint32_t side_ = 1;
  std::vector<std::uint32_t> foreign_before_;  // (i, j, k): foreign cells with all three indices below
  std::vector<std::size_t> first_;
  std::vector<int> ranks_;
  std::vector<std::uint64_t> stamp_;
  std::uint64_t current_ = 0;
};

// A rank's own points bucketed in a grid of about four points per cell over their box (2, 4 and 8 measured alike
// on 4e6 points, two ranks: exchange 5.8-6.0 s, 5.6-5.8 s, 6.2-6.4 s).
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
    const std::uint32_t per_axis = std::max<std::uint32_t>(1, std::uint32_t(std::cbrt(double(n) / 4)));
    const std::uint32_t cells[3] = {per_axis, per_axis, per_axis};
    grid_ = Box_grid(lo, hi, cells);
    first_.assign(grid_.number_of_cells() + 1, 0);
    for(std::size_t i = 0; i < n; ++i) ++first_[grid_.cell_of(&points[3 * i]) + 1];
    for(std::size_t c = 0; c < grid_.number_of_cells(); ++c) first_[c + 1] += first_[c];
    order_.resize(n);
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for(std::size_t i = 0; i < n; ++i) order_[next[grid_.cell_of(&points[3 * i])]++] = std::uint32_t(i);
    // Each cell's points' box, in floats rounded outward (12 bytes a point): a ball that meets a cell but not its
    // points (the thin cap, along a face of the domain, of the ball of a flat cell on the hull) skips them.
    const float far = std::numeric_limits<float>::infinity();
    points_box_.assign(6 * grid_.number_of_cells(), 0);
    for(std::size_t c = 0; c < grid_.number_of_cells(); ++c) {
      float* box = &points_box_[6 * c];
      for(int a = 0; a < 3; ++a) {
        box[a] = far;
        box[a + 3] = -far;
      }
      for(std::size_t m = first_[c]; m < first_[c + 1]; ++m)
        for(int a = 0; a < 3; ++a) {
          const double x = points[3 * std::size_t(order_[m]) + a];
          box[a] = std::min(box[a], std::nextafter(float(x), -far));
          box[a + 3] = std::max(box[a + 3], std::nextafter(float(x), far));
        }
    }
  }

  // Whether the ball may hold a point of cell c (false for an empty cell: its box is empty).
  bool points_of_cell_may_meet(const Ball_bound& ball, std::size_t c) const
  {
    if(!ball.is_finite()) return first_[c] != first_[c + 1];
    const float* box = &points_box_[6 * c];
    double d2 = 0;
    for(int a = 0; a < 3; ++a) {
      const double x = ball.center[a];
      const double d = x < box[a] ? box[a] - x : (x > box[a + 3] ? x - box[a + 3] : (box[a] <= box[a + 3] ? 0 : 1e308));
      d2 += d * d;
    }
    return d2 <= ball.radius * ball.radius * (1 + 1e-12);
  }

  // Up to `wanted` points i in the ball with accept(i), nearest to `near` among those seen. First the cells in
  // rings of growing distance around near's cell, at most `rings` of them, ending one ring after the first that
  // found a point: a ball reaching far into this rank's points finds one there at once. If none was found, every
  // cell that meets the ball: a ball that only grazes these points (the thin cap of a flat cell's ball) costs its
  // few cells. Returns whether points of the ball may be left unchosen (the asker asks again while its cell lives).
  template <class Accept>
  bool nearest_in_ball(const Ball_bound& ball, const double near[3], std::size_t wanted, Accept accept,
                       std::vector<std::uint32_t>& chosen) const
  {
    constexpr std::int64_t rings = 3;
    chosen.clear();
    std::vector<std::pair<double, std::uint32_t>>& found = found_;
    found.clear();
    auto look_in = [&](std::size_t c) {
      if(!points_of_cell_may_meet(ball, c)) return;
      for(std::size_t m = first_[c]; m < first_[c + 1]; ++m) {
        const std::uint32_t p = order_[m];
        const double* q = &points_[3 * std::size_t(p)];
        if(!ball.contains(q) || !accept(p)) continue;
        const double dx = q[0] - near[0], dy = q[1] - near[1], dz = q[2] - near[2];
        found.push_back({dx * dx + dy * dy + dz * dz, p});
      }
    };
    std::int64_t first[3], last[3], centre[3];
    grid_.box_of(ball, first, last);
    for(int a = 0; a < 3; ++a) centre[a] = std::clamp<std::int64_t>(grid_.cell_along(a, near[a]), first[a], last[a]);
    std::int64_t reach = 0;
    for(int a = 0; a < 3; ++a) reach = std::max({reach, centre[a] - first[a], last[a] - centre[a]});
    std::int64_t stop = std::min(reach, rings - 1);
    std::int64_t d = 0;
    for(; d <= stop; ++d) {
      for(std::int64_t k = std::max(first[2], centre[2] - d); k <= std::min(last[2], centre[2] + d); ++k)
        for(std::int64_t j = std::max(first[1], centre[1] - d); j <= std::min(last[1], centre[1] + d); ++j) {
          const bool face = std::abs(k - centre[2]) == d || std::abs(j - centre[1]) == d;
          // Inside the ring's faces in k and j, only the two cells at distance d along i.
          const std::int64_t step = face ? 1 : std::max<std::int64_t>(2 * d, 1);
          for(std::int64_t i = centre[0] - d; i <= centre[0] + d; i += step) {
            if(i < first[0] || i > last[0]) continue;
            if(grid_.cell_meets(ball, std::uint32_t(i), std::uint32_t(j), std::uint32_t(k)))
              look_in(grid_.index(std::uint32_t(i), std::uint32_t(j), std::uint32_t(k)));
          }
        }
      if(!found.empty() && stop > d + 1) stop = d + 1;
    }
    bool covered = d > reach;
    // Any point of the ball will do there: the first cells that hold one end the search.
    if(found.empty() && !covered) {
      covered = true;
      grid_.for_each_cell_meeting(ball, [&](std::size_t c) {
        look_in(c);
        if(found.size() < wanted) return true;
        covered = false;
        return false;
      });
    }
    const std::size_t n = std::min(found.size(), wanted);
    std::partial_sort(found.begin(), found.begin() + std::ptrdiff_t(n), found.end());
    for(std::size_t m = 0; m < n; ++m) chosen.push_back(found[m].second);
    return found.size() > wanted || (!covered && !found.empty());
  }

private:
  const std::vector<double>& points_;
  Box_grid grid_;
  std::vector<std::size_t> first_;
  std::vector<std::uint32_t> order_;
  std::vector<float> points_box_;  // per cell: lo x, y, z, hi x, y, z
  mutable std::vector<std::pair<double, std::uint32_t>> found_;
};

} // namespace distributed
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_DISTRIBUTED_SPATIAL_GRIDS_H
