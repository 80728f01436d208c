// Insertion order of the points: Biased Randomized Insertion Order (Amenta, Choi, Rote) rounds, every round but the
// first sorted along the Moore curve.
//
// Paper §2.3 ("Fast spatial sorting"): random rounds of geometrically growing size keep cavities small, the sort
// within a round keeps walks short. The rounds follow HXT (HXT_FACTS §2): ratio 7.5 down from n while a round would
// exceed 2048 points, so 1e6 points give 316 | 2054 | 15407 | 115556 | 866667. Unlike HXT, everything is one radix
// sort of 64-bit (key, index) pairs, key = (round << 3b) | Moore index with b = brio_bits_per_axis(n); the first
// round's low bits are hash bits, which leaves it in random order. Only runs of points that share a key are sorted
// again, along the curve of their own box (sort_shared_cells).

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_BRIO_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_BRIO_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Moore_curve.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

namespace brio_detail {

constexpr double round_ratio = 7.5;
constexpr std::size_t first_round_max = 2048;
// 2^32 points need 9 rounds; the round number is stored in the key above the Moore index.
constexpr std::size_t max_rounds = 16;

// A bijective 64-bit mixer (the splitmix64 finalizer): consecutive inputs give independent-looking outputs.
inline std::uint64_t mix64(std::uint64_t z)
{
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  return z ^ (z >> 31);
}

// Depends on the input position only, never on the thread that computes it, so the order is reproducible for any
// thread count. Mixing the seed first keeps seeds s and s + golden from giving shifted copies of one sequence.
inline std::uint64_t point_hash(std::uint64_t index, std::uint64_t seed)
{
  return mix64(mix64(seed) + index * 0x9e3779b97f4a7c15ull);
}

} // namespace brio_detail

// Expected cumulative end of each round for n points (the last one is n). The rounds actually drawn have these
// sizes on average; each point's round is a biased coin, so the counts vary by about their square root.
inline std::vector<std::size_t> brio_round_targets(std::size_t n)
{
  std::vector<std::size_t> ends{n};
  std::size_t end = n;
  while(end > brio_detail::first_round_max) {
    end = std::size_t(double(end) / brio_detail::round_ratio);
    ends.push_back(end);
  }
  std::reverse(ends.begin(), ends.end());
  return ends;
}

// Where the input points are read, in place (a point source): point(i) is the address of the x, y, z of point i,
// three consecutive doubles.  Packed_points is an array x0 y0 z0 x1 ...; the class's range insertion also reads a
// user's array of CGAL points through its own source, without copying it first (Fast_Delaunay_triangulation_3.h).
struct Packed_points
{
  const double* xyz;
  const double* point(std::size_t i) const { return xyz + 3 * i; }
};

// Whether T is a point source rather than packed coordinates (a pointer or an array, which the overloads below wrap).
template <class T>
using enable_if_point_source = typename std::enable_if<!std::is_pointer<typename std::decay<T>::type>::value>::type;

// How brio_keys lays out a key: bits [0, index_bits) hold the Moore index (hash bits in round 0), the bits above
// hold the round; key_bits is what the radix sort needs to look at.
struct Bounding_box
{
  double lo[3];
  double hi[3];
};

struct Brio_key_layout
{
  int bits_per_axis = 1;
  int index_bits = 3;
  int key_bits = 3;
  std::size_t rounds = 1;
  Bounding_box box{}; // the points' box, the Moore grid's (unset for no point)
};

// Box of n >= 1 points, each chunk reduced separately: min and max are exact, so any chunking gives the same box.
template <class Points, class = enable_if_point_source<Points>>
Bounding_box bounding_box(const Points& points, std::size_t n, int num_threads)
{
  CGAL_precondition(n > 0);
  // Four points per step into 12 independent lanes (lane j sees axis j % 3): the min/max chains no longer serialise
  // and the compiler vectorises the lanes; 1.1-1.7 ms instead of 4.5 ms for 1e6 points.
  constexpr std::size_t lanes = 12;
  const int chunks = chunk_count(n, num_threads);
  std::vector<Bounding_box> partial(static_cast<std::size_t>(chunks));
  for_each_chunk(chunks, [&](int c) {
    const std::size_t begin = chunk_begin(n, chunks, c), end = chunk_begin(n, chunks, c + 1);
    double lo[lanes], hi[lanes];
    for(std::size_t j = 0; j < lanes; ++j)
      lo[j] = hi[j] = points.point(begin)[j % 3];
    std::size_t i = begin;
    for(; i + lanes / 3 <= end; i += lanes / 3)
      for(std::size_t k = 0; k < lanes / 3; ++k) {
        const double* p = points.point(i + k);
        for(std::size_t a = 0; a < 3; ++a) {
          lo[3 * k + a] = std::min(lo[3 * k + a], p[a]);
          hi[3 * k + a] = std::max(hi[3 * k + a], p[a]);
        }
      }
    for(; i < end; ++i)
      for(std::size_t j = 0; j < 3; ++j) {
        lo[j] = std::min(lo[j], points.point(i)[j]);
        hi[j] = std::max(hi[j], points.point(i)[j]);
      }
    Bounding_box& box = partial[std::size_t(c)];
    for(std::size_t a = 0; a < 3; ++a) {
      box.lo[a] = std::min({lo[a], lo[a + 3], lo[a + 6], lo[a + 9]});
      box.hi[a] = std::max({hi[a], hi[a + 3], hi[a + 6], hi[a + 9]});
    }
  });
  Bounding_box box = partial[0];
  for(const Bounding_box& other : partial)
    for(int a = 0; a < 3; ++a) {
      box.lo[a] = std::min(box.lo[a], other.lo[a]);
      box.hi[a] = std::max(box.hi[a], other.hi[a]);
    }
  return box;
}

inline Bounding_box bounding_box(const double* xyz, std::size_t n, int num_threads)
{
  return bounding_box(Packed_points{xyz}, n, num_threads);
}

namespace brio_detail {
inline int round_bits(std::size_t rounds)
{
  int bits = 0;
  while((std::size_t(1) << bits) < rounds)
    ++bits;
  return bits;
}
} // namespace brio_detail

// Resolution of the curve: as fine as a 64-bit key with the round number allows (20 bits per axis for up to 16
// rounds), not moore_bits_per_axis(n). Measured on 1e6 clustered points (20 blobs of sigma 1e-3): the n-based 9 bits
// left ~2000 points per cell in random order, walks grew from 5 to 35 steps per point and the triangulation took
// 6.8 s instead of 2.9 s; on uniform points the finer key costs ~30 ms more sorting.
inline int brio_bits_per_axis(std::size_t n)
{
  const int round_bits = brio_detail::round_bits(brio_round_targets(n).size());
  return std::min(Moore_curve::max_bits_per_axis, (64 - round_bits) / 3);
}

// Fills `items` with one (key, point index) pair per point, in input order and unsorted; sorting them by key gives
// the insertion order. The Moore grid is the points' bounding box with the default split. Points must be finite.
template <class Points, class = enable_if_point_source<Points>>
Brio_key_layout brio_keys(const Points& points, std::size_t n, std::uint64_t seed, int num_threads,
                          std::vector<Key_value<std::uint32_t>>& items)
{
  CGAL_precondition(n <= std::size_t(std::numeric_limits<std::uint32_t>::max()) + 1);
  const std::vector<std::size_t> targets = brio_round_targets(n);
  CGAL_assertion(targets.size() <= brio_detail::max_rounds);

  Brio_key_layout layout;
  layout.rounds = targets.size();
  const int round_bits = brio_detail::round_bits(layout.rounds);
  layout.bits_per_axis = brio_bits_per_axis(n);
  layout.index_bits = 3 * layout.bits_per_axis;
  layout.key_bits = layout.index_bits + round_bits;
  CGAL_assertion(layout.key_bits <= 64);

  items.resize(n);
  if(n == 0)
    return layout;

  // A point joins round r when the top 53 bits of its hash reach the first r thresholds (targets as fractions of n).
  std::array<std::uint64_t, brio_detail::max_rounds> threshold{};
  const std::size_t threshold_count = layout.rounds - 1;
  for(std::size_t k = 0; k < threshold_count; ++k)
    threshold[k] = std::uint64_t(double(targets[k]) / double(n) * 0x1p53);

  layout.box = bounding_box(points, n, num_threads);
  const Bounding_box& box = layout.box;
  const Moore_grid grid(box.lo, box.hi, layout.bits_per_axis);
  const Moore_curve curve(layout.bits_per_axis);
  const int index_bits = layout.index_bits;
  const std::uint64_t index_mask = (std::uint64_t(1) << index_bits) - 1;
  const int chunks = chunk_count(n, num_threads);
  for_each_chunk(chunks, [&](int c) {
    const std::size_t end = chunk_begin(n, chunks, c + 1);
    for(std::size_t i = chunk_begin(n, chunks, c); i < end; ++i) {
      const std::uint64_t hash = brio_detail::point_hash(i, seed);
      std::uint64_t round = 0;
      for(std::size_t k = 0; k < threshold_count; ++k)
        round += (hash >> 11) >= threshold[k];
      // The round-0 low bits are re-mixed: the top bits of `hash` are biased small in round 0, by selection.
      const std::uint64_t low = round == 0 ? brio_detail::mix64(hash) & index_mask : grid.key(curve, points.point(i));
      items[i] = {round << index_bits | low, std::uint32_t(i)};
    }
  });
  return layout;
}

inline Brio_key_layout brio_keys(const double* xyz, std::size_t n, std::uint64_t seed, int num_threads,
                                 std::vector<Key_value<std::uint32_t>>& items)
{
  return brio_keys(Packed_points{xyz}, n, seed, num_threads, items);
}

namespace brio_detail {

// Runs of at least this many points in one cell of the grid are sorted again.
constexpr std::size_t shared_cell_min = 32;
constexpr std::size_t shared_cell_budget = 64;

// Points of a round that share one cell of the grid (a cluster far smaller
// than the bounding box, or points whose scales lie far apart, 1e-200 to
// 1e200) would go in the input order, each walk crossing the cell's whole
// triangulation: on 2e4 points of scales 10^-200 to 10^200 a walk took 829
// steps, and most steps an exact predicate.  Each such run of equal keys in
// items[begin, n) is sorted again along the Moore curve of its own bounding
// box, and so on in the runs that this leaves.  A run whose points all get
// one key again (points a few subnormals apart) is left as it is, so every
// run sorted again is smaller than the one it came from.  The points sorted
// again, all levels together, are at most shared_cell_budget times those of
// the rounds: points at 400 decades of scales need about 35 times, while a
// block of repeated points approached by a chain of points at every binary
// scale would be sorted again at each of ~100 levels.  Keys stay as they are;
// the order within a run depends on the points only.
template <class Points>
void sort_shared_cells(const Points& points, std::vector<Key_value<std::uint32_t>>& items, std::size_t begin)
{
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  auto push_runs = [&](std::size_t first, std::size_t last, auto&& key_of) {
    for(std::size_t a = first; a < last;) {
      std::size_t b = a + 1;
      while(b < last && key_of(b) == key_of(a))
        ++b;
      if(b - a >= shared_cell_min) runs.emplace_back(a, b);
      a = b;
    }
  };
  push_runs(begin, items.size(), [&](std::size_t k) { return items[k].key; });
  if(runs.empty()) return;
  std::size_t budget = shared_cell_budget * (items.size() - begin);
  const int bits = Moore_curve::max_bits_per_axis;
  const Moore_curve curve(bits);
  std::vector<std::pair<std::uint64_t, std::uint32_t>> cell;
  while(!runs.empty()) {
    const std::size_t a = runs.back().first, b = runs.back().second;
    runs.pop_back();
    if(b - a > budget) continue;
    budget -= b - a;
    double lo[3], hi[3];
    for(int axis = 0; axis < 3; ++axis)
      lo[axis] = hi[axis] = points.point(items[a].value)[axis];
    for(std::size_t k = a; k < b; ++k)
      for(int axis = 0; axis < 3; ++axis) {
        lo[axis] = std::min(lo[axis], points.point(items[k].value)[axis]);
        hi[axis] = std::max(hi[axis], points.point(items[k].value)[axis]);
      }
    if(lo[0] == hi[0] && lo[1] == hi[1] && lo[2] == hi[2]) continue; // one point, repeated
    const Moore_grid grid(lo, hi, bits);
    cell.resize(b - a);
    for(std::size_t k = a; k < b; ++k)
      cell[k - a] = {grid.key(curve, points.point(items[k].value)), items[k].value};
    std::sort(cell.begin(), cell.end());
    if(cell.front().first == cell.back().first) continue;
    for(std::size_t k = a; k < b; ++k)
      items[k].value = cell[k - a].second;
    const std::size_t before = runs.size();
    push_runs(0, b - a, [&](std::size_t k) { return cell[k].first; });
    for(std::size_t r = before; r < runs.size(); ++r) {
      runs[r].first += a;
      runs[r].second += a;
    }
  }
}

} // namespace brio_detail

struct Brio_order
{
  std::vector<std::uint32_t> order;      // permutation of [0, n): insertion order
  std::vector<std::size_t> round_end;    // cumulative end of each round in `order`; never empty, back() == n
  Bounding_box box{};                    // the points' bounding box (n >= 1)
};

// Buffers reused across calls. After brio_order, items[k] = (key, order[k]) for every k: for k >= round_end[0],
// key & ((1 << 3 * layout.bits_per_axis) - 1) is the Moore index of point order[k] on the default grid of the
// points' bounding box, and key >> (3 * layout.bits_per_axis) is the round of every k.
struct Brio_workspace
{
  std::vector<Key_value<std::uint32_t>> items;
  std::vector<Key_value<std::uint32_t>> scratch;
  Brio_key_layout layout;
};

// The n points of a point source, all finite; the same seed gives the same order for any num_threads.
template <class Points, class = enable_if_point_source<Points>>
void brio_order(const Points& points, std::size_t n, std::uint64_t seed, int num_threads, Brio_workspace& workspace,
                Brio_order& result)
{
  workspace.layout = brio_keys(points, n, seed, num_threads, workspace.items);
  radix_sort(workspace.items, workspace.scratch, workspace.layout.key_bits, num_threads);

  std::vector<Key_value<std::uint32_t>>& items = workspace.items;
  const int index_bits = workspace.layout.index_bits;
  result.round_end.resize(workspace.layout.rounds);
  for(std::size_t r = 0; r < workspace.layout.rounds; ++r)
    result.round_end[r] = std::size_t(
      std::partition_point(items.begin(), items.end(),
                           [&](const Key_value<std::uint32_t>& item) { return (item.key >> index_bits) <= r; }) -
      items.begin());
  brio_detail::sort_shared_cells(points, items, result.round_end[0]);

  result.order.resize(n);
  const int chunks = chunk_count(n, num_threads);
  for_each_chunk(chunks, [&](int c) {
    const std::size_t end = chunk_begin(n, chunks, c + 1);
    for(std::size_t k = chunk_begin(n, chunks, c); k < end; ++k)
      result.order[k] = items[k].value;
  });
  result.box = workspace.layout.box;
}

// xyz holds n finite points as x0 y0 z0 x1 ...
inline void brio_order(const double* xyz, std::size_t n, std::uint64_t seed, int num_threads,
                       Brio_workspace& workspace, Brio_order& result)
{
  brio_order(Packed_points{xyz}, n, seed, num_threads, workspace, result);
}

template <class Points, class = enable_if_point_source<Points>>
Brio_order brio_order(const Points& points, std::size_t n, std::uint64_t seed = 0, int num_threads = 1)
{
  Brio_workspace workspace;
  Brio_order result;
  brio_order(points, n, seed, num_threads, workspace, result);
  return result;
}

inline Brio_order brio_order(const double* xyz, std::size_t n, std::uint64_t seed = 0, int num_threads = 1)
{
  return brio_order(Packed_points{xyz}, n, seed, num_threads);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_INTERNAL_BRIO_H
