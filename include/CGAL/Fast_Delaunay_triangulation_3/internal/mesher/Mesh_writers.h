// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A Tetrahedral_mesh written as Medit .mesh, VTK .vtu or Gmsh .msh 4.1 by
// the writers of Mesh_file_writers.h (the formats are described there):
// subdomains and input surfaces become references, cell arrays or entities.

#ifndef CGAL_FDT3_INTERNAL_MESHER_MESH_WRITERS_H
#define CGAL_FDT3_INTERNAL_MESHER_MESH_WRITERS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Mesh_file_writers.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedral_mesh.h>

#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

typedef CGAL::Fast_mesher_3::Tetrahedral_mesh Output_mesh;

// The mesh as a source of Mesh_file_writers.h.
class Tetrahedral_mesh_source
{
public:
  explicit Tetrahedral_mesh_source(const Output_mesh& mesh) : m_(mesh) {}
  std::size_t number_of_points() const { return m_.points.size(); }
  const double* point(std::size_t i) const { return m_.points[i].data(); }
  std::size_t number_of_tetrahedra() const { return m_.tetrahedra.size(); }
  std::size_t number_of_triangles() const { return m_.triangles.size(); }
  int number_of_subdomains() const { return m_.number_of_subdomains; }
  int number_of_surfaces() const { return m_.number_of_surfaces; }
  template <class F>
  void for_each_tetrahedron(F f) const
  {
    for(std::size_t t = 0; t < m_.tetrahedra.size(); ++t) f(m_.tetrahedra[t].data(), m_.subdomain[t]);
  }
  template <class F>
  void for_each_triangle(F f) const
  {
    for(std::size_t t = 0; t < m_.triangles.size(); ++t) f(m_.triangles[t].data(), m_.surface[t]);
  }

private:
  const Output_mesh& m_;
};

// Picks the format from the extension: .mesh, .vtu or .msh.
inline void write_mesh_file(const std::string& path, const Output_mesh& mesh)
{
  std::ofstream out(path, std::ios::binary);
  if(!out) throw std::runtime_error("Tetrahedral_mesher: cannot write '" + path + "'");
  const Tetrahedral_mesh_source source(mesh);
  if(ends_with(path, ".mesh")) write_medit(out, source);
  else if(ends_with(path, ".vtu")) write_vtu(out, source);
  else if(ends_with(path, ".msh")) write_msh41(out, source);
  else throw std::invalid_argument("Tetrahedral_mesher: unknown output format for '" + path +
                                   "' (use .mesh, .vtu or .msh)");
  if(!out) throw std::runtime_error("Tetrahedral_mesher: error while writing '" + path + "'");
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_MESH_WRITERS_H
