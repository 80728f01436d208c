// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The facet and edge iterators of the triangulation layer
// (Flat_triangulation_3.h): codes over the cell slots of the anchor's arrays.

#ifndef CGAL_FDT3_INTERNAL_FACE_ITERATORS_H
#define CGAL_FDT3_INTERNAL_FACE_ITERATORS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <CGAL/assertions.h>

#include <cstddef>
#include <iterator>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Facets and edges are enumerated once each, from the cell of smallest
// index among those that share them.  Both are bidirectional, as CGAL's:
// a code is listed when accepts(code), in either direction.  A facet's code
// is 4 t + i, an edge's 6 t + k (cell_edge_vertices[k]).
template <class Anchor, class Facet, bool finite_only>
class Facet_iterator
{
  typedef typename Facet::first_type Cell_handle;

public:
  typedef std::bidirectional_iterator_tag iterator_category;
  typedef Facet value_type;
  typedef std::ptrdiff_t difference_type;
  typedef const Facet* pointer;
  typedef const Facet& reference;

  Facet_iterator() = default;
  Facet_iterator(const Anchor* tr, std::size_t code) : tr_(tr), code_(code) { skip(); }
  const Facet& operator*() const { return facet_; }
  const Facet* operator->() const { return &facet_; }
  Facet_iterator& operator++() { ++code_; skip(); return *this; }
  Facet_iterator operator++(int) { Facet_iterator old = *this; ++*this; return old; }
  Facet_iterator& operator--()
  {
    do {
      CGAL_precondition(code_ > 0);
      --code_;
    } while(!accepts(code_));
    facet_ = Facet(Cell_handle(tr_, code_ >> 2), static_cast<int>(code_ & 3));
    return *this;
  }
  Facet_iterator operator--(int) { Facet_iterator old = *this; --*this; return old; }
  friend bool operator==(const Facet_iterator& a, const Facet_iterator& b) { return a.code_ == b.code_; }
  friend bool operator!=(const Facet_iterator& a, const Facet_iterator& b) { return a.code_ != b.code_; }

private:
  // In dimension 2 the facets are the triangles, as (c, 3).
  bool accepts(std::size_t code) const
  {
    const Flat_storage& m = tr_->core.mesh;
    const Tet_id t = static_cast<Tet_id>(code >> 2);
    const int i = static_cast<int>(code & 3);
    if(!m.is_live(t)) return false;
    if(tr_->dimension() == 2) return i == 3 && !(finite_only && tr_->has_infinite_vertex(t));
    if(m.neighbor(t, i) < t) return false;
    return !(finite_only && m.is_ghost(t) && i != 3);
  }
  void skip()
  {
    const std::size_t end = 4 * tr_->slots_of_faces(2);
    while(code_ < end && !accepts(code_)) ++code_;
    if(code_ < end) facet_ = Facet(Cell_handle(tr_, code_ >> 2), static_cast<int>(code_ & 3));
  }
  const Anchor* tr_ = nullptr;
  std::size_t code_ = 0;
  Facet facet_;
};

template <class Anchor, class Edge, bool finite_only>
class Edge_iterator
{
  typedef typename Edge::first_type Cell_handle;

public:
  typedef std::bidirectional_iterator_tag iterator_category;
  typedef Edge value_type;
  typedef std::ptrdiff_t difference_type;
  typedef const Edge* pointer;
  typedef const Edge& reference;

  Edge_iterator() = default;
  Edge_iterator(const Anchor* tr, std::size_t code) : tr_(tr), code_(code) { skip(); }
  const Edge& operator*() const { return edge_; }
  const Edge* operator->() const { return &edge_; }
  Edge_iterator& operator++() { ++code_; skip(); return *this; }
  Edge_iterator operator++(int) { Edge_iterator old = *this; ++*this; return old; }
  Edge_iterator& operator--()
  {
    do {
      CGAL_precondition(code_ > 0);
      --code_;
      // A free slot: none of its six codes is listed.
      if(!tr_->core.mesh.is_live(static_cast<Tet_id>(code_ / 6))) code_ -= code_ % 6;
    } while(!accepts(code_));
    set_edge();
    return *this;
  }
  Edge_iterator operator--(int) { Edge_iterator old = *this; --*this; return old; }
  friend bool operator==(const Edge_iterator& a, const Edge_iterator& b) { return a.code_ == b.code_; }
  friend bool operator!=(const Edge_iterator& a, const Edge_iterator& b) { return a.code_ != b.code_; }

private:
  // In dimension 1 the edges are the segments (c, 0, 1); in dimension 2
  // each triangle reports the edges whose other triangle has a larger index.
  bool accepts(std::size_t code) const
  {
    const Flat_storage& m = tr_->core.mesh;
    const int dimension = tr_->dimension();
    const Tet_id t = static_cast<Tet_id>(code / 6);
    if(!m.is_live(t)) return false;
    const int i = cell_edge_vertices[code % 6][0], j = cell_edge_vertices[code % 6][1];
    if(j > dimension) return false;
    if(finite_only && (m.vertex(t, i) == ghost_vertex || m.vertex(t, j) == ghost_vertex)) return false;
    if(dimension == 1) return true;
    if(dimension == 2) return m.neighbor(t, 3 - i - j) > t;
    return dimension == 3 && tr_->smallest_cell_around_edge(t, i, j) == t;
  }
  void skip()
  {
    const std::size_t end = 6 * tr_->slots_of_faces(1);
    for(; code_ < end; ++code_) {
      // A free slot: none of its six codes is listed.
      if(!tr_->core.mesh.is_live(static_cast<Tet_id>(code_ / 6))) { code_ += 5 - code_ % 6; continue; }
      if(accepts(code_)) break;
    }
    if(code_ < end) set_edge();
  }
  void set_edge()
  {
    const int k = static_cast<int>(code_ % 6);
    edge_ = Edge(Cell_handle(tr_, code_ / 6), cell_edge_vertices[k][0], cell_edge_vertices[k][1]);
  }
  const Anchor* tr_ = nullptr;
  std::size_t code_ = 0;
  Edge edge_;
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_FACE_ITERATORS_H
