// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Constrained meshes for the mesh improvement's tests, built without the
// mesher: CGAL's Delaunay triangulation of random points in a cube (its
// slivers are what the improvement is for) or hand-made tetrahedra, with
// every hull facet constrained.  And the checks that do not trust the
// improvement: what must not change (hull facets, the positions of surface
// vertices, subdomains) compared with a copy taken before.

#ifndef FDT3_TEST_IMPROVEMENT_CASES_H
#define FDT3_TEST_IMPROVEMENT_CASES_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedron_quality.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Random.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

namespace improvement_cases {

namespace mi = CGAL::Fast_Delaunay_triangulation_3_internal::mesher;
using CGAL::Fast_Delaunay_triangulation_3_internal::Tet_id;
using CGAL::Fast_Delaunay_triangulation_3_internal::Vertex_id;
typedef CGAL::Exact_predicates_inexact_constructions_kernel K;

// Positively oriented tetrahedra -> a constrained mesh in subdomain
// `subdomain_of(tet index)`; hull facets and facets between subdomains are
// constrained.
template <class Subdomain_of>
mi::Constrained_mesh constrained_mesh(const std::vector<std::array<double, 3>>& points,
                                      const std::vector<std::array<Vertex_id, 4>>& tets, Subdomain_of subdomain_of)
{
  mi::Constrained_mesh cm;
  cm.mesh = mi::flat_storage_from_tetrahedra(points, tets);
  mi::set_box(points, cm);
  cm.fit_slot_arrays();
  int most = 0;
  for(Tet_id t = 0; t < tets.size(); ++t) {
    cm.subdomain[t] = subdomain_of(t);
    most = std::max(most, cm.subdomain[t]);
  }
  cm.number_of_subdomains = most;
  for(Tet_id t = 0; t < cm.mesh.number_of_slots(); ++t)
    for(int f = 0; f < 4; ++f)
      if(cm.subdomain[t] != cm.subdomain[cm.mesh.neighbor(t, f)]) cm.constrained[t] |= std::uint8_t(1u << f);
  cm.size.assign(points.size(), 1.0);
  return cm;
}

inline mi::Constrained_mesh constrained_mesh(const std::vector<std::array<double, 3>>& points,
                                             const std::vector<std::array<Vertex_id, 4>>& tets)
{
  return constrained_mesh(points, tets, [](Tet_id) { return 1; });
}

// CGAL's Delaunay triangulation of `input` as a constrained mesh, each cell
// in subdomain `subdomain_of(x of its centroid)`.
template <class Subdomain_of_x>
mi::Constrained_mesh delaunay_mesh(const std::vector<K::Point_3>& input, Subdomain_of_x subdomain_of)
{
  CGAL::Delaunay_triangulation_3<K> dt(input.begin(), input.end());
  std::vector<std::array<double, 3>> points;
  std::map<CGAL::Delaunay_triangulation_3<K>::Vertex_handle, Vertex_id> id;
  for(auto v = dt.finite_vertices_begin(); v != dt.finite_vertices_end(); ++v) {
    id[v] = static_cast<Vertex_id>(points.size());
    points.push_back({v->point().x(), v->point().y(), v->point().z()});
  }
  std::vector<std::array<Vertex_id, 4>> tets;
  std::vector<int> subdomain;
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    tets.push_back({id[c->vertex(0)], id[c->vertex(1)], id[c->vertex(2)], id[c->vertex(3)]});
    double x = 0;
    for(int i = 0; i < 4; ++i) x += c->vertex(i)->point().x() / 4;
    subdomain.push_back(subdomain_of(x));
  }
  return constrained_mesh(points, tets, [&](Tet_id t) { return subdomain[t]; });
}

// CGAL's Delaunay triangulation of the centres of a k x k x k grid of the
// unit cube, each moved at random by up to 0.35 of the spacing, and the
// grid's nodes on the cube's faces: well-spaced points, whose Delaunay
// tetrahedra are good but for the slivers (what a refined mesh looks like).  With `two_subdomains`, the
// tetrahedra whose centroid has x < 0.5 form subdomain 2 (a staircase
// interface inside, constrained).
inline mi::Constrained_mesh random_cube_mesh(int k, unsigned seed, bool two_subdomains = false)
{
  CGAL::Random random(seed);
  std::vector<K::Point_3> input;
  const double h = 1.0 / k;
  for(int i = 0; i <= k; ++i)
    for(int j = 0; j <= k; ++j)
      for(int l = 0; l <= k; ++l)
        if(i == 0 || j == 0 || l == 0 || i == k || j == k || l == k) input.emplace_back(i * h, j * h, l * h);
  auto jittered = [&](int i) { return (i + 0.5) * h + random.get_double(-0.35, 0.35) * h; };
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
      for(int l = 0; l < k; ++l) input.emplace_back(jittered(i), jittered(j), jittered(l));
  return delaunay_mesh(input, [two_subdomains](double x) { return two_subdomains && x < 0.5 ? 2 : 1; });
}

// CGAL's Delaunay triangulation of n random points on the unit sphere:
// every vertex is on the surface (the hull), so no vertex may move, and the
// tetrahedra inside are as bad as chance makes them.
inline mi::Constrained_mesh sphere_points_mesh(int n, unsigned seed)
{
  CGAL::Random random(seed);
  std::vector<K::Point_3> input;
  while(static_cast<int>(input.size()) < n) {
    const double x = random.get_double(-1, 1), y = random.get_double(-1, 1), z = random.get_double(-1, 1);
    const double r = std::sqrt(x * x + y * y + z * z);
    if(r > 0.1 && r <= 1) input.emplace_back(x / r, y / r, z / r);
  }
  return delaunay_mesh(input, [](double) { return 1; });
}

inline double gamma_of(const mi::Constrained_mesh& cm, Tet_id t)
{
  const Vertex_id* tv = cm.mesh.vertex_ids(t);
  return mi::gamma_quality(cm.mesh.point(tv[0]), cm.mesh.point(tv[1]), cm.mesh.point(tv[2]), cm.mesh.point(tv[3]));
}

inline bool is_volume(const mi::Constrained_mesh& cm, Tet_id t)
{
  return cm.mesh.is_live(t) && !cm.mesh.is_ghost(t) && cm.subdomain[t] > 0;
}

inline double worst_gamma(const mi::Constrained_mesh& cm)
{
  double worst = 1;
  for(Tet_id t = 0; t < cm.mesh.number_of_slots(); ++t)
    if(is_volume(cm, t)) worst = std::min(worst, gamma_of(cm, t));
  return worst;
}

// The improvement's figures and the test's own computation of the same
// gamma: the compiler may contract a * b + c into one rounding in one place
// and not in the other (-march=native has FMA), and a sliver's gamma comes
// from a cancelling difference, so they agree to 1e-12, not to 4 ulps.
#define EXPECT_SAME_GAMMA(a, b) EXPECT_NEAR(a, b, 1e-12)

inline std::size_t count_below(const mi::Constrained_mesh& cm, double threshold)
{
  std::size_t n = 0;
  for(Tet_id t = 0; t < cm.mesh.number_of_slots(); ++t)
    if(is_volume(cm, t) && gamma_of(cm, t) < threshold) ++n;
  return n;
}

inline double smallest_dihedral_degrees(const mi::Constrained_mesh& cm)
{
  double smallest = 180;
  for(Tet_id t = 0; t < cm.mesh.number_of_slots(); ++t) {
    if(!is_volume(cm, t)) continue;
    const Vertex_id* tv = cm.mesh.vertex_ids(t);
    const double* w[4] = {cm.mesh.point(tv[0]), cm.mesh.point(tv[1]), cm.mesh.point(tv[2]), cm.mesh.point(tv[3])};
    smallest = std::min(smallest, mi::dihedral_range(w).smallest);
  }
  return smallest;
}

// The constrained facets by their vertices' coordinates, with the subdomains
// on their two sides, and the volume of each subdomain.
struct Invariants
{
  std::set<std::array<double, 10>> constrained_facets;
  std::vector<double> volume;
  std::set<std::array<double, 3>> surface_points;
};

inline Invariants invariants(const mi::Constrained_mesh& cm)
{
  Invariants inv;
  const auto& m = cm.mesh;
  inv.volume.assign(cm.number_of_subdomains + 1, 0.0);
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t)) continue;
    if(is_volume(cm, t)) {
      const Vertex_id* tv = m.vertex_ids(t);
      const K::Point_3 p[4] = {{m.point(tv[0])[0], m.point(tv[0])[1], m.point(tv[0])[2]},
                               {m.point(tv[1])[0], m.point(tv[1])[1], m.point(tv[1])[2]},
                               {m.point(tv[2])[0], m.point(tv[2])[1], m.point(tv[2])[2]},
                               {m.point(tv[3])[0], m.point(tv[3])[1], m.point(tv[3])[2]}};
      inv.volume[cm.subdomain[t]] += CGAL::volume(p[0], p[1], p[2], p[3]);
    }
    for(int f = 0; f < 4; ++f) {
      if(!cm.is_constrained(t, f) || cm.subdomain[t] <= 0) continue;
      std::vector<std::array<double, 3>> corners;
      for(int i = 0; i < 3; ++i) {
        const double* p = m.point(m.vertex(t, CGAL::Fast_Delaunay_triangulation_3_internal::facet_vertex[f][i]));
        corners.push_back({p[0], p[1], p[2]});
        inv.surface_points.insert(corners.back());
      }
      std::sort(corners.begin(), corners.end());
      std::array<double, 10> key;
      for(int i = 0; i < 3; ++i)
        for(int a = 0; a < 3; ++a) key[3 * i + a] = corners[i][a];
      key[9] = cm.subdomain[t];
      inv.constrained_facets.insert(key);
    }
  }
  return inv;
}

inline void expect_same_invariants(const Invariants& before, const Invariants& after)
{
  EXPECT_TRUE(before.constrained_facets == after.constrained_facets) << "constrained facets or their sides changed";
  EXPECT_TRUE(before.surface_points == after.surface_points) << "a surface vertex moved";
  ASSERT_EQ(before.volume.size(), after.volume.size());
  for(std::size_t s = 1; s < before.volume.size(); ++s)
    EXPECT_NEAR(before.volume[s], after.volume[s], 1e-12 * std::max(1.0, before.volume[s])) << "subdomain " << s;
}

inline void expect_valid(const mi::Constrained_mesh& cm)
{
  std::string why;
  EXPECT_TRUE(cm.is_valid(&why)) << why;
  std::size_t live = 0, ghosts = 0;
  for(Tet_id t = 0; t < cm.mesh.number_of_slots(); ++t) {
    live += cm.mesh.is_live(t) ? 1 : 0;
    ghosts += cm.mesh.is_live(t) && cm.mesh.is_ghost(t) ? 1 : 0;
  }
  EXPECT_EQ(live, cm.mesh.live_tets);
  EXPECT_EQ(ghosts, cm.mesh.ghost_tets);
  for(Tet_id t : cm.mesh.free_tets) EXPECT_FALSE(cm.mesh.is_live(t));
  // No vertex dropped: a replacement whose region swallowed a vertex's
  // whole star would leave it in no tetrahedron, which the facets alone
  // do not show.
  std::vector<char> used(cm.mesh.vertices.size(), 0);
  for(Tet_id t = 0; t < cm.mesh.number_of_slots(); ++t) {
    if(!cm.mesh.is_live(t)) continue;
    for(int i = 0; i < 4; ++i) {
      const Vertex_id v = cm.mesh.vertex(t, i);
      if(v < used.size()) used[v] = 1;
    }
  }
  EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0) << "vertices in no tetrahedron";
}

} // namespace improvement_cases

#endif // FDT3_TEST_IMPROVEMENT_CASES_H
