// Vertex and cell infos (Triangulation_vertex_base_with_info_3,
// Triangulation_cell_base_with_info_3): one test body runs on
// CGAL::Delaunay_triangulation_3 and on CGAL::Fast_Delaunay_triangulation_3
// with the same data structure argument.  Infos are compared by the points of
// their vertices or cells, never by handles.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/transform_iterator.hpp>
#include <boost/iterator/zip_iterator.hpp>

#include <iterator>
#include <map>
#include <sstream>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

using namespace fdt3_test;

namespace test_vertex_and_cell_infos {

// CGAL leaves a new int info uninitialised; a class type has a definite Info().
struct Label
{
  int value = 0;
  Label() = default;
  Label(int v) : value(v) {}
  operator int() const { return value; }
};

typedef CGAL::Triangulation_vertex_base_with_info_3<Label, K> Vb;
typedef CGAL::Triangulation_cell_base_with_info_3<Label, K, CGAL::Delaunay_triangulation_cell_base_3<K>> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Delaunay_triangulation_3<K, Tds> Cgal_info_dt;
typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds> Fast_info_dt;

// Vertex infos only, the data structure of CGAL's info examples.
typedef CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<K>> Tds_vertex_info;
static_assert(std::is_void<CGAL::Fast_Delaunay_triangulation_3<K, Tds_vertex_info>::Cell_info>::value,
              "no cell info without a cell base with info");
static_assert(std::is_void<CGAL::Fast_Delaunay_triangulation_3<K>::Vertex_info>::value,
              "no vertex info by default");

template <class Tr>
class Infos : public ::testing::Test
{
};

struct Names
{
  template <class Tr>
  static std::string GetName(int)
  {
    return std::is_same<Tr, Cgal_info_dt>::value ? "Cgal" : "Fast";
  }
};

typedef ::testing::Types<Cgal_info_dt, Fast_info_dt> Triangulations;
TYPED_TEST_SUITE(Infos, Triangulations, Names);

std::vector<Point> distinct_points(const std::string& name, std::size_t n)
{
  std::vector<Point> points = to_points<Point>(make_points(name, n, 21));
  std::vector<Point> distinct;
  std::set<Point_key> seen;
  for(const Point& p : points)
    if(seen.insert(point_key(p)).second) distinct.push_back(p);
  return distinct;
}

template <class Tr>
std::map<Point_key, int> vertex_infos(const Tr& tr)
{
  std::map<Point_key, int> infos;
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v)
    infos[point_key(v->point())] = v->info();
  return infos;
}

template <class Tr>
Cell_key cell_key(const Tr& tr, typename Tr::Cell_handle c)
{
  Cell_key key;
  for(int i = 0; i < 4; ++i) key[i] = point_key(tr.point(c, i));
  std::sort(key.begin(), key.end());
  return key;
}

template <class Tr>
std::map<Cell_key, int> cell_infos(const Tr& tr)
{
  std::map<Cell_key, int> infos;
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c)
    infos[cell_key(tr, c)] = c->info();
  return infos;
}

std::map<Point_key, int> expected_infos(const std::vector<Point>& points)
{
  std::map<Point_key, int> infos;
  for(std::size_t i = 0; i < points.size(); ++i) infos[point_key(points[i])] = static_cast<int>(i) + 1;
  return infos;
}

struct Pair_with_index
{
  const std::vector<Point>* points;
  std::pair<Point, Label> operator()(int i) const { return std::make_pair((*points)[i], i + 1); }
};

const char* const distributions[] = {"uniform", "grid", "sphere"};

TYPED_TEST(Infos, RangeOfPairsSetsEveryVertexInfo)
{
  for(const char* d : distributions) {
    SCOPED_TRACE(d);
    const std::vector<Point> points = distinct_points(d, 200);
    std::vector<std::pair<Point, Label>> pairs;
    for(std::size_t i = 0; i < points.size(); ++i) pairs.emplace_back(points[i], static_cast<int>(i) + 1);

    TypeParam by_constructor(pairs.begin(), pairs.end());
    EXPECT_EQ(vertex_infos(by_constructor), expected_infos(points));

    TypeParam by_insert;
    EXPECT_EQ(by_insert.insert(pairs.begin(), pairs.end()), static_cast<std::ptrdiff_t>(points.size()));
    EXPECT_EQ(vertex_infos(by_insert), expected_infos(points));
  }
}

TYPED_TEST(Infos, ZipAndTransformIterators)
{
  const std::vector<Point> points = distinct_points("uniform", 150);
  std::vector<Label> indices;
  for(std::size_t i = 0; i < points.size(); ++i) indices.push_back(static_cast<int>(i) + 1);

  TypeParam zipped(boost::make_zip_iterator(boost::make_tuple(points.begin(), indices.begin())),
                   boost::make_zip_iterator(boost::make_tuple(points.end(), indices.end())));
  EXPECT_EQ(vertex_infos(zipped), expected_infos(points));

  // Pairs yielded by value, as in CGAL's info_insert_with_transform_iterator example.
  const Pair_with_index make_pair{&points};
  TypeParam transformed;
  transformed.insert(boost::make_transform_iterator(boost::counting_iterator<int>(0), make_pair),
                     boost::make_transform_iterator(boost::counting_iterator<int>(int(points.size())), make_pair));
  EXPECT_EQ(vertex_infos(transformed), expected_infos(points));
}

// CGAL assigns the info after every insertion, duplicates included: a point
// already present gets the new info.
TYPED_TEST(Infos, DuplicateOfAnExistingVertexOverwritesItsInfo)
{
  const std::vector<Point> points = distinct_points("grid", 64);
  std::vector<std::pair<Point, Label>> pairs;
  for(std::size_t i = 0; i < points.size(); ++i) pairs.emplace_back(points[i], static_cast<int>(i) + 1);
  TypeParam tr(pairs.begin(), pairs.end());

  const std::vector<std::pair<Point, Label>> again = {{points[3], 1000}, {Point(0.5, 0.5, 0.5), 2000}};
  EXPECT_EQ(tr.insert(again.begin(), again.end()), 1);
  std::map<Point_key, int> expected = expected_infos(points);
  expected[point_key(points[3])] = 1000;
  expected[point_key(Point(0.5, 0.5, 0.5))] = 2000;
  EXPECT_EQ(vertex_infos(tr), expected);
}

// Within one range, which duplicate wins depends on the insertion order
// (CGAL: its spatial sort); it is always one of the duplicates' infos.
TYPED_TEST(Infos, DuplicatesInOneRangeKeepOneOfTheirInfos)
{
  const std::vector<Point> points = distinct_points("uniform", 100);
  std::vector<std::pair<Point, Label>> pairs;
  for(std::size_t i = 0; i < points.size(); ++i) {
    pairs.emplace_back(points[i], static_cast<int>(i) + 1);
    if(i % 3 == 0) pairs.emplace_back(points[i], -static_cast<int>(i) - 1);
  }
  TypeParam tr;
  EXPECT_EQ(tr.insert(pairs.begin(), pairs.end()), static_cast<std::ptrdiff_t>(points.size()));
  const std::map<Point_key, int> infos = vertex_infos(tr);
  ASSERT_EQ(infos.size(), points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    const int info = infos.at(point_key(points[i]));
    const int given = static_cast<int>(i) + 1;
    if(i % 3 == 0)
      EXPECT_TRUE(info == given || info == -given) << info;
    else
      EXPECT_EQ(info, given);
  }
}

TYPED_TEST(Infos, WrittenThroughHandlesAndIterators)
{
  const std::vector<Point> points = distinct_points("uniform", 120);
  TypeParam tr(points.begin(), points.end());
  // A range of points only: every info is Info().
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) EXPECT_EQ(v->info(), 0);

  std::map<Point_key, int> written;
  int next = 1;
  for(auto v : tr.finite_vertex_handles()) {
    v->info() = next;
    written[point_key(v->point())] = next++;
  }
  tr.infinite_vertex()->info() = -5;
  // Read back through the cells' vertex handles.
  for(auto c = tr.all_cells_begin(); c != tr.all_cells_end(); ++c)
    for(int i = 0; i < 4; ++i) {
      const typename TypeParam::Vertex_handle v = c->vertex(i);
      if(tr.is_infinite(v))
        EXPECT_EQ(v->info(), -5);
      else
        EXPECT_EQ(v->info(), written.at(point_key(v->point())));
    }

  typename TypeParam::Vertex_handle v = tr.insert(Point(0.25, 0.5, 0.75));
  v->info() = 4242;
  written[point_key(Point(0.25, 0.5, 0.75))] = 4242;
  EXPECT_EQ(vertex_infos(tr), written);
  EXPECT_EQ(tr.infinite_vertex()->info(), -5);
}

// Cells untouched by an insertion keep their infos; the cells of the
// re-triangulated region are new and have Info().  Both triangulations have
// the same cells, so the (cell, info) maps must agree.
TYPED_TEST(Infos, CellInfosSurviveOutsideTheCavity)
{
  // Not the sphere: a point inside it is in conflict with nearly every cell.
  for(const char* d : {"uniform", "grid"}) {
    SCOPED_TRACE(d);
    const std::vector<Point> points = distinct_points(d, 150);
    TypeParam tr(points.begin(), points.end());
    for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) EXPECT_EQ(c->info(), 0);
    std::map<Cell_key, int> before;
    int next = 1;
    for(auto c : tr.finite_cell_handles()) {
      c->info() = next;
      before[cell_key(tr, c)] = next++;
    }
    EXPECT_EQ(cell_infos(tr), before);

    const std::vector<Point> more = {Point(0.31, 0.52, 0.43), Point(1.5, 1.5, 1.5), Point(2.01, 1.7, 0.3)};
    tr.insert(more.begin(), more.end());
    tr.insert(Point(0.6, 0.11, 0.9));
    std::size_t kept = 0, fresh = 0;
    for(const auto& [cell, info] : cell_infos(tr)) {
      auto old = before.find(cell);
      if(old == before.end()) {
        EXPECT_EQ(info, 0);
        ++fresh;
      } else {
        EXPECT_EQ(info, old->second);
        ++kept;
      }
    }
    EXPECT_GT(kept, 0u);
    EXPECT_GT(fresh, 0u);
  }
}

TYPED_TEST(Infos, CopiesCarryInfos)
{
  const std::vector<Point> points = distinct_points("sphere", 100);
  std::vector<std::pair<Point, Label>> pairs;
  for(std::size_t i = 0; i < points.size(); ++i) pairs.emplace_back(points[i], static_cast<int>(i) + 1);
  TypeParam tr(pairs.begin(), pairs.end());
  for(auto c : tr.finite_cell_handles()) c->info() = 9;
  TypeParam copy(tr);
  for(auto v : tr.finite_vertex_handles()) v->info() = 0;
  EXPECT_EQ(vertex_infos(copy), expected_infos(points));
  for(auto c = copy.finite_cells_begin(); c != copy.finite_cells_end(); ++c) EXPECT_EQ(c->info(), 9);
  TypeParam assigned;
  assigned = copy;
  EXPECT_EQ(vertex_infos(assigned), expected_infos(points));
  assigned.clear();
  EXPECT_EQ(assigned.number_of_vertices(), 0u);
}

TYPED_TEST(Infos, SinglePassInputIterator)
{
  const std::vector<Point> points = distinct_points("grid", 27);
  std::stringstream text;
  for(const Point& p : points) text << p << '\n';
  TypeParam tr;
  const std::ptrdiff_t added = tr.insert(std::istream_iterator<Point>(text), std::istream_iterator<Point>());
  EXPECT_EQ(added, static_cast<std::ptrdiff_t>(points.size()));
  EXPECT_EQ(tr.number_of_vertices(), points.size());
  EXPECT_EQ(tr.dimension(), 3);
}

// Our choice among duplicates of one range is deterministic: the last in
// input order, as if the elements were inserted one by one.
TEST(InfosFast, LastDuplicateInInputOrderWins)
{
  const std::vector<std::pair<Point, Label>> pairs = {
      {Point(0, 0, 0), 1}, {Point(1, 0, 0), 2}, {Point(0, 1, 0), 3}, {Point(0, 0, 1), 4},
      {Point(1, 0, 0), 5}, {Point(0, 0, 0), 6}, {Point(1, 0, 0), 7}};
  Fast_info_dt tr(pairs.begin(), pairs.end());
  const std::map<Point_key, int> expected = {{point_key(Point(0, 0, 0)), 6}, {point_key(Point(1, 0, 0)), 7},
                                             {point_key(Point(0, 1, 0)), 3}, {point_key(Point(0, 0, 1)), 4}};
  EXPECT_EQ(vertex_infos(tr), expected);
}

#ifdef CGAL_LINKED_WITH_TBB
// The parallel engine (Parallel_tag data structure) gives every vertex its info too.
TEST(InfosFast, ParallelDataStructure)
{
  typedef CGAL::Triangulation_data_structure_3<Vb, CGAL::Delaunay_triangulation_cell_base_3<K>, CGAL::Parallel_tag>
      Parallel_tds;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Parallel_tds> Parallel_dt;
  const std::vector<Point> points = distinct_points("uniform", 20000);
  std::vector<Label> indices;
  for(std::size_t i = 0; i < points.size(); ++i) indices.push_back(static_cast<int>(i) + 1);
  Parallel_dt tr;
  tr.set_number_of_threads(2);
  tr.insert(boost::make_zip_iterator(boost::make_tuple(points.begin(), indices.begin())),
            boost::make_zip_iterator(boost::make_tuple(points.end(), indices.end())));
  EXPECT_EQ(vertex_infos(tr), expected_infos(points));
}
#endif

} // namespace test_vertex_and_cell_infos
