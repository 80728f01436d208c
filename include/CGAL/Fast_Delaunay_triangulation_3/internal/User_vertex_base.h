// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A user's vertex base with extra members (CGAL manual, "Adding handles" and
// "Color" examples): a class template deriving from
// Triangulation_vertex_base_3 that follows the Rebind_TDS protocol, given in
// the Triangulation_data_structure_3 argument.
//
// The point and the incident cell stay in the flat arrays.  Beside them, one
// object of the user's base, rebound to our handles, is kept per vertex in a
// side array indexed like the vertex infos (vertex id, plus one record for the
// infinite vertex), and v->member reaches it:
//
//   User_vertex<Tr, Base>   derives from the rebound user base; point(),
//                             cell() and info() hide the base's and read the
//                             triangulation (the base's own point and cell
//                             are never written); it knows its triangulation
//                             and vertex id, so the handle is a lookup.
//   User_vertex_handle      (triangulation, vertex id); operator-> is a
//                             mutable User_vertex*, as CGAL's handles give
//                             mutable vertices.
//   Rebinding_tds<Tr>         what Rebind_TDS is given: its Vertex_handle and
//                             Cell_handle are ours, so members of type
//                             Vertex_handle in the user's base hold our handles.
//
// CGAL's own bases (Triangulation_vertex_base_3, with_info) are "plain": they
// get no record, and the handle stays the facade handle of Handles.h.

#ifndef CGAL_FDT3_INTERNAL_USER_VERTEX_BASE_H
#define CGAL_FDT3_INTERNAL_USER_VERTEX_BASE_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Handles.h>

#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_ds_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

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

// Bases whose every member the flat arrays or the info array serve.
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

// The data structure a user's base is rebound to.  Only named while the
// triangulation class is being defined; its members are looked up when the
// user's base is instantiated, once the triangulation is complete.
template <class Tr>
struct Rebinding_tds
{
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Concurrency_tag Concurrency_tag;
};

// The user's base rebound to Rebinding_tds<Tr> (void for a plain base).
template <class Tds, class Tr, bool plain = Is_plain_vertex_base<typename Vertex_base_of<Tds>::type>::value>
struct Rebound_vertex_base { typedef void type; };
template <class Tds, class Tr>
struct Rebound_vertex_base<Tds, Tr, false>
{
  typedef typename Vertex_base_of<Tds>::type::template Rebind_TDS<Rebinding_tds<Tr>>::Other type;
};

template <class Tr, class Base>
class User_vertex : public Base
{
public:
  typedef typename Tr::Point Point;
  typedef typename Tr::Cell_handle Cell_handle;

  Point point() const { return tr_->point_of(id_); }
  Cell_handle cell() const { return tr_->incident_cell_of(id_); }
  // The triangulation owns points and adjacency: a vertex cannot be moved or
  // re-attached through its handle.
  void set_point(const Point&) = delete;
  void set_cell(Cell_handle) = delete;
  template <class T = Tr>
  typename T::Vertex_info& info() const { return tr_->vertex_info(id_); }
  // The base's is_valid would test its own (never written) cell.
  bool is_valid(bool = false, int = 0) const { return tr_ != nullptr; }

  // Nothing else is named here, so that the user's members (an id() of
  // Triangulation_vertex_base_with_id_3, say) stay visible.
  void attach_to_triangulation(const Tr* tr, Vertex_id id)
  {
    tr_ = tr;
    id_ = id;
  }

private:
  const Tr* tr_ = nullptr;
  Vertex_id id_ = 0;
};

template <class Tr, class Record>
class User_vertex_handle : public Handle_order<User_vertex_handle<Tr, Record>>
{
public:
  typedef Record value_type;
  typedef Tr Triangulation;

  User_vertex_handle() = default;
  User_vertex_handle(std::nullptr_t) {}
  User_vertex_handle(const Tr* tr, Vertex_id id) : tr_(tr), id_(id) {}

  Record* operator->() const { return &tr_->user_vertex(id_); }
  Record& operator*() const { return tr_->user_vertex(id_); }
  explicit operator bool() const { return tr_ != nullptr; }

  const Tr* owner() const { return tr_; }
  Vertex_id index() const { return id_; }

private:
  const Tr* tr_ = nullptr;
  Vertex_id id_ = 0;
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
  template <class Tr>
  void resize(const Tr* tr, std::size_t vertices)
  {
    const std::size_t old = records_.size();
    records_.resize(vertices);
    if(infinite_.empty()) infinite_.resize(1);
    for(std::size_t v = old; v < vertices; ++v) records_[v].attach_to_triangulation(tr, static_cast<Vertex_id>(v));
    infinite_.front().attach_to_triangulation(tr, ghost_vertex);
  }

  // After the triangulation was copied, moved or swapped.
  template <class Tr>
  void attach(const Tr* tr)
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

template <>
class User_vertices<void>
{
public:
  template <class Tr>
  void resize(const Tr*, std::size_t) {}
  template <class Tr>
  void attach(const Tr*) {}
  void clear() {}
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

namespace std {
template <class Tr, class Record>
struct hash<CGAL::Fast_Delaunay_triangulation_3_internal::User_vertex_handle<Tr, Record>>
{
  std::size_t operator()(const CGAL::Fast_Delaunay_triangulation_3_internal::User_vertex_handle<Tr, Record>& h) const
  {
    return hash_value(h);
  }
};
} // namespace std

#endif // CGAL_FDT3_INTERNAL_USER_VERTEX_BASE_H
