// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher's input checks: every bad surface is refused with an
// Invalid_surface whose message names the problem (and the triangles), and
// good files in each format are read.

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <gtest/gtest.h>

#include "mesher_checks.h"
#include "mesher_shapes.h"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace test_mesher_input {

using mesher_shapes::Surface;
namespace fm = CGAL::Fast_mesher_3;

std::string temporary(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("fdt3_mesher_input_" + name)).string();
}

// Runs `call`, which must throw Invalid_surface; returns its message.
template <class Call>
std::string refusal(Call call)
{
  try {
    call();
  } catch(const fm::Invalid_surface& e) {
    return e.what();
  }
  ADD_FAILURE() << "no Invalid_surface thrown";
  return std::string();
}

std::string refusal_of(const Surface& s)
{
  return refusal([&] { fm::mesh_surfaces(s.points, s.triangles); });
}

std::string refusal_of_file(const std::string& path)
{
  return refusal([&] { fm::mesh_surface_files({path}); });
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

TEST(MesherInput, EmptyFile)
{
  const std::string path = temporary("empty.off");
  { std::ofstream out(path); }
  const std::string message = refusal_of_file(path);
  EXPECT_TRUE(contains(message, "empty")) << message;
  std::remove(path.c_str());
}

TEST(MesherInput, FileWithoutTriangles)
{
  const std::string path = temporary("points_only.off");
  {
    std::ofstream out(path);
    out << "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n";
  }
  const std::string message = refusal_of_file(path);
  EXPECT_TRUE(contains(message, "no triangles")) << message;
  std::remove(path.c_str());
}

TEST(MesherInput, MissingFile)
{
  const std::string message = refusal_of_file(temporary("does_not_exist.off"));
  EXPECT_TRUE(contains(message, "cannot open")) << message;
}

TEST(MesherInput, NaNCoordinate)
{
  Surface s = mesher_shapes::cube();
  s.points[5][1] = std::numeric_limits<double>::quiet_NaN();
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "NaN")) << message;
  EXPECT_TRUE(contains(message, "#5")) << message;
}

TEST(MesherInput, NaNCoordinateInFile)
{
  const std::string path = temporary("nan.off");
  Surface s = mesher_shapes::cube();
  mesher_shapes::write_off(path, s);
  // Replace the second coordinate of point 3 by "nan" in the text.
  std::ifstream in(path);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  in.close();
  std::ofstream out(path);
  out << "OFF\n8 12 0\n";
  for(std::size_t i = 0; i < s.points.size(); ++i) {
    if(i == 3) out << s.points[i][0] << " nan " << s.points[i][2] << "\n";
    else out << s.points[i][0] << ' ' << s.points[i][1] << ' ' << s.points[i][2] << "\n";
  }
  for(const auto& t : s.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << "\n";
  out.close();
  // Either the reader rejects the token or the check names the coordinate:
  // never a mesh.
  const std::string message = refusal_of_file(path);
  EXPECT_TRUE(contains(message, "NaN") || contains(message, "cannot read")) << message;
  std::remove(path.c_str());
}

TEST(MesherInput, InfiniteCoordinate)
{
  Surface s = mesher_shapes::cube();
  s.points[2][0] = std::numeric_limits<double>::infinity();
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "infinite")) << message;
}

TEST(MesherInput, OpenSurface)
{
  Surface s = mesher_shapes::cube();
  s.triangles.erase(s.triangles.begin() + 4); // triangle 4 of the cube
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "open")) << message;
  // The triangles around the hole are named: triangle 5 (the other half of
  // the same face) has a boundary edge.
  EXPECT_TRUE(contains(message, "4")) << message;
}

TEST(MesherInput, NonManifoldEdge)
{
  // Two cubes sharing the edge x = y = 1: four triangles at that edge.
  Surface shifted = mesher_shapes::cube(0, 1);
  for(auto& p : shifted.points) {
    p[0] += 1;
    p[1] += 1;
  }
  const Surface s = mesher_shapes::combine(mesher_shapes::cube(0, 1), shifted);
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "non-manifold edges")) << message;
}

TEST(MesherInput, NonManifoldVertex)
{
  // Two cubes sharing the corner (1, 1, 1), point 7 of the first, to which
  // the second's point 0 is merged.
  const Surface s = mesher_shapes::combine(mesher_shapes::cube(0, 1), mesher_shapes::cube(1, 2));
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "non-manifold vertices")) << message;
  EXPECT_TRUE(contains(message, "#7")) << message;
  // A corner that only meets itself is fine: one cube alone.
  EXPECT_NO_THROW(fm::mesh_surfaces(mesher_shapes::cube().points, mesher_shapes::cube().triangles));
}

TEST(MesherInput, InconsistentOrientation)
{
  Surface s = mesher_shapes::icosphere(1);
  std::swap(s.triangles[7][0], s.triangles[7][1]);
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "orientation")) << message;
  EXPECT_TRUE(contains(message, "7")) << message;
}

TEST(MesherInput, DegenerateTriangle)
{
  // A cube with one face split at its centre into 4 triangles, plus a
  // zero-area sliver triangle: (a, centre, b) collinear.
  Surface s = mesher_shapes::cube();
  s.points.push_back({0.5, 0.5, 0.0}); // centre of the bottom face
  s.points.push_back({0.5, 0.5, 0.0}); // the same point again: merged
  s.triangles[0] = {0, 2, 8};
  s.triangles[1] = {2, 3, 9};          // refers to the duplicate: merged, fine
  s.triangles.push_back({3, 1, 8});
  s.triangles.push_back({1, 0, 8});
  ASSERT_NO_THROW(fm::mesh_surfaces(s.points, s.triangles));
  Surface d = s;
  d.triangles.push_back({0, 8, 8});
  const std::string message = refusal_of(d);
  EXPECT_TRUE(contains(message, "degenerate")) << message;
  EXPECT_TRUE(contains(message, "#14")) << message;
}

TEST(MesherInput, SelfIntersection)
{
  // Two overlapping spheres: closed, oriented, manifold, but crossing.
  const Surface s = mesher_shapes::combine(mesher_shapes::icosphere(1, 1.0),
                                           mesher_shapes::icosphere(1, 1.0, {0.7, 0.1, 0.05}));
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "self-intersecting")) << message;
  EXPECT_TRUE(contains(message, " x ")) << message; // names pairs of triangles
}

TEST(MesherInput, PolygonsOtherThanTrianglesAreRefused)
{
  const std::string path = temporary("quad.off");
  {
    std::ofstream out(path);
    out << "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n";
  }
  const std::string message = refusal_of_file(path);
  EXPECT_TRUE(contains(message, "only triangles")) << message;
  std::remove(path.c_str());
}

TEST(MesherInput, ReadsOffStlObjAndSeveralFiles)
{
  const Surface outer = mesher_shapes::icosphere(1, 1.0);
  const Surface inner = mesher_shapes::icosphere(0, 0.4);
  const std::string off = temporary("outer.off"), obj = temporary("inner.obj"), stl = temporary("inner.stl");
  mesher_shapes::write_off(off, outer);
  {
    std::ofstream out(obj);
    out.precision(17);
    for(const auto& p : inner.points) out << "v " << p[0] << ' ' << p[1] << ' ' << p[2] << "\n";
    for(const auto& t : inner.triangles) out << "f " << t[0] + 1 << ' ' << t[1] + 1 << ' ' << t[2] + 1 << "\n";
  }
  {
    std::ofstream out(stl);
    out.precision(17);
    out << "solid inner\n";
    for(const auto& t : inner.triangles) {
      out << "facet normal 0 0 0\nouter loop\n";
      for(int i = 0; i < 3; ++i)
        out << "vertex " << inner.points[t[i]][0] << ' ' << inner.points[t[i]][1] << ' ' << inner.points[t[i]][2]
            << "\n";
      out << "endloop\nendfacet\n";
    }
    out << "endsolid inner\n";
  }
  for(const std::string& second : {obj, stl}) {
    const fm::Tetrahedral_mesh mesh = fm::mesh_surface_files({off, second});
    EXPECT_EQ(mesh.number_of_surfaces, 2) << second;
    EXPECT_EQ(mesh.number_of_subdomains, 2) << second;
    EXPECT_EQ(mesh.triangles.size(), outer.triangles.size() + inner.triangles.size()) << second;
  }
  for(const std::string& path : {off, obj, stl}) std::remove(path.c_str());
}

// The package reads ASCII OFF files itself (CGAL's reader only for other
// headers): the same points, to the bit, and the same polygons as CGAL's
// reader on files written in the ways the format allows: comments, blank
// lines, counts on the header's line, a number of edges of -1, colours
// after a vertex or a face, tabs and CRLF line ends, coordinates of 17
// digits, exponents, integers, subnormal and underflowing coordinates.
TEST(MesherInput, OffFilesAreReadAsCgalReadsThem)
{
  namespace input = CGAL::Fast_Delaunay_triangulation_3_internal::mesher;
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  const Surface sphere = mesher_shapes::icosphere(2, 1.0);
  std::vector<std::string> texts;
  {
    std::ostringstream plain;
    plain.precision(17);
    plain << "OFF\n" << sphere.points.size() << ' ' << sphere.triangles.size() << " 0\n";
    for(const auto& p : sphere.points) plain << p[0] * 1e-7 << ' ' << p[1] << ' ' << p[2] * 3e5 << "\n";
    for(const auto& t : sphere.triangles) plain << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << "\n";
    texts.push_back(plain.str());
  }
  {
    std::ostringstream awkward;
    awkward.precision(17);
    awkward << "OFF # a comment after the header\n# a comment line\n\n"
            << sphere.points.size() << "\t" << sphere.triangles.size() << " -1 # counts\n";
    for(std::size_t i = 0; i < sphere.points.size(); ++i) {
      awkward << int(std::floor(sphere.points[i][0] * 4)) << ' ' << sphere.points[i][1] << '\t';
      if(i == 5) awkward << "1e-310"; // subnormal
      else if(i == 6) awkward << "-3e-400"; // below the subnormals: -0
      else awkward << sphere.points[i][2];
      awkward << (i % 3 == 0 ? "\r\n" : i % 3 == 1 ? " 0.25 0.5 1 # coloured\n\n" : "\n  # comment\n");
    }
    for(const auto& t : sphere.triangles) awkward << "3  " << t[0] << ' ' << t[1] << ' ' << t[2] << " 0.5 0.5 1\n";
    texts.push_back(awkward.str());
  }
  for(std::size_t k = 0; k < texts.size(); ++k) {
    const std::string path = temporary("as_cgal_" + std::to_string(k) + ".off");
    std::ofstream(path) << texts[k];
    std::vector<std::array<double, 3>> points;
    std::vector<std::vector<std::size_t>> polygons;
    ASSERT_TRUE(input::surface_detail::read_ascii_off(path, points, polygons)) << k;
    std::vector<K::Point_3> cgal_points;
    std::vector<std::vector<std::size_t>> cgal_polygons;
    ASSERT_TRUE(CGAL::IO::read_polygon_soup(path, cgal_points, cgal_polygons)) << k;
    ASSERT_EQ(points.size(), cgal_points.size()) << k;
    for(std::size_t i = 0; i < points.size(); ++i)
      for(int a = 0; a < 3; ++a) ASSERT_EQ(points[i][a], cgal_points[i][a]) << k << ", point " << i;
    EXPECT_EQ(polygons, cgal_polygons) << k;
    std::remove(path.c_str());
  }
  // Other headers are CGAL's to read.
  const std::string coff = temporary("colours.off");
  std::ofstream(coff) << "COFF\n3 1 0\n0 0 0 1 0 0 1\n1 0 0 0 1 0 1\n0 1 0 0 0 1 1\n3 0 1 2\n";
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
  EXPECT_FALSE(input::surface_detail::read_ascii_off(coff, points, polygons));
  EXPECT_TRUE(points.empty() && polygons.empty());
  std::remove(coff.c_str());
}

// A closed surface facing inward (each triangle reversed) is refused, alone
// or nested in a good one, with the surface's number.
TEST(MesherInput, InsideOutSurfacesAreRefused)
{
  Surface inside_out = mesher_shapes::cube();
  for(auto& t : inside_out.triangles) std::swap(t[1], t[2]);
  std::string message = refusal_of(inside_out);
  EXPECT_TRUE(contains(message, "surface 1") && contains(message, "inside out")) << message;
  Surface inner = mesher_shapes::cube(0.25, 0.75);
  for(auto& t : inner.triangles) std::swap(t[1], t[2]);
  message = refusal_of(mesher_shapes::combine(mesher_shapes::cube(), inner));
  EXPECT_TRUE(contains(message, "surface 2") && contains(message, "inside out")) << message;
  // Reversed back, the nested pair is meshed: two subdomains.
  for(auto& t : inner.triangles) std::swap(t[1], t[2]);
  const fm::Tetrahedral_mesh mesh = fm::mesh_surfaces(mesher_shapes::combine(mesher_shapes::cube(), inner).points,
                                                      mesher_shapes::combine(mesher_shapes::cube(), inner).triangles);
  EXPECT_EQ(mesh.number_of_subdomains, 2);
}

// Far from 1 in either direction, the mesh is the unit-size mesh scaled:
// TetGen and the sizes see the input scaled by a power of two (exact), and
// the input points come back bit for bit.
TEST(MesherInput, HugeAndTinyCoordinatesAreMeshed)
{
  const fm::Tetrahedral_mesh unit = fm::mesh_surfaces(mesher_shapes::cube().points, mesher_shapes::cube().triangles);
  for(const double scale : {0x1p330, 0x1p1000, 0x1p-330, 0x1p-1000, 1e100, 1e300, 1e-100, 1e-300}) {
    Surface s = mesher_shapes::cube();
    for(auto& p : s.points)
      for(double& x : p) x *= scale;
    fm::Tetrahedral_mesh mesh;
    ASSERT_NO_THROW(mesh = fm::mesh_surfaces(s.points, s.triangles)) << "scale " << scale;
    mesher_checks::expect_all_positive(mesh);
    mesher_checks::expect_boundary_is_input(mesh, s);
    int exponent;
    const bool power_of_two = std::frexp(scale, &exponent) == 0.5;
    if(power_of_two) { // every coordinate exactly the unit mesh's, scaled
      ASSERT_EQ(mesh.points.size(), unit.points.size()) << "scale " << scale;
      ASSERT_EQ(mesh.tetrahedra, unit.tetrahedra) << "scale " << scale;
      for(std::size_t i = 0; i < mesh.points.size(); ++i)
        for(int a = 0; a < 3; ++a) ASSERT_EQ(mesh.points[i][a], unit.points[i][a] * scale) << "scale " << scale;
    }
  }
}

TEST(MesherInput, CoordinatesNoCommonScaleHoldsAreRefused)
{
  Surface s = mesher_shapes::cube();
  for(auto& p : s.points)
    for(double& x : p) x *= 1e300;
  s.points[0] = {1e-300, 1e-300, 1e-300};
  const std::string message = refusal_of(s);
  EXPECT_TRUE(contains(message, "point #0") && contains(message, "common scale")) << message;
}

// The defects of an OFF file named with their line, not CGAL's generic
// "cannot read".
TEST(MesherInput, OffDefectsAreNamedWithTheirLine)
{
  const Surface cube = mesher_shapes::cube();
  struct Case
  {
    std::string name, header, bad_vertex, bad_face, expected;
  };
  const Case cases[] = {
      {"nan", "8 12 0", "nan 0 0", "", "line 3: vertex 0 has coordinate 'nan'"},
      {"inf", "8 12 0", "0 inf 0", "", "line 3: vertex 0 has coordinate 'inf'"},
      {"huge", "8 12 0", "0 0 1e400", "", "line 3: vertex 0 has coordinate '1e400', not a finite double"},
      {"word", "8 12 0", "0 zero 0", "", "vertex 0 has coordinate 'zero', not a finite decimal number"},
      {"hexadecimal", "8 12 0", "0x1p-1 0 0", "", "vertex 0 has coordinate '0x1p-1', not a finite decimal number"},
      {"binary faces", "8 BINARY 0", "", "", "line 2: the number of faces is 'BINARY', not a count"},
      {"commented", "8 12 0\n# a comment\n\n", "0 0 x", "", "line 6: vertex 0 has coordinate 'x'"},
      {"negative", "-8 12 0", "", "", "line 2: the number of vertices is '-8'"},
      {"trillion", "1000000000000 12 0", "", "", "claims 1000000000000 vertices"},
      {"index", "8 12 0", "", "3 0 1 8", "refers to vertex '8', not one of the 8 vertices"},
      {"two", "8 12 0", "0 0 # z?", "", "line 3: vertex 0 has 2 coordinates, not 3"},
      {"corners", "8 12 0", "", "3 0 1", "line 11: face 0 has 2 of its 3 vertices"},
      {"short", "8 13 0", "", "", "the file ends before face 12 of 13"},
  };
  for(const Case& c : cases) {
    const std::string path = temporary("defect_" + c.name + ".off");
    {
      std::ofstream out(path);
      out << "OFF\n" << c.header << "\n";
      for(std::size_t i = 0; i < cube.points.size(); ++i) {
        if(i == 0 && !c.bad_vertex.empty()) out << c.bad_vertex << "\n";
        else out << cube.points[i][0] << ' ' << cube.points[i][1] << ' ' << cube.points[i][2] << "\n";
      }
      for(std::size_t t = 0; t < cube.triangles.size(); ++t) {
        if(t == 0 && !c.bad_face.empty()) out << c.bad_face << "\n";
        else out << "3 " << cube.triangles[t][0] << ' ' << cube.triangles[t][1] << ' ' << cube.triangles[t][2] << "\n";
      }
    }
    const std::string message = refusal_of_file(path);
    EXPECT_TRUE(contains(message, c.expected)) << c.name << ": " << message;
    EXPECT_TRUE(contains(message, path)) << c.name << ": " << message;
    std::remove(path.c_str());
  }
}

} // namespace test_mesher_input
