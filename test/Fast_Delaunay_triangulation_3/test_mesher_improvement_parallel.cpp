// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh improvement in Moore partitions (mesher/Mesh_improvement.h), 2 to 4
// of them, on random Delaunay meshes small enough for ThreadSanitizer (this
// file is in the parallel test program): the same invariants as the
// sequential improvement, operations actually done inside partitions and
// some deferred across their cuts, about the sequential result's quality,
// and the same mesh bit for bit for the same number of partitions.

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Mesh_improvement.h>

#include <gtest/gtest.h>

#include "improvement_cases.h"

#include <cstring>
#include <vector>

namespace test_mesher_improvement_parallel {

using namespace improvement_cases;
namespace fdt = CGAL::Fast_Delaunay_triangulation_3_internal;

mi::Improvement_options partitioned(int threads)
{
  mi::Improvement_options options;
  options.threads = threads;
  options.min_bad_per_partition = 16; // the inputs are small
  return options;
}

// Slot for slot (a free slot's record past its mark is never read, so it is
// not compared), vertex for vertex, and the same free list.
bool same_storage(const fdt::Flat_storage& a, const fdt::Flat_storage& b)
{
  if(a.tets.size() != b.tets.size() || a.vertices.size() != b.vertices.size() || a.free_tets != b.free_tets)
    return false;
  for(Tet_id t = 0; t < a.tets.size(); ++t) {
    if(a.is_live(t) != b.is_live(t)) return false;
    if(a.is_live(t) && std::memcmp(&a.tets[t], &b.tets[t], sizeof(fdt::Tet_record)) != 0) return false;
  }
  return std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(fdt::Vertex_record)) == 0;
}

TEST(ImprovementInPartitions, InvariantsQualityAndReproducibility)
{
  mi::Constrained_mesh original = random_cube_mesh(15, 5, true);
  mi::Constrained_mesh sequential = original;
  const mi::Improvement_statistics alone = mi::improve_mesh(sequential, mi::Improvement_options());
  for(int threads = 2; threads <= 4; ++threads) {
    SCOPED_TRACE(std::to_string(threads) + " partitions");
    mi::Constrained_mesh cm = original;
    const Invariants before = invariants(cm);
    const mi::Improvement_statistics stats = mi::improve_mesh(cm, partitioned(threads));
    expect_valid(cm);
    expect_same_invariants(before, invariants(cm));
    EXPECT_GT(stats.operations_in_partitions, 0u);
    EXPECT_GT(stats.deferred, 0u);
    EXPECT_GE(stats.min_gamma_after, stats.min_gamma_before);
    EXPECT_LE(stats.bad_after, alone.bad_after + alone.bad_before / 20);

    mi::Constrained_mesh again = original;
    mi::improve_mesh(again, partitioned(threads));
    EXPECT_TRUE(same_storage(cm.mesh, again.mesh));
    EXPECT_TRUE(cm.subdomain == again.subdomain);
    EXPECT_TRUE(cm.constrained == again.constrained);
  }
}

// With a dihedral target, in partitions: the statistics after the passes
// (from the slots each pass reshaped, and the first scan's figures for the
// others) are those of a full recount, and the mesh is reproducible.
TEST(ImprovementInPartitions, DihedralTargetStatisticsMatchARecount)
{
  const mi::Constrained_mesh original = random_cube_mesh(15, 6, true);
  for(int threads = 1; threads <= 3; ++threads) {
    SCOPED_TRACE(std::to_string(threads) + " partitions");
    mi::Improvement_options options = partitioned(threads);
    options.min_dihedral_target = 15;
    mi::Constrained_mesh cm = original;
    const Invariants before = invariants(cm);
    const mi::Improvement_statistics stats = mi::improve_mesh(cm, options);
    expect_valid(cm);
    expect_same_invariants(before, invariants(cm));
    EXPECT_GT(stats.relocations + stats.edge_removals, 0u);
    EXPECT_EQ(stats.bad_before, count_below(original, options.quality_threshold));
    EXPECT_EQ(stats.bad_after, count_below(cm, options.quality_threshold));
    EXPECT_SAME_GAMMA(stats.min_gamma_after, worst_gamma(cm));
    EXPECT_NEAR(stats.min_dihedral_after, smallest_dihedral_degrees(cm), 1e-9);
    EXPECT_GT(stats.min_dihedral_after, stats.min_dihedral_before);
    mi::Constrained_mesh again = original;
    mi::improve_mesh(again, options);
    EXPECT_TRUE(same_storage(cm.mesh, again.mesh));
  }
}

} // namespace test_mesher_improvement_parallel
