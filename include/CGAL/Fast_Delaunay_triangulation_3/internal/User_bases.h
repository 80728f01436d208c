// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A user's vertex or cell base with extra members (CGAL manual, "Adding
// handles" and "Color" examples): a class template deriving from
// Triangulation_vertex_base_3 (or a cell base) that follows the Rebind_TDS
// protocol, given in the Triangulation_data_structure_3 argument.
//
// The points and the adjacency stay in the flat arrays.  Beside them, one
// object of the user's base, rebound to our handles, is kept per vertex (by
// vertex id, plus one for the infinite vertex) and per cell slot, in side
// arrays like the infos, and v->member / c->member reach it:
//
//   User_vertex<Tr, Base>   derives from the rebound user base; point(),
//                           cell() and info() hide the base's and read the
//                           triangulation (the base's own point and cell are
//                           never written).
//   User_cell<Tr, Base>     likewise for cells: vertex(), neighbor(), index(),
//                           has_vertex(), has_neighbor(), info() and
//                           circumcenter() are the triangulation's.  A slot
//                           whose four vertices changed holds a new cell (the
//                           reasoning of Cell_infos): its base is reset when
//                           next reached.
//   User_handle             (storage anchor, index); operator-> is a mutable
//                           record pointer, as CGAL's handles give mutable
//                           vertices and cells.
//   Rebinding_tds<Tr>       what Rebind_TDS is given: its Vertex_handle and
//                           Cell_handle are ours, so members of those types
//                           in the user's base hold our handles.
//
// CGAL's own bases (Triangulation_vertex_base_3, Triangulation_cell_base_3,
// Delaunay_triangulation_cell_base_3, with_info) are "plain": they get no
// record, and the handles stay the facade handles of Handles.h.

#ifndef CGAL_FDT3_INTERNAL_USER_BASES_H
#define CGAL_FDT3_INTERNAL_USER_BASES_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Handles.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_and_cell_infos.h>

#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_ds_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/Triangulation_cell_base_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_ds_cell_base_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <functional>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// The vertex base given to a CGAL data structure, before rebinding (void for
// Default).
template <class Tds>
struct Vertex_base_of { typedef void type; };
template <class Vb, class Cb, class Ct>
struct Vertex_base_of<Triangulation_data_structure_3<Vb, Cb, Ct>> { typedef Vb type; };

template <class Tds>
struct Cell_base_of { typedef void type; };
template <class Vb, class Cb, class Ct>
struct Cell_base_of<Triangulation_data_structure_3<Vb, Cb, Ct>> { typedef Cb type; };

// Bases whose every member the flat arrays or the info arrays serve.
template <class Vb>
struct Is_plain_vertex_base : std::false_type {};
template <>
struct Is_plain_vertex_base<void> : std::true_type {};
template <class T>
struct Is_plain_vertex_base<Triangulation_ds_vertex_base_3<T>> : std::true_type {};
template <class Gt, class DSVb>
struct Is_plain_vertex_base<Triangulation_vertex_base_3<Gt, DSVb>> : Is_plain_vertex_base<DSVb> {};
template <class Info, class Gt, class Vb>
struct Is_plain_vertex_base<Triangulation_vertex_base_with_info_3<Info, Gt, Vb>> : Is_plain_vertex_base<Vb> {};

template <class Cb>
struct Is_plain_cell_base : std::false_type {};
template <>
struct Is_plain_cell_base<void> : std::true_type {};
template <class T>
struct Is_plain_cell_base<Triangulation_ds_cell_base_3<T>> : std::true_type {};
template <class Gt, class Cb>
struct Is_plain_cell_base<Triangulation_cell_base_3<Gt, Cb>> : Is_plain_cell_base<Cb> {};
template <class Gt, class Cb>
struct Is_plain_cell_base<Delaunay_triangulation_cell_base_3<Gt, Cb>> : Is_plain_cell_base<Cb> {};
template <class Info, class Gt, class Cb>
struct Is_plain_cell_base<Triangulation_cell_base_with_info_3<Info, Gt, Cb>> : Is_plain_cell_base<Cb> {};

// The data structure a user's base is rebound to.  Only named while the
// triangulation class is being defined; its members are looked up when the
// user's base is instantiated, once the triangulation is complete.
template <class Tr>
struct Rebinding_tds
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex Vertex;
  typedef typename Tr::Cell Cell;
  typedef typename Tr::Concurrency_tag Concurrency_tag;
  // The bookkeeping a cell base carries for CGAL's data structure; unused.
  typedef typename Triangulation_data_structure_3<>::Cell_data Cell_data;
};

// The user's base rebound to Rebinding_tds<Tr> (void for a plain base).
template <class Tds, class Tr, bool plain = Is_plain_vertex_base<typename Vertex_base_of<Tds>::type>::value>
struct Rebound_vertex_base { typedef void type; };
template <class Tds, class Tr>
struct Rebound_vertex_base<Tds, Tr, false>
{
  typedef typename Vertex_base_of<Tds>::type::template Rebind_TDS<Rebinding_tds<Tr>>::Other type;
};

template <class Tds, class Tr, bool plain = Is_plain_cell_base<typename Cell_base_of<Tds>::type>::value>
struct Rebound_cell_base { typedef void type; };
template <class Tds, class Tr>
struct Rebound_cell_base<Tds, Tr, false>
{
  typedef typename Cell_base_of<Tds>::type::template Rebind_TDS<Rebinding_tds<Tr>>::Other type;
};

template <class Tr, class Base>
class User_vertex : public Base
{
public:
  typedef typename Tr::Point Point;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Anchor Anchor;

  // A reference, as CGAL's: code keeps references to points (CGAL's
  // Alpha_shape_3 in its exact comparison mode evaluates lazily from them).
  // The record holds a copy of its vertex's point, which the anchor renews
  // when the vertex moves (Storage_anchor::point_replaced).
  const Point& point() const { return point_; }
  // Only while the triangulation copies another data structure
  // (Data_structure_copy.h): the copy's point.  Otherwise it throws
  // std::logic_error, as a vertex moves through move().
  void set_point(const Point& p)
  {
    tr_->assign_point(id_, p);
    point_ = p;
  }
  Cell_handle cell() const { return tr_->incident_cell_of(id_); }
  // The triangulation owns the adjacency: a vertex cannot be re-attached
  // through its handle.
  void set_cell(Cell_handle) = delete;
  template <class T = Tr>
  typename T::Vertex_info& info() const { return tr_->vertex_info(id_); }
  // The base's is_valid would test its own (never written) cell.
  bool is_valid(bool = false, int = 0) const { return tr_ != nullptr; }

  // Nothing else is named here, so that the user's members (an id() of
  // Triangulation_vertex_base_with_id_3, say) stay visible.
  void attach_to_triangulation(const Anchor* tr, Vertex_id id)
  {
    tr_ = tr;
    id_ = id;
    point_ = tr->current_point(id);
  }

private:
  const Anchor* tr_ = nullptr;
  Vertex_id id_ = 0;
  Point point_;
};

template <class Tr, class Base>
class User_cell : public Base
{
public:
  typedef typename Tr::Point Point;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;

  Vertex_handle vertex(int i) const { return facade_.vertex(i); }
  Cell_handle neighbor(int i) const { return facade_.neighbor(i); }
  int index(Vertex_handle v) const { return facade_.index(v); }
  int index(Cell_handle c) const { return facade_.index(c); }
  bool has_vertex(Vertex_handle v) const { return facade_.has_vertex(v); }
  bool has_vertex(Vertex_handle v, int& i) const { return facade_.has_vertex(v, i); }
  bool has_neighbor(Cell_handle c) const { return facade_.has_neighbor(c); }
  bool has_neighbor(Cell_handle c, int& i) const { return facade_.has_neighbor(c, i); }
  bool is_valid(bool verbose = false, int level = 0) const { return facade_.is_valid(verbose, level); }
  template <class T = Tr>
  typename T::Cell_info& info() const { return facade_.info(); }
  Point circumcenter() const { return facade_.circumcenter(); }
  template <class Gt>
  Point circumcenter(const Gt&) const { return facade_.circumcenter(); }
  // The triangulation owns the adjacency.
  template <class... A>
  void set_vertex(A&&...) = delete;
  template <class... A>
  void set_vertices(A&&...) = delete;
  template <class... A>
  void set_neighbor(A&&...) = delete;
  template <class... A>
  void set_neighbors(A&&...) = delete;

  void attach_to_triangulation(const typename Tr::Anchor* tr, Tet_id id) { facade_ = Cell_facade<Tr>(tr, id); }

private:
  Cell_facade<Tr> facade_;
};

// A handle to a record of a user base: Record is the triangulation's Vertex
// or Cell, Index its vertex id or cell slot.  An iterator too, as
// Flat_handle (Handles.h).
template <class Tr, class Record, class Index>
class User_handle : public Handle_order<User_handle<Tr, Record, Index>>
{
  // Named in a member function: Tr is incomplete where the handle type is.
  static auto kind()
  {
    return typename std::conditional<std::is_same<Record, typename Tr::Vertex>::value, Vertex_kind, Cell_kind>::type();
  }

public:
  typedef std::bidirectional_iterator_tag iterator_category;
  typedef Record value_type;
  typedef Record& reference;
  typedef Record* pointer;
  typedef std::ptrdiff_t difference_type;
  typedef typename Tr::Anchor Anchor;

  User_handle() = default;
  User_handle(std::nullptr_t) {}
  User_handle(const Anchor* tr, Index id) : tr_(tr), id_(id) {}

  Record* operator->() const { return &tr_->user_record(static_cast<const Record*>(nullptr), id_); }
  Record& operator*() const { return *operator->(); }
  explicit operator bool() const { return tr_ != nullptr; }

  const Anchor* owner() const { return tr_; }
  Index index() const { return id_; }

  User_handle& operator++()
  {
    id_ = next_index(*tr_, kind(), id_);
    return *this;
  }
  User_handle operator++(int)
  {
    User_handle old = *this;
    ++*this;
    return old;
  }
  User_handle& operator--()
  {
    id_ = previous_index(*tr_, kind(), id_);
    return *this;
  }
  User_handle operator--(int)
  {
    User_handle old = *this;
    --*this;
    return old;
  }

private:
  const Anchor* tr_ = nullptr;
  Index id_ = 0;
};

// One record per vertex id and one for the infinite vertex.  The vectors are
// of a type still incomplete where the triangulation declares this member.
template <class Record>
class User_vertices
{
public:
  // A reference that stays valid until the next insertion.
  Record& at(Vertex_id v) const
  {
    if(v == ghost_vertex) return infinite_.front();
    CGAL_assertion(v < records_.size());
    return records_[v];
  }

  // After an insertion: new vertices get a default-constructed base.
  template <class Anchor>
  void resize(const Anchor* tr, std::size_t vertices)
  {
    const std::size_t old = records_.size();
    records_.resize(vertices);
    if(infinite_.empty()) infinite_.resize(1);
    for(std::size_t v = old; v < vertices; ++v) records_[v].attach_to_triangulation(tr, static_cast<Vertex_id>(v));
    infinite_.front().attach_to_triangulation(tr, ghost_vertex);
  }

  // Vertex v stands at another point.
  template <class Anchor>
  void point_replaced(const Anchor* tr, Vertex_id v)
  {
    if(v < records_.size()) records_[v].attach_to_triangulation(tr, v);
  }

  // After the triangulation's data was copied to another anchor.
  template <class Anchor>
  void attach(const Anchor* tr)
  {
    for(std::size_t v = 0; v < records_.size(); ++v) records_[v].attach_to_triangulation(tr, static_cast<Vertex_id>(v));
    if(!infinite_.empty()) infinite_.front().attach_to_triangulation(tr, ghost_vertex);
  }

  void clear()
  {
    records_.clear();
    infinite_.clear();
  }

private:
  mutable std::vector<Record> records_;
  mutable std::vector<Record> infinite_;
};

// One record per cell slot, with the four vertex ids of the cell it was made
// for.  Records of a type still incomplete where the member is declared.
template <class Record>
class User_cells
{
public:
  template <class Anchor>
  Record& at(const Anchor* tr, const Flat_storage& m, Tet_id t) const
  {
    CGAL_precondition(t < m.number_of_slots() && m.is_live(t));
    if(t >= records_.size()) {
      records_.resize(m.number_of_slots());
      cells_.resize(m.number_of_slots(), std::array<Vertex_id, 4>{{ghost_vertex, ghost_vertex, ghost_vertex, ghost_vertex}});
    }
    const Vertex_id* tv = m.vertex_ids(t);
    if(!std::equal(tv, tv + 4, cells_[t].begin())) {
      records_[t] = Record();
      std::copy(tv, tv + 4, cells_[t].begin());
    }
    records_[t].attach_to_triangulation(tr, t);
    return records_[t];
  }

  // As Cell_infos::rename and Cell_infos::lift.
  void rename(const Flat_storage& m, Tet_id t, const Vertex_id* before)
  {
    if(t >= records_.size() || !std::equal(before, before + 4, cells_[t].begin())) return;
    std::copy(m.vertex_ids(t), m.vertex_ids(t) + 4, cells_[t].begin());
  }
  void lift(const Flat_storage& m, const Lifted_cells& lifted)
  {
    for(Tet_id t = 0; t < records_.size(); ++t)
      if(lifted.keeps(t, cells_[t].data())) std::copy(m.vertex_ids(t), m.vertex_ids(t) + 4, cells_[t].begin());
  }

  // Slot t holds a new cell: a default record when next read.
  void forget(Tet_id t)
  {
    if(t < records_.size()) cells_[t] = std::array<Vertex_id, 4>{{ghost_vertex, ghost_vertex, ghost_vertex, ghost_vertex}};
  }

  void clear()
  {
    records_.clear();
    cells_.clear();
  }

private:
  mutable std::vector<Record> records_;
  // Four ghost ids match no cell (a cell has at most one ghost vertex).
  mutable std::vector<std::array<Vertex_id, 4>> cells_;
};

template <>
class User_cells<void>
{
public:
  void rename(const Flat_storage&, Tet_id, const Vertex_id*) {}
  void lift(const Flat_storage&, const Lifted_cells&) {}
  void forget(Tet_id) {}
  void clear() {}
};

template <>
class User_vertices<void>
{
public:
  template <class Anchor>
  void resize(const Anchor*, std::size_t) {}
  template <class Anchor>
  void point_replaced(const Anchor*, Vertex_id) {}
  template <class Anchor>
  void attach(const Anchor*) {}
  void clear() {}
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

// As for Flat_handle (Handles.h): CGAL's Unique_hash_map hashes by index.
namespace CGAL {
namespace internal {
namespace handle {
template <class Tr, class Record, class Index>
struct Hash_functor<CGAL::Fast_Delaunay_triangulation_3_internal::User_handle<Tr, Record, Index>>
{
  std::size_t operator()(const CGAL::Fast_Delaunay_triangulation_3_internal::User_handle<Tr, Record, Index>& h)
  {
    return h ? std::size_t(h.index()) + 1 : 0;
  }
};
} // namespace handle
} // namespace internal
} // namespace CGAL

namespace std {
template <class Tr, class Record, class Index>
struct hash<CGAL::Fast_Delaunay_triangulation_3_internal::User_handle<Tr, Record, Index>>
{
  std::size_t operator()(const CGAL::Fast_Delaunay_triangulation_3_internal::User_handle<Tr, Record, Index>& h) const
  {
    return hash_value(h);
  }
};
} // namespace std

#endif // CGAL_FDT3_INTERNAL_USER_BASES_H
