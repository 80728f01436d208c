// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The cells crossed by a segment [p, q] in dimension 3, in order from the
// cell of p to the cell of q (CGAL's segment_traverser_cells_begin/end), as
// a forward iterator that takes one step of the straight walk per increment.
//
// A step leaves the current cell through the facet that the line pq pierces
// and that q lies strictly beyond.  Facet i of a positively oriented cell has
// q beyond it when replacing vertex i by q makes the cell negative; the line
// pierces the triangle (a, b, c) when orient(p, q, a, b), orient(p, q, b, c)
// and orient(p, q, c, a) share one sign.  With p strictly inside the first
// cell and pq crossing no edge or vertex (general position) exactly one facet
// qualifies, so the cells are CGAL's.  Both points must lie in the convex
// hull: the walk never enters an infinite cell.  From vertex to vertex the
// walk starts in the cell of the first vertex that the segment enters and
// stops in the cell that has the second vertex.

#ifndef CGAL_FDT3_INTERNAL_SEGMENT_TRAVERSER_H
#define CGAL_FDT3_INTERNAL_SEGMENT_TRAVERSER_H

#include <CGAL/assertions.h>
#include <CGAL/enum.h>

#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

template <class Tr>
class Segment_cell_iterator
{
public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Point Point;
  typedef std::forward_iterator_tag iterator_category;
  typedef typename Tr::Cell value_type;
  typedef const value_type* pointer;
  typedef const value_type& reference;
  typedef std::ptrdiff_t difference_type;

  // The end.
  Segment_cell_iterator() = default;
  Segment_cell_iterator(const Tr* tr, const Point& p, const Point& q, Cell_handle hint)
      : tr_(tr), p_(p), q_(q)
  {
    CGAL_precondition(tr->dimension() == 3);
    cell_ = tr->locate(p, hint);
    CGAL_precondition(!tr->is_infinite(cell_));
  }

  // From vertex vs to vertex vt: the first cell is the cell of vs that the
  // segment enters, the one whose cone at vs holds vt (vt inside each of its
  // three facets through vs).
  Segment_cell_iterator(const Tr* tr, typename Tr::Vertex_handle vs, typename Tr::Vertex_handle vt)
      : tr_(tr), p_(vs->point()), q_(vt->point())
  {
    CGAL_precondition(tr->dimension() == 3 && vs != vt && !tr->is_infinite(vs) && !tr->is_infinite(vt));
    std::vector<Cell_handle> around;
    tr->finite_incident_cells(vs, std::back_inserter(around));
    for(Cell_handle c : around) {
      cell_ = c;
      const int k = c->index(vs);
      bool inside_cone = true;
      for(int i = 0; i < 4 && inside_cone; ++i)
        if(i != k) inside_cone = orientation_with_q_at(i) == POSITIVE;
      if(inside_cone) return;
    }
    CGAL_assertion(false);
  }

  reference operator*() const { return *cell_; }
  pointer operator->() const { return cell_.operator->(); }
  operator Cell_handle() const { return cell_; }
  Cell_handle handle() const { return cell_; }

  Segment_cell_iterator& operator++()
  {
    step();
    return *this;
  }
  Segment_cell_iterator operator++(int)
  {
    Segment_cell_iterator old = *this;
    step();
    return old;
  }
  friend bool operator==(const Segment_cell_iterator& a, const Segment_cell_iterator& b)
  {
    return a.cell_ == b.cell_;
  }
  friend bool operator!=(const Segment_cell_iterator& a, const Segment_cell_iterator& b) { return !(a == b); }

private:
  Point vertex_point(int i) const { return cell_->vertex(i)->point(); }

  Orientation orientation_with_q_at(int i) const
  {
    Point v[4] = {vertex_point(0), vertex_point(1), vertex_point(2), vertex_point(3)};
    v[i] = q_;
    return tr_->geom_traits().orientation_3_object()(v[0], v[1], v[2], v[3]);
  }

  bool line_pierces_facet(int i) const
  {
    const auto orientation = tr_->geom_traits().orientation_3_object();
    const Point a = vertex_point((i + 1) & 3), b = vertex_point((i + 2) & 3), c = vertex_point((i + 3) & 3);
    const Orientation s0 = orientation(p_, q_, a, b);
    const Orientation s1 = orientation(p_, q_, b, c);
    const Orientation s2 = orientation(p_, q_, c, a);
    return s0 == s1 && s1 == s2 && s0 != COPLANAR;
  }

  // After the cell of q, the end (a null cell).
  void step()
  {
    int exit = -1;
    for(int i = 0; i < 4 && exit < 0; ++i)
      if(i != entry_ && orientation_with_q_at(i) == NEGATIVE && line_pierces_facet(i)) exit = i;
    if(exit < 0) {
      cell_ = Cell_handle();
      return;
    }
    const Cell_handle next = cell_->neighbor(exit);
    entry_ = tr_->mirror_index(cell_, exit);
    cell_ = next;
    CGAL_assertion(!tr_->is_infinite(cell_));
  }

  const Tr* tr_ = nullptr;
  Point p_, q_;
  Cell_handle cell_;
  int entry_ = -1;
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_SEGMENT_TRAVERSER_H
