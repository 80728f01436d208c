// Moore curve and grid map (paper §2.3, §3.3): the curve is checked against its definition (a closed walk through
// face-adjacent cells visiting every cell once, nested across resolutions), the grid map against its specification.

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Moore_curve.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

using namespace CGAL::Fast_Delaunay_triangulation_3_internal;

namespace test_moore_curve {

struct Cell
{
  std::uint32_t x, y, z;
};

bool face_adjacent(const Cell& a, const Cell& b)
{
  const auto d = [](std::uint32_t u, std::uint32_t v) { return u > v ? u - v : v - u; };
  return d(a.x, b.x) + d(a.y, b.y) + d(a.z, b.z) == 1;
}

// The cell visited at each index, or an empty vector when two cells share an index or an index is out of range.
std::vector<Cell> cells_in_curve_order(const Moore_curve& curve)
{
  const std::uint32_t side = std::uint32_t(1) << curve.bits_per_axis();
  const std::size_t total = std::size_t(side) * side * side;
  std::vector<Cell> at(total);
  std::vector<bool> used(total, false);
  for(std::uint32_t x = 0; x < side; ++x)
    for(std::uint32_t y = 0; y < side; ++y)
      for(std::uint32_t z = 0; z < side; ++z) {
        const std::uint64_t i = curve.index(x, y, z);
        if(i >= total || used[i])
          return {};
        used[i] = true;
        at[i] = {x, y, z};
      }
  return at;
}

TEST(MooreCurve, BijectionOntoAllIndices)
{
  for(int b = 1; b <= 6; ++b) {
    const std::vector<Cell> at = cells_in_curve_order(Moore_curve(b));
    EXPECT_EQ(at.size(), std::size_t(1) << (3 * b)) << "b = " << b;
  }
}

TEST(MooreCurve, ConsecutiveCellsAreFaceAdjacent)
{
  for(int b = 1; b <= 6; ++b) {
    const std::vector<Cell> at = cells_in_curve_order(Moore_curve(b));
    ASSERT_FALSE(at.empty());
    for(std::size_t i = 0; i + 1 < at.size(); ++i)
      ASSERT_TRUE(face_adjacent(at[i], at[i + 1])) << "b = " << b << ", index " << i;
  }
}

TEST(MooreCurve, IsClosed)
{
  for(int b = 1; b <= 6; ++b) {
    const std::vector<Cell> at = cells_in_curve_order(Moore_curve(b));
    ASSERT_FALSE(at.empty());
    EXPECT_TRUE(face_adjacent(at.back(), at.front())) << "b = " << b;
  }
}

// Every aligned block of 2^k cells per axis is one run of 8^k consecutive indices: the locality the partitions rely
// on at every scale, and the reason a coarser curve is a prefix of a finer one.
TEST(MooreCurve, AlignedBlocksAreContiguousRuns)
{
  const int b = 5;
  const Moore_curve curve(b);
  const std::vector<Cell> at = cells_in_curve_order(curve);
  ASSERT_FALSE(at.empty());
  for(int k = 1; k < b; ++k) {
    const std::size_t run = std::size_t(1) << (3 * k);
    for(std::size_t start = 0; start < at.size(); start += run)
      for(std::size_t i = start; i < start + run; ++i) {
        ASSERT_EQ(at[i].x >> k, at[start].x >> k) << "k = " << k << ", index " << i;
        ASSERT_EQ(at[i].y >> k, at[start].y >> k);
        ASSERT_EQ(at[i].z >> k, at[start].z >> k);
      }
  }
}

TEST(MooreCurve, CoarserResolutionIsPrefixOfFiner)
{
  std::mt19937_64 random(7);
  for(int fine = 2; fine <= Moore_curve::max_bits_per_axis; ++fine)
    for(int coarse = 1; coarse < fine; ++coarse) {
      const Moore_curve f(fine), c(coarse);
      for(int trial = 0; trial < 50; ++trial) {
        const std::uint32_t mask = (std::uint32_t(1) << fine) - 1;
        const std::uint32_t x = std::uint32_t(random()) & mask, y = std::uint32_t(random()) & mask,
                            z = std::uint32_t(random()) & mask;
        const int drop = fine - coarse;
        ASSERT_EQ(f.index(x, y, z) >> (3 * drop), c.index(x >> drop, y >> drop, z >> drop))
          << "fine " << fine << ", coarse " << coarse;
      }
    }
}

// The cell holding index `wanted(level)` at each level, found by descending into the one child that holds it
// there. Returns false when no child does, i.e. when the curve is not nested.
template <class Wanted>
bool descend_to(int b, const Wanted& wanted, Cell& cell)
{
  cell = {0, 0, 0};
  for(int level = 1; level <= b; ++level) {
    const Moore_curve curve(level);
    bool found = false;
    Cell next{};
    for(std::uint32_t child = 0; child < 8; ++child) {
      const Cell c{2 * cell.x + (child & 1u), 2 * cell.y + (child >> 1 & 1u), 2 * cell.z + (child >> 2 & 1u)};
      if(curve.index(c.x, c.y, c.z) == wanted(level)) {
        next = c;
        found = true;
      }
    }
    if(!found)
      return false;
    cell = next;
  }
  return true;
}

TEST(MooreCurve, FinestResolutionExtremes)
{
  const Moore_curve curve(21);
  const std::uint32_t top = (std::uint32_t(1) << 21) - 1;
  const std::uint64_t last_index = (std::uint64_t(1) << 63) - 1;
  std::vector<std::uint64_t> seen;
  for(std::uint32_t x : {0u, 1u, top - 1, top})
    for(std::uint32_t y : {0u, 1u, top - 1, top})
      for(std::uint32_t z : {0u, 1u, top - 1, top}) {
        const std::uint64_t i = curve.index(x, y, z);
        EXPECT_LE(i, last_index);
        seen.push_back(i);
      }
  std::sort(seen.begin(), seen.end());
  EXPECT_TRUE(std::adjacent_find(seen.begin(), seen.end()) == seen.end()) << "two corner cells share an index";

  // The loop closes at 21 bits too, where the index uses 63 bits.
  Cell first{}, last{};
  ASSERT_TRUE(descend_to(21, [](int) { return std::uint64_t(0); }, first));
  ASSERT_TRUE(descend_to(21, [](int level) { return (std::uint64_t(1) << (3 * level)) - 1; }, last));
  EXPECT_EQ(curve.index(first.x, first.y, first.z), 0u);
  EXPECT_EQ(curve.index(last.x, last.y, last.z), last_index);
  EXPECT_TRUE(face_adjacent(first, last));
}

TEST(MooreBitsPerAxis, MonotoneAndClamped)
{
  int previous = moore_bits_per_axis(0);
  EXPECT_GE(previous, 1);
  for(std::size_t n = 1; n < (std::size_t(1) << 62); n = n * 3 / 2 + 1) {
    const int b = moore_bits_per_axis(n);
    EXPECT_GE(b, previous) << "n = " << n;
    EXPECT_GE(b, 1);
    EXPECT_LE(b, 21);
    previous = b;
  }
  EXPECT_EQ(moore_bits_per_axis(std::numeric_limits<std::size_t>::max()), 21);
  // ceil(log2(n) / 3) + 2
  EXPECT_EQ(moore_bits_per_axis(8), 3);
  EXPECT_EQ(moore_bits_per_axis(9), 4);
  EXPECT_EQ(moore_bits_per_axis(1000000), 9);
  EXPECT_EQ(moore_bits_per_axis(10000000), 10);
}

TEST(MooreGrid, CornersAndCentreOfTheUnitCube)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  for(int b : {1, 5, 21}) {
    const Moore_grid grid(lo, hi, b);
    const std::uint32_t top = (std::uint32_t(1) << b) - 1;
    for(int a = 0; a < 3; ++a) {
      EXPECT_EQ(grid.cell(a, 0.0), 0u);
      EXPECT_EQ(grid.cell(a, 1.0), top);
      EXPECT_EQ(grid.cell(a, 0.5), std::uint32_t(1) << (b - 1));
      EXPECT_EQ(grid.cell(a, 0.5 - 1e-9), (std::uint32_t(1) << (b - 1)) - 1);
    }
  }
}

TEST(MooreGrid, ClampsOutOfBoxHugeInfiniteAndNaN)
{
  const double lo[3] = {-1, 2, 3}, hi[3] = {1, 4, 5};
  const int b = 10;
  const Moore_grid grid(lo, hi, b);
  const std::uint32_t top = (std::uint32_t(1) << b) - 1;
  const double inf = std::numeric_limits<double>::infinity();
  const double big = std::numeric_limits<double>::max();
  for(int a = 0; a < 3; ++a) {
    EXPECT_EQ(grid.cell(a, -1e300), 0u);
    EXPECT_EQ(grid.cell(a, -big), 0u);
    EXPECT_EQ(grid.cell(a, -inf), 0u);
    EXPECT_EQ(grid.cell(a, lo[a] - 1e-3), 0u);
    EXPECT_EQ(grid.cell(a, 1e300), top);
    EXPECT_EQ(grid.cell(a, big), top);
    EXPECT_EQ(grid.cell(a, inf), top);
    EXPECT_EQ(grid.cell(a, hi[a] + 1e-3), top);
    EXPECT_LE(grid.cell(a, std::numeric_limits<double>::quiet_NaN()), top);
  }
  const double p[3] = {std::nan(""), -inf, 1e308};
  EXPECT_LT(grid.key(Moore_curve(b), p), std::uint64_t(1) << (3 * b));
}

TEST(MooreGrid, HugeBoxDoesNotOverflow)
{
  const double big = std::numeric_limits<double>::max();
  const double lo[3] = {-big, -big, -big}, hi[3] = {big, big, big};
  const Moore_grid grid(lo, hi, 8);
  for(int a = 0; a < 3; ++a) {
    EXPECT_EQ(grid.cell(a, -big), 0u);
    EXPECT_EQ(grid.cell(a, big), 255u);
    EXPECT_EQ(grid.cell(a, 0.0), 128u);
    EXPECT_EQ(grid.cell(a, big / 2), 192u);
  }
}

TEST(MooreGrid, FlatAndThinAxesAreWidened)
{
  // x spans 100, y spans 1, z is flat: y and z get the width 100 / 1.5, centred on the input.
  const double lo[3] = {0, 0, 7}, hi[3] = {100, 1, 7};
  const int b = 12;
  const Moore_grid grid(lo, hi, b);
  const std::uint32_t half = std::uint32_t(1) << (b - 1);
  EXPECT_EQ(grid.cell(0, 0.0), 0u);
  EXPECT_EQ(grid.cell(0, 100.0), 2 * half - 1);
  EXPECT_EQ(grid.cell(2, 7.0), half);
  EXPECT_EQ(grid.cell(1, 0.5), half);
  // Cells along y are 1.5 times the x cell width: y = 0 and y = 1 are about 4096 / 66.7 = 61 cells apart.
  const double spread = double(grid.cell(1, 1.0)) - double(grid.cell(1, 0.0));
  EXPECT_NEAR(spread, 2 * half / (100 / 1.5), 1.0);
  // A point slightly off the flat plane stays next to the centre instead of jumping to an end of the grid.
  EXPECT_NEAR(double(grid.cell(2, 7.0 + 1.0)), double(half) + 2 * half / (100 / 1.5), 1.0);
  EXPECT_NEAR(double(grid.cell(2, 7.0 - 1.0)), double(half) - 2 * half / (100 / 1.5), 1.0);
}

TEST(MooreGrid, SinglePointBox)
{
  const double lo[3] = {3, 3, 3}, hi[3] = {3, 3, 3};
  const Moore_grid grid(lo, hi, 6);
  for(int a = 0; a < 3; ++a) {
    EXPECT_EQ(grid.cell(a, 3.0), 32u);
    EXPECT_EQ(grid.cell(a, 4.0), 63u);
    EXPECT_EQ(grid.cell(a, 2.0), 0u);
  }
}

TEST(MooreGrid, SplitMapsEachSideOntoHalfTheGrid)
{
  const double lo[3] = {0, 0, 0}, hi[3] = {1, 1, 1};
  const double split[3] = {0.1, 0.9, 0.5};
  const int b = 16;
  const Moore_grid grid(lo, hi, b, split);
  const double half = double(std::uint32_t(1) << (b - 1));
  // Below the split: [0, s] onto [0, half); above: [s, 1] onto [half, 2 half).
  for(int a = 0; a < 3; ++a) {
    const double s = split[a];
    EXPECT_LT(grid.cell(a, s - 1e-9), std::uint32_t(half)) << "axis " << a;
    EXPECT_GE(grid.cell(a, s + 1e-9), std::uint32_t(half)) << "axis " << a;
    EXPECT_NEAR(double(grid.cell(a, s / 2)), half / 2, 1.0) << "axis " << a;
    EXPECT_NEAR(double(grid.cell(a, s + (1 - s) / 2)), 1.5 * half, 1.0) << "axis " << a;
    EXPECT_EQ(grid.cell(a, 0.0), 0u);
    EXPECT_EQ(grid.cell(a, 1.0), std::uint32_t(2 * half - 1));
    std::uint32_t previous = 0;
    for(int k = 0; k <= 1000; ++k) {
      const std::uint32_t c = grid.cell(a, k / 1000.0);
      ASSERT_GE(c, previous) << "the map must be monotone, axis " << a << ", k " << k;
      previous = c;
    }
  }
}

// The partitioned insertion reads its coarse keys off BRIO's order (Parallel_insertion.h, sorted runs): the cell of
// a point at b bits must be its cell at any finer resolution shifted right, on the same box, for points inside,
// on the faces of and outside the box.
TEST(MooreGrid, CoarserCellIsPrefixOfFiner)
{
  std::mt19937_64 random(11);
  std::uniform_real_distribution<double> unit(-0.1, 1.1);
  for(int trial = 0; trial < 20; ++trial) {
    double lo[3], hi[3];
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::ldexp(unit(random) - 0.5, int(random() % 40) - 20);
      hi[a] = lo[a] + std::ldexp(unit(random) + 0.2, int(random() % 40) - 20);
    }
    for(int fine = 2; fine <= Moore_curve::max_bits_per_axis; ++fine) {
      const int coarse = 1 + int(random() % std::uint64_t(fine - 1));
      const Moore_grid f(lo, hi, fine), c(lo, hi, coarse);
      for(int k = 0; k < 200; ++k) {
        const int axis = int(random() % 3);
        const double t = k < 3 ? double(k) / 2 : unit(random);
        const double x = lo[axis] + t * (hi[axis] - lo[axis]);
        ASSERT_EQ(f.cell(axis, x) >> (fine - coarse), c.cell(axis, x))
          << "fine " << fine << ", coarse " << coarse << ", axis " << axis << ", t " << t;
      }
    }
  }
}

} // namespace test_moore_curve
