// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Moore-partitioned, lock-free parallel insertion (paper §3).
//
// The points of a BRIO round are cut into `partitions` runs of equal size
// along the Moore curve; every vertex of the mesh belongs to the partition
// whose key range holds its own Moore key.  Each partition is inserted by one
// task with the ordinary kernel, restricted to the tetrahedra it owns: those
// with all their vertices in its partition (Partition_ownership, stricter than
// the paper's rule; its walks go around the tetrahedra they may not enter).
// An insertion whose walk or cavity cannot avoid another tetrahedron is
// aborted and kept for the next attempt.  Later attempts change the
// partitions with a new coordinate transform of the curve's grid and a
// circular shift of the curve (§3.3); points whose median lies off the
// middle of the box are cut by median planes instead in the first attempt
// (and in the retry of 2 partitions).  The number of partitions halves when
// fewer than 1/5 of the attempts succeed or fewer than
// `min_points_per_partition` points per partition remain, down to a
// sequential finish (§3.4).  The first BRIO round is always sequential.
// Vertices that BRIO sorted on the engine's grid get their partition from
// that order (a few binary searches per attempt on the plain curve and its
// shifts) rather than from one Moore key each per attempt.
//
// Memory (§3.6): before an attempt the arrays get room for every partition's
// worst case, and each partition takes fresh slots from its own fixed range,
// so no array moves while tasks run (each partition maps the pages of its
// range a step ahead of their use) and the slots a partition uses do not
// depend on scheduling: the result is the same cell for cell for the same
// input, seed and partition count, whatever the thread count.  Tasks run in
// the caller's TBB arena, so tbb::global_control and tbb::task_arena limit
// the threads as they do for CGAL's parallel triangulation.
//
// What happens to one point is a policy (Delaunay_point_insertion: the
// kernel's insert); the mesher's refinement (paper §4) passes its own, with
// constrained, star-shaped cavities, and reuses everything else here.

#ifndef CGAL_FDT3_INTERNAL_PARALLEL_INSERTION_H
#define CGAL_FDT3_INTERNAL_PARALLEL_INSERTION_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Moore_curve.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <random>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// One attempt of the partitioned insertion: the paper's Table 2 row.
struct Partition_round
{
  std::size_t points = 0;          // points tried
  std::size_t inserted = 0;        // inserted (duplicates included)
  int partitions = 1;              // 1: sequential
  std::size_t mesh_vertices = 0;   // vertices in the mesh before the attempt
  // Barrier engine (Barrier_insertion.h; `partitions` holds its runs):
  // cavities searched again in a later iteration because a run of smaller
  // index claimed one of their tetrahedra.
  std::size_t retried = 0;
  // Partitions cut by median planes instead of the curve (see
  // Partitioned_insertion::off_centre_median).
  bool plane_cut = false;
  double seconds = 0;
};

// Fresh tetrahedron slots of one partition: its own free list first, then a
// fixed range of new slots reserved for it before the tasks start.  The
// pages of the range are mapped a step ahead of their first use, in one
// system call per step (Raw_array::prefault): concurrent page faults of two
// threads contend in the kernel, and mapping the whole range at once would
// make the slack reserved for a worst case resident (points on a sphere use
// 3 of the 7 slots per point).
struct Partition_slots
{
  static constexpr Tet_id map_step = Tet_id(1) << 16;

  std::vector<Tet_id>* free;
  Tet_id next_fresh, end_fresh;
  Raw_array<Tet_record>* tets = nullptr; // null: no mapping ahead
  Tet_id mapped_end = 0;

  bool reserve(std::size_t n) const
  {
    return free->size() + static_cast<std::size_t>(end_fresh - next_fresh) >= n;
  }
  Tet_id take()
  {
    if(!free->empty()) {
      const Tet_id t = free->back();
      free->pop_back();
      return t;
    }
    CGAL_assertion(next_fresh < end_fresh);
    if(next_fresh >= mapped_end) map_ahead();
    return next_fresh++;
  }
  void map_ahead()
  {
    mapped_end = std::min<Tet_id>(end_fresh, next_fresh + map_step);
    if(tets != nullptr) tets->prefault(next_fresh, mapped_end);
  }
  void give(Tet_id t) { free->push_back(t); }
};

// The per-point step of Partitioned_insertion, here the Delaunay kernel's.
// A policy provides
//   Kernel<Ownership, Slots, Paths>
//                              the kernel a partition (or the sequential
//                              finish) runs, with the predicates' forms
//                              Paths (chosen once per run of points);
//   prepare(partitions, slots) called before the kernels run: room for
//                              `partitions` concurrent users and per-slot
//                              data for `slots` tetrahedron slots;
//   insert(kernel, partition, v, hint, duplicate_of, next)
//                              one point, inside a task: may only touch what
//                              the kernel owns; `aborted` means try again
//                              in a later attempt; `next` is the point that
//                              follows v in its run (or null).
struct Delaunay_point_insertion
{
  template <class Ownership, class Slots, class Paths = Default_paths>
  using Kernel = Delaunay_kernel<Ownership, Slots, Walk_to_the_end, Paths>;

  void prepare(int, std::size_t) {}

  template <class K>
  Insertion_result insert(K& kernel, int, Vertex_id v, Tet_id& hint, Vertex_id& duplicate_of, const double* next)
  {
    return kernel.insert(v, hint, duplicate_of, next);
  }
};

class Partitioned_insertion
{
public:
  // Paper §3.4's threshold; a setter lowers it where batches are small
  // (the mesher's tests, to run the partitions at all).
  static constexpr std::size_t default_min_points_per_partition = 3000;
  static constexpr std::size_t retry_mesh_ratio = 32;
  // Fresh tetrahedron slots reserved per point of a partition: a Delaunay
  // tetrahedralization has about 6.7 tetrahedra per vertex, so 7 leaves a
  // little slack; a partition that runs out aborts its remaining points like
  // any other conflict.  The slots a partition leaves unused are marked free,
  // which touches their pages: a larger margin costs resident memory.
  static constexpr std::size_t fresh_slots_per_point = 7;

  Partitioned_insertion(Flat_storage& mesh, const Static_filter& filter,
                        const Sub_determinant_filter& sub_filter, const double box_lo[3],
                        const double box_hi[3], std::uint64_t seed, bool timed)
      : m_(mesh), filter_(filter), sub_filter_(sub_filter), seed_(seed), timed_(timed)
  {
    for(int a = 0; a < 3; ++a) {
      lo_[a] = box_lo[a];
      hi_[a] = box_hi[a];
    }
  }

  // Inserts `points` (vertex ids whose records are written) with up to
  // `partitions` concurrent partitions.  duplicate_of[v - first_new] receives
  // the existing vertex for a duplicate.  Appends one row per attempt to
  // `rounds` and the kernels' counters to `stats`.
  void insert(std::vector<Vertex_id> points, int partitions, Vertex_id first_new,
              std::vector<Vertex_id>& duplicate_of, Tet_id& hint, std::vector<Partition_round>& rounds,
              Kernel_statistics& stats)
  {
    Delaunay_point_insertion delaunay;
    insert(std::move(points), partitions, first_new, duplicate_of, hint, rounds, stats, delaunay);
  }

  // The same with another per-point step (see Delaunay_point_insertion);
  // a point the policy rejects counts as settled, like an inserted one.
  template <class Policy>
  void insert(std::vector<Vertex_id> points, int partitions, Vertex_id first_new,
              std::vector<Vertex_id>& duplicate_of, Tet_id& hint, std::vector<Partition_round>& rounds,
              Kernel_statistics& stats, Policy& policy)
  {
    int attempt = 0;
    settled_ = 0;
    while(!points.empty()) {
      while(partitions > 1 && points.size() < min_points_per_partition_ * std::size_t(partitions))
        partitions /= 2;
      // A retry pays a fixed price proportional to the vertex keys it computes
      // (every mesh vertex's, unless sorted runs spare them) and gains at most
      // a share of its few points' insertion time: past this ratio the
      // sequential finish is faster.  Kept keys (keep_vertex_keys) are
      // charged as if computed, so that keeping them never changes a mesh.
      const bool rotated = partitions > 1 && rotation_of_sorted_run(points, attempt, partitions);
      if(attempt > 0 && partitions > 1 && !by_plane(attempt, partitions) &&
         points.size() * retry_mesh_ratio < keys_to_compute(points, rotated))
        partitions = 1;
      Partition_round row;
      row.points = points.size();
      row.partitions = partitions;
      row.mesh_vertices = vertices_in_mesh_;
      const auto t0 = std::chrono::steady_clock::now();
      if(partitions <= 1) {
        insert_sequentially(points, first_new, duplicate_of, hint, stats, policy);
        row.inserted = row.points;
        points.clear();
      } else {
        std::vector<Vertex_id> failed;
        if(attempt == 0) plane_cuts_ = off_centre_median(points);
        row.plane_cut = by_plane(attempt, partitions);
        insert_partitioned(points, partitions, attempt++, rotated, first_new, duplicate_of, failed, stats, policy);
        row.inserted = points.size() - failed.size();
        points.swap(failed);
        if(5 * row.inserted < row.points) partitions /= 2;
      }
      vertices_in_mesh_ += row.inserted;
      settled_ += row.inserted;
      if(progress_) progress_(settled_);
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      rounds.push_back(row);
    }
    if(!m_.is_live(hint)) hint = m_.first_live_tet();
  }

  void set_vertices_in_mesh(std::size_t n) { vertices_in_mesh_ = n; }
  // Every vertex of the mesh has an id below max(n, the ids of the points
  // being inserted): the partitions of the records above are not computed.
  // The default is every record.
  void set_vertex_end(std::size_t n) { vertex_end_ = n; }
  // Vertex id ranges [first, second) whose points are in the order of the
  // plain Moore curve of this engine's grid (BRIO rounds sorted on the same
  // box, whose finer keys nest the engine's): along such a run the
  // partition of a vertex, and the cut of points taken from it in order,
  // follow from a few keys found by binary search, on the plain curve and
  // on its circular shifts, instead of one key per vertex per attempt.
  typedef std::pair<Vertex_id, Vertex_id> Vertex_range;
  void set_sorted_runs(std::vector<Vertex_range> runs) { sorted_runs_ = std::move(runs); }
  void set_min_points_per_partition(std::size_t n) { min_points_per_partition_ = std::max<std::size_t>(n, 1); }
  // The plain curve's key of each vertex record, computed once and kept
  // while this engine lives, for the attempts whose curve is the plain one
  // shifted (both first attempts of 2 partitions, the first of more): the
  // caller promises that no record moves meanwhile.  Without sorted runs,
  // each such attempt computed the key of every mesh vertex, three times
  // for the first (choose_first_cut's two cuts, then the chosen one): on
  // bunny00's refinement, 0.03 s of its 0.59 s insertion on 2 threads.
  void keep_vertex_keys() { keep_vertex_keys_ = true; }
  // Called with the points of insert()'s call settled so far: after every
  // attempt, and every progress_step points of the sequential finish and of
  // partition 0 during an attempt (there an estimate: partition 0's share
  // done times the attempt's points; never two calls at once, but possibly
  // from a worker thread).
  static constexpr std::size_t progress_step = std::size_t(1) << 16;
  void set_progress(std::function<void(std::size_t)> progress) { progress_ = std::move(progress); }

private:
  // Algorithm 1's loop over points[begin, end) with one kernel; the points
  // the kernel could not take go to `failures`.  Each insertion also sees
  // the next point, which the Delaunay kernel's hint aims at.
  // With `report`, it follows the points done every progress_step points
  // (the loop is cut into chunks: nothing more per point).
  template <class Policy, class Kernel>
  void insert_run(Policy& policy, Kernel& kernel, int partition, const Vertex_id* begin, const Vertex_id* end,
                  Vertex_id first_new, std::vector<Vertex_id>& duplicate_of, Tet_id& hint,
                  std::vector<Vertex_id>& failures, const std::function<void(std::size_t)>* report = nullptr) const
  {
    const std::size_t chunk = report ? progress_step : std::size_t(end - begin);
    for(const Vertex_id* chunk_begin = begin; chunk_begin != end;) {
      const Vertex_id* chunk_end = chunk_begin + std::min<std::size_t>(chunk, std::size_t(end - chunk_begin));
      for(const Vertex_id* v = chunk_begin; v != chunk_end; ++v) {
        const double* next = v + 1 != end ? m_.point(v[1]) : nullptr;
        Vertex_id existing = ghost_vertex;
        const Insertion_result r =
            hint == no_tet ? Insertion_result::aborted : policy.insert(kernel, partition, *v, hint, existing, next);
        if(r == Insertion_result::duplicate) duplicate_of[*v - first_new] = existing;
        else if(r == Insertion_result::aborted) failures.push_back(*v);
      }
      const std::size_t done = std::size_t(chunk_end - begin);
      if(report) (*report)(done);
      chunk_begin = chunk_end;
    }
  }

  template <class Policy>
  void insert_sequentially(const std::vector<Vertex_id>& points, Vertex_id first_new,
                           std::vector<Vertex_id>& duplicate_of, Tet_id& hint, Kernel_statistics& stats,
                           Policy& policy)
  {
    policy.prepare(1, m_.number_of_slots());
    Insertion_scratch scratch;
    scratch.timed = timed_;
    if(!m_.is_live(hint)) hint = m_.first_live_tet();
    std::vector<Vertex_id> failures;
    const std::size_t before = settled_;
    const std::function<void(std::size_t)> report = [&](std::size_t done) { progress_(before + done); };
    with_vector_paths([&](auto paths) {
      typename Policy::template Kernel<Sequential_ownership, Mesh_slots, decltype(paths)> kernel(
          m_, scratch, Mesh_slots{&m_}, filter_, sub_filter_);
      insert_run(policy, kernel, 0, points.data(), points.data() + points.size(), first_new, duplicate_of, hint,
                 failures, progress_ ? &report : nullptr);
    });
    CGAL_assertion(failures.empty()); // only a partition aborts
    m_.live_tets += scratch.live_delta;
    m_.ghost_tets += scratch.ghost_delta;
    stats.add(scratch.stats);
  }

  // Moore keys on a transformed grid (§3.3): attempt 0 uses the plain curve;
  // later attempts move the split of every axis and rotate the curve, so the
  // new partition borders cross the regions where the old ones failed.
  struct Curve_transform
  {
    double split[3] = {0.5, 0.5, 0.5};
    std::uint64_t shift = 0;

    // The plain curve's grid, possibly shifted along the curve.
    bool shift_only() const { return split[0] == 0.5 && split[1] == 0.5 && split[2] == 0.5; }
  };

  // With 2 partitions the first retry shifts the plain curve by a quarter:
  // the new cut is the plane perpendicular to the old one, where the failed
  // points lie, and crosses it along a line only (1e6 uniform points: 92.6%
  // of the retried points settle instead of 78.7% with a random transform).
  // With more partitions the same shift (half a partition) brings cuts back
  // onto old ones (8 partitions: 26% instead of 71%): they stay random.
  // The first two attempts of 2 partitions take the two cuts in the order
  // choose_first_cut found best.
  Curve_transform transform_for(int attempt, int partitions, int key_bits) const
  {
    Curve_transform c;
    if(partitions == 2 && attempt <= 1) {
      if((attempt == 1) != quarter_cut_first_) c.shift = std::uint64_t(1) << (key_bits - 2);
      return c;
    }
    if(attempt == 0) return c;
    std::mt19937_64 rng(seed_ * 0x9e3779b97f4a7c15ull + std::uint64_t(attempt));
    std::uniform_real_distribution<double> split(0.2, 0.8);
    for(double& s : c.split) s = split(rng);
    c.shift = rng();
    return c;
  }

  // Which of the two perpendicular cuts of 2 partitions the first attempt
  // takes: the one fewer tetrahedra of the mesh so far cross (their vertices
  // in both partitions; a sample of the slots).  The curve's halves are
  // fixed planes of the grid, whatever the points: on points near a torus
  // lying in the plane of one cut, nearly every tetrahedron inside the tube
  // crosses it: 1e6 points, the partitions insert 34% of the big round with
  // that cut and 97% with the other.  Costs the vertex partitions of both
  // cuts, once per round (the chosen one's are then computed again).
  void choose_first_cut(const std::vector<Vertex_id>& points, int partitions, bool rotated)
  {
    quarter_cut_first_ = false;
    if(partitions != 2 || m_.live_tets < 64 * first_cut_sample) return;
    std::size_t crossing[2];
    for(int quarter = 0; quarter < 2; ++quarter) {
      quarter_cut_first_ = quarter == 1;
      const Attempt_curve keys(lo_, hi_, transform_for(0, partitions, 3 * Attempt_curve::bits));
      const Attempt_cut plan = rotated
                                 ? cut_rotated(m_, points, partitions, keys)
                                 : cut_by_sorting(m_, points, partitions, keys, kept_keys(points, keys, partitions));
      assign_vertex_partitions(mesh_vertex_end(points), partitions, keys, plan.first_key);
      crossing[quarter] = 0;
      for(Tet_id t = 0; t < m_.number_of_slots(); t += first_cut_sample) {
        if(!m_.is_live(t) || m_.is_ghost(t)) continue;
        const Vertex_id* tv = m_.vertex_ids(t);
        const std::uint8_t j = partition_of_vertex_[tv[0]];
        crossing[quarter] += (partition_of_vertex_[tv[1]] != j) | (partition_of_vertex_[tv[2]] != j) |
                             (partition_of_vertex_[tv[3]] != j);
      }
    }
    quarter_cut_first_ = crossing[1] < crossing[0];
  }
  static constexpr Tet_id first_cut_sample = 7;

  // Keys of the curve of one attempt, over the engine's grid.
  struct Attempt_curve
  {
    static constexpr int bits = 16;
    static constexpr std::uint64_t key_mask = (std::uint64_t(1) << (3 * bits)) - 1;
    Moore_curve curve;
    Curve_transform transform;
    Moore_grid grid;
    Moore_grid plain_grid;

    Attempt_curve(const double lo[3], const double hi[3], const Curve_transform& t)
        : curve(bits), transform(t), grid(lo, hi, bits, t.split), plain_grid(lo, hi, bits)
    {}
    bool shift_only() const { return transform.shift_only(); }
    std::uint64_t key(const double* p) const { return (grid.key(curve, p) + transform.shift) & key_mask; }
    std::uint64_t plain_key(const double* p) const { return plain_grid.key(curve, p); }
  };

  // Whether `points` are increasing ids of one sorted run, hence in the
  // order of the plain curve (the failures of a plain attempt, partition
  // after partition, stay so).
  bool in_run_order(const std::vector<Vertex_id>& points) const
  {
    if(points.empty()) return false;
    const auto run = std::find_if(sorted_runs_.begin(), sorted_runs_.end(), [&](const Vertex_range& r) {
      return r.first <= points.front() && points.front() < r.second;
    });
    if(run == sorted_runs_.end() || points.back() >= run->second) return false;
    for(std::size_t i = 1; i < points.size(); ++i)
      if(points[i] <= points[i - 1]) return false;
    return true;
  }

  // Vertex ids below nv that no sorted run holds: their keys are computed
  // one by one.
  std::size_t vertices_outside_runs(std::size_t nv) const
  {
    std::size_t inside = 0;
    for(const Vertex_range& r : sorted_runs_)
      if(r.first < nv) inside += std::min<std::size_t>(r.second, nv) - r.first;
    return nv - inside;
  }

  // Vertex ids that may be in a tetrahedron during an attempt on `points`:
  // those below vertex_end_ and the points'.  The records above them are
  // later BRIO rounds, not in the mesh yet.
  std::size_t mesh_vertex_end(const std::vector<Vertex_id>& points) const
  {
    return std::min(m_.vertices.size(), std::max<std::size_t>(vertex_end_, std::size_t(largest_id(points)) + 1));
  }

  // Whether the attempt's curve is the plain one shifted and `points` are in
  // plain curve order: then its order is a rotation of theirs and the
  // vertices of sorted runs need no key (one linear check per attempt).
  bool rotation_of_sorted_run(const std::vector<Vertex_id>& points, int attempt, int partitions) const
  {
    return transform_for(attempt, partitions, 3 * Attempt_curve::bits).shift_only() && in_run_order(points);
  }

  // Vertex keys an attempt computes one by one before its tasks start: the
  // price of a retry, paid whatever the number of points.
  std::size_t keys_to_compute(const std::vector<Vertex_id>& points, bool rotated) const
  {
    return rotated ? vertices_outside_runs(mesh_vertex_end(points)) : vertices_in_mesh_;
  }

  // The points of an attempt in the order of its curve, cut into
  // `partitions` runs of about equal size at key changes: partition j takes
  // sorted[cut[j], cut[j + 1]), the keys in [first_key[j], first_key[j + 1]).
  struct Attempt_cut
  {
    std::vector<Vertex_id> sorted;
    std::vector<std::size_t> cut;
    std::vector<std::uint64_t> first_key;
  };

  // Fills cut and first_key of `plan`, given its sorted points and the
  // attempt key of sorted[i].
  template <class Key_at>
  static void cut_sorted(Attempt_cut& plan, int partitions, const Key_at& key_at)
  {
    const std::size_t n = plan.sorted.size();
    plan.cut.assign(partitions + 1, 0);
    plan.first_key.assign(partitions + 1, 0);
    for(int j = 1; j < partitions; ++j) {
      std::size_t c = std::max(plan.cut[j - 1], n * std::size_t(j) / std::size_t(partitions));
      if(c > 0 && c < n) {
        std::uint64_t previous = key_at(c - 1), current = key_at(c);
        while(c < n && current == previous) {
          if(++c < n) current = key_at(c);
        }
        plan.first_key[j] = c < n ? current : Attempt_curve::key_mask + 1;
      } else {
        plan.first_key[j] = c < n ? key_at(c) : Attempt_curve::key_mask + 1;
      }
      plan.cut[j] = c;
    }
    plan.cut[partitions] = n;
    plan.first_key[partitions] = Attempt_curve::key_mask + 1;
  }

  // Points in plain curve order: the attempt's curve is the same up to a
  // circular shift, so its order is a rotation, found by binary search.
  static Attempt_cut cut_rotated(const Flat_storage& m, const std::vector<Vertex_id>& points, int partitions,
                                 const Attempt_curve& c)
  {
    Attempt_cut plan;
    const std::uint64_t wrap = (Attempt_curve::key_mask + 1 - c.transform.shift) & Attempt_curve::key_mask;
    const std::size_t first = c.transform.shift == 0
                                ? 0
                                : std::size_t(std::partition_point(points.begin(), points.end(),
                                                                   [&](Vertex_id v) {
                                                                     return c.plain_key(m.point(v)) < wrap;
                                                                   }) -
                                              points.begin());
    plan.sorted.resize(points.size());
    std::rotate_copy(points.begin(), points.begin() + first, points.end(), plan.sorted.begin());
    CGAL_assertion(std::is_sorted(plan.sorted.begin(), plan.sorted.end(), [&](Vertex_id a, Vertex_id b) {
      return c.key(m.point(a)) < c.key(m.point(b));
    }));
    cut_sorted(plan, partitions, [&](std::size_t i) { return c.key(m.point(plan.sorted[i])); });
    return plan;
  }

  // Any points: one key each, radix sorted on the partitions' threads.
  // `plain`: kept plain keys of the vertices (see keep_vertex_keys), for a
  // shift-only curve; null: computed here.
  static Attempt_cut cut_by_sorting(const Flat_storage& m, const std::vector<Vertex_id>& points, int partitions,
                                    const Attempt_curve& c, const std::uint64_t* plain = nullptr)
  {
    CGAL_precondition(plain == nullptr || c.shift_only());
    std::vector<Key_value<std::uint32_t>> items(points.size()), scratch_items;
    const int chunks = chunk_count(points.size(), partitions);
    for_each_chunk(chunks, [&](int k) {
      for(std::size_t i = chunk_begin(points.size(), chunks, k); i < chunk_begin(points.size(), chunks, k + 1); ++i) {
        const Vertex_id v = points[i];
        items[i] = {plain ? (plain[v] + c.transform.shift) & Attempt_curve::key_mask : c.key(m.point(v)), v};
      }
    });
    const bool in_order = std::is_sorted(items.begin(), items.end(),
                                         [](const Key_value<std::uint32_t>& a, const Key_value<std::uint32_t>& b) {
                                           return a.key < b.key;
                                         });
    if(!in_order) radix_sort(items, scratch_items, 3 * Attempt_curve::bits, partitions);
    std::vector<Key_value<std::uint32_t>>().swap(scratch_items); // not needed while the mesh grows
    Attempt_cut plan;
    // The points alone: a quarter of the keyed items' bytes.
    plan.sorted.resize(items.size());
    for(std::size_t i = 0; i < items.size(); ++i) plan.sorted[i] = items[i].value;
    cut_sorted(plan, partitions, [&](std::size_t i) { return items[i].key; });
    return plan;
  }

  // The first id of [begin, end), a sorted run, whose plain key is at
  // least `key` (end if none).
  Vertex_id first_id_at_or_past(Vertex_id begin, Vertex_id end, const Attempt_curve& c, std::uint64_t key) const
  {
    while(begin < end) {
      const Vertex_id middle = begin + (end - begin) / 2;
      if(c.plain_key(m_.point(middle)) < key) begin = middle + 1;
      else end = middle;
    }
    return begin;
  }

  static std::uint8_t partition_of_key(std::uint64_t k, const std::vector<std::uint64_t>& first_key)
  {
    const int partitions = int(first_key.size()) - 1;
    int j = 0;
    while(j + 1 < partitions && k >= first_key[j + 1]) ++j;
    return static_cast<std::uint8_t>(j);
  }

  // partition_of_vertex_ for the ids below nv.  On a shift-only curve the
  // partition along a sorted run changes only where the plain key crosses a
  // cut or the wrap of the shift: a few binary searches and fills.
  void assign_vertex_partitions(std::size_t nv, int partitions, const Attempt_curve& c,
                                const std::vector<std::uint64_t>& first_key)
  {
    partition_of_vertex_.resize(m_.vertices.size());
    if(keep_vertex_keys_ && c.shift_only()) {
      CGAL_assertion(sorted_runs_.empty()); // kept keys stand in for the runs' searches
      const std::uint64_t* plain = plain_keys(nv, partitions);
      const std::uint64_t shift = c.transform.shift;
      for_each_range(nv, partitions, [&](std::size_t begin, std::size_t end) {
        for(std::size_t v = begin; v < end; ++v)
          partition_of_vertex_[v] = partition_of_key((plain[v] + shift) & Attempt_curve::key_mask, first_key);
      });
      return;
    }
    std::vector<Vertex_range> by_key;
    std::vector<Vertex_range> computed;
    if(c.shift_only()) {
      std::size_t next = 0;
      for(const Vertex_range& r : sorted_runs_) {
        if(r.first >= nv) continue;
        if(r.first > next) computed.push_back({Vertex_id(next), r.first});
        by_key.push_back({r.first, Vertex_id(std::min<std::size_t>(r.second, nv))});
        next = std::min<std::size_t>(r.second, nv);
      }
      if(next < nv) computed.push_back({Vertex_id(next), Vertex_id(nv)});
    } else {
      computed.push_back({0, Vertex_id(nv)});
    }

    // Plain keys where the attempt's partition may change.
    const std::uint64_t mask = Attempt_curve::key_mask;
    std::vector<std::uint64_t> breaks;
    for(int j = 1; j < partitions; ++j) breaks.push_back((first_key[j] - c.transform.shift) & mask);
    if(c.transform.shift != 0) breaks.push_back((mask + 1 - c.transform.shift) & mask);
    std::sort(breaks.begin(), breaks.end());
    for(const Vertex_range& r : by_key) {
      Vertex_id begin = r.first;
      for(std::size_t b = 0; b <= breaks.size() && begin < r.second; ++b) {
        const Vertex_id end = b == breaks.size() ? r.second
                                                 : first_id_at_or_past(begin, r.second, c, breaks[b]);
        if(end > begin) {
          const std::uint8_t j = partition_of_key(c.key(m_.point(begin)), first_key);
          std::fill(partition_of_vertex_.begin() + begin, partition_of_vertex_.begin() + end, j);
          CGAL_assertion(partition_of_key(c.key(m_.point(end - 1)), first_key) == j);
        }
        begin = end;
      }
    }

    for(const Vertex_range& r : computed) {
      const std::size_t n = r.second - r.first;
      const int chunks = chunk_count(n, partitions);
      for_each_chunk(chunks, [&](int k) {
        const std::size_t end = r.first + chunk_begin(n, chunks, k + 1);
        for(std::size_t v = r.first + chunk_begin(n, chunks, k); v < end; ++v)
          partition_of_vertex_[v] = partition_of_key(c.key(m_.point(Vertex_id(v))), first_key);
      });
    }
  }

  template <class Policy>
  void insert_partitioned(const std::vector<Vertex_id>& points, int partitions, int attempt, bool rotated,
                          Vertex_id first_new, std::vector<Vertex_id>& duplicate_of,
                          std::vector<Vertex_id>& failed, Kernel_statistics& stats, Policy& policy)
  {
    const bool plane = by_plane(attempt, partitions);
    Attempt_cut plan;
    if(plane) {
      plan = cut_by_median_planes(points, partitions);
    } else {
      if(attempt == 0) choose_first_cut(points, partitions, rotated);
      const Attempt_curve keys(lo_, hi_, transform_for(attempt, partitions, 3 * Attempt_curve::bits));
      plan = rotated ? cut_rotated(m_, points, partitions, keys)
                     : cut_by_sorting(m_, points, partitions, keys, kept_keys(points, keys, partitions));
      assign_vertex_partitions(mesh_vertex_end(points), partitions, keys, plan.first_key);
    }
    const std::vector<Vertex_id>& sorted = plan.sorted;
    const std::vector<std::size_t>& cut = plan.cut;

    // Room for every partition's worst case, fixed before the tasks start.
    std::vector<Tet_id> fresh_begin(partitions + 1);
    fresh_begin[0] = m_.number_of_slots();
    for(int j = 0; j < partitions; ++j)
      fresh_begin[j + 1] = fresh_begin[j] + fresh_slots_per_point * (cut[j + 1] - cut[j]) + 4096;
    resize_cell_arrays(fresh_begin[partitions]);
    policy.prepare(partitions, fresh_begin[partitions]);

    std::vector<std::vector<Tet_id>> free_lists(partitions);
    for(std::size_t k = 0; k < m_.free_tets.size(); ++k)
      free_lists[k % partitions].push_back(m_.free_tets[k]);
    m_.free_tets.clear();
    std::vector<Insertion_scratch> scratches(partitions);
    std::vector<std::vector<Vertex_id>> failures(partitions);
    std::vector<Tet_id> next_fresh(partitions);
    const std::size_t before = settled_, share = cut[1] - cut[0];
    const std::function<void(std::size_t)> report = [&](std::size_t done) {
      progress_(before + (share == 0 ? 0 : done * points.size() / share));
    };

    const std::vector<Tet_id> hints = owned_start_tets(partitions, fresh_begin[0]);
    for_each_chunk(partitions, [&](int j) {
      Insertion_scratch& scratch = scratches[j];
      scratch.timed = timed_;
      Partition_ownership ownership;
      ownership.partition_of_vertex = partition_of_vertex_.data();
      ownership.partition = static_cast<std::uint8_t>(j);
      const std::function<void(std::size_t)>* progress = j == 0 && progress_ ? &report : nullptr;
      const Vertex_id *begin = sorted.data() + cut[j], *end = sorted.data() + cut[j + 1];
      with_vector_paths([&](auto paths) {
        typedef decltype(paths) Paths;
        typename Policy::template Kernel<Partition_ownership, Partition_slots, Paths> kernel(
            m_, scratch, Partition_slots{&free_lists[j], fresh_begin[j], fresh_begin[j + 1], &m_.tets}, filter_,
            sub_filter_, ownership);
        Tet_id hint = hints[j];
        insert_run(policy, kernel, j, begin, end, first_new, duplicate_of, hint, failures[j], progress);
        next_fresh[j] = kernel.slots().next_fresh;
      });
    });

    // Unused fresh slots and the partitions' free lists go back to the mesh.
    for(int j = 0; j < partitions; ++j) {
      m_.live_tets += scratches[j].live_delta;
      m_.ghost_tets += scratches[j].ghost_delta;
      stats.add(scratches[j].stats);
      if(j + 1 < partitions) {
        for(Tet_id t = next_fresh[j]; t < fresh_begin[j + 1]; ++t) {
          m_.tets[t].v[0] = mark_bit; // never written: free
          m_.free_tets.push_back(t);
        }
      }
      m_.free_tets.insert(m_.free_tets.end(), free_lists[j].begin(), free_lists[j].end());
      failed.insert(failed.end(), failures[j].begin(), failures[j].end());
    }
    // Points of a sorted run cut on a shifted curve fail in a rotation of the
    // run's order; rotated back, the retry cuts them by binary search like
    // the first attempt instead of computing every mesh vertex's key, a price
    // that sent the retry of 2 partitions to the sequential finish (1e6
    // points near a torus: 17,463 points there, twice the usual cavity each,
    // 0.07 to 0.10 s on one thread).  Cut by planes, they fail in the
    // partitions' order; in id order again, a retry on the curve finds its
    // cut by binary search too (3 partitions of 1e6 points near bunny00:
    // 82.5% of that retry settled instead of 79.0%).
    if(plane && in_run_order(points)) std::sort(failed.begin(), failed.end());
    if(rotated && !plane) {
      std::rotate(failed.begin(), std::is_sorted_until(failed.begin(), failed.end()), failed.end());
      CGAL_assertion(std::is_sorted(failed.begin(), failed.end()));
    }
    // The last partition's unused range is simply cut off the arrays.
    resize_cell_arrays(next_fresh[partitions - 1]);
  }

  // Whether the points' median lies off the middle of the engine's box by
  // more than median_offset_for_planes of its extent, along some axis.  The
  // curve's halves are planes through the middle of the box; cut at the
  // points' median elsewhere, the partitions' border follows the curve's
  // cells in steps and meets more tetrahedra.  Measured on 1e6 points, 2
  // threads (medians of 3 alternating runs of 3 rounds, curve / planes):
  // bunny00's surface, median 12.5% off, 0.881 / 0.815 s (its big round
  // settles 96.0% instead of 93.3%, the retry 95.0% instead of 78.8%);
  // 20 clusters, 6-7% off, 0.858 / 0.825 s.  Where the median is near the
  // middle (uniform, Gaussian, shell, torus: at most 1% off) the curve stays:
  // planes there made the torus 3.5% slower (0.793 / 0.821 s), since a
  // partition's points, in curve order, jump wherever the curve crosses a
  // plane that is not its own split.  A sample of the points suffices.
  // More partitions follow the points the same way, as boxes of a tree of
  // median planes: bunny00's big round of 4 partitions settles 93.3% instead
  // of 87.1% on the curve, of 8 partitions 87.9% instead of 71.8%, and the
  // whole insertion (4 and 8 partitions run by 2 threads, so the sum of the
  // work) took 0.90 s instead of 1.00 s and 1.13 s instead of 1.40 s;
  // 20 clusters 0.85 s instead of 0.97 s and 0.93 s instead of 1.35 s.
  static constexpr double median_offset_for_planes = 0.05;
  bool off_centre_median(const std::vector<Vertex_id>& points) const
  {
    const std::size_t stride = median_sample_stride(points.size());
    for(int a = 0; a < 3; ++a) {
      const double middle = 0.5 * (lo_[a] + hi_[a]), extent = hi_[a] - lo_[a];
      if(!(extent > 0)) continue;
      const double median = sampled_quantile(points.data(), points.size(), a, stride, 0.5);
      if(std::abs(median - middle) > median_offset_for_planes * extent) return true;
    }
    return false;
  }

  // Such points are cut by median planes (cut_by_median_planes) in their
  // first attempt, and in the retry when it has 2 partitions: its points lie
  // along the first plane, so its own plane crosses that one.  A retry of
  // more partitions takes the curve: its points lie along several planes,
  // and new medians fall on some of them (bunny00, 1e6 points: 27% of the
  // retry of 4 partitions settled against 79% on the curve, 30% against 58%
  // with 8).
  bool by_plane(int attempt, int partitions) const
  {
    return plane_cuts_ && (attempt == 0 || (attempt == 1 && partitions == 2));
  }

  static std::size_t median_sample_stride(std::size_t n) { return std::max<std::size_t>(1, n / 65536); }

  double sampled_quantile(const Vertex_id* points, std::size_t n, int axis, std::size_t stride, double q) const
  {
    std::vector<double> c;
    c.reserve(n / stride + 1);
    for(std::size_t i = 0; i < n; i += stride) c.push_back(m_.point(points[i])[axis]);
    const std::size_t at = std::min(c.size() - 1, std::size_t(q * double(c.size())));
    std::nth_element(c.begin(), c.begin() + at, c.end());
    return c[at];
  }

  // The median planes of an attempt, as a k-d tree: a node splits its
  // points at `split` along `axis`; a child below 0 is partition -1 - child.
  struct Plane_node
  {
    int axis;
    double split;
    int below, above;
  };

  static std::uint8_t partition_in_tree(const std::vector<Plane_node>& tree, const double* p)
  {
    int node = 0;
    while(node >= 0) node = p[tree[node].axis] < tree[node].split ? tree[node].below : tree[node].above;
    return static_cast<std::uint8_t>(-1 - node);
  }

  // Partitions [first, first + k) take points[begin, end): split at the
  // sampled quantile floor(k/2)/k of the axis along which the points spread
  // most, the lower floor(k/2) partitions below it.  Each side keeps its
  // points in their order.  Returns the node's index, or -1 - first for a leaf.
  int split_by_planes(std::vector<Vertex_id>& points, std::size_t begin, std::size_t end, int first, int k,
                      std::vector<Plane_node>& tree, std::vector<std::size_t>& cut)
  {
    if(k == 1) {
      cut[first + 1] = end;
      return -1 - first;
    }
    Vertex_id* p = points.data() + begin;
    const std::size_t n = end - begin, stride = median_sample_stride(n);
    double lo[3], hi[3];
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::numeric_limits<double>::infinity();
      hi[a] = -lo[a];
    }
    for(std::size_t i = 0; i < n; i += stride)
      for(int a = 0; a < 3; ++a) {
        lo[a] = std::min(lo[a], m_.point(p[i])[a]);
        hi[a] = std::max(hi[a], m_.point(p[i])[a]);
      }
    int axis = 0;
    for(int a = 1; a < 3; ++a)
      if(hi[a] - lo[a] > hi[axis] - lo[axis]) axis = a;
    const int k_below = k / 2;
    const double split = n == 0 ? 0. : sampled_quantile(p, n, axis, stride, double(k_below) / k);
    const std::size_t below = std::size_t(
        std::stable_partition(p, p + n, [&](Vertex_id v) { return m_.point(v)[axis] < split; }) - p);
    const int node = int(tree.size());
    tree.push_back({axis, split, 0, 0});
    const int lower = split_by_planes(points, begin, begin + below, first, k_below, tree, cut);
    const int upper = split_by_planes(points, begin + below, end, first + k_below, k - k_below, tree, cut);
    tree[node].below = lower;
    tree[node].above = upper;
    return node;
  }

  // A partition's points share a box of the tree's planes, and every mesh
  // vertex finds its partition by a few comparisons (no Moore key).
  Attempt_cut cut_by_median_planes(const std::vector<Vertex_id>& points, int partitions)
  {
    Attempt_cut plan;
    plan.sorted = points;
    plan.cut.assign(partitions + 1, 0); // first_key stays empty: no curve
    std::vector<Plane_node> tree;
    split_by_planes(plan.sorted, 0, points.size(), 0, partitions, tree, plan.cut);
    partition_of_vertex_.resize(m_.vertices.size());
    for_each_range(mesh_vertex_end(points), partitions, [&](std::size_t b, std::size_t e) {
      for(std::size_t v = b; v < e; ++v)
        partition_of_vertex_[v] = partition_in_tree(tree, m_.point(Vertex_id(v)));
    });
    return plan;
  }

  // The kept plain keys of the vertex ids below nv, computed on
  // `threads` threads where missing.
  const std::uint64_t* plain_keys(std::size_t nv, int threads)
  {
    const std::size_t first = vertex_keys_.size();
    if(first < nv) {
      const Attempt_curve plain(lo_, hi_, Curve_transform());
      vertex_keys_.resize(nv);
      for_each_range(nv - first, threads, [&](std::size_t begin, std::size_t end) {
        for(std::size_t v = first + begin; v < first + end; ++v)
          vertex_keys_[v] = plain.plain_key(m_.point(Vertex_id(v)));
      });
    }
    return vertex_keys_.data();
  }

  // The kept keys for cut_by_sorting of `points` on curve c, or null.
  const std::uint64_t* kept_keys(const std::vector<Vertex_id>& points, const Attempt_curve& c, int threads)
  {
    if(!keep_vertex_keys_ || !c.shift_only()) return nullptr;
    return plain_keys(mesh_vertex_end(points), threads);
  }

  static Vertex_id largest_id(const std::vector<Vertex_id>& points)
  {
    return points.empty() ? Vertex_id(0) : *std::max_element(points.begin(), points.end());
  }

  void resize_cell_arrays(std::size_t slots)
  {
    // Each partition writes the fresh slots it uses; the unused ones are
    // marked free or cut off after the tasks.
    m_.resize_tets(slots, Flat_storage::New_slots::left_unwritten);
  }

  // A live tetrahedron owned by each partition (no_tet if none), found by one
  // sequential scan before the tasks start, so that no task reads cells
  // another task is rewriting.  Only the slots below `end` hold cells: the
  // fresh ranges above are unwritten (a partition that owns nothing made the
  // scan run into them and read garbage vertex ids).
  std::vector<Tet_id> owned_start_tets(int partitions, Tet_id end) const
  {
    std::vector<Tet_id> hints(partitions, no_tet);
    int missing = partitions;
    Partition_ownership ownership;
    ownership.partition_of_vertex = partition_of_vertex_.data();
    for(Tet_id t = 0; t < end && missing > 0; ++t) {
      if(!m_.is_live(t)) continue;
      const std::uint8_t j = partition_of_vertex_[m_.vertex(t, 0)];
      ownership.partition = j;
      if(hints[j] == no_tet && ownership.owns(m_, t)) {
        hints[j] = t;
        --missing;
      }
    }
    return hints;
  }

  Flat_storage& m_;
  Static_filter filter_;
  Sub_determinant_filter sub_filter_;
  bool quarter_cut_first_ = false;
  bool plane_cuts_ = false; // the current insert()'s points are cut by planes (off_centre_median)
  double lo_[3], hi_[3];
  std::uint64_t seed_;
  bool timed_;
  std::size_t vertices_in_mesh_ = 0;
  std::size_t vertex_end_ = std::numeric_limits<std::size_t>::max();
  std::size_t min_points_per_partition_ = default_min_points_per_partition;
  std::vector<std::uint8_t> partition_of_vertex_;
  std::vector<Vertex_range> sorted_runs_;
  bool keep_vertex_keys_ = false;
  std::vector<std::uint64_t> vertex_keys_; // see keep_vertex_keys()
  std::function<void(std::size_t)> progress_;
  std::size_t settled_ = 0; // points of the current insert() settled
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_PARALLEL_INSERTION_H
