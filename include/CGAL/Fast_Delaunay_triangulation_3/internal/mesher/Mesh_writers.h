// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Writers of a Tetrahedral_mesh in three ASCII formats that finite-element
// tools read: Medit .mesh (references = subdomain / surface numbers), VTK
// .vtu (cell arrays "subdomain" and "surface", 0 where they do not apply)
// and Gmsh .msh 4.1 (one discrete volume
// entity per subdomain, one discrete surface entity per input surface).
// Coordinates are written with 17 significant digits so they read back
// bit for bit.

#ifndef CGAL_FDT3_INTERNAL_MESHER_MESH_WRITERS_H
#define CGAL_FDT3_INTERNAL_MESHER_MESH_WRITERS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedral_mesh.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

typedef CGAL::Fast_mesher_3::Tetrahedral_mesh Output_mesh;

inline void write_medit(std::ostream& out, const Output_mesh& mesh)
{
  out.precision(17);
  out << "MeshVersionFormatted 2\nDimension 3\n";
  out << "Vertices\n" << mesh.points.size() << "\n";
  for(const auto& p : mesh.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << " 0\n";
  out << "Triangles\n" << mesh.triangles.size() << "\n";
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& v = mesh.triangles[t];
    out << v[0] + 1 << ' ' << v[1] + 1 << ' ' << v[2] + 1 << ' ' << mesh.surface[t] << "\n";
  }
  out << "Tetrahedra\n" << mesh.tetrahedra.size() << "\n";
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& v = mesh.tetrahedra[t];
    out << v[0] + 1 << ' ' << v[1] + 1 << ' ' << v[2] + 1 << ' ' << v[3] + 1 << ' ' << mesh.subdomain[t] << "\n";
  }
  out << "End\n";
}

// VTK unstructured grid: tetrahedra (type 10) then triangles (type 5); the
// cell arrays "subdomain" (0 for triangles) and "surface" (0 for tetrahedra).
inline void write_vtu(std::ostream& out, const Output_mesh& mesh)
{
  out.precision(17);
  const std::size_t cells = mesh.tetrahedra.size() + mesh.triangles.size();
  out << "<?xml version=\"1.0\"?>\n"
      << "<VTKFile type=\"UnstructuredGrid\" version=\"0.1\" byte_order=\"LittleEndian\">\n"
      << "<UnstructuredGrid>\n"
      << "<Piece NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\"" << cells << "\">\n"
      << "<Points>\n<DataArray type=\"Float64\" NumberOfComponents=\"3\" format=\"ascii\">\n";
  for(const auto& p : mesh.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << "\n";
  out << "</DataArray>\n</Points>\n<Cells>\n<DataArray type=\"Int64\" Name=\"connectivity\" format=\"ascii\">\n";
  for(const auto& v : mesh.tetrahedra) out << v[0] << ' ' << v[1] << ' ' << v[2] << ' ' << v[3] << "\n";
  for(const auto& v : mesh.triangles) out << v[0] << ' ' << v[1] << ' ' << v[2] << "\n";
  out << "</DataArray>\n<DataArray type=\"Int64\" Name=\"offsets\" format=\"ascii\">\n";
  std::size_t offset = 0;
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) out << (offset += 4) << "\n";
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t) out << (offset += 3) << "\n";
  out << "</DataArray>\n<DataArray type=\"UInt8\" Name=\"types\" format=\"ascii\">\n";
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) out << "10\n";
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t) out << "5\n";
  out << "</DataArray>\n</Cells>\n<CellData>\n<DataArray type=\"Int32\" Name=\"subdomain\" format=\"ascii\">\n";
  for(int s : mesh.subdomain) out << s << "\n";
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t) out << "0\n";
  out << "</DataArray>\n<DataArray type=\"Int32\" Name=\"surface\" format=\"ascii\">\n";
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) out << "0\n";
  for(int s : mesh.surface) out << s << "\n";
  out << "</DataArray>\n</CellData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n";
}

// Gmsh 4.1: entities are surfaces 1..S and volumes 1..V, without bounding
// lists (discrete entities); all nodes in one block on volume 1; one
// element block per entity.  Node and element tags start at 1.
inline void write_msh41(std::ostream& out, const Output_mesh& mesh)
{
  out.precision(17);
  double lo[3], hi[3];
  for(int a = 0; a < 3; ++a) {
    lo[a] = std::numeric_limits<double>::infinity();
    hi[a] = -lo[a];
  }
  for(const auto& p : mesh.points)
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::min(lo[a], p[a]);
      hi[a] = std::max(hi[a], p[a]);
    }
  auto box = [&]() {
    std::string s;
    for(double x : {lo[0], lo[1], lo[2], hi[0], hi[1], hi[2]}) s += std::to_string(x) + " ";
    return s;
  };
  const int surfaces = mesh.number_of_surfaces, volumes = mesh.number_of_subdomains;
  out << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  out << "$Entities\n0 0 " << surfaces << ' ' << volumes << "\n";
  for(int s = 1; s <= surfaces; ++s) out << s << ' ' << box() << "0 0\n";
  for(int v = 1; v <= volumes; ++v) out << v << ' ' << box() << "0 0\n";
  out << "$EndEntities\n";

  const std::size_t n = mesh.points.size();
  out << "$Nodes\n1 " << n << " 1 " << n << "\n3 1 0 " << n << "\n";
  for(std::size_t i = 1; i <= n; ++i) out << i << "\n";
  for(const auto& p : mesh.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << "\n";
  out << "$EndNodes\n";

  const std::size_t elements = mesh.tetrahedra.size() + mesh.triangles.size();
  out << "$Elements\n" << surfaces + volumes << ' ' << elements << " 1 " << elements << "\n";
  std::size_t tag = 0;
  for(int s = 1; s <= surfaces; ++s) {
    const std::size_t count = static_cast<std::size_t>(std::count(mesh.surface.begin(), mesh.surface.end(), s));
    out << "2 " << s << " 2 " << count << "\n";
    for(std::size_t t = 0; t < mesh.triangles.size(); ++t)
      if(mesh.surface[t] == s) {
        const auto& v = mesh.triangles[t];
        out << ++tag << ' ' << v[0] + 1 << ' ' << v[1] + 1 << ' ' << v[2] + 1 << "\n";
      }
  }
  for(int d = 1; d <= volumes; ++d) {
    const std::size_t count =
        static_cast<std::size_t>(std::count(mesh.subdomain.begin(), mesh.subdomain.end(), d));
    out << "3 " << d << " 4 " << count << "\n";
    for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
      if(mesh.subdomain[t] == d) {
        const auto& v = mesh.tetrahedra[t];
        out << ++tag << ' ' << v[0] + 1 << ' ' << v[1] + 1 << ' ' << v[2] + 1 << ' ' << v[3] + 1 << "\n";
      }
  }
  out << "$EndElements\n";
}

inline bool ends_with(const std::string& s, const std::string& suffix)
{
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// Picks the format from the extension: .mesh, .vtu or .msh.
inline void write_mesh_file(const std::string& path, const Output_mesh& mesh)
{
  std::ofstream out(path);
  if(!out) throw std::runtime_error("Tetrahedral_mesher: cannot write '" + path + "'");
  if(ends_with(path, ".mesh")) write_medit(out, mesh);
  else if(ends_with(path, ".vtu")) write_vtu(out, mesh);
  else if(ends_with(path, ".msh")) write_msh41(out, mesh);
  else throw std::invalid_argument("Tetrahedral_mesher: unknown output format for '" + path +
                                   "' (use .mesh, .vtu or .msh)");
  if(!out) throw std::runtime_error("Tetrahedral_mesher: error while writing '" + path + "'");
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_MESH_WRITERS_H
