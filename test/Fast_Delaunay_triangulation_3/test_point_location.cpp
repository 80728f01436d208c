// Point location and the predicates on cells (locate with every hint
// overload, side_of_cell, side_of_sphere, nearest_vertex, is_vertex, is_edge,
// is_facet, is_cell): the same function runs on CGAL::Delaunay_triangulation_3
// and on ours, and the answers are compared by points.  Both triangulations
// have the same cells, so where a query lies (at a vertex, in the relative
// interior of an edge, a facet or a cell, outside the hull) is a geometric
// fact both must report identically; only the cell chosen among those that
// share a face may differ, so faces are compared as sets of points.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <cmath>
#include <limits>
#include <map>
#include <string>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_point_location {

const Point_key infinite_key(std::numeric_limits<double>::infinity(), 0, 0);

template <class Tr>
Point_key key_of(const Tr& tr, typename Tr::Vertex_handle v)
{
  return tr.is_infinite(v) ? infinite_key : point_key(v->point());
}

// The vertices of c at the given indices, as sorted point keys.
template <class Tr>
std::vector<Point_key> face_key(const Tr& tr, typename Tr::Cell_handle c, std::vector<int> indices)
{
  std::vector<Point_key> key;
  for(int i : indices) key.push_back(key_of(tr, c->vertex(i)));
  std::sort(key.begin(), key.end());
  return key;
}

template <class Tr>
std::vector<Point_key> cell_key(const Tr& tr, typename Tr::Cell_handle c)
{
  return face_key(tr, c, {0, 1, 2, 3});
}

// A query point for every case: the vertices, points on the edges, facets and
// in the cells of a grid (exact midpoints), the hull planes inside and
// outside the hull, points just outside hull vertices, random points.
std::vector<Point> queries(const std::vector<Point>& input, bool grid)
{
  std::vector<Point> q(input.begin(), input.end());
  if(grid) {
    for(double x = -1; x <= 5; x += 0.5)
      for(double y = -0.5; y <= 4.5; y += 0.5)
        for(double z : {0.0, 0.5, 1.5, 4.0, 4.5}) q.emplace_back(x, y, z);
    q.emplace_back(0, 1.3, 2.7);
    q.emplace_back(0, -1, 2);
    q.emplace_back(4, 4, 7);
  }
  std::vector<Xyz> random = uniform_points(200, 77);
  for(const Xyz& r : random) q.emplace_back(2.4 * r.x - 0.7, 2.4 * r.y - 0.7, 2.4 * r.z - 0.7);
  for(std::size_t i = 0; i < input.size(); i += 7)
    q.emplace_back(input[i].x() * (1 + 1e-12), input[i].y() - 1e-13, input[i].z() + 1e-9);
  return q;
}

enum class Hint { none, cell, vertex };

struct Located
{
  int type;
  std::vector<Point_key> face; // the vertex, edge, facet or cell; empty outside the hull
  friend bool operator==(const Located& a, const Located& b) { return a.type == b.type && a.face == b.face; }
};

// Locates every query with the given hint overload, checks what can be
// checked inside one triangulation, and returns the locations by point.
template <class Tr>
std::vector<Located> locate_all(const Tr& tr, const std::vector<Point>& q, Hint hint)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  std::vector<Located> result;
  Cell_handle previous_cell = tr.finite_cells_begin();
  Vertex_handle previous_vertex = tr.finite_vertices_begin();
  for(const Point& p : q) {
    typename Tr::Locate_type lt = Tr::OUTSIDE_AFFINE_HULL;
    int li = -1, lj = -1;
    Cell_handle c, plain;
    switch(hint) {
    case Hint::none:
      c = tr.locate(p, lt, li, lj);
      plain = tr.locate(p);
      break;
    case Hint::cell:
      c = tr.locate(p, lt, li, lj, previous_cell);
      plain = tr.locate(p, previous_cell);
      break;
    case Hint::vertex:
      c = tr.locate(p, lt, li, lj, previous_vertex);
      plain = tr.locate(p, previous_vertex);
      break;
    }
    Located loc{int(lt), {}};
    switch(lt) {
    case Tr::VERTEX:
      loc.face = face_key(tr, c, {li});
      EXPECT_TRUE(c->vertex(li)->point() == p);
      previous_vertex = c->vertex(li);
      break;
    case Tr::EDGE:
      loc.face = face_key(tr, c, {li, lj});
      EXPECT_TRUE(CGAL::collinear(p, tr.point(c, li), tr.point(c, lj)));
      break;
    case Tr::FACET: {
      std::vector<int> f;
      for(int i = 0; i < 4; ++i)
        if(i != li) f.push_back(i);
      loc.face = face_key(tr, c, f);
      EXPECT_FALSE(tr.is_infinite(c));
      break;
    }
    case Tr::CELL:
      loc.face = cell_key(tr, c);
      EXPECT_FALSE(tr.is_infinite(c));
      break;
    case Tr::OUTSIDE_CONVEX_HULL: {
      // An infinite cell whose finite facet sees p strictly; li its infinite vertex.
      EXPECT_TRUE(tr.is_infinite(c));
      EXPECT_TRUE(tr.is_infinite(c->vertex(li)));
      typename Tr::Locate_type side_lt;
      int i, j;
      EXPECT_EQ(tr.side_of_cell(p, c, side_lt, i, j), CGAL::ON_BOUNDED_SIDE);
      break;
    }
    default: ADD_FAILURE() << "unexpected locate type " << int(lt);
    }
    // Without lt, the cell holds p too (it may be another cell sharing the face).
    typename Tr::Locate_type plain_lt;
    int i, j;
    EXPECT_NE(tr.side_of_cell(p, plain, plain_lt, i, j), CGAL::ON_UNBOUNDED_SIDE);
    EXPECT_EQ(tr.inexact_locate(p) == Cell_handle(), false);
    if(!tr.is_infinite(c)) previous_cell = c;
    result.push_back(loc);
  }
  return result;
}

struct Input
{
  std::string name;
  std::vector<Point> points;
  bool grid;
};

std::vector<Input> inputs()
{
  return {{"uniform", to_points<Point>(make_points("uniform", 200, 31)), false},
          {"grid", to_points<Point>(make_points("grid", 125, 32)), true},
          {"sphere", to_points<Point>(make_points("sphere", 150, 33)), false}};
}

TEST(PointLocation, SameLocationsAsCgalWithEveryHint)
{
  for(const Input& in : inputs()) {
    SCOPED_TRACE(in.name);
    const Cgal_dt cgal(in.points.begin(), in.points.end());
    const Fast_dt fast(in.points.begin(), in.points.end());
    const std::vector<Point> q = queries(in.points, in.grid);
    std::map<int, int> types;
    for(Hint hint : {Hint::none, Hint::cell, Hint::vertex}) {
      SCOPED_TRACE(int(hint));
      const std::vector<Located> expected = locate_all(cgal, q, hint);
      const std::vector<Located> got = locate_all(fast, q, hint);
      ASSERT_EQ(expected.size(), got.size());
      for(std::size_t k = 0; k < q.size(); ++k) {
        EXPECT_TRUE(expected[k] == got[k]) << "query " << q[k] << ": CGAL type " << expected[k].type
                                           << ", ours " << got[k].type;
        ++types[got[k].type];
      }
    }
    // The queries reach every case on the grid.
    if(in.grid) {
      EXPECT_EQ(types.size(), 5u);
    }
  }
}

TEST(PointLocation, SideOfCellAndSideOfSphereAsCgal)
{
  for(const Input& in : inputs()) {
    SCOPED_TRACE(in.name);
    const Cgal_dt cgal(in.points.begin(), in.points.end());
    const Fast_dt fast(in.points.begin(), in.points.end());
    std::vector<Point> q = queries(in.points, in.grid);
    q.resize(std::min<std::size_t>(q.size(), 400));
    auto sides = [&q](const auto& tr) {
      std::map<std::pair<std::vector<Point_key>, std::size_t>, std::array<int, 4>> out;
      for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
        for(std::size_t k = 0; k < q.size(); k += 3) {
          typename std::decay_t<decltype(tr)>::Locate_type lt = std::decay_t<decltype(tr)>::CELL;
          int i = 0, j = 0;
          const int side = int(tr.side_of_cell(q[k], c, lt, i, j));
          // The perturbation assumes distinct points: CGAL's answer for a
          // vertex of the cell itself depends on its sort of equal points.
          const bool at_vertex = side == int(CGAL::ON_BOUNDARY) && lt == std::decay_t<decltype(tr)>::VERTEX;
          out[{cell_key(tr, c), k}] = {side, side == int(CGAL::ON_UNBOUNDED_SIDE) ? -1 : int(lt),
                                       int(tr.side_of_sphere(c, q[k])),
                                       at_vertex ? 99 : int(tr.side_of_sphere(c, q[k], true))};
        }
      return out;
    };
    const auto expected = sides(cgal), got = sides(fast);
    ASSERT_EQ(expected.size(), got.size());
    int shown = 0;
    for(auto a = expected.begin(), b = got.begin(); a != expected.end(); ++a, ++b) {
      EXPECT_TRUE(a->first == b->first);
      if(a->second != b->second && shown++ < 5)
        ADD_FAILURE() << "query " << q[a->first.second] << " infinite cell "
                      << (std::get<0>(a->first.first.back()) == std::numeric_limits<double>::infinity()) << ": CGAL "
                      << a->second[0] << ' ' << a->second[1] << ' ' << a->second[2] << ' ' << a->second[3]
                      << ", ours " << b->second[0] << ' ' << b->second[1] << ' ' << b->second[2] << ' '
                      << b->second[3];
    }
  }
}

TEST(PointLocation, NearestVertexAndIsVertexAsCgal)
{
  for(const Input& in : inputs()) {
    SCOPED_TRACE(in.name);
    const Cgal_dt cgal(in.points.begin(), in.points.end());
    const Fast_dt fast(in.points.begin(), in.points.end());
    for(const Point& p : queries(in.points, in.grid)) {
      double best = std::numeric_limits<double>::infinity();
      for(const Point& v : in.points) best = std::min(best, CGAL::to_double(CGAL::squared_distance(p, v)));
      const Fast_dt::Vertex_handle v = fast.nearest_vertex(p);
      const Cgal_dt::Vertex_handle w = cgal.nearest_vertex(p);
      EXPECT_EQ(CGAL::to_double(CGAL::squared_distance(p, v->point())), best);
      EXPECT_EQ(CGAL::to_double(CGAL::squared_distance(p, w->point())), best);
      EXPECT_EQ(CGAL::squared_distance(p, fast.nearest_vertex(p, fast.finite_cells_begin())->point()), best);

      Fast_dt::Vertex_handle fv;
      Cgal_dt::Vertex_handle cv;
      const bool on = cgal.is_vertex(p, cv);
      ASSERT_EQ(fast.is_vertex(p, fv), on);
      if(on) {
        EXPECT_TRUE(fv->point() == p);
      }
    }
  }
}

// is_edge / is_facet / is_cell on vertex tuples: true exactly for the faces
// of the triangulation (the same in both), with indices into the cell found.
template <class Tr>
std::vector<int> faces_by_vertices(const Tr& tr)
{
  std::vector<typename Tr::Vertex_handle> v;
  for(auto it = tr.finite_vertices_begin(); it != tr.finite_vertices_end(); ++it) v.push_back(it);
  std::sort(v.begin(), v.end(), [](auto a, auto b) { return point_key(a->point()) < point_key(b->point()); });
  v.push_back(tr.infinite_vertex());
  std::vector<int> answers;
  typename Tr::Cell_handle c;
  const std::size_t n = v.size();
  for(std::size_t a = 0; a < n; a += 3)
    for(std::size_t b = a + 1; b < n; b += 5) {
      int i = -1, j = -1, k = -1, l = -1;
      const bool edge = tr.is_edge(v[a], v[b], c, i, j);
      answers.push_back(edge);
      if(edge) {
        EXPECT_TRUE(c->vertex(i) == v[a] && c->vertex(j) == v[b]);
      }
      for(std::size_t d = b + 1; d < n; d += 11) {
        const bool facet = tr.is_facet(v[a], v[b], v[d], c, i, j, k);
        answers.push_back(facet);
        if(facet) {
          EXPECT_TRUE(c->vertex(i) == v[a] && c->vertex(j) == v[b] && c->vertex(k) == v[d]);
        }
        for(std::size_t e = d + 1; e < n; e += 7) {
          const bool cell = tr.is_cell(v[a], v[b], v[d], v[e], c, i, j, k, l);
          answers.push_back(cell);
          if(cell) {
            EXPECT_TRUE(c->vertex(i) == v[a] && c->vertex(j) == v[b] && c->vertex(k) == v[d] && c->vertex(l) == v[e]);
            EXPECT_TRUE(tr.is_cell(c));
          }
        }
      }
    }
  // Every finite edge of the triangulation is found.
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    int i, j;
    EXPECT_TRUE(tr.is_edge(e->first->vertex(e->second), e->first->vertex(e->third), c, i, j));
  }
  EXPECT_TRUE(tr.is_vertex(tr.infinite_vertex()));
  EXPECT_TRUE(tr.is_cell(tr.infinite_cell()));
  EXPECT_TRUE(tr.is_infinite(tr.infinite_cell()));
  return answers;
}

TEST(PointLocation, IsEdgeIsFacetIsCellAsCgal)
{
  for(const Input& in : inputs()) {
    SCOPED_TRACE(in.name);
    const Cgal_dt cgal(in.points.begin(), in.points.end());
    const Fast_dt fast(in.points.begin(), in.points.end());
    const std::vector<int> expected = faces_by_vertices(cgal);
    EXPECT_EQ(faces_by_vertices(fast), expected);
    EXPECT_GT(std::count(expected.begin(), expected.end(), 1), 0);
  }
}

TEST(PointLocation, TriangleAndSegmentAsCgal)
{
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 100, 35));
  const Cgal_dt cgal(points.begin(), points.end());
  const Fast_dt fast(points.begin(), points.end());
  // The plane of triangle(f) is oriented as CGAL orients it: the cell is on its positive side.
  auto signs = [](const auto& tr) {
    std::map<std::vector<Point_key>, int> out;
    for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f)
      for(auto g : {*f, tr.mirror_facet(*f)}) {
        if(tr.is_infinite(g.first)) continue;
        const auto t = tr.triangle(g);
        out[cell_key(tr, g.first)] += int(CGAL::orientation(t[0], t[1], t[2], tr.point(g.first, g.second)));
      }
    for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e)
      EXPECT_EQ(tr.segment(*e).squared_length(),
                CGAL::squared_distance(tr.point(e->first, e->second), tr.point(e->first, e->third)));
    return out;
  };
  EXPECT_TRUE(signs(cgal) == signs(fast));
}

} // namespace test_point_location
