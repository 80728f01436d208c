// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// CGAL::Fast_Delaunay_triangulation_3: a drop-in for CGAL's
// Delaunay_triangulation_3 that stores the triangulation in flat arrays and
// inserts points with the engine of Marot, Pellerin and Remacle, "One
// machine, one minute, three billion tetrahedra" (2019): BRIO + Moore-curve
// sort, visibility walk, cavity by breadth-first search, Delaunay ball with a
// cavity adjacency table, ghost vertex, exact predicates with CGAL's symbolic
// perturbation.  For points in any position the finite cells are exactly those
// of CGAL::Delaunay_triangulation_3 on the same points.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Conflict_zone.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Equality.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Point_location.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_io.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_and_cell_infos.h>

#include <CGAL/Default.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/enum.h>
#include <CGAL/iterator.h>
#include <CGAL/utility.h>
#include <CGAL/tags.h>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/global_control.h>
#include <tbb/task_arena.h>
#endif

#include <algorithm>
#include <cstdint>
#include <functional>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

// The Delaunay layer: what changes the triangulation (insertion, removal,
// moves), what needs the Delaunay property (conflict zones, nearest vertex,
// Voronoi duals, Gabriel tests, the validity check) and the file format.
// Types, handles, iterators, access, point location and adjacency come from
// the triangulation layer it derives from (internal/Flat_triangulation_3.h),
// as CGAL's Delaunay_triangulation_3 derives from Triangulation_3.
template <class Gt = Exact_predicates_inexact_constructions_kernel, class Tds_ = Default,
          class Location_policy_ = Default, class Lock_data_structure_ = Default>
class Fast_Delaunay_triangulation_3
    : public Fast_Delaunay_triangulation_3_layers::Flat_triangulation_3<Gt, Tds_, Location_policy_,
                                                                        Lock_data_structure_>
{
  typedef Fast_Delaunay_triangulation_3<Gt, Tds_, Location_policy_, Lock_data_structure_> Self;

public:
  // The triangulation layer, public as CGAL's Delaunay_triangulation_3::Tr_Base.
  typedef Fast_Delaunay_triangulation_3_layers::Flat_triangulation_3<Gt, Tds_, Location_policy_,
                                                                      Lock_data_structure_>
      Tr_Base;

private:
  typedef Fast_Delaunay_triangulation_3_internal::Lower_dimensional_triangulation Lower;
  // The names of the triangulation layer this layer uses: a dependent base's
  // members are not found without them.  (Users see every public member of
  // the base through the derivation, whether listed here or not.)
  using typename Tr_Base::Core;
  using typename Tr_Base::Flat_storage;
  using typename Tr_Base::Tet_id;
  using typename Tr_Base::Vertex_id;

public:
  using typename Tr_Base::Anchor;
  using typename Tr_Base::Cell_circulator;
  using typename Tr_Base::Cell_handle;
  using typename Tr_Base::Concurrency_tag;
  using typename Tr_Base::Edge;
  using typename Tr_Base::Facet;
  using typename Tr_Base::Geom_traits;
  using typename Tr_Base::Insertion_report;
  using typename Tr_Base::Line;
  using typename Tr_Base::Locate_type;
  using typename Tr_Base::Lock_data_structure;
  using typename Tr_Base::Object;
  using typename Tr_Base::Point;
  using typename Tr_Base::size_type;
  using typename Tr_Base::Vertex_handle;
  using typename Tr_Base::Vertex_info;
  using Tr_Base::OUTSIDE_AFFINE_HULL;
  using Tr_Base::VERTEX;

  using Tr_Base::dimension;
  using Tr_Base::geom_traits;
  using Tr_Base::incident_cell_of;
  using Tr_Base::incident_cells;
  using Tr_Base::infinite_vertex;
  using Tr_Base::is_infinite;
  using Tr_Base::is_vertex;
  using Tr_Base::locate;
  using Tr_Base::mirror_index;
  using Tr_Base::mirror_vertex;
  using Tr_Base::next_around_edge;
  using Tr_Base::number_of_vertices;
  using Tr_Base::point;
  using Tr_Base::point_of;

private:
  using Tr_Base::anchor_;
  using Tr_Base::below_3;
  using Tr_Base::engine_coordinates;
  using Tr_Base::exact_coordinates;
  using Tr_Base::keeps_kernel_points;
  using Tr_Base::kernel_queries;
  using Tr_Base::threads_;
  using Tr_Base::throw_not_doubles;
  using Tr_Base::vertex_count;

public:
  // ---------------------------------------------------------------- creation
  explicit Fast_Delaunay_triangulation_3(const Geom_traits& gt = Geom_traits(),
                                         Lock_data_structure* lock_ds = nullptr)
      : Tr_Base(gt, lock_ds)
  {}
  explicit Fast_Delaunay_triangulation_3(Lock_data_structure* lock_ds, const Geom_traits& gt = Geom_traits())
      : Tr_Base(gt, lock_ds)
  {}
  template <class InputIterator>
  Fast_Delaunay_triangulation_3(InputIterator first, InputIterator last,
                                const Geom_traits& gt = Geom_traits(),
                                Lock_data_structure* lock_ds = nullptr)
      : Tr_Base(gt, lock_ds)
  {
    insert(first, last);
  }
  template <class InputIterator>
  Fast_Delaunay_triangulation_3(InputIterator first, InputIterator last, Lock_data_structure* lock_ds,
                                const Geom_traits& gt = Geom_traits())
      : Tr_Base(gt, lock_ds)
  {
    insert(first, last);
  }

  // Copies and moves as the triangulation layer makes them (see there).
  Fast_Delaunay_triangulation_3(const Self&) = default;
  Fast_Delaunay_triangulation_3(Self&&) noexcept = default;
  Self& operator=(const Self&) = default;
  Self& operator=(Self&&) noexcept = default;
  void swap(Self& other) noexcept { Tr_Base::swap(other); }

  // ---------------------------------------------------------------- options
  // Seed of the insertion order (the triangulation itself does not depend on it).
  void set_seed(std::uint64_t seed) { anchor_->core.seed = seed; }
  // Per-phase timings of insertions (sort, walk, cavity, ball), see last_insertion_report().
  void set_phase_timing(bool on) { anchor_->core.timed = on; }
  const Insertion_report& last_insertion_report() const { return anchor_->core.last_report; }
  // Cache the in-sphere sub-determinants of the paper's §2.4 (32 more bytes
  // per cell); off by default, see Sub_determinants.h for the measurement.
  void set_sub_determinants(bool on) { anchor_->core.set_sub_determinants(on); }
  bool sub_determinants() const { return anchor_->core.sub_determinants(); }
  // Number of Moore partitions inserted concurrently by the parallel engine
  // (paper §3); 1 is the sequential kernel.  The threads that run them are
  // those of the caller's TBB arena, so tbb::global_control and
  // tbb::task_arena limit them as for CGAL's parallel triangulation.
  // 0 (the default with Parallel_tag) means one partition per thread of the
  // caller's arena; the default with Sequential_tag is 1.
  void set_number_of_threads(int n) { threads_ = std::max(0, std::min(n, 255)); }
  int number_of_threads() const { return threads_; }
  // Which parallel engine inserts a range on several threads: the
  // Moore-partitioned one of the paper's §3 (the default), or the
  // barrier-synchronised two-level kernel of "Multi-threaded mesh generation"
  // (internal/Barrier_insertion.h), which ties with it on points sampled
  // from a surface and is slower elsewhere (2 cores).  Both build the same
  // cells.
  typedef Fast_Delaunay_triangulation_3_internal::Triangulation_core::Parallel_engine Parallel_engine;
  void set_parallel_engine(Parallel_engine engine) { anchor_->core.parallel_engine = engine; }
  Parallel_engine parallel_engine() const { return anchor_->core.parallel_engine; }
  // Called during every insertion of a range of n > 1 points with (points
  // settled, n): (0, n) once the points are sorted, then increasing values
  // every few thousand points (in the partitioned rounds an estimate from
  // the first partition), last (n, n).  Never per point, never two calls at
  // once, possibly from a worker thread.  The triangulation does not depend
  // on it.  An empty function (the default) turns it off.
  void set_progress(std::function<void(std::size_t done, std::size_t total)> progress)
  {
    anchor_->core.progress = std::move(progress);
  }

  // ---------------------------------------------------------------- insertion
  // Inserts the points of [first, last); returns the number of new vertices.
  // A point with a NaN or infinite coordinate throws std::invalid_argument
  // before anything changes.  Duplicates are stored once.  With vertex infos,
  // the range may also hold std::pair<Point, Info> or (Point, Info) tuples
  // (boost::zip_iterator): every vertex gets the info of the last element
  // equal to it in input order (CGAL overwrites too, in its spatial-sort
  // order), a vertex already present included.  Cells of the re-triangulated
  // region are new: their infos are Info(), as in CGAL.
  template <class InputIterator>
  std::ptrdiff_t insert(InputIterator first, InputIterator last,
                        typename std::enable_if<!std::is_convertible<InputIterator, Cell_handle>::value>::type* = nullptr)
  {
    typedef typename std::iterator_traits<InputIterator>::value_type Value;
    std::vector<Vertex_id> vertex_of_input;
    if constexpr(std::is_convertible<Value, Point>::value) {
      return insert_range_of_points(first, last, keeps_kernel_points ? &vertex_of_input : nullptr);
    } else {
      static_assert(!std::is_void<Vertex_info>::value,
                    "points with infos need a vertex base with info (Triangulation_vertex_base_with_info_3)");
      // With a kernel whose FT is not double, the user's points are kept
      // (Kernel_points.h): gathered first, their doubles checked exact.
      std::vector<Point> points;
      std::vector<double> xyz;
      std::vector<Vertex_info> infos;
      Fast_Delaunay_triangulation_3_internal::read_points_and_infos(first, last, infos, [&](const Point& p) {
        if constexpr(keeps_kernel_points) points.push_back(p);
        append_coordinates(xyz, p);
      });
      const std::ptrdiff_t added = insert_coordinates(xyz, &vertex_of_input, &points);
      anchor_->vertex_infos.assign(vertex_of_input, infos);
      return added;
    }
  }

  // Not in CGAL: inserts the points of [first, last) as insert(first, last)
  // does and writes to `vertices`, in input order, the handle of each point's
  // vertex (for a duplicate, that of the vertex equal to it, older or new).
  // Callers holding points in arrays (the Python module, index-array
  // exports) get from it their input-to-vertex map without a search.
  template <class InputIterator, class OutputIterator>
  OutputIterator insert_and_give_vertices(InputIterator first, InputIterator last, OutputIterator vertices)
  {
    std::vector<Vertex_id> vertex_of_input;
    insert_range_of_points(first, last, &vertex_of_input);
    for(Vertex_id v : vertex_of_input) *vertices++ = Vertex_handle(anchor_.get(), v);
    return vertices;
  }

  // Not in CGAL: insert_and_give_vertices for the n points given as x, y, z
  // triples of doubles (point i at xyz[3i], xyz[3i + 1], xyz[3i + 2]), read
  // where they are, with no point object made per row: the Python module's
  // numpy arrays.  For kernels with double coordinates.
  template <class OutputIterator, bool doubles = !keeps_kernel_points>
  typename std::enable_if<doubles, OutputIterator>::type
  insert_coordinates_and_give_vertices(const double* xyz, std::size_t n, OutputIterator vertices)
  {
    std::vector<Vertex_id> vertex_of_input;
    const std::vector<Point> no_points;
    insert_points(Fast_Delaunay_triangulation_3_internal::Packed_points{xyz}, n, &vertex_of_input, &no_points,
                  nullptr);
    for(Vertex_id v : vertex_of_input) *vertices++ = Vertex_handle(anchor_.get(), v);
    return vertices;
  }

  Vertex_handle insert(const Point& p)
  {
    double xyz[3];
    engine_coordinates(p, xyz);
    anchor_->incident_cells.clear();
    anchor_->core.partitions = 1; // one point: no partitioned round to run
    const Vertex_id old_count = vertex_count();
    const Vertex_id v = anchor_->core.insert_one(xyz);
    vertices_added();
    keep_input(v, p, old_count);
    return Vertex_handle(anchor_.get(), v);
  }
  // CGAL's insert(p, hint): in dimension 3 the kernel's walk starts at the
  // hint (a cell, or a cell of the vertex); below, CGAL's locate starts
  // there.  The lock zone of CGAL's parallel insertion is always granted:
  // nothing is locked.
  Vertex_handle insert(const Point& p, Cell_handle start, bool* could_lock_zone = nullptr)
  {
    if(could_lock_zone) *could_lock_zone = true;
    std::vector<Tet_id> ball;
    return insert_from(p, start, ball);
  }
  Vertex_handle insert(const Point& p, Vertex_handle hint, bool* could_lock_zone = nullptr)
  {
    return insert(p, hint_cell(hint), could_lock_zone);
  }
  // CGAL's insert after locate(p, lt, li, lj, ...): a point located at a
  // vertex is that vertex; otherwise, in dimension 3, the walk starts at c,
  // where p is.  Below dimension 3 CGAL's insert(p, lt, c, li, lj) runs.
  Vertex_handle insert(const Point& p, Locate_type lt, Cell_handle c, int li, int lj,
                       bool* could_lock_zone = nullptr)
  {
    if(dimension() < 3) {
      if(could_lock_zone) *could_lock_zone = true;
      std::vector<Tet_id> around;
      return insert_below_dimension_3(p, Cell_handle(), &lt, c, li, lj, around);
    }
    if(lt == VERTEX) {
      if(could_lock_zone) *could_lock_zone = true;
      return c->vertex(li);
    }
    return insert(p, c, could_lock_zone);
  }
  // CGAL's insert_outside_affine_hull: p raises the dimension by one (from
  // -1 to 0 the first point).  The new cells are the cones from p over the
  // cells of the old dimension, CGAL's construction and the only
  // triangulation of the new points, so the Delaunay one.  CGAL's
  // preconditions (dimension < 3, p outside the affine hull) are checked:
  // std::invalid_argument, the triangulation unchanged.
  Vertex_handle insert_outside_affine_hull(const Point& p)
  {
    double xyz[3];
    engine_coordinates(p, xyz);
    if(dimension() == 3)
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::insert_outside_affine_hull: dimension 3, "
                                  "every point is in the affine hull");
    Locate_type lt;
    int li = 0, lj = 0;
    const Cell_handle c = locate(p, lt, li, lj);
    if(lt != OUTSIDE_AFFINE_HULL)
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::insert_outside_affine_hull: the point is in the "
                                  "affine hull of the vertices (dimension " + std::to_string(dimension()) + ")");
    std::vector<Tet_id> around;
    return insert_below_dimension_3(p, Cell_handle(), &lt, c, li, lj, around);
  }

  // The cells incident to the vertex of p after its insertion, as CGAL: for
  // a new vertex, the kernel's Delaunay ball; for a point already there, the
  // cells around that vertex.  Below dimension 3, CGAL's list: the triangles
  // around the vertex in turning order, its two segments, or its point cell.
  template <class OutputItCells>
  Vertex_handle insert_and_give_new_cells(const Point& p, OutputItCells fit, Cell_handle start = Cell_handle())
  {
    std::vector<Tet_id> ball;
    const Vertex_handle v = insert_from(p, start, ball);
    give_new_cells(v, ball, fit);
    return v;
  }
  template <class OutputItCells>
  Vertex_handle insert_and_give_new_cells(const Point& p, OutputItCells fit, Vertex_handle hint)
  {
    return insert_and_give_new_cells(p, fit, hint_cell(hint));
  }
  template <class OutputItCells>
  Vertex_handle insert_and_give_new_cells(const Point& p, Locate_type lt, Cell_handle c, int li, int lj,
                                          OutputItCells fit)
  {
    if(dimension() < 3) {
      std::vector<Tet_id> around;
      const Vertex_handle v = insert_below_dimension_3(p, Cell_handle(), &lt, c, li, lj, around);
      give_new_cells(v, around, fit);
      return v;
    }
    if(lt == VERTEX) {
      const Vertex_handle v = c->vertex(li);
      give_new_cells(v, std::vector<Tet_id>(), fit);
      return v;
    }
    (void)lj;
    return insert_and_give_new_cells(p, fit, c);
  }

  // CGAL's insert_in_hole (dimension 3 or 2): the cells of [cells_begin,
  // cells_end), distinct and forming a hole star-shaped from p (such as the
  // conflict zone of find_conflicts), are replaced by the new vertex of p
  // joined to the hole's boundary facets, with the kernel's Delaunay ball
  // step.  (begin, i) is a boundary facet of the hole, as in CGAL; the ball
  // step finds the boundary itself.  In dimension 2 the triangles of the
  // hole are replaced by CGAL's insert_in_hole, (begin, i) a boundary edge.
  // Preconditions as CGAL's (unchecked): p is no vertex and the hole is
  // star-shaped from it.
  template <class CellIt>
  Vertex_handle insert_in_hole(const Point& p, CellIt cells_begin, CellIt cells_end, Cell_handle begin, int i)
  {
    CGAL_precondition(dimension() >= 2);
    CGAL_precondition(begin != Cell_handle() && i >= 0 && i <= dimension());
    double xyz[3];
    engine_coordinates(p, xyz);
    const std::vector<Tet_id> hole = cell_ids(cells_begin, cells_end);
    std::vector<Tet_id> ball;
    const Vertex_id old_count = vertex_count();
    Vertex_id v;
    if(dimension() == 2) {
      v = anchor_->core.insert_in_hole_below_dimension_3(xyz, hole, begin.index(), i, ball);
      vertices_added();
    } else {
      v = anchor_->core.insert_in_hole(xyz, hole.data(), hole.size(), ball);
      after_single_insertion(ball);
    }
    keep_input(v, p, old_count);
    return Vertex_handle(anchor_.get(), v);
  }

  // CGAL 5.5's overload that places newv, a vertex of tds().create_vertex()
  // not yet in a cell, at p (the same cells as the overload above).  Any
  // other vertex throws std::invalid_argument, nothing changed.
  template <class CellIt>
  Vertex_handle insert_in_hole(const Point& p, CellIt cells_begin, CellIt cells_end, Cell_handle begin, int i,
                               Vertex_handle newv)
  {
    CGAL_precondition(dimension() >= 2);
    CGAL_precondition(begin != Cell_handle() && i >= 0 && i <= dimension());
    if(newv.owner() != anchor_.get() || newv.index() == Fast_Delaunay_triangulation_3_internal::ghost_vertex ||
       !anchor_->tds.is_created(newv.index()))
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::insert_in_hole: the vertex is not one of "
                                  "tds().create_vertex() waiting for a cell");
    double xyz[3];
    engine_coordinates(p, xyz);
    const std::vector<Tet_id> hole = cell_ids(cells_begin, cells_end);
    std::vector<Tet_id> ball;
    anchor_->tds.placed(newv.index());
    if(dimension() == 2) {
      anchor_->core.insert_in_hole_below_dimension_3(xyz, hole, begin.index(), i, ball, newv.index());
      vertices_added();
    } else {
      anchor_->core.insert_in_hole(xyz, hole.data(), hole.size(), ball, newv.index());
      after_single_insertion(ball);
    }
    anchor_->point_replaced(newv.index(), p);
    return newv;
  }

  // ---------------------------------------------------------------- removal and moves
  // CGAL's remove(v): the cells of v go, the hole is re-triangulated by the
  // Delaunay triangulation of the remaining points (the same as CGAL's:
  // unique under its perturbation).  Handles of the other vertices and of
  // the cells outside the hole stay valid, with their infos; the new cells
  // have Info().  The removed vertex's id is not given again.  Below
  // dimension 3, and when the remaining points stop spanning 3D, CGAL's
  // triangulation beside the arrays removes it.  The infinite vertex, a
  // removed vertex or a handle of another triangulation throw
  // std::invalid_argument, and nothing changes.
  void remove(Vertex_handle v) { remove_vertex(v, anchor_->made_cells); }
  // CGAL's concurrency-safe spelling: nothing is locked, the zone is always granted.
  bool remove(Vertex_handle v, bool* could_lock_zone)
  {
    if(could_lock_zone) *could_lock_zone = true;
    remove(v);
    return true;
  }
  // CGAL's remove_and_give_new_cells: the cells that fill the hole.
  template <class OutputItCells>
  void remove_and_give_new_cells(Vertex_handle v, OutputItCells fit)
  {
    std::vector<Tet_id> made;
    remove_vertex(v, made);
    for(Tet_id t : made) *fit++ = Cell_handle(anchor_.get(), t);
  }
  // Removes the vertices of [first, last); returns how many went.  All
  // handles are checked first: a bad one, or one given twice (CGAL's
  // precondition), throws std::invalid_argument before anything changes.
  // With a Parallel_tag data structure (or set_number_of_threads()), as
  // CGAL's, the removals run on the threads of the caller's TBB arena in
  // dimension 3 (Parallel_removal.h: slabs of space, each removed by its
  // own thread when its star stays in its slab, the others one by one
  // after).
  template <class InputIterator>
  size_type remove(InputIterator first, InputIterator last)
  {
    const std::vector<Vertex_handle> vertices = checked_vertices_to_remove(first, last);
    const size_type before = number_of_vertices();
    const int partitions = partitions_for_insertion();
    if(dimension() == 3 && partitions > 1 && vertices.size() >= min_vertices_per_removal_partition * 2) {
      std::vector<Vertex_id> ids, deferred;
      for(Vertex_handle v : vertices) ids.push_back(v.index());
      (void)incident_cell_of(ids.front()); // the v->cell() cache, complete
      std::vector<Tet_id> made;
      anchor_->core.remove_in_partitions(ids, partitions, min_vertices_per_removal_partition, anchor_->incident_cells,
                                         deferred, Anchor::keeps_cell_records ? &made : nullptr);
      anchor_->cells_made_keeping_incident_cells(made);
      for(Vertex_id v : deferred) remove(Vertex_handle(anchor_.get(), v));
    } else {
      for(Vertex_handle v : vertices) remove(v);
    }
    return before - number_of_vertices();
  }
  // CGAL's remove_cluster: the same result as remove(first, last) (CGAL
  // re-triangulates the union of the stars at once; here the vertices go one
  // by one, which gives the same unique triangulation).
  template <class InputIterator>
  size_type remove_cluster(InputIterator first, InputIterator last)
  {
    return remove(first, last);
  }

  // CGAL's move_if_no_collision: if p is another vertex, that vertex is
  // returned and nothing changes; otherwise v moves to p and is returned,
  // its handle and info kept (its cells are new, with Info()).  In dimension
  // 3, when the cells of v with p for its point are still the Delaunay
  // triangulation (is_delaunay_after_displacement), only the point changes
  // and the cells of v keep their slots; when v is not on the hull and p is
  // in the kernel of its star, flips from the star with p make it Delaunay
  // (the cells without v that stay keep their slots and infos); otherwise v
  // is removed and inserted again under the same id.  A NaN or infinite
  // coordinate throws std::invalid_argument, nothing changed.
  Vertex_handle move_if_no_collision(Vertex_handle v, const Point& p)
  {
    return move_vertex(v, p, false, anchor_->made_cells);
  }
  template <class OutputItCells>
  Vertex_handle move_if_no_collision_and_give_new_cells(Vertex_handle v, const Point& p, OutputItCells fit)
  {
    std::vector<Tet_id> made;
    const Vertex_handle w = move_vertex(v, p, false, made);
    if(w == v) for(Tet_id t : made) *fit++ = Cell_handle(anchor_.get(), t);
    return w;
  }
  // CGAL's move: as move_if_no_collision, except that if p is another
  // vertex w, v is removed and w returned.
  Vertex_handle move(Vertex_handle v, const Point& p) { return move_vertex(v, p, true, anchor_->made_cells); }

  // CGAL's is_delaunay_after_displacement (dimension 3): whether the cells
  // of v, with p for v's point, are still the Delaunay triangulation, so
  // that moving v to p changes nothing else.  Exact, with CGAL's
  // perturbation.  CGAL 5.5 checks the facets through v only; this also
  // checks the facets opposite v, without which the answer can be wrong.
  bool is_delaunay_after_displacement(Vertex_handle v, const Point& p) const
  {
    check_removable(v, "is_delaunay_after_displacement");
    if(dimension() != 3)
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::is_delaunay_after_displacement: dimension " +
                                  std::to_string(dimension()) + ", not 3");
    double xyz[3];
    engine_coordinates(p, xyz);
    if(v->point() == p) return true;
    return anchor_->core.stays_delaunay_after_move(v.index(), xyz, removal_start(v));
  }

  // ---------------------------------------------------------------- conflict zone (dimensions 3 and 2)
  // CGAL's find_conflicts: c must be in conflict with p (e.g. the cell of
  // locate(p) when p is no vertex).  Writes the boundary facets (c', i) with
  // c' in conflict and c'->neighbor(i) not, the cells in conflict, and with
  // the third iterator each facet between two cells in conflict once.  The
  // test is the insertion's own (CGAL's perturbed in-sphere), so the zone is
  // exactly CGAL's; only the order of the output differs.  The triangulation
  // is left unchanged (see Conflict_zone.h).  A point that is no double
  // (an exact kernel's construction) is tested with the kernel's predicates
  // (Kernel_queries.h).  In dimension 2 CGAL's triangulation answers:
  // triangles, their edges as (c, i).
  template <class OutputIteratorBoundaryFacets, class OutputIteratorCells, class OutputIteratorInternalFacets>
  Triple<OutputIteratorBoundaryFacets, OutputIteratorCells, OutputIteratorInternalFacets>
  find_conflicts(const Point& p, Cell_handle c, OutputIteratorBoundaryFacets bfit, OutputIteratorCells cit,
                 OutputIteratorInternalFacets ifit, bool* could_lock_zone = nullptr) const
  {
    CGAL_precondition(dimension() >= 2);
    if(could_lock_zone) *could_lock_zone = true;
    if(dimension() == 2) return below_3().find_conflicts(p, c, bfit, cit, ifit);
    double q[3];
    const bool with_internal = !std::is_same<OutputIteratorInternalFacets, Emptyset_iterator>::value;
    Fast_Delaunay_triangulation_3_internal::Conflict_zone zone;
    if(exact_coordinates(p, q)) {
      Core::check_finite(q, 1);
      Fast_Delaunay_triangulation_3_internal::find_conflict_zone(anchor_->core.mesh, c.index(), q, with_internal, zone);
    } else {
      kernel_queries().conflict_zone(c.index(), p, with_internal, zone);
    }
    for(auto code : zone.boundary) *bfit++ = facet_of_code(code);
    for(Tet_id t : zone.cells) *cit++ = Cell_handle(anchor_.get(), t);
    for(auto code : zone.internal) *ifit++ = facet_of_code(code);
    return make_triple(bfit, cit, ifit);
  }
  template <class OutputIteratorBoundaryFacets, class OutputIteratorCells>
  std::pair<OutputIteratorBoundaryFacets, OutputIteratorCells>
  find_conflicts(const Point& p, Cell_handle c, OutputIteratorBoundaryFacets bfit, OutputIteratorCells cit,
                 bool* could_lock_zone = nullptr) const
  {
    const Triple<OutputIteratorBoundaryFacets, OutputIteratorCells, Emptyset_iterator> t =
        find_conflicts(p, c, bfit, cit, Emptyset_iterator(), could_lock_zone);
    return std::make_pair(t.first, t.second);
  }
  // The vertices of the boundary facets of the conflict zone, each once, in
  // increasing handle order (the infinite vertex first when on the boundary);
  // CGAL writes the same set in its own handle order.  In dimension 2,
  // CGAL's answer (the same set, in CGAL's order for its triangulation).
  template <class OutputIterator>
  OutputIterator vertices_on_conflict_zone_boundary(const Point& p, Cell_handle c, OutputIterator res) const
  {
    if(dimension() == 2) return below_3().vertices_on_conflict_zone_boundary(p, c, res);
    std::vector<Facet> facets;
    find_conflicts(p, c, std::back_inserter(facets), Emptyset_iterator());
    std::vector<Vertex_handle> vertices;
    for(const Facet& f : facets)
      for(int k = 1; k < 4; ++k) vertices.push_back(f.first->vertex((f.second + k) & 3));
    std::sort(vertices.begin(), vertices.end(), [](Vertex_handle a, Vertex_handle b) {
      return handle_order(a) < handle_order(b);
    });
    vertices.erase(std::unique(vertices.begin(), vertices.end()), vertices.end());
    return std::copy(vertices.begin(), vertices.end(), res);
  }
  // CGAL's deprecated name of vertices_on_conflict_zone_boundary.
  template <class OutputIterator>
  OutputIterator vertices_in_conflict(const Point& p, Cell_handle c, OutputIterator res) const
  {
    return vertices_on_conflict_zone_boundary(p, c, res);
  }

  Bounded_side side_of_sphere(Cell_handle c, const Point& p, bool perturb = false) const
  {
    CGAL_precondition(dimension() == 3);
    double q[3];
    if(!exact_coordinates(p, q)) return static_cast<Bounded_side>(kernel_queries().side_of_sphere(c.index(), p, perturb));
    return static_cast<Bounded_side>(
        Fast_Delaunay_triangulation_3_internal::side_of_sphere(anchor_->core.mesh, c.index(), q, perturb));
  }
  Vertex_handle nearest_vertex(const Point& p, Cell_handle start = Cell_handle()) const
  {
    return Fast_Delaunay_triangulation_3_internal::nearest_vertex(static_cast<const Tr_Base&>(*this), p, start);
  }
  // The finite vertex of c nearest to p, among its dimension() + 1 vertices
  // (CGAL's cells below dimension 3); on a tie the lower index in c, as
  // CGAL, whose vertex order in a cell may differ from this one's.
  Vertex_handle nearest_vertex_in_cell(const Point& p, Cell_handle c) const
  {
    CGAL_precondition(dimension() >= 0 && c != Cell_handle());
    const auto closer = geom_traits().less_distance_to_point_3_object();
    Vertex_handle nearest;
    for(int i = 0; i <= std::max(dimension(), 0); ++i) {
      const Vertex_handle v = c->vertex(i);
      if(v == Vertex_handle() || is_infinite(v)) continue;
      if(nearest == Vertex_handle() || closer(p, v->point(), nearest->point())) nearest = v;
    }
    CGAL_postcondition(nearest != Vertex_handle());
    return nearest;
  }
  // ---------------------------------------------------------------- Voronoi duals and Gabriel (dimension 3)
  // CGAL's Delaunay_triangulation_3 semantics, with Gt's constructions and
  // predicates on the cells' points in this triangulation's vertex order.
  // CGAL numbers the vertices of a cell differently, so a construction may
  // differ from CGAL's in its last bits (a circumcenter is computed from its
  // first point); predicates give the same answers.
  Point dual(Cell_handle c) const
  {
    CGAL_precondition(dimension() == 3 && !is_infinite(c));
    return anchor_->circumcenter(c.index());
  }
  Object dual(const Facet& f) const { return dual(f.first, f.second); }
  // The Voronoi edge of a finite facet: the segment between the duals of its
  // two cells (possibly of length 0), or for a hull facet the ray from the
  // dual of its finite cell, away from that cell, along the facet's
  // equidistant line.
  Object dual(Cell_handle c, int i) const
  {
    CGAL_precondition(dimension() == 3 && !is_infinite(c, i));
    const Cell_handle n = c->neighbor(i);
    if(!is_infinite(c) && !is_infinite(n))
      return anchor_->traits.construct_object_3_object()(anchor_->traits.construct_segment_3_object()(dual(c), dual(n)));
    const Cell_handle finite = is_infinite(c) ? n : c;
    const int in = is_infinite(c) ? mirror_index(c, i) : i;
    // The facet's vertices ordered so that its equidistant line leaves the
    // finite cell: the even permutations start at in + 1, the odd ones need
    // their first two vertices swapped.
    int k[3] = {(in + 1) & 3, (in + 2) & 3, (in + 3) & 3};
    if(in & 1) std::swap(k[0], k[1]);
    const Line l =
        anchor_->traits.construct_equidistant_line_3_object()(point(finite, k[0]), point(finite, k[1]), point(finite, k[2]));
    return anchor_->traits.construct_object_3_object()(anchor_->traits.construct_ray_3_object()(dual(finite), l));
  }
  // The line that supports dual(c, i), through facet i's vertices in c's order.
  Line dual_support(Cell_handle c, int i) const
  {
    CGAL_precondition(dimension() == 3 && !is_infinite(c, i));
    return anchor_->traits.construct_equidistant_line_3_object()(point(c, (i + 1) & 3), point(c, (i + 2) & 3),
                                                         point(c, (i + 3) & 3));
  }

  // A facet (an edge) is Gabriel when no vertex lies strictly inside its
  // smallest circumscribed sphere; only the vertices opposite it (around it)
  // can, so only those are tested.
  bool is_Gabriel(const Facet& f) const { return is_Gabriel(f.first, f.second); }
  bool is_Gabriel(Cell_handle c, int i) const
  {
    CGAL_precondition(dimension() == 3 && !is_infinite(c, i));
    const auto side = anchor_->traits.side_of_bounded_sphere_3_object();
    const Point a = point(c, (i + 1) & 3), b = point(c, (i + 2) & 3), d = point(c, (i + 3) & 3);
    for(const Vertex_handle v : {c->vertex(i), mirror_vertex(c, i)})
      if(!is_infinite(v) && side(a, b, d, v->point()) == ON_BOUNDED_SIDE) return false;
    return true;
  }
  bool is_Gabriel(const Edge& e) const { return is_Gabriel(e.first, e.second, e.third); }
  bool is_Gabriel(Cell_handle c, int i, int j) const
  {
    CGAL_precondition(dimension() == 3 && !is_infinite(c, i, j));
    const auto side = anchor_->traits.side_of_bounded_sphere_3_object();
    const Vertex_handle u = c->vertex(i), v = c->vertex(j);
    const Point a = u->point(), b = v->point();
    Cell_circulator cells = incident_cells(c, i, j), done = cells;
    do {
      const Cell_handle x = cells;
      for(int k = 0; k < 4; ++k) {
        const Vertex_handle w = x->vertex(k);
        if(w != u && w != v && !is_infinite(w) && side(a, b, w->point()) == ON_BOUNDED_SIDE) return false;
      }
    } while(++cells != done);
    return true;
  }

  // Where p, in the plane of facet i of c, lies with respect to the facet's
  // circumcircle; with perturb, never ON_BOUNDARY: CGAL's symbolic
  // perturbation decides.  For a facet through the infinite vertex, CGAL's
  // documented meaning: in the plane of the cell's finite facet, inside is
  // the open half-plane beyond the facet's finite edge, and on the edge's
  // line the segment decides (inside strictly between its ends, boundary at
  // an end).  (CGAL 5.5's code takes the finite-facet branch for those
  // facets and the other for the finite facet of an infinite cell; finite
  // facets agree with it exactly.)  In dimension 2, CGAL's answer for
  // triangle (c, 3).
  Bounded_side side_of_circle(const Facet& f, const Point& p, bool perturb = false) const
  {
    return side_of_circle(f.first, f.second, p, perturb);
  }
  Bounded_side side_of_circle(Cell_handle c, int i, const Point& p, bool perturb = false) const
  {
    CGAL_precondition(dimension() >= 2 && i >= 0 && i < 4);
    if(dimension() == 2) return below_3().side_of_circle(c, i, p, perturb);
    if(!is_infinite(c) || i == 3) {
      const int i0 = i > 0 ? 0 : 1, i1 = i > 1 ? 1 : 2, i2 = i > 2 ? 2 : 3;
      const Point &a = point(c, i0), &b = point(c, i1), &d = point(c, i2);
      CGAL_precondition(anchor_->traits.coplanar_3_object()(a, b, d, p));
      if(!perturb) return anchor_->traits.coplanar_side_of_bounded_circle_3_object()(a, b, d, p);
      double q[3];
      if(!exact_coordinates(p, q))
        return static_cast<Bounded_side>(kernel_queries().coplanar_side_of_bounded_circle(a, b, d, p, true));
      const Flat_storage& m = anchor_->core.mesh;
      return static_cast<Bounded_side>(Fast_Delaunay_triangulation_3_internal::perturbed_coplanar_side_of_bounded_circle(
          m.point(c->vertex(i0).index()), m.point(c->vertex(i1).index()), m.point(c->vertex(i2).index()), q));
    }
    // Facet i of a ghost cell: the infinite vertex (slot 3) and the edge (v1, v2).
    const Point v1 = point(c, next_around_edge(3, i)), v2 = point(c, next_around_edge(i, 3));
    const auto coplanar_orientation = anchor_->traits.coplanar_orientation_3_object();
    const int o = static_cast<int>(coplanar_orientation(v1, v2, point(c, i))) *
                  static_cast<int>(coplanar_orientation(v1, v2, p));
    if(o != 0) return static_cast<Bounded_side>(-o);
    if(anchor_->traits.collinear_are_strictly_ordered_along_line_3_object()(v1, p, v2)) return ON_BOUNDED_SIDE;
    return p == v1 || p == v2 ? ON_BOUNDARY : ON_UNBOUNDED_SIDE;
  }

  // ---------------------------------------------------------------- checking
  // Combinatorial validity, positive orientation and the local Delaunay
  // property with exact predicates.
  bool is_valid(bool verbose = false, int = 0) const
  {
    std::string why;
    const bool ok = anchor_->core.is_valid(&why);
    if(!ok && verbose) std::cerr << "Fast_Delaunay_triangulation_3::is_valid: " << why << std::endl;
    return ok;
  }

  // ---------------------------------------------------------------- input / output
  // CGAL's file format for Triangulation_3, ASCII or binary after the
  // stream's CGAL::IO mode; see operator<< and operator>> below and
  // internal/Triangulation_io.h for the layout.  Points are written with the
  // stream's precision, as CGAL does: set it to 17 for an exact round trip.
  // The stream is flushed at the end, as CGAL's writer leaves it (its last
  // line ends with std::endl): a program may read the file back while its
  // std::ofstream is still open.
  void write(std::ostream& os) const
  {
    if(dimension() == 3) {
      Fast_Delaunay_triangulation_3_internal::write_triangulation_3(
          os, anchor_->core.mesh, [this](Vertex_id v) { return point_of(v); });
      os.flush();
      return;
    }
    // No cells are stored below dimension 3.  CGAL's triangulation of the
    // same points has the cells CGAL would write (it is unique there, as in
    // dimension 3); building it costs O(n log n), once per write.
    std::vector<Point> points;
    points.reserve(number_of_vertices());
    for(Vertex_id v = 0; v < vertex_count(); ++v)
      if(!anchor_->core.mesh.is_dead(v)) points.push_back(point_of(v));
    os << Delaunay_triangulation_3<Gt>(points.begin(), points.end());
    os.flush();
  }

  // Replaces the triangulation by the one read from `is`, after checking it
  // (counts, index ranges, symmetric adjacency, orientation, Delaunay
  // property; see Triangulation_reader).  On bad input: returns false, sets
  // the stream's failbit, puts the reason (with the position) in `error` and
  // leaves the triangulation unchanged.  Below dimension 3 the file's cells
  // are checked and dropped: only the vertices are kept.
  bool read(std::istream& is, std::string* error = nullptr)
  {
    Flat_storage built;
    int built_dimension = -1;
    Fast_Delaunay_triangulation_3_internal::Triangulation_reader<Point> reader(is);
    if(!reader.read(built, built_dimension)) {
      if(error) *error = reader.error();
      is.setstate(std::ios_base::failbit);
      return false;
    }
    anchor_->core.assign(std::move(built), built_dimension);
    anchor_->incident_cells.clear();
    anchor_->tds.forget_created(); // their records are gone with the old arrays
    anchor_->kernel_points.clear(); // rebuilt from the doubles read
    // The file carries no infos: every vertex and cell starts with Info().
    anchor_->vertex_infos.clear();
    anchor_->user_vertices.clear();
    vertices_added();
    anchor_->cell_infos.clear();
    anchor_->user_cells.clear();
    return true;
  }

private:
  // Below this many vertices per thread, a range is removed one by one.
  static constexpr std::size_t min_vertices_per_removal_partition = 256;

  int partitions_for_insertion() const
  {
    if(threads_ > 0) return threads_;
#ifdef CGAL_LINKED_WITH_TBB
    // The arena's concurrency ignores a tbb::global_control limit: take both.
    const std::size_t allowed =
        tbb::global_control::active_value(tbb::global_control::max_allowed_parallelism);
    const int threads = static_cast<int>(std::min<std::size_t>(
        allowed, static_cast<std::size_t>(tbb::this_task_arena::max_concurrency())));
    return std::max(1, std::min(255, threads));
#else
    return 1;
#endif
  }

  void check_removable(Vertex_handle v, const char* what) const
  {
    if(v == Vertex_handle() || v.owner() != anchor_.get() || is_infinite(v) || !is_vertex(v)) {
      std::ostringstream message;
      message << "Fast_Delaunay_triangulation_3::" << what << ": "
              << (v == Vertex_handle() ? "null vertex handle"
                  : v.owner() != anchor_.get() ? "a vertex of another triangulation"
                  : is_infinite(v) ? "the infinite vertex" : "a vertex already removed");
      throw std::invalid_argument(message.str());
    }
  }
  template <class InputIterator>
  std::vector<Vertex_handle> checked_vertices_to_remove(InputIterator first, InputIterator last) const
  {
    std::vector<Vertex_handle> vertices;
    std::vector<Vertex_id> ids;
    for(; first != last; ++first) {
      const Vertex_handle v = *first;
      check_removable(v, "remove");
      vertices.push_back(v);
      ids.push_back(v.index());
    }
    std::sort(ids.begin(), ids.end());
    if(std::adjacent_find(ids.begin(), ids.end()) != ids.end())
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::remove: a vertex is given twice in the range");
    return vertices;
  }
  // The start of the removal's star: a cell of v in dimension 3.  With the
  // v->cell() cache gone (insert(p) drops it), a walk to v's point finds one,
  // until the walks since the cache was last built cost about as much as
  // building it (O(n)): then it is built, so that neither removals between
  // insertions nor long runs of removals pay O(n) each.
  Tet_id removal_start(Vertex_handle v) const
  {
    if(dimension() < 3) return 0;
    std::size_t& walks = anchor_->walks_without_incident_cells;
    if(anchor_->incident_cells.empty() && ++walks <= std::size_t(vertex_count()) / 1024 + 16) {
      Locate_type lt;
      int li, lj;
      const Cell_handle c = locate(v->point(), lt, li, lj);
      CGAL_assertion(lt == VERTEX && c->vertex(li) == v);
      return c.index();
    }
    walks = 0;
    return incident_cell_of(v.index()).index();
  }
  void remove_vertex(Vertex_handle v, std::vector<Tet_id>& made)
  {
    check_removable(v, "remove");
    anchor_->core.remove(v.index(), removal_start(v), made);
    anchor_->cells_made(made);
  }
  Vertex_handle move_vertex(Vertex_handle v, const Point& p, bool remove_on_collision, std::vector<Tet_id>& made)
  {
    check_removable(v, remove_on_collision ? "move" : "move_if_no_collision");
    double xyz[3];
    engine_coordinates(p, xyz);
    if(v->point() == p) return v;
    const Tet_id start = removal_start(v);
    if(dimension() == 3 && anchor_->core.move_within_star(v.index(), xyz, start, made)) {
      anchor_->cells_made(made);
      anchor_->point_replaced(v.index(), p);
      return v;
    }
    if(!remove_on_collision) {
      // As CGAL, p is located from v's cell: moves are mostly short.
      Locate_type lt;
      int li, lj;
      const Cell_handle c = number_of_vertices() > 1 ? locate(p, lt, li, lj, v) : Cell_handle();
      if(c != Cell_handle() && lt == VERTEX) return c->vertex(li);
    }
    // move(): a point already there is found by the insertion, after v's
    // removal, which is then all that happens (one walk fewer).
    const Vertex_id moved = anchor_->core.move(v.index(), xyz, start, made);
    anchor_->cells_made(made);
    if(moved == v.index()) anchor_->point_replaced(moved, p);
    return Vertex_handle(anchor_.get(), moved);
  }

  // The slots of the cells of a range of Cell_handles (or of iterators
  // that convert to them).
  template <class CellIt>
  static std::vector<Tet_id> cell_ids(CellIt first, CellIt last)
  {
    std::vector<Tet_id> ids;
    for(; first != last; ++first) {
      const Cell_handle c = *first;
      ids.push_back(c.index());
    }
    return ids;
  }

  // Dimension 3: the kernel's insertion from `start`; below, CGAL's from
  // the same start (`ball`: the cells of the vertex, in CGAL's order).
  Vertex_handle insert_from(const Point& p, Cell_handle start, std::vector<Tet_id>& ball)
  {
    ball.clear();
    if(dimension() < 3) return insert_below_dimension_3(p, start, nullptr, Cell_handle(), 0, 0, ball);
    double xyz[3];
    engine_coordinates(p, xyz);
    const Vertex_id old_count = vertex_count();
    const Vertex_id v = anchor_->core.insert_one_from(xyz, start ? start.index() : Tet_id(-1), ball);
    after_single_insertion(ball);
    keep_input(v, p, old_count);
    return Vertex_handle(anchor_.get(), v);
  }
  // Every vertex of a deleted cell is a vertex of the ball (a Delaunay
  // insertion removes no vertex), so pointing the vertices of the ball at it
  // repairs the v->cell() cache at the cost of the ball, and the
  // `v = insert(p, v)` idiom never rebuilds it.
  void after_single_insertion(const std::vector<Tet_id>& ball)
  {
    vertices_added();
    if(anchor_->incident_cells.empty()) return;
    anchor_->incident_cells.resize(vertex_count());
    for(Tet_id t : ball)
      for(int i = 0; i < 4; ++i) {
        const Vertex_id w = anchor_->core.mesh.vertex(t, i);
        if(w != Fast_Delaunay_triangulation_3_internal::ghost_vertex) anchor_->incident_cells[w] = t;
      }
  }
  // As CGAL's insert(p, start) (lt null) or insert(p, *lt, c, li, lj); a
  // point that lifts the dimension goes to the 3D build.  `around`: the
  // cells of the vertex in the order of CGAL's insert_and_give_new_cells
  // (empty after the lift).
  Vertex_handle insert_below_dimension_3(const Point& p, Cell_handle start, const Locate_type* lt, Cell_handle c,
                                         int li, int lj, std::vector<Tet_id>& around)
  {
    double xyz[3];
    engine_coordinates(p, xyz);
    anchor_->incident_cells.clear();
    anchor_->core.partitions = 1;
    typename Lower::Location where;
    if(lt) where = below_3().location(*lt, c, li, lj);
    const Vertex_id old_count = vertex_count();
    const Vertex_id v = anchor_->core.insert_one_below_dimension_3(xyz, start ? start.index() : Tet_id(-1),
                                                                   lt ? &where : nullptr, around);
    vertices_added();
    keep_input(v, p, old_count);
    return Vertex_handle(anchor_.get(), v);
  }

  void vertices_added() { anchor_->vertices_added(); }
  Cell_handle hint_cell(Vertex_handle hint) const
  {
    return hint == Vertex_handle() ? Cell_handle() : hint->cell();
  }
  template <class OutputItCells>
  void give_new_cells(Vertex_handle v, const std::vector<Tet_id>& ball, OutputItCells& fit) const
  {
    if(dimension() < 3) {
      for(Tet_id t : ball) *fit++ = Cell_handle(anchor_.get(), t);
      return;
    }
    if(ball.empty()) {
      fit = incident_cells(v, fit);
      return;
    }
    for(Tet_id t : ball) *fit++ = Cell_handle(anchor_.get(), t);
  }
  Facet facet_of_code(std::uint64_t code) const
  {
    return Facet(Cell_handle(anchor_.get(), static_cast<Tet_id>(code >> 2)), static_cast<int>(code & 3));
  }
  // The infinite vertex first, then by id (the order of handles in CGAL's
  // containers: the infinite vertex is created first).
  static std::uint64_t handle_order(Vertex_handle v)
  {
    return v.index() == Fast_Delaunay_triangulation_3_internal::ghost_vertex ? 0 : std::uint64_t(v.index()) + 1;
  }

  // The points of a range of Point: with a kernel whose FT is not double,
  // the user's points are kept (Kernel_points.h), gathered first and their
  // doubles checked exact (vertex_of_input must not be null); else an array
  // of them is read in place and any other range copied to doubles.
  template <class InputIterator>
  std::ptrdiff_t insert_range_of_points(InputIterator first, InputIterator last,
                                        std::vector<Vertex_id>* vertex_of_input)
  {
    std::vector<Point> points;
    std::vector<double> xyz;
    if constexpr(keeps_kernel_points) {
      points.assign(first, last);
      append_coordinates(points.begin(), points.end(), xyz, std::forward_iterator_tag());
    } else {
      if constexpr(is_point_array_iterator<InputIterator>())
        if(first != last && coordinates_in_place(*first))
          return insert_points(Point_objects{std::addressof(*first)}, std::size_t(last - first), vertex_of_input,
                               &points, nullptr);
      append_coordinates(first, last, xyz, typename std::iterator_traits<InputIterator>::iterator_category());
    }
    return insert_coordinates(xyz, vertex_of_input, &points);
  }

  // Consumes `xyz`: the core frees it once the vertex records are written,
  // so the copy of the input does not stay resident while the mesh grows.
  // `points`: the user's objects of the range, empty when the kernel's FT
  // is double (then vertex_of_input may be null).
  std::ptrdiff_t insert_coordinates(std::vector<double>& xyz, std::vector<Vertex_id>* vertex_of_input,
                                    const std::vector<Point>* points)
  {
    return insert_points(Fast_Delaunay_triangulation_3_internal::Packed_points{xyz.data()}, xyz.size() / 3,
                         vertex_of_input, points, &xyz);
  }

  // The same for n points read from a point source (BRIO.h); `consumed`:
  // the copy of the input that it reads, if any.
  template <class Points>
  std::ptrdiff_t insert_points(const Points& source, std::size_t n, std::vector<Vertex_id>* vertex_of_input,
                               const std::vector<Point>* points, std::vector<double>* consumed)
  {
    Core::check_finite(source, n);
    anchor_->incident_cells.clear();
    anchor_->core.partitions = partitions_for_insertion();
    const std::size_t added = anchor_->core.insert(source, n, vertex_of_input, consumed);
    anchor_->vertices_added(points->empty() ? nullptr : points, vertex_of_input);
    return static_cast<std::ptrdiff_t>(added);
  }

  // An array of points whose x(), y(), z() are references to three
  // consecutive doubles, as in CGAL's kernels with double coordinates: the
  // range insertion reads them where they are instead of copying them first
  // (1e6 points: 24 MB less at the peak, and the copy's 15-20 ms, most of
  // them page faults, on one thread).
  struct Point_objects
  {
    const Point* points;
    const double* point(std::size_t i) const { return &points[i].x(); }
  };
  // Iterators of such arrays: pointers and std::vector's.
  template <class Iterator>
  static constexpr bool is_point_array_iterator()
  {
    typedef typename std::iterator_traits<Iterator>::value_type Value;
    return std::is_same<decltype(std::declval<const Point&>().x()), const double&>::value &&
           std::is_same<typename std::remove_cv<Value>::type, Point>::value &&
           (std::is_pointer<Iterator>::value ||
            std::is_same<Iterator, typename std::vector<Point>::iterator>::value ||
            std::is_same<Iterator, typename std::vector<Point>::const_iterator>::value);
  }
  // Whether p's coordinates are laid out as Point_objects reads them (the
  // same for every object of the type).
  static bool coordinates_in_place(const Point& p)
  {
    return &p.y() == &p.x() + 1 && &p.z() == &p.x() + 2;
  }

  template <class InputIterator>
  static void append_coordinates(InputIterator first, InputIterator last, std::vector<double>& xyz,
                                 std::forward_iterator_tag)
  {
    xyz.reserve(3 * static_cast<std::size_t>(std::distance(first, last)));
    append_coordinates(first, last, xyz, std::input_iterator_tag());
  }
  template <class InputIterator>
  static void append_coordinates(InputIterator first, InputIterator last, std::vector<double>& xyz,
                                 std::input_iterator_tag)
  {
    for(; first != last; ++first) append_coordinates(xyz, *first);
  }
  static void append_coordinates(std::vector<double>& xyz, const Point& p)
  {
    double c[3];
    if(!exact_coordinates(p, c)) throw_not_doubles(p, "point #" + std::to_string(xyz.size() / 3) + " of the input");
    xyz.insert(xyz.end(), c, c + 3);
  }

  // After the insertion of p as vertex v: a new vertex (id from old_count
  // on) keeps the user's object.
  void keep_input(Vertex_id v, const Point& p, Vertex_id old_count)
  {
    if(v >= old_count && v != Fast_Delaunay_triangulation_3_internal::ghost_vertex)
      anchor_->kernel_points.keep_input(v, p);
  }
};

// Writes `tr` as CGAL::Triangulation_3's operator<< writes the same
// triangulation: the file is readable by CGAL's operator>> and gives the same
// cells.  In dimension 3 the vertices and cells are in our order (infinite
// vertex last in each infinite cell).
template <class Gt, class Tds, class Lp, class Lds>
std::ostream& operator<<(std::ostream& os, const Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& tr)
{
  tr.write(os);
  return os;
}

// Reads a file written by CGAL's (or our) operator<<; on bad input sets the
// failbit and leaves `tr` unchanged (tr.read(is, &error) says why).
template <class Gt, class Tds, class Lp, class Lds>
std::istream& operator>>(std::istream& is, Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& tr)
{
  tr.read(is);
  return is;
}

// Equality as CGAL's operator== on Triangulation_3 defines it: the two
// triangulations are isomorphic by the map that sends each vertex to the
// vertex with the same point (same dimension, same vertices, same cells as
// point sets).  Dimension 3 compares the finite cells (the infinite ones
// follow from the hull).  Below it the vertices decide, because a Delaunay triangulation with CGAL's symbolic
// perturbation is the only one of its points in every dimension.
template <class Gt1, class Tds1, class Lp1, class Lds1, class Gt2, class Tds2, class Lp2, class Lds2>
bool operator==(const Fast_Delaunay_triangulation_3<Gt1, Tds1, Lp1, Lds1>& a,
                const Fast_Delaunay_triangulation_3<Gt2, Tds2, Lp2, Lds2>& b)
{
  return Fast_Delaunay_triangulation_3_internal::same_triangulation(a, b);
}
template <class Gt1, class Tds1, class Lp1, class Lds1, class Gt2, class Tds2, class Lp2, class Lds2>
bool operator!=(const Fast_Delaunay_triangulation_3<Gt1, Tds1, Lp1, Lds1>& a,
                const Fast_Delaunay_triangulation_3<Gt2, Tds2, Lp2, Lds2>& b)
{
  return !(a == b);
}
template <class Gt1, class Tds1, class Lp1, class Lds1, class Gt2, class Tds2, class Lp2, class Lds2>
bool operator==(const Fast_Delaunay_triangulation_3<Gt1, Tds1, Lp1, Lds1>& a,
                const Delaunay_triangulation_3<Gt2, Tds2, Lp2, Lds2>& b)
{
  return Fast_Delaunay_triangulation_3_internal::same_triangulation(a, b);
}
template <class Gt1, class Tds1, class Lp1, class Lds1, class Gt2, class Tds2, class Lp2, class Lds2>
bool operator==(const Delaunay_triangulation_3<Gt2, Tds2, Lp2, Lds2>& b,
                const Fast_Delaunay_triangulation_3<Gt1, Tds1, Lp1, Lds1>& a)
{
  return a == b;
}
template <class Gt1, class Tds1, class Lp1, class Lds1, class Gt2, class Tds2, class Lp2, class Lds2>
bool operator!=(const Fast_Delaunay_triangulation_3<Gt1, Tds1, Lp1, Lds1>& a,
                const Delaunay_triangulation_3<Gt2, Tds2, Lp2, Lds2>& b)
{
  return !(a == b);
}
template <class Gt1, class Tds1, class Lp1, class Lds1, class Gt2, class Tds2, class Lp2, class Lds2>
bool operator!=(const Delaunay_triangulation_3<Gt2, Tds2, Lp2, Lds2>& b,
                const Fast_Delaunay_triangulation_3<Gt1, Tds1, Lp1, Lds1>& a)
{
  return !(a == b);
}

} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_H
