// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Mesh improvement: the step the paper leaves out (§4 and its conclusion:
// "edge swap, edge collapse, edge split, vertex relocation and face swap ...
// using the same parallel framework").  A tetrahedron's quality is its
// gamma (Tetrahedron_quality.h) or, with a dihedral target, the lower of
// gamma and threshold * sin(smallest dihedral angle) / sin(target); every
// tetrahedron of quality under the threshold is worked on (in slot order
// in the first pass of flips and moves, worst first after it) by local
// operations that each must raise the worst quality of the region they
// touch:
//
//   edge removal   the ring of n = 3..max_ring tetrahedra around one of its
//                  edges is replaced by the 2n - 4 tetrahedra of the best
//                  triangulation of the ring's polygon (Shewchuk's edge
//                  removal; n = 3 is the 3-2 flip, n = 4 the 4-4 flip): the
//                  polygon triangulation maximising the worst quality, by
//                  dynamic programming over its diagonals (Klincsek);
//   face removal   the 2-3 flip of one of its facets;
//   relocation     each of its vertices that is not on the surface moves
//                  toward the weighted mean of the points that would make
//                  each tetrahedron of its ball regular, or toward the
//                  worst one's alone, or (only if it does better) toward the
//                  mean of its neighbours, halving the step until the worst
//                  quality of the ball goes up;
//   Steiner point  where none of these helps (typically a sliver whose four
//                  vertices are on the surface, which relocation cannot
//                  move), a new interior vertex splits one of its interior
//                  edges (the edge's ring becomes twice as many tetrahedra)
//                  or one of its interior facets (two tetrahedra become
//                  six), or is put at the regular apex of one of its
//                  facets and joined to the boundary of a cavity grown from
//                  it: the tetrahedra whose circumscribed spheres hold the
//                  point, or those behind every boundary facet the point
//                  would make a bad tetrahedron with (up to
//                  max_steiner_region, never across a constrained facet);
//                  placed by the same search as relocation, and kept only
//                  if the region's worst quality goes up.
//
// What every operation keeps: positive orientation, checked with the exact
// predicate before anything is written; the input triangles (a constrained
// facet is never crossed, a vertex on one never moves, so the boundary is
// the same set of triangles); the subdomain of every tetrahedron (the
// regions never span two).  Topological changes go through
// replace_tetrahedra (Tetrahedra_replacement.h), the same code as the TDS
// view's flips.
//
// In parallel the paper's framework is reused: vertices get the partition
// of their Moore key's range (the ranges cut the bad tetrahedra into equal
// shares); a partition works only on tetrahedra whose four vertices are
// its own, so two partitions never read or write the same tetrahedron or
// vertex; an operation that would reach another one's is left for the next
// attempt, whose cuts are shifted by half a partition, and what is left
// after that is done sequentially.  Steiner points are added in that
// sequential step only: a new vertex grows the per-vertex arrays, which the
// partitions share.  Each partition takes slots from its own
// free list and its own range of fresh slots, so the mesh depends on the
// number of partitions, never on the threads' timing.

#ifndef CGAL_FDT3_INTERNAL_MESHER_MESH_IMPROVEMENT_H
#define CGAL_FDT3_INTERNAL_MESHER_MESH_IMPROVEMENT_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Moore_curve.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Tetrahedra_replacement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Sizing.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedron_quality.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

struct Improvement_options
{
  double quality_threshold = 0.3; // quality (gamma, see below) under which a tetrahedron is worked on
  // Degrees: a tetrahedron whose smallest dihedral angle is under this is
  // worked on too, with the quality min(gamma, quality_threshold *
  // sin(angle) / sin(min_dihedral_target)); 0 for gamma alone.
  double min_dihedral_target = 0;
  int max_passes = 10;            // sweeps over the bad tetrahedra
  int threads = 1;                // partitions; the result depends on this number only
  std::size_t min_bad_per_partition = 256;
  int max_ring = 8;               // largest edge ring that edge removal retriangulates
  bool add_steiner_points = true; // off: the vertex set stays as it is
};

struct Improvement_statistics
{
  std::size_t bad_before = 0, bad_after = 0; // tetrahedra under the threshold
  double min_gamma_before = 1, min_gamma_after = 1; // over the volumes' tetrahedra
  double min_dihedral_before = 180, min_dihedral_after = 180; // degrees, over the volumes
  std::size_t below_10_degrees_before = 0, below_10_degrees_after = 0;
  // Of the bad tetrahedra left, those whose four vertices are on the
  // surface: relocation cannot touch them and only a Steiner point could.
  std::size_t bad_after_on_surface = 0;
  // Of the bad tetrahedra left (wherever their vertices are), those on a
  // constrained facet under which no tetrahedron reaches the threshold
  // (gamma_ceiling_on_triangle, a proven bound): the surface forces them.
  // The constrained facets are the input triangles (mesh_surfaces), or
  // every facet improve_mesh keeps: the boundary and the interfaces.
  std::size_t bad_after_forced_by_surface = 0;
  // Of the bad tetrahedra left, those whose four vertices are on the
  // surface and that stand on no forcing facet (as counted just above):
  // triangles wider than the material under them (a wall or a step
  // narrower than they are) leave these, and only a finer surface mends
  // them.
  std::size_t bad_after_on_surface_not_forced = 0;
  std::size_t edge_removals = 0, face_removals = 0, relocations = 0;
  std::size_t steiner_points = 0; // interior vertices added by edge or facet splits or in a cavity
  std::size_t deferred = 0; // operations that met another partition and were retried
  std::size_t operations_in_partitions = 0; // of the operations, those done in attempts with several partitions
  int passes = 0;
  double seconds = 0;

  void add(const Improvement_statistics& o)
  {
    edge_removals += o.edge_removals;
    face_removals += o.face_removals;
    relocations += o.relocations;
    steiner_points += o.steiner_points;
    deferred += o.deferred;
  }
};

class Mesh_improvement
{
public:
  Mesh_improvement(Constrained_mesh& cm, const Improvement_options& options) : cm_(cm), options_(options)
  {
    options_.max_ring = std::max(3, std::min(options_.max_ring, max_ring_limit));
    const double target = std::min(options_.min_dihedral_target, 70.0);
    if(target > 0) dihedral_scale_ = options_.quality_threshold / std::sin(target * quality_detail::pi / 180);
  }

  Improvement_statistics run()
  {
    const auto t0 = std::chrono::steady_clock::now();
    Improvement_statistics stats;
    cm_.fit_slot_arrays();
    mark_surface_vertices();
    set_incident_tetrahedra();
    partition_of_vertex_.assign(cm_.mesh.vertices.size(), 0);
    std::vector<Bad_tet> bad;
    shape_figures(stats.min_gamma_before, stats.bad_before, stats.min_dihedral_before, stats.below_10_degrees_before,
                  &bad);
    // Steiner points come only once flips and relocation have done what
    // they can: a split made early takes the place of a better flip (on 60
    // points of a sphere, splitting first left a worst gamma of 0.009,
    // flipping first 0.019 before any split).  Each phase has max_passes.
    // The first Steiner pass takes every bad tetrahedron, but flips and
    // relocation only where the last pass changed something.
    changed_.assign(cm_.mesh.vertices.size(), 1);
    for(int phase = 0; phase < (options_.add_steiner_points ? 2 : 1); ++phase) {
      steiner_phase_ = phase == 1;
      for(int pass = 0; pass < options_.max_passes && !bad.empty(); ++pass) {
        ++stats.passes;
        every_bad_tetrahedron_ = pass == 0;
        active_.swap(changed_);
        changed_.assign(cm_.mesh.vertices.size(), 0);
        reshaped_.clear();
        const std::size_t changes = operations(stats);
        improve(bad, stats);
        bad = bad_tetrahedra_after_pass(bad);
        if(operations(stats) == changes) break;
      }
    }
    shape_figures(stats.min_gamma_after, stats.bad_after, stats.min_dihedral_after, stats.below_10_degrees_after);
    // The statistics count gamma: a tetrahedron under the threshold is on
    // the work list whatever the dihedral target.
    for(const Bad_tet& b : bad) {
      if(gamma_of(b.t) >= options_.quality_threshold) continue;
      const Vertex_id* tv = cm_.mesh.vertex_ids(b.t);
      const bool on_surface = on_surface_[tv[0]] && on_surface_[tv[1]] && on_surface_[tv[2]] && on_surface_[tv[3]];
      const bool forced = on_forcing_input_triangle(b.t);
      stats.bad_after_on_surface += on_surface ? 1 : 0;
      stats.bad_after_forced_by_surface += forced ? 1 : 0;
      stats.bad_after_on_surface_not_forced += on_surface && !forced ? 1 : 0;
    }
    stats.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return stats;
  }

private:
  static constexpr int max_ring_limit = 10;
  static constexpr std::size_t max_ball = 256;
  // Tetrahedra a Steiner point's cavity may replace.  The cavities that
  // fix a sliver under a nearly flat surface edge hold 20 to 40 (elephant);
  // the cone over 64 has at most 2 * 64 + 2 tetrahedra, which the position
  // search's fixed arrays (max_ball) hold.
  static constexpr std::size_t max_steiner_region = 64;
  static_assert(2 * max_steiner_region + 2 <= max_ball, "a cavity's cone fits the position search");
  // Rounds of the position search for a new Steiner point: it starts at
  // an edge's midpoint, a facet's centroid or a facet's regular apex,
  // rarely where it belongs.  Every candidate split gets the first number,
  // the one kept the second (couplingdown, whose walls are thinner than its
  // triangles, tries about 18 splits for each of 3600 bad tetrahedra: 4
  // rounds for all took 4.4 s, 2 then 4 for the winner 3.7 s).
  static constexpr int candidate_search_rounds = 2, chosen_search_rounds = 4;

  static std::size_t operations(const Improvement_statistics& s)
  {
    return s.edge_removals + s.face_removals + s.relocations + s.steiner_points;
  }

  struct Bad_tet
  {
    double quality;
    Tet_id t;
    friend bool operator<(const Bad_tet& x, const Bad_tet& y)
    {
      return x.quality != y.quality ? x.quality < y.quality : x.t < y.t;
    }
  };

  // One partition's state during an attempt.
  struct Worker
  {
    std::uint8_t partition = 0;
    std::vector<Tet_id>* free_slots = nullptr;
    Tet_id next_fresh = 0, fresh_end = 0;
    bool may_add_vertices = false; // the sequential step only
    Replacement_scratch replacement;
    Replacement_counts counts;
    Improvement_statistics stats;
    std::vector<Tet_id> deferred;
    std::vector<Tet_id> need_steiner; // left for the sequential step, which may add vertices
    std::vector<Tet_id> reshaped;     // slots written or with a corner moved
    std::vector<Tet_id> ball;
    std::vector<std::array<Vertex_id, 4>> ball_corners;
    std::vector<std::array<Vertex_id, 4>> made;
    std::vector<Tet_id> slots;

    std::size_t slots_left() const { return free_slots->size() + (fresh_end - next_fresh); }
    Tet_id new_slot()
    {
      if(!free_slots->empty()) {
        const Tet_id t = free_slots->back();
        free_slots->pop_back();
        return t;
      }
      CGAL_assertion(next_fresh < fresh_end);
      return next_fresh++;
    }
  };

  // What an operation did (improved), or what a search found (found): or
  // nothing worth doing, or another partition's tetrahedra in the way (the
  // bad tetrahedron is retried in the next attempt).
  enum class Outcome { improved, found, unchanged, foreign };

  // ------------------------------------------------------------ set-up
  void mark_surface_vertices()
  {
    const Flat_storage& m = cm_.mesh;
    on_surface_.assign(m.vertices.size(), 0);
    for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t)) continue;
      const Vertex_id* tv = m.vertex_ids(t);
      if(m.is_ghost(t) || cm_.subdomain[t] <= 0) {
        for(int i = 0; i < 4; ++i)
          if(tv[i] != ghost_vertex) on_surface_[tv[i]] = 1;
        continue;
      }
      for(int f = 0; f < 4; ++f)
        if(cm_.is_constrained(t, f))
          for(int i = 0; i < 3; ++i) on_surface_[tv[facet_vertex[f][i]]] = 1;
    }
  }

  void set_incident_tetrahedra()
  {
    const Flat_storage& m = cm_.mesh;
    incident_.assign(m.vertices.size(), no_tet);
    for(Tet_id t = 0; t < m.number_of_slots(); ++t)
      if(is_volume(t))
        for(int i = 0; i < 4; ++i) incident_[m.vertex(t, i)] = t;
  }

  bool is_volume(Tet_id t) const
  {
    return cm_.mesh.is_live(t) && !cm_.mesh.is_ghost(t) && cm_.subdomain[t] > 0;
  }

  // What the operations raise: gamma, or with a dihedral target the lower
  // of gamma and the scaled sine of the smallest dihedral angle (a
  // tetrahedron can have gamma well above 0.3 and an angle of 11 degrees).
  double quality(const double* a, const double* b, const double* c, const double* d) const
  {
    if(dihedral_scale_ == 0) return gamma_quality(a, b, c, d);
    double sine;
    const double gamma = gamma_quality(a, b, c, d, &sine);
    return quality_of_shape(gamma, sine);
  }
  // From gamma and the sine of the smallest dihedral angle.
  double quality_of_shape(double gamma, double sine) const
  {
    return dihedral_scale_ == 0 ? gamma : std::min(gamma, dihedral_scale_ * sine);
  }
  double quality_of(const Vertex_id* tv) const
  {
    const Flat_storage& m = cm_.mesh;
    return quality(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]));
  }

  // Each volume tetrahedron's gamma and smallest dihedral sine, kept by
  // slot from the first figures on: every operation writes those of the
  // slots it fills or reshapes (set_shape), so that the edge rings, the
  // work lists and the last figures read them (bunny00: 2 million ring
  // tetrahedra measured again in the first pass alone).  A worker writes
  // only slots of its own partition, and reads only those.
  struct Shape
  {
    double gamma = 0, sine = 0;
  };
  static Shape shape_of_points(const double* a, const double* b, const double* c, const double* d)
  {
    Shape s;
    s.gamma = gamma_quality(a, b, c, d, &s.sine);
    return s;
  }
  void set_shape(Tet_id t)
  {
    const Flat_storage& m = cm_.mesh;
    const Vertex_id* tv = m.vertex_ids(t);
    shape_[t] = shape_of_points(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]));
  }
  // Slots grow with the mesh's arrays (never while a worker reads them).
  void fit_shapes() { shape_.resize(cm_.mesh.number_of_slots()); }
  double gamma_of(Tet_id t) const { return shape_[t].gamma; }
  double quality_of(Tet_id t) const { return quality_of_shape(shape_[t].gamma, shape_[t].sine); }

  // The tetrahedra of quality under the threshold after a pass, from the
  // list before it: only a tetrahedron whose slot was written or whose
  // corner moved in the pass (reshaped_) can have changed its quality, so
  // the others keep their place in or out of the list, and only those are
  // looked at again (a pass late in the improvement changes a few hundred
  // of a million tetrahedra).  In slot order too.
  std::vector<Bad_tet> bad_tetrahedra_after_pass(const std::vector<Bad_tet>& before)
  {
    std::sort(reshaped_.begin(), reshaped_.end());
    reshaped_.erase(std::unique(reshaped_.begin(), reshaped_.end()), reshaped_.end());
    std::vector<Bad_tet> bad;
    for(const Bad_tet& b : before)
      if(is_volume(b.t) && !std::binary_search(reshaped_.begin(), reshaped_.end(), b.t)) bad.push_back(b);
    for(Tet_id t : reshaped_) {
      if(!is_volume(t)) continue;
      const double q = quality_of(t);
      if(q < options_.quality_threshold) bad.push_back({q, t});
    }
    std::sort(bad.begin(), bad.end(), [](const Bad_tet& x, const Bad_tet& y) { return x.t < y.t; });
    return bad;
  }

  // Over the volumes' tetrahedra: the lowest gamma, how many are under the
  // threshold, the smallest dihedral angle and how many are under 10
  // degrees.  The first call (with `bad`: the tetrahedra of quality under
  // the threshold, the work list, in slot order) measures every slot; the
  // last reads the kept shapes.  The angles compare as sines (the smallest
  // is at most 70.5 degrees, where the sine still rises).
  void shape_figures(double& lowest_gamma, std::size_t& under_threshold, double& smallest_angle,
                     std::size_t& below_10_degrees, std::vector<Bad_tet>* bad = nullptr)
  {
    if(bad) fit_shapes();
    const std::size_t slots = cm_.mesh.number_of_slots();
    const int chunks = chunk_count(slots, std::max(1, options_.threads));
    const double sine_of_10_degrees = std::sin(10 * quality_detail::pi / 180);
    // A sine above 1 stands for no tetrahedron (180 degrees, as before any).
    std::vector<double> lowest(chunks, 1.0), smallest_sine(chunks, 2.0);
    std::vector<std::size_t> under(chunks, 0), below(chunks, 0);
    std::vector<std::vector<Bad_tet>> found(chunks);
    for_each_chunk(chunks, [&](int c) {
      const Tet_id end = static_cast<Tet_id>(chunk_begin(slots, chunks, c + 1));
      for(Tet_id t = static_cast<Tet_id>(chunk_begin(slots, chunks, c)); t < end; ++t) {
        if(!is_volume(t)) continue;
        if(bad) set_shape(t);
        const Shape& s = shape_[t];
        lowest[c] = std::min(lowest[c], s.gamma);
        under[c] += s.gamma < options_.quality_threshold ? 1 : 0;
        const double q = quality_of_shape(s.gamma, s.sine);
        if(bad && q < options_.quality_threshold) found[c].push_back({q, t});
        smallest_sine[c] = std::min(smallest_sine[c], s.sine);
        below[c] += s.sine < sine_of_10_degrees ? 1 : 0;
      }
    });
    lowest_gamma = *std::min_element(lowest.begin(), lowest.end());
    const double sine = *std::min_element(smallest_sine.begin(), smallest_sine.end());
    smallest_angle = sine > 1 ? 180 : degrees_of_sine(sine);
    under_threshold = below_10_degrees = 0;
    for(int c = 0; c < chunks; ++c) {
      under_threshold += under[c];
      below_10_degrees += below[c];
      if(bad) bad->insert(bad->end(), found[c].begin(), found[c].end());
    }
  }

  // The lowest `measure` (gamma_quality, or this class's quality) of the
  // tetrahedra that t's input triangles make with their regular apexes (1
  // without one): an estimate of the best any tetrahedron on those
  // triangles can have, from below (gamma_ceiling_on_triangle bounds it
  // from above).
  template <class Measure>
  double input_triangle_ceiling(Tet_id t, const Measure& measure) const
  {
    const Flat_storage& m = cm_.mesh;
    const Vertex_id* tv = m.vertex_ids(t);
    double ceiling = 1;
    for(int f = 0; f < 4; ++f) {
      if(!cm_.is_constrained(t, f)) continue;
      double apex[3];
      regular_apex(tv, f, apex);
      ceiling = std::min(ceiling, measure(apex, m.point(tv[facet_vertex[f][0]]), m.point(tv[facet_vertex[f][1]]),
                                          m.point(tv[facet_vertex[f][2]])));
    }
    return ceiling;
  }
  double input_triangle_ceiling(Tet_id t) const
  {
    return input_triangle_ceiling(t, [this](const double* a, const double* b, const double* c, const double* d) {
      return quality(a, b, c, d);
    });
  }

  // t stands on an input triangle under which no tetrahedron reaches the
  // threshold's gamma.
  bool on_forcing_input_triangle(Tet_id t) const
  {
    const Flat_storage& m = cm_.mesh;
    const Vertex_id* tv = m.vertex_ids(t);
    for(int f = 0; f < 4; ++f)
      if(cm_.is_constrained(t, f) &&
         gamma_ceiling_on_triangle(m.point(tv[facet_vertex[f][0]]), m.point(tv[facet_vertex[f][1]]),
                                   m.point(tv[facet_vertex[f][2]])) < options_.quality_threshold)
        return true;
    return false;
  }

  // ------------------------------------------------------------ partitions
  // Every operation on t but the Steiner cavity reads only tetrahedra that
  // share a vertex with t, and every change marks the vertices of the
  // tetrahedra it made or moved (changed_): a bad tetrahedron none of whose
  // vertices changed in the last pass would meet the same refusals again,
  // and is skipped (active_).  A cavity reaches further, so a skipped
  // tetrahedron may miss one that a change further off would now allow: a
  // chance lost, never validity.
  bool is_active(Tet_id t) const
  {
    const Vertex_id* tv = cm_.mesh.vertex_ids(t);
    return active_[tv[0]] || active_[tv[1]] || active_[tv[2]] || active_[tv[3]];
  }

  void mark_changed(const std::vector<std::array<Vertex_id, 4>>& tets)
  {
    for(const auto& tv : tets)
      for(Vertex_id v : tv) changed_[v] = 1;
  }

  void improve(const std::vector<Bad_tet>& bad, Improvement_statistics& stats)
  {
    std::vector<Tet_id> todo;
    for(const Bad_tet& b : bad)
      if(every_bad_tetrahedron_ || is_active(b.t)) todo.push_back(b.t);
    const int partitions = static_cast<int>(std::min<std::size_t>(
        std::max(1, std::min(options_.threads, 255)), std::max<std::size_t>(1, bad.size() / options_.min_bad_per_partition)));
    need_steiner_.clear();
    if(partitions > 1) {
      const std::vector<std::uint64_t>& keys = vertex_keys();
      for(int attempt = 0; attempt < 2 && !todo.empty(); ++attempt)
        todo = attempt_in_partitions(todo, partitions, keys, attempt == 0 ? 0.0 : 0.5, stats);
      // What only a new vertex could help joins the sequential step, in
      // slot order; a slot listed twice is worked on once.
      todo.insert(todo.end(), need_steiner_.begin(), need_steiner_.end());
      std::sort(todo.begin(), todo.end());
      todo.erase(std::unique(todo.begin(), todo.end()), todo.end());
    }
    std::fill(partition_of_vertex_.begin(), partition_of_vertex_.end(), std::uint8_t(0));
    std::vector<std::vector<Tet_id>> lists(1, todo);
    run_workers(lists, stats);
  }

  // The Moore keys that place vertices in partitions, computed once (and
  // for each added vertex): a relocated vertex keeps its key, which only
  // decides which partition owns it.
  const std::vector<std::uint64_t>& vertex_keys()
  {
    const Flat_storage& m = cm_.mesh;
    if(vertex_keys_.empty()) key_grid_bits_ = moore_bits_per_axis(m.vertices.size());
    const Moore_grid grid(cm_.box_lo, cm_.box_hi, key_grid_bits_);
    const Moore_curve curve(grid.bits_per_axis());
    const std::size_t first = vertex_keys_.size(), n = m.vertices.size() - first;
    vertex_keys_.resize(m.vertices.size());
    const int chunks = chunk_count(n, std::max(1, options_.threads));
    for_each_chunk(chunks, [&](int c) {
      const std::size_t end = first + chunk_begin(n, chunks, c + 1);
      for(std::size_t v = first + chunk_begin(n, chunks, c); v < end; ++v)
        vertex_keys_[v] = grid.key(curve, m.point(static_cast<Vertex_id>(v)));
    });
    return vertex_keys_;
  }

  // Cuts at the keys of the bad tetrahedra's first vertices, at shares
  // (j + shift) / partitions; a key before the first cut goes with the last
  // partition (the Moore curve is closed).  Returns what must be retried.
  // A deferred slot may have been freed or reused since: only the live
  // volume tetrahedra among `listed` are tried again.
  std::vector<Tet_id> attempt_in_partitions(const std::vector<Tet_id>& listed, int partitions,
                                            const std::vector<std::uint64_t>& keys, double shift,
                                            Improvement_statistics& stats)
  {
    const Flat_storage& m = cm_.mesh;
    std::vector<Tet_id> todo;
    for(Tet_id t : listed)
      if(is_volume(t)) todo.push_back(t);
    if(todo.empty()) return todo;
    std::vector<std::uint64_t> sorted(todo.size());
    for(std::size_t i = 0; i < todo.size(); ++i) sorted[i] = keys[m.vertex(todo[i], 0)];
    std::sort(sorted.begin(), sorted.end());
    std::vector<std::uint64_t> cuts(partitions);
    for(int j = 0; j < partitions; ++j)
      cuts[j] = sorted[std::min(sorted.size() - 1, static_cast<std::size_t>((j + shift) * sorted.size() / partitions))];
    const std::size_t n = m.vertices.size();
    const int chunks = chunk_count(n, std::max(1, options_.threads));
    for_each_chunk(chunks, [&](int c) {
      const std::size_t end = chunk_begin(n, chunks, c + 1);
      for(std::size_t v = chunk_begin(n, chunks, c); v < end; ++v) {
        const int above = static_cast<int>(std::upper_bound(cuts.begin(), cuts.end(), keys[v]) - cuts.begin());
        partition_of_vertex_[v] = static_cast<std::uint8_t>(above == 0 ? partitions - 1 : above - 1);
      }
    });
    std::vector<std::vector<Tet_id>> lists(partitions);
    std::vector<Tet_id> left;
    for(Tet_id t : todo) {
      const std::uint8_t p = partition_of_vertex_[m.vertex(t, 0)];
      (owned_by(t, p) ? lists[p] : left).push_back(t);
    }
    std::vector<Tet_id> retry = run_workers(lists, stats);
    left.insert(left.end(), retry.begin(), retry.end());
    std::sort(left.begin(), left.end());
    left.erase(std::unique(left.begin(), left.end()), left.end());
    return left;
  }

  // Room for every worker's worst case is fixed before they start: an
  // operation on a bad tetrahedron adds at most max_ring - 4 tetrahedra
  // (edge removal), or max_ring_limit (a Steiner point on an edge of that
  // ring), and each bad tetrahedron gets at most one topological operation.
  // A single worker is the sequential step, the one that may add vertices;
  // a Steiner cavity adds up to max_steiner_region + 2, and that worker,
  // alone, grows its range at the arrays' end when it runs short
  // (grow_fresh_range) rather than reserving that much per bad tetrahedron.
  std::vector<Tet_id> run_workers(std::vector<std::vector<Tet_id>>& lists, Improvement_statistics& stats)
  {
    Flat_storage& m = cm_.mesh;
    const int partitions = static_cast<int>(lists.size());
    const int added_per_operation = partitions == 1 ? max_ring_limit : std::max(1, options_.max_ring - 4);
    std::vector<Tet_id> fresh_begin(partitions + 1);
    fresh_begin[0] = static_cast<Tet_id>(m.number_of_slots());
    for(int j = 0; j < partitions; ++j)
      fresh_begin[j + 1] = fresh_begin[j] + static_cast<Tet_id>(added_per_operation * lists[j].size() + 64);
    m.resize_tets(fresh_begin[partitions], Flat_storage::New_slots::left_unwritten);
    cm_.fit_slot_arrays();
    fit_shapes();
    std::vector<std::vector<Tet_id>> free_lists(partitions);
    for(std::size_t k = 0; k < m.free_tets.size(); ++k) free_lists[k % partitions].push_back(m.free_tets[k]);
    m.free_tets.clear();
    std::vector<Worker> workers(partitions);
    for_each_chunk(partitions, [&](int j) {
      Worker& w = workers[j];
      w.partition = static_cast<std::uint8_t>(j);
      w.free_slots = &free_lists[j];
      w.next_fresh = fresh_begin[j];
      w.fresh_end = fresh_begin[j + 1];
      w.may_add_vertices = partitions == 1;
      // The first pass, which meets every bad tetrahedron (bunny00: 60,000
      // of 1.25 million), takes them in slot order, which follows the
      // Moore curve of the refinement: each one's neighbourhood is then
      // mostly in cache from the last one's (improvement 0.95 -> 0.80 s on
      // 1 thread; as many left bad).  Later passes, with the few that
      // resisted, take the worst first, which gets the first choice of
      // operations.
      std::vector<Bad_tet> order;
      for(Tet_id t : lists[j])
        if(is_volume(t)) order.push_back({quality_of(t), t});
      if(!(every_bad_tetrahedron_ && !steiner_phase_)) std::sort(order.begin(), order.end());
      for(const Bad_tet& b : order) improve_tetrahedron(w, b.t);
    });
    std::vector<Tet_id> retry;
    for(int j = 0; j < partitions; ++j) {
      Worker& w = workers[j];
      m.live_tets = std::size_t(std::ptrdiff_t(m.live_tets) + w.counts.live);
      m.ghost_tets = std::size_t(std::ptrdiff_t(m.ghost_tets) + w.counts.ghost);
      stats.add(w.stats);
      if(partitions > 1) stats.operations_in_partitions += operations(w.stats);
      if(j + 1 < partitions)
        for(Tet_id t = w.next_fresh; t < fresh_begin[j + 1]; ++t) {
          m.tets[t].v[0] = mark_bit;
          m.free_tets.push_back(t);
        }
      m.free_tets.insert(m.free_tets.end(), free_lists[j].begin(), free_lists[j].end());
      retry.insert(retry.end(), w.deferred.begin(), w.deferred.end());
      reshaped_.insert(reshaped_.end(), w.reshaped.begin(), w.reshaped.end());
      need_steiner_.insert(need_steiner_.end(), w.need_steiner.begin(), w.need_steiner.end());
    }
    m.resize_tets(workers[partitions - 1].next_fresh, Flat_storage::New_slots::left_unwritten);
    cm_.fit_slot_arrays();
    return retry;
  }

  // The sequential worker's fresh range ends where the arrays end: it may
  // extend both (nothing else runs).
  void grow_fresh_range(Worker& w, std::size_t at_least)
  {
    Flat_storage& m = cm_.mesh;
    CGAL_precondition(w.may_add_vertices && w.fresh_end == m.number_of_slots());
    const std::size_t extra = std::max<std::size_t>(at_least, 1024);
    m.resize_tets(w.fresh_end + extra, Flat_storage::New_slots::left_unwritten);
    cm_.fit_slot_arrays();
    fit_shapes();
    w.fresh_end = static_cast<Tet_id>(w.fresh_end + extra);
  }

  bool owned_by(Tet_id t, std::uint8_t p) const
  {
    if(!is_volume(t)) return false;
    const Vertex_id* tv = cm_.mesh.vertex_ids(t);
    return partition_of_vertex_[tv[0]] == p && partition_of_vertex_[tv[1]] == p &&
           partition_of_vertex_[tv[2]] == p && partition_of_vertex_[tv[3]] == p;
  }
  bool own_vertex(Vertex_id v, std::uint8_t p) const { return v != ghost_vertex && partition_of_vertex_[v] == p; }

  // ------------------------------------------------------------ one bad tetrahedron
  void improve_tetrahedron(Worker& w, Tet_id t)
  {
    if(!is_volume(t)) return;
    const double q = quality_of(t);
    // On an input triangle too skinny for the threshold, a tetrahedron
    // near that triangle's best is left as it is.
    if(q >= options_.quality_threshold || q >= 0.9 * input_triangle_ceiling(t)) return;
    if(!owned_by(t, w.partition)) {
      w.deferred.push_back(t);
      ++w.stats.deferred;
      return;
    }
    bool foreign = false;
    Outcome o;
    if(is_active(t)) { // else nothing around t changed since these failed
      o = remove_best_edge(w, t);
      if(o == Outcome::improved) return;
      foreign |= o == Outcome::foreign;
      o = remove_best_facet(w, t);
      if(o == Outcome::improved) return;
      foreign |= o == Outcome::foreign;
      Vertex_id corners[4];
      std::copy(cm_.mesh.vertex_ids(t), cm_.mesh.vertex_ids(t) + 4, corners);
      for(Vertex_id v : corners) {
        if(on_surface_[v]) continue;
        o = relocate(w, v);
        foreign |= o == Outcome::foreign;
        if(!is_volume(t) || quality_of(t) >= options_.quality_threshold) return;
      }
    }
    if(!steiner_phase_) {
      if(foreign) {
        w.deferred.push_back(t);
        ++w.stats.deferred;
      }
      return;
    }
    if(!w.may_add_vertices) {
      // Another partition's tetrahedra in the way: the shifted attempt may
      // do better; otherwise only the sequential step's Steiner points.
      (foreign ? w.deferred : w.need_steiner).push_back(t);
      w.stats.deferred += foreign ? 1 : 0;
      return;
    }
    o = add_steiner_point(w, t);
    if(o == Outcome::improved) return;
    foreign |= o == Outcome::foreign;
    if(foreign) {
      w.deferred.push_back(t);
      ++w.stats.deferred;
    }
  }

  // After a replacement: the region's subdomain, constrained bits copied
  // from the tetrahedra outside, incidences.
  void after_replacement(const Worker& w, std::size_t made, int subdomain)
  {
    Flat_storage& m = cm_.mesh;
    for(std::size_t k = 0; k < made; ++k) {
      const Tet_id s = w.slots[k];
      cm_.subdomain[s] = subdomain;
      std::uint8_t bits = 0;
      for(int f = 0; f < 4; ++f) {
        const Facet_code back = m.neighbor_code(s, f);
        const Tet_id u = tet_of(back);
        if(std::find(w.slots.begin(), w.slots.begin() + made, u) == w.slots.begin() + made &&
           cm_.is_constrained(u, facet_of(back)))
          bits |= std::uint8_t(1u << f);
      }
      cm_.constrained[s] = bits;
      for(int i = 0; i < 4; ++i) incident_[m.vertex(s, i)] = s;
      set_shape(s);
    }
  }

  bool all_positive(const std::vector<std::array<Vertex_id, 4>>& tets) const
  {
    const Flat_storage& m = cm_.mesh;
    for(const auto& tv : tets)
      if(orientation(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])) <= 0) return false;
    return true;
  }

  void replace(Worker& w, const Tet_id* region, std::size_t region_size, int subdomain)
  {
    w.slots.resize(w.made.size());
    replace_tetrahedra(cm_.mesh, region, region_size, w.made.data(), w.made.size(), w.slots.data(), w.replacement,
                       w.counts, [&w] { return w.new_slot(); }, [&](Tet_id s) {
                         cm_.mesh.mark_free(s);
                         w.free_slots->push_back(s);
                       });
    after_replacement(w, w.made.size(), subdomain);
    mark_changed(w.made);
    w.reshaped.insert(w.reshaped.end(), w.slots.begin(), w.slots.end());
  }

  // ------------------------------------------------------------ edge removal
  struct Edge_ring
  {
    Vertex_id a, b;
    int n = 0;
    Vertex_id ring[max_ring_limit];
    Tet_id tets[max_ring_limit]; // tets[i] = (a, b, ring[i], ring[i + 1]), positively
    double worst = 1;
  };

  static bool even_permutation(const int p[4])
  {
    int inversions = 0;
    for(int i = 0; i < 4; ++i)
      for(int j = i + 1; j < 4; ++j) inversions += p[i] > p[j] ? 1 : 0;
    return inversions % 2 == 0;
  }

  // The ring around edge (slot i, slot j) of t, walked across the facets that
  // hold the edge, each of which must be unconstrained with both sides in
  // t's subdomain and in w's partition.
  Outcome edge_ring(const Worker& w, Tet_id t, int i, int j, Edge_ring& r, int max_ring) const
  {
    const Flat_storage& m = cm_.mesh;
    const Vertex_id* tv = m.vertex_ids(t);
    int k = -1, l = -1;
    for(int s = 0; s < 4; ++s)
      if(s != i && s != j) (k < 0 ? k : l) = s;
    const int order[4] = {i, j, k, l};
    if(!even_permutation(order)) std::swap(k, l);
    r.a = tv[i];
    r.b = tv[j];
    r.n = 0;
    Tet_id cur = t;
    Vertex_id x = tv[k];
    for(;;) {
      if(r.n == max_ring) return Outcome::unchanged;
      if(!is_volume(cur) || cm_.subdomain[cur] != cm_.subdomain[t]) return Outcome::unchanged;
      const Vertex_id* cv = m.vertex_ids(cur);
      int sx = -1;
      Vertex_id y = no_vertex;
      for(int s = 0; s < 4; ++s) {
        if(cv[s] == x) sx = s;
        else if(cv[s] != r.a && cv[s] != r.b) y = cv[s];
      }
      if(sx < 0 || y == no_vertex) return Outcome::unchanged;
      if(!own_vertex(y, w.partition) || !own_vertex(x, w.partition)) return Outcome::foreign;
      r.ring[r.n] = x;
      r.tets[r.n] = cur;
      ++r.n;
      if(cm_.is_constrained(cur, sx)) return Outcome::unchanged;
      cur = m.neighbor(cur, sx);
      x = y;
      if(cur == t) break;
    }
    if(r.n < 3 || x != r.ring[0]) return Outcome::unchanged;
    r.worst = 1;
    for(int s = 0; s < r.n; ++s) r.worst = std::min(r.worst, quality_of(r.tets[s]));
    return Outcome::found;
  }

  // Klincsek's dynamic programme over the ring polygon: best[i][j] is the
  // largest worst quality of a triangulation of ring[i..j], each triangle
  // (i, m, j) standing for the tetrahedra (a, i, m, j) and (i, m, j, b).
  // Only triangulations better than `floor` matter: a triangle whose
  // sub-polygons or first tetrahedron are no better is not measured
  // further, and the result is at most `floor` when none is better.
  double best_ring_triangulation(const Edge_ring& r, int split[max_ring_limit][max_ring_limit], double floor) const
  {
    const Flat_storage& m = cm_.mesh;
    double best[max_ring_limit][max_ring_limit];
    const double* pa = m.point(r.a);
    const double* pb = m.point(r.b);
    for(int len = 1; len < r.n; ++len)
      for(int i = 0; i + len < r.n; ++i) {
        const int j = i + len;
        if(len == 1) {
          best[i][j] = std::numeric_limits<double>::infinity();
          continue;
        }
        best[i][j] = -std::numeric_limits<double>::infinity();
        for(int mid = i + 1; mid < j; ++mid) {
          const double bar = std::max(best[i][j], floor);
          const double sub = std::min(best[i][mid], best[mid][j]);
          if(sub <= bar) continue;
          const double* pi = m.point(r.ring[i]);
          const double* pm = m.point(r.ring[mid]);
          const double* pj = m.point(r.ring[j]);
          const double above = std::min(sub, quality(pa, pi, pm, pj));
          if(above <= bar) continue;
          const double q = std::min(above, quality(pi, pm, pj, pb));
          if(q > best[i][j]) {
            best[i][j] = q;
            split[i][j] = mid;
          }
        }
      }
    return best[0][r.n - 1];
  }

  void ring_tetrahedra(const Edge_ring& r, const int split[max_ring_limit][max_ring_limit], int i, int j,
                       std::vector<std::array<Vertex_id, 4>>& out) const
  {
    if(j - i < 2) return;
    const int mid = split[i][j];
    out.push_back({r.a, r.ring[i], r.ring[mid], r.ring[j]});
    out.push_back({r.ring[i], r.ring[mid], r.ring[j], r.b});
    ring_tetrahedra(r, split, i, mid, out);
    ring_tetrahedra(r, split, mid, j, out);
  }

  Outcome remove_best_edge(Worker& w, Tet_id t)
  {
    bool foreign = false;
    Edge_ring best_ring, r;
    double best_gain = 0, best_quality = 0;
    int best_split[max_ring_limit][max_ring_limit], split[max_ring_limit][max_ring_limit];
    for(const auto& e : cell_edge_vertices) {
      const Outcome o = edge_ring(w, t, e[0], e[1], r, options_.max_ring);
      if(o == Outcome::foreign) foreign = true;
      if(o != Outcome::found) continue;
      const double q = best_ring_triangulation(r, split, r.worst + best_gain);
      if(q - r.worst > best_gain) {
        best_gain = q - r.worst;
        best_quality = q;
        best_ring = r;
        std::copy(&split[0][0], &split[0][0] + max_ring_limit * max_ring_limit, &best_split[0][0]);
      }
    }
    if(best_gain <= 0 || best_quality <= 0) return foreign ? Outcome::foreign : Outcome::unchanged;
    w.made.clear();
    ring_tetrahedra(best_ring, best_split, 0, best_ring.n - 1, w.made);
    if(!all_positive(w.made) || w.slots_left() < w.made.size()) return Outcome::unchanged;
    replace(w, best_ring.tets, best_ring.n, cm_.subdomain[t]);
    ++w.stats.edge_removals;
    return Outcome::improved;
  }

  // ------------------------------------------------------------ face removal (2-3)
  Outcome remove_best_facet(Worker& w, Tet_id t)
  {
    const Flat_storage& m = cm_.mesh;
    bool foreign = false;
    int best_facet = -1;
    double best_quality = 0;
    std::array<Vertex_id, 4> best_made[3];
    const Vertex_id* tv = m.vertex_ids(t);
    for(int i = 0; i < 4; ++i) {
      if(cm_.is_constrained(t, i)) continue;
      const Tet_id u = m.neighbor(t, i);
      if(!is_volume(u) || cm_.subdomain[u] != cm_.subdomain[t]) continue;
      const Vertex_id q = m.vertex(u, facet_of(m.neighbor_code(t, i)));
      if(!own_vertex(q, w.partition)) {
        foreign = true;
        continue;
      }
      const double worst = std::min(quality_of(t), quality_of(u));
      std::array<Vertex_id, 4> made[3];
      double quality = 1;
      for(int k = 0, c = 0; k < 4; ++k) {
        if(k == i) continue;
        for(int s = 0; s < 4; ++s) made[c][s] = tv[s];
        made[c][k] = q;
        quality = std::min(quality, quality_of(made[c].data()));
        ++c;
      }
      if(quality > worst && quality > best_quality) {
        best_facet = i;
        best_quality = quality;
        std::copy(made, made + 3, best_made);
      }
    }
    if(best_facet < 0) return foreign ? Outcome::foreign : Outcome::unchanged;
    w.made.assign(best_made, best_made + 3);
    if(!all_positive(w.made) || w.slots_left() < 1) return Outcome::unchanged;
    const Tet_id region[2] = {t, m.neighbor(t, best_facet)};
    replace(w, region, 2, cm_.subdomain[t]);
    ++w.stats.face_removals;
    return Outcome::improved;
  }

  // ------------------------------------------------------------ relocation
  // The tetrahedra around v, all of them its partition's, in w.ball.
  Outcome collect_ball(Worker& w, Vertex_id v) const
  {
    const Flat_storage& m = cm_.mesh;
    w.ball.clear();
    const Tet_id start = incident_[v];
    if(start == no_tet || !is_volume(start)) return Outcome::unchanged;
    w.ball.push_back(start);
    for(std::size_t k = 0; k < w.ball.size(); ++k) {
      const Tet_id t = w.ball[k];
      if(!owned_by(t, w.partition)) return Outcome::foreign;
      const Vertex_id* tv = m.vertex_ids(t);
      for(int f = 0; f < 4; ++f) {
        if(tv[f] == v) continue; // the facet opposite v does not hold it
        const Tet_id u = m.neighbor(t, f);
        if(std::find(w.ball.begin(), w.ball.end(), u) != w.ball.end()) continue;
        if(w.ball.size() == max_ball) return Outcome::unchanged;
        w.ball.push_back(u);
      }
    }
    return Outcome::found;
  }

  // The corner of tv: p in place of v (which need not have a record yet).
  const double* corner(Vertex_id id, Vertex_id v, const double* p) const
  {
    return id == v ? p : cm_.mesh.point(id);
  }

  // The quality of tetrahedron tv with v at p.
  double quality_with(const std::array<Vertex_id, 4>& tv, Vertex_id v, const double* p) const
  {
    return quality(corner(tv[0], v, p), corner(tv[1], v, p), corner(tv[2], v, p), corner(tv[3], v, p));
  }

  // The worst quality of `ball` with v at p (v's record is not changed), or
  // any value at most `enough` once it is known to be at most that: a
  // candidate position fails on its first tetrahedron no better than the
  // best so far, and the worst ones come first.
  double ball_quality(const std::vector<std::array<Vertex_id, 4>>& ball, Vertex_id v, const double* p,
                      double enough = 0) const
  {
    double worst = 1;
    for(const auto& tv : ball) {
      worst = std::min(worst, quality_with(tv, v, p));
      if(worst <= enough) return worst;
    }
    return worst;
  }

  // Exact: every tetrahedron of `ball` positive with v at p.
  bool ball_positive(const std::vector<std::array<Vertex_id, 4>>& ball, Vertex_id v, const double* p) const
  {
    for(const auto& tv : ball)
      if(orientation(corner(tv[0], v, p), corner(tv[1], v, p), corner(tv[2], v, p), corner(tv[3], v, p)) <= 0)
        return false;
    return true;
  }

  // Where the slot-s corner of positive tetrahedron tv would make it
  // regular on its opposite facet: above the facet's centroid, at the
  // height of the regular tetrahedron with the facet's mean edge, on the
  // side positive orientation asks for.
  void regular_apex(const Vertex_id* tv, int s, double* out) const
  {
    const Flat_storage& m = cm_.mesh;
    // (tv[s], facet_vertex[s]...) is an even permutation of the slots, so positive.
    const double* x = m.point(tv[facet_vertex[s][0]]);
    const double* y = m.point(tv[facet_vertex[s][1]]);
    const double* z = m.point(tv[facet_vertex[s][2]]);
    double e1[3], e2[3], n[3];
    for(int a = 0; a < 3; ++a) {
      e1[a] = y[a] - x[a];
      e2[a] = z[a] - x[a];
    }
    quality_detail::cross(e1, e2, n);
    const double nn = quality_detail::norm(n);
    const double edge = (distance(x, y) + distance(y, z) + distance(z, x)) / 3;
    // orientation(v, x, y, z) > 0 means (v - x) . n < 0.
    const double height = nn > 0 ? -std::sqrt(2.0 / 3.0) * edge / nn : 0;
    for(int a = 0; a < 3; ++a) out[a] = (x[a] + y[a] + z[a]) / 3 + height * n[a];
  }

  // A tetrahedron of the position search: its corners, the regular apex of
  // its facet opposite the moving vertex (which does not move with it), and
  // its quality with that vertex where the search stands.
  struct Search_tet
  {
    double quality;
    double apex[3];
    std::array<Vertex_id, 4> corners;
  };

  // t.apex for the slot of tetrahedron t.corners that holds v.
  void set_apex(Search_tet& t, Vertex_id v) const
  {
    int s = 0;
    while(t.corners[s] != v) ++s;
    regular_apex(t.corners.data(), s, t.apex);
  }

  // The search for v's position in `ball` (reordered), from `start`: toward the weighted
  // mean of the regular apexes (weight 1 / quality, so the bad tetrahedra pull
  // hardest), toward the worst tetrahedron's apex, and (only if it does
  // better) toward the neighbours' mean (Laplacian), halving each step until
  // the worst quality goes up; each of `rounds` rounds starts where the last
  // one ended.  Returns the worst quality at `best` (start's if nothing helps).
  // The tetrahedra are ordered worst first at `start`, so that a candidate
  // position fails on its first tetrahedron no better than the best so far.
  // `tets`: the caller's search tetrahedra of `ball`, in its order, with
  // their apexes set (they are reordered with it), for searches of one ball
  // from several starts; null: found here.  `at_start`: ball_quality(ball,
  // v, start) of the ball in its order on entry.
  // Each apex and each quality at a round's start is computed once: they
  // were most of the improvement's time.
  double best_position(std::vector<std::array<Vertex_id, 4>>& ball, Vertex_id v, const double* start,
                       int rounds, double* best, Search_tet* tets = nullptr, double* at_start = nullptr) const
  {
    const std::size_t n = ball.size();
    CGAL_assertion(n <= max_ball);
    Search_tet own[max_ball];
    if(tets == nullptr) {
      tets = own;
      for(std::size_t k = 0; k < n; ++k) {
        tets[k].corners = ball[k];
        set_apex(tets[k], v);
      }
    }
    double worst_in_order = 1;
    for(std::size_t k = 0; k < n; ++k) {
      tets[k].quality = quality_with(tets[k].corners, v, start);
      if(worst_in_order > 0) worst_in_order = std::min(worst_in_order, tets[k].quality);
    }
    if(at_start) *at_start = worst_in_order;
    std::sort(tets, tets + n, [](const Search_tet& x, const Search_tet& y) {
      return x.quality != y.quality ? x.quality < y.quality : x.corners < y.corners;
    });
    for(std::size_t k = 0; k < n; ++k) ball[k] = tets[k].corners;
    std::copy(start, start + 3, best);
    double best_quality = n > 0 ? std::min(1.0, tets[0].quality) : 1;
    for(int round = 0; round < rounds; ++round) {
      const double here[3] = {best[0], best[1], best[2]};
      if(round > 0)
        for(std::size_t k = 0; k < n; ++k) tets[k].quality = quality_with(tets[k].corners, v, here);
      double targets[3][3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
      double weight_sum = 0, worst_quality = 2;
      std::size_t neighbours = 0;
      for(std::size_t k = 0; k < n; ++k) {
        const Search_tet& t = tets[k];
        const double g = t.quality;
        const double weight = 1 / std::max(g, 1e-3);
        for(int a = 0; a < 3; ++a) targets[0][a] += weight * t.apex[a];
        weight_sum += weight;
        if(g < worst_quality) {
          worst_quality = g;
          std::copy(t.apex, t.apex + 3, targets[1]);
        }
        for(int i = 0; i < 4; ++i)
          if(t.corners[i] != v) {
            for(int a = 0; a < 3; ++a) targets[2][a] += cm_.mesh.point(t.corners[i])[a];
            ++neighbours;
          }
      }
      for(int a = 0; a < 3; ++a) {
        targets[0][a] /= weight_sum;
        targets[2][a] /= double(neighbours);
      }
      const double quality_before = best_quality;
      for(const auto& target : targets) {
        for(double step = 1; step >= 1.0 / 16; step /= 2) {
          double p[3];
          for(int a = 0; a < 3; ++a) p[a] = here[a] + step * (target[a] - here[a]);
          const double q = ball_quality(ball, v, p, best_quality);
          if(q > best_quality) {
            best_quality = q;
            std::copy(p, p + 3, best);
            break;
          }
        }
      }
      if(!(best_quality > quality_before)) break;
    }
    return best_quality;
  }

  Outcome relocate(Worker& w, Vertex_id v)
  {
    const Outcome ball = collect_ball(w, v);
    if(ball != Outcome::found) return ball;
    Flat_storage& m = cm_.mesh;
    w.ball_corners.clear();
    for(Tet_id t : w.ball) {
      const Vertex_id* tv = m.vertex_ids(t);
      w.ball_corners.push_back({tv[0], tv[1], tv[2], tv[3]});
    }
    const double here[3] = {m.point(v)[0], m.point(v)[1], m.point(v)[2]};
    double best[3], worst;
    const double best_quality = best_position(w.ball_corners, v, here, 1, best, nullptr, &worst);
    // A move must gain 1%: smaller gains do not change the mesh's figures,
    // but they keep the vertices around active pass after pass.
    if(!(best_quality > 1.01 * worst) || !ball_positive(w.ball_corners, v, best)) return Outcome::unchanged;
    std::copy(best, best + 3, m.vertices[v].xyz);
    // h belongs to the position: the user's bounds at the new one.
    cm_.size[v] = cm_.size.bounded(cm_.size[v], best, cm_.subdomain[w.ball.front()]);
    for(Tet_id t : w.ball) set_shape(t);
    mark_changed(w.ball_corners);
    w.reshaped.insert(w.reshaped.end(), w.ball.begin(), w.ball.end());
    ++w.stats.relocations;
    return Outcome::improved;
  }

  // ------------------------------------------------------------ Steiner points
  // The best split found so far: the region it replaces, the tetrahedra it
  // makes with the new vertex, where that vertex goes and its size.
  struct Split
  {
    double gain = 0;
    double quality = 0; // the worst of `made` with the new vertex at `point`
    double point[3];
    std::vector<std::array<Vertex_id, 4>> made;
    Tet_id region[max_steiner_region];
    std::size_t region_size = 0;
    double size = 0;
  };

  // How many of `tets` are bad with vertex c at p.
  std::size_t bad_count(const std::vector<std::array<Vertex_id, 4>>& tets, Vertex_id c, const double* p) const
  {
    std::size_t n = 0;
    for(const auto& tv : tets)
      n += quality_with(tv, c, p) < options_.quality_threshold ? 1 : 0;
    return n;
  }

  // One split: `region` becomes w.made, whose new vertex c is placed by the
  // position search from `start` and from a point further in; kept in
  // `best` if it gains more than the best so far.
  // A split may leave at most two more bad tetrahedra than it removes
  // (they are better than the one it removes), unless it removes a true
  // sliver (below): where the walls are thinner than the surface
  // triangles, a new vertex would otherwise trade one sliver for many.
  // (On CGAL's data, no slack at all kept fandisk's worst sliver, 0.06
  // degrees, where two give 6.7 degrees; four grew couplingdown's bad
  // tetrahedra by a fifth.)
  void consider_split(Worker& w, Vertex_id c, const Tet_id* region, std::size_t region_size, const double* start,
                      double size, Split& best) const
  {
    double worst = 1;
    std::size_t bad_in_region = 0;
    for(std::size_t k = 0; k < region_size; ++k) {
      const double g = quality_of(region[k]);
      worst = std::min(worst, g);
      bad_in_region += g < options_.quality_threshold ? 1 : 0;
    }
    // A heuristic bound: no position of c makes a tetrahedron much better
    // than the one with c at the regular apex of its facet opposite c (not
    // exactly the best: an obtuse facet does a little better above its
    // circumcentre); if the worst of those cannot beat the best split so
    // far, the searches are not run.
    // The apexes are the searches' too.
    CGAL_assertion(w.made.size() <= max_ball);
    Search_tet tets[max_ball];
    double ceiling = 1;
    for(std::size_t k = 0; k < w.made.size(); ++k) {
      Search_tet& t = tets[k];
      t.corners = w.made[k];
      set_apex(t, c);
      ceiling = std::min(ceiling, quality_with(t.corners, c, t.apex));
      if(ceiling - worst <= best.gain) return;
    }
    // Two starts: the given one (the split simplex's centre, or a facet's
    // regular apex), and halfway from it to the centre of the new
    // tetrahedra's other corners.  Where the region is a flat sliver
    // between two surface triangles, a midpoint lies on the surface's
    // near-plane and the search from it stays flat; the second start is
    // inside.
    double centre[3] = {0, 0, 0};
    std::size_t corners = 0;
    for(const auto& tv : w.made)
      for(Vertex_id v : tv)
        if(v != c) {
          for(int a = 0; a < 3; ++a) centre[a] += cm_.mesh.point(v)[a];
          ++corners;
        }
    double inner[3];
    for(int a = 0; a < 3; ++a) inner[a] = (start[a] + centre[a] / double(corners)) / 2;
    double p[3], p_inner[3];
    double q = best_position(w.made, c, start, candidate_search_rounds, p, tets);
    if(q < options_.quality_threshold) {
      const double q_inner = best_position(w.made, c, inner, candidate_search_rounds, p_inner, tets);
      if(q_inner > q) {
        q = q_inner;
        std::copy(p_inner, p_inner + 3, p);
      }
    }
    // A true sliver (quality under a quarter of the threshold) may go for
    // any number of tetrahedra at half the threshold or better (fandisk,
    // 2 threads: gamma 0.0006 for five at 0.21 or better); a region's
    // worst may go for any number at 0.8 of the threshold or better if
    // that raises it by a quarter (bunny00, 2 threads: the last bad one,
    // 8.95 degrees, between two surface triangles, for four of quality
    // 0.26, 13 degrees or more), not for less: a tetrahedron just under
    // the threshold would be traded for several (torus, target 20
    // degrees: one left at 19.93 degrees).
    const bool removes_a_sliver = worst < options_.quality_threshold / 4 && q >= options_.quality_threshold / 2;
    const bool nearly_good = q >= 0.8 * options_.quality_threshold && q >= 1.25 * worst;
    if(q > 0 && q - worst > best.gain &&
       (removes_a_sliver || nearly_good || bad_count(w.made, c, p) <= bad_in_region + 2)) {
      best.gain = q - worst;
      best.quality = q;
      std::copy(p, p + 3, best.point);
      best.made = w.made;
      std::copy(region, region + region_size, best.region);
      best.region_size = region_size;
      best.size = size;
    }
  }

  // The tetrahedra joining vertex c to the boundary facets of `region`
  // (distinct tetrahedra of one subdomain, connected through facets), each
  // made from its tetrahedron with c in place of the vertex opposite the
  // facet, so that c on the inner side makes it positive.  If all of them
  // are positive, they fill the region exactly (the cone and the region
  // have the same boundary), so the region is a ball and every new facet
  // through c has two tetrahedra.  What positivity does not see is a vertex
  // inside the region and on none of its boundary facets: the mesh mostly
  // is not Delaunay any more, so a cavity grown by spheres may hold a whole
  // vertex star, and the cone would drop that vertex.  False then, and
  // when a facet inside the region is constrained (an input triangle would
  // go).
  bool star_of_region(Worker& w, const Tet_id* region, std::size_t region_size, Vertex_id c)
  {
    CGAL_precondition(w.may_add_vertices); // the stamps are not per partition
    const Flat_storage& m = cm_.mesh;
    w.made.clear();
    if(boundary_stamp_.size() < m.vertices.size()) boundary_stamp_.resize(m.vertices.size(), 0);
    if(++stamp_ == 0) {
      std::fill(boundary_stamp_.begin(), boundary_stamp_.end(), 0);
      stamp_ = 1;
    }
    for(std::size_t k = 0; k < region_size; ++k) {
      const Vertex_id* sv = m.vertex_ids(region[k]);
      for(int f = 0; f < 4; ++f) {
        const Tet_id u = m.neighbor(region[k], f);
        if(std::find(region, region + region_size, u) != region + region_size) {
          if(cm_.is_constrained(region[k], f)) return false;
          continue;
        }
        std::array<Vertex_id, 4> q = {sv[0], sv[1], sv[2], sv[3]};
        q[f] = c;
        w.made.push_back(q);
        for(int i = 0; i < 3; ++i) boundary_stamp_[sv[facet_vertex[f][i]]] = stamp_;
      }
    }
    for(std::size_t k = 0; k < region_size; ++k) {
      const Vertex_id* sv = m.vertex_ids(region[k]);
      for(int i = 0; i < 4; ++i)
        if(boundary_stamp_[sv[i]] != stamp_) return false;
    }
    return true;
  }

  // How a Steiner cavity grows from t across unconstrained facets of its
  // subdomain: to the tetrahedra whose circumscribed spheres hold the new
  // point (Bowyer-Watson), or across every boundary facet whose cone to
  // the point would be under the threshold (the cavity a point needs to see
  // its boundary well, which the spheres of a mesh no longer Delaunay do
  // not give).
  enum class Cavity_rule { spheres, quality };

  // region[0] = t on entry; returns the region's size.
  std::size_t grow_cavity(const Worker& w, Tet_id t, const double* p, Cavity_rule rule, Tet_id* region,
                          bool& foreign) const
  {
    const Flat_storage& m = cm_.mesh;
    std::size_t region_size = 1;
    for(std::size_t k = 0; k < region_size && region_size < max_steiner_region; ++k) {
      const Vertex_id* kv = m.vertex_ids(region[k]);
      for(int g = 0; g < 4 && region_size < max_steiner_region; ++g) {
        if(cm_.is_constrained(region[k], g)) continue;
        const Tet_id u = m.neighbor(region[k], g);
        if(!is_volume(u) || cm_.subdomain[u] != cm_.subdomain[t]) continue;
        if(std::find(region, region + region_size, u) != region + region_size) continue;
        const Vertex_id* uv = m.vertex_ids(u);
        if(!own_vertex(uv[0], w.partition) || !own_vertex(uv[1], w.partition) || !own_vertex(uv[2], w.partition) ||
           !own_vertex(uv[3], w.partition)) {
          foreign = true;
          continue;
        }
        const bool grows =
            rule == Cavity_rule::spheres
                ? side_of_oriented_sphere(m.point(uv[0]), m.point(uv[1]), m.point(uv[2]), m.point(uv[3]), p) > 0
                : quality(g == 0 ? p : m.point(kv[0]), g == 1 ? p : m.point(kv[1]), g == 2 ? p : m.point(kv[2]),
                          g == 3 ? p : m.point(kv[3])) < options_.quality_threshold;
        if(grows) region[region_size++] = u;
      }
    }
    return region_size;
  }

  // The best split of an interior edge or facet of t by a new vertex, or
  // the best cavity around one of its facets' regular apexes, if it raises
  // the worst quality of the region it replaces.  The new vertex is interior
  // (no constrained facet is in the region's inside), gets the mean size of
  // the split simplex's vertices (of t's, for a cavity), and may be
  // relocated later.  Only the sequential step comes here (a new vertex
  // grows arrays the partitions share), so the ownership tests below
  // always pass there; they keep the code right if that changes.
  Outcome add_steiner_point(Worker& w, Tet_id t)
  {
    Flat_storage& m = cm_.mesh;
    // A tetrahedron no split helped is not searched again in a later pass
    // (its surroundings rarely change, and the search is the costly part).
    std::array<Vertex_id, 4> key;
    std::copy(m.vertex_ids(t), m.vertex_ids(t) + 4, key.begin());
    std::sort(key.begin(), key.end());
    if(std::binary_search(no_split_helped_.begin(), no_split_helped_.end(), key)) return Outcome::unchanged;
    const Vertex_id c = static_cast<Vertex_id>(m.vertices.size());
    bool foreign = false;
    Split best;
    Edge_ring r;
    // The first split that leaves no bad tetrahedron ends the search: the
    // position searches are most of the improvement's time.
    auto region_is_good = [&] { return best.quality >= options_.quality_threshold; };
    for(const auto& e : cell_edge_vertices) {
      if(region_is_good()) break;
      const Outcome o = edge_ring(w, t, e[0], e[1], r, max_ring_limit);
      foreign |= o == Outcome::foreign;
      if(o != Outcome::found) continue;
      // Each (a, b, x, y) of the ring becomes (c, b, x, y) and (a, c, x, y).
      w.made.clear();
      for(int i = 0; i < r.n; ++i) {
        const Vertex_id x = r.ring[i], y = r.ring[(i + 1) % r.n];
        w.made.push_back({c, r.b, x, y});
        w.made.push_back({r.a, c, x, y});
      }
      double mid[3];
      for(int a = 0; a < 3; ++a) mid[a] = (m.point(r.a)[a] + m.point(r.b)[a]) / 2;
      consider_split(w, c, r.tets, static_cast<std::size_t>(r.n), mid, (cm_.size[r.a] + cm_.size[r.b]) / 2, best);
    }
    const Vertex_id* tv = m.vertex_ids(t);
    for(int f = 0; f < 4 && !region_is_good(); ++f) {
      if(cm_.is_constrained(t, f)) continue;
      const Tet_id u = m.neighbor(t, f);
      if(!is_volume(u) || cm_.subdomain[u] != cm_.subdomain[t]) continue;
      const Vertex_id* uv = m.vertex_ids(u);
      const int g = facet_of(m.neighbor_code(t, f)); // u's slot opposite the facet
      if(!own_vertex(uv[g], w.partition)) {
        foreign = true;
        continue;
      }
      // Each tetrahedron of the pair gives three, c in place of one of the
      // facet's corners in turn: the cone over the pair's six outer facets.
      const Tet_id region[2] = {t, u};
      const bool cone = star_of_region(w, region, 2, c);
      CGAL_assertion(cone); // the shared facet is not constrained, and all five vertices are outer
      (void)cone;
      double centroid[3] = {0, 0, 0};
      double size = 0;
      for(int i = 0; i < 3; ++i) {
        const Vertex_id x = tv[facet_vertex[f][i]];
        for(int a = 0; a < 3; ++a) centroid[a] += m.point(x)[a] / 3;
        size += cm_.size[x] / 3;
      }
      consider_split(w, c, region, 2, centroid, size, best);
    }
    // A vertex where a facet of t would have its regular apex (on t's
    // side), joined to the boundary of a cavity grown from t across
    // unconstrained facets (grow_cavity), which stops at the surface.
    // Where t lies flat on the surface, with two surface triangles at a
    // nearly flat edge, its only interior edge and facets lie near the
    // surface too, and no split of them takes the new vertex deep enough;
    // the cavity reaches the tetrahedra behind them.  (Elephant, 1 thread,
    // gamma alone: 69 tetrahedra left under gamma 0.3 without cavities, 11
    // with Bowyer-Watson ones, 1 with both rules; bunny00 27 and 1 for the
    // last two, its smallest dihedral angle 4.2 and 8.8 degrees.)
    double corners_size = 0;
    for(int i = 0; i < 4; ++i) corners_size += cm_.size[tv[i]] / 4;
    // Two rules or two apexes often give the same region; it is searched
    // once, from the first apex that gave it (a start lost, time saved).
    std::vector<std::vector<Tet_id>> cavities_tried; // sorted
    for(int f = 0; f < 4 && !region_is_good(); ++f) {
      double apex[3];
      regular_apex(tv, f, apex);
      for(const Cavity_rule rule : {Cavity_rule::spheres, Cavity_rule::quality}) {
        if(region_is_good()) break;
        Tet_id region[max_steiner_region] = {t};
        const std::size_t region_size = grow_cavity(w, t, apex, rule, region, foreign);
        std::vector<Tet_id> sorted(region, region + region_size);
        std::sort(sorted.begin(), sorted.end());
        if(std::find(cavities_tried.begin(), cavities_tried.end(), sorted) != cavities_tried.end()) continue;
        cavities_tried.push_back(std::move(sorted));
        // t alone would be a 1-4 split of t from inside it, which cannot
        // make a sliver's four corners into good tetrahedra.
        if(region_size < 2 || !star_of_region(w, region, region_size, c)) continue;
        consider_split(w, c, region, region_size, apex, corners_size, best);
      }
    }
    if(best.gain <= 0) {
      if(!foreign) no_split_helped_.insert(std::upper_bound(no_split_helped_.begin(), no_split_helped_.end(), key), key);
      return foreign ? Outcome::foreign : Outcome::unchanged;
    }
    {
      double p[3];
      if(best_position(best.made, c, best.point, chosen_search_rounds, p) > best.quality &&
         bad_count(best.made, c, p) <= bad_count(best.made, c, best.point))
        std::copy(p, p + 3, best.point);
    }
    if(!ball_positive(best.made, c, best.point)) return Outcome::unchanged;
    if(w.slots_left() + best.region_size < best.made.size()) grow_fresh_range(w, best.made.size());
    Vertex_record record;
    std::copy(best.point, best.point + 3, record.xyz);
    record.scratch = 0;
    m.vertices.push_back(record);
    cm_.size.push_back(cm_.size.bounded(best.size, best.point, cm_.subdomain[t]));
    on_surface_.push_back(0);
    incident_.push_back(no_tet);
    partition_of_vertex_.push_back(w.partition);
    active_.push_back(1);
    changed_.push_back(1);
    w.made = best.made;
    replace(w, best.region, best.region_size, cm_.subdomain[t]);
    ++w.stats.steiner_points;
    return Outcome::improved;
  }

  Constrained_mesh& cm_;
  Improvement_options options_;
  std::vector<std::uint8_t> on_surface_;
  std::vector<Tet_id> incident_;
  std::vector<std::uint8_t> partition_of_vertex_;
  std::vector<Tet_id> need_steiner_; // gathered from the partitions' workers
  // star_of_region's scratch (the sequential step's only): per vertex, the
  // number of the last call that met it on a boundary facet.
  std::vector<std::uint32_t> boundary_stamp_;
  std::uint32_t stamp_ = 0;
  double dihedral_scale_ = 0; // quality_threshold / sin(min_dihedral_target); 0: gamma alone
  bool steiner_phase_ = false;
  bool every_bad_tetrahedron_ = true; // the pass works on inactive ones too
  std::vector<std::uint8_t> active_, changed_; // per vertex: changed in the last pass, in this one
  std::vector<Tet_id> reshaped_;               // slots written or with a corner moved in this pass
  std::vector<std::uint64_t> vertex_keys_;     // see vertex_keys()
  int key_grid_bits_ = 0;
  std::vector<Shape> shape_;                   // per slot, see quality_of(Tet_id)
  std::vector<std::array<Vertex_id, 4>> no_split_helped_; // sorted corners, in order
  static constexpr Tet_id no_tet = ~Tet_id(0);
};

// Improves the volumes of `cm` in place (its input triangles and subdomains
// kept); the statistics say what was done and what is left.
inline Improvement_statistics improve_mesh(Constrained_mesh& cm, const Improvement_options& options)
{
  return Mesh_improvement(cm, options).run();
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_MESH_IMPROVEMENT_H
