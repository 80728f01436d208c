// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The data of one triangulation (flat arrays, infos, user records, the
// traits), kept on the heap and owned through a pointer by the triangulation
// layer (Flat_triangulation_3.h).  Handles and iterators point here, not at
// the triangulation object: swap() and the moves exchange the pointer, so a
// handle keeps designating its vertex or cell wherever the data goes, as
// CGAL's handles (pointers into the data structure, which swap and move hand
// over) do.  The anchor never moves while it lives, and `c->vertex(i)` reads
// anchor->core.mesh with the loads a pointer to the triangulation would need.
//
// Everything a handle dereference needs is answered here, without the
// public object (which may have been swapped away from this data).

#ifndef CGAL_FDT3_INTERNAL_STORAGE_ANCHOR_H
#define CGAL_FDT3_INTERNAL_STORAGE_ANCHOR_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_tds.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_points.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Lower_dimensions.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_core.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/User_bases.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_and_cell_infos.h>

#include <algorithm>
#include <cstddef>
#include <stdexcept>
#include <type_traits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

template <class Tr>
class Storage_anchor
{
public:
  typedef typename Tr::Geom_traits Geom_traits;
  typedef typename Tr::Point Point;
  typedef typename Tr::Vertex_handle Vertex_handle;
  typedef typename Tr::Cell_handle Cell_handle;
  typedef typename Tr::Vertex_info Vertex_info;
  typedef typename Tr::Cell_info Cell_info;
  typedef typename Tr::Vertex Vertex;
  typedef typename Tr::Cell Cell;

  // The kernel's points are kept per vertex when its FT is not double
  // (Kernel_points.h); otherwise they are the vertex records.
  static constexpr bool keeps_kernel_points = !std::is_same<typename Geom_traits::FT, double>::value;

  explicit Storage_anchor(const Geom_traits& gt) : traits(gt), tds(this) {}
  // User vertex records know the anchor they belong to: a copy's records
  // must name the copy.
  Storage_anchor(const Storage_anchor& other)
      : traits(other.traits), core(other.core), incident_cells(other.incident_cells),
        kernel_points(other.kernel_points), vertex_infos(other.vertex_infos), cell_infos(other.cell_infos),
        user_vertices(other.user_vertices), user_cells(other.user_cells), tds(this, other.tds),
        dimension_seen_(other.dimension_seen_),
        vertices_seen_(other.vertices_seen_)
  {
    user_vertices.attach(this);
  }
  Storage_anchor& operator=(const Storage_anchor&) = delete;

  void clear()
  {
    core.clear();
    incident_cells.clear();
    kernel_points.clear();
    vertex_infos.clear();
    cell_infos.clear();
    user_vertices.clear();
    user_cells.clear();
    tds.forget_created();
    dimension_seen_ = -1;
    vertices_seen_ = 0;
  }

  Geom_traits traits;
  Triangulation_core core;
  mutable std::vector<Tet_id> incident_cells; // lazily built v->cell() cache (dimension 3)
  mutable std::size_t walks_without_incident_cells = 0; // removals that located their vertex instead
  std::vector<Tet_id> made_cells; // the new cells of a removal or a move, kept from one to the next
  Kernel_points<Point, keeps_kernel_points> kernel_points;
  Vertex_infos<Vertex_info> vertex_infos;
  Cell_infos<Cell_info> cell_infos;
  User_vertices<typename Tr::User_vertex_record> user_vertices;
  User_cells<typename Tr::User_cell_record> user_cells;
  Flat_tds<Storage_anchor, typename Tr::Tds_types> tds; // what the triangulation's tds() returns

  // After an insertion: new vertices get Info() and a default user vertex
  // base; cells CGAL changed in place below dimension 3 keep theirs, and so
  // do the triangles that one new vertex lifts to tetrahedra.  (When several
  // new vertices lift the dimension, which cells CGAL keeps depends on its
  // insertion order: all get Info().)
  // `inserted`, `vertex_of_input`: the user's points of a range and their
  // vertices, kept as the new vertices' kernel points (Kernel_points.h).
  void vertices_added(const std::vector<Point>* inserted = nullptr,
                      const std::vector<Vertex_id>* vertex_of_input = nullptr)
  {
    const std::size_t n = core.vertex_slots();
    kernel_points.resize(core.mesh, inserted, vertex_of_input);
    vertex_infos.resize(n);
    user_vertices.resize(this, n);
    if(core.lower.active()) {
      for(const auto& r : core.lower.take_renamed_cells()) {
        cell_infos.rename(core.mesh, r.slot, r.before);
        user_cells.rename(core.mesh, r.slot, r.before);
      }
    } else if(dimension_seen_ == 2 && dimension() == 3 && n == vertices_seen_ + 1) {
      const Lifted_cells lifted(core.mesh, static_cast<Vertex_id>(n - 1));
      cell_infos.lift(core.mesh, lifted);
      user_cells.lift(core.mesh, lifted);
    }
    dimension_seen_ = dimension();
    vertices_seen_ = n;
  }

  // After a removal or a move: `made` are the slots of the new cells, whose
  // infos and user records start afresh (a slot may come back to a cell with
  // the vertices it had before the vertex was inserted: the vertex ids alone
  // no longer tell).  The v->cell() cache follows the new cells, which hold
  // every vertex whose cached cell went.
  void cells_made(const std::vector<Tet_id>& made)
  {
    for(Tet_id t : made) {
      cell_infos.forget(t);
      user_cells.forget(t);
    }
    vertices_added();
    if(incident_cells.empty()) return;
    if(dimension() < 3) {
      incident_cells.clear();
      return;
    }
    incident_cells.resize(core.vertex_slots(), Tet_id(-1));
    for(Tet_id t : made)
      for(int i = 0; i < 4; ++i) {
        const Vertex_id w = core.mesh.vertex(t, i);
        if(w != ghost_vertex) incident_cells[w] = t;
      }
  }

  // Vertex v (same id) now stands at p: a move, or a vertex of
  // tds().create_vertex() placed by insert_in_hole.
  void point_replaced(Vertex_id v, const Point& p)
  {
    kernel_points.replace(v, p);
    user_vertices.point_replaced(this, v);
  }

  // ---------------------------------------------------------------- copies of another data structure
  // An anchor filled by copy_data_structure (Data_structure_copy.h) takes
  // the points its conversion functors assign (Vertex_point_reference):
  // one per vertex id, while `being_copied`.
  mutable std::vector<Point> points_being_copied;
  bool being_copied = false;
  void assign_point(Vertex_id v, const Point& p) const
  {
    if(!being_copied)
      throw std::logic_error("Fast_Delaunay_triangulation_3: a vertex's point is not assigned: the vertex moves "
                             "through move() or move_if_no_collision()");
    if(v != ghost_vertex) points_being_copied[v] = p;
  }
  Point current_point(Vertex_id v) const
  {
    return !being_copied || v == ghost_vertex ? point_of(v) : points_being_copied[v];
  }

  // Takes the data `staged` was filled with (a copy of another data
  // structure, checked): arrays, kernel points, infos and user records.
  // The traits, the engine's settings and the lock data stay this anchor's.
  void take_copy(Storage_anchor& staged)
  {
    const int copied_dimension = staged.core.dimension;
    core.assign(std::move(staged.core.mesh), copied_dimension);
    incident_cells.clear();
    tds.forget_created();
    kernel_points = std::move(staged.kernel_points);
    vertex_infos = std::move(staged.vertex_infos);
    cell_infos = std::move(staged.cell_infos);
    user_vertices = std::move(staged.user_vertices);
    user_vertices.attach(this);
    user_cells = std::move(staged.user_cells);
    dimension_seen_ = dimension();
    vertices_seen_ = core.vertex_slots();
  }

  // Whether new cells need telling (cells_made): infos or user records.
  static constexpr bool keeps_cell_records =
      !std::is_void<Cell_info>::value || !std::is_void<typename Tr::User_cell_record>::value;
  // After removals that kept v->cell() themselves (Parallel_removal.h):
  // `made` (listed twice, some) start with Info() and default records.
  void cells_made_keeping_incident_cells(const std::vector<Tet_id>& made)
  {
    for(Tet_id t : made) {
      cell_infos.forget(t);
      user_cells.forget(t);
    }
    vertices_added();
  }

  // ---------------------------------------------------------------- read by handles and iterators
  const Flat_storage& flat_storage() const { return core.mesh; }
  int dimension() const { return core.dimension; }
  Point point_of(Vertex_id v) const
  {
    if constexpr(keeps_kernel_points) {
      return kernel_points.at(v);
    } else {
      if(v == ghost_vertex) return Point(0, 0, 0);
      const double* p = core.mesh.point(v);
      return Point(p[0], p[1], p[2]);
    }
  }
  template <class Info = Vertex_info>
  Info& vertex_info(Vertex_id v) const { return vertex_infos.at(v); }
  template <class Info = Cell_info>
  Info& cell_info(Tet_id c) const { return cell_infos.at(core.mesh, c); }
  template <class Record = Vertex>
  Record& user_record(const Vertex*, Vertex_id v) const { return user_vertices.at(v); }
  template <class Record = Cell>
  Record& user_record(const Cell*, Tet_id c) const { return user_cells.at(this, core.mesh, c); }

  // Dimension 3, finite cell: the centre of its circumscribed sphere, from
  // the cell's points in its vertex order.
  Point circumcenter(Tet_id t) const
  {
    CGAL_precondition(dimension() == 3 && !core.mesh.is_ghost(t));
    const Vertex_id* v = core.mesh.vertex_ids(t);
    return traits.construct_circumcenter_3_object()(point_of(v[0]), point_of(v[1]), point_of(v[2]),
                                                    point_of(v[3]));
  }

  // Below dimension 3, CGAL's triangulation beside the arrays knows v->cell();
  // in dimension 3 a cache built on first use, one tetrahedron per vertex.
  Cell_handle incident_cell_of(Vertex_id v) const
  {
    if(dimension() < 3) return cell_of_reference(core.lower.vertex(v)->cell());
    if(v == ghost_vertex) return infinite_cell();
    if(incident_cells.empty()) build_incident_cells();
    return Cell_handle(this, incident_cells[v]);
  }
  // A cell that has the infinite vertex.
  Cell_handle infinite_cell() const
  {
    if(dimension() < 3) return incident_cell_of(ghost_vertex);
    const Flat_storage& m = core.mesh;
    for(Tet_id t = 0; t < m.number_of_slots(); ++t)
      if(m.is_live(t) && m.is_ghost(t)) return Cell_handle(this, t);
    return Cell_handle();
  }
  // The slot a cell of CGAL's triangulation below dimension 3 is copied to.
  Cell_handle cell_of_reference(Lower_dimensional_triangulation::Reference_cell c) const
  {
    if(c == Lower_dimensional_triangulation::Reference_cell() ||
       Lower_dimensional_triangulation::slot(c) == lower_dimensions_detail::Slot::none)
      return Cell_handle();
    return Cell_handle(this, Lower_dimensional_triangulation::slot(c));
  }

  // Below dimension 3 the infinite vertex may be in any slot up to the dimension.
  bool has_infinite_vertex(Tet_id t) const
  {
    const Vertex_id* v = core.mesh.vertex_ids(t);
    const int last = std::max(dimension(), 0);
    return std::find(v, v + last + 1, ghost_vertex) != v + last + 1;
  }
  // Slots the iterators over faces of dimension `face_dimension` scan: none
  // when the triangulation has no such faces.
  std::size_t slots_of_faces(int face_dimension) const
  {
    return dimension() < face_dimension ? 0 : core.mesh.number_of_slots();
  }
  // The cell of smallest index among those around edge (v_i, v_j) of t.
  Tet_id smallest_cell_around_edge(Tet_id t, int i, int j) const
  {
    const Flat_storage& m = core.mesh;
    const Vertex_id a = m.vertex(t, i), b = m.vertex(t, j);
    // Turning around the edge: leave each cell through the facet opposite the
    // off-edge vertex that the previous cell did not share.
    Vertex_id cross = m.vertex(t, (i != 0 && j != 0) ? 0 : (i != 1 && j != 1) ? 1 : 2);
    Tet_id smallest = t, c = t;
    for(;;) {
      int cross_slot = -1;
      Vertex_id other = cross;
      for(int s = 0; s < 4; ++s) {
        const Vertex_id v = m.vertex(c, s);
        if(v == a || v == b) continue;
        if(v == cross) cross_slot = s;
        else other = v;
      }
      CGAL_assertion(cross_slot >= 0);
      c = m.neighbor(c, cross_slot);
      if(c == t) break;
      smallest = std::min(smallest, c);
      cross = other;
    }
    return smallest;
  }

private:
  // The dimension and vertex count at the end of the last insertion.
  int dimension_seen_ = -1;
  std::size_t vertices_seen_ = 0;

  void build_incident_cells() const
  {
    const Flat_storage& m = core.mesh;
    incident_cells.assign(core.vertex_slots(), Tet_id(-1));
    for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t)) continue;
      for(int i = 0; i < 4; ++i) {
        const Vertex_id v = m.vertex(t, i);
        if(v != ghost_vertex) incident_cells[v] = t;
      }
    }
  }
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_STORAGE_ANCHOR_H
