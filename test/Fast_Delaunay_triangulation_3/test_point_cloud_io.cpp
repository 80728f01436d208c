// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Point_cloud_io.h's readers on small files written here byte by byte from
// the formats' descriptions (not by the library), with every bad-input case
// the readers name; Triangulation_writers.h's files read back by small
// readers written here and compared with CGAL::Delaunay_triangulation_3 on
// the same points; the progress callback of the insertion.

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Point_cloud_io.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Triangulation_writers.h>

#include <gtest/gtest.h>

#include "point_sets.h"
#include "triangulation_checks.h"

#include <CGAL/Delaunay_triangulation_3.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace test_point_cloud_io {

namespace io = CGAL::Fast_Delaunay_triangulation_3_io;
typedef fdt3_test::K K;
typedef fdt3_test::Point Point;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;
typedef fdt3_test::Cgal_dt Cgal_dt;

std::string temporary(const std::string& name)
{
  return (std::filesystem::temp_directory_path() / ("fdt3_point_cloud_io_" + name)).string();
}

std::string write_file(const std::string& name, const std::string& bytes)
{
  const std::string path = temporary(name);
  std::ofstream out(path, std::ios::binary);
  out.write(bytes.data(), std::streamsize(bytes.size()));
  return path;
}

// The message of the Point_file_error that reading `path` throws ("" if none).
std::string read_error(const std::string& path)
{
  try {
    io::read_points(path);
  } catch(const io::Point_file_error& e) {
    return e.what();
  }
  return std::string();
}

bool contains(const std::string& text, const std::string& part) { return text.find(part) != std::string::npos; }

// Values with exact float and double forms, so that float32 files hold them.
const std::vector<double> three_points = {0.5, -1.25, 3.0, 1e3, 0.125, -7.5, 2.0, 4.0, -0.0625};

// Bytes of value v of type T in the given byte order.
template <class T>
std::string bytes_of(T v, bool little_endian)
{
  char b[sizeof(T)];
  std::memcpy(b, &v, sizeof(T));
  const std::uint16_t one = 1;
  const bool host_little = *reinterpret_cast<const unsigned char*>(&one) == 1;
  if(host_little != little_endian) std::reverse(b, b + sizeof(T));
  return std::string(b, sizeof(T));
}

// ---------------------------------------------------------------- .xyz

TEST(PointCloudXyz, ExtraColumnsCommentsAndBlankLinesAreSkipped)
{
  const std::string path = write_file("a.xyz",
                                      "# a scan\n"
                                      "\n"
                                      "0.5 -1.25 3 0 0 1\n"
                                      "   # indented comment\n"
                                      "+1e3,0.125,-7.5\r\n"
                                      "2\t4\t-0.0625 255 255 255");
  EXPECT_EQ(io::read_xyz(path), three_points);
  EXPECT_EQ(io::read_points(path), three_points);
}

TEST(PointCloudXyz, TwoColumnsAndNonNumbersAreNamed)
{
  const std::string two = read_error(write_file("two.xyz", "1 2 3\n# c\n4 5\n"));
  EXPECT_TRUE(contains(two, "two.xyz: line 3: 2 columns")) << two;
  const std::string word = read_error(write_file("word.xyz", "1 2 3\n4 five 6\n"));
  EXPECT_TRUE(contains(word, "line 2: 'five' is not a number")) << word;
  const std::string glued = read_error(write_file("glued.xyz", "1 2 3x\n"));
  EXPECT_TRUE(contains(glued, "line 1: '3x' is not a number")) << glued;
}

TEST(PointCloudXyz, NanIsReadAndRefusedByTheTriangulation)
{
  const std::vector<double> xyz = io::read_points(write_file("nan.xyz", "0 0 0\n1 0 0\nnan 1 0\n0 0 1\n"));
  ASSERT_EQ(xyz.size(), 12u);
  std::vector<Point> points;
  for(std::size_t i = 0; i < xyz.size(); i += 3) points.emplace_back(xyz[i], xyz[i + 1], xyz[i + 2]);
  Fast_dt tr;
  try {
    tr.insert(points.begin(), points.end());
    FAIL() << "NaN accepted";
  } catch(const std::invalid_argument& e) {
    EXPECT_TRUE(contains(e.what(), "point #2")) << e.what();
    EXPECT_TRUE(contains(e.what(), "NaN")) << e.what();
  }
  EXPECT_EQ(tr.number_of_vertices(), 0u);
}

TEST(PointCloudIo, UnknownExtensionAndMissingFileAreRefused)
{
  EXPECT_TRUE(contains(read_error(write_file("a.txt", "1 2 3\n")), "unknown point file extension"));
  EXPECT_TRUE(contains(read_error(temporary("absent.xyz")), "cannot open"));
}

// ---------------------------------------------------------------- .off

TEST(PointCloudOff, VerticesAreReadAndFacesIgnored)
{
  const std::string off = write_file("a.off",
                                     "OFF\n# comment\n3 1 0\n0.5 -1.25 3\n1e3 0.125 -7.5\n\n2 4 -0.0625\n3 0 1 2\n");
  EXPECT_EQ(io::read_off(off), three_points);
  // Counts on the header line; COFF: a colour after each vertex.
  const std::string coff = write_file("c.off",
                                      "COFF 3 0 0\n0.5 -1.25 3 1 0 0 1\n1e3 0.125 -7.5 1 0 0 1\n2 4 -0.0625 0 0 1 1\n");
  EXPECT_EQ(io::read_points(coff), three_points);
}

TEST(PointCloudOff, BadHeaderAndTruncatedVerticesAreNamed)
{
  const std::string header = read_error(write_file("h.off", "PLY\n3 0 0\n"));
  EXPECT_TRUE(contains(header, "line 1: wrong header 'PLY'")) << header;
  const std::string truncated = read_error(write_file("t.off", "OFF\n3 0 0\n1 2 3\n4 5 6\n"));
  EXPECT_TRUE(contains(truncated, "ends before vertex 2 of 3")) << truncated;
  const std::string count = read_error(write_file("n.off", "OFF\nmany 0 0\n"));
  EXPECT_TRUE(contains(count, "line 2: the vertex count 'many' is not a number")) << count;
  const std::string columns = read_error(write_file("col.off", "OFF\n1 0 0\n1 2\n"));
  EXPECT_TRUE(contains(columns, "line 3: 2 columns")) << columns;
}

// ---------------------------------------------------------------- .ply

TEST(PointCloudPly, AsciiWithOtherPropertiesAndFaces)
{
  const std::string path = write_file("a.ply",
                                      "ply\nformat ascii 1.0\ncomment made by hand\n"
                                      "element vertex 3\nproperty float x\nproperty float y\nproperty double z\n"
                                      "property uchar red\n"
                                      "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                      "0.5 -1.25 3 10\n1e3 0.125 -7.5 20\n2 4 -0.0625 30\n3 0 1 2\n");
  EXPECT_EQ(io::read_ply(path), three_points);
}

// A binary PLY: an element before the vertices (with a list), vertices of
// mixed types with a colour between the coordinates, then faces.
std::string binary_ply(bool little, bool list_in_vertex)
{
  std::string s = std::string("ply\nformat ") + (little ? "binary_little_endian" : "binary_big_endian") +
                  " 1.0\nelement camera 2\nproperty float32 focal\nproperty list uint8 int32 ids\n"
                  "element vertex 3\nproperty float64 x\nproperty uchar red\nproperty float y\nproperty double z\n" +
                  (list_in_vertex ? "property list uchar ushort rings\n" : "") +
                  "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
  for(int c = 0; c < 2; ++c) {
    s += bytes_of(float(35), little);
    s += bytes_of(std::uint8_t(c + 1), little);
    for(int k = 0; k <= c; ++k) s += bytes_of(std::int32_t(k), little);
  }
  for(int i = 0; i < 3; ++i) {
    s += bytes_of(three_points[3 * i], little);
    s += bytes_of(std::uint8_t(200), little);
    s += bytes_of(float(three_points[3 * i + 1]), little);
    s += bytes_of(three_points[3 * i + 2], little);
    if(list_in_vertex) {
      s += bytes_of(std::uint8_t(i), little);
      for(int k = 0; k < i; ++k) s += bytes_of(std::uint16_t(k), little);
    }
  }
  s += bytes_of(std::uint8_t(3), little);
  for(int k = 0; k < 3; ++k) s += bytes_of(std::int32_t(k), little);
  return s;
}

TEST(PointCloudPly, BinaryBothEndiannesses)
{
  for(bool little : {true, false})
    for(bool list : {false, true}) {
      const std::string path = write_file("b.ply", binary_ply(little, list));
      EXPECT_EQ(io::read_points(path), three_points) << (little ? "little" : "big") << " endian, list " << list;
    }
}

TEST(PointCloudPly, BadHeadersAndTruncatedDataAreNamed)
{
  const std::string magic = read_error(write_file("m.ply", "plx\nformat ascii 1.0\n"));
  EXPECT_TRUE(contains(magic, "m.ply: line 1: wrong header")) << magic;
  const std::string integer_x = read_error(write_file(
      "i.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty int x\nproperty float y\nproperty float z\n"
               "end_header\n1 2 3\n"));
  EXPECT_TRUE(contains(integer_x, "line 4: vertex property x must be float or double")) << integer_x;
  const std::string no_z = read_error(write_file(
      "z.ply", "ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n1 2\n"));
  EXPECT_TRUE(contains(no_z, "no property z")) << no_z;
  const std::string format = read_error(write_file("f.ply", "ply\nformat binary_middle_endian 1.0\n"));
  EXPECT_TRUE(contains(format, "line 2: unknown PLY format 'binary_middle_endian'")) << format;
  const std::string word = read_error(write_file(
      "w.ply", "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\nproperty float y\nproperty float z\n"
               "end_header\n1 2 3\n4 y 6\n"));
  EXPECT_TRUE(contains(word, "line 9: 'y' is not a number")) << word;
  // A signed list count of -1 in the element before the vertices.
  const std::string header = "ply\nformat binary_little_endian 1.0\nelement camera 1\n"
                             "property list int8 int32 ids\nelement vertex 0\nproperty float x\n"
                             "property float y\nproperty float z\nend_header\n";
  const std::string negative = read_error(write_file("n.ply", header + bytes_of(std::int8_t(-1), true)));
  EXPECT_TRUE(contains(negative, "byte offset " + std::to_string(header.size()) + ": negative list count -1"))
      << negative;
  std::string bytes = binary_ply(true, false);
  bytes.resize(bytes.size() - 20); // inside the last vertex
  const std::string truncated = read_error(write_file("t.ply", bytes));
  EXPECT_TRUE(contains(truncated, "t.ply: byte offset")) << truncated;
  EXPECT_TRUE(contains(truncated, "truncated binary data")) << truncated;
}

// ---------------------------------------------------------------- .npy

// A .npy file: magic, version, header length, the dict padded with spaces
// to a multiple of 64 bytes ending in '\n', then the data.
std::string npy(const std::string& dict, const std::string& data, int major = 1)
{
  const std::size_t prefix = major == 1 ? 10 : 12;
  std::string header = dict;
  while((prefix + header.size() + 1) % 64 != 0) header += ' ';
  header += '\n';
  std::string s = std::string("\x93NUMPY", 6) + char(major) + char(0);
  if(major == 1) s += bytes_of(std::uint16_t(header.size()), true);
  else s += bytes_of(std::uint32_t(header.size()), true);
  return s + header + data;
}

template <class T>
std::string values(const std::vector<double>& v, bool fortran, bool little = true)
{
  std::string s;
  const std::size_t n = v.size() / 3;
  for(std::size_t k = 0; k < v.size(); ++k) {
    const std::size_t i = fortran ? k % n : k / 3, a = fortran ? k / n : k % 3;
    s += bytes_of(T(v[3 * i + a]), little);
  }
  return s;
}

TEST(PointCloudNpy, Float64Float32CAndFortranOrder)
{
  const std::string c_order = "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 3), }";
  const std::string c8 = npy(c_order, values<double>(three_points, false));
  EXPECT_EQ(io::read_npy(write_file("c8.npy", c8)), three_points);
  const std::string c4 =
      npy("{'descr': '<f4', 'fortran_order': False, 'shape': (3, 3), }", values<float>(three_points, false));
  EXPECT_EQ(io::read_points(write_file("c4.npy", c4)), three_points);
  const std::string f8 =
      npy("{'descr': '<f8', 'fortran_order': True, 'shape': (3, 3), }", values<double>(three_points, true));
  EXPECT_EQ(io::read_points(write_file("f8.npy", f8)), three_points);
  const std::string v2 = npy(c_order, values<double>(three_points, false), 2);
  EXPECT_EQ(io::read_points(write_file("v2.npy", v2)), three_points);
  const std::string big = npy("{'descr': '>f8', 'fortran_order': False, 'shape': (3, 3), }",
                              values<double>(three_points, false, false));
  EXPECT_EQ(io::read_points(write_file("big.npy", big)), three_points);
  const std::string empty = npy("{'descr': '<f8', 'fortran_order': False, 'shape': (0, 3), }", "");
  EXPECT_TRUE(io::read_points(write_file("empty.npy", empty)).empty());
}

TEST(PointCloudNpy, WrongMagicDtypeShapeAndTruncationAreNamed)
{
  const std::string magic = read_error(write_file("m.npy", "not numpy at all"));
  EXPECT_TRUE(contains(magic, "byte offset 0: wrong header")) << magic;
  const std::string dtype = read_error(write_file(
      "i.npy", npy("{'descr': '<i4', 'fortran_order': False, 'shape': (3, 3), }", std::string(36, '\0'))));
  EXPECT_TRUE(contains(dtype, "unsupported dtype '<i4'")) << dtype;
  const std::string shape = read_error(write_file(
      "s.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (4, 2), }", std::string(64, '\0'))));
  EXPECT_TRUE(contains(shape, "unsupported shape (4,2)")) << shape;
  const std::string flat = read_error(write_file(
      "v.npy", npy("{'descr': '<f8', 'fortran_order': False, 'shape': (9,), }", std::string(72, '\0'))));
  EXPECT_TRUE(contains(flat, "unsupported shape (9,)")) << flat;
  std::string data = values<double>(three_points, false);
  data.resize(data.size() - 5);
  const std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (3, 3), }";
  const std::string truncated = read_error(write_file("t.npy", npy(dict, data)));
  EXPECT_TRUE(contains(truncated, "truncated binary data")) << truncated;
  // At the start of the data, after the header.
  EXPECT_TRUE(contains(truncated, "byte offset " + std::to_string(npy(dict, "").size()) + ":")) << truncated;
}

// ---------------------------------------------------------------- writers

struct Triangulations
{
  std::vector<Point> points;
  Fast_dt fast;
  Cgal_dt cgal;
};

const Triangulations& clustered()
{
  static const Triangulations t = [] {
    Triangulations r;
    for(const fdt3_test::Xyz& p : fdt3_test::clustered_points(300)) r.points.emplace_back(p.x, p.y, p.z);
    r.fast.insert(r.points.begin(), r.points.end());
    r.cgal.insert(r.points.begin(), r.points.end());
    return r;
  }();
  return t;
}

fdt3_test::Cell_key cell_key(const std::vector<Point>& points, const std::uint64_t* v)
{
  fdt3_test::Cell_key k;
  for(int i = 0; i < 4; ++i) k[i] = std::make_tuple(points[v[i]].x(), points[v[i]].y(), points[v[i]].z());
  std::sort(k.begin(), k.end());
  return k;
}

std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

// A .vtu with raw appended arrays, header_type UInt64, read from the XML
// attributes and the byte offsets they give (VTK's file format document).
struct Vtu
{
  std::vector<Point> points;
  std::vector<fdt3_test::Cell_key> cells;
  std::size_t tetra_types = 0;
};

Vtu read_vtu(const std::string& path)
{
  const std::string text = file_text(path);
  auto attribute_after = [&](std::size_t from, const std::string& name) {
    const std::size_t at = text.find(name + "=\"", from) + name.size() + 2;
    return text.substr(at, text.find('"', at) - at);
  };
  const std::size_t np = std::stoul(attribute_after(0, "NumberOfPoints"));
  const std::size_t nc = std::stoul(attribute_after(0, "NumberOfCells"));
  const std::size_t data = text.find('_', text.find("<AppendedData")) + 1;
  auto array = [&](const std::string& name) {
    const std::size_t declared = name.empty() ? text.find("<DataArray") : text.find("Name=\"" + name + "\"");
    const std::size_t start = data + std::stoul(attribute_after(declared, "offset"));
    std::uint64_t bytes;
    std::memcpy(&bytes, text.data() + start, 8);
    return std::make_pair(text.data() + start + 8, bytes);
  };
  Vtu v;
  const auto xyz = array("");
  EXPECT_EQ(xyz.second, 24 * np);
  for(std::size_t i = 0; i < np; ++i) {
    double p[3];
    std::memcpy(p, xyz.first + 24 * i, 24);
    v.points.emplace_back(p[0], p[1], p[2]);
  }
  const auto connectivity = array("connectivity"), offsets = array("offsets"), types = array("types");
  EXPECT_EQ(connectivity.second, 16 * nc);
  EXPECT_EQ(offsets.second, 4 * nc);
  EXPECT_EQ(types.second, nc);
  for(std::size_t c = 0; c < nc; ++c) {
    std::int32_t ids[4], end;
    std::memcpy(ids, connectivity.first + 16 * c, 16);
    std::memcpy(&end, offsets.first + 4 * c, 4);
    EXPECT_EQ(end, std::int32_t(4 * (c + 1)));
    v.tetra_types += types.first[c] == 10;
    std::uint64_t u[4];
    for(int k = 0; k < 4; ++k) u[k] = std::uint64_t(ids[k]);
    v.cells.push_back(cell_key(v.points, u));
  }
  std::sort(v.cells.begin(), v.cells.end());
  return v;
}

TEST(TriangulationWriters, VtuHasCgalsFiniteCells)
{
  const Triangulations& t = clustered();
  const std::string path = temporary("cells.vtu");
  io::write_triangulation(path, t.fast);
  const Vtu back = read_vtu(path);
  EXPECT_EQ(back.points.size(), t.cgal.number_of_vertices());
  EXPECT_EQ(back.tetra_types, t.cgal.number_of_finite_cells());
  EXPECT_TRUE(back.cells == fdt3_test::finite_cell_keys(t.cgal));
  std::remove(path.c_str());
}

// Medit and Gmsh 4.1 ASCII: the sections read by keyword.
std::vector<fdt3_test::Cell_key> read_medit_cells(const std::string& path, std::size_t& vertices)
{
  std::istringstream in(file_text(path));
  std::vector<Point> points;
  std::vector<fdt3_test::Cell_key> cells;
  std::string word;
  while(in >> word) {
    std::size_t n = 0;
    if(word == "Vertices") {
      in >> n;
      for(std::size_t i = 0; i < n; ++i) {
        double x, y, z;
        int reference;
        in >> x >> y >> z >> reference;
        points.emplace_back(x, y, z);
      }
    } else if(word == "Tetrahedra") {
      in >> n;
      for(std::size_t i = 0; i < n; ++i) {
        std::uint64_t v[4];
        int reference;
        in >> v[0] >> v[1] >> v[2] >> v[3] >> reference;
        for(auto& x : v) --x;
        EXPECT_EQ(reference, 1);
        cells.push_back(cell_key(points, v));
      }
    }
  }
  vertices = points.size();
  std::sort(cells.begin(), cells.end());
  return cells;
}

std::vector<fdt3_test::Cell_key> read_msh41_cells(const std::string& path, std::size_t& vertices)
{
  std::istringstream in(file_text(path));
  std::vector<Point> points;
  std::vector<fdt3_test::Cell_key> cells;
  std::string line;
  while(std::getline(in, line)) {
    if(line == "$Nodes") {
      std::size_t blocks, n, lo, hi, count;
      int dim, tag, parametric;
      in >> blocks >> n >> lo >> hi >> dim >> tag >> parametric >> count;
      EXPECT_EQ(blocks, 1u);
      for(std::size_t i = 0; i < count; ++i) {
        std::size_t node;
        in >> node;
        EXPECT_EQ(node, i + 1);
      }
      for(std::size_t i = 0; i < count; ++i) {
        double x, y, z;
        in >> x >> y >> z;
        points.emplace_back(x, y, z);
      }
    } else if(line == "$Elements") {
      std::size_t blocks, n, lo, hi;
      in >> blocks >> n >> lo >> hi;
      for(std::size_t b = 0; b < blocks; ++b) {
        int dim, entity, type;
        std::size_t count;
        in >> dim >> entity >> type >> count;
        for(std::size_t i = 0; i < count; ++i) {
          std::uint64_t tag, v[4];
          in >> tag >> v[0] >> v[1] >> v[2] >> v[3];
          EXPECT_EQ(type, 4);
          for(auto& x : v) --x;
          cells.push_back(cell_key(points, v));
        }
      }
    }
  }
  vertices = points.size();
  std::sort(cells.begin(), cells.end());
  return cells;
}

TEST(TriangulationWriters, MeditAndGmshHaveCgalsFiniteCells)
{
  const Triangulations& t = clustered();
  for(const char* name : {"cells.mesh", "cells.msh"}) {
    const std::string path = temporary(name);
    io::write_triangulation(path, t.fast);
    std::size_t vertices = 0;
    const std::vector<fdt3_test::Cell_key> cells =
        std::string(name) == "cells.mesh" ? read_medit_cells(path, vertices) : read_msh41_cells(path, vertices);
    EXPECT_EQ(vertices, t.cgal.number_of_vertices()) << name;
    EXPECT_EQ(cells.size(), t.cgal.number_of_finite_cells()) << name;
    EXPECT_TRUE(cells == fdt3_test::finite_cell_keys(t.cgal)) << name;
    std::remove(path.c_str());
  }
}

TEST(TriangulationWriters, OffHullIsCgalsHullOrientedOutward)
{
  const Triangulations& t = clustered();
  const std::string path = temporary("hull.off");
  io::write_triangulation(path, t.fast);
  std::istringstream in(file_text(path));
  std::string magic;
  std::size_t nv, nf, ne;
  in >> magic >> nv >> nf >> ne;
  EXPECT_EQ(magic, "OFF");
  std::vector<Point> points(nv);
  for(Point& p : points) {
    double x, y, z;
    in >> x >> y >> z;
    p = Point(x, y, z);
  }
  // The centroid of the input points is inside the hull.
  double c[3] = {0, 0, 0};
  for(const Point& p : t.points) {
    c[0] += p.x() / double(t.points.size());
    c[1] += p.y() / double(t.points.size());
    c[2] += p.z() / double(t.points.size());
  }
  const Point inside(c[0], c[1], c[2]);
  std::vector<fdt3_test::Facet_key> facets;
  for(std::size_t f = 0; f < nf; ++f) {
    std::size_t three, a, b, d;
    in >> three >> a >> b >> d;
    ASSERT_EQ(three, 3u);
    ASSERT_TRUE(a < nv && b < nv && d < nv);
    EXPECT_EQ(CGAL::orientation(points[a], points[b], points[d], inside), CGAL::NEGATIVE) << "facet " << f;
    fdt3_test::Facet_key k = {fdt3_test::point_key(points[a]), fdt3_test::point_key(points[b]),
                              fdt3_test::point_key(points[d])};
    std::sort(k.begin(), k.end());
    facets.push_back(k);
  }
  std::sort(facets.begin(), facets.end());
  EXPECT_TRUE(facets == fdt3_test::hull_facet_keys(t.cgal));
  EXPECT_EQ(nv, fdt3_test::hull_vertex_keys(t.cgal).size());
  std::remove(path.c_str());
}

TEST(TriangulationWriters, CgalFormatReadsBackIntoCgal)
{
  const Triangulations& t = clustered();
  const std::string path = temporary("tr.cgal");
  io::write_triangulation(path, t.fast);
  Cgal_dt back;
  std::ifstream in(path);
  in >> back;
  ASSERT_TRUE(bool(in));
  EXPECT_TRUE(back.is_valid());
  EXPECT_TRUE(fdt3_test::finite_cell_keys(back) == fdt3_test::finite_cell_keys(t.cgal));
  std::remove(path.c_str());
}

TEST(TriangulationWriters, RemovedVerticesAreRenumberedAndLowDimensionsHaveNoCells)
{
  Fast_dt fast;
  Cgal_dt cgal;
  const Triangulations& t = clustered();
  fast.insert(t.points.begin(), t.points.end());
  cgal.insert(t.points.begin(), t.points.end());
  int k = 0;
  for(auto v = fast.finite_vertices_begin(); v != fast.finite_vertices_end() && k < 10; ++k) {
    auto next = std::next(v);
    cgal.remove(cgal.nearest_vertex(v->point()));
    fast.remove(v);
    v = next;
  }
  const std::string path = temporary("removed.vtu");
  io::write_triangulation(path, fast);
  const Vtu back = read_vtu(path);
  EXPECT_EQ(back.points.size(), cgal.number_of_vertices());
  EXPECT_TRUE(back.cells == fdt3_test::finite_cell_keys(cgal));

  Fast_dt flat;
  const std::vector<Point> square = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0)};
  flat.insert(square.begin(), square.end());
  io::write_triangulation(path, flat);
  const Vtu none = read_vtu(path);
  EXPECT_EQ(none.points.size(), 4u);
  EXPECT_TRUE(none.cells.empty());
  EXPECT_THROW(io::write_triangulation(temporary("cells.vtk"), flat), std::invalid_argument);
  std::remove(path.c_str());
}

// ---------------------------------------------------------------- progress

TEST(InsertionProgress, IncreasesToTheTotalAndChangesNothing)
{
  std::vector<Point> points;
  for(const fdt3_test::Xyz& p : fdt3_test::uniform_points(20000)) points.emplace_back(p.x, p.y, p.z);
  points.insert(points.end(), points.begin(), points.begin() + 100); // duplicates
  Cgal_dt cgal(points.begin(), points.end());
  for(int threads : {1, 2, -2}) { // -2: 2 threads, the barrier engine
    Fast_dt tr;
    tr.set_number_of_threads(std::abs(threads));
    if(threads < 0) tr.set_parallel_engine(Fast_dt::Parallel_engine::barrier);
    std::vector<std::pair<std::size_t, std::size_t>> calls;
    tr.set_progress([&](std::size_t done, std::size_t total) { calls.emplace_back(done, total); });
    tr.insert(points.begin(), points.end());
    ASSERT_GE(calls.size(), 3u) << threads << " threads";
    EXPECT_EQ(calls.front(), std::make_pair(std::size_t(0), points.size()));
    EXPECT_EQ(calls.back(), std::make_pair(points.size(), points.size()));
    for(std::size_t i = 1; i < calls.size(); ++i) {
      EXPECT_GT(calls[i].first, calls[i - 1].first) << "call " << i;
      EXPECT_EQ(calls[i].second, points.size());
    }
    EXPECT_LT(calls.size(), 100u) << "not a call per point";
    fdt3_test::expect_same_as_cgal(tr, cgal);
    // Single insertions report nothing.
    calls.clear();
    tr.insert(Point(0.5, 0.5, 0.5001));
    EXPECT_TRUE(calls.empty());
  }
}

} // namespace test_point_cloud_io
