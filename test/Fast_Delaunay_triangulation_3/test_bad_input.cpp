// Points with a NaN or infinite coordinate: insert(first, last) (from arrays,
// read in place, and from other ranges), the range constructor and insert(p)
// throw std::invalid_argument whose message names the position of the first
// bad point in the input, and the triangulation is left exactly as it was
// (same vertices, same cells, valid) and usable.
// Extreme but finite coordinates are accepted.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <cctype>
#include <deque>
#include <iterator>
#include <limits>
#include <list>
#include <string>
#include <vector>

using namespace fdt3_test;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

namespace test_bad_input {

struct Bad_value
{
  const char* name;
  double value;
};

const Bad_value bad_values[] = {{"NaN", std::numeric_limits<double>::quiet_NaN()},
                                {"+inf", std::numeric_limits<double>::infinity()},
                                {"-inf", -std::numeric_limits<double>::infinity()}};

// Triangulations a failed insertion must leave alone: empty, one vertex,
// planar (triangles only), spatial.
struct Start
{
  const char* name;
  std::vector<Point> points;
};

std::vector<Start> starts()
{
  std::vector<Point> planar;
  for(const Xyz& q : uniform_points(20, 1)) planar.emplace_back(q.x, q.y, 0.5);
  return {{"empty", {}},
          {"one point", {Point(0.5, 0.5, 0.5)}},
          {"planar", planar},
          {"spatial", to_points<Point>(uniform_points(50, 2))}};
}

Point with_coordinate(const Point& p, int axis, double value)
{
  double xyz[3] = {p.x(), p.y(), p.z()};
  xyz[axis] = value;
  return Point(xyz[0], xyz[1], xyz[2]);
}

// Everything observable about a triangulation, recorded before an insertion
// that must fail.
struct Snapshot
{
  int dimension;
  std::size_t vertices, cells;
  std::vector<Point_key> vertex_keys;
  std::vector<Cell_key> cell_keys;

  explicit Snapshot(const Fast_dt& tr)
      : dimension(tr.dimension()), vertices(tr.number_of_vertices()), cells(tr.number_of_cells()),
        vertex_keys(finite_vertex_keys(tr)), cell_keys(finite_cell_keys(tr))
  {
  }
};

void expect_unchanged(const Fast_dt& tr, const Snapshot& before)
{
  EXPECT_TRUE(tr.is_valid());
  EXPECT_EQ(tr.dimension(), before.dimension);
  EXPECT_EQ(tr.number_of_vertices(), before.vertices);
  EXPECT_EQ(tr.number_of_cells(), before.cells);
  EXPECT_TRUE(finite_vertex_keys(tr) == before.vertex_keys) << "vertices changed";
  EXPECT_TRUE(finite_cell_keys(tr) == before.cell_keys) << "cells changed";
}

// The non-negative integers written in a message.
std::vector<unsigned long long> numbers_in(const std::string& message)
{
  std::vector<unsigned long long> numbers;
  for(std::size_t i = 0; i < message.size();) {
    if(!std::isdigit(static_cast<unsigned char>(message[i]))) { ++i; continue; }
    std::size_t j = i;
    while(j < message.size() && std::isdigit(static_cast<unsigned char>(message[j]))) ++j;
    numbers.push_back(std::stoull(message.substr(i, j - i)));
    i = j;
  }
  return numbers;
}

void expect_names_position(const std::invalid_argument& e, std::size_t position)
{
  const std::vector<unsigned long long> numbers = numbers_in(e.what());
  EXPECT_NE(std::find(numbers.begin(), numbers.end(), position), numbers.end())
      << "the message \"" << e.what() << "\" does not name position " << position;
}

// Calls `insert` and expects std::invalid_argument naming `position`.
template <class Insert>
void expect_invalid_argument_at(Insert insert, std::size_t position)
{
  try {
    insert();
    ADD_FAILURE() << "no exception";
  } catch(const std::invalid_argument& e) {
    expect_names_position(e, position);
  } catch(...) {
    ADD_FAILURE() << "an exception other than std::invalid_argument";
  }
}

// A single-pass iterator over a vector: insert(first, last) may read each
// point only once.
class Single_pass_iterator
{
public:
  typedef std::input_iterator_tag iterator_category;
  typedef Point value_type;
  typedef std::ptrdiff_t difference_type;
  typedef const Point* pointer;
  typedef const Point& reference;

  Single_pass_iterator(const std::vector<Point>* points, std::size_t i) : points_(points), i_(i) {}
  const Point& operator*() const { return (*points_)[i_]; }
  const Point* operator->() const { return &(*points_)[i_]; }
  Single_pass_iterator& operator++() { ++i_; return *this; }
  Single_pass_iterator operator++(int) { Single_pass_iterator old = *this; ++i_; return old; }
  friend bool operator==(const Single_pass_iterator& a, const Single_pass_iterator& b) { return a.i_ == b.i_; }
  friend bool operator!=(const Single_pass_iterator& a, const Single_pass_iterator& b) { return a.i_ != b.i_; }

private:
  const std::vector<Point>* points_;
  std::size_t i_;
};

TEST(Bad_input, RangeInsertThrowsNamingThePositionAndChangesNothing)
{
  const std::vector<Point> batch = to_points<Point>(uniform_points(1001, 3));
  for(const Start& start : starts())
    for(const Bad_value& bad : bad_values)
      for(int axis = 0; axis < 3; ++axis)
        for(std::size_t position : {std::size_t(0), std::size_t(500), batch.size() - 1}) {
          SCOPED_TRACE(std::string(start.name) + ", " + bad.name + " in coordinate " + std::to_string(axis) +
                       " of point " + std::to_string(position));
          std::vector<Point> points = batch;
          points[position] = with_coordinate(points[position], axis, bad.value);
          Fast_dt tr(start.points.begin(), start.points.end());
          const Snapshot before(tr);
          expect_invalid_argument_at([&] { tr.insert(points.begin(), points.end()); }, position);
          expect_unchanged(tr, before);
        }
}

// The range insertion reads arrays of points (pointers, std::vector) where
// they are and copies other ranges first: both check every point before
// anything changes.
TEST(Bad_input, EveryKindOfRangeThrowsAlike)
{
  std::vector<Point> points = to_points<Point>(uniform_points(301, 8));
  points[200] = with_coordinate(points[200], 2, bad_values[0].value);
  const std::list<Point> listed(points.begin(), points.end());
  const std::deque<Point> queued(points.begin(), points.end());
  const Point* const array = points.data();
  for(const Start& start : starts()) {
    SCOPED_TRACE(start.name);
    Fast_dt tr(start.points.begin(), start.points.end());
    const Snapshot before(tr);
    expect_invalid_argument_at([&] { tr.insert(array, array + points.size()); }, 200);
    expect_unchanged(tr, before);
    expect_invalid_argument_at([&] { tr.insert(points.cbegin(), points.cend()); }, 200);
    expect_unchanged(tr, before);
    expect_invalid_argument_at([&] { tr.insert(listed.begin(), listed.end()); }, 200);
    expect_unchanged(tr, before);
    expect_invalid_argument_at([&] { tr.insert(queued.begin(), queued.end()); }, 200);
    expect_unchanged(tr, before);
    std::vector<Fast_dt::Vertex_handle> none;
    expect_invalid_argument_at(
        [&] { tr.insert_and_give_vertices(points.begin(), points.end(), std::back_inserter(none)); }, 200);
    expect_invalid_argument_at(
        [&] { tr.insert_and_give_vertices(listed.begin(), listed.end(), std::back_inserter(none)); }, 200);
    EXPECT_TRUE(none.empty());
    expect_unchanged(tr, before);
  }
}

TEST(Bad_input, FirstBadPointIsNamed)
{
  std::vector<Point> points = to_points<Point>(uniform_points(40, 4));
  points[17] = with_coordinate(points[17], 1, bad_values[1].value);
  points[23] = with_coordinate(points[23], 0, bad_values[0].value);
  points[31] = with_coordinate(points[31], 2, bad_values[2].value);
  Fast_dt tr;
  expect_invalid_argument_at([&] { tr.insert(points.begin(), points.end()); }, 17);
  EXPECT_EQ(tr.number_of_vertices(), 0u);
}

TEST(Bad_input, ConstructorThrowsNamingThePosition)
{
  for(const Bad_value& bad : bad_values) {
    SCOPED_TRACE(bad.name);
    std::vector<Point> points = to_points<Point>(uniform_points(30, 5));
    points[12] = with_coordinate(points[12], 2, bad.value);
    expect_invalid_argument_at([&] { Fast_dt tr(points.begin(), points.end()); }, 12);
  }
}

TEST(Bad_input, SinglePassRangeThrowsAndChangesNothing)
{
  for(const Start& start : starts()) {
    SCOPED_TRACE(start.name);
    std::vector<Point> points = to_points<Point>(uniform_points(25, 6));
    points[9] = with_coordinate(points[9], 0, bad_values[0].value);
    Fast_dt tr(start.points.begin(), start.points.end());
    const Snapshot before(tr);
    expect_invalid_argument_at(
        [&] { tr.insert(Single_pass_iterator(&points, 0), Single_pass_iterator(&points, points.size())); }, 9);
    expect_unchanged(tr, before);
  }
}

TEST(Bad_input, PointInsertThrowsAndChangesNothing)
{
  for(const Start& start : starts())
    for(const Bad_value& bad : bad_values)
      for(int axis = 0; axis < 3; ++axis) {
        SCOPED_TRACE(std::string(start.name) + ", " + bad.name + " in coordinate " + std::to_string(axis));
        const Point p = with_coordinate(Point(0.25, 0.75, 0.125), axis, bad.value);
        Fast_dt tr(start.points.begin(), start.points.end());
        const Snapshot before(tr);
        EXPECT_THROW(tr.insert(p), std::invalid_argument);
        expect_unchanged(tr, before);
        EXPECT_THROW(tr.insert(p, tr.infinite_vertex()), std::invalid_argument);
        EXPECT_THROW(tr.insert(p, Fast_dt::Cell_handle(tr.finite_cells_begin())), std::invalid_argument);
        expect_unchanged(tr, before);
      }
}

// insert_outside_affine_hull checks CGAL's preconditions: a point in the
// affine hull (a vertex included) or any point in dimension 3, as well as a
// NaN or infinite coordinate, throws std::invalid_argument and changes nothing.
TEST(Bad_input, InsertOutsideAffineHullNeedsAPointOutsideIt)
{
  std::vector<Point> line;
  for(int i = 0; i < 5; ++i) line.emplace_back(i, i, 0);
  const std::vector<std::pair<Start, std::vector<Point>>> cases = {
      {{"one point", {Point(0.5, 0.5, 0.5)}}, {Point(0.5, 0.5, 0.5)}},
      {{"collinear", line}, {Point(2.5, 2.5, 0), Point(-7, -7, 0), Point(4, 4, 0)}},
      {starts()[2], {Point(0.3, 0.9, 0.5), Point(40, -3, 0.5), starts()[2].points[3]}},
      {starts()[3], {Point(0.5, 0.5, 0.5), Point(9, 9, 9)}},
  };
  for(const auto& c : cases) {
    Fast_dt tr(c.first.points.begin(), c.first.points.end());
    const Snapshot before(tr);
    std::vector<Point> bad = c.second;
    bad.push_back(Point(std::numeric_limits<double>::quiet_NaN(), 1, 2));
    for(const Point& p : bad) {
      SCOPED_TRACE(std::string(c.first.name) + ", point " + std::to_string(p.x()));
      EXPECT_THROW(tr.insert_outside_affine_hull(p), std::invalid_argument);
      expect_unchanged(tr, before);
    }
  }
}

TEST(Bad_input, UsableAfterAFailedInsertion)
{
  // After each failure, the good points still give CGAL's triangulation.
  for(const Start& start : starts()) {
    SCOPED_TRACE(start.name);
    const std::vector<Point> good = to_points<Point>(uniform_points(60, 7));
    std::vector<Point> bad_batch = good;
    bad_batch[30] = with_coordinate(bad_batch[30], 1, bad_values[0].value);
    Fast_dt tr(start.points.begin(), start.points.end());
    EXPECT_THROW(tr.insert(bad_batch.begin(), bad_batch.end()), std::invalid_argument);
    EXPECT_THROW(tr.insert(bad_batch[30]), std::invalid_argument);
    EXPECT_EQ(tr.insert(good.begin(), good.begin() + 30), std::ptrdiff_t(30));
    for(auto p = good.begin() + 30; p != good.end(); ++p) EXPECT_TRUE(tr.insert(*p)->point() == *p);
    std::vector<Point> all = start.points;
    all.insert(all.end(), good.begin(), good.end());
    expect_same_as_cgal(tr, Cgal_dt(all.begin(), all.end()));
  }
}

TEST(Bad_input, ExtremeFiniteCoordinatesAreAccepted)
{
  // The largest and smallest doubles, subnormals and signed zeros are valid input.
  const double big = std::numeric_limits<double>::max(), small = std::numeric_limits<double>::min(),
               tiny = std::numeric_limits<double>::denorm_min();
  const std::vector<Point> points = {
      Point(0, 0, 0),        Point(big, 0, 0),        Point(0, big, 0),          Point(0, 0, big),
      Point(-big, -big, 0),  Point(tiny, tiny, tiny), Point(-tiny, 0, small),    Point(small, -small, 0),
      Point(-0.0, 1, 1),     Point(1, 1, 1),          Point(big / 2, big / 2, big / 2), Point(-1, -big, big)};
  const Cgal_dt cgal(points.begin(), points.end());
  const Fast_dt bulk(points.begin(), points.end());
  expect_same_as_cgal(bulk, cgal);
  Fast_dt one_by_one;
  for(const Point& p : points) EXPECT_TRUE(one_by_one.insert(p)->point() == p);
  expect_same_as_cgal(one_by_one, cgal);
}

} // namespace test_bad_input
