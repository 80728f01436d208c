// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh improvement (mesher/Mesh_improvement.h) and the shape measures it
// optimises (mesher/Tetrahedron_quality.h): the measures against their
// definitions computed with CGAL; each operation on a hand-made
// configuration (the sliver between four nearly coplanar points, edges with
// rings of 3 to 7 tetrahedra); random Delaunay meshes, one and two
// subdomains: valid, positively oriented (exact), constrained facets,
// surface vertices and subdomain volumes unchanged, the worst gamma never
// lower; the replacement refusing a region it does not close; the mesher
// with and without the step, through the quality report.

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Tetrahedra_replacement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Mesh_improvement.h>

#include <gtest/gtest.h>

#include "improvement_cases.h"
#include "mesher_checks.h"
#include "mesher_shapes.h"

#include <cmath>
#include <cstring>
#include <vector>

namespace test_mesher_improvement {

using namespace improvement_cases;
namespace fdt = CGAL::Fast_Delaunay_triangulation_3_internal;

K::Point_3 to_point(const std::array<double, 3>& p) { return K::Point_3(p[0], p[1], p[2]); }

// gamma = 3 r_in / r_circ from CGAL's constructions: r_in = 3 V / A.
double gamma_by_definition(const std::array<std::array<double, 3>, 4>& w)
{
  const K::Point_3 p[4] = {to_point(w[0]), to_point(w[1]), to_point(w[2]), to_point(w[3])};
  const double volume = CGAL::volume(p[0], p[1], p[2], p[3]);
  double area = 0;
  for(int f = 0; f < 4; ++f)
    area += std::sqrt(CGAL::squared_area(p[(f + 1) % 4], p[(f + 2) % 4], p[(f + 3) % 4]));
  const double r_in = 3 * std::abs(volume) / area;
  const double r_circ = std::sqrt(CGAL::squared_radius(p[0], p[1], p[2], p[3]));
  return (volume < 0 ? -1 : 1) * 3 * r_in / r_circ;
}

double gamma_of(const std::array<std::array<double, 3>, 4>& w)
{
  return mi::gamma_quality(w[0].data(), w[1].data(), w[2].data(), w[3].data());
}

TEST(Quality, GammaMatchesItsDefinition)
{
  const double s = std::sqrt(8.0 / 9), t = std::sqrt(2.0 / 9), u = std::sqrt(2.0 / 3);
  const std::array<std::array<double, 3>, 4> regular = {{{0, 0, 1}, {s, 0, -1.0 / 3}, {-t, u, -1.0 / 3}, {-t, -u, -1.0 / 3}}};
  const double g = gamma_of(regular);
  EXPECT_NEAR(std::abs(g), 1.0, 1e-12);
  std::array<std::array<double, 3>, 4> inverted = regular;
  std::swap(inverted[0], inverted[1]);
  EXPECT_NEAR(gamma_of(inverted), -g, 1e-12);
  EXPECT_EQ(gamma_of({{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}}}), 0.0);
  const std::array<std::array<double, 3>, 4> corner = {{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}};
  EXPECT_NEAR(gamma_of(corner), gamma_by_definition(corner), 1e-12);
  CGAL::Random random(7);
  for(int k = 0; k < 1000; ++k) {
    std::array<std::array<double, 3>, 4> w;
    for(auto& p : w)
      for(double& x : p) x = random.get_double(-1, 1);
    const double expected = gamma_by_definition(w);
    EXPECT_NEAR(gamma_of(w), expected, 1e-9 * (1 + 1 / std::abs(expected))) << k;
  }
}

TEST(Quality, DihedralAngles)
{
  const std::array<double, 3> corner[4] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  const double* w[4] = {corner[0].data(), corner[1].data(), corner[2].data(), corner[3].data()};
  const mi::Dihedral_range r = mi::dihedral_range(w);
  EXPECT_NEAR(r.largest, 90, 1e-9);
  EXPECT_NEAR(r.smallest, std::acos(1 / std::sqrt(3.0)) * 180 / 3.14159265358979323846, 1e-9);
}

// The ring of n tetrahedra (a, b, p_i, p_i+1) around the edge a = (0, 0, h),
// b = (0, 0, -h) with p on the unit circle, clockwise seen from a (which
// makes them positive): for h = 2 every one is a needle (gamma < 0.33) and
// a triangulation of the polygon does better.
mi::Constrained_mesh edge_ring(int n, double h)
{
  std::vector<std::array<double, 3>> points = {{0, 0, h}, {0, 0, -h}};
  for(int i = 0; i < n; ++i) {
    const double angle = -2 * 3.14159265358979323846 * i / n;
    points.push_back({std::cos(angle), std::sin(angle), 0});
  }
  std::vector<std::array<Vertex_id, 4>> tets;
  for(int i = 0; i < n; ++i) tets.push_back({0, 1, Vertex_id(2 + i), Vertex_id(2 + (i + 1) % n)});
  return constrained_mesh(points, tets);
}

bool has_edge(const mi::Constrained_mesh& cm, Vertex_id a, Vertex_id b)
{
  for(Tet_id t = 0; t < cm.mesh.number_of_slots(); ++t) {
    if(!is_volume(cm, t)) continue;
    const Vertex_id* tv = cm.mesh.vertex_ids(t);
    if(std::count(tv, tv + 4, a) && std::count(tv, tv + 4, b)) return true;
  }
  return false;
}

TEST(Improvement, EdgeRemovalOnRingsOf3To7)
{
  for(int n = 3; n <= 7; ++n) {
    mi::Constrained_mesh cm = edge_ring(n, 2.0);
    expect_valid(cm);
    const Invariants before = invariants(cm);
    const double worst = worst_gamma(cm);
    ASSERT_LT(worst, 0.33) << n;
    mi::Improvement_options options;
    options.quality_threshold = 0.5;
    const mi::Improvement_statistics stats = mi::improve_mesh(cm, options);
    SCOPED_TRACE("ring of " + std::to_string(n));
    expect_valid(cm);
    expect_same_invariants(before, invariants(cm));
    EXPECT_FALSE(has_edge(cm, 0, 1));
    EXPECT_GE(stats.edge_removals, 1u);
    EXPECT_EQ(stats.relocations, 0u); // every vertex is on the surface
    EXPECT_GT(worst_gamma(cm), worst + 0.03);
  }
}

// The octahedron T, p0..p3, B cut into the two tetrahedra above the diagonal
// p0 p2, the two below the other diagonal p1 p3, and between them the sliver
// (p0, p1, p2, p3) of four nearly coplanar points.
TEST(Improvement, SliverBetweenFourNearlyCoplanarPoints)
{
  const double e = 1e-3;
  const std::vector<std::array<double, 3>> points = {{1, 0, e}, {0, 1, -e}, {-1, 0, e}, {0, -1, -e}, {0, 0, 1}, {0, 0, -1}};
  std::vector<std::array<Vertex_id, 4>> tets = {{4, 0, 1, 2}, {4, 0, 2, 3}, {5, 1, 2, 3}, {5, 3, 0, 1}, {0, 1, 2, 3}};
  for(auto& t : tets)
    if(CGAL::orientation(to_point(points[t[0]]), to_point(points[t[1]]), to_point(points[t[2]]),
                         to_point(points[t[3]])) != CGAL::POSITIVE)
      std::swap(t[0], t[1]);
  mi::Constrained_mesh cm = constrained_mesh(points, tets);
  expect_valid(cm);
  const Invariants before = invariants(cm);
  ASSERT_LT(worst_gamma(cm), 0.01);
  const mi::Improvement_statistics stats = mi::improve_mesh(cm, mi::Improvement_options());
  expect_valid(cm);
  expect_same_invariants(before, invariants(cm));
  EXPECT_EQ(cm.mesh.live_tets - cm.mesh.ghost_tets, 4u);
  EXPECT_GT(worst_gamma(cm), 0.3);
  EXPECT_EQ(stats.bad_before, 1u);
  EXPECT_EQ(stats.bad_after, 0u);
  EXPECT_FALSE(has_edge(cm, 0, 2) && has_edge(cm, 1, 3)); // the sliver held both diagonals
}

void expect_improved(mi::Constrained_mesh& cm, const mi::Improvement_options& options, mi::Improvement_statistics* out)
{
  expect_valid(cm);
  const Invariants before = invariants(cm);
  const double worst = worst_gamma(cm);
  const std::size_t bad = count_below(cm, options.quality_threshold);
  const mi::Improvement_statistics stats = mi::improve_mesh(cm, options);
  expect_valid(cm);
  expect_same_invariants(before, invariants(cm));
  EXPECT_EQ(stats.bad_before, bad);
  EXPECT_EQ(stats.bad_after, count_below(cm, options.quality_threshold));
  EXPECT_DOUBLE_EQ(stats.min_gamma_before, worst);
  EXPECT_DOUBLE_EQ(stats.min_gamma_after, worst_gamma(cm));
  EXPECT_GE(worst_gamma(cm), worst);
  EXPECT_LT(stats.bad_after, bad / 10);
  EXPECT_GT(stats.edge_removals, 0u);
  EXPECT_GT(stats.relocations, 0u);
  if(out) *out = stats;
}

TEST(Improvement, RandomDelaunayMesh)
{
  mi::Constrained_mesh cm = random_cube_mesh(13, 3);
  expect_improved(cm, mi::Improvement_options(), nullptr);
}

TEST(Improvement, TwoSubdomainsKeepTheirInterface)
{
  mi::Constrained_mesh cm = random_cube_mesh(11, 11, true);
  ASSERT_EQ(cm.number_of_subdomains, 2);
  expect_improved(cm, mi::Improvement_options(), nullptr);
}

TEST(Improvement, ReplacementRefusesARegionItDoesNotClose)
{
  mi::Constrained_mesh cm = edge_ring(5, 2.0);
  const fdt::Flat_storage before = cm.mesh;
  std::vector<Tet_id> region = {0, 1, 2, 3, 4};
  // Only three of the fan's six tetrahedra: the region's boundary is not covered.
  const std::vector<std::array<Vertex_id, 4>> made = {{0, 2, 3, 4}, {2, 3, 4, 1}, {0, 2, 4, 5}};
  std::vector<Tet_id> slots(made.size());
  fdt::Replacement_scratch scratch;
  EXPECT_THROW(fdt::replace_tetrahedra(cm.mesh, region.data(), region.size(), made.data(), made.size(), slots.data(),
                                       scratch),
               std::logic_error);
  ASSERT_EQ(before.tets.size(), cm.mesh.tets.size());
  EXPECT_EQ(std::memcmp(before.tets.data(), cm.mesh.tets.data(), before.tets.size() * sizeof(fdt::Tet_record)), 0);
  EXPECT_EQ(before.live_tets, cm.mesh.live_tets);
}

// Through the public mesher: the step on and off, seen by the quality report.
TEST(Improvement, MesherOptimizesByDefault)
{
  using namespace CGAL::Fast_mesher_3;
  const mesher_shapes::Surface s = mesher_shapes::torus(1, 0.35, 40, 16);
  Mesher_options off;
  off.optimize = false;
  Mesher_statistics stats_off, stats_on;
  const Tetrahedral_mesh plain = mesh_surfaces(s.points, s.triangles, off, &stats_off);
  const Tetrahedral_mesh improved = mesh_surfaces(s.points, s.triangles, Mesher_options(), &stats_on);
  const Quality_report q_off = quality_report(plain), q_on = quality_report(improved);
  EXPECT_EQ(stats_off.improvement.passes, 0);
  EXPECT_GT(stats_on.improvement.passes, 0);
  EXPECT_EQ(stats_on.improvement.bad_before, q_off.tetrahedra_below_gamma_0_3);
  EXPECT_EQ(stats_on.improvement.bad_after, q_on.tetrahedra_below_gamma_0_3);
  EXPECT_LT(q_on.tetrahedra_below_gamma_0_3, q_off.tetrahedra_below_gamma_0_3 / 4);
  EXPECT_GE(q_on.min_gamma, q_off.min_gamma);
  EXPECT_TRUE(q_on.boundary_equals_input());
  EXPECT_EQ(q_on.inverted_tetrahedra, 0u);
  mesher_checks::expect_all_positive(improved);
  mesher_checks::expect_boundary_is_input(improved, s);
  mesher_checks::expect_every_tetrahedron_tagged(improved);
  EXPECT_NEAR(mesher_checks::volume_of_subdomain(improved, 1), mesher_checks::volume_of_subdomain(plain, 1),
              1e-9 * mesher_checks::volume_of_subdomain(plain, 1));
  EXPECT_EQ(plain.points.size(), improved.points.size());

  // The report's histograms count every tetrahedron once.
  std::size_t in_gamma = 0, in_dihedral = 0;
  for(std::size_t n : q_on.gamma_histogram) in_gamma += n;
  for(std::size_t n : q_on.min_dihedral_histogram) in_dihedral += n;
  EXPECT_EQ(in_gamma, q_on.tetrahedra);
  EXPECT_EQ(in_dihedral, q_on.tetrahedra);
  EXPECT_LE(q_on.min_gamma, q_on.gamma_1st_percentile);
  EXPECT_LE(q_on.gamma_1st_percentile, q_on.mean_gamma);
  EXPECT_LE(q_on.min_dihedral_degrees, q_on.min_dihedral_1st_percentile);
  EXPECT_LE(q_on.min_dihedral_1st_percentile, q_on.mean_min_dihedral);
}

} // namespace test_mesher_improvement
