// The barrier-synchronised engine (the two-level kernel of "Multi-threaded
// mesh generation", internal/Barrier_insertion.h): on every kind of input,
// with 2 and 3 threads, the triangulation is valid and its finite cells are
// exactly CGAL's, most points inserted by the barrier iterations; cavities
// that meet are searched again; the same input and thread count give the
// same cells in the same order, also when one thread does all the work.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/task_arena.h>
#endif

using namespace fdt3_test;

namespace test_parallel_barrier {

typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

// Small enough for ThreadSanitizer in CI, large enough for the last BRIO
// round (about 26,000 points) to reach 256 points per run with 3 threads.
constexpr std::size_t points_per_case = 30000;

void insert_with_barriers(Fast_dt& dt, const std::vector<Point>& points, int threads)
{
  dt.set_number_of_threads(threads);
  dt.set_parallel_engine(Fast_dt::Parallel_engine::barrier);
  dt.insert(points.begin(), points.end());
}

// Points inserted by the barrier iterations (rows with several runs), and
// cavities searched again there.
std::pair<std::size_t, std::size_t> barrier_counts(const Fast_dt& dt)
{
  std::size_t inserted = 0, retried = 0;
  for(const auto& r : dt.last_insertion_report().rounds)
    if(r.partitions > 1) {
      inserted += r.inserted;
      retried += r.retried;
    }
  return {inserted, retried};
}

struct Case { std::string distribution; int threads; };
void PrintTo(const Case& c, std::ostream* os) { *os << c.distribution << " with " << c.threads << " threads"; }

class Barrier_agreement : public ::testing::TestWithParam<Case> {};

TEST_P(Barrier_agreement, SameCellsAsCgal)
{
  const Case c = GetParam();
  const std::vector<Point> points = to_points<Point>(make_points(c.distribution, points_per_case));
  Fast_dt fast;
  insert_with_barriers(fast, points, c.threads);
  const Cgal_dt cgal(points.begin(), points.end());

  std::size_t inserted = 0;
  for(const auto& r : fast.last_insertion_report().rounds) inserted += r.inserted;
  EXPECT_EQ(inserted + 4, points.size());
  // Unlike the partitions, no round falls back for long cells: the last
  // round alone is 87% of the points.
  EXPECT_GT(barrier_counts(fast).first, points.size() * 3 / 4) << "the barrier iterations inserted too few points";
  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

std::vector<Case> cases()
{
  // 3 threads (24 runs) on two inputs only: each case takes about 5 s under
  // ThreadSanitizer.
  return {{"uniform", 2}, {"uniform", 3}, {"sphere", 2}, {"grid", 2}, {"duplicates", 2}, {"shell", 3}, {"torus", 2}};
}

INSTANTIATE_TEST_SUITE_P(Distributions, Barrier_agreement, ::testing::ValuesIn(cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return info.param.distribution + "_" + std::to_string(info.param.threads);
                         });

// Points on a sphere: every cell spans the ball, so cavities of far-apart
// points meet, and the run of larger index searches its point again.
TEST(Barrier_insertion, CavitiesThatMeetAreSearchedAgain)
{
  const std::vector<Point> points = to_points<Point>(make_points("sphere", points_per_case, 31));
  Fast_dt fast;
  insert_with_barriers(fast, points, 2);
  EXPECT_GT(barrier_counts(fast).second, 0u);
  ASSERT_TRUE(fast.is_valid(true));
  const Cgal_dt cgal(points.begin(), points.end());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

TEST(Barrier_insertion, ReproducibleCellForCell)
{
  const std::vector<Point> points = to_points<Point>(make_points("shell", points_per_case, 32));
  Fast_dt first, second;
  insert_with_barriers(first, points, 2);
  insert_with_barriers(second, points, 2);
  EXPECT_TRUE(cells_in_slot_order(first) == cells_in_slot_order(second));
}

// A second range into a triangulation whose free slots the first one left,
// with the in-sphere sub-determinants cached (written by the balls).
TEST(Barrier_insertion, IntoNonEmptyTriangulationWithSubDeterminants)
{
  const std::size_t half = points_per_case / 2;
  const std::vector<Point> points = to_points<Point>(make_points("gauss", 2 * half, 33));
  Fast_dt fast;
  fast.set_sub_determinants(true);
  fast.set_number_of_threads(2);
  fast.set_parallel_engine(Fast_dt::Parallel_engine::barrier);
  fast.insert(points.begin(), points.begin() + half);
  fast.remove(fast.finite_vertices_begin());
  fast.insert(points.begin() + half, points.end());
  EXPECT_GT(barrier_counts(fast).first, half / 2);
  ASSERT_TRUE(fast.is_valid(true));
  std::vector<Point> kept;
  for(auto v = fast.finite_vertices_begin(); v != fast.finite_vertices_end(); ++v) kept.push_back(v->point());
  const Cgal_dt cgal(kept.begin(), kept.end());
  EXPECT_EQ(kept.size(), 2 * half - 1);
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

// A progress callback that throws (a user cancelling a long insertion) is
// called from inside the barrier iterations, where the other thread waits at
// a barrier: the exception reaches the caller, and the triangulation can be
// cleared and used again.
TEST(Barrier_insertion, ExceptionInAThreadReachesTheCaller)
{
  // Progress is reported every 65,536 points of the iterations, which the
  // last BRIO round of 80,000 points reaches.
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 80000, 35));
  Fast_dt fast;
  fast.set_number_of_threads(2);
  fast.set_parallel_engine(Fast_dt::Parallel_engine::barrier);
  struct Cancelled {};
  bool cancelled = false;
  fast.set_progress([&](std::size_t done, std::size_t total) {
    if(done > total / 4 && done < total && !cancelled) {
      cancelled = true;
      throw Cancelled();
    }
  });
  EXPECT_THROW(fast.insert(points.begin(), points.end()), Cancelled);
  EXPECT_TRUE(cancelled);
  fast.clear();
  fast.set_progress({});
  const std::vector<Point> some(points.begin(), points.begin() + 20000);
  fast.insert(some.begin(), some.end());
  ASSERT_TRUE(fast.is_valid());
  const Cgal_dt cgal(some.begin(), some.end());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

#ifdef CGAL_LINKED_WITH_TBB
// Limited to one thread by the caller's arena, the one thread takes the
// other thread's runs at the first barrier: the same cells in the same slots.
TEST(Barrier_insertion, InsideSingleThreadArena)
{
#if defined(__SANITIZE_THREAD__)
  GTEST_SKIP() << "TBB's scheduler is not instrumented for ThreadSanitizer";
#endif
  const std::vector<Point> points = to_points<Point>(make_points("torus", points_per_case, 34));
  Fast_dt in_arena, free_running;
  tbb::task_arena arena(1);
  arena.execute([&] { insert_with_barriers(in_arena, points, 2); });
  insert_with_barriers(free_running, points, 2);
  EXPECT_GT(barrier_counts(in_arena).first, points.size() / 2);
  ASSERT_TRUE(in_arena.is_valid());
  EXPECT_TRUE(cells_in_slot_order(in_arena) == cells_in_slot_order(free_running));
}
#endif

} // namespace test_parallel_barrier
