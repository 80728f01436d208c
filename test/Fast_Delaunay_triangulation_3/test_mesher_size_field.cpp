// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The user's size: a function h(x, y, z), a cap per subdomain, a size-field
// file (subdomain caps and background points).  Refinement follows them
// where they are below the surface's size and leaves the rest alone; a
// function that returns no size, or throws, is reported on the caller's
// thread, also from the partitions' threads; a malformed file is refused
// with its line, the options left as they were.

#include <CGAL/Fast_Delaunay_triangulation_3/Surface_remeshing.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <gtest/gtest.h>

#include "mesher_checks.h"
#include "mesher_shapes.h"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace test_mesher_size_field {

using namespace CGAL::Fast_mesher_3;

// Tetrahedra whose centroid has x above / below 0.
std::array<std::size_t, 2> tetrahedra_by_side(const Tetrahedral_mesh& mesh)
{
  std::array<std::size_t, 2> n = {0, 0};
  for(const auto& t : mesh.tetrahedra) {
    double x = 0;
    for(std::uint32_t v : t) x += mesh.points[v][0] / 4;
    ++n[x > 0 ? 0 : 1];
  }
  return n;
}

// The Steiner points' nearest surface vertex: the k-d tree's answer is the
// scan's, ties (points halfway between two, at a grid cell's centre with
// more equally near points than the tree is first asked for, on a vertex
// and its copy) included, and the scan takes the first in index order.
TEST(SizeField, NearestInputPointByTreeAsByScan)
{
  namespace fdt = CGAL::Fast_Delaunay_triangulation_3_internal;
  std::vector<std::array<double, 3>> points;
  for(int i = 0; i < 6; ++i)
    for(int j = 0; j < 6; ++j)
      for(int k = 0; k < 6; ++k) points.push_back({0.25 * i, 0.25 * j, 0.25 * k});
  CGAL::Random random(5);
  for(int i = 0; i < 300; ++i) // away from the grid, whose ties the first queries test
    points.push_back({random.get_double(2, 3), random.get_double(2, 3), random.get_double(2, 3)});
  for(std::size_t i = 0; i < 216; i += 7) points.push_back(points[i]); // duplicates: the first copy wins

  fdt::Flat_storage m;
  std::vector<fdt::Vertex_id> queries;
  auto add_query = [&](double x, double y, double z) {
    fdt::Vertex_record record = {{x, y, z}, 0};
    m.vertices.push_back(record);
    queries.push_back(static_cast<fdt::Vertex_id>(m.vertices.size() - 1));
  };
  add_query(0.125, 0.5, 0.5);    // halfway between two grid points
  add_query(0.125, 0.125, 0.125); // the centre of a grid cell: its 8 corners and 3 copies, 11 at once
  add_query(0.25, 0.5, 0.25);    // on a grid point
  for(std::size_t i = 0; i < 216; i += 7) add_query(points[i][0], points[i][1], points[i][2]);
  for(int i = 0; i < 500; ++i)
    add_query(random.get_double(-0.5, 3.5), random.get_double(-0.5, 3.5), random.get_double(-0.5, 3.5));

  const std::vector<std::size_t> scan = fdt::mesher::nearest_input_points(points, m, queries, 0);
  const std::vector<std::size_t> tree = fdt::mesher::nearest_input_points(points, m, queries, 1);
  EXPECT_EQ(tree, scan);
  // Halfway between (0, 0.5, 0.5) and (0.25, 0.5, 0.5): the first of them.
  EXPECT_EQ(scan[0], std::size_t(0 * 36 + 2 * 6 + 2));
  EXPECT_EQ(scan[1], std::size_t(0));
  EXPECT_EQ(scan[2], std::size_t(1 * 36 + 2 * 6 + 1));
  for(std::size_t i = 0, q = 3; i < 216; i += 7, ++q) EXPECT_EQ(scan[q], i);
  // Against a plain minimum.
  for(std::size_t q = 0; q < queries.size(); ++q) {
    double least = std::numeric_limits<double>::infinity();
    for(const auto& p : points) least = std::min(least, fdt::mesher::distance(m.point(queries[q]), p.data()));
    EXPECT_EQ(fdt::mesher::distance(m.point(queries[q]), points[scan[q]].data()), least) << q;
  }
  // 30 points at distance 5 from the origin, (5, 0, 0) and (3, 4, 0) with
  // their signs and axes, in a shuffled order among farther ones: the tree
  // must be asked for more than eight to find the first of them.
  std::vector<std::array<double, 3>> sphere;
  for(int axis = 0; axis < 3; ++axis)
    for(double sign : {-1.0, 1.0}) {
      std::array<double, 3> p = {0, 0, 0};
      p[axis] = 5 * sign;
      sphere.push_back(p);
      for(int other = 0; other < 3; ++other)
        if(other != axis)
          for(double other_sign : {-1.0, 1.0}) {
            std::array<double, 3> r = {0, 0, 0};
            r[axis] = 3 * sign;
            r[other] = 4 * other_sign;
            sphere.push_back(r);
          }
    }
  ASSERT_EQ(sphere.size(), 30u);
  for(int i = 0; i < 200; ++i) sphere.push_back({random.get_double(6, 9), random.get_double(6, 9), random.get_double(-9, 9)});
  for(std::size_t i = sphere.size() - 1; i > 0; --i)
    std::swap(sphere[i], sphere[static_cast<std::size_t>(random.get_int(0, int(i) + 1))]);
  std::size_t first_at_5 = 0;
  while(std::abs(fdt::mesher::distance(sphere[first_at_5].data(), std::array<double, 3>{0, 0, 0}.data()) - 5) > 0)
    ++first_at_5;
  fdt::Flat_storage origin;
  origin.vertices.push_back(fdt::Vertex_record{{0, 0, 0}, 0});
  EXPECT_EQ(fdt::mesher::nearest_input_points(sphere, origin, {0}, 1), std::vector<std::size_t>{first_at_5});
  EXPECT_EQ(fdt::mesher::nearest_input_points(sphere, origin, {0}, 0), std::vector<std::size_t>{first_at_5});

  // Nothing to search among, or nothing to search for.
  EXPECT_TRUE(fdt::mesher::nearest_input_points(points, m, {}).empty());
  EXPECT_EQ(fdt::mesher::nearest_input_points({}, m, queries),
            std::vector<std::size_t>(queries.size(), std::size_t(-1)));
}

TEST(SizeField, FunctionRefinesWhereItIsBelowTheSurfaceSize)
{
  const mesher_shapes::Surface s = mesher_shapes::torus(1, 0.35, 40, 16);
  for(int threads : {1, 2}) {
    SCOPED_TRACE("threads " + std::to_string(threads));
    Mesher_options plain_options;
    plain_options.threads = threads;
    // The torus's triangles are over 0.05: the improvement works in vain
    // on the flat tetrahedra along them and takes most of the time, so it
    // runs once, on 1 thread, to check its Steiner points' sizes too.
    plain_options.optimize = false;
    Mesher_options fine = plain_options;
    fine.optimize = threads == 1;
    fine.size_function = [](double x, double, double) { return x > 0 ? 0.05 : 1e3; };
    const Tetrahedral_mesh plain = mesh_surfaces(s.points, s.triangles, plain_options);
    const Tetrahedral_mesh mesh = mesh_surfaces(s.points, s.triangles, fine);
    const auto n_plain = tetrahedra_by_side(plain), n = tetrahedra_by_side(mesh);
    EXPECT_GT(n[0], 3 * n_plain[0]); // the half where h is 0.05
    // The other half: refined only in the band near x = 0, where the
    // sizes blend.
    EXPECT_LT(n[1], 2 * n_plain[1]);
    EXPECT_LT(n[1], n[0] / 2);
    // Every point's size is the function's where it is smaller.
    for(std::size_t v = 0; v < mesh.points.size(); ++v) {
      if(mesh.points[v][0] > 0) {
        EXPECT_LE(mesh.size[v], 0.05 * (1 + 1e-12)) << v;
      }
    }
    mesher_checks::expect_all_positive(mesh);
    mesher_checks::expect_boundary_is_input(mesh, s);
    EXPECT_NEAR(mesher_checks::volume_of_subdomain(mesh, 1), mesher_checks::volume_of_subdomain(plain, 1),
                1e-9 * mesher_checks::volume_of_subdomain(plain, 1));
  }
}

TEST(SizeField, CapPerSubdomain)
{
  const mesher_shapes::Surface s =
      mesher_shapes::combine(mesher_shapes::icosphere(2, 1.0), mesher_shapes::icosphere(1, 0.4, {0.02, 0.01, 0}));
  const Tetrahedral_mesh plain = mesh_surfaces(s.points, s.triangles);
  ASSERT_EQ(plain.number_of_subdomains, 2);
  const int inner =
      mesher_checks::volume_of_subdomain(plain, 1) < mesher_checks::volume_of_subdomain(plain, 2) ? 1 : 2;
  auto count = [](const Tetrahedral_mesh& m, int subdomain) {
    return static_cast<std::size_t>(std::count(m.subdomain.begin(), m.subdomain.end(), subdomain));
  };
  Mesher_options options;
  options.subdomain_sizes.assign(2, 0.0);
  options.subdomain_sizes[inner - 1] = 0.05;
  const Tetrahedral_mesh capped = mesh_surfaces(s.points, s.triangles, options);
  ASSERT_EQ(capped.number_of_subdomains, 2);
  const int inner_capped =
      mesher_checks::volume_of_subdomain(capped, 1) < mesher_checks::volume_of_subdomain(capped, 2) ? 1 : 2;
  EXPECT_GT(count(capped, inner_capped), 5 * count(plain, inner));
  EXPECT_LT(count(capped, 3 - inner_capped), count(plain, 3 - inner) * 3 / 2);
  // Inside the capped subdomain, every point off the surface has h <= the cap.
  std::vector<char> on_surface(capped.points.size(), 0);
  for(const auto& tri : capped.triangles)
    for(std::uint32_t v : tri) on_surface[v] = 1;
  for(std::size_t t = 0; t < capped.tetrahedra.size(); ++t) {
    if(capped.subdomain[t] != inner_capped) continue;
    for(std::uint32_t v : capped.tetrahedra[t]) {
      if(!on_surface[v]) {
        EXPECT_LE(capped.size[v], 0.05 * (1 + 1e-12));
      }
    }
  }
  mesher_checks::expect_boundary_is_input(capped, s);

  Mesher_options negative;
  negative.subdomain_sizes = {-1};
  EXPECT_THROW(mesh_surfaces(s.points, s.triangles, negative), std::invalid_argument);
  // Bad bounds are refused before the file is read, and before a remeshing.
  Mesher_options no_size;
  no_size.maximum_size = 0;
  for(const Mesher_options& bad : {negative, no_size}) {
    const std::string name = bad.maximum_size > 0 ? "subdomain_sizes[0]" : "maximum_size";
    for(int remeshed = 0; remeshed < 2; ++remeshed) {
      try {
        if(remeshed) mesh_remeshed_surface_files({"no such file.off"}, {0.1}, bad);
        else mesh_surface_files({"no such file.off"}, bad);
        ADD_FAILURE() << name << " accepted";
      } catch(const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
      }
    }
  }
}

// Input triangles over the size next to them are counted once each, with
// a subdomain's cap applying on its side only.  Cubes [0, 1]^3 and
// [0.3, 0.7]^3: their right triangles have circumradius 0.707 and 0.283.
TEST(SizeField, TrianglesOverTheSizeAreCounted)
{
  const mesher_shapes::Surface s = mesher_shapes::combine(mesher_shapes::cube(0, 1), mesher_shapes::cube(0.3, 0.7));
  Mesher_statistics stats;
  Mesher_options options;
  options.optimize = false;
  const Tetrahedral_mesh plain = mesh_surfaces(s.points, s.triangles, options, &stats);
  ASSERT_EQ(plain.number_of_subdomains, 2);
  EXPECT_EQ(stats.triangles_over_size, 0u); // h from the surface's own edges
  const int inner = mesher_checks::volume_of_subdomain(plain, 1) < mesher_checks::volume_of_subdomain(plain, 2) ? 1 : 2;
  auto over_size = [&](const Mesher_options& o) {
    Mesher_statistics st;
    mesh_surfaces(s.points, s.triangles, o, &st);
    return st.triangles_over_size;
  };
  Mesher_options cap = options;
  cap.maximum_size = 0.6; // 1.4 h = 0.84: every triangle within
  EXPECT_EQ(over_size(cap), 0u);
  cap.maximum_size = 0.4; // 1.4 h = 0.56: the outer cube's triangles over it
  EXPECT_EQ(over_size(cap), 12u);
  cap.maximum_size = 0.1; // every triangle over it, the inner ones counted once
  EXPECT_EQ(over_size(cap), 24u);
  Mesher_options inner_cap = options;
  inner_cap.subdomain_sizes.assign(2, 0.0);
  inner_cap.subdomain_sizes[inner - 1] = 0.1; // only the inner cube's triangles border it
  EXPECT_EQ(over_size(inner_cap), 12u);
  Mesher_options outer_cap = options;
  outer_cap.subdomain_sizes.assign(2, 0.0);
  outer_cap.subdomain_sizes[2 - inner] = 0.1; // both cubes' triangles border the shell
  EXPECT_EQ(over_size(outer_cap), 24u);
}

TEST(SizeField, AFunctionWithoutASizeIsReported)
{
  const mesher_shapes::Surface s = mesher_shapes::torus(1, 0.35, 20, 8);
  for(int threads : {1, 2}) {
    Mesher_options options;
    options.threads = threads;
    options.size_function = [](double x, double, double) {
      return x > 0.5 ? std::numeric_limits<double>::quiet_NaN() : 0.1;
    };
    try {
      mesh_surfaces(s.points, s.triangles, options);
      ADD_FAILURE() << "a NaN size was accepted";
    } catch(const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("size_function("), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("not a positive finite size"), std::string::npos) << e.what();
    }
    options.size_function = [](double, double, double) { return -1.0; };
    EXPECT_THROW(mesh_surfaces(s.points, s.triangles, options), std::invalid_argument);
    options.size_function = [](double x, double, double) -> double {
      if(x < -0.5) throw std::runtime_error("the user's own error");
      return 0.2;
    };
    try {
      mesh_surfaces(s.points, s.triangles, options);
      ADD_FAILURE() << "the function's exception was lost";
    } catch(const std::runtime_error& e) {
      EXPECT_EQ(std::string(e.what()), "the user's own error");
    }
  }
}

std::string write_file(const std::string& name, const std::string& text)
{
  const std::string path = testing::TempDir() + name;
  std::ofstream(path) << text;
  return path;
}

TEST(SizeField, FileWithSubdomainsAndBackgroundPoints)
{
  const std::string path = write_file("fdt3_size_field.txt",
                                      "# a comment\n"
                                      "subdomain 2 0.25   # the second volume\n"
                                      "\n"
                                      "0 0 0 0.5\n"
                                      "1 0 0 0.125\n");
  Mesher_options options;
  read_size_field(path, options);
  ASSERT_EQ(options.subdomain_sizes.size(), 2u);
  EXPECT_EQ(options.subdomain_sizes[0], 0.0);
  EXPECT_EQ(options.subdomain_sizes[1], 0.25);
  ASSERT_TRUE(static_cast<bool>(options.size_function));
  EXPECT_EQ(options.size_function(0.1, 0, 0), 0.5);   // nearest: the origin
  EXPECT_EQ(options.size_function(0.9, 0.2, 0), 0.125);
  // Combined with a function already given: the smaller.
  Mesher_options both;
  both.size_function = [](double, double, double) { return 0.3; };
  read_size_field(path, both);
  EXPECT_EQ(both.size_function(0.1, 0, 0), 0.3);
  EXPECT_EQ(both.size_function(0.9, 0, 0), 0.125);

  // A mesh with it: the background points cap h near them.
  const mesher_shapes::Surface s = mesher_shapes::cube(0, 1);
  const Tetrahedral_mesh plain = mesh_surfaces(s.points, s.triangles);
  Mesher_options fine;
  read_size_field(write_file("fdt3_size_field_fine.txt", "0.5 0.5 0.5 0.1\n"), fine);
  const Tetrahedral_mesh mesh = mesh_surfaces(s.points, s.triangles, fine);
  EXPECT_GT(mesh.tetrahedra.size(), 10 * plain.tetrahedra.size());
  mesher_checks::expect_boundary_is_input(mesh, s);
}

TEST(SizeField, MalformedFilesAreRefusedWithTheirLine)
{
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"0 0 0\n", "line 1: expected 'X Y Z H' or 'subdomain S H', found 3 words"},
      {"# ok\n0 0 0 1\n0 0 x 1\n", "line 3: 'x' is not a finite coordinate"},
      {"0 0 0 -1\n", "line 1: '-1' is not a positive finite size"},
      {"0 0 0 1e400\n", "line 1: '1e400' is not a positive finite size"},
      {"subdomain 0 1\n", "line 1: '0' is not a subdomain number"},
      {"subdomain 1\n", "line 1: 'subdomain S H' takes two numbers, not 1"},
      {"subdomain 1 0.5\nsubdomain 1 0.25\n", "line 2: subdomain 1 is given twice"},
      {"# nothing\n\n", "no entries"},
  };
  for(const auto& c : cases) {
    Mesher_options options;
    options.subdomain_sizes = {7};
    try {
      read_size_field(write_file("fdt3_bad_size_field.txt", c.first), options);
      ADD_FAILURE() << "accepted: " << c.first;
    } catch(const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.second), std::string::npos) << e.what();
    }
    EXPECT_EQ(options.subdomain_sizes, std::vector<double>{7});
    EXPECT_FALSE(static_cast<bool>(options.size_function));
  }
  Mesher_options options;
  EXPECT_THROW(read_size_field(testing::TempDir() + "fdt3_no_such_file.txt", options), std::invalid_argument);
}

} // namespace test_mesher_size_field
