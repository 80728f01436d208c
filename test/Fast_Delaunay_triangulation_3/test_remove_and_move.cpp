// remove, remove(range), remove_cluster, move and move_if_no_collision.  The
// oracle is CGAL::Delaunay_triangulation_3 built from the points that remain
// (the perturbed Delaunay triangulation is unique): after every step the
// finite cells, as point sets, must be CGAL's.  Surviving handles must still
// designate their points, with their vertex infos; cells outside the hole
// keep their infos.  Inputs: random points, the 5x5x5 grid (heavy
// degeneracy), cospherical points, coplanar points and fewer than five
// points, removed and moved through every dimension.
#include "triangulation_checks.h"

#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/convert_to_cgal.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <random>
#include <stdexcept>
#include <vector>

using namespace fdt3_test;

namespace test_remove_and_move {

typedef CGAL::Triangulation_vertex_base_with_info_3<int, K> Vb;
typedef CGAL::Triangulation_cell_base_with_info_3<int, K, CGAL::Delaunay_triangulation_cell_base_3<K>> Cb;
typedef CGAL::Triangulation_data_structure_3<Vb, Cb> Tds;
typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds> Fast_dt;
typedef Fast_dt::Vertex_handle Vertex_handle;

// The triangulation under test and what it must hold: each live handle with
// its point and the info given to it when it was inserted.
struct Tracked
{
  struct Entry
  {
    Vertex_handle first;
    Point second;
    int info;
  };
  Fast_dt tr;
  std::vector<Entry> vertices;
  int next_info = 1;

  Vertex_handle insert(const Point& p)
  {
    const std::size_t before = tr.number_of_vertices();
    const Vertex_handle v = tr.insert(p);
    if(tr.number_of_vertices() != before) add(v, p);
    return v;
  }
  void add(Vertex_handle v, const Point& p)
  {
    v->info() = next_info;
    vertices.push_back({v, p, next_info++});
  }
  // A bulk insertion (BRIO order, partitioned with threads), each point's
  // vertex then found by its point.
  void insert_range(const std::vector<Point>& points)
  {
    tr.insert(points.begin(), points.end());
    for(const Point& p : points) {
      Vertex_handle v;
      ASSERT_TRUE(tr.is_vertex(p, v));
      add(v, p);
    }
  }
  void remove_at(std::size_t k)
  {
    tr.remove(vertices[k].first);
    forget(k);
  }
  std::vector<Point> points() const
  {
    std::vector<Point> p;
    for(const auto& e : vertices) p.push_back(e.second);
    return p;
  }
  void forget(std::size_t k) { vertices.erase(vertices.begin() + static_cast<std::ptrdiff_t>(k)); }

  // Same triangulation as CGAL's of the same points; every handle still at
  // its point with its info.
  void check(const char* where) const
  {
    SCOPED_TRACE(where);
    const std::vector<Point> p = points();
    const Cgal_dt cgal(p.begin(), p.end());
    expect_same_as_cgal(tr, cgal);
    for(const auto& e : vertices) {
      ASSERT_TRUE(tr.is_vertex(e.first));
      EXPECT_EQ(e.first->point(), e.second);
      EXPECT_EQ(e.first->info(), e.info);
    }
    std::size_t iterated = 0;
    for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) ++iterated;
    EXPECT_EQ(iterated, vertices.size());
    EXPECT_EQ(std::size_t(std::distance(tr.all_vertices_begin(), tr.all_vertices_end())), vertices.size() + 1);
  }
};

Point random_point(std::mt19937_64& rng)
{
  std::uniform_real_distribution<double> u(0, 1);
  return Point(u(rng), u(rng), u(rng));
}
std::vector<Point> random_points(int n, std::mt19937_64& rng)
{
  std::vector<Point> p;
  for(int i = 0; i < n; ++i) p.push_back(random_point(rng));
  return p;
}

// Random steps on `points`: insert a point of `points`, remove a vertex or
// move one (a little, far, or onto another vertex), checked against CGAL
// after each step.
void random_steps(const std::vector<Point>& points, int steps, std::uint64_t seed, bool on_grid,
                  bool sub_determinants = false)
{
  Tracked t;
  t.tr.set_sub_determinants(sub_determinants);
  for(const Point& p : points) t.insert(p);
  t.check("initial");
  std::mt19937_64 rng(seed);
  for(int s = 0; s < steps && !::testing::Test::HasFatalFailure(); ++s) {
    const int kind = static_cast<int>(rng() % 4);
    if(kind == 0 || t.vertices.empty()) {
      t.insert(points[rng() % points.size()]);
    } else if(kind == 1) {
      t.remove_at(rng() % t.vertices.size());
    } else {
      const std::size_t k = rng() % t.vertices.size();
      const Point from = t.vertices[k].second;
      Point to;
      if(kind == 2 && on_grid) to = Point(from.x() + double(rng() % 3) - 1, from.y(), from.z() + 1);
      else if(kind == 2) to = Point(from.x() + 0.01 * (double(rng() % 100) / 100 - 0.5), from.y(), from.z());
      else to = points[rng() % points.size()];
      std::size_t other = t.vertices.size();
      for(std::size_t j = 0; j < t.vertices.size(); ++j)
        if(j != k && t.vertices[j].second == to) other = j;
      const Vertex_handle w = t.tr.move(t.vertices[k].first, to);
      if(other != t.vertices.size()) {
        EXPECT_EQ(w, t.vertices[other].first); // onto another vertex: v is removed
        t.forget(k);
      } else {
        EXPECT_EQ(w, t.vertices[k].first); // the handle (and info) move with it
        t.vertices[k].second = to;
      }
    }
      t.check(("step " + std::to_string(s)).c_str());
  }
}

std::vector<Point> grid(int k)
{
  std::vector<Point> p;
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
      for(int l = 0; l < k; ++l) p.emplace_back(i, j, l);
  return p;
}

TEST(Remove, RandomPointsInsertRemoveMove)
{
  std::mt19937_64 rng(11);
  const std::vector<Point> points = random_points(150, rng);
  random_steps(points, 120, 12, false);
}

TEST(Remove, GridInsertRemoveMove) { random_steps(grid(5), 120, 13, true); }

// The new tetrahedra get their cached sub-determinants (is_valid's Delaunay
// checks do not read them; later insertions do).
TEST(Remove, WithSubDeterminants)
{
  std::mt19937_64 rng(26);
  const std::vector<Point> points = random_points(100, rng);
  random_steps(points, 80, 27, false, true);
  random_steps(grid(4), 60, 28, true, true);
}

TEST(Remove, CosphericalInsertRemoveMove)
{
  std::vector<Point> points = to_points<Point>(integer_sphere_points(50));
  points.emplace_back(0, 0, 0);
  random_steps(points, 80, 14, true);
}

// Every vertex of the grid removed, in random order: the last ones span a
// plane, a line, a point, nothing.
TEST(Remove, WholeGridDownToEmpty)
{
  Tracked t;
  for(const Point& p : grid(4)) t.insert(p);
  std::mt19937_64 rng(15);
  int dimension_seen[4] = {0, 0, 0, 0};
  while(!t.vertices.empty() && !::testing::Test::HasFatalFailure()) {
    t.remove_at(rng() % t.vertices.size());
    t.check("after a removal");
    if(t.tr.dimension() >= 0) ++dimension_seen[t.tr.dimension()];
  }
  EXPECT_EQ(t.tr.dimension(), -1);
  EXPECT_EQ(t.tr.number_of_vertices(), 0u);
  EXPECT_GT(dimension_seen[3], 0);
  EXPECT_TRUE(t.tr.is_valid());
}

// Removing the apex of a pyramid on a square leaves coplanar points: the
// dimension drops to 2; moving a base vertex up lifts it back to 3.
TEST(Remove, DimensionDropAndLift)
{
  Tracked t;
  for(const Point& p : {Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(1, 1, 0), Point(0.5, 0.5, 0)})
    t.insert(p);
  const Vertex_handle apex = t.insert(Point(0.5, 0.5, 1));
  t.check("pyramid");
  ASSERT_EQ(t.tr.dimension(), 3);
  t.tr.remove(apex);
  t.forget(t.vertices.size() - 1);
  t.check("apex removed");
  EXPECT_EQ(t.tr.dimension(), 2);
  const Vertex_handle v = t.vertices[1].first;
  EXPECT_EQ(t.tr.move(v, Point(1, 0, 2)), v);
  t.vertices[1].second = Point(1, 0, 2);
  t.check("lifted by a move");
  EXPECT_EQ(t.tr.dimension(), 3);
  EXPECT_EQ(t.tr.move(v, Point(1, 0, 0)), v);
  t.vertices[1].second = Point(1, 0, 0);
  t.check("moved back into the plane");
  EXPECT_EQ(t.tr.dimension(), 2);
}

// A pyramid on a cube: the apex's link (the top face) is flat, yet the rest
// spans 3D, so the hole is filled by hull facets only.
TEST(Remove, FlatLinkOnTheHull)
{
  Tracked t;
  for(const Point& p : grid(2)) t.insert(p);
  const Vertex_handle apex = t.insert(Point(0.4, 0.45, 3));
  t.check("pyramid on a cube");
  t.tr.remove(apex);
  t.forget(t.vertices.size() - 1);
  t.check("apex removed");
  EXPECT_EQ(t.tr.dimension(), 3);
}

// Apexes over the top face of a 3x3x3 grid, random and over grid points
// (cospherical ties): the link is flat or not, both fills against CGAL.
TEST(Remove, ApexesOverAGridFace)
{
  std::mt19937_64 rng(30);
  std::uniform_real_distribution<double> u(0, 2);
  std::vector<Point> apexes = {Point(1, 1, 3), Point(0, 0, 2.5), Point(2, 1, 4), Point(1, 1, 2.25)};
  for(int k = 0; k < 16; ++k) apexes.emplace_back(u(rng), u(rng), 2 + u(rng) / 4);
  for(const Point& apex : apexes) {
    Tracked t;
    for(const Point& p : grid(3)) t.insert(p);
    const Vertex_handle v = t.insert(apex);
      t.tr.remove(v);
    t.forget(t.vertices.size() - 1);
    t.check("apex removed");
    if(::testing::Test::HasFatalFailure()) return;
  }
}

// Coplanar points (dimension 2) and fewer than five points: removals and
// moves in dimensions -1 to 3, up and down.
TEST(Remove, LowerDimensions)
{
  std::vector<Point> plane;
  for(int i = 0; i < 30; ++i) plane.emplace_back(i % 6, i / 6, 0);
  random_steps(plane, 60, 16, true);
  random_steps({Point(0, 0, 0), Point(1, 0, 0), Point(0, 1, 0), Point(0, 0, 1)}, 60, 17, true);
  random_steps({Point(0, 0, 0), Point(2, 0, 0), Point(1, 0, 0)}, 40, 18, true);
}

// Every hull vertex of random points, each with ghost cells in its star.
TEST(Remove, HullVertices)
{
  Tracked t;
  std::mt19937_64 rng(19);
  for(const Point& p : random_points(200, rng)) t.insert(p);
  std::vector<Vertex_handle> hull;
  t.tr.adjacent_vertices(t.tr.infinite_vertex(), std::back_inserter(hull));
  ASSERT_GT(hull.size(), 10u);
  for(std::size_t h = 0; h < hull.size() && !::testing::Test::HasFatalFailure(); ++h) {
    bool on_hull = false;
    std::vector<Fast_dt::Cell_handle> cells;
    t.tr.incident_cells(hull[h], std::back_inserter(cells));
    for(auto c : cells) on_hull = on_hull || t.tr.is_infinite(c);
    EXPECT_TRUE(on_hull);
    t.tr.remove(hull[h]);
    for(std::size_t k = 0; k < t.vertices.size(); ++k)
      if(t.vertices[k].first == hull[h]) t.forget(k);
    t.check("hull vertex removed");
  }
}

// Cells outside the hole keep their infos; the cells that fill it are new
// (Info()), as in CGAL.
TEST(Remove, CellInfosOutsideTheHoleSurvive)
{
  Tracked t;
  std::mt19937_64 rng(20);
  for(const Point& p : random_points(100, rng)) t.insert(p);
  for(int round = 0; round < 10; ++round) {
    std::map<Cell_key, int> info_of;
    int next = 1;
    for(auto c = t.tr.finite_cells_begin(); c != t.tr.finite_cells_end(); ++c) {
      c->info() = next++;
      Cell_key k;
      for(int i = 0; i < 4; ++i) k[i] = point_key(c->vertex(i)->point());
      std::sort(k.begin(), k.end());
      info_of[k] = c->info();
    }
    t.remove_at(rng() % t.vertices.size());
    std::size_t kept = 0, fresh = 0;
    for(auto c = t.tr.finite_cells_begin(); c != t.tr.finite_cells_end(); ++c) {
      Cell_key k;
      for(int i = 0; i < 4; ++i) k[i] = point_key(c->vertex(i)->point());
      std::sort(k.begin(), k.end());
      const auto found = info_of.find(k);
      if(found != info_of.end()) {
        EXPECT_EQ(c->info(), found->second);
        ++kept;
      } else {
        EXPECT_EQ(c->info(), 0);
        ++fresh;
      }
    }
    EXPECT_GT(kept, 0u);
    EXPECT_GT(fresh, 0u);
  }
}

TEST(Remove, RangeReturnsTheCount)
{
  Tracked t;
  std::mt19937_64 rng(21);
  for(const Point& p : random_points(120, rng)) t.insert(p);
  std::vector<Vertex_handle> gone;
  for(int k = 0; k < 30; ++k) {
    gone.push_back(t.vertices.back().first);
    t.vertices.pop_back();
  }
  bool could_lock_zone = false;
  EXPECT_TRUE(t.tr.remove(gone.back(), &could_lock_zone));
  EXPECT_TRUE(could_lock_zone);
  gone.pop_back();
  t.insert(Point(0.5, 0.5, 0.5));
  EXPECT_EQ(t.tr.remove(gone.begin(), gone.begin() + 15), 15u);
  EXPECT_EQ(t.tr.remove_cluster(gone.begin() + 15, gone.end()), 14u);
  t.check("after the ranges");
  for(Vertex_handle v : gone) EXPECT_FALSE(t.tr.is_vertex(v));
}

TEST(Move, OntoAnotherVertex)
{
  Tracked t;
  std::mt19937_64 rng(22);
  for(const Point& p : random_points(60, rng)) t.insert(p);
  const Vertex_handle v = t.vertices[3].first, w = t.vertices[7].first;
  EXPECT_EQ(t.tr.move_if_no_collision(v, w->point()), w);
  t.check("move_if_no_collision onto a vertex changes nothing");
  EXPECT_EQ(t.tr.move_if_no_collision(v, v->point()), v);
  EXPECT_EQ(t.tr.move(v, w->point()), w);
  t.forget(3);
  t.check("move onto a vertex removes v");
  EXPECT_FALSE(t.tr.is_vertex(v));
}

TEST(Move, MoveIfNoCollisionKeepsTheHandle)
{
  Tracked t;
  std::mt19937_64 rng(23);
  for(const Point& p : random_points(80, rng)) t.insert(p);
  for(int s = 0; s < 40 && !::testing::Test::HasFatalFailure(); ++s) {
    const std::size_t k = rng() % t.vertices.size();
    const Point to = s % 2 ? random_point(rng) : Point(t.vertices[k].second.x() + 1e-3, t.vertices[k].second.y(),
                                                        t.vertices[k].second.z());
    std::vector<Fast_dt::Cell_handle> made;
    EXPECT_EQ(t.tr.move_if_no_collision_and_give_new_cells(t.vertices[k].first, to, std::back_inserter(made)),
              t.vertices[k].first);
    t.vertices[k].second = to;
    // The cells of the moved vertex are all new.
    std::vector<Fast_dt::Cell_handle> around;
    t.tr.incident_cells(t.vertices[k].first, std::back_inserter(around));
    std::sort(made.begin(), made.end());
    for(auto c : around) EXPECT_TRUE(std::binary_search(made.begin(), made.end(), c));
    t.check("moved");
  }
}

// Oracle of is_delaunay_after_displacement(v, p): the cells of the
// triangulation with p for v's point are those of CGAL's triangulation of the
// moved points.
bool cells_stay_delaunay(const Tracked& t, std::size_t k, const Point& to)
{
  std::vector<Point> moved = t.points();
  moved[k] = to;
  const Cgal_dt cgal(moved.begin(), moved.end());
  if(cgal.dimension() != 3 || cgal.number_of_vertices() != moved.size()) return false;
  std::vector<Cell_key> ours;
  const Point from = t.vertices[k].second;
  for(auto c = t.tr.finite_cells_begin(); c != t.tr.finite_cells_end(); ++c) {
    Cell_key key;
    for(int i = 0; i < 4; ++i) {
      const Point& q = c->vertex(i)->point();
      key[i] = point_key(q == from ? to : q);
    }
    std::sort(key.begin(), key.end());
    ours.push_back(key);
  }
  std::sort(ours.begin(), ours.end());
  return ours == finite_cell_keys(cgal);
}

// Moves of every size on random points (hull vertices included) and on a
// grid, whose ties only CGAL's perturbation decides: the answer of
// is_delaunay_after_displacement is the oracle's, and the moves that keep
// the cells (taken in place) and those that do not both give CGAL's
// triangulation.
void check_displacements(const std::vector<Point>& points, const std::vector<double>& scales, int moves,
                         std::uint64_t seed)
{
  Tracked t;
  for(const Point& p : points) t.insert(p);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  int kept = 0, changed = 0;
  for(int s = 0; s < moves && !::testing::Test::HasFatalFailure(); ++s) {
    const std::size_t k = rng() % t.vertices.size();
    const double scale = scales[rng() % scales.size()];
    const Point& from = t.vertices[k].second;
    const Point to(from.x() + scale * u(rng), from.y() + scale * u(rng), from.z() + scale * u(rng));
    const bool expected = cells_stay_delaunay(t, k, to);
    ASSERT_EQ(t.tr.is_delaunay_after_displacement(t.vertices[k].first, to), expected) << "move " << s;
    std::vector<Fast_dt::Cell_handle> around, made;
    t.tr.incident_cells(t.vertices[k].first, std::back_inserter(around));
    ASSERT_EQ(t.tr.move_if_no_collision_and_give_new_cells(t.vertices[k].first, to, std::back_inserter(made)),
              t.vertices[k].first);
    t.vertices[k].second = to;
    if(expected) {
      // In place: the very cells of v, all reported as new.
      std::sort(around.begin(), around.end());
      std::sort(made.begin(), made.end());
      EXPECT_EQ(made, around);
      ++kept;
    } else {
      ++changed;
    }
    t.check(("move " + std::to_string(s)).c_str());
  }
  EXPECT_GT(kept, moves / 10);
  EXPECT_GT(changed, moves / 10);
}

TEST(Move, InPlaceWhenTheCellsStayDelaunay)
{
  std::mt19937_64 rng(31);
  check_displacements(random_points(150, rng), {1e-9, 1e-3, 3e-2, 0.2}, 160, 32);
}

TEST(Move, InPlaceOnAGridDecidedByThePerturbation)
{
  // Moves by 0 or 1 along each axis and by tiny amounts: cospherical and
  // coplanar ties everywhere.
  std::vector<Point> points = grid(4);
  Tracked t;
  for(const Point& p : points) t.insert(p);
  std::mt19937_64 rng(33);
  int kept = 0;
  for(int s = 0; s < 120 && !::testing::Test::HasFatalFailure(); ++s) {
    const std::size_t k = rng() % t.vertices.size();
    const Point& from = t.vertices[k].second;
    const double d = s % 2 ? 1.0 : 1.0 / 1024;
    const Point to(from.x() + d * double(int(rng() % 3) - 1), from.y() + d * double(int(rng() % 3) - 1),
                   from.z());
    bool collides = false;
    for(const auto& e : t.vertices) collides = collides || (e.second == to && e.first != t.vertices[k].first);
    if(collides || to == from) continue;
    const bool expected = cells_stay_delaunay(t, k, to);
    ASSERT_EQ(t.tr.is_delaunay_after_displacement(t.vertices[k].first, to), expected) << "move " << s;
    kept += expected;
    ASSERT_EQ(t.tr.move(t.vertices[k].first, to), t.vertices[k].first);
    t.vertices[k].second = to;
    t.check(("grid move " + std::to_string(s)).c_str());
  }
  EXPECT_GT(kept, 0);
}

// The sorted point keys of a finite cell.
Cell_key key_of(Fast_dt::Cell_handle c)
{
  Cell_key key;
  for(int i = 0; i < 4; ++i) key[i] = point_key(c->vertex(i)->point());
  std::sort(key.begin(), key.end());
  return key;
}

// Short moves of interior and hull vertices: by Lawson's flips on random
// points, and on a grid, whose ties get the flips stuck (four points in a
// plane), by the flips undone and the star re-triangulated.  CGAL keeps the
// cells without v that are in the triangulation of the moved points: each
// keeps its handle, its vertices and its info; the cells reported as new
// are exactly the others of the triangulation after the move.
// step > 0: each coordinate of a move a multiple of step (more ties).
void check_cells_kept_by_moves(const std::vector<Point>& points, double scale, double step, int moves,
                               std::uint64_t seed)
{
  Tracked t;
  for(const Point& p : points) t.insert(p);
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  int info = 1, moves_with_new_cells_without_v = 0;
  for(int s = 0; s < moves && !::testing::Test::HasFatalFailure(); ++s) {
    const std::size_t k = rng() % t.vertices.size();
    const Vertex_handle v = t.vertices[k].first;
    const Point& from = t.vertices[k].second;
    auto offset = [&] { return step > 0 ? step * std::round(scale * u(rng) / step) : scale * u(rng); };
    const Point to(from.x() + offset(), from.y() + offset(), from.z() + offset());
    bool collides = to == from;
    for(const auto& e : t.vertices) collides = collides || e.second == to;
    if(collides) continue;
    std::vector<Point> moved = t.points();
    moved[k] = to;
    const Cgal_dt after(moved.begin(), moved.end());
    const std::vector<Cell_key> after_keys = finite_cell_keys(after);
    struct Kept
    {
      Fast_dt::Cell_handle c;
      Cell_key key;
      int info;
    };
    std::vector<Kept> kept;
    std::vector<Cell_key> kept_keys;
    for(auto c = t.tr.finite_cells_begin(); c != t.tr.finite_cells_end(); ++c) {
      c->info() = info++;
      const Cell_key key = key_of(c);
      if(!c->has_vertex(v) && std::binary_search(after_keys.begin(), after_keys.end(), key)) {
        kept.push_back({c, key, c->info()});
        kept_keys.push_back(key);
      }
    }
    std::vector<Fast_dt::Cell_handle> made;
    ASSERT_EQ(t.tr.move_if_no_collision_and_give_new_cells(v, to, std::back_inserter(made)), v);
    t.vertices[k].second = to;
    for(const Kept& e : kept) {
      ASSERT_TRUE(t.tr.is_cell(e.c)) << "move " << s;
      EXPECT_EQ(key_of(e.c), e.key) << "move " << s;
      EXPECT_EQ(e.c->info(), e.info) << "move " << s;
    }
    std::vector<Cell_key> made_keys, expected;
    bool without_v = false;
    for(Fast_dt::Cell_handle c : made)
      if(!t.tr.is_infinite(c)) {
        made_keys.push_back(key_of(c));
        without_v = without_v || !c->has_vertex(v);
      }
    moves_with_new_cells_without_v += without_v;
    std::sort(made_keys.begin(), made_keys.end());
    std::sort(kept_keys.begin(), kept_keys.end());
    std::set_difference(after_keys.begin(), after_keys.end(), kept_keys.begin(), kept_keys.end(),
                        std::back_inserter(expected));
    EXPECT_EQ(made_keys, expected) << "move " << s;
    t.check(("move " + std::to_string(s)).c_str());
  }
  // Flips that made cells without v (a 2-3 flip of a facet through v, or
  // cells beyond the star in conflict with the new point) were met.
  EXPECT_GT(moves_with_new_cells_without_v, moves / 10);
}

TEST(Move, ShortMovesKeepTheCellsCgalKeeps)
{
  std::mt19937_64 rng(41);
  // Mean spacing of 200 points in the unit cube: 0.17.
  check_cells_kept_by_moves(random_points(200, rng), 0.05, 0, 80, 42);
  std::vector<Point> points = grid(4);
  for(Point& p : points) p = Point(p.x() / 4, p.y() / 4, p.z() / 4);
  check_cells_kept_by_moves(points, 1.0 / 16, 1.0 / 64, 60, 43);
}

TEST(Move, IsDelaunayAfterDisplacementRefusesBadInput)
{
  Tracked t;
  std::mt19937_64 rng(34);
  for(const Point& p : random_points(20, rng)) t.insert(p);
  const Vertex_handle v = t.vertices[0].first;
  EXPECT_TRUE(t.tr.is_delaunay_after_displacement(v, v->point()));
  EXPECT_THROW(t.tr.is_delaunay_after_displacement(t.tr.infinite_vertex(), Point(0, 0, 0)), std::invalid_argument);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(t.tr.is_delaunay_after_displacement(v, Point(nan, 0, 0)), std::invalid_argument);
  Fast_dt flat;
  for(int i = 0; i < 5; ++i) flat.insert(Point(i, i * i, 0));
  EXPECT_THROW(flat.is_delaunay_after_displacement(flat.finite_vertices_begin(), Point(0, 0, 1)),
               std::invalid_argument);
}

TEST(Remove, BadInputThrowsAndChangesNothing)
{
  Tracked t;
  std::mt19937_64 rng(24);
  for(const Point& p : random_points(30, rng)) t.insert(p);
  Fast_dt other;
  const Vertex_handle foreign = other.insert(Point(0, 0, 0));
  EXPECT_THROW(t.tr.remove(t.tr.infinite_vertex()), std::invalid_argument);
  EXPECT_THROW(t.tr.remove(foreign), std::invalid_argument);
  const Vertex_handle v = t.vertices[0].first;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(t.tr.move(v, Point(nan, 0, 0)), std::invalid_argument);
  EXPECT_THROW(t.tr.move_if_no_collision(v, Point(0, std::numeric_limits<double>::infinity(), 0)),
               std::invalid_argument);
  const std::vector<Vertex_handle> twice = {t.vertices[1].first, t.vertices[2].first, t.vertices[1].first};
  EXPECT_THROW(t.tr.remove(twice.begin(), twice.end()), std::invalid_argument);
  t.check("after the bad calls");
  t.tr.remove(v);
  t.forget(0);
  EXPECT_THROW(t.tr.remove(v), std::invalid_argument);
  t.check("after removing a vertex twice");
}

// Removed vertices leave dead records: insertions after them, copies, I/O
// and equality see only the live ones.
TEST(Remove, DeadRecordsAfterwards)
{
  Tracked t;
  std::mt19937_64 rng(25);
  for(const Point& p : random_points(50, rng)) t.insert(p);
  for(int k = 0; k < 10; ++k) t.remove_at(0);
  t.insert_range(random_points(40, rng));
  t.check("bulk insertion after removals");
  const Fast_dt copy(t.tr);
  EXPECT_TRUE(copy == t.tr);
  std::stringstream file;
  file.precision(17);
  file << t.tr;
  Cgal_dt read_by_cgal;
  file >> read_by_cgal;
  ASSERT_TRUE(read_by_cgal.is_valid());
  EXPECT_TRUE(finite_cell_keys(read_by_cgal) == finite_cell_keys(t.tr));
  Cgal_dt converted;
  CGAL::convert_to_cgal(t.tr, converted);
  ASSERT_TRUE(converted.is_valid());
  EXPECT_EQ(converted.number_of_vertices(), t.tr.number_of_vertices());
  EXPECT_TRUE(finite_cell_keys(converted) == finite_cell_keys(t.tr));
}

// The partitioned engine inserts after removals (dead records among the ids
// it partitions).
TEST(Remove, ParallelInsertionAfterRemovals)
{
  Tracked t;
  t.tr.set_number_of_threads(2);
  std::mt19937_64 rng(29);
  t.insert_range(random_points(3000, rng));
  for(int k = 0; k < 300; ++k) t.remove_at(rng() % t.vertices.size());
  t.insert_range(random_points(3000, rng));
  t.check("parallel insertion after removals");
}

} // namespace test_remove_and_move
