// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Infos of vertices and cells (CGAL's Triangulation_vertex_base_with_info_3
// and Triangulation_cell_base_with_info_3) kept in side arrays beside the flat
// mesh, so the kernel's records stay the paper's 32-byte vertex and
// fixed-width tetrahedron arrays whatever the user attaches.
//
//   vertex infos: indexed by vertex id (ids never change once a bulk
//                 insertion has returned), plus one for the infinite vertex;
//   cell infos:   indexed by cell slot, each with the four vertex ids of the
//                 cell it was written for.  The kernel reuses slots, so a slot
//                 whose vertices changed holds a new cell: its info is reset
//                 to Info() when next read.  A Delaunay cell destroyed by an
//                 insertion never comes back (it is in conflict with the new
//                 vertex for good), so equal vertex ids mean the same cell;
//                 a removal may bring one back, so it resets the entries of
//                 the slots it fills (forget).
//                 Below dimension 3 CGAL also changes some cells in place
//                 (Lower_dimensional_triangulation::Renamed_cell): their
//                 infos are re-keyed to the new vertex ids.  When one
//                 vertex v lifts dimension 2 to 3, CGAL makes each triangle
//                 (a, b, c) the tetrahedron (a, b, c, v) in place, and so
//                 does the lift here (Lifted_cells).
//
// Without infos (the default data structure) both arrays are empty types
// and insertion takes the plain path: nothing is paid for them.

#ifndef CGAL_FDT3_INTERNAL_VERTEX_AND_CELL_INFOS_H
#define CGAL_FDT3_INTERNAL_VERTEX_AND_CELL_INFOS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <boost/tuple/tuple.hpp>

#include <algorithm>
#include <array>
#include <iterator>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// The Info of the vertex and cell types of a CGAL data structure (rebound by
// the data structure, as CGAL does), or void when they have none or when the
// data structure is Default.
template <class Tds, class = void>
struct Vertex_info_of { typedef void type; };
template <class Tds>
struct Vertex_info_of<Tds, std::void_t<typename Tds::Vertex::Info>> { typedef typename Tds::Vertex::Info type; };

template <class Tds, class = void>
struct Cell_info_of { typedef void type; };
template <class Tds>
struct Cell_info_of<Tds, std::void_t<typename Tds::Cell::Info>> { typedef typename Tds::Cell::Info type; };

// After one vertex v lifted dimension 2 to 3 (cone_over_triangles): each
// triangle (a, b, c) is the tetrahedron (a, b, c, v) in its own slot.
class Lifted_cells
{
public:
  Lifted_cells(const Flat_storage& m, Vertex_id v) : m_(m), v_(v) {}

  // Whether slot t, whose info was kept under the ids `key` (a triangle's:
  // the last one no_vertex), holds the tetrahedron of that triangle.
  bool keeps(Tet_id t, const Vertex_id* key) const
  {
    if(key[3] != no_vertex || t >= m_.number_of_slots() || !m_.is_live(t)) return false;
    const Vertex_id* tv = m_.vertex_ids(t);
    const Vertex_id expected[4] = {key[0], key[1], key[2], v_};
    for(Vertex_id w : expected)
      if(std::find(tv, tv + 4, w) == tv + 4) return false;
    return true;
  }

private:
  const Flat_storage& m_;
  Vertex_id v_;
};

// One info in a vector: a wrapper, so that Info = bool gets real references.
template <class Info>
struct Info_slot
{
  Info value = Info();
};

template <class Info>
class Vertex_infos
{
public:
  // A reference that stays valid until the next insertion.
  Info& at(Vertex_id v) const
  {
    if(v == ghost_vertex) return infinite_.value;
    CGAL_assertion(v < infos_.size());
    return infos_[v].value;
  }

  // After an insertion: one info per vertex, new vertices with Info().
  void resize(std::size_t vertices) { infos_.resize(vertices); }

  // infos[i] goes to vertex_of_input[i], in input order: a vertex given
  // several times (or already present) keeps the last of its infos, as
  // CGAL's insert of a range with infos overwrites on every duplicate.
  void assign(const std::vector<Vertex_id>& vertex_of_input, std::vector<Info>& infos)
  {
    for(std::size_t i = 0; i < infos.size(); ++i) infos_[vertex_of_input[i]].value = std::move(infos[i]);
  }

  void clear()
  {
    infos_.clear();
    infinite_ = Info_slot<Info>();
  }

private:
  mutable std::vector<Info_slot<Info>> infos_;
  mutable Info_slot<Info> infinite_;
};

template <>
class Vertex_infos<void>
{
public:
  void resize(std::size_t) {}
  void clear() {}
};

template <class Info>
class Cell_infos
{
public:
  Info& at(const Flat_storage& m, Tet_id t) const
  {
    CGAL_precondition(t < m.number_of_slots() && m.is_live(t));
    if(t >= entries_.size()) entries_.resize(m.number_of_slots());
    Entry& e = entries_[t];
    const Vertex_id* tv = m.vertex_ids(t);
    if(!std::equal(tv, tv + 4, e.cell)) {
      e.info = Info();
      std::copy(tv, tv + 4, e.cell);
    }
    return e.info;
  }

  // The cell of slot t, which had the vertices `before`, now has those of m.
  void rename(const Flat_storage& m, Tet_id t, const Vertex_id* before)
  {
    if(t >= entries_.size() || !std::equal(before, before + 4, entries_[t].cell)) return;
    std::copy(m.vertex_ids(t), m.vertex_ids(t) + 4, entries_[t].cell);
  }
  // The infos of the triangles stay with their tetrahedra, in their slots.
  void lift(const Flat_storage& m, const Lifted_cells& lifted)
  {
    for(Tet_id t = 0; t < entries_.size(); ++t)
      if(lifted.keeps(t, entries_[t].cell))
        std::copy(m.vertex_ids(t), m.vertex_ids(t) + 4, entries_[t].cell);
  }

  // Slot t holds a new cell: its info is Info() when next read.
  void forget(Tet_id t)
  {
    if(t < entries_.size()) entries_[t] = Entry();
  }

  void clear() { entries_.clear(); }

private:
  struct Entry
  {
    Info info = Info();
    // Four ghost ids match no cell (a cell has at most one ghost vertex).
    Vertex_id cell[4] = {ghost_vertex, ghost_vertex, ghost_vertex, ghost_vertex};
  };
  mutable std::vector<Entry> entries_;
};

template <>
class Cell_infos<void>
{
public:
  void rename(const Flat_storage&, Tet_id, const Vertex_id*) {}
  void lift(const Flat_storage&, const Lifted_cells&) {}
  void forget(Tet_id) {}
  void clear() {}
};

// The point and the info of one element of a range given to insert(): a
// std::pair<Point, Info> (CGAL's insert of pairs), or a tuple (Point, Info) as
// yielded by boost::zip_iterator.
template <class A, class B>
const A& point_part(const std::pair<A, B>& v) { return v.first; }
template <class A, class B>
const B& info_part(const std::pair<A, B>& v) { return v.second; }
template <class H, class T>
const H& point_part(const boost::tuples::cons<H, T>& v) { return boost::get<0>(v); }
template <class H, class T>
const auto& info_part(const boost::tuples::cons<H, T>& v) { return boost::get<1>(v); }
template <class A, class B>
const A& point_part(const std::tuple<A, B>& v) { return std::get<0>(v); }
template <class A, class B>
const B& info_part(const std::tuple<A, B>& v) { return std::get<1>(v); }

// Hands the points of a range of (point, info) elements to add_point and
// keeps their infos, in input order.  Single-pass iterators are read once.
template <class Info, class InputIterator, class Add_point>
void read_points_and_infos(InputIterator first, InputIterator last, std::vector<Info>& infos,
                           const Add_point& add_point)
{
  if(std::is_base_of<std::forward_iterator_tag,
                      typename std::iterator_traits<InputIterator>::iterator_category>::value)
    infos.reserve(static_cast<std::size_t>(std::distance(first, last)));
  for(; first != last; ++first) {
    // By value: transform and zip iterators yield temporaries.
    const auto value = *first;
    add_point(point_part(value));
    infos.push_back(info_part(value));
  }
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_VERTEX_AND_CELL_INFOS_H
