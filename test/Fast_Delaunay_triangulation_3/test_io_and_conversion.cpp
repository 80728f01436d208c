// CGAL's Triangulation_3 file format both ways (ours -> CGAL, CGAL -> ours,
// ours -> ours, ASCII and binary), rejection of malformed files with the
// triangulation left as it was, and the hand-off to CGAL's own types
// (Delaunay_triangulation_3 with sequential and parallel data structures,
// Mesh_complex_3_in_triangulation_3 and tetrahedral remeshing).  CGAL is the
// oracle: cells are compared with those of CGAL's triangulation of the same
// points, and CGAL's is_valid() judges what we build for it.

#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/convert_to_cgal.h>

#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Tetrahedral_remeshing/Remeshing_triangulation_3.h>
#include <CGAL/tetrahedral_remeshing.h>

#include <gtest/gtest.h>

#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace test_io_and_conversion {

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

// A cell as the points of its four slots in order; the infinite vertex is
// (inf, inf, inf).  Compares cells of two triangulations slot by slot.
typedef std::array<Point_key, 4> Ordered_cell;

template <class Tr>
std::vector<Ordered_cell> cells_in_order(const Tr& tr)
{
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<Ordered_cell> cells;
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    Ordered_cell cell;
    for(int i = 0; i < 4; ++i)
      cell[i] = tr.is_infinite(c->vertex(i)) ? Point_key(inf, inf, inf) : point_key(c->vertex(i)->point());
    cells.push_back(cell);
  }
  return cells;
}

template <class Tr>
std::string to_text(const Tr& tr)
{
  std::ostringstream os;
  os.precision(17);
  os << tr;
  return os.str();
}

template <class Tr>
std::string to_binary(const Tr& tr)
{
  std::ostringstream os(std::ios::binary);
  CGAL::IO::set_binary_mode(os);
  os << tr;
  return os.str();
}

template <class Tr>
bool from_text(const std::string& text, Tr& tr)
{
  std::istringstream is(text);
  return bool(is >> tr);
}

template <class Tr>
bool from_binary(const std::string& bytes, Tr& tr)
{
  std::istringstream is(bytes, std::ios::binary);
  CGAL::IO::set_binary_mode(is);
  return bool(is >> tr);
}

struct Named_input
{
  std::string name;
  std::vector<Point> points;
};

std::vector<Named_input> three_dimensional_inputs()
{
  return {
      {"uniform", to_points<Point>(uniform_points(2000, 11))},
      {"grid", to_points<Point>(grid_points(216, 12))},          // 6^3: cospherical everywhere
      {"integer_sphere", to_points<Point>(integer_sphere_points(50))},
      {"four", to_points<Point>(uniform_points(4, 13))},
      {"five", to_points<Point>(uniform_points(5, 14))},
  };
}

// Every infinite cell is oriented as if its infinite vertex were a point
// beyond the hull facet: the reflection of the finite neighbour's far vertex
// through the facet's centroid makes it positive.
template <class Tr>
void expect_infinite_cells_face_outwards(const Tr& tr)
{
  const K k;
  std::size_t checked = 0;
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c) {
    const typename Tr::Cell_handle ch = c;
    if(!tr.is_infinite(ch)) continue;
    const int inf = ch->index(tr.infinite_vertex());
    const typename Tr::Cell_handle inside = ch->neighbor(inf);
    const Point far = inside->vertex(tr.mirror_index(ch, inf))->point();
    double centroid[3] = {0, 0, 0};
    for(int i = 0; i < 4; ++i)
      if(i != inf) {
        centroid[0] += ch->vertex(i)->point().x() / 3;
        centroid[1] += ch->vertex(i)->point().y() / 3;
        centroid[2] += ch->vertex(i)->point().z() / 3;
      }
    const Point beyond(2 * centroid[0] - far.x(), 2 * centroid[1] - far.y(), 2 * centroid[2] - far.z());
    Point p[4];
    for(int i = 0; i < 4; ++i) p[i] = i == inf ? beyond : ch->vertex(i)->point();
    ASSERT_EQ(k.orientation_3_object()(p[0], p[1], p[2], p[3]), CGAL::POSITIVE) << "infinite vertex in slot " << inf;
    ++checked;
  }
  EXPECT_GT(checked, 0u);
}

TEST(FileFormat, OursReadByCgalGivesCgalsCells)
{
  for(const Named_input& input : three_dimensional_inputs()) {
    SCOPED_TRACE(input.name);
    const Fast_dt ours(input.points.begin(), input.points.end());
    const Cgal_dt reference(input.points.begin(), input.points.end());
    for(bool binary : {false, true}) {
      SCOPED_TRACE(binary ? "binary" : "ascii");
      Cgal_dt cgal;
      ASSERT_TRUE(binary ? from_binary(to_binary(ours), cgal) : from_text(to_text(ours), cgal));
      EXPECT_TRUE(cgal.is_valid());
      EXPECT_TRUE(cells_in_order(cgal) == cells_in_order(ours)) << "cells differ from the written ones";
      EXPECT_EQ(cgal.number_of_cells(), reference.number_of_cells());
      EXPECT_TRUE(finite_cell_keys(cgal) == finite_cell_keys(reference)) << "not CGAL's triangulation";
    }
  }
}

TEST(FileFormat, CgalReadByOursGivesCgalsCells)
{
  for(const Named_input& input : three_dimensional_inputs()) {
    SCOPED_TRACE(input.name);
    const Cgal_dt cgal(input.points.begin(), input.points.end());
    expect_infinite_cells_face_outwards(cgal);
    for(bool binary : {false, true}) {
      SCOPED_TRACE(binary ? "binary" : "ascii");
      Fast_dt ours;
      ASSERT_TRUE(binary ? from_binary(to_binary(cgal), ours) : from_text(to_text(cgal), ours));
      expect_same_as_cgal(ours, cgal);
      expect_infinite_cells_face_outwards(ours);
      // Finite cells keep CGAL's vertex order; infinite ones have the
      // infinite vertex moved to slot 3 by an even permutation.
      const std::vector<Ordered_cell> read = cells_in_order(ours), written = cells_in_order(cgal);
      ASSERT_EQ(read.size(), written.size());
      std::size_t same_finite = 0, finite = 0, c = 0;
      for(auto it = cgal.all_cells_begin(); it != cgal.all_cells_end(); ++it, ++c) {
        if(cgal.is_infinite(Cgal_dt::Cell_handle(it))) continue;
        ++finite;
        if(read[c] == written[c]) ++same_finite;
      }
      EXPECT_EQ(same_finite, finite);
    }
  }
}

TEST(FileFormat, OursReadByOursIsTheSameTriangulation)
{
  for(const Named_input& input : three_dimensional_inputs()) {
    SCOPED_TRACE(input.name);
    const Fast_dt ours(input.points.begin(), input.points.end());
    Fast_dt copy;
    copy.set_sub_determinants(true); // kept across the read, recomputed for the new cells
    ASSERT_TRUE(from_text(to_text(ours), copy));
    EXPECT_TRUE(copy.sub_determinants());
    EXPECT_TRUE(copy.is_valid());
    EXPECT_TRUE(cells_in_order(copy) == cells_in_order(ours));
    expect_same_as_cgal(copy, Cgal_dt(input.points.begin(), input.points.end()));
    // The copy is a working triangulation: inserting more points gives CGAL's result.
    std::vector<Point> more = to_points<Point>(uniform_points(300, 99));
    copy.insert(more.begin(), more.end());
    more.insert(more.end(), input.points.begin(), input.points.end());
    expect_same_as_cgal(copy, Cgal_dt(more.begin(), more.end()));
  }
}

TEST(FileFormat, WritesTheSameBytesAsCgal)
{
  // Same text as CGAL for the same vertex and cell order: a triangulation
  // read from CGAL's file is written back byte for byte.
  const std::vector<Point> points = to_points<Point>(uniform_points(300, 21));
  const Cgal_dt cgal(points.begin(), points.end());
  Fast_dt ours;
  ASSERT_TRUE(from_text(to_text(cgal), ours));
  Cgal_dt cgal_copy;
  ASSERT_TRUE(from_text(to_text(ours), cgal_copy));
  EXPECT_EQ(to_text(ours), to_text(cgal_copy));
  EXPECT_EQ(to_binary(ours), to_binary(cgal_copy));
}

// Dimensions -1 to 2: we store no cells there, so the file is CGAL's (made
// by CGAL's triangulation of our vertices); reading keeps only the vertices.
TEST(FileFormat, LowerDimensionsBothWays)
{
  std::vector<Named_input> inputs = {
      {"empty", {}},
      {"one point", {Point(1, 2, 3)}},
      {"collinear", {Point(0, 0, 0), Point(2, 2, 2), Point(1, 1, 1), Point(5, 5, 5)}},
      {"coplanar grid", {}},
      {"cocircular", to_points<Point>(tilted_circle_points())},
  };
  for(int i = 0; i < 4; ++i)
    for(int j = 0; j < 4; ++j) inputs[3].points.push_back(Point(i, j, 0.5));
  for(const Named_input& input : inputs) {
    SCOPED_TRACE(input.name);
    const Fast_dt ours(input.points.begin(), input.points.end());
    const Cgal_dt reference(input.points.begin(), input.points.end());
    ASSERT_LT(ours.dimension(), 3);

    Cgal_dt cgal;
    ASSERT_TRUE(from_text(to_text(ours), cgal));
    EXPECT_TRUE(cgal.is_valid());
    EXPECT_EQ(cgal.dimension(), reference.dimension());
    EXPECT_TRUE(finite_vertex_keys(cgal) == finite_vertex_keys(reference));
    EXPECT_TRUE(finite_facet_keys(cgal) == finite_facet_keys(reference));
    EXPECT_TRUE(finite_edge_keys(cgal) == finite_edge_keys(reference));

    const std::vector<Point> previous = to_points<Point>(uniform_points(10, 3));
    for(bool binary : {false, true}) {
      Fast_dt back(previous.begin(), previous.end());
      ASSERT_TRUE(binary ? from_binary(to_binary(reference), back) : from_text(to_text(reference), back));
      EXPECT_TRUE(back.is_valid());
      EXPECT_EQ(back.dimension(), reference.dimension());
      EXPECT_TRUE(finite_vertex_keys(back) == finite_vertex_keys(reference));
      EXPECT_EQ(back.number_of_cells(), 0u);
    }
  }
}

// ---------------------------------------------------------------- bad input

// A file as lines: 0 dimension, 1 n, 2..n+1 points, n+2 m, then m cell lines
// and m neighbour lines.
struct File_lines
{
  std::vector<std::string> lines;
  std::size_t n = 0, m = 0;

  explicit File_lines(const std::string& text)
  {
    std::istringstream is(text);
    for(std::string line; std::getline(is, line);) lines.push_back(line);
    n = std::stoul(lines[1]);
    m = std::stoul(lines[n + 2]);
  }
  std::string& cell(std::size_t c) { return lines[n + 3 + c]; }
  std::string& neighbors(std::size_t c) { return lines[n + 3 + m + c]; }
  std::string text() const
  {
    std::string s;
    for(const std::string& line : lines) s += line + "\n";
    return s;
  }
};

// A file in CGAL's format for the given finite cells (vertex indices 1..n,
// positively oriented): an infinite cell on every facet that has one cell
// only, adjacency by matching facets.  For files that CGAL would not write.
std::string file_of_cells(const std::vector<Point>& points, std::vector<std::array<std::size_t, 4>> cells)
{
  const std::size_t finite = cells.size();
  std::map<std::array<std::size_t, 3>, std::vector<std::pair<std::size_t, int>>> sides;
  auto facet = [&](std::size_t c, int i) {
    std::array<std::size_t, 3> f;
    for(int k = 0, j = 0; k < 4; ++k)
      if(k != i) f[j++] = cells[c][k];
    std::sort(f.begin(), f.end());
    return f;
  };
  for(std::size_t c = 0; c < finite; ++c)
    for(int i = 0; i < 4; ++i) sides[facet(c, i)].push_back({c, i});
  for(std::size_t c = 0; c < finite; ++c)
    for(int i = 0; i < 4; ++i) {
      if(sides[facet(c, i)].size() != 1) continue;
      // The infinite vertex in place of the inner vertex sees the facet from
      // inside: swap two other slots to face outwards.
      std::array<std::size_t, 4> ghost = cells[c];
      ghost[i] = 0;
      std::swap(ghost[(i + 1) % 4], ghost[(i + 2) % 4]);
      cells.push_back(ghost);
    }
  sides.clear();
  for(std::size_t c = 0; c < cells.size(); ++c)
    for(int i = 0; i < 4; ++i) sides[facet(c, i)].push_back({c, i});
  std::ostringstream os;
  os.precision(17);
  os << "3\n" << points.size() << "\n";
  for(const Point& p : points) os << p << "\n";
  os << cells.size() << "\n";
  for(const auto& c : cells) os << c[0] << " " << c[1] << " " << c[2] << " " << c[3] << "\n";
  for(std::size_t c = 0; c < cells.size(); ++c)
    for(int i = 0; i < 4; ++i) {
      const auto& pair = sides[facet(c, i)];
      os << (pair[0].first == c ? pair[1].first : pair[0].first) << (i == 3 ? "\n" : " ");
    }
  return os.str();
}

TEST(FileFormat, FileOfCellsWritesValidTriangulations)
{
  // The helper below is itself checked: two tetrahedra that are CGAL's
  // triangulation of their five points are read by CGAL and by us.
  const std::vector<Point> points = {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1),
                                     Point(0.3, 0.3, -1)};
  const std::string text = file_of_cells(points, {{1, 2, 3, 4}, {1, 3, 2, 5}});
  Cgal_dt cgal;
  ASSERT_TRUE(from_text(text, cgal));
  EXPECT_TRUE(cgal.is_valid());
  Fast_dt ours;
  ASSERT_TRUE(from_text(text, ours));
  expect_same_as_cgal(ours, Cgal_dt(points.begin(), points.end()));
}

struct Bad_file
{
  std::string name;
  std::string text;
};

std::vector<Bad_file> bad_files()
{
  const std::vector<Point> points = to_points<Point>(uniform_points(30, 31));
  const std::string good = to_text(Cgal_dt(points.begin(), points.end()));
  std::vector<Bad_file> bad;
  bad.push_back({"empty stream", ""});
  bad.push_back({"truncated in the points", good.substr(0, good.size() / 4)});
  bad.push_back({"truncated in the neighbours", good.substr(0, good.size() - good.size() / 8)});
  bad.push_back({"dimension 4", "4\n0\n"});
  bad.push_back({"negative vertex count", "3\n-4\n"});
  bad.push_back({"not a number", "3\nmany\n"});
  {
    File_lines f(good);
    f.lines[f.n + 2] = "-" + f.lines[f.n + 2];
    bad.push_back({"negative cell count", f.text()});
  }
  {
    File_lines f(good);
    f.cell(3) = "1 2 3 " + std::to_string(f.n + 1);
    bad.push_back({"vertex index out of range", f.text()});
  }
  {
    File_lines f(good);
    f.neighbors(2) = "0 1 2 " + std::to_string(f.m);
    bad.push_back({"neighbour index out of range", f.text()});
  }
  {
    File_lines f(good);
    f.cell(0) = "0 0 1 2";
    bad.push_back({"two infinite vertices", f.text()});
  }
  {
    // Swapping two neighbour entries breaks the symmetry (or the shared facet).
    File_lines f(good);
    std::istringstream is(f.neighbors(5));
    std::string a, b, c, d;
    is >> a >> b >> c >> d;
    f.neighbors(5) = b + " " + a + " " + c + " " + d;
    bad.push_back({"asymmetric adjacency", f.text()});
  }
  {
    // Two vertices of one finite cell swapped: it is negatively oriented.
    const Cgal_dt cgal(points.begin(), points.end());
    std::size_t finite = 0;
    for(auto c = cgal.all_cells_begin(); c != cgal.all_cells_end(); ++c, ++finite)
      if(!cgal.is_infinite(Cgal_dt::Cell_handle(c))) break;
    File_lines f(good);
    std::istringstream is(f.cell(finite));
    std::string a, b, c, d;
    is >> a >> b >> c >> d;
    f.cell(finite) = b + " " + a + " " + c + " " + d;
    bad.push_back({"vertex order swapped", f.text()});
  }
  {
    // A point moved far away: the cells are no longer Delaunay (or not positive).
    File_lines f(good);
    f.lines[2] = "100 -100 100";
    bad.push_back({"moved point", f.text()});
  }
  {
    File_lines f(good);
    f.lines[1] = std::to_string(f.n - 1);
    bad.push_back({"vertex count one short", f.text()});
  }
  {
    // Two valid triangulations far apart, written as one: every local check
    // passes, only connectivity tells.
    const std::vector<Point> near = to_points<Point>(uniform_points(4, 32));
    std::vector<Point> far;
    for(const Point& p : near) far.push_back(Point(p.x() + 10, p.y(), p.z()));
    File_lines a(to_text(Cgal_dt(near.begin(), near.end()))), b(to_text(Cgal_dt(far.begin(), far.end())));
    auto shifted = [](const std::string& line, std::size_t vertex_shift, std::size_t cell_shift) {
      std::istringstream is(line);
      std::string out;
      for(std::size_t k; is >> k;)
        out += std::to_string(k == 0 && cell_shift == 0 ? 0 : k + vertex_shift + cell_shift) + " ";
      return out;
    };
    File_lines f = a;
    f.lines = {"3", "8"};
    for(std::size_t v = 0; v < 4; ++v) f.lines.push_back(a.lines[2 + v]);
    for(std::size_t v = 0; v < 4; ++v) f.lines.push_back(b.lines[2 + v]);
    f.lines.push_back(std::to_string(a.m + b.m));
    for(std::size_t c = 0; c < a.m; ++c) f.lines.push_back(a.cell(c));
    for(std::size_t c = 0; c < b.m; ++c) f.lines.push_back(shifted(b.cell(c), 4, 0));
    for(std::size_t c = 0; c < a.m; ++c) f.lines.push_back(a.neighbors(c));
    for(std::size_t c = 0; c < b.m; ++c) f.lines.push_back(shifted(b.neighbors(c), 0, a.m));
    bad.push_back({"two triangulations in one file", f.text()});
  }
  // Two tetrahedra on both sides of the facet abc, each empty of the other's
  // far vertex, but their union is not convex (segment d e misses abc): only
  // the hull facets' side of the Delaunay property fails.
  bad.push_back({"non-convex hull",
                 file_of_cells({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1), Point(2, 2, -0.1)},
                               {{1, 2, 3, 4}, {1, 3, 2, 5}})});
  bad.push_back({"coplanar points said to span dimension 3", "3\n4\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n"});
  bad.push_back({"duplicate points in dimension 1", "1\n3\n0 0 0\n1 1 1\n1 1 1\n4\n1 2\n2 3\n3 0\n0 1\n1 3\n2 0\n3 1\n0 2\n"});
  bad.push_back({"dimension 0 with two points", "0\n2\n0 0 0\n1 1 1\n"});
  return bad;
}

TEST(FileFormat, BadInputSetsFailbitAndLeavesTheTriangulationUnchanged)
{
  const std::vector<Point> points = to_points<Point>(grid_points(64, 41));
  for(const Bad_file& file : bad_files()) {
    SCOPED_TRACE(file.name);
    Fast_dt ours(points.begin(), points.end());
    const std::vector<Ordered_cell> before = cells_in_order(ours);
    std::istringstream is(file.text);
    std::string error;
    EXPECT_FALSE(ours.read(is, &error));
    EXPECT_TRUE(is.fail());
    EXPECT_FALSE(error.empty());
    EXPECT_TRUE(cells_in_order(ours) == before);
    EXPECT_EQ(ours.number_of_vertices(), points.size());
    expect_same_as_cgal(ours, Cgal_dt(points.begin(), points.end()));

    std::istringstream again(file.text);
    again >> ours;
    EXPECT_TRUE(again.fail()) << "operator>> accepted it";
    EXPECT_TRUE(cells_in_order(ours) == before);
  }
}

TEST(FileFormat, ErrorNamesThePosition)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(30, 31));
  File_lines f(to_text(Cgal_dt(points.begin(), points.end())));
  f.cell(7) = "1 2 3 999";
  std::istringstream is(f.text());
  Fast_dt ours;
  std::string error;
  ASSERT_FALSE(ours.read(is, &error));
  EXPECT_NE(error.find("vertex 3 of cell 7"), std::string::npos) << error;
  EXPECT_NE(error.find("999"), std::string::npos) << error;
}

// ---------------------------------------------------------------- conversion

template <class Target>
void expect_converted(const Fast_dt& ours, const Target& target, const std::vector<Point>& points, bool same_order)
{
  EXPECT_TRUE(target.is_valid(false));
  EXPECT_TRUE(target.tds().is_valid(false));
  EXPECT_EQ(target.dimension(), ours.dimension());
  EXPECT_EQ(target.number_of_vertices(), ours.number_of_vertices());
  EXPECT_EQ(target.number_of_cells(), ours.number_of_cells());
  EXPECT_TRUE(finite_cell_keys(target) == finite_cell_keys(Cgal_dt(points.begin(), points.end())));
  if(same_order) {
    EXPECT_TRUE(cells_in_order(target) == cells_in_order(ours));
  }
}

TEST(Conversion, ToCgalDelaunayTriangulation)
{
  for(const Named_input& input : three_dimensional_inputs()) {
    SCOPED_TRACE(input.name);
    const Fast_dt ours(input.points.begin(), input.points.end());
    Cgal_dt cgal(input.points.begin(), input.points.begin() + 2); // replaced
    CGAL::convert_to_cgal(ours, cgal);
    expect_converted(ours, cgal, input.points, true);
    expect_infinite_cells_face_outwards(cgal);
    // A working CGAL triangulation: CGAL's own insertion and removal on it
    // give CGAL's triangulation of the resulting point set.
    std::vector<Point> more = to_points<Point>(uniform_points(200, 77));
    cgal.insert(more.begin(), more.end());
    const Point removed = cgal.finite_vertices_begin()->point();
    cgal.remove(cgal.finite_vertices_begin());
    EXPECT_TRUE(cgal.is_valid());
    std::vector<Point> all = input.points;
    all.insert(all.end(), more.begin(), more.end());
    all.erase(std::remove(all.begin(), all.end(), removed), all.end());
    const Cgal_dt reference(all.begin(), all.end());
    EXPECT_TRUE(finite_cell_keys(cgal) == finite_cell_keys(reference));
  }
}

#ifdef CGAL_LINKED_WITH_TBB
TEST(Conversion, ToCgalParallelDelaunayTriangulation)
{
  typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<K>,
                                               CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>
      Parallel_tds;
  typedef CGAL::Delaunay_triangulation_3<K, Parallel_tds> Parallel_dt;
  for(const Named_input& input : three_dimensional_inputs()) {
    SCOPED_TRACE(input.name);
    const Fast_dt ours(input.points.begin(), input.points.end());
    Parallel_dt cgal;
    CGAL::convert_to_cgal(ours, cgal);
    expect_converted(ours, cgal, input.points, false);
  }
}
#endif

TEST(Conversion, LowerDimensionsInsertThePoints)
{
  std::vector<Point> coplanar;
  for(int i = 0; i < 5; ++i)
    for(int j = 0; j < 5; ++j) coplanar.push_back(Point(i, j, 0));
  const Fast_dt ours(coplanar.begin(), coplanar.end());
  Cgal_dt cgal;
  CGAL::convert_to_cgal(ours, cgal);
  EXPECT_TRUE(cgal.is_valid());
  EXPECT_EQ(cgal.dimension(), 2);
  EXPECT_TRUE(finite_facet_keys(cgal) == finite_facet_keys(Cgal_dt(coplanar.begin(), coplanar.end())));
}

typedef CGAL::Tetrahedral_remeshing::Remeshing_triangulation_3<K> Remeshing_tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Remeshing_tr> C3t3;

// The facets of ours between cells of different sides of x = 0.5 (the hull
// counts as side 0), counted independently of the conversion.
std::size_t interface_facets(const Fast_dt& ours, double cut)
{
  auto side = [&](Fast_dt::Cell_handle c) {
    if(ours.is_infinite(c)) return 0;
    double x = 0;
    for(int i = 0; i < 4; ++i) x += c->vertex(i)->point().x() / 4;
    return x < cut ? 1 : 2;
  };
  std::size_t count = 0;
  for(auto f = ours.finite_facets_begin(); f != ours.finite_facets_end(); ++f)
    if(side(f->first) != side(f->first->neighbor(f->second))) ++count;
  return count;
}

TEST(Conversion, ToMeshComplexOneSubdomain)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(300, 51));
  const Fast_dt ours(points.begin(), points.end());
  C3t3 c3t3;
  CGAL::convert_to_c3t3(ours, c3t3);
  EXPECT_TRUE(c3t3.triangulation().is_valid());
  EXPECT_EQ(c3t3.number_of_cells_in_complex(), ours.number_of_finite_cells());
  EXPECT_EQ(c3t3.number_of_facets_in_complex(), hull_facet_keys(ours).size());
  EXPECT_EQ(c3t3.number_of_facets_in_complex(), interface_facets(ours, 2.0));
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    EXPECT_EQ(c3t3.subdomain_index(c), 1);
  std::size_t surface_vertices = 0;
  for(auto v = c3t3.triangulation().finite_vertices_begin(); v != c3t3.triangulation().finite_vertices_end(); ++v)
    if(v->in_dimension() == 2) ++surface_vertices;
  EXPECT_EQ(surface_vertices, hull_vertex_keys(ours).size());
}

TEST(Conversion, ToMeshComplexWithSubdomainFunctor)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(300, 52));
  const Fast_dt ours(points.begin(), points.end());
  C3t3 c3t3;
  CGAL::convert_to_c3t3(ours, c3t3, [](Fast_dt::Cell_handle c) {
    double x = 0;
    for(int i = 0; i < 4; ++i) x += c->vertex(i)->point().x() / 4;
    return x < 0.5 ? 1 : 2;
  });
  std::size_t in_one = 0, in_two = 0;
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    (c3t3.subdomain_index(c) == 1 ? in_one : in_two)++;
  EXPECT_GT(in_one, 0u);
  EXPECT_GT(in_two, 0u);
  EXPECT_EQ(in_one + in_two, ours.number_of_finite_cells());
  EXPECT_EQ(c3t3.number_of_facets_in_complex(), interface_facets(ours, 0.5));
  // Three patches: hull of 1, hull of 2, interface 1-2.
  std::set<int> patches;
  for(auto f = c3t3.facets_in_complex_begin(); f != c3t3.facets_in_complex_end(); ++f)
    patches.insert(c3t3.surface_patch_index(*f));
  EXPECT_EQ(patches.size(), 3u);
}

TEST(Conversion, TetrahedralRemeshingAcceptsTheMeshComplex)
{
  const std::vector<Point> points = to_points<Point>(uniform_points(300, 53));
  const Fast_dt ours(points.begin(), points.end());
  C3t3 c3t3;
  CGAL::convert_to_c3t3(ours, c3t3);
  const std::size_t cells_before = c3t3.number_of_cells_in_complex();
  // The hull is protected (its sharp edges are not marked as features, so
  // remeshing it would round them off); the inside is remeshed.
  CGAL::tetrahedral_isotropic_remeshing(
      c3t3, 0.1, CGAL::parameters::number_of_iterations(2).remesh_boundaries(false));
  EXPECT_TRUE(c3t3.triangulation().is_valid());
  EXPECT_GT(c3t3.number_of_cells_in_complex(), 0u);
  EXPECT_NE(c3t3.number_of_cells_in_complex(), cells_before) << "the remesher did nothing";
  // The domain is kept: the volume of the complex is the hull's.
  double volume_before = 0, volume_after = 0;
  for(auto c = ours.finite_cells_begin(); c != ours.finite_cells_end(); ++c)
    volume_before += ours.tetrahedron(c).volume();
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c)
    volume_after += c3t3.triangulation().tetrahedron(c).volume();
  EXPECT_NEAR(volume_after, volume_before, 1e-9 * volume_before);
}

} // namespace test_io_and_conversion
