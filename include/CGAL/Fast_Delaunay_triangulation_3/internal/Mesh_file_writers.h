// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Tetrahedral meshes in three formats finite-element tools read, written
// from any source of points and cells (the mesher's Tetrahedral_mesh, a
// triangulation's finite cells) so that each format is written once:
//   Medit .mesh    ASCII; references = subdomain / surface numbers
//   VTK .vtu       XML with the arrays appended as raw binary (ASCII takes
//                  minutes and three times the bytes at 6.7e7 cells); cell
//                  arrays "subdomain" and "surface" (0 where they do not
//                  apply) when the mesh has surface triangles
//   Gmsh .msh 4.1  ASCII; one discrete volume entity per subdomain, one
//                  discrete surface entity per input surface
// Numbers go through std::to_chars into a buffer: coordinates in the
// shortest form that reads back bit for bit.
//
// A source provides
//   std::size_t number_of_points() const;   const double* point(std::size_t i) const;
//   std::size_t number_of_tetrahedra() const;
//   template <class F> void for_each_tetrahedron(F f) const;  f(const std::uint32_t* v, int subdomain),
//                                 v: 4 point numbers from 0, positively oriented; subdomains from 1
//   std::size_t number_of_triangles() const;
//   template <class F> void for_each_triangle(F f) const;     f(const std::uint32_t* v, int surface)
//   int number_of_subdomains() const;   int number_of_surfaces() const;
// The pieces of a distributed mesh pass the points' global numbers (node_ids): a point array "global_id" in the
// .vtu; node tags = global number + 1 in the .msh, whose element tags then start at first_element_tag.

#ifndef CGAL_FDT3_INTERNAL_MESH_FILE_WRITERS_H
#define CGAL_FDT3_INTERNAL_MESH_FILE_WRITERS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Byte_order.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Text and bytes gathered in a buffer and written to the stream by blocks;
// numbers are formatted in place (std::to_chars at the cursor).
class Output_buffer
{
public:
  explicit Output_buffer(std::ostream& out) : out_(out), buffer_(capacity + room) {}
  ~Output_buffer() { flush(); }
  Output_buffer(const Output_buffer&) = delete;
  Output_buffer& operator=(const Output_buffer&) = delete;

  Output_buffer& text(const char* s) { return bytes(s, std::strlen(s)); }
  Output_buffer& text(const std::string& s) { return bytes(s.data(), s.size()); }
  Output_buffer& character(char c)
  {
    buffer_[size_++] = c;
    return check();
  }
  Output_buffer& number(double x)
  {
    size_ = std::size_t(std::to_chars(cursor(), cursor() + room, x).ptr - buffer_.data());
    return check();
  }
  template <class Integer>
  Output_buffer& integer(Integer i)
  {
    size_ = std::size_t(std::to_chars(cursor(), cursor() + room, i).ptr - buffer_.data());
    return check();
  }
  // The bytes of a value in the machine's order.
  template <class T>
  Output_buffer& binary(T value)
  {
    static_assert(sizeof(T) <= room, "one value fits in the room after the capacity");
    std::memcpy(cursor(), &value, sizeof(T));
    size_ += sizeof(T);
    return check();
  }
  Output_buffer& bytes(const char* s, std::size_t n)
  {
    if(n > room) {
      flush();
      out_.write(s, std::streamsize(n));
      return *this;
    }
    std::memcpy(cursor(), s, n);
    size_ += n;
    return check();
  }
  void flush()
  {
    if(size_ > 0) out_.write(buffer_.data(), std::streamsize(size_));
    size_ = 0;
  }

private:
  // Written when the buffer holds `capacity` bytes; one item (a number, a
  // value, a short text) always fits in the `room` after it.
  static constexpr std::size_t capacity = std::size_t(1) << 20, room = 64;
  char* cursor() { return buffer_.data() + size_; }
  Output_buffer& check()
  {
    if(size_ >= capacity) flush();
    return *this;
  }
  std::ostream& out_;
  std::vector<char> buffer_;
  std::size_t size_ = 0;
};

template <class Source>
void write_medit(std::ostream& out, const Source& mesh)
{
  Output_buffer o(out);
  o.text("MeshVersionFormatted 2\nDimension 3\nVertices\n").integer(mesh.number_of_points()).character('\n');
  for(std::size_t i = 0; i < mesh.number_of_points(); ++i) {
    const double* p = mesh.point(i);
    o.number(p[0]).character(' ').number(p[1]).character(' ').number(p[2]).text(" 0\n");
  }
  if(mesh.number_of_triangles() > 0) {
    o.text("Triangles\n").integer(mesh.number_of_triangles()).character('\n');
    mesh.for_each_triangle([&](const std::uint32_t* v, int surface) {
      for(int k = 0; k < 3; ++k) o.integer(v[k] + std::uint64_t(1)).character(' ');
      o.integer(surface).character('\n');
    });
  }
  o.text("Tetrahedra\n").integer(mesh.number_of_tetrahedra()).character('\n');
  mesh.for_each_tetrahedron([&](const std::uint32_t* v, int subdomain) {
    for(int k = 0; k < 4; ++k) o.integer(v[k] + std::uint64_t(1)).character(' ');
    o.integer(subdomain).character('\n');
  });
  o.text("End\n");
}

// VTK unstructured grid, tetrahedra (type 10) then triangles (type 5), the
// arrays appended raw, each after its byte count (header_type UInt64).
template <class Source>
void write_vtu(std::ostream& out, const Source& mesh, const std::uint64_t* node_ids = nullptr)
{
  const std::uint64_t points = mesh.number_of_points(), tets = mesh.number_of_tetrahedra(),
                      triangles = mesh.number_of_triangles(), cells = tets + triangles;
  const std::uint64_t corners = 4 * tets + 3 * triangles;
  const bool wide_offsets = corners > std::uint64_t(std::numeric_limits<std::int32_t>::max());
  const bool cell_arrays = triangles > 0;
  struct Array { const char* type; const char* name; int components; std::uint64_t bytes; };
  std::vector<Array> arrays = {{"Float64", nullptr, 3, 24 * points},
                               {"Int32", "connectivity", 1, 4 * corners},
                               {wide_offsets ? "Int64" : "Int32", "offsets", 1, (wide_offsets ? 8 : 4) * cells},
                               {"UInt8", "types", 1, cells}};
  if(cell_arrays) {
    arrays.push_back({"Int32", "subdomain", 1, 4 * cells});
    arrays.push_back({"Int32", "surface", 1, 4 * cells});
  }
  const std::size_t ids_array = arrays.size();
  if(node_ids) arrays.push_back({"UInt64", "global_id", 1, 8 * points});
  Output_buffer o(out);
  std::uint64_t offset = 0;
  auto declare = [&](const Array& a) {
    o.text("<DataArray type=\"").text(a.type).character('"');
    if(a.name) o.text(" Name=\"").text(a.name).character('"');
    if(a.components > 1) o.text(" NumberOfComponents=\"").integer(a.components).character('"');
    o.text(" format=\"appended\" offset=\"").integer(offset).text("\"/>\n");
    offset += 8 + a.bytes;
  };
  o.text("<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"")
      .text(machine_is_little_endian() ? "LittleEndian" : "BigEndian")
      .text("\" header_type=\"UInt64\">\n<UnstructuredGrid>\n<Piece NumberOfPoints=\"")
      .integer(points).text("\" NumberOfCells=\"").integer(cells).text("\">\n<Points>\n");
  declare(arrays[0]);
  o.text("</Points>\n<Cells>\n");
  for(int k = 1; k <= 3; ++k) declare(arrays[k]);
  o.text("</Cells>\n");
  if(cell_arrays) {
    o.text("<CellData>\n");
    declare(arrays[4]);
    declare(arrays[5]);
    o.text("</CellData>\n");
  }
  if(node_ids) {
    o.text("<PointData>\n");
    declare(arrays[ids_array]);
    o.text("</PointData>\n");
  }
  o.text("</Piece>\n</UnstructuredGrid>\n<AppendedData encoding=\"raw\">\n_");

  o.binary(arrays[0].bytes);
  for(std::size_t i = 0; i < points; ++i) o.bytes(reinterpret_cast<const char*>(mesh.point(i)), 24);
  o.binary(arrays[1].bytes);
  mesh.for_each_tetrahedron([&](const std::uint32_t* v, int) {
    for(int k = 0; k < 4; ++k) o.binary(std::int32_t(v[k]));
  });
  mesh.for_each_triangle([&](const std::uint32_t* v, int) {
    for(int k = 0; k < 3; ++k) o.binary(std::int32_t(v[k]));
  });
  o.binary(arrays[2].bytes);
  std::uint64_t end = 0;
  for(std::uint64_t c = 0; c < cells; ++c) {
    end += c < tets ? 4 : 3;
    if(wide_offsets) o.binary(std::int64_t(end));
    else o.binary(std::int32_t(end));
  }
  o.binary(arrays[3].bytes);
  for(std::uint64_t c = 0; c < cells; ++c) o.binary(std::uint8_t(c < tets ? 10 : 5));
  if(cell_arrays) {
    o.binary(arrays[4].bytes);
    mesh.for_each_tetrahedron([&](const std::uint32_t*, int subdomain) { o.binary(std::int32_t(subdomain)); });
    for(std::uint64_t t = 0; t < triangles; ++t) o.binary(std::int32_t(0));
    o.binary(arrays[5].bytes);
    for(std::uint64_t t = 0; t < tets; ++t) o.binary(std::int32_t(0));
    mesh.for_each_triangle([&](const std::uint32_t*, int surface) { o.binary(std::int32_t(surface)); });
  }
  if(node_ids) {
    o.binary(arrays[ids_array].bytes);
    for(std::size_t i = 0; i < points; ++i) o.binary(node_ids[i]);
  }
  o.text("\n</AppendedData>\n</VTKFile>\n");
}

// Gmsh 4.1 ASCII: entities are surfaces 1..S and volumes 1..V, without
// bounding lists (discrete entities); all nodes in one block on volume 1;
// one element block per entity.  Node and element tags start at 1.
template <class Source>
void write_msh41(std::ostream& out, const Source& mesh, const std::uint64_t* node_ids = nullptr,
                 std::uint64_t first_element_tag = 1)
{
  double lo[3], hi[3];
  for(int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for(std::size_t i = 0; i < mesh.number_of_points(); ++i)
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], mesh.point(i)[a]);
      hi[a] = std::max(hi[a], mesh.point(i)[a]);
    }
  if(mesh.number_of_points() == 0)
    for(int a = 0; a < 3; ++a) lo[a] = hi[a] = 0;
  const int surfaces = mesh.number_of_surfaces(), volumes = std::max(1, mesh.number_of_subdomains());
  std::vector<std::size_t> triangles_on(surfaces + 1, 0), tetrahedra_in(volumes + 1, 0);
  mesh.for_each_triangle([&](const std::uint32_t*, int s) { ++triangles_on[s]; });
  mesh.for_each_tetrahedron([&](const std::uint32_t*, int d) { ++tetrahedra_in[d]; });

  Output_buffer o(out);
  auto box = [&]() {
    for(double x : {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]}) o.number(x).character(' ');
  };
  o.text("$MeshFormat\n4.1 0 8\n$EndMeshFormat\n$Entities\n0 0 ").integer(surfaces).character(' ')
      .integer(volumes).character('\n');
  for(int s = 1; s <= surfaces; ++s) {
    o.integer(s).character(' ');
    box();
    o.text("0 0\n");
  }
  for(int v = 1; v <= volumes; ++v) {
    o.integer(v).character(' ');
    box();
    o.text("0 0\n");
  }
  o.text("$EndEntities\n");

  const std::size_t n = mesh.number_of_points();
  auto node_tag = [&](std::uint32_t i) { return (node_ids ? node_ids[i] : std::uint64_t(i)) + 1; };
  std::uint64_t lowest_tag = n > 0 ? node_tag(0) : 1, highest_tag = n > 0 ? lowest_tag : 0;
  for(std::size_t i = 0; i < n; ++i) {
    lowest_tag = std::min(lowest_tag, node_tag(std::uint32_t(i)));
    highest_tag = std::max(highest_tag, node_tag(std::uint32_t(i)));
  }
  o.text("$Nodes\n1 ").integer(n).character(' ').integer(lowest_tag).character(' ').integer(highest_tag)
      .text("\n3 1 0 ").integer(n).character('\n');
  for(std::size_t i = 0; i < n; ++i) o.integer(node_tag(std::uint32_t(i))).character('\n');
  for(std::size_t i = 0; i < n; ++i) {
    const double* p = mesh.point(i);
    o.number(p[0]).character(' ').number(p[1]).character(' ').number(p[2]).character('\n');
  }
  o.text("$EndNodes\n");

  const std::size_t elements = mesh.number_of_tetrahedra() + mesh.number_of_triangles();
  o.text("$Elements\n").integer(surfaces + volumes).character(' ').integer(elements).character(' ')
      .integer(first_element_tag).character(' ').integer(first_element_tag + elements - 1)
      .character('\n');
  std::uint64_t tag = first_element_tag - 1;
  for(int s = 1; s <= surfaces; ++s) {
    o.text("2 ").integer(s).text(" 2 ").integer(triangles_on[s]).character('\n');
    mesh.for_each_triangle([&](const std::uint32_t* v, int surface) {
      if(surface != s) return;
      o.integer(++tag);
      for(int k = 0; k < 3; ++k) o.character(' ').integer(node_tag(v[k]));
      o.character('\n');
    });
  }
  for(int d = 1; d <= volumes; ++d) {
    o.text("3 ").integer(d).text(" 4 ").integer(tetrahedra_in[d]).character('\n');
    mesh.for_each_tetrahedron([&](const std::uint32_t* v, int subdomain) {
      if(subdomain != d) return;
      o.integer(++tag);
      for(int k = 0; k < 4; ++k) o.character(' ').integer(node_tag(v[k]));
      o.character('\n');
    });
  }
  o.text("$EndElements\n");
}

inline bool ends_with(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESH_FILE_WRITERS_H
