// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Remeshing the mesher's input surfaces to a length (Surface_remeshing.h):
// the result lies on the input, keeps its sharp edges and corners and the
// volume it encloses, each surface apart; meshed at that length it has no
// triangle over the size and no tetrahedron under gamma 0.3, where the
// input's own large triangles left some; meshed through
// mesh_remeshed_surfaces, a wall thinner than the length shortens it.  Bad
// options and bad surfaces are refused with the reason.

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Surface_remeshing.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <gtest/gtest.h>

#include "mesher_checks.h"
#include "mesher_shapes.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_mesher_surface_remeshing {

using namespace CGAL::Fast_mesher_3;

mesher_shapes::Surface as_shape(const Surface_triangles& s) { return {s.points, s.triangles}; }

std::vector<double> edge_lengths(const Surface_triangles& s)
{
  std::vector<double> lengths;
  for(const auto& t : s.triangles)
    for(int i = 0; i < 3; ++i) {
      const auto& a = s.points[t[i]];
      const auto& b = s.points[t[(i + 1) % 3]];
      lengths.push_back(std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                                  (a[2] - b[2]) * (a[2] - b[2])));
    }
  std::sort(lengths.begin(), lengths.end());
  return lengths;
}

// How many of p's coordinates are lo or hi (to 1e-12): 1 on a face of the
// cube [lo, hi]^3, 2 on an edge, 3 at a corner; 0 off its surface.
int coordinates_on_cube(const std::array<double, 3>& p, double lo, double hi)
{
  int on = 0;
  for(double x : p) on += std::abs(x - lo) < 1e-12 || std::abs(x - hi) < 1e-12 ? 1 : 0;
  return on;
}

bool inside_closed_cube(const std::array<double, 3>& p, double lo, double hi)
{
  for(double x : p)
    if(x < lo - 1e-12 || x > hi + 1e-12) return false;
  return true;
}

TEST(SurfaceRemeshing, ACubeKeepsItsFacesEdgesAndCorners)
{
  const mesher_shapes::Surface cube = mesher_shapes::cube(0, 1);
  const double length = 0.2;
  const Surface_triangles remeshed = remesh_surfaces(cube.points, cube.triangles, {length});
  ASSERT_GT(remeshed.triangles.size(), 150u); // six unit faces in triangles of about 0.017 each: ~350
  std::size_t corners = 0, on_edges = 0;
  for(const auto& p : remeshed.points) {
    ASSERT_TRUE(inside_closed_cube(p, 0, 1));
    const int on = coordinates_on_cube(p, 0, 1);
    ASSERT_GE(on, 1) << "a vertex off the cube's faces";
    corners += on == 3 ? 1 : 0;
    on_edges += on == 2 ? 1 : 0;
  }
  EXPECT_EQ(corners, 8u);
  EXPECT_GE(on_edges, 12u * 3); // each unit edge split into about five
  EXPECT_NEAR(mesher_shapes::enclosed_volume(as_shape(remeshed)), 1.0, 1e-9);
  const std::vector<double> lengths = edge_lengths(remeshed);
  const double median = lengths[lengths.size() / 2];
  EXPECT_GT(median, 0.7 * length);
  EXPECT_LT(median, 4.0 / 3 * length);
  EXPECT_LT(lengths.back(), 2 * length);

  // Meshed at the same size: the input's twelve triangles are over it and
  // leave bad tetrahedra along them; the remeshed surface leaves none.
  Mesher_options options;
  options.maximum_size = length;
  Mesher_statistics as_given, after_remeshing;
  mesh_surfaces(cube.points, cube.triangles, options, &as_given);
  const Tetrahedral_mesh mesh = mesh_surfaces(remeshed.points, remeshed.triangles, options, &after_remeshing);
  EXPECT_EQ(as_given.triangles_over_size, 12u);
  EXPECT_GT(as_given.improvement.bad_after, 0u);
  EXPECT_EQ(after_remeshing.triangles_over_size, 0u);
  EXPECT_EQ(after_remeshing.improvement.bad_after, 0u);
  const Quality_report report = quality_report(mesh, 1);
  EXPECT_GE(report.min_dihedral_degrees, options.min_dihedral_target);
  EXPECT_TRUE(report.boundary_equals_input());
}

TEST(SurfaceRemeshing, NestedSurfacesKeepTheirOwnVerticesAndVolumes)
{
  const mesher_shapes::Surface s = mesher_shapes::combine(mesher_shapes::cube(0, 1), mesher_shapes::cube(0.4, 0.6));
  const double length = 0.15;
  const Surface_triangles remeshed = remesh_surfaces(s.points, s.triangles, {length});
  std::size_t outer = 0, inner = 0;
  for(const auto& p : remeshed.points) {
    const bool on_outer = coordinates_on_cube(p, 0, 1) >= 1 && inside_closed_cube(p, 0, 1);
    const bool on_inner = coordinates_on_cube(p, 0.4, 0.6) >= 1 && inside_closed_cube(p, 0.4, 0.6);
    ASSERT_TRUE(on_outer != on_inner) << "a vertex on neither cube, or on both";
    (on_outer ? outer : inner) += 1;
  }
  EXPECT_GT(outer, 200u);
  EXPECT_GE(inner, 8u); // the small cube's faces are about one length wide: little more than its corners
  EXPECT_NEAR(mesher_shapes::enclosed_volume(as_shape(remeshed)), 1.0 + 0.2 * 0.2 * 0.2, 1e-9);
  const Tetrahedral_mesh mesh = mesh_surfaces(remeshed.points, remeshed.triangles);
  EXPECT_EQ(mesh.number_of_subdomains, 2);
}

TEST(SurfaceRemeshing, ASmoothSurfaceStaysOnItsTriangles)
{
  typedef CGAL::Epick K;
  const mesher_shapes::Surface sphere = mesher_shapes::icosphere(2);
  Surface_remeshing_options options;
  options.target_edge_length = 0.1;
  const Surface_triangles remeshed = remesh_surfaces(sphere.points, sphere.triangles, options);
  // Every vertex projected onto one of the input's flat triangles.
  std::vector<K::Triangle_3> input;
  auto point = [](const std::array<double, 3>& p) { return K::Point_3(p[0], p[1], p[2]); };
  for(const auto& t : sphere.triangles)
    input.emplace_back(point(sphere.points[t[0]]), point(sphere.points[t[1]]), point(sphere.points[t[2]]));
  typedef CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::iterator>>>
      Tree;
  const Tree tree(input.begin(), input.end());
  for(const auto& p : remeshed.points) ASSERT_LT(tree.squared_distance(point(p)), 1e-24);
  const double input_volume = mesher_shapes::enclosed_volume(sphere);
  EXPECT_NEAR(mesher_shapes::enclosed_volume(as_shape(remeshed)), input_volume, 0.01 * input_volume);
  const std::vector<double> lengths = edge_lengths(remeshed);
  EXPECT_GT(lengths[lengths.size() / 2], 0.7 * options.target_edge_length);
  EXPECT_LT(lengths[lengths.size() / 2], 4.0 / 3 * options.target_edge_length);
}

TEST(SurfaceRemeshing, SurfacesRemeshedIntoEachOtherAreRefused)
{
  // Spheres 0.01 apart, remeshed to 0.3: the outer one's chords cut 0.011
  // into it, through the inner one.
  const mesher_shapes::Surface s = mesher_shapes::combine(mesher_shapes::icosphere(3, 1), mesher_shapes::icosphere(3, 0.99));
  remesh_surfaces(s.points, s.triangles, {0.12}); // chords cutting 0.002 deep: accepted
  try {
    remesh_surfaces(s.points, s.triangles, {0.3});
    ADD_FAILURE() << "accepted";
  } catch(const Invalid_surface& e) {
    EXPECT_NE(std::string(e.what()).find("are not valid mesher input"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("intersect"), std::string::npos) << e.what();
  }
}

// The unit cube's faces as n x n grids whose inner points are pushed
// towards a diagonal within their face, split along the other diagonal:
// skinny triangles, some of which the other diagonal widens.  The faces at
// 0 are exactly planar (every term of their coordinate is 0).
CGAL::Surface_mesh<CGAL::Epick::Point_3> skewed_cube(int n)
{
  typedef CGAL::Epick::Point_3 P;
  CGAL::Surface_mesh<P> mesh;
  std::map<std::array<long, 3>, CGAL::Surface_mesh<P>::Vertex_index> at;
  auto vertex = [&](const std::array<double, 3>& p) {
    const std::array<long, 3> key{std::lround(p[0] * 1e9), std::lround(p[1] * 1e9), std::lround(p[2] * 1e9)};
    auto it = at.find(key);
    if(it == at.end()) it = at.emplace(key, mesh.add_vertex(P(p[0], p[1], p[2]))).first;
    return it->second;
  };
  const mesher_shapes::Surface cube = mesher_shapes::cube(0, 1);
  for(std::size_t f = 0; f < cube.triangles.size(); f += 2) { // the quads (a, b, c, d), counter-clockwise
    const std::array<std::size_t, 4> q{cube.triangles[f][0], cube.triangles[f][1], cube.triangles[f][2],
                                       cube.triangles[f + 1][2]};
    auto point = [&](int i, int j) {
      double s = double(i) / n, t = double(j) / n;
      if(i > 0 && i < n && j > 0 && j < n) { // inside the face: pushed towards the (s = t) diagonal
        const double m = (s + t) / 2;
        s = m + 0.15 * (s - m);
        t = m + 0.15 * (t - m);
      }
      std::array<double, 3> p;
      for(int k = 0; k < 3; ++k)
        p[k] = (1 - s) * (1 - t) * cube.points[q[0]][k] + s * (1 - t) * cube.points[q[1]][k] +
               s * t * cube.points[q[2]][k] + (1 - s) * t * cube.points[q[3]][k];
      return vertex(p);
    };
    for(int i = 0; i < n; ++i)
      for(int j = 0; j < n; ++j) {
        const auto v00 = point(i, j), v10 = point(i + 1, j), v11 = point(i + 1, j + 1), v01 = point(i, j + 1);
        mesh.add_face(v00, v10, v01);
        mesh.add_face(v10, v11, v01);
      }
  }
  return mesh;
}

TEST(SurfaceRemeshing, FlipsWidenTheSmallestAngleOfCoplanarTriangles)
{
  typedef CGAL::Surface_mesh<CGAL::Epick::Point_3> Mesh;
  Mesh mesh = skewed_cube(6);
  ASSERT_TRUE(mesh.is_valid() && CGAL::is_closed(mesh));
  // Over the faces but z = 0, which holds the features.
  auto smallest_of_all = [](const Mesh& m) {
    double smallest = CGAL_PI;
    for(auto f : faces(m)) {
      const auto h = halfedge(f, m);
      if(m.point(source(h, m)).z() == 0 && m.point(target(h, m)).z() == 0 && m.point(target(next(h, m), m)).z() == 0)
        continue;
      smallest = std::min(smallest, remeshing_detail::smallest_angle(m.point(source(h, m)), m.point(target(h, m)),
                                                                     m.point(target(next(h, m), m))));
    }
    return smallest;
  };
  auto volume = [](const Mesh& m) {
    Surface_triangles s;
    for(auto v : vertices(m)) s.points.push_back({m.point(v).x(), m.point(v).y(), m.point(v).z()});
    for(auto f : faces(m)) {
      std::array<std::size_t, 3> t;
      int i = 0;
      for(auto v : vertices_around_face(halfedge(f, m), m)) t[i++] = std::size_t(v);
      s.triangles.push_back(t);
    }
    return mesher_shapes::enclosed_volume(as_shape(s));
  };
  const double before = smallest_of_all(mesh);
  // The edges inside the face z = 0 marked as features: they stay.
  auto sharp = mesh.add_property_map<Mesh::Edge_index, bool>("e:sharp", false).first;
  std::vector<std::pair<Mesh::Vertex_index, Mesh::Vertex_index>> kept;
  for(auto e : edges(mesh)) {
    const auto u = source(halfedge(e, mesh), mesh), v = target(halfedge(e, mesh), mesh);
    const auto &p = mesh.point(u), &q = mesh.point(v);
    const bool inside_the_face = p.z() == 0 && q.z() == 0 && !(p.x() == q.x() && (p.x() == 0 || p.x() == 1)) &&
                                 !(p.y() == q.y() && (p.y() == 0 || p.y() == 1));
    if(inside_the_face) {
      put(sharp, e, true);
      kept.emplace_back(u, v);
    }
  }
  remeshing_detail::flip_to_wider_angles(mesh, sharp);
  ASSERT_TRUE(mesh.is_valid() && CGAL::is_closed(mesh));
  for(const auto& uv : kept) EXPECT_TRUE(CGAL::halfedge(uv.first, uv.second, mesh).second) << "a feature flipped";
  EXPECT_LT(before * 180 / CGAL_PI, 13); // 12.8 degrees, 14.7 after the flips
  EXPECT_GT(smallest_of_all(mesh), 1.1 * before);
  EXPECT_NEAR(volume(mesh), 1.0, 1e-12); // flips within the faces: the cube unchanged
  // No edge inside the faces x = 0 and y = 0 is left whose flip would widen
  // its triangles (z = 0 holds the features).
  std::size_t flippable = 0;
  for(auto e : edges(mesh)) {
    const auto h = halfedge(e, mesh), o = opposite(h, mesh);
    const auto &a = mesh.point(source(h, mesh)), &b = mesh.point(target(h, mesh));
    const auto &c = mesh.point(target(next(h, mesh), mesh)), &d = mesh.point(target(next(o, mesh), mesh));
    const bool on_x0 = a.x() == 0 && b.x() == 0 && c.x() == 0 && d.x() == 0;
    const bool on_y0 = a.y() == 0 && b.y() == 0 && c.y() == 0 && d.y() == 0;
    if(!(on_x0 || on_y0) || degree(source(h, mesh), mesh) <= 3 || degree(target(h, mesh), mesh) <= 3) continue;
    // The other diagonal of a convex quadrilateral, not yet an edge: a flip
    // the pass could have made.
    const bool convex = CGAL::coplanar_orientation(a, b, c, d) == CGAL::NEGATIVE &&
                        CGAL::coplanar_orientation(c, d, a, b) == CGAL::NEGATIVE;
    bool joined = false;
    for(auto around : halfedges_around_target(target(next(h, mesh), mesh), mesh))
      joined = joined || source(around, mesh) == target(next(o, mesh), mesh);
    if(!convex || joined) continue;
    ++flippable;
    const double now = std::min(remeshing_detail::smallest_angle(a, b, c), remeshing_detail::smallest_angle(b, a, d));
    const double after = std::min(remeshing_detail::smallest_angle(a, d, c), remeshing_detail::smallest_angle(b, c, d));
    EXPECT_LE(after, now * (1 + 1e-6));
  }
  EXPECT_GT(flippable, 80u); // the check above looked at the edges inside those faces
}

mesher_shapes::Surface plate(double thickness)
{
  mesher_shapes::Surface plate = mesher_shapes::cube(0, 1);
  for(auto& p : plate.points) p[2] *= thickness;
  return plate;
}

// A plate 0.05 thick remeshed to 0.1: a triangle on one face lies over
// vertices of the other, closer than it is wide, and the tetrahedra
// between them have their four vertices on the surface: no interior point
// mends them.  Meshing the remeshed plate shortens the length until the
// mesh has none; with no shortening allowed, or no improvement to count
// them, they stay.
TEST(SurfaceRemeshing, MeshingShortensTheLengthWhereAWallIsThinnerThanIt)
{
  const mesher_shapes::Surface thin = plate(0.05);
  Surface_remeshing_options once;
  once.target_edge_length = 0.1;
  once.shortenings = 0;
  Mesher_statistics first;
  mesh_remeshed_surfaces(thin.points, thin.triangles, once, Mesher_options(), &first);
  EXPECT_EQ(first.remeshing_attempts, 1u);
  EXPECT_EQ(first.remeshed_edge_length, 0.1);
  EXPECT_EQ(first.discarded_meshing_seconds, 0);
  EXPECT_GT(first.improvement.bad_after_on_surface_not_forced, 0u);

  Mesher_options unoptimized;
  unoptimized.optimize = false;
  Mesher_statistics plain;
  mesh_remeshed_surfaces(thin.points, thin.triangles, {0.1}, unoptimized, &plain);
  EXPECT_EQ(plain.remeshing_attempts, 1u);

  // Through a file as through memory: the same mesh.
  const std::string path =
      (std::filesystem::temp_directory_path() / "fdt3_surface_remeshing_plate.off").string();
  mesher_shapes::write_off(path, thin);
  Mesher_statistics shortened;
  const Tetrahedral_mesh mesh = mesh_remeshed_surface_files({path}, {0.1}, Mesher_options(), &shortened);
  std::filesystem::remove(path);
  EXPECT_GT(shortened.remeshing_attempts, 1u);
  EXPECT_EQ(shortened.improvement.bad_after_on_surface_not_forced, 0u);
  // None left: the last attempt is the one kept.
  EXPECT_DOUBLE_EQ(shortened.remeshed_edge_length, 0.1 * std::pow(0.9, shortened.remeshing_attempts - 1));
  EXPECT_LT(shortened.improvement.bad_after, first.improvement.bad_after);
  EXPECT_EQ(shortened.remeshed_triangles, mesh.triangles.size());
  EXPECT_GT(shortened.remeshed_triangles, first.remeshed_triangles);
  mesher_checks::expect_all_positive(mesh);
  EXPECT_NEAR(mesher_checks::volume_of_subdomain(mesh, 1), 0.05, 1e-12);
  const Tetrahedral_mesh in_memory = mesh_remeshed_surfaces(thin.points, thin.triangles, {0.1});
  EXPECT_EQ(in_memory.points, mesh.points);
  EXPECT_EQ(in_memory.tetrahedra, mesh.tetrahedra);
}

TEST(SurfaceRemeshing, BadOptionsAndSurfacesAreRefused)
{
  const mesher_shapes::Surface cube = mesher_shapes::cube(0, 1);
  // What `call` is refused with, or "accepted".
  auto refusal_of = [](auto&& call) -> std::string {
    try {
      call();
    } catch(const std::invalid_argument& e) {
      return e.what();
    }
    return "accepted";
  };
  auto message_of = [&](const Surface_remeshing_options& options, const mesher_shapes::Surface& s) {
    return refusal_of([&] { remesh_surfaces(s.points, s.triangles, options); });
  };
  for(double length : {0.0, -1.0, std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()})
    EXPECT_NE(message_of({length}, cube).find("target_edge_length must be positive"), std::string::npos) << length;
  EXPECT_NE(message_of({1e-6}, cube).find("would give about"), std::string::npos);
  Surface_remeshing_options options;
  options.target_edge_length = 0.1;
  options.sharp_edge_angle = 200;
  EXPECT_NE(message_of(options, cube).find("sharp_edge_angle"), std::string::npos);
  options.sharp_edge_angle = 60;
  options.iterations = 0;
  EXPECT_NE(message_of(options, cube).find("iterations"), std::string::npos);

  options.iterations = 3;
  options.shortenings = 21;
  EXPECT_NE(message_of(options, cube).find("shortenings"), std::string::npos);
  EXPECT_NE(refusal_of([&] { mesh_remeshed_surfaces(cube.points, cube.triangles, {0.0}); })
                .find("target_edge_length must be positive"),
            std::string::npos);
  // Refused before the file is read: the targets are checked first.
  Mesher_options bad_target;
  bad_target.quality_threshold = 2;
  EXPECT_NE(refusal_of([&] { mesh_remeshed_surface_files({"no such file.off"}, {0.1}, bad_target); })
                .find("quality_threshold"),
            std::string::npos);

  mesher_shapes::Surface open = cube;
  open.triangles.pop_back();
  EXPECT_THROW(remesh_surfaces(open.points, open.triangles, {0.1}), Invalid_surface);
  EXPECT_THROW(mesh_remeshed_surfaces(open.points, open.triangles, {0.1}), Invalid_surface);
  try {
    remesh_surface_files({"no such file.off"}, {0.1});
    ADD_FAILURE() << "a missing file accepted";
  } catch(const std::exception& e) {
    EXPECT_NE(std::string(e.what()).find("no such file.off"), std::string::npos) << e.what();
  }
}

} // namespace test_mesher_surface_remeshing
