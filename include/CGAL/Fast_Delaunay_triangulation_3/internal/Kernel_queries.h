// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Dimension-3 queries at a point whose coordinates are not doubles (a
// construction of a kernel with exact constructions, such as EPEC): the
// engine's predicates read doubles, so these run the same steps as
// Point_location.h (visibility walk, classification in the cell found,
// in-sphere with CGAL's symbolic perturbation) with the kernel's own exact
// predicates on the vertices' kernel points.  Only queries take this path;
// every vertex has double coordinates (Kernel_points.h), so a query point
// that is no double is never equal to a vertex.

#ifndef CGAL_FDT3_INTERNAL_KERNEL_QUERIES_H
#define CGAL_FDT3_INTERNAL_KERNEL_QUERIES_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Conflict_zone.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Point_location.h>

#include <CGAL/enum.h>

#include <algorithm>
#include <cstdint>
#include <unordered_set>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Anchor: the Storage_anchor (traits, mesh and point_of).
template <class Anchor>
class Kernel_queries
{
public:
  typedef typename Anchor::Geom_traits Gt;
  typedef typename Gt::Point_3 Point;

  explicit Kernel_queries(const Anchor& a) : a_(a), m_(a.core.mesh) {}

  // The orientation of t with p in place of vertex i (i = 3 in a ghost
  // cell: p against its hull facet), CGAL's sign.
  int orientation_with(Tet_id t, int i, const Point& p) const
  {
    Point q[4] = {point(t, 0), point(t, 1), point(t, 2), i == 3 ? p : point(t, 3)};
    q[i] = p;
    return static_cast<int>(a_.traits.orientation_3_object()(q[0], q[1], q[2], q[3]));
  }

  // The visibility walk of Point_location.h: leave a finite cell through a
  // facet that p is strictly beyond, until none is (p in the closure of the
  // cell) or the cell entered is a ghost (p strictly beyond that hull
  // facet).  The facet tried first rotates pseudo-randomly so that the walk
  // cannot cycle in a degenerate triangulation.
  Location locate(Tet_id start, const Point& p) const
  {
    Tet_id t = start < m_.number_of_slots() && m_.is_live(start) ? start : m_.first_live_tet();
    if(m_.is_ghost(t)) t = m_.neighbor(t, 3);
    std::uint32_t state = 2463534242u;
    for(;;) {
      state ^= state << 13;
      state ^= state >> 17;
      state ^= state << 5;
      const int first = static_cast<int>(state & 3);
      int o[4];
      int exit = -1;
      for(int k = 0; k < 4 && exit < 0; ++k) {
        const int i = (first + k) & 3;
        o[i] = orientation_with(t, i, p);
        if(o[i] < 0) exit = i;
      }
      if(exit < 0) return location_from_orientations(t, o);
      t = m_.neighbor(t, exit);
      if(m_.is_ghost(t)) return outside_hull(t);
    }
  }

  // Below dimension 3 (the cells are CGAL's, copied to the slots, the
  // infinite vertex in any slot up to the dimension): CGAL's locate of p,
  // which is no vertex, by a scan of the cells.  Outside the affine hull
  // the cell is none; outside the hull an infinite cell whose finite face
  // separates p from the hull, li its infinite vertex.
  Location locate_below_dimension_3(const Point& p) const
  {
    Location loc;
    loc.cell = Tet_id(-1);
    const int d = a_.dimension();
    if(d < 1) return loc; // no vertex, or one that p is not
    const Tet_id finite = first_finite_cell();
    const Point u = point(finite, 0), w = point(finite, 1);
    const bool in_hull = d == 1 ? bool(a_.traits.collinear_3_object()(u, w, p))
                                : a_.traits.orientation_3_object()(u, w, point(finite, 2), p) == COPLANAR;
    if(!in_hull) return loc;
    for(Tet_id t = 0; t < m_.number_of_slots(); ++t) {
      if(!m_.is_live(t) || a_.has_infinite_vertex(t)) continue;
      if(d == 1) {
        if(!a_.traits.collinear_are_strictly_ordered_along_line_3_object()(point(t, 0), p, point(t, 1))) continue;
        loc.cell = t;
        loc.type = Location_type::edge;
        loc.li = 0;
        loc.lj = 1;
        return loc;
      }
      Location_type type;
      int i = -1, j = -1;
      if(side_of_triangle(a_.traits, p, point(t, 0), point(t, 1), point(t, 2), type, i, j) == ON_UNBOUNDED_SIDE)
        continue;
      loc.cell = t;
      loc.type = type;
      loc.li = type == Location_type::facet ? 3 : i;
      loc.lj = type == Location_type::edge ? j : -1;
      return loc;
    }
    // Outside the hull: the infinite cell of a hull face (a vertex, an edge)
    // that p is strictly beyond, seen from the finite cell across it.
    for(Tet_id t = 0; t < m_.number_of_slots(); ++t) {
      if(!m_.is_live(t) || !a_.has_infinite_vertex(t)) continue;
      const int g = m_.vertex(t, 0) == ghost_vertex ? 0 : m_.vertex(t, 1) == ghost_vertex ? 1 : 2;
      const Tet_id n = m_.neighbor(t, g);
      const int k = index_in(n, t);
      const Point x = point(n, k); // the finite cell's vertex off the hull face
      bool beyond;
      if(d == 1) {
        beyond = a_.traits.collinear_are_strictly_ordered_along_line_3_object()(p, point(t, 1 - g), x);
      } else {
        const Point f0 = point(t, (g + 1) % 3), f1 = point(t, (g + 2) % 3);
        const auto coplanar_orientation = a_.traits.coplanar_orientation_3_object();
        const Orientation op = coplanar_orientation(f0, f1, p);
        beyond = op != COLLINEAR && op != coplanar_orientation(f0, f1, x);
      }
      if(!beyond) continue;
      loc.cell = t;
      loc.type = Location_type::outside_convex_hull;
      loc.li = g;
      return loc;
    }
    CGAL_assertion_msg(false, "no cell holds or sees a point of the affine hull");
    return loc;
  }

  Bounded_side side_of_cell(Tet_id t, const Point& p, Location_type& lt, int& i, int& j) const
  {
    return Fast_Delaunay_triangulation_3_internal::side_of_cell(
        a_.traits, m_, t, p, [&](int k) { return orientation_with(t, k, p); },
        [this](Vertex_id v) { return a_.point_of(v); }, lt, i, j);
  }

  // As side_of_sphere of Point_location.h: +1 inside; a ghost cell's
  // inside is the open half-space beyond its hull facet, then the facet's
  // circumcircle within its plane.
  int side_of_sphere(Tet_id t, const Point& p, bool perturb) const
  {
    const Point w0 = point(t, 0), w1 = point(t, 1), w2 = point(t, 2);
    if(!m_.is_ghost(t)) {
      const Point w3 = point(t, 3);
      const int side = static_cast<int>(a_.traits.side_of_oriented_sphere_3_object()(w0, w1, w2, w3, p));
      if(side != 0 || !perturb) return side;
      return perturbed_tie_break(w0, w1, w2, w3, p);
    }
    const int o = orientation_with(t, 3, p);
    if(o != 0) return o;
    return coplanar_side_of_bounded_circle(w0, w1, w2, p, perturb);
  }

  // The conflict zone of Conflict_zone.h grown from `start` (in conflict
  // with p) by the same perturbed in-sphere test, here side_of_sphere with
  // perturbation; the marks of the kernel's search are replaced by a set of
  // the cells seen, so the mesh is only read.
  void conflict_zone(Tet_id start, const Point& p, bool with_internal, Conflict_zone& zone) const
  {
    zone.cells.assign(1, start);
    std::unordered_set<Tet_id> in_zone = {start}, outside;
    for(std::size_t k = 0; k < zone.cells.size(); ++k)
      for(int f = 0; f < 4; ++f) {
        const Tet_id u = m_.neighbor(zone.cells[k], f);
        if(in_zone.count(u) != 0 || outside.count(u) != 0) continue;
        if(side_of_sphere(u, p, true) > 0) {
          in_zone.insert(u);
          zone.cells.push_back(u);
        } else {
          outside.insert(u);
        }
      }
    zone.boundary.clear();
    zone.internal.clear();
    for(const Tet_id t : zone.cells)
      for(int f = 0; f < 4; ++f) {
        const Tet_id u = m_.neighbor(t, f);
        if(in_zone.count(u) == 0) zone.boundary.push_back(facet_code(t, f));
        else if(with_internal && t < u) zone.internal.push_back(facet_code(t, f));
      }
  }

  // CGAL's coplanar_side_of_bounded_circle(p0, p1, p2, p, perturb) for
  // coplanar points, p0, p1, p2 not collinear: +1 inside.
  int coplanar_side_of_bounded_circle(const Point& p0, const Point& p1, const Point& p2, const Point& p,
                                      bool perturb) const
  {
    const int side = static_cast<int>(a_.traits.coplanar_side_of_bounded_circle_3_object()(p0, p1, p2, p));
    if(side != 0 || !perturb) return side;
    // The perturbation of Predicates.h: the largest point in the
    // lexicographic order whose coefficient is not zero decides.
    const auto orientation = a_.traits.coplanar_orientation_3_object();
    const Point* points[4] = {&p0, &p1, &p2, &p};
    std::sort(points, points + 4, [this](const Point* x, const Point* y) { return smaller(*x, *y); });
    const int local = static_cast<int>(orientation(p0, p1, p2));
    for(int i = 3; i > 0; --i) {
      if(points[i] == &p) return -1;
      int o = 0;
      if(points[i] == &p2 && (o = static_cast<int>(orientation(p0, p1, p))) != 0) return o * local;
      if(points[i] == &p1 && (o = static_cast<int>(orientation(p0, p, p2))) != 0) return o * local;
      if(points[i] == &p0 && (o = static_cast<int>(orientation(p, p1, p2))) != 0) return o * local;
    }
    return -local;
  }

private:
  const Anchor& a_;
  const Flat_storage& m_;

  Point point(Tet_id t, int i) const { return a_.point_of(m_.vertex(t, i)); }
  Tet_id first_finite_cell() const
  {
    for(Tet_id t = 0; t < m_.number_of_slots(); ++t)
      if(m_.is_live(t) && !a_.has_infinite_vertex(t)) return t;
    CGAL_assertion_msg(false, "no finite cell in dimension 1 or 2");
    return 0;
  }
  // The slot of n's neighbour t in n (n and t adjacent below dimension 3).
  int index_in(Tet_id n, Tet_id t) const
  {
    const int last = a_.dimension();
    for(int i = 0; i < last; ++i)
      if(m_.neighbor(n, i) == t) return i;
    return last;
  }
  bool smaller(const Point& x, const Point& y) const
  {
    return a_.traits.compare_xyz_3_object()(x, y) == SMALLER;
  }

  // perturbed_tie_break of Predicates.h with the kernel's predicates: the
  // two lexicographically largest of the five points decide.
  int perturbed_tie_break(const Point& p0, const Point& p1, const Point& p2, const Point& p3, const Point& p) const
  {
    const auto orientation = a_.traits.orientation_3_object();
    const Point* const points[5] = {&p0, &p1, &p2, &p3, &p};
    const Point* largest = points[0];
    const Point* second = nullptr;
    for(int i = 1; i < 5; ++i) {
      if(smaller(*largest, *points[i])) {
        second = largest;
        largest = points[i];
      } else if(second == nullptr || smaller(*second, *points[i])) {
        second = points[i];
      }
    }
    for(const Point* top : {largest, second}) {
      if(top == &p) return -1;
      int o = 0;
      if(top == &p3 && (o = static_cast<int>(orientation(p0, p1, p2, p))) != 0) return o;
      if(top == &p2 && (o = static_cast<int>(orientation(p0, p1, p, p3))) != 0) return o;
      if(top == &p1 && (o = static_cast<int>(orientation(p0, p, p2, p3))) != 0) return o;
      if(top == &p0 && (o = static_cast<int>(orientation(p, p1, p2, p3))) != 0) return o;
    }
    CGAL_assertion_msg(false, "perturbation did not decide: duplicate points?");
    return -1;
  }
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_KERNEL_QUERIES_H
