// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Delaunay-refinement tetrahedral mesher of the paper's §4 (Algorithm 2):
// closed triangulated surfaces in, a tetrahedral mesh of the volumes they
// bound out, with the surface triangles as its boundary, exactly.
//
//   EMPTYMESH        Delaunay of the surface vertices (this package's engine)
//   RECOVERBOUNDARY  kept as is when no input triangle is missing, else TetGen
//                    on the region the missing triangles cross (the whole
//                    surface if that fails; needs -ltet and TETLIBRARY; CMake
//                    target Fast_Delaunay_triangulation_3::TetGen here)
//   colouring        one subdomain per volume, the outside dropped
//   refinement       circumcentres of tetrahedra with radius > 1.4 h, filtered
//                    at 0.7 h, inserted by batches with constrained,
//                    star-shaped cavities, each batch by the partitioned
//                    parallel engine of §3
//
//   #include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>
//   CGAL::Fast_mesher_3::Tetrahedral_mesh mesh =
//       CGAL::Fast_mesher_3::mesh_surface_files({"part.off"}, options);
//   CGAL::Fast_mesher_3::write_mesh("part.mesh", mesh);
//
// Also as CGAL's Mesh_complex_3_in_triangulation_3: mesh_surfaces_to_c3t3.
//
// Not yet (issue 5): no user size function; no mesh improvement (slivers
// stay); surfaces may not touch.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_TETRAHEDRAL_MESHER_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_TETRAHEDRAL_MESHER_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Boundary_recovery.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/C3t3_conversion.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Mesh_improvement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Mesh_writers.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Quality_report.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Refinement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Sizing.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedral_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Unit_scaling.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Volume_colouring.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <functional>
#include <limits>
#include <ostream>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_mesher_3 {

typedef Fast_Delaunay_triangulation_3_internal::mesher::Invalid_surface Invalid_surface;

struct Mesher_options
{
  // Global maximum of h; the default size is the surface's, interpolated.
  double maximum_size = std::numeric_limits<double>::infinity();
  // Moore partitions (one per thread) of the empty mesh and of every
  // refinement batch; 1 is sequential.  The mesh depends on this number
  // only, not on the threads that run the partitions: the same input and
  // `threads` give the same mesh, bit for bit.
  int threads = 1;
  // A refinement batch with fewer points per partition halves its
  // partitions (the paper's 3000, §3.4); lower only to exercise the
  // partitions on small inputs.
  std::size_t min_points_per_thread =
      Fast_Delaunay_triangulation_3_internal::Partitioned_insertion::default_min_points_per_partition;
  double radius_ratio = 1.4;
  double min_edge_ratio = 0.7;
  int max_refinement_passes = 200;
  // Mesh improvement after refinement (Mesh_improvement.h): edge and face
  // removals and vertex relocation on every tetrahedron whose gamma =
  // 3 r_in / r_circ is under quality_threshold (Gmsh's default target),
  // with the same partitions as refinement.  Off: the refined Delaunay mesh.
  bool optimize = true;
  double quality_threshold = 0.3;
  int max_improvement_passes = 10;
  // Called after each refinement pass with (pass number, points inserted,
  // tetrahedra in the volumes); the library itself prints nothing.
  std::function<void(int, std::size_t, std::size_t)> progress;
};

// Seconds and counts of the phases, in the paper's Figure 12 split.
struct Mesher_statistics
{
  double input_seconds = 0, empty_mesh_seconds = 0, recovery_seconds = 0, colouring_seconds = 0,
         refinement_seconds = 0, improvement_seconds = 0, total_seconds = 0;
  std::size_t missing_triangles = 0; // input triangles absent from the empty mesh
  bool used_tetgen = false;
  std::size_t recovery_region_tetrahedra = 0; // empty-mesh tetrahedra re-meshed by the local recovery
  std::size_t flipped_components = 0;          // parts of that region recovered by our flips
  std::size_t tetgen_components = 0;           // and by TetGen
  bool whole_surface_to_tetgen = false;        // the local recovery failed, TetGen took everything
  std::size_t steiner_points = 0;    // added by the recovery, inside the volumes
  int refinement_passes = 0;
  // Parts of refinement_seconds: SAMPLEPOINTS, FILTERPOINTS (sequential) and
  // INSERTPOINTS (the partitioned engine).
  double sample_seconds = 0, filter_seconds = 0, insert_seconds = 0;
  std::size_t refinement_points = 0, filtered_points = 0, aborted_points = 0;
  // Refinement points inserted or dropped by attempts with several
  // partitions, and the number of such attempts (the rest is sequential).
  std::size_t points_settled_in_partitions = 0;
  std::size_t partitioned_attempts = 0;
  // What the improvement did; all zero when options.optimize is off.
  Fast_Delaunay_triangulation_3_internal::mesher::Improvement_statistics improvement;
};

namespace mesher_detail {

using namespace Fast_Delaunay_triangulation_3_internal::mesher;

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// `on_mesh(cm)` sees the final constrained mesh before it is extracted.
// `soup` is at the unit scale of `scaling` (Unit_scaling.h); the mesh
// handed on and returned is at the input's.
template <class On_mesh>
Tetrahedral_mesh mesh_soup(const Surface_soup& soup, const Unit_scaling& scaling, const Mesher_options& options,
                           Mesher_statistics& stats, On_mesh on_mesh)
{
  typedef std::chrono::steady_clock Clock;
  Clock::time_point t0 = Clock::now();
  Constrained_mesh cm;
  const Recovery_report recovery = empty_mesh_and_recovery(soup, options.threads, cm);
  stats.empty_mesh_seconds = recovery.empty_mesh_seconds;
  stats.recovery_seconds = recovery.recovery_seconds;
  stats.missing_triangles = recovery.missing_triangles;
  stats.used_tetgen = recovery.used_tetgen;
  stats.recovery_region_tetrahedra = recovery.region_tetrahedra;
  stats.flipped_components = recovery.flipped_components;
  stats.tetgen_components = recovery.tetgen_components;
  stats.whole_surface_to_tetgen = recovery.whole_surface_to_tetgen;
  stats.steiner_points = recovery.steiner_points;

  Clock::time_point t1 = Clock::now();
  flag_constrained_facets(soup, cm);
  colour_volumes(cm);
  surface_sizes(soup, scaling.to_unit(options.maximum_size), cm);
  stats.colouring_seconds = seconds_since(t1);

  t1 = Clock::now();
  Refinement_options refinement;
  refinement.radius_ratio = options.radius_ratio;
  refinement.min_edge_ratio = options.min_edge_ratio;
  refinement.max_passes = options.max_refinement_passes;
  refinement.threads = std::max(1, options.threads);
  refinement.min_points_per_thread = options.min_points_per_thread;
  Constrained_refinement refine(cm, refinement);
  const std::vector<Refinement_pass> passes = refine.run([&](const Refinement_pass& pass, int k) {
    if(options.progress) options.progress(k, pass.inserted, pass.tetrahedra);
  });
  stats.refinement_passes = static_cast<int>(passes.size());
  for(const Refinement_pass& pass : passes) {
    stats.refinement_points += pass.inserted;
    stats.filtered_points += pass.filtered_out;
    stats.aborted_points += pass.aborted;
    stats.sample_seconds += pass.sample_seconds;
    stats.filter_seconds += pass.filter_seconds;
    stats.insert_seconds += pass.insert_seconds;
    stats.points_settled_in_partitions += pass.settled_in_partitions;
    for(const auto& attempt : pass.attempts) stats.partitioned_attempts += attempt.partitions > 1 ? 1 : 0;
  }
  stats.refinement_seconds = seconds_since(t1);
  if(options.optimize) {
    Improvement_options improvement;
    improvement.quality_threshold = options.quality_threshold;
    improvement.max_passes = options.max_improvement_passes;
    improvement.threads = std::max(1, options.threads);
    stats.improvement = improve_mesh(cm, improvement);
    stats.improvement_seconds = stats.improvement.seconds;
  }
  scaling.unscale(cm);
  on_mesh(static_cast<const Constrained_mesh&>(cm));
  Tetrahedral_mesh mesh = extract_mesh(cm, soup);
  stats.total_seconds = seconds_since(t0);
  return mesh;
}

// Reads and checks the input with `read_soup`, then meshes it.
template <class Read_soup, class On_mesh>
Tetrahedral_mesh read_and_mesh(Read_soup read_soup, const Mesher_options& options, Mesher_statistics* statistics,
                               On_mesh on_mesh)
{
  const auto t0 = std::chrono::steady_clock::now();
  Surface_soup soup = read_soup();
  const Unit_scaling scaling(soup);
  scaling.scale(soup);
  Mesher_statistics stats;
  stats.input_seconds = seconds_since(t0);
  Tetrahedral_mesh mesh = mesh_soup(soup, scaling, options, stats, [&](const Constrained_mesh& cm) {
    on_mesh(cm, soup);
  });
  if(statistics) *statistics = stats;
  return mesh;
}

} // namespace mesher_detail

// Meshes the volumes bounded by the surfaces of the files (any format
// CGAL::IO::read_polygon_soup reads).  Throws Invalid_surface, naming the
// problem and the triangles, for an input that is not a set of closed,
// oriented, manifold, non-intersecting triangulated surfaces.
inline Tetrahedral_mesh mesh_surface_files(const std::vector<std::string>& paths,
                                           const Mesher_options& options = Mesher_options(),
                                           Mesher_statistics* statistics = nullptr)
{
  return mesher_detail::read_and_mesh([&] { return mesher_detail::read_surfaces(paths); }, options, statistics,
                                      [](const auto&, const auto&) {});
}

// The same for triangles in memory (indices into `points`).
inline Tetrahedral_mesh mesh_surfaces(const std::vector<std::array<double, 3>>& points,
                                      const std::vector<std::array<std::size_t, 3>>& triangles,
                                      const Mesher_options& options = Mesher_options(),
                                      Mesher_statistics* statistics = nullptr)
{
  return mesher_detail::read_and_mesh([&] { return mesher_detail::surfaces_from_triangles(points, triangles); },
                                      options, statistics, [](const auto&, const auto&) {});
}

// The same, and the mesh also as CGAL's Mesh_complex_3_in_triangulation_3
// (convert_to_cgal.h's approach: cells created directly, the convex hull
// included; tetrahedra of subdomain s in the complex with index s, input
// triangles as surface facets with their surface number, or the pair of
// subdomains when the patch index type is a pair).  The mesh is not
// Delaunay: use a triangulation type that does not require it, such as
// Tetrahedral_remeshing::Remeshing_triangulation_3.
template <class C3t3>
Tetrahedral_mesh mesh_surface_files_to_c3t3(const std::vector<std::string>& paths, C3t3& c3t3,
                                            const Mesher_options& options = Mesher_options(),
                                            Mesher_statistics* statistics = nullptr)
{
  return mesher_detail::read_and_mesh([&] { return mesher_detail::read_surfaces(paths); }, options, statistics,
                                      [&](const auto& cm, const auto& soup) {
                                        mesher_detail::constrained_mesh_to_c3t3(cm, soup, c3t3);
                                      });
}

template <class C3t3>
Tetrahedral_mesh mesh_surfaces_to_c3t3(const std::vector<std::array<double, 3>>& points,
                                       const std::vector<std::array<std::size_t, 3>>& triangles, C3t3& c3t3,
                                       const Mesher_options& options = Mesher_options(),
                                       Mesher_statistics* statistics = nullptr)
{
  return mesher_detail::read_and_mesh([&] { return mesher_detail::surfaces_from_triangles(points, triangles); },
                                      options, statistics, [&](const auto& cm, const auto& soup) {
                                        mesher_detail::constrained_mesh_to_c3t3(cm, soup, c3t3);
                                      });
}

// Writes .mesh (Medit), .vtu (VTK, raw binary appended) or .msh (Gmsh 4.1, ASCII), by extension.
inline void write_mesh(const std::string& path, const Tetrahedral_mesh& mesh)
{
  Fast_Delaunay_triangulation_3_internal::mesher::write_mesh_file(path, mesh);
}

inline Quality_report quality_report(const Tetrahedral_mesh& mesh)
{
  return Fast_Delaunay_triangulation_3_internal::mesher::quality_report(mesh);
}

inline void print_quality_report(std::ostream& out, const Quality_report& report)
{
  Fast_Delaunay_triangulation_3_internal::mesher::print_quality_report(out, report);
}

} // namespace Fast_mesher_3
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_TETRAHEDRAL_MESHER_H
