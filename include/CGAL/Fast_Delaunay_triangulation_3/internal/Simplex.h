// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A vertex, edge, facet or cell of the triangulation as one value, with the
// interface of CGAL::Triangulation_simplex_3: built from a Vertex_handle, an
// Edge, a Facet or a Cell_handle, converted back, compared.  Two simplices
// are equal when they are the same face, whatever cell represents it (an edge
// from either end, a facet from either side).  The order sorts by dimension,
// then by the handles of the face (CGAL sorts by addresses, so only the
// dimension part of its order is reproducible).

#ifndef CGAL_FDT3_INTERNAL_SIMPLEX_H
#define CGAL_FDT3_INTERNAL_SIMPLEX_H

#include <CGAL/Triangulation_simplex_3.h>
#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <ostream>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

template <class Tr>
class Simplex_3
{
public:
  typedef Simplex_3 Simplex;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Edge Edge;
  typedef typename Tr::Facet Facet;

  // Undefined: as CGAL's, of dimension 3 with a null cell.
  Simplex_3() = default;
  Simplex_3(Vertex_handle v) : vertex_(v), dimension_(0) { CGAL_precondition(v != Vertex_handle()); }
  Simplex_3(const Edge& e) : cell_(e.first), i_(e.second), j_(e.third), dimension_(1)
  {
    CGAL_precondition(e.first != Cell_handle());
  }
  Simplex_3(const Facet& f) : cell_(f.first), i_(f.second), dimension_(2)
  {
    CGAL_precondition(f.first != Cell_handle());
  }
  Simplex_3(Cell_handle c) : cell_(c), dimension_(3) { CGAL_precondition(c != Cell_handle()); }
  // Circulators and edge / facet iterators, as CGAL's simplex accepts them.
  Simplex_3(typename Tr::Cell_circulator c) : Simplex_3(Cell_handle(c)) {}
  Simplex_3(typename Tr::Facet_circulator f) : Simplex_3(*f) {}
  Simplex_3(typename Tr::All_edges_iterator e) : Simplex_3(*e) {}
  Simplex_3(typename Tr::Finite_edges_iterator e) : Simplex_3(*e) {}
  Simplex_3(typename Tr::All_facets_iterator f) : Simplex_3(*f) {}
  Simplex_3(typename Tr::Finite_facets_iterator f) : Simplex_3(*f) {}

  int dimension() const { return dimension_; }

  operator Vertex_handle() const
  {
    CGAL_precondition(dimension_ == 0);
    return vertex_;
  }
  operator Edge() const
  {
    CGAL_precondition(dimension_ == 1);
    return Edge(cell_, i_, j_);
  }
  operator Facet() const
  {
    CGAL_precondition(dimension_ == 2);
    return Facet(cell_, i_);
  }
  operator Cell_handle() const
  {
    CGAL_precondition(dimension_ == 3);
    return cell_;
  }

  // CGAL's own simplex over tds(), the type CGAL's examples name
  // (Triangulation_simplex_3<DT::Triangulation_data_structure>): the same face.
  operator CGAL::Triangulation_simplex_3<typename Tr::Triangulation_data_structure>() const
  {
    typedef CGAL::Triangulation_simplex_3<typename Tr::Triangulation_data_structure> Cgal_simplex;
    switch(dimension_) {
      case 0: return Cgal_simplex(vertex_);
      case 1: return Cgal_simplex(Edge(cell_, i_, j_));
      case 2: return Cgal_simplex(Facet(cell_, i_));
      default: return cell_ == Cell_handle() ? Cgal_simplex() : Cgal_simplex(cell_);
    }
  }

  // A cell that has the simplex.
  Cell_handle incident_cell() const { return dimension_ == 0 ? vertex_->cell() : cell_; }

  // The face as sorted handles: vertices for a vertex and an edge, the two
  // cells for a facet, the cell for a cell.
  friend bool operator==(const Simplex_3& a, const Simplex_3& b)
  {
    return a.dimension_ == b.dimension_ && a.key() == b.key();
  }
  friend bool operator!=(const Simplex_3& a, const Simplex_3& b) { return !(a == b); }
  friend bool operator<(const Simplex_3& a, const Simplex_3& b)
  {
    if(a.dimension_ != b.dimension_) return a.dimension_ < b.dimension_;
    return a.key() < b.key();
  }

  // The vertices of the face (as CGAL prints them, by handle).
  friend std::ostream& operator<<(std::ostream& os, const Simplex_3& s)
  {
    switch(s.dimension_) {
      case 0: return os << s.vertex_.index();
      case 1: return os << s.cell_->vertex(s.i_).index() << ' ' << s.cell_->vertex(s.j_).index();
      case 2:
        return os << s.cell_->vertex((s.i_ + 1) & 3).index() << ' ' << s.cell_->vertex((s.i_ + 2) & 3).index()
                  << ' ' << s.cell_->vertex((s.i_ + 3) & 3).index();
      case 3:
        return os << s.cell_->vertex(0).index() << ' ' << s.cell_->vertex(1).index() << ' '
                  << s.cell_->vertex(2).index() << ' ' << s.cell_->vertex(3).index();
      default: return os;
    }
  }

private:
  // Vertex handles and cell handles both order by (triangulation, index);
  // a key holds cell handles only for facets and cells.
  struct Key
  {
    std::array<Vertex_handle, 2> vertices;
    std::array<Cell_handle, 2> cells;
    bool operator==(const Key& k) const { return vertices == k.vertices && cells == k.cells; }
    bool operator<(const Key& k) const
    {
      return vertices != k.vertices ? vertices < k.vertices : cells < k.cells;
    }
  };
  Key key() const
  {
    Key k;
    switch(dimension_) {
      case 0: k.vertices = {vertex_, Vertex_handle()}; break;
      case 1:
        k.vertices = {cell_->vertex(i_), cell_->vertex(j_)};
        if(k.vertices[1] < k.vertices[0]) std::swap(k.vertices[0], k.vertices[1]);
        break;
      case 2:
        k.cells = {cell_, cell_->neighbor(i_)};
        if(k.cells[1] < k.cells[0]) std::swap(k.cells[0], k.cells[1]);
        break;
      default: k.cells = {cell_, Cell_handle()}; break;
    }
    return k;
  }

  Vertex_handle vertex_;
  Cell_handle cell_;
  int i_ = 0, j_ = 0;
  int dimension_ = 3;
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_SIMPLEX_H
