// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A Fast_Delaunay_triangulation_3 written to a file, the format by the
// extension:
//   .vtu   VTK unstructured grid, the finite tetrahedra, raw binary arrays
//   .mesh  Medit (ASCII), the finite tetrahedra, reference 1
//   .msh   Gmsh 4.1 (ASCII), the finite tetrahedra in one volume entity
//   .off   the convex hull: its triangles oriented outward, its vertices
//          numbered from 0 in the triangulation's order
//   .cgal  CGAL's triangulation format (operator<<, ASCII, 17 digits), which
//          CGAL's and this package's operator>> read back with the
//          infinite cells
// The points of .vtu, .mesh and .msh are the vertices in the
// triangulation's order (sorted for insertion, not the input's); the
// formats themselves are written by Mesh_file_writers.h.  Below dimension
// 3 there are no tetrahedra: the files hold the vertices only (and .off no
// facets).
//
//   #include <CGAL/Fast_Delaunay_triangulation_3/Triangulation_writers.h>
//   CGAL::Fast_Delaunay_triangulation_3_io::write_triangulation("cloud.vtu", tr);

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_TRIANGULATION_WRITERS_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_TRIANGULATION_WRITERS_H

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Mesh_file_writers.h>

#include <cstdint>
#include <fstream>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// The finite tetrahedra of a triangulation's flat arrays as a source of
// Mesh_file_writers.h; the live vertices numbered densely (they already are
// unless vertices were removed).
class Finite_cells_source
{
public:
  Finite_cells_source(const Flat_storage& mesh, int dimension) : m_(mesh), three_d_(dimension == 3)
  {
    if(m_.dead_vertices == 0) return;
    number_.assign(m_.vertices.size(), 0);
    for(std::size_t v = 0; v < m_.vertices.size(); ++v) {
      if(m_.is_dead(Vertex_id(v))) continue;
      number_[v] = std::uint32_t(live_.size());
      live_.push_back(Vertex_id(v));
    }
  }
  std::size_t number_of_points() const { return m_.live_vertices(); }
  const double* point(std::size_t i) const { return m_.point(live_.empty() ? Vertex_id(i) : live_[i]); }
  std::size_t number_of_tetrahedra() const { return three_d_ ? m_.live_tets - m_.ghost_tets : 0; }
  std::size_t number_of_triangles() const { return 0; }
  int number_of_subdomains() const { return 1; }
  int number_of_surfaces() const { return 0; }
  template <class F>
  void for_each_tetrahedron(F f) const
  {
    if(!three_d_) return;
    std::uint32_t v[4];
    for(std::size_t t = 0; t < m_.number_of_slots(); ++t) {
      if(!m_.is_live(t) || m_.is_ghost(t)) continue;
      for(int k = 0; k < 4; ++k) v[k] = number(m_.vertex(t, k));
      f(static_cast<const std::uint32_t*>(v), 1);
    }
  }
  template <class F>
  void for_each_triangle(F) const
  {}

private:
  std::uint32_t number(Vertex_id v) const { return number_.empty() ? std::uint32_t(v) : number_[v]; }
  const Flat_storage& m_;
  bool three_d_;
  std::vector<Vertex_id> live_;
  std::vector<std::uint32_t> number_;
};

template <class Tr>
Finite_cells_source finite_cells(const Tr& tr)
{
  return Finite_cells_source(tr.flat_storage(), tr.dimension());
}

} // namespace Fast_Delaunay_triangulation_3_internal

namespace Fast_Delaunay_triangulation_3_io {

// Writes the finite tetrahedra as VTK .vtu (raw binary appended arrays).
template <class Tr>
void write_vtu(std::ostream& out, const Tr& tr)
{
  Fast_Delaunay_triangulation_3_internal::write_vtu(out, Fast_Delaunay_triangulation_3_internal::finite_cells(tr));
}

template <class Tr>
void write_medit(std::ostream& out, const Tr& tr)
{
  Fast_Delaunay_triangulation_3_internal::write_medit(out, Fast_Delaunay_triangulation_3_internal::finite_cells(tr));
}

template <class Tr>
void write_msh41(std::ostream& out, const Tr& tr)
{
  Fast_Delaunay_triangulation_3_internal::write_msh41(out, Fast_Delaunay_triangulation_3_internal::finite_cells(tr));
}

// The convex hull as OFF: the finite facet of every infinite cell, which the
// ghost cell (a, b, c, infinite) stores in the order that faces outward.
template <class Tr>
void write_hull_off(std::ostream& out, const Tr& tr)
{
  typedef Fast_Delaunay_triangulation_3_internal::Vertex_id Vertex_id;
  const auto& m = tr.flat_storage();
  const bool three_d = tr.dimension() == 3;
  const std::uint32_t unused = std::uint32_t(-1);
  std::vector<std::uint32_t> number(m.vertices.size(), unused);
  std::size_t facets = 0;
  if(three_d)
    for(std::size_t t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t) || !m.is_ghost(t)) continue;
      ++facets;
      for(int k = 0; k < 3; ++k) number[m.vertex(t, k)] = 0;
    }
  std::vector<Vertex_id> hull;
  for(std::size_t v = 0; v < number.size(); ++v) {
    const bool on_hull = three_d ? number[v] != unused : !m.is_dead(Vertex_id(v));
    if(!on_hull) continue;
    number[v] = std::uint32_t(hull.size());
    hull.push_back(Vertex_id(v));
  }
  Fast_Delaunay_triangulation_3_internal::Output_buffer o(out);
  o.text("OFF\n").integer(hull.size()).character(' ').integer(facets).text(" 0\n");
  for(Vertex_id v : hull) {
    const double* p = m.point(v);
    o.number(p[0]).character(' ').number(p[1]).character(' ').number(p[2]).character('\n');
  }
  if(three_d)
    for(std::size_t t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t) || !m.is_ghost(t)) continue;
      o.character('3');
      for(int k = 0; k < 3; ++k) o.character(' ').integer(number[m.vertex(t, k)]);
      o.character('\n');
    }
}

// By extension: .vtu, .mesh, .msh, .off (the convex hull) or .cgal (CGAL's
// format).  Throws std::invalid_argument for another extension and
// std::runtime_error when the file cannot be written.
template <class Tr>
void write_triangulation(const std::string& path, const Tr& tr)
{
  using Fast_Delaunay_triangulation_3_internal::ends_with;
  const bool known = ends_with(path, ".vtu") || ends_with(path, ".mesh") || ends_with(path, ".msh") ||
                     ends_with(path, ".off") || ends_with(path, ".cgal");
  if(!known)
    throw std::invalid_argument("write_triangulation: unknown output format for '" + path +
                                "' (use .vtu, .mesh, .msh, .off or .cgal)");
  std::ofstream out(path, std::ios::binary);
  if(!out) throw std::runtime_error("write_triangulation: cannot write '" + path + "'");
  if(ends_with(path, ".vtu")) write_vtu(out, tr);
  else if(ends_with(path, ".mesh")) write_medit(out, tr);
  else if(ends_with(path, ".msh")) write_msh41(out, tr);
  else if(ends_with(path, ".off")) write_hull_off(out, tr);
  else {
    out.precision(17); // the stream's default 6 digits would move the points
    out << tr;
  }
  out.flush();
  if(!out) throw std::runtime_error("write_triangulation: error while writing '" + path + "'");
}

} // namespace Fast_Delaunay_triangulation_3_io
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_TRIANGULATION_WRITERS_H
