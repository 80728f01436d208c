// The distributed triangulation under mpirun (CTest runs this program with 1, 2, 3, 4 and 8 ranks): the union of
// the owned cells over the ranks must be CGAL's triangulation of all the points, cell for cell, each cell owned
// once; bad input must be refused on every rank alike. Each test runs the same collective calls on every rank and
// decides on rank 0, which broadcasts the verdict, so that a failure never leaves a rank waiting in a collective.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Distributed_Delaunay_triangulation_3.h>

#include <gtest/gtest.h>
#include <mpi.h>

#include "../point_sets.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace test_distributed_delaunay {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Distributed_Delaunay_triangulation_3<K> Distributed;
typedef Distributed::Global_id Id;
typedef Distributed::Global_cell Global_cell;
typedef CGAL::Delaunay_triangulation_3<K> Cgal_delaunay;

int rank_of_world()
{
  int r = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &r);
  return r;
}
int ranks_of_world()
{
  int k = 1;
  MPI_Comm_size(MPI_COMM_WORLD, &k);
  return k;
}

// The same verdict on every rank: rank 0's.
bool agreed(bool verdict_on_rank_0)
{
  int v = verdict_on_rank_0 ? 1 : 0;
  MPI_Bcast(&v, 1, MPI_INT, 0, MPI_COMM_WORLD);
  return v == 1;
}

// What each rank hands over: points [first, last) of the whole set, ids = positions.
struct Share
{
  std::vector<double> xyz;
  std::vector<Id> ids;
};
Share share_of(const std::vector<fdt3_test::Xyz>& all, std::size_t first, std::size_t last)
{
  Share s;
  for(std::size_t i = first; i < last; ++i) {
    s.xyz.insert(s.xyz.end(), {all[i].x, all[i].y, all[i].z});
    s.ids.push_back(Id(i));
  }
  return s;
}
Share even_share(const std::vector<fdt3_test::Xyz>& all)
{
  const std::size_t k = std::size_t(ranks_of_world()), r = std::size_t(rank_of_world());
  return share_of(all, all.size() * r / k, all.size() * (r + 1) / k);
}

// A cell as its ids in increasing order.
Global_cell sorted(Global_cell c)
{
  std::sort(c.begin(), c.end());
  return c;
}

// CGAL's finite cells of all the points, named by the smallest id of each vertex's point.
std::vector<Global_cell> cgal_cells(const std::vector<fdt3_test::Xyz>& all)
{
  std::map<std::array<double, 3>, Id> smallest_id;
  for(std::size_t i = 0; i < all.size(); ++i) smallest_id.emplace(std::array<double, 3>{all[i].x, all[i].y, all[i].z}, Id(i));
  const std::vector<K::Point_3> points = fdt3_test::to_points<K::Point_3>(all);
  const Cgal_delaunay dt(points.begin(), points.end());
  std::vector<Global_cell> cells;
  if(dt.dimension() < 3) return cells;
  for(auto c = dt.finite_cells_begin(); c != dt.finite_cells_end(); ++c) {
    Global_cell g;
    for(int k = 0; k < 4; ++k) {
      const K::Point_3& p = c->vertex(k)->point();
      g[k] = smallest_id.at({p.x(), p.y(), p.z()});
    }
    cells.push_back(sorted(g));
  }
  std::sort(cells.begin(), cells.end());
  return cells;
}

// Every rank's cells, on rank 0 (empty elsewhere).
std::vector<Global_cell> gathered(const std::vector<Global_cell>& mine)
{
  const CGAL::Fast_Delaunay_triangulation_3_internal::distributed::Communicator comm(MPI_COMM_WORLD);
  return comm.all_gather(mine);
}

struct Check
{
  bool same_as_cgal = false;
  bool each_owned_once = false;
  bool positively_oriented = false;
  std::size_t cells = 0, expected = 0;
};

// The owned cells of all ranks against CGAL on rank 0; also checks the orientation of each with the exact predicate.
Check check_against_cgal(const Distributed& dt, const std::vector<fdt3_test::Xyz>& all)
{
  std::vector<Global_cell> mine = dt.owned_cells();
  bool oriented = true;
  for(const Global_cell& c : mine) {
    K::Point_3 p[4];
    for(int k = 0; k < 4; ++k) p[k] = K::Point_3(all[c[k]].x, all[c[k]].y, all[c[k]].z);
    oriented = oriented && CGAL::orientation(p[0], p[1], p[2], p[3]) == CGAL::POSITIVE;
  }
  for(Global_cell& c : mine) c = sorted(c);
  std::vector<Global_cell> all_cells = gathered(mine);
  int oriented_everywhere = oriented ? 1 : 0;
  MPI_Allreduce(MPI_IN_PLACE, &oriented_everywhere, 1, MPI_INT, MPI_MIN, MPI_COMM_WORLD);
  Check check;
  check.positively_oriented = oriented_everywhere == 1;
  if(rank_of_world() == 0) {
    std::sort(all_cells.begin(), all_cells.end());
    check.cells = all_cells.size();
    check.each_owned_once = std::adjacent_find(all_cells.begin(), all_cells.end()) == all_cells.end();
    const std::vector<Global_cell> expected = cgal_cells(all);
    check.expected = expected.size();
    check.same_as_cgal = all_cells == expected;
  }
  check.same_as_cgal = agreed(check.same_as_cgal);
  check.each_owned_once = agreed(check.each_owned_once);
  return check;
}

void expect_cgal_cells(const Distributed& dt, const std::vector<fdt3_test::Xyz>& all)
{
  const Check check = check_against_cgal(dt, all);
  EXPECT_TRUE(check.same_as_cgal) << check.cells << " cells owned, CGAL has " << check.expected;
  EXPECT_TRUE(check.each_owned_once);
  EXPECT_TRUE(check.positively_oriented);
  EXPECT_EQ(dt.dimension(), 3);
}

std::vector<fdt3_test::Xyz> points_of(const std::string& distribution, std::size_t n)
{
  return fdt3_test::make_points(distribution, n, 11);
}

// Each rank handed an equal run of the points of a distribution.
void expect_cgal_cells_of(const std::string& distribution, std::size_t n)
{
  const auto all = points_of(distribution, n);
  const Share s = even_share(all);
  const Distributed dt(MPI_COMM_WORLD, s.xyz, s.ids);
  expect_cgal_cells(dt, all);
}

TEST(DistributedDelaunay, UniformPointsGiveCgalsCells) { expect_cgal_cells_of("uniform", 3000); }
TEST(DistributedDelaunay, ClusteredPointsGiveCgalsCells) { expect_cgal_cells_of("clusters", 3000); }
// A shuffled integer grid: many cospherical and coplanar points, decided by the symbolic perturbation on every rank.
TEST(DistributedDelaunay, GridPointsGiveCgalsCells) { expect_cgal_cells_of("grid", 1000); }
// Every point on the hull: the hull round sends them all to every rank.
TEST(DistributedDelaunay, PointsOnASphereGiveCgalsCells) { expect_cgal_cells_of("sphere", 800); }
// Far from the origin: the balls' bounds in doubles lose most of their bits to the offset.
TEST(DistributedDelaunay, OffsetPointsGiveCgalsCells) { expect_cgal_cells_of("offset", 2000); }

// The same points whatever the ranks were handed: each rank's share taken from the whole set by stride.
TEST(DistributedDelaunay, InterleavedSharesGiveCgalsCells)
{
  const auto all = points_of("gauss", 2000);
  Share s;
  for(std::size_t i = std::size_t(rank_of_world()); i < all.size(); i += std::size_t(ranks_of_world())) {
    s.xyz.insert(s.xyz.end(), {all[i].x, all[i].y, all[i].z});
    s.ids.push_back(Id(i));
  }
  const Distributed dt(MPI_COMM_WORLD, s.xyz, s.ids);
  expect_cgal_cells(dt, all);
}

TEST(DistributedDelaunay, GhostLayerCellsAreCgalCellsOfOtherRanks)
{
  const auto all = points_of("uniform", 2000);
  const Share s = even_share(all);
  const Distributed dt(MPI_COMM_WORLD, s.xyz, s.ids);
  std::vector<Global_cell> layer;
  for(auto c = dt.local_triangulation().finite_cells_begin(); c != dt.local_triangulation().finite_cells_end(); ++c)
    if(dt.is_ghost_layer(c)) layer.push_back(sorted(dt.global_cell(c)));
  const std::size_t layer_size = layer.size();
  const std::vector<Global_cell> all_layers = gathered(layer);
  bool all_cgal = true;
  if(rank_of_world() == 0) {
    const std::vector<Global_cell> expected = cgal_cells(all);
    for(const Global_cell& c : all_layers) all_cgal = all_cgal && std::binary_search(expected.begin(), expected.end(), c);
  }
  EXPECT_TRUE(agreed(all_cgal));
  if(ranks_of_world() == 1) {
    EXPECT_EQ(layer_size, 0u);
  }
}

// All the points handed to rank 0; the partition spreads them.
TEST(DistributedDelaunay, AllPointsHandedToOneRank)
{
  const auto all = points_of("uniform", 1500);
  const Share s = rank_of_world() == 0 ? share_of(all, 0, all.size()) : Share();
  const Distributed dt(MPI_COMM_WORLD, s.xyz, s.ids);
  expect_cgal_cells(dt, all);
  if(ranks_of_world() > 1) {
    EXPECT_GT(dt.statistics().own_points, 0u);
  }
}

// A rank handed nothing, and more ranks than points: ranks that own no point take part in every round.
TEST(DistributedDelaunay, RanksWithoutPoints)
{
  const auto all = points_of("uniform", 900);
  const Share s = rank_of_world() == 1 ? Share() : even_share(all);
  // The points handed over, in rank order, and named by their place there (rank 1's share is left out).
  const CGAL::Fast_Delaunay_triangulation_3_internal::distributed::Communicator comm(MPI_COMM_WORLD);
  std::vector<fdt3_test::Xyz> given;
  for(Id i : comm.all_gather(s.ids)) given.push_back(all[i]);
  const Distributed dt(MPI_COMM_WORLD, s.xyz);
  expect_cgal_cells(dt, given);

  const auto few = points_of("uniform", 6);
  const Share tiny = rank_of_world() == 0 ? share_of(few, 0, few.size()) : Share();
  const Distributed small(MPI_COMM_WORLD, tiny.xyz, tiny.ids);
  expect_cgal_cells(small, few);
}

// Equal points handed to different ranks: stored once, under the smallest id, listed by the rank storing them.
TEST(DistributedDelaunay, DuplicatesAcrossRanksAreStoredOnce)
{
  auto all = points_of("uniform", 1200);
  const std::size_t distinct = all.size();
  for(std::size_t i = 0; i < distinct; i += 7) all.push_back(all[i]);       // copies at the end (other ranks)
  for(std::size_t i = 0; i < distinct; i += 31) all.push_back(all[i + 3]);  // and again
  const Share s = even_share(all);
  const Distributed dt(MPI_COMM_WORLD, s.xyz, s.ids);
  expect_cgal_cells(dt, all);

  std::vector<std::array<Id, 2>> mine;
  for(const Distributed::Duplicate& d : dt.duplicates()) mine.push_back({d.id, d.stored_as});
  const CGAL::Fast_Delaunay_triangulation_3_internal::distributed::Communicator comm(MPI_COMM_WORLD);
  std::vector<std::array<Id, 2>> listed = comm.all_gather(mine);
  const std::uint64_t stored = comm.sum(dt.statistics().own_points);
  bool right = true;
  if(rank_of_world() == 0) {
    std::vector<std::array<Id, 2>> expected;
    for(std::size_t i = distinct; i < all.size(); ++i) {
      std::size_t first = 0;
      while(all[first].x != all[i].x || all[first].y != all[i].y || all[first].z != all[i].z) ++first;
      expected.push_back({Id(i), Id(first)});
    }
    std::sort(expected.begin(), expected.end());
    std::sort(listed.begin(), listed.end());
    right = listed == expected && stored == distinct;
  }
  EXPECT_TRUE(agreed(right));
}

// Below dimension 3 there is no tetrahedron to own; every rank agrees on the dimension.
TEST(DistributedDelaunay, CoplanarAndEmptyInputs)
{
  std::vector<fdt3_test::Xyz> plane;
  for(const fdt3_test::Xyz& p : points_of("uniform", 500)) plane.push_back({p.x, p.y, 0.25});
  const Share s = even_share(plane);
  const Distributed flat(MPI_COMM_WORLD, s.xyz, s.ids);
  EXPECT_EQ(flat.dimension(), 2);
  EXPECT_TRUE(flat.owned_cells().empty());

  const Distributed none(MPI_COMM_WORLD, std::vector<double>(), std::vector<Id>());
  EXPECT_EQ(none.dimension(), -1);
  EXPECT_TRUE(none.owned_cells().empty());
}

// A NaN on the last rank: every rank throws the same error, naming the point and its rank, and nobody hangs.
TEST(DistributedDelaunay, NotANumberOnOneRankIsRefusedEverywhere)
{
  const auto all = points_of("uniform", 400);
  Share s = even_share(all);
  const int last = ranks_of_world() - 1;
  if(rank_of_world() == last) {
    s.xyz.insert(s.xyz.end(), {0.5, std::numeric_limits<double>::quiet_NaN(), 0.5});
    s.ids.push_back(Id(all.size()));
  }
  std::string message;
  try {
    const Distributed dt(MPI_COMM_WORLD, s.xyz, s.ids);
  } catch(const CGAL::Distributed_input_error& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("point " + std::to_string(all.size()) + " (on rank " + std::to_string(last) + ")"),
            std::string::npos)
      << message;
  const CGAL::Fast_Delaunay_triangulation_3_internal::distributed::Communicator comm(MPI_COMM_WORLD);
  EXPECT_EQ(comm.broadcast(message, 0), message);

  // Coordinates and ids that do not match: refused the same way.
  Share bad = even_share(all);
  if(rank_of_world() == 0) bad.xyz.pop_back();
  std::string mismatch;
  try {
    const Distributed dt(MPI_COMM_WORLD, bad.xyz, bad.ids);
  } catch(const CGAL::Distributed_input_error& e) {
    mismatch = e.what();
  }
  EXPECT_NE(mismatch.find("rank 0 has"), std::string::npos) << mismatch;
}

TEST(DistributedDelaunay, StatisticsAddUp)
{
  const auto all = points_of("uniform", 3000);
  const Share s = even_share(all);
  const Distributed dt(MPI_COMM_WORLD, s.xyz, s.ids);
  const CGAL::Distributed_delaunay_statistics& st = dt.statistics();
  const CGAL::Fast_Delaunay_triangulation_3_internal::distributed::Communicator comm(MPI_COMM_WORLD);
  EXPECT_EQ(comm.sum(st.input_points), all.size());
  EXPECT_EQ(comm.sum(st.own_points), all.size());
  EXPECT_EQ(comm.sum(st.owned_cells), comm.sum(dt.owned_cells().size()));
  EXPECT_EQ(comm.max(std::uint64_t(st.exchange_rounds)), comm.min(std::uint64_t(st.exchange_rounds)));
  EXPECT_EQ(dt.local_triangulation().number_of_vertices(), st.own_points + st.ghost_points);
  if(ranks_of_world() == 1) {
    EXPECT_EQ(st.ghost_points, 0u);
  }
}

} // namespace test_distributed_delaunay

// On the ranks other than 0, which print no progress: each failed assertion, with the rank.
class Failure_printer : public ::testing::EmptyTestEventListener
{
  void OnTestPartResult(const ::testing::TestPartResult& result) override
  {
    if(result.failed())
      std::fprintf(stderr, "[rank %d] %s:%d: %s\n", test_distributed_delaunay::rank_of_world(),
                   result.file_name() ? result.file_name() : "?", result.line_number(), result.summary());
  }
};

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  if(test_distributed_delaunay::rank_of_world() != 0) {
    ::testing::TestEventListeners& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new Failure_printer);
  }
  const int result = RUN_ALL_TESTS();
  MPI_Finalize();
  return result;
}
