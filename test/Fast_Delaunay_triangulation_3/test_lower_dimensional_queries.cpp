// Queries and single insertions below dimension 3 against
// CGAL::Delaunay_triangulation_3 built from the same points: locate (with
// and without hints), side_of_facet / side_of_edge / side_of_circle, the
// incident and adjacent elements of every vertex, degree, is_vertex /
// is_edge / is_facet, insert with a hint or after locate, the cells given by
// insert_and_give_new_cells, find_conflicts, vertices_on_conflict_zone_boundary
// and insert_in_hole in dimension 2, and the insertion that lifts the
// dimension.  The two triangulations number their vertices and cells
// differently, so every answer is compared as the points of the simplices
// it names (as sets where CGAL's order depends on its own history).
#include "triangulation_checks.h"

#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <random>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_lower_dimensional_queries {

typedef std::vector<Point_key> Simplex_key; // sorted points, the infinite one as infinite_point_key

template <class Tr>
Simplex_key key_of(const Tr& tr, std::initializer_list<typename Tr::Vertex_handle> vertices)
{
  Simplex_key k;
  for(const auto& v : vertices) k.push_back(vertex_point_key(tr, v));
  std::sort(k.begin(), k.end());
  return k;
}
// A cell of dimension d: its vertices 0..d.
template <class Tr>
Simplex_key cell_key(const Tr& tr, typename Tr::Cell_handle c)
{
  Simplex_key k;
  if(c == typename Tr::Cell_handle()) return k;
  for(int i = 0; i <= std::max(tr.dimension(), 0); ++i) k.push_back(vertex_point_key(tr, c->vertex(i)));
  std::sort(k.begin(), k.end());
  return k;
}
// Facet (c, i): the vertices of c up to the dimension, but vertex i.
template <class Tr>
Simplex_key facet_key(const Tr& tr, const typename Tr::Facet& f)
{
  Simplex_key k;
  for(int i = 0; i <= tr.dimension(); ++i)
    if(i != f.second) k.push_back(vertex_point_key(tr, f.first->vertex(i)));
  std::sort(k.begin(), k.end());
  return k;
}
template <class Tr>
Simplex_key edge_key(const Tr& tr, const typename Tr::Edge& e)
{
  return key_of(tr, {e.first->vertex(e.second), e.first->vertex(e.third)});
}

template <class T>
std::vector<T> sorted(std::vector<T> v)
{
  std::sort(v.begin(), v.end());
  return v;
}

// The simplex that (lt, li, lj) names in c, as CGAL documents locate's answer.
template <class Tr>
Simplex_key located_simplex(const Tr& tr, typename Tr::Locate_type lt, typename Tr::Cell_handle c, int li, int lj)
{
  switch(lt) {
  case Tr::VERTEX: return key_of(tr, {c->vertex(li)});
  case Tr::EDGE: return key_of(tr, {c->vertex(li), c->vertex(lj)});
  case Tr::FACET:
    if(tr.dimension() == 2) return cell_key(tr, c);
    return facet_key(tr, typename Tr::Facet(c, li));
  default: return cell_key(tr, c);
  }
}

// The vertex of tr at point p (the infinite vertex for infinite_point_key).
template <class Tr>
typename Tr::Vertex_handle vertex_at(const Tr& tr, const Point_key& p)
{
  for(auto v = tr.all_vertices_begin(); v != tr.all_vertices_end(); ++v)
    if(vertex_point_key(tr, v) == p) return v;
  return typename Tr::Vertex_handle();
}

template <class Tr>
typename Tr::Cell_handle cell_with_key(const Tr& tr, const Simplex_key& key)
{
  for(auto c : lower_dimensional_cells(tr))
    if(cell_key(tr, c) == key) return c;
  return typename Tr::Cell_handle();
}

// What locate says about q, comparable across the two triangulations.  The
// cell is unique except for a point on a vertex or an edge (any cell of it)
// or outside the hull of a triangle set (any infinite triangle that sees it).
template <class Tr>
struct Location_key
{
  typename Tr::Locate_type lt;
  Simplex_key simplex;
  bool null_cell;
};
template <class Tr>
Location_key<Tr> locate_key(const Tr& tr, const Point& q, typename Tr::Cell_handle start)
{
  typename Tr::Locate_type lt;
  int li = -1, lj = -1;
  const typename Tr::Cell_handle c = tr.locate(q, lt, li, lj, start);
  Location_key<Tr> k{lt, {}, c == typename Tr::Cell_handle()};
  if(lt == Tr::OUTSIDE_AFFINE_HULL) return k;
  EXPECT_FALSE(k.null_cell);
  const bool unique = !(lt == Tr::OUTSIDE_CONVEX_HULL && tr.dimension() == 2);
  if(unique) k.simplex = located_simplex(tr, lt, c, li, lj);
  else {
    // The infinite triangle's finite edge sees q: CGAL's own side_of_facet
    // on the CGAL triangle with the same points says so (checked by caller).
    k.simplex = cell_key(tr, c);
  }
  return k;
}

// Queries: the vertices, midpoints of the finite edges, centroids of the
// finite triangles, points beyond the hull in the affine hull, points off it.
std::vector<Point> query_points(const Cgal_dt& cgal, const std::vector<Point>& extra)
{
  std::vector<Point> q = extra;
  for(auto v = cgal.finite_vertices_begin(); v != cgal.finite_vertices_end(); ++v) q.push_back(v->point());
  if(cgal.dimension() >= 1)
    for(auto e = cgal.finite_edges_begin(); e != cgal.finite_edges_end(); ++e)
      q.push_back(CGAL::midpoint(e->first->vertex(e->second)->point(), e->first->vertex(e->third)->point()));
  if(cgal.dimension() == 2)
    for(auto f = cgal.finite_facets_begin(); f != cgal.finite_facets_end(); ++f) {
      const auto c = f->first;
      q.push_back(CGAL::centroid(c->vertex(0)->point(), c->vertex(1)->point(), c->vertex(2)->point()));
    }
  return q;
}

void expect_same_locations(const Fast_dt& fast, const Cgal_dt& cgal, const std::vector<Point>& queries)
{
  // Hints: no hint, then every cell of ours (a sample for large inputs) as start.
  std::vector<Fast_dt::Cell_handle> starts(1, Fast_dt::Cell_handle());
  if(fast.dimension() >= 0) {
    const auto cells = lower_dimensional_cells(fast);
    for(std::size_t i = 0; i < cells.size(); i += 1 + cells.size() / 8) starts.push_back(cells[i]);
  }
  for(const Point& q : queries) {
    SCOPED_TRACE("query " + std::to_string(q.x()) + " " + std::to_string(q.y()) + " " + std::to_string(q.z()));
    const Location_key<Cgal_dt> expected = locate_key(cgal, q, Cgal_dt::Cell_handle());
    for(const Fast_dt::Cell_handle& start : starts) {
      const Location_key<Fast_dt> got = locate_key(fast, q, start);
      ASSERT_EQ(static_cast<int>(got.lt), static_cast<int>(expected.lt));
      EXPECT_EQ(got.null_cell, expected.null_cell);
      if(expected.lt == Cgal_dt::OUTSIDE_CONVEX_HULL && cgal.dimension() == 2) {
        // Any infinite triangle whose finite edge sees q.
        const Cgal_dt::Cell_handle same = cell_with_key(cgal, got.simplex);
        ASSERT_TRUE(same != Cgal_dt::Cell_handle());
        EXPECT_TRUE(same->has_vertex(cgal.infinite_vertex()));
        Cgal_dt::Locate_type lt;
        int li, lj;
        EXPECT_NE(cgal.side_of_facet(q, same, lt, li, lj), CGAL::ON_UNBOUNDED_SIDE);
      } else {
        EXPECT_EQ(got.simplex, expected.simplex);
      }
    }
    // The Vertex_handle hint overload and the plain ones.
    if(fast.number_of_vertices() > 0) {
      Fast_dt::Locate_type lt;
      int li, lj;
      fast.locate(q, lt, li, lj, Fast_dt::Vertex_handle(fast.finite_vertices_begin()));
      EXPECT_EQ(static_cast<int>(lt), static_cast<int>(expected.lt));
      EXPECT_EQ(fast.locate(q) == Fast_dt::Cell_handle(), expected.null_cell);
      EXPECT_EQ(fast.locate(q, fast.infinite_vertex()) == Fast_dt::Cell_handle(), expected.null_cell);
    }
    Fast_dt::Vertex_handle fv;
    Cgal_dt::Vertex_handle cv;
    ASSERT_EQ(fast.is_vertex(q, fv), cgal.is_vertex(q, cv));
    if(cgal.is_vertex(q, cv)) {
      EXPECT_TRUE(fv->point() == cv->point());
    }
    // inexact_locate below dimension 3 returns its start, as CGAL's.
    if(fast.dimension() < 3 && starts.size() > 1) {
      EXPECT_TRUE(fast.inexact_locate(q, starts[1]) == starts[1]);
    }
  }
}

// side_of_facet (dimension 2), side_of_edge (dimension 1), side_of_circle
// (dimension 2) of every cell of ours against the CGAL cell with the same points.
void expect_same_sides(const Fast_dt& fast, const Cgal_dt& cgal, const std::vector<Point>& queries)
{
  const int d = cgal.dimension();
  if(d != 1 && d != 2) return;
  for(const Fast_dt::Cell_handle c : lower_dimensional_cells(fast)) {
    const Cgal_dt::Cell_handle cc = cell_with_key(cgal, cell_key(fast, c));
    ASSERT_TRUE(cc != Cgal_dt::Cell_handle());
    for(const Point& q : queries) {
      // Both leave lt alone outside the simplex.
      Fast_dt::Locate_type lt = Fast_dt::OUTSIDE_AFFINE_HULL;
      Cgal_dt::Locate_type clt = Cgal_dt::OUTSIDE_AFFINE_HULL;
      int li = -1, lj = -1, cli = -1, clj = -1;
      CGAL::Bounded_side side, cside;
      if(d == 2) {
        if(!CGAL::coplanar(cgal.finite_vertices_begin()->point(), std::next(cgal.finite_vertices_begin())->point(),
                           std::next(cgal.finite_vertices_begin(), 2)->point(), q))
          continue;
        side = fast.side_of_facet(q, c, lt, li, lj);
        cside = cgal.side_of_facet(q, cc, clt, cli, clj);
        for(bool perturb : {false, true}) {
          EXPECT_EQ(fast.side_of_circle(c, 3, q, perturb), cgal.side_of_circle(cc, 3, q, perturb));
        }
      } else {
        if(!CGAL::collinear(cgal.finite_vertices_begin()->point(), std::next(cgal.finite_vertices_begin())->point(),
                            q))
          continue;
        side = fast.side_of_edge(q, c, lt, li);
        cside = cgal.side_of_edge(q, cc, clt, cli);
      }
      ASSERT_EQ(side, cside);
      ASSERT_EQ(static_cast<int>(lt), static_cast<int>(clt));
      if(side == CGAL::ON_UNBOUNDED_SIDE) continue;
      if(lt == Fast_dt::VERTEX) {
        EXPECT_EQ(key_of(fast, {c->vertex(li)}), key_of(cgal, {cc->vertex(cli)}));
      }
      // side_of_edge's EDGE is the segment itself (li unset).
      if(lt == Fast_dt::EDGE && d == 2) {
        EXPECT_EQ(key_of(fast, {c->vertex(li), c->vertex(lj)}), key_of(cgal, {cc->vertex(cli), cc->vertex(clj)}));
      }
    }
  }
}

template <class Tr, class Handle>
std::vector<Simplex_key> keys_of_cells(const Tr& tr, const std::vector<Handle>& cells)
{
  std::vector<Simplex_key> k;
  for(const auto& c : cells) k.push_back(cell_key(tr, c));
  return sorted(k);
}

// An element that a query writes (cell, facet, edge or vertex), as points.
template <class Tr>
struct Element_key
{
  const Tr& tr;
  Simplex_key operator()(const typename Tr::Cell_handle& c) const { return cell_key(tr, c); }
  Simplex_key operator()(const typename Tr::Facet& f) const { return facet_key(tr, f); }
  Simplex_key operator()(const typename Tr::Edge& e) const { return edge_key(tr, e); }
  Simplex_key operator()(const typename Tr::Vertex_handle& v) const { return key_of(tr, {v}); }
};

// One query on both triangulations (`query(tr, out)` writes elements of
// type Element<Tr> to out): the same elements, as a multiset.
template <template <class> class Element, class Query>
void expect_same_output(const Fast_dt& fast, const Cgal_dt& cgal, const Query& query)
{
  std::vector<Element<Fast_dt>> a;
  std::vector<Element<Cgal_dt>> b;
  query(fast, std::back_inserter(a));
  query(cgal, std::back_inserter(b));
  std::vector<Simplex_key> ka, kb;
  for(const auto& x : a) ka.push_back(Element_key<Fast_dt>{fast}(x));
  for(const auto& x : b) kb.push_back(Element_key<Cgal_dt>{cgal}(x));
  EXPECT_EQ(sorted(ka), sorted(kb));
}
template <class Tr> using Cell_of = typename Tr::Cell_handle;
template <class Tr> using Facet_of = typename Tr::Facet;
template <class Tr> using Edge_of = typename Tr::Edge;
template <class Tr> using Vertex_of = typename Tr::Vertex_handle;

// The incident and adjacent elements of every vertex, the infinite one
// included, as multisets of point sets; degree.
void expect_same_adjacency(const Fast_dt& fast, const Cgal_dt& cgal)
{
  for(auto cv = cgal.all_vertices_begin(); cv != cgal.all_vertices_end(); ++cv) {
    const Point_key at = vertex_point_key(cgal, cv);
    ASSERT_TRUE(vertex_at(fast, at) != Fast_dt::Vertex_handle());
    SCOPED_TRACE(cgal.is_infinite(cv) ? std::string("infinite vertex") : "vertex at x " + std::to_string(cv->point().x()));
    EXPECT_EQ(fast.degree(vertex_at(fast, at)), cgal.degree(cv));
    // The same vertex in either triangulation.
    auto v = [&at](const auto& tr) { return vertex_at(tr, at); };
    expect_same_output<Cell_of>(fast, cgal, [&](const auto& tr, auto out) { tr.incident_cells(v(tr), out); });
    expect_same_output<Cell_of>(fast, cgal, [&](const auto& tr, auto out) { tr.finite_incident_cells(v(tr), out); });
    if(cgal.dimension() >= 2) {
      expect_same_output<Facet_of>(fast, cgal, [&](const auto& tr, auto out) { tr.incident_facets(v(tr), out); });
      expect_same_output<Facet_of>(fast, cgal,
                                   [&](const auto& tr, auto out) { tr.finite_incident_facets(v(tr), out); });
    }
    if(cgal.dimension() >= 1) {
      expect_same_output<Edge_of>(fast, cgal, [&](const auto& tr, auto out) { tr.incident_edges(v(tr), out); });
      expect_same_output<Edge_of>(fast, cgal,
                                  [&](const auto& tr, auto out) { tr.finite_incident_edges(v(tr), out); });
    }
    expect_same_output<Vertex_of>(fast, cgal, [&](const auto& tr, auto out) { tr.adjacent_vertices(v(tr), out); });
    expect_same_output<Vertex_of>(fast, cgal,
                                  [&](const auto& tr, auto out) { tr.finite_adjacent_vertices(v(tr), out); });
    expect_same_output<Vertex_of>(fast, cgal, [&](const auto& tr, auto out) { tr.incident_vertices(v(tr), out); });
  }
}

// is_edge / is_facet on every pair / triple of vertices (infinite included).
void expect_same_is_edge_and_facet(const Fast_dt& fast, const Cgal_dt& cgal)
{
  std::vector<Cgal_dt::Vertex_handle> cv;
  for(auto v = cgal.all_vertices_begin(); v != cgal.all_vertices_end(); ++v) cv.push_back(v);
  if(cv.size() > 12) cv.resize(12);
  std::vector<Fast_dt::Vertex_handle> fv;
  for(const auto& v : cv) fv.push_back(vertex_at(fast, vertex_point_key(cgal, v)));
  for(std::size_t a = 0; a < cv.size(); ++a)
    for(std::size_t b = 0; b < cv.size(); ++b) {
      Fast_dt::Cell_handle fc;
      Cgal_dt::Cell_handle cc;
      int i = -1, j = -1, ci = -1, cj = -1;
      const bool edge = cgal.is_edge(cv[a], cv[b], cc, ci, cj);
      ASSERT_EQ(fast.is_edge(fv[a], fv[b], fc, i, j), edge);
      if(edge) {
        EXPECT_TRUE(fc->vertex(i) == fv[a] && fc->vertex(j) == fv[b]);
      }
      for(std::size_t c = b + 1; c < cv.size(); ++c) {
        int k = -1, ck = -1;
        const bool facet = cgal.is_facet(cv[a], cv[b], cv[c], cc, ci, cj, ck);
        ASSERT_EQ(fast.is_facet(fv[a], fv[b], fv[c], fc, i, j, k), facet);
        if(facet) {
          EXPECT_TRUE(fc->vertex(i) == fv[a] && fc->vertex(j) == fv[b] && fc->vertex(k) == fv[c]);
        }
      }
    }
  for(const Fast_dt::Cell_handle c : lower_dimensional_cells(fast)) {
    EXPECT_FALSE(fast.is_cell(c)) << "CGAL has no cells below dimension 3";
  }
}

// The insertions of q, each on a fresh copy of both triangulations: with a
// cell hint, with a vertex hint, after locate, and by
// insert_and_give_new_cells; the result and the new cells must be CGAL's.
void expect_same_insertions(const std::vector<Point>& points, const Point& q)
{
  const Cgal_dt cgal_before(points.begin(), points.end());
  const Fast_dt fast_before(points.begin(), points.end());
  Cgal_dt cgal_after = cgal_before;
  cgal_after.insert(q);
  for(int how = 0; how < 4; ++how) {
    SCOPED_TRACE("insertion kind " + std::to_string(how));
    Fast_dt fast = fast_before;
    Cgal_dt cgal = cgal_before;
    std::vector<Fast_dt::Cell_handle> fast_cells;
    std::vector<Cgal_dt::Cell_handle> cgal_cells;
    Fast_dt::Vertex_handle v;
    const auto fcells = lower_dimensional_cells(fast);
    const Fast_dt::Cell_handle hint = fcells.empty() ? Fast_dt::Cell_handle() : fcells.back();
    if(how == 0) v = fast.insert(q, hint);
    if(how == 1) v = fast.insert(q, fast.number_of_vertices() ? Fast_dt::Vertex_handle(fast.finite_vertices_begin())
                                                              : Fast_dt::Vertex_handle());
    if(how == 2) {
      Fast_dt::Locate_type lt;
      int li = -1, lj = -1;
      const Fast_dt::Cell_handle c = fast.locate(q, lt, li, lj, hint);
      v = fast.insert(q, lt, c, li, lj);
    }
    if(how == 3) {
      v = fast.insert_and_give_new_cells(q, std::back_inserter(fast_cells), hint);
      cgal.insert_and_give_new_cells(q, std::back_inserter(cgal_cells));
      if(cgal.dimension() < 3) {
        EXPECT_EQ(keys_of_cells(fast, fast_cells), keys_of_cells(cgal, cgal_cells));
      } else {
        EXPECT_EQ(fast_cells.size(), cgal_cells.size());
      }
    }
    ASSERT_TRUE(v != Fast_dt::Vertex_handle());
    EXPECT_TRUE(v->point() == q);
    EXPECT_TRUE(fast.is_valid());
    expect_same_as_cgal(fast, cgal_after);
    if(fast.dimension() < 3) expect_same_adjacency(fast, cgal_after);
  }
}

// Dimension 2: the conflict zone of q and its replacement by insert_in_hole.
void expect_same_conflicts(const std::vector<Point>& points, const Point& q)
{
  Cgal_dt cgal(points.begin(), points.end());
  Fast_dt fast(points.begin(), points.end());
  ASSERT_EQ(cgal.dimension(), 2);
  Cgal_dt::Locate_type clt;
  int li, lj;
  const Cgal_dt::Cell_handle cc = cgal.locate(q, clt, li, lj);
  if(clt == Cgal_dt::VERTEX || clt == Cgal_dt::OUTSIDE_AFFINE_HULL) return;
  const Fast_dt::Cell_handle fc = fast.locate(q);
  std::vector<Cgal_dt::Facet> cb, ci;
  std::vector<Cgal_dt::Cell_handle> ccells;
  std::vector<Fast_dt::Facet> fb, fi;
  std::vector<Fast_dt::Cell_handle> fcells;
  cgal.find_conflicts(q, cc, std::back_inserter(cb), std::back_inserter(ccells), std::back_inserter(ci));
  fast.find_conflicts(q, fc, std::back_inserter(fb), std::back_inserter(fcells), std::back_inserter(fi));
  EXPECT_EQ(keys_of_cells(fast, fcells), keys_of_cells(cgal, ccells));
  std::vector<Simplex_key> kfb, kcb, kfi, kci;
  for(const auto& f : fb) kfb.push_back(facet_key(fast, f));
  for(const auto& f : cb) kcb.push_back(facet_key(cgal, f));
  for(const auto& f : fi) kfi.push_back(facet_key(fast, f));
  for(const auto& f : ci) kci.push_back(facet_key(cgal, f));
  EXPECT_EQ(sorted(kfb), sorted(kcb));
  EXPECT_EQ(sorted(kfi), sorted(kci));
  std::vector<Fast_dt::Vertex_handle> fv;
  std::vector<Cgal_dt::Vertex_handle> cv;
  fast.vertices_on_conflict_zone_boundary(q, fc, std::back_inserter(fv));
  cgal.vertices_on_conflict_zone_boundary(q, cc, std::back_inserter(cv));
  std::vector<Point_key> kfv, kcv;
  for(const auto& v : fv) kfv.push_back(vertex_point_key(fast, v));
  for(const auto& v : cv) kcv.push_back(vertex_point_key(cgal, v));
  EXPECT_EQ(sorted(kfv), sorted(kcv));

  const Fast_dt::Vertex_handle v = fast.insert_in_hole(q, fcells.begin(), fcells.end(), fb[0].first, fb[0].second);
  cgal.insert_in_hole(q, ccells.begin(), ccells.end(), cb[0].first, cb[0].second);
  EXPECT_TRUE(v->point() == q);
  EXPECT_TRUE(fast.is_valid());
  expect_same_as_cgal(fast, cgal);
  expect_same_adjacency(fast, cgal);
}

// Everything above on one input; `extra` queries are added to the vertices,
// edge midpoints and triangle centroids.
void expect_same_queries(const std::vector<Point>& points, const std::vector<Point>& extra)
{
  const Cgal_dt cgal(points.begin(), points.end());
  const Fast_dt fast(points.begin(), points.end());
  ASSERT_LT(cgal.dimension(), 3) << "the input does not test what it should";
  ASSERT_TRUE(fast.is_valid(true));
  expect_same_as_cgal(fast, cgal);
  const std::vector<Point> queries = query_points(cgal, extra);
  {
    SCOPED_TRACE("locate");
    expect_same_locations(fast, cgal, queries);
  }
  {
    SCOPED_TRACE("side_of");
    expect_same_sides(fast, cgal, queries);
  }
  if(cgal.dimension() >= 0) {
    SCOPED_TRACE("adjacency");
    expect_same_adjacency(fast, cgal);
    expect_same_is_edge_and_facet(fast, cgal);
  }
  for(const Point& q : extra) {
    SCOPED_TRACE("insert " + std::to_string(q.x()) + " " + std::to_string(q.y()) + " " + std::to_string(q.z()));
    expect_same_insertions(points, q);
    if(cgal.dimension() == 2) expect_same_conflicts(points, q);
  }
}

std::vector<Point> planar_grid(int n)
{
  std::vector<Point> points;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < n; ++j) points.push_back(Point(i, j, 0));
  return points;
}

// ---------------------------------------------------------------- inputs

TEST(Lower_dimensional_queries, EmptyTriangulation)
{
  expect_same_queries({}, {Point(0, 0, 0), Point(1, 2, 3)});
}

TEST(Lower_dimensional_queries, OnePoint)
{
  expect_same_queries({Point(1, 1, 1)}, {Point(1, 1, 1), Point(2, 1, 1)});
}

TEST(Lower_dimensional_queries, TwoPoints)
{
  expect_same_queries({Point(0, 0, 0), Point(2, 2, 2)},
                      {Point(1, 1, 1), Point(3, 3, 3), Point(-1, -1, -1), Point(0, 0, 0), Point(1, 0, 0)});
}

TEST(Lower_dimensional_queries, CollinearUnsortedWithDuplicates)
{
  std::vector<Point> points;
  for(int i : {5, -3, 0, 8, 2, 5, -7, 1, 0}) points.push_back(Point(i, 2 * i, -i));
  expect_same_queries(points, {Point(1.5, 3, -1.5), Point(20, 40, -20), Point(-20, -40, 20), Point(2, 4, -2),
                               Point(1, 1, 1), Point(-7, -14, 7)});
}

TEST(Lower_dimensional_queries, CoplanarRandom)
{
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  std::vector<Point> points;
  for(int i = 0; i < 40; ++i) points.push_back(Point(u(rng), u(rng), 0.5));
  expect_same_queries(points, {Point(0.1, 0.2, 0.5), Point(5, 5, 0.5), Point(-3, 0.1, 0.5), Point(0, 0, 1),
                               Point(0.25, -0.75, 0.5)});
}

TEST(Lower_dimensional_queries, CocircularPoints)
{
  // Points of the circle x^2 + y^2 = 25 with integer coordinates: every
  // triangulation of them is Delaunay, the perturbation decides.
  const std::vector<Point> points = {Point(5, 0, 0),  Point(4, 3, 0),   Point(3, 4, 0),  Point(0, 5, 0),
                                     Point(-3, 4, 0), Point(-4, 3, 0),  Point(-5, 0, 0), Point(-4, -3, 0),
                                     Point(-3, -4, 0), Point(0, -5, 0), Point(3, -4, 0), Point(4, -3, 0)};
  expect_same_queries(points, {Point(0, 0, 0), Point(0.5, 0.25, 0), Point(6, 6, 0), Point(0, 0, 2)});
}

TEST(Lower_dimensional_queries, PlanarGrid)
{
  expect_same_queries(planar_grid(5), {Point(2, 2, 0), Point(1.5, 1.5, 0), Point(1.5, 2, 0), Point(0.25, 0.5, 0),
                                       Point(7, 2, 0), Point(-1, -1, 0), Point(2, 2, 1), Point(4, 5, 0)});
}

TEST(Lower_dimensional_queries, TiltedPlane)
{
  // The plane x + y + z = 1 with dyadic coordinates (exactly coplanar).
  std::vector<Point> points;
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 5; ++j) {
      const double x = i * 0.25 + (j % 2) * 0.125, y = j * 0.375;
      points.push_back(Point(x, y, 1 - x - y));
    }
  expect_same_queries(points, {Point(0.5, 0.5, 0), Point(10, 0, -9), Point(0.3125, 0.1875, 0.5),
                               Point(0.5, 0.5, 0.5)});
}

// ---------------------------------------------------------------- incremental paths

// One point at a time with every kind of hint, checked against CGAL after
// every insertion (so every dimension change, every in-place split of a
// segment and every dimension-2 hole is met), until the lift to 3D.
TEST(Lower_dimensional_insertion, OnePointAtATimeWithHints)
{
  std::vector<Point> points = {Point(0, 0, 0), Point(0, 0, 0), Point(4, 0, 0), Point(2, 0, 0), Point(-2, 0, 0),
                               Point(9, 0, 0),  Point(3, 3, 0), Point(1, -2, 0), Point(2, 1, 0), Point(2, 0, 0),
                               Point(6, 6, 0), Point(-5, 5, 0), Point(1, 1, 0), Point(2, 2, 5), Point(1, 1, 1)};
  Fast_dt fast;
  Cgal_dt cgal;
  std::vector<Point> so_far;
  for(std::size_t k = 0; k < points.size(); ++k) {
    SCOPED_TRACE("point " + std::to_string(k));
    const Point& p = points[k];
    Fast_dt::Vertex_handle v;
    switch(k % 3) {
    case 0: v = fast.insert(p, fast.infinite_cell()); break;
    case 1: v = fast.insert(p, fast.number_of_vertices() ? Fast_dt::Vertex_handle(fast.finite_vertices_begin())
                                                        : Fast_dt::Vertex_handle());
            break;
    default: {
      Fast_dt::Locate_type lt;
      int li = -1, lj = -1;
      const Fast_dt::Cell_handle c = fast.locate(p, lt, li, lj);
      v = fast.insert(p, lt, c, li, lj);
    }
    }
    cgal.insert(p);
    so_far.push_back(p);
    ASSERT_TRUE(v->point() == p);
    ASSERT_TRUE(fast.is_valid(true));
    expect_same_as_cgal(fast, cgal);
    if(cgal.dimension() < 3) {
      expect_same_adjacency(fast, cgal);
      expect_same_locations(fast, cgal, query_points(cgal, {Point(0.5, 0.25, 0), Point(100, 1, 0)}));
    }
  }
  EXPECT_EQ(fast.dimension(), 3);
}

// A cell base of a user's own (CGAL's Rebind_TDS protocol) with a label.
template <class GT, class Cb = CGAL::Delaunay_triangulation_cell_base_3<GT>>
class Labelled_cell_base : public Cb
{
public:
  std::string label;
  template <class TDS2>
  struct Rebind_TDS
  {
    typedef typename Cb::template Rebind_TDS<TDS2>::Other Cb2;
    typedef Labelled_cell_base<GT, Cb2> Other;
  };
  using Cb::Cb;
};

// CGAL changes some cells in place and they keep their infos: the cell of
// the empty triangulation becomes the infinite point cell, each change of
// dimension below 3 extends every cell by a vertex, in dimension 1 a split
// segment keeps one of its ends, and a point that lifts dimension 2 to 3 makes
// every triangle a tetrahedron with it.  After every insertion the cells, by
// their vertices, carry the same labels as CGAL's; then each cell still
// without one gets the next label, in key order.  `label(c)` is the label of
// cell c (its info, or a member of a user's cell base).
template <class Cb, class Label>
void expect_labels_follow_cells(const Label& label)
{
  typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>, Cb> Tds;
  CGAL::Fast_Delaunay_triangulation_3<K, Tds> fast;
  CGAL::Delaunay_triangulation_3<K, Tds> cgal;
  // Collinear points splitting segments and extending the line at both ends,
  // coplanar ones, one that lifts the points to 3D, one more.
  const std::vector<Point> points = {Point(0, 0, 0), Point(4, 0, 0), Point(2, 0, 0), Point(-2, 0, 0),
                                     Point(3, 0, 0), Point(9, 0, 0), Point(1, 0, 0), Point(3, 3, 0),
                                     Point(1, -2, 0), Point(2, 1, 0), Point(-5, 5, 0), Point(1, 1, 3),
                                     Point(0.5, 0.25, -2)};
  // Every cell of the triangulation, once: the point cells below dimension 1.
  auto cells = [](const auto& tr) {
    std::vector<decltype(tr.infinite_cell())> c;
    if(tr.dimension() == 3)
      for(auto x = tr.all_cells_begin(); x != tr.all_cells_end(); ++x) c.push_back(x);
    else if(tr.dimension() == 2)
      for(auto f = tr.all_facets_begin(); f != tr.all_facets_end(); ++f) c.push_back(f->first);
    else if(tr.dimension() == 1)
      for(auto e = tr.all_edges_begin(); e != tr.all_edges_end(); ++e) c.push_back(e->first);
    else {
      c.push_back(tr.infinite_cell());
      if(tr.dimension() == 0) c.push_back(tr.infinite_cell()->neighbor(0));
    }
    return c;
  };
  auto labels = [&](const auto& tr) {
    std::vector<std::pair<Simplex_key, std::string>> l;
    for(auto c : cells(tr)) l.emplace_back(cell_key(tr, c), label(c));
    return sorted(l);
  };
  auto label_new_cells = [&](auto& tr, int first_label) {
    std::vector<std::pair<Simplex_key, decltype(tr.infinite_cell())>> unlabelled;
    for(auto c : cells(tr))
      if(label(c).empty()) unlabelled.emplace_back(cell_key(tr, c), c);
    std::sort(unlabelled.begin(), unlabelled.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
    for(auto& u : unlabelled) label(u.second) = "cell " + std::to_string(first_label++);
    return first_label;
  };
  label(fast.infinite_cell()) = label(cgal.infinite_cell()) = "empty";
  int next_label = 0, kept_in_3d = 0;
  for(std::size_t k = 0; k < points.size(); ++k) {
    SCOPED_TRACE("point " + std::to_string(k));
    fast.insert(points[k]);
    cgal.insert(points[k]);
    ASSERT_EQ(fast.dimension(), cgal.dimension());
    const auto expected = labels(cgal);
    EXPECT_EQ(labels(fast), expected);
    if(fast.dimension() == 3)
      for(const auto& l : expected) kept_in_3d += !l.second.empty();
    label_new_cells(fast, next_label);
    next_label = label_new_cells(cgal, next_label);
  }
  EXPECT_EQ(fast.dimension(), 3);
  EXPECT_GT(kept_in_3d, 10) << "the test needs labels that survive the lift";
}

TEST(Lower_dimensional_insertion, CellInfosFollowCellsChangedInPlace)
{
  expect_labels_follow_cells<CGAL::Triangulation_cell_base_with_info_3<std::string, K>>(
      [](auto c) -> std::string& { return c->info(); });
}

TEST(Lower_dimensional_insertion, UserCellBasesFollowCellsChangedInPlace)
{
  expect_labels_follow_cells<Labelled_cell_base<K>>([](auto c) -> std::string& { return c->label; });
}

// A cell info set on a triangle survives insertions that do not destroy the
// triangle, as in CGAL; a new triangle gets Info() (CGAL leaves a plain int
// uninitialised there, so only the old triangles are compared).
TEST(Lower_dimensional_insertion, CellInfosOfUntouchedTrianglesSurvive)
{
  typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                               CGAL::Triangulation_cell_base_with_info_3<int, K>>
      Tds;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds> Fast_info;
  typedef CGAL::Delaunay_triangulation_3<K, Tds> Cgal_info;
  const std::vector<Point> points = planar_grid(4);
  Fast_info fast(points.begin(), points.end());
  Cgal_info cgal(points.begin(), points.end());
  std::vector<Simplex_key> labelled;
  for(auto f = cgal.all_facets_begin(); f != cgal.all_facets_end(); ++f) labelled.push_back(cell_key(cgal, f->first));
  labelled = sorted(labelled);
  auto label = [&labelled](auto& tr) {
    for(auto f = tr.all_facets_begin(); f != tr.all_facets_end(); ++f)
      f->first->info() =
          1 + int(std::lower_bound(labelled.begin(), labelled.end(), cell_key(tr, f->first)) - labelled.begin());
  };
  label(fast);
  label(cgal);
  auto labels = [&labelled](const auto& tr) {
    std::vector<std::pair<Simplex_key, int>> l;
    for(auto f = tr.all_facets_begin(); f != tr.all_facets_end(); ++f) {
      const Simplex_key k = cell_key(tr, f->first);
      if(std::binary_search(labelled.begin(), labelled.end(), k)) l.emplace_back(k, f->first->info());
    }
    return sorted(l);
  };
  for(const Point& q : {Point(0.5, 0.5, 0), Point(5, 1, 0), Point(2.25, 2.5, 0)}) {
    fast.insert(q);
    cgal.insert(q);
    const auto expected = labels(cgal);
    ASSERT_GT(expected.size(), 10u) << "the test needs triangles that survive";
    EXPECT_EQ(labels(fast), expected);
    for(auto f = fast.all_facets_begin(); f != fast.all_facets_end(); ++f)
      if(!std::binary_search(labelled.begin(), labelled.end(), cell_key(fast, f->first))) {
        EXPECT_EQ(f->first->info(), 0) << "a new triangle has Info()";
      }
  }
}

// Copies, moves, swaps and a file read keep the CGAL triangulation beside
// the arrays consistent: the queries still agree with CGAL afterwards.
TEST(Lower_dimensional_insertion, CopyMoveSwapAndReadKeepQueries)
{
  const std::vector<Point> plane = planar_grid(4);
  const std::vector<Point> line = {Point(0, 0, 1), Point(3, 0, 1), Point(1, 0, 1)};
  const Cgal_dt cgal_plane(plane.begin(), plane.end()), cgal_line(line.begin(), line.end());
  const std::vector<Point> queries = {Point(1.5, 1.5, 0), Point(2, 0, 1), Point(9, 9, 0), Point(5, 0, 1)};
  Fast_dt a(plane.begin(), plane.end());
  Fast_dt b(line.begin(), line.end());
  Fast_dt copy(a);
  expect_same_locations(copy, cgal_plane, query_points(cgal_plane, queries));
  expect_same_adjacency(copy, cgal_plane);
  Fast_dt assigned;
  assigned = b;
  expect_same_locations(assigned, cgal_line, query_points(cgal_line, queries));
  a.swap(b);
  expect_same_locations(a, cgal_line, query_points(cgal_line, queries));
  expect_same_locations(b, cgal_plane, query_points(cgal_plane, queries));
  Fast_dt moved(std::move(b));
  expect_same_locations(moved, cgal_plane, query_points(cgal_plane, queries));
  expect_same_adjacency(moved, cgal_plane);
  EXPECT_EQ(b.dimension(), -1);
  b.insert(Point(1, 2, 3));
  EXPECT_EQ(b.dimension(), 0);
  // The copy is independent of the original.
  copy.insert(Point(1.5, 1.5, 0));
  expect_same_locations(a, cgal_line, query_points(cgal_line, queries));
  Cgal_dt cgal_copy = cgal_plane;
  cgal_copy.insert(Point(1.5, 1.5, 0));
  expect_same_as_cgal(copy, cgal_copy);
  expect_same_locations(copy, cgal_copy, query_points(cgal_copy, queries));

  std::stringstream file;
  file.precision(17);
  file << cgal_plane;
  Fast_dt read;
  ASSERT_TRUE(static_cast<bool>(file >> read));
  expect_same_as_cgal(read, cgal_plane);
  expect_same_locations(read, cgal_plane, query_points(cgal_plane, queries));
  expect_same_adjacency(read, cgal_plane);
  read.clear();
  EXPECT_EQ(read.dimension(), -1);
  read.insert(plane.begin(), plane.end());
  expect_same_as_cgal(read, cgal_plane);
}

// Many collinear then coplanar points inserted one at a time: the CGAL
// triangulation is updated, not rebuilt per insertion (that was quadratic:
// 156 s for these 9,000 points in a Release build, 0.14 s now).
TEST(Lower_dimensional_insertion, ManySingleInsertionsStayFast)
{
  std::vector<Point> points;
  for(int i = 0; i < 3000; ++i) points.push_back(Point((i * 7919) % 3000, 0, 0));
  for(int i = 0; i < 6000; ++i) points.push_back(Point((i * 7919) % 3001, (i * 104729) % 2999, 0));
  Fast_dt fast;
  for(const Point& p : points) fast.insert(p);
  const Cgal_dt cgal(points.begin(), points.end());
  expect_same_as_cgal(fast, cgal);
  EXPECT_TRUE(fast.is_valid());
}

} // namespace test_lower_dimensional_queries
