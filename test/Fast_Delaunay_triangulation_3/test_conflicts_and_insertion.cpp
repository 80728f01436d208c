// Conflict zones and the insertion overloads of CGAL's
// Delaunay_triangulation_3 (find_conflicts with two and three iterators,
// vertices_on_conflict_zone_boundary, insert_in_hole, insert with a cell, a
// vertex or a location as hint, insert_and_give_new_cells), compared with
// CGAL::Delaunay_triangulation_3 on the same points.  Cells and facets are
// compared as sorted point tuples (the infinite vertex as a point at
// infinity): the two triangulations are the same, only their numbering and
// the order of the outputs differ.  The integer grid makes many query points
// cospherical with cells, where only the symbolic perturbation decides
// whether a cell is in conflict.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <cmath>
#include <deque>
#include <iterator>
#include <limits>
#include <list>
#include <set>
#include <string>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_conflicts_and_insertion {

template <class Tr>
std::array<Point_key, 3> facet_key(const Tr& tr, const typename Tr::Facet& f)
{
  std::array<Point_key, 3> k;
  for(int i = 0, j = 0; i < 4; ++i)
    if(i != f.second) k[j++] = vertex_point_key(tr, f.first->vertex(i));
  std::sort(k.begin(), k.end());
  return k;
}

struct Zone
{
  std::vector<std::array<Point_key, 4>> cells;
  // A boundary facet with the cell in conflict it was reported from.
  std::vector<std::pair<std::array<Point_key, 3>, std::array<Point_key, 4>>> boundary;
  std::vector<std::array<Point_key, 3>> internal;
  std::vector<Point_key> boundary_vertices;
  friend bool operator==(const Zone& a, const Zone& b)
  {
    return a.cells == b.cells && a.boundary == b.boundary && a.internal == b.internal &&
           a.boundary_vertices == b.boundary_vertices;
  }
};

// The conflict zone of a query that is no vertex, from the cell locate()
// gives, with every form of the query; checks what one triangulation can
// check by itself.
template <class Tr>
Zone conflict_zone(const Tr& tr, const Point& p)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Facet Facet;
  typedef typename Tr::Vertex_handle Vertex_handle;
  const Cell_handle c = tr.locate(p);
  std::vector<Facet> boundary, internal, boundary2;
  std::vector<Cell_handle> cells, cells2;
  tr.find_conflicts(p, c, std::back_inserter(boundary), std::back_inserter(cells), std::back_inserter(internal));
  tr.find_conflicts(p, c, std::back_inserter(boundary2), std::back_inserter(cells2));
  EXPECT_TRUE(boundary == boundary2 && cells == cells2) << "two- and three-iterator forms differ";
  std::vector<Vertex_handle> vertices, vertices2;
  tr.vertices_on_conflict_zone_boundary(p, c, std::back_inserter(vertices));
  tr.vertices_in_conflict(p, c, std::back_inserter(vertices2));
  EXPECT_TRUE(vertices == vertices2);

  Zone z;
  std::set<Cell_handle> in_zone(cells.begin(), cells.end());
  EXPECT_EQ(in_zone.size(), cells.size()) << "a cell reported twice";
  for(Cell_handle x : cells) {
    z.cells.push_back(cell_point_keys(tr, x));
    EXPECT_EQ(tr.side_of_sphere(x, p, true), CGAL::ON_BOUNDED_SIDE);
  }
  for(const Facet& f : boundary) {
    EXPECT_EQ(in_zone.count(f.first), 1u);
    EXPECT_EQ(in_zone.count(f.first->neighbor(f.second)), 0u);
    z.boundary.emplace_back(facet_key(tr, f), cell_point_keys(tr, f.first));
  }
  for(const Facet& f : internal) {
    EXPECT_EQ(in_zone.count(f.first), 1u);
    EXPECT_EQ(in_zone.count(f.first->neighbor(f.second)), 1u);
    z.internal.push_back(facet_key(tr, f));
  }
  // Euler on the zone, a topological ball: 4 C = 2 I + B.
  EXPECT_EQ(4 * cells.size(), 2 * internal.size() + boundary.size());
  for(Vertex_handle v : vertices) z.boundary_vertices.push_back(vertex_point_key(tr, v));
  std::sort(z.cells.begin(), z.cells.end());
  std::sort(z.boundary.begin(), z.boundary.end());
  std::sort(z.internal.begin(), z.internal.end());
  std::sort(z.boundary_vertices.begin(), z.boundary_vertices.end());
  EXPECT_TRUE(std::adjacent_find(z.boundary_vertices.begin(), z.boundary_vertices.end()) ==
              z.boundary_vertices.end());
  return z;
}

struct Case
{
  std::string name;
  std::vector<Point> points;
  std::vector<Point> queries; // no vertex among them
};

// Uniform points with queries inside and outside the hull; the 5x5x5 grid
// with queries at the centres of unit cubes, squares and edges (where the
// perturbation chose how each cube is split) and outside it, in hull planes
// too; integer points on a sphere.
std::vector<Case> cases()
{
  std::vector<Case> all;
  Case uniform{"uniform", to_points<Point>(make_points("uniform", 400, 31)), {}};
  for(const Xyz& r : uniform_points(150, 32)) uniform.queries.emplace_back(2 * r.x - 0.5, 2 * r.y - 0.5, 2 * r.z - 0.5);
  all.push_back(uniform);

  Case grid{"grid", {}, {}};
  for(int i = 0; i < 5; ++i)
    for(int j = 0; j < 5; ++j)
      for(int k = 0; k < 5; ++k) grid.points.emplace_back(i, j, k);
  for(double x : {0.5, 1.5, 3.5})
    for(double y : {0.0, 1.5, 2.5})
      for(double z : {0.5, 2.0, 3.5}) grid.queries.emplace_back(x, y, z);
  for(const Point& q : {Point(-1, 2, 2), Point(2, 2, 5), Point(5.5, 5.5, 5.5), Point(0, 1.5, -0.5),
                        Point(2, 0, 4.5), Point(4, 4, 6), Point(-0.5, -0.5, 2), Point(0, 0.5, 0.5)})
    grid.queries.push_back(q);
  all.push_back(grid);

  // Every other integer point of the sphere x^2 + y^2 + z^2 = 89, and a few
  // inside: most cells have that sphere as circumsphere, and the withheld
  // points, on it, tie with all of them.
  Case sphere{"cospherical", {}, {}};
  bool take = true;
  for(int x = -9; x <= 9; ++x)
    for(int y = -9; y <= 9; ++y)
      for(int z = -9; z <= 9; ++z) {
        if(x * x + y * y + z * z != 89) continue;
        (take ? sphere.points : sphere.queries).emplace_back(x, y, z);
        take = !take;
      }
  for(const Point& q : {Point(0, 0, 0), Point(1, 2, -3), Point(-4, 1, 0)}) sphere.points.push_back(q);
  for(const Point& q : {Point(0, 0, 12), Point(2, 2, 2), Point(9.5, 0, 0)}) sphere.queries.push_back(q);
  all.push_back(sphere);
  return all;
}

class Conflicts : public ::testing::TestWithParam<int> {};

TEST_P(Conflicts, FindConflictsGivesCgalZoneAndChangesNothing)
{
  const Case c = cases()[GetParam()];
  const Fast_dt fast(c.points.begin(), c.points.end());
  const Cgal_dt cgal(c.points.begin(), c.points.end());
  const std::vector<Cell_key> cells_before = finite_cell_keys(fast);
  std::size_t ties = 0;
  for(const Point& q : c.queries) {
    const Zone ours = conflict_zone(fast, q);
    const Zone theirs = conflict_zone(cgal, q);
    EXPECT_TRUE(ours == theirs) << c.name << ": zone of (" << q << ") differs from CGAL's";
    for(auto x = cgal.all_cells_begin(); x != cgal.all_cells_end(); ++x)
      if(cgal.side_of_sphere(x, q, false) == CGAL::ON_BOUNDARY) ++ties;
  }
  if(c.name == "cospherical") {
    EXPECT_GT(ties, 100u) << "the queries must hit cospherical ties";
  }
  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_TRUE(finite_cell_keys(fast) == cells_before);
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

// insert_in_hole of the zone find_conflicts gives, query after query, builds
// the triangulation CGAL's insert builds.
TEST_P(Conflicts, InsertInHoleOfTheZoneIsCgalInsert)
{
  const Case c = cases()[GetParam()];
  Fast_dt fast(c.points.begin(), c.points.end());
  Cgal_dt cgal(c.points.begin(), c.points.end());
  for(const Point& q : c.queries) {
    const Fast_dt::Cell_handle start = fast.locate(q);
    std::vector<Fast_dt::Facet> boundary;
    std::vector<Fast_dt::Cell_handle> zone;
    fast.find_conflicts(q, start, std::back_inserter(boundary), std::back_inserter(zone));
    const std::size_t cells_before = fast.number_of_cells();
    const Fast_dt::Vertex_handle v =
        fast.insert_in_hole(q, zone.begin(), zone.end(), boundary.front().first, boundary.front().second);
    EXPECT_TRUE(v->point() == q);
    EXPECT_EQ(fast.number_of_cells(), cells_before + boundary.size() - zone.size());
    std::vector<Fast_dt::Cell_handle> around;
    fast.incident_cells(v, std::back_inserter(around));
    EXPECT_EQ(around.size(), boundary.size());
    cgal.insert(q);
  }
  ASSERT_TRUE(fast.is_valid(true));
  EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
  EXPECT_TRUE(hull_facet_keys(fast) == hull_facet_keys(cgal));
}

INSTANTIATE_TEST_SUITE_P(Inputs, Conflicts, ::testing::Values(0, 1, 2),
                         [](const ::testing::TestParamInfo<int>& info) { return cases()[info.param].name; });

enum class Overload { cell, vertex, location, new_cells_cell, new_cells_vertex, new_cells_location };

// Inserts the points one at a time with one hint overload, the hint being
// the previous answer (the idiom of CGAL's examples), a far cell, the
// infinite cell or the infinite vertex in turn.  The first points, below
// dimension 3, take the same overloads (locate's answer included).
template <class Tr>
void insert_one_by_one(Tr& tr, const std::vector<Point>& points, Overload how)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  Vertex_handle previous;
  std::size_t k = 0;
  for(const Point& p : points) {
    Cell_handle cell_hint = previous == Vertex_handle() ? Cell_handle() : previous->cell();
    Vertex_handle vertex_hint = previous;
    if(tr.dimension() == 3 && k % 7 == 3) {
      cell_hint = tr.infinite_cell();
      vertex_hint = tr.infinite_vertex();
    } else if(tr.dimension() == 3 && k % 7 == 5) {
      cell_hint = tr.finite_cells_begin();
      vertex_hint = tr.finite_vertices_begin();
    }
    std::vector<Cell_handle> new_cells;
    const std::size_t before = tr.number_of_vertices();
    Vertex_handle v;
    typename Tr::Locate_type lt = Tr::OUTSIDE_AFFINE_HULL;
    int li = -1, lj = -1;
    Cell_handle located;
    located = tr.locate(p, lt, li, lj, cell_hint);
    switch(how) {
    case Overload::cell: v = tr.insert(p, cell_hint); break;
    case Overload::vertex: v = tr.insert(p, vertex_hint); break;
    case Overload::location:
      v = tr.insert(p, lt, located, li, lj);
      break;
    case Overload::new_cells_cell: v = tr.insert_and_give_new_cells(p, std::back_inserter(new_cells), cell_hint); break;
    case Overload::new_cells_vertex:
      v = tr.insert_and_give_new_cells(p, std::back_inserter(new_cells), vertex_hint);
      break;
    case Overload::new_cells_location:
      v = tr.insert_and_give_new_cells(p, lt, located, li, lj, std::back_inserter(new_cells));
      break;
    }
    EXPECT_TRUE(v->point() == p);
    EXPECT_EQ(tr.number_of_vertices(), before + (lt == Tr::VERTEX ? 0 : 1));
    const bool gives_cells = how == Overload::new_cells_cell || how == Overload::new_cells_vertex ||
                             how == Overload::new_cells_location;
    if(gives_cells && tr.dimension() == 3) {
      std::vector<Cell_handle> around;
      tr.incident_cells(v, std::back_inserter(around));
      EXPECT_TRUE(std::set<Cell_handle>(new_cells.begin(), new_cells.end()) ==
                  std::set<Cell_handle>(around.begin(), around.end()));
      EXPECT_EQ(new_cells.size(), around.size());
    }
    previous = v;
    ++k;
  }
}

TEST(HintedInsertion, EveryOverloadBuildsCgalsTriangulation)
{
  for(const std::string name : {"uniform", "grid"}) {
    std::vector<Point> points = to_points<Point>(make_points(name, 300, 41));
    // Duplicates, given again later: each returns the existing vertex.
    for(std::size_t i = 0; i < 30; ++i) points.push_back(points[7 * i]);
    const Cgal_dt cgal(points.begin(), points.end());
    for(Overload how : {Overload::cell, Overload::vertex, Overload::location, Overload::new_cells_cell,
                        Overload::new_cells_vertex, Overload::new_cells_location}) {
      Fast_dt fast;
      insert_one_by_one(fast, points, how);
      ASSERT_TRUE(fast.is_valid(true)) << name;
      EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices()) << name;
      EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal)) << name << " overload " << int(how);
      // The same loop on CGAL gives the same new cells: checked by points.
      if(how == Overload::new_cells_cell) {
        Cgal_dt reference;
        insert_one_by_one(reference, points, how);
        EXPECT_TRUE(finite_cell_keys(reference) == finite_cell_keys(cgal));
      }
    }
  }
}

// The new cells of one insertion, as point tuples, equal CGAL's; a point
// already present gives the cells around its vertex, as CGAL does.
TEST(HintedInsertion, NewCellsAreCgals)
{
  const std::vector<Point> points = to_points<Point>(make_points("grid", 125, 43));
  std::vector<Point> more = points;
  for(const Xyz& r : uniform_points(60, 44)) more.emplace_back(5 * r.x - 0.5, 5 * r.y - 0.5, 5 * r.z - 0.5);
  more.emplace_back(1.5, 1.5, 1.5);
  more.emplace_back(2, 2, 2); // a vertex
  Fast_dt fast(points.begin(), points.end());
  Cgal_dt cgal(points.begin(), points.end());
  for(std::size_t i = points.size(); i < more.size(); ++i) {
    std::vector<Fast_dt::Cell_handle> ours;
    std::vector<Cgal_dt::Cell_handle> theirs;
    fast.insert_and_give_new_cells(more[i], std::back_inserter(ours));
    cgal.insert_and_give_new_cells(more[i], std::back_inserter(theirs));
    std::vector<std::array<Point_key, 4>> a, b;
    for(auto c : ours) a.push_back(cell_point_keys(fast, c));
    for(auto c : theirs) b.push_back(cell_point_keys(cgal, c));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_TRUE(a == b) << "new cells of (" << more[i] << ")";
  }
  EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
}

// insert(p, v) keeps the v->cell() cache exact without rebuilding it: every
// vertex's cell has it, after insertions that destroyed cached cells.
TEST(HintedInsertion, VertexCellsStayRightAcrossHintedInsertions)
{
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 500, 45));
  Fast_dt fast(points.begin(), points.begin() + 100);
  Fast_dt::Vertex_handle hint = fast.finite_vertices_begin();
  (void)hint->cell(); // builds the cache
  for(std::size_t i = 100; i < points.size(); ++i) {
    hint = fast.insert(points[i], hint);
    if(i % 50 != 0) continue;
    for(auto v = fast.finite_vertices_begin(); v != fast.finite_vertices_end(); ++v) {
      ASSERT_TRUE(v->cell()->has_vertex(v)) << "stale v->cell() after " << i << " insertions";
    }
  }
  for(auto v = fast.all_vertices_begin(); v != fast.all_vertices_end(); ++v) {
    ASSERT_TRUE(v->cell()->has_vertex(Fast_dt::Vertex_handle(v)));
  }
  const Cgal_dt cgal(points.begin(), points.end());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
}

// insert_and_give_vertices (not in CGAL) gives, in input order, the vertex at
// each point: a new vertex, an older one, or for a duplicate within the range
// the vertex of its first copy; the triangulation is CGAL's of all points, in
// every dimension the points span.
TEST(BulkInsertion, GivesTheVertexOfEveryInputPoint)
{
  for(const std::string name : {"uniform", "grid", "coplanar", "collinear"}) {
    const bool flat = name == "coplanar" || name == "collinear";
    std::vector<Point> points = to_points<Point>(make_points(flat ? "uniform" : name, 200, 47));
    for(Point& p : points)
      if(flat) p = Point(p.x(), name == "coplanar" ? p.y() : 2 * p.x(), 0);
    Fast_dt fast(points.begin(), points.begin() + 50);
    for(std::size_t i = 0; i < 40; ++i) points.push_back(points[5 * i]);
    std::vector<Fast_dt::Vertex_handle> vertices;
    fast.insert_and_give_vertices(points.begin() + 50, points.end(), std::back_inserter(vertices));
    ASSERT_EQ(vertices.size(), points.size() - 50) << name;
    for(std::size_t i = 0; i < vertices.size(); ++i)
      ASSERT_EQ(vertices[i]->point(), points[50 + i]) << name << " point " << 50 + i;
    for(std::size_t i = 10; i < 40; ++i) {
      EXPECT_EQ(vertices[200 - 50 + i], vertices[5 * i - 50]) << name << " duplicate " << i;
    }
    const Cgal_dt cgal(points.begin(), points.end());
    ASSERT_TRUE(fast.is_valid()) << name;
    EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices()) << name;
    EXPECT_EQ(fast.dimension(), cgal.dimension()) << name;
    if(cgal.dimension() == 3) {
      EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal)) << name;
    }
  }
  Fast_dt fast;
  const Point bad[] = {Point(0, 0, 0), Point(std::numeric_limits<double>::quiet_NaN(), 0, 0)};
  std::vector<Fast_dt::Vertex_handle> none;
  EXPECT_THROW(fast.insert_and_give_vertices(bad, bad + 2, std::back_inserter(none)), std::invalid_argument);
  EXPECT_EQ(fast.number_of_vertices(), 0u);
  EXPECT_TRUE(none.empty());
}

// Arrays of points (pointers, std::vector) are read where they are, other
// ranges copied first: the same triangulation (CGAL's) and vertices either
// way, in every dimension, duplicates included; the triangulation keeps its
// own copy of the points (the array may change afterwards).
TEST(BulkInsertion, ArraysAndOtherRangesGiveTheSameTriangulation)
{
  for(const std::string name : {"uniform", "coplanar"}) {
    std::vector<Point> points = to_points<Point>(make_points("uniform", 3000, 53));
    if(name == "coplanar")
      for(Point& p : points) p = Point(p.x(), p.y(), 0.25);
    for(std::size_t i = 0; i < 100; ++i) points.push_back(points[7 * i]);
    const std::list<Point> listed(points.begin(), points.end());
    const std::deque<Point> queued(points.begin(), points.end());
    const Cgal_dt cgal(points.begin(), points.end());
    auto expect_cgals = [&](const Fast_dt& fast, const char* range) {
      SCOPED_TRACE(name + ", from " + range);
      ASSERT_TRUE(fast.is_valid());
      EXPECT_EQ(fast.dimension(), cgal.dimension());
      EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
      EXPECT_TRUE(finite_vertex_keys(fast) == finite_vertex_keys(cgal));
      EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));
    };
    std::vector<Point> array = points;
    Fast_dt from_array;
    EXPECT_EQ(from_array.insert(array.data(), array.data() + array.size()), std::ptrdiff_t(3000));
    for(Point& p : array) p = Point(9, 9, 9);
    expect_cgals(from_array, "a pointer range, then overwritten");
    expect_cgals(Fast_dt(points.cbegin(), points.cend()), "a vector");
    expect_cgals(Fast_dt(listed.begin(), listed.end()), "a list");
    expect_cgals(Fast_dt(queued.begin(), queued.end()), "a deque");

    Fast_dt half(points.begin(), points.begin() + 1500), half_too(points.begin(), points.begin() + 1500);
    std::vector<Fast_dt::Vertex_handle> in_place, copied;
    half.insert_and_give_vertices(points.begin() + 1500, points.end(), std::back_inserter(in_place));
    half_too.insert_and_give_vertices(std::next(listed.begin(), 1500), listed.end(), std::back_inserter(copied));
    ASSERT_EQ(in_place.size(), copied.size());
    for(std::size_t i = 0; i < in_place.size(); ++i) {
      ASSERT_EQ(in_place[i]->point(), points[1500 + i]) << name << " point " << 1500 + i;
      ASSERT_EQ(copied[i]->point(), points[1500 + i]) << name << " point " << 1500 + i;
    }
    expect_cgals(half, "insert_and_give_vertices on a vector");
    expect_cgals(half_too, "insert_and_give_vertices on a list");
  }
}

// insert_coordinates_and_give_vertices (not in CGAL; the Python module's
// entry) reads x, y, z triples where they are: the vertices that
// insert_and_give_vertices gives for the same points, duplicates included,
// and a non-finite coordinate throws naming its point and changes nothing.
TEST(BulkInsertion, CoordinateTriplesGiveTheVerticesOfTheirPoints)
{
  std::vector<Point> points = to_points<Point>(make_points("uniform", 2000, 59));
  for(std::size_t i = 0; i < 50; ++i) points.push_back(points[11 * i]);
  std::vector<double> xyz;
  for(const Point& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  Fast_dt from_points(points.begin(), points.begin() + 500), from_triples(points.begin(), points.begin() + 500);
  std::vector<Fast_dt::Vertex_handle> by_points, by_triples;
  from_points.insert_and_give_vertices(points.begin() + 500, points.end(), std::back_inserter(by_points));
  from_triples.insert_coordinates_and_give_vertices(xyz.data() + 3 * 500, points.size() - 500,
                                                    std::back_inserter(by_triples));
  ASSERT_EQ(by_triples.size(), by_points.size());
  for(std::size_t i = 0; i < by_triples.size(); ++i) {
    ASSERT_EQ(by_triples[i]->point(), points[500 + i]) << "point " << 500 + i;
    ASSERT_EQ(by_points[i]->point(), points[500 + i]) << "point " << 500 + i;
  }
  for(std::size_t i = 0; i < 50; ++i)
    EXPECT_EQ(by_triples[points.size() - 550 + i]->point(), points[11 * i]);
  const Cgal_dt cgal(points.begin(), points.end());
  ASSERT_TRUE(from_triples.is_valid());
  EXPECT_EQ(from_triples.number_of_vertices(), cgal.number_of_vertices());
  EXPECT_TRUE(finite_cell_keys(from_triples) == finite_cell_keys(cgal));

  const std::vector<Point_key> vertices_before = finite_vertex_keys(from_triples);
  const std::vector<Cell_key> cells_before = finite_cell_keys(from_triples);
  xyz[3 * 700 + 1] = std::numeric_limits<double>::infinity();
  std::vector<Fast_dt::Vertex_handle> none;
  try {
    from_triples.insert_coordinates_and_give_vertices(xyz.data(), points.size(), std::back_inserter(none));
    ADD_FAILURE() << "no exception";
  } catch(const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("#700 "), std::string::npos) << e.what();
  }
  EXPECT_TRUE(none.empty());
  EXPECT_TRUE(finite_vertex_keys(from_triples) == vertices_before);
  EXPECT_TRUE(finite_cell_keys(from_triples) == cells_before);
}

// insert(p) in a loop, with points in random order, after a bulk insertion,
// after removals, and growing the box at every point: CGAL's triangulation,
// and walks of a few steps (they start from a grid of recent vertices; from
// the previous insertion a walk crossed ~n^(1/3) cells: 28 steps at 2e4).
TEST(OneByOneInsertion, CgalsTriangulationWithShortWalks)
{
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 6000, 49));
  Fast_dt fast;
  double steps = 0;
  std::size_t walks = 0;
  for(std::size_t i = 0; i < points.size(); ++i) {
    fast.insert(points[i]);
    if(i >= 1000) {
      steps += static_cast<double>(fast.last_insertion_report().kernel.walk_steps);
      ++walks;
    }
    if(i == 2000) fast.insert(points.begin(), points.begin() + 10); // bulk: duplicates only
    if(i == 3000) {
      std::vector<Fast_dt::Vertex_handle> some;
      for(std::size_t k = 0; k < 100; ++k) {
        Fast_dt::Vertex_handle v;
        if(fast.is_vertex(points[20 * k], v)) some.push_back(v);
      }
      fast.remove(some.begin(), some.end());
      for(std::size_t k = 0; k < 100; ++k) fast.insert(points[20 * k]);
    }
  }
  EXPECT_LT(steps / static_cast<double>(walks), 12.0);
  ASSERT_TRUE(fast.is_valid());
  const Cgal_dt cgal(points.begin(), points.end());
  EXPECT_TRUE(finite_cell_keys(fast) == finite_cell_keys(cgal));

  // Points along a line away from the origin: the box grows with each.
  Fast_dt growing;
  Cgal_dt reference;
  for(int i = 0; i < 2000; ++i) {
    const double t = 1 + i;
    const Point p(t, std::sin(t) * t, std::cos(3 * t) * t);
    growing.insert(p);
    reference.insert(p);
  }
  ASSERT_TRUE(growing.is_valid());
  EXPECT_TRUE(finite_cell_keys(growing) == finite_cell_keys(reference));
}

} // namespace test_conflicts_and_insertion
