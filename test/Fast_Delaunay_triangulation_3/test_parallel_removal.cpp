// remove(first, last) on several threads (Parallel_removal.h), as CGAL's with
// a Parallel_tag data structure.  The oracle is CGAL::Delaunay_triangulation_3
// of the points that remain: the finite cells must be CGAL's, every
// surviving handle at its point with its info, the triangulation valid.
// Inputs: random points (a third of them removed, hull vertices included),
// the 12x12x12 grid (every removal decided by the perturbation) and points
// on a sphere; 2 and 4 partitions.  The partition engine is also run alone,
// to check that it removes most vertices itself (the others are deferred
// to the sequential removal) and leaves a valid triangulation.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <random>
#include <string>
#include <vector>

using namespace fdt3_test;

namespace test_parallel_removal {

typedef CGAL::Triangulation_vertex_base_with_info_3<int, K> Vb;
typedef CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag> Tds;
typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds> Parallel_dt;

std::vector<Point> test_points(const std::string& kind)
{
  if(kind == "grid") {
    std::vector<Point> p;
    for(int i = 0; i < 12; ++i)
      for(int j = 0; j < 12; ++j)
        for(int l = 0; l < 12; ++l) p.emplace_back(i, j, l);
    return p;
  }
  return to_points<Point>(make_points(kind, 6000));
}

struct Case { std::string points; int threads; };
void PrintTo(const Case& c, std::ostream* os) { *os << c.points << " with " << c.threads << " threads"; }
class Parallel_removal_agreement : public ::testing::TestWithParam<Case> {};

TEST_P(Parallel_removal_agreement, SameCellsAsCgalAndHandlesKept)
{
  const Case c = GetParam();
  const std::vector<Point> points = test_points(c.points);
  Parallel_dt tr;
  tr.set_number_of_threads(c.threads);
  std::vector<std::pair<Point, int>> with_info;
  for(std::size_t i = 0; i < points.size(); ++i) with_info.push_back({points[i], int(i)});
  tr.insert(with_info.begin(), with_info.end());
  std::mt19937_64 rng(7);
  std::vector<Parallel_dt::Vertex_handle> gone, kept;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    (rng() % 3 == 0 ? gone : kept).push_back(v);
  EXPECT_EQ(tr.remove(gone.begin(), gone.end()), gone.size());
  ASSERT_TRUE(tr.is_valid(true));
  std::vector<Point> remaining;
  for(Parallel_dt::Vertex_handle v : kept) {
    ASSERT_TRUE(tr.is_vertex(v));
    EXPECT_EQ(v->point(), points[std::size_t(v->info())]);
    remaining.push_back(v->point());
  }
  for(Parallel_dt::Vertex_handle v : gone) EXPECT_FALSE(tr.is_vertex(v));
  EXPECT_EQ(tr.number_of_vertices(), kept.size());
  const Cgal_dt cgal(remaining.begin(), remaining.end());
  expect_same_as_cgal(tr, cgal);
  // The v->cell() the removal kept is right.
  for(Parallel_dt::Vertex_handle v : kept) ASSERT_TRUE(v->cell()->has_vertex(v));
  // It goes on as a triangulation.
  tr.insert(points.begin(), points.begin() + 100);
  EXPECT_TRUE(tr.is_valid());
}

INSTANTIATE_TEST_SUITE_P(Inputs, Parallel_removal_agreement,
                         ::testing::Values(Case{"uniform", 2}, Case{"uniform", 4}, Case{"grid", 2},
                                           Case{"sphere", 2}));

// The engine alone: with 2 slabs all but a few vertices go in parallel, the
// rest are deferred, and what it leaves is the Delaunay triangulation of the
// others.
TEST(Parallel_removal_engine, RemovesMostAndDefersTheRest)
{
  namespace internal = CGAL::Fast_Delaunay_triangulation_3_internal;
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 20000));
  const CGAL::Fast_Delaunay_triangulation_3<K> fast(points.begin(), points.end());
  internal::Triangulation_core core;
  core.dimension = 3;
  core.mesh = fast.flat_storage();
  internal::Flat_storage& m = core.mesh;
  std::vector<internal::Tet_id> incident(m.vertices.size());
  for(internal::Tet_id t = 0; t < m.number_of_slots(); ++t)
    if(m.is_live(t))
      for(int i = 0; i < 4; ++i)
        if(m.vertex(t, i) != internal::ghost_vertex) incident[m.vertex(t, i)] = t;
  std::vector<internal::Vertex_id> ids;
  for(internal::Vertex_id v = 0; v < m.vertices.size(); v += 4) ids.push_back(v);
  std::vector<internal::Vertex_id> deferred;
  std::vector<internal::Tet_id> made;
  core.remove_in_partitions(ids, 2, 256, incident, deferred, &made);
  // One round defers the vertices whose stars cross the cut (14% of them
  // here); the next rounds cut those across.
  EXPECT_LT(deferred.size(), ids.size() / 50) << deferred.size() << " of " << ids.size() << " deferred";
  EXPECT_EQ(m.live_vertices(), m.vertices.size() - (ids.size() - deferred.size()));
  std::string why;
  ASSERT_TRUE(core.is_valid(&why)) << why;
  std::vector<Point> remaining;
  for(internal::Vertex_id v = 0; v < m.vertices.size(); ++v)
    if(!m.is_dead(v)) remaining.push_back(Point(m.point(v)[0], m.point(v)[1], m.point(v)[2]));
  const Cgal_dt cgal(remaining.begin(), remaining.end());
  std::size_t finite = 0;
  for(internal::Tet_id t = 0; t < m.number_of_slots(); ++t) finite += m.is_live(t) && !m.is_ghost(t);
  EXPECT_EQ(finite, cgal.number_of_finite_cells());
  for(internal::Tet_id t : made) ASSERT_TRUE(m.is_live(t));
  for(internal::Vertex_id v = 0; v < m.vertices.size(); ++v) {
    if(m.is_dead(v)) continue;
    ASSERT_GE(internal::index_of(m, incident[v], v), 0) << "v->cell() of vertex " << v;
  }
}

} // namespace test_parallel_removal
