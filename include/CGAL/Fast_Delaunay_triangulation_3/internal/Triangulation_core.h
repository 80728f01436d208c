// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangulation without CGAL types: flat arrays, the dimension, and the
// main insertion loop of Algorithm 1 (INIT, SORT, then WALK / CAVITY /
// DELAUNAYBALL per point).  The triangulation layer (Flat_triangulation_3.h)
// wraps it with handles and iterators, the Delaunay layer (the public class)
// calls its insertions, removals and moves; data flows one way: points ->
// sort -> kernel -> arrays.
//
// Dimensions below 3: the (distinct) vertices and CGAL's lower-dimensional
// cells, kept by a CGAL triangulation updated point by point
// (Lower_dimensions.h); the first insertion that makes the points span 3D
// drops it and joins a vertex off the plane to the triangles (from dimension
// 2) or builds the tetrahedra of all points (from below).  Vertex ids never change
// once given, except that a bulk insertion removes its own duplicates before
// returning; a removed vertex leaves a dead record (Flat_storage.h), which
// only a move of that vertex revives.

#ifndef CGAL_FDT3_INTERNAL_TRIANGULATION_CORE_H
#define CGAL_FDT3_INTERNAL_TRIANGULATION_CORE_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/BRIO.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Barrier_insertion.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Displacement_flips.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Lower_dimensions.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Parallel_insertion.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_displacement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Parallel_removal.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_removal.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Walk_start_grid.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <numeric>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Timings of the last bulk insertion, in the paper's Table 1 breakdown.
struct Insertion_report
{
  std::size_t points = 0;
  double sort_seconds = 0, init_seconds = 0, insertion_seconds = 0, finish_seconds = 0;
  Kernel_statistics kernel;
  // Partitioned insertion: one row per attempt (paper's Table 2); empty when sequential.
  std::vector<Partition_round> rounds;
};

class Triangulation_core
{
public:
  Flat_storage mesh;
  int dimension = -1;
  // Active exactly while dimension < 3.
  Lower_dimensional_triangulation lower;
  std::uint64_t seed = 0;
  bool timed = false; // per-phase times (four clock reads per point)
  // Moore partitions inserted concurrently (1: sequential kernel only).
  int partitions = 1;
  // Which parallel engine inserts the BRIO rounds after the first.
  enum class Parallel_engine { partitioned, barrier };
  Parallel_engine parallel_engine = Parallel_engine::partitioned;
  // Called during a bulk insertion of n > 1 points with (points settled, n):
  // (0, n) once sorted, then increasing values every few thousand points
  // (per chunk of the sequential loop, per attempt and per chunk of
  // partition 0 of the partitioned rounds, an estimate there), last (n, n).
  // Never per point; never two calls at once, possibly from a worker thread.
  std::function<void(std::size_t, std::size_t)> progress;

  bool sub_determinants() const { return mesh.with_sub_determinants; }
  // Caches the in-sphere sub-determinants of every tetrahedron (or drops them).
  void set_sub_determinants(bool on)
  {
    if(on == mesh.with_sub_determinants) return;
    mesh.with_sub_determinants = on;
    if(!on) {
      mesh.tet_sub_determinants = Raw_array<double>();
      return;
    }
    mesh.tet_sub_determinants.resize(4 * mesh.number_of_slots());
    if(dimension < 3) return; // computed when the tetrahedra are built
    for(Tet_id t = 0; t < mesh.number_of_slots(); ++t)
      if(mesh.is_live(t)) update_sub_determinants(mesh, t);
  }
  Insertion_report last_report;

  // Live vertices; vertex_slots() counts the dead records too (ids are below it).
  std::size_t number_of_vertices() const { return mesh.live_vertices(); }
  std::size_t vertex_slots() const { return mesh.vertices.size(); }

  Triangulation_core()
  {
    mesh.with_sub_determinants = sub_determinants_by_default;
    reset_bounding_box();
    lower.start(mesh);
  }

  void clear()
  {
    mesh.clear();
    reset_bounding_box();
    dimension = -1;
    lower.start(mesh);
    hint_ = 0;
    walk_starts_.clear();
    tet_of_vertex_.clear();
  }

  // Takes over a triangulation built elsewhere (a file read by
  // Triangulation_io.h), already checked with is_valid(): compact slots,
  // distinct vertices; below dimension 3 only the vertices, whose cells are
  // rebuilt here (the Delaunay triangulation is unique).  Keeps the options.
  void assign(Flat_storage&& built, int built_dimension)
  {
    const bool with_sub_determinants = mesh.with_sub_determinants;
    mesh = std::move(built);
    mesh.with_sub_determinants = false;
    dimension = built_dimension;
    if(dimension < 3) lower.rebuild(mesh);
    else lower.stop();
    reset_bounding_box();
    extend_bounding_box(0);
    hint_ = mesh.first_live_tet();
    set_sub_determinants(with_sub_determinants);
  }

  // Throws std::invalid_argument naming the first non-finite coordinate of
  // the n points of a point source (BRIO.h).
  template <class Points, class = enable_if_point_source<Points>>
  static void check_finite(const Points& points, std::size_t n)
  {
    for(std::size_t i = 0; i < n; ++i) {
      for(int a = 0; a < 3; ++a) {
        const double c = points.point(i)[a];
        if(!std::isfinite(c)) {
          std::ostringstream message;
          message << "Fast_Delaunay_triangulation_3: point #" << i << " of the input has a "
                  << (std::isnan(c) ? "NaN" : "infinite") << " coordinate";
          throw std::invalid_argument(message.str());
        }
      }
    }
  }
  static void check_finite(const double* xyz, std::size_t n) { check_finite(Packed_points{xyz}, n); }

  // Inserts n points given as x, y, z triples (already checked finite).
  // vertex_of_input, if not null, receives for every input point the id of
  // its vertex (an older vertex for a duplicate).  Returns the number of new
  // vertices.  If `consumed` is the vector holding xyz, it is freed as soon
  // as the vertex records are written (before the mesh grows).
  std::size_t insert(const double* xyz, std::size_t n, std::vector<Vertex_id>* vertex_of_input,
                     std::vector<double>* consumed = nullptr)
  {
    CGAL_precondition(consumed == nullptr || consumed->data() == xyz);
    return insert(Packed_points{xyz}, n, vertex_of_input, consumed);
  }

  // The same for the n points of a point source (BRIO.h), read where they
  // are; `consumed`, if not null, is the copy of the input that the source
  // reads, freed as above.
  template <class Points, class = enable_if_point_source<Points>>
  std::size_t insert(const Points& points, std::size_t n, std::vector<Vertex_id>* vertex_of_input,
                     std::vector<double>* consumed = nullptr)
  {
    last_report = Insertion_report();
    last_report.points = n;
    if(n == 0) {
      if(vertex_of_input) vertex_of_input->clear();
      return 0;
    }
    if(vertex_slots() + n > max_vertices)
      throw std::length_error("Fast_Delaunay_triangulation_3: more than 2^31 - 2 vertices");

    const Clock::time_point t0 = Clock::now();
    // The bulk insertion remakes the tetrahedra: one-point insertions after
    // it start their grid and tetrahedra of vertices afresh.
    walk_starts_.clear();
    tet_of_vertex_.clear();
    const std::size_t first_new = vertex_slots();
    Brio_order order = brio_order(points, n, seed, partitions);
    mesh.vertices.resize(first_new + n);
    write_vertex_records(points, order.order, first_new);
    bool rounds_in_curve_order = true;
    for(int a = 0; a < 3; ++a) {
      box_lo_[a] = std::min(box_lo_[a], order.box.lo[a]);
      box_hi_[a] = std::max(box_hi_[a], order.box.hi[a]);
      rounds_in_curve_order = rounds_in_curve_order && box_lo_[a] == order.box.lo[a] && box_hi_[a] == order.box.hi[a];
    }
    // The points are not read again.
    if(consumed != nullptr) std::vector<double>().swap(*consumed);
    const Clock::time_point t1 = Clock::now();
    last_report.sort_seconds = seconds(t0, t1);
    progress_total_ = n;
    progress_done_ = 0;
    if(progress && n > 1) progress(0, n);

    // duplicate_of[i]: the vertex that new vertex first_new + i duplicates, or
    // ghost_vertex if it is a genuine new vertex.
    std::vector<Vertex_id> duplicate_of(n, ghost_vertex);
    Vertex_id simplex[4];
    std::size_t added = 0;
    if(dimension == 3) {
      mesh.reserve_tets(expected_tets(n));
      insert_new_vertices(first_new, order.round_end, rounds_in_curve_order, duplicate_of, nullptr);
    } else if(extend_affine_hull(first_new, hull_simplex(simplex), simplex) == 3) {
      lift_to_dimension_3(first_new, simplex[3], order.round_end, rounds_in_curve_order, duplicate_of);
    } else {
      // Duplicates are found by CGAL's insertion, which writes final ids.
      added = insert_below_dimension_3(first_new, duplicate_of);
    }
    const Clock::time_point t2 = Clock::now();
    if(dimension == 3) added = remove_duplicates(first_new, duplicate_of);
    if(vertex_of_input) {
      vertex_of_input->resize(n);
      for(std::size_t i = 0; i < n; ++i)
        (*vertex_of_input)[order.order[i]] = duplicate_of[i];
    }
    last_report.finish_seconds = seconds(t2, Clock::now());
    report_progress(n);
    return added;
  }

  // Inserts one point; returns its vertex id (an older one for a duplicate).
  // In dimension 3 without the bulk path's sort and buffers (insert(p) in a
  // loop: see insert_one_from).
  Vertex_id insert_one(const double* p)
  {
    if(dimension == 3) return insert_one_from(p, Tet_id(-1), single_ball_);
    std::vector<Vertex_id> id;
    insert(p, 1, &id);
    return id[0];
  }

  // Dimension of the affine hull of the vertices (-1 if there are none).
  int affine_dimension() const
  {
    Vertex_id simplex[4];
    return extend_affine_hull(0, -1, simplex);
  }

  // Below dimension 3, one point as CGAL's insert(p, start) (`where` null)
  // or insert(p, lt, c, li, lj) (`where` = locate(p)'s answer).  Returns its
  // vertex (an older one for a duplicate); `around` receives the cells of
  // that vertex in the order of CGAL's insert_and_give_new_cells, or nothing
  // when the point lifts the triangulation to 3D.
  Vertex_id insert_one_below_dimension_3(const double* p, Tet_id start,
                                         const Lower_dimensional_triangulation::Location* where,
                                         std::vector<Tet_id>& around)
  {
    CGAL_precondition(dimension < 3);
    around.clear();
    const Vertex_id v = append_vertex(p);
    Vertex_id simplex[4];
    if(extend_affine_hull(v, hull_simplex(simplex), simplex) == 3) {
      mesh.vertices.resize(v);
      return insert_one(p);
    }
    last_report = Insertion_report();
    last_report.points = 1;
    const Vertex_id inserted =
        where ? lower.insert(mesh, v, *where, &around)
              : lower.insert(mesh, v, start < mesh.number_of_slots() && mesh.is_live(start)
                                          ? lower.cell(start) : Lower_dimensional_triangulation::Reference_cell(),
                             &around);
    if(inserted != v) mesh.vertices.resize(v); // the box keeps p: it is an existing vertex
    dimension = lower.delaunay().dimension();
    return inserted;
  }

  // Dimension 2, CGAL's insert_in_hole: the triangles hole[0..n), star-shaped
  // from p (p is no vertex), replaced by the new vertex joined to the hole's
  // boundary edges; (begin, i) is one of them.
  // `given`: a record of create_unplaced_vertex() to place at p instead of
  // a new one (CGAL's insert_in_hole with newv).
  Vertex_id insert_in_hole_below_dimension_3(const double* p, const std::vector<Tet_id>& hole, Tet_id begin, int i,
                                             std::vector<Tet_id>& around, Vertex_id given = ghost_vertex)
  {
    CGAL_precondition(dimension == 2);
    const Vertex_id v = given == ghost_vertex ? append_vertex(p) : place_unplaced_vertex(given, p);
    lower.insert_in_hole(mesh, v, hole, begin, i, &around);
    last_report = Insertion_report();
    last_report.points = 1;
    return v;
  }

  // Dimension 3: one point by the sequential kernel, its walk starting at
  // `start` (the last insertion's tetrahedron when `start` is not live), as
  // CGAL's insert(p, hint).  Returns the new vertex, or the older vertex that
  // p duplicates; `ball` receives the new tetrahedra (none for a duplicate).
  Vertex_id insert_one_from(const double* p, Tet_id start, std::vector<Tet_id>& ball)
  {
    CGAL_precondition(dimension == 3);
    const Vertex_id v = append_vertex(p);
    Insertion_scratch& scratch = single_scratch_;
    Delaunay_kernel<> kernel = sequential_kernel(scratch);
    Tet_id hint = start < mesh.number_of_slots() && mesh.is_live(start) ? start : hint_;
    if(!mesh.is_live(hint)) hint = mesh.first_live_tet();
    hint = walk_starts_.start(mesh, p, hint, mesh.live_vertices(), box_lo_, box_hi_, [this](Vertex_id w) {
      return w < tet_of_vertex_.size() ? tet_of_vertex_[w] : Tet_id(-1);
    });
    Vertex_id existing = ghost_vertex;
    const bool duplicate = kernel.insert(v, hint, existing) == Insertion_result::duplicate;
    hint_ = hint;
    ball.clear();
    if(duplicate) {
      mesh.vertices.resize(v); // the box keeps p: it is an existing vertex
      finish_single_insertion(scratch);
      return existing;
    }
    ball.assign(scratch.ball.begin(), scratch.ball.end());
    walk_starts_.remember(p, v);
    // Every vertex of a deleted tetrahedron is one of the ball's: pointing
    // them at the ball keeps tet_of_vertex_ exact through single insertions.
    if(tet_of_vertex_.size() < vertex_slots()) tet_of_vertex_.resize(2 * vertex_slots(), Tet_id(-1));
    for(Tet_id t : ball)
      for(int i = 0; i < 4; ++i)
        if(mesh.vertex(t, i) != ghost_vertex) tet_of_vertex_[mesh.vertex(t, i)] = t;
    finish_single_insertion(scratch);
    return v;
  }

  // Dimension 3, CGAL's insert_in_hole: the distinct tetrahedra hole[0..n),
  // star-shaped from p (p is no vertex), are replaced by the new vertex of p
  // joined to their boundary facets, listed in `ball`.
  Vertex_id insert_in_hole(const double* p, const Tet_id* hole, std::size_t n, std::vector<Tet_id>& ball,
                           Vertex_id given = ghost_vertex)
  {
    CGAL_precondition(dimension == 3 && n > 0);
    const Vertex_id v = given == ghost_vertex ? append_vertex(p) : place_unplaced_vertex(given, p);
    Insertion_scratch& scratch = single_scratch_;
    Delaunay_kernel<> kernel = sequential_kernel(scratch);
    const bool filled = kernel.fill_hole(v, hole, n);
    CGAL_assertion(filled); // the mesh's own slots never run out
    (void)filled;
    ball.assign(scratch.ball.begin(), scratch.ball.end());
    hint_ = ball.front();
    finish_single_insertion(scratch);
    return v;
  }

  // CGAL's tds().create_vertex(): a record in no cell, dead (neither
  // counted nor iterated) until insert_in_hole places it.  Its coordinates
  // stay finite for the passes that read every record and are not in the
  // filters' bounding box.
  Vertex_id create_unplaced_vertex()
  {
    if(vertex_slots() + 1 > max_vertices)
      throw std::length_error("Fast_Delaunay_triangulation_3: more than 2^31 - 2 vertices");
    const Vertex_id v = static_cast<Vertex_id>(vertex_slots());
    Vertex_record r;
    r.xyz[0] = r.xyz[1] = r.xyz[2] = 0;
    r.scratch = 0;
    mesh.vertices.push_back(r);
    mesh.kill_vertex(v);
    return v;
  }

  // Removes live vertex v, whose record stays dead.  Dimension 3: `start`
  // is a tetrahedron of v; the star of v is re-triangulated in place
  // (Vertex_removal.h) and new_cells receives the new tetrahedra; every
  // other tetrahedron keeps its slot.  When the remaining points no longer
  // span 3D, and below dimension 3, CGAL's triangulation beside the arrays
  // takes over (new_cells: the slots of the cells it made).
  void remove(Vertex_id v, Tet_id start, std::vector<Tet_id>& new_cells)
  {
    CGAL_precondition(v < vertex_slots() && !mesh.is_dead(v));
    new_cells.clear();
    if(dimension < 3) {
      lower.remove(mesh, v, new_cells);
      mesh.kill_vertex(v);
      dimension = lower.delaunay().dimension();
      return;
    }
    Removal_hole& hole = removal_.hole;
    carve_hole(mesh, v, start, hole);
    if(removal_.link.build(mesh, hole.link)) {
      if(!fill_hole_with_link_cells(mesh, hole, removal_.link.mesh(), removal_.filling, new_cells))
        throw std::logic_error("Fast_Delaunay_triangulation_3: a facet of the hole of a removed vertex is not in "
                               "the Delaunay triangulation of its link");
    } else if(hole.finite_star == mesh.live_tets - mesh.ghost_tets) {
      // Every finite tetrahedron has v and the others are coplanar.
      mesh.kill_vertex(v);
      lower.rebuild(mesh);
      dimension = lower.delaunay().dimension();
      lower.take_fresh_slots(new_cells);
      hint_ = 0;
      return;
    } else {
      fill_flat_hole(mesh, hole, new_cells);
    }
    mesh.kill_vertex(v);
    hint_ = new_cells.front();
  }

  // Removes what it can of `vertices` (live, distinct; dimension 3) on up
  // to `partitions` threads (Parallel_removal.h), leaving the others in
  // `deferred` for remove().  The vertices a round defers lie along the
  // cuts between its slabs: the next round cuts them across (the longest
  // axis of what is left), while each thread has at least
  // `min_per_partition` of them, at most four rounds.  incident_cells:
  // v->cell() of every vertex, complete, kept so; `made`, unless null: the
  // new cells still there (one may be listed twice).
  void remove_in_partitions(const std::vector<Vertex_id>& vertices, int partitions, std::size_t min_per_partition,
                            std::vector<Tet_id>& incident_cells, std::vector<Vertex_id>& deferred,
                            std::vector<Tet_id>* made)
  {
    CGAL_precondition(dimension == 3);
    std::vector<Vertex_id> todo = vertices;
    std::vector<Tet_id> made_in_round;
    if(made) made->clear();
    for(int round = 0; round < 4; ++round) {
      const int used = static_cast<int>(std::min<std::size_t>(std::size_t(partitions), todo.size() / min_per_partition));
      if(used < 2) break;
      Parallel_removal::run(mesh, incident_cells, todo, used, deferred, made ? &made_in_round : nullptr);
      // A cell made in an earlier round may be gone.
      if(made) {
        made->erase(std::remove_if(made->begin(), made->end(), [this](Tet_id t) { return !mesh.is_live(t); }),
                    made->end());
        made->insert(made->end(), made_in_round.begin(), made_in_round.end());
      }
      const bool progress = deferred.size() < todo.size();
      todo.swap(deferred);
      if(!progress) break;
    }
    deferred.swap(todo);
    hint_ = mesh.first_live_tet();
  }

  // Moves live vertex v to p (finite, not v's point), keeping its id: v is
  // removed, then its record revived at p and inserted.  Returns v, or the
  // vertex already at p (v then stays removed: CGAL's move).  new_cells: the
  // slots of every cell made by either step that is still there (each once).
  Vertex_id move(Vertex_id v, const double* p, Tet_id start, std::vector<Tet_id>& new_cells)
  {
    std::vector<Tet_id> made;
    remove(v, start, made);
    const Vertex_id moved = reinsert(v, p, new_cells);
    made.insert(made.end(), new_cells.begin(), new_cells.end());
    std::sort(made.begin(), made.end());
    made.erase(std::unique(made.begin(), made.end()), made.end());
    new_cells.clear();
    for(Tet_id t : made)
      if(t < mesh.number_of_slots() && mesh.is_live(t)) new_cells.push_back(t);
    return moved;
  }

  // Moves live vertex v (dimension 3; `start` a tetrahedron of v) to p when
  // p stays in the kernel of the star of v (Vertex_displacement.h).  On the
  // hull, only if the star is still Delaunay with p for v's point (`new_cells`:
  // the tetrahedra of v, in their slots).  Inside, by Lawson's flips from the
  // star with p (Displacement_flips.h; `new_cells`: the tetrahedra of v and
  // those the flips made); where they get stuck, by re-triangulating the
  // star and the tetrahedra in conflict with p beyond it from their vertices
  // and p at once (the hole of Vertex_displacement.h, filled by
  // Vertex_removal.h), which costs about one removal.  Otherwise returns
  // false and changes nothing: the caller removes v and inserts p.
  bool move_within_star(Vertex_id v, const double* p, Tet_id start, std::vector<Tet_id>& new_cells)
  {
    CGAL_precondition(dimension == 3 && v < vertex_slots() && !mesh.is_dead(v));
    new_cells.clear();
    Removal_hole& hole = removal_.hole;
    cells_around_vertex(mesh, start, v, hole.star, hole.seen);
    extend_bounding_box_to(p); // the filter covers p
    const Static_filter filter = Static_filter::for_box(box_lo_, box_hi_);
    bool on_hull = false;
    if(!star_positive_with(mesh, v, p, hole.star, filter, on_hull)) return false;
    if(on_hull && !star_locally_delaunay_with(mesh, v, p, hole.star, filter)) return false;
    double old_point[3];
    std::copy(mesh.vertices[v].xyz, mesh.vertices[v].xyz + 3, old_point);
    auto place_v_at = [&](const double* q) { std::copy(q, q + 3, mesh.vertices[v].xyz); };
    place_v_at(p);
    if(on_hull || flips_.run(mesh, v, hole.star, filter, max_flips_per_move)) {
      new_cells.assign(hole.star.begin(), hole.star.end());
      if(!on_hull && flips_.flips() != 0) {
        flips_.made_slots(new_cells);
        std::sort(new_cells.begin(), new_cells.end());
        new_cells.erase(std::unique(new_cells.begin(), new_cells.end()), new_cells.end());
        new_cells.erase(
            std::remove_if(new_cells.begin(), new_cells.end(), [this](Tet_id t) { return !mesh.is_live(t); }),
            new_cells.end());
      }
      if(mesh.with_sub_determinants)
        for(Tet_id t : new_cells) update_sub_determinants(mesh, t);
    } else {
      flips_.undo();
      place_v_at(old_point);
      carve_found_star(mesh, v, hole);
      add_conflicts_of_moved_point(mesh, v, p, hole, filter);
      if(!removal_.link.build(mesh, hole.link, p)) return false;
      place_v_at(p);
      hole.inner = v;
      if(!fill_hole_with_link_cells(mesh, hole, removal_.link.mesh(), removal_.filling, new_cells)) {
        // Ruled out by the uniqueness of the perturbed triangulation; nothing
        // has changed but v's point.
        CGAL_assertion_msg(false, "a facet of the star of a moved vertex is not in the triangulation of its "
                                  "link and new point");
        place_v_at(old_point);
        return false;
      }
      // The filling has its sub-determinants (Shared_slots::count_in).
    }
    hint_ = new_cells.front();
    return true;
  }

  // Whether moving live vertex v (dimension 3) to p keeps every cell but
  // v's point (CGAL's is_delaunay_after_displacement).
  bool stays_delaunay_after_move(Vertex_id v, const double* p, Tet_id start) const
  {
    CGAL_precondition(dimension == 3 && v < vertex_slots() && !mesh.is_dead(v));
    std::vector<Tet_id> star;
    cells_around_vertex(mesh, start, v, star);
    double lo[3], hi[3];
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::min(box_lo_[a], p[a]);
      hi[a] = std::max(box_hi_[a], p[a]);
    }
    const Static_filter filter = Static_filter::for_box(lo, hi);
    // Orientation first: it rejects most moves that fail, at a quarter of
    // the price of an in-sphere test.
    bool on_hull = false;
    return star_positive_with(mesh, v, p, star, filter, on_hull) &&
           star_locally_delaunay_with(mesh, v, p, star, filter);
  }

  // Exact validity: combinatorics, orientation and the (perturbed) local
  // Delaunay property on every facet.  Writes the first problem to `why`.
  bool is_valid(std::string* why = nullptr) const;

private:
  // The dead record of v back at p, inserted with its id; returns v, or
  // the vertex at p, v's record dead again.  new_cells: the Delaunay ball in
  // 3D, else every cell made.
  Vertex_id reinsert(Vertex_id v, const double* p, std::vector<Tet_id>& new_cells)
  {
    mesh.revive_vertex(v, p);
    extend_bounding_box_with(v);
    Vertex_id simplex[4];
    if(dimension == 3) {
      Insertion_scratch& scratch = single_scratch_;
      Delaunay_kernel<> kernel = sequential_kernel(scratch);
      Tet_id hint = mesh.is_live(hint_) ? hint_ : mesh.first_live_tet();
      Vertex_id existing = ghost_vertex;
      const Insertion_result result = kernel.insert(v, hint, existing);
      hint_ = hint;
      new_cells.assign(scratch.ball.begin(), scratch.ball.end());
      finish_single_insertion(scratch);
      if(result == Insertion_result::duplicate) {
        mesh.kill_vertex(v);
        return existing;
      }
    } else if(extend_affine_hull(0, -1, simplex) == 3) {
      // One vertex lifts the dimension by one: the others are coplanar.
      CGAL_assertion(dimension == 2);
      lower.stop();
      cone_over_triangles(mesh, v);
      hint_ = mesh.first_live_tet();
      dimension = 3;
      new_cells.clear();
      for(Tet_id t = 0; t < mesh.number_of_slots(); ++t)
        if(mesh.is_live(t)) new_cells.push_back(t);
    } else {
      const Vertex_id inserted = lower.insert(mesh, v, Lower_dimensional_triangulation::Reference_cell(), nullptr);
      dimension = lower.delaunay().dimension();
      lower.take_fresh_slots(new_cells);
      if(inserted != v) {
        mesh.kill_vertex(v);
        return inserted;
      }
    }
    return v;
  }
  typedef std::chrono::steady_clock Clock;
  static double seconds(Clock::time_point a, Clock::time_point b)
  {
    return std::chrono::duration<double>(b - a).count();
  }

  // The record of one new vertex at p, inside the bounding box of the filters.
  Vertex_id append_vertex(const double* p)
  {
    if(vertex_slots() + 1 > max_vertices)
      throw std::length_error("Fast_Delaunay_triangulation_3: more than 2^31 - 2 vertices");
    const Vertex_id v = static_cast<Vertex_id>(vertex_slots());
    Vertex_record r;
    r.xyz[0] = p[0]; r.xyz[1] = p[1]; r.xyz[2] = p[2];
    r.scratch = 0;
    mesh.vertices.push_back(r);
    extend_bounding_box(v);
    return v;
  }
  Vertex_id place_unplaced_vertex(Vertex_id v, const double* p)
  {
    mesh.revive_vertex(v, p);
    extend_bounding_box_with(v);
    return v;
  }
  Delaunay_kernel<> sequential_kernel(Insertion_scratch& scratch)
  {
    scratch.timed = false;
    return Delaunay_kernel<>(mesh, scratch, Mesh_slots{&mesh}, Static_filter::for_box(box_lo_, box_hi_),
                             Sub_determinant_filter::for_box(box_lo_, box_hi_));
  }
  // Applies the counts of the scratch kept for single insertions and resets them.
  void finish_single_insertion(Insertion_scratch& scratch)
  {
    mesh.live_tets += scratch.live_delta;
    mesh.ghost_tets += scratch.ghost_delta;
    last_report = Insertion_report();
    last_report.points = 1;
    last_report.kernel = scratch.stats;
    scratch.live_delta = scratch.ghost_delta = 0;
    scratch.stats = Kernel_statistics();
  }

  // 6.75 tetrahedra per vertex in the Poisson limit, ghosts included.
  static std::size_t expected_tets(std::size_t n) { return n * 27 / 4 + n / 16 + 64; }

  // Inserts vertices [begin, end) in order, skipping those in `skip`.
  // new_points: [begin, end) are the new points of insert(), whose progress
  // is reported.
  void insert_range(Vertex_id begin, Vertex_id end, Vertex_id first_new,
                    std::vector<Vertex_id>& duplicate_of, const Vertex_id* skip = nullptr, bool new_points = false)
  {
    const Clock::time_point t0 = Clock::now();
    const bool report = new_points && progress;
    insert_in_order(mesh, vertex_list(begin, end, skip), first_new, duplicate_of, hint_,
                    Static_filter::for_box(box_lo_, box_hi_), Sub_determinant_filter::for_box(box_lo_, box_hi_),
                    timed, last_report.kernel,
                    report ? std::max<std::size_t>(progress_total_ / 256, 4096) : 0,
                    [&](std::size_t done) { report_progress(done); });
    last_report.insertion_seconds += seconds(t0, Clock::now());
  }

  // Forwards `done` (at most the total) to `progress` if it is more than
  // the last value reported.
  void report_progress(std::size_t done)
  {
    done = std::min(done, progress_total_);
    if(!progress || progress_total_ < 2 || done <= progress_done_) return;
    progress_done_ = done;
    progress(done, progress_total_);
  }

  // Dead records are in no list: they are in no tetrahedron.
  std::vector<Vertex_id> vertex_list(std::size_t begin, std::size_t end, const Vertex_id* skip) const
  {
    std::vector<Vertex_id> list;
    list.reserve(end - begin);
    const bool any_dead = mesh.dead_vertices != 0;
    for(std::size_t i = begin; i < end; ++i) {
      const Vertex_id v = static_cast<Vertex_id>(i);
      if(any_dead && mesh.is_dead(v)) continue;
      if(!skip || (v != skip[0] && v != skip[1] && v != skip[2] && v != skip[3])) list.push_back(v);
    }
    return list;
  }

  // Grows the bounding box of all vertices (kept incrementally: single-point
  // insertions must not scan the vertices).
  // Vertex records first_new + i = point order[i] of the input, written
  // (random reads of the input) on the threads of the partitioned engine.
  template <class Points>
  void write_vertex_records(const Points& points, const std::vector<std::uint32_t>& order, std::size_t first_new)
  {
    const std::size_t n = order.size();
    const int chunks = chunk_count(n, partitions);
    for_each_chunk(chunks, [&](int c) {
      const std::size_t end = chunk_begin(n, chunks, c + 1);
      for(std::size_t i = chunk_begin(n, chunks, c); i < end; ++i) {
        Vertex_record& r = mesh.vertices[first_new + i];
        const double* p = points.point(order[i]);
        r.xyz[0] = p[0]; r.xyz[1] = p[1]; r.xyz[2] = p[2];
        r.scratch = 0;
      }
    });
  }

  void extend_bounding_box(std::size_t first)
  {
    for(std::size_t v = first; v < vertex_slots(); ++v)
      for(int a = 0; a < 3; ++a) {
        box_lo_[a] = std::min(box_lo_[a], mesh.vertices[v].xyz[a]);
        box_hi_[a] = std::max(box_hi_[a], mesh.vertices[v].xyz[a]);
      }
  }
  void extend_bounding_box_with(Vertex_id v) { extend_bounding_box_to(mesh.vertices[v].xyz); }
  void extend_bounding_box_to(const double* p)
  {
    for(int a = 0; a < 3; ++a) {
      box_lo_[a] = std::min(box_lo_[a], p[a]);
      box_hi_[a] = std::max(box_hi_[a], p[a]);
    }
  }
  void reset_bounding_box()
  {
    for(int a = 0; a < 3; ++a) {
      box_lo_[a] = std::numeric_limits<double>::infinity();
      box_hi_[a] = -std::numeric_limits<double>::infinity();
    }
  }

  // The new vertices [first_new, end) in their BRIO rounds: sequentially, or
  // round by round with the partitioned engine (the first round always
  // sequential, paper §3.4).  rounds_in_curve_order: BRIO sorted the rounds
  // after the first on the grid of box_lo_, box_hi_ (the new points' box
  // holds the old vertices).
  void insert_new_vertices(Vertex_id first_new, const std::vector<std::size_t>& round_end,
                           bool rounds_in_curve_order, std::vector<Vertex_id>& duplicate_of, const Vertex_id* skip)
  {
    const Vertex_id end = static_cast<Vertex_id>(vertex_slots());
    if(partitions <= 1) {
      insert_range(first_new, end, first_new, duplicate_of, skip, true);
      return;
    }
    const Clock::time_point t0 = Clock::now();
    if(parallel_engine == Parallel_engine::barrier) {
      Barrier_insertion barrier(mesh, Static_filter::for_box(box_lo_, box_hi_),
                                Sub_determinant_filter::for_box(box_lo_, box_hi_), timed);
      barrier.set_vertices_in_mesh(first_new);
      std::size_t begin = 0;
      if(progress) barrier.set_progress([&](std::size_t settled) { report_progress(begin + settled); });
      for(std::size_t r = 0; r < round_end.size(); ++r) {
        barrier.insert(vertex_list(first_new + begin, first_new + round_end[r], skip), r == 0 ? 1 : partitions,
                       first_new, duplicate_of, hint_, last_report.rounds, last_report.kernel);
        begin = round_end[r];
        report_progress(begin);
      }
      last_report.insertion_seconds += seconds(t0, Clock::now());
      return;
    }
    Partitioned_insertion engine(mesh, Static_filter::for_box(box_lo_, box_hi_),
                                 Sub_determinant_filter::for_box(box_lo_, box_hi_), box_lo_, box_hi_,
                                 seed, timed);
    engine.set_vertices_in_mesh(first_new);
    if(rounds_in_curve_order) {
      std::vector<Partitioned_insertion::Vertex_range> runs;
      for(std::size_t r = 1; r < round_end.size(); ++r)
        runs.push_back({Vertex_id(first_new + round_end[r - 1]), Vertex_id(first_new + round_end[r])});
      engine.set_sorted_runs(std::move(runs));
    }
    // The vertices of the mesh: the old ones, the earlier rounds' and the
    // initial simplex's (which may come from any round).
    std::size_t simplex_end = 0;
    if(skip != nullptr)
      for(int k = 0; k < 4; ++k) simplex_end = std::max<std::size_t>(simplex_end, std::size_t(skip[k]) + 1);
    std::size_t begin = 0;
    if(progress) engine.set_progress([&](std::size_t settled) { report_progress(begin + settled); });
    for(std::size_t r = 0; r < round_end.size(); ++r) {
      engine.set_vertex_end(std::max<std::size_t>(first_new + begin, simplex_end));
      engine.insert(vertex_list(first_new + begin, first_new + round_end[r], skip), r == 0 ? 1 : partitions,
                    first_new, duplicate_of, hint_,
                    last_report.rounds, last_report.kernel);
      begin = round_end[r];
      report_progress(begin);
    }
    last_report.insertion_seconds += seconds(t0, Clock::now());
  }


  // The new vertices [first_new, end) make the points span 3D; `apex` is
  // the first of them off the affine hull of the old ones.  CGAL's
  // triangulation is dropped.  From dimension 2, the apex is joined to the
  // triangles, as CGAL does (cone_over_triangles), and the other new
  // vertices are inserted into those tetrahedra.  From a lower dimension
  // (few cells), the tetrahedra of all vertices are built from the first
  // four affinely independent ones.
  void lift_to_dimension_3(Vertex_id first_new, Vertex_id apex, const std::vector<std::size_t>& round_end,
                           bool rounds_in_curve_order, std::vector<Vertex_id>& duplicate_of)
  {
    const Clock::time_point t0 = Clock::now();
    lower.stop();
    if(dimension == 2) {
      CGAL_assertion(apex >= first_new);
      const Vertex_id skip[4] = {apex, apex, apex, apex};
      cone_over_triangles(mesh, apex);
      hint_ = mesh.first_live_tet();
      dimension = 3;
      last_report.init_seconds = seconds(t0, Clock::now());
      mesh.reserve_tets(expected_tets(vertex_slots() - first_new));
      insert_new_vertices(first_new, round_end, rounds_in_curve_order, duplicate_of, skip);
      return;
    }
    Vertex_id simplex[4];
    const int spanned = extend_affine_hull(0, -1, simplex);
    CGAL_assertion(spanned == 3);
    (void)spanned;
    create_initial_tetrahedron(simplex);
    dimension = 3;
    last_report.init_seconds = seconds(t0, Clock::now());
    mesh.reserve_tets(expected_tets(vertex_slots()));
    insert_range(0, first_new, first_new, duplicate_of, simplex);
    insert_new_vertices(first_new, round_end, rounds_in_curve_order, duplicate_of, simplex);
  }

  // The new vertices [first_new, end), which keep the points in less than
  // 3D, inserted one by one into CGAL's triangulation in the order of their
  // ids (BRIO / Moore order, so each locate starts near its point).  The
  // records are compacted as CGAL finds duplicates, so every vertex enters
  // with its final id; duplicate_of[i] becomes the final id of new vertex i.
  // Returns the number of vertices added.
  std::size_t insert_below_dimension_3(Vertex_id first_new, std::vector<Vertex_id>& duplicate_of)
  {
    const Clock::time_point t0 = Clock::now();
    // Copying all cells once costs about what copying the changed ones
    // after each point does when the new vertices are an eighth of all.
    const bool copy_once = 8 * duplicate_of.size() >= vertex_slots();
    Lower_dimensional_triangulation::Reference_cell hint;
    Vertex_id next = first_new;
    for(std::size_t i = 0; i < duplicate_of.size(); ++i) {
      if(next != first_new + i) mesh.vertices[next] = mesh.vertices[first_new + i];
      const Vertex_id v = copy_once ? lower.insert_unsynchronised(mesh, next, hint)
                                    : lower.insert(mesh, next, hint, nullptr);
      hint = lower.vertex(v)->cell();
      duplicate_of[i] = v;
      if(v == next) ++next;
    }
    if(copy_once) lower.synchronise(mesh);
    mesh.vertices.resize(next);
    dimension = lower.delaunay().dimension();
    last_report.insertion_seconds = seconds(t0, Clock::now());
    return next - first_new;
  }

  // Vertices spanning the affine hull of all vertices below dimension 3: the
  // finite vertices of a finite cell of CGAL's triangulation.  Returns the
  // dimension.
  int hull_simplex(Vertex_id simplex[4]) const
  {
    CGAL_precondition(dimension < 3);
    if(dimension < 0) return dimension;
    typedef Lower_dimensional_triangulation::Reference_cell Reference_cell;
    const auto& dt = lower.delaunay();
    const Reference_cell infinite = dt.infinite_vertex()->cell();
    const Reference_cell finite = dimension == 0 ? infinite->neighbor(0)
                                                 : infinite->neighbor(infinite->index(dt.infinite_vertex()));
    for(int i = 0; i <= dimension; ++i) simplex[i] = Lower_dimensional_triangulation::id(finite->vertex(i));
    return dimension;
  }

  // Greedily extends simplex[0..spanned] (affinely independent vertices
  // spanning the hull of the vertices before `first`) with the vertices from
  // `first` on: the first vertex, the first different from it, the first
  // not collinear with those, the first not coplanar with those three (exact
  // predicates).  Returns the dimension of the hull of all vertices.
  int extend_affine_hull(Vertex_id first, int spanned, Vertex_id simplex[4]) const
  {
    const Vertex_id count = static_cast<Vertex_id>(vertex_slots());
    for(Vertex_id v = first; v < count && spanned < 3; ++v) {
      if(mesh.is_dead(v)) continue;
      const double* p = mesh.point(v);
      const bool independent =
          spanned == -1 ||
          (spanned == 0 && !same_point(mesh.point(simplex[0]), p)) ||
          (spanned == 1 && !collinear(mesh.point(simplex[0]), mesh.point(simplex[1]), p)) ||
          (spanned == 2 &&
           orientation(mesh.point(simplex[0]), mesh.point(simplex[1]), mesh.point(simplex[2]), p) != 0);
      if(independent) simplex[++spanned] = v;
    }
    return spanned;
  }

  // One finite tetrahedron and its four ghosts (make_initial_tetrahedron).
  void create_initial_tetrahedron(Vertex_id simplex[4])
  {
    make_initial_tetrahedron(mesh, simplex);
    hint_ = 0;
  }

  // Drops the duplicate vertex records of the last insertion, renumbering
  // the new vertices; turns duplicate_of into the final id of every new
  // vertex.  Returns the number of vertices added.
  std::size_t remove_duplicates(Vertex_id first_new, std::vector<Vertex_id>& duplicate_of)
  {
    const std::size_t n = duplicate_of.size();
    std::vector<Vertex_id> new_id(n);
    Vertex_id next = first_new;
    for(std::size_t i = 0; i < n; ++i) {
      if(duplicate_of[i] == ghost_vertex) {
        if(next != first_new + i) mesh.vertices[next] = mesh.vertices[first_new + i];
        new_id[i] = next++;
      }
    }
    const std::size_t added = next - first_new;
    auto final_id = [&](Vertex_id v) { return v < first_new ? v : new_id[v - first_new]; };
    if(added != n) {
      mesh.vertices.resize(next);
      // Free slots are skipped: those reserved for a partition and never used
      // hold no vertex ids at all.
      for(Tet_id t = 0; t < mesh.number_of_slots(); ++t) {
        if(!mesh.is_live(t)) continue;
        for(int i = 0; i < 4; ++i) {
          Vertex_id& v = mesh.vertex_ids(t)[i];
          if(v != ghost_vertex && v != no_vertex && v >= first_new) v = new_id[v - first_new];
        }
      }
    }
    for(std::size_t i = 0; i < n; ++i)
      duplicate_of[i] = duplicate_of[i] == ghost_vertex ? new_id[i] : final_id(duplicate_of[i]);
    return added;
  }

  Tet_id hint_ = 0;
  // One-point insertions: where their walks start, and the buffers they
  // reuse (the kernel's and the new cells').
  Walk_start_grid walk_starts_;
  std::vector<Tet_id> tet_of_vertex_; // checked before use: other updates do not keep it
  Insertion_scratch single_scratch_;
  std::vector<Tet_id> single_ball_;
  double box_lo_[3], box_hi_[3];
  std::size_t progress_total_ = 0, progress_done_ = 0;
  // Kept from one removal to the next (Vertex_removal.h).
  struct Removal_buffers
  {
    Removal_hole hole;
    Link_triangulation link;
    Hole_filling_buffers filling;
  } removal_;
  // Kept from one move to the next.  Beyond this many flips a move takes the
  // general path: a short move needs a few.
  Displacement_flips flips_;
  static constexpr std::size_t max_flips_per_move = 256;
};

inline bool Triangulation_core::is_valid(std::string* why) const
{
  auto fail = [why](const std::string& message) {
    if(why) *why = message;
    return false;
  };
  if(dimension < 3) return lower_dimensional_cells_are_valid(mesh, dimension, why) && lower.is_copied_into(mesh, why);
  const Flat_storage& m = mesh;
  std::size_t live = 0, ghosts = 0;
  std::vector<char> used(vertex_slots(), 0);
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t)) continue;
    ++live;
    const std::string at = "tetrahedron " + std::to_string(t) + ": ";
    for(int i = 0; i < 4; ++i) {
      const Vertex_id v = m.vertex(t, i);
      if(v == ghost_vertex) {
        if(i != 3) return fail(at + "ghost vertex not in slot 3");
        continue;
      }
      if(v >= vertex_slots()) return fail(at + "vertex id out of range");
      if(m.is_dead(v)) return fail(at + "removed vertex " + std::to_string(v));
      used[v] = 1;
      for(int j = 0; j < i; ++j)
        if(m.vertex(t, j) == v) return fail(at + "repeated vertex");
    }
    for(int i = 0; i < 4; ++i) {
      const Facet_code code = m.neighbor_code(t, i);
      if(tet_of(code) >= m.number_of_slots() || !m.is_live(tet_of(code)))
        return fail(at + "neighbour is not a live tetrahedron");
      if(m.neighbor_code(code) != facet_code(t, i)) return fail(at + "asymmetric adjacency");
      // Same facet, seen reversed from the other side.
      Vertex_id mine[3], other[3];
      for(int k = 0, a = 0, b = 0; k < 4; ++k) {
        if(k != i) mine[a++] = m.vertex(t, k);
        if(k != facet_of(code)) other[b++] = m.vertex(tet_of(code), k);
      }
      std::sort(mine, mine + 3);
      std::sort(other, other + 3);
      if(!std::equal(mine, mine + 3, other)) return fail(at + "neighbours do not share the facet");
    }
    if(m.is_ghost(t)) {
      ++ghosts;
      if(m.is_ghost(m.neighbor(t, 3))) return fail(at + "ghost tetrahedron on a ghost facet");
      continue;
    }
    const double* p[4] = {m.point(m.vertex(t, 0)), m.point(m.vertex(t, 1)),
                          m.point(m.vertex(t, 2)), m.point(m.vertex(t, 3))};
    if(orientation(p[0], p[1], p[2], p[3]) <= 0) return fail(at + "not positively oriented");
    for(int i = 0; i < 4; ++i) {
      const Facet_code code = m.neighbor_code(t, i);
      const Vertex_id opposite = m.vertex(tet_of(code), facet_of(code));
      if(opposite == ghost_vertex) {
        // Hull facet: the ghost must see it from outside.
        const Tet_id g = tet_of(code);
        if(orientation(m.point(m.vertex(g, 0)), m.point(m.vertex(g, 1)), m.point(m.vertex(g, 2)),
                       p[i]) >= 0)
          return fail(at + "hull facet seen from the wrong side");
        continue;
      }
      if(finite_cell_in_conflict(p[0], p[1], p[2], p[3], m.point(opposite)))
        return fail(at + "not locally Delaunay across facet " + std::to_string(i));
    }
  }
  if(live != m.live_tets || ghosts != m.ghost_tets) return fail("tetrahedron counts out of date");
  for(std::size_t v = 0; v < used.size(); ++v)
    if(!used[v] && !m.is_dead(Vertex_id(v))) return fail("vertex " + std::to_string(v) + " is in no tetrahedron");
  return true;
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_TRIANGULATION_CORE_H
