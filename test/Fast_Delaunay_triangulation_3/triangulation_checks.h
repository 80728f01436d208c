// Independent checks of a triangulation, used by several tests: the finite
// vertices, facets, edges, cells and hull as sorted point tuples (comparable
// with CGAL's), exact orientation, adjacency symmetry, local Delaunay
// property, volume = convex hull volume.
#ifndef CGAL_FDT3_TEST_TRIANGULATION_CHECKS_H
#define CGAL_FDT3_TEST_TRIANGULATION_CHECKS_H

#include "point_sets.h"

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_3.h>
#include <CGAL/Polyhedron_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <iterator>
#include <limits>
#include <map>
#include <set>
#include <tuple>
#include <vector>

namespace fdt3_test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Delaunay_triangulation_3<K> Cgal_dt;

// The sanitizer builds (AddressSanitizer with UBSan, ThreadSanitizer) run the
// tests 5 to 20 times slower than Release; they look for memory and thread
// errors, which the same code paths show on smaller inputs, so the largest
// cases take fewer points there.  Release checks them at full size.
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
constexpr bool sanitized_build = true;
#else
constexpr bool sanitized_build = false;
#endif

// A cell as its four points sorted lexicographically: independent of vertex
// numbering, so cells of two triangulations can be compared.
typedef std::array<std::tuple<double, double, double>, 4> Cell_key;

// CGAL's perturbed predicates (side_of_oriented_sphere and
// coplanar_side_of_bounded_circle with perturb = true) are protected members
// of Delaunay_triangulation_3: reach them from a derived class.
struct Cgal_perturbed_predicates : Cgal_dt
{
  using Cgal_dt::coplanar_side_of_bounded_circle;
  using Cgal_dt::side_of_oriented_sphere;
};

// A point as a tuple, so that simplices of two triangulations can be
// compared as sorted point tuples, independently of vertex numbering.
typedef std::tuple<double, double, double> Point_key;
typedef std::array<Point_key, 3> Facet_key;
typedef std::array<Point_key, 2> Edge_key;

inline Point_key point_key(const Point& p) { return Point_key(p.x(), p.y(), p.z()); }

// Any vertex, the infinite one included (as a point at infinity), and any
// cell as the sorted keys of its vertices.
const Point_key infinite_point_key(std::numeric_limits<double>::infinity(), 0, 0);

template <class Tr>
Point_key vertex_point_key(const Tr& tr, typename Tr::Vertex_handle v)
{
  return tr.is_infinite(v) ? infinite_point_key : point_key(v->point());
}

template <class Tr>
std::array<Point_key, 4> cell_point_keys(const Tr& tr, typename Tr::Cell_handle c)
{
  std::array<Point_key, 4> k;
  for(int i = 0; i < 4; ++i) k[i] = vertex_point_key(tr, c->vertex(i));
  std::sort(k.begin(), k.end());
  return k;
}

// The distinct points of an input, sorted: what the finite vertices must be.
inline std::vector<Point_key> distinct_point_keys(const std::vector<Point>& points)
{
  std::vector<Point_key> keys;
  for(const Point& p : points) keys.push_back(point_key(p));
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

template <class Tr>
std::vector<Point_key> finite_vertex_keys(const Tr& tr)
{
  std::vector<Point_key> keys;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    keys.push_back(point_key(v->point()));
  std::sort(keys.begin(), keys.end());
  return keys;
}

template <class Tr>
std::vector<Facet_key> finite_facet_keys(const Tr& tr)
{
  std::vector<Facet_key> keys;
  for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f) {
    Facet_key k;
    for(int i = 0, j = 0; i < 4; ++i)
      if(i != f->second) k[j++] = point_key(f->first->vertex(i)->point());
    std::sort(k.begin(), k.end());
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

template <class Tr>
std::vector<Edge_key> finite_edge_keys(const Tr& tr)
{
  std::vector<Edge_key> keys;
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    Edge_key k = {point_key(e->first->vertex(e->second)->point()),
                  point_key(e->first->vertex(e->third)->point())};
    std::sort(k.begin(), k.end());
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

// The convex hull as seen from the infinite vertex: the finite facets of the
// infinite cells, and their vertices.
template <class Tr>
std::vector<Facet_key> hull_facet_keys(const Tr& tr)
{
  std::vector<Facet_key> keys;
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    const typename Tr::Cell_handle ch = c;
    if(!tr.is_infinite(ch)) continue;
    const int inf = ch->index(tr.infinite_vertex());
    Facet_key k;
    for(int i = 0, j = 0; i < 4; ++i)
      if(i != inf) k[j++] = point_key(ch->vertex(i)->point());
    std::sort(k.begin(), k.end());
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

template <class Tr>
std::vector<Point_key> hull_vertex_keys(const Tr& tr)
{
  std::vector<Point_key> keys;
  for(const Facet_key& f : hull_facet_keys(tr)) keys.insert(keys.end(), f.begin(), f.end());
  std::sort(keys.begin(), keys.end());
  keys.erase(std::unique(keys.begin(), keys.end()), keys.end());
  return keys;
}

template <class Tr>
std::vector<Cell_key> finite_cell_keys(const Tr& tr)
{
  std::vector<Cell_key> keys;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    Cell_key k;
    for(int i = 0; i < 4; ++i) {
      const Point p = c->vertex(i)->point();
      k[i] = std::make_tuple(p.x(), p.y(), p.z());
    }
    std::sort(k.begin(), k.end());
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

// Orientation, adjacency symmetry and local Delaunay property checked with
// CGAL's exact predicates and CGAL's perturbed in-sphere test, through the
// public handle interface only.
template <class Tr>
void expect_locally_delaunay(const Tr& tr)
{
  const K k;
  const Cgal_perturbed_predicates oracle{};
  std::size_t checked = 0;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    const Point p0 = c->vertex(0)->point(), p1 = c->vertex(1)->point(), p2 = c->vertex(2)->point(),
                p3 = c->vertex(3)->point();
    ASSERT_EQ(k.orientation_3_object()(p0, p1, p2, p3), CGAL::POSITIVE);
    for(int i = 0; i < 4; ++i) {
      auto n = c->neighbor(i);
      const int j = tr.mirror_index(typename Tr::Cell_handle(c), i);
      ASSERT_EQ(n->neighbor(j), typename Tr::Cell_handle(c)) << "adjacency not symmetric";
      for(int l = 0; l < 4; ++l) {
        if(l != i) {
          ASSERT_TRUE(n->has_vertex(c->vertex(l)));
        }
      }
      if(tr.is_infinite(n->vertex(j))) continue;
      const Point q = n->vertex(j)->point();
      ASSERT_NE(oracle.side_of_oriented_sphere(p0, p1, p2, p3, q, true), CGAL::ON_POSITIVE_SIDE)
          << "not locally Delaunay";
      ++checked;
    }
  }
  EXPECT_GT(checked + (tr.number_of_finite_cells() == 1 ? 1 : 0), 0u);
}

// Sum of the cells' exact volumes equals the exact volume of the convex hull
// (CGAL::convex_hull_3, exact predicates; volumes in exact rationals).
template <class Tr>
void expect_volume_of_hull(const Tr& tr, const std::vector<Point>& points)
{
  typedef CGAL::Simple_cartesian<CGAL::Exact_rational> EK;
  typedef EK::Point_3 EP;
  CGAL::Cartesian_converter<K, EK> to_exact;
  EK::FT volume = 0;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    volume += CGAL::volume(to_exact(c->vertex(0)->point()), to_exact(c->vertex(1)->point()),
                           to_exact(c->vertex(2)->point()), to_exact(c->vertex(3)->point()));
  CGAL::Polyhedron_3<K> hull;
  CGAL::convex_hull_3(points.begin(), points.end(), hull);
  EK::FT hull_volume = 0;
  const EP origin = to_exact(points.front());
  for(auto f = hull.facets_begin(); f != hull.facets_end(); ++f) {
    auto h = f->facet_begin();
    const EP a = to_exact(h->vertex()->point());
    ++h;
    EP b = to_exact(h->vertex()->point());
    for(++h; h != f->facet_begin(); ++h) {
      const EP c = to_exact(h->vertex()->point());
      hull_volume += CGAL::volume(origin, a, b, c);
      b = c;
    }
  }
  EXPECT_TRUE(volume == hull_volume) << CGAL::to_double(volume) << " vs " << CGAL::to_double(hull_volume);
}

// Below dimension 3: the counts of every kind of face, the iterators that
// enumerate them, and the finite triangles (dimension 2) and segments
// (dimensions 1 and 2) as point tuples.
template <class Tr>
void expect_same_lower_dimensional_faces(const Tr& tr, const Cgal_dt& cgal)
{
  ASSERT_LT(cgal.dimension(), 3);
  EXPECT_EQ(tr.number_of_cells(), cgal.number_of_cells());
  EXPECT_EQ(tr.number_of_finite_cells(), cgal.number_of_finite_cells());
  EXPECT_EQ(tr.number_of_facets(), cgal.number_of_facets());
  EXPECT_EQ(tr.number_of_finite_facets(), cgal.number_of_finite_facets());
  EXPECT_EQ(tr.number_of_edges(), cgal.number_of_edges());
  EXPECT_EQ(tr.number_of_finite_edges(), cgal.number_of_finite_edges());
  EXPECT_EQ(std::distance(tr.all_cells_begin(), tr.all_cells_end()), 0);
  EXPECT_EQ(std::distance(tr.finite_cells_begin(), tr.finite_cells_end()), 0);
  EXPECT_EQ(std::size_t(std::distance(tr.all_facets_begin(), tr.all_facets_end())), cgal.number_of_facets());
  EXPECT_EQ(std::size_t(std::distance(tr.all_edges_begin(), tr.all_edges_end())), cgal.number_of_edges());
  EXPECT_TRUE(finite_facet_keys(tr) == finite_facet_keys(cgal)) << "different triangles";
  EXPECT_TRUE(finite_edge_keys(tr) == finite_edge_keys(cgal)) << "different edges";
}

// The cells of a triangulation of dimension 0, 1 or 2, reached as CGAL users
// reach them: triangles through the facets, segments through the edges, the
// two point cells through a vertex and its neighbour.
template <class Tr>
std::vector<typename Tr::Cell_handle> lower_dimensional_cells(const Tr& tr)
{
  std::vector<typename Tr::Cell_handle> cells;
  if(tr.dimension() == 2)
    for(auto f = tr.all_facets_begin(); f != tr.all_facets_end(); ++f) cells.push_back(f->first);
  if(tr.dimension() == 1)
    for(auto e = tr.all_edges_begin(); e != tr.all_edges_end(); ++e) cells.push_back(e->first);
  if(tr.dimension() == 0) {
    const typename Tr::Cell_handle c = tr.finite_vertices_begin()->cell();
    cells.push_back(c);
    cells.push_back(c->neighbor(0));
  }
  return cells;
}

// `tr` is the triangulation CGAL builds from the same points: same dimension
// and vertices, and the same cells (in dimension 3 also checked
// independently) or lower-dimensional faces.
template <class Tr>
void expect_same_as_cgal(const Tr& tr, const Cgal_dt& cgal)
{
  EXPECT_TRUE(tr.is_valid());
  ASSERT_EQ(tr.dimension(), cgal.dimension());
  ASSERT_EQ(tr.number_of_vertices(), cgal.number_of_vertices());
  EXPECT_TRUE(finite_vertex_keys(tr) == finite_vertex_keys(cgal)) << "different vertices";
  if(cgal.dimension() < 3) {
    expect_same_lower_dimensional_faces(tr, cgal);
    return;
  }
  EXPECT_EQ(tr.number_of_cells(), cgal.number_of_cells());
  EXPECT_EQ(tr.number_of_finite_cells(), cgal.number_of_finite_cells());
  EXPECT_TRUE(finite_cell_keys(tr) == finite_cell_keys(cgal)) << "different cells";
  expect_locally_delaunay(tr);
}

// The points of the finite cells in iteration order: equal for two triangulations only if every cell is in the
// same slot with its vertices in the same order (what reproducibility and the choice of predicate forms promise).
template <class Tr>
std::vector<std::array<double, 12>> cells_in_slot_order(const Tr& t)
{
  std::vector<std::array<double, 12>> cells;
  for(auto c = t.finite_cells_begin(); c != t.finite_cells_end(); ++c) {
    std::array<double, 12> a;
    for(int i = 0; i < 4; ++i) {
      const auto p = c->vertex(i)->point();
      a[3 * i] = CGAL::to_double(p.x());
      a[3 * i + 1] = CGAL::to_double(p.y());
      a[3 * i + 2] = CGAL::to_double(p.z());
    }
    cells.push_back(a);
  }
  return cells;
}

} // namespace fdt3_test

#endif
