// tds(): the combinatorial layer with CGAL's Triangulation_data_structure_3
// interface.  One templated body runs on CGAL::Delaunay_triangulation_3 and
// on ours: CGAL passing proves each assertion can hold, ours passing that
// the code written against CGAL's TDS runs unchanged.  The oracle is CGAL's
// TDS on the same points: counts, the cells a raw iteration visits, the
// cells after create_vertex + insert_in_hole, the cells after a 2-3 flip
// and after the 3-2 flip that undoes it.
#include "triangulation_checks.h"

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_simplex_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <vector>

using namespace fdt3_test;

namespace test_tds_interface {

typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;
#if defined(NDEBUG) || defined(CGAL_NDEBUG) || defined(CGAL_NO_ASSERTIONS) || \
    defined(CGAL_TRIANGULATION_NO_ASSERTIONS)
constexpr bool cgal_assertions_on = false;
#else
constexpr bool cgal_assertions_on = true;
#endif

template <class Tr>
struct Tds_interface : ::testing::Test
{
};
typedef ::testing::Types<Cgal_dt, Fast_dt> Both;
TYPED_TEST_SUITE(Tds_interface, Both);

template <class Tr>
std::vector<Cell_key> all_cell_keys(const Tr& tr)
{
  std::vector<Cell_key> keys;
  for(auto c = tr.cells_begin(); c != tr.cells_end(); ++c) keys.push_back(cell_point_keys(tr, c));
  std::sort(keys.begin(), keys.end());
  return keys;
}

std::vector<Point> coplanar_points(std::size_t n)
{
  std::vector<Point> points;
  for(const Xyz& p : uniform_points(n, 11)) points.push_back(Point(p.x, p.y, p.x)); // exactly on the plane z = x
  return points;
}

std::vector<Point> collinear_points(std::size_t n)
{
  std::vector<Point> points;
  for(const Xyz& p : uniform_points(n, 12)) points.push_back(Point(p.x, 2 * p.x, -p.x));
  return points;
}

std::vector<std::vector<Point>> inputs()
{
  return {to_points<Point>(uniform_points(200)), to_points<Point>(grid_points(125)), coplanar_points(60),
          collinear_points(8), std::vector<Point>(1, Point(1, 2, 3)), std::vector<Point>()};
}

// The counts of tds() and the number of cells a raw iteration, through the
// triangulation's Cell_iterator, visits.
template <class Tr>
struct Tds_counts
{
  std::size_t vertices, cells, facets, edges, raw_cells, iterated_vertices, iterated_facets, iterated_edges;
  int dimension;
};
template <class Tr>
Tds_counts<Tr> counts_of(const Tr& tr)
{
  typedef typename Tr::Triangulation_data_structure Tds;
  const Tds& tds = tr.tds();
  Tds_counts<Tr> k;
  k.vertices = tds.number_of_vertices();
  k.cells = tds.number_of_cells();
  k.facets = tds.number_of_facets();
  k.edges = tds.number_of_edges();
  k.raw_cells = 0;
  typename Tr::Cell_iterator cit;
  for(cit = tr.tds().raw_cells_begin(); cit != tr.tds().raw_cells_end(); ++cit) {
    typename Tr::Cell_handle ch = cit;
    EXPECT_TRUE(ch != typename Tr::Cell_handle());
    ++k.raw_cells;
  }
  k.iterated_vertices = static_cast<std::size_t>(std::distance(tds.vertices_begin(), tds.vertices_end()));
  k.iterated_facets = static_cast<std::size_t>(std::distance(tds.facets_begin(), tds.facets_end()));
  k.iterated_edges = static_cast<std::size_t>(std::distance(tds.edges_begin(), tds.edges_end()));
  k.dimension = tds.dimension();
  return k;
}
template <class A, class B>
bool same_counts(const Tds_counts<A>& a, const Tds_counts<B>& b)
{
  return a.vertices == b.vertices && a.cells == b.cells && a.facets == b.facets && a.edges == b.edges &&
         a.raw_cells == b.raw_cells && a.iterated_vertices == b.iterated_vertices &&
         a.iterated_facets == b.iterated_facets && a.iterated_edges == b.iterated_edges && a.dimension == b.dimension;
}

TYPED_TEST(Tds_interface, CountsAndRawCellsAreCgalTds)
{
  for(const std::vector<Point>& points : inputs()) {
    TypeParam tr(points.begin(), points.end());
    Cgal_dt cgal(points.begin(), points.end());
    EXPECT_TRUE(tr.tds().is_valid(true));
    const Tds_counts<TypeParam> mine = counts_of(tr);
    const Tds_counts<Cgal_dt> theirs = counts_of(cgal);
    EXPECT_TRUE(same_counts(mine, theirs)) << points.size() << " points, dimension " << tr.dimension() << ": "
                                           << mine.vertices << "/" << theirs.vertices << " vertices, "
                                           << mine.cells << "/" << theirs.cells << " cells, " << mine.facets << "/"
                                           << theirs.facets << " facets, " << mine.edges << "/" << theirs.edges
                                           << " edges, " << mine.raw_cells << "/" << theirs.raw_cells
                                           << " raw cells";
    EXPECT_EQ(tr.tds().number_of_vertices(), tr.number_of_vertices() + 1);
    // Every raw cell is a cell of the TDS in dimension 3, none below.
    for(auto c = tr.tds().raw_cells_begin(); c != tr.tds().raw_cells_end(); ++c)
      EXPECT_EQ(tr.tds().is_cell(c), tr.dimension() == 3);
  }
}

TYPED_TEST(Tds_interface, AdjacencyAndMembershipAreCgalTds)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  const std::vector<Point> points = to_points<Point>(uniform_points(100, 21));
  TypeParam tr(points.begin(), points.end());
  Cgal_dt cgal(points.begin(), points.end());
  for(const Point& p : std::vector<Point>{points[0], points[17], points[42]}) {
    Vertex_handle v;
    Cgal_dt::Vertex_handle w;
    ASSERT_TRUE(tr.is_vertex(p, v) && cgal.is_vertex(p, w));
    EXPECT_TRUE(tr.tds().is_vertex(v));
    EXPECT_TRUE(tr.tds().is_valid(v));
    EXPECT_EQ(tr.tds().degree(v), cgal.tds().degree(w));
    std::vector<Cell_handle> cells;
    tr.tds().incident_cells(v, std::back_inserter(cells));
    std::vector<Cgal_dt::Cell_handle> cgal_cells;
    cgal.tds().incident_cells(w, std::back_inserter(cgal_cells));
    EXPECT_EQ(cells.size(), cgal_cells.size());
    std::vector<Vertex_handle> around;
    tr.tds().adjacent_vertices(v, std::back_inserter(around));
    EXPECT_EQ(around.size(), cgal.tds().degree(w));
    for(Vertex_handle u : around) {
      Cell_handle c;
      int i, j;
      ASSERT_TRUE(tr.tds().is_edge(v, u, c, i, j));
      EXPECT_TRUE(c->vertex(i) == v && c->vertex(j) == u);
    }
    // A facet and its mirror.
    const Cell_handle c = cells.front();
    const int i = (c->index(v) + 1) % 4;
    const typename TypeParam::Facet f(c, i), g = tr.tds().mirror_facet(f);
    EXPECT_TRUE(g.first->neighbor(g.second) == c);
    EXPECT_EQ(tr.tds().mirror_index(c, i), g.second);
    Cell_handle fc;
    int fi, fj, fk;
    EXPECT_TRUE(
        tr.tds().is_facet(c->vertex((i + 1) % 4), c->vertex((i + 2) % 4), c->vertex((i + 3) % 4), fc, fi, fj, fk));
    EXPECT_TRUE(fc == c || fc == g.first);
    EXPECT_TRUE(tr.tds().is_cell(c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)));
    EXPECT_TRUE(tr.tds().is_valid(c));
    EXPECT_EQ(static_cast<std::size_t>(std::distance(tr.tds().facets().begin(), tr.tds().facets().end())),
              cgal.tds().number_of_facets());
    EXPECT_EQ(static_cast<std::size_t>(std::distance(tr.tds().edges().begin(), tr.tds().edges().end())),
              cgal.tds().number_of_edges());
    // The simplices of CGAL's Triangulation_simplex_3 over the TDS.
    CGAL::Triangulation_simplex_3<typename TypeParam::Triangulation_data_structure> sv(v), sc(c), sf(f);
    EXPECT_EQ(sv.dimension(), 0);
    EXPECT_EQ(sf.dimension(), 2);
    EXPECT_EQ(sc.dimension(), 3);
  }
}

// The segment simplex traverser read as CGAL's examples read it, into
// Triangulation_simplex_3<DT::Triangulation_data_structure>.  Random points,
// so the segment meets cells and the facets between them only: as many
// cells as CGAL's cell traverser visits, one facet fewer.  (CGAL's own
// simplex iterator is not run: under UBSan it binds a null reference here.)
TEST(Tds_view, SegmentSimplicesAsTriangulationSimplex3)
{
  typedef CGAL::Triangulation_simplex_3<Fast_dt::Triangulation_data_structure> Simplex;
  const std::vector<Point> points = to_points<Point>(uniform_points(200, 91));
  Fast_dt tr(points.begin(), points.end());
  Cgal_dt cgal(points.begin(), points.end());
  const Point p(0.1, 0.2, 0.3), q(0.8, 0.7, 0.75);
  std::array<int, 4> count = {0, 0, 0, 0};
  std::vector<Cell_key> cells;
  for(const Simplex s : tr.segment_traverser_simplices(p, q)) {
    ++count[s.dimension()];
    if(s.dimension() == 3) cells.push_back(cell_point_keys(tr, Fast_dt::Cell_handle(s)));
  }
  std::vector<Cell_key> cgal_cells;
  for(auto c = cgal.segment_traverser_cells_begin(p, q); c != cgal.segment_traverser_cells_end(); ++c)
    cgal_cells.push_back(cell_point_keys(cgal, Cgal_dt::Cell_handle(c)));
  EXPECT_TRUE(cells == cgal_cells);
  EXPECT_GT(count[3], 3);
  EXPECT_EQ(count[2], count[3] - 1);
  EXPECT_EQ(count[0] + count[1], 0);
}

// CGAL's test suite pattern: a vertex from tds().create_vertex() placed by
// insert_in_hole over the conflict zone of find_conflicts.
TYPED_TEST(Tds_interface, CreateVertexThenInsertInHoleGivesCgalCells)
{
  typedef typename TypeParam::Cell_handle Cell_handle;
  typedef typename TypeParam::Facet Facet;
  for(const std::vector<Point>& points : {to_points<Point>(uniform_points(150, 31)), coplanar_points(40)}) {
    TypeParam tr(points.begin(), points.end());
    const Point p = tr.dimension() == 3 ? Point(0.31, 0.52, 0.47) : Point(0.3, 0.4, 0.3);
    typename TypeParam::Locate_type lt;
    int li, lj;
    const Cell_handle c = tr.locate(p, lt, li, lj);
    ASSERT_TRUE(lt == TypeParam::CELL || lt == TypeParam::FACET);
    std::vector<Facet> boundary;
    std::vector<Cell_handle> cells;
    tr.find_conflicts(p, c, std::back_inserter(boundary), std::back_inserter(cells));
    const typename TypeParam::Vertex_handle newv = tr.tds().create_vertex();
    EXPECT_TRUE(tr.tds().is_vertex(newv));
    const typename TypeParam::Vertex_handle v =
        tr.insert_in_hole(p, cells.begin(), cells.end(), boundary.front().first, boundary.front().second, newv);
    EXPECT_TRUE(v == newv);
    EXPECT_TRUE(v->point() == p);
    EXPECT_TRUE(tr.tds().is_valid(true));
    EXPECT_TRUE(tr.is_valid(true));
    std::vector<Point> more = points;
    more.push_back(p);
    Cgal_dt cgal(more.begin(), more.end());
    EXPECT_EQ(tr.number_of_vertices(), cgal.number_of_vertices());
    EXPECT_TRUE(same_counts(counts_of(tr), counts_of(cgal)));
    EXPECT_TRUE(finite_cell_keys(tr) == finite_cell_keys(cgal)) << "dimension " << tr.dimension();
    if(tr.dimension() == 3) {
      EXPECT_TRUE(all_cell_keys(tr) == all_cell_keys(cgal));
    }
  }
}

// Point after point through the conflict zone, every other one with a
// created vertex (the pattern of CGAL's own test suite), from one point on:
// points that lift the dimension go through insert().  tds().is_valid()
// after each, and at the end CGAL's cells.
TYPED_TEST(Tds_interface, InsertInHoleLoopThroughDimensions)
{
  typedef typename TypeParam::Cell_handle Cell_handle;
  typedef typename TypeParam::Facet Facet;
  std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0), Point(0.5, 0.25, 0)};
  for(const Xyz& p : uniform_points(60, 71)) points.push_back(Point(p.x, p.y, p.z));
  TypeParam tr;
  for(std::size_t n = 0; n < points.size(); ++n) {
    const Point& p = points[n];
    typename TypeParam::Locate_type lt;
    int li, lj;
    const Cell_handle c = tr.locate(p, lt, li, lj);
    if(lt == TypeParam::VERTEX) continue;
    if(tr.dimension() < 2 || lt == TypeParam::OUTSIDE_AFFINE_HULL) {
      tr.insert(p);
    } else {
      std::vector<Facet> boundary;
      std::vector<Cell_handle> cells;
      tr.find_conflicts(p, c, std::back_inserter(boundary), std::back_inserter(cells));
      if(n % 2 == 0) {
        tr.insert_in_hole(p, cells.begin(), cells.end(), boundary.front().first, boundary.front().second);
      } else {
        const typename TypeParam::Vertex_handle v = tr.tds().create_vertex();
        tr.insert_in_hole(p, cells.begin(), cells.end(), boundary.front().first, boundary.front().second, v);
      }
    }
    ASSERT_TRUE(tr.tds().is_valid(true)) << "after point " << n << ", dimension " << tr.dimension();
  }
  EXPECT_TRUE(tr.is_valid(true));
  Cgal_dt cgal(points.begin(), points.end());
  EXPECT_TRUE(all_cell_keys(tr) == all_cell_keys(cgal));
  EXPECT_EQ(tr.number_of_vertices(), cgal.number_of_vertices());
}

// Moves that change the dimension both ways (CGAL's test suite checks
// tds().is_valid() after each): the TDS stays valid in every dimension.
TYPED_TEST(Tds_interface, MovesThroughDimensionsKeepTdsValid)
{
  TypeParam tr;
  const typename TypeParam::Vertex_handle a = tr.insert(Point(0, 0, 0));
  tr.insert(Point(0, 1, 0));
  EXPECT_TRUE(tr.tds().is_valid(true));
  tr.move_if_no_collision(a, Point(0, 2, 1));
  EXPECT_TRUE(tr.tds().is_valid(true));
  EXPECT_EQ(tr.dimension(), 1);
  const typename TypeParam::Vertex_handle b = tr.insert(Point(0, 3, 5));
  EXPECT_EQ(tr.dimension(), 2);
  const typename TypeParam::Vertex_handle c = tr.insert(Point(0, 1, 1));
  tr.move_if_no_collision(b, Point(1, 1, 1));
  EXPECT_EQ(tr.dimension(), 3);
  EXPECT_TRUE(tr.tds().is_valid(true));
  tr.move_if_no_collision(b, Point(0, 2, 0));
  EXPECT_EQ(tr.dimension(), 2);
  EXPECT_TRUE(tr.tds().is_valid(true));
  tr.move_if_no_collision(c, Point(0, 3, 0));
  EXPECT_EQ(tr.dimension(), 2);
  EXPECT_TRUE(tr.tds().is_valid(true));
  tr.move_if_no_collision(a, Point(0, 4, 0));
  EXPECT_EQ(tr.dimension(), 1);
  EXPECT_TRUE(tr.tds().is_valid(true));
  EXPECT_TRUE(tr.is_valid(true));
}

// A 2-3 flip of a finite interior facet, then the 3-2 flip of the new edge:
// one cell more, then the same cells as before.  The flips are
// combinatorial: after the first the triangulation is no longer Delaunay
// (random points: no four cospherical), which is_valid() reports on both.
TYPED_TEST(Tds_interface, FlipTwoThreeThenThreeTwoBack)
{
  typedef typename TypeParam::Cell_handle Cell_handle;
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  const std::vector<Point> points = to_points<Point>(uniform_points(120, 41));
  TypeParam tr(points.begin(), points.end());
  Cgal_dt cgal(points.begin(), points.end());
  const std::vector<Cell_key> before = all_cell_keys(tr);
  ASSERT_TRUE(before == all_cell_keys(cgal));
  const std::size_t cells = tr.tds().number_of_cells();

  // The first finite facet in point order whose 2-3 flip is convex: the same
  // facet on both triangulations.
  std::vector<std::pair<Facet_key, std::pair<Point, Point>>> candidates;
  for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f) {
    const Cell_handle c = f->first, n = c->neighbor(f->second);
    if(tr.is_infinite(c) || tr.is_infinite(n)) continue;
    const Point p = c->vertex(f->second)->point(), q = tr.mirror_vertex(c, f->second)->point();
    Point t[3];
    for(int k = 1, a = 0; k < 4; ++k) t[a++] = c->vertex((f->second + k) % 4)->point();
    // p q crosses the triangle: the three new cells are positively oriented.
    if(CGAL::orientation(p, q, t[0], t[1]) == CGAL::orientation(p, q, t[1], t[2]) &&
       CGAL::orientation(p, q, t[1], t[2]) == CGAL::orientation(p, q, t[2], t[0])) {
      Facet_key key = {point_key(t[0]), point_key(t[1]), point_key(t[2])};
      std::sort(key.begin(), key.end());
      candidates.push_back({key, {p, q}});
    }
  }
  ASSERT_FALSE(candidates.empty());
  const auto chosen = *std::min_element(candidates.begin(), candidates.end(),
                                        [](const auto& a, const auto& b) { return a.first < b.first; });
  Vertex_handle p, q;
  ASSERT_TRUE(tr.is_vertex(chosen.second.first, p) && tr.is_vertex(chosen.second.second, q));
  EXPECT_FALSE(tr.tds().is_edge(p, q));
  Cell_handle c;
  int i = -1, j = -1, k = -1;
  // The cell with p opposite the chosen facet.
  bool found = false;
  std::vector<Cell_handle> around;
  tr.incident_cells(p, std::back_inserter(around));
  for(Cell_handle x : around) {
    const int at = x->index(p);
    if(!tr.is_infinite(x) && tr.mirror_vertex(x, at) == q) {
      c = x;
      i = at;
      found = true;
    }
  }
  ASSERT_TRUE(found);
  ASSERT_TRUE(tr.tds().flip(c, i));
  EXPECT_EQ(tr.tds().number_of_cells(), cells + 1);
  EXPECT_TRUE(tr.tds().is_valid(true));
  // CGAL's is_valid() asserts where assertions are on instead of returning false.
  if(!std::is_same<TypeParam, Cgal_dt>::value || !cgal_assertions_on) {
    EXPECT_FALSE(tr.is_valid());
  }
  EXPECT_TRUE(tr.tds().is_edge(p, q));
  // Not flippable again: the edge is there now.
  ASSERT_TRUE(tr.tds().is_edge(p, q, c, i, j));
  k = tr.next_around_edge(i, j);
  EXPECT_FALSE(tr.tds().flip(c, k)) << "the facet's new edge would be an existing edge";

  // Back: the new edge has degree 3.
  ASSERT_TRUE(tr.tds().is_edge(p, q, c, i, j));
  ASSERT_TRUE(tr.tds().flip(typename TypeParam::Edge(c, i, j)));
  EXPECT_EQ(tr.tds().number_of_cells(), cells);
  EXPECT_TRUE(tr.tds().is_valid(true));
  EXPECT_TRUE(tr.is_valid(true));
  EXPECT_TRUE(all_cell_keys(tr) == before);
  EXPECT_FALSE(tr.tds().is_edge(p, q));
}

// An edge of degree other than 3 is not flipped; nothing changes.
TYPED_TEST(Tds_interface, ThreeTwoFlipRefusesOtherDegrees)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(120, 51));
  TypeParam tr(points.begin(), points.end());
  const std::vector<Cell_key> before = all_cell_keys(tr);
  std::size_t refused = 0;
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end() && refused < 20; ++e) {
    std::size_t degree = 0;
    auto cc = tr.incident_cells(*e), done = cc;
    do { ++degree; ++cc; } while(cc != done);
    if(degree == 3) continue;
    EXPECT_FALSE(tr.tds().flip(*e));
    ++refused;
  }
  EXPECT_EQ(refused, 20u);
  EXPECT_TRUE(all_cell_keys(tr) == before);
  EXPECT_TRUE(tr.is_valid());
}

// Ours only: flips keep the kernel's caches (sub-determinants, the cells of
// the vertices) current: after flips out and back, on the hull too, more
// insertions still give CGAL's cells.
TEST(Tds_view, InsertionAfterFlipsGivesCgalCells)
{
  for(bool sub_determinants : {false, true}) {
    std::vector<Point> points = to_points<Point>(uniform_points(80, 81));
    Fast_dt tr;
    tr.set_sub_determinants(sub_determinants);
    tr.insert(points.begin(), points.end());
    std::size_t flips = 0;
    // Every 7th facet, hull facets included, flipped and flipped back.
    std::vector<Fast_dt::Facet> facets(tr.all_facets_begin(), tr.all_facets_end());
    for(std::size_t n = 0; n < facets.size(); n += 7) {
      const Fast_dt::Vertex_handle p = facets[n].first->vertex(facets[n].second);
      const Fast_dt::Vertex_handle q = tr.mirror_vertex(facets[n].first, facets[n].second);
      if(!tr.tds().flip(facets[n])) continue;
      ++flips;
      ASSERT_TRUE(tr.tds().is_valid(true));
      Fast_dt::Cell_handle c;
      int i, j;
      ASSERT_TRUE(tr.tds().is_edge(p, q, c, i, j));
      ASSERT_TRUE(tr.tds().flip(c, i, j));
      ASSERT_TRUE(tr.tds().is_valid(true));
      ASSERT_TRUE(tr.is_valid(true));
      facets.assign(tr.all_facets_begin(), tr.all_facets_end());
    }
    EXPECT_GT(flips, 10u);
    const std::vector<Point> more = to_points<Point>(uniform_points(80, 82));
    tr.insert(more.begin(), more.end());
    for(const Point& p : {Point(2, 2, 2), Point(-1, 0.5, 0.5)}) tr.insert(p);
    points.insert(points.end(), more.begin(), more.end());
    points.push_back(Point(2, 2, 2));
    points.push_back(Point(-1, 0.5, 0.5));
    Cgal_dt cgal(points.begin(), points.end());
    EXPECT_TRUE(tr.is_valid(true));
    EXPECT_TRUE(all_cell_keys(tr) == all_cell_keys(cgal)) << "sub-determinants " << sub_determinants;
  }
}

// Ours only: a vertex created in dimension 2 waits through the lift to 3D
// and a bulk insertion, then is placed; CGAL's cells at each step.
TEST(Tds_view, CreatedVertexWaitsThroughTheLift)
{
  std::vector<Point> points = coplanar_points(30);
  Fast_dt tr(points.begin(), points.end());
  ASSERT_EQ(tr.dimension(), 2);
  const Fast_dt::Vertex_handle v = tr.tds().create_vertex();
  const std::vector<Point> more = to_points<Point>(uniform_points(40, 101));
  tr.insert(more.begin(), more.end());
  points.insert(points.end(), more.begin(), more.end());
  ASSERT_EQ(tr.dimension(), 3);
  EXPECT_TRUE(tr.tds().is_vertex(v));
  EXPECT_TRUE(tr.tds().is_valid(true));
  EXPECT_TRUE(finite_cell_keys(tr) == finite_cell_keys(Cgal_dt(points.begin(), points.end())));
  const Point p(0.4, 0.45, 0.5);
  std::vector<Fast_dt::Cell_handle> cells;
  std::vector<Fast_dt::Facet> boundary;
  tr.find_conflicts(p, tr.locate(p), std::back_inserter(boundary), std::back_inserter(cells));
  EXPECT_TRUE(tr.insert_in_hole(p, cells.begin(), cells.end(), boundary[0].first, boundary[0].second, v) == v);
  points.push_back(p);
  EXPECT_TRUE(tr.tds().is_valid(true));
  EXPECT_TRUE(tr.is_valid(true));
  EXPECT_TRUE(finite_cell_keys(tr) == finite_cell_keys(Cgal_dt(points.begin(), points.end())));
  EXPECT_EQ(tr.number_of_vertices(), points.size());
}

// Ours only: what a created vertex is before it is placed, and the errors.
TEST(Tds_view, CreatedVertexIsInvisibleUntilPlaced)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(50, 61));
  Fast_dt tr(points.begin(), points.end());
  const std::size_t vertices = tr.number_of_vertices();
  const Fast_dt::Vertex_handle v = tr.tds().create_vertex();
  EXPECT_TRUE(tr.tds().is_vertex(v));
  EXPECT_EQ(tr.number_of_vertices(), vertices);
  EXPECT_EQ(static_cast<std::size_t>(std::distance(tr.finite_vertices_begin(), tr.finite_vertices_end())), vertices);
  EXPECT_TRUE(tr.tds().is_valid(true));
  EXPECT_TRUE(tr.is_valid(true));
  // A live vertex is the triangulation's to remove; a vertex is placed once.
  EXPECT_THROW(tr.tds().delete_vertex(tr.finite_vertices_begin()), std::invalid_argument);
  tr.tds().delete_vertex(v);
  EXPECT_FALSE(tr.tds().is_vertex(v));
  EXPECT_THROW(tr.tds().delete_vertex(v), std::invalid_argument);
  std::vector<Fast_dt::Cell_handle> cells;
  std::vector<Fast_dt::Facet> boundary;
  const Point p(0.5, 0.5, 0.5);
  tr.find_conflicts(p, tr.locate(p), std::back_inserter(boundary), std::back_inserter(cells));
  EXPECT_THROW(tr.insert_in_hole(p, cells.begin(), cells.end(), boundary[0].first, boundary[0].second, v),
               std::invalid_argument);
  EXPECT_TRUE(tr.is_valid());
  EXPECT_EQ(tr.number_of_vertices(), vertices);
  // tds() follows the data through a swap, as handles do.
  Fast_dt other;
  other.swap(tr);
  EXPECT_EQ(other.tds().number_of_vertices(), vertices + 1);
  EXPECT_EQ(tr.tds().number_of_vertices(), 1u);
  const Fast_dt copy(other);
  EXPECT_EQ(copy.tds().number_of_cells(), other.tds().number_of_cells());
  EXPECT_TRUE(copy.tds().is_valid());
}

// ---------------------------------------------------------------- copy_tds
// CGAL's copy_triangulation_3 example, on CGAL's classes and on ours: an
// Epick triangulation copied into an Epeck one by tds().copy_tds() with
// CGAL's conversion functors (which skip the first vertex they see, the
// infinite one), then set_infinite_vertex().
typedef CGAL::Exact_predicates_exact_constructions_kernel Epeck;
typedef CGAL::Cartesian_converter<K, Epeck> To_epeck;

template <class Source, class Copy>
struct Example_vertex_conversion
{
  mutable bool first_vertex = true;
  typename Copy::Vertex operator()(const typename Source::Vertex&) const { return typename Copy::Vertex(); }
  void operator()(const typename Source::Vertex& source, typename Copy::Vertex& copy) const
  {
    if(!first_vertex) copy.point() = To_epeck()(source.point());
    else first_vertex = false;
  }
};
template <class Source, class Copy>
struct Example_cell_conversion
{
  typename Copy::Cell operator()(const typename Source::Cell&) const { return typename Copy::Cell(); }
  void operator()(const typename Source::Cell&, typename Copy::Cell&) const {}
};

// Finite cells as sorted point triples of doubles, any kernel.
template <class Tr>
std::vector<Cell_key> finite_cell_keys_of_any_kernel(const Tr& tr)
{
  std::vector<Cell_key> keys;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    Cell_key k;
    for(int i = 0; i < 4; ++i) {
      const auto p = c->vertex(i)->point();
      k[i] = std::make_tuple(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
    }
    std::sort(k.begin(), k.end());
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}
template <class Tr>
std::vector<Point> finite_points_in_order(const Tr& tr)
{
  std::vector<Point> points;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    const auto p = v->point();
    points.push_back(Point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())));
  }
  return points;
}

template <template <class...> class Dt>
void copy_epick_into_epeck_as_cgal_example_does()
{
  typedef Dt<K> Source;
  typedef Dt<Epeck> Copy;
  for(const std::vector<Point>& points : inputs()) {
    const Source source(points.begin(), points.end());
    Copy copy;
    copy.set_infinite_vertex(copy.tds().copy_tds(source.tds(), source.infinite_vertex(),
                                                 Example_vertex_conversion<Source, Copy>(),
                                                 Example_cell_conversion<Source, Copy>()));
    ASSERT_TRUE(copy.is_valid(true)) << points.size() << " points";
    EXPECT_EQ(copy.dimension(), source.dimension());
    EXPECT_EQ(copy.number_of_vertices(), source.number_of_vertices());
    EXPECT_EQ(copy.number_of_cells(), source.number_of_cells());
    EXPECT_TRUE(finite_points_in_order(copy) == finite_points_in_order(source)) << "vertex order";
    EXPECT_TRUE(finite_cell_keys_of_any_kernel(copy) == finite_cell_keys_of_any_kernel(source));
    // The copy is a working triangulation.
    copy.insert(typename Epeck::Point_3(0.5, 0.25, 0.125));
    EXPECT_TRUE(copy.is_valid());
  }
}
TEST(Tds_copy, CgalExampleOnCgalClasses) { copy_epick_into_epeck_as_cgal_example_does<CGAL::Delaunay_triangulation_3>(); }
TEST(Tds_copy, CgalExampleOnOurClass) { copy_epick_into_epeck_as_cgal_example_does<CGAL::Fast_Delaunay_triangulation_3>(); }

// From CGAL's data structure into ours and back, with infos carried by the
// default conversion: the cells are CGAL's, in CGAL's order, and every
// vertex and cell keeps its info.
typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_with_info_3<int, K>,
                                             CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Delaunay_triangulation_cell_base_3<K>>>
    Info_tds;

TEST(Tds_copy, FromCgalDataStructureWithInfosAndBack)
{
  typedef CGAL::Delaunay_triangulation_3<K, Info_tds> Cgal_info_dt;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Info_tds> Fast_info_dt;
  for(const std::vector<Point>& points : inputs()) {
    Cgal_info_dt cgal(points.begin(), points.end());
    int n = 0;
    for(auto v = cgal.finite_vertices_begin(); v != cgal.finite_vertices_end(); ++v) v->info() = ++n;
    for(auto c = cgal.all_cells_begin(); c != cgal.all_cells_end(); ++c) c->info() = ++n;
    Fast_info_dt fast;
    fast.set_infinite_vertex(fast.tds().copy_tds(cgal.tds(), cgal.infinite_vertex()));
    ASSERT_TRUE(fast.is_valid(true)) << points.size() << " points";
    EXPECT_TRUE(finite_points_in_order(fast) == finite_points_in_order(cgal));
    auto w = cgal.finite_vertices_begin();
    for(auto v = fast.finite_vertices_begin(); v != fast.finite_vertices_end(); ++v, ++w) EXPECT_EQ(v->info(), w->info());
    // Dimension 3: the same cells in the same order, infos included (an
    // infinite cell may have its vertices permuted, evenly).
    if(cgal.dimension() == 3) {
      auto key = [](const auto& tr, auto c) {
        std::array<Point, 4> k;
        for(int i = 0; i < 4; ++i) k[i] = tr.is_infinite(c->vertex(i)) ? Point(9, 9, 9) : c->vertex(i)->point();
        if(!tr.is_infinite(c)) return k;
        std::sort(k.begin(), k.end());
        return k;
      };
      auto d = cgal.all_cells_begin();
      for(auto c = fast.all_cells_begin(); c != fast.all_cells_end(); ++c, ++d) {
        EXPECT_TRUE(key(fast, c) == key(cgal, d));
        EXPECT_EQ(c->info(), d->info());
      }
      EXPECT_TRUE(d == cgal.all_cells_end());
    }
    // Back into CGAL's class, through CGAL's own copy_tds.
    Cgal_info_dt back;
    back.set_infinite_vertex(back.tds().copy_tds(fast.tds(), fast.infinite_vertex()));
    EXPECT_TRUE(back.is_valid(true));
    EXPECT_TRUE(finite_cell_keys(back) == finite_cell_keys(cgal));
  }
}

// What cannot be a copy is refused with the reason, and the triangulation
// stays as it was.
TEST(Tds_copy, RefusesWhatIsNotADelaunayTriangulationOfDoubles)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(60, 5));
  const std::vector<Point> others = to_points<Point>(uniform_points(30, 6));
  Fast_dt fast(others.begin(), others.end());
  const std::vector<Cell_key> before = finite_cell_keys(fast);
  auto expect_refused = [&](auto&& copy, const std::string& reason) {
    try {
      copy();
      ADD_FAILURE() << "accepted: " << reason;
    } catch(const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(reason), std::string::npos) << e.what();
    }
    EXPECT_TRUE(fast.is_valid());
    EXPECT_TRUE(finite_cell_keys(fast) == before);
  };
  // A 2-3 flip of a locally Delaunay facet: a valid TDS, no longer Delaunay.
  Cgal_dt flipped(points.begin(), points.end());
  bool did_flip = false;
  for(auto f = flipped.finite_facets_begin(); f != flipped.finite_facets_end() && !did_flip; ++f)
    if(!flipped.is_infinite(f->first->neighbor(f->second)) && !flipped.is_infinite(f->first)) did_flip = flipped.tds().flip(*f);
  ASSERT_TRUE(did_flip && flipped.tds().is_valid());
  expect_refused([&] { fast.tds().copy_tds(flipped.tds(), flipped.infinite_vertex()); }, "not a Delaunay triangulation");
  // The infinite vertex is needed.
  const Cgal_dt cgal(points.begin(), points.end());
  expect_refused([&] { fast.tds().copy_tds(cgal.tds(), Cgal_dt::Vertex_handle()); }, "infinite vertex must be given");
  // A point that is not exactly doubles, into an exact kernel.
  typedef CGAL::Fast_Delaunay_triangulation_3<Epeck> Fast_epeck;
  Fast_epeck exact;
  struct Third_of_x
  {
    Fast_epeck::Vertex operator()(const Cgal_dt::Vertex&) const { return Fast_epeck::Vertex(); }
    void operator()(const Cgal_dt::Vertex& source, Fast_epeck::Vertex& copy) const
    {
      copy.point() = Epeck::Point_3(Epeck::FT(source.point().x()) / 3, source.point().y(), source.point().z());
    }
  };
  try {
    exact.tds().copy_tds(cgal.tds(), cgal.infinite_vertex(), Third_of_x(), CGAL::Fast_Delaunay_triangulation_3_internal::Default_cell_conversion());
    ADD_FAILURE() << "a third accepted";
  } catch(const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("not doubles"), std::string::npos) << e.what();
  }
  EXPECT_EQ(exact.number_of_vertices(), 0u);
  // set_infinite_vertex takes only the infinite vertex.
  EXPECT_THROW(fast.set_infinite_vertex(fast.finite_vertices_begin()), std::invalid_argument);
  EXPECT_NO_THROW(fast.set_infinite_vertex(fast.infinite_vertex()));
  // A vertex's point is not assigned outside a copy.
  Fast_dt::Vertex v = *fast.finite_vertices_begin();
  EXPECT_THROW(v.point() = Point(0, 0, 0), std::logic_error);
}

} // namespace test_tds_interface
