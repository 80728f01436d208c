// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The boundary recovery (Boundary_recovery.h) on its own, before any
// refinement: the local path (flips of ours, TetGen on components) and the
// fallback (TetGen on the whole surface), each checked independently of the
// recovery's own report: every input triangle a facet on both of its sides,
// the surface points unmoved with their ids, no extra vertex on the surface,
// every tetrahedron positive (exact), the mesh still tiling the convex hull
// (its volume equal to the empty mesh's), the volume inside the surface
// equal to the volume the surface encloses.

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <gtest/gtest.h>

#include "cgal_data_surface.h"
#include "mesher_shapes.h"

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace test_mesher_recovery {

using mesher_shapes::read_cgal_data_surface;

namespace fm = CGAL::Fast_Delaunay_triangulation_3_internal::mesher;
namespace fi = CGAL::Fast_Delaunay_triangulation_3_internal;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
using mesher_shapes::Surface;

fm::Surface_soup soup_of(const Surface& s)
{
  return CGAL::Fast_mesher_3::mesher_detail::surfaces_from_triangles(s.points, s.triangles);
}

K::Point_3 point(const fi::Flat_storage& m, fi::Vertex_id v)
{
  return K::Point_3(m.point(v)[0], m.point(v)[1], m.point(v)[2]);
}

double volume_of(const fm::Constrained_mesh& cm, bool inside_only)
{
  const fi::Flat_storage& m = cm.mesh;
  double v = 0;
  for(fi::Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || m.is_ghost(t) || (inside_only && cm.subdomain[t] <= 0)) continue;
    const fi::Vertex_id* tv = m.vertex_ids(t);
    v += CGAL::volume(point(m, tv[0]), point(m, tv[1]), point(m, tv[2]), point(m, tv[3]));
  }
  return v;
}

std::size_t negative_or_flat_tetrahedra(const fi::Flat_storage& m)
{
  std::size_t bad = 0;
  for(fi::Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || m.is_ghost(t)) continue;
    const fi::Vertex_id* tv = m.vertex_ids(t);
    bad += CGAL::orientation(point(m, tv[0]), point(m, tv[1]), point(m, tv[2]), point(m, tv[3])) != CGAL::POSITIVE;
  }
  return bad;
}

// The checks of the file's header on a recovered mesh; `hull_volume` is
// the empty mesh's, `inside_volume` what the outer surfaces enclose.
void expect_recovered(const fm::Surface_soup& soup, fm::Constrained_mesh& cm, double hull_volume,
                      double inside_volume, const std::vector<std::array<double, 3>>& empty_mesh_points)
{
  const fi::Flat_storage& m = cm.mesh;
  // Ids and coordinates of the surface points as the empty mesh had them.
  for(std::size_t i = 0; i < soup.points.size(); ++i) {
    const fi::Vertex_id v = cm.vertex_of_input[i];
    ASSERT_LT(v, m.vertices.size());
    EXPECT_EQ(m.point(v)[0], soup.points[i][0]);
    EXPECT_EQ(m.point(v)[1], soup.points[i][1]);
    EXPECT_EQ(m.point(v)[2], soup.points[i][2]);
  }
  for(std::size_t v = 0; v < empty_mesh_points.size() && v < m.vertices.size(); ++v)
    EXPECT_EQ(m.point(static_cast<fi::Vertex_id>(v))[0], empty_mesh_points[v][0]);

  fm::flag_constrained_facets(soup, cm); // throws if an input triangle is not a facet
  fm::colour_volumes(cm);
  std::string why;
  EXPECT_TRUE(cm.is_valid(&why)) << why;
  EXPECT_EQ(negative_or_flat_tetrahedra(m), 0u);

  // Steiner points: none on a constrained facet.
  std::vector<char> is_surface_point(m.vertices.size(), 0);
  for(fi::Vertex_id v : cm.vertex_of_input) is_surface_point[v] = 1;
  std::size_t steiner_on_surface = 0;
  for(fi::Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t)) continue;
    for(int f = 0; f < 4; ++f) {
      if(!cm.is_constrained(t, f)) continue;
      for(int i = 0; i < 3; ++i) {
        const fi::Vertex_id v = m.vertex(t, fi::facet_vertex[f][i]);
        steiner_on_surface += v != fi::ghost_vertex && !is_surface_point[v];
      }
    }
  }
  EXPECT_EQ(steiner_on_surface, 0u);

  EXPECT_NEAR(volume_of(cm, false), hull_volume, 1e-9 * hull_volume);
  EXPECT_NEAR(volume_of(cm, true), inside_volume, 1e-9 * hull_volume);
}

struct Empty_mesh
{
  fm::Constrained_mesh cm;
  std::vector<fm::Triangle_key> input, missing;
  double hull_volume = 0;
  std::vector<std::array<double, 3>> points;
};

Empty_mesh empty_mesh_of(const fm::Surface_soup& soup)
{
  Empty_mesh e;
  fm::empty_mesh(soup, 1, e.cm);
  e.cm.fit_slot_arrays();
  e.input = fm::input_triangle_keys(soup, e.cm.vertex_of_input);
  e.missing = fm::missing_facets(e.cm.mesh, e.input);
  e.hull_volume = volume_of(e.cm, false);
  for(fi::Vertex_id v = 0; v < e.cm.mesh.vertices.size(); ++v)
    e.points.push_back({e.cm.mesh.point(v)[0], e.cm.mesh.point(v)[1], e.cm.mesh.point(v)[2]});
  return e;
}

// Both paths on one surface; returns the local path's report.
fm::Recovery_report recover_both_ways(const Surface& s, double inside_volume)
{
  const fm::Surface_soup soup = soup_of(s);
  Empty_mesh local = empty_mesh_of(soup);
  EXPECT_GT(local.missing.size(), 0u) << "the surface needs no recovery: a test of nothing";
  fm::Recovery_report report;
  EXPECT_TRUE(fm::recover_locally(local.input, local.missing, local.cm, report));
  local.cm.fit_slot_arrays();
  expect_recovered(soup, local.cm, local.hull_volume, inside_volume, local.points);
  EXPECT_FALSE(report.whole_surface_to_tetgen);
  EXPECT_EQ(report.flipped_components + report.tetgen_components > 0, true);

  Empty_mesh whole = empty_mesh_of(soup);
  fm::Recovery_report fallback;
  fm::recover_with_tetgen(soup, whole.cm, fallback);
  whole.cm.fit_slot_arrays();
  // The fallback numbers vertices as the input does: compare with those.
  std::vector<std::array<double, 3>> none;
  expect_recovered(soup, whole.cm, whole.hull_volume, inside_volume, none);
  EXPECT_TRUE(fallback.whole_surface_to_tetgen);
  return report;
}

// A square pyramid, its base on the convex hull: the two diagonals of the
// cocircular base are equally Delaunay, the perturbation picks one.  Of the
// two inputs, one base diagonal each, one needs the recovery: one 2-2 flip
// in the base's plane, no TetGen call.
TEST(BoundaryRecovery, PyramidBaseByOneHullFlip)
{
  int recovered = 0;
  for(int diagonal = 0; diagonal < 2; ++diagonal) {
    Surface s;
    s.points = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.4, 0.45, 0.8}};
    s.triangles = {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}};
    if(diagonal == 0) s.triangles.insert(s.triangles.end(), {{0, 2, 1}, {0, 3, 2}});
    else s.triangles.insert(s.triangles.end(), {{1, 3, 2}, {1, 0, 3}});
    const fm::Surface_soup soup = soup_of(s);
    Empty_mesh e = empty_mesh_of(soup);
    if(e.missing.empty()) continue;
    ++recovered;
    EXPECT_EQ(e.missing.size(), 2u);
    const fm::Recovery_report report = recover_both_ways(s, std::abs(mesher_shapes::enclosed_volume(s)));
    EXPECT_EQ(report.flipped_components, 1u);
    EXPECT_EQ(report.tetgen_components, 0u);
    EXPECT_FALSE(report.used_tetgen);
  }
  EXPECT_EQ(recovered, 1);
}

// The cube's six faces all with the other diagonal than the empty mesh's:
// two 6-tetrahedron triangulations that no sequence of flips, each adding a
// face, joins; one component without walls, TetGen's.
TEST(BoundaryRecovery, CubeWholeComponentByTetgen)
{
  const fm::Recovery_report report = recover_both_ways(mesher_shapes::cube(0, 1), 1.0);
  EXPECT_EQ(report.tetgen_components, 1u);
  EXPECT_FALSE(report.whole_surface_to_tetgen);
}

TEST(BoundaryRecovery, Torus)
{
  const Surface s = mesher_shapes::torus(1.0, 0.35, 24, 10);
  recover_both_ways(s, std::abs(mesher_shapes::enclosed_volume(s)));
}

TEST(BoundaryRecovery, TwoCubesNested)
{
  const Surface both = mesher_shapes::combine(mesher_shapes::cube(0, 1), mesher_shapes::cube(0.3, 0.6));
  recover_both_ways(both, 1.0);
}

// CGAL's fandisk: 1106 of 12946 triangles missing, flat faces on the hull;
// both of the local path's ways are used.
TEST(BoundaryRecovery, CgalDataFandisk)
{
  Surface s;
  if(!read_cgal_data_surface("fandisk.off", s))
    GTEST_SKIP() << FDT3_CGAL_DATA_DIR "/fandisk.off is missing (apt install libcgal-demo, re-run CMake)";
  const fm::Recovery_report report = recover_both_ways(s, std::abs(mesher_shapes::enclosed_volume(s)));
  EXPECT_GT(report.flipped_components, 0u);
  EXPECT_GT(report.tetgen_components, 0u);
}

// CGAL's couplingdown: one component TetGen cannot mesh inside its walls
// from the convex hull of its points (it splits a wall); the second try,
// the component's hull facets as constraints, holds, so the local path
// succeeds, with Steiner points inside that component.
TEST(BoundaryRecovery, CgalDataCouplingSecondTry)
{
  Surface s;
  if(!read_cgal_data_surface("couplingdown.off", s))
    GTEST_SKIP() << FDT3_CGAL_DATA_DIR "/couplingdown.off is missing (apt install libcgal-demo, re-run CMake)";
  const fm::Recovery_report report = recover_both_ways(s, std::abs(mesher_shapes::enclosed_volume(s)));
  EXPECT_GT(report.tetgen_components, 0u);
  EXPECT_GT(report.steiner_points, 0u);
}

// The exact overlap test of two triangles of one plane: interiors that
// cross, nest or coincide meet; triangles sharing an edge or a corner, or
// apart, do not.
TEST(BoundaryRecovery, CoplanarInteriorsMeet)
{
  // In the plane z = x + y, so that no coordinate plane is the triangles'.
  auto at = [](double x, double y) { return std::array<double, 3>{x, y, x + y}; };
  const std::vector<std::array<double, 3>> p = {at(0, 0), at(4, 0), at(0, 4), at(4, 4),  at(1, 1),
                                               at(2, 1), at(1, 2), at(-1, 2), at(5, 2), at(8, 0)};
  auto triangle = [&](int a, int b, int c) { return std::array<const double*, 3>{p[a].data(), p[b].data(), p[c].data()}; };
  EXPECT_TRUE(fm::coplanar_interiors_meet(triangle(0, 1, 2), triangle(4, 5, 6)));  // nested
  EXPECT_TRUE(fm::coplanar_interiors_meet(triangle(4, 5, 6), triangle(0, 1, 2)));
  EXPECT_TRUE(fm::coplanar_interiors_meet(triangle(0, 1, 2), triangle(7, 8, 3)));  // crossing
  EXPECT_TRUE(fm::coplanar_interiors_meet(triangle(0, 1, 2), triangle(2, 1, 0)));  // the same
  EXPECT_TRUE(fm::coplanar_interiors_meet(triangle(0, 1, 3), triangle(0, 1, 2)));  // one edge, same side
  EXPECT_FALSE(fm::coplanar_interiors_meet(triangle(0, 1, 2), triangle(1, 3, 2))); // an edge shared
  EXPECT_FALSE(fm::coplanar_interiors_meet(triangle(0, 1, 2), triangle(1, 9, 8))); // a corner shared
  EXPECT_FALSE(fm::coplanar_interiors_meet(triangle(4, 5, 6), triangle(1, 9, 8))); // apart
}

// fandisk's components with their hull facets as constraints (the local
// recovery's second try): some have a hull facet crossed by an input
// triangle of a flat face, which the recovery never gives TetGen (it
// crashed the process on them); TetGen runs on every other one.
TEST(BoundaryRecovery, CgalDataFandiskNoCrossedHullFacetForTetgen)
{
  Surface s;
  if(!read_cgal_data_surface("fandisk.off", s))
    GTEST_SKIP() << FDT3_CGAL_DATA_DIR "/fandisk.off is missing (apt install libcgal-demo, re-run CMake)";
  const fm::Surface_soup soup = soup_of(s);
  Empty_mesh e = empty_mesh_of(soup);
  const fm::Recovery_region region = fm::recovery_region(e.cm.mesh, e.missing);
  std::vector<std::vector<fm::Triangle_key>> missing_in(region.number_of_components());
  for(std::size_t i = 0; i < e.missing.size(); ++i) missing_in[region.component_of_missing[i]].push_back(e.missing[i]);
  std::vector<fi::Vertex_id> local(e.cm.mesh.vertices.size(), fi::Vertex_id(-1));
  std::size_t crossed = 0, meshed = 0;
  for(std::size_t c = 0; c < region.number_of_components(); ++c) {
    if(fm::component_size(region, c) <= fm::max_flipped_component) continue;
    const fm::Local_problem problem = fm::local_problem(e.cm.mesh, region, c, e.input, missing_in[c], local, true);
    if(fm::hull_facet_crosses_a_triangle(problem)) {
      ++crossed;
      continue;
    }
    try {
      fm::tetgen_recovery(problem.points, problem.triangles, "pYMO0zQ");
      ++meshed;
    } catch(const std::runtime_error&) {
    }
  }
  EXPECT_GT(crossed, 0u);
  EXPECT_GT(meshed, 0u);
}

} // namespace test_mesher_recovery
