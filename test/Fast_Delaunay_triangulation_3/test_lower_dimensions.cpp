// Triangulations of dimension -1, 0, 1 and 2 against
// CGAL::Delaunay_triangulation_3 on the same points: the dimension, every
// count, the iterators, the finite triangles and segments as point tuples
// (CGAL's perturbed 2D Delaunay triangulation is unique, so they must be
// equal), then the same after a point that lifts the dimension.  The handle
// conventions of each dimension (null slots above the dimension, neighbour i
// opposite vertex i, mirror indices, orientation of neighbours, v->cell())
// are one test body run on both triangulations.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <random>
#include <string>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_lower_dimensions {

// CGAL's conventions for cells below dimension 3, checked through handles.
template <class Tr>
void expect_lower_dimensional_conventions(const Tr& tr)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const int d = tr.dimension();
  ASSERT_GE(d, 0);
  ASSERT_LT(d, 3);
  const std::vector<Cell_handle> cells = lower_dimensional_cells(tr);
  const std::size_t expected = d == 0 ? 2 : d == 1 ? tr.number_of_vertices() + 1 : 2 * tr.number_of_vertices() - 2;
  ASSERT_EQ(cells.size(), expected);
  std::size_t infinite = 0;
  for(const Cell_handle& c : cells) {
    bool has_infinite = false;
    for(int i = 0; i < 4; ++i) {
      if(i > d) {
        EXPECT_TRUE(c->vertex(i) == Vertex_handle()) << "vertex slot " << i << " above dimension " << d;
        EXPECT_TRUE(c->neighbor(i) == Cell_handle()) << "neighbour slot " << i << " above dimension " << d;
        continue;
      }
      ASSERT_TRUE(c->vertex(i) != Vertex_handle());
      has_infinite = has_infinite || tr.is_infinite(c->vertex(i));
      EXPECT_EQ(c->index(c->vertex(i)), i);
      const Cell_handle n = c->neighbor(i);
      ASSERT_TRUE(n != Cell_handle());
      const int j = tr.mirror_index(c, i);
      EXPECT_TRUE(n->neighbor(j) == c) << "asymmetric adjacency";
      EXPECT_EQ(n->index(c), j);
      EXPECT_TRUE(tr.mirror_vertex(c, i) == n->vertex(j));
      EXPECT_FALSE(n->has_vertex(c->vertex(i)));
      for(int k = 0; k <= d; ++k)
        if(k != i) {
          EXPECT_TRUE(n->has_vertex(c->vertex(k))) << "neighbours do not share a face";
        }
      if(d == 1) {
        EXPECT_EQ(j, 1 - i) << "segments not chained head to tail";
      }
      if(d == 2) {
        EXPECT_TRUE(c->vertex((i + 1) % 3) == n->vertex((j + 2) % 3)) << "inconsistent orientation";
      }
    }
    if(has_infinite) ++infinite;
    if(d == 2) {
      EXPECT_EQ(tr.is_infinite(typename Tr::Facet(c, 3)), has_infinite);
      if(!has_infinite) {
        const typename Tr::Triangle t = tr.triangle(c, 3);
        for(int i = 0; i < 3; ++i) {
          EXPECT_TRUE(t.vertex(i) == c->vertex(i)->point());
        }
      }
    }
    if(d >= 1)
      for(int i = 0; i <= d; ++i)
        for(int j = 0; j <= d; ++j)
          if(i != j) {
            EXPECT_EQ(tr.is_infinite(c, i, j), tr.is_infinite(c->vertex(i)) || tr.is_infinite(c->vertex(j)));
          }
  }
  // Infinite cells: one point cell, two segments, one triangle per hull edge.
  const std::size_t expected_infinite = d == 0 ? 1 : d == 1 ? 2 : tr.number_of_facets() - tr.number_of_finite_facets();
  EXPECT_EQ(infinite, expected_infinite);
  for(auto v = tr.all_vertices_begin(); v != tr.all_vertices_end(); ++v) {
    const Vertex_handle vh = v;
    ASSERT_TRUE(vh->cell() != Cell_handle());
    EXPECT_TRUE(vh->cell()->has_vertex(vh)) << "v->cell() does not contain v";
  }
  EXPECT_TRUE(tr.infinite_cell()->has_vertex(tr.infinite_vertex()));
}

// Our triangulation equals CGAL's (dimension, counts, faces) and both follow
// CGAL's conventions.
void expect_same(const Fast_dt& fast, const Cgal_dt& cgal)
{
  expect_same_as_cgal(fast, cgal);
  if(cgal.dimension() >= 0 && cgal.dimension() < 3) {
    {
      SCOPED_TRACE("CGAL");
      expect_lower_dimensional_conventions(cgal);
    }
    SCOPED_TRACE("Fast");
    expect_lower_dimensional_conventions(fast);
  }
}

void expect_same_in_bulk_and_one_by_one(const std::vector<Point>& points)
{
  const Cgal_dt cgal(points.begin(), points.end());
  {
    SCOPED_TRACE("bulk");
    expect_same(Fast_dt(points.begin(), points.end()), cgal);
  }
  SCOPED_TRACE("one by one");
  Fast_dt fast;
  for(const Point& p : points) EXPECT_TRUE(fast.insert(p)->point() == p);
  expect_same(fast, cgal);
}

// The points, then the points and one more that lifts the dimension, each
// compared with CGAL; the added point also inserted alone into the first.
void expect_same_before_and_after_lifting(const std::vector<Point>& points, const Point& lift,
                                          int dimension_before)
{
  const Cgal_dt cgal_before(points.begin(), points.end());
  ASSERT_EQ(cgal_before.dimension(), dimension_before) << "the input does not test what it should";
  expect_same_in_bulk_and_one_by_one(points);
  std::vector<Point> lifted = points;
  lifted.push_back(lift);
  const Cgal_dt cgal_after(lifted.begin(), lifted.end());
  ASSERT_EQ(cgal_after.dimension(), dimension_before + 1);
  expect_same_in_bulk_and_one_by_one(lifted);
  SCOPED_TRACE("lifted by insert(p)");
  Fast_dt fast(points.begin(), points.end());
  fast.insert(lift);
  expect_same(fast, cgal_after);
}

std::vector<Point> shuffled(std::vector<Point> points, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  std::shuffle(points.begin(), points.end(), rng);
  return points;
}

// ---------------------------------------------------------------- few points

TEST(Few_points, ZeroOneTwoThreePoints)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(4, 21));
  for(std::size_t n = 0; n <= 3; ++n) {
    SCOPED_TRACE(std::to_string(n) + " points");
    const std::vector<Point> first(points.begin(), points.begin() + n);
    expect_same_in_bulk_and_one_by_one(first);
    EXPECT_EQ(Fast_dt(first.begin(), first.end()).dimension(), int(n) - 1);
  }
  expect_same_before_and_after_lifting(std::vector<Point>(points.begin(), points.begin() + 3), points[3], 2);
}

TEST(Few_points, EmptyTriangulation)
{
  const Fast_dt fast;
  const Cgal_dt cgal;
  expect_same(fast, cgal);
  EXPECT_EQ(std::distance(fast.all_facets_begin(), fast.all_facets_end()), 0);
  EXPECT_EQ(std::distance(fast.all_edges_begin(), fast.all_edges_end()), 0);
}

// ---------------------------------------------------------------- collinear

TEST(Collinear, UnsortedWithDuplicatesThenOffTheLine)
{
  // a + t d for t in -12..12, each repeated every third time, shuffled.
  std::vector<Point> line;
  for(int t = -12; t <= 12; ++t) {
    line.emplace_back(0.5 + 3 * t, -1.25 + 0.5 * t, 2 - 0.75 * t);
    if(t % 3 == 0) line.emplace_back(0.5 + 3 * t, -1.25 + 0.5 * t, 2 - 0.75 * t);
  }
  line = shuffled(line, 22);
  expect_same_before_and_after_lifting(line, Point(1, 1, 1), 1);
  EXPECT_EQ(Fast_dt(line.begin(), line.end()).number_of_vertices(), 25u);
}

TEST(Collinear, TwoPointsAndSortedOrders)
{
  const std::vector<Point> two = {Point(1, 2, 3), Point(-1, 0, 7)};
  expect_same_before_and_after_lifting(two, Point(0, 0, 0), 1);
  std::vector<Point> line;
  for(int t = 0; t < 15; ++t) line.emplace_back(t, 2 * t, -t);
  expect_same_in_bulk_and_one_by_one(line);
  std::reverse(line.begin(), line.end());
  expect_same_in_bulk_and_one_by_one(line);
}

// ---------------------------------------------------------------- coplanar

TEST(Coplanar, RandomPointsThenApex)
{
  std::vector<Point> plane;
  for(const Xyz& q : uniform_points(200, 23)) plane.emplace_back(q.x, q.y, -0.5);
  expect_same_before_and_after_lifting(plane, Point(0.3, 0.6, 0.25), 2);
}

TEST(Coplanar, RegularGridWithCocircularTies)
{
  // Every unit square of the grid has 4 cocircular corners: only CGAL's
  // perturbation decides its diagonal.
  std::vector<Point> grid;
  for(int u = 0; u < 12; ++u)
    for(int v = 0; v < 10; ++v) grid.emplace_back(u, v, u + 2 * v);
  expect_same_before_and_after_lifting(shuffled(grid, 24), Point(0, 0, 5), 2);
  std::vector<Point> flat;
  for(int u = 0; u < 8; ++u)
    for(int v = 0; v < 8; ++v) flat.emplace_back(v, 0, u);
  expect_same_before_and_after_lifting(flat, Point(3, -1, 3), 2);
}

TEST(Coplanar, AllPointsOnACircle)
{
  // The 48 integer points of x^2 + y^2 = 5525 (all cocircular), at z = 3.
  std::vector<Point> circle;
  for(int x = -75; x <= 75; ++x)
    for(int y = -75; y <= 75; ++y)
      if(x * x + y * y == 5525) circle.emplace_back(x, y, 3);
  ASSERT_EQ(circle.size(), 48u);
  expect_same_before_and_after_lifting(shuffled(circle, 25), Point(0, 0, 10), 2);
  expect_same_before_and_after_lifting(to_points<Point>(tilted_circle_points()), Point(10, -10, 5), 2);
  // With the centre: every triangle has it or is one of the cocircular ones.
  circle.emplace_back(0, 0, 3);
  expect_same_in_bulk_and_one_by_one(circle);
}

TEST(Coplanar, TiltedPlaneNonIntegerCoordinates)
{
  // z = 0.5 x - 0.75 y + 0.375 holds exactly for multiples of 2^-10 of this
  // size: the points are exactly coplanar, none of them on an axis plane.
  std::mt19937_64 rng(26);
  std::uniform_int_distribution<int> coordinate(-100000, 100000);
  std::vector<Point> plane;
  for(int i = 0; i < 150; ++i) {
    const double x = coordinate(rng) / 1024.0, y = coordinate(rng) / 1024.0;
    plane.emplace_back(x, y, 0.5 * x - 0.75 * y + 0.375);
  }
  // Some repeats and a cocircular square.
  plane.push_back(plane[3]);
  plane.push_back(plane[77]);
  for(double x : {1.5, 2.5})
    for(double y : {-0.25, 0.75}) plane.emplace_back(x, y, 0.5 * x - 0.75 * y + 0.375);
  expect_same_before_and_after_lifting(plane, Point(0.1, 0.2, 50.3), 2);
}

// ---------------------------------------------------------------- incremental

TEST(Incremental, OnePointAtATimeThroughEveryDimension)
{
  // A point, a duplicate, the line, the plane, then space; compared with
  // CGAL after every insert(p).
  const std::vector<Point> points = {Point(0.5, 0.5, 0.5), Point(0.5, 0.5, 0.5), Point(1.5, 0.5, 0.5),
                                     Point(-2, 0.5, 0.5),  Point(3, 0.5, 0.5),   Point(0, 1, 0.5),
                                     Point(1, -2, 0.5),    Point(2, 2, 0.5),     Point(1, 1, 0.5),
                                     Point(0.5, 0.5, 0.5), Point(1, 0, 3),       Point(0, 0, -1)};
  const int expected_dimension[] = {0, 0, 1, 1, 1, 2, 2, 2, 2, 2, 3, 3};
  Fast_dt fast;
  Cgal_dt cgal;
  for(std::size_t i = 0; i < points.size(); ++i) {
    SCOPED_TRACE("after point " + std::to_string(i));
    const Fast_dt::Vertex_handle v = fast.insert(points[i]);
    cgal.insert(points[i]);
    EXPECT_TRUE(v->point() == points[i]);
    EXPECT_EQ(cgal.dimension(), expected_dimension[i]);
    expect_same(fast, cgal);
  }
}

TEST(Incremental, BatchesThatStayPlanarThenLift)
{
  std::vector<Point> plane;
  for(const Xyz& q : uniform_points(90, 27)) plane.emplace_back(q.x, 0.25, q.z);
  Fast_dt fast;
  Cgal_dt cgal;
  for(std::size_t begin = 0; begin < plane.size(); begin += 30) {
    fast.insert(plane.begin() + begin, plane.begin() + begin + 30);
    cgal.insert(plane.begin() + begin, plane.begin() + begin + 30);
    expect_same(fast, cgal);
  }
  const std::vector<Point> apexes = to_points<Point>(uniform_points(5, 28));
  fast.insert(apexes.begin(), apexes.end());
  cgal.insert(apexes.begin(), apexes.end());
  expect_same(fast, cgal);
}

// The lift joins the apex to the triangles in their slots and puts the
// ghosts below in free slots: after removals in dimension 2 (free slots
// among the triangles), from either side of the plane, from a grid (ties),
// by insert(p) and by a range with more points in the plane and off it,
// with the in-sphere sub-determinants cached or not (the insertions after
// the lift read those of the new tetrahedra).
TEST(Incremental, LiftAfterRemovalsFromEitherSide)
{
  // Squares of side 3 in the plane 2x - 2y + z = 0 (cocircular ties).
  std::vector<Point> grid;
  for(int u = 0; u < 9; ++u)
    for(int v = 0; v < 7; ++v) grid.emplace_back(u + 2 * v, 2 * u + v, 2 * u - 2 * v);
  const std::vector<Point> points = shuffled(grid, 31);
  for(const bool cached : {false, true})
  for(const Point& apex : {Point(2, 1, 9), Point(2, 1, -9), Point(40, -3, 0)}) {
    SCOPED_TRACE("apex " + std::to_string(apex.x()) + " " + std::to_string(apex.z()) +
                 (cached ? ", sub-determinants cached" : ""));
    Fast_dt fast;
    fast.set_sub_determinants(cached);
    fast.insert(points.begin(), points.end());
    Cgal_dt cgal(points.begin(), points.end());
    ASSERT_EQ(fast.dimension(), 2);
    for(std::size_t k = 0; k < points.size(); k += 5) {
      fast.remove(fast.nearest_vertex(points[k]));
      cgal.remove(cgal.nearest_vertex(points[k]));
    }
    expect_same(fast, cgal);
    Fast_dt by_range = fast;
    fast.insert(apex);
    cgal.insert(apex);
    EXPECT_TRUE(fast.is_valid(true));
    expect_same(fast, cgal);
    // The apex and, in the same range, removed grid points and two more apexes.
    std::vector<Point> more = {apex, Point(apex.x() + 1, apex.y(), 2 * apex.z()), Point(1, 0, -apex.z())};
    for(std::size_t k = 0; k < points.size(); k += 5) more.push_back(points[k]);
    by_range.insert(more.begin(), more.end());
    std::vector<Point> all = points;
    all.insert(all.end(), more.begin(), more.end());
    EXPECT_TRUE(by_range.is_valid(true));
    expect_same(by_range, Cgal_dt(all.begin(), all.end()));
  }
}

// ---------------------------------------------------------------- queries

TEST(Queries, IsEdgeAndIsFacetBelowDimensionThree)
{
  std::vector<Point> plane;
  for(int u = 0; u < 5; ++u)
    for(int v = 0; v < 4; ++v) plane.emplace_back(u, v, 7);
  for(int line = 0; line < 2; ++line) {
    const std::vector<Point> points =
        line ? std::vector<Point>{Point(0, 0, 0), Point(1, 1, 1), Point(3, 3, 3), Point(2, 2, 2)} : plane;
    const Fast_dt fast(points.begin(), points.end());
    const Cgal_dt cgal(points.begin(), points.end());
    std::map<Point_key, Fast_dt::Vertex_handle> fast_vertex;
    std::map<Point_key, Cgal_dt::Vertex_handle> cgal_vertex;
    for(auto v = fast.finite_vertices_begin(); v != fast.finite_vertices_end(); ++v) fast_vertex[point_key(v->point())] = v;
    for(auto v = cgal.finite_vertices_begin(); v != cgal.finite_vertices_end(); ++v) cgal_vertex[point_key(v->point())] = v;
    std::size_t edges = 0, facets = 0;
    for(const auto& a : fast_vertex)
      for(const auto& b : fast_vertex) {
        Fast_dt::Cell_handle c;
        Cgal_dt::Cell_handle d;
        int i = 0, j = 0, k = 0, l = 0;
        const bool is_edge = fast.is_edge(a.second, b.second, c, i, j);
        ASSERT_EQ(is_edge, cgal.is_edge(cgal_vertex[a.first], cgal_vertex[b.first], d, k, l));
        if(!is_edge) continue;
        ++edges;
        EXPECT_TRUE(c->vertex(i) == a.second && c->vertex(j) == b.second);
        if(line) continue;
        for(const auto& w : fast_vertex) {
          int m = 0, n = 0;
          const bool is_facet = fast.is_facet(a.second, b.second, w.second, c, i, j, m);
          ASSERT_EQ(is_facet, cgal.is_facet(cgal_vertex[a.first], cgal_vertex[b.first], cgal_vertex[w.first], d, k, l, n));
          if(!is_facet) continue;
          ++facets;
          EXPECT_TRUE(c->vertex(i) == a.second && c->vertex(j) == b.second && c->vertex(m) == w.second);
        }
      }
    // CGAL 5.5 finds no edge in dimension 1 (it looks among incident cells).
    EXPECT_EQ(edges, line ? 0 : 2 * fast.number_of_finite_edges());
    EXPECT_EQ(facets, line ? 0 : 6 * fast.number_of_finite_facets());
  }
}

TEST(Queries, CellInfosOnTriangles)
{
  typedef CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Delaunay_triangulation_cell_base_3<K>> Cb;
  typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>, Cb> Tds;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds> Fast_info_dt;
  std::vector<Point> plane;
  for(const Xyz& q : uniform_points(40, 29)) plane.emplace_back(q.x, q.y, 1);
  const Fast_info_dt tr(plane.begin(), plane.end());
  ASSERT_EQ(tr.dimension(), 2);
  int label = 0;
  for(auto f = tr.all_facets_begin(); f != tr.all_facets_end(); ++f) f->first->info() = ++label;
  // Read back through the neighbours: every triangle is some triangle's neighbour.
  std::map<int, int> seen;
  for(auto f = tr.all_facets_begin(); f != tr.all_facets_end(); ++f)
    for(int i = 0; i < 3; ++i) ++seen[f->first->neighbor(i)->info()];
  EXPECT_EQ(seen.size(), std::size_t(label));
  for(const auto& s : seen) EXPECT_EQ(s.second, 3) << "triangle " << s.first;
}

// ---------------------------------------------------------------- validity

TEST(Validity, DetectsBrokenLowerDimensionalCells)
{
  using namespace CGAL::Fast_Delaunay_triangulation_3_internal;
  std::vector<double> xyz;
  for(int u = 0; u < 4; ++u)
    for(int v = 0; v < 4; ++v) xyz.insert(xyz.end(), {double(u), double(v) + 0.1 * u, 2.0});
  Triangulation_core core;
  core.insert(xyz.data(), xyz.size() / 3, nullptr);
  ASSERT_EQ(core.dimension, 2);
  ASSERT_TRUE(core.is_valid());
  const Tet_id finite = [&] {
    for(Tet_id t = 0;; ++t)
      if(std::find(core.mesh.tets[t].v, core.mesh.tets[t].v + 3, ghost_vertex) == core.mesh.tets[t].v + 3) return t;
  }();
  {
    // Reversed triangle: orientation of neighbours and adjacency break.
    Triangulation_core broken = core;
    std::swap(broken.mesh.tets[finite].v[0], broken.mesh.tets[finite].v[1]);
    EXPECT_FALSE(broken.is_valid());
  }
  {
    // A used slot above the dimension.
    Triangulation_core broken = core;
    broken.mesh.tets[finite].v[3] = 0;
    EXPECT_FALSE(broken.is_valid());
  }
  {
    // A vertex off the plane.
    Triangulation_core broken = core;
    broken.mesh.vertices[broken.mesh.tets[finite].v[0]].xyz[2] += 1;
    EXPECT_FALSE(broken.is_valid());
  }
  {
    // The vertex beyond an inner edge moved to the centroid of the triangle:
    // inside its circumcircle.
    Triangulation_core broken = core;
    Flat_storage& m = broken.mesh;
    bool moved = false;
    for(int i = 0; i < 3 && !moved; ++i) {
      const Vertex_id w = m.vertex(tet_of(m.neighbor_code(finite, i)), facet_of(m.neighbor_code(finite, i)));
      if(w == ghost_vertex) continue;
      for(int a = 0; a < 3; ++a)
        m.vertices[w].xyz[a] = (m.point(m.vertex(finite, 0))[a] + m.point(m.vertex(finite, 1))[a] +
                                m.point(m.vertex(finite, 2))[a]) / 3;
      moved = true;
    }
    ASSERT_TRUE(moved);
    std::string why;
    EXPECT_FALSE(broken.is_valid(&why));
    EXPECT_FALSE(why.empty());
  }
  {
    // A finite triangle rotated (vertices and neighbours together): still a
    // valid triangulation, but no longer the copy of CGAL's triangulation
    // that answers the queries.
    Triangulation_core broken = core;
    Flat_storage& m = broken.mesh;
    const Tet_record r = m.tets[finite];
    for(int i = 0; i < 3; ++i) {
      m.tets[finite].v[i] = r.v[(i + 1) % 3];
      m.tets[finite].n[i] = r.n[(i + 1) % 3];
    }
    for(int i = 0; i < 3; ++i) m.neighbor_code(m.tets[finite].n[i]) = facet_code(finite, i);
    EXPECT_TRUE(lower_dimensional_cells_are_valid(m, 2, nullptr));
    std::string why;
    EXPECT_FALSE(broken.is_valid(&why));
    EXPECT_NE(why.find("CGAL"), std::string::npos) << why;
  }
  {
    std::vector<double> line = {0, 0, 0, 1, 1, 1, 2, 2, 2, 3, 3, 3};
    Triangulation_core collinear;
    collinear.insert(line.data(), 4, nullptr);
    ASSERT_EQ(collinear.dimension, 1);
    ASSERT_TRUE(collinear.is_valid());
    // Two vertices trade places: the chain is no longer in order along the line.
    std::swap(collinear.mesh.vertices[0].xyz, collinear.mesh.vertices[1].xyz);
    EXPECT_FALSE(collinear.is_valid());
  }
}

} // namespace test_lower_dimensions
