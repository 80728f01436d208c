// The CGAL interface, one test body for two triangulations (CGAL's
// _test_cls_delaunay_3 pattern): every typed test runs on
// CGAL::Delaunay_triangulation_3, which proves its assertions can hold, and
// on CGAL::Fast_Delaunay_triangulation_3, which proves the drop-in.  The
// assertions relate counts, iterators, ranges and handle navigation to each
// other and to independent facts (Euler's relation, distinct input points).
// The tests at the end compare the two triangulations of the same points.
//
// Most typed tests exercise dimension 3; the empty triangulation, insertion,
// backward iteration, points(), insert_outside_affine_hull,
// nearest_vertex_in_cell and the file flush run in every dimension, and
// test_lower_dimensions.cpp runs the conventions of dimensions 0 to 2 on both
// triangulations.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <boost/functional/hash.hpp>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <string>
#include <tuple>
#include <type_traits>
#include <unordered_map>
#include <unordered_set>
#include <utility>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_concept_interface {

struct Named_points
{
  std::string name;
  std::vector<Point> points;
};

// Small inputs in general and in degenerate position (the grid is exactly
// cospherical and coplanar in many places; duplicates are stored once).
std::vector<Named_points> inputs()
{
  std::vector<Named_points> all;
  for(const char* d : {"uniform", "grid", "sphere", "duplicates"})
    all.push_back({d, to_points<Point>(make_points(d, 150, 11))});
  return all;
}

template <class Tr>
class Concept : public ::testing::Test
{
};

struct Triangulation_names
{
  template <class Tr>
  static std::string GetName(int)
  {
    return std::is_same<Tr, Cgal_dt>::value ? "Cgal" : "Fast";
  }
};

typedef ::testing::Types<Cgal_dt, Fast_dt> Triangulations;
TYPED_TEST_SUITE(Concept, Triangulations, Triangulation_names);

template <class Iterator>
std::size_t count(Iterator first, Iterator last)
{
  return static_cast<std::size_t>(std::distance(first, last));
}

// Dimension -1 (no point, or after clear()): one cell, which holds the
// infinite vertex only and has no neighbour, and no cell, facet or edge to
// iterate over.
template <class Tr>
void expect_empty_with_infinite_cell(const Tr& tr)
{
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  EXPECT_EQ(tr.dimension(), -1);
  EXPECT_EQ(tr.number_of_vertices(), 0u);
  EXPECT_EQ(tr.number_of_cells(), 0u);
  EXPECT_EQ(tr.number_of_facets(), 0u);
  EXPECT_EQ(tr.number_of_edges(), 0u);
  const Cell_handle c = tr.infinite_cell();
  ASSERT_TRUE(c != Cell_handle());
  EXPECT_TRUE(c->vertex(0) == tr.infinite_vertex());
  for(int i = 1; i < 4; ++i) EXPECT_TRUE(c->vertex(i) == Vertex_handle());
  for(int i = 0; i < 4; ++i) EXPECT_TRUE(c->neighbor(i) == Cell_handle());
  EXPECT_TRUE(tr.infinite_vertex()->cell() == c);
  EXPECT_TRUE(c->has_vertex(tr.infinite_vertex()));
  EXPECT_EQ(count(tr.all_cells_begin(), tr.all_cells_end()), 0u);
  EXPECT_EQ(count(tr.all_facets_begin(), tr.all_facets_end()), 0u);
  EXPECT_EQ(count(tr.all_edges_begin(), tr.all_edges_end()), 0u);
  EXPECT_EQ(count(tr.all_vertices_begin(), tr.all_vertices_end()), 1u);
  EXPECT_TRUE(tr.is_valid());
}

// The vertices of a facet or an edge, sorted by handle order: the same for
// every (cell, index) representation of it.
template <class Tr>
std::array<typename Tr::Vertex_handle, 3> facet_vertices(const typename Tr::Facet& f)
{
  std::array<typename Tr::Vertex_handle, 3> v;
  for(int i = 0, j = 0; i < 4; ++i)
    if(i != f.second) v[j++] = f.first->vertex(i);
  std::sort(v.begin(), v.end());
  return v;
}

template <class Tr>
std::pair<typename Tr::Vertex_handle, typename Tr::Vertex_handle>
edge_vertices(typename Tr::Cell_handle c, int i, int j)
{
  return std::minmax(c->vertex(i), c->vertex(j));
}

TYPED_TEST(Concept, EmptyTriangulation)
{
  TypeParam tr;
  EXPECT_EQ(tr.dimension(), -1);
  EXPECT_EQ(tr.number_of_vertices(), 0u);
  EXPECT_EQ(tr.number_of_cells(), 0u);
  EXPECT_EQ(tr.number_of_finite_cells(), 0u);
  EXPECT_EQ(tr.number_of_finite_facets(), 0u);
  EXPECT_EQ(tr.number_of_finite_edges(), 0u);
  EXPECT_TRUE(tr.is_valid());
  EXPECT_EQ(count(tr.finite_vertices_begin(), tr.finite_vertices_end()), 0u);
  EXPECT_EQ(count(tr.finite_cells_begin(), tr.finite_cells_end()), 0u);
  EXPECT_EQ(count(tr.finite_facets_begin(), tr.finite_facets_end()), 0u);
  EXPECT_EQ(count(tr.finite_edges_begin(), tr.finite_edges_end()), 0u);
  // Even the empty triangulation has its infinite vertex.
  ASSERT_EQ(count(tr.all_vertices_begin(), tr.all_vertices_end()), 1u);
  EXPECT_TRUE(typename TypeParam::Vertex_handle(tr.all_vertices_begin()) == tr.infinite_vertex());
  EXPECT_TRUE(tr.is_infinite(tr.infinite_vertex()));
  expect_empty_with_infinite_cell(tr);
}

TYPED_TEST(Concept, CountsEqualIteration)
{
  for(const Named_points& input : inputs()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    ASSERT_EQ(tr.dimension(), 3);
    const std::size_t v = count(tr.finite_vertices_begin(), tr.finite_vertices_end());
    const std::size_t e = count(tr.finite_edges_begin(), tr.finite_edges_end());
    const std::size_t f = count(tr.finite_facets_begin(), tr.finite_facets_end());
    const std::size_t c = count(tr.finite_cells_begin(), tr.finite_cells_end());
    const std::size_t all_v = count(tr.all_vertices_begin(), tr.all_vertices_end());
    const std::size_t all_e = count(tr.all_edges_begin(), tr.all_edges_end());
    const std::size_t all_f = count(tr.all_facets_begin(), tr.all_facets_end());
    const std::size_t all_c = count(tr.all_cells_begin(), tr.all_cells_end());
    EXPECT_EQ(v, tr.number_of_vertices());
    EXPECT_EQ(e, tr.number_of_finite_edges());
    EXPECT_EQ(f, tr.number_of_finite_facets());
    EXPECT_EQ(c, tr.number_of_finite_cells());
    EXPECT_EQ(all_v, tr.number_of_vertices() + 1);
    EXPECT_EQ(all_e, tr.number_of_edges());
    EXPECT_EQ(all_f, tr.number_of_facets());
    EXPECT_EQ(all_c, tr.number_of_cells());
    EXPECT_EQ(count(tr.vertices_begin(), tr.vertices_end()), all_v);
    EXPECT_EQ(count(tr.edges_begin(), tr.edges_end()), all_e);
    EXPECT_EQ(count(tr.facets_begin(), tr.facets_end()), all_f);
    EXPECT_EQ(count(tr.cells_begin(), tr.cells_end()), all_c);
    EXPECT_EQ(v, distinct_point_keys(input.points).size());

    // Independent relations: the finite cells triangulate a ball (Euler
    // characteristic 1); with the infinite vertex they triangulate a
    // 3-sphere (characteristic 0); every facet has two cells.
    EXPECT_EQ(v + f, e + c + 1);
    EXPECT_EQ(all_v + all_f, all_e + all_c);
    EXPECT_EQ(2 * all_f, 4 * all_c);
    // Hull facets: one per infinite cell, and seen from one finite cell.
    EXPECT_EQ(all_c - c, 2 * f - 4 * c);
  }
}

TYPED_TEST(Concept, AllVerticesHoldTheInfiniteVertexOnce)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  for(const Named_points& input : inputs()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    std::set<Vertex_handle> finite, all;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
      EXPECT_FALSE(tr.is_infinite(Vertex_handle(v)));
      finite.insert(v);
    }
    std::size_t infinite = 0;
    for(auto v = tr.all_vertices_begin(); v != tr.all_vertices_end(); ++v) {
      const Vertex_handle h = v;
      if(tr.is_infinite(h)) {
        ++infinite;
        EXPECT_TRUE(h == tr.infinite_vertex());
      } else {
        EXPECT_EQ(finite.count(h), 1u);
      }
      all.insert(h);
    }
    EXPECT_EQ(infinite, 1u);
    EXPECT_EQ(all.size(), finite.size() + 1);
    EXPECT_EQ(finite.count(tr.infinite_vertex()), 0u);
  }
}

TYPED_TEST(Concept, EachFacetEnumeratedOnce)
{
  typedef typename TypeParam::Facet Facet;
  for(const Named_points& input : inputs()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    std::set<std::array<typename TypeParam::Vertex_handle, 3>> all, finite;
    for(auto f = tr.all_facets_begin(); f != tr.all_facets_end(); ++f) {
      EXPECT_TRUE(all.insert(facet_vertices<TypeParam>(*f)).second) << "facet enumerated twice";
      if(!tr.is_infinite(*f)) finite.insert(facet_vertices<TypeParam>(*f));
    }
    std::set<std::array<typename TypeParam::Vertex_handle, 3>> iterated_finite;
    for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f) {
      EXPECT_FALSE(tr.is_infinite(*f));
      EXPECT_TRUE(iterated_finite.insert(facet_vertices<TypeParam>(*f)).second) << "facet enumerated twice";
    }
    EXPECT_TRUE(iterated_finite == finite);
    // Every facet of every cell is there.
    for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
      for(int i = 0; i < 4; ++i)
        EXPECT_EQ(all.count(facet_vertices<TypeParam>(Facet(c, i))), 1u);
    EXPECT_EQ(all.size(), tr.number_of_facets());
    EXPECT_EQ(finite.size(), tr.number_of_finite_facets());
  }
}

TYPED_TEST(Concept, EachEdgeEnumeratedOnce)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  for(const Named_points& input : inputs()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    std::set<std::pair<Vertex_handle, Vertex_handle>> all, finite;
    for(auto e = tr.all_edges_begin(); e != tr.all_edges_end(); ++e) {
      EXPECT_TRUE(all.insert(edge_vertices<TypeParam>(e->first, e->second, e->third)).second)
          << "edge enumerated twice";
      if(!tr.is_infinite(*e)) finite.insert(edge_vertices<TypeParam>(e->first, e->second, e->third));
    }
    std::set<std::pair<Vertex_handle, Vertex_handle>> iterated_finite;
    for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
      EXPECT_FALSE(tr.is_infinite(*e));
      EXPECT_TRUE(iterated_finite.insert(edge_vertices<TypeParam>(e->first, e->second, e->third)).second)
          << "edge enumerated twice";
    }
    EXPECT_TRUE(iterated_finite == finite);
    for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
      for(int i = 0; i < 4; ++i)
        for(int j = i + 1; j < 4; ++j) EXPECT_EQ(all.count(edge_vertices<TypeParam>(c, i, j)), 1u);
    EXPECT_EQ(all.size(), tr.number_of_edges());
    EXPECT_EQ(finite.size(), tr.number_of_finite_edges());
  }
}

TYPED_TEST(Concept, NeighboursAndMirrorsAreConsistent)
{
  typedef typename TypeParam::Cell_handle Cell_handle;
  typedef typename TypeParam::Facet Facet;
  for(const Named_points& input : inputs()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    for(Cell_handle c : tr.all_cell_handles()) {
      for(int i = 0; i < 4; ++i) {
        const Cell_handle n = c->neighbor(i);
        const int j = tr.mirror_index(c, i);
        ASSERT_TRUE(n->neighbor(j) == c);
        EXPECT_EQ(n->index(c), j);
        EXPECT_EQ(c->index(n), i);
        EXPECT_TRUE(c->has_neighbor(n));
        EXPECT_TRUE(tr.mirror_vertex(c, i) == n->vertex(j));
        EXPECT_FALSE(c->has_vertex(n->vertex(j)));
        for(int k = 0; k < 4; ++k) {
          if(k != i) {
            EXPECT_TRUE(n->has_vertex(c->vertex(k)));
          }
        }

        const Facet f(c, i);
        const Facet m = tr.mirror_facet(f);
        EXPECT_TRUE(m.first == n);
        EXPECT_EQ(m.second, j);
        EXPECT_TRUE(tr.mirror_facet(m) == f);
        EXPECT_TRUE(facet_vertices<TypeParam>(m) == facet_vertices<TypeParam>(f));

        EXPECT_EQ(c->index(c->vertex(i)), i);
        int k = -1;
        EXPECT_TRUE(c->has_vertex(c->vertex(i), k));
        EXPECT_EQ(k, i);
      }
    }
  }
}

TYPED_TEST(Concept, VerticesKnowAnIncidentCell)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  for(const Named_points& input : inputs()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    for(Vertex_handle v : tr.all_vertex_handles()) {
      const Cell_handle c = v->cell();
      ASSERT_TRUE(c->has_vertex(v));
      EXPECT_TRUE(c->vertex(c->index(v)) == v);
    }
    std::map<Vertex_handle, std::size_t> incident;
    for(Cell_handle c : tr.all_cell_handles())
      for(int i = 0; i < 4; ++i) {
        EXPECT_TRUE(c->vertex(i)->cell()->has_vertex(c->vertex(i)));
        ++incident[c->vertex(i)];
      }
    EXPECT_EQ(incident.size(), tr.number_of_vertices() + 1);
    // Every vertex is in at least 4 cells.
    for(const auto& vi : incident) EXPECT_GE(vi.second, 4u);
    EXPECT_TRUE(tr.is_infinite(tr.infinite_cell()));
    EXPECT_TRUE(tr.infinite_cell()->has_vertex(tr.infinite_vertex()));
  }
}

TYPED_TEST(Concept, IsInfiniteOverloadsAgree)
{
  typedef typename TypeParam::Cell_handle Cell_handle;
  typedef typename TypeParam::Facet Facet;
  typedef typename TypeParam::Edge Edge;
  const std::vector<Point> points = to_points<Point>(make_points("grid", 64, 3));
  const TypeParam tr(points.begin(), points.end());
  const auto inf = tr.infinite_vertex();
  std::size_t infinite_cells = 0;
  for(Cell_handle c : tr.all_cell_handles()) {
    EXPECT_EQ(tr.is_infinite(c), c->has_vertex(inf));
    infinite_cells += tr.is_infinite(c) ? 1 : 0;
    for(int i = 0; i < 4; ++i) {
      const bool facet_infinite = c->has_vertex(inf) && c->vertex(i) != inf;
      EXPECT_EQ(tr.is_infinite(c, i), facet_infinite);
      EXPECT_EQ(tr.is_infinite(Facet(c, i)), facet_infinite);
      for(int j = i + 1; j < 4; ++j) {
        const bool edge_infinite = c->vertex(i) == inf || c->vertex(j) == inf;
        EXPECT_EQ(tr.is_infinite(c, i, j), edge_infinite);
        EXPECT_EQ(tr.is_infinite(Edge(c, i, j)), edge_infinite);
      }
    }
  }
  EXPECT_EQ(infinite_cells, tr.number_of_cells() - tr.number_of_finite_cells());
  for(Cell_handle c : tr.finite_cell_handles()) EXPECT_FALSE(tr.is_infinite(c));
}

// Handles in iteration order, from an iterator pair (through the iterator's
// conversion to a handle) or from a range of handles.
template <class Handle, class Iterator>
std::vector<Handle> handles_in(Iterator first, Iterator last)
{
  std::vector<Handle> out;
  for(; first != last; ++first) out.push_back(Handle(first));
  return out;
}

template <class Handle, class Range>
std::vector<Handle> handles_in(const Range& range)
{
  std::vector<Handle> out;
  for(Handle h : range) out.push_back(h);
  return out;
}

template <class Iterator>
std::vector<std::tuple<typename Iterator::value_type::first_type, int, int>> edges_in(Iterator first,
                                                                                   Iterator last)
{
  std::vector<std::tuple<typename Iterator::value_type::first_type, int, int>> out;
  for(; first != last; ++first) out.emplace_back(first->first, first->second, first->third);
  return out;
}

template <class Iterator>
std::vector<typename Iterator::value_type> facets_in(Iterator first, Iterator last)
{
  return std::vector<typename Iterator::value_type>(first, last);
}

TYPED_TEST(Concept, RangesEqualIterators)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 100, 5));
  const TypeParam tr(points.begin(), points.end());

  const std::vector<Cell_handle> finite_cells =
      handles_in<Cell_handle>(tr.finite_cells_begin(), tr.finite_cells_end());
  ASSERT_EQ(finite_cells.size(), tr.number_of_finite_cells());
  EXPECT_TRUE(handles_in<Cell_handle>(tr.finite_cell_handles()) == finite_cells);
  EXPECT_TRUE(handles_in<Cell_handle>(tr.all_cell_handles()) ==
              handles_in<Cell_handle>(tr.all_cells_begin(), tr.all_cells_end()));
  EXPECT_TRUE(handles_in<Vertex_handle>(tr.finite_vertex_handles()) ==
              handles_in<Vertex_handle>(tr.finite_vertices_begin(), tr.finite_vertices_end()));
  EXPECT_TRUE(handles_in<Vertex_handle>(tr.all_vertex_handles()) ==
              handles_in<Vertex_handle>(tr.all_vertices_begin(), tr.all_vertices_end()));
  EXPECT_TRUE(facets_in(tr.finite_facets().begin(), tr.finite_facets().end()) ==
              facets_in(tr.finite_facets_begin(), tr.finite_facets_end()));
  EXPECT_TRUE(facets_in(tr.all_facets().begin(), tr.all_facets().end()) ==
              facets_in(tr.all_facets_begin(), tr.all_facets_end()));
  EXPECT_TRUE(edges_in(tr.finite_edges().begin(), tr.finite_edges().end()) ==
              edges_in(tr.finite_edges_begin(), tr.finite_edges_end()));
  EXPECT_TRUE(edges_in(tr.all_edges().begin(), tr.all_edges().end()) ==
              edges_in(tr.all_edges_begin(), tr.all_edges_end()));

  // Dereferencing an iterator and going through its handle reach the same element.
  auto c = tr.finite_cells_begin();
  EXPECT_TRUE(c->vertex(0) == Cell_handle(c)->vertex(0));
  EXPECT_TRUE((*c).neighbor(1) == Cell_handle(c)->neighbor(1));
  auto v = tr.finite_vertices_begin();
  EXPECT_TRUE(v->point() == Vertex_handle(v)->point());
}

TYPED_TEST(Concept, HandlesWorkAsKeys)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  const std::vector<Point> points = to_points<Point>(make_points("gauss", 120, 9));
  const TypeParam tr(points.begin(), points.end());

  std::set<Vertex_handle> vertex_set;
  std::map<Cell_handle, std::size_t> cell_number;
  std::unordered_map<Vertex_handle, Point> point_of;                      // std::hash
  std::unordered_set<Cell_handle, boost::hash<Cell_handle>> cell_hash_set; // boost::hash
  for(Vertex_handle v : tr.all_vertex_handles()) {
    vertex_set.insert(v);
    if(!tr.is_infinite(v)) point_of[v] = v->point();
  }
  for(Cell_handle c : tr.all_cell_handles()) {
    cell_number.emplace(c, cell_number.size());
    cell_hash_set.insert(c);
  }
  EXPECT_EQ(vertex_set.size(), tr.number_of_vertices() + 1);
  EXPECT_EQ(point_of.size(), tr.number_of_vertices());
  EXPECT_EQ(cell_number.size(), tr.number_of_cells());
  EXPECT_EQ(cell_hash_set.size(), tr.number_of_cells());

  // Handles reached by navigation find the keys stored from iteration, and
  // equal handles hash equally.
  const std::hash<Vertex_handle> std_hash;
  const boost::hash<Cell_handle> boost_hash;
  for(Cell_handle c : tr.all_cell_handles()) {
    for(int i = 0; i < 4; ++i) {
      const Vertex_handle v = c->vertex(i);
      EXPECT_EQ(vertex_set.count(v), 1u);
      if(!tr.is_infinite(v)) {
        ASSERT_EQ(point_of.count(v), 1u);
        EXPECT_TRUE(point_of[v] == v->point());
        EXPECT_EQ(std_hash(v), std_hash(*vertex_set.find(v)));
      }
      const Cell_handle n = c->neighbor(i);
      EXPECT_EQ(cell_number.count(n), 1u);
      EXPECT_EQ(cell_hash_set.count(n), 1u);
      EXPECT_EQ(boost_hash(n), boost_hash(cell_number.find(n)->first));
    }
  }
  // Distinct handles are distinct keys.
  std::set<Point_key> distinct_points;
  for(const auto& vp : point_of) distinct_points.insert(point_key(vp.second));
  EXPECT_EQ(distinct_points.size(), point_of.size());
}

TYPED_TEST(Concept, CopyIsEqualAndIndependent)
{
  typedef typename TypeParam::Cell_handle Cell_handle;
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 200, 21));
  const std::vector<Point> more = to_points<Point>(make_points("uniform", 50, 22));
  std::vector<Point> union_of_both = points;
  union_of_both.insert(union_of_both.end(), more.begin(), more.end());
  const Cgal_dt reference(union_of_both.begin(), union_of_both.end());

  TypeParam original(points.begin(), points.end());
  const std::vector<Cell_key> before = finite_cell_keys(original);

  TypeParam copy(original);
  TypeParam assigned(more.begin(), more.end());
  assigned = original;
  for(TypeParam* t : {&copy, &assigned}) {
    EXPECT_TRUE(t->is_valid());
    EXPECT_EQ(t->number_of_vertices(), original.number_of_vertices());
    EXPECT_EQ(t->number_of_cells(), original.number_of_cells());
    EXPECT_TRUE(finite_cell_keys(*t) == before);
    EXPECT_TRUE(t->infinite_vertex() != original.infinite_vertex());
    // Navigation in the copy stays in the copy.
    std::set<Cell_handle> own(t->all_cell_handles().begin(), t->all_cell_handles().end());
    std::set<Cell_handle> others(original.all_cell_handles().begin(), original.all_cell_handles().end());
    for(Cell_handle c : t->all_cell_handles())
      for(int i = 0; i < 4; ++i) {
        EXPECT_EQ(own.count(c->neighbor(i)), 1u);
        EXPECT_EQ(others.count(c->neighbor(i)), 0u);
      }
    EXPECT_EQ(t->is_infinite(t->infinite_cell()), true);

    t->insert(more.begin(), more.end());
    expect_same_as_cgal(*t, reference);
    EXPECT_TRUE(finite_cell_keys(original) == before) << "the original changed with its copy";
    EXPECT_TRUE(original.is_valid());
  }
}

TYPED_TEST(Concept, MoveTransfersTheTriangulation)
{
  const std::vector<Point> points = to_points<Point>(make_points("grid", 125, 23));
  const Cgal_dt reference(points.begin(), points.end());

  TypeParam source(points.begin(), points.end());
  TypeParam moved(std::move(source));
  expect_same_as_cgal(moved, reference);
  // CGAL 5.5 leaves a moved-from triangulation unusable until clear();
  // after clear() both must be empty, valid and reusable.
  source.clear();
  EXPECT_EQ(source.number_of_vertices(), 0u);
  EXPECT_EQ(source.dimension(), -1);
  EXPECT_TRUE(source.is_valid());
  source.insert(points.begin(), points.end());
  expect_same_as_cgal(source, reference);

  const std::vector<Point> other_points = to_points<Point>(make_points("uniform", 30, 24));
  TypeParam target(other_points.begin(), other_points.end());
  target = std::move(moved);
  expect_same_as_cgal(target, reference);
  moved.clear();
  EXPECT_EQ(moved.number_of_vertices(), 0u);
  EXPECT_TRUE(moved.is_valid());
}

TYPED_TEST(Concept, SwapExchangesTriangulations)
{
  const std::vector<Point> a_points = to_points<Point>(make_points("uniform", 80, 25));
  const std::vector<Point> b_points = to_points<Point>(make_points("sphere", 60, 26));
  const Cgal_dt a_reference(a_points.begin(), a_points.end());
  const Cgal_dt b_reference(b_points.begin(), b_points.end());
  TypeParam a(a_points.begin(), a_points.end());
  TypeParam b(b_points.begin(), b_points.end());
  a.swap(b);
  expect_same_as_cgal(a, b_reference);
  expect_same_as_cgal(b, a_reference);
  using std::swap;
  swap(a, b);
  expect_same_as_cgal(a, a_reference);
  expect_same_as_cgal(b, b_reference);
  TypeParam empty;
  a.swap(empty);
  EXPECT_EQ(a.number_of_vertices(), 0u);
  EXPECT_TRUE(a.is_valid());
  expect_same_as_cgal(empty, a_reference);
}

// Handles point into the data, which swap() and the moves hand over: a
// handle taken before designates the same vertex or cell afterwards, in the
// triangulation that now holds the data; handles kept as map keys still find
// their entries; an iterator over all cells goes on over the same cells.
TYPED_TEST(Concept, HandlesFollowTheData)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  const std::vector<Point> a_points = to_points<Point>(make_points("uniform", 80, 31));
  const std::vector<Point> b_points = to_points<Point>(make_points("grid", 64, 32));
  TypeParam a(a_points.begin(), a_points.end());
  TypeParam b(b_points.begin(), b_points.end());

  std::map<Vertex_handle, Point> point_of;
  for(auto v = a.finite_vertices_begin(); v != a.finite_vertices_end(); ++v) point_of[v] = v->point();
  std::vector<std::pair<Cell_handle, std::array<Vertex_handle, 4>>> cells;
  for(auto c = a.all_cells_begin(); c != a.all_cells_end(); ++c)
    cells.push_back({c, {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)}});
  const Vertex_handle infinite = a.infinite_vertex();
  const auto rest = std::next(a.all_cells_begin(), 5);

  // Every handle of a's data, checked in the triangulation `holder`.
  auto expect_held_by = [&](const TypeParam& holder, const char* when) {
    SCOPED_TRACE(when);
    EXPECT_TRUE(holder.infinite_vertex() == infinite);
    std::set<Vertex_handle> held(holder.finite_vertex_handles().begin(), holder.finite_vertex_handles().end());
    for(const auto& vp : point_of) {
      EXPECT_EQ(held.count(vp.first), 1u);
      EXPECT_TRUE(vp.first->point() == vp.second);
    }
    std::set<Cell_handle> held_cells(holder.all_cell_handles().begin(), holder.all_cell_handles().end());
    EXPECT_EQ(held_cells.size(), cells.size());
    for(const auto& c : cells) {
      EXPECT_EQ(held_cells.count(c.first), 1u);
      for(int i = 0; i < 4; ++i) EXPECT_TRUE(c.first->vertex(i) == c.second[i]);
    }
    EXPECT_EQ(count(rest, holder.all_cells_end()), cells.size() - 5);
    EXPECT_TRUE(holder.is_valid());
  };

  a.swap(b);
  expect_held_by(b, "after a.swap(b)");
  TypeParam moved(std::move(b));
  expect_held_by(moved, "after move construction");
  TypeParam assigned(b_points.begin(), b_points.end());
  assigned = std::move(moved);
  expect_held_by(assigned, "after move assignment");
  // The other triangulation has b's points, and handles of its own.
  std::vector<Point> expected = b_points, held;
  for(auto v = a.finite_vertices_begin(); v != a.finite_vertices_end(); ++v) {
    held.push_back(v->point());
    EXPECT_EQ(point_of.count(v), 0u);
  }
  std::sort(expected.begin(), expected.end());
  std::sort(held.begin(), held.end());
  expected.erase(std::unique(expected.begin(), expected.end()), expected.end());
  EXPECT_TRUE(held == expected);
}

TYPED_TEST(Concept, ClearEmptiesAndAllowsReuse)
{
  const std::vector<Point> points = to_points<Point>(make_points("clusters", 100, 27));
  const Cgal_dt reference(points.begin(), points.end());
  TypeParam tr(points.begin(), points.end());
  tr.clear();
  EXPECT_EQ(tr.dimension(), -1);
  EXPECT_EQ(tr.number_of_vertices(), 0u);
  EXPECT_EQ(tr.number_of_cells(), 0u);
  EXPECT_EQ(tr.number_of_finite_edges(), 0u);
  EXPECT_TRUE(tr.finite_cells_begin() == tr.finite_cells_end());
  EXPECT_TRUE(tr.finite_vertices_begin() == tr.finite_vertices_end());
  EXPECT_EQ(count(tr.all_vertices_begin(), tr.all_vertices_end()), 1u);
  EXPECT_TRUE(tr.is_valid());
  expect_empty_with_infinite_cell(tr);
  EXPECT_EQ(tr.insert(points.begin(), points.end()), std::ptrdiff_t(reference.number_of_vertices()));
  expect_same_as_cgal(tr, reference);
}

TYPED_TEST(Concept, RangeInsertReturnsTheNumberOfNewVertices)
{
  // Duplicates inside each batch and across batches; the batches go through
  // dimensions 0, 1, 2 and 3.
  const std::vector<Point> batches[] = {
      {Point(1, 1, 1), Point(1, 1, 1)},
      {Point(2, 2, 2), Point(1, 1, 1), Point(3, 3, 3), Point(2, 2, 2)},
      {Point(0, 1, 0), Point(0, 1, 0), Point(3, 3, 3)},
      {Point(0, 0, 5), Point(2, 2, 2), Point(0, 0, 5)},
      to_points<Point>(make_points("duplicates", 100, 28)),
      to_points<Point>(make_points("duplicates", 100, 28)),
      {},
  };
  const int expected_dimension[] = {0, 1, 2, 3, 3, 3, 3};
  TypeParam tr;
  std::vector<Point> so_far;
  for(std::size_t b = 0; b < std::size(batches); ++b) {
    SCOPED_TRACE("batch " + std::to_string(b));
    const std::size_t distinct_before = distinct_point_keys(so_far).size();
    so_far.insert(so_far.end(), batches[b].begin(), batches[b].end());
    const std::size_t distinct_after = distinct_point_keys(so_far).size();
    EXPECT_EQ(tr.insert(batches[b].begin(), batches[b].end()),
              std::ptrdiff_t(distinct_after - distinct_before));
    EXPECT_EQ(tr.number_of_vertices(), distinct_after);
    EXPECT_EQ(tr.dimension(), expected_dimension[b]);
    EXPECT_TRUE(finite_vertex_keys(tr) == distinct_point_keys(so_far));
  }
  const Cgal_dt reference(so_far.begin(), so_far.end());
  expect_same_as_cgal(tr, reference);
}

TYPED_TEST(Concept, PointInsertReturnsItsVertex)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  auto vertex_at = [](const TypeParam& tr, const Point& p) {
    Vertex_handle found;
    std::size_t matches = 0;
    for(Vertex_handle v : tr.finite_vertex_handles())
      if(v->point() == p) { found = v; ++matches; }
    EXPECT_EQ(matches, 1u);
    return found;
  };
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0),
                                     Point(0, 0, 1), Point(1, 1, 1), Point(0.5, 0.25, 0.125)};
  TypeParam tr;
  for(std::size_t i = 0; i < points.size(); ++i) {
    SCOPED_TRACE("point " + std::to_string(i));
    const Vertex_handle v = tr.insert(points[i]);
    EXPECT_EQ(tr.number_of_vertices(), i + 1);
    EXPECT_TRUE(v->point() == points[i]);
    EXPECT_FALSE(tr.is_infinite(v));
    EXPECT_TRUE(v == vertex_at(tr, points[i]));
    // Inserting it again, or any earlier point, returns the existing vertex
    // in every dimension.
    for(std::size_t j = 0; j <= i; ++j) {
      const Vertex_handle w = vertex_at(tr, points[j]);
      EXPECT_TRUE(tr.insert(points[j]) == w);
      EXPECT_EQ(tr.number_of_vertices(), i + 1);
    }
  }
  ASSERT_EQ(tr.dimension(), 3);
  EXPECT_TRUE(tr.is_valid());

  const Point p(0.25, 0.25, 0.25), q(2, 2, 2);
  const Vertex_handle vp = tr.insert(p, tr.infinite_cell());
  EXPECT_TRUE(vp->point() == p);
  EXPECT_TRUE(vp->cell()->has_vertex(vp));
  const Vertex_handle vq = tr.insert(q, vp);
  EXPECT_TRUE(vq->point() == q);
  EXPECT_TRUE(tr.insert(p, Cell_handle(tr.finite_cells_begin())) == vp);
  EXPECT_TRUE(tr.insert(q, vq) == vq);
  std::vector<Point> all = points;
  all.push_back(p);
  all.push_back(q);
  const Cgal_dt reference(all.begin(), all.end());
  expect_same_as_cgal(tr, reference);
}

TYPED_TEST(Concept, PointsAndTetrahedraOfCells)
{
  const std::vector<Point> points = to_points<Point>(make_points("sphere", 80, 29));
  const TypeParam tr(points.begin(), points.end());
  const K::Orientation_3 orientation = tr.geom_traits().orientation_3_object();
  for(auto c : tr.finite_cell_handles()) {
    for(int i = 0; i < 4; ++i) EXPECT_TRUE(tr.point(c, i) == c->vertex(i)->point());
    const K::Tetrahedron_3 t = tr.tetrahedron(c);
    EXPECT_EQ(orientation(t[0], t[1], t[2], t[3]), CGAL::POSITIVE);
  }
  for(auto v : tr.finite_vertex_handles()) EXPECT_TRUE(tr.point(v) == v->point());
}

// ---------------------------------------------------------------- backward iteration, points(), affine hull
// Inputs of every dimension, -1 to 3, for the tests that run in all of them.
std::vector<Named_points> inputs_of_every_dimension()
{
  std::vector<Named_points> all = inputs();
  all.push_back({"empty", {}});
  all.push_back({"one point twice", {Point(1, 2, 3), Point(1, 2, 3)}});
  std::vector<Point> line, plane;
  for(int i = 0; i < 6; ++i) line.emplace_back(i, 2 * i, -i);
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) plane.emplace_back(i, j, i + j); // cocircular squares
  all.push_back({"collinear", line});
  all.push_back({"coplanar grid", plane});
  return all;
}

// Walking from last back to first with prefix and with postfix -- meets the
// elements of the forward walk in reverse order; postfix -- returns the old
// position.  `key` reads the element at an iterator.
template <class Iterator, class Key>
void expect_backward_is_reversed_forward(Iterator first, Iterator last, Key key, const char* what)
{
  SCOPED_TRACE(what);
  static_assert(std::is_convertible<typename std::iterator_traits<Iterator>::iterator_category,
                                    std::bidirectional_iterator_tag>::value,
                "a bidirectional iterator, as CGAL's");
  typedef decltype(key(first)) Element;
  std::vector<Element> forward, prefix, postfix;
  for(Iterator it = first; it != last; ++it) forward.push_back(key(it));
  for(Iterator it = last; it != first;) {
    --it;
    prefix.push_back(key(it));
  }
  for(Iterator it = last; it != first;) {
    const Iterator old = it--;
    EXPECT_TRUE(++Iterator(it) == old);
    postfix.push_back(key(it));
  }
  std::reverse(prefix.begin(), prefix.end());
  std::reverse(postfix.begin(), postfix.end());
  EXPECT_EQ(prefix.size(), forward.size());
  EXPECT_TRUE(prefix == forward);
  EXPECT_TRUE(postfix == forward);
}

// CGAL's iterators over vertices, cells, facets and edges, the handle
// iterators of its ranges and its point iterator are bidirectional
// (_test_cls_iterator walks them from end() to begin()).
TYPED_TEST(Concept, EveryIteratorRunsBackwards)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  for(const Named_points& input : inputs_of_every_dimension()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    const auto cell = [](auto it) { return Cell_handle(it); };
    const auto vertex = [](auto it) { return Vertex_handle(it); };
    const auto element = [](auto it) { return *it; };
    const auto edge = [](auto it) { return std::make_tuple(it->first, it->second, it->third); };
    const auto point = [](auto it) { return point_key(*it); };
    expect_backward_is_reversed_forward(tr.all_cells_begin(), tr.all_cells_end(), cell, "all cells");
    expect_backward_is_reversed_forward(tr.cells_begin(), tr.cells_end(), cell, "cells");
    expect_backward_is_reversed_forward(tr.finite_cells_begin(), tr.finite_cells_end(), cell, "finite cells");
    expect_backward_is_reversed_forward(tr.all_vertices_begin(), tr.all_vertices_end(), vertex, "all vertices");
    expect_backward_is_reversed_forward(tr.finite_vertices_begin(), tr.finite_vertices_end(), vertex,
                                        "finite vertices");
    expect_backward_is_reversed_forward(tr.all_facets_begin(), tr.all_facets_end(), element, "all facets");
    expect_backward_is_reversed_forward(tr.finite_facets_begin(), tr.finite_facets_end(), element,
                                        "finite facets");
    expect_backward_is_reversed_forward(tr.all_edges_begin(), tr.all_edges_end(), edge, "all edges");
    expect_backward_is_reversed_forward(tr.finite_edges_begin(), tr.finite_edges_end(), edge, "finite edges");
    expect_backward_is_reversed_forward(tr.all_cell_handles().begin(), tr.all_cell_handles().end(), element,
                                        "all cell handles");
    expect_backward_is_reversed_forward(tr.finite_cell_handles().begin(), tr.finite_cell_handles().end(), element,
                                        "finite cell handles");
    expect_backward_is_reversed_forward(tr.all_vertex_handles().begin(), tr.all_vertex_handles().end(), element,
                                        "all vertex handles");
    expect_backward_is_reversed_forward(tr.finite_vertex_handles().begin(), tr.finite_vertex_handles().end(),
                                        element, "finite vertex handles");
    expect_backward_is_reversed_forward(tr.points_begin(), tr.points_end(), point, "points");
    // The counts are those of the forward walks checked elsewhere: a
    // backward walk that stopped early would have failed above.
    EXPECT_EQ(count(tr.finite_vertices_begin(), tr.finite_vertices_end()), tr.number_of_vertices());
  }
}

// points() lists the points of the finite vertices in their order, each
// distinct input point once.
TYPED_TEST(Concept, PointsAreThoseOfTheFiniteVertices)
{
  for(const Named_points& input : inputs_of_every_dimension()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    std::vector<Point_key> of_vertices, of_points, of_range;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) of_vertices.push_back(point_key(v->point()));
    for(typename TypeParam::Point_iterator p = tr.points_begin(); p != tr.points_end(); ++p) {
      of_points.push_back(point_key(*p));
      EXPECT_EQ(p->x(), (*p).x());
    }
    const typename TypeParam::Points range = tr.points();
    EXPECT_TRUE(range.first == tr.points_begin());
    EXPECT_TRUE(range.second == tr.points_end());
    for(const Point& p : range) of_range.push_back(point_key(p));
    EXPECT_TRUE(of_points == of_vertices);
    EXPECT_TRUE(of_range == of_vertices);
    std::sort(of_points.begin(), of_points.end());
    EXPECT_TRUE(of_points == distinct_point_keys(input.points));
  }
}

// CGAL's insert_outside_affine_hull: the point raises the dimension by
// one, and the triangulation is the Delaunay triangulation of all the
// points (the one CGAL builds from them at once).
TYPED_TEST(Concept, InsertOutsideAffineHullRaisesTheDimension)
{
  struct Case
  {
    std::vector<Point> before;
    Point outside;
  };
  std::vector<Point> line, plane;
  for(int i = 0; i < 6; ++i) line.emplace_back(i, 2 * i, -i);
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) plane.emplace_back(i, j, 0);
  const std::vector<Case> cases = {
      {{}, Point(1, 2, 3)},
      {{Point(1, 2, 3)}, Point(0, 0, 0)},
      {{Point(0, 0, 0), Point(1, 0, 0)}, Point(0, 1, 0)},
      {{Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0)}, Point(0, 0, 1)},
      {line, Point(0, 0, 1)},
      {line, Point(3, 6, -2.5)},
      {plane, Point(0, 0, 1)},
      {plane, Point(1.5, 1.5, -1)}, // above the centre of the cocircular grid squares
      {plane, Point(9, -4, 1e-9)},
  };
  for(const Case& c : cases) {
    SCOPED_TRACE(c.before.size());
    TypeParam tr(c.before.begin(), c.before.end());
    const int dimension = tr.dimension();
    const typename TypeParam::Vertex_handle v = tr.insert_outside_affine_hull(c.outside);
    EXPECT_TRUE(v->point() == c.outside);
    EXPECT_EQ(tr.dimension(), dimension + 1);
    std::vector<Point> all = c.before;
    all.push_back(c.outside);
    expect_same_as_cgal(tr, Cgal_dt(all.begin(), all.end()));
  }
}

// nearest_vertex_in_cell: a finite vertex of the cell, and none of the
// cell's finite vertices is strictly nearer (CGAL's cells below dimension 3
// included: triangles and segments; in dimension 0 CGAL 5.5 reads
// c->vertex(1), a null handle, so that dimension is left out).
TYPED_TEST(Concept, NearestVertexInCellIsTheNearestOfItsFiniteVertices)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  const std::vector<Point> queries = to_points<Point>(make_points("uniform", 5, 43));
  for(const Named_points& input : inputs_of_every_dimension()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    if(tr.dimension() < 1) continue;
    std::vector<Cell_handle> cells = lower_dimensional_cells(tr);
    for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) cells.push_back(c);
    const K::Less_distance_to_point_3 closer = tr.geom_traits().less_distance_to_point_3_object();
    for(const Cell_handle c : cells) {
      for(const Point& q : queries) {
        const Vertex_handle v = tr.nearest_vertex_in_cell(q, c);
        ASSERT_TRUE(v != Vertex_handle());
        EXPECT_FALSE(tr.is_infinite(v));
        EXPECT_TRUE(c->has_vertex(v));
        for(int i = 0; i <= tr.dimension(); ++i) {
          if(!tr.is_infinite(c->vertex(i))) {
            EXPECT_FALSE(closer(q, c->vertex(i)->point(), v->point()));
          }
        }
      }
    }
  }
}

// The stream is flushed when operator<< returns, as CGAL's writer leaves
// it: CGAL's simple_triangulation_3 reads its file back while the
// std::ofstream that wrote it is still open.
TYPED_TEST(Concept, WrittenFileIsReadableBeforeTheStreamCloses)
{
  int k = 0;
  for(const Named_points& input : inputs_of_every_dimension()) {
    SCOPED_TRACE(input.name);
    const TypeParam tr(input.points.begin(), input.points.end());
    const std::string path = ::testing::TempDir() + "fdt3_flush_" + std::to_string(k++) + "_" +
                             ::testing::UnitTest::GetInstance()->current_test_info()->name() + ".txt";
    std::ofstream out(path);
    out.precision(17);
    out << tr;
    std::ifstream in(path);
    TypeParam back;
    in >> back;
    EXPECT_FALSE(in.fail());
    EXPECT_TRUE(back.is_valid());
    EXPECT_EQ(back.dimension(), tr.dimension());
    EXPECT_EQ(back.number_of_vertices(), tr.number_of_vertices());
    EXPECT_EQ(back.number_of_cells(), tr.number_of_cells());
    EXPECT_TRUE(finite_vertex_keys(back) == finite_vertex_keys(tr));
    out.close();
    std::remove(path.c_str());
  }
}

// As CGAL's Delaunay_triangulation_3: neither regular nor periodic.
TYPED_TEST(Concept, TagsAreThoseOfADelaunayTriangulation)
{
  static_assert(std::is_same<typename TypeParam::Weighted_tag, CGAL::Tag_false>::value, "not weighted");
  static_assert(std::is_same<typename TypeParam::Periodic_tag, CGAL::Tag_false>::value, "not periodic");
  static_assert(std::is_void<typename TypeParam::Lock_data_structure>::value, "no locks when sequential");
}

// As CGAL's Delaunay_triangulation_3, the class derives from its
// triangulation layer and names it Tr_Base (CGAL's Fixed_alpha_shape_3 uses
// the name); the internal names our class had before the split stay public.
TYPED_TEST(Concept, DerivesFromItsTriangulationLayer)
{
  static_assert(std::is_base_of<typename TypeParam::Tr_Base, TypeParam>::value, "derives from Tr_Base");
}
static_assert(std::is_class<Fast_dt::Anchor>::value && std::is_class<Fast_dt::Tds_types>::value,
              "the storage anchor and the data structure's types are still named through the class");

// The handle conversions and comparisons of CGAL's test suite
// (_test_cls_iterator.h, _test_cls_circulator.h): iterators to handles,
// handles against iterators, a default circulator against 0.
TYPED_TEST(Concept, IteratorsConvertToAndCompareWithHandles)
{
  typedef typename TypeParam::Vertex_handle Vertex_handle;
  typedef typename TypeParam::Cell_handle Cell_handle;
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 40, 41));
  const TypeParam tr(points.begin(), points.end());
  const Vertex_handle first = tr.vertices_begin();
  EXPECT_TRUE(tr.is_infinite(first));
  EXPECT_TRUE(first == tr.all_vertices_begin());
  EXPECT_FALSE(first != tr.all_vertices_begin());
  // (CGAL's handle ranges dereference to an iterator that converts to the handle.)
  Vertex_handle v = *tr.all_vertex_handles().second;
  EXPECT_TRUE(v == tr.all_vertices_end());
  v = *tr.finite_vertex_handles().second;
  EXPECT_TRUE(v == Vertex_handle(tr.finite_vertices_end()));
  Cell_handle ch = *tr.all_cell_handles().first;
  EXPECT_TRUE(ch == tr.all_cells_begin());
  ch = *tr.finite_cell_handles().second;
  EXPECT_TRUE(ch == Cell_handle(tr.finite_cells_end()));
  const Cell_handle c = tr.finite_cells_begin();
  EXPECT_FALSE(tr.is_infinite(c));
  typename TypeParam::Facet_circulator none;
  EXPECT_TRUE(none == 0);
  typename TypeParam::Cell_circulator around = tr.incident_cells(*tr.finite_edges_begin());
  const Cell_handle at = around;
  EXPECT_TRUE(at->has_vertex(tr.finite_edges_begin()->first->vertex(tr.finite_edges_begin()->second)));
  std::vector<Vertex_handle> vertices;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) vertices.push_back(v);
  EXPECT_EQ(vertices.size(), tr.number_of_vertices());
}

// Beyond CGAL 5.5, whose moved-from triangulation needs clear() first: a
// moved-from Fast_Delaunay_triangulation_3 is empty and valid at once.
TEST(Fast_only, MovedFromIsEmptyAndValid)
{
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 50, 30));
  Fast_dt source(points.begin(), points.end());
  Fast_dt moved(std::move(source));
  Fast_dt assigned;
  assigned = std::move(moved);
  for(const Fast_dt* t : {&source, &moved}) {
    EXPECT_EQ(t->number_of_vertices(), 0u);
    EXPECT_EQ(t->dimension(), -1);
    EXPECT_EQ(t->number_of_cells(), 0u);
    EXPECT_TRUE(t->finite_vertices_begin() == t->finite_vertices_end());
    EXPECT_TRUE(t->is_valid());
    expect_empty_with_infinite_cell(*t);
  }
  EXPECT_EQ(assigned.number_of_vertices(), points.size());
  EXPECT_TRUE(assigned.is_valid());
}

// Beyond what CGAL 5.5 guarantees (its finite iterators test finiteness
// against the object they came from): every iterator of this class, finite
// ones, facets and edges included, follows the data through swap() and moves.
TEST(Fast_only, IteratorsFollowTheData)
{
  const std::vector<Point> points = to_points<Point>(make_points("uniform", 60, 33));
  Fast_dt a(points.begin(), points.end());
  auto cells = std::next(a.finite_cells_begin(), 3);
  auto facets = std::next(a.finite_facets_begin(), 3);
  auto edges = std::next(a.finite_edges_begin(), 3);
  auto vertices = std::next(a.finite_vertices_begin(), 3);
  const std::size_t n_cells = count(cells, a.finite_cells_end()), n_facets = count(facets, a.finite_facets_end()),
                    n_edges = count(edges, a.finite_edges_end()), n_vertices = count(vertices, a.finite_vertices_end());
  const Fast_dt::Cell_handle first_cell = cells;
  Fast_dt b;
  b.swap(a);
  Fast_dt c(std::move(b));
  EXPECT_EQ(a.number_of_vertices(), 0u);
  EXPECT_TRUE(Fast_dt::Cell_handle(cells) == first_cell);
  EXPECT_EQ(count(cells, c.finite_cells_end()), n_cells);
  EXPECT_EQ(count(facets, c.finite_facets_end()), n_facets);
  EXPECT_EQ(count(edges, c.finite_edges_end()), n_edges);
  EXPECT_EQ(count(vertices, c.finite_vertices_end()), n_vertices);
}

// Ranges of this package that CGAL 5.5 lacks (finite_cells(), all_cells(),
// finite_vertices(), all_vertices()): the same elements as the iterators.
TEST(Fast_only, CellAndVertexRangesEqualIterators)
{
  typedef Fast_dt::Cell_handle Cell_handle;
  typedef Fast_dt::Vertex_handle Vertex_handle;
  const std::vector<Point> points = to_points<Point>(make_points("grid", 64, 32));
  const Fast_dt tr(points.begin(), points.end());
  EXPECT_TRUE(handles_in<Cell_handle>(tr.finite_cells().begin(), tr.finite_cells().end()) ==
              handles_in<Cell_handle>(tr.finite_cells_begin(), tr.finite_cells_end()));
  EXPECT_TRUE(handles_in<Cell_handle>(tr.all_cells().begin(), tr.all_cells().end()) ==
              handles_in<Cell_handle>(tr.all_cells_begin(), tr.all_cells_end()));
  EXPECT_TRUE(handles_in<Vertex_handle>(tr.finite_vertices().begin(), tr.finite_vertices().end()) ==
              handles_in<Vertex_handle>(tr.finite_vertices_begin(), tr.finite_vertices_end()));
  EXPECT_TRUE(handles_in<Vertex_handle>(tr.all_vertices().begin(), tr.all_vertices().end()) ==
              handles_in<Vertex_handle>(tr.all_vertices_begin(), tr.all_vertices_end()));
  std::size_t finite = 0;
  for(const Fast_dt::Cell& c : tr.finite_cells()) finite += c.has_vertex(tr.infinite_vertex()) ? 0 : 1;
  EXPECT_EQ(finite, tr.number_of_finite_cells());
}

// Ours against CGAL on the same points: every count and the finite facets,
// edges and hull as point tuples.
class Same_as_cgal : public ::testing::TestWithParam<std::string> {};

TEST_P(Same_as_cgal, CountsFacetsEdgesAndHull)
{
  for(std::size_t n : {std::size_t(5), std::size_t(60), std::size_t(400)}) {
    SCOPED_TRACE(n);
    const std::vector<Point> points = to_points<Point>(make_points(GetParam(), n, 31));
    const Fast_dt fast(points.begin(), points.end());
    const Cgal_dt cgal(points.begin(), points.end());
    ASSERT_EQ(fast.dimension(), cgal.dimension());
    EXPECT_EQ(fast.number_of_vertices(), cgal.number_of_vertices());
    EXPECT_TRUE(finite_vertex_keys(fast) == finite_vertex_keys(cgal));
    EXPECT_EQ(fast.number_of_cells(), cgal.number_of_cells());
    EXPECT_EQ(fast.number_of_finite_cells(), cgal.number_of_finite_cells());
    EXPECT_EQ(fast.number_of_facets(), cgal.number_of_facets());
    EXPECT_EQ(fast.number_of_finite_facets(), cgal.number_of_finite_facets());
    EXPECT_EQ(fast.number_of_edges(), cgal.number_of_edges());
    EXPECT_EQ(fast.number_of_finite_edges(), cgal.number_of_finite_edges());
    EXPECT_TRUE(finite_facet_keys(fast) == finite_facet_keys(cgal));
    EXPECT_TRUE(finite_edge_keys(fast) == finite_edge_keys(cgal));
    EXPECT_TRUE(hull_facet_keys(fast) == hull_facet_keys(cgal));
    EXPECT_TRUE(hull_vertex_keys(fast) == hull_vertex_keys(cgal));
  }
}

INSTANTIATE_TEST_SUITE_P(Distributions, Same_as_cgal,
                         ::testing::Values("uniform", "gauss", "clusters", "sphere", "grid", "duplicates",
                                           "offset", "tiny"));

} // namespace test_concept_interface
