// The segment traverser (cells and simplices) against two oracles:
//   - CGAL::Delaunay_triangulation_3 on the same points, for segments in
//     general position (random points), inside the hull or leaving it: the
//     same cells and simplices in the same order;
//   - point location in an exact CGAL triangulation of the same points: the
//     faces holding the points x(t) of the segment, t on a set of parameters,
//     in order.  On the integer grid every event of a segment between
//     half-integer points (crossing a facet plane, whose normal has entries in
//     {-1, 0, 1}) falls at t = a / b with b <= 18, so locating x(t) at these
//     fractions and at the midpoints between them gives every face the segment
//     meets: the simplices must be exactly these.  Elsewhere the located faces
//     must appear among the simplices, in order.
// Segments that start outside the hull follow CGAL's walk among the infinite
// cells; the sources are chosen so that CGAL's located cell is the only
// candidate.  In dimension 2 CGAL's own cell traverser answers on both sides,
// between points (its simplex traverser and its walk from a vertex are
// broken there).
// CGAL 5.5 is not the oracle for degenerate segments: its sequence through
// vertices and along edges changes with the insertion order of the same points,
// and it lists faces that the segment does not meet (a cell between an edge
// and a vertex on a segment along the edge, a cell instead of the facet when
// the segment lies in the facet).  The tests count and print how often it
// agrees there.

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Random.h>
#include <CGAL/point_generators_3.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <iostream>
#include <random>
#include <set>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace test_segment_traverser {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Exact_predicates_exact_constructions_kernel Exact_kernel;
typedef K::Point_3 Point;
typedef CGAL::Delaunay_triangulation_3<K> Cgal_dt;
typedef CGAL::Delaunay_triangulation_3<Exact_kernel> Exact_dt;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

struct Segment
{
  Point p, q;
};

// A face as the sorted text of its vertices' points ("inf" for the infinite
// vertex), prefixed by its dimension.
template <class Tr, class Vertex_range>
std::string face_text(const Tr& T, const Vertex_range& vertices, int dimension)
{
  std::vector<std::string> names;
  for(auto v : vertices) {
    std::ostringstream name;
    if(T.is_infinite(v)) name << "inf";
    else name << v->point();
    names.push_back(name.str());
  }
  std::sort(names.begin(), names.end());
  std::string text = std::to_string(dimension) + ":";
  for(const std::string& n : names) text += " (" + n + ")";
  return text;
}

// Its vertices up to the dimension (a triangle in dimension 2).
template <class Tr>
std::string cell_text(const Tr& T, typename Tr::Cell_handle c)
{
  std::vector<typename Tr::Vertex_handle> v;
  for(int i = 0; i <= T.dimension(); ++i) v.push_back(c->vertex(i));
  return face_text(T, v, 3);
}

template <class Tr>
std::string simplex_text(const Tr& T, const typename Tr::Simplex& s)
{
  std::vector<typename Tr::Vertex_handle> v;
  switch(s.dimension()) {
    case 0: v.push_back(typename Tr::Vertex_handle(s)); break;
    case 1: {
      const typename Tr::Edge e = s;
      v = {e.first->vertex(e.second), e.first->vertex(e.third)};
      break;
    }
    case 2: {
      const typename Tr::Facet f = s;
      for(int k = 0; k <= T.dimension(); ++k)
        if(k != f.second) v.push_back(f.first->vertex(k));
      break;
    }
    default: return cell_text(T, typename Tr::Cell_handle(s));
  }
  return face_text(T, v, s.dimension());
}

struct Walk_texts
{
  std::vector<std::string> cells, simplices;
  bool operator==(const Walk_texts& w) const { return cells == w.cells && simplices == w.simplices; }
};

template <class Tr>
Walk_texts point_walk(const Tr& T, const Segment& s)
{
  Walk_texts w;
  for(auto c = T.segment_traverser_cells_begin(s.p, s.q); c != T.segment_traverser_cells_end(); ++c)
    w.cells.push_back(cell_text(T, typename Tr::Cell_handle(c)));
  for(const typename Tr::Simplex& x : T.segment_traverser_simplices(s.p, s.q)) w.simplices.push_back(simplex_text(T, x));
  return w;
}

template <class Tr>
Walk_texts vertex_walk(const Tr& T, const Segment& s)
{
  typename Tr::Vertex_handle vs, vt;
  EXPECT_TRUE(T.is_vertex(s.p, vs) && T.is_vertex(s.q, vt));
  Walk_texts w;
  for(typename Tr::Cell_handle c : T.segment_traverser_cell_handles(vs, vt)) w.cells.push_back(cell_text(T, c));
  // CGAL 5.5's simplex iterator between two grid vertices dereferences a null
  // cell (Triangulation_segment_simplex_iterator_3::shared_facet).
  if constexpr(!std::is_same<Tr, Cgal_dt>::value)
    for(const typename Tr::Simplex& x : T.segment_traverser_simplices(vs, vt))
      w.simplices.push_back(simplex_text(T, x));
  return w;
}

typedef Exact_kernel::FT Exact;

std::vector<Exact> uniform_parameters(int n)
{
  std::vector<Exact> t;
  for(int i = 0; i <= n; ++i) t.push_back(Exact(i) / n);
  return t;
}

// All a / b in [0, 1] with b <= max_denominator, and the midpoints between them.
std::vector<Exact> fraction_parameters(int max_denominator)
{
  std::vector<std::pair<int, int>> fractions;
  for(int b = 1; b <= max_denominator; ++b)
    for(int a = 0; a <= b; ++a) fractions.push_back({a, b});
  std::sort(fractions.begin(), fractions.end(), [](auto x, auto y) { return x.first * y.second < y.first * x.second; });
  std::vector<Exact> t;
  for(auto f : fractions) {
    const Exact x = Exact(f.first) / f.second;
    if(!t.empty() && t.back() == x) continue;
    if(!t.empty()) t.push_back((t.back() + x) / 2);
    t.push_back(x);
  }
  return t;
}

// The faces of the exact triangulation holding x(t), in order, each once.
std::vector<std::string> sampled_faces(const Exact_dt& T, const Segment& s, const std::vector<Exact>& parameters,
                                       bool cells)
{
  typedef Exact_kernel::Point_3 Exact_point;
  const Exact_point p(s.p.x(), s.p.y(), s.p.z()), q(s.q.x(), s.q.y(), s.q.z());
  std::vector<std::string> faces;
  for(const Exact& t : parameters) {
    const Exact_point x = p + t * (q - p);
    Exact_dt::Locate_type lt;
    int li, lj;
    const Exact_dt::Cell_handle c = T.locate(x, lt, li, lj);
    std::vector<Exact_dt::Vertex_handle> v;
    if(lt == Exact_dt::VERTEX) v = {c->vertex(li)};
    else if(lt == Exact_dt::EDGE) v = {c->vertex(li), c->vertex(lj)};
    else if(lt == Exact_dt::FACET) {
      for(int k = 0; k < 4; ++k)
        if(k != li) v.push_back(c->vertex(k));
    } else v = {c->vertex(0), c->vertex(1), c->vertex(2), c->vertex(3)};
    if(cells && v.size() < 4) continue;
    // Outside the hull the located infinite cell is one of several.
    if(lt == Exact_dt::OUTSIDE_CONVEX_HULL) continue;
    std::string text = face_text(T, v, int(v.size()) - 1);
    // Exact points print with more digits than doubles: compare through doubles.
    if(faces.empty() || faces.back() != text) faces.push_back(text);
  }
  return faces;
}

bool is_subsequence(const std::vector<std::string>& part, const std::vector<std::string>& whole)
{
  std::size_t j = 0;
  for(const std::string& x : whole)
    if(j < part.size() && part[j] == x) ++j;
  return j == part.size();
}

struct Report
{
  int segments = 0, same_cells = 0, same_simplices = 0;
};

// exact_faces: the parameters catch every event, so the simplices are exactly
// the located faces; otherwise the located faces are a subsequence.
template <class Walk>
Report check_segments(const std::vector<Point>& points, const std::vector<Segment>& segments, Walk walk,
                      const std::vector<Exact>& parameters, bool exact_faces)
{
  Report report;
  const Fast_dt fast(points.begin(), points.end());
  const Cgal_dt cgal(points.begin(), points.end());
  std::vector<Exact_kernel::Point_3> exact_points;
  for(const Point& p : points) exact_points.emplace_back(p.x(), p.y(), p.z());
  const Exact_dt exact(exact_points.begin(), exact_points.end());

  for(const Segment& s : segments) {
    ++report.segments;
    const Walk_texts ours = walk(fast, s);
    const Walk_texts theirs = walk(cgal, s);
    report.same_cells += theirs.cells == ours.cells;
    report.same_simplices += theirs.simplices == ours.simplices;
    const std::vector<std::string> located = sampled_faces(exact, s, parameters, false);
    if(exact_faces) EXPECT_EQ(located, ours.simplices) << "simplices from " << s.p << " to " << s.q;
    else EXPECT_TRUE(is_subsequence(located, ours.simplices)) << "simplices from " << s.p << " to " << s.q;
    EXPECT_TRUE(is_subsequence(sampled_faces(exact, s, parameters, true), ours.cells))
        << "cells from " << s.p << " to " << s.q;
    // The cells met in their interior are listed among the cells, in order.
    std::vector<std::string> interior_cells;
    for(const std::string& f : ours.simplices)
      if(f[0] == '3') interior_cells.push_back(f);
    EXPECT_TRUE(is_subsequence(interior_cells, ours.cells));
    // Each face once; faces and cells alternate with their boundaries.
    for(std::size_t k = 1; k < ours.simplices.size(); ++k)
      EXPECT_NE(ours.simplices[k - 1].substr(0, 1), ours.simplices[k].substr(0, 1));
    EXPECT_FALSE(ours.cells.empty());
  }
  return report;
}

std::vector<Point> grid(int n)
{
  std::vector<Point> points;
  for(int x = 0; x < n; ++x)
    for(int y = 0; y < n; ++y)
      for(int z = 0; z < n; ++z) points.emplace_back(x, y, z);
  return points;
}

std::vector<Point> random_points(std::size_t n, int seed, double radius)
{
  CGAL::Random random(seed);
  CGAL::Random_points_in_cube_3<Point> generator(radius, random);
  std::vector<Point> points;
  std::copy_n(generator, n, std::back_inserter(points));
  return points;
}

// Segments inside a grid [0, n-1]^3, chosen to meet vertices, run along edges
// and lie in facets: grid lines, face diagonals, points on half-integers.
std::vector<Segment> grid_segments(int n, int seed)
{
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> half(0, 2 * (n - 1));
  std::vector<Segment> segments;
  while(segments.size() < 120) {
    Point p(half(random) / 2.0, half(random) / 2.0, half(random) / 2.0);
    Point q(half(random) / 2.0, half(random) / 2.0, half(random) / 2.0);
    // Half the segments keep one or two coordinates fixed: in grid planes and lines.
    if(segments.size() % 3 == 0) q = Point(q.x(), p.y(), q.z());
    if(segments.size() % 3 == 1) q = Point(q.x(), p.y(), p.z());
    if(p != q) segments.push_back({p, q});
  }
  return segments;
}

TEST(SegmentTraverser, RandomSegmentsInRandomPoints)
{
  const std::vector<Point> points = random_points(300, 7, 1.0);
  std::vector<Segment> segments;
  const std::vector<Point> ends = random_points(200, 8, 0.5);
  for(std::size_t k = 0; k + 1 < ends.size(); k += 2) segments.push_back({ends[k], ends[k + 1]});
  const Report r = check_segments(
      points, segments, [](const auto& T, const Segment& s) { return point_walk(T, s); }, uniform_parameters(64), false);
  EXPECT_EQ(r.segments, r.same_cells);
  EXPECT_EQ(r.segments, r.same_simplices);
}

TEST(SegmentTraverser, DegenerateSegmentsInGrid)
{
  const Report r = check_segments(
      grid(4), grid_segments(4, 1), [](const auto& T, const Segment& s) { return point_walk(T, s); },
      fraction_parameters(18), true);
  std::cout << "degenerate segments: cells of " << r.same_cells << ", simplices of " << r.same_simplices << " out of "
            << r.segments << " as CGAL 5.5 lists them\n";
}

TEST(SegmentTraverser, VertexToVertexInGrid)
{
  std::mt19937 random(5);
  std::uniform_int_distribution<int> coordinate(0, 3);
  std::vector<Segment> segments;
  while(segments.size() < 80) {
    const Point p(coordinate(random), coordinate(random), coordinate(random));
    Point q(coordinate(random), coordinate(random), coordinate(random));
    if(segments.size() % 2 == 0) q = Point(q.x(), p.y(), q.z());
    if(p != q) segments.push_back({p, q});
  }
  const Report r = check_segments(
      grid(4), segments, [](const auto& T, const Segment& s) { return vertex_walk(T, s); }, fraction_parameters(18),
      true);
  std::cout << "vertex to vertex: cells of " << r.same_cells << " out of " << r.segments << " as CGAL 5.5 lists them\n";
}

TEST(SegmentTraverser, SegmentsLeavingTheHull)
{
  const std::vector<Point> points = random_points(200, 9, 1.0);
  std::vector<Segment> segments;
  const std::vector<Point> inside = random_points(60, 10, 0.5), outside = random_points(60, 11, 3.0);
  for(std::size_t k = 0; k < inside.size(); ++k)
    if(std::abs(outside[k].x()) > 1 || std::abs(outside[k].y()) > 1 || std::abs(outside[k].z()) > 1)
      segments.push_back({inside[k], outside[k]});
  const Report r = check_segments(
      points, segments, [](const auto& T, const Segment& s) { return point_walk(T, s); }, uniform_parameters(64), false);
  EXPECT_EQ(r.segments, r.same_cells);
  EXPECT_EQ(r.segments, r.same_simplices);
  EXPECT_GT(r.segments, 20);
}

} // namespace test_segment_traverser

namespace test_segment_traverser {

// Points just outside the middle of hull facets, offset along the outer
// normal, kept when they see that facet only: CGAL's locate has a single
// answer there, the infinite cell of that facet, so its traverser's start does
// not depend on its storage.
std::vector<Point> sources_seeing_one_facet(const Cgal_dt& T, double offset)
{
  const auto orientation = K().orientation_3_object();
  // Whether x sees the finite facet of the infinite cell c.
  auto sees = [&](Cgal_dt::Cell_handle c, const Point& x) {
    std::array<Point, 4> p;
    for(int i = 0; i < 4; ++i) p[i] = T.is_infinite(c->vertex(i)) ? x : c->vertex(i)->point();
    return orientation(p[0], p[1], p[2], p[3]) == CGAL::POSITIVE;
  };
  std::vector<Point> sources;
  for(auto c = T.all_cells_begin(); c != T.all_cells_end(); ++c) {
    if(!T.is_infinite(c)) continue;
    const int inf = c->index(T.infinite_vertex());
    const K::Triangle_3 facet = T.triangle(c, inf);
    const Point g = CGAL::centroid(facet);
    K::Vector_3 n = facet.supporting_plane().orthogonal_vector();
    n = n / std::sqrt(n.squared_length());
    Point s = g + offset * n;
    if(!sees(c, s)) s = g - offset * n;
    int seen = 0;
    for(auto d = T.all_cells_begin(); d != T.all_cells_end(); ++d) seen += T.is_infinite(d) && sees(d, s);
    if(seen == 1) sources.push_back(s);
  }
  return sources;
}

// From outside the hull, CGAL's cells and simplices: into the hull (and out
// again), staying in the infinite cell of the source, and crossing to
// neighbouring infinite cells.
TEST(SegmentTraverser, SegmentsFromOutsideTheHull)
{
  const std::vector<Point> points = random_points(150, 12, 1.0);
  const Cgal_dt cgal(points.begin(), points.end());
  const std::vector<Point> sources = sources_seeing_one_facet(cgal, 1e-3);
  ASSERT_GT(sources.size(), 40u);
  const std::vector<Point> inside = random_points(sources.size(), 13, 0.4);
  std::vector<Segment> entering, staying, around;
  for(std::size_t k = 0; k < sources.size(); ++k) {
    const Point& s = sources[k];
    entering.push_back({s, inside[k]});
    entering.push_back({s, s + 3 * (inside[k] - s)}); // out again on the other side
    staying.push_back({s, s + 1e-3 * (s - inside[k])}); // further out: still sees the facet
    // Sideways, mostly along the hull: often into neighbouring infinite cells.
    const Point t = s + 0.3 * K::Vector_3(inside[k].y(), -inside[k].x(), inside[k].z() - inside[k].y());
    around.push_back({s, t});
  }
  auto walk = [](const auto& T, const Segment& s) { return point_walk(T, s); };
  const Report r_entering = check_segments(points, entering, walk, uniform_parameters(64), false);
  EXPECT_EQ(r_entering.segments, r_entering.same_cells);
  EXPECT_EQ(r_entering.segments, r_entering.same_simplices);
  const Report r_staying = check_segments(points, staying, walk, uniform_parameters(64), false);
  EXPECT_EQ(r_staying.segments, r_staying.same_cells);
  EXPECT_EQ(r_staying.segments, r_staying.same_simplices);
  const Report r_around = check_segments(points, around, walk, uniform_parameters(64), false);
  std::cout << "from outside, sideways: cells of " << r_around.same_cells << ", simplices of "
            << r_around.same_simplices << " out of " << r_around.segments << " as CGAL 5.5 lists them\n";
  // The source sees one facet only, so CGAL's located cell is ours and the
  // first step sideways is CGAL's whenever one plane only has the target behind.
  const Fast_dt fast(points.begin(), points.end());
  for(const Segment& s : around) {
    const std::vector<std::string> ours = point_walk(fast, s).cells, theirs = point_walk(cgal, s).cells;
    ASSERT_GE(ours.size(), 1u);
    ASSERT_GE(theirs.size(), 1u);
    EXPECT_EQ(ours[0], theirs[0]);
  }
}

// Dimension 2: the cells of CGAL's traverser between points of the plane.
// Sources outside the hull start from the infinite triangle that CGAL's
// locate picks among those that see them, which depends on the
// triangulation's storage: those walks are counted, not compared.
TEST(SegmentTraverser, DimensionTwo)
{
  CGAL::Random random(14);
  std::vector<Point> points;
  for(int k = 0; k < 120; ++k) points.emplace_back(random.get_double(-1, 1), random.get_double(-1, 1), 0.5);
  const Fast_dt fast(points.begin(), points.end());
  const Cgal_dt cgal(points.begin(), points.end());
  ASSERT_EQ(fast.dimension(), 2);
  int compared = 0, outside = 0, same_outside = 0;
  for(int k = 0; k < 80; ++k) {
    const double r = k < 40 ? 0.9 : 2.0; // the last ones often leave the hull or start outside it
    const Segment s{Point(random.get_double(-r, r), random.get_double(-r, r), 0.5),
                    Point(random.get_double(-r, r), random.get_double(-r, r), 0.5)};
    std::vector<std::string> ours, theirs;
    for(Fast_dt::Cell_handle c : fast.segment_traverser_cell_handles(s.p, s.q)) ours.push_back(cell_text(fast, c));
    for(Cgal_dt::Cell_handle c : cgal.segment_traverser_cell_handles(s.p, s.q)) theirs.push_back(cell_text(cgal, c));
    EXPECT_FALSE(ours.empty());
    Cgal_dt::Locate_type lt;
    int li, lj;
    cgal.locate(s.p, lt, li, lj);
    if(lt == Cgal_dt::OUTSIDE_CONVEX_HULL) {
      ++outside;
      same_outside += ours == theirs;
      continue;
    }
    EXPECT_EQ(ours, theirs) << "from " << s.p << " to " << s.q;
    ++compared;
  }
  std::cout << "dimension 2, from outside the hull: cells of " << same_outside << " out of " << outside
            << " as CGAL 5.5 lists them\n";
  EXPECT_GE(compared, 40);
}

} // namespace test_segment_traverser
