// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher's result handed to CGAL as a Mesh_complex_3_in_triangulation_3
// on a Remeshing_triangulation_3: CGAL's own validity check, the complex's
// counts against the arrays, and CGAL's tetrahedral remeshing running on it.

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <gtest/gtest.h>

#include "mesher_shapes.h"

#include <cmath>
#include <set>

namespace test_mesher_c3t3 {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<K> Remeshing_triangulation;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Remeshing_triangulation> C3t3;

TEST(MesherC3t3, NestedSpheresInCgalsComplex)
{
  const mesher_shapes::Surface outer = mesher_shapes::icosphere(1, 1.0);
  const mesher_shapes::Surface inner = mesher_shapes::icosphere(0, 0.4, {0.02, 0.01, 0});
  const mesher_shapes::Surface both = mesher_shapes::combine(outer, inner);
  CGAL::Fast_mesher_3::Mesher_options options;
  options.maximum_size = 0.3;
  C3t3 c3t3;
  const CGAL::Fast_mesher_3::Tetrahedral_mesh mesh =
      CGAL::Fast_mesher_3::mesh_surfaces_to_c3t3(both.points, both.triangles, c3t3, options);

  EXPECT_TRUE(c3t3.triangulation().is_valid());
  EXPECT_EQ(c3t3.number_of_cells_in_complex(), mesh.tetrahedra.size());
  EXPECT_EQ(c3t3.number_of_facets_in_complex(), both.triangles.size());
  std::set<int> subdomains;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    subdomains.insert(c3t3.subdomain_index(c));
    EXPECT_FALSE(c3t3.triangulation().is_infinite(c));
  }
  EXPECT_EQ(subdomains, (std::set<int>{1, 2}));
  std::set<int> patches;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    patches.insert(c3t3.surface_patch_index(*f));
  // The remeshing triangulation's patch index is an int: the surface number.
  EXPECT_EQ(patches, (std::set<int>{1, 2}));

  // CGAL's remeshing runs on it with the surface protected: the volume of
  // the complex stays the volume the outer surface encloses.
  CGAL::tetrahedral_isotropic_remeshing(
      c3t3, 0.25, CGAL::parameters::number_of_iterations(1).remesh_boundaries(false));
  EXPECT_TRUE(c3t3.triangulation().is_valid());
  double volume = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    volume += c3t3.triangulation().tetrahedron(c).volume();
  const double enclosed = std::abs(mesher_shapes::enclosed_volume(outer));
  EXPECT_NEAR(volume, enclosed, 1e-9 * enclosed);
}

} // namespace test_mesher_c3t3
