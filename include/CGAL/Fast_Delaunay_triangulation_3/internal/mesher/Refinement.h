// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lines 4-8 of the paper's Algorithm 2: while the mesh has large
// tetrahedra, SAMPLEPOINTS (circumcentres of the tetrahedra whose
// circumradius exceeds 1.4 h; the centroid when the centre falls outside
// the tetrahedron's subdomain), FILTERPOINTS (no two accepted points closer
// than 0.7 h) and INSERTPOINTS in one large batch per pass (the first pass
// in two rounds, see insert_points).
//
// The cavity of a refinement point is the Delaunay cavity with the two
// changes of §4: it never crosses a constrained facet (so the surface is
// never broken and each cavity stays in one subdomain), and, since the mesh
// is then not Delaunay any more, it is made star-shaped from the point: a
// tetrahedron whose boundary facet does not see the point leaves the
// cavity, and the test repeats.  The cavity also aborts the point when one
// of its vertices is closer than 0.7 h (§2.4's modified cavity).
//
// A batch goes through the partitioned engine of §3 (Parallel_insertion.h)
// with its own per-point step, Constrained_point_insertion: the kernel's
// WALK (one that gives up, the mesh not being Delaunay), the constrained
// star-shaped cavity, then the kernel's DELAUNAYBALL (fill_hole).  A
// partition owns the tetrahedra whose vertices are all in it
// (Partition_ownership, as in Delaunay insertion); a point whose walk cannot
// stay in them, or whose cavity reaches another one, is tried again with new
// partitions, and the last ones sequentially (§3.3-§3.4).  Points dropped by
// the rules above are dropped whatever the partitions.  The mesh depends on
// the thread count (the partitions), never on the scheduling.

#ifndef CGAL_FDT3_INTERNAL_MESHER_REFINEMENT_H
#define CGAL_FDT3_INTERNAL_MESHER_REFINEMENT_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Parallel_insertion.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Sizing.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

struct Refinement_options
{
  double radius_ratio = 1.4;   // refine when circumradius > radius_ratio * h
  double min_edge_ratio = 0.7; // no new edge shorter than min_edge_ratio * h
  int max_passes = 200;
  // Moore partitions of a batch (paper §3); 1 inserts it sequentially.
  int threads = 1;
  // Fewer points per partition halve the partitions (§3.4's 3000).
  std::size_t min_points_per_thread = Partitioned_insertion::default_min_points_per_partition;
  // The engine keeps every vertex's curve key for a batch's attempts
  // (Partitioned_insertion::keep_vertex_keys); off, each attempt computes
  // them again: the same partitions, hence the same mesh (a test compares).
  bool keep_vertex_keys = true;
};

struct Refinement_pass
{
  // aborted: filtered points the insertion dropped (edge filter, star
  // shape, subdomain, walk), whatever the partitions.
  std::size_t candidates = 0, filtered_out = 0, aborted = 0, inserted = 0;
  std::size_t settled_in_partitions = 0; // points inserted or dropped by attempts with several partitions
  std::size_t walk_steps = 0;             // of the insertions' walks, every attempt's
  std::vector<Partition_round> attempts;  // the engine's attempts (paper Table 2)
  std::size_t tetrahedra = 0; // live finite tetrahedra inside the volumes after the pass
  double seconds = 0;
  double sample_seconds = 0, filter_seconds = 0, insert_seconds = 0; // parts of `seconds`
};

// A refinement point: where, its size and the subdomain it must fall in.
struct Refinement_point
{
  double p[3];
  double h;
  int subdomain;
};

// Circumcentre of a tetrahedron (floating point; an imprecise centre only
// moves the point a little, it never breaks the mesh since every
// combinatorial decision below is exact).  False when the tetrahedron is flat.
inline bool circumcentre(const double* a, const double* b, const double* c, const double* d, double centre[3])
{
  double u[3], v[3], w[3];
  for(int i = 0; i < 3; ++i) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = d[i] - a[i];
  }
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const double ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const double vxw[3] = {v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2], v[0] * w[1] - v[1] * w[0]};
  const double wxu[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
  const double uxv[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double det = 2 * (u[0] * vxw[0] + u[1] * vxw[1] + u[2] * vxw[2]);
  if(det == 0 || !std::isfinite(det)) return false;
  for(int i = 0; i < 3; ++i) centre[i] = a[i] + (uu * vxw[i] + vv * wxu[i] + ww * uxv[i]) / det;
  return true;
}

// One refinement point into the mesh, as the partitioned engine's per-point
// step (see Delaunay_point_insertion).  Vertex v is point v - first_new of
// the batch.  Inside a task it reads and writes only what its kernel owns:
// the tetrahedra of its partition and their neighbours, whose slots are its
// own (Partition_ownership), and their subdomain, constrained and no_sample
// entries.
class Constrained_point_insertion
{
public:
  template <class Ownership, class Slots, class Paths = Default_paths>
  using Kernel = Delaunay_kernel<Ownership, Slots, Walk_giving_up, Paths>;

  // no_sample: per slot, set to 0 for every tetrahedron the insertions make.
  Constrained_point_insertion(Constrained_mesh& cm, double min_edge_ratio,
                              const std::vector<Refinement_point>& batch, Vertex_id first_new,
                              std::vector<std::uint8_t>& no_sample)
      : cm_(cm), min_edge_ratio_(min_edge_ratio), batch_(batch), first_new_(first_new), no_sample_(no_sample),
        inserted_(batch.size(), 0)
  {}

  bool inserted(std::size_t i) const { return inserted_[i] != 0; }

  void prepare(int partitions, std::size_t slots)
  {
    CGAL_assertion(slots == cm_.mesh.number_of_slots());
    (void)slots;
    cm_.fit_slot_arrays();
    no_sample_.resize(slots, 0);
    if(cavities_.size() < std::size_t(partitions)) cavities_.resize(partitions);
  }

  // `next` is not used: the hint is the new ball's first tetrahedron, or
  // the one the walk found when the point is rejected.  The points come
  // along the Moore curve, so the last ball is near; the tetrahedron a point
  // was sampled in is not, as a rule, by then: its slot has mostly been
  // freed and taken again elsewhere (bunny00, 1 thread: 15 walk steps per
  // point from there).  A hint left at the last ball after a rejection sent
  // the late passes' walks across the mesh, where nearly every point is
  // rejected: fandisk with h at most 0.004 (6.4 million tetrahedra, 2
  // threads) spent 0.6-0.8 s on each of its last passes' 100,000 points,
  // and its refinement took 8.8 s instead of 5.3 s.
  template <class K>
  Insertion_result insert(K& kernel, int partition, Vertex_id v, Tet_id& hint, Vertex_id&, const double*)
  {
    const Flat_storage& m = cm_.mesh;
    const Refinement_point& r = batch_[v - first_new_];
    const Tet_id start = kernel.walk(hint, r.p);
    if(start == no_tet) return K::partitioned ? Insertion_result::aborted : Insertion_result::rejected;
    hint = start;
    if(m.is_ghost(start) || cm_.subdomain[start] != r.subdomain) return Insertion_result::rejected;
    std::vector<Tet_id>& cavity = cavities_[partition];
    const Insertion_result found = constrained_cavity(kernel, start, r, cavity);
    if(found != Insertion_result::inserted) return found;
    if(!kernel.fill_hole(v, cavity.data(), cavity.size())) return Insertion_result::aborted;
    inherit_flags<K>(kernel.scratch(), r.subdomain);
    hint = kernel.scratch().ball.front();
    inserted_[v - first_new_] = 1;
    return Insertion_result::inserted;
  }

private:
  // The new tetrahedra are in the cavity's subdomain; facet 0 of each is a
  // cavity boundary facet and is constrained when the outside one was; the
  // other facets contain the new point, never on the surface.  In a task the
  // per-slot arrays were sized by prepare() for every slot it may take.
  template <class K>
  void inherit_flags(const Insertion_scratch& s, int subdomain)
  {
    if(!K::partitioned) {
      cm_.fit_slot_arrays();
      no_sample_.resize(cm_.mesh.number_of_slots(), 0);
    }
    for(std::size_t k = 0; k < s.ball.size(); ++k) {
      const Tet_id t = s.ball[k];
      CGAL_assertion(t < cm_.subdomain.size() && t < no_sample_.size());
      no_sample_[t] = 0;
      const Facet_code outside = s.boundary[k].outside;
      cm_.subdomain[t] = subdomain;
      cm_.constrained[t] = cm_.is_constrained(tet_of(outside), facet_of(outside)) ? 1 : 0;
    }
  }

  // Vertex i of a tetrahedron that may carry the cavity mark.
  Vertex_id vertex(Tet_id t, int i) const { return cm_.mesh.vertex(t, i) & ~mark_bit; }

  bool is_close(Vertex_id v, const Refinement_point& r) const
  {
    const double* w = cm_.mesh.point(v);
    return distance(w, r.p) < min_edge_ratio_ * r.h || same_point(w, r.p);
  }

  // CAVITY with constraints, then made star-shaped.  The cavity is carried
  // by the kernel's mark (a live tetrahedron's neighbours are live, so a
  // marked neighbour is in the cavity).  Returns `inserted` with the cavity
  // in `cavity` and no mark left; otherwise, with no mark left either,
  // `aborted` (it reached a tetrahedron the kernel does not own) or
  // `rejected` (a vertex closer than the edge filter allows, no conflict, or
  // the start tetrahedron not star-shaped from the point).
  template <class K>
  Insertion_result constrained_cavity(const K& kernel, Tet_id start, const Refinement_point& r,
                                      std::vector<Tet_id>& cavity)
  {
    Flat_storage& m = cm_.mesh;
    cavity.clear();
    // Before any conflict test: a point equal to a vertex of `start` (the
    // only vertices it can equal) has no perturbed conflict status.
    for(int i = 0; i < 4; ++i)
      if(is_close(vertex(start, i), r)) return Insertion_result::rejected;
    if(!kernel.in_conflict(start, r.p)) return Insertion_result::rejected;
    m.mark_free(start);
    cavity.push_back(start);
    Insertion_result result = Insertion_result::inserted;
    for(std::size_t k = 0; k < cavity.size() && result == Insertion_result::inserted; ++k) {
      const Tet_id t = cavity[k];
      for(int f = 0; f < 4; ++f) {
        if(cm_.is_constrained(t, f)) continue;
        const Facet_code code = m.neighbor_code(t, f);
        const Tet_id u = tet_of(code);
        if(!m.is_live(u) || !kernel.in_conflict(u, r.p)) continue;
        CGAL_assertion(!m.is_ghost(u) && cm_.subdomain[u] == r.subdomain);
        // u's other three vertices are t's, already looked at.
        if(!kernel.owns(u)) result = Insertion_result::aborted;
        else if(is_close(vertex(u, facet_of(code)), r)) result = Insertion_result::rejected;
        if(result != Insertion_result::inserted) break;
        m.mark_free(u);
        cavity.push_back(u);
      }
    }
    if(result == Insertion_result::inserted && !make_star_shaped<K>(start, r.p, cavity))
      result = Insertion_result::rejected;
    for(Tet_id t : cavity) m.unmark_free(t);
    return result;
  }

  // The paper's rule: drop every tetrahedron with a boundary facet that
  // does not see p strictly, until none is left (false if the start is
  // dropped).  Dropped tetrahedra lose the mark and leave `cavity`.
  // (p, facet f's vertices in facet_vertex order) has the orientation of t
  // with p in place of its vertex f: the four are the walk's four facet
  // tests, which the vector form certifies at once for most tetrahedra.
  template <class K>
  bool make_star_shaped(Tet_id start, const double* p, std::vector<Tet_id>& cavity)
  {
    Flat_storage& m = cm_.mesh;
    for(bool changed = true; changed;) {
      changed = false;
      for(std::size_t k = 0; k < cavity.size();) {
        const Tet_id t = cavity[k];
        const double* w[4] = {m.point(vertex(t, 0)), m.point(vertex(t, 1)), m.point(vertex(t, 2)),
                              m.point(vertex(t, 3))};
        int beyond = 0, before = 0; // bit f: certified negative, positive
#ifdef CGAL_FDT3_SIMD_RECORDS
        if constexpr(K::Vector_paths::avx2)
          certified_facet_sides_of_records(w[0], w[1], w[2], w[3], p, cm_.filter.orientation, beyond, before);
#endif
        bool sees_all = true;
        for(int f = 0; f < 4 && sees_all; ++f) {
          if(!m.is_live(m.neighbor(t, f)) || (before >> f & 1)) continue;
          sees_all = !(beyond >> f & 1) &&
                     orientation(cm_.filter, p, w[facet_vertex[f][0]], w[facet_vertex[f][1]], w[facet_vertex[f][2]]) > 0;
        }
        if(sees_all) {
          ++k;
          continue;
        }
        if(t == start) return false;
        m.unmark_free(t);
        cavity[k] = cavity.back();
        cavity.pop_back();
        changed = true;
      }
    }
    return true;
  }

  Constrained_mesh& cm_;
  double min_edge_ratio_;
  const std::vector<Refinement_point>& batch_;
  Vertex_id first_new_;
  std::vector<std::uint8_t>& no_sample_;     // see Constrained_refinement::no_sample_
  std::vector<std::uint8_t> inserted_;       // per batch point, written by the task that inserts it
  std::vector<std::vector<Tet_id>> cavities_; // per partition
};

// The accepted points of FILTERPOINTS by grid cell: one linked list per
// cell, heads in an open-addressing table.  Replaces a
// std::unordered_multimap (one node allocation per point, 27 bucket
// searches per candidate) that took about 40% of the refinement.
class Filter_cell_lists
{
public:
  static constexpr std::uint32_t none = std::uint32_t(-1);
  struct Cell { std::int64_t i, j, k; };

  // Room for `points` points (the table stays at most half full).
  void reserve(std::size_t points)
  {
    std::size_t capacity = 16;
    while(capacity < 2 * points) capacity *= 2;
    slots_.assign(capacity, Slot{{0, 0, 0}, none});
    next_.clear();
    next_.reserve(points);
  }

  std::uint32_t first(const Cell& c) const { return slots_[find(c)].head; }
  std::uint32_t next(std::uint32_t q) const { return next_[q]; }

  // Point q (numbered in order from 0) joins cell c.
  void add(const Cell& c, std::uint32_t q)
  {
    CGAL_precondition(q == next_.size() && next_.size() < slots_.size() / 2);
    Slot& slot = slots_[find(c)];
    slot.cell = c;
    next_.push_back(slot.head);
    slot.head = q;
  }

private:
  struct Slot { Cell cell; std::uint32_t head; };

  // The slot of c, or the empty slot where c would go (the table is at
  // most half full, so there is one).
  std::size_t find(const Cell& c) const
  {
    const std::size_t mask = slots_.size() - 1;
    std::size_t h = ((static_cast<std::uint64_t>(c.i) * 73856093u) ^ (static_cast<std::uint64_t>(c.j) * 19349663u) ^
                     (static_cast<std::uint64_t>(c.k) * 83492791u)) * 0x9e3779b97f4a7c15ull >> 20;
    for(;; ++h) {
      const Slot& s = slots_[h & mask];
      if(s.head == none || (s.cell.i == c.i && s.cell.j == c.j && s.cell.k == c.k)) return h & mask;
    }
  }

  std::vector<Slot> slots_;
  std::vector<std::uint32_t> next_;
};

// The filter's cells: cubes of side `side`.
struct Filter_cells
{
  double side;

  std::int64_t index(double x) const { return static_cast<std::int64_t>(std::floor(x / side)); }
  Filter_cell_lists::Cell cell_of(const double* p) const { return {index(p[0]), index(p[1]), index(p[2])}; }

  // Whether a point of `kept`, listed by cell in `grid`, is closer to r
  // than `radius`.
  bool has_point_near(const Filter_cell_lists& grid, const std::vector<Refinement_point>& kept,
                      const Refinement_point& r, double radius) const
  {
    // A hair wider than the radius: p +- radius rounds.
    const double reach = radius * (1 + 1e-12);
    std::int64_t from[3], to[3];
    for(int a = 0; a < 3; ++a) {
      from[a] = index(r.p[a] - reach);
      to[a] = index(r.p[a] + reach);
    }
    for(std::int64_t i = from[0]; i <= to[0]; ++i)
      for(std::int64_t j = from[1]; j <= to[1]; ++j)
        for(std::int64_t k = from[2]; k <= to[2]; ++k)
          for(std::uint32_t q = grid.first({i, j, k}); q != Filter_cell_lists::none; q = grid.next(q))
            if(distance(kept[q].p, r.p) < radius) return true;
    return false;
  }
};

// FILTERPOINTS: greedy in the curve's order with a hash grid; a point is
// dropped when an accepted one is closer than min_edge_ratio times its
// size.  A point looks at the cells its radius's box reaches on each
// axis, so any cell size gives the same answer and only sets the cost,
// measured on bunny00 (the filter still sequential, the pass's filter
// time, same points):
// a cell of the 90th percentile of the radii and a reach of one cell all
// around, 27 cells, 0.174 s; the radius's box, 0.145 s; that box in
// cells of twice that percentile, 0.125 s, of three times, 0.117 s.
// On several threads (from 2 x 16,384 candidates, chunk_count) the
// curve's order is cut into one run per thread (a run of the curve is a
// compact region) and each run is filtered so on its own; then a point a
// run kept is dropped if a point that an earlier run kept is too close.
// That second look reads only what the first kept, so it too runs as one
// task per run; a point it drops may have made its run drop a neighbour,
// so near the runs' borders a few points fewer go in, which the next pass
// makes up (bunny00's refinement inserts 0.1% fewer points on 2 threads;
// 70,000 random points in 4 slabs under 3 radii wide, mostly border, keep
// 7.9% fewer).  One run is the greedy filter itself.
inline void filter_points(std::vector<Refinement_point>& points, double min_edge_ratio, int threads)
{
  if(points.empty()) return;
  // The percentile of a sample (every stride-th point): the cell size
  // sets only the cost, and the selection over every radius took a
  // quarter of the filter on bunny00.
  const std::size_t stride = std::max<std::size_t>(1, points.size() / 4096);
  std::vector<double> radii;
  for(std::size_t i = 0; i < points.size(); i += stride) radii.push_back(min_edge_ratio * points[i].h);
  const std::size_t at = std::min(radii.size() - 1, radii.size() * 9 / 10);
  std::nth_element(radii.begin(), radii.begin() + at, radii.end());
  const Filter_cells cells{3 * radii[at]};
  const int runs = chunk_count(points.size(), threads);
  std::vector<Filter_cell_lists> grids(runs);
  std::vector<std::vector<Refinement_point>> kept(runs);
  for_each_chunk(runs, [&](int c) {
    const std::size_t begin = chunk_begin(points.size(), runs, c), end = chunk_begin(points.size(), runs, c + 1);
    grids[c].reserve(end - begin);
    for(std::size_t i = begin; i < end; ++i) {
      const Refinement_point& r = points[i];
      if(cells.has_point_near(grids[c], kept[c], r, min_edge_ratio * r.h)) continue;
      grids[c].add(cells.cell_of(r.p), static_cast<std::uint32_t>(kept[c].size()));
      kept[c].push_back(r);
    }
  });
  std::vector<std::vector<char>> dropped(runs);
  for_each_chunk(runs, [&](int c) {
    dropped[c].assign(kept[c].size(), 0);
    for(std::size_t i = 0; i < kept[c].size(); ++i) {
      const Refinement_point& r = kept[c][i];
      for(int d = 0; d < c && !dropped[c][i]; ++d)
        dropped[c][i] = cells.has_point_near(grids[d], kept[d], r, min_edge_ratio * r.h);
    }
  });
  points.clear();
  for(int c = 0; c < runs; ++c)
    for(std::size_t i = 0; i < kept[c].size(); ++i)
      if(!dropped[c][i]) points.push_back(kept[c][i]);
}

class Constrained_refinement
{
public:
  Constrained_refinement(Constrained_mesh& cm, const Refinement_options& options)
      : cm_(cm), options_(options)
  {}

  // Runs passes until no point is inserted; `progress` sees every pass.
  std::vector<Refinement_pass> run(const std::function<void(const Refinement_pass&, int)>& progress)
  {
    std::vector<Refinement_pass> passes;
    for(int k = 0; k < options_.max_passes; ++k) {
      typedef std::chrono::steady_clock Clock;
      const Clock::time_point t0 = Clock::now();
      Refinement_pass pass;
      std::vector<Refinement_point> points = sample_points();
      pass.candidates = points.size();
      const Clock::time_point t1 = Clock::now();
      sort_along_curve(points);
      filter_points(points, options_.min_edge_ratio, options_.threads);
      pass.filtered_out = pass.candidates - points.size();
      const Clock::time_point t2 = Clock::now();
      insert_points(points, k == 0, pass);
      const Clock::time_point t3 = Clock::now();
      pass.sample_seconds = std::chrono::duration<double>(t1 - t0).count();
      pass.filter_seconds = std::chrono::duration<double>(t2 - t1).count();
      pass.insert_seconds = std::chrono::duration<double>(t3 - t2).count();
      CGAL_assertion_code(std::string why;)
      CGAL_assertion_msg(cm_.is_valid(&why), why.c_str());
      pass.tetrahedra = count_volume_tetrahedra();
      pass.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      passes.push_back(pass);
      if(progress) progress(pass, k);
      if(pass.inserted == 0) break;
    }
    return passes;
  }

private:
  std::size_t count_volume_tetrahedra() const
  {
    std::atomic<std::size_t> n(0);
    for_each_range(cm_.mesh.number_of_slots(), options_.threads, [&](std::size_t begin, std::size_t end) {
      std::size_t here = 0;
      for(Tet_id t = static_cast<Tet_id>(begin); t < end; ++t)
        here += cm_.mesh.is_live(t) && cm_.subdomain[t] > 0 ? 1 : 0;
      n += here;
    });
    return n;
  }

  // SAMPLEPOINTS: circumcentres of large tetrahedra that fall in their own
  // subdomain (a centre beyond the surface would need the surface split,
  // which this mesher never does).  The slots are cut into one run per
  // thread, each sampled with its own walk (the mesh is only read), and the
  // runs' points joined in slot order.
  std::vector<Refinement_point> sample_points()
  {
    const std::size_t slots = cm_.mesh.number_of_slots();
    no_sample_.resize(slots, 0);
    const int chunks = chunk_count(slots, std::max(1, options_.threads));
    // One walk state per run, kept from pass to pass: one thread samples
    // exactly as the sequential mesher always did.
    if(walk_scratches_.size() < std::size_t(chunks)) walk_scratches_.resize(chunks);
    std::vector<std::vector<Refinement_point>> found(chunks);
    for_each_chunk(chunks, [&](int c) {
      sample_slots(chunk_begin(slots, chunks, c), chunk_begin(slots, chunks, c + 1), walk_scratches_[c], found[c]);
    });
    std::vector<Refinement_point> points;
    for(const std::vector<Refinement_point>& run : found) points.insert(points.end(), run.begin(), run.end());
    return points;
  }

  void sample_slots(Tet_id begin, Tet_id end, Insertion_scratch& scratch, std::vector<Refinement_point>& points)
  {
    const Flat_storage& m = cm_.mesh;
    // The kernel's walk, sequential: it reads the mesh and writes only `scratch`.
    Delaunay_kernel<Sequential_ownership, Mesh_slots, Walk_giving_up> walker(cm_.mesh, scratch, Mesh_slots{&cm_.mesh},
                                                                            cm_.filter);
    for(Tet_id t = begin; t < end; ++t) {
      if(no_sample_[t] || !m.is_live(t) || cm_.subdomain[t] <= 0) continue;
      const Vertex_id* tv = m.vertex_ids(t);
      const double* w[4] = {m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])};
      // A first look, before the circumcentre's own h: the vertices' mean,
      // within the caps (a subdomain's cap is below its surface's sizes).
      const double h_mean =
          cm_.size.capped((cm_.size[tv[0]] + cm_.size[tv[1]] + cm_.size[tv[2]] + cm_.size[tv[3]]) / 4, cm_.subdomain[t]);
      Refinement_point r;
      if(!circumcentre(w[0], w[1], w[2], w[3], r.p)) {
        no_sample_[t] = 1;
        continue;
      }
      const double radius = distance(r.p, w[0]);
      if(radius <= options_.radius_ratio * h_mean) {
        no_sample_[t] = 1;
        continue;
      }
      // Outside the input's box the static filters do not hold (and the
      // centre is outside every volume anyway): no walk there.
      Tet_id u = cm_.in_box(r.p) ? walker.walk(t, r.p) : no_tet;
      if(u == no_tet || m.is_ghost(u) || cm_.subdomain[u] != cm_.subdomain[t]) {
        // The centre lies beyond the surface, which is never split: the
        // centroid, inside t, refines t instead (the corners of a cube
        // have all their centres outside after the first point).
        for(int a = 0; a < 3; ++a) r.p[a] = (w[0][a] + w[1][a] + w[2][a] + w[3][a]) / 4;
        u = t;
      }
      r.h = interpolated_size(cm_, u, r.p);
      if(radius <= options_.radius_ratio * r.h) continue;
      r.subdomain = cm_.subdomain[t];
      points.push_back(r);
    }
  }

  // The candidates in the order of the Moore curve over the input's box.
  // FILTERPOINTS and INSERTPOINTS then meet them in this order: the filter's
  // grid cells and the insertions' tetrahedra are near those of the last
  // point (in sampling order, the slot order of tetrahedra reused far
  // apart, the sequential walk took 19 steps per point; bunny00, 1 thread).
  // Where the insertion keeps the order (sequentially, after the first
  // pass's first round), an accepted point is also never refused at
  // insertion by one accepted after it with a smaller h.
  void sort_along_curve(std::vector<Refinement_point>& points) const
  {
    const Moore_grid grid(cm_.box_lo, cm_.box_hi, moore_bits_per_axis(points.size()));
    const Moore_curve curve(grid.bits_per_axis());
    std::vector<Key_value<std::uint32_t>> keyed(points.size()), scratch;
    for_each_range(points.size(), options_.threads, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i) keyed[i] = {grid.key(curve, points[i].p), static_cast<std::uint32_t>(i)};
    });
    // Stable: points with one key keep their sampling order.
    radix_sort(keyed, scratch, 3 * grid.bits_per_axis(), std::max(1, options_.threads));
    std::vector<Refinement_point> sorted(points.size());
    for_each_range(points.size(), options_.threads, [&](std::size_t begin, std::size_t end) {
      for(std::size_t i = begin; i < end; ++i) sorted[i] = points[keyed[i].value];
    });
    points.swap(sorted);
  }

  // INSERTPOINTS: every point gets its vertex record first (the engine
  // partitions vertices by their records), then the engine inserts them.
  void insert_points(const std::vector<Refinement_point>& points, bool first_pass, Refinement_pass& pass)
  {
    Flat_storage& m = cm_.mesh;
    const Vertex_id first_new = static_cast<Vertex_id>(m.vertices.size());
    std::vector<Vertex_id> ids(points.size());
    for(std::size_t i = 0; i < points.size(); ++i) {
      Vertex_record record;
      record.xyz[0] = points[i].p[0]; record.xyz[1] = points[i].p[1]; record.xyz[2] = points[i].p[2];
      record.scratch = 0;
      m.vertices.push_back(record);
      cm_.size.push_back(points[i].h);
      ids[i] = first_new + static_cast<Vertex_id>(i);
    }
    Constrained_point_insertion policy(cm_, options_.min_edge_ratio, points, first_new, no_sample_);
    Partitioned_insertion engine(m, cm_.filter, Sub_determinant_filter(), cm_.box_lo, cm_.box_hi, 0, false);
    engine.set_vertices_in_mesh(first_new);
    engine.set_min_points_per_partition(options_.min_points_per_thread);
    if(options_.keep_vertex_keys) engine.keep_vertex_keys(); // it lives for this batch: no vertex moves
    std::vector<Vertex_id> duplicate_of(points.size(), ghost_vertex); // never written: no duplicate result
    Tet_id hint = m.first_live_tet();
    Kernel_statistics stats;
    // The first pass fills the empty mesh, whose tetrahedra span the
    // volume from surface to surface: its first points have cavities of
    // hundreds of tetrahedra, which partitions cannot hold (bunny00, 2
    // threads: 17% of 32,747 points settled in partitions, 0.35 s for the
    // pass).  Every 16th point first, as a round of its own, breaks those
    // tetrahedra up; the rest then mostly settles in partitions (62%, 0.21 s).
    if(first_pass && ids.size() >= 2 * first_pass_stride) {
      std::vector<Vertex_id> coarse, rest;
      for(std::size_t i = 0; i < ids.size(); ++i) (i % first_pass_stride == 0 ? coarse : rest).push_back(ids[i]);
      engine.insert(std::move(coarse), std::max(1, options_.threads), first_new, duplicate_of, hint, pass.attempts,
                    stats, policy);
      ids.swap(rest);
    }
    engine.insert(std::move(ids), std::max(1, options_.threads), first_new, duplicate_of, hint, pass.attempts,
                  stats, policy);
    for(std::size_t i = 0; i < points.size(); ++i) pass.inserted += policy.inserted(i) ? 1 : 0;
    pass.aborted = points.size() - pass.inserted;
    pass.walk_steps = stats.walk_steps;
    for(const Partition_round& attempt : pass.attempts)
      if(attempt.partitions > 1) pass.settled_in_partitions += attempt.inserted;
    drop_unused_vertices(first_new, policy);
  }

  // The records of the points left out are in no tetrahedron: the inserted
  // ones move down over them, and the tetrahedra follow.
  void drop_unused_vertices(Vertex_id first_new, const Constrained_point_insertion& policy)
  {
    Flat_storage& m = cm_.mesh;
    const std::size_t n = m.vertices.size() - first_new;
    std::vector<Vertex_id> renumber(n);
    Vertex_id next = first_new;
    for(std::size_t i = 0; i < n; ++i) {
      if(!policy.inserted(i)) continue;
      renumber[i] = next;
      m.vertices[next] = m.vertices[first_new + i];
      cm_.size[next] = cm_.size[first_new + i];
      ++next;
    }
    if(next == first_new + n) return;
    m.vertices.resize(next);
    cm_.size.resize(next);
    for_each_range(m.number_of_slots(), options_.threads, [&](std::size_t begin, std::size_t end) {
      for(Tet_id t = static_cast<Tet_id>(begin); t < end; ++t) {
        if(!m.is_live(t)) continue;
        Vertex_id* tv = m.vertex_ids(t);
        for(int i = 0; i < 4; ++i)
          if(tv[i] >= first_new && tv[i] != ghost_vertex) tv[i] = renumber[tv[i] - first_new];
      }
    });
  }

  static constexpr std::size_t first_pass_stride = 16;

  Constrained_mesh& cm_;
  Refinement_options options_;
  std::vector<Insertion_scratch> walk_scratches_; // SAMPLEPOINTS' walks, one per run of slots
  // Per slot: 1 when SAMPLEPOINTS found that its tetrahedron gives no
  // point whatever the rest of the mesh (flat, or small by its own
  // vertices' sizes), which holds until an insertion writes the slot again
  // (Constrained_point_insertion clears it).  Later passes skip those:
  // the last passes insert a few hundred points, or none, into a million
  // tetrahedra.
  std::vector<std::uint8_t> no_sample_;
};

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_REFINEMENT_H
