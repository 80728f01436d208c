// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher on closed surfaces: cube, sphere, torus, two nested spheres, and
// two of CGAL's own data surfaces (libcgal-demo).
// Every check is independent of the mesher's own report: orientation by
// CGAL's exact predicate, volumes against the volume the surface encloses,
// the boundary rebuilt from the tetrahedra and compared, by coordinates,
// with the input triangles.

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include "mesher_checks.h"
#include "cgal_data_surface.h"
#include "mesher_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_mesher_shapes {

using mesher_shapes::read_cgal_data_surface;

using namespace mesher_checks;

Mesh mesh_and_check_one_volume(const Surface& s, double maximum_size,
                                CGAL::Fast_mesher_3::Mesher_statistics& stats, int improvement_passes = 10)
{
  CGAL::Fast_mesher_3::Mesher_options options;
  options.maximum_size = maximum_size;
  options.max_improvement_passes = improvement_passes;
  Mesh mesh = CGAL::Fast_mesher_3::mesh_surfaces(s.points, s.triangles, options, &stats);
  EXPECT_EQ(mesh.number_of_subdomains, 1);
  expect_every_tetrahedron_tagged(mesh);
  expect_all_positive(mesh);
  expect_boundary_is_input(mesh, s);
  const double enclosed = std::abs(mesher_shapes::enclosed_volume(s));
  EXPECT_NEAR(volume_of_subdomain(mesh, 1), enclosed, 1e-9 * enclosed);
  EXPECT_GT(stats.refinement_points, 0u) << "the refinement inserted nothing";
  return mesh;
}

TEST(Mesher, Cube)
{
  CGAL::Fast_mesher_3::Mesher_statistics stats;
  const Mesh mesh = mesh_and_check_one_volume(mesher_shapes::cube(0, 1), 0.2, stats);
  // The cube's diagonals are not Delaunay-unique: the one component, the whole
  // mesh, is beyond our flips and goes to TetGen.
  EXPECT_TRUE(stats.used_tetgen);
  // Interior points exist: the 8 corners alone cannot hold tetrahedra of radius <= 1.4 h.
  EXPECT_GT(mesh.points.size(), 50u);
}

TEST(Mesher, Sphere)
{
  const Surface s = mesher_shapes::icosphere(2);
  CGAL::Fast_mesher_3::Mesher_statistics stats;
  const Mesh mesh = mesh_and_check_one_volume(s, 0.15, stats);
  // A convex surface of Delaunay triangles: the empty mesh already has them all.
  EXPECT_EQ(stats.missing_triangles, 0u);
  EXPECT_FALSE(stats.used_tetgen);
  EXPECT_GT(mesh.points.size(), s.points.size());
}

TEST(Mesher, Torus)
{
  CGAL::Fast_mesher_3::Mesher_statistics stats;
  mesh_and_check_one_volume(mesher_shapes::torus(1.0, 0.35, 24, 10), 0.2, stats);
  EXPECT_GT(stats.missing_triangles, 0u); // the hole's side is not Delaunay: recovery needed
}

TEST(Mesher, NestedSpheresGiveTwoSubdomains)
{
  const Surface outer = mesher_shapes::icosphere(2, 1.0);
  const Surface inner = mesher_shapes::icosphere(1, 0.45, {0.05, -0.02, 0.03});
  const Surface both = mesher_shapes::combine(outer, inner);
  CGAL::Fast_mesher_3::Mesher_options options;
  options.maximum_size = 0.2;
  const Mesh mesh = CGAL::Fast_mesher_3::mesh_surfaces(both.points, both.triangles, options);
  ASSERT_EQ(mesh.number_of_subdomains, 2);
  EXPECT_EQ(mesh.number_of_surfaces, 2);
  expect_every_tetrahedron_tagged(mesh);
  expect_all_positive(mesh);
  expect_boundary_is_input(mesh, both);
  const double v_outer = std::abs(mesher_shapes::enclosed_volume(outer));
  const double v_inner = std::abs(mesher_shapes::enclosed_volume(inner));
  const double v1 = volume_of_subdomain(mesh, 1), v2 = volume_of_subdomain(mesh, 2);
  // Which subdomain is the shell depends on slot order: accept either numbering.
  const double shell = std::max(v1, v2), ball = std::min(v1, v2);
  EXPECT_NEAR(ball, v_inner, 1e-9 * v_outer);
  EXPECT_NEAR(shell, v_outer - v_inner, 1e-9 * v_outer);
  // Boundary triangles carry the number of their surface.
  for(std::size_t t = 0; t < both.triangles.size(); ++t)
    EXPECT_EQ(mesh.surface[t], t < outer.triangles.size() ? 1 : 2);
}

TEST(Mesher, SameInputSameMesh)
{
  // Sequential refinement: the same input gives the same mesh, bit for bit.
  const Surface s = mesher_shapes::torus(1.0, 0.35, 24, 10);
  CGAL::Fast_mesher_3::Mesher_options options;
  options.maximum_size = 0.15;
  const Mesh a = CGAL::Fast_mesher_3::mesh_surfaces(s.points, s.triangles, options);
  const Mesh b = CGAL::Fast_mesher_3::mesh_surfaces(s.points, s.triangles, options);
  EXPECT_EQ(a.points, b.points);
  EXPECT_EQ(a.tetrahedra, b.tetrahedra);
  EXPECT_EQ(a.subdomain, b.subdomain);
}

TEST(Mesher, QualityReportAgreesWithIndependentChecks)
{
  const Surface s = mesher_shapes::icosphere(2);
  CGAL::Fast_mesher_3::Mesher_options options;
  options.maximum_size = 0.2;
  const Mesh mesh = CGAL::Fast_mesher_3::mesh_surfaces(s.points, s.triangles, options);
  const CGAL::Fast_mesher_3::Quality_report q = CGAL::Fast_mesher_3::quality_report(mesh);
  EXPECT_TRUE(q.boundary_equals_input());
  EXPECT_EQ(q.inverted_tetrahedra, 0u);
  EXPECT_EQ(q.tetrahedra, mesh.tetrahedra.size());
  // Extreme dihedral angles recomputed with CGAL's own function (no sliver
  // removal yet: near-flat slivers are possible, so only the agreement is tested).
  double min_angle = 180, max_angle = 0;
  for(const auto& t : mesh.tetrahedra)
    for(int a = 0; a < 4; ++a)
      for(int b = a + 1; b < 4; ++b) {
        int others[2], k = 0;
        for(int i = 0; i < 4; ++i)
          if(i != a && i != b) others[k++] = i;
        const double angle = std::abs(CGAL::approximate_dihedral_angle(
            point(mesh, t[a]), point(mesh, t[b]), point(mesh, t[others[0]]), point(mesh, t[others[1]])));
        min_angle = std::min(min_angle, angle);
        max_angle = std::max(max_angle, angle);
      }
  EXPECT_NEAR(q.min_dihedral_degrees, min_angle, 1e-6);
  EXPECT_NEAR(q.max_dihedral_degrees, max_angle, 1e-6);
  std::size_t histogram_total = 0;
  for(std::size_t n : q.radius_edge_histogram) histogram_total += n;
  EXPECT_EQ(histogram_total, mesh.tetrahedra.size());

  // A mesh with one boundary triangle removed is reported.
  Mesh broken = mesh;
  broken.triangles.pop_back();
  EXPECT_FALSE(CGAL::Fast_mesher_3::quality_report(broken).boundary_equals_input());

  // A mesh the report would read past is refused, the defect named.
  auto expect_refused = [](const Mesh& bad, const std::string& words) {
    try {
      CGAL::Fast_mesher_3::quality_report(bad, 2);
      ADD_FAILURE() << "reported on a mesh with " << words;
    } catch(const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  ASSERT_GT(mesh.tetrahedra.size(), 5u);
  Mesh past_the_points = mesh;
  past_the_points.tetrahedra[5][3] = static_cast<std::uint32_t>(mesh.points.size());
  expect_refused(past_the_points, "quality_report: tetrahedron #5 refers to point #" +
                                      std::to_string(mesh.points.size()) + ", past the");
  Mesh untagged = mesh;
  untagged.subdomain.pop_back();
  expect_refused(untagged, "subdomain tags for " + std::to_string(mesh.tetrahedra.size()) + " tetrahedra");
  Mesh short_of_sizes = mesh;
  short_of_sizes.size.pop_back();
  expect_refused(short_of_sizes, std::to_string(mesh.size.size() - 1) + " sizes for " +
                                     std::to_string(mesh.points.size()) + " points");
  // Without sizes (what improve_mesh returns for a mesh without them) the
  // edges are counted, not measured.
  Mesh without_sizes = mesh;
  without_sizes.size.clear();
  const CGAL::Fast_mesher_3::Quality_report unsized = CGAL::Fast_mesher_3::quality_report(without_sizes, 2);
  EXPECT_TRUE(q.has_sizes);
  EXPECT_FALSE(unsized.has_sizes);
  EXPECT_EQ(unsized.edges, q.edges);
  EXPECT_EQ(unsized.edges_below_0_7h, 0u);
  EXPECT_EQ(unsized.max_edge_over_h, 0.0);
  EXPECT_EQ(unsized.tetrahedra_below_gamma_0_3, q.tetrahedra_below_gamma_0_3);
}

// The report's loops on two threads give every figure of one thread's.
TEST(Mesher, QualityReportSameOnTwoThreads)
{
  const Surface s = mesher_shapes::cube();
  CGAL::Fast_mesher_3::Mesher_options options;
  options.maximum_size = 0.04;
  options.optimize = false; // the cube's two triangles a face leave flat tetrahedra the improvement would work on
  const Mesh mesh = CGAL::Fast_mesher_3::mesh_surfaces(s.points, s.triangles, options);
  ASSERT_GT(mesh.tetrahedra.size(), 40000u); // two chunks of at least 16384
  const CGAL::Fast_mesher_3::Quality_report a = CGAL::Fast_mesher_3::quality_report(mesh, 1);
  const CGAL::Fast_mesher_3::Quality_report b = CGAL::Fast_mesher_3::quality_report(mesh, 2);
  EXPECT_EQ(a.tetrahedra_per_subdomain, b.tetrahedra_per_subdomain);
  EXPECT_EQ(a.min_dihedral_degrees, b.min_dihedral_degrees);
  EXPECT_EQ(a.max_dihedral_degrees, b.max_dihedral_degrees);
  EXPECT_EQ(a.min_dihedral_1st_percentile, b.min_dihedral_1st_percentile);
  EXPECT_EQ(a.mean_min_dihedral, b.mean_min_dihedral);
  EXPECT_EQ(a.min_dihedral_histogram, b.min_dihedral_histogram);
  EXPECT_EQ(a.tetrahedra_below_10_degrees, b.tetrahedra_below_10_degrees);
  EXPECT_EQ(a.min_gamma, b.min_gamma);
  EXPECT_EQ(a.gamma_1st_percentile, b.gamma_1st_percentile);
  EXPECT_EQ(a.mean_gamma, b.mean_gamma);
  EXPECT_EQ(a.gamma_histogram, b.gamma_histogram);
  EXPECT_EQ(a.tetrahedra_below_gamma_0_3, b.tetrahedra_below_gamma_0_3);
  EXPECT_EQ(a.tetrahedra_forced_below_gamma_0_3, b.tetrahedra_forced_below_gamma_0_3);
  EXPECT_EQ(a.radius_edge_histogram, b.radius_edge_histogram);
  EXPECT_EQ(a.max_radius_edge, b.max_radius_edge);
  EXPECT_EQ(a.edges, b.edges);
  EXPECT_EQ(a.edges_below_0_7h, b.edges_below_0_7h);
  EXPECT_EQ(a.min_edge_over_h, b.min_edge_over_h);
  EXPECT_EQ(a.max_edge_over_h, b.max_edge_over_h);
  EXPECT_EQ(a.mean_edge_over_h, b.mean_edge_over_h);
  EXPECT_EQ(a.inverted_tetrahedra, b.inverted_tetrahedra);
  EXPECT_EQ(a.missing_input_triangles, b.missing_input_triangles);
  EXPECT_EQ(a.extra_boundary_facets, b.extra_boundary_facets);
  std::size_t in_histogram = 0;
  for(std::size_t k : b.gamma_histogram) in_histogram += k;
  EXPECT_EQ(in_histogram, mesh.tetrahedra.size());
}

// A cube of cells^3 unit cells, each cut into the 6 tetrahedra around its
// diagonal from (i, j, k) to (i + 1, j + 1, k + 1); subdomain 1 where x <
// cells / 2, 2 beyond; h varies from vertex to vertex, from 0.9 to 1.7.
Mesh cut_cube_grid(int cells)
{
  Mesh mesh;
  const int side = cells + 1;
  auto id = [&](int i, int j, int k) { return std::uint32_t(i + side * (j + side * k)); };
  for(int k = 0; k < side; ++k)
    for(int j = 0; j < side; ++j)
      for(int i = 0; i < side; ++i) mesh.points.push_back({double(i), double(j), double(k)});
  for(std::size_t v = 0; v < mesh.points.size(); ++v) mesh.size.push_back(0.9 + 0.8 * double((v * 7919) % 13) / 13);
  const int axes[6][3] = {{0, 1, 2}, {0, 2, 1}, {1, 0, 2}, {1, 2, 0}, {2, 0, 1}, {2, 1, 0}};
  for(int k = 0; k < cells; ++k)
    for(int j = 0; j < cells; ++j)
      for(int i = 0; i < cells; ++i)
        for(const auto& order : axes) {
          int corner[3] = {i, j, k};
          std::array<std::uint32_t, 4> tetrahedron;
          tetrahedron[0] = id(corner[0], corner[1], corner[2]);
          for(int step = 0; step < 3; ++step) {
            ++corner[order[step]];
            tetrahedron[step + 1] = id(corner[0], corner[1], corner[2]);
          }
          mesh.tetrahedra.push_back(tetrahedron);
          mesh.subdomain.push_back(2 * i < cells ? 1 : 2);
        }
  mesh.number_of_subdomains = 2;
  return mesh;
}

// The report's edge and facet figures are those of the sorted lists of the
// mesh's edges and facets, on 1 and 2 threads (35,937 vertices: two chunks
// of its vertex loop), with flat tetrahedra of a repeated vertex, and input
// triangles of every kind: boundary facets (one left out), a copy, one of a
// point the mesh does not have, one that is no facet (twice), and a facet
// inside a subdomain.
TEST(Mesher, QualityReportEdgesAndFacetsAsListsCountThem)
{
  Mesh mesh = cut_cube_grid(32);
  ASSERT_GE(mesh.points.size(), 32768u);
  mesh.tetrahedra.push_back({0, 0, 100, 200});
  mesh.tetrahedra.push_back({300, 400, 400, 500});
  mesh.subdomain.push_back(1);
  mesh.subdomain.push_back(1);

  typedef std::array<std::uint32_t, 3> Facet;
  std::vector<std::pair<Facet, int>> facet_sides;
  std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& v = mesh.tetrahedra[t];
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) edges.push_back({std::min(v[i], v[j]), std::max(v[i], v[j])});
    for(int f = 0; f < 4; ++f) {
      Facet facet;
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != f) facet[k++] = v[i];
      std::sort(facet.begin(), facet.end());
      facet_sides.push_back({facet, mesh.subdomain[t]});
    }
  }
  std::sort(edges.begin(), edges.end());
  edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
  std::sort(facet_sides.begin(), facet_sides.end());
  std::vector<Facet> boundary, inside;
  for(std::size_t k = 0; k < facet_sides.size();) {
    std::size_t end = k;
    while(end < facet_sides.size() && facet_sides[end].first == facet_sides[k].first) ++end;
    const bool on_boundary = end - k == 1 || (end - k == 2 && facet_sides[k].second != facet_sides[k + 1].second);
    (on_boundary ? boundary : inside).push_back(facet_sides[k].first);
    k = end;
  }
  auto is_facet = [&](const Facet& f) {
    return std::binary_search(boundary.begin(), boundary.end(), f) ||
           std::binary_search(inside.begin(), inside.end(), f);
  };
  // Outside: 6 * 2 * 32^2 triangles, the interface 2 * 32^2, the flat
  // tetrahedra's facets with a repeated vertex 4.
  ASSERT_EQ(boundary.size(), 14u * 32 * 32 + 4);
  const Facet no_facet = {0, 1, 40}, inner_facet = inside[inside.size() / 2];
  ASSERT_FALSE(is_facet(no_facet));
  mesh.triangles.assign(boundary.begin() + 1, boundary.end()); // one left out
  mesh.triangles.push_back(boundary.back());                   // a copy
  mesh.triangles.push_back({0, 1, std::uint32_t(mesh.points.size())});
  mesh.triangles.push_back(no_facet);
  mesh.triangles.push_back(no_facet);
  mesh.triangles.push_back(inner_facet);

  // The report's own distance: the same roundings, so min and max compare exactly.
  using CGAL::Fast_Delaunay_triangulation_3_internal::mesher::distance;
  double min_ratio = std::numeric_limits<double>::infinity(), max_ratio = 0, sum = 0;
  std::size_t below = 0;
  for(const auto& e : edges) {
    const double ratio = distance(mesh.points[e.first].data(), mesh.points[e.second].data()) /
                         ((mesh.size[e.first] + mesh.size[e.second]) / 2);
    min_ratio = std::min(min_ratio, ratio);
    max_ratio = std::max(max_ratio, ratio);
    sum += ratio;
    below += ratio < 0.7 ? 1 : 0;
  }
  EXPECT_EQ(min_ratio, 0); // the edges (0, 0) and (400, 400)
  EXPECT_GT(below, 2u);

  const CGAL::Fast_mesher_3::Quality_report one = CGAL::Fast_mesher_3::quality_report(mesh, 1);
  const CGAL::Fast_mesher_3::Quality_report two = CGAL::Fast_mesher_3::quality_report(mesh, 2);
  for(const CGAL::Fast_mesher_3::Quality_report* q : {&one, &two}) {
    EXPECT_EQ(q->edges, edges.size());
    EXPECT_EQ(q->edges_below_0_7h, below);
    EXPECT_EQ(q->min_edge_over_h, min_ratio);
    EXPECT_EQ(q->max_edge_over_h, max_ratio);
    EXPECT_NEAR(q->mean_edge_over_h, sum / edges.size(), 1e-10); // sums of 230,000 ratios in two orders
    // Missing: the triangle of a point the mesh does not have, the one that
    // is no facet twice, the inner facet.  Extra: the boundary facet left out.
    EXPECT_EQ(q->missing_input_triangles, 4u);
    EXPECT_EQ(q->extra_boundary_facets, 1u);
  }
  EXPECT_EQ(one.mean_edge_over_h, two.mean_edge_over_h);
}

// CGAL's elephant: a fine organic surface whose triangles the empty mesh
// already has (no TetGen), h from the surface alone.
TEST(Mesher, CgalDataElephant)
{
  Surface s;
  if(!read_cgal_data_surface("elephant.off", s))
    GTEST_SKIP() << FDT3_CGAL_DATA_DIR "/elephant.off is missing (apt install libcgal-demo, re-run CMake)";
  CGAL::Fast_mesher_3::Mesher_statistics stats;
  mesh_and_check_one_volume(s, std::numeric_limits<double>::infinity(), stats);
}

// CGAL's couplingdown, a mechanical part: long thin triangles on flat faces
// and holes, hundreds of them missing from the empty mesh (the local recovery,
// by flips and by TetGen on small components).
TEST(Mesher, CgalDataMechanicalPart)
{
  Surface s;
  if(!read_cgal_data_surface("couplingdown.off", s))
    GTEST_SKIP() << FDT3_CGAL_DATA_DIR "/couplingdown.off is missing (apt install libcgal-demo, re-run CMake)";
  CGAL::Fast_mesher_3::Mesher_statistics stats;
  // The recovery is what this is about; couplingdown's improvement works
  // for seconds on tetrahedra its thin walls force (the manual says why):
  // two passes of each phase run every operation on it.
  mesh_and_check_one_volume(s, std::numeric_limits<double>::infinity(), stats, 2);
  EXPECT_GT(stats.missing_triangles, 0u);
  EXPECT_TRUE(stats.used_tetgen);
  EXPECT_GT(stats.improvement.steiner_points, 0u);
}

} // namespace test_mesher_shapes
