// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL's file format for Triangulation_3 (its operator<< / operator>>, with
// the cell section of Triangulation_data_structure_3), read into and written
// from the flat arrays in linear time.  Not part of the paper: it lets a
// triangulation travel between this package and CGAL.
//
// ASCII layout; the binary mode (CGAL::IO::set_binary_mode) has the same
// fields as raw int (dimension), std::size_t (counts and indices) and the
// kernel's binary points:
//
//   d                       dimension
//   n                       number of finite vertices
//   n points                file vertex k (1..n); index 0 is the infinite vertex
//   m                       number of cells, finite and infinite
//   m lines "i0 i1 i2 i3"   vertex indices of each cell
//   m lines "c0 c1 c2 c3"   cell indices of the neighbours; ck is opposite ik
//   m empty lines           the cells' own data (nothing for default cells)
//
// Below dimension 3 the "cells" are the (d+1)-tuples of CGAL's
// d-dimensional data structure (dimension 0 and -1: no cell section).
//
// Infinite cells: CGAL may put the infinite vertex in any slot; we keep it in
// slot 3.  Both orient an infinite cell as if the infinite vertex were a
// point beyond its hull facet (positive orientation), so moving it to slot 3
// with an even permutation keeps the meaning:
//
//   infinite vertex in slot i < 3:  swap slots i and 3, and swap the other two.

#ifndef CGAL_FDT3_INTERNAL_TRIANGULATION_IO_H
#define CGAL_FDT3_INTERNAL_TRIANGULATION_IO_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_points.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_core.h>

#include <CGAL/IO/io.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <numeric>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// New slot of the vertex (or neighbour) in `slot` of a cell whose infinite
// vertex was in `infinite_slot` (3 for a finite cell: nothing moves).  The
// two slots other than infinite_slot and 3 sum to 3 - infinite_slot.
inline int slot_with_ghost_last(int slot, int infinite_slot)
{
  if(infinite_slot == 3) return slot;
  if(slot == infinite_slot) return 3;
  if(slot == 3) return infinite_slot;
  return 3 - infinite_slot - slot;
}

// Writes a triangulation of dimension 3 in CGAL's format.  `point_of(v)`
// makes the kernel point of vertex v; it is written with the kernel's
// operator<<, as CGAL does, so the stream's mode and precision apply.
template <class Point_of>
void write_triangulation_3(std::ostream& os, const Flat_storage& mesh, Point_of point_of)
{
  const bool ascii = IO::is_ascii(os);
  const std::size_t n = mesh.live_vertices();
  const std::size_t slots = mesh.number_of_slots();
  // Vertices are numbered in id order, skipping removed ones (1 + index:
  // 0 is the infinite vertex).
  std::vector<std::size_t> index_of_vertex(mesh.vertices.size(), 0);
  for(std::size_t v = 0, k = 0; v < mesh.vertices.size(); ++v)
    if(!mesh.is_dead(static_cast<Vertex_id>(v))) index_of_vertex[v] = ++k;
  auto put = [&](std::size_t value, char separator) {
    if(ascii) os << value << separator;
    else CGAL::write(os, value);
  };
  if(ascii) os << 3 << '\n' << n << '\n';
  else {
    CGAL::write(os, int(3));
    CGAL::write(os, n);
  }
  for(std::size_t v = 0; v < mesh.vertices.size(); ++v) {
    if(mesh.is_dead(static_cast<Vertex_id>(v))) continue;
    os << point_of(static_cast<Vertex_id>(v));
    if(ascii) os << '\n';
  }

  // Cells are numbered in slot order, skipping free slots.
  std::vector<std::size_t> index_of_slot(slots, 0);
  std::size_t m = 0;
  for(Tet_id t = 0; t < slots; ++t)
    if(mesh.is_live(t)) index_of_slot[t] = m++;
  put(m, '\n');
  for(Tet_id t = 0; t < slots; ++t) {
    if(!mesh.is_live(t)) continue;
    for(int i = 0; i < 4; ++i) {
      const Vertex_id v = mesh.vertex(t, i);
      put(v == ghost_vertex ? 0 : index_of_vertex[v], i == 3 ? '\n' : ' ');
    }
  }
  for(Tet_id t = 0; t < slots; ++t) {
    if(!mesh.is_live(t)) continue;
    for(int i = 0; i < 4; ++i) put(index_of_slot[mesh.neighbor(t, i)], i == 3 ? '\n' : ' ');
  }
  if(ascii)
    for(std::size_t c = 0; c < m; ++c) os << '\n';
}

// The cells of a triangulation of dimension 3 in CGAL's numbering: what a
// file's cell section holds, and what a copy of another data structure
// (Flat_tds::copy_tds) gives.  Cell c has vertices[4c + i] (0 for the
// infinite vertex, k for vertex k - 1 of the storage) and, opposite vertex
// i, neighbour neighbors[4c + i] (a cell number).  Indices are in range.
struct Cell_table
{
  std::vector<std::size_t> vertices;
  std::vector<std::size_t> neighbors;
  std::size_t size() const { return vertices.size() / 4; }
};

// Builds the cells of a table into `mesh`, which holds the vertices, and
// checks them completely before anyone sees them: at most one infinite
// vertex per cell, symmetric adjacency across shared facets, one connected
// piece, positive orientation, the (perturbed) local Delaunay property on
// every facet including the hull's, every vertex used.  False, with the
// reason in error(), when the table is not a Delaunay triangulation.
class Cell_table_assembler
{
public:
  bool assemble(const Cell_table& table, Flat_storage& mesh)
  {
    const std::size_t m = table.size();
    if(m == 0) return fail("dimension 3 with no cells");
    for(std::size_t c = 0; c < m; ++c) {
      Vertex_id v[4];
      int infinite = 3, infinite_count = 0;
      for(int i = 0; i < 4; ++i) {
        const std::size_t k = table.vertices[4 * c + i];
        v[i] = k == 0 ? ghost_vertex : static_cast<Vertex_id>(k - 1);
        if(k == 0) {
          infinite = i;
          ++infinite_count;
        }
      }
      if(infinite_count > 1) return fail(cell_name(c) + " has more than one infinite vertex");
      const Tet_id t = mesh.new_tet();
      for(int i = 0; i < 4; ++i) {
        mesh.vertex_ids(t)[slot_with_ghost_last(i, infinite)] = v[i];
        // The neighbour's cell number; a facet code once all are known.
        mesh.tets[t].n[slot_with_ghost_last(i, infinite)] = static_cast<Facet_code>(table.neighbors[4 * c + i]);
      }
      if(infinite_count == 1) ++mesh.ghost_tets;
    }
    mesh.live_tets = m;
    if(mesh.ghost_tets == m) return fail("no finite cell");
    for(Tet_id t = 0; t < m; ++t)
      for(int i = 0; i < 4; ++i)
        if(!link_facet(mesh, t, i)) return false;
    return check_3(mesh);
  }

  const std::string& error() const { return error_; }

private:
  bool fail(const std::string& message)
  {
    error_ = message;
    return false;
  }
  static std::string cell_name(std::size_t c) { return "cell " + std::to_string(c); }

  // Called for t = 0, 1, ... in order.  Neighbour entry i of t holds the
  // neighbour's cell number u from the table; replaces it by the facet code of the
  // same facet seen from u.  The entries of u hold facet codes if u < t
  // (linked already) and cell indices otherwise.
  bool link_facet(Flat_storage& mesh, Tet_id t, int i)
  {
    const Tet_id u = mesh.neighbor_code(t, i);
    int mirror = -1, outside = 0;
    for(int j = 0; j < 4; ++j) {
      const Vertex_id w = mesh.vertex(u, j);
      bool on_facet = false;
      for(int k = 0; k < 4; ++k)
        if(k != i && mesh.vertex(t, k) == w) on_facet = true;
      if(!on_facet) {
        mirror = j;
        ++outside;
      }
    }
    if(outside != 1 || u == t)
      return fail(cell_name(t) + " and its neighbour " + cell_name(u) + " do not share facet " + std::to_string(i));
    // The neighbour's entry for this facet is either still a cell index (u
    // is later in the pass) or already a facet code (u was linked before).
    const Facet_code back = mesh.neighbor_code(u, mirror);
    const Tet_id back_cell = u < t ? tet_of(back) : back;
    if(back_cell != t)
      return fail("adjacency is not symmetric: " + cell_name(t) + " has neighbour " + cell_name(u) +
                  ", which does not have " + cell_name(t) + " as neighbour " + std::to_string(mirror));
    mesh.tets[t].n[i] = facet_code(u, mirror);
    return true;
  }

  bool check_3(Flat_storage& mesh)
  {
    if(!is_connected(mesh)) return fail("the cells form more than one connected piece");
    Triangulation_core check;
    check.dimension = 3;
    check.mesh = std::move(mesh);
    std::string why;
    const bool valid = check.is_valid(&why) && hull_is_delaunay(check.mesh, why);
    mesh = std::move(check.mesh);
    return valid || fail("not a Delaunay triangulation: " + why);
  }

  static bool is_connected(const Flat_storage& mesh)
  {
    std::vector<char> seen(mesh.number_of_slots(), 0);
    std::vector<Tet_id> stack(1, 0);
    seen[0] = 1;
    std::size_t reached = 1;
    while(!stack.empty()) {
      const Tet_id t = stack.back();
      stack.pop_back();
      for(int i = 0; i < 4; ++i) {
        const Tet_id u = mesh.neighbor(t, i);
        if(seen[u]) continue;
        seen[u] = 1;
        ++reached;
        stack.push_back(u);
      }
    }
    return reached == mesh.number_of_slots();
  }

  // The ghost cells' side of the Delaunay property (Triangulation_core's
  // is_valid checks finite cells only): the far vertex of each neighbouring
  // hull facet is not beyond this one, which makes the hull convex.
  static bool hull_is_delaunay(const Flat_storage& mesh, std::string& why)
  {
    for(Tet_id g = 0; g < mesh.number_of_slots(); ++g) {
      if(!mesh.is_ghost(g)) continue;
      const double* a = mesh.point(mesh.vertex(g, 0));
      const double* b = mesh.point(mesh.vertex(g, 1));
      const double* c = mesh.point(mesh.vertex(g, 2));
      for(int i = 0; i < 3; ++i) {
        const Facet_code code = mesh.neighbor_code(g, i);
        const Vertex_id far = mesh.vertex(tet_of(code), facet_of(code));
        if(ghost_cell_in_conflict(a, b, c, mesh.point(far))) {
          why = "hull facet of cell " + std::to_string(g) + " is not convex towards facet " + std::to_string(i);
          return false;
        }
      }
    }
    return true;
  }

  std::string error_;
};

// Below dimension 3 the cells are not kept: the vertices must be distinct
// points spanning exactly `dimension`, whose triangulation is then built.
// False, with the reason in `error`, otherwise.
inline bool vertices_span_dimension(Flat_storage& mesh, int dimension, std::string& error)
{
  std::vector<Vertex_id> order(mesh.vertices.size());
  std::iota(order.begin(), order.end(), Vertex_id(0));
  std::sort(order.begin(), order.end(), [&mesh](Vertex_id a, Vertex_id b) {
    return lexicographically_smaller(mesh.point(a), mesh.point(b));
  });
  for(std::size_t k = 1; k < order.size(); ++k)
    if(same_point(mesh.point(order[k - 1]), mesh.point(order[k]))) {
      error = "points " + std::to_string(order[k - 1] + 1) + " and " + std::to_string(order[k] + 1) + " are equal";
      return false;
    }
  Triangulation_core check;
  check.mesh = std::move(mesh);
  const int spanned = check.affine_dimension();
  mesh = std::move(check.mesh);
  if(spanned != dimension) {
    error = "dimension " + std::to_string(dimension) + " but the points span dimension " + std::to_string(spanned);
    return false;
  }
  return true;
}

// Reads one triangulation in CGAL's format into a new Flat_storage and
// checks it completely before anyone sees it: counts and index ranges here,
// the cells by Cell_table_assembler, and below dimension 3 the vertices by
// vertices_span_dimension.  Below
// dimension 3 the cell section is checked and dropped (this package stores
// no lower-dimensional cells).
template <class Point>
class Triangulation_reader
{
public:
  explicit Triangulation_reader(std::istream& is) : is_(is), ascii_(IO::is_ascii(is)) {}

  // True on success, with the result in `mesh` and `dimension`; else false
  // and error() says what is wrong and where.
  bool read(Flat_storage& mesh, int& dimension)
  {
    if(!read_dimension(dimension)) return false;
    std::size_t n = 0;
    if(!read_number(n, max_vertices, "number of vertices")) return false;
    if(!read_points(n, mesh)) return false;
    if(dimension == 3) return read_cells_3(mesh);
    std::string why;
    return read_lower_dimensional_cells(dimension, n) && (vertices_span_dimension(mesh, dimension, why) || fail(why));
  }

  const std::string& error() const { return error_; }

private:
  bool fail(const std::string& message)
  {
    error_ = message;
    return false;
  }

  bool read_dimension(int& dimension)
  {
    if(ascii_) is_ >> dimension;
    else CGAL::read(is_, dimension);
    if(!is_) return fail("the stream ends before the dimension");
    if(dimension < -1 || dimension > 3)
      return fail("dimension " + std::to_string(dimension) + " is not in [-1, 3]");
    return true;
  }

  // A count or index in [0, limit]; in ASCII a minus sign is an error, not
  // a huge unsigned value.
  bool read_number(std::size_t& value, std::size_t limit, const std::string& what)
  {
    if(ascii_) {
      long long signed_value = 0;
      is_ >> signed_value;
      if(!is_) return fail("the stream ends or has no number at " + what);
      if(signed_value < 0) return fail(what + " is negative (" + std::to_string(signed_value) + ")");
      value = static_cast<std::size_t>(signed_value);
    } else {
      CGAL::read(is_, value);
      if(!is_) return fail("the stream ends at " + what);
    }
    if(value > limit)
      return fail(what + " is " + std::to_string(value) + ", more than " + std::to_string(limit));
    return true;
  }
  bool read_points(std::size_t n, Flat_storage& mesh)
  {
    mesh.clear();
    for(std::size_t v = 0; v < n; ++v) {
      Point p;
      if(!(is_ >> p)) return fail("the stream ends or is unreadable at point " + std::to_string(v + 1));
      // The format writes doubles (an exact kernel's operator<< writes the
      // double of each coordinate); a coordinate read as a decimal or a
      // quotient is taken as its nearest double.
      Vertex_record r = {{0, 0, 0}, 0};
      nearest_coordinates(p, r.xyz);
      if(!std::isfinite(r.xyz[0]) || !std::isfinite(r.xyz[1]) || !std::isfinite(r.xyz[2]))
        return fail("point " + std::to_string(v + 1) + " has a non-finite coordinate");
      mesh.vertices.push_back(r);
    }
    return true;
  }

  static std::string cell_name(std::size_t c) { return "cell " + std::to_string(c); }

  // The table grows as the cells arrive, so a huge count in a short file
  // fails at the end of the stream rather than in the allocator.
  bool read_cells_3(Flat_storage& mesh)
  {
    const std::size_t n = mesh.vertices.size();
    std::size_t m = 0;
    if(!read_number(m, max_tets, "number of cells")) return false;
    Cell_table table;
    for(std::size_t c = 0; c < m; ++c)
      for(int i = 0; i < 4; ++i) {
        std::size_t k = 0;
        if(!read_number(k, n, "vertex " + std::to_string(i) + " of " + cell_name(c))) return false;
        table.vertices.push_back(k);
      }
    for(std::size_t c = 0; c < m; ++c)
      for(int i = 0; i < 4; ++i) {
        std::size_t u = 0;
        if(!read_number(u, m - 1, "neighbour " + std::to_string(i) + " of " + cell_name(c))) return false;
        table.neighbors.push_back(u);
      }
    Cell_table_assembler assembler;
    return assembler.assemble(table, mesh) || fail(assembler.error());
  }

  // Dimensions 1 and 2: m (d+1)-tuples of vertex indices, then of neighbour
  // indices; a sphere of n + 1 vertices has 2n - 2 triangles, a circle n + 1
  // edges.
  bool read_lower_dimensional_cells(int dimension, std::size_t n)
  {
    if(dimension < 1) return true;
    std::size_t m = 0;
    if(!read_number(m, max_tets, "number of cells")) return false;
    const std::size_t expected = dimension == 2 ? 2 * n - 2 : n + 1;
    if(n < std::size_t(dimension) + 1 || m != expected)
      return fail(std::to_string(m) + " cells for " + std::to_string(n) + " vertices in dimension " +
                  std::to_string(dimension) + " (expected " + std::to_string(expected) + ")");
    const int k = dimension + 1;
    std::vector<std::size_t> vertices(k * m), neighbors(k * m);
    for(std::size_t c = 0; c < m; ++c)
      for(int i = 0; i < k; ++i) {
        if(!read_number(vertices[k * c + i], n, "vertex " + std::to_string(i) + " of " + cell_name(c)))
          return false;
        for(int j = 0; j < i; ++j)
          if(vertices[k * c + j] == vertices[k * c + i]) return fail(cell_name(c) + " repeats a vertex");
      }
    for(std::size_t c = 0; c < m; ++c)
      for(int i = 0; i < k; ++i)
        if(!read_number(neighbors[k * c + i], m - 1, "neighbour " + std::to_string(i) + " of " + cell_name(c)))
          return false;
    for(std::size_t c = 0; c < m; ++c)
      for(int i = 0; i < k; ++i) {
        const std::size_t u = neighbors[k * c + i];
        if(std::find(&neighbors[k * u], &neighbors[k * u] + k, c) == &neighbors[k * u] + k)
          return fail("adjacency is not symmetric between " + cell_name(c) + " and " + cell_name(u));
      }
    return true;
  }

  std::istream& is_;
  bool ascii_;
  std::string error_;
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_TRIANGULATION_IO_H
