// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Barrier-synchronised parallel insertion: the two-level multithreaded
// Delaunay kernel of Remacle et al., "Multi-threaded mesh generation"
// (§3-4), beside the Moore-partitioned engine of Parallel_insertion.h.
//
// The points of a BRIO round, in curve order, are cut into runs of equal
// size (the paper's M threads times M2 points each).  Every iteration takes
// the next point of every run, in two steps separated by barriers:
//   CAVITIES  each run walks to its point and searches its cavity in the
//             triangulation of the last iteration, which nobody writes
//             meanwhile; it claims every tetrahedron it tests (those in
//             conflict and those just outside) in a per-slot word;
//   BALLS     a run whose claimed tetrahedra no run of smaller index claimed
//             too fills its cavity; the others search the same point again
//             in the next iteration.
// So conflicts are decided by the cavities themselves, not by which region
// a tetrahedron's vertices lie in, and no walk ever fails.  Outside
// tetrahedra are claimed too because a ball rewrites their neighbour codes.
//
// A claim word holds (iteration, 255 - run, in conflict) and grows by an
// atomic maximum, so every word ends holding its highest-priority claimer
// whatever the timing; a run that sees or overwrites a claim of its
// iteration marks the lower run as beaten.  Which points an iteration
// inserts, and the slots each run takes (its own free list and fixed range
// of fresh slots), follow from the input alone: the triangulation is the
// same cell for cell for the same input and thread count, whatever the
// timing.
//
// Each thread runs a fixed share of the runs (a run's cavity is searched
// and filled in the same cache) and publishes the steps it has finished.
// A share that no thread has started when the first barrier has waited for
// it a while (its TBB thread busy elsewhere) is taken by the waiting
// thread, so a barrier never waits for a thread that is not there.
//
// Per point this engine costs about 1.2 times the sequential kernel (the
// claim words are one more cache line per tested tetrahedron; the vertex
// numbering of the ball cannot use the shared vertex scratch words), and
// its threads wait for each other at every barrier.  On 2 cores it is slower
// than the partitioned engine on every input measured, so the partitioned
// engine stays the default (the manual's Parallel Insertion section has the
// table).
//
// An exception in one thread (an assertion, std::bad_alloc) stops the others
// at their next barrier and is thrown again by insert(); the triangulation
// is then left incomplete.

#ifndef CGAL_FDT3_INTERNAL_BARRIER_INSERTION_H
#define CGAL_FDT3_INTERNAL_BARRIER_INSERTION_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Parallel_insertion.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <thread>
#include <vector>

#if defined(__x86_64__) || defined(__i386__)
#include <immintrin.h>
#endif

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// One run of points of the barrier engine and what its current point needs.
struct Barrier_run
{
  const Vertex_id* next = nullptr; // the point this run inserts next
  const Vertex_id* end = nullptr;
  Tet_id hint = 0;
  std::vector<Tet_id> free;        // freed slots, taken first
  Partition_slots slots;           // then its own range of fresh slots
  Tet_id first_fresh_slot = 0;     // where that range starts
  Insertion_scratch scratch;       // walk's random state, statistics, deltas
  std::vector<Tet_id> cavity;      // found by CAVITIES, filled by BALLS
  std::vector<Facet_code> facets;  // cavity boundary, as (cavity tetrahedron, facet)
  std::vector<Boundary_facet> boundary; // the same facets as new tetrahedra, read by CAVITIES
  std::size_t cavity_ghosts = 0;
  bool large = false;              // more than 31 boundary vertices: glued by the edge hash
  std::vector<Tet_id> ball;
  // Local numbers 1..31 of the boundary vertices, for the adjacency table,
  // in an open-addressing table of the run's own (the vertex records'
  // scratch words are shared with other runs' cavities); empty keys are the
  // ghost vertex, and the keys used are emptied after each cavity.
  static constexpr unsigned numbering_size = 128;
  // Keys stored at most: the table stays sparse enough to probe, and past
  // 31 vertices the numbers are saturated anyway.
  static constexpr unsigned numbering_limit = 96;
  Vertex_id numbering_key[numbering_size];
  std::uint8_t numbering_value[numbering_size];
  std::uint8_t numbering_used[numbering_size];
  unsigned numbered = 0;
  bool has_cavity = false;         // CAVITIES left a cavity for BALLS
  bool stalled = false;            // out of slots: the rest goes sequential
  std::size_t retries = 0;         // points tried again after a run of smaller index won
  std::atomic<bool> beaten{false}; // a run of smaller index claimed a tetrahedron of the cavity

  Barrier_run() { std::fill(std::begin(numbering_key), std::end(numbering_key), ghost_vertex); }
  bool done() const { return stalled || next == end; }
};

// One thread's place in the barrier engine, alone on its cache line: the
// steps it has finished, published for the others' barrier waits.
struct alignas(64) Barrier_participant
{
  std::atomic<int> taken{0};
  std::atomic<std::uint64_t> steps_done{0};
  int active_runs = 0; // runs with points left after its last BALLS step
};

class Barrier_insertion
{
public:
  // Runs per thread (the paper's M2): more runs make the barriers rarer and
  // the iterations' work more even, and cost memory for each run's lists
  // (shell, 1e6 points, 2 threads: 1, 2, 4, 8, 16 runs took 1.94, 1.87,
  // 1.83, 1.78, 1.77 s).
  static constexpr int runs_per_thread = 8;
  // Below this many points per run a round is inserted sequentially.
  static constexpr std::size_t min_points_per_run = 256;

  Barrier_insertion(Flat_storage& mesh, const Static_filter& filter, const Sub_determinant_filter& sub_filter,
                    bool timed)
      : m_(mesh), filter_(filter), sub_filter_(sub_filter), timed_(timed)
  {}

  void set_vertices_in_mesh(std::size_t n) { vertices_in_mesh_ = n; }
  // Called with the points of insert()'s call settled so far: every
  // Partitioned_insertion::progress_step points of the sequential parts, and
  // about as often during the barrier iterations (there an estimate: run 0's
  // share done times the runs; called by the thread that runs run 0).
  void set_progress(std::function<void(std::size_t)> progress) { progress_ = std::move(progress); }

  // Inserts `points` (vertex ids whose records are written, in curve order)
  // with `threads` threads; duplicate_of[v - first_new] receives the
  // existing vertex for a duplicate.  Appends one row to `rounds` for the
  // barrier iterations and one for the sequential finish, if any.  The
  // rounds of fewer than 256 points per run are sequential; runs are capped
  // at 255 (the claim word's field).
  void insert(const std::vector<Vertex_id>& points, int threads, Vertex_id first_new,
              std::vector<Vertex_id>& duplicate_of, Tet_id& hint, std::vector<Partition_round>& rounds,
              Kernel_statistics& stats)
  {
    if(!m_.is_live(hint)) hint = m_.first_live_tet();
    const int runs = std::min<int>(threads * runs_per_thread, 255);
    std::vector<Vertex_id> rest;
    if(threads > 1 && points.size() >= min_points_per_run * std::size_t(runs)) {
      const auto t0 = std::chrono::steady_clock::now();
      Partition_round row;
      row.points = points.size();
      row.partitions = runs;
      row.mesh_vertices = vertices_in_mesh_;
      row.retried = insert_with_barriers(points, threads, runs, first_new, duplicate_of, hint, stats, rest);
      row.inserted = points.size() - rest.size();
      row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      vertices_in_mesh_ += row.inserted;
      rounds.push_back(row);
      if(progress_) progress_(row.inserted);
    } else {
      rest = points;
    }
    if(rest.empty()) return;
    const auto t0 = std::chrono::steady_clock::now();
    Partition_round row;
    row.points = row.inserted = rest.size();
    row.mesh_vertices = vertices_in_mesh_;
    const std::size_t before = points.size() - rest.size();
    const std::size_t step = progress_ ? Partitioned_insertion::progress_step : 0;
    insert_in_order(m_, rest, first_new, duplicate_of, hint, filter_, sub_filter_, timed_, stats, step,
                    [&](std::size_t done) { progress_(before + done); });
    row.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    vertices_in_mesh_ += row.inserted;
    rounds.push_back(row);
  }

private:
  // Claim words: iteration (23 bits), 255 - run (8 bits), in conflict (1 bit).
  static constexpr unsigned run_shift = 1, iteration_shift = 9;
  static constexpr std::uint64_t max_iterations = (std::uint64_t(1) << 23) - 1;

  static std::uint32_t claim_base(std::uint64_t iteration, std::size_t run)
  {
    return static_cast<std::uint32_t>((iteration << iteration_shift) | ((255 - run) << run_shift));
  }
  static int run_of_claim(std::uint32_t c) { return 255 - int((c >> run_shift) & 255u); }
  static std::uint64_t iteration_of_claim(std::uint32_t c) { return c >> iteration_shift; }

  // The barrier iterations over `points`; the points of runs that ran out
  // of slots go to `rest`, and `hint` becomes a tetrahedron near the first
  // of them.  Returns the number of cavities found again in a later
  // iteration.
  std::size_t insert_with_barriers(const std::vector<Vertex_id>& points, int threads, int runs,
                                   Vertex_id first_new, std::vector<Vertex_id>& duplicate_of, Tet_id& hint,
                                   Kernel_statistics& stats, std::vector<Vertex_id>& rest)
  {
    // Fresh slots: every run's worst case, fixed before the threads start.
    std::vector<Barrier_run> run(static_cast<std::size_t>(runs));
    std::vector<Tet_id> fresh_begin(runs + 1);
    fresh_begin[0] = m_.number_of_slots();
    for(int r = 0; r < runs; ++r) {
      const std::size_t begin = chunk_begin(points.size(), runs, r), end = chunk_begin(points.size(), runs, r + 1);
      run[r].next = points.data() + begin;
      run[r].end = points.data() + end;
      run[r].hint = hint;
      run[r].scratch.timed = timed_;
      fresh_begin[r + 1] = fresh_begin[r] + Partitioned_insertion::fresh_slots_per_point * (end - begin) + 4096;
    }
    m_.resize_tets(fresh_begin[runs], Flat_storage::New_slots::left_unwritten);
    for(std::size_t k = 0; k < m_.free_tets.size(); ++k) run[k % runs].free.push_back(m_.free_tets[k]);
    m_.free_tets.clear();
    for(int r = 0; r < runs; ++r)
    {
      run[r].slots = Partition_slots{&run[r].free, fresh_begin[r], fresh_begin[r + 1], &m_.tets};
      run[r].first_fresh_slot = fresh_begin[r];
    }
    claims_.assign(fresh_begin[runs], 0);

    // Participant k runs the k-th share of the runs on one thread, so a
    // run's cavity is searched and filled in the same cache.  Steps alternate
    // CAVITIES (even) and BALLS (odd); after each, every slot publishes the
    // steps it has finished and waits for the others.  A share that no
    // thread has taken while the first barrier waits for it (its TBB thread
    // busy elsewhere) is taken by the waiting thread: only the first barrier
    // can wait for a share that has not started.
    std::vector<Barrier_participant> participants(static_cast<std::size_t>(threads));
    std::atomic<bool> failed{false};
    std::exception_ptr failure;
    std::mutex failure_mutex;
    const std::size_t run0_points = static_cast<std::size_t>(run[0].end - run[0].next);
    const std::uint64_t report_every =
        2 * std::max<std::uint64_t>(1, Partitioned_insertion::progress_step / std::uint64_t(runs));
    auto runs_of = [&](int k) {
      return std::make_pair(chunk_begin(runs, threads, k), chunk_begin(runs, threads, k + 1));
    };
    auto participant = [&](int c) {
      int untaken = 0;
      if(!participants[c].taken.compare_exchange_strong(untaken, 1)) return;
      std::vector<int> mine(1, c);
      try {
      with_vector_paths([&](auto paths) {
        typedef Delaunay_kernel<Sequential_ownership, Mesh_slots, Walk_to_the_end, decltype(paths)> Kernel;
        auto run_step = [&](int k, std::uint64_t step) {
          int active_runs = 0;
          for(std::size_t r = runs_of(k).first; r < runs_of(k).second; ++r) {
            Barrier_run& me = run[r];
            Kernel kernel(m_, me.scratch, Mesh_slots{&m_}, filter_, sub_filter_);
            if(step % 2 == 0) {
              if(!me.done()) find_cavity(kernel, run, r, step / 2 + 1, duplicate_of, first_new);
            } else if(me.has_cavity) {
              me.has_cavity = false;
              if(me.beaten.load(std::memory_order_relaxed)) {
                me.beaten.store(false, std::memory_order_relaxed);
                ++me.retries;
              } else {
                fill_ball(me);
              }
            }
            active_runs += me.done() ? 0 : 1;
          }
          // Read by the others after this step's barrier, rewritten only two
          // steps later, past the next barrier, which they must cross first.
          if(step % 2 == 1) participants[k].active_runs = active_runs;
          if(k == 0 && step % report_every == report_every - 1 && progress_)
            progress_(static_cast<std::size_t>(run[0].end - run[0].next) >= run0_points
                          ? 0
                          : (run0_points - static_cast<std::size_t>(run[0].end - run[0].next)) * std::size_t(runs));
          participants[k].steps_done.store(step + 1, std::memory_order_release);
        };
        for(std::uint64_t step = 0;; ++step) {
          for(std::size_t j = 0; j < mine.size(); ++j) run_step(mine[j], step);
          const auto waiting_since = std::chrono::steady_clock::now();
          for(int k = 0; k < threads; ++k) {
            unsigned spins = 0;
            while(participants[k].steps_done.load(std::memory_order_acquire) <= step) {
              if(failed.load(std::memory_order_relaxed)) return;
              if(step == 0 && spins % 1024 == 1023 &&
                 std::chrono::steady_clock::now() - waiting_since > std::chrono::milliseconds(2)) {
                int never_started = 0;
                if(participants[k].taken.compare_exchange_strong(never_started, 1)) {
                  mine.push_back(k);
                  run_step(k, step);
                }
              }
              pause(spins);
            }
          }
          if(step % 2 == 1) {
            int active_runs = 0;
            for(int k = 0; k < threads; ++k) active_runs += participants[k].active_runs;
            if(active_runs == 0 || step / 2 + 2 >= max_iterations) return;
          }
        }
      });
      } catch(...) {
        std::lock_guard<std::mutex> lock(failure_mutex);
        if(!failure) failure = std::current_exception();
        failed.store(true, std::memory_order_relaxed);
      }
    };
    for_each_chunk(threads, participant);
    if(failure) std::rethrow_exception(failure);

    // Unused fresh slots and the runs' free lists go back to the mesh; the
    // points of stalled runs are left for the sequential finish.
    Tet_id end = fresh_begin[0];
    std::size_t retried = 0;
    hint = run[0].hint;
    for(int r = 0; r < runs; ++r) {
      Barrier_run& me = run[r];
      m_.live_tets += me.scratch.live_delta;
      m_.ghost_tets += me.scratch.ghost_delta;
      stats.add(me.scratch.stats);
      m_.free_tets.insert(m_.free_tets.end(), me.free.begin(), me.free.end());
      if(r + 1 < runs) {
        for(Tet_id t = me.slots.next_fresh; t < fresh_begin[r + 1]; ++t) {
          m_.tets[t].v[0] = mark_bit; // never written: free
          m_.free_tets.push_back(t);
        }
      } else {
        end = me.slots.next_fresh;
      }
      if(rest.empty() && me.next != me.end) hint = me.hint;
      rest.insert(rest.end(), me.next, me.end);
      retried += me.retries;
    }
    m_.resize_tets(end, Flat_storage::New_slots::left_unwritten);
    if(!m_.is_live(hint)) hint = m_.first_live_tet();
    claims_.clear();
    claims_.shrink_to_fit();
    return retried;
  }

  static void pause(unsigned& spins)
  {
    if(++spins % 1024 != 0) {
#if defined(__x86_64__) || defined(__i386__)
      _mm_pause();
#endif
    } else {
      std::this_thread::yield();
    }
  }

  // The claim word of t rises to `value` unless a run of smaller index holds
  // it in this iteration; whichever of two runs has the larger index is
  // marked beaten.
  void claim(Tet_id t, std::uint32_t value, std::vector<Barrier_run>& run, Barrier_run& me)
  {
    std::uint32_t* word = &claims_[t];
    std::uint32_t old = __atomic_load_n(word, __ATOMIC_RELAXED);
    while(old < value) {
      if(__atomic_compare_exchange_n(word, &old, value, true, __ATOMIC_RELAXED, __ATOMIC_RELAXED)) {
        if(iteration_of_claim(old) == iteration_of_claim(value))
          run[run_of_claim(old)].beaten.store(true, std::memory_order_relaxed);
        return;
      }
    }
    if((old >> run_shift) > (value >> run_shift)) me.beaten.store(true, std::memory_order_relaxed);
  }

  // Whether this run's search has already tested t, and with which outcome
  // (1 in conflict, 0 not, -1 not tested), when a run of smaller index
  // holds t's word: the run's own lists say (rare, only where cavities
  // meet).  The queue holds the facet codes the search entered through.
  __attribute__((noinline)) int own_outcome(const Barrier_run& me, Tet_id t, std::size_t queued,
                                            std::size_t found) const
  {
    for(std::size_t k = 0; k < queued; ++k)
      if(tet_of(static_cast<Facet_code>(me.cavity[k])) == t) return 1;
    for(std::size_t k = 0; k < found; ++k)
      if(tet_of(m_.neighbor_code(me.facets[k])) == t) return 0;
    return -1;
  }

  // CAVITIES for run r: walk, duplicate check, breadth-first search of the
  // tetrahedra in conflict, claiming each one tested.  Reads the mesh only.
  template <class Kernel>
  void find_cavity(Kernel& kernel, std::vector<Barrier_run>& run, std::size_t r, std::uint64_t iteration,
                   std::vector<Vertex_id>& duplicate_of, Vertex_id first_new)
  {
    Barrier_run& me = run[r];
    const Vertex_id v = *me.next;
    const double* p = m_.point(v);
    if(!m_.is_live(me.hint)) me.hint = some_live_tet(run);
    typedef std::chrono::steady_clock Clock;
    Clock::time_point t0, t1;
    if(me.scratch.timed) t0 = Clock::now();
    const Tet_id start = kernel.walk(me.hint, p);
    if(me.scratch.timed) {
      t1 = Clock::now();
      me.scratch.stats.walk_seconds += std::chrono::duration<double>(t1 - t0).count();
    }
    me.hint = start;
    if(!m_.is_ghost(start)) {
      for(int i = 0; i < 4; ++i) {
        const Vertex_id w = m_.vertex(start, i);
        if(same_point(m_.point(w), p)) {
          duplicate_of[v - first_new] = w;
          ++me.scratch.stats.duplicates;
          ++me.next;
          return;
        }
      }
    }
    const std::uint32_t base = claim_base(iteration, r);
    // As in the kernel's search, whether a neighbour is in conflict steers
    // no branch: it is written both as the next queue entry (the facet code
    // it was entered through) and as the next boundary facet, and only the
    // counts move.  Both lists have room for one more pop's four entries.
    std::vector<Tet_id>& queue = me.cavity;
    std::vector<Facet_code>& facets = me.facets;
    if(queue.size() < 64) queue.resize(64);
    if(facets.size() < 64) facets.resize(64);
    std::size_t queued = 0, found = 0;
    auto visit = [&](Tet_id t, int f) __attribute__((always_inline)) {
      const Facet_code code = m_.neighbor_code(t, f);
      const Tet_id u = tet_of(code);
      const std::uint32_t held = __atomic_load_n(&claims_[u], __ATOMIC_RELAXED);
      bool conflict;
      if((held >> run_shift) == (base >> run_shift)) {
        if(held & 1u) return; // in the cavity already
        conflict = false;     // tested already, through another facet
      } else {
        const int known = (held >> run_shift) > (base >> run_shift) ? own_outcome(me, u, queued, found) : -1;
        if(known == 1) return;
        conflict = known == 0 ? false : kernel.in_conflict(u, p);
        if(known < 0) {
          ++me.scratch.stats.conflict_tests;
          claim(u, base | std::uint32_t(conflict), run, me);
          const Facet_code* n = m_.tets[u].n;
          for(int g = 0; g < 4; ++g) {
            __builtin_prefetch(&m_.tets[tet_of(n[g])]);
            __builtin_prefetch(&claims_[tet_of(n[g])]);
          }
        }
      }
      queue[queued] = code;
      queued += conflict;
      facets[found] = facet_code(t, f);
      found += !conflict;
    };
    claim(start, base | 1u, run, me);
    queue[queued++] = facet_code(start, 0);
    for(int f = 0; f < 4; ++f) visit(start, f);
    for(std::size_t k = 1; k < queued; ++k) {
      if(queued + 3 > queue.size()) queue.resize(2 * queue.size());
      if(found + 3 > facets.size()) facets.resize(2 * facets.size());
      const Facet_code entered = static_cast<Facet_code>(queue[k]);
      const Tet_id t = tet_of(entered);
      const int back = facet_of(entered);
      visit(t, (back + 1) & 3);
      visit(t, (back + 2) & 3);
      visit(t, (back + 3) & 3);
    }
    for(std::size_t k = 0; k < queued; ++k) queue[k] = tet_of(static_cast<Facet_code>(queue[k]));
    queue.resize(queued);
    facets.resize(found);
    record_boundary(me);
    me.has_cavity = true;
    if(me.scratch.timed) me.scratch.stats.cavity_seconds += std::chrono::duration<double>(Clock::now() - t1).count();
  }

  // The boundary facets as new tetrahedra (p, a, b, c), with the ghost last,
  // their outside neighbours and local vertex numbers, read while the
  // cavity's records are in cache.
  void record_boundary(Barrier_run& me)
  {
    me.numbered = 0;
    me.large = false;
    const std::size_t facets = me.facets.size();
    me.boundary.resize(facets);
    for(std::size_t k = 0; k < facets; ++k) {
      const Facet_code code = me.facets[k];
      const Vertex_id* tv = m_.vertex_ids(tet_of(code));
      const int f = facet_of(code);
      Vertex_id a = tv[facet_vertex[f][0]], b = tv[facet_vertex[f][1]], c = tv[facet_vertex[f][2]];
      if(a == ghost_vertex) {
        a = b; b = c; c = ghost_vertex;
      } else if(b == ghost_vertex) {
        b = a; a = c; c = ghost_vertex;
      }
      Boundary_facet& record = me.boundary[k];
      record.v[0] = a;
      record.v[1] = b;
      record.v[2] = c;
      record.local[0] = number_vertex(me, a);
      record.local[1] = number_vertex(me, b);
      record.local[2] = number_vertex(me, c);
      record.outside = m_.neighbor_code(code);
    }
    me.large = me.numbered >= Insertion_scratch::table_size;
    for(unsigned i = 0; i < me.numbered; ++i) me.numbering_key[me.numbering_used[i]] = ghost_vertex;
    me.cavity_ghosts = 0;
    for(Tet_id t : me.cavity) me.cavity_ghosts += m_.is_ghost(t) ? 1 : 0;
  }

  // Whether v is new on the boundary is a branch no predictor learns (as in
  // the kernel's numbering): when v's slot holds v or nothing, which is
  // nearly always the case, v is written there either way and only the
  // count moves for a new one.  Past 31 vertices the numbers saturate and
  // the ball takes the edge hash.
  static std::uint8_t number_vertex(Barrier_run& me, Vertex_id v)
  {
    if(v == ghost_vertex) return 0;
    static_assert(Barrier_run::numbering_size == 128, "7-bit hash");
    const unsigned h = (v * 2654435761u) >> 25;
    const Vertex_id key = me.numbering_key[h];
    if((key != v && key != ghost_vertex) || me.numbered >= Barrier_run::numbering_limit)
      return number_vertex_after_collision(me, v, h);
    const bool fresh = key != v;
    me.numbering_key[h] = v;
    me.numbering_used[me.numbered] = static_cast<std::uint8_t>(h);
    me.numbered += fresh;
    const unsigned number = std::min<unsigned>(me.numbered, Insertion_scratch::table_size - 1);
    me.numbering_value[h] = fresh ? static_cast<std::uint8_t>(number) : me.numbering_value[h];
    return me.numbering_value[h];
  }

  __attribute__((noinline)) static std::uint8_t number_vertex_after_collision(Barrier_run& me, Vertex_id v,
                                                                              unsigned h)
  {
    constexpr unsigned mask = Barrier_run::numbering_size - 1;
    for(;;) {
      const Vertex_id key = me.numbering_key[h];
      if(key == v) return me.numbering_value[h];
      if(key == ghost_vertex) break;
      h = (h + 1) & mask;
    }
    if(me.numbered >= Barrier_run::numbering_limit) return Insertion_scratch::table_size - 1;
    me.numbering_key[h] = v;
    me.numbering_used[me.numbered++] = static_cast<std::uint8_t>(h);
    me.numbering_value[h] =
        static_cast<std::uint8_t>(std::min<unsigned>(me.numbered, Insertion_scratch::table_size - 1));
    return me.numbering_value[h];
  }

  // A live tetrahedron to walk from when another run's ball deleted this
  // run's hint (rare: runs are far apart on the curve).  Fresh slots that no
  // run has written yet hold garbage and are skipped.
  Tet_id some_live_tet(const std::vector<Barrier_run>& run) const
  {
    for(Tet_id t = 0; t < run.front().first_fresh_slot; ++t)
      if(m_.is_live(t)) return t;
    for(const Barrier_run& r : run)
      for(Tet_id t = r.first_fresh_slot; t < r.slots.next_fresh; ++t)
        if(m_.is_live(t)) return t;
    CGAL_assertion_msg(false, "no live tetrahedron");
    return 0;
  }

  // BALLS for one run whose cavity no run of smaller index touched: the
  // cavity becomes the new vertex joined to its boundary facets.  When the
  // run's slots cannot hold the ball, the mesh stays as it is and the run
  // stops: its points go to the sequential finish.
  void fill_ball(Barrier_run& me)
  {
    if(!me.scratch.timed) return fill_ball_untimed(me);
    const auto t0 = std::chrono::steady_clock::now();
    fill_ball_untimed(me);
    me.scratch.stats.ball_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }

  void fill_ball_untimed(Barrier_run& me)
  {
    const Vertex_id v = *me.next;
    const std::size_t facets = me.facets.size(), cells = me.cavity.size();
    if(facets > cells && !me.slots.reserve(facets - cells)) {
      me.stalled = true;
      return;
    }
    me.ball.resize(facets);
    const std::size_t reused = std::min(facets, cells);
    std::copy(me.cavity.begin(), me.cavity.begin() + reused, me.ball.begin());
    for(std::size_t k = reused; k < cells; ++k) {
      m_.mark_free(me.cavity[k]);
      me.slots.give(me.cavity[k]);
    }
    for(std::size_t k = reused; k < facets; ++k) me.ball[k] = me.slots.take();

    std::size_t new_ghosts = 0;
    for(std::size_t k = 0; k < facets; ++k) {
      const Boundary_facet& b = me.boundary[k];
      const Tet_id t = me.ball[k];
      Tet_record& record = m_.tets[t];
      record.v[0] = v; record.v[1] = b.v[0]; record.v[2] = b.v[1]; record.v[3] = b.v[2];
      record.n[0] = b.outside;
      m_.neighbor_code(b.outside) = facet_code(t, 0);
      new_ghosts += b.v[2] == ghost_vertex ? 1 : 0;
      if(m_.with_sub_determinants) update_sub_determinants(m_, t);
    }
    if(me.large) {
      glue_ball_by_edge_hash(m_, me.boundary.data(), me.ball.data(), me.boundary.size(), me.scratch.large_edges);
      ++me.scratch.stats.large_cavities;
    } else {
      glue_with_table(me);
      ++me.scratch.stats.small_cavities;
    }
    me.scratch.live_delta += static_cast<std::ptrdiff_t>(facets) - static_cast<std::ptrdiff_t>(cells);
    me.scratch.ghost_delta += static_cast<std::ptrdiff_t>(new_ghosts) - static_cast<std::ptrdiff_t>(me.cavity_ghosts);
    ++me.scratch.stats.inserted;
    me.scratch.stats.cavity_tets += cells;
    me.scratch.stats.ball_tets += facets;
    ++me.next;
    me.hint = me.ball[me.next == me.end ? 0
                                        : nearest_boundary_facet(m_, me.boundary.data(), me.boundary.size(),
                                                                 m_.point(*me.next))];
  }

  // Facet i of a new tetrahedron holds the point and the boundary edge
  // opposite b.v[i - 1]; across it lies the new tetrahedron with the same
  // edge reversed, found through the adjacency table indexed by the edge's
  // local vertex numbers, as in the kernel.
  void glue_with_table(Barrier_run& me) const
  {
    constexpr unsigned n = Insertion_scratch::table_size;
    Facet_code* table = me.scratch.edge_table;
    const std::size_t facets = me.boundary.size();
    for(std::size_t k = 0; k < facets; ++k) {
      const Boundary_facet& b = me.boundary[k];
      const unsigned a = b.local[0], bb = b.local[1], c = b.local[2];
      const Tet_id t = me.ball[k];
      table[bb * n + c] = facet_code(t, 1);
      table[c * n + a] = facet_code(t, 2);
      table[a * n + bb] = facet_code(t, 3);
    }
    for(std::size_t k = 0; k < facets; ++k) {
      const Boundary_facet& b = me.boundary[k];
      const unsigned a = b.local[0], bb = b.local[1], c = b.local[2];
      Facet_code* nb = m_.tets[me.ball[k]].n;
      nb[1] = table[c * n + bb];
      nb[2] = table[a * n + c];
      nb[3] = table[bb * n + a];
    }
  }

  Flat_storage& m_;
  Static_filter filter_;
  Sub_determinant_filter sub_filter_;
  bool timed_;
  std::size_t vertices_in_mesh_ = 0;
  std::function<void(std::size_t)> progress_;
  std::vector<std::uint32_t> claims_; // per slot, during insert_with_barriers
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_BARRIER_INSERTION_H
