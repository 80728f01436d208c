// The 48-byte tetrahedron record with 64-bit neighbour codes
// (CGAL_FDT3_64_BIT_FACET_CODES, for more than 2^30 tetrahedra) must give the
// same triangulation as the default 32-byte record, sequentially and in
// parallel: both are compared with CGAL.
#define CGAL_FDT3_64_BIT_FACET_CODES
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <cstdint>
#include <type_traits>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_wide_facet_codes {

static_assert(std::is_same<CGAL::Fast_Delaunay_triangulation_3_internal::Facet_code, std::uint64_t>::value,
              "the switch selects 64-bit facet codes");
static_assert(sizeof(CGAL::Fast_Delaunay_triangulation_3_internal::Tet_record) == 48, "wide record");

class Wide_facet_codes : public ::testing::TestWithParam<std::string> {};

TEST_P(Wide_facet_codes, SameCellsAsCgal)
{
  // Under the sanitizers 10,000: the last BRIO round (8,667 points) still
  // gives 2 partitions their 3,000 points each.
  const std::vector<Point> points = to_points<Point>(make_points(GetParam(), sanitized_build ? 10000 : 20000));
  Cgal_dt cgal(points.begin(), points.end());
  for(int threads : {1, 2}) {
    Fast_dt fast;
    fast.set_number_of_threads(threads);
    fast.insert(points.begin(), points.end());
    std::size_t partitioned = 0;
    for(const auto& r : fast.last_insertion_report().rounds)
      if(r.partitions > 1) partitioned += r.inserted;
    if(threads > 1) {
      EXPECT_GT(partitioned, 0u) << "no partitioned round ran";
    }
    ASSERT_TRUE(fast.is_valid(true)) << threads << " threads";
    EXPECT_EQ(fast.number_of_cells(), cgal.number_of_cells()) << threads << " threads";
    EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal)) << threads << " threads";
  }
}

INSTANTIATE_TEST_SUITE_P(Distributions, Wide_facet_codes,
                         ::testing::Values("uniform", "clusters", "grid", "duplicates"));

} // namespace test_wide_facet_codes

// 4 * tetrahedron + facet in 64 bits.
static_assert(CGAL::Fast_Delaunay_triangulation_3_internal::max_tets == (std::uint64_t(1) << 62),
              "64-bit codes address 2^62 tetrahedra");
