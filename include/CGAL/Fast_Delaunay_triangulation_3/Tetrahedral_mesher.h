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
//   improvement      edge and face removals, vertex relocation, then interior
//                    Steiner points, on tetrahedra under a gamma threshold,
//                    in the same partitions (Mesh_improvement.h); also on a
//                    mesh of your own: improve_mesh
//
// Also as CGAL's Mesh_complex_3_in_triangulation_3: mesh_surfaces_to_c3t3.
// Surfaces coarser than the size: remesh them first (Surface_remeshing.h).
//
// Sizes: maximum_size, subdomain_sizes, size_function, or a size-field
// file (read_size_field).  Not yet: surfaces may not touch.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_TETRAHEDRAL_MESHER_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_TETRAHEDRAL_MESHER_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Boundary_recovery.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/C3t3_conversion.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Mesh_improvement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Mesh_writers.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Quality_report.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Refinement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Size_field_file.h>
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
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_mesher_3 {

typedef Fast_Delaunay_triangulation_3_internal::mesher::Invalid_surface Invalid_surface;
typedef Fast_Delaunay_triangulation_3_internal::mesher::Improvement_statistics Improvement_statistics;

struct Mesher_options
{
  // Global maximum of h; the default size is the surface's, interpolated.
  double maximum_size = std::numeric_limits<double>::infinity();
  // The user's size, h(x, y, z) in the input's coordinates: where it is
  // smaller than the surface's, it is the size (refinement and the
  // improvement's Steiner points follow it; the surface itself is never
  // split, so near a coarse surface the tetrahedra stay coarse).  Called
  // from several threads at once; it must return a positive finite size
  // (else the mesher throws std::invalid_argument, or rethrows what it
  // threw).  read_size_field() makes one from a file.
  std::function<double(double, double, double)> size_function;
  // subdomain_sizes[s - 1]: the largest h in subdomain s (numbered as in
  // Tetrahedral_mesh::subdomain); 0 or absent: no cap there.
  std::vector<double> subdomain_sizes;
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
  // removals, vertex relocation and, where nothing else helps, interior
  // Steiner points, on every tetrahedron whose gamma = 3 r_in / r_circ is
  // under quality_threshold (Gmsh's default target) or whose smallest
  // dihedral angle is under min_dihedral_target, with the same partitions
  // as refinement.  Off: the refined Delaunay mesh.
  bool optimize = true;
  double quality_threshold = 0.3;
  // Degrees: a tetrahedron whose smallest dihedral angle is under this is
  // improved too, as if its gamma were under quality_threshold; 0 for
  // gamma alone.
  double min_dihedral_target = 15;
  int max_improvement_passes = 10;
  bool improvement_adds_points = true; // off: the improvement keeps the refined mesh's points
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
  std::size_t tetgen_components = 0;           // and by TetGen (both 0 when TetGen took everything)
  bool whole_surface_to_tetgen = false;        // the local recovery failed, TetGen took everything
  std::size_t steiner_points = 0;    // added by the recovery, inside the volumes
  // Input triangles whose circumradius is over radius_ratio times the size
  // next to them (the corners' h, with a subdomain's cap on its side).  The
  // surface is never split, so the tetrahedra on these stay over the size
  // and those between them and the smaller ones inside come out flat, which
  // the improvement cannot mend: such a surface wants remeshing to the size
  // first (remesh_surfaces, Surface_remeshing.h).
  std::size_t triangles_over_size = 0;
  int refinement_passes = 0;
  // Parts of refinement_seconds: SAMPLEPOINTS, FILTERPOINTS (one run per
  // thread) and INSERTPOINTS (the partitioned engine).
  double sample_seconds = 0, filter_seconds = 0, insert_seconds = 0;
  std::size_t refinement_points = 0, filtered_points = 0, aborted_points = 0;
  // Refinement points inserted or dropped by attempts with several
  // partitions, and the number of such attempts (the rest is sequential).
  std::size_t points_settled_in_partitions = 0;
  std::size_t partitioned_attempts = 0;
  // What the improvement did; all zero when options.optimize is off.
  Fast_Delaunay_triangulation_3_internal::mesher::Improvement_statistics improvement;
  // mesh_remeshed_surfaces (Surface_remeshing.h); all zero otherwise: the
  // seconds of the remeshings (with the checks of their output), the
  // attempts, the edge length and triangles of the one kept, and the
  // seconds spent meshing the others or failing (total_seconds counts both;
  // input_seconds is then the reading and checking of the input).
  double remeshing_seconds = 0, discarded_meshing_seconds = 0, remeshed_edge_length = 0;
  unsigned int remeshing_attempts = 0;
  std::size_t remeshed_triangles = 0;
};

namespace mesher_detail {

using namespace Fast_Delaunay_triangulation_3_internal::mesher;

inline double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

// The improvement's options from the mesher's.  Throws
// std::invalid_argument, prefixed with `caller`, for a target out of range;
// called before anything is read or changed.
inline Improvement_options improvement_options_of(const Mesher_options& options, const std::string& caller)
{
  if(!(options.quality_threshold > 0 && options.quality_threshold <= 1))
    throw std::invalid_argument(caller + ": quality_threshold must be in (0, 1]");
  // The regular tetrahedron's dihedral angles, 70.53 degrees, are the
  // largest smallest angle a tetrahedron can have.
  if(!(options.min_dihedral_target >= 0 && options.min_dihedral_target <= 70))
    throw std::invalid_argument(caller + ": min_dihedral_target must be in [0, 70] degrees");
  Improvement_options improvement;
  improvement.quality_threshold = options.quality_threshold;
  improvement.min_dihedral_target = options.min_dihedral_target;
  improvement.max_passes = options.max_improvement_passes;
  improvement.add_steiner_points = options.improvement_adds_points;
  improvement.threads = std::max(1, options.threads);
  return improvement;
}

// Throws std::invalid_argument for a bound of h out of range.
inline void check_size_bounds(const Mesher_options& options)
{
  if(!(options.maximum_size > 0)) throw std::invalid_argument("Tetrahedral_mesher: maximum_size must be positive");
  for(std::size_t s = 0; s < options.subdomain_sizes.size(); ++s) {
    const double h = options.subdomain_sizes[s];
    if(!(h >= 0) || std::isinf(h))
      throw std::invalid_argument("Tetrahedral_mesher: subdomain_sizes[" + std::to_string(s) +
                                  "] (subdomain " + std::to_string(s + 1) + ") must be a finite size, or 0 for none");
  }
}

// What can be refused of the options before anything is read or meshed:
// the bounds of h and, when the mesh is improved, the improvement's targets
// (a bad size would otherwise be found only once the boundary is recovered,
// after every remeshing of the surface).
inline void check_mesher_options(const Mesher_options& options)
{
  check_size_bounds(options);
  if(options.optimize) improvement_options_of(options, "Tetrahedral_mesher");
}

// The user's bounds of h, at the unit scale of `scaling`.
inline void set_size_bounds(const Mesher_options& options, const Unit_scaling& scaling, Size_field& field)
{
  check_size_bounds(options);
  field.set_cap(scaling.to_unit(options.maximum_size));
  std::vector<double> caps(options.subdomain_sizes.size() + 1, 0.0);
  for(std::size_t s = 0; s < options.subdomain_sizes.size(); ++s)
    caps[s + 1] = scaling.to_unit(options.subdomain_sizes[s]);
  field.set_subdomain_caps(std::move(caps));
  if(options.size_function) {
    const std::function<double(double, double, double)> h = options.size_function;
    field.set_function([h, scaling](const double* p) {
      const double x = scaling.from_unit(p[0]), y = scaling.from_unit(p[1]), z = scaling.from_unit(p[2]);
      const double value = h(x, y, z);
      if(!(value > 0) || std::isinf(value)) {
        std::ostringstream s;
        s << "Tetrahedral_mesher: size_function(" << x << ", " << y << ", " << z << ") returned " << value
          << ", not a positive finite size";
        throw std::invalid_argument(s.str());
      }
      return scaling.to_unit(value);
    });
  }
}

// What the refinement starts from, after the boundary recovery: the
// constrained facets flagged, the volumes coloured, the sizes set (the
// user's bounds, then the surface's).  Throws the user's size error.
inline void colour_and_size(const Surface_soup& soup, const Unit_scaling& scaling, const Mesher_options& options,
                            Constrained_mesh& cm)
{
  flag_constrained_facets(soup, cm, std::max(1, options.threads));
  colour_volumes(cm);
  set_size_bounds(options, scaling, cm.size);
  surface_sizes(soup, cm);
  cm.size.rethrow_user_error();
}

inline Refinement_options refinement_options(const Mesher_options& options)
{
  Refinement_options refinement;
  refinement.radius_ratio = options.radius_ratio;
  refinement.min_edge_ratio = options.min_edge_ratio;
  refinement.max_passes = options.max_refinement_passes;
  refinement.threads = std::max(1, options.threads);
  refinement.min_points_per_thread = options.min_points_per_thread;
  return refinement;
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
  colour_and_size(soup, scaling, options, cm);
  stats.triangles_over_size = triangles_over_size(cm, options.radius_ratio);
  stats.colouring_seconds = seconds_since(t1);

  t1 = Clock::now();
  Constrained_refinement refine(cm, refinement_options(options));
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
  cm.size.rethrow_user_error();
  if(options.optimize) {
    stats.improvement = improve_mesh(cm, improvement_options_of(options, "Tetrahedral_mesher"));
    stats.improvement_seconds = stats.improvement.seconds;
    cm.size.rethrow_user_error();
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
  check_mesher_options(options);
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

namespace mesher_detail {

using namespace Fast_Delaunay_triangulation_3_internal;

inline void refuse_mesh(const std::string& what) { throw std::invalid_argument("improve_mesh: " + what); }

// `mesh` checked and as a constrained mesh at the unit scale of `scaling`:
// its tetrahedra positive (exact), no facet in three of them, every
// boundary edge in two boundary facets, its triangles facets of the mesh.
// Constrained: its triangles, the boundary, and every facet between two
// subdomains.  Vertex ids are the mesh's point indices.
inline Constrained_mesh constrained_mesh_of(const Tetrahedral_mesh& mesh, const Unit_scaling& scaling)
{
  const std::size_t n = mesh.points.size();
  if(mesh.tetrahedra.empty()) refuse_mesh("the mesh has no tetrahedra");
  const std::string defect = index_defect(mesh);
  if(!defect.empty()) refuse_mesh(defect);
  if(n >= std::size_t(ghost_vertex)) refuse_mesh("too many points");
  std::vector<std::array<double, 3>> points(n);
  for(std::size_t i = 0; i < n; ++i)
    for(int a = 0; a < 3; ++a) points[i][a] = scaling.to_unit(mesh.points[i][a]);
  std::vector<std::array<Vertex_id, 4>> tets(mesh.tetrahedra.size());
  for(std::size_t t = 0; t < tets.size(); ++t) {
    for(int i = 0; i < 4; ++i) tets[t][i] = mesh.tetrahedra[t][i];
    if(mesh.subdomain[t] < 1) refuse_mesh("tetrahedron #" + std::to_string(t) + " has subdomain " +
                                          std::to_string(mesh.subdomain[t]) + " (subdomains are numbered from 1)");
    if(orientation(points[tets[t][0]].data(), points[tets[t][1]].data(), points[tets[t][2]].data(),
                   points[tets[t][3]].data()) <= 0)
      refuse_mesh("tetrahedron #" + std::to_string(t) + " is not positively oriented (or is flat)");
  }
  struct Listed_triangle
  {
    Triangle_key key;
    std::size_t number; // in mesh.triangles
    bool operator<(const Listed_triangle& o) const { return key < o.key || (key == o.key && number < o.number); }
  };
  std::vector<Listed_triangle> listed;
  for(std::size_t k = 0; k < mesh.triangles.size(); ++k) {
    const auto& tri = mesh.triangles[k];
    for(std::uint32_t v : tri)
      if(v >= n) refuse_mesh("triangle #" + std::to_string(k) + " refers to point #" + std::to_string(v) + ", past the " +
                             std::to_string(n) + " points");
    listed.push_back({Triangle_key::of(tri[0], tri[1], tri[2]), k});
  }
  std::sort(listed.begin(), listed.end());

  Constrained_mesh cm;
  // Each facet in one tetrahedron (boundary) or two, each boundary edge in
  // two boundary facets (a closed boundary, no two volumes meeting at an
  // edge only): the flat arrays' pairing finds what breaks that.
  try {
    cm.mesh = flat_storage_from_tetrahedra(points, tets);
  } catch(const std::invalid_argument& e) {
    refuse_mesh(e.what());
  }
  set_box(points, cm);
  cm.fit_slot_arrays();
  int most = 0;
  for(Tet_id t = 0; t < tets.size(); ++t) {
    cm.subdomain[t] = mesh.subdomain[t];
    most = std::max(most, mesh.subdomain[t]);
  }
  cm.number_of_subdomains = std::max(most, mesh.number_of_subdomains);
  const Flat_storage& m = cm.mesh;
  std::vector<bool> is_facet(listed.size(), false);
  for(Tet_id t = 0; t < m.number_of_slots(); ++t)
    for(int f = 0; f < 4; ++f) {
      const Triangle_key key = facet_key(m, t, f);
      const auto at = std::lower_bound(listed.begin(), listed.end(), Listed_triangle{key, 0});
      const bool is_listed = at != listed.end() && at->key == key;
      // Equal keys are one triangle given twice: all of them are facets.
      for(auto same = at; is_listed && same != listed.end() && same->key == key; ++same)
        is_facet[same - listed.begin()] = true;
      if(is_listed || cm.subdomain[t] != cm.subdomain[m.neighbor(t, f)]) cm.constrained[t] |= std::uint8_t(1u << f);
    }
  std::size_t first_not_a_facet = mesh.triangles.size();
  for(std::size_t k = 0; k < listed.size(); ++k)
    if(!is_facet[k]) first_not_a_facet = std::min(first_not_a_facet, listed[k].number);
  if(first_not_a_facet < mesh.triangles.size())
    refuse_mesh("triangle #" + std::to_string(first_not_a_facet) + " is not a facet of the tetrahedra");
  cm.size.assign(n, 0.0);
  for(std::size_t i = 0; i < mesh.size.size(); ++i) cm.size[i] = scaling.to_unit(mesh.size[i]);
  return cm;
}

} // namespace mesher_detail

// Improves a tetrahedral mesh in place, as the mesher's last step does
// (options: quality_threshold, min_dihedral_target, max_improvement_passes,
// threads, improvement_adds_points): its boundary, its triangles and the facets
// between subdomains are kept exactly, points on them do not move, every
// tetrahedron keeps its subdomain; interior points may move and, unless
// improvement_adds_points is off, interior points may be added (after the
// given ones, with the mean size of their neighbours when sizes are given).
// The tetrahedra come back in a new order.  Throws std::invalid_argument,
// naming the defect, for a mesh it cannot take (the mesh is left as it was):
// tetrahedra not positively oriented, indices out of range, a facet in
// three tetrahedra, a boundary that is not closed, triangles that are not
// facets of the mesh; and for options out of range.  With a dihedral
// target the worst gamma may go down a little where an angle goes up.
inline Improvement_statistics improve_mesh(Tetrahedral_mesh& mesh, const Mesher_options& options = Mesher_options())
{
  using namespace mesher_detail;
  const Improvement_options improvement = improvement_options_of(options, "improve_mesh");
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
    for(double x : mesh.points[i])
      if(!std::isfinite(x)) refuse_mesh("point #" + std::to_string(i) + " has a coordinate that is not finite");
  Surface_soup extent;
  extent.points = mesh.points;
  const Unit_scaling scaling(extent); // throws Invalid_surface (an invalid_argument) past a double's range
  Constrained_mesh cm = constrained_mesh_of(mesh, scaling);
  const Improvement_statistics stats =
      Fast_Delaunay_triangulation_3_internal::mesher::improve_mesh(cm, improvement);
  scaling.unscale(cm);
  const Flat_storage& m = cm.mesh;
  Tetrahedral_mesh out;
  out.points.resize(m.vertices.size());
  for(Vertex_id v = 0; v < m.vertices.size(); ++v) out.points[v] = {m.point(v)[0], m.point(v)[1], m.point(v)[2]};
  if(!mesh.size.empty()) out.size = cm.size.values();
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || m.is_ghost(t) || cm.subdomain[t] <= 0) continue;
    const Vertex_id* tv = m.vertex_ids(t);
    out.tetrahedra.push_back({tv[0], tv[1], tv[2], tv[3]});
    out.subdomain.push_back(cm.subdomain[t]);
  }
  out.triangles = std::move(mesh.triangles);
  out.surface = std::move(mesh.surface);
  out.number_of_subdomains = cm.number_of_subdomains;
  out.number_of_surfaces = mesh.number_of_surfaces;
  mesh = std::move(out);
  return stats;
}

// Reads a size field file into `options` (the format is in
// internal/mesher/Size_field_file.h: lines 'subdomain S H' and 'X Y Z H'):
// its subdomain caps replace options.subdomain_sizes, and its background
// points, if any, give a size function (the size of the nearest one),
// combined with options.size_function by the smaller of the two.  Throws
// std::invalid_argument naming the file and the line of a defect; options
// are left as they were then.
inline void read_size_field(const std::string& path, Mesher_options& options)
{
  using namespace Fast_Delaunay_triangulation_3_internal::mesher;
  Size_field_entries entries = read_size_field_entries(path);
  std::function<double(double, double, double)> nearest;
  if(!entries.points.empty()) nearest = Nearest_point_size(entries.points, std::move(entries.sizes));
  options.subdomain_sizes = std::move(entries.subdomain_sizes);
  if(!nearest) return;
  if(options.size_function) {
    const std::function<double(double, double, double)> given = options.size_function;
    options.size_function = [given, nearest](double x, double y, double z) {
      return std::min(given(x, y, z), nearest(x, y, z));
    };
  } else {
    options.size_function = nearest;
  }
}

// Writes .mesh (Medit), .vtu (VTK, raw binary appended) or .msh (Gmsh 4.1, ASCII), by extension.
inline void write_mesh(const std::string& path, const Tetrahedral_mesh& mesh)
{
  Fast_Delaunay_triangulation_3_internal::mesher::write_mesh_file(path, mesh);
}

// The figures of Quality_report; `threads` share its loops (TBB), and the
// figures are the same for any number.  Flat or inverted tetrahedra are
// counted, not refused; std::invalid_argument if a tetrahedron refers to a
// point the mesh lacks, the subdomain tags are not one per tetrahedron or
// the sizes neither one per point nor none (then the edges are not
// measured against h: Quality_report::has_sizes).
inline Quality_report quality_report(const Tetrahedral_mesh& mesh, int threads = 1)
{
  return Fast_Delaunay_triangulation_3_internal::mesher::quality_report(mesh, threads);
}

inline void print_quality_report(std::ostream& out, const Quality_report& report)
{
  Fast_Delaunay_triangulation_3_internal::mesher::print_quality_report(out, report);
}

} // namespace Fast_mesher_3
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_TETRAHEDRAL_MESHER_H
