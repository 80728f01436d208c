// BRIO insertion order (paper §2.3): a permutation, in rounds of the specified geometric sizes, reproducible from its
// seed and thread-count independent, each later round following the Moore curve (checked against keys recomputed
// from Moore_grid and by the geometric locality of consecutive points), the first round in random order.

#include <CGAL/Fast_Delaunay_triangulation_3/internal/BRIO.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

using namespace CGAL::Fast_Delaunay_triangulation_3_internal;

namespace test_brio {

std::vector<double> uniform_points(std::size_t n, std::uint64_t seed, double scale = 1.0, double offset = 0.0)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> coordinate(0.0, 1.0);
  std::vector<double> xyz(3 * n);
  for(double& c : xyz)
    c = offset + scale * coordinate(random);
  return xyz;
}

::testing::AssertionResult is_permutation_of_indices(const std::vector<std::uint32_t>& order, std::size_t n)
{
  if(order.size() != n)
    return ::testing::AssertionFailure() << "size " << order.size() << " instead of " << n;
  std::vector<bool> seen(n, false);
  for(std::size_t k = 0; k < n; ++k) {
    if(order[k] >= n || seen[order[k]])
      return ::testing::AssertionFailure() << "position " << k << " holds " << order[k];
    seen[order[k]] = true;
  }
  return ::testing::AssertionSuccess();
}

// The round boundaries as specified: n divided by 7.5 while the round would exceed 2048 points.
std::vector<double> specified_round_ends(std::size_t n)
{
  std::vector<double> ends{double(n)};
  double end = double(n);
  while(end > 2048) {
    end = std::floor(end / 7.5);
    ends.insert(ends.begin(), end);
  }
  return ends;
}

std::vector<std::uint64_t> moore_keys_of(const std::vector<double>& xyz)
{
  const std::size_t n = xyz.size() / 3;
  if(n == 0)
    return {};
  double lo[3] = {xyz[0], xyz[1], xyz[2]}, hi[3] = {xyz[0], xyz[1], xyz[2]};
  for(std::size_t i = 0; i < n; ++i)
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], xyz[3 * i + a]);
      hi[a] = std::max(hi[a], xyz[3 * i + a]);
    }
  const int bits = brio_bits_per_axis(n);
  const Moore_grid grid(lo, hi, bits);
  const Moore_curve curve(bits);
  std::vector<std::uint64_t> keys(n);
  for(std::size_t i = 0; i < n; ++i)
    keys[i] = grid.key(curve, &xyz[3 * i]);
  return keys;
}

::testing::AssertionResult rounds_follow_moore_curve(const std::vector<double>& xyz, const Brio_order& brio)
{
  const std::vector<std::uint64_t> keys = moore_keys_of(xyz);
  for(std::size_t r = 1; r < brio.round_end.size(); ++r)
    for(std::size_t k = brio.round_end[r - 1] + 1; k < brio.round_end[r]; ++k)
      if(keys[brio.order[k - 1]] > keys[brio.order[k]])
        return ::testing::AssertionFailure() << "round " << r << ", position " << k << ": Moore key "
                                             << keys[brio.order[k]] << " after " << keys[brio.order[k - 1]];
  return ::testing::AssertionSuccess();
}

double distance(const std::vector<double>& xyz, std::uint32_t i, std::uint32_t j)
{
  const double dx = xyz[3 * i] - xyz[3 * j], dy = xyz[3 * i + 1] - xyz[3 * j + 1], dz = xyz[3 * i + 2] - xyz[3 * j + 2];
  return std::sqrt(dx * dx + dy * dy + dz * dz);
}

double mean_step(const std::vector<double>& xyz, const std::vector<std::uint32_t>& order, std::size_t begin,
                 std::size_t end)
{
  double sum = 0;
  for(std::size_t k = begin + 1; k < end; ++k)
    sum += distance(xyz, order[k - 1], order[k]);
  return sum / double(end - begin - 1);
}

TEST(Brio, IsPermutationWithConsistentRounds)
{
  for(std::size_t n : {0u, 1u, 2u, 3u, 10u, 1000u, 2048u, 2049u, 5000u, 100000u}) {
    const std::vector<double> xyz = uniform_points(n, n);
    const Brio_order brio = brio_order(xyz.data(), n, 42);
    ASSERT_TRUE(is_permutation_of_indices(brio.order, n)) << "n " << n;
    const std::vector<double> specified = specified_round_ends(n);
    ASSERT_EQ(brio.round_end.size(), specified.size()) << "n " << n;
    ASSERT_TRUE(std::is_sorted(brio.round_end.begin(), brio.round_end.end())) << "n " << n;
    EXPECT_EQ(brio.round_end.back(), n);
    EXPECT_TRUE(rounds_follow_moore_curve(xyz, brio)) << "n " << n;
  }
}

TEST(Brio, SmallInputIsOneRandomRound)
{
  const std::size_t n = 2000;
  const std::vector<double> xyz = uniform_points(n, 5);
  const Brio_order brio = brio_order(xyz.data(), n, 1);
  ASSERT_EQ(brio.round_end, std::vector<std::size_t>{n});
  // Neither the input order nor its reverse: about half of the consecutive pairs ascend.
  std::size_t ascending = 0;
  for(std::size_t k = 1; k < n; ++k)
    ascending += brio.order[k] > brio.order[k - 1];
  EXPECT_GT(ascending, n * 2 / 5);
  EXPECT_LT(ascending, n * 3 / 5);
}

TEST(Brio, SameSeedSameOrderOtherSeedOtherOrder)
{
  const std::size_t n = 50000;
  const std::vector<double> xyz = uniform_points(n, 3);
  const Brio_order a = brio_order(xyz.data(), n, 9);
  const Brio_order b = brio_order(xyz.data(), n, 9);
  const Brio_order c = brio_order(xyz.data(), n, 10);
  EXPECT_EQ(a.order, b.order);
  EXPECT_EQ(a.round_end, b.round_end);
  EXPECT_NE(a.order, c.order);
  // A different seed draws other points into the first round, not just a different order of the same ones.
  std::vector<std::uint32_t> first_a(a.order.begin(), a.order.begin() + std::ptrdiff_t(a.round_end[0]));
  std::vector<std::uint32_t> first_c(c.order.begin(), c.order.begin() + std::ptrdiff_t(c.round_end[0]));
  std::sort(first_a.begin(), first_a.end());
  std::sort(first_c.begin(), first_c.end());
  EXPECT_NE(first_a, first_c);
}

TEST(Brio, ThreadCountDoesNotChangeTheOrder)
{
  const std::size_t n = 200000;
  const std::vector<double> xyz = uniform_points(n, 8);
  const Brio_order one = brio_order(xyz.data(), n, 5, 1);
  for(int threads : {2, 3}) {
    const Brio_order other = brio_order(xyz.data(), n, 5, threads);
    EXPECT_EQ(one.order, other.order) << "threads " << threads;
    EXPECT_EQ(one.round_end, other.round_end) << "threads " << threads;
  }
}

// 1e6 points: the rounds 316 | 2054 | 15407 | 115556 | 866667 of the specification, each within 6 standard
// deviations of its binomial draw.
TEST(Brio, RoundSizesGrowGeometrically)
{
  const std::size_t n = 1000000;
  const std::vector<double> xyz = uniform_points(n, 1);
  const Brio_order brio = brio_order(xyz.data(), n, 123, 2);
  const double expected[] = {316, 2054, 15407, 115556, 866667};
  ASSERT_EQ(brio.round_end.size(), 5u);
  std::size_t begin = 0;
  for(std::size_t r = 0; r < 5; ++r) {
    const double size = double(brio.round_end[r] - begin);
    const double p = expected[r] / double(n);
    const double sigma = std::sqrt(double(n) * p * (1 - p));
    EXPECT_NEAR(size, expected[r], 6 * sigma) << "round " << r;
    begin = brio.round_end[r];
  }
  EXPECT_TRUE(rounds_follow_moore_curve(xyz, brio));
}

// Independent of how keys are computed: consecutive points of a sorted round are near each other, those of the
// random first round are as far apart as random pairs (mean distance in the unit cube ~0.66).
TEST(Brio, SortedRoundsAreLocalFirstRoundIsNot)
{
  const std::size_t n = 100000;
  const std::vector<double> xyz = uniform_points(n, 21);
  const Brio_order brio = brio_order(xyz.data(), n, 77);
  const std::size_t rounds = brio.round_end.size();
  ASSERT_GE(rounds, 3u);
  const double first = mean_step(xyz, brio.order, 0, brio.round_end[0]);
  const double last = mean_step(xyz, brio.order, brio.round_end[rounds - 2], n);
  EXPECT_GT(first, 0.5);
  // A curve through 87,000 uniform points steps about (1 / 87000)^(1/3) ~ 0.023 on average.
  EXPECT_LT(last, 0.05);
}

TEST(Brio, WorkspaceExposesMooreKeysAndRounds)
{
  const std::size_t n = 30000;
  const std::vector<double> xyz = uniform_points(n, 4, 10.0, -3.0);
  Brio_workspace workspace;
  Brio_order brio;
  for(std::uint64_t seed : {1u, 2u}) {   // the second call reuses the buffers
    brio_order(xyz.data(), n, seed, 2, workspace, brio);
    ASSERT_TRUE(is_permutation_of_indices(brio.order, n));
    const std::vector<std::uint64_t> keys = moore_keys_of(xyz);
    const int index_bits = 3 * workspace.layout.bits_per_axis;
    ASSERT_EQ(workspace.items.size(), n);
    std::size_t round = 0;
    for(std::size_t k = 0; k < n; ++k) {
      while(k >= brio.round_end[round])
        ++round;
      ASSERT_EQ(workspace.items[k].value, brio.order[k]);
      ASSERT_EQ(workspace.items[k].key >> index_bits, round) << "position " << k;
      if(round > 0) {
        ASSERT_EQ(workspace.items[k].key & ((std::uint64_t(1) << index_bits) - 1), keys[brio.order[k]]);
      }
    }
  }
}

TEST(Brio, DegenerateInputs)
{
  const std::size_t n = 20000;
  std::vector<std::vector<double>> inputs;
  inputs.push_back(std::vector<double>(3 * n, 1.25));                 // one point repeated
  inputs.push_back(uniform_points(n, 2));                             // coplanar: z = 0
  for(std::size_t i = 0; i < n; ++i)
    inputs.back()[3 * i + 2] = 0;
  inputs.push_back(uniform_points(n, 3));                             // collinear along x
  for(std::size_t i = 0; i < n; ++i)
    inputs.back()[3 * i + 1] = inputs.back()[3 * i + 2] = 0.5;
  inputs.push_back(uniform_points(n, 4, 2e300, -1e300));              // near the ends of the double range
  inputs.push_back(uniform_points(n, 5, 1e-300, 1e6));                // tiny extent, large offset (all equal)
  inputs.push_back(std::vector<double>(3 * n, 0.0));                  // two points a subnormal apart, repeated:
  for(std::size_t i = 0; i < n; i += 2)                               // one cell even on their own box
    inputs.back()[3 * i] = 4.9e-324;
  std::vector<double> grid;                                           // integer grid with duplicates
  for(std::size_t i = 0; i < n; ++i)
    for(int a = 0; a < 3; ++a)
      grid.push_back(double((i / (a == 0 ? 1 : a == 1 ? 20 : 400)) % 20));
  inputs.push_back(grid);
  for(std::size_t k = 0; k < inputs.size(); ++k) {
    const Brio_order brio = brio_order(inputs[k].data(), n, 6, 2);
    EXPECT_TRUE(is_permutation_of_indices(brio.order, n)) << "input " << k;
    EXPECT_EQ(brio.round_end.back(), n) << "input " << k;
    EXPECT_TRUE(rounds_follow_moore_curve(inputs[k], brio)) << "input " << k;
  }
}

// Points at scales 10^-200 to 10^200 nearly all share the grid's central
// cell: the runs of equal keys follow the Moore curve of their own bounding
// box, while the keys of the grid still order every round.
TEST(Brio, PointsSharingACellFollowTheCurveOfTheirOwnBox)
{
  const std::size_t n = 20000;
  std::mt19937_64 random(8);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-200, 200);
  std::vector<double> xyz(3 * n);
  for(std::size_t i = 0; i < n; ++i) {
    const double scale = std::pow(10.0, exponent(random));
    for(int a = 0; a < 3; ++a)
      xyz[3 * i + a] = scale * unit(random);
  }
  const Brio_order brio = brio_order(xyz.data(), n, 3, 2);
  ASSERT_TRUE(is_permutation_of_indices(brio.order, n));
  EXPECT_TRUE(rounds_follow_moore_curve(xyz, brio));
  EXPECT_EQ(brio.order, brio_order(xyz.data(), n, 3, 1).order);
  const std::vector<std::uint64_t> keys = moore_keys_of(xyz);
  std::size_t runs = 0;
  for(std::size_t r = 1; r < brio.round_end.size(); ++r)
    for(std::size_t a = brio.round_end[r - 1]; a < brio.round_end[r];) {
      std::size_t b = a + 1;
      while(b < brio.round_end[r] && keys[brio.order[b]] == keys[brio.order[a]])
        ++b;
      if(b - a >= 32) {
        ++runs;
        double lo[3], hi[3];
        for(int c = 0; c < 3; ++c)
          lo[c] = hi[c] = xyz[3 * brio.order[a] + c];
        for(std::size_t k = a; k < b; ++k)
          for(int c = 0; c < 3; ++c) {
            lo[c] = std::min(lo[c], xyz[3 * brio.order[k] + c]);
            hi[c] = std::max(hi[c], xyz[3 * brio.order[k] + c]);
          }
        const Moore_grid grid(lo, hi, Moore_curve::max_bits_per_axis);
        const Moore_curve curve(Moore_curve::max_bits_per_axis);
        for(std::size_t k = a + 1; k < b; ++k)
          ASSERT_LE(grid.key(curve, &xyz[3 * brio.order[k - 1]]), grid.key(curve, &xyz[3 * brio.order[k]]))
              << "round " << r << ", position " << k;
      }
      a = b;
    }
  EXPECT_GT(runs, 0u) << "the input does not test what it should";
}

} // namespace test_brio
