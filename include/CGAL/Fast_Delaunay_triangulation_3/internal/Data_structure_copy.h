// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's copy_tds(): a triangulation becomes a copy of another data
// structure (CGAL's Triangulation_data_structure_3, this package's, or any
// with its interface), with user functors that convert vertices and cells.
// CGAL's own example copies an Epick triangulation into an Epeck one this
// way, then names the copy's infinite vertex with set_infinite_vertex().
//
// CGAL 5.5's protocol, kept call for call because functors may count their
// calls (CGAL's example skips the point of the first vertex it sees, the
// infinite one): for every source vertex in the source's order
// convert_vertex(v), which makes a vertex, then convert_vertex(v, copy),
// which fills the copy (point, info, members of a user base); then the same
// for every source cell with convert_cell.
//
// Here the copies are made in a fresh anchor, so that nothing changes when
// the source cannot be taken: its vertices get ids in the source's order
// (the infinite one is the ghost), the functors fill them (the points they
// assign land in the anchor's points_being_copied), the points must be
// exactly doubles, and then, in dimension 3, the source's cells in its
// order go through the file reader's assembler (Triangulation_io.h), which
// checks that they are a Delaunay triangulation of those points, exactly.
// Below dimension 3 no cells are stored: the points' triangulation is
// built, and each source cell must be one of its cells (a source that is
// not the Delaunay triangulation of its points is refused).

#ifndef CGAL_FDT3_INTERNAL_DATA_STRUCTURE_COPY_H
#define CGAL_FDT3_INTERNAL_DATA_STRUCTURE_COPY_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_points.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_io.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <map>
#include <numeric>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// CGAL's default conversions: the point (and the info, if both vertices
// have one of the same type) goes over; cells carry nothing but an info.
struct Default_vertex_conversion
{
  template <class Source_vertex>
  int operator()(const Source_vertex&) const { return 0; }
  template <class Source_vertex, class Vertex>
  void operator()(const Source_vertex& source, Vertex& copy) const
  {
    set_point(copy, source.point(), 0);
    copy_info(source, copy, 0);
  }
  // A vertex of a user base takes its point by set_point(), as CGAL's.
  template <class Vertex, class P>
  static auto set_point(Vertex& copy, const P& p, int) -> decltype(copy.set_point(p), void())
  {
    copy.set_point(p);
  }
  template <class Vertex, class P>
  static void set_point(Vertex& copy, const P& p, long)
  {
    copy.point() = p;
  }
  template <class S, class T>
  static auto copy_info(const S& source, T& copy, int) -> decltype(copy.info() = source.info(), void())
  {
    copy.info() = source.info();
  }
  template <class S, class T>
  static void copy_info(const S&, T&, long) {}
};
struct Default_cell_conversion
{
  template <class Source_cell>
  int operator()(const Source_cell&) const { return 0; }
  template <class Source_cell, class Cell>
  void operator()(const Source_cell& source, Cell& copy) const
  {
    Default_vertex_conversion::copy_info(source, copy, 0);
  }
};

// Calls f with a writable element of handle h: the record itself for a
// user base, a copy of the facade otherwise (a facade is a view: the copy
// writes where the original would).
template <class Handle, class F>
void with_writable(const Handle& h, F&& f)
{
  if constexpr(std::is_const<std::remove_reference_t<decltype(*h)>>::value) {
    auto element = *h;
    f(element);
  } else {
    f(*h);
  }
}

// Anchor: the triangulation's Storage_anchor; Source: a data structure with
// CGAL's TDS interface.  Throws std::invalid_argument naming the defect, and
// then `target` is unchanged.
template <class Anchor, class Source, class Convert_vertex, class Convert_cell>
void copy_data_structure(Anchor& target, const Source& source, typename Source::Vertex_handle infinite,
                         const Convert_vertex& convert_vertex, const Convert_cell& convert_cell)
{
  typedef typename Anchor::Point Point;
  typedef typename Anchor::Vertex_handle Vertex_handle;
  typedef typename Anchor::Cell_handle Cell_handle;
  typedef typename Source::Vertex_handle Source_vertex;
  typedef typename Source::Cell_handle Source_cell;
  const std::string where = "Fast_Delaunay_triangulation_3::tds().copy_tds: ";
  auto refuse = [&where](const std::string& why) { throw std::invalid_argument(where + why); };

  const int dimension = source.dimension();
  if(dimension < -1 || dimension > 3) refuse("the source has dimension " + std::to_string(dimension));
  if(infinite == Source_vertex())
    refuse("the source's infinite vertex must be given: it becomes the copy's infinite vertex");

  // Vertex numbers as in CGAL's file format: 0 the infinite vertex, k the
  // copy's vertex k - 1, in the source's order.
  std::vector<Source_vertex> source_vertices;
  std::map<Source_vertex, std::size_t> number_of_vertex;
  std::size_t finite_count = 0;
  for(auto v = source.vertices_begin(); v != source.vertices_end(); ++v) {
    const Source_vertex h = v;
    source_vertices.push_back(h);
    number_of_vertex[h] = h == infinite ? 0 : ++finite_count;
  }
  if(number_of_vertex.count(infinite) == 0) refuse("the given infinite vertex is not a vertex of the source");
  if(finite_count > max_vertices) refuse("the source has more vertices than this triangulation can hold");
  // A cell's vertex or neighbour that the source does not list is a
  // broken source, not the infinite vertex or cell 0.
  auto vertex_number = [&](const Source_vertex& v) {
    const auto found = number_of_vertex.find(v);
    if(found == number_of_vertex.end()) refuse("a cell of the source has a vertex the source does not list");
    return found->second;
  };
  std::vector<Source_cell> source_cells;
  std::map<Source_cell, std::size_t> number_of_cell;
  for(auto c = source.cells_begin(); c != source.cells_end(); ++c) {
    const Source_cell h = c;
    number_of_cell[h] = source_cells.size();
    source_cells.push_back(h);
  }
  Anchor staged(target.traits);
  Flat_storage built;
  built.vertices.resize(finite_count);
  std::fill(built.vertices.begin(), built.vertices.end(), Vertex_record{{0, 0, 0}, 0});
  staged.being_copied = true;
  staged.points_being_copied.assign(finite_count, Point(0, 0, 0));
  staged.vertex_infos.resize(finite_count);
  staged.user_vertices.resize(&staged, finite_count);
  for(const Source_vertex& v : source_vertices) {
    const std::size_t k = vertex_number(v);
    const Vertex_handle copy(&staged, k == 0 ? ghost_vertex : static_cast<Vertex_id>(k - 1));
    (void)convert_vertex(*v);
    with_writable(copy, [&](auto& element) { convert_vertex(*v, element); });
  }
  for(std::size_t k = 0; k < finite_count; ++k) {
    double* xyz = built.vertices[k].xyz;
    if(!exact_coordinates(staged.points_being_copied[k], xyz))
      refuse("the point of vertex " + std::to_string(k + 1) + " has coordinates that are not doubles");
    if(!std::isfinite(xyz[0]) || !std::isfinite(xyz[1]) || !std::isfinite(xyz[2]))
      refuse("the point of vertex " + std::to_string(k + 1) + " has a non-finite coordinate");
  }

  std::vector<Tet_id> slot_of_cell(source_cells.size(), Tet_id(-1));
  if(dimension == 3) {
    Cell_table table;
    for(const Source_cell& c : source_cells)
      for(int i = 0; i < 4; ++i) {
        table.vertices.push_back(vertex_number(c->vertex(i)));
        const auto neighbor = number_of_cell.find(c->neighbor(i));
        if(neighbor == number_of_cell.end()) refuse("a cell of the source has a neighbour the source does not list");
        table.neighbors.push_back(neighbor->second);
      }
    Cell_table_assembler assembler;
    if(!assembler.assemble(table, built)) refuse(assembler.error());
    std::iota(slot_of_cell.begin(), slot_of_cell.end(), Tet_id(0));
  } else {
    std::string why;
    if(!vertices_span_dimension(built, dimension, why)) refuse(why);
  }
  staged.core.assign(std::move(built), dimension);

  // Below dimension 3, each source cell (dimension + 1 vertices) finds the
  // slot of the cell with the same vertices.
  if(dimension >= 1 && dimension < 3) {
    typedef std::array<std::size_t, 3> Key;
    auto key_of = [dimension](auto number) {
      Key key = {{0, 0, 0}};
      for(int i = 0; i <= dimension; ++i) key[i] = number(i);
      std::sort(key.begin(), key.begin() + dimension + 1);
      return key;
    };
    const Flat_storage& m = staged.core.mesh;
    std::map<Key, Tet_id> slot_of_key;
    for(Tet_id t = 0; t < m.number_of_slots(); ++t)
      if(m.is_live(t))
        slot_of_key[key_of([&](int i) {
          const Vertex_id v = m.vertex(t, i);
          return v == ghost_vertex ? std::size_t(0) : std::size_t(v) + 1;
        })] = t;
    for(std::size_t k = 0; k < source_cells.size(); ++k) {
      const auto found =
          slot_of_key.find(key_of([&](int i) { return vertex_number(source_cells[k]->vertex(i)); }));
      if(found == slot_of_key.end())
        refuse("cell " + std::to_string(k) + " of the source is not a cell of the Delaunay triangulation of its points");
      slot_of_cell[k] = found->second;
    }
  }
  for(std::size_t k = 0; k < source_cells.size(); ++k) {
    (void)convert_cell(*source_cells[k]);
    if(slot_of_cell[k] == Tet_id(-1)) continue; // dimensions 0 and -1 store no cells
    with_writable(Cell_handle(&staged, slot_of_cell[k]), [&](auto& element) { convert_cell(*source_cells[k], element); });
  }

  std::vector<Vertex_id> identity(finite_count);
  std::iota(identity.begin(), identity.end(), Vertex_id(0));
  staged.kernel_points.resize(staged.core.mesh, &staged.points_being_copied, &identity);
  staged.being_copied = false;
  target.take_copy(staged);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_DATA_STRUCTURE_COPY_H
