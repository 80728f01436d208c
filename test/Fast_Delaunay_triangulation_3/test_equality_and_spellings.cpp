// operator== / operator!= (between two of ours, and with
// CGAL::Delaunay_triangulation_3 on either side) and CGAL's template
// spellings: a location policy second or third, and a Parallel_tag data
// structure with CGAL's Spatial_lock_grid_3 as lock data structure.  CGAL's
// own operator== is the reference: the same points must compare equal, one
// moved point or one more point must not.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <CGAL/Spatial_lock_grid_3.h>
#endif

#include <algorithm>
#include <random>
#include <type_traits>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_equality_and_spellings {

std::vector<Point> input(const char* name, std::size_t n) { return to_points<Point>(make_points(name, n, 61)); }

TEST(Equality, SamePointsAreEqualToCgalAndToOurs)
{
  for(const char* name : {"uniform", "grid", "sphere"}) {
    std::vector<Point> points = input(name, 400);
    const Fast_dt fast(points.begin(), points.end());
    const Cgal_dt cgal(points.begin(), points.end());
    ASSERT_TRUE(cgal == Cgal_dt(points.begin(), points.end())); // CGAL's own meaning
    EXPECT_TRUE(fast == cgal) << name;
    EXPECT_TRUE(cgal == fast) << name;
    EXPECT_FALSE(fast != cgal);
    EXPECT_FALSE(cgal != fast);
    // Another insertion order and one point at a time: the same triangulation.
    std::shuffle(points.begin(), points.end(), std::mt19937(62));
    Fast_dt one_by_one;
    for(const Point& p : points) one_by_one.insert(p);
    EXPECT_TRUE(one_by_one == fast) << name;
    EXPECT_FALSE(one_by_one != fast);
    EXPECT_TRUE(fast == fast);
  }
}

TEST(Equality, OnePointMovedOrAddedIsNotEqual)
{
  for(const char* name : {"uniform", "grid"}) {
    const std::vector<Point> points = input(name, 300);
    const Fast_dt fast(points.begin(), points.end());
    std::vector<Point> moved = points;
    moved[17] = Point(moved[17].x() + 1e-3, moved[17].y(), moved[17].z());
    const Cgal_dt cgal_moved(moved.begin(), moved.end());
    const Fast_dt fast_moved(moved.begin(), moved.end());
    ASSERT_FALSE(Cgal_dt(points.begin(), points.end()) == cgal_moved); // CGAL agrees they differ
    EXPECT_FALSE(fast == cgal_moved) << name;
    EXPECT_FALSE(cgal_moved == fast) << name;
    EXPECT_TRUE(fast != cgal_moved);
    EXPECT_FALSE(fast == fast_moved);
    EXPECT_TRUE(fast != fast_moved);
    Fast_dt more = fast;
    more.insert(Point(0.5, 0.5, 7));
    EXPECT_FALSE(more == fast);
    EXPECT_FALSE(more == Cgal_dt(points.begin(), points.end()));
  }
}

// A cospherical 2x2x2 cube: 8 points, several Delaunay triangulations
// without perturbation; the perturbed one is unique, so CGAL's and ours
// coincide; the cube with one corner moved inward does not.
TEST(Equality, DegenerateInputsAndLowerDimensions)
{
  std::vector<Point> cube;
  for(int i = 0; i < 2; ++i)
    for(int j = 0; j < 2; ++j)
      for(int k = 0; k < 2; ++k) cube.emplace_back(i, j, k);
  const Fast_dt fast(cube.begin(), cube.end());
  EXPECT_TRUE(fast == Cgal_dt(cube.begin(), cube.end()));
  std::vector<Point> dented = cube;
  dented[7] = Point(0.9, 0.9, 0.9);
  EXPECT_FALSE(fast == Cgal_dt(dented.begin(), dented.end()));

  // Coplanar, collinear, one point, empty: dimension and vertices decide.
  const std::vector<Point> square = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0), Point(2, 3, 0)};
  const std::vector<Point> line = {Point(0, 0, 0), Point(1, 1, 1), Point(3, 3, 3)};
  for(const std::vector<Point>& low : {square, line, std::vector<Point>(1, Point(1, 2, 3)), std::vector<Point>()}) {
    const Fast_dt ours(low.begin(), low.end());
    const Cgal_dt theirs(low.begin(), low.end());
    EXPECT_EQ(ours.dimension(), theirs.dimension());
    EXPECT_TRUE(ours == theirs);
    EXPECT_TRUE(theirs == ours);
  }
  std::vector<Point> other_square = square;
  other_square.back() = Point(2, 4, 0);
  EXPECT_FALSE(Fast_dt(square.begin(), square.end()) == Cgal_dt(other_square.begin(), other_square.end()));
  EXPECT_FALSE(Fast_dt(square.begin(), square.end()) == Cgal_dt(line.begin(), line.end()));
}

typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                             CGAL::Delaunay_triangulation_cell_base_3<K>>
    Tds;

// Each spelling compiles, reports CGAL's Location_policy type and builds
// CGAL's triangulation.
template <class Tr, class Policy>
void expect_spelling_works()
{
  static_assert(std::is_same<typename Tr::Location_policy, Policy>::value, "CGAL's Location_policy typedef");
  static_assert(std::is_same<typename Tr::Concurrency_tag, CGAL::Sequential_tag>::value, "sequential");
  const std::vector<Point> points = input("uniform", 300);
  const Tr tr(points.begin(), points.end());
  EXPECT_TRUE(tr.is_valid());
  EXPECT_TRUE(tr == Cgal_dt(points.begin(), points.end()));
  EXPECT_TRUE(finite_cell_keys(tr) == finite_cell_keys(Cgal_dt(points.begin(), points.end())));
}

TEST(Spellings, LocationPoliciesAreAccepted)
{
  expect_spelling_works<CGAL::Fast_Delaunay_triangulation_3<K>, CGAL::Compact_location>();
  expect_spelling_works<CGAL::Fast_Delaunay_triangulation_3<K, CGAL::Fast_location>, CGAL::Fast_location>();
  expect_spelling_works<CGAL::Fast_Delaunay_triangulation_3<K, Tds, CGAL::Fast_location>, CGAL::Fast_location>();
  expect_spelling_works<CGAL::Fast_Delaunay_triangulation_3<K, Tds, CGAL::Compact_location>, CGAL::Compact_location>();
  expect_spelling_works<CGAL::Fast_Delaunay_triangulation_3<K, CGAL::Default, CGAL::Fast_location>,
                        CGAL::Fast_location>();
  // The policy second and a data structure argument of Default are the same class's behaviour.
  typedef CGAL::Fast_Delaunay_triangulation_3<K, CGAL::Fast_location> Fast_second;
  static_assert(std::is_void<Fast_second::Vertex_info>::value, "the policy is no data structure");
  // Both sides of == may use different spellings.
  const std::vector<Point> points = input("grid", 125);
  EXPECT_TRUE(Fast_second(points.begin(), points.end()) == Fast_dt(points.begin(), points.end()));
  EXPECT_TRUE((CGAL::Delaunay_triangulation_3<K, CGAL::Fast_location>(points.begin(), points.end())) ==
              Fast_second(points.begin(), points.end()));
}

#ifdef CGAL_LINKED_WITH_TBB
// CGAL's parallel spelling with its lock grid: compiles, keeps the lock data
// structure it is given, inserts in parallel and builds CGAL's triangulation.
TEST(Spellings, ParallelTagWithSpatialLockGrid)
{
#if defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "TBB's scheduler is not instrumented for ThreadSanitizer";
#endif
  typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                               CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>
      Parallel_tds;
  typedef CGAL::Spatial_lock_grid_3<CGAL::Tag_priority_blocking> Lock;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Parallel_tds, CGAL::Default, Lock> Parallel_fast_dt;
  static_assert(std::is_same<Parallel_fast_dt::Lock_data_structure, Lock>::value, "the lock type as given");
  static_assert(std::is_same<Parallel_fast_dt::Concurrency_tag, CGAL::Parallel_tag>::value, "parallel");
  const std::vector<Point> points = input("uniform", 2000);
  Lock locks(CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 50);
  Parallel_fast_dt fast(points.begin(), points.end(), &locks);
  EXPECT_EQ(fast.get_lock_data_structure(), &locks);
  EXPECT_TRUE(fast.is_parallel());
  ASSERT_TRUE(fast.is_valid());
  EXPECT_TRUE(fast == Cgal_dt(points.begin(), points.end()));
  // The sequential insertions of CGAL's interface work on it too.
  Parallel_fast_dt::Vertex_handle v = fast.insert(Point(0.5, 0.5, 1.5), fast.finite_vertices_begin());
  EXPECT_TRUE(v->point() == Point(0.5, 0.5, 1.5));
  std::vector<Point> more = points;
  more.emplace_back(0.5, 0.5, 1.5);
  EXPECT_TRUE(fast == Cgal_dt(more.begin(), more.end()));
}

// The lock data structure left to its default, as CGAL's examples spell the
// parallel triangulation (parallel_insertion_in_delaunay_3.cpp): CGAL's own
// choice for a Parallel_tag data structure, Spatial_lock_grid_3 with
// blocking priorities, constructible from a box and a resolution.
TEST(Spellings, ParallelTagWithTheDefaultLockDataStructure)
{
#if defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "TBB's scheduler is not instrumented for ThreadSanitizer";
#endif
  typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                               CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>
      Parallel_tds;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Parallel_tds> Parallel_fast_dt;
  typedef CGAL::Delaunay_triangulation_3<K, Parallel_tds> Parallel_cgal_dt;
  static_assert(std::is_same<Parallel_fast_dt::Lock_data_structure, Parallel_cgal_dt::Lock_data_structure>::value,
                "CGAL's default lock data structure");
  static_assert(std::is_same<Parallel_fast_dt::Lock_data_structure,
                             CGAL::Spatial_lock_grid_3<CGAL::Tag_priority_blocking>>::value,
                "CGAL's default lock data structure");
  const std::vector<Point> points = input("uniform", 1000);
  Parallel_fast_dt::Lock_data_structure locking_ds(CGAL::Bbox_3(0, 0, 0, 1, 1, 1), 50);
  Parallel_fast_dt fast(points.begin(), points.end(), &locking_ds);
  EXPECT_EQ(fast.get_lock_data_structure(), &locking_ds);
  ASSERT_TRUE(fast.is_valid());
  EXPECT_TRUE(fast == Cgal_dt(points.begin(), points.end()));
  Parallel_fast_dt later;
  EXPECT_EQ(later.get_lock_data_structure(), nullptr);
  later.set_lock_data_structure(&locking_ds);
  EXPECT_EQ(later.get_lock_data_structure(), &locking_ds);
}
#endif

// Sequential, CGAL has no lock data structure (void), whatever the location
// policy; given one explicitly, both take it.
TEST(Spellings, SequentialLockDataStructureIsCgals)
{
  static_assert(std::is_void<Fast_dt::Lock_data_structure>::value, "void, as CGAL's");
  static_assert(std::is_same<CGAL::Fast_Delaunay_triangulation_3<K, CGAL::Fast_location>::Lock_data_structure,
                             CGAL::Delaunay_triangulation_3<K, CGAL::Fast_location>::Lock_data_structure>::value,
                "as CGAL's");
  struct Own_lock {};
  static_assert(std::is_same<CGAL::Fast_Delaunay_triangulation_3<K, CGAL::Default, CGAL::Default,
                                                                 Own_lock>::Lock_data_structure,
                             Own_lock>::value,
                "the argument when given");
  static_assert(std::is_same<Cgal_dt::Lock_data_structure, Fast_dt::Lock_data_structure>::value, "as CGAL's");
  const std::vector<Point> points = input("grid", 27);
  const Fast_dt fast(points.begin(), points.end(), nullptr);
  EXPECT_EQ(fast.get_lock_data_structure(), nullptr);
  EXPECT_TRUE(fast == Cgal_dt(points.begin(), points.end()));
}

} // namespace test_equality_and_spellings
