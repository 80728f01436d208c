// Where the time of a bulk insertion goes, in the breakdown of Table 1 of
// Marot, Pellerin and Remacle (2019): sort, walk, cavity, Delaunay ball, and
// the rest.  set_phase_timing(true) turns on the clocks around the walk,
// cavity and ball of every point (four clock reads per point, so a timed run
// is a little slower than an untimed one); the sort, init and finish times and
// the counters are always recorded.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/point_generators_3.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Triangulation;
typedef Triangulation::Point Point;

int main()
{
  CGAL::Random random(7);
  CGAL::Random_points_in_cube_3<Point> generator(1.0, random);
  std::vector<Point> points;
  std::copy_n(generator, 100000, std::back_inserter(points));

  Triangulation triangulation;
  triangulation.set_phase_timing(true);
  const auto start = std::chrono::steady_clock::now();
  triangulation.insert(points.begin(), points.end());
  const double total = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  const Triangulation::Insertion_report& report = triangulation.last_insertion_report();
  const double sort = report.sort_seconds, init = report.init_seconds;
  const double walk = report.kernel.walk_seconds, cavity = report.kernel.cavity_seconds;
  const double ball = report.kernel.ball_seconds;
  // Everything the phase clocks do not cover: the insertion loop, removing
  // duplicates, the clock reads themselves.
  const double other = total - (sort + init + walk + cavity + ball);

  std::printf("%zu points, %zu vertices, %zu finite cells\n\n", report.points, triangulation.number_of_vertices(),
              triangulation.number_of_finite_cells());
  std::printf("phase       seconds   share\n");
  const char* names[] = {"sort", "init", "walk", "cavity", "ball", "other", "total"};
  const double times[] = {sort, init, walk, cavity, ball, other, total};
  for(int k = 0; k < 7; ++k)
    std::printf("%-8s %10.4f %6.1f%%\n", names[k], times[k], 100 * times[k] / total);

  const double inserted = static_cast<double>(report.kernel.inserted);
  std::printf("\nper inserted point: %.2f walk steps, %.2f cavity tetrahedra, %.2f ball tetrahedra, "
              "%.2f conflict tests\n",
              report.kernel.walk_steps / inserted, report.kernel.cavity_tets / inserted,
              report.kernel.ball_tets / inserted, report.kernel.conflict_tests / inserted);
  std::printf("cavities glued with the adjacency table: %llu, with the fallback: %llu\n",
              static_cast<unsigned long long>(report.kernel.small_cavities),
              static_cast<unsigned long long>(report.kernel.large_cavities));
  std::printf("inserted by the kernel: %llu, duplicates: %llu\n",
              static_cast<unsigned long long>(report.kernel.inserted),
              static_cast<unsigned long long>(report.kernel.duplicates));
  return 0;
}
