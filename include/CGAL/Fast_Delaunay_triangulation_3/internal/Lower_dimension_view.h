// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Every answer of the triangulation below dimension 3, in one place.  There
// the arrays hold no tetrahedra: CGAL's triangulation of the same vertices,
// kept beside them (Lower_dimensions.h), answers, and each of its cells has
// a slot of ours.  This view takes our handles, asks CGAL's triangulation
// with its own, and gives the answer back in our handles, in CGAL's order.
// The triangulation and Delaunay layers call it wherever dimension() < 3
// (except for the queries at points that are no doubles, which the
// kernel's predicates answer, Kernel_queries.h, and for the file writer,
// which builds CGAL's triangulation of the points afresh).

#ifndef CGAL_FDT3_INTERNAL_LOWER_DIMENSION_VIEW_H
#define CGAL_FDT3_INTERNAL_LOWER_DIMENSION_VIEW_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Lower_dimensions.h>

#include <CGAL/enum.h>
#include <CGAL/utility.h>

#include <cstddef>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Tr: the triangulation layer (Flat_triangulation_3), for its handle types
// and its conversion of a query point to the engine's doubles.
template <class Tr>
class Lower_dimension_view
{
  typedef typename Tr::Anchor Anchor;
  typedef typename Tr::Point Point;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Facet Facet;
  typedef typename Tr::Edge Edge;
  typedef Lower_dimensional_triangulation Lower;
  typedef typename Lower::Reference_cell Reference_cell;
  typedef typename Lower::Reference_vertex Reference_vertex;
  typedef typename Lower::Reference_point Reference_point;
  typedef typename Lower::Delaunay::Facet Reference_facet;
  typedef typename Lower::Delaunay::Edge Reference_edge;

public:
  explicit Lower_dimension_view(const Anchor* anchor) : anchor_(anchor) {}

  // ---------------------------------------------------------------- location
  template <class Locate_type>
  Cell_handle locate(const Point& p, Locate_type& lt, int& li, int& lj, Cell_handle start) const
  {
    typename Lower::Locate_type type;
    const Reference_cell c = delaunay().locate(reference(p), type, li, lj, reference(start));
    lt = static_cast<Locate_type>(type);
    return ours(c);
  }
  // CGAL's side_of_facet / side_of_edge leave lt alone outside the simplex,
  // and so do these.
  template <class Locate_type>
  Bounded_side side_of_facet(const Point& p, Cell_handle c, Locate_type& lt, int& li, int& lj) const
  {
    typename Lower::Locate_type type = unset_locate_type();
    const Bounded_side side = delaunay().side_of_facet(reference(p), reference(c), type, li, lj);
    if(type != unset_locate_type()) lt = static_cast<Locate_type>(type);
    return side;
  }
  template <class Locate_type>
  Bounded_side side_of_edge(const Point& p, Cell_handle c, Locate_type& lt, int& li) const
  {
    typename Lower::Locate_type type = unset_locate_type();
    const Bounded_side side = delaunay().side_of_edge(reference(p), reference(c), type, li);
    if(type != unset_locate_type()) lt = static_cast<Locate_type>(type);
    return side;
  }
  Bounded_side side_of_circle(Cell_handle c, int i, const Point& p, bool perturb) const
  {
    return delaunay().side_of_circle(reference(c), i, reference(p), perturb);
  }

  // ---------------------------------------------------------------- faces and adjacency
  // CGAL 5.5 looks for an edge among the cells around u, and finds none
  // below dimension 2: is_edge() is false in dimension 1.
  bool is_edge(Vertex_handle u, Vertex_handle v, Cell_handle& c, int& i, int& j) const
  {
    Reference_cell rc;
    if(!delaunay().is_edge(reference(u), reference(v), rc, i, j)) return false;
    c = ours(rc);
    return true;
  }
  bool is_facet(Vertex_handle u, Vertex_handle v, Vertex_handle w, Cell_handle& c, int& i, int& j, int& k) const
  {
    Reference_cell rc;
    if(!delaunay().is_facet(reference(u), reference(v), reference(w), rc, i, j, k)) return false;
    c = ours(rc);
    return true;
  }
  // CGAL defines incident cells and facets from dimension 2, edges from
  // dimension 1; below that they are empty.
  template <class OutputIterator>
  OutputIterator incident_cells(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    return translated<Reference_cell>(out, [&](auto to) {
      if(finite_only) delaunay().finite_incident_cells(reference(v), to);
      else delaunay().incident_cells(reference(v), to);
    });
  }
  template <class OutputIterator>
  OutputIterator incident_facets(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    return translated<Reference_facet>(out, [&](auto to) {
      if(finite_only) delaunay().finite_incident_facets(reference(v), to);
      else delaunay().incident_facets(reference(v), to);
    });
  }
  template <class OutputIterator>
  OutputIterator incident_edges(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    return translated<Reference_edge>(out, [&](auto to) {
      if(finite_only) delaunay().finite_incident_edges(reference(v), to);
      else delaunay().incident_edges(reference(v), to);
    });
  }
  template <class OutputIterator>
  OutputIterator adjacent_vertices(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    return translated<Reference_vertex>(out, [&](auto to) {
      if(finite_only) delaunay().finite_adjacent_vertices(reference(v), to);
      else delaunay().adjacent_vertices(reference(v), to);
    });
  }
  std::size_t degree(Vertex_handle v) const { return delaunay().degree(reference(v)); }

  // ---------------------------------------------------------------- traversal and conflicts (dimension 2)
  // The cells CGAL's cell traverser meets from p to q (in the plane of the points).
  std::vector<Cell_handle> segment_cells(const Point& p, const Point& q, Cell_handle hint) const
  {
    std::vector<Cell_handle> cells;
    auto it = delaunay().segment_traverser_cells_begin(reference(p), reference(q), reference(hint));
    for(; it != delaunay().segment_traverser_cells_end(); ++it) cells.push_back(ours(Reference_cell(it)));
    return cells;
  }
  template <class OutputIteratorBoundaryFacets, class OutputIteratorCells, class OutputIteratorInternalFacets>
  Triple<OutputIteratorBoundaryFacets, OutputIteratorCells, OutputIteratorInternalFacets>
  find_conflicts(const Point& p, Cell_handle c, OutputIteratorBoundaryFacets bfit, OutputIteratorCells cit,
                 OutputIteratorInternalFacets ifit) const
  {
    std::vector<Reference_facet> boundary, internal;
    std::vector<Reference_cell> cells;
    delaunay().find_conflicts(reference(p), reference(c), std::back_inserter(boundary), std::back_inserter(cells),
                              std::back_inserter(internal));
    for(const Reference_facet& f : boundary) *bfit++ = ours(f);
    for(Reference_cell x : cells) *cit++ = ours(x);
    for(const Reference_facet& f : internal) *ifit++ = ours(f);
    return make_triple(bfit, cit, ifit);
  }
  template <class OutputIterator>
  OutputIterator vertices_on_conflict_zone_boundary(const Point& p, Cell_handle c, OutputIterator res) const
  {
    return translated<Reference_vertex>(res, [&](auto to) {
      delaunay().vertices_on_conflict_zone_boundary(reference(p), reference(c), to);
    });
  }

  // Where a caller located p (CGAL's insert(p, lt, c, li, lj)), in CGAL's terms.
  template <class Locate_type>
  typename Lower::Location location(Locate_type lt, Cell_handle c, int li, int lj) const
  {
    typename Lower::Location where;
    where.type = static_cast<typename Lower::Locate_type>(lt);
    where.cell = reference(c);
    where.li = li;
    where.lj = lj;
    return where;
  }

  // ---------------------------------------------------------------- handles both ways
  // Every CGAL cell has its slot, the one cell of the empty triangulation included.
  Reference_cell reference(Cell_handle c) const { return c ? lower().cell(c.index()) : Reference_cell(); }
  Reference_vertex reference(Vertex_handle v) const
  {
    return v == Vertex_handle() ? Reference_vertex() : lower().vertex(v.index());
  }
  // CGAL's triangulation holds the vertices' doubles, so a query point must
  // have double coordinates too (else std::invalid_argument).
  static Reference_point reference(const Point& p)
  {
    double xyz[3];
    Tr::engine_coordinates(p, xyz);
    return Reference_point(xyz[0], xyz[1], xyz[2]);
  }

private:
  Cell_handle ours(Reference_cell c) const { return anchor_->cell_of_reference(c); }
  Vertex_handle ours(Reference_vertex v) const
  {
    return v == Reference_vertex() ? Vertex_handle() : Vertex_handle(anchor_, Lower::id(v));
  }
  Facet ours(const Reference_facet& f) const { return Facet(ours(f.first), f.second); }
  Edge ours(const Reference_edge& e) const { return Edge(ours(e.first), e.second, e.third); }

  // Runs `query` with an output iterator of CGAL's elements of type
  // Reference, and writes them to `out` as ours, in CGAL's order.
  template <class Reference, class OutputIterator, class Query>
  OutputIterator translated(OutputIterator out, const Query& query) const
  {
    std::vector<Reference> found;
    query(std::back_inserter(found));
    for(const Reference& x : found) *out++ = ours(x);
    return out;
  }

  // A value no enumerator of CGAL's Locate_type has (but in the enum's
  // range, 0..7): CGAL did not set lt.
  static typename Lower::Locate_type unset_locate_type() { return static_cast<typename Lower::Locate_type>(7); }

  const Lower& lower() const { return anchor_->core.lower; }
  const typename Lower::Delaunay& delaunay() const { return lower().delaunay(); }

  const Anchor* anchor_;
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_LOWER_DIMENSION_VIEW_H
