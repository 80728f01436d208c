// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher's output as plain arrays, the form every writer and the
// quality report read: vertices, tetrahedra with their subdomain (1, 2, ...),
// boundary triangles with the number of the input surface they come from.
// Extracted from the constrained mesh without its outside (subdomain 0) and
// ghost tetrahedra, vertices renumbered densely.

#ifndef CGAL_FDT3_INTERNAL_MESHER_TETRAHEDRAL_MESH_H
#define CGAL_FDT3_INTERNAL_MESHER_TETRAHEDRAL_MESH_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_mesher_3 {

// Tetrahedra are positively oriented (CGAL's orientation); triangles keep
// the orientation of the input surface.
struct Tetrahedral_mesh
{
  std::vector<std::array<double, 3>> points;
  std::vector<double> size;                      // target h at each point
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  std::vector<int> subdomain;                    // per tetrahedron, from 1
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<int> surface;                      // per triangle, from 1
  int number_of_subdomains = 0;
  int number_of_surfaces = 0;
};

} // namespace Fast_mesher_3

namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

// What makes `mesh` unreadable by index, or empty if nothing: subdomain
// tags other than one per tetrahedron, sizes neither one per point nor
// none, a tetrahedron referring to a point the mesh lacks.  The callers
// that take a user's mesh (improve_mesh, quality_report) refuse it with
// this text after their own name.
inline std::string index_defect(const CGAL::Fast_mesher_3::Tetrahedral_mesh& mesh)
{
  const std::size_t n = mesh.points.size();
  if(mesh.subdomain.size() != mesh.tetrahedra.size())
    return std::to_string(mesh.subdomain.size()) + " subdomain tags for " + std::to_string(mesh.tetrahedra.size()) +
           " tetrahedra";
  if(!mesh.size.empty() && mesh.size.size() != n)
    return std::to_string(mesh.size.size()) + " sizes for " + std::to_string(n) +
           " points (give one per point, or none)";
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for(std::uint32_t v : mesh.tetrahedra[t])
      if(v >= n)
        return "tetrahedron #" + std::to_string(t) + " refers to point #" + std::to_string(v) + ", past the " +
               std::to_string(n) + " points";
  return std::string();
}

inline CGAL::Fast_mesher_3::Tetrahedral_mesh extract_mesh(const Constrained_mesh& cm,
                                                                         const Surface_soup& soup)
{
  CGAL::Fast_mesher_3::Tetrahedral_mesh out;
  const Flat_storage& m = cm.mesh;
  const std::uint32_t unused = std::uint32_t(-1);
  std::vector<std::uint32_t> number(m.vertices.size(), unused);
  auto number_of = [&](Vertex_id v) {
    if(number[v] == unused) {
      number[v] = static_cast<std::uint32_t>(out.points.size());
      out.points.push_back({m.point(v)[0], m.point(v)[1], m.point(v)[2]});
      out.size.push_back(cm.size[v]);
    }
    return number[v];
  };
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || cm.subdomain[t] <= 0) continue;
    const Vertex_id* tv = m.vertex_ids(t);
    out.tetrahedra.push_back({number_of(tv[0]), number_of(tv[1]), number_of(tv[2]), number_of(tv[3])});
    out.subdomain.push_back(cm.subdomain[t]);
  }
  for(std::size_t t = 0; t < soup.triangles.size(); ++t) {
    std::array<std::uint32_t, 3> tri;
    for(int i = 0; i < 3; ++i) tri[i] = number_of(cm.vertex_of_input[soup.triangles[t][i]]);
    out.triangles.push_back(tri);
    out.surface.push_back(soup.surface[t]);
  }
  out.number_of_subdomains = cm.number_of_subdomains;
  out.number_of_surfaces = soup.number_of_surfaces;
  return out;
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_TETRAHEDRAL_MESH_H
