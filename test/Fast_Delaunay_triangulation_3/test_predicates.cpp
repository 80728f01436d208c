// Unit tests of internal/Predicates.h against CGAL:
//  - orientation and side_of_oriented_sphere, without and with the static
//    (bounding box) filter stage, have the sign of Epick's exact predicates
//    on random, nearly degenerate (1 ulp off a plane or a sphere), grid,
//    offset and scaled inputs, scales around the filters' limits included,
//    and so does the cavity's conflict test on vertex records, with its
//    bound from the test's own points;
//  - the filtered in-circle test of coplanar points has the sign of Epick's
//    exact one on exactly coplanar lattice points, cocircular ones included;
//  - the perturbed in-sphere and in-circle tests equal
//    Delaunay_triangulation_3's side_of_oriented_sphere(..., true) and
//    coplanar_side_of_bounded_circle(..., true) on cospherical and cocircular
//    integer points in every permutation;
//  - the filter constants are at least, and within 1e-4 of, the error bounds
//    their comments derive, and the magnitude limits keep those bounds valid.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>

#include <algorithm>
#include <array>
#include <cfloat>
#include <cmath>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <vector>

using namespace fdt3_test;
namespace P = CGAL::Fast_Delaunay_triangulation_3_internal;

namespace test_predicates {

typedef std::array<double, 3> Coordinates;

Point to_point(const Coordinates& c) { return Point(c[0], c[1], c[2]); }
Coordinates to_coordinates(const Point& p) { return {p.x(), p.y(), p.z()}; }

int cgal_orientation(const Coordinates& p, const Coordinates& q, const Coordinates& r, const Coordinates& s)
{
  return static_cast<int>(K().orientation_3_object()(to_point(p), to_point(q), to_point(r), to_point(s)));
}

int cgal_side_of_oriented_sphere(const Coordinates& p, const Coordinates& q, const Coordinates& r,
                                 const Coordinates& s, const Coordinates& t)
{
  return static_cast<int>(K().side_of_oriented_sphere_3_object()(to_point(p), to_point(q), to_point(r),
                                                                 to_point(s), to_point(t)));
}

// Moves x by k units in the last place (towards +inf for k > 0).
double ulps(double x, int k)
{
  for(; k > 0; --k) x = std::nextafter(x, std::numeric_limits<double>::infinity());
  for(; k < 0; ++k) x = std::nextafter(x, -std::numeric_limits<double>::infinity());
  return x;
}

class Generator
{
public:
  explicit Generator(std::uint64_t seed) : rng_(seed) {}

  double uniform(double lo = 0, double hi = 1) { return std::uniform_real_distribution<double>(lo, hi)(rng_); }
  int integer(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(rng_); }

  Coordinates point(double scale, double offset)
  {
    return {offset + scale * uniform(), offset + scale * uniform(), offset + scale * uniform()};
  }

  // p moved off by -2..2 ulps in one random coordinate.
  Coordinates nudged(Coordinates p)
  {
    const int axis = integer(0, 2);
    p[axis] = ulps(p[axis], integer(-2, 2));
    return p;
  }

  // A point of the plane of a, b, c, rounded, then nudged.
  Coordinates near_plane(const Coordinates& a, const Coordinates& b, const Coordinates& c)
  {
    const double u = uniform(-1, 2), v = uniform(-1, 2);
    Coordinates d;
    for(int i = 0; i < 3; ++i) d[i] = a[i] + u * (b[i] - a[i]) + v * (c[i] - a[i]);
    return nudged(d);
  }

  // A point of the sphere of centre c and radius r, rounded.
  Coordinates on_sphere(const Coordinates& c, double r)
  {
    std::normal_distribution<double> g;
    double x, y, z, n;
    do { x = g(rng_); y = g(rng_); z = g(rng_); n = std::sqrt(x * x + y * y + z * z); } while(n < 1e-3);
    return {c[0] + r * x / n, c[1] + r * y / n, c[2] + r * z / n};
  }

  // The same, then nudged.
  Coordinates near_sphere(const Coordinates& c, double r) { return nudged(on_sphere(c, r)); }

  template <class T>
  void shuffle(std::vector<T>& v)
  {
    std::shuffle(v.begin(), v.end(), rng_);
  }

private:
  std::mt19937_64 rng_;
};

// The static filter of the smallest box around the points: the tightest, so
// the most aggressive, that the kernel could build for them.
template <std::size_t N>
P::Static_filter tight_static_filter(const std::array<Coordinates, N>& points)
{
  double lo[3], hi[3];
  for(int a = 0; a < 3; ++a) {
    lo[a] = hi[a] = points[0][a];
    for(const Coordinates& p : points) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  }
  return P::Static_filter::for_box(lo, hi);
}

// Magnitudes of the coordinates (and of their differences): ordinary, far
// beyond the filters' limits, just inside and outside each limit, where
// products of five differences are subnormal (1e-62), and where the cavity
// test's underflow term is most of its bound (1e-26).
struct Frame
{
  double scale, offset;
};

std::vector<Frame> frames()
{
  return {{1, 0},      {1e-120, 0}, {1e120, 0},  {1e-99, 0}, {1e-96, 0}, {1e101, 0}, {1e103, 0},
          {1e-60, 0},  {1e-57, 0},  {1e60, 0},   {1e62, 0},  {1, 1e15},  {1e-3, 1e8}, {1e-300, 0},
          {1e-62, 0},  {1e-26, 0}};
}

std::string describe(const Frame& f)
{
  return "scale " + std::to_string(f.scale) + ", offset " + std::to_string(f.offset);
}

TEST(Orientation, SignOfCgalsExactPredicate)
{
  Generator g(1);
  std::size_t zeros = 0, tested = 0;
  for(const Frame& f : frames()) {
    SCOPED_TRACE(describe(f));
    for(int i = 0; i < 1500; ++i) {
      const Coordinates a = g.point(f.scale, f.offset), b = g.point(f.scale, f.offset),
                        c = g.point(f.scale, f.offset);
      // Random, nearly coplanar, and exactly coplanar by construction when no rounding happens.
      const Coordinates d = (i % 3 == 0) ? g.point(f.scale, f.offset) : g.near_plane(a, b, c);
      const int expected = cgal_orientation(a, b, c, d);
      ASSERT_EQ(P::orientation(a.data(), b.data(), c.data(), d.data()), expected)
          << "case " << i;
      const P::Static_filter filter = tight_static_filter(std::array<Coordinates, 4>{a, b, c, d});
      ASSERT_EQ(P::orientation(filter, a.data(), b.data(), c.data(), d.data()), expected)
          << "static filter, case " << i;
      ASSERT_EQ(P::orientation(b.data(), a.data(), c.data(), d.data()), -expected) << "case " << i;
      ASSERT_EQ(P::orientation(d.data(), a.data(), b.data(), c.data()), -expected) << "case " << i;
      zeros += expected == 0 ? 1 : 0;
      ++tested;
    }
  }
  EXPECT_GT(zeros, 100u) << "too few exactly coplanar cases (of " << tested << ") to exercise the exact stage";
}

#ifdef CGAL_FDT3_SIMD_RECORDS
// The vector form in a function built for AVX2 (a plain build compiles the
// test bodies for the baseline processor).
CGAL_FDT3_TARGET_AVX2 void store_facet_orientations_of_records(const double* a, const double* b, const double* c,
                                                               const double* d, const double* t, double volumes[4])
{
  _mm256_storeu_pd(volumes, P::facet_orientations_of_records(a, b, c, d, t));
}

// The walk's four facet orientations of a tetrahedron of vertex records
// against a point, certified by the static filter: every certified sign is
// CGAL's exact one (random, nearly coplanar, exactly coplanar grid points).
TEST(Orientation, FacetOrientationsOfRecordsCertifyExactSigns)
{
  if(!P::processor_has_avx2_and_fma()) GTEST_SKIP() << "this processor has no AVX2 and FMA";
  Generator g(32);
  std::size_t certified = 0, tested = 0;
  for(const Frame& f : frames()) {
    SCOPED_TRACE(describe(f));
    for(int i = 0; i < 1500; ++i) {
      std::array<Coordinates, 5> p;
      for(int k = 0; k < 3; ++k) p[k] = g.point(f.scale, f.offset);
      if(i % 3 == 2)
        for(Coordinates& q : p) q = {f.scale * g.integer(0, 2), f.scale * g.integer(0, 2), f.scale * g.integer(0, 2)};
      else {
        p[3] = g.point(f.scale, f.offset);
        p[4] = (i % 3 == 0) ? g.point(f.scale, f.offset) : g.near_plane(p[0], p[1], p[2]);
      }
      P::Vertex_record records[4];
      for(int k = 0; k < 4; ++k) {
        std::copy(p[k].begin(), p[k].end(), records[k].xyz);
        records[k].scratch = std::uint64_t(i + k); // denormals in the fourth lane
      }
      const P::Static_filter filter = tight_static_filter(p);
      double volumes[4];
      store_facet_orientations_of_records(records[0].xyz, records[1].xyz, records[2].xyz, records[3].xyz,
                                          p[4].data(), volumes);
      for(int facet = 0; facet < 4; ++facet) {
        std::array<Coordinates, 4> q = {p[0], p[1], p[2], p[3]};
        q[facet] = p[4];
        const int expected = cgal_orientation(q[0], q[1], q[2], q[3]);
        ++tested;
        if(volumes[facet] > filter.orientation) {
          ASSERT_EQ(expected, 1) << "case " << i << " facet " << facet;
          ++certified;
        } else if(volumes[facet] < -filter.orientation) {
          ASSERT_EQ(expected, -1) << "case " << i << " facet " << facet;
          ++certified;
        }
      }
    }
  }
  EXPECT_GT(certified, tested / 3);
}
#endif

TEST(Orientation, GridPoints)
{
  // Small integer coordinates: zero determinants everywhere, also scaled.
  Generator g(2);
  for(double scale : {1.0, 1e-120, 1e120, 0.1, 1e-97, 1e102}) {
    SCOPED_TRACE(scale);
    for(int i = 0; i < 3000; ++i) {
      std::array<Coordinates, 4> p;
      for(Coordinates& q : p)
        q = {scale * g.integer(0, 3), scale * g.integer(0, 3), scale * g.integer(0, 3)};
      ASSERT_EQ(P::orientation(p[0].data(), p[1].data(), p[2].data(), p[3].data()),
                cgal_orientation(p[0], p[1], p[2], p[3]));
    }
  }
}

TEST(Side_of_oriented_sphere, SignOfCgalsExactPredicate)
{
  Generator g(3);
  for(const Frame& f : frames()) {
    SCOPED_TRACE(describe(f));
    for(int i = 0; i < 1500; ++i) {
      std::array<Coordinates, 5> p;
      if(i % 3 == 0) {
        for(Coordinates& q : p) q = g.point(f.scale, f.offset);
      } else {
        const Coordinates centre = g.point(f.scale, f.offset);
        const double radius = f.scale * g.uniform(0.1, 1);
        for(Coordinates& q : p) q = g.near_sphere(centre, radius);
      }
      const int expected = cgal_side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4]);
      ASSERT_EQ(P::side_of_oriented_sphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()),
                expected)
          << "case " << i;
      ASSERT_EQ(P::side_of_oriented_sphere(p[1].data(), p[0].data(), p[2].data(), p[3].data(), p[4].data()),
                -expected)
          << "case " << i;
      ASSERT_EQ(P::side_of_oriented_sphere(tight_static_filter(p), p[0].data(), p[1].data(), p[2].data(),
                                           p[3].data(), p[4].data()),
                expected)
          << "static filter, case " << i;
    }
  }
}

// The kernel's conflict test reads the four vertices as 32-byte records (with
// AVX2, a vectorised determinant): with any scratch word beside the
// coordinates (zero, small integers read as denormals, all ones read as a
// NaN) it must decide as the perturbed predicate on random, nearly
// cospherical and exactly cospherical points, at every scale (the per-call
// bound at the limits of its range too), with and without the static
// filter; so must the conflict test on coordinates of moves and checks.
TEST(Side_of_oriented_sphere, RecordConflictTestAsScalarOne)
{
  Generator g(31);
  const std::vector<Xyz> sphere = integer_sphere_points(101);
  const std::uint64_t scratch_words[] = {0, 7, 31, ~std::uint64_t(0)};
  std::size_t conflicts = 0, tested = 0;
  for(const Frame& f : frames()) {
    SCOPED_TRACE(describe(f));
    for(int i = 0; i < 900; ++i) {
      std::array<Coordinates, 5> p;
      if(i % 3 == 0) {
        for(Coordinates& q : p) q = g.point(f.scale, f.offset);
      } else if(i % 3 == 1) {
        const Coordinates centre = g.point(f.scale, f.offset);
        const double radius = f.scale * g.uniform(0.1, 1);
        for(Coordinates& q : p) q = g.near_sphere(centre, radius);
      } else {
        for(Coordinates& q : p) {
          const Xyz& s = sphere[static_cast<std::size_t>(g.integer(0, int(sphere.size()) - 1))];
          q = {f.scale * s.x + f.offset, f.scale * s.y, f.scale * s.z};
        }
      }
      // Positive orientation, as in the triangulation; skip flat tetrahedra,
      // and a fifth point drawn again (the perturbation asserts that no two
      // points are equal).
      const int o = cgal_orientation(p[0], p[1], p[2], p[3]);
      if(o == 0 || std::count(p.begin(), p.end() - 1, p[4]) != 0) continue;
      if(o < 0) std::swap(p[0], p[1]);
      P::Vertex_record records[4];
      for(int k = 0; k < 4; ++k) {
        std::copy(p[k].begin(), p[k].end(), records[k].xyz);
        records[k].scratch = scratch_words[(i + k) % 4];
      }
      const bool expected =
          P::perturbed_side_of_oriented_sphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()) > 0;
      ASSERT_EQ(P::finite_cell_in_conflict(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()),
                expected)
          << "case " << i;
      for(const P::Static_filter& filter : {P::Static_filter(), tight_static_filter(p)}) {
        // Both forms, whichever the build and the processor would choose.
        ASSERT_EQ(P::finite_record_in_conflict<P::Scalar_paths>(records[0].xyz, records[1].xyz, records[2].xyz,
                                                                records[3].xyz, p[4].data(), filter),
                  expected)
            << "case " << i;
#ifdef CGAL_FDT3_SIMD_RECORDS
        if(P::processor_has_avx2_and_fma()) {
          ASSERT_EQ(P::finite_record_in_conflict<P::Avx2_paths>(records[0].xyz, records[1].xyz, records[2].xyz,
                                                                records[3].xyz, p[4].data(), filter),
                    expected)
              << "case " << i;
        }
#endif
        conflicts += expected ? 1 : 0;
        ++tested;
      }
    }
  }
  EXPECT_GT(conflicts, tested / 10);
  EXPECT_LT(conflicts, tested - tested / 10);
}

TEST(Side_of_oriented_sphere, IntegerSpherePointsOffByAnUlp)
{
  // Exactly cospherical integer points, then the fifth point moved by 1 ulp,
  // at several scales (powers of two keep them exactly cospherical).
  const std::vector<Xyz> sphere = integer_sphere_points(101);
  Generator g(4);
  for(double scale : {1.0, std::ldexp(1.0, -400), std::ldexp(1.0, 400), std::ldexp(1.0, -190),
                      std::ldexp(1.0, 200), 1e-120, 1e120}) {
    SCOPED_TRACE(scale);
    std::size_t zeros = 0;
    for(int i = 0; i < 2000; ++i) {
      std::array<Coordinates, 5> p;
      for(Coordinates& q : p) {
        const Xyz& s = sphere[static_cast<std::size_t>(g.integer(0, int(sphere.size()) - 1))];
        q = {scale * s.x, scale * s.y, scale * s.z};
      }
      if(i % 2 == 1) p[4] = g.nudged(p[4]);
      const int expected = cgal_side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4]);
      ASSERT_EQ(P::side_of_oriented_sphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()),
                expected)
          << "case " << i;
      ASSERT_EQ(P::side_of_oriented_sphere(tight_static_filter(p), p[0].data(), p[1].data(), p[2].data(),
                                           p[3].data(), p[4].data()),
                expected)
          << "static filter, case " << i;
      zeros += expected == 0 ? 1 : 0;
    }
    if(scale == 1.0 || scale == std::ldexp(1.0, -400)) {
      EXPECT_GT(zeros, 500u);
    }
  }
}

TEST(Side_of_oriented_sphere, GridPoints)
{
  Generator g(5);
  for(double scale : {1.0, 1e-120, 1e120, 1e-58, 1e61}) {
    SCOPED_TRACE(scale);
    for(int i = 0; i < 3000; ++i) {
      std::array<Coordinates, 5> p;
      for(Coordinates& q : p)
        q = {scale * g.integer(0, 3), scale * g.integer(0, 3), scale * g.integer(0, 3)};
      ASSERT_EQ(P::side_of_oriented_sphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()),
                cgal_side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4]));
    }
  }
}

// The exact-in-double stage decides integer (and dyadic) inputs whose
// coordinate differences span few bits; at and just past its limits (spans
// 9 / 10 for the in-sphere test, 16 / 17 for the orientation) and with
// inexact differences (an offset of 2^53) the signs must still be CGAL's.
TEST(Exact_in_double, SpansAroundTheLimits)
{
  Generator g(6);
  for(int range : {1, 7, 255, 511, 1023, 65535, 131071}) {
    for(double unit : {1.0, 0.125, 1024.0}) {
      for(double offset : {0.0, 9007199254740992.0}) {
        SCOPED_TRACE(std::to_string(range) + " " + std::to_string(unit) + " " + std::to_string(offset));
        for(int i = 0; i < 2000; ++i) {
          std::array<Coordinates, 5> p;
          for(Coordinates& q : p)
            q = {offset + unit * g.integer(0, range), unit * g.integer(0, range), unit * g.integer(0, range)};
          ASSERT_EQ(P::orientation(p[0].data(), p[1].data(), p[2].data(), p[3].data()),
                    cgal_orientation(p[0], p[1], p[2], p[3]));
          ASSERT_EQ(P::side_of_oriented_sphere(p[0].data(), p[1].data(), p[2].data(), p[3].data(), p[4].data()),
                    cgal_side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4]));
        }
      }
    }
  }
}

TEST(Exact_in_double, BitSpanOfDifferences)
{
  P::Bit_span span;
  span.add_difference(5.0, 1.0);   // 4 = 2^2
  span.add_difference(1.5, 1.0);   // 0.5 = 2^-1
  EXPECT_TRUE(span.exact);
  EXPECT_EQ(span.high, 2);
  EXPECT_EQ(span.low, -1);
  EXPECT_TRUE(span.at_most(4));
  EXPECT_FALSE(span.at_most(3));
  P::Bit_span inexact;
  inexact.add_difference(1.0, 1e-30); // rounds
  EXPECT_FALSE(inexact.exact);
  EXPECT_FALSE(inexact.at_most(64));
}

// ---------------------------------------------------------------- symbolic perturbation

// k distinct indices out of n, at random.
std::vector<std::size_t> pick(Generator& g, std::size_t n, std::size_t k)
{
  std::vector<std::size_t> all(n);
  std::iota(all.begin(), all.end(), std::size_t(0));
  g.shuffle(all);
  all.resize(k);
  return all;
}

std::vector<std::vector<Point>> five_point_subsets(const std::vector<Point>& points, std::size_t how_many,
                                                   Generator& g)
{
  std::vector<std::vector<Point>> subsets;
  for(std::size_t s = 0; s < how_many; ++s) {
    std::vector<Point> subset;
    for(std::size_t i : pick(g, points.size(), 5)) subset.push_back(points[i]);
    subsets.push_back(subset);
  }
  return subsets;
}

// Compares the perturbed in-sphere test with CGAL's on every permutation of
// each 5-point subset whose first four points are positively oriented.
// Returns the number of comparisons.
std::size_t expect_perturbed_in_sphere_as_cgal(const std::vector<std::vector<Point>>& subsets)
{
  const Cgal_perturbed_predicates cgal{};
  const K::Orientation_3 orientation = K().orientation_3_object();
  std::size_t compared = 0;
  for(std::vector<Point> p : subsets) {
    std::sort(p.begin(), p.end());
    std::size_t permutations = 0;
    do {
      ++permutations;
      if(orientation(p[0], p[1], p[2], p[3]) != CGAL::POSITIVE) continue;
      const Coordinates c[5] = {to_coordinates(p[0]), to_coordinates(p[1]), to_coordinates(p[2]),
                                to_coordinates(p[3]), to_coordinates(p[4])};
      const int ours = P::perturbed_side_of_oriented_sphere(c[0].data(), c[1].data(), c[2].data(),
                                                            c[3].data(), c[4].data());
      const int expected = static_cast<int>(cgal.side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4], true));
      EXPECT_NE(expected, 0);
      EXPECT_EQ(ours, expected) << p[0] << " | " << p[1] << " | " << p[2] << " | " << p[3] << " | " << p[4];
      if(ours != expected) return compared;
      ++compared;
    } while(std::next_permutation(p.begin(), p.end()));
    EXPECT_EQ(permutations, 120u);
  }
  return compared;
}

TEST(Perturbation, InSphereOnCosphericalIntegerPoints)
{
  Generator g(6);
  std::size_t compared = 0;
  // Every 5-subset of the octahedron and of the cube corners.
  const std::vector<Point> octahedron = {Point(1, 0, 0), Point(-1, 0, 0), Point(0, 1, 0),
                                         Point(0, -1, 0), Point(0, 0, 1), Point(0, 0, -1)};
  std::vector<Point> cube;
  for(int i = 0; i < 8; ++i) cube.emplace_back(i & 1, (i >> 1) & 1, (i >> 2) & 1);
  const std::vector<Point>* sets[] = {&octahedron, &cube};
  for(const std::vector<Point>* set : sets) {
    std::vector<std::vector<Point>> subsets;
    const std::size_t n = set->size();
    for(std::size_t mask = 0; mask < (std::size_t(1) << n); ++mask) {
      if(__builtin_popcountll(mask) != 5) continue;
      std::vector<Point> subset;
      for(std::size_t i = 0; i < n; ++i)
        if(mask >> i & 1) subset.push_back((*set)[i]);
      subsets.push_back(subset);
    }
    compared += expect_perturbed_in_sphere_as_cgal(subsets);
  }
  // Random subsets of integer spheres (many coplanar quadruples: the second
  // monomial of the perturbation decides) and of a grid.
  compared += expect_perturbed_in_sphere_as_cgal(
      five_point_subsets(to_points<Point>(integer_sphere_points(25)), 150, g));
  compared += expect_perturbed_in_sphere_as_cgal(
      five_point_subsets(to_points<Point>(integer_sphere_points(101)), 100, g));
  std::vector<Point> grid;
  for(int x = 0; x < 3; ++x)
    for(int y = 0; y < 3; ++y)
      for(int z = 0; z < 3; ++z) grid.emplace_back(x, y, z);
  compared += expect_perturbed_in_sphere_as_cgal(five_point_subsets(grid, 100, g));
  EXPECT_GT(compared, 10000u);
}

TEST(Perturbation, InSphereWhenNotDegenerate)
{
  // The unperturbed answer passes through: four cospherical points and a
  // fifth inside or outside their sphere.
  Generator g(7);
  const std::vector<Point> sphere = to_points<Point>(integer_sphere_points(25));
  std::vector<std::vector<Point>> subsets;
  for(int s = 0; s < 40; ++s) {
    std::vector<Point> subset;
    for(std::size_t i : pick(g, sphere.size(), 4)) subset.push_back(sphere[i]);
    subset.emplace_back(g.integer(-6, 6), g.integer(-6, 6), g.integer(-6, 6));
    if(std::count(subset.begin(), subset.end() - 1, subset.back()) == 0) subsets.push_back(subset);
  }
  EXPECT_GT(expect_perturbed_in_sphere_as_cgal(subsets), 1000u);
}

// Compares the perturbed in-circle test with CGAL's on every permutation of
// each coplanar 4-point subset whose first three points are not collinear.
std::size_t expect_perturbed_in_circle_as_cgal(const std::vector<std::vector<Point>>& subsets)
{
  const Cgal_perturbed_predicates cgal{};
  const K::Collinear_3 collinear = K().collinear_3_object();
  std::size_t compared = 0;
  for(std::vector<Point> p : subsets) {
    EXPECT_TRUE(K().coplanar_3_object()(p[0], p[1], p[2], p[3]));
    std::sort(p.begin(), p.end());
    do {
      if(collinear(p[0], p[1], p[2])) continue;
      const Coordinates c[4] = {to_coordinates(p[0]), to_coordinates(p[1]), to_coordinates(p[2]),
                                to_coordinates(p[3])};
      const int ours =
          P::perturbed_coplanar_side_of_bounded_circle(c[0].data(), c[1].data(), c[2].data(), c[3].data());
      const int expected =
          static_cast<int>(cgal.coplanar_side_of_bounded_circle(p[0], p[1], p[2], p[3], true));
      EXPECT_NE(expected, 0);
      EXPECT_EQ(ours, expected) << p[0] << " | " << p[1] << " | " << p[2] << " | " << p[3];
      if(ours != expected) return compared;
      ++compared;
    } while(std::next_permutation(p.begin(), p.end()));
  }
  return compared;
}

TEST(Perturbation, InCircleOnCocircularIntegerPoints)
{
  std::vector<std::vector<Point>> subsets;
  // Every 4-subset of the tilted circle (exactly cocircular).
  const std::vector<Point> circle = to_points<Point>(tilted_circle_points());
  for(std::size_t a = 0; a < circle.size(); ++a)
    for(std::size_t b = a + 1; b < circle.size(); ++b)
      for(std::size_t c = b + 1; c < circle.size(); ++c)
        for(std::size_t d = c + 1; d < circle.size(); ++d)
          subsets.push_back({circle[a], circle[b], circle[c], circle[d]});
  // Random 4-subsets of a 4 x 4 grid in the same tilted plane (cocircular
  // squares and rectangles, collinear triples) and of the z = 0 circle of
  // the sphere x^2 + y^2 + z^2 = 25 with its centre.
  Generator g(8);
  std::vector<Point> tilted_grid;
  for(int u = 0; u < 4; ++u)
    for(int v = 0; v < 4; ++v) tilted_grid.emplace_back(u + 2 * v, 2 * u + v, 2 * u - 2 * v);
  for(int s = 0; s < 300; ++s) {
    std::vector<Point> subset;
    for(std::size_t i : pick(g, tilted_grid.size(), 4)) subset.push_back(tilted_grid[i]);
    subsets.push_back(subset);
  }
  std::vector<Point> flat_circle = {Point(0, 0, 0)};
  for(const Point& p : to_points<Point>(integer_sphere_points(25)))
    if(p.z() == 0) flat_circle.push_back(p);
  for(int s = 0; s < 100; ++s) {
    std::vector<Point> subset;
    for(std::size_t i : pick(g, flat_circle.size(), 4)) subset.push_back(flat_circle[i]);
    subsets.push_back(subset);
  }
  EXPECT_GT(expect_perturbed_in_circle_as_cgal(subsets), 10000u);
}

// ---------------------------------------------------------------- small helpers

TEST(Helpers, LexicographicOrderAndCollinearityAsCgal)
{
  Generator g(9);
  for(int i = 0; i < 5000; ++i) {
    const Coordinates p = {double(g.integer(-2, 2)), double(g.integer(-2, 2)), double(g.integer(-2, 2))};
    const Coordinates q = {double(g.integer(-2, 2)), double(g.integer(-2, 2)), double(g.integer(-2, 2))};
    const Coordinates r = {double(g.integer(-2, 2)), double(g.integer(-2, 2)), double(g.integer(-2, 2))};
    const CGAL::Comparison_result cmp = K().compare_xyz_3_object()(to_point(p), to_point(q));
    ASSERT_EQ(P::lexicographically_smaller(p.data(), q.data()), cmp == CGAL::SMALLER);
    ASSERT_EQ(P::same_point(p.data(), q.data()), cmp == CGAL::EQUAL);
    ASSERT_EQ(P::collinear(p.data(), q.data(), r.data()),
              K().collinear_3_object()(to_point(p), to_point(q), to_point(r)));
  }
}

// The filtered coplanar orientation (the walk of dimension 2) answers CGAL's
// exact coplanar_orientation: random triples, nearly collinear ones, and
// triples in a vertical plane, whose xy projection is a line (the answer
// then comes from another projection), at every frame's magnitude.
TEST(Coplanar_orientation, SignOfCgalsExactPredicate)
{
  Generator g(11);
  std::size_t collinear_in_xy = 0, near_collinear = 0;
  for(const Frame& f : frames()) {
    SCOPED_TRACE(describe(f));
    for(int i = 0; i < 1500; ++i) {
      const Coordinates a = g.point(f.scale, f.offset), b = g.point(f.scale, f.offset);
      Coordinates c = g.point(f.scale, f.offset);
      if(i % 3 == 1) {
        // Nearly on the line ab.
        const double u = g.uniform(-1, 2);
        for(int k = 0; k < 3; ++k) c[k] = a[k] + u * (b[k] - a[k]);
        c = g.nudged(c);
        ++near_collinear;
      } else if(i % 3 == 2) {
        // In the plane x = a.x, so all three project onto one line in xy.
        c[0] = a[0];
        Coordinates d = b;
        d[0] = a[0];
        const int expected = static_cast<int>(
            K().coplanar_orientation_3_object()(to_point(a), to_point(d), to_point(c)));
        ASSERT_EQ(P::coplanar_orientation(a.data(), d.data(), c.data()), expected) << "case " << i;
        ++collinear_in_xy;
        continue;
      }
      const int expected =
          static_cast<int>(K().coplanar_orientation_3_object()(to_point(a), to_point(b), to_point(c)));
      ASSERT_EQ(P::coplanar_orientation(a.data(), b.data(), c.data()), expected) << "case " << i;
      ASSERT_EQ(P::coplanar_orientation(b.data(), a.data(), c.data()), -expected) << "case " << i;
    }
  }
  EXPECT_GT(collinear_in_xy, 1000u);
  EXPECT_GT(near_collinear, 1000u);
}

// The filtered in-circle test of four coplanar points answers CGAL's exact
// coplanar_side_of_bounded_circle: points of integer lattices in tilted
// planes (so exactly coplanar in double), random ones, exactly cocircular
// ones (the corners of the lattice's rectangles, the points of a circle of
// the plane) and ones a lattice step off a circle, scaled by powers of two
// (exact) from far below to far above the filter's range, and moved away
// from the origin.
TEST(Coplanar_side_of_bounded_circle, SignOfCgalsExactPredicate)
{
  Generator g(12);
  // (u, v) -> origin + u * a + v * b: two planes through the lattice Z^3.
  const std::array<std::array<Coordinates, 2>, 2> planes = {{{{{1, 2, 2}, {2, 1, -2}}}, {{{3, 0, 1}, {0, 5, 2}}}}};
  const std::vector<std::pair<double, double>> frames = {
      {1, 0}, {std::ldexp(1.0, -40), 0}, {std::ldexp(1.0, 40), 0}, {std::ldexp(1.0, -1000), 0},
      {std::ldexp(1.0, 900), 0}, {1, std::ldexp(1.0, 30)}, {std::ldexp(1.0, -20), 1}};
  std::size_t inside = 0, outside = 0, on_circle = 0;
  for(const auto& frame : frames)
    for(const auto& plane : planes) {
      auto lattice_point = [&](long u, long v) {
        Coordinates c;
        for(int k = 0; k < 3; ++k)
          c[k] = frame.second + frame.first * (double(u) * plane[0][k] + double(v) * plane[1][k]);
        return c;
      };
      for(int i = 0; i < 2000; ++i) {
        std::array<long, 8> uv;
        if(i % 4 == 0) {
          // The corners of a rectangle of the lattice: cocircular.
          const long u0 = g.integer(-50, 50), v0 = g.integer(-50, 50);
          const long du = g.integer(1, 20), dv = g.integer(1, 20);
          uv = {u0, v0, u0 + du, v0, u0 + du, v0 + dv, u0, v0 + dv};
        } else if(i % 4 == 1) {
          // A lattice circle (u^2 + v^2 = 25 in lattice coordinates is no
          // circle in space unless a, b are orthogonal and of equal length,
          // which both planes' first pair is); the fourth point a step off.
          const std::array<std::array<long, 2>, 12> circle = {
              {{5, 0}, {4, 3}, {3, 4}, {0, 5}, {-3, 4}, {-4, 3}, {-5, 0}, {-4, -3}, {-3, -4}, {0, -5}, {3, -4}, {4, -3}}};
          for(int k = 0; k < 4; ++k) {
            const auto& c = circle[std::size_t(g.integer(0, 11))];
            uv[2 * k] = c[0];
            uv[2 * k + 1] = c[1];
          }
          if(g.integer(0, 1)) uv[6 + g.integer(0, 1)] += g.integer(0, 1) ? 1 : -1;
        } else {
          for(long& x : uv) x = g.integer(-1000, 1000);
        }
        const Coordinates p = lattice_point(uv[0], uv[1]), q = lattice_point(uv[2], uv[3]),
                          r = lattice_point(uv[4], uv[5]), t = lattice_point(uv[6], uv[7]);
        if(K().collinear_3_object()(to_point(p), to_point(q), to_point(r))) continue;
        ASSERT_EQ(cgal_orientation(p, q, r, t), 0);
        const int expected = static_cast<int>(K().coplanar_side_of_bounded_circle_3_object()(
            to_point(p), to_point(q), to_point(r), to_point(t)));
        ASSERT_EQ(P::coplanar_side_of_bounded_circle(p.data(), q.data(), r.data(), t.data()), expected)
            << "frame " << frame.first << " + " << frame.second << ", case " << i;
        ASSERT_EQ(P::coplanar_side_of_bounded_circle(q.data(), p.data(), r.data(), t.data()), expected);
        (expected > 0 ? inside : expected < 0 ? outside : on_circle) += 1;
      }
    }
  // Four points of a circle in the plane z = x, rounded (then z set to x
  // again: exactly coplanar), nearly cocircular: the rounding of the
  // floating-point stage can flip their sign.
  std::size_t near_circle = 0;
  for(double scale : {1.0, 1e-30, 1e30}) {
    for(int i = 0; i < 3000; ++i) {
      const double cx = scale * g.uniform(-1, 1), cy = scale * g.uniform(-1, 1), radius = scale * g.uniform(0.1, 1);
      std::array<Coordinates, 4> c;
      for(Coordinates& point : c) {
        const double angle = g.uniform(0, 6.283185307179586);
        point[0] = cx + radius * std::cos(angle) / std::sqrt(2.0);
        point[1] = cy + radius * std::sin(angle);
        point[2] = point[0];
      }
      if(K().collinear_3_object()(to_point(c[0]), to_point(c[1]), to_point(c[2]))) continue;
      const int expected = static_cast<int>(K().coplanar_side_of_bounded_circle_3_object()(
          to_point(c[0]), to_point(c[1]), to_point(c[2]), to_point(c[3])));
      ASSERT_EQ(P::coplanar_side_of_bounded_circle(c[0].data(), c[1].data(), c[2].data(), c[3].data()), expected)
          << "scale " << scale << ", case " << i;
      ++near_circle;
    }
  }
  EXPECT_GT(inside, 5000u);
  EXPECT_GT(outside, 5000u);
  EXPECT_GT(on_circle, 3000u);
  EXPECT_GT(near_circle, 8000u);
}

// ---------------------------------------------------------------- filter constants

TEST(Filter_bounds, ConstantsCoverTheirDerivation)
{
  // Predicates.h: |error| <= c(eps) * permanent with eps = 2^-53,
  //   orient3d: c = (7 + 56 eps) eps,   permanent <= 6 mx my mz;
  //   insphere: c = (16 + 224 eps) eps, permanent <= 4 * 6 mx my mz L.
  // Computed in long double, which holds these sums exactly enough.
  const long double eps = std::ldexp(1.0L, -53);
  const long double orientation = (7 + 56 * eps) * eps * 6;
  const long double in_sphere = (16 + 224 * eps) * eps * 4 * 6;
  EXPECT_EQ(P::Filter_bounds::unit_roundoff, std::ldexp(1.0, -53));
  EXPECT_GE(static_cast<long double>(P::Filter_bounds::orientation), orientation);
  EXPECT_GE(static_cast<long double>(P::Filter_bounds::in_sphere), in_sphere);
  EXPECT_LT(static_cast<long double>(P::Filter_bounds::orientation) / orientation - 1, 1e-4L);
  EXPECT_LT(static_cast<long double>(P::Filter_bounds::in_sphere) / in_sphere - 1, 1e-4L);
  // The cavity search's bound in the largest difference M: mx my mz L <= 3 M^5.
  EXPECT_GE(static_cast<long double>(P::Filter_bounds::in_sphere_of_largest), 3 * in_sphere);
  EXPECT_LT(static_cast<long double>(P::Filter_bounds::in_sphere_of_largest) / (3 * in_sphere) - 1, 1e-4L);
  // Its underflow term: under 64 products, each off by 2^-1075 times at most 6 in_sphere_max^3 (scaled
  // before the power of two, which a long double of double's range would flush to zero alone).
  const long double largest = P::Filter_bounds::in_sphere_max;
  EXPECT_GE(static_cast<long double>(P::Filter_bounds::in_sphere_underflow),
            std::ldexp(64 * 6 * largest * largest * largest, -1075));
}

// The double-double stage, alone: never a sign other than the exact one, 0 on
// exactly cospherical points, and decisive on points rounded onto a sphere
// (the input it is there for) at every scale of its range.
TEST(Side_of_oriented_sphere, DoubleDoubleStageCertifiesExactSigns)
{
  // CGAL's sign (the opposite of Shewchuk's) of the stage, scalar and, where
  // built, on AVX lanes: both must agree.
  const auto dd_sign = [](const std::array<Coordinates, 5>& p) {
    const double* const others[4] = {p[0].data(), p[1].data(), p[2].data(), p[3].data()};
    double m[3];
    P::max_differences(p[4].data(), others, m);
    const double bound = 2 * P::Filter_bounds::in_sphere_double_double * (m[0] * m[1] * m[2]) *
                         (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const int scalar = -P::in_sphere_determinant_sign_double_double_scalar(p[0].data(), p[1].data(), p[2].data(),
                                                                           p[3].data(), p[4].data(), bound);
#ifdef CGAL_FDT3_SIMD_RECORDS
    if(!P::processor_has_avx2_and_fma()) return scalar;
    const int lanes = -P::in_sphere_determinant_sign_double_double_lanes(p[0].data(), p[1].data(), p[2].data(),
                                                                         p[3].data(), p[4].data(), bound);
    // Different roundings may leave one of them undecided, never opposite.
    EXPECT_TRUE(scalar == lanes || scalar == 0 || lanes == 0) << scalar << " and " << lanes;
    return lanes != 0 ? lanes : scalar;
#else
    return scalar;
#endif
  };
  Generator g(12);
  for(const Frame& f : std::vector<Frame>{{1, 0}, {1e-25, 0}, {1e25, 0}, {1, 1e6}, {1e-3, 1e8}}) {
    SCOPED_TRACE(describe(f));
    std::size_t decided = 0, cases = 0;
    for(int i = 0; i < 3000; ++i) {
      std::array<Coordinates, 5> p;
      const Coordinates centre = g.point(f.scale, f.offset);
      const double radius = f.scale * g.uniform(0.1, 1);
      for(Coordinates& q : p) q = i % 2 == 0 ? g.on_sphere(centre, radius) : g.near_sphere(centre, radius);
      const int expected = cgal_side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4]);
      const int sign = dd_sign(p);
      ASSERT_TRUE(sign == 0 || sign == expected) << "case " << i << ": " << sign << " instead of " << expected;
      ++cases;
      if(sign != 0) ++decided;
    }
    if(f.offset == 0) {
      EXPECT_GT(decided, cases * 99 / 100) << decided << " of " << cases;
    }
  }
  const std::vector<Xyz> sphere = integer_sphere_points(101);
  for(int i = 0; i < 2000; ++i) {
    std::array<Coordinates, 5> p;
    for(Coordinates& q : p) {
      const Xyz& s = sphere[static_cast<std::size_t>(g.integer(0, int(sphere.size()) - 1))];
      q = {s.x, s.y, s.z};
    }
    if(cgal_side_of_oriented_sphere(p[0], p[1], p[2], p[3], p[4]) == 0) {
      ASSERT_EQ(dd_sign(p), 0) << "cospherical case " << i;
    }
  }
}

TEST(Filter_bounds, DoubleDoubleConstantCoversItsDerivation)
{
  // 16 operations deep at most, 5 eps^2 each, four times over, times the
  // permanent's 4 * 6.
  const long double eps = std::ldexp(1.0L, -53);
  const long double bound = 4 * 16 * 5 * eps * eps * 24;
  EXPECT_GE(static_cast<long double>(P::Filter_bounds::in_sphere_double_double), bound);
  EXPECT_LT(static_cast<long double>(P::Filter_bounds::in_sphere_double_double) / bound - 1, 1e-3L);
  // Within the range the bound stays far above underflow.
  const double lo = P::Filter_bounds::in_sphere_double_double_min;
  EXPECT_GT(P::Filter_bounds::in_sphere_double_double * lo * lo * lo * (lo * lo), 1e-200);
}

TEST(Filter_bounds, LimitsKeepTheBoundsInNormalRange)
{
  // Inside the limits (all per-axis maxima in (min, max)), the bound and the
  // permanent it covers are normal doubles: neither underflows below the
  // smallest normal (where absolute rounding errors stop scaling) nor
  // overflows.  Products of three maxima for orient3d, five for insphere.
  const double lo_o = P::Filter_bounds::orientation_min, hi_o = P::Filter_bounds::orientation_max;
  const double lo_s = P::Filter_bounds::in_sphere_min, hi_s = P::Filter_bounds::in_sphere_max;
  EXPECT_GT(P::Filter_bounds::orientation * lo_o * lo_o * lo_o, DBL_MIN);
  EXPECT_LT(6 * hi_o * hi_o * hi_o, DBL_MAX);
  EXPECT_GT(P::Filter_bounds::in_sphere * lo_s * lo_s * lo_s * (lo_s * lo_s), DBL_MIN);
  EXPECT_LT(4 * 6 * hi_s * hi_s * hi_s * (3 * hi_s * hi_s), DBL_MAX);
}

} // namespace test_predicates
