// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The faces and cells met by a segment [p, q] in dimension 3, in order from p
// to q (CGAL's segment_traverser_simplices and segment_traverser_cells).
//
// One walk serves both.  Along the line x(t) = (1 - t) p + t q, the
// barycentric coordinate of x(t) for vertex k of a finite cell is affine in t:
// lambda_k(t) = (1 - t) lambda_k(p) + t lambda_k(q), lambda_k(x) being the
// orientation determinant of the cell with vertex k replaced by x.  These are
// computed in exact rational arithmetic from the input doubles, so every
// decision (where the segment leaves a cell, whether it runs along an edge or
// inside a facet, whether it passes through a vertex) is a comparison of exact
// numbers and no degenerate case needs its own code:
//   - in a cell, the segment occupies [t_in, t_out], t_out the first zero of a
//     decreasing lambda (or 1); the face of x(t) is the set of vertices with
//     lambda_k(t) > 0, read at t_in, in between, and at t_out;
//   - at t_out the walk moves to a finite cell incident to the face of
//     x(t_out) that holds x(t_out + epsilon) in its closure (each lambda either
//     positive there or zero and not decreasing).
// The faces so listed are the open faces that the segment meets, each once, in
// order: this is canonical, whatever cell stores a face.  Where the segment
// runs in a face of dimension below 3 several cells hold it; the walk takes the
// first one found around the face, so the cell sequence there is one valid
// choice (CGAL 5.5's choice depends on its own storage: a Delaunay_triangulation_3
// built from the same points in another order may list other cells).
//
// A segment may leave the hull: the walk then ends with the infinite cell
// behind the hull facet through which it leaves, as CGAL's does.  One that
// starts outside the hull follows CGAL 5.5's rule (walk_to_next_3_inf in
// Triangulation_segment_traverser_3_impl.h), so that the cells are CGAL's:
// from the infinite cell that locate(p) gives (its finite facet sees p), stay
// there if q sees that facet too; else cross to the infinite neighbour
// behind the first plane through p and a hull edge of the cell that has q
// strictly behind it; else enter the hull through the cell's finite facet.
// The rule is sound while p sees the cell's facet; CGAL also applies it to
// cells reached outside whose facet p does not see, and may then enter the
// hull through a facet the segment misses and walk on inside: this walk ends
// there instead.  CGAL's choice among several planes with q behind follows
// its vertex order, and its located cell among several facets that see p its
// stochastic walk: there the two may differ.

#ifndef CGAL_FDT3_INTERNAL_SEGMENT_TRAVERSER_H
#define CGAL_FDT3_INTERNAL_SEGMENT_TRAVERSER_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_points.h>

#include <CGAL/Exact_rational.h>
#include <CGAL/assertions.h>
#include <CGAL/number_utils.h>

#include <array>
#include <cstddef>
#include <iterator>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// A face of a cell as the set of its vertex indices (bit k: vertex k).
template <class Tr>
struct Segment_face
{
  typename Tr::Cell_handle cell;
  unsigned mask;
};

template <class Tr>
struct Segment_walk_result
{
  std::vector<typename Tr::Cell_handle> cells;
  std::vector<Segment_face<Tr>> faces;
};

template <class Tr>
class Segment_walk
{
public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Point Point;
  typedef CGAL::Exact_rational Exact;
  typedef Segment_face<Tr> Face;

  Segment_walk(const Tr* tr, const Point& p, const Point& q) : tr_(tr), p_(exact(p)), q_(exact(q)) {}

  // From the face `start` (holding p) to q.
  Segment_walk_result<Tr> run(Face start)
  {
    Segment_walk_result<Tr> out;
    walk(out, start, 0);
    return out;
  }

  // p strictly outside the hull, in the infinite cell c whose finite facet
  // sees it.
  Segment_walk_result<Tr> run_from_outside(Cell_handle c)
  {
    Segment_walk_result<Tr> out;
    Cell_handle previous;
    // The walk outside never comes back to a cell (each step crosses a plane
    // through p that q is behind), so it visits each infinite cell once at most.
    for(std::size_t steps = 0; steps <= tr_->number_of_cells(); ++steps) {
      out.cells.push_back(c);
      out.faces.push_back(Face{c, 15u});
      const int inf = c->index(tr_->infinite_vertex());
      std::array<Exact_point, 4> v;
      for(int k = 0; k < 4; ++k) v[k] = k == inf ? q_ : exact(c->vertex(k)->point());
      if(CGAL::is_positive(determinant(v))) return out; // q sees the facet too
      v[inf] = p_;
      const bool p_sees_facet = CGAL::is_positive(determinant(v));
      int behind = -1;
      for(int k = 0; k < 4 && behind < 0; ++k) {
        if(k == inf || c->neighbor(k) == previous) continue;
        const Exact_point keep = v[k];
        v[k] = q_;
        if(CGAL::is_negative(determinant(v))) behind = k;
        v[k] = keep;
      }
      if(behind < 0) {
        const Cell_handle fin = c->neighbor(inf);
        if(p_sees_facet) enter_hull(out, fin, fin->index(c));
        return out;
      }
      out.faces.push_back(Face{c, 15u & ~(1u << behind)});
      previous = c;
      c = c->neighbor(behind);
    }
    CGAL_assertion_msg(false, "segment walk outside the hull does not end");
    return out;
  }

private:
  // Through facet j of the finite cell fin, the first point of the segment
  // in the hull.
  void enter_hull(Segment_walk_result<Tr>& out, Cell_handle fin, int j)
  {
    const Lambdas l = lambdas(fin);
    CGAL_assertion(CGAL::is_negative(l.at_p[j]) && !CGAL::is_negative(l.at_q[j]));
    const Exact t = l.at_p[j] / (l.at_p[j] - l.at_q[j]);
    const Face at{fin, positive_mask(l, t)};
    if(t == 1) { // q on the hull
      add_face(out, at);
      out.cells.push_back(fin);
      return;
    }
    walk(out, at, t);
  }

  // From the face `at` of x(t) to q.
  void walk(Segment_walk_result<Tr>& out, Face at, Exact t)
  {
    for(;;) {
      Lambdas cell = continuation_cell(at, t, out.cells.empty() ? Cell_handle() : out.cells.back());
      if(cell.c == Cell_handle()) {
        leave_hull(t, out);
        return;
      }
      const Exact t_out = exit_parameter(cell);
      CGAL_assertion(t < t_out);
      add_face(out, Face{cell.c, positive_mask(cell, t)});
      add_face(out, Face{cell.c, positive_mask(cell, (t + t_out) / 2)});
      add_face(out, Face{cell.c, positive_mask(cell, t_out)});
      out.cells.push_back(cell.c);
      if(t_out == 1) return;
      t = t_out;
      at = Face{cell.c, positive_mask(cell, t_out)};
    }
  }

  typedef std::array<Exact, 3> Exact_point;

  struct Lambdas
  {
    Cell_handle c;
    std::array<Exact, 4> at_p, at_q;
    Exact at(int k, const Exact& t) const { return at_p[k] + t * (at_q[k] - at_p[k]); }
  };

  // The walk's arithmetic is exact: a point of an exact kernel whose
  // coordinates are not doubles enters with its exact coordinates.
  static Exact_point exact(const Point& p)
  {
    double xyz[3];
    if(exact_coordinates(p, xyz)) return {Exact(xyz[0]), Exact(xyz[1]), Exact(xyz[2])};
    if constexpr(Is_lazy<Point>::value) {
      return exact_point_of(p.exact());
    } else {
      return exact_point_of(p);
    }
  }
  template <class Exact_kernel_point>
  static Exact_point exact_point_of(const Exact_kernel_point& p)
  {
    typedef typename std::decay<decltype(p.x())>::type Coordinate;
    if constexpr(std::is_constructible<Exact, const Coordinate&>::value) {
      return {Exact(p.x()), Exact(p.y()), Exact(p.z())};
    } else {
      throw std::invalid_argument(
          "Fast_Delaunay_triangulation_3: segment traversal from or to a point whose coordinates are neither doubles"
          " nor of CGAL's exact rational type");
    }
  }

  static Exact determinant(const std::array<Exact_point, 4>& v)
  {
    Exact m[3][3];
    for(int r = 0; r < 3; ++r)
      for(int k = 0; k < 3; ++k) m[r][k] = v[r + 1][k] - v[0][k];
    return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
           m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
  }

  Lambdas lambdas(Cell_handle c) const
  {
    Lambdas l;
    l.c = c;
    std::array<Exact_point, 4> v;
    for(int k = 0; k < 4; ++k) v[k] = exact(c->vertex(k)->point());
    for(int k = 0; k < 4; ++k) {
      const Exact_point keep = v[k];
      v[k] = p_;
      l.at_p[k] = determinant(v);
      v[k] = q_;
      l.at_q[k] = determinant(v);
      v[k] = keep;
    }
    return l;
  }

  static unsigned positive_mask(const Lambdas& l, const Exact& t)
  {
    unsigned mask = 0;
    for(int k = 0; k < 4; ++k)
      if(CGAL::is_positive(l.at(k, t))) mask |= 1u << k;
    return mask;
  }

  // The segment stays in the closed cell until the first decreasing
  // barycentric coordinate vanishes.
  static Exact exit_parameter(const Lambdas& l)
  {
    Exact t_out = 1;
    for(int k = 0; k < 4; ++k)
      if(l.at_q[k] < l.at_p[k]) {
        const Exact t_k = l.at_p[k] / (l.at_p[k] - l.at_q[k]);
        if(t_k < t_out) t_out = t_k;
      }
    return t_out;
  }

  // Holds x(t) and x(t + epsilon): no coordinate negative at t, and none
  // vanishing there while decreasing.
  static bool holds_continuation(const Lambdas& l, const Exact& t)
  {
    for(int k = 0; k < 4; ++k) {
      const Exact value = l.at(k, t);
      if(CGAL::is_negative(value)) return false;
      if(CGAL::is_zero(value) && l.at_q[k] < l.at_p[k]) return false;
    }
    return true;
  }

  std::vector<Cell_handle> cells_around(const Face& f) const
  {
    std::vector<Cell_handle> around;
    int index[4], n = 0;
    for(int k = 0; k < 4; ++k)
      if(f.mask & (1u << k)) index[n++] = k;
    switch(n) {
      case 4: around.push_back(f.cell); break;
      case 3: {
        around.push_back(f.cell);
        for(int k = 0; k < 4; ++k)
          if(!(f.mask & (1u << k))) around.push_back(f.cell->neighbor(k));
        break;
      }
      case 2: {
        typename Tr::Cell_circulator c = tr_->incident_cells(f.cell, index[0], index[1]), done = c;
        do around.push_back(c); while(++c != done);
        break;
      }
      default: tr_->incident_cells(f.cell->vertex(index[0]), std::back_inserter(around)); break;
    }
    return around;
  }

  // A null cell when the segment leaves the hull at x(t).
  // The cell just left is skipped: the walk only moves forward.
  Lambdas continuation_cell(const Face& at, const Exact& t, Cell_handle left) const
  {
    for(Cell_handle c : cells_around(at)) {
      if(c == left || tr_->is_infinite(c)) continue;
      Lambdas l = lambdas(c);
      if(holds_continuation(l, t)) return l;
    }
    return Lambdas();
  }

  // Behind the hull facet through which the segment leaves: one facet of the
  // last cell that holds the exit face and has q strictly beyond.
  void leave_hull(const Exact& t, Segment_walk_result<Tr>& out) const
  {
    CGAL_assertion(!out.cells.empty());
    const Lambdas last = lambdas(out.cells.back());
    for(int k = 0; k < 4; ++k) {
      const Cell_handle behind = last.c->neighbor(k);
      if(!tr_->is_infinite(behind) || (positive_mask(last, t) & (1u << k)) || !CGAL::is_negative(last.at_q[k]))
        continue;
      out.cells.push_back(behind);
      out.faces.push_back(Face{behind, 15u});
      return;
    }
    CGAL_assertion(false);
  }

  void add_face(Segment_walk_result<Tr>& out, const Face& f) const
  {
    if(!out.faces.empty() && same_face(out.faces.back(), f)) return;
    out.faces.push_back(f);
  }

  static bool same_face(const Face& a, const Face& b)
  {
    if(a.cell == b.cell) return a.mask == b.mask;
    int na = 0, nb = 0;
    for(int k = 0; k < 4; ++k) {
      if(a.mask & (1u << k)) {
        ++na;
        if(!b.cell->has_vertex(a.cell->vertex(k))) return false;
      }
      if(b.mask & (1u << k)) ++nb;
    }
    return na == nb;
  }

  const Tr* tr_;
  Exact_point p_, q_;
};

// Forward iterator over a walk computed once and shared by the copies.
template <class Tr, class Value>
class Segment_walk_iterator
{
public:
  typedef std::forward_iterator_tag iterator_category;
  typedef Value value_type;
  typedef const Value* pointer;
  typedef const Value& reference;
  typedef std::ptrdiff_t difference_type;

  // The end.
  Segment_walk_iterator() = default;
  explicit Segment_walk_iterator(std::vector<Value> values)
      : values_(values.empty() ? nullptr : std::make_shared<const std::vector<Value>>(std::move(values)))
  {}

  reference operator*() const { return (*values_)[i_]; }
  pointer operator->() const { return &(*values_)[i_]; }

  Segment_walk_iterator& operator++()
  {
    if(++i_ == values_->size()) *this = Segment_walk_iterator();
    return *this;
  }
  Segment_walk_iterator operator++(int)
  {
    Segment_walk_iterator old = *this;
    ++*this;
    return old;
  }
  friend bool operator==(const Segment_walk_iterator& a, const Segment_walk_iterator& b)
  {
    return a.values_ == b.values_ && a.i_ == b.i_;
  }
  friend bool operator!=(const Segment_walk_iterator& a, const Segment_walk_iterator& b) { return !(a == b); }

private:
  std::shared_ptr<const std::vector<Value>> values_;
  std::size_t i_ = 0;
};

// The cells, dereferencing to the cell and converting to its handle, as
// CGAL's Triangulation_segment_cell_iterator_3.
template <class Tr>
class Segment_cell_iterator : public Segment_walk_iterator<Tr, typename Tr::Cell_handle>
{
  typedef Segment_walk_iterator<Tr, typename Tr::Cell_handle> Base;

public:
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Cell value_type;
  typedef const value_type* pointer;
  typedef const value_type& reference;

  Segment_cell_iterator() = default;
  explicit Segment_cell_iterator(std::vector<Cell_handle> cells) : Base(std::move(cells)) {}

  // Through the handle stored in the walk: a facade handle holds the cell it
  // dereferences to, so a copy of it would not outlive this call.
  reference operator*() const { return *Base::operator*(); }
  pointer operator->() const { return Base::operator*().operator->(); }
  operator Cell_handle() const { return handle(); }
  Cell_handle handle() const { return Base::operator*(); }

  Segment_cell_iterator& operator++()
  {
    Base::operator++();
    return *this;
  }
  Segment_cell_iterator operator++(int)
  {
    Segment_cell_iterator old = *this;
    Base::operator++();
    return old;
  }
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_SEGMENT_TRAVERSER_H
