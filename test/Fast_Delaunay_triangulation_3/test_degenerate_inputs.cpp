// Degenerate inputs against CGAL::Delaunay_triangulation_3 on the same
// points: few points, coincident, collinear, coplanar and cospherical sets,
// duplicates, huge offsets, tiny and huge scales.  Below dimension 3 the
// dimension and the vertices must equal CGAL's; in dimension 3 the cells
// must, whatever the insertion order (CGAL's perturbation makes its
// triangulation unique), in bulk, one point at a time or mixed.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_degenerate_inputs {

Fast_dt insert_one_by_one(const std::vector<Point>& points)
{
  Fast_dt tr;
  for(const Point& p : points) {
    const Fast_dt::Vertex_handle v = tr.insert(p);
    EXPECT_TRUE(v->point() == p);
  }
  return tr;
}

bool lexicographically_smaller(const Point& a, const Point& b) { return point_key(a) < point_key(b); }

// The points as given, shuffled twice, sorted and reverse sorted; each order
// inserted in bulk and one point at a time must give CGAL's triangulation.
void expect_same_as_cgal_in_every_order(const std::vector<Point>& points)
{
  const Cgal_dt reference(points.begin(), points.end());
  std::vector<std::pair<std::string, std::vector<Point>>> orders;
  orders.push_back({"given", points});
  for(std::uint64_t seed : {1u, 2u}) {
    std::vector<Point> shuffled = points;
    std::mt19937_64 rng(seed);
    std::shuffle(shuffled.begin(), shuffled.end(), rng);
    orders.push_back({"shuffled " + std::to_string(seed), shuffled});
  }
  std::vector<Point> sorted = points;
  std::sort(sorted.begin(), sorted.end(), lexicographically_smaller);
  orders.push_back({"sorted", sorted});
  std::reverse(sorted.begin(), sorted.end());
  orders.push_back({"reversed", sorted});

  for(const auto& order : orders) {
    SCOPED_TRACE(order.first + " order");
    {
      SCOPED_TRACE("bulk");
      const Fast_dt bulk(order.second.begin(), order.second.end());
      expect_same_as_cgal(bulk, reference);
    }
    {
      SCOPED_TRACE("one by one");
      expect_same_as_cgal(insert_one_by_one(order.second), reference);
    }
  }
}

// One step of a scenario: a batch inserted with insert(first, last) or
// point by point with insert(p).
struct Step
{
  std::vector<Point> points;
  bool one_by_one;
};

// The same insertions into ours and into CGAL's, comparing the return values
// and then the triangulations after every step.
void expect_same_as_cgal_after_each_step(const std::vector<Step>& steps)
{
  Fast_dt fast;
  Cgal_dt cgal;
  for(std::size_t s = 0; s < steps.size(); ++s) {
    SCOPED_TRACE("step " + std::to_string(s));
    const std::vector<Point>& points = steps[s].points;
    if(steps[s].one_by_one) {
      for(const Point& p : points) {
        const Fast_dt::Vertex_handle v = fast.insert(p);
        const Cgal_dt::Vertex_handle w = cgal.insert(p);
        ASSERT_TRUE(v->point() == w->point());
        ASSERT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
        ASSERT_EQ(fast.dimension(), cgal.dimension());
      }
    } else {
      EXPECT_EQ(fast.insert(points.begin(), points.end()), cgal.insert(points.begin(), points.end()));
    }
    expect_same_as_cgal(fast, cgal);
  }
}

std::vector<Point> scaled(std::vector<Point> points, double factor)
{
  for(Point& p : points) p = Point(p.x() * factor, p.y() * factor, p.z() * factor);
  return points;
}

std::vector<Point> translated(std::vector<Point> points, double offset)
{
  for(Point& p : points) p = Point(p.x() + offset, p.y() + offset, p.z() + offset);
  return points;
}

// Integer points on the surface of the cube [0, k-1]^3.
std::vector<Point> cube_surface(int k)
{
  std::vector<Point> points;
  for(int x = 0; x < k; ++x)
    for(int y = 0; y < k; ++y)
      for(int z = 0; z < k; ++z)
        if(x == 0 || y == 0 || z == 0 || x == k - 1 || y == k - 1 || z == k - 1) points.emplace_back(x, y, z);
  return points;
}

std::vector<Point> cube_corners()
{
  std::vector<Point> points;
  for(int i = 0; i < 8; ++i) points.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  return points;
}

std::vector<Point> octahedron()
{
  return {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0), Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
}

// ---------------------------------------------------------------- few points

TEST(Few_points, ZeroToTenRandomPoints)
{
  for(std::uint64_t seed : {1u, 2u, 3u})
    for(std::size_t n = 0; n <= 10; ++n) {
      SCOPED_TRACE("seed " + std::to_string(seed) + ", " + std::to_string(n) + " points");
      expect_same_as_cgal_in_every_order(to_points<Point>(uniform_points(n, seed)));
    }
}

TEST(Few_points, ZeroToTenCubePoints)
{
  // Cube corners (cospherical, coplanar by fours), then the centre and a face centre.
  std::vector<Point> points = cube_corners();
  points.emplace_back(0.5, 0.5, 0.5);
  points.emplace_back(0.5, 0.5, 0);
  for(std::size_t n = 0; n <= points.size(); ++n) {
    SCOPED_TRACE(std::to_string(n) + " points");
    expect_same_as_cgal_in_every_order(std::vector<Point>(points.begin(), points.begin() + n));
  }
}

// ---------------------------------------------------------------- lower dimensions

TEST(Lower_dimensions, AllPointsCoincide)
{
  for(std::size_t n : {1, 2, 3, 10, 100}) {
    SCOPED_TRACE(std::to_string(n) + " copies");
    const std::vector<Point> points(n, Point(0.1, -2.5, 1e-3));
    expect_same_as_cgal_in_every_order(points);
    const Fast_dt tr(points.begin(), points.end());
    EXPECT_EQ(tr.dimension(), 0);
    EXPECT_EQ(tr.number_of_vertices(), 1u);
  }
}

TEST(Lower_dimensions, CollinearThenCoplanarThenSpatial)
{
  // Exactly collinear integer points a + t d, shuffled.
  std::vector<Point> line;
  for(int t = -10; t <= 10; ++t) line.emplace_back(1 + 3 * t, 2 - t, 3 + 2 * t);
  std::mt19937_64 rng(4);
  std::shuffle(line.begin(), line.end(), rng);
  const std::vector<Point> off_line = {Point(0, 0, 0)};
  const std::vector<Point> off_plane = {Point(5, 5, -7)};

  expect_same_as_cgal_after_each_step({{line, false}, {off_line, false}, {off_plane, false}});
  expect_same_as_cgal_after_each_step({{line, true}, {off_line, true}, {off_plane, true}});
  expect_same_as_cgal_after_each_step({{line, true}, {line, false}, {off_plane, true}, {off_line, false}});

  std::vector<Point> all = line;
  all.insert(all.end(), off_line.begin(), off_line.end());
  all.insert(all.end(), off_plane.begin(), off_plane.end());
  expect_same_as_cgal_in_every_order(all);
  EXPECT_EQ(Fast_dt(line.begin(), line.end()).dimension(), 1);
}

TEST(Lower_dimensions, NearlyCollinearInDoubles)
{
  // a + t (0.1, 0.2, 0.3) rounded to doubles: collinear or not as the
  // roundings fall; CGAL's exact answer decides.
  std::vector<Point> points;
  for(int t = 0; t <= 20; ++t) points.emplace_back(0.7 + t * 0.1, 0.3 + t * 0.2, -0.1 + t * 0.3);
  expect_same_as_cgal_in_every_order(points);
}

TEST(Lower_dimensions, CoplanarGridThenApexes)
{
  // The integer points of the plane z = x + 2y, a grid full of cocircular
  // quadruples; then one apex, then a second one on the other side.
  std::vector<Point> plane;
  for(int u = -4; u <= 4; ++u)
    for(int v = -4; v <= 4; ++v) plane.emplace_back(u, v, u + 2 * v);
  const std::vector<Point> apex = {Point(0, 0, 10)}, other_apex = {Point(1, 1, -10)};
  EXPECT_EQ(Fast_dt(plane.begin(), plane.end()).dimension(), 2);

  expect_same_as_cgal_after_each_step({{plane, false}, {apex, false}, {other_apex, false}});
  expect_same_as_cgal_after_each_step({{plane, true}, {apex, true}, {other_apex, true}});
  std::vector<Point> cone = plane;
  cone.push_back(apex[0]);
  expect_same_as_cgal_in_every_order(cone);
  cone.push_back(other_apex[0]);
  expect_same_as_cgal_in_every_order(cone);
}

TEST(Lower_dimensions, RandomCoplanarPlusOnePoint)
{
  std::vector<Point> points;
  for(const Xyz& q : uniform_points(60, 5)) points.emplace_back(q.x, q.y, 0.25);
  points.emplace_back(0.5, 0.5, 1.0);
  expect_same_as_cgal_in_every_order(points);
  expect_same_as_cgal_after_each_step(
      {{std::vector<Point>(points.begin(), points.end() - 1), false}, {{points.back()}, true}});
}

TEST(Lower_dimensions, CocircularInATiltedPlaneThenPoles)
{
  // The circle and both poles (+-5 n, at distance 15) lie on one sphere
  // around the origin; the origin is its centre.
  const std::vector<Point> circle = to_points<Point>(tilted_circle_points());
  ASSERT_EQ(circle.size(), 12u);
  EXPECT_EQ(Fast_dt(circle.begin(), circle.end()).dimension(), 2);
  const std::vector<Point> poles = {Point(10, -10, 5), Point(-10, 10, -5)};
  const std::vector<Point> centre = {Point(0, 0, 0)};
  expect_same_as_cgal_after_each_step({{circle, false}, {{poles[0]}, true}, {{poles[1]}, true}, {centre, false}});
  expect_same_as_cgal_after_each_step({{circle, true}, {poles, false}, {centre, true}});
  std::vector<Point> all = circle;
  all.insert(all.end(), poles.begin(), poles.end());
  expect_same_as_cgal_in_every_order(all);
  all.push_back(centre[0]);
  expect_same_as_cgal_in_every_order(all);
}

// ---------------------------------------------------------------- cospherical

TEST(Cospherical, Octahedron)
{
  expect_same_as_cgal_in_every_order(octahedron());
  std::vector<Point> with_centre = octahedron();
  with_centre.emplace_back(0, 0, 0);
  expect_same_as_cgal_in_every_order(with_centre);
}

TEST(Cospherical, CubeCorners)
{
  expect_same_as_cgal_in_every_order(cube_corners());
  expect_same_as_cgal_in_every_order(translated(scaled(cube_corners(), 3), -1.5));
}

TEST(Cospherical, IntegerPointsOnSpheres)
{
  for(int r2 : {25, 101, 125}) {
    SCOPED_TRACE("x^2 + y^2 + z^2 = " + std::to_string(r2));
    std::vector<Point> points = to_points<Point>(integer_sphere_points(r2));
    ASSERT_GT(points.size(), 20u);
    expect_same_as_cgal_in_every_order(points);
    points.emplace_back(0, 0, 0);
    expect_same_as_cgal_in_every_order(points);
  }
}

TEST(Cospherical, CubeSurfaceLatticeAndCentre)
{
  std::vector<Point> points = cube_surface(5);
  points.emplace_back(2, 2, 2);
  expect_same_as_cgal_in_every_order(points);
  expect_same_as_cgal_in_every_order(cube_surface(4));
}

// ---------------------------------------------------------------- duplicates

TEST(Duplicates, InterleavedWithNewPoints)
{
  // Every new point is followed by a repeat of an earlier one; the grid
  // part repeats points while the triangulation is still planar.
  std::vector<Point> fresh;
  for(int x = 0; x < 3; ++x)
    for(int y = 0; y < 3; ++y) fresh.emplace_back(x, y, 0);
  const std::vector<Point> uniform = to_points<Point>(uniform_points(60, 6));
  fresh.insert(fresh.end(), uniform.begin(), uniform.end());
  std::mt19937_64 rng(7);
  std::vector<Point> points;
  for(std::size_t i = 0; i < fresh.size(); ++i) {
    points.push_back(fresh[i]);
    points.push_back(fresh[std::uniform_int_distribution<std::size_t>(0, i)(rng)]);
  }
  expect_same_as_cgal_in_every_order(points);
  const Fast_dt tr(points.begin(), points.end());
  EXPECT_EQ(tr.number_of_vertices(), distinct_point_keys(points).size());
  expect_same_as_cgal_after_each_step({{std::vector<Point>(points.begin(), points.begin() + 30), true},
                                       {points, false},
                                       {points, true}});
}

TEST(Duplicates, SignedZerosAreOnePoint)
{
  const std::vector<Point> points = {Point(0, 0, 0),  Point(-0.0, 0, 0), Point(0, -0.0, -0.0), Point(1, 0, 0),
                                     Point(0, 1, 0),  Point(0, 0, 1),    Point(-0.0, 1, 0),    Point(1, -0.0, 0)};
  expect_same_as_cgal_in_every_order(points);
}

// ---------------------------------------------------------------- extreme coordinates

TEST(Extreme_coordinates, HugeOffset)
{
  // At 1e15 the spacing of doubles is 0.125: the uniform points snap to a
  // lattice, full of coplanar and cospherical subsets.
  expect_same_as_cgal_in_every_order(translated(scaled(to_points<Point>(uniform_points(200, 8)), 100), 1e15));
  expect_same_as_cgal_in_every_order(translated(to_points<Point>(grid_points(64, 9)), 1e15));
}

TEST(Extreme_coordinates, TinyScale)
{
  // Products of coordinate differences underflow in the floating-point filters.
  expect_same_as_cgal_in_every_order(scaled(to_points<Point>(uniform_points(150, 10)), 1e-200));
  expect_same_as_cgal_in_every_order(scaled(to_points<Point>(grid_points(64, 11)), 1e-200));
}

TEST(Extreme_coordinates, HugeScale)
{
  // Products of coordinate differences overflow in the floating-point filters.
  expect_same_as_cgal_in_every_order(scaled(to_points<Point>(uniform_points(150, 12)), 1e200));
  expect_same_as_cgal_in_every_order(scaled(to_points<Point>(grid_points(64, 13)), 1e200));
}

// Every point at its own scale, 10^-200 to 10^200: almost all of them share
// the central cell of the Moore grid of the bounding box.  They are sorted
// again along the curve of their own box, so walks stay short (about 800
// steps per point on 2e4 such points before, most with an exact predicate),
// in the plane too.
TEST(Extreme_coordinates, EveryPointAtItsOwnScale)
{
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-200, 200);
  std::vector<Point> space, plane;
  for(int i = 0; i < 3000; ++i) {
    const double scale = std::pow(10.0, exponent(rng));
    space.emplace_back(scale * unit(rng), scale * unit(rng), scale * unit(rng));
    plane.emplace_back(scale * unit(rng), scale * unit(rng), 0.0);
  }
  const Fast_dt fast(space.begin(), space.end());
  expect_same_as_cgal(fast, Cgal_dt(space.begin(), space.end()));
  const auto& report = fast.last_insertion_report();
  EXPECT_LT(report.kernel.walk_steps, 20 * space.size()) << "walks cross the central cell";
  const Fast_dt flat(plane.begin(), plane.end());
  ASSERT_EQ(flat.dimension(), 2);
  expect_same_as_cgal(flat, Cgal_dt(plane.begin(), plane.end()));
}

TEST(Extreme_coordinates, ScalesAroundTheFilterLimits)
{
  // Just inside and outside the magnitudes where the filters give up.
  for(double scale : {1e-99, 1e-96, 1e-59, 1e-57, 1e60, 1e62, 1e101, 1e103}) {
    SCOPED_TRACE(scale);
    expect_same_as_cgal_in_every_order(scaled(to_points<Point>(sphere_points(60, 14)), scale));
    expect_same_as_cgal_in_every_order(scaled(to_points<Point>(grid_points(27, 15)), scale));
  }
}

TEST(Extreme_coordinates, MixedMagnitudes)
{
  // Points at magnitudes from 1e-150 to 1e150 in one triangulation.
  const std::vector<Point> base = to_points<Point>(gaussian_points(140, 16));
  const double magnitudes[] = {1e-150, 1e-40, 1e-8, 1, 1e8, 1e40, 1e150};
  std::vector<Point> points;
  for(std::size_t i = 0; i < base.size(); ++i) {
    const double m = magnitudes[i % 7];
    points.emplace_back(base[i].x() * m, base[i].y() * m, base[i].z() * m);
  }
  expect_same_as_cgal_in_every_order(points);
}

// ---------------------------------------------------------------- incremental

TEST(Incremental, MixedBulkAndSingleInsertions)
{
  for(const char* name : {"uniform", "grid", "sphere", "duplicates"}) {
    SCOPED_TRACE(name);
    const std::vector<Point> points = to_points<Point>(make_points(name, 240, 17));
    const std::size_t third = points.size() / 3;
    const std::vector<Point> a(points.begin(), points.begin() + third);
    const std::vector<Point> b(points.begin() + third, points.begin() + 2 * third);
    const std::vector<Point> c(points.begin() + 2 * third, points.end());
    expect_same_as_cgal_after_each_step({{a, false}, {b, true}, {c, false}});
    expect_same_as_cgal_after_each_step({{a, true}, {b, false}, {c, true}});
    // Singles that start the triangulation, then one bulk batch.
    expect_same_as_cgal_after_each_step({{std::vector<Point>(points.begin(), points.begin() + 3), true},
                                         {points, false}});
  }
}

TEST(Incremental, IntegerSphereOnePointAtATime)
{
  std::vector<Point> points = to_points<Point>(integer_sphere_points(101));
  points.emplace_back(0, 0, 0);
  expect_same_as_cgal_after_each_step({{points, true}});
}

} // namespace test_degenerate_inputs
