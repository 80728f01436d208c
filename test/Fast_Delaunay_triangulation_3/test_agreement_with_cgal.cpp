// For every distribution, degenerate ones included, the finite cells are
// exactly those of CGAL::Delaunay_triangulation_3 on the same points, and the
// triangulation passes independent checks.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_agreement_with_cgal {

struct Case { std::string distribution; std::size_t n; };

class Agreement : public ::testing::TestWithParam<Case> {};

TEST_P(Agreement, SameCellsAsCgal)
{
  const Case c = GetParam();
  const std::vector<Point> points = to_points<Point>(make_points(c.distribution, c.n));
  Fast_dt fast(points.begin(), points.end());
  Cgal_dt cgal(points.begin(), points.end());

  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_EQ(fast.dimension(), cgal.dimension());
  EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
  EXPECT_EQ(fast.number_of_finite_cells(), cgal.number_of_finite_cells());
  EXPECT_EQ(fast.number_of_cells(), cgal.number_of_cells());
  EXPECT_EQ(fast.number_of_finite_facets(), cgal.number_of_finite_facets());
  EXPECT_EQ(fast.number_of_finite_edges(), cgal.number_of_finite_edges());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
  expect_locally_delaunay(fast);
  expect_volume_of_hull(fast, points);
}

std::vector<Case> cases()
{
  std::vector<Case> all;
  for(const char* d : {"uniform", "gauss", "clusters", "sphere", "grid", "duplicates", "offset", "tiny"})
    for(std::size_t n : {std::size_t(20), std::size_t(500), std::size_t(sanitized_build ? 5000 : 20000)})
      all.push_back({d, n});
  return all;
}

INSTANTIATE_TEST_SUITE_P(Distributions, Agreement, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.distribution + "_" + std::to_string(info.param.n);
                         });

} // namespace test_agreement_with_cgal

namespace test_agreement_with_cgal {

// The cached sub-determinants (paper §2.4) only change how the conflict test
// is evaluated: cells must still be CGAL's, degenerate inputs included.
class Sub_determinants : public ::testing::TestWithParam<std::string> {};

TEST_P(Sub_determinants, SameCellsAsCgal)
{
  const std::vector<Point> points = to_points<Point>(make_points(GetParam(), 5000));
  Fast_dt fast;
  fast.set_sub_determinants(true);
  ASSERT_TRUE(fast.sub_determinants());
  fast.insert(points.begin(), points.begin() + points.size() / 2);
  fast.insert(points.begin() + points.size() / 2, points.end());
  const Cgal_dt cgal(points.begin(), points.end());
  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

TEST(Sub_determinants, SwitchedOnAfterConstruction)
{
  const std::vector<Point> points = to_points<Point>(make_points("grid", 3000));
  Fast_dt fast(points.begin(), points.begin() + 1000);
  fast.set_sub_determinants(true);
  fast.insert(points.begin() + 1000, points.end());
  fast.set_sub_determinants(false);
  fast.insert(Point(0.5, 0.5, 0.5));
  Cgal_dt cgal(points.begin(), points.end());
  cgal.insert(Point(0.5, 0.5, 0.5));
  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

// Extents outside [1e-50, 1e50] disable the sub-determinant filter: every
// test must then go to the full predicates and still give CGAL's cells.
TEST(Sub_determinants, ExtremeExtents)
{
  for(double scale : {1e-60, 1e60}) {
    std::vector<Point> points;
    for(const Xyz& q : uniform_points(2000, 12)) points.emplace_back(q.x * scale, q.y * scale, q.z * scale);
    Fast_dt fast;
    fast.set_sub_determinants(true);
    fast.insert(points.begin(), points.end());
    const Cgal_dt cgal(points.begin(), points.end());
    ASSERT_TRUE(fast.is_valid(true)) << scale;
    EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal)) << scale;
  }
}

INSTANTIATE_TEST_SUITE_P(Distributions, Sub_determinants,
                         ::testing::Values("uniform", "clusters", "sphere", "grid", "duplicates", "offset", "tiny"));

} // namespace test_agreement_with_cgal

namespace test_agreement_with_cgal {

// Inserting the centre of a sphere of many points makes every cell conflict:
// the cavity boundary has far more than 31 vertices, so the Delaunay ball
// must take the sorted-edge fallback instead of the adjacency table.
TEST(Regression, CosphericalShellForcesLargeCavityFallback)
{
  std::vector<Point> shell;
  for(const Xyz& q : sphere_points(400, 11)) shell.emplace_back(q.x, q.y, q.z);
  Fast_dt fast(shell.begin(), shell.end());
  fast.insert(Point(0, 0, 0));
  EXPECT_EQ(fast.last_insertion_report().kernel.large_cavities, 1u);
  EXPECT_EQ(fast.last_insertion_report().kernel.small_cavities, 0u);
  shell.push_back(Point(0, 0, 0));
  const Cgal_dt cgal(shell.begin(), shell.end());
  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_EQ(fast.number_of_finite_cells(), cgal.number_of_finite_cells());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

} // namespace test_agreement_with_cgal

namespace test_agreement_with_cgal {

namespace I = CGAL::Fast_Delaunay_triangulation_3_internal;

// The scalar forms of the predicates while it lives (see use_avx2_paths).
struct Scalar_paths_forced
{
  Scalar_paths_forced() { I::scalar_paths_forced() = true; }
  ~Scalar_paths_forced() { I::scalar_paths_forced() = false; }
};

using fdt3_test::cells_in_slot_order;

// An insertion chooses the AVX2 forms of the walk's and the cavity search's
// predicates where the processor has them, the scalar forms elsewhere (or
// when forced): both must build CGAL's cells, and the same triangulation
// cell for cell.  The scalar run happens on every machine and build, so
// that the forms a processor without AVX2 runs stay tested on one with it.
class Vector_paths : public ::testing::TestWithParam<std::string> {};

TEST_P(Vector_paths, ScalarAndAvx2FormsBuildTheSameTriangulation)
{
  const std::vector<Point> points = to_points<Point>(make_points(GetParam(), 10000));
  const Cgal_dt cgal(points.begin(), points.end());
  std::vector<std::array<double, 12>> scalar_cells;
  {
    Scalar_paths_forced scalar;
    ASSERT_FALSE(I::use_avx2_paths());
    Fast_dt fast(points.begin(), points.end());
    ASSERT_TRUE(fast.is_valid(true));
    EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
    scalar_cells = cells_in_slot_order(fast);
  }
  if(!I::processor_has_avx2_and_fma()) GTEST_SKIP() << "no AVX2 and FMA on this processor (or in this build)";
  ASSERT_TRUE(I::use_avx2_paths());
  Fast_dt fast(points.begin(), points.end());
  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
  EXPECT_TRUE(cells_in_slot_order(fast) == scalar_cells);
}

INSTANTIATE_TEST_SUITE_P(Distributions, Vector_paths,
                         ::testing::Values("uniform", "clusters", "sphere", "grid", "shell", "torus", "duplicates",
                                           "tiny"));

} // namespace test_agreement_with_cgal
