// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triangulations of dimension 0, 1 and 2 (one point, collinear points,
// coplanar points) in the flat arrays, with the cells CGAL's
// Delaunay_triangulation_3 has there.  The paper's engine is 3D only; these
// inputs are a corner case, so while the dimension is below 3 a CGAL
// Delaunay_triangulation_3 of the same vertices is kept beside the flat
// arrays and updated by every insertion.  Its cells are copied into
// Tet_records, vertex order and neighbours included, so handles and
// iterators read them like tetrahedra, and the queries that CGAL defines
// below dimension 3 (point location, side_of_*, incident and adjacent
// elements, conflict zones) are answered by that triangulation, handles
// mapped both ways: a CGAL cell knows its slot (cell info), a slot its CGAL
// cell, a CGAL vertex its id (vertex info), an id its CGAL vertex.
//
//   dimension -1: 1 cell (infinite), no neighbour: even the empty
//                 triangulation has its infinite cell;
//   dimension 0:  2 cells (v) and (infinite), neighbours of each other;
//   dimension 1:  segments (v0, v1); neighbour i is opposite vertex i; the
//                 n - 1 finite segments and 2 infinite ones form a cycle in
//                 which neighbor(0)->vertex(0) == vertex(1);
//   dimension 2:  triangles (v0, v1, v2), consistently oriented (the shared
//                 edge runs the other way in the neighbour), finite ones and
//                 one infinite triangle per hull edge: 2n - 2 in all.
//
// Slots above the dimension (above 0 in dimension -1) hold `no_vertex` and
// a neighbour code pointing back at the cell itself (never followed: handles
// answer null there).  The infinite vertex may sit in any slot of a
// lower-dimensional cell, as in CGAL, so Flat_storage::is_ghost (slot 3) is
// meaningless below dimension 3; `ghost_tets` still counts the cells that
// have it.  Nothing here runs in dimension 3: lifting to 3D drops the CGAL
// triangulation; from dimension 2 the triangles become tetrahedra in their
// slots (cone_over_triangles), from below the arrays are built anew
// (Triangulation_core::lift_to_dimension_3).

#ifndef CGAL_FDT3_INTERNAL_LOWER_DIMENSIONS_H
#define CGAL_FDT3_INTERNAL_LOWER_DIMENSIONS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>
#include <CGAL/iterator.h>

#include <algorithm>
#include <iterator>
#include <limits>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

namespace lower_dimensions_detail {
typedef Exact_predicates_inexact_constructions_kernel Epick;
// The slot a CGAL cell is copied to.  Cells that CGAL creates start without
// one (a default member initialiser: CGAL's info base leaves a plain integer
// uninitialised), which is how the copy tells new cells from old ones.
struct Slot
{
  static constexpr Tet_id none = std::numeric_limits<Tet_id>::max();
  Tet_id id = none;
};
typedef Triangulation_vertex_base_with_info_3<Vertex_id, Epick> Vb;
typedef Triangulation_cell_base_with_info_3<Slot, Epick, Delaunay_triangulation_cell_base_3<Epick>> Cb;
typedef Delaunay_triangulation_3<Epick, Triangulation_data_structure_3<Vb, Cb>> Reference_delaunay;

inline bool has_vertex(const Tet_record& r, int dimension, Vertex_id v)
{
  return std::find(r.v, r.v + dimension + 1, v) != r.v + dimension + 1;
}
} // namespace lower_dimensions_detail

// The CGAL triangulation of the vertices while they span less than 3D, and
// the copy of its cells in the flat arrays.  Value semantics: a copy copies
// CGAL's triangulation (infos included) and re-indexes the handles.
class Lower_dimensional_triangulation
{
public:
  typedef lower_dimensions_detail::Reference_delaunay Delaunay;
  typedef Delaunay::Cell_handle Reference_cell;
  typedef Delaunay::Vertex_handle Reference_vertex;
  typedef Delaunay::Locate_type Locate_type;
  typedef lower_dimensions_detail::Epick::Point_3 Reference_point;

  // A cell that CGAL changed in place, keeping the cell: dimension 1 splits a
  // segment by moving one of its ends, a change of dimension extends every
  // cell.  Infos and user records are keyed by the vertex ids of their cell
  // (Vertex_and_cell_infos.h), so these tell them to follow.
  struct Renamed_cell
  {
    Tet_id slot;
    Vertex_id before[4];
  };

  // Where a point is, as CGAL's locate() says it.
  struct Location
  {
    Locate_type type = Delaunay::OUTSIDE_AFFINE_HULL;
    Reference_cell cell;
    int li = 0, lj = 0;
  };

  Lower_dimensional_triangulation() = default;
  Lower_dimensional_triangulation(const Lower_dimensional_triangulation& other)
  {
    if(!other.active()) return;
    delaunay_.reset(new Delaunay(*other.delaunay_));
    index_handles();
  }
  Lower_dimensional_triangulation& operator=(const Lower_dimensional_triangulation& other)
  {
    if(this != &other) {
      Lower_dimensional_triangulation copy(other);
      *this = std::move(copy);
    }
    return *this;
  }
  // Moving keeps CGAL's cells where they are: the handles stay valid.
  Lower_dimensional_triangulation(Lower_dimensional_triangulation&&) noexcept = default;
  Lower_dimensional_triangulation& operator=(Lower_dimensional_triangulation&&) noexcept = default;

  bool active() const { return delaunay_ != nullptr; }
  // An empty triangulation, and its one cell copied into m, which holds no
  // cell yet.
  void start(Flat_storage& m)
  {
    CGAL_precondition(m.live_tets == 0);
    delaunay_.reset(new Delaunay);
    delaunay_->infinite_vertex()->info() = ghost_vertex;
    cells_.clear();
    vertices_.clear();
    renamed_.clear();
    fresh_.clear();
    synchronise(m);
  }
  void stop()
  {
    delaunay_.reset();
    std::vector<Renamed_cell>().swap(renamed_);
    std::vector<Tet_id>().swap(fresh_);
    std::vector<Reference_cell>().swap(cells_);
    std::vector<Reference_vertex>().swap(vertices_);
  }

  const Delaunay& delaunay() const { return *delaunay_; }
  // The cells changed in place since the last call, oldest first.
  std::vector<Renamed_cell> take_renamed_cells()
  {
    std::vector<Renamed_cell> renamed;
    renamed.swap(renamed_);
    return renamed;
  }
  Reference_cell cell(Tet_id slot) const { return cells_[slot]; }
  static Tet_id slot(Reference_cell c) { return c->info().id; }
  Reference_vertex vertex(Vertex_id v) const
  {
    return v == ghost_vertex ? delaunay_->infinite_vertex() : vertices_[v];
  }
  static Vertex_id id(Reference_vertex v) { return v->info(); }
  static Reference_point point(const Flat_storage& m, Vertex_id v)
  {
    const double* p = m.point(v);
    return Reference_point(p[0], p[1], p[2]);
  }

  Location locate(const Reference_point& p, Reference_cell start) const
  {
    Location where;
    where.cell = delaunay_->locate(p, where.type, where.li, where.lj, start);
    return where;
  }

  // locate(p, start) for an insertion of p, which is in the plane of the
  // triangles in dimension 2: a visibility walk over CGAL's triangles with
  // the filtered coplanar orientation.  A point strictly inside a finite
  // triangle gets that triangle (FACET, li = 3), CGAL's only answer there;
  // a point on an edge or a vertex, or outside the hull, gets CGAL's answer
  // from the triangle reached.  CGAL's locate() first asks, exactly, whether
  // p is off the plane: for points in the plane that is an exact evaluation
  // of a zero every time, a third of the insertion of 1e5 coplanar points.
  Location locate_in_plane(const Reference_point& p, Reference_cell start) const
  {
    if(delaunay_->dimension() != 2) return locate(p, start);
    const Reference_vertex infinite = delaunay_->infinite_vertex();
    Reference_cell c = start == Reference_cell() ? infinite->cell() : start;
    if(c->has_vertex(infinite)) c = c->neighbor(c->index(infinite));
    const double q[3] = {p.x(), p.y(), p.z()};
    double corner[3][3];
    auto load = [&](Reference_cell cell) {
      for(int i = 0; i < 3; ++i) {
        const Reference_point& w = cell->vertex(i)->point();
        corner[i][0] = w.x();
        corner[i][1] = w.y();
        corner[i][2] = w.z();
      }
    };
    load(c);
    // Finite triangles are consistently oriented: one sign for all.
    const int inward = coplanar_orientation(corner[0], corner[1], corner[2]);
    // A visibility walk ends on a Delaunay triangulation; the bound only
    // guards against a broken one (2n - 2 triangles in all).
    for(std::size_t steps = 0; steps <= 2 * delaunay_->number_of_vertices(); ++steps) {
      bool on_a_line = false;
      int exit = -1;
      for(int i = 0; i < 3 && exit < 0; ++i) {
        const int side = coplanar_orientation(corner[(i + 1) % 3], corner[(i + 2) % 3], q);
        if(side == -inward) exit = i;
        on_a_line = on_a_line || side == 0;
      }
      if(exit < 0) {
        if(on_a_line) break;
        Location where;
        where.type = Delaunay::FACET;
        where.cell = c;
        where.li = 3;
        return where;
      }
      const Reference_cell next = c->neighbor(exit);
      if(next->has_vertex(infinite)) break;
      c = next;
      load(c);
    }
    return locate(p, c);
  }

  // Vertex v of m (record written, id final: the next id) inserted as
  // CGAL's insert(p, start).  Returns v, or the older vertex at the same
  // point (then nothing changed and the caller drops v's record).  The point
  // must not lift the dimension to 3.  `around` receives the slots of the
  // cells of the returned vertex in the order of CGAL's
  // insert_and_give_new_cells.
  Vertex_id insert(Flat_storage& m, Vertex_id v, Reference_cell start, std::vector<Tet_id>* around)
  {
    return insert(m, v, locate_in_plane(point(m, v), start), around);
  }
  // As CGAL's insert(p, lt, c, li, lj), `where` being locate(p)'s answer.
  Vertex_id insert(Flat_storage& m, Vertex_id v, const Location& where, std::vector<Tet_id>* around)
  {
    const Reference_point p = point(m, v);
    fresh_.clear();
    const int dimension_before = delaunay_->dimension();
    const std::size_t vertices_before = delaunay_->number_of_vertices();
    // In dimension 2 CGAL replaces the cells in conflict with p; below, it
    // splits a segment in place (the segment keeps its slot) or raises the
    // dimension (every cell is re-copied).
    std::vector<Reference_cell> deleted;
    Reference_vertex r;
    if(dimension_before == 2 && where.type != Delaunay::VERTEX && where.type != Delaunay::OUTSIDE_AFFINE_HULL) {
      // CGAL's insert(p, ...) there is find_conflicts and insert_in_hole:
      // called apart, the conflict zone is searched once, not twice.
      Delaunay::Facet boundary_edge;
      delaunay_->find_conflicts(p, where.cell, Oneset_iterator<Delaunay::Facet>(boundary_edge),
                                std::back_inserter(deleted));
      r = delaunay_->insert_in_hole(p, deleted.begin(), deleted.end(), boundary_edge.first, boundary_edge.second);
    } else {
      r = delaunay_->insert(p, where.type, where.cell, where.li, where.lj);
    }
    if(delaunay_->number_of_vertices() != vertices_before) {
      set_vertex(v, r);
      if(delaunay_->dimension() != dimension_before) synchronise(m);
      else copy_new_cells(m, deleted, r);
    }
    if(around) slots_around(r, *around);
    return id(r);
  }

  // Many vertices at once (a range insertion that stays below 3D): each as
  // insert() inserts it, but the cells are copied into m once, by
  // synchronise() after the last one, instead of after every point (which
  // cost as much as CGAL's own insertion).  Until then m's cells are out of
  // date: nothing but insert_unsynchronised and synchronise may follow.
  Vertex_id insert_unsynchronised(const Flat_storage& m, Vertex_id v, Reference_cell start)
  {
    const Reference_point p = point(m, v);
    const Location where = locate_in_plane(p, start);
    const std::size_t vertices_before = delaunay_->number_of_vertices();
    Reference_vertex r;
    if(delaunay_->dimension() == 2 && where.type != Delaunay::VERTEX &&
       where.type != Delaunay::OUTSIDE_AFFINE_HULL) {
      Delaunay::Facet boundary_edge;
      conflicts_.clear();
      delaunay_->find_conflicts(p, where.cell, Oneset_iterator<Delaunay::Facet>(boundary_edge),
                                std::back_inserter(conflicts_));
      r = delaunay_->insert_in_hole(p, conflicts_.begin(), conflicts_.end(), boundary_edge.first,
                                    boundary_edge.second);
    } else {
      r = delaunay_->insert(p, where.type, where.cell, where.li, where.lj);
    }
    if(delaunay_->number_of_vertices() != vertices_before) set_vertex(v, r);
    return id(r);
  }
  // Every cell copied again: after insert_unsynchronised calls, a change
  // of dimension, a removal.  A CGAL cell whose slot still names it keeps it
  // (and its cell info: CGAL changes a segment in place in dimension 1, a
  // change of dimension extends every cell), slots no cell keeps are freed,
  // new cells take free slots, each cell is copied once.
  void synchronise(Flat_storage& m)
  {
    fresh_.clear();
    std::vector<char> kept(m.number_of_slots(), 0);
    std::vector<Reference_cell> made;
    for(auto c = delaunay_->tds().raw_cells_begin(); c != delaunay_->tds().raw_cells_end(); ++c) {
      const Tet_id t = slot(c);
      if(t < cells_.size() && cells_[t] == Reference_cell(c) && m.is_live(t)) kept[t] = 1;
      else made.push_back(c);
    }
    std::vector<Renamed_cell> before;
    for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t)) continue;
      if(!kept[t]) {
        free_slot(m, t);
        continue;
      }
      before.push_back(Renamed_cell{t, {}});
      std::copy(m.tets[t].v, m.tets[t].v + 4, before.back().before);
    }
    if(made.size() > m.free_tets.size()) m.reserve_tets(made.size() - m.free_tets.size());
    cells_.reserve(m.number_of_slots() + made.size());
    for(Reference_cell c : made) take_new_slot(m, c);
    for(auto c = delaunay_->tds().raw_cells_begin(); c != delaunay_->tds().raw_cells_end(); ++c) copy_cell(m, c);
    for(const Renamed_cell& r : before)
      if(!std::equal(r.before, r.before + 4, m.tets[r.slot].v)) renamed_.push_back(r);
  }

  // CGAL's insert_in_hole in dimension 2: the cells of `hole` (slots),
  // forming a hole star-shaped from the point of v, replaced by v joined to
  // the hole's boundary edges; (begin, i) is a boundary edge of the hole.
  void insert_in_hole(Flat_storage& m, Vertex_id v, const std::vector<Tet_id>& hole, Tet_id begin, int i,
                      std::vector<Tet_id>* around)
  {
    CGAL_precondition(delaunay_->dimension() == 2);
    std::vector<Reference_cell> deleted;
    for(Tet_id t : hole) deleted.push_back(cells_[t]);
    const Reference_vertex r =
        delaunay_->insert_in_hole(point(m, v), deleted.begin(), deleted.end(), cells_[begin], i);
    set_vertex(v, r);
    copy_new_cells(m, deleted, r);
    if(around) slots_around(r, *around);
  }

  // CGAL's remove(v): its cells are copied again (the others keep their
  // slots); `fresh` receives the slots of the cells CGAL made.  m's record
  // of v is left to the caller.
  void remove(Flat_storage& m, Vertex_id v, std::vector<Tet_id>& fresh)
  {
    CGAL_precondition(v < vertices_.size() && vertices_[v] != Reference_vertex());
    fresh_.clear();
    delaunay_->remove(vertices_[v]);
    vertices_[v] = Reference_vertex();
    synchronise(m);
    take_fresh_slots(fresh);
  }
  // The slots given to new CGAL cells by the last insertion, removal or rebuild.
  void take_fresh_slots(std::vector<Tet_id>& fresh)
  {
    fresh.clear();
    fresh.swap(fresh_);
  }

  // The triangulation of the live vertices of m, which are distinct and span
  // less than 3D (a file read by Triangulation_io.h, or what a removal
  // leaves of a 3D triangulation), in the order of their ids.
  void rebuild(Flat_storage& m)
  {
    m.tets.clear();
    m.free_tets.clear();
    m.tet_sub_determinants.clear();
    m.live_tets = m.ghost_tets = 0;
    start(m);
    Reference_cell hint;
    for(Vertex_id v = 0; v < m.vertices.size(); ++v) {
      if(m.is_dead(v)) continue;
      const Vertex_id inserted = insert(m, v, hint, nullptr);
      CGAL_assertion(inserted == v);
      hint = vertex(inserted)->cell();
    }
  }

  // Whether the flat arrays hold exactly CGAL's cells: one live slot per
  // CGAL cell, naming it back, with its vertices and neighbours, and the
  // vertex ids of CGAL's vertices.  Writes the first difference to `why`.
  bool is_copied_into(const Flat_storage& m, std::string* why) const
  {
    auto fail = [why](const std::string& message) {
      if(why) *why = message;
      return false;
    };
    if(!active()) return fail("no CGAL triangulation below dimension 3");
    if(vertices_.size() > m.vertices.size() || delaunay_->number_of_vertices() != m.live_vertices())
      return fail("CGAL's triangulation has another number of vertices");
    for(Vertex_id v = 0; v < m.vertices.size(); ++v) {
      const bool in_cgal = v < vertices_.size() && vertices_[v] != Reference_vertex();
      if(m.is_dead(v)) {
        if(in_cgal) return fail("removed vertex " + std::to_string(v) + " is in CGAL's triangulation");
        continue;
      }
      if(!in_cgal) return fail("vertex " + std::to_string(v) + " is not in CGAL's triangulation");
      const double* p = m.point(v);
      if(id(vertices_[v]) != v || vertices_[v]->point() != Reference_point(p[0], p[1], p[2]))
        return fail("vertex " + std::to_string(v) + " is not CGAL's vertex of that id");
    }
    const int dimension = delaunay_->dimension();
    std::size_t cells = 0;
    for(auto c = delaunay_->tds().raw_cells_begin(); c != delaunay_->tds().raw_cells_end(); ++c, ++cells) {
      const Tet_id t = slot(c);
      const std::string at = "slot " + std::to_string(t) + ": ";
      if(t >= m.number_of_slots() || !m.is_live(t) || t >= cells_.size() || cells_[t] != Reference_cell(c))
        return fail("a CGAL cell has no live slot naming it");
      for(int i = 0; i <= std::max(dimension, 0); ++i)
        if(m.vertex(t, i) != id(c->vertex(i))) return fail(at + "not CGAL's vertex " + std::to_string(i));
      for(int i = 0; i <= dimension; ++i) {
        const Reference_cell n = c->neighbor(i);
        if(m.neighbor_code(t, i) != facet_code(slot(n), n->index(c)))
          return fail(at + "not CGAL's neighbour " + std::to_string(i));
      }
    }
    return cells == m.live_tets ? true : fail("live slots that are no CGAL cell");
  }

private:
  // Handles of a copied triangulation, from its infos.
  void index_handles()
  {
    cells_.clear();
    vertices_.clear();
    for(auto v = delaunay_->finite_vertices_begin(); v != delaunay_->finite_vertices_end(); ++v) set_vertex(v->info(), v);
    for(auto c = delaunay_->tds().raw_cells_begin(); c != delaunay_->tds().raw_cells_end(); ++c) {
      if(c->info().id >= cells_.size()) cells_.resize(c->info().id + 1);
      cells_[c->info().id] = c;
    }
  }

  // Ids of removed vertices have no CGAL vertex: vertices_ has null handles.
  void set_vertex(Vertex_id v, Reference_vertex r)
  {
    r->info() = v;
    if(v >= vertices_.size()) vertices_.resize(v + 1, Reference_vertex());
    vertices_[v] = r;
  }

  // The cells of r in CGAL's order of insert_and_give_new_cells.
  void cells_around(Reference_vertex r, std::vector<Reference_cell>& cells) const
  {
    cells.clear();
    const Reference_cell first = r->cell();
    switch(delaunay_->dimension()) {
    case 2:
      for(Reference_cell c = first;;) {
        cells.push_back(c);
        c = c->neighbor((c->index(r) + 1) % 3);
        if(c == first) break;
      }
      break;
    case 1:
      cells.push_back(first);
      cells.push_back(first->neighbor(1 - first->index(r)));
      break;
    default: cells.push_back(first);
    }
  }
  void slots_around(Reference_vertex r, std::vector<Tet_id>& slots) const
  {
    std::vector<Reference_cell> cells;
    cells_around(r, cells);
    slots.clear();
    for(Reference_cell c : cells) slots.push_back(slot(c));
  }

  // After an insertion in the same dimension: the cells of the new vertex r
  // are new or changed in place, those of `deleted` gone; the neighbours of
  // r's cells changed their neighbour fields.
  void copy_new_cells(Flat_storage& m, const std::vector<Reference_cell>& deleted, Reference_vertex r)
  {
    std::vector<Reference_cell> changed;
    cells_around(r, changed);
    std::vector<Tet_id> freed;
    for(Reference_cell c : deleted) freed.push_back(slot(c));
    resynchronise(m, freed, changed);
  }
  // `changed`: the CGAL cells to copy again (new or modified); `released`:
  // slots whose cells may be gone.  A cell keeps its slot while the slot
  // still names it (so its cell info survives, as in CGAL); the released
  // slots that no changed cell keeps are freed, and new cells take free slots.
  void resynchronise(Flat_storage& m, std::vector<Tet_id>& released, const std::vector<Reference_cell>& changed)
  {
    std::vector<Tet_id> kept;
    std::vector<Reference_cell> fresh;
    for(Reference_cell c : changed) {
      const Tet_id t = slot(c);
      if(t < cells_.size() && cells_[t] == c) kept.push_back(t);
      else fresh.push_back(c);
    }
    std::sort(kept.begin(), kept.end());
    for(Tet_id t : released)
      if(!std::binary_search(kept.begin(), kept.end(), t)) free_slot(m, t);
    for(Reference_cell c : fresh) take_new_slot(m, c);
    std::vector<Renamed_cell> before;
    for(Tet_id t : kept) {
      before.push_back(Renamed_cell{t, {}});
      std::copy(m.tets[t].v, m.tets[t].v + 4, before.back().before);
    }
    const int dimension = delaunay_->dimension();
    for(Reference_cell c : changed) {
      copy_cell(m, c);
      for(int i = 0; i <= dimension; ++i) copy_cell(m, c->neighbor(i));
    }
    for(const Renamed_cell& r : before)
      if(!std::equal(r.before, r.before + 4, m.tets[r.slot].v)) renamed_.push_back(r);
  }

  // A slot for a cell CGAL made; copy_cell fills it.
  void take_new_slot(Flat_storage& m, Reference_cell c)
  {
    const Tet_id t = m.new_tet();
    Tet_record& r = m.tets[t];
    std::fill(r.v, r.v + 4, no_vertex);
    ++m.live_tets;
    c->info().id = t;
    if(t >= cells_.size()) cells_.resize(t + 1);
    cells_[t] = c;
    fresh_.push_back(t);
  }

  void free_slot(Flat_storage& m, Tet_id t)
  {
    if(lower_dimensions_detail::has_vertex(m.tets[t], 3, ghost_vertex)) --m.ghost_tets;
    --m.live_tets;
    m.mark_free(t);
    m.free_tets.push_back(t);
    cells_[t] = Reference_cell();
  }

  void copy_cell(Flat_storage& m, Reference_cell c) const
  {
    using lower_dimensions_detail::has_vertex;
    const Tet_id t = slot(c);
    Tet_record& r = m.tets[t];
    if(has_vertex(r, 3, ghost_vertex)) --m.ghost_tets;
    const int dimension = delaunay_->dimension();
    for(int i = 0; i < 4; ++i) {
      // The cell of dimension -1 has its vertex 0 (the infinite vertex) and no neighbour.
      r.v[i] = i <= std::max(dimension, 0) ? id(c->vertex(i)) : no_vertex;
      if(i > dimension) {
        r.n[i] = facet_code(t, i);
        continue;
      }
      const Reference_cell n = c->neighbor(i);
      r.n[i] = facet_code(slot(n), n->index(c));
    }
    if(has_vertex(r, 3, ghost_vertex)) ++m.ghost_tets;
  }

  std::unique_ptr<Delaunay> delaunay_;
  std::vector<Reference_cell> cells_;      // by slot; null for a free slot
  std::vector<Reference_vertex> vertices_; // by vertex id
  std::vector<Renamed_cell> renamed_;
  std::vector<Tet_id> fresh_;              // slots of new cells, see take_fresh_slots
  std::vector<Reference_cell> conflicts_;  // insert_unsynchronised's scratch
};

// Checks the cells of a triangulation of dimension -1 to 2: CGAL's
// combinatorial conventions (counts, adjacency, orientation of neighbours,
// connectivity) and, exactly, the geometry: collinear vertices in order along
// the line; coplanar vertices, consistently oriented non-degenerate finite
// triangles, a locally convex hull and the perturbed local Delaunay property.
inline bool lower_dimensional_cells_are_valid(const Flat_storage& m, int dimension, std::string* why)
{
  using namespace lower_dimensions_detail;
  auto fail = [why](const std::string& message) {
    if(why) *why = message;
    return false;
  };
  const std::size_t n = m.live_vertices();
  std::vector<Vertex_id> live_ids; // the ids of the live vertices
  for(Vertex_id v = 0; v < m.vertices.size(); ++v)
    if(!m.is_dead(v)) live_ids.push_back(v);
  if(dimension == -1) {
    if(n != 0 || m.live_tets != 1 || m.ghost_tets != 1) return fail("vertices or cells in dimension -1");
    const Tet_id t = m.first_live_tet();
    for(int i = 0; i < 4; ++i)
      if(m.vertex(t, i) != (i == 0 ? ghost_vertex : no_vertex))
        return fail("the cell of dimension -1 holds other than the infinite vertex");
    return true;
  }
  const std::size_t expected_cells = dimension == 0 ? 2 : dimension == 1 ? n + 1 : 2 * n - 2;
  if(m.live_tets != expected_cells) return fail("wrong number of cells for dimension " + std::to_string(dimension));

  std::size_t live = 0, ghosts = 0;
  std::vector<char> used(m.vertices.size(), 0);
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t)) continue;
    ++live;
    const Tet_record& r = m.tets[t];
    const std::string at = "cell " + std::to_string(t) + ": ";
    for(int i = 0; i < 4; ++i) {
      const Vertex_id v = r.v[i];
      if(i > dimension) {
        if(v != no_vertex) return fail(at + "vertex slot above the dimension is used");
        continue;
      }
      if(v != ghost_vertex && (v >= m.vertices.size() || m.is_dead(v))) return fail(at + "vertex id out of range");
      if(v != ghost_vertex) used[v] = 1;
      for(int j = 0; j < i; ++j)
        if(r.v[j] == v) return fail(at + "repeated vertex");
    }
    if(has_vertex(r, dimension, ghost_vertex)) ++ghosts;
    for(int i = 0; i <= dimension; ++i) {
      const Facet_code code = r.n[i];
      const Tet_id u = tet_of(code);
      const int j = facet_of(code);
      if(u >= m.number_of_slots() || !m.is_live(u) || j > dimension)
        return fail(at + "neighbour is not a live cell");
      if(m.neighbor_code(code) != facet_code(t, i)) return fail(at + "asymmetric adjacency");
      for(int k = 0; k <= dimension; ++k)
        if(k != i && !has_vertex(m.tets[u], dimension, r.v[k])) return fail(at + "neighbours do not share a face");
      // CGAL's orientation of neighbours (Triangulation_data_structure_3::is_valid).
      if(dimension == 1 && j != 1 - i) return fail(at + "segments not chained head to tail");
      if(dimension == 2 && r.v[(i + 1) % 3] != m.vertex(u, (j + 2) % 3))
        return fail(at + "neighbouring triangles not consistently oriented");
    }
  }
  if(live != m.live_tets || ghosts != m.ghost_tets) return fail("cell counts out of date");
  for(Vertex_id v : live_ids)
    if(!used[v]) return fail("vertex " + std::to_string(v) + " is in no cell");

  // One connected cycle / sphere.
  std::vector<char> reached(m.number_of_slots(), 0);
  std::vector<Tet_id> stack(1, m.first_live_tet());
  reached[stack[0]] = 1;
  std::size_t reached_count = 1;
  while(!stack.empty()) {
    const Tet_id t = stack.back();
    stack.pop_back();
    for(int i = 0; i <= dimension; ++i) {
      const Tet_id u = m.neighbor(t, i);
      if(!reached[u]) { reached[u] = 1; ++reached_count; stack.push_back(u); }
    }
  }
  if(reached_count != live) return fail("cells are not connected");

  const Epick k;
  auto point = [&m, &k](Vertex_id v) {
    const double* p = m.point(v);
    return Epick::Point_3(p[0], p[1], p[2]);
  };
  if(dimension == 0) return ghosts == 1 ? true : fail("dimension 0 needs one infinite cell");
  if(dimension == 1) {
    if(ghosts != 2) return fail("dimension 1 needs two infinite segments");
    for(std::size_t i = 2; i < n; ++i)
      if(!k.collinear_3_object()(point(live_ids[0]), point(live_ids[1]), point(live_ids[i])))
        return fail("vertices of dimension 1 not collinear");
    for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t)) continue;
      const Vertex_id a = m.vertex(t, 0), b = m.vertex(t, 1), c = m.vertex(m.neighbor(t, 0), 1);
      if(a == ghost_vertex || b == ghost_vertex || c == ghost_vertex) continue;
      if(!k.collinear_are_strictly_ordered_along_line_3_object()(point(a), point(b), point(c)))
        return fail("segments " + std::to_string(t) + " and its neighbour overlap");
    }
    return true;
  }

  // Dimension 2: the orientation of the first finite triangle is the reference.
  Tet_id first = 0;
  while(!m.is_live(first) || has_vertex(m.tets[first], 2, ghost_vertex)) ++first;
  const double* ref[3] = {m.point(m.vertex(first, 0)), m.point(m.vertex(first, 1)), m.point(m.vertex(first, 2))};
  const int reference_orientation = predicates_detail::coplanar_orientation_exact(ref[0], ref[1], ref[2]);
  if(reference_orientation == 0) return fail("flat finite triangle");
  for(Vertex_id v : live_ids)
    if(orientation(ref[0], ref[1], ref[2], m.point(v)) != 0) return fail("vertices of dimension 2 not coplanar");
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t)) continue;
    const std::string at = "triangle " + std::to_string(t) + ": ";
    const Tet_record& r = m.tets[t];
    const int g = static_cast<int>(std::find(r.v, r.v + 3, ghost_vertex) - r.v);
    if(g < 3) {
      // Hull edge (a, b); w beyond it inside, r the next hull vertex after b.
      const Vertex_id a = r.v[(g + 1) % 3], b = r.v[(g + 2) % 3];
      const Facet_code inside = r.n[g];
      const Vertex_id w = m.vertex(tet_of(inside), facet_of(inside));
      const Facet_code next = r.n[(g + 1) % 3];
      const Vertex_id after = m.vertex(tet_of(next), facet_of(next));
      if(w == ghost_vertex || after == ghost_vertex) return fail(at + "infinite triangle next to an infinite edge");
      if(predicates_detail::coplanar_orientation_exact(m.point(a), m.point(b), m.point(w), m.point(after)) < 0)
        return fail(at + "hull not convex");
      continue;
    }
    const double* p[3] = {m.point(r.v[0]), m.point(r.v[1]), m.point(r.v[2])};
    if(predicates_detail::coplanar_orientation_exact(p[0], p[1], p[2]) != reference_orientation)
      return fail(at + "not oriented as the other finite triangles");
    for(int i = 0; i < 3; ++i) {
      const Vertex_id opposite = m.vertex(tet_of(r.n[i]), facet_of(r.n[i]));
      if(opposite == ghost_vertex) continue;
      if(perturbed_coplanar_side_of_bounded_circle(p[0], p[1], p[2], m.point(opposite)) > 0)
        return fail(at + "not locally Delaunay across edge " + std::to_string(i));
    }
  }
  return true;
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_LOWER_DIMENSIONS_H
