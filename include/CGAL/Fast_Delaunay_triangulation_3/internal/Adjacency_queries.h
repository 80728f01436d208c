// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Adjacency queries of CGAL's Triangulation_3 on the flat arrays: the cells
// around a vertex (breadth-first search across the facets that contain it,
// starting from v->cell()), the facets, edges and vertices derived from them,
// and the circulators around an edge, which turn in CGAL's direction
// (Triangulation_utils_3::next_around_edge) so that the same edge of the same
// triangulation yields the same cyclic sequence as CGAL.  Dimension 3 only.

#ifndef CGAL_FDT3_INTERNAL_ADJACENCY_QUERIES_H
#define CGAL_FDT3_INTERNAL_ADJACENCY_QUERIES_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <CGAL/circulator_bases.h>
#include <CGAL/Triangulation_utils_3.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <iterator>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Set of 64-bit ids with open addressing: one allocation per query, no node
// per element; sized for the ~27 cells of a typical vertex and grown for the
// infinite vertex, which has one cell per hull facet.
class Id_set
{
public:
  Id_set() : slots_(64, empty) {}

  // True if id was not in the set.
  bool insert(std::uint64_t id)
  {
    if(2 * (count_ + 1) > slots_.size()) grow();
    return place(slots_, id);
  }
  // Empties the set for the next query, keeping its table unless a big star
  // made it large.
  void clear()
  {
    if(slots_.size() > 256) slots_.assign(64, empty);
    else std::fill(slots_.begin(), slots_.end(), empty);
    count_ = 0;
  }
  bool contains(std::uint64_t id) const
  {
    const std::size_t mask = slots_.size() - 1;
    for(std::size_t k = hash(id) & mask;; k = (k + 1) & mask) {
      if(slots_[k] == id) return true;
      if(slots_[k] == empty) return false;
    }
  }

private:
  static constexpr std::uint64_t empty = ~std::uint64_t(0);

  bool place(std::vector<std::uint64_t>& table, std::uint64_t id)
  {
    const std::size_t mask = table.size() - 1;
    for(std::size_t k = hash(id) & mask;; k = (k + 1) & mask) {
      if(table[k] == id) return false;
      if(table[k] == empty) {
        table[k] = id;
        ++count_;
        return true;
      }
    }
  }
  static std::size_t hash(std::uint64_t id) { return static_cast<std::size_t>((id * 0x9e3779b97f4a7c15ull) >> 20); }
  void grow()
  {
    std::vector<std::uint64_t> bigger(2 * slots_.size(), empty);
    count_ = 0;
    for(std::uint64_t id : slots_)
      if(id != empty) place(bigger, id);
    slots_.swap(bigger);
  }

  std::vector<std::uint64_t> slots_;
  std::size_t count_ = 0;
};

// An output iterator that only counts (degree()).
struct Counting_output
{
  std::size_t* count;
  typedef std::output_iterator_tag iterator_category;
  typedef void value_type;
  typedef void difference_type;
  typedef void pointer;
  typedef void reference;
  Counting_output& operator*() { return *this; }
  Counting_output& operator++() { return *this; }
  Counting_output operator++(int) { return *this; }
  template <class T>
  Counting_output& operator=(const T&) { ++*count; return *this; }
};

inline int index_of(const Flat_storage& m, Tet_id t, Vertex_id v)
{
  for(int i = 0; i < 4; ++i)
    if(m.vertex(t, i) == v) return i;
  return -1;
}

// Every cell that has v, in breadth-first order from `start` (which has v).
// seen: a set kept by a caller that asks many times (removals, moves).
inline void cells_around_vertex(const Flat_storage& m, Tet_id start, Vertex_id v, std::vector<Tet_id>& cells,
                                Id_set& seen)
{
  CGAL_precondition(index_of(m, start, v) >= 0);
  cells.clear();
  seen.clear();
  seen.insert(start);
  cells.push_back(start);
  for(std::size_t k = 0; k < cells.size(); ++k) {
    const Tet_id t = cells[k];
    // The vertex records are read next (a removal numbers them, a move
    // reads their points): their loads start here.
    for(int i = 0; i < 4; ++i) {
      const Vertex_id w = m.vertex(t, i);
      if(w != v && w != ghost_vertex) __builtin_prefetch(m.vertices.data() + w);
    }
    for(int f = 0; f < 4; ++f) {
      if(m.vertex(t, f) == v) continue; // the one facet without v
      const Tet_id u = m.neighbor(t, f);
      if(seen.insert(u)) {
        // Read a few cells later: the load overlaps the others' (in a big
        // triangulation each cell of a star met afresh misses the caches).
        __builtin_prefetch(m.vertex_ids(u));
        cells.push_back(u);
      }
    }
  }
}
inline void cells_around_vertex(const Flat_storage& m, Tet_id start, Vertex_id v, std::vector<Tet_id>& cells)
{
  Id_set seen;
  cells_around_vertex(m, start, v, cells, seen);
}

// The vertices joined to v by an edge, each once with a cell that has the
// edge, in the order of `cells` (the cells around v).
inline void vertices_around_vertex(const Flat_storage& m, const std::vector<Tet_id>& cells, Vertex_id v,
                                   std::vector<Vertex_id>& vertices, std::vector<Tet_id>* cell_of_edge)
{
  vertices.clear();
  if(cell_of_edge) cell_of_edge->clear();
  Id_set seen;
  for(Tet_id t : cells)
    for(int i = 0; i < 4; ++i) {
      const Vertex_id w = m.vertex(t, i);
      if(w == v || !seen.insert(w)) continue;
      vertices.push_back(w);
      if(cell_of_edge) cell_of_edge->push_back(t);
    }
}

// The cell after `t` around the edge (a, b), turning as CGAL's circulators
// do: forward around the oriented edge (a, b), backward around (b, a).
inline Tet_id next_cell_around_edge(const Flat_storage& m, Tet_id t, Vertex_id a, Vertex_id b)
{
  return m.neighbor(t, Triangulation_utils_3::next_around_edge(index_of(m, t, a), index_of(m, t, b)));
}

// CGAL's Cell_circulator and Facet_circulator around an edge: bidirectional
// circulators (CGAL's circulator concept: compared with nullptr when empty,
// used in do { } while(c != done) loops).  Tr provides the handle types.
template <class Tr>
class Cell_circulator_around_edge
{
public:
  typedef typename Tr::Cell Cell;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef Cell value_type;
  typedef const Cell& reference;
  typedef const Cell* pointer;
  typedef std::size_t size_type;
  typedef std::ptrdiff_t difference_type;
  typedef Bidirectional_circulator_tag iterator_category;

  Cell_circulator_around_edge() = default;
  Cell_circulator_around_edge(const typename Tr::Anchor* tr, Vertex_id a, Vertex_id b, Tet_id start)
      : a_(a), b_(b), pos_(tr, start)
  {}

  reference operator*() const { return *pos_; }
  pointer operator->() const { return &*pos_; }
  operator Cell_handle() const { return pos_; }

  Cell_circulator_around_edge& operator++()
  {
    pos_ = Cell_handle(tr(), next_cell_around_edge(tr()->flat_storage(), pos_.index(), a_, b_));
    return *this;
  }
  Cell_circulator_around_edge& operator--()
  {
    pos_ = Cell_handle(tr(), next_cell_around_edge(tr()->flat_storage(), pos_.index(), b_, a_));
    return *this;
  }
  Cell_circulator_around_edge operator++(int) { Cell_circulator_around_edge old = *this; ++*this; return old; }
  Cell_circulator_around_edge operator--(int) { Cell_circulator_around_edge old = *this; --*this; return old; }

  friend bool operator==(const Cell_circulator_around_edge& x, const Cell_circulator_around_edge& y)
  {
    return x.pos_ == y.pos_ && x.a_ == y.a_ && x.b_ == y.b_;
  }
  friend bool operator!=(const Cell_circulator_around_edge& x, const Cell_circulator_around_edge& y) { return !(x == y); }
  friend bool operator==(const Cell_circulator_around_edge& x, std::nullptr_t) { return x.pos_ == nullptr; }
  friend bool operator!=(const Cell_circulator_around_edge& x, std::nullptr_t) { return x.pos_ != nullptr; }
  // CGAL's handles compare circulators with cells.
  friend bool operator==(const Cell_circulator_around_edge& x, const Cell_handle& c) { return x.pos_ == c; }
  friend bool operator!=(const Cell_circulator_around_edge& x, const Cell_handle& c) { return x.pos_ != c; }

private:
  const typename Tr::Anchor* tr() const { return pos_.owner(); }
  Vertex_id a_ = 0, b_ = 0;
  Cell_handle pos_;
};

// Yields, for each cell around the edge (a, b), the facet of that cell which
// comes next when turning around (a, b): CGAL's Facet(pos, next_around_edge(i, j)).
template <class Tr>
class Facet_circulator_around_edge
{
public:
  typedef typename Tr::Facet Facet;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef Facet value_type;
  typedef Facet reference;
  typedef const Facet* pointer;
  typedef std::size_t size_type;
  typedef std::ptrdiff_t difference_type;
  typedef Bidirectional_circulator_tag iterator_category;

  Facet_circulator_around_edge() = default;
  Facet_circulator_around_edge(const typename Tr::Anchor* tr, Vertex_id a, Vertex_id b, Tet_id start) : cells_(tr, a, b, start), a_(a), b_(b) {}

  Facet operator*() const
  {
    const Cell_handle c = cells_;
    const Flat_storage& m = c.owner()->flat_storage();
    return Facet(c, Triangulation_utils_3::next_around_edge(index_of(m, c.index(), a_), index_of(m, c.index(), b_)));
  }
  struct Arrow { Facet f; const Facet* operator->() const { return &f; } };
  Arrow operator->() const { return Arrow{**this}; }

  Facet_circulator_around_edge& operator++() { ++cells_; return *this; }
  Facet_circulator_around_edge& operator--() { --cells_; return *this; }
  Facet_circulator_around_edge operator++(int) { Facet_circulator_around_edge old = *this; ++*this; return old; }
  Facet_circulator_around_edge operator--(int) { Facet_circulator_around_edge old = *this; --*this; return old; }

  friend bool operator==(const Facet_circulator_around_edge& x, const Facet_circulator_around_edge& y)
  {
    return x.cells_ == y.cells_;
  }
  friend bool operator!=(const Facet_circulator_around_edge& x, const Facet_circulator_around_edge& y) { return !(x == y); }
  friend bool operator==(const Facet_circulator_around_edge& x, std::nullptr_t) { return x.cells_ == nullptr; }
  friend bool operator!=(const Facet_circulator_around_edge& x, std::nullptr_t) { return x.cells_ != nullptr; }

private:
  Cell_circulator_around_edge<Tr> cells_;
  Vertex_id a_ = 0, b_ = 0;
};

// Triangulation_3::is_edge / is_facet / is_cell on vertices: a cell around u
// with the other vertices; on success (c, i, j, ...) are their indices in it.
template <class Tr, std::size_t N>
bool find_cell_with(const Tr& tr, typename Tr::Vertex_handle u,
                    const typename Tr::Vertex_handle (&others)[N], typename Tr::Cell_handle& c, int (&index)[N + 1])
{
  const Flat_storage& m = tr.flat_storage();
  std::vector<Tet_id> cells;
  cells_around_vertex(m, tr.incident_cell_of(u.index()).index(), u.index(), cells);
  for(Tet_id t : cells) {
    bool all = true;
    for(std::size_t k = 0; k < N && all; ++k) {
      index[k + 1] = index_of(m, t, others[k].index());
      all = index[k + 1] >= 0;
    }
    if(!all) continue;
    index[0] = index_of(m, t, u.index());
    c = typename Tr::Cell_handle(tr.storage_anchor(), t);
    return true;
  }
  return false;
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_ADJACENCY_QUERIES_H
