// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Checks of a mesher's output that do not trust the mesher: orientation by
// CGAL's exact predicate, volumes by CGAL, the boundary rebuilt from the
// tetrahedra and compared, by coordinates, with the input triangles.

#ifndef FDT3_TEST_MESHER_CHECKS_H
#define FDT3_TEST_MESHER_CHECKS_H

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include "mesher_shapes.h"

#include <algorithm>
#include <array>
#include <map>
#include <set>
#include <vector>

namespace mesher_checks {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Fast_mesher_3::Tetrahedral_mesh Mesh;
using mesher_shapes::Surface;

typedef std::array<std::array<double, 3>, 3> Coordinates_triangle;

inline Coordinates_triangle sorted_triangle(std::array<double, 3> a, std::array<double, 3> b, std::array<double, 3> c)
{
  Coordinates_triangle t{{a, b, c}};
  std::sort(t.begin(), t.end());
  return t;
}

inline K::Point_3 point(const Mesh& mesh, std::uint32_t v)
{
  return K::Point_3(mesh.points[v][0], mesh.points[v][1], mesh.points[v][2]);
}

inline double tetrahedron_volume(const Mesh& mesh, const std::array<std::uint32_t, 4>& t)
{
  return CGAL::volume(point(mesh, t[0]), point(mesh, t[1]), point(mesh, t[2]), point(mesh, t[3]));
}

inline void expect_all_positive(const Mesh& mesh)
{
  std::size_t bad = 0;
  for(const auto& t : mesh.tetrahedra)
    if(CGAL::orientation(point(mesh, t[0]), point(mesh, t[1]), point(mesh, t[2]), point(mesh, t[3])) !=
       CGAL::POSITIVE)
      ++bad;
  EXPECT_EQ(bad, 0u) << "tetrahedra not positively oriented";
}

// Facets of the mesh that bound a subdomain (one tetrahedron, or two of
// different subdomains) must be the input triangles, and nothing else.
inline void expect_boundary_is_input(const Mesh& mesh, const Surface& input)
{
  std::map<Coordinates_triangle, std::vector<int>> sides;
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    for(int f = 0; f < 4; ++f) {
      std::array<std::array<double, 3>, 3> v;
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != f) v[k++] = mesh.points[mesh.tetrahedra[t][i]];
      sides[sorted_triangle(v[0], v[1], v[2])].push_back(mesh.subdomain[t]);
    }
  std::set<Coordinates_triangle> boundary;
  for(const auto& entry : sides) {
    ASSERT_LE(entry.second.size(), 2u) << "a facet shared by three tetrahedra";
    if(entry.second.size() == 1 || entry.second[0] != entry.second[1]) boundary.insert(entry.first);
  }
  std::set<Coordinates_triangle> wanted;
  for(const auto& t : input.triangles)
    wanted.insert(sorted_triangle(input.points[t[0]], input.points[t[1]], input.points[t[2]]));
  EXPECT_EQ(wanted.size(), input.triangles.size());
  EXPECT_TRUE(boundary == wanted) << boundary.size() << " boundary facets for " << wanted.size()
                                  << " input triangles";
}

inline double volume_of_subdomain(const Mesh& mesh, int s)
{
  double v = 0;
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t)
    if(mesh.subdomain[t] == s) v += tetrahedron_volume(mesh, mesh.tetrahedra[t]);
  return v;
}

inline void expect_every_tetrahedron_tagged(const Mesh& mesh)
{
  ASSERT_EQ(mesh.subdomain.size(), mesh.tetrahedra.size());
  for(int s : mesh.subdomain) {
    ASSERT_GE(s, 1);
    ASSERT_LE(s, mesh.number_of_subdomains);
  }
  std::set<int> used(mesh.subdomain.begin(), mesh.subdomain.end());
  EXPECT_EQ(static_cast<int>(used.size()), mesh.number_of_subdomains);
}

} // namespace mesher_checks

#endif // FDT3_TEST_MESHER_CHECKS_H
