// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher's writers, read back by small readers written here from the
// formats' specifications (Medit .mesh, Gmsh 4.1 .msh, VTK .vtu with raw
// appended arrays), not from the writers: same points bit for bit, same
// tetrahedra, subdomains, triangles and surface numbers.

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <gtest/gtest.h>

#include "mesher_shapes.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_mesher_output {

namespace fm = CGAL::Fast_mesher_3;

std::string temporary(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("fdt3_mesher_output_" + name)).string();
}

const fm::Tetrahedral_mesh& nested_spheres_mesh()
{
  static const fm::Tetrahedral_mesh mesh = [] {
    const mesher_shapes::Surface s = mesher_shapes::combine(mesher_shapes::icosphere(1, 1.0),
                                                            mesher_shapes::icosphere(0, 0.4, {0.02, 0.01, 0}));
    fm::Mesher_options options;
    options.maximum_size = 0.3;
    return fm::mesh_surfaces(s.points, s.triangles, options);
  }();
  return mesh;
}

// Medit: keyword sections; indices from 1; a reference after each element.
fm::Tetrahedral_mesh read_medit(const std::string& path)
{
  fm::Tetrahedral_mesh m;
  std::ifstream in(path);
  std::string word;
  while(in >> word) {
    std::size_t n = 0;
    if(word == "Vertices") {
      in >> n;
      m.points.resize(n);
      int reference;
      for(auto& p : m.points) in >> p[0] >> p[1] >> p[2] >> reference;
    } else if(word == "Triangles") {
      in >> n;
      m.triangles.resize(n);
      m.surface.resize(n);
      for(std::size_t t = 0; t < n; ++t) {
        for(auto& v : m.triangles[t]) { in >> v; --v; }
        in >> m.surface[t];
      }
    } else if(word == "Tetrahedra") {
      in >> n;
      m.tetrahedra.resize(n);
      m.subdomain.resize(n);
      for(std::size_t t = 0; t < n; ++t) {
        for(auto& v : m.tetrahedra[t]) { in >> v; --v; }
        in >> m.subdomain[t];
      }
    }
  }
  return m;
}

// Gmsh 4.1 ASCII: node blocks (tags, then coordinates), element blocks by
// entity (type 2 triangles on surfaces, type 4 tetrahedra in volumes).
fm::Tetrahedral_mesh read_msh41(const std::string& path)
{
  fm::Tetrahedral_mesh m;
  std::ifstream in(path);
  std::string line;
  std::map<std::size_t, std::size_t> index_of_tag;
  while(std::getline(in, line)) {
    if(line == "$MeshFormat") {
      std::string version;
      in >> version;
      if(version != "4.1") throw std::runtime_error("not 4.1");
    } else if(line == "$Nodes") {
      std::size_t blocks, nodes, lo, hi;
      in >> blocks >> nodes >> lo >> hi;
      for(std::size_t b = 0; b < blocks; ++b) {
        int dim, tag, parametric;
        std::size_t count;
        in >> dim >> tag >> parametric >> count;
        std::vector<std::size_t> tags(count);
        for(auto& t : tags) in >> t;
        for(std::size_t k = 0; k < count; ++k) {
          std::array<double, 3> p;
          in >> p[0] >> p[1] >> p[2];
          index_of_tag[tags[k]] = m.points.size();
          m.points.push_back(p);
        }
      }
    } else if(line == "$Elements") {
      std::size_t blocks, elements, lo, hi;
      in >> blocks >> elements >> lo >> hi;
      for(std::size_t b = 0; b < blocks; ++b) {
        int dim, entity, type;
        std::size_t count;
        in >> dim >> entity >> type >> count;
        for(std::size_t k = 0; k < count; ++k) {
          std::size_t tag, v;
          in >> tag;
          if(type == 2) {
            std::array<std::uint32_t, 3> t;
            for(auto& x : t) { in >> v; x = static_cast<std::uint32_t>(index_of_tag.at(v)); }
            m.triangles.push_back(t);
            m.surface.push_back(entity);
          } else if(type == 4) {
            std::array<std::uint32_t, 4> t;
            for(auto& x : t) { in >> v; x = static_cast<std::uint32_t>(index_of_tag.at(v)); }
            m.tetrahedra.push_back(t);
            m.subdomain.push_back(entity);
          } else {
            throw std::runtime_error("unexpected element type");
          }
        }
      }
    }
  }
  return m;
}

typedef std::map<std::array<std::uint32_t, 4>, int> Tetrahedra_by_vertices;

Tetrahedra_by_vertices tetrahedra_by_vertices(const fm::Tetrahedral_mesh& m)
{
  Tetrahedra_by_vertices result;
  for(std::size_t t = 0; t < m.tetrahedra.size(); ++t) result[m.tetrahedra[t]] = m.subdomain[t];
  return result;
}

TEST(MesherOutput, MeditReadsBackExactly)
{
  const fm::Tetrahedral_mesh& mesh = nested_spheres_mesh();
  ASSERT_EQ(mesh.number_of_subdomains, 2);
  const std::string path = temporary("nested.mesh");
  fm::write_mesh(path, mesh);
  const fm::Tetrahedral_mesh back = read_medit(path);
  EXPECT_EQ(back.points, mesh.points);
  EXPECT_EQ(back.tetrahedra, mesh.tetrahedra);
  EXPECT_EQ(back.subdomain, mesh.subdomain);
  EXPECT_EQ(back.triangles, mesh.triangles);
  EXPECT_EQ(back.surface, mesh.surface);
  std::remove(path.c_str());
}

TEST(MesherOutput, Gmsh41ReadsBackExactly)
{
  const fm::Tetrahedral_mesh& mesh = nested_spheres_mesh();
  const std::string path = temporary("nested.msh");
  fm::write_mesh(path, mesh);
  const fm::Tetrahedral_mesh back = read_msh41(path);
  EXPECT_EQ(back.points, mesh.points);
  // Elements are grouped by entity: compare as sets with their tags.
  EXPECT_EQ(tetrahedra_by_vertices(back), tetrahedra_by_vertices(mesh));
  ASSERT_EQ(back.triangles.size(), mesh.triangles.size());
  std::map<std::array<std::uint32_t, 3>, int> wanted, got;
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t) wanted[mesh.triangles[t]] = mesh.surface[t];
  for(std::size_t t = 0; t < back.triangles.size(); ++t) got[back.triangles[t]] = back.surface[t];
  EXPECT_EQ(got, wanted);
  std::remove(path.c_str());
}

// VTK XML with the arrays appended raw (header_type UInt64): each array's
// bytes at the offset its DataArray declares, after the '_' that opens the
// appended data, behind a 64-bit byte count.
std::string vtu_array(const std::string& text, const std::string& name)
{
  const std::size_t declared = text.find("Name=\"" + name + "\"");
  if(declared == std::string::npos) return std::string();
  const std::size_t at = text.find("offset=\"", declared) + 8;
  const std::size_t offset = std::stoul(text.substr(at, text.find('"', at) - at));
  const std::size_t start = text.find('_', text.find("<AppendedData")) + 1 + offset;
  std::uint64_t bytes;
  std::memcpy(&bytes, text.data() + start, 8);
  return text.substr(start + 8, bytes);
}

TEST(MesherOutput, VtuHasTheCellsAndArrays)
{
  const fm::Tetrahedral_mesh& mesh = nested_spheres_mesh();
  const std::string path = temporary("nested.vtu");
  fm::write_mesh(path, mesh);
  std::ifstream in(path, std::ios::binary);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::ostringstream header;
  const std::size_t cells = mesh.tetrahedra.size() + mesh.triangles.size();
  header << "NumberOfPoints=\"" << mesh.points.size() << "\" NumberOfCells=\"" << cells << "\"";
  EXPECT_NE(text.find(header.str()), std::string::npos);
  // The types: one 10 per tetrahedron, then one 5 per triangle.
  const std::string types = vtu_array(text, "types");
  ASSERT_EQ(types.size(), cells);
  EXPECT_EQ(std::size_t(std::count(types.begin(), types.begin() + mesh.tetrahedra.size(), char(10))),
            mesh.tetrahedra.size());
  EXPECT_EQ(std::size_t(std::count(types.begin() + mesh.tetrahedra.size(), types.end(), char(5))),
            mesh.triangles.size());
  // The cell arrays: subdomain of each tetrahedron (0 for triangles),
  // surface of each triangle (0 for tetrahedra).
  const std::string subdomain = vtu_array(text, "subdomain"), surface = vtu_array(text, "surface");
  ASSERT_EQ(subdomain.size(), 4 * cells);
  ASSERT_EQ(surface.size(), 4 * cells);
  for(std::size_t c = 0; c < cells; ++c) {
    std::int32_t d, s;
    std::memcpy(&d, subdomain.data() + 4 * c, 4);
    std::memcpy(&s, surface.data() + 4 * c, 4);
    const bool tetrahedron = c < mesh.tetrahedra.size();
    ASSERT_EQ(d, tetrahedron ? mesh.subdomain[c] : 0) << "cell " << c;
    ASSERT_EQ(s, tetrahedron ? 0 : mesh.surface[c - mesh.tetrahedra.size()]) << "cell " << c;
  }
  // The connectivity: the tetrahedra's then the triangles' vertices.
  const std::string connectivity = vtu_array(text, "connectivity");
  ASSERT_EQ(connectivity.size(), 4 * (4 * mesh.tetrahedra.size() + 3 * mesh.triangles.size()));
  std::vector<std::int32_t> ids(connectivity.size() / 4);
  std::memcpy(ids.data(), connectivity.data(), connectivity.size());
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for(int k = 0; k < 4; ++k) ASSERT_EQ(std::uint32_t(ids[4 * t + k]), mesh.tetrahedra[t][k]);
  for(std::size_t t = 0; t < mesh.triangles.size(); ++t)
    for(int k = 0; k < 3; ++k)
      ASSERT_EQ(std::uint32_t(ids[4 * mesh.tetrahedra.size() + 3 * t + k]), mesh.triangles[t][k]);
  std::remove(path.c_str());
}

TEST(MesherOutput, UnknownExtensionIsRefused)
{
  EXPECT_THROW(fm::write_mesh(temporary("nested.xyz"), nested_spheres_mesh()), std::invalid_argument);
}

} // namespace test_mesher_output
