// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lightweight vertex and cell handles over the flat arrays, with the member
// functions of CGAL's Triangulation_3 vertices and cells (v->point(),
// c->vertex(i), c->neighbor(i), c->index(v), ...), and the iterators that
// enumerate them.  A handle is a (storage anchor, index) pair: the anchor
// (Storage_anchor.h) holds the triangulation's data and goes with it through
// swap() and moves, so handles follow the data as CGAL's do; a copy of the
// triangulation has an anchor of its own, so handles are not carried over.

#ifndef CGAL_FDT3_INTERNAL_HANDLES_H
#define CGAL_FDT3_INTERNAL_HANDLES_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <CGAL/Handle_hash_function.h>

#include <cstddef>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <type_traits>
#include <utility>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// CGAL's handles are the iterators of its containers: `Cell_handle` and
// `Cell_iterator` are one type there, and so are `Vertex_handle` and
// `Vertex_iterator`.  Code relies on it: Triangulation_3_to_lcc.h looks a
// Cell_iterator up in a std::map keyed by Cell_handle, Alpha_shape_3 hashes
// handles through std::iterator_traits.  Ours are iterators too, and step
// through the arrays of their anchor:
// - cells in slot order over the live slots; the end is (anchor, number of
//   slots), whatever the dimension (the TDS's raw cells);
// - vertices as CGAL lists them, the infinite one first, then the live ids
//   in order; the end is (anchor, number of vertex records).
struct Vertex_kind {};
struct Cell_kind {};

template <class Anchor, class Index>
Index first_index_from(const Anchor& a, Cell_kind, Index t)
{
  const Flat_storage& m = a.flat_storage();
  while(t < m.number_of_slots() && !m.is_live(t)) ++t;
  return t;
}
template <class Anchor, class Index>
Index first_index_from(const Anchor& a, Vertex_kind, Index v)
{
  const Flat_storage& m = a.flat_storage();
  while(v < m.vertices.size() && m.is_dead(v)) ++v;
  return v;
}
template <class Anchor, class Index>
Index next_index(const Anchor& a, Cell_kind kind, Index t)
{
  return first_index_from(a, kind, Index(t + 1));
}
template <class Anchor, class Index>
Index next_index(const Anchor& a, Vertex_kind kind, Index v)
{
  return first_index_from(a, kind, v == ghost_vertex ? Index(0) : Index(v + 1));
}
// Stepping back from the first element is undefined, as for CGAL's.
template <class Anchor, class Index>
Index previous_index(const Anchor& a, Cell_kind, Index t)
{
  const Flat_storage& m = a.flat_storage();
  do {
    CGAL_precondition(t > 0);
    --t;
  } while(!m.is_live(t));
  return t;
}
template <class Anchor, class Index>
Index previous_index(const Anchor& a, Vertex_kind, Index v)
{
  CGAL_precondition(v != ghost_vertex);
  const Flat_storage& m = a.flat_storage();
  while(v > 0)
    if(!m.is_dead(--v)) return v;
  return ghost_vertex;
}

// What point() of a vertex that is not const gives: its point (it is one),
// and the target of an assignment in CGAL's copy_tds() protocol, where the
// conversion functor sets the copy's point with `copy.point() = p`
// (Data_structure_copy.h: the anchor being filled takes it).  Any other
// assignment throws std::logic_error: a vertex of a triangulation moves
// through move(), and a silent write to a temporary would leave the user
// believing it moved.  Being a Point, it goes wherever the point went
// before (template arguments, comparisons, members).  (A vertex of a user
// base holds its point and sets it with set_point(): User_bases.h.)
template <class Anchor, class Point>
class Vertex_point_reference : public Point
{
public:
  Vertex_point_reference(const Anchor* anchor, Vertex_id v)
      : Point(anchor == nullptr ? Point() : anchor->current_point(v)), anchor_(anchor), v_(v) {}
  Vertex_point_reference(const Vertex_point_reference&) = default;

  Vertex_point_reference& operator=(const Point& p)
  {
    if(anchor_ == nullptr)
      throw std::logic_error("Fast_Delaunay_triangulation_3: a vertex that belongs to no triangulation has no point");
    anchor_->assign_point(v_, p);
    Point::operator=(p);
    return *this;
  }
  Vertex_point_reference& operator=(const Vertex_point_reference& other)
  {
    return *this = static_cast<const Point&>(other);
  }

private:
  const Anchor* anchor_;
  Vertex_id v_;
};

// A vertex seen through the anchor of the triangulation Tr (which provides
// point_of, incident_cell_of and the handle types).
template <class Tr>
class Vertex_facade
{
public:
  typedef typename Tr::Point Point;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Anchor Anchor;
  typedef Vertex_kind Kind;

  Vertex_facade() = default;
  Vertex_facade(const Anchor* tr, Vertex_id id) : tr_(tr), id_(id) {}

  Point point() const { return tr_->point_of(id_); }
  Vertex_point_reference<Anchor, Point> point() { return {tr_, id_}; }
  Cell_handle cell() const { return tr_->incident_cell_of(id_); }
  bool is_valid(bool = false, int = 0) const { return tr_ != nullptr; }
  // Only with a vertex base with info: the info lives in the triangulation's
  // side array, writable through any handle (as CGAL's is through its handles).
  template <class T = Tr>
  typename T::Vertex_info& info() const { return tr_->vertex_info(id_); }

  Vertex_id id() const { return id_; }
  const Anchor* anchor() const { return tr_; }

private:
  const Anchor* tr_ = nullptr;
  Vertex_id id_ = 0;
};

template <class Tr>
class Cell_facade
{
public:
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Anchor Anchor;
  typedef Cell_kind Kind;

  Cell_facade() = default;
  Cell_facade(const Anchor* tr, Tet_id id) : tr_(tr), id_(id) {}

  // Below dimension 3, slots above the dimension are null handles, as in CGAL.
  Vertex_handle vertex(int i) const
  {
    const Vertex_id v = mesh().vertex(id_, i);
    return v == no_vertex ? Vertex_handle() : Vertex_handle(tr_, v);
  }
  Cell_handle neighbor(int i) const
  {
    return i > tr_->dimension() ? Cell_handle() : Cell_handle(tr_, mesh().neighbor(id_, i));
  }
  int index(Vertex_handle v) const
  {
    int i = -1;
    const bool found = has_vertex(v, i);
    CGAL_precondition(found);
    (void)found;
    return i;
  }
  int index(Cell_handle c) const
  {
    int i = -1;
    const bool found = has_neighbor(c, i);
    CGAL_precondition(found);
    (void)found;
    return i;
  }
  bool has_vertex(Vertex_handle v) const
  {
    int i;
    return has_vertex(v, i);
  }
  bool has_vertex(Vertex_handle v, int& i) const
  {
    for(int k = 0; k < 4; ++k)
      if(mesh().vertex(id_, k) == v.index()) { i = k; return true; }
    return false;
  }
  bool has_neighbor(Cell_handle c) const
  {
    int i;
    return has_neighbor(c, i);
  }
  bool has_neighbor(Cell_handle c, int& i) const
  {
    for(int k = 0; k <= tr_->dimension(); ++k)
      if(mesh().neighbor(id_, k) == c.index()) { i = k; return true; }
    return false;
  }
  bool is_valid(bool = false, int = 0) const { return tr_ != nullptr && mesh().is_live(id_); }
  // Only with a cell base with info (see Vertex_and_cell_infos.h).
  template <class T = Tr>
  typename T::Cell_info& info() const { return tr_->cell_info(id_); }
  // Dimension 3, finite cell: the centre of its circumscribed sphere.
  typename Tr::Point circumcenter() const { return tr_->circumcenter(id_); }

  Tet_id id() const { return id_; }
  const Anchor* anchor() const { return tr_; }

private:
  const Flat_storage& mesh() const { return tr_->flat_storage(); }
  const Anchor* tr_ = nullptr;
  Tet_id id_ = 0;
};

// Equality, order and hash of handles by (anchor, index), so handles work as
// std::map / unordered_map keys; the anchor does not change with swap() or a
// move, so neither does the order of the keys.  Handle provides owner() and
// index().
template <class Handle>
class Handle_order
{
public:
  friend bool operator==(const Handle& a, const Handle& b)
  {
    return a.owner() == b.owner() && a.index() == b.index();
  }
  friend bool operator!=(const Handle& a, const Handle& b) { return !(a == b); }
  friend bool operator==(const Handle& a, std::nullptr_t) { return !a; }
  friend bool operator!=(const Handle& a, std::nullptr_t) { return bool(a); }
  friend bool operator<(const Handle& a, const Handle& b)
  {
    if(a.owner() != b.owner()) return std::less<const void*>()(a.owner(), b.owner());
    return a.index() < b.index();
  }
  friend bool operator>(const Handle& a, const Handle& b) { return b < a; }
  friend bool operator<=(const Handle& a, const Handle& b) { return !(b < a); }
  friend bool operator>=(const Handle& a, const Handle& b) { return !(a < b); }
  friend std::size_t hash_value(const Handle& h) { return std::hash<decltype(h.index())>()(h.index()); }
};

// A handle that holds its facade by value, so `->` needs no storage
// elsewhere; also the iterator over its kind (see Vertex_kind above).  Its
// element lives in it, so a std::reverse_iterator, which dereferences a
// temporary copy, would hand out a dangling reference: walk backwards with --.
template <class Facade, class Index>
class Flat_handle : public Handle_order<Flat_handle<Facade, Index>>
{
public:
  typedef std::bidirectional_iterator_tag iterator_category;
  typedef Facade value_type;
  typedef const Facade& reference;
  typedef const Facade* pointer;
  typedef std::ptrdiff_t difference_type;
  typedef typename Facade::Anchor Anchor;

  Flat_handle() = default;
  Flat_handle(std::nullptr_t) {}
  Flat_handle(const Anchor* anchor, Index id) : facade_(anchor, id) {}

  const Facade* operator->() const { return &facade_; }
  const Facade& operator*() const { return facade_; }
  explicit operator bool() const { return facade_.anchor() != nullptr; }

  const Anchor* owner() const { return facade_.anchor(); }
  Index index() const { return facade_.id(); }

  Flat_handle& operator++()
  {
    facade_ = Facade(owner(), next_index(*owner(), typename Facade::Kind(), index()));
    return *this;
  }
  Flat_handle operator++(int)
  {
    Flat_handle old = *this;
    ++*this;
    return old;
  }
  Flat_handle& operator--()
  {
    facade_ = Facade(owner(), previous_index(*owner(), typename Facade::Kind(), index()));
    return *this;
  }
  Flat_handle operator--(int)
  {
    Flat_handle old = *this;
    --*this;
    return old;
  }

private:
  Facade facade_;
};

// Iterates over indices [0, end) that satisfy Tr's filter `Accept`, and
// dereferences as its handle does (to the vertex or cell, as CGAL's
// iterators); converts to the handle.  Bidirectional, as CGAL's iterators
// over its containers: decrementing the first position is undefined, as
// there.  The element lives in the iterator (its handle's facade), so a
// std::reverse_iterator, which dereferences a temporary copy, would hand out
// a dangling reference: walk backwards with --.
template <class Handle, class Index, class Accept>
class Filtered_index_iterator
{
public:
  typedef std::bidirectional_iterator_tag iterator_category;
  typedef decltype(*std::declval<const Handle&>()) reference;
  typedef typename std::remove_reference<reference>::type value_type;
  typedef value_type* pointer;
  typedef std::ptrdiff_t difference_type;
  typedef typename Handle::Anchor Anchor;

  Filtered_index_iterator() = default;
  Filtered_index_iterator(const Anchor* anchor, Index id, Index end) : handle_(anchor, id), end_(end)
  {
    skip();
  }

  reference operator*() const { return *handle_; }
  pointer operator->() const { return handle_.operator->(); }
  operator Handle() const { return handle_; }

  Filtered_index_iterator& operator++()
  {
    handle_ = Handle(handle_.owner(), handle_.index() + 1);
    skip();
    return *this;
  }
  Filtered_index_iterator operator++(int)
  {
    Filtered_index_iterator old = *this;
    ++*this;
    return old;
  }
  Filtered_index_iterator& operator--()
  {
    Index id = handle_.index();
    do {
      CGAL_precondition(id > 0);
      --id;
    } while(!Accept()(*handle_.owner(), id));
    handle_ = Handle(handle_.owner(), id);
    return *this;
  }
  Filtered_index_iterator operator--(int)
  {
    Filtered_index_iterator old = *this;
    --*this;
    return old;
  }
  friend bool operator==(const Filtered_index_iterator& a, const Filtered_index_iterator& b)
  {
    return a.handle_.index() == b.handle_.index();
  }
  friend bool operator!=(const Filtered_index_iterator& a, const Filtered_index_iterator& b)
  {
    return !(a == b);
  }

private:
  void skip()
  {
    Index id = handle_.index();
    while(id < end_ && !Accept()(*handle_.owner(), id)) ++id;
    handle_ = Handle(handle_.owner(), id);
  }

  Handle handle_;
  Index end_ = 0;
};

// Adapts an iterator that converts to a handle into one that yields handles
// (CGAL's *_handles() ranges); bidirectional when Base is.
template <class Base, class Handle>
class Handle_iterator
{
public:
  typedef typename std::iterator_traits<Base>::iterator_category iterator_category;
  typedef Handle value_type;
  typedef std::ptrdiff_t difference_type;
  typedef const Handle* pointer;
  typedef Handle reference;

  Handle_iterator() = default;
  explicit Handle_iterator(Base base) : base_(base) {}
  Handle operator*() const { return Handle(base_); }
  struct Arrow { Handle h; const Handle* operator->() const { return &h; } };
  Arrow operator->() const { return Arrow{Handle(base_)}; }
  Handle_iterator& operator++() { ++base_; return *this; }
  Handle_iterator operator++(int) { Handle_iterator old = *this; ++base_; return old; }
  Handle_iterator& operator--() { --base_; return *this; }
  Handle_iterator operator--(int) { Handle_iterator old = *this; --base_; return old; }
  friend bool operator==(const Handle_iterator& a, const Handle_iterator& b) { return a.base_ == b.base_; }
  friend bool operator!=(const Handle_iterator& a, const Handle_iterator& b) { return a.base_ != b.base_; }

private:
  Base base_;
};

// The points of the vertices of a vertex iterator (CGAL's Point_iterator,
// bidirectional).  A point is assembled from the flat coordinate array, so
// it is yielded by value: `const Point& p = *it` and range-for loops bind it
// as they would CGAL's reference, and std::reverse_iterator works; `&*it`
// does not.
template <class Base, class Point>
class Point_iterator
{
public:
  typedef std::bidirectional_iterator_tag iterator_category;
  typedef Point value_type;
  typedef std::ptrdiff_t difference_type;
  typedef const Point* pointer;
  typedef Point reference;

  Point_iterator() = default;
  explicit Point_iterator(Base base) : base_(base) {}
  Point operator*() const { return base_->point(); }
  struct Arrow { Point p; const Point* operator->() const { return &p; } };
  Arrow operator->() const { return Arrow{base_->point()}; }
  Point_iterator& operator++() { ++base_; return *this; }
  Point_iterator operator++(int) { Point_iterator old = *this; ++base_; return old; }
  Point_iterator& operator--() { --base_; return *this; }
  Point_iterator operator--(int) { Point_iterator old = *this; --base_; return old; }
  friend bool operator==(const Point_iterator& a, const Point_iterator& b) { return a.base_ == b.base_; }
  friend bool operator!=(const Point_iterator& a, const Point_iterator& b) { return a.base_ != b.base_; }
  const Base& base() const { return base_; }

private:
  Base base_;
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

// CGAL's Unique_hash_map (its copy_tds(), Alpha_shape_3, ...) hashes a
// handle by the address of its element, and takes the hash for the key.
// Our elements live in the handles, so the address would change from copy
// to copy: the hash is the index instead (one more, null handles are 0),
// one-to-one over the handles of one triangulation.  CGAL leaves this class
// template open for that.
namespace CGAL {
namespace internal {
namespace handle {
template <class Facade, class Index>
struct Hash_functor<CGAL::Fast_Delaunay_triangulation_3_internal::Flat_handle<Facade, Index>>
{
  std::size_t operator()(const CGAL::Fast_Delaunay_triangulation_3_internal::Flat_handle<Facade, Index>& h)
  {
    return h ? std::size_t(h.index()) + 1 : 0;
  }
};
} // namespace handle
} // namespace internal
} // namespace CGAL

// CGAL's handles hash with std::hash as well as boost::hash (hash_value):
// code that keys a std::unordered_map by handle must compile unchanged.
namespace std {
template <class Facade, class Index>
struct hash<CGAL::Fast_Delaunay_triangulation_3_internal::Flat_handle<Facade, Index>>
{
  std::size_t operator()(const CGAL::Fast_Delaunay_triangulation_3_internal::Flat_handle<Facade, Index>& h) const
  {
    return hash_value(h);
  }
};
} // namespace std

#endif // CGAL_FDT3_INTERNAL_HANDLES_H
