// Adjacency queries around vertices (incident cells, facets, edges, adjacent
// vertices, their finite variants, degree) and the circulators around an
// edge: the same function runs on CGAL::Delaunay_triangulation_3 and on ours,
// and the answers are compared by points (sets around a vertex; cyclic
// sequences around an edge, which are geometric since both triangulations
// have the same positively oriented cells and turn the same way).
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/circulator.h>

#include <iterator>
#include <limits>
#include <map>
#include <string>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_adjacency_queries {

typedef std::vector<Point_key> Face;
const Point_key infinite_key(std::numeric_limits<double>::infinity(), 0, 0);

template <class Tr>
Point_key key_of(const Tr& tr, typename Tr::Vertex_handle v)
{
  return tr.is_infinite(v) ? infinite_key : point_key(v->point());
}

template <class Tr>
Face face_of(const Tr& tr, typename Tr::Cell_handle c, std::initializer_list<int> skip_or_take, bool take)
{
  Face f;
  for(int i = 0; i < 4; ++i) {
    const bool listed = std::find(skip_or_take.begin(), skip_or_take.end(), i) != skip_or_take.end();
    if(listed == take) f.push_back(key_of(tr, c->vertex(i)));
  }
  std::sort(f.begin(), f.end());
  return f;
}

// Everything around one vertex, each list sorted.
struct Around
{
  std::vector<Face> cells, finite_cells, facets, finite_facets, edges, finite_edges;
  std::vector<Point_key> vertices, finite_vertices;
  std::size_t degree = 0;
  friend bool operator==(const Around& a, const Around& b)
  {
    return a.cells == b.cells && a.finite_cells == b.finite_cells && a.facets == b.facets &&
           a.finite_facets == b.finite_facets && a.edges == b.edges && a.finite_edges == b.finite_edges &&
           a.vertices == b.vertices && a.finite_vertices == b.finite_vertices && a.degree == b.degree;
  }
};

template <class T>
std::vector<T> sorted(std::vector<T> v)
{
  std::sort(v.begin(), v.end());
  return v;
}

template <class Tr>
Around around(const Tr& tr, typename Tr::Vertex_handle v)
{
  typedef typename Tr::Cell_handle Cell_handle;
  Around a;
  std::vector<Cell_handle> cells;
  tr.incident_cells(v, std::back_inserter(cells));
  for(Cell_handle c : cells) {
    EXPECT_TRUE(c->has_vertex(v));
    a.cells.push_back(face_of(tr, c, {}, false));
  }
  cells.clear();
  tr.finite_incident_cells(v, std::back_inserter(cells));
  for(Cell_handle c : cells) {
    EXPECT_FALSE(tr.is_infinite(c));
    a.finite_cells.push_back(face_of(tr, c, {}, false));
  }
  std::vector<typename Tr::Facet> facets;
  tr.incident_facets(v, std::back_inserter(facets));
  for(const auto& f : facets) a.facets.push_back(face_of(tr, f.first, {f.second}, false));
  facets.clear();
  tr.finite_incident_facets(v, std::back_inserter(facets));
  for(const auto& f : facets) a.finite_facets.push_back(face_of(tr, f.first, {f.second}, false));
  std::vector<typename Tr::Edge> edges;
  tr.incident_edges(v, std::back_inserter(edges));
  for(const auto& e : edges) a.edges.push_back(face_of(tr, e.first, {e.second, e.third}, true));
  edges.clear();
  tr.finite_incident_edges(v, std::back_inserter(edges));
  for(const auto& e : edges) a.finite_edges.push_back(face_of(tr, e.first, {e.second, e.third}, true));
  std::vector<typename Tr::Vertex_handle> vertices;
  tr.adjacent_vertices(v, std::back_inserter(vertices));
  for(auto w : vertices) a.vertices.push_back(key_of(tr, w));
  vertices.clear();
  tr.finite_adjacent_vertices(v, std::back_inserter(vertices));
  for(auto w : vertices) a.finite_vertices.push_back(key_of(tr, w));
  a.degree = tr.degree(v);

  a.cells = sorted(a.cells);
  a.finite_cells = sorted(a.finite_cells);
  a.facets = sorted(a.facets);
  a.finite_facets = sorted(a.finite_facets);
  a.edges = sorted(a.edges);
  a.finite_edges = sorted(a.finite_edges);
  a.vertices = sorted(a.vertices);
  a.finite_vertices = sorted(a.finite_vertices);
  // Each face once.
  EXPECT_TRUE(std::adjacent_find(a.cells.begin(), a.cells.end()) == a.cells.end());
  EXPECT_TRUE(std::adjacent_find(a.facets.begin(), a.facets.end()) == a.facets.end());
  EXPECT_TRUE(std::adjacent_find(a.edges.begin(), a.edges.end()) == a.edges.end());
  EXPECT_TRUE(std::adjacent_find(a.vertices.begin(), a.vertices.end()) == a.vertices.end());
  EXPECT_EQ(a.degree, a.vertices.size());
  return a;
}

template <class Tr>
std::map<Point_key, Around> around_every_vertex(const Tr& tr)
{
  std::map<Point_key, Around> all;
  for(auto v = tr.all_vertices_begin(); v != tr.all_vertices_end(); ++v) {
    const typename Tr::Vertex_handle h = v;
    all[key_of(tr, h)] = around(tr, h);
  }
  return all;
}

// Rotated so that the smallest element comes first.
template <class T>
std::vector<T> canonical_cycle(std::vector<T> cycle)
{
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  return cycle;
}

// Around every finite edge, oriented from its smaller to its larger point:
// the cells and facets met by the circulators, forward and backward.
template <class Tr>
std::map<Face, std::vector<std::vector<Face>>> around_every_edge(const Tr& tr)
{
  std::map<Face, std::vector<std::vector<Face>>> all;
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    const typename Tr::Cell_handle c = e->first;
    int i = e->second, j = e->third;
    if(point_key(c->vertex(j)->point()) < point_key(c->vertex(i)->point())) std::swap(i, j);
    std::vector<Face> forward, backward, facets, facets_from_start;

    typename Tr::Cell_circulator cc = tr.incident_cells(c, i, j), done = cc;
    EXPECT_TRUE(cc != nullptr);
    do {
      const typename Tr::Cell_handle d = cc;
      EXPECT_TRUE(d->has_vertex(c->vertex(i)) && d->has_vertex(c->vertex(j)));
      forward.push_back(face_of(tr, d, {}, false));
      ++cc;
    } while(cc != done);
    EXPECT_EQ(CGAL::circulator_size(cc), forward.size());

    typename Tr::Cell_circulator back = tr.incident_cells(typename Tr::Edge(c, i, j), c);
    for(std::size_t k = 0; k < forward.size(); ++k, --back) backward.push_back(face_of(tr, back, {}, false));
    std::reverse(backward.begin() + 1, backward.end());

    typename Tr::Facet_circulator fc = tr.incident_facets(c, i, j), fdone = fc;
    do {
      const typename Tr::Facet f = *fc;
      facets.push_back(face_of(tr, f.first, {f.second}, false));
      ++fc;
    } while(fc != fdone);
    // Starting from a given facet: the same cycle.
    const int k = CGAL::Triangulation_utils_3::next_around_edge(i, j);
    typename Tr::Facet_circulator from = tr.incident_facets(c, i, j, typename Tr::Facet(c, 6 - i - j - k));
    for(std::size_t n = 0; n < facets.size(); ++n, ++from)
      facets_from_start.push_back(face_of(tr, from->first, {from->second}, false));

    const Face edge = {point_key(c->vertex(i)->point()), point_key(c->vertex(j)->point())};
    all[edge] = {canonical_cycle(forward), canonical_cycle(backward), canonical_cycle(facets),
                 canonical_cycle(facets_from_start)};
    EXPECT_TRUE(canonical_cycle(forward) == canonical_cycle(backward));
    EXPECT_TRUE(canonical_cycle(facets) == canonical_cycle(facets_from_start));
    EXPECT_EQ(facets.size(), forward.size());
  }
  return all;
}

struct Input
{
  std::string name;
  std::vector<Point> points;
};

std::vector<Input> inputs()
{
  return {{"uniform", to_points<Point>(make_points("uniform", 200, 41))},
          {"grid", to_points<Point>(make_points("grid", 125, 42))},
          {"sphere", to_points<Point>(make_points("sphere", 150, 43))},
          {"duplicates", to_points<Point>(make_points("duplicates", 150, 44))}};
}

TEST(AdjacencyQueries, AroundEveryVertexAsCgal)
{
  for(const Input& in : inputs()) {
    SCOPED_TRACE(in.name);
    const Cgal_dt cgal(in.points.begin(), in.points.end());
    const Fast_dt fast(in.points.begin(), in.points.end());
    const std::map<Point_key, Around> expected = around_every_vertex(cgal);
    const std::map<Point_key, Around> got = around_every_vertex(fast);
    ASSERT_EQ(expected.size(), got.size());
    std::size_t differ = 0;
    for(const auto& [key, a] : expected) {
      ASSERT_EQ(got.count(key), 1u);
      const Around& b = got.at(key);
      if(a == b) continue;
      if(differ++ < 3)
        ADD_FAILURE() << "around " << std::get<0>(key) << ' ' << std::get<1>(key) << ' ' << std::get<2>(key)
                      << ": cells " << (a.cells == b.cells) << (a.finite_cells == b.finite_cells) << " facets "
                      << (a.facets == b.facets) << (a.finite_facets == b.finite_facets) << " edges "
                      << (a.edges == b.edges) << (a.finite_edges == b.finite_edges) << " vertices "
                      << (a.vertices == b.vertices) << (a.finite_vertices == b.finite_vertices) << " degree "
                      << a.degree << ' ' << b.degree << " sizes " << a.finite_edges.size() << ' '
                      << b.finite_edges.size();
    }
    EXPECT_EQ(differ, 0u);
    // The infinite vertex sees the whole hull.
    EXPECT_EQ(got.at(infinite_key).cells.size(), hull_facet_keys(fast).size());
  }
}

TEST(AdjacencyQueries, CirculatorsAroundEveryEdgeAsCgal)
{
  for(const Input& in : inputs()) {
    SCOPED_TRACE(in.name);
    const Cgal_dt cgal(in.points.begin(), in.points.end());
    const Fast_dt fast(in.points.begin(), in.points.end());
    const auto expected = around_every_edge(cgal);
    const auto got = around_every_edge(fast);
    ASSERT_EQ(expected.size(), got.size());
    EXPECT_TRUE(expected == got);
  }
}

// A loop written for CGAL's circulators (CGAL_For_all, Circulator_from_iterator idiom).
TEST(AdjacencyQueries, CgalCirculatorIdioms)
{
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 100, 45));
  const Fast_dt fast(points.begin(), points.end());
  const Cgal_dt cgal(points.begin(), points.end());
  auto count_all = [](const auto& tr) {
    std::size_t total = 0;
    for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
      auto c = tr.incident_cells(*e), done = c;
      CGAL_For_all(c, done) ++total;
      EXPECT_FALSE(CGAL::is_empty_range(c, done));
    }
    return total;
  };
  EXPECT_EQ(count_all(fast), count_all(cgal));
  // Each finite edge of each cell is met once.
  std::size_t incidences = 0;
  for(auto c = fast.all_cells_begin(); c != fast.all_cells_end(); ++c)
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) incidences += !fast.is_infinite(c, i, j);
  EXPECT_EQ(count_all(fast), incidences);
}

} // namespace test_adjacency_queries
