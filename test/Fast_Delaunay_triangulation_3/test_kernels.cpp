// Any CGAL kernel: one test body instantiated for EPEC, EPEC with
// Fast_location, Simple_cartesian<double>, EPICK and
// Simple_cartesian<Exact_rational> (exact, not lazy), each against
// CGAL::Delaunay_triangulation_3 of the same kernel (and location policy) on
// the same points.  Points with double coordinates go through the double
// engine; the kernel's own objects come back from v->point(); queries at
// points an exact construction made (not doubles) are answered exactly;
// an input point whose coordinates are not doubles is refused.

#include "point_sets.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/convert_to_cgal.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/intersections.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <limits>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

namespace test_kernels {

using fdt3_test::Xyz;

typedef CGAL::Exact_predicates_exact_constructions_kernel Epec;
typedef CGAL::Exact_predicates_inexact_constructions_kernel Epick;
typedef CGAL::Simple_cartesian<double> Cartesian;
typedef CGAL::Simple_cartesian<CGAL::Exact_rational> Rational;

template <class K, class... Policy>
struct Config
{
  typedef K Kernel;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Policy...> Fast;
  typedef CGAL::Delaunay_triangulation_3<K, Policy...> Cgal;
  static constexpr bool exact_constructions = !std::is_same<typename K::FT, double>::value;
};

typedef ::testing::Types<Config<Epec>, Config<Epec, CGAL::Fast_location>, Config<Cartesian>, Config<Epick>,
                         Config<Rational>>
    Configs;

// The coordinates of a point that has double coordinates, compared as
// doubles: only used for points that are doubles exactly (checked by
// PointsAreTheObjectsInserted).
typedef std::tuple<double, double, double> Key;
template <class Point>
Key key(const Point& p)
{
  return Key(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}
typedef std::array<Key, 4> Cell_key;
template <class Tr>
Cell_key cell_key(typename Tr::Cell_handle c)
{
  Cell_key k;
  for(int i = 0; i < 4; ++i) k[i] = key(c->vertex(i)->point());
  std::sort(k.begin(), k.end());
  return k;
}
template <class Tr>
std::vector<Cell_key> finite_cells(const Tr& tr)
{
  std::vector<Cell_key> keys;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) keys.push_back(cell_key<Tr>(c));
  std::sort(keys.begin(), keys.end());
  return keys;
}

template <class C>
class Kernels : public ::testing::Test
{
public:
  typedef typename C::Kernel K;
  typedef typename K::Point_3 Point;
  typedef typename K::FT FT;
  typedef typename C::Fast Fast;
  typedef typename C::Cgal Cgal;

  static std::vector<Point> random_points() { return fdt3_test::to_points<Point>(fdt3_test::uniform_points(300, 11)); }
  static std::vector<Point> grid() { return fdt3_test::to_points<Point>(fdt3_test::grid_points(125, 12)); }

  // Query points: doubles, and with an exact kernel points made by
  // constructions (not doubles): inside cells, on facets and edges (exact
  // barycentres), outside the hull.
  static std::vector<Point> queries(const Cgal& cgal)
  {
    std::vector<Point> q = fdt3_test::to_points<Point>(fdt3_test::uniform_points(40, 13));
    for(const Xyz& x : fdt3_test::uniform_points(5, 14)) q.emplace_back(3 * x.x - 1, x.y, x.z);
    if constexpr(C::exact_constructions) {
      int k = 0;
      for(auto c = cgal.finite_cells_begin(); c != cgal.finite_cells_end() && k < 30; ++c, ++k) {
        const Point a = c->vertex(0)->point(), b = c->vertex(1)->point(), d = c->vertex(2)->point(),
                    e = c->vertex(3)->point();
        q.push_back(CGAL::barycenter(a, 1, b, 2, d, 3, e, 5)); // inside
        q.push_back(CGAL::barycenter(a, 1, b, 1, d, 1));       // on a facet
        q.push_back(CGAL::barycenter(a, 1, b, 2));             // on an edge
        q.push_back(CGAL::barycenter(a, -1, b, 2, d, 2));      // often outside the cell, maybe the hull
        q.push_back(Point(a.x() * 3 - FT(1) / 3, a.y(), a.z())); // beyond the hull for some
      }
    }
    return q;
  }
};

TYPED_TEST_SUITE(Kernels, Configs);

TYPED_TEST(Kernels, SameCellsAsCgal)
{
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  for(const auto& points : {TestFixture::random_points(), TestFixture::grid()}) {
    const Fast ours(points.begin(), points.end());
    const Cgal cgal(points.begin(), points.end());
    EXPECT_TRUE(ours.is_valid());
    EXPECT_TRUE(cgal.is_valid());
    EXPECT_EQ(ours.number_of_vertices(), cgal.number_of_vertices());
    EXPECT_EQ(ours.number_of_finite_cells(), cgal.number_of_finite_cells());
    EXPECT_EQ(finite_cells(ours), finite_cells(cgal));
  }
}

// Removal and moves with every kernel: the cells stay CGAL's, a moved vertex
// holds the object it was moved to, a move to a point that is no double is
// refused with nothing changed.
TYPED_TEST(Kernels, RemoveAndMoveAsCgal)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::FT FT;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  // CGAL's triangulation with inexact predicates loses its grid vertices
  // (is_vertex fails after a few removals): no oracle there.
  if(std::is_same<typename TestFixture::K, Cartesian>::value) GTEST_SKIP() << "inexact predicates in CGAL's class";
  for(const auto& points : {TestFixture::random_points(), TestFixture::grid()}) {
    Fast ours(points.begin(), points.end());
    Cgal cgal(points.begin(), points.end());
    for(std::size_t k = 0; k < points.size(); k += 7) {
      typename Fast::Vertex_handle v;
      typename Cgal::Vertex_handle w;
      ASSERT_TRUE(ours.is_vertex(points[k], v));
      ASSERT_TRUE(cgal.is_vertex(points[k], w));
      if(k % 2 == 0) {
        ours.remove(v);
        cgal.remove(w);
        continue;
      }
      // Doubles: the engine takes exact doubles only (checked below).
      const Point target(CGAL::to_double(points[k].x()) + 0.25, CGAL::to_double(points[k].y()),
                         CGAL::to_double(points[k].z()) - 0.125);
      const typename Fast::Vertex_handle moved = ours.move(v, target);
      cgal.move(w, target);
      EXPECT_TRUE(moved->point() == target);
    }
    EXPECT_TRUE(ours.is_valid());
    EXPECT_EQ(ours.number_of_vertices(), cgal.number_of_vertices());
    EXPECT_EQ(finite_cells(ours), finite_cells(cgal));
    if constexpr(std::is_same<FT, double>::value) continue;
    else {
      const typename Fast::Vertex_handle v = ours.finite_vertices_begin();
      const Point before = v->point();
      const Point third(FT(1) / 3, FT(0), FT(0));
      EXPECT_THROW(ours.move(v, third), std::invalid_argument);
      EXPECT_TRUE(v->point() == before);
      EXPECT_EQ(finite_cells(ours), finite_cells(cgal));
    }
  }
}

TYPED_TEST(Kernels, PointsAreTheObjectsInserted)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::Fast Fast;
  const std::vector<Point> points = TestFixture::random_points();
  Fast ours(points.begin(), points.begin() + 200);
  // One at a time, with a duplicate, and a second range.
  ours.insert(points[200]);
  ours.insert(points[0]);
  ours.insert(points.begin() + 201, points.end());
  ASSERT_EQ(ours.number_of_vertices(), points.size());
  for(const Point& p : points) {
    typename Fast::Vertex_handle v;
    ASSERT_TRUE(ours.is_vertex(p, v));
    EXPECT_TRUE(v->point() == p);
  }
  if constexpr(TypeParam::exact_constructions) {
    // A point an exact construction made, whose value is a double exactly,
    // is accepted (its interval need not be a single double).
    typedef typename TestFixture::FT FT;
    const Point p(FT(1) / 3 * 3 + FT(7), FT(2) / 7 * 7, FT(-1) / 5 * 10);
    const typename Fast::Vertex_handle v = ours.insert(p);
    EXPECT_TRUE(v->point() == p);
    EXPECT_TRUE(v->point() == Point(8, 2, -2));
    EXPECT_TRUE(ours.is_valid());
  }
}

TYPED_TEST(Kernels, LocateAndNearestVertexAsCgal)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  const std::vector<Point> points = TestFixture::random_points();
  const Fast ours(points.begin(), points.end());
  const Cgal cgal(points.begin(), points.end());
  // Per location type, how many query points that are no doubles met it.
  std::map<int, std::size_t> not_doubles;
  for(const Point& q : TestFixture::queries(cgal)) {
    double xyz[3];
    const bool doubles = CGAL::Fast_Delaunay_triangulation_3_internal::exact_coordinates(q, xyz);
    typename Fast::Locate_type lt;
    typename Cgal::Locate_type clt;
    int li = -1, lj = -1, cli = -1, clj = -1;
    const typename Fast::Cell_handle c = ours.locate(q, lt, li, lj);
    const typename Cgal::Cell_handle cc = cgal.locate(q, clt, cli, clj);
    ASSERT_EQ(static_cast<int>(lt), static_cast<int>(clt));
    if(!doubles) ++not_doubles[static_cast<int>(lt)];
    if(lt == Fast::CELL) {
      EXPECT_EQ(cell_key<Fast>(c), cell_key<Cgal>(cc));
    }
    if(lt == Fast::FACET) {
      std::vector<Key> a, b;
      for(int k = 0; k < 4; ++k) {
        if(k != li) a.push_back(key(c->vertex(k)->point()));
        if(k != cli) b.push_back(key(cc->vertex(k)->point()));
      }
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      EXPECT_EQ(a, b);
    }
    if(lt == Fast::EDGE) {
      std::array<Key, 2> a = {key(c->vertex(li)->point()), key(c->vertex(lj)->point())},
                         b = {key(cc->vertex(cli)->point()), key(cc->vertex(clj)->point())};
      std::sort(a.begin(), a.end());
      std::sort(b.begin(), b.end());
      EXPECT_EQ(a, b);
    }
    if(lt == Fast::OUTSIDE_CONVEX_HULL) {
      EXPECT_TRUE(ours.is_infinite(c));
    }
    EXPECT_TRUE(ours.nearest_vertex(q)->point() == cgal.nearest_vertex(q)->point());
    // side_of_cell of the cell found, and the in-sphere test of CGAL's cell.
    int si = -1, sj = -1;
    EXPECT_NE(ours.side_of_cell(q, c, lt, si, sj), CGAL::ON_UNBOUNDED_SIDE);
    if(clt == Cgal::CELL && !cgal.is_infinite(cc)) {
      EXPECT_EQ(ours.side_of_sphere(c, q, true), cgal.side_of_sphere(cc, q, true));
    }
  }
  if constexpr(TypeParam::exact_constructions) {
    EXPECT_GE(not_doubles[Fast::CELL], 30u);
    EXPECT_GE(not_doubles[Fast::FACET], 20u);
    EXPECT_GE(not_doubles[Fast::EDGE], 20u);
    EXPECT_GE(not_doubles[Fast::OUTSIDE_CONVEX_HULL], 3u);
  }
}

// Below dimension 3 (one point, collinear points, coplanar points): lt as
// CGAL's, and the face found holds the same points.  With an exact kernel
// the queries are no doubles: on edges, in triangles, beyond the hull, off
// the affine hull.
TYPED_TEST(Kernels, LocateBelowDimension3AsCgal)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::FT FT;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  std::vector<Point> line, plane;
  for(int i = 0; i < 7; ++i) line.push_back(Point(i * i, 2 * i * i, 0));
  for(int i = 0; i < 5; ++i)
    for(int j = 0; j < 5; ++j) plane.push_back(Point(i + 0.25 * (j % 2), j, 0));
  for(const auto& points : {std::vector<Point>(1, Point(1, 2, 3)), line, plane}) {
    const Fast ours(points.begin(), points.end());
    const Cgal cgal(points.begin(), points.end());
    ASSERT_EQ(ours.dimension(), cgal.dimension());
    std::vector<Point> queries = {Point(0.5, 0.5, 0), Point(100, 3, 0), Point(1, 2, 0)};
    if constexpr(TypeParam::exact_constructions) {
      const FT third = FT(1) / 3;
      if(points.size() > 1) queries.push_back(CGAL::barycenter(points.front(), 4, points.back(), -3));
      for(std::size_t k = 0; k + 2 < points.size(); ++k) {
        queries.push_back(CGAL::barycenter(points[k], 1, points[k + 1], 2));
        queries.push_back(CGAL::barycenter(points[k], 1, points[k + 1], 2, points[k + 2], 4));
        queries.push_back(CGAL::barycenter(points[k], -1, points[k + 1], 3));
        queries.push_back(Point(points[k].x(), points[k].y(), third));
        queries.push_back(Point(points[k].x() * 5 + third, points[k].y() * 10 - third, 0));
      }
    }
    std::map<int, int> seen;
    for(const Point& q : queries) {
      typename Fast::Locate_type lt;
      typename Cgal::Locate_type clt;
      int li = -1, lj = -1, cli = -1, clj = -1;
      const typename Fast::Cell_handle c = ours.locate(q, lt, li, lj);
      const typename Cgal::Cell_handle cc = cgal.locate(q, clt, cli, clj);
      ASSERT_EQ(static_cast<int>(lt), static_cast<int>(clt));
      ++seen[static_cast<int>(lt)];
      if(lt == Fast::EDGE) {
        std::array<Key, 2> a = {key(c->vertex(li)->point()), key(c->vertex(lj)->point())},
                           b = {key(cc->vertex(cli)->point()), key(cc->vertex(clj)->point())};
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        EXPECT_EQ(a, b);
      }
      if(lt == Fast::FACET) {
        std::array<Key, 3> a, b;
        for(int k = 0; k < 3; ++k) {
          a[k] = key(c->vertex(k)->point());
          b[k] = key(cc->vertex(k)->point());
        }
        std::sort(a.begin(), a.end());
        std::sort(b.begin(), b.end());
        EXPECT_EQ(a, b);
      }
      if(lt == Fast::OUTSIDE_CONVEX_HULL) {
        EXPECT_TRUE(ours.is_infinite(c));
      }
      typename Fast::Vertex_handle v;
      EXPECT_EQ(ours.is_vertex(q, v), lt == Fast::VERTEX);
      // Ties are broken differently: the distance is CGAL's.
      EXPECT_EQ(typename TestFixture::K().compare_distance_3_object()(q, ours.nearest_vertex(q)->point(),
                                                                       cgal.nearest_vertex(q)->point()),
                CGAL::EQUAL);
    }
    if constexpr(TypeParam::exact_constructions) {
      EXPECT_GE(seen[Fast::OUTSIDE_AFFINE_HULL], 1);
      if(points.size() > 1) {
        EXPECT_GE(seen[Fast::EDGE], 1);
        EXPECT_GE(seen[Fast::OUTSIDE_CONVEX_HULL], 1);
      }
      if(points.size() > 7) {
        EXPECT_GE(seen[Fast::FACET], 1);
      }
    }
  }
}

TYPED_TEST(Kernels, DualIsCgalCircumcenter)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  const std::vector<Point> points = TestFixture::random_points();
  const Fast ours(points.begin(), points.end());
  const Cgal cgal(points.begin(), points.end());
  std::map<Cell_key, typename Cgal::Cell_handle> cgal_cell;
  for(auto c = cgal.finite_cells_begin(); c != cgal.finite_cells_end(); ++c) cgal_cell[cell_key<Cgal>(c)] = c;
  for(auto c = ours.finite_cells_begin(); c != ours.finite_cells_end(); ++c) {
    const typename Cgal::Cell_handle cc = cgal_cell.at(cell_key<Fast>(c));
    const Point center = ours.dual(c);
    // The kernel's tetrahedron of the cell's points, positively oriented.
    const typename TestFixture::K::Tetrahedron_3 tetrahedron = ours.tetrahedron(c);
    for(int i = 0; i < 4; ++i) EXPECT_TRUE(tetrahedron.vertex(i) == c->vertex(i)->point());
    EXPECT_EQ(tetrahedron.orientation(), CGAL::POSITIVE);
    if constexpr(TypeParam::exact_constructions) {
      EXPECT_TRUE(center == cgal.dual(cc));
      // The centre is no double in general: the exact queries decide.
      EXPECT_EQ(ours.side_of_sphere(c, center), CGAL::ON_BOUNDED_SIDE);
      EXPECT_TRUE(ours.tetrahedron(c).has_on_bounded_side(center) == cgal.tetrahedron(cc).has_on_bounded_side(center));
    } else {
      EXPECT_LT(CGAL::squared_distance(center, cgal.dual(cc)), 1e-20);
    }
  }
}

// The conflict zone of each query point (cells, boundary facets, internal
// facets, boundary vertices) as point sets; the infinite vertex as a key of
// its own.
TYPED_TEST(Kernels, ConflictZoneAsCgal)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  const std::vector<Point> points = TestFixture::random_points();
  const Fast ours(points.begin(), points.end());
  const Cgal cgal(points.begin(), points.end());
  const Key infinite(1e300, 1e300, 1e300);
  auto vertex_key = [&](const auto& tr, const auto& v) { return tr.is_infinite(v) ? infinite : key(v->point()); };
  auto cell_keys = [&](const auto& tr, const auto& cells) {
    std::vector<Cell_key> keys;
    for(const auto& c : cells) {
      Cell_key k;
      for(int i = 0; i < 4; ++i) k[i] = vertex_key(tr, c->vertex(i));
      std::sort(k.begin(), k.end());
      keys.push_back(k);
    }
    std::sort(keys.begin(), keys.end());
    return keys;
  };
  auto facet_keys = [&](const auto& tr, const auto& facets) {
    std::vector<std::array<Key, 3>> keys;
    for(const auto& f : facets) {
      std::array<Key, 3> k;
      for(int i = 0, j = 0; i < 4; ++i)
        if(i != f.second) k[j++] = vertex_key(tr, f.first->vertex(i));
      std::sort(k.begin(), k.end());
      keys.push_back(k);
    }
    std::sort(keys.begin(), keys.end());
    return keys;
  };
  for(const Point& q : TestFixture::queries(cgal)) {
    typename Fast::Vertex_handle v;
    if(ours.is_vertex(q, v)) continue;
    std::vector<typename Fast::Facet> boundary, internal;
    std::vector<typename Fast::Cell_handle> cells;
    std::vector<typename Cgal::Facet> cgal_boundary, cgal_internal;
    std::vector<typename Cgal::Cell_handle> cgal_cells;
    ours.find_conflicts(q, ours.locate(q), std::back_inserter(boundary), std::back_inserter(cells),
                        std::back_inserter(internal));
    cgal.find_conflicts(q, cgal.locate(q), std::back_inserter(cgal_boundary), std::back_inserter(cgal_cells),
                        std::back_inserter(cgal_internal));
    EXPECT_EQ(cell_keys(ours, cells), cell_keys(cgal, cgal_cells));
    EXPECT_EQ(facet_keys(ours, boundary), facet_keys(cgal, cgal_boundary));
    EXPECT_EQ(facet_keys(ours, internal), facet_keys(cgal, cgal_internal));
    std::vector<typename Fast::Vertex_handle> around;
    std::vector<typename Cgal::Vertex_handle> cgal_around;
    ours.vertices_on_conflict_zone_boundary(q, ours.locate(q), std::back_inserter(around));
    cgal.vertices_on_conflict_zone_boundary(q, cgal.locate(q), std::back_inserter(cgal_around));
    std::vector<Key> a, b;
    for(const auto& w : around) a.push_back(vertex_key(ours, w));
    for(const auto& w : cgal_around) b.push_back(vertex_key(cgal, w));
    std::sort(a.begin(), a.end());
    std::sort(b.begin(), b.end());
    EXPECT_EQ(a, b);
  }
}

// Between barycentres of two far cells (no doubles with an exact kernel,
// and in general position), checked independently of CGAL's traverser
// (whose CGAL 5.5 code reads signs it has not computed, see CMakeLists.txt):
// a chain of adjacent cells from the cell of p to the cell of q, exactly
// the finite cells whose tetrahedron the segment meets (the kernel's exact
// do_intersect).
TYPED_TEST(Kernels, SegmentTraverserMeetsExactlyTheCellsTheSegmentMeets)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::K K;
  const std::vector<Point> points = TestFixture::random_points();
  const Fast ours(points.begin(), points.end());
  std::vector<typename Fast::Cell_handle> cells;
  for(auto c = ours.finite_cells_begin(); c != ours.finite_cells_end(); ++c) cells.push_back(c);
  auto inside = [](typename Fast::Cell_handle c) {
    return CGAL::barycenter(c->vertex(0)->point(), 1, c->vertex(1)->point(), 2, c->vertex(2)->point(), 3,
                            c->vertex(3)->point(), 4);
  };
  for(std::size_t k = 0; k < 50; k += 10) {
    const typename Fast::Cell_handle from = cells[k], to = cells[cells.size() - 1 - k];
    const Point p = inside(from), q = inside(to);
    const typename K::Segment_3 segment(p, q);
    std::vector<typename Fast::Cell_handle> walked;
    for(auto c = ours.segment_traverser_cells_begin(p, q); c != ours.segment_traverser_cells_end(); ++c)
      walked.push_back(c);
    ASSERT_GE(walked.size(), 2u);
    EXPECT_TRUE(walked.front() == from);
    EXPECT_TRUE(walked.back() == to);
    for(std::size_t i = 0; i + 1 < walked.size(); ++i) EXPECT_TRUE(walked[i]->has_neighbor(walked[i + 1]));
    std::vector<typename Fast::Cell_handle> met;
    for(const typename Fast::Cell_handle c : cells)
      if(CGAL::do_intersect(ours.tetrahedron(c), segment)) met.push_back(c);
    std::sort(walked.begin(), walked.end());
    std::sort(met.begin(), met.end());
    EXPECT_TRUE(walked == met);
  }
}

TYPED_TEST(Kernels, IoRoundTrip)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  const std::vector<Point> points = TestFixture::random_points();
  const Fast ours(points.begin(), points.end());
  std::stringstream file;
  file.precision(17);
  file << ours;
  // Into a triangulation that has other points: they all go.
  const std::vector<Point> others = TestFixture::grid();
  Fast back(others.begin(), others.end());
  std::string error;
  ASSERT_TRUE(back.read(file, &error)) << error;
  EXPECT_EQ(finite_cells(back), finite_cells(ours));
  for(auto v = back.finite_vertices_begin(); v != back.finite_vertices_end(); ++v) {
    typename Fast::Vertex_handle w;
    ASSERT_TRUE(ours.is_vertex(v->point(), w));
    EXPECT_TRUE(w->point() == v->point());
  }
  // CGAL reads our file, and we read CGAL's.
  std::stringstream again;
  again.precision(17);
  again << ours;
  Cgal cgal;
  again >> cgal;
  ASSERT_TRUE(cgal.is_valid());
  EXPECT_EQ(cgal.number_of_vertices(), ours.number_of_vertices());
  const Cgal reference(points.begin(), points.end());
  EXPECT_TRUE(ours == reference);
  if constexpr(TypeParam::exact_constructions) {
    // A vertex 1e-20 / 3 away from ours (the same double when rounded): no
    // longer the same triangulation.
    typedef typename TestFixture::FT FT;
    std::vector<Point> moved = points;
    moved[0] = Point(moved[0].x() + FT(1e-20) / 3, moved[0].y(), moved[0].z());
    const Cgal other(moved.begin(), moved.end());
    EXPECT_TRUE(key(moved[0]) == key(points[0]));
    EXPECT_FALSE(ours == other);
    EXPECT_TRUE(ours != other);
  }
  std::stringstream cgal_file;
  cgal_file.precision(17);
  cgal_file << reference;
  Fast from_cgal;
  ASSERT_TRUE(from_cgal.read(cgal_file, &error)) << error;
  EXPECT_EQ(finite_cells(from_cgal), finite_cells(reference));
}

TYPED_TEST(Kernels, ConvertToCgalOfTheSameKernel)
{
  typedef typename TestFixture::Point Point;
  typedef typename TestFixture::Fast Fast;
  typedef typename TestFixture::Cgal Cgal;
  const std::vector<Point> points = TestFixture::grid();
  const Fast ours(points.begin(), points.end());
  Cgal converted;
  CGAL::convert_to_cgal(ours, converted);
  EXPECT_TRUE(converted.is_valid());
  EXPECT_EQ(finite_cells(converted), finite_cells(Cgal(points.begin(), points.end())));
  for(auto v = converted.finite_vertices_begin(); v != converted.finite_vertices_end(); ++v) {
    typename Fast::Vertex_handle w;
    ASSERT_TRUE(ours.is_vertex(v->point(), w));
    EXPECT_TRUE(w->point() == v->point());
  }
}

TYPED_TEST(Kernels, InputNotRepresentableAsDoublesIsRefused)
{
  if constexpr(TypeParam::exact_constructions) {
    typedef typename TestFixture::Point Point;
    typedef typename TestFixture::FT FT;
    typedef typename TestFixture::Fast Fast;
    std::vector<Point> points = TestFixture::random_points();
    Fast ours(points.begin(), points.end());
    const std::vector<Cell_key> before = finite_cells(ours);
    const Point third(FT(1) / 3, FT(0.5), FT(0.5));
    try {
      ours.insert(third);
      FAIL() << "no exception";
    } catch(const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("not representable as doubles"), std::string::npos) << e.what();
    }
    std::vector<Point> more = {Point(0.25, 0.25, 0.25), Point(0.75, 0.5, 0.5), third};
    try {
      ours.insert(more.begin(), more.end());
      FAIL() << "no exception";
    } catch(const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("point #2 of the input"), std::string::npos) << e.what();
    }
    EXPECT_EQ(ours.number_of_vertices(), points.size());
    EXPECT_EQ(finite_cells(ours), before);
    EXPECT_TRUE(ours.is_valid());
#ifdef NDEBUG
    // A lazy point made from NaN or infinity (CGAL's debug builds assert
    // at its construction) is refused as with doubles, without asking for
    // its exact value (GMP raises SIGFPE on a NaN).
    if constexpr(std::is_same<typename TestFixture::K, Epec>::value) {
      for(const double bad : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
        std::vector<Point> with_bad = {Point(0.25, 0.25, 0.25), Point(0.5, bad, 0.5)};
        EXPECT_THROW(ours.insert(with_bad.begin(), with_bad.end()), std::invalid_argument);
        EXPECT_THROW(ours.insert(with_bad[1]), std::invalid_argument);
      }
      EXPECT_EQ(ours.number_of_vertices(), points.size());
    }
#endif
    // Below dimension 3, queries other than locate need doubles too.
    const std::vector<Point> plane = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)};
    const Fast flat(plane.begin(), plane.end());
    const Point in_plane(FT(1) / 3, FT(1) / 7, 0);
    EXPECT_THROW(flat.side_of_circle(flat.finite_facets_begin()->first, 3, in_plane), std::invalid_argument);
  }
}

} // namespace test_kernels
