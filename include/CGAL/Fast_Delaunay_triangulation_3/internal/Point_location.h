// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Point location in a 3D triangulation held in Flat_storage (CGAL's
// Triangulation_3::locate and the side_of_* predicates): the kernel's
// visibility walk (paper §2.1) finds a tetrahedron whose closure contains the
// query, or the ghost tetrahedron of a hull facet that sees it strictly; the
// four exact orientations of the query against the tetrahedron's facets then
// tell whether it lies inside, on a facet, on an edge or at a vertex, with
// CGAL's numbering of li, lj.  Dimension 3 only.

#ifndef CGAL_FDT3_INTERNAL_POINT_LOCATION_H
#define CGAL_FDT3_INTERNAL_POINT_LOCATION_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>

#include <CGAL/enum.h>

#include <iterator>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// The order of CGAL's Triangulation_3::Locate_type.
enum class Location_type { vertex = 0, edge, facet, cell, outside_convex_hull, outside_affine_hull };

struct Location
{
  Tet_id cell = 0;
  Location_type type = Location_type::outside_affine_hull;
  int li = -1, lj = -1;
};

// The kernel's walk reads the mesh and writes only its scratch (the random
// facet order and counters), so a const mesh is safe to walk.
inline Tet_id walk_to(const Flat_storage& m, Tet_id start, const double* p)
{
  Flat_storage& mesh = const_cast<Flat_storage&>(m);
  Insertion_scratch scratch;
  Delaunay_kernel<> kernel(mesh, scratch, Mesh_slots{&mesh});
  if(start >= m.number_of_slots() || !m.is_live(start)) start = m.first_live_tet();
  return kernel.walk(start, p);
}

// Where p is in the closure of finite tetrahedron t, from o[i], the
// orientation of t with p in place of vertex i, none negative: p is on
// facet i <=> o[i] = 0.
inline Location location_from_orientations(Tet_id t, const int* o)
{
  int on = 0;
  for(int i = 0; i < 4; ++i) {
    CGAL_assertion(o[i] >= 0);
    on += o[i] == 0 ? 1 : 0;
  }
  Location loc;
  loc.cell = t;
  switch(on) {
  case 0: loc.type = Location_type::cell; break;
  case 1:
    loc.type = Location_type::facet;
    loc.li = o[0] == 0 ? 0 : o[1] == 0 ? 1 : o[2] == 0 ? 2 : 3;
    break;
  case 2: // on the edge of the two vertices whose facets do not hold p
    loc.type = Location_type::edge;
    loc.li = o[0] != 0 ? 0 : o[1] != 0 ? 1 : 2;
    loc.lj = o[loc.li + 1] != 0 ? loc.li + 1 : o[loc.li + 2] != 0 ? loc.li + 2 : loc.li + 3;
    break;
  default: // three facets: the vertex opposite the fourth
    loc.type = Location_type::vertex;
    loc.li = o[0] != 0 ? 0 : o[1] != 0 ? 1 : o[2] != 0 ? 2 : 3;
    break;
  }
  return loc;
}

// o[i]: the exact orientation of t with p in place of vertex i (for a ghost
// cell, i = 3: p against its hull facet).
inline int orientation_with(const Flat_storage& m, Tet_id t, int i, const double* p)
{
  const double* q[4] = {m.point(m.vertex(t, 0)), m.point(m.vertex(t, 1)), m.point(m.vertex(t, 2)),
                        i == 3 ? p : m.point(m.vertex(t, 3))};
  q[i] = p;
  return orientation(q[0], q[1], q[2], q[3]);
}

inline Location classify_in_cell(const Flat_storage& m, Tet_id t, const double* p)
{
  int o[4];
  for(int i = 0; i < 4; ++i) o[i] = orientation_with(m, t, i, p);
  return location_from_orientations(t, o);
}

// CGAL's semantics in dimension 3: a point on the hull boundary is located in
// a finite cell; a point outside is located in the ghost cell of a hull facet
// that sees it strictly, li being its infinite vertex.
inline Location outside_hull(Tet_id ghost)
{
  Location loc;
  loc.cell = ghost;
  loc.type = Location_type::outside_convex_hull;
  loc.li = 3;
  return loc;
}

inline Location locate(const Flat_storage& m, Tet_id start, const double* p)
{
  const Tet_id t = walk_to(m, start, p);
  return m.is_ghost(t) ? outside_hull(t) : classify_in_cell(m, t, p);
}

// Position of p, coplanar with the non-degenerate triangle (a, b, c), with
// respect to it (CGAL's side_of_triangle): edge k is (k, k+1 mod 3).
template <class Gt>
Bounded_side side_of_triangle(const Gt& gt, const typename Gt::Point_3& p, const typename Gt::Point_3& a,
                              const typename Gt::Point_3& b, const typename Gt::Point_3& c,
                              Location_type& lt, int& i, int& j)
{
  const auto coplanar_orientation = gt.coplanar_orientation_3_object();
  const Orientation abc = coplanar_orientation(a, b, c);
  const Orientation o[3] = {coplanar_orientation(a, b, p), coplanar_orientation(b, c, p),
                            coplanar_orientation(c, a, p)};
  for(Orientation x : o)
    if(x == -abc) {
      lt = Location_type::outside_convex_hull;
      return ON_UNBOUNDED_SIDE;
    }
  const int on = (o[0] == ZERO) + (o[1] == ZERO) + (o[2] == ZERO);
  if(on == 0) {
    lt = Location_type::facet;
    return ON_BOUNDED_SIDE;
  }
  if(on == 1) {
    lt = Location_type::edge;
    i = o[0] == ZERO ? 0 : o[1] == ZERO ? 1 : 2;
    j = (i + 1) % 3;
    return ON_BOUNDARY;
  }
  lt = Location_type::vertex; // on two edges: their common vertex
  i = o[0] != ZERO ? 2 : o[1] != ZERO ? 0 : 1;
  return ON_BOUNDARY;
}

// CGAL's side_of_cell: for a ghost cell, "inside" is the open half-space
// beyond its hull facet and "boundary" the closed hull facet.
// `orientation_with(k)` is the orientation of t with p in place of vertex k
// (the doubles' predicates for a point with double coordinates, the
// kernel's otherwise); `point(v)` the kernel point of vertex v.
template <class Gt, class Orientation_with, class Point_of>
Bounded_side side_of_cell(const Gt& gt, const Flat_storage& m, Tet_id t, const typename Gt::Point_3& p,
                          const Orientation_with& orientation_with, const Point_of& point, Location_type& lt,
                          int& i, int& j)
{
  if(!m.is_ghost(t)) {
    int o[4];
    for(int k = 0; k < 4; ++k) {
      o[k] = orientation_with(k);
      if(o[k] < 0) {
        lt = Location_type::outside_convex_hull;
        return ON_UNBOUNDED_SIDE;
      }
    }
    const Location loc = location_from_orientations(t, o);
    lt = loc.type;
    // side_of_tetrahedron numbers an edge by its smallest and largest free index.
    i = loc.li;
    j = loc.lj;
    return lt == Location_type::cell ? ON_BOUNDED_SIDE : ON_BOUNDARY;
  }
  const int o = orientation_with(3);
  if(o > 0) {
    lt = Location_type::cell;
    return ON_BOUNDED_SIDE;
  }
  if(o < 0) return ON_UNBOUNDED_SIDE;
  // In the plane of the hull facet (vertices 0, 1, 2 of the ghost cell).
  int fi = -1, fj = -1;
  const Bounded_side side = side_of_triangle(gt, p, point(m.vertex(t, 0)), point(m.vertex(t, 1)),
                                             point(m.vertex(t, 2)), lt, fi, fj);
  if(side == ON_BOUNDED_SIDE) {
    i = 3;
    return ON_BOUNDARY;
  }
  if(side == ON_BOUNDARY) {
    i = fi;
    if(lt == Location_type::edge) j = fj;
  }
  return side;
}

// CGAL's side_of_sphere(c, p, perturb): +1 inside, for a ghost cell the open
// half-space beyond its hull facet (then its circumcircle within the plane).
inline int side_of_sphere(const Flat_storage& m, Tet_id t, const double* p, bool perturb)
{
  const double* w[3] = {m.point(m.vertex(t, 0)), m.point(m.vertex(t, 1)), m.point(m.vertex(t, 2))};
  if(!m.is_ghost(t)) {
    const double* w3 = m.point(m.vertex(t, 3));
    return perturb ? perturbed_side_of_oriented_sphere(w[0], w[1], w[2], w3, p)
                   : side_of_oriented_sphere(w[0], w[1], w[2], w3, p);
  }
  const int o = orientation(w[0], w[1], w[2], p);
  if(o != 0) return o;
  return perturb ? perturbed_coplanar_side_of_bounded_circle(w[0], w[1], w[2], p)
                 : coplanar_side_of_bounded_circle(w[0], w[1], w[2], p);
}

// Delaunay_triangulation_3::nearest_vertex in dimension 3: from the finite
// vertices of the cell of p, move to a strictly nearer adjacent vertex while
// there is one (the Delaunay graph holds a path of decreasing distance);
// ties keep the current vertex, as CGAL does.
template <class Tr>
typename Tr::Vertex_handle nearest_vertex(const Tr& tr, const typename Tr::Point& p,
                                          typename Tr::Cell_handle start)
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  const auto closer = tr.geom_traits().less_distance_to_point_3_object();
  auto nearer = [&](Vertex_handle v, Vertex_handle w) {
    if(tr.is_infinite(v)) return w;
    if(tr.is_infinite(w)) return v;
    return closer(p, w->point(), v->point()) ? w : v;
  };
  if(tr.number_of_vertices() == 0) return Vertex_handle();
  if(tr.dimension() < 3) {
    Vertex_handle best = tr.finite_vertices_begin();
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) best = nearer(best, v);
    return best;
  }
  typename Tr::Locate_type lt;
  int li = -1, lj = -1;
  const typename Tr::Cell_handle c = tr.locate(p, lt, li, lj, start);
  if(lt == Tr::VERTEX) return c->vertex(li);
  Vertex_handle best = c->vertex(0);
  for(int i = 1; i < 4; ++i) best = nearer(best, c->vertex(i));
  std::vector<Vertex_handle> around;
  for(;;) {
    around.clear();
    tr.adjacent_vertices(best, std::back_inserter(around));
    Vertex_handle next = best;
    for(Vertex_handle w : around) next = nearer(next, w);
    if(next == best) return best;
    best = next;
  }
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_POINT_LOCATION_H
