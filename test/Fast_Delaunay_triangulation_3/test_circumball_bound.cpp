// The bound of a circumscribed ball that the distributed triangulation sends to other ranks
// (internal/distributed/Circumball_bound.h) must contain the true closed ball: a point of the ball left outside
// would be a ghost never asked for, and a wrong cell. Checked with exact rationals on well-shaped, nearly flat and
// far-off tetrahedra, which take the three paths (doubles with an error bound, intervals, rationals).

#include <CGAL/Exact_rational.h>
#include <CGAL/FPU.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/distributed/Circumball_bound.h>

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace test_circumball_bound {

using CGAL::Exact_rational;
namespace distributed = CGAL::Fast_Delaunay_triangulation_3_internal::distributed;

// Whether ball(c, r) surely contains the exact circumball of p: r >= |c - z| + R, with the exact centre z and
// radius R, decided with upper bounds of the two square roots (so "true" is never wrong).
bool contains_exact_circumball(const distributed::Ball_bound& ball, const double* const p[4])
{
  CGAL::Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
  Exact_rational offset[3], den;
  distributed::circumcenter_offset(p, offset, den);
  Exact_rational distance2 = 0, radius2 = 0;
  for(int k = 0; k < 3; ++k) {
    const Exact_rational z = Exact_rational(p[0][k]) + offset[k] / den;
    distance2 += (z - Exact_rational(ball.center[k])) * (z - Exact_rational(ball.center[k]));
    radius2 += (offset[k] / den) * (offset[k] / den);
  }
  const double distance_up = std::nextafter(std::sqrt(CGAL::to_interval(distance2).second), HUGE_VAL);
  const double radius_up = std::nextafter(std::sqrt(CGAL::to_interval(radius2).second), HUGE_VAL);
  return distance_up + radius_up <= ball.radius;
}

struct Tetrahedron
{
  double p[4][3];
};

Tetrahedron random_tetrahedron(std::mt19937_64& rng, double offset, double flatness)
{
  std::uniform_real_distribution<double> u(0, 1);
  Tetrahedron t;
  for(int v = 0; v < 3; ++v)
    for(int k = 0; k < 3; ++k) t.p[v][k] = offset + u(rng);
  // The fourth corner near the plane z = 0 of the first three when they are flattened too.
  for(int k = 0; k < 3; ++k) t.p[3][k] = offset + u(rng);
  if(flatness > 0) {
    for(int v = 0; v < 3; ++v) t.p[v][2] = offset;
    t.p[3][2] = offset + flatness * (u(rng) + 0.5);
  }
  return t;
}

void expect_bounds_hold(double offset, double flatness)
{
  std::mt19937_64 rng(17);
  CGAL::Protect_FPU_rounding<true> upward;
  for(int trial = 0; trial < 2000; ++trial) {
    const Tetrahedron t = random_tetrahedron(rng, offset, flatness);
    const double* const corners[4] = {t.p[0], t.p[1], t.p[2], t.p[3]};
    const distributed::Ball_bound ball = distributed::circumball_bound(corners);
    ASSERT_TRUE(contains_exact_circumball(ball, corners))
        << "offset " << offset << ", flatness " << flatness << ", trial " << trial;
  }
}

TEST(CircumballBound, WellShapedTetrahedra) { expect_bounds_hold(0, 0); }
TEST(CircumballBound, NearlyFlatTetrahedra)
{
  expect_bounds_hold(0, 1e-6);
  expect_bounds_hold(0, 1e-13);
}
TEST(CircumballBound, FarFromTheOrigin)
{
  expect_bounds_hold(1e9, 0);
  expect_bounds_hold(1e6, 1e-9);
}

// The fast path's claim checked on its own: when it answers, its ball holds the exact one.
TEST(CircumballBound, FastPathHoldsWhereItAnswers)
{
  std::mt19937_64 rng(5);
  int answered = 0;
  for(int trial = 0; trial < 4000; ++trial) {
    const Tetrahedron t = random_tetrahedron(rng, trial % 2 ? 1e5 : 0, trial % 3 ? 0 : 1e-7);
    const double* const corners[4] = {t.p[0], t.p[1], t.p[2], t.p[3]};
    distributed::Ball_bound ball;
    if(!distributed::fast_circumball_bound(corners, ball)) continue;
    ++answered;
    ASSERT_TRUE(contains_exact_circumball(ball, corners)) << "trial " << trial;
  }
  EXPECT_GT(answered, 1000);
}

} // namespace test_circumball_bound
