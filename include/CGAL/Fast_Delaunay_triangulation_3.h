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

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Adjacency_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Conflict_zone.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Equality.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Handles.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_points.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Point_location.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Segment_traverser.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Simplex.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Storage_anchor.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_core.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_io.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/User_bases.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_and_cell_infos.h>

#include <CGAL/Default.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/Location_policy.h>
#include <CGAL/Triangulation_utils_3.h>
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

namespace Fast_Delaunay_triangulation_3_internal {
// The concurrency tag of a CGAL Triangulation_data_structure_3 (Sequential_tag
// for Default or a data structure without one).
template <class Tds, class = void>
struct Concurrency_of { typedef Sequential_tag type; };
template <class Tds>
struct Concurrency_of<Tds, std::void_t<typename Tds::Concurrency_tag>> { typedef typename Tds::Concurrency_tag type; };

// CGAL's spellings put a location policy second (Delaunay_triangulation_3<K,
// Fast_location>) or third (<K, Tds, Fast_location>).  The data structure
// argument is Default in the first case.
template <class T>
struct Is_location_policy : std::false_type {};
template <class Tag>
struct Is_location_policy<CGAL::Location_policy<Tag>> : std::true_type {};

template <class Tds_, class Location_policy_>
struct Template_arguments
{
  static constexpr bool policy_second = Is_location_policy<Tds_>::value;
  typedef typename std::conditional<policy_second, Default, Tds_>::type Tds;
  typedef typename std::conditional<policy_second, Tds_,
                                    typename Default::Get<Location_policy_, Compact_location>::type>::type
      Location_policy;
};
} // namespace Fast_Delaunay_triangulation_3_internal

template <class Gt = Exact_predicates_inexact_constructions_kernel, class Tds_ = Default,
          class Location_policy_ = Default, class Lock_data_structure_ = Default>
class Fast_Delaunay_triangulation_3 : public Triangulation_utils_3
{
  typedef Fast_Delaunay_triangulation_3<Gt, Tds_, Location_policy_, Lock_data_structure_> Self;
  typedef Fast_Delaunay_triangulation_3_internal::Template_arguments<Tds_, Location_policy_> Arguments;
  typedef Fast_Delaunay_triangulation_3_internal::Triangulation_core Core;
  typedef Fast_Delaunay_triangulation_3_internal::Flat_storage Flat_storage;
  typedef Fast_Delaunay_triangulation_3_internal::Vertex_id Vertex_id;
  typedef Fast_Delaunay_triangulation_3_internal::Tet_id Tet_id;
  typedef Fast_Delaunay_triangulation_3_internal::Lower_dimensional_triangulation Lower;
  typedef typename Lower::Reference_cell Reference_cell;
  typedef typename Lower::Reference_vertex Reference_vertex;
  typedef typename Lower::Delaunay::Facet Reference_facet;
  typedef typename Lower::Delaunay::Edge Reference_edge;

public:
  typedef Gt Geom_traits;
  // With a Triangulation_data_structure_3<..., Parallel_tag>, insertions use
  // the parallel engine on the threads of the caller's TBB arena, as CGAL's
  // parallel triangulation does.  The lock data structure is accepted for
  // compatibility and not needed: the engine partitions space instead.
  typedef typename Fast_Delaunay_triangulation_3_internal::Concurrency_of<typename Arguments::Tds>::type Concurrency_tag;
  // Fast_location or Compact_location, as given (Compact_location by
  // default, as CGAL): accepted for the spelling only.  Both locate and
  // insert with the kernel's visibility walk from the last insertion or the
  // hint, which is already the fast path; there is no hierarchy to build.
  typedef typename Arguments::Location_policy Location_policy;
  // CGAL's own choice, taken from CGAL: with Parallel_tag (and TBB) its
  // Spatial_lock_grid_3<Tag_priority_blocking> when the argument is
  // Default, else void when Default; the argument when given.  Stored by
  // the constructors and get/set_lock_data_structure, never locked.
  typedef typename Triangulation_3_base<Concurrency_tag, Lock_data_structure_>::Lock_data_structure
      Lock_data_structure;
  // As CGAL's Delaunay_triangulation_3: not a regular nor a periodic triangulation.
  typedef Tag_false Weighted_tag;
  typedef Tag_false Periodic_tag;
  typedef typename Gt::Point_3 Point;
  typedef typename Gt::Segment_3 Segment;
  typedef typename Gt::Triangle_3 Triangle;
  typedef typename Gt::Tetrahedron_3 Tetrahedron;
  typedef typename Gt::Line_3 Line;
  typedef typename Gt::Ray_3 Ray;
  typedef typename Gt::Object_3 Object;
  typedef std::size_t size_type;
  typedef std::ptrdiff_t difference_type;
  // As Triangulation_3's (which says: "to have a back_inserter").
  typedef Point value_type;
  typedef const value_type& const_reference;

private:
  // A user's vertex or cell base with members of its own (see User_bases.h):
  // rebound to our handles, one per vertex or cell in a side array; void for
  // CGAL's own bases, whose vertices and cells are plain facades over the
  // flat arrays.
  typedef typename Fast_Delaunay_triangulation_3_internal::Rebound_vertex_base<typename Arguments::Tds, Self>::type
      User_vertex_base;
  typedef typename Fast_Delaunay_triangulation_3_internal::Rebound_cell_base<typename Arguments::Tds, Self>::type
      User_cell_base;
  static constexpr bool has_user_vertex_base = !std::is_void<User_vertex_base>::value;
  static constexpr bool has_user_cell_base = !std::is_void<User_cell_base>::value;

public:
  typedef typename std::conditional<has_user_vertex_base,
                                    Fast_Delaunay_triangulation_3_internal::User_vertex<Self, User_vertex_base>,
                                    Fast_Delaunay_triangulation_3_internal::Vertex_facade<Self>>::type Vertex;
  typedef typename std::conditional<has_user_cell_base,
                                    Fast_Delaunay_triangulation_3_internal::User_cell<Self, User_cell_base>,
                                    Fast_Delaunay_triangulation_3_internal::Cell_facade<Self>>::type Cell;
  typedef typename std::conditional<has_user_vertex_base,
                                    Fast_Delaunay_triangulation_3_internal::User_handle<Self, Vertex, Vertex_id>,
                                    Fast_Delaunay_triangulation_3_internal::Flat_handle<Vertex, Vertex_id>>::type
      Vertex_handle;
  typedef typename std::conditional<has_user_cell_base,
                                    Fast_Delaunay_triangulation_3_internal::User_handle<Self, Cell, Tet_id>,
                                    Fast_Delaunay_triangulation_3_internal::Flat_handle<Cell, Tet_id>>::type
      Cell_handle;
  // Info of Triangulation_vertex_base_with_info_3 / Triangulation_cell_base_with_info_3
  // in the data structure argument (void without): v->info(), c->info().
  typedef typename Fast_Delaunay_triangulation_3_internal::Vertex_info_of<typename Arguments::Tds>::type Vertex_info;
  typedef typename Fast_Delaunay_triangulation_3_internal::Cell_info_of<typename Arguments::Tds>::type Cell_info;
  typedef std::pair<Cell_handle, int> Facet;
  typedef CGAL::Triple<Cell_handle, int, int> Edge;

  // Internal: what handles point at (Storage_anchor.h), and the records of
  // user bases it keeps (void for CGAL's own bases).
  typedef Fast_Delaunay_triangulation_3_internal::Storage_anchor<Self> Anchor;
  typedef typename std::conditional<has_user_vertex_base, Vertex, void>::type User_vertex_record;
  typedef typename std::conditional<has_user_cell_base, Cell, void>::type User_cell_record;

  // CGAL's combinatorial layer: a view over the same arrays (Flat_tds.h)
  // with the Triangulation_data_structure_3 interface and these handles and
  // iterators (tds().raw_cells_begin() assigns to a Cell_iterator).
  struct Tds_types
  {
    typedef typename Self::Vertex_handle Vertex_handle;
    typedef typename Self::Cell_handle Cell_handle;
    typedef typename Self::Vertex Vertex;
    typedef typename Self::Cell Cell;
    typedef typename Self::Facet Facet;
    typedef typename Self::Edge Edge;
    typedef typename Self::All_cells_iterator Cell_iterator;
    typedef typename Self::All_vertices_iterator Vertex_iterator;
    typedef typename Self::All_facets_iterator Facet_iterator;
    typedef typename Self::All_edges_iterator Edge_iterator;
    typedef typename Self::Cell_circulator Cell_circulator;
    typedef typename Self::Facet_circulator Facet_circulator;
    typedef typename Self::Concurrency_tag Concurrency_tag;
  };
  typedef Fast_Delaunay_triangulation_3_internal::Flat_tds<Anchor, Tds_types> Triangulation_data_structure;
  typedef Triangulation_data_structure Tds;

  enum Locate_type { VERTEX = 0, EDGE, FACET, CELL, OUTSIDE_CONVEX_HULL, OUTSIDE_AFFINE_HULL };

private:
  // Filters of the index iterators.
  struct Accept_finite_cell
  {
    bool operator()(const Anchor& a, Tet_id id) const
    {
      return a.core.mesh.is_live(id) && !a.core.mesh.is_ghost(id);
    }
  };
  struct Accept_live_vertex
  {
    bool operator()(const Anchor& a, Vertex_id id) const { return !a.core.mesh.is_dead(id); }
  };

public:
  // As in CGAL, the handle is the iterator over all cells (Handles.h).
  typedef Cell_handle All_cells_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Filtered_index_iterator<Cell_handle, Tet_id, Accept_finite_cell>
      Finite_cells_iterator;
  typedef All_cells_iterator Cell_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Filtered_index_iterator<Vertex_handle, Vertex_id, Accept_live_vertex>
      Finite_vertices_iterator;

  // All vertices: the infinite vertex first, then the finite ones (CGAL's
  // order), skipping the records of removed vertices.  As in CGAL, the
  // handle is the iterator (Handles.h).
  typedef Vertex_handle All_vertices_iterator;
  typedef Vertex_handle Vertex_iterator;

  // Facets and edges are enumerated once each, from the cell of smallest
  // index among those that share them.  Both are bidirectional, as CGAL's:
  // a code is listed when accepts(code), in either direction.
  template <bool finite_only>
  class Facet_iterator_t
  {
  public:
    typedef std::bidirectional_iterator_tag iterator_category;
    typedef Facet value_type;
    typedef std::ptrdiff_t difference_type;
    typedef const Facet* pointer;
    typedef const Facet& reference;

    Facet_iterator_t() = default;
    Facet_iterator_t(const Anchor* tr, std::size_t code) : tr_(tr), code_(code) { skip(); }
    const Facet& operator*() const { return facet_; }
    const Facet* operator->() const { return &facet_; }
    Facet_iterator_t& operator++() { ++code_; skip(); return *this; }
    Facet_iterator_t operator++(int) { Facet_iterator_t old = *this; ++*this; return old; }
    Facet_iterator_t& operator--()
    {
      do {
        CGAL_precondition(code_ > 0);
        --code_;
      } while(!accepts(code_));
      facet_ = Facet(Cell_handle(tr_, code_ >> 2), static_cast<int>(code_ & 3));
      return *this;
    }
    Facet_iterator_t operator--(int) { Facet_iterator_t old = *this; --*this; return old; }
    friend bool operator==(const Facet_iterator_t& a, const Facet_iterator_t& b) { return a.code_ == b.code_; }
    friend bool operator!=(const Facet_iterator_t& a, const Facet_iterator_t& b) { return a.code_ != b.code_; }

  private:
    // In dimension 2 the facets are the triangles, as (c, 3).
    bool accepts(std::size_t code) const
    {
      const Flat_storage& m = tr_->core.mesh;
      const Tet_id t = static_cast<Tet_id>(code >> 2);
      const int i = static_cast<int>(code & 3);
      if(!m.is_live(t)) return false;
      if(tr_->dimension() == 2) return i == 3 && !(finite_only && tr_->has_infinite_vertex(t));
      if(m.neighbor(t, i) < t) return false;
      return !(finite_only && m.is_ghost(t) && i != 3);
    }
    void skip()
    {
      const std::size_t end = 4 * tr_->slots_of_faces(2);
      while(code_ < end && !accepts(code_)) ++code_;
      if(code_ < end) facet_ = Facet(Cell_handle(tr_, code_ >> 2), static_cast<int>(code_ & 3));
    }
    const Anchor* tr_ = nullptr;
    std::size_t code_ = 0;
    Facet facet_;
  };
  typedef Facet_iterator_t<false> All_facets_iterator;
  typedef Facet_iterator_t<true> Finite_facets_iterator;
  typedef All_facets_iterator Facet_iterator;

  template <bool finite_only>
  class Edge_iterator_t
  {
  public:
    typedef std::bidirectional_iterator_tag iterator_category;
    typedef Edge value_type;
    typedef std::ptrdiff_t difference_type;
    typedef const Edge* pointer;
    typedef const Edge& reference;

    Edge_iterator_t() = default;
    Edge_iterator_t(const Anchor* tr, std::size_t code) : tr_(tr), code_(code) { skip(); }
    const Edge& operator*() const { return edge_; }
    const Edge* operator->() const { return &edge_; }
    Edge_iterator_t& operator++() { ++code_; skip(); return *this; }
    Edge_iterator_t operator++(int) { Edge_iterator_t old = *this; ++*this; return old; }
    Edge_iterator_t& operator--()
    {
      do {
        CGAL_precondition(code_ > 0);
        --code_;
        // A free slot: none of its six codes is listed.
        if(!tr_->core.mesh.is_live(static_cast<Tet_id>(code_ / 6))) code_ -= code_ % 6;
      } while(!accepts(code_));
      set_edge();
      return *this;
    }
    Edge_iterator_t operator--(int) { Edge_iterator_t old = *this; --*this; return old; }
    friend bool operator==(const Edge_iterator_t& a, const Edge_iterator_t& b) { return a.code_ == b.code_; }
    friend bool operator!=(const Edge_iterator_t& a, const Edge_iterator_t& b) { return a.code_ != b.code_; }

  private:
    // In dimension 1 the edges are the segments (c, 0, 1); in dimension 2
    // each triangle reports the edges whose other triangle has a larger index.
    bool accepts(std::size_t code) const
    {
      const Flat_storage& m = tr_->core.mesh;
      const int dimension = tr_->dimension();
      const Tet_id t = static_cast<Tet_id>(code / 6);
      if(!m.is_live(t)) return false;
      const int i = edge_vertex[code % 6][0], j = edge_vertex[code % 6][1];
      if(j > dimension) return false;
      if(finite_only && (m.vertex(t, i) == Fast_Delaunay_triangulation_3_internal::ghost_vertex ||
                         m.vertex(t, j) == Fast_Delaunay_triangulation_3_internal::ghost_vertex))
        return false;
      if(dimension == 1) return true;
      if(dimension == 2) return m.neighbor(t, 3 - i - j) > t;
      return dimension == 3 && tr_->smallest_cell_around_edge(t, i, j) == t;
    }
    void skip()
    {
      const std::size_t end = 6 * tr_->slots_of_faces(1);
      for(; code_ < end; ++code_) {
        // A free slot: none of its six codes is listed.
        if(!tr_->core.mesh.is_live(static_cast<Tet_id>(code_ / 6))) { code_ += 5 - code_ % 6; continue; }
        if(accepts(code_)) break;
      }
      if(code_ < end) set_edge();
    }
    void set_edge() { edge_ = Edge(Cell_handle(tr_, code_ / 6), edge_vertex[code_ % 6][0], edge_vertex[code_ % 6][1]); }
    const Anchor* tr_ = nullptr;
    std::size_t code_ = 0;
    Edge edge_;
  };
  typedef Edge_iterator_t<false> All_edges_iterator;
  typedef Edge_iterator_t<true> Finite_edges_iterator;
  typedef All_edges_iterator Edge_iterator;

  typedef Fast_Delaunay_triangulation_3_internal::Handle_iterator<All_cells_iterator, Cell_handle> All_cell_handles_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Handle_iterator<Finite_cells_iterator, Cell_handle> Finite_cell_handles_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Handle_iterator<All_vertices_iterator, Vertex_handle> All_vertex_handles_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Handle_iterator<Finite_vertices_iterator, Vertex_handle> Finite_vertex_handles_iterator;

  typedef Iterator_range<All_cells_iterator> All_cells;
  typedef Iterator_range<Finite_cells_iterator> Finite_cells;
  typedef Iterator_range<All_vertices_iterator> All_vertices;
  typedef Iterator_range<Finite_vertices_iterator> Finite_vertices;
  typedef Iterator_range<All_facets_iterator> All_facets;
  typedef Iterator_range<Finite_facets_iterator> Finite_facets;
  typedef Iterator_range<All_edges_iterator> All_edges;
  typedef Iterator_range<Finite_edges_iterator> Finite_edges;
  typedef Iterator_range<All_cell_handles_iterator> All_cell_handles;
  typedef Iterator_range<Finite_cell_handles_iterator> Finite_cell_handles;
  typedef Iterator_range<All_vertex_handles_iterator> All_vertex_handles;
  typedef Iterator_range<Finite_vertex_handles_iterator> Finite_vertex_handles;
  // The points of the finite vertices, in their order (see Handles.h).
  typedef Fast_Delaunay_triangulation_3_internal::Point_iterator<Finite_vertices_iterator, Point> Point_iterator;
  typedef Iterator_range<Point_iterator> Points;

  typedef Fast_Delaunay_triangulation_3_internal::Insertion_report Insertion_report;

  // Around an edge, in CGAL's direction.
  typedef Fast_Delaunay_triangulation_3_internal::Cell_circulator_around_edge<Self> Cell_circulator;
  typedef Fast_Delaunay_triangulation_3_internal::Facet_circulator_around_edge<Self> Facet_circulator;

  // A vertex, edge, facet or cell as one value (CGAL's Triangulation_simplex_3).
  typedef Fast_Delaunay_triangulation_3_internal::Simplex_3<Self> Simplex;
  // The cells crossed by a segment (see Segment_traverser.h).
  typedef Fast_Delaunay_triangulation_3_internal::Segment_cell_iterator<Self> Segment_cell_iterator;
  typedef Iterator_range<Fast_Delaunay_triangulation_3_internal::Handle_iterator<Segment_cell_iterator, Cell_handle>>
      Segment_traverser_cell_handles;
  typedef Fast_Delaunay_triangulation_3_internal::Segment_walk_iterator<Self, Simplex> Segment_simplex_iterator;
  typedef Iterator_range<Segment_simplex_iterator> Segment_traverser_simplices;

  // ---------------------------------------------------------------- creation
  explicit Fast_Delaunay_triangulation_3(const Geom_traits& gt = Geom_traits(),
                                         Lock_data_structure* lock_ds = nullptr)
      : anchor_(new Anchor(gt)), lock_ds_(lock_ds)
  {}
  explicit Fast_Delaunay_triangulation_3(Lock_data_structure* lock_ds, const Geom_traits& gt = Geom_traits())
      : anchor_(new Anchor(gt)), lock_ds_(lock_ds)
  {}

  template <class InputIterator>
  Fast_Delaunay_triangulation_3(InputIterator first, InputIterator last,
                                const Geom_traits& gt = Geom_traits(),
                                Lock_data_structure* lock_ds = nullptr)
      : anchor_(new Anchor(gt)), lock_ds_(lock_ds)
  {
    insert(first, last);
  }
  template <class InputIterator>
  Fast_Delaunay_triangulation_3(InputIterator first, InputIterator last, Lock_data_structure* lock_ds,
                                const Geom_traits& gt = Geom_traits())
      : anchor_(new Anchor(gt)), lock_ds_(lock_ds)
  {
    insert(first, last);
  }

  Lock_data_structure* get_lock_data_structure() const { return lock_ds_; }
  void set_lock_data_structure(Lock_data_structure* lock_ds) { lock_ds_ = lock_ds; }
  bool is_parallel() const { return std::is_same<Concurrency_tag, Parallel_tag>::value; }

  // A copy has an anchor of its own: handles of `other` stay with `other`.
  Fast_Delaunay_triangulation_3(const Self& other)
      : anchor_(new Anchor(*other.anchor_)), lock_ds_(other.lock_ds_), threads_(other.threads_)
  {}
  // The data and its anchor change hands, so handles of `other` designate
  // the same vertices and cells, now in *this; `other` is left empty and
  // valid, with an anchor of its own (an allocation: a bad_alloc there
  // terminates).
  Fast_Delaunay_triangulation_3(Self&& other) noexcept
      : anchor_(std::move(other.anchor_)), lock_ds_(other.lock_ds_), threads_(other.threads_)
  {
    other.anchor_.reset(new Anchor(anchor_->traits));
  }
  Self& operator=(const Self& other)
  {
    if(this != &other) {
      anchor_.reset(new Anchor(*other.anchor_));
      lock_ds_ = other.lock_ds_;
      threads_ = other.threads_;
    }
    return *this;
  }
  Self& operator=(Self&& other) noexcept
  {
    if(this != &other) {
      anchor_ = std::move(other.anchor_);
      lock_ds_ = other.lock_ds_;
      threads_ = other.threads_;
      other.anchor_.reset(new Anchor(anchor_->traits));
    }
    return *this;
  }
  // Handles and iterators follow the data, as CGAL's do.
  void swap(Self& other) noexcept
  {
    std::swap(anchor_, other.anchor_);
    std::swap(lock_ds_, other.lock_ds_);
    std::swap(threads_, other.threads_);
  }
  void clear() { anchor_->clear(); }

  // CGAL's way to name the infinite vertex after tds().copy_tds().  Ours is
  // a fixed vertex of the arrays, which copy_tds() returns: only that one
  // is accepted, anything else throws std::invalid_argument.
  void set_infinite_vertex(Vertex_handle v)
  {
    if(v != infinite_vertex())
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::set_infinite_vertex: the infinite vertex is "
                                  "fixed; only the vertex tds().copy_tds() returned can be given");
  }

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
    std::vector<double> xyz;
    // With a kernel whose FT is not double, the user's points are kept
    // (Kernel_points.h): gathered first, their doubles checked exact.
    std::vector<Point> points;
    std::vector<Vertex_id> vertex_of_input;
    std::vector<Vertex_id>* const ids = keeps_kernel_points ? &vertex_of_input : nullptr;
    if constexpr(std::is_convertible<Value, Point>::value) {
      if constexpr(keeps_kernel_points) {
        points.assign(first, last);
        append_coordinates(points.begin(), points.end(), xyz, std::forward_iterator_tag());
      } else {
        append_coordinates(first, last, xyz, typename std::iterator_traits<InputIterator>::iterator_category());
      }
      return insert_coordinates(xyz, ids, &points);
    } else {
      static_assert(!std::is_void<Vertex_info>::value,
                    "points with infos need a vertex base with info (Triangulation_vertex_base_with_info_3)");
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
    std::vector<Point> points;
    std::vector<double> xyz;
    if constexpr(keeps_kernel_points) {
      points.assign(first, last);
      append_coordinates(points.begin(), points.end(), xyz, std::forward_iterator_tag());
    } else {
      append_coordinates(first, last, xyz, typename std::iterator_traits<InputIterator>::iterator_category());
    }
    std::vector<Vertex_id> vertex_of_input;
    insert_coordinates(xyz, &vertex_of_input, &points);
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
  void remove(Vertex_handle v)
  {
    std::vector<Tet_id> made;
    remove_vertex(v, made);
  }
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
  // in the kernel of its star, the star and the cells beyond it in conflict
  // with p are re-triangulated from their vertices and p at once; otherwise
  // v is removed and inserted again under the same id.  A NaN or infinite
  // coordinate throws std::invalid_argument, nothing changed.
  Vertex_handle move_if_no_collision(Vertex_handle v, const Point& p)
  {
    std::vector<Tet_id> made;
    return move_vertex(v, p, false, made);
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
  Vertex_handle move(Vertex_handle v, const Point& p)
  {
    std::vector<Tet_id> made;
    return move_vertex(v, p, true, made);
  }

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
    if(dimension() == 2) {
      std::vector<Reference_facet> boundary, internal;
      std::vector<Reference_cell> cells;
      lower().delaunay().find_conflicts(to_reference(p), to_reference(c), std::back_inserter(boundary),
                                        std::back_inserter(cells), std::back_inserter(internal));
      for(const Reference_facet& f : boundary) *bfit++ = from_reference(f);
      for(Reference_cell x : cells) *cit++ = from_reference(x);
      for(const Reference_facet& f : internal) *ifit++ = from_reference(f);
      return make_triple(bfit, cit, ifit);
    }
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
    if(dimension() == 2) {
      std::vector<Reference_vertex> vertices;
      lower().delaunay().vertices_on_conflict_zone_boundary(to_reference(p), to_reference(c),
                                                            std::back_inserter(vertices));
      for(Reference_vertex v : vertices) *res++ = from_reference(v);
      return res;
    }
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

  // ---------------------------------------------------------------- segment traverser (dimensions 3 and 2)
  // The cells and the faces met by the segment [p, q] (or [vs, vt]) in
  // order (see Segment_traverser.h); p may lie outside the hull.  In
  // dimension 2, CGAL's cell traverser on CGAL's triangulation beside the
  // arrays answers, p and q in the plane of the points.  The rest needs
  // dimension 3: in dimension 2 CGAL 5.5's simplex traverser dereferences a
  // null cell, and its cell traverser from a vertex reads vertex(-1) (UBSan).
  Segment_cell_iterator segment_traverser_cells_begin(const Point& p, const Point& q,
                                                      Cell_handle hint = Cell_handle()) const
  {
    if(dimension() == 2)
      return Segment_cell_iterator(planar_segment_cells(
          lower().delaunay().segment_traverser_cells_begin(to_reference(p), to_reference(q), to_reference(hint))));
    return Segment_cell_iterator(segment_walk(p, q, hint).cells);
  }
  Segment_cell_iterator segment_traverser_cells_begin(Vertex_handle vs, Vertex_handle vt) const
  {
    return Segment_cell_iterator(segment_walk(vs, vt).cells);
  }
  Segment_cell_iterator segment_traverser_cells_end() const { return Segment_cell_iterator(); }
  Segment_traverser_cell_handles segment_traverser_cell_handles(Vertex_handle vs, Vertex_handle vt) const
  {
    return cell_handles_of(segment_traverser_cells_begin(vs, vt));
  }
  Segment_traverser_cell_handles segment_traverser_cell_handles(const Point& p, const Point& q,
                                                                Cell_handle hint = Cell_handle()) const
  {
    return cell_handles_of(segment_traverser_cells_begin(p, q, hint));
  }
  Segment_simplex_iterator segment_traverser_simplices_begin(const Point& p, const Point& q,
                                                             Cell_handle hint = Cell_handle()) const
  {
    return Segment_simplex_iterator(simplices_of(segment_walk(p, q, hint)));
  }
  Segment_simplex_iterator segment_traverser_simplices_begin(Vertex_handle vs, Vertex_handle vt) const
  {
    return Segment_simplex_iterator(simplices_of(segment_walk(vs, vt)));
  }
  Segment_simplex_iterator segment_traverser_simplices_end() const { return Segment_simplex_iterator(); }
  Segment_traverser_simplices segment_traverser_simplices(const Point& p, const Point& q,
                                                          Cell_handle hint = Cell_handle()) const
  {
    return Segment_traverser_simplices(segment_traverser_simplices_begin(p, q, hint),
                                       segment_traverser_simplices_end());
  }
  Segment_traverser_simplices segment_traverser_simplices(Vertex_handle vs, Vertex_handle vt) const
  {
    return Segment_traverser_simplices(segment_traverser_simplices_begin(vs, vt), segment_traverser_simplices_end());
  }

  // ---------------------------------------------------------------- access
  const Geom_traits& geom_traits() const { return anchor_->traits; }
  // The combinatorial layer (Flat_tds.h); it goes with the data through
  // swap() and moves, as the handles do.
  Tds& tds() { return anchor_->tds; }
  const Tds& tds() const { return anchor_->tds; }
  int dimension() const { return anchor_->core.dimension; }
  size_type number_of_vertices() const { return anchor_->core.number_of_vertices(); }
  // Cells, finite and infinite; 0 in dimension < 3, as in CGAL (the triangles
  // of dimension 2 are facets, the segments of dimension 1 edges).
  size_type number_of_cells() const { return dimension() < 3 ? 0 : anchor_->core.mesh.live_tets; }
  size_type number_of_finite_cells() const
  {
    return dimension() < 3 ? 0 : anchor_->core.mesh.live_tets - anchor_->core.mesh.ghost_tets;
  }
  size_type number_of_facets() const
  {
    return dimension() == 3 ? 2 * number_of_cells() : dimension() == 2 ? anchor_->core.mesh.live_tets : 0;
  }
  size_type number_of_finite_facets() const
  {
    if(dimension() == 2) return anchor_->core.mesh.live_tets - anchor_->core.mesh.ghost_tets;
    return dimension() < 3 ? 0 : (4 * number_of_finite_cells() + anchor_->core.mesh.ghost_tets) / 2;
  }
  // Dimension 3: Euler's relation on the triangulated ball, V - E + F - T = 1.
  // Dimension 2: each triangle has 3 edges, each edge 2 triangles, and one
  // infinite edge per infinite triangle (per hull edge, so per hull vertex).
  // Dimension 1: the segments, two of them infinite.
  size_type number_of_finite_edges() const
  {
    switch(dimension()) {
      case 3: return number_of_vertices() + number_of_finite_facets() - number_of_finite_cells() - 1;
      case 2: return 3 * anchor_->core.mesh.live_tets / 2 - anchor_->core.mesh.ghost_tets;
      case 1: return anchor_->core.mesh.live_tets - 2;
      default: return 0;
    }
  }
  // Plus one infinite edge per hull vertex; the hull is a triangulated sphere
  // with H facets and H/2 + 2 vertices.
  size_type number_of_edges() const
  {
    switch(dimension()) {
      case 3: return number_of_finite_edges() + anchor_->core.mesh.ghost_tets / 2 + 2;
      case 2: return 3 * anchor_->core.mesh.live_tets / 2;
      case 1: return anchor_->core.mesh.live_tets;
      default: return 0;
    }
  }

  Vertex_handle infinite_vertex() const
  {
    return Vertex_handle(anchor_.get(), Fast_Delaunay_triangulation_3_internal::ghost_vertex);
  }
  // Below dimension 3, a triangle, segment or point cell that has the infinite
  // vertex; in dimension -1 the cell that holds only the infinite vertex.
  Cell_handle infinite_cell() const { return anchor_->infinite_cell(); }

  bool is_infinite(Vertex_handle v) const { return v.index() == Fast_Delaunay_triangulation_3_internal::ghost_vertex; }
  // Also below dimension 3 (where CGAL requires dimension 3): whether c has
  // the infinite vertex.
  bool is_infinite(Cell_handle c) const
  {
    return dimension() == 3 ? anchor_->core.mesh.is_ghost(c.index()) : has_infinite_vertex(c.index());
  }
  // Dimension 2: facet (c, 3) is the triangle c.
  bool is_infinite(Cell_handle c, int i) const
  {
    CGAL_precondition(dimension() == 3 || (dimension() == 2 && i == 3));
    if(dimension() == 2) return has_infinite_vertex(c.index());
    return is_infinite(c) && i != 3; // the ghost vertex is always vertex 3
  }
  bool is_infinite(const Facet& f) const { return is_infinite(f.first, f.second); }
  bool is_infinite(Cell_handle c, int i, int j) const
  {
    return is_infinite(c->vertex(i)) || is_infinite(c->vertex(j));
  }
  bool is_infinite(const Edge& e) const { return is_infinite(e.first, e.second, e.third); }

  int mirror_index(Cell_handle c, int i) const
  {
    return Fast_Delaunay_triangulation_3_internal::facet_of(anchor_->core.mesh.neighbor_code(c.index(), i));
  }
  Vertex_handle mirror_vertex(Cell_handle c, int i) const
  {
    return c->neighbor(i)->vertex(mirror_index(c, i));
  }
  Facet mirror_facet(const Facet& f) const
  {
    return Facet(f.first->neighbor(f.second), mirror_index(f.first, f.second));
  }

  // A reference where the vertex holds its point (a user vertex base, as
  // CGAL's Alpha_shape_3 needs), else a value built from the arrays.
  decltype(auto) point(Cell_handle c, int i) const { return c->vertex(i)->point(); }
  decltype(auto) point(Vertex_handle v) const { return v->point(); }
  Tetrahedron tetrahedron(Cell_handle c) const
  {
    return Tetrahedron(point(c, 0), point(c, 1), point(c, 2), point(c, 3));
  }
  // Facet i of c oriented as CGAL orients it (positive seen from c's inside).
  Triangle triangle(Cell_handle c, int i) const
  {
    CGAL_precondition(!is_infinite(c, i));
    if((i & 1) == 0) return Triangle(point(c, (i + 2) & 3), point(c, (i + 1) & 3), point(c, (i + 3) & 3));
    return Triangle(point(c, (i + 1) & 3), point(c, (i + 2) & 3), point(c, (i + 3) & 3));
  }
  Triangle triangle(const Facet& f) const { return triangle(f.first, f.second); }
  Segment segment(Cell_handle c, int i, int j) const
  {
    CGAL_precondition(!is_infinite(c, i, j));
    return Segment(point(c, i), point(c, j));
  }
  Segment segment(const Edge& e) const { return segment(e.first, e.second, e.third); }

  // ---------------------------------------------------------------- point location
  // CGAL's semantics: a point on the hull boundary is in a finite cell; one
  // outside is in an infinite cell whose finite facet sees it, li being the
  // infinite vertex.  The cell found may differ from CGAL's when several
  // qualify (a point on a facet, an edge or a vertex); lt never does.  Below
  // dimension 3, CGAL's locate on CGAL's triangulation of the same vertices
  // answers (Lower_dimensions.h), from the start cell given; a point that is
  // no double is located by the kernel's predicates (Kernel_queries.h).
  Cell_handle locate(const Point& p, Locate_type& lt, int& li, int& lj, Cell_handle start = Cell_handle(),
                     bool* could_lock_zone = nullptr) const
  {
    if(could_lock_zone) *could_lock_zone = true;
    double q[3];
    if(dimension() < 3 && !exact_coordinates(p, q)) {
      const Fast_Delaunay_triangulation_3_internal::Location loc = kernel_queries().locate_below_dimension_3(p);
      lt = static_cast<Locate_type>(loc.type);
      if(loc.li >= 0) li = loc.li;
      if(loc.lj >= 0) lj = loc.lj;
      return loc.cell == Tet_id(-1) ? Cell_handle() : Cell_handle(anchor_.get(), loc.cell);
    }
    if(dimension() < 3) {
      typename Lower::Locate_type type;
      const Reference_cell c = lower().delaunay().locate(to_reference(p), type, li, lj, to_reference(start));
      lt = static_cast<Locate_type>(type);
      return from_reference(c);
    }
    const Tet_id from = start ? start.index() : Tet_id(-1);
    const Fast_Delaunay_triangulation_3_internal::Location loc =
        exact_coordinates(p, q) ? Fast_Delaunay_triangulation_3_internal::locate(anchor_->core.mesh, from, q)
                                : kernel_queries().locate(from, p);
    lt = static_cast<Locate_type>(loc.type);
    if(loc.li >= 0) li = loc.li;
    if(loc.lj >= 0) lj = loc.lj;
    return Cell_handle(anchor_.get(), loc.cell);
  }
  Cell_handle locate(const Point& p, Cell_handle start = Cell_handle(), bool* could_lock_zone = nullptr) const
  {
    Locate_type lt;
    int li, lj;
    return locate(p, lt, li, lj, start, could_lock_zone);
  }
  Cell_handle locate(const Point& p, Locate_type& lt, int& li, int& lj, Vertex_handle hint,
                     bool* could_lock_zone = nullptr) const
  {
    return locate(p, lt, li, lj, hint == Vertex_handle() ? Cell_handle() : hint->cell(), could_lock_zone);
  }
  Cell_handle locate(const Point& p, Vertex_handle hint, bool* could_lock_zone = nullptr) const
  {
    return locate(p, hint == Vertex_handle() ? Cell_handle() : hint->cell(), could_lock_zone);
  }
  // The exact walk is cheap enough here (filtered predicates): the cell of
  // locate().  Below dimension 3, `start`, as CGAL's inexact_locate returns.
  Cell_handle inexact_locate(const Point& p, Cell_handle start = Cell_handle(), int = 2500,
                             bool* could_lock_zone = nullptr) const
  {
    if(dimension() < 3) {
      if(could_lock_zone) *could_lock_zone = true;
      return start;
    }
    return locate(p, start, could_lock_zone);
  }
  Bounded_side side_of_cell(const Point& p, Cell_handle c, Locate_type& lt, int& i, int& j) const
  {
    CGAL_precondition(dimension() == 3);
    // lt has a meaning only on the bounded side or the boundary (CGAL's
    // words); on the unbounded side it says outside.
    Fast_Delaunay_triangulation_3_internal::Location_type type =
        Fast_Delaunay_triangulation_3_internal::Location_type::outside_convex_hull;
    double q[3];
    Bounded_side side;
    if(exact_coordinates(p, q)) {
      const Flat_storage& m = anchor_->core.mesh;
      side = Fast_Delaunay_triangulation_3_internal::side_of_cell(
          anchor_->traits, m, c.index(), p,
          [&](int k) { return Fast_Delaunay_triangulation_3_internal::orientation_with(m, c.index(), k, q); },
          [this](Vertex_id v) { return point_of(v); }, type, i, j);
    } else {
      side = kernel_queries().side_of_cell(c.index(), p, type, i, j);
    }
    lt = static_cast<Locate_type>(type);
    return side;
  }
  // Dimension 2: p against triangle (c, 3), as CGAL (lt, li, lj about c).
  Bounded_side side_of_facet(const Point& p, Cell_handle c, Locate_type& lt, int& li, int& lj) const
  {
    CGAL_precondition(dimension() == 2);
    typename Lower::Locate_type type = unset_locate_type();
    const Bounded_side side = lower().delaunay().side_of_facet(to_reference(p), to_reference(c), type, li, lj);
    if(type != unset_locate_type()) lt = static_cast<Locate_type>(type);
    return side;
  }
  Bounded_side side_of_facet(const Point& p, const Facet& f, Locate_type& lt, int& li, int& lj) const
  {
    CGAL_precondition(f.second == 3);
    return side_of_facet(p, f.first, lt, li, lj);
  }
  // Dimension 1: p against segment (c, 0, 1), as CGAL.
  Bounded_side side_of_edge(const Point& p, Cell_handle c, Locate_type& lt, int& li) const
  {
    CGAL_precondition(dimension() == 1);
    typename Lower::Locate_type type = unset_locate_type();
    const Bounded_side side = lower().delaunay().side_of_edge(to_reference(p), to_reference(c), type, li);
    if(type != unset_locate_type()) lt = static_cast<Locate_type>(type);
    return side;
  }
  Bounded_side side_of_edge(const Point& p, const Edge& e, Locate_type& lt, int& li) const
  {
    CGAL_precondition(e.second == 0 && e.third == 1);
    return side_of_edge(p, e.first, lt, li);
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
    return Fast_Delaunay_triangulation_3_internal::nearest_vertex(*this, p, start);
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
  bool is_vertex(const Point& p, Vertex_handle& v) const
  {
    Locate_type lt;
    int li, lj;
    const Cell_handle c = locate(p, lt, li, lj);
    if(lt != VERTEX) return false;
    v = c->vertex(li);
    return true;
  }
  bool is_vertex(Vertex_handle v) const
  {
    return v.owner() == anchor_.get() &&
           (is_infinite(v) || (v.index() < vertex_count() && !anchor_->core.mesh.is_dead(v.index())));
  }
  bool is_cell(Cell_handle c) const
  {
    return dimension() == 3 && c.owner() == anchor_.get() && c.index() < anchor_->core.mesh.number_of_slots() &&
           anchor_->core.mesh.is_live(c.index());
  }
  // Below dimension 3 CGAL's triangulation answers (CGAL 5.5 looks among
  // the cells around u, and finds none below dimension 2: is_edge() is
  // false in dimension 1).
  bool is_edge(Vertex_handle u, Vertex_handle v, Cell_handle& c, int& i, int& j) const
  {
    if(dimension() < 3) {
      typename Lower::Reference_cell rc;
      if(!lower().delaunay().is_edge(to_reference(u), to_reference(v), rc, i, j)) return false;
      c = from_reference(rc);
      return true;
    }
    int index[2];
    const Vertex_handle others[1] = {v};
    if(u == v || !Fast_Delaunay_triangulation_3_internal::find_cell_with(*this, u, others, c, index)) return false;
    i = index[0]; j = index[1];
    return true;
  }
  bool is_facet(Vertex_handle u, Vertex_handle v, Vertex_handle w, Cell_handle& c, int& i, int& j, int& k) const
  {
    if(dimension() < 3) {
      typename Lower::Reference_cell rc;
      if(!lower().delaunay().is_facet(to_reference(u), to_reference(v), to_reference(w), rc, i, j, k)) return false;
      c = from_reference(rc);
      return true;
    }
    int index[3];
    const Vertex_handle others[2] = {v, w};
    if(u == v || u == w || v == w ||
       !Fast_Delaunay_triangulation_3_internal::find_cell_with(*this, u, others, c, index))
      return false;
    i = index[0]; j = index[1]; k = index[2];
    return true;
  }
  bool is_cell(Vertex_handle u, Vertex_handle v, Vertex_handle w, Vertex_handle t, Cell_handle& c, int& i, int& j,
               int& k, int& l) const
  {
    int index[4];
    const Vertex_handle others[3] = {v, w, t};
    if(dimension() < 3 || !Fast_Delaunay_triangulation_3_internal::find_cell_with(*this, u, others, c, index))
      return false;
    i = index[0]; j = index[1]; k = index[2]; l = index[3];
    return true;
  }
  bool is_cell(Vertex_handle u, Vertex_handle v, Vertex_handle w, Vertex_handle t, Cell_handle& c) const
  {
    int i, j, k, l;
    return is_cell(u, v, w, t, c, i, j, k, l);
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
    if(dimension() == 2) return lower().delaunay().side_of_circle(to_reference(c), i, to_reference(p), perturb);
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

  // Triangulation_3::side_of_tetrahedron: p against the positively oriented
  // tetrahedron (p0, p1, p2, p3); lt, i, j as side_of_cell.
  Bounded_side side_of_tetrahedron(const Point& p, const Point& p0, const Point& p1, const Point& p2,
                                   const Point& p3, Locate_type& lt, int& i, int& j) const
  {
    const auto orientation = anchor_->traits.orientation_3_object();
    CGAL_precondition(orientation(p0, p1, p2, p3) == POSITIVE);
    const Orientation o[4] = {orientation(p, p1, p2, p3), orientation(p0, p, p2, p3), orientation(p0, p1, p, p3),
                              orientation(p0, p1, p2, p)};
    int on = 0;
    for(Orientation x : o) {
      if(x == NEGATIVE) {
        lt = OUTSIDE_CONVEX_HULL;
        return ON_UNBOUNDED_SIDE;
      }
      on += x == ZERO ? 1 : 0;
    }
    auto first = [&o](Orientation x) { return o[0] == x ? 0 : o[1] == x ? 1 : o[2] == x ? 2 : 3; };
    switch(on) {
    case 0: lt = CELL; return ON_BOUNDED_SIDE;
    case 1: lt = FACET; i = first(ZERO); return ON_BOUNDARY;
    case 2: // on the edge of the two vertices whose facets do not hold p
      lt = EDGE;
      i = first(POSITIVE);
      j = o[3] == POSITIVE ? 3 : o[2] == POSITIVE ? 2 : 1;
      return ON_BOUNDARY;
    default: lt = VERTEX; i = first(POSITIVE); return ON_BOUNDARY;
    }
  }

  // ---------------------------------------------------------------- adjacency
  // Below dimension 3, CGAL's triangulation answers, in its order (CGAL
  // defines incident cells and facets from dimension 2, edges from
  // dimension 1; below that they are empty).
  template <class OutputIterator>
  OutputIterator incident_cells(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_cell>(out, [&](auto to) { lower().delaunay().incident_cells(to_reference(v), to); });
    return cells_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_incident_cells(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_cell>(out, [&](auto to) { lower().delaunay().finite_incident_cells(to_reference(v), to); });
    return cells_around(v, out, true);
  }
  template <class OutputIterator>
  OutputIterator incident_facets(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_facet>(out, [&](auto to) { lower().delaunay().incident_facets(to_reference(v), to); });
    return facets_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_incident_facets(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_facet>(out, [&](auto to) { lower().delaunay().finite_incident_facets(to_reference(v), to); });
    return facets_around(v, out, true);
  }
  template <class OutputIterator>
  OutputIterator incident_edges(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_edge>(out, [&](auto to) { lower().delaunay().incident_edges(to_reference(v), to); });
    return edges_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_incident_edges(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_edge>(out, [&](auto to) { lower().delaunay().finite_incident_edges(to_reference(v), to); });
    return edges_around(v, out, true);
  }
  template <class OutputIterator>
  OutputIterator adjacent_vertices(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_vertex>(out, [&](auto to) { lower().delaunay().adjacent_vertices(to_reference(v), to); });
    return vertices_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_adjacent_vertices(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_dimension_3<Reference_vertex>(out, [&](auto to) { lower().delaunay().finite_adjacent_vertices(to_reference(v), to); });
    return vertices_around(v, out, true);
  }
  template <class OutputIterator>
  OutputIterator incident_vertices(Vertex_handle v, OutputIterator out) const { return adjacent_vertices(v, out); }
  template <class OutputIterator>
  OutputIterator finite_incident_vertices(Vertex_handle v, OutputIterator out) const
  {
    return finite_adjacent_vertices(v, out);
  }
  // Adjacent vertices, the infinite one included (CGAL's count).
  size_type degree(Vertex_handle v) const
  {
    if(dimension() < 3) return lower().delaunay().degree(to_reference(v));
    std::size_t n = 0;
    vertices_around(v, Fast_Delaunay_triangulation_3_internal::Counting_output{&n}, false);
    return n;
  }

  Cell_circulator incident_cells(Cell_handle c, int i, int j) const { return incident_cells(c, i, j, c); }
  Cell_circulator incident_cells(const Edge& e) const { return incident_cells(e.first, e.second, e.third); }
  Cell_circulator incident_cells(Cell_handle c, int i, int j, Cell_handle start) const
  {
    CGAL_precondition(dimension() == 3 && start->has_vertex(c->vertex(i)) && start->has_vertex(c->vertex(j)));
    return Cell_circulator(anchor_.get(), c->vertex(i).index(), c->vertex(j).index(), start.index());
  }
  Cell_circulator incident_cells(const Edge& e, Cell_handle start) const
  {
    return incident_cells(e.first, e.second, e.third, start);
  }
  Facet_circulator incident_facets(Cell_handle c, int i, int j) const
  {
    CGAL_precondition(dimension() == 3);
    return Facet_circulator(anchor_.get(), c->vertex(i).index(), c->vertex(j).index(), c.index());
  }
  Facet_circulator incident_facets(const Edge& e) const { return incident_facets(e.first, e.second, e.third); }
  // Starting at facet f of start: from start if f is the facet that follows
  // it around the edge, else from the cell on the other side of f.
  Facet_circulator incident_facets(Cell_handle c, int i, int j, Cell_handle start, int f) const
  {
    CGAL_precondition(dimension() == 3);
    const int si = start->index(c->vertex(i)), sj = start->index(c->vertex(j));
    const Cell_handle from = f == next_around_edge(si, sj) ? start : start->neighbor(f);
    return Facet_circulator(anchor_.get(), c->vertex(i).index(), c->vertex(j).index(), from.index());
  }
  Facet_circulator incident_facets(const Edge& e, Cell_handle start, int f) const
  {
    return incident_facets(e.first, e.second, e.third, start, f);
  }
  Facet_circulator incident_facets(Cell_handle c, int i, int j, const Facet& start) const
  {
    return incident_facets(c, i, j, start.first, start.second);
  }
  Facet_circulator incident_facets(const Edge& e, const Facet& start) const
  {
    return incident_facets(e.first, e.second, e.third, start.first, start.second);
  }

  // ---------------------------------------------------------------- iterators
  // No cells below dimension 3, as in CGAL.
  All_cells_iterator all_cells_begin() const
  {
    return dimension() < 3 ? all_cells_end() : anchor_->tds.raw_cells_begin();
  }
  All_cells_iterator all_cells_end() const { return anchor_->tds.raw_cells_end(); }
  All_cells_iterator cells_begin() const { return all_cells_begin(); }
  All_cells_iterator cells_end() const { return all_cells_end(); }
  Finite_cells_iterator finite_cells_begin() const { return Finite_cells_iterator(anchor_.get(), 0, cell_slots()); }
  Finite_cells_iterator finite_cells_end() const { return Finite_cells_iterator(anchor_.get(), cell_slots(), cell_slots()); }

  // The infinite vertex exists even in the empty triangulation, as in CGAL.
  All_vertices_iterator all_vertices_begin() const { return anchor_->tds.vertices_begin(); }
  All_vertices_iterator all_vertices_end() const { return anchor_->tds.vertices_end(); }
  All_vertices_iterator vertices_begin() const { return all_vertices_begin(); }
  All_vertices_iterator vertices_end() const { return all_vertices_end(); }
  Finite_vertices_iterator finite_vertices_begin() const
  {
    return Finite_vertices_iterator(anchor_.get(), 0, vertex_count());
  }
  Finite_vertices_iterator finite_vertices_end() const
  {
    return Finite_vertices_iterator(anchor_.get(), vertex_count(), vertex_count());
  }

  All_facets_iterator all_facets_begin() const { return All_facets_iterator(anchor_.get(), 0); }
  All_facets_iterator all_facets_end() const { return All_facets_iterator(anchor_.get(), 4 * slots_of_faces(2)); }
  All_facets_iterator facets_begin() const { return all_facets_begin(); }
  All_facets_iterator facets_end() const { return all_facets_end(); }
  Finite_facets_iterator finite_facets_begin() const { return Finite_facets_iterator(anchor_.get(), 0); }
  Finite_facets_iterator finite_facets_end() const { return Finite_facets_iterator(anchor_.get(), 4 * slots_of_faces(2)); }

  All_edges_iterator all_edges_begin() const { return All_edges_iterator(anchor_.get(), 0); }
  All_edges_iterator all_edges_end() const { return All_edges_iterator(anchor_.get(), 6 * slots_of_faces(1)); }
  All_edges_iterator edges_begin() const { return all_edges_begin(); }
  All_edges_iterator edges_end() const { return all_edges_end(); }
  Finite_edges_iterator finite_edges_begin() const { return Finite_edges_iterator(anchor_.get(), 0); }
  Finite_edges_iterator finite_edges_end() const { return Finite_edges_iterator(anchor_.get(), 6 * slots_of_faces(1)); }

  All_cells all_cells() const { return All_cells(all_cells_begin(), all_cells_end()); }
  Finite_cells finite_cells() const { return Finite_cells(finite_cells_begin(), finite_cells_end()); }
  All_vertices all_vertices() const { return All_vertices(all_vertices_begin(), all_vertices_end()); }
  Finite_vertices finite_vertices() const { return Finite_vertices(finite_vertices_begin(), finite_vertices_end()); }
  All_facets all_facets() const { return All_facets(all_facets_begin(), all_facets_end()); }
  Finite_facets finite_facets() const { return Finite_facets(finite_facets_begin(), finite_facets_end()); }
  All_edges all_edges() const { return All_edges(all_edges_begin(), all_edges_end()); }
  Finite_edges finite_edges() const { return Finite_edges(finite_edges_begin(), finite_edges_end()); }

  All_cell_handles all_cell_handles() const
  {
    return All_cell_handles(All_cell_handles_iterator(all_cells_begin()), All_cell_handles_iterator(all_cells_end()));
  }
  Finite_cell_handles finite_cell_handles() const
  {
    return Finite_cell_handles(Finite_cell_handles_iterator(finite_cells_begin()),
                               Finite_cell_handles_iterator(finite_cells_end()));
  }
  All_vertex_handles all_vertex_handles() const
  {
    return All_vertex_handles(All_vertex_handles_iterator(all_vertices_begin()),
                              All_vertex_handles_iterator(all_vertices_end()));
  }
  Finite_vertex_handles finite_vertex_handles() const
  {
    return Finite_vertex_handles(Finite_vertex_handles_iterator(finite_vertices_begin()),
                                 Finite_vertex_handles_iterator(finite_vertices_end()));
  }
  Point_iterator points_begin() const { return Point_iterator(finite_vertices_begin()); }
  Point_iterator points_end() const { return Point_iterator(finite_vertices_end()); }
  Points points() const { return Points(points_begin(), points_end()); }

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

  // ---------------------------------------------------------------- internals
  const Anchor* storage_anchor() const { return anchor_.get(); }
  const Flat_storage& flat_storage() const { return anchor_->core.mesh; }
  // For an export that ends the triangulation (the Python module's
  // delaunay() turns the tetrahedron records into its output in place):
  // the arrays to take apart.  Only clear() and the destructor may follow.
  Flat_storage& flat_storage_to_take_apart() { return anchor_->core.mesh; }
  Point point_of(Vertex_id v) const { return anchor_->point_of(v); }
  Cell_handle incident_cell_of(Vertex_id v) const { return anchor_->incident_cell_of(v); }
  bool has_infinite_vertex(Tet_id t) const { return anchor_->has_infinite_vertex(t); }
  std::size_t slots_of_faces(int face_dimension) const { return anchor_->slots_of_faces(face_dimension); }

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
    if(lt) {
      where.type = static_cast<typename Lower::Locate_type>(*lt);
      where.cell = to_reference(c);
      where.li = li;
      where.lj = lj;
    }
    const Vertex_id old_count = vertex_count();
    const Vertex_id v = anchor_->core.insert_one_below_dimension_3(xyz, start ? start.index() : Tet_id(-1),
                                                           lt ? &where : nullptr, around);
    vertices_added();
    keep_input(v, p, old_count);
    return Vertex_handle(anchor_.get(), v);
  }

  // Handles of CGAL's triangulation below dimension 3 (Lower_dimensions.h)
  // and ours, both ways; every CGAL cell has its slot, the one cell of the
  // empty triangulation included.
  const Lower& lower() const { return anchor_->core.lower; }
  // CGAL's side_of_facet / side_of_edge leave lt alone outside the simplex:
  // a value no enumerator has (but in the enum's range, 0..7) tells, so
  // that ours leave the caller's lt alone too.
  static typename Lower::Locate_type unset_locate_type() { return static_cast<typename Lower::Locate_type>(7); }
  Cell_handle from_reference(Reference_cell c) const { return anchor_->cell_of_reference(c); }
  Vertex_handle from_reference(Reference_vertex v) const
  {
    return v == Reference_vertex() ? Vertex_handle() : Vertex_handle(anchor_.get(), Lower::id(v));
  }
  Facet from_reference(const Reference_facet& f) const { return Facet(from_reference(f.first), f.second); }
  Edge from_reference(const Reference_edge& e) const { return Edge(from_reference(e.first), e.second, e.third); }
  Reference_cell to_reference(Cell_handle c) const { return c ? lower().cell(c.index()) : Reference_cell(); }
  Reference_vertex to_reference(Vertex_handle v) const
  {
    return v == Vertex_handle() ? Reference_vertex() : lower().vertex(v.index());
  }
  // Below dimension 3 CGAL's triangulation of the vertices' doubles
  // answers, so a query point must have double coordinates too.
  static typename Lower::Reference_point to_reference(const Point& p)
  {
    double xyz[3];
    engine_coordinates(p, xyz);
    return typename Lower::Reference_point(xyz[0], xyz[1], xyz[2]);
  }
  // Runs `query` with an output iterator of CGAL's elements of type
  // Reference, and writes them to `out` as our handles, in CGAL's order.
  template <class Reference, class OutputIterator, class Query>
  OutputIterator below_dimension_3(OutputIterator out, const Query& query) const
  {
    std::vector<Reference> found;
    query(std::back_inserter(found));
    for(const Reference& x : found) *out++ = from_reference(x);
    return out;
  }

  typedef Fast_Delaunay_triangulation_3_internal::Segment_walk<Self> Segment_walk;
  typedef Fast_Delaunay_triangulation_3_internal::Segment_walk_result<Self> Segment_walk_result;

  Segment_walk_result segment_walk(const Point& p, const Point& q, Cell_handle hint) const
  {
    CGAL_precondition(dimension() == 3 && p != q);
    Locate_type lt;
    int li, lj;
    const Cell_handle c = locate(p, lt, li, lj, hint);
    if(lt == OUTSIDE_CONVEX_HULL) return Segment_walk(this, p, q).run_from_outside(c);
    unsigned mask = 15u;
    if(lt == VERTEX) mask = 1u << li;
    else if(lt == EDGE) mask = (1u << li) | (1u << lj);
    else if(lt == FACET) mask = 15u & ~(1u << li);
    return Segment_walk(this, p, q).run({c, mask});
  }
  Segment_walk_result segment_walk(Vertex_handle vs, Vertex_handle vt) const
  {
    CGAL_precondition(dimension() == 3 && vs != vt && !is_infinite(vs) && !is_infinite(vt));
    const Cell_handle c = vs->cell();
    return Segment_walk(this, vs->point(), vt->point()).run({c, 1u << c->index(vs)});
  }
  std::vector<Cell_handle> planar_segment_cells(typename Lower::Delaunay::Segment_cell_iterator it) const
  {
    std::vector<Cell_handle> cells;
    for(; it != lower().delaunay().segment_traverser_cells_end(); ++it) cells.push_back(from_reference(Reference_cell(it)));
    return cells;
  }
  std::vector<Simplex> simplices_of(const Segment_walk_result& walk) const
  {
    std::vector<Simplex> simplices;
    for(const auto& f : walk.faces) {
      int index[4], n = 0;
      for(int k = 0; k < 4; ++k)
        if(f.mask & (1u << k)) index[n++] = k;
      if(n == 1) simplices.push_back(Simplex(f.cell->vertex(index[0])));
      else if(n == 2) simplices.push_back(Simplex(Edge(f.cell, index[0], index[1])));
      else if(n == 3) simplices.push_back(Simplex(Facet(f.cell, 6 - index[0] - index[1] - index[2])));
      else simplices.push_back(Simplex(f.cell));
    }
    return simplices;
  }

  Segment_traverser_cell_handles cell_handles_of(Segment_cell_iterator begin) const
  {
    typedef Fast_Delaunay_triangulation_3_internal::Handle_iterator<Segment_cell_iterator, Cell_handle> Handles;
    return Segment_traverser_cell_handles(Handles(begin), Handles(segment_traverser_cells_end()));
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

  void cells_around(Vertex_handle v, std::vector<Tet_id>& cells) const
  {
    CGAL_precondition(dimension() == 3);
    Fast_Delaunay_triangulation_3_internal::cells_around_vertex(anchor_->core.mesh, incident_cell_of(v.index()).index(),
                                                                v.index(), cells);
  }
  template <class OutputIterator>
  OutputIterator cells_around(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    std::vector<Tet_id> cells;
    cells_around(v, cells);
    for(Tet_id t : cells)
      if(!finite_only || !anchor_->core.mesh.is_ghost(t)) *out++ = Cell_handle(anchor_.get(), t);
    return out;
  }
  // Each facet once, from the cell of smaller index.
  template <class OutputIterator>
  OutputIterator facets_around(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    const Flat_storage& m = anchor_->core.mesh;
    std::vector<Tet_id> cells;
    cells_around(v, cells);
    for(Tet_id t : cells)
      for(int f = 0; f < 4; ++f) {
        if(m.vertex(t, f) == v.index() || m.neighbor(t, f) < t) continue;
        if(finite_only && m.is_ghost(t) && f != 3) continue;
        *out++ = Facet(Cell_handle(anchor_.get(), t), f);
      }
    return out;
  }
  template <class OutputIterator>
  OutputIterator edges_around(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    const Flat_storage& m = anchor_->core.mesh;
    std::vector<Tet_id> cells, cell_of_edge;
    std::vector<Vertex_id> vertices;
    cells_around(v, cells);
    Fast_Delaunay_triangulation_3_internal::vertices_around_vertex(m, cells, v.index(), vertices, &cell_of_edge);
    for(std::size_t k = 0; k < vertices.size(); ++k) {
      // Only the other vertex is tested: CGAL lists every edge of the
      // infinite vertex among its "finite" incident edges too.
      if(finite_only && vertices[k] == Fast_Delaunay_triangulation_3_internal::ghost_vertex) continue;
      const Tet_id t = cell_of_edge[k];
      *out++ = Edge(Cell_handle(anchor_.get(), t), Fast_Delaunay_triangulation_3_internal::index_of(m, t, v.index()),
                    Fast_Delaunay_triangulation_3_internal::index_of(m, t, vertices[k]));
    }
    return out;
  }
  template <class OutputIterator>
  OutputIterator vertices_around(Vertex_handle v, OutputIterator out, bool finite_only) const
  {
    std::vector<Tet_id> cells;
    std::vector<Vertex_id> vertices;
    cells_around(v, cells);
    Fast_Delaunay_triangulation_3_internal::vertices_around_vertex(anchor_->core.mesh, cells, v.index(), vertices, nullptr);
    for(Vertex_id w : vertices)
      if(!finite_only || w != Fast_Delaunay_triangulation_3_internal::ghost_vertex) *out++ = Vertex_handle(anchor_.get(), w);
    return out;
  }

  // Consumes `xyz`: the core frees it once the vertex records are written,
  // so the copy of the input does not stay resident while the mesh grows.
  // `points`: the user's objects of the range, empty when the kernel's FT
  // is double (then vertex_of_input may be null).
  std::ptrdiff_t insert_coordinates(std::vector<double>& xyz, std::vector<Vertex_id>* vertex_of_input,
                                    const std::vector<Point>* points)
  {
    const std::size_t n = xyz.size() / 3;
    Core::check_finite(xyz.data(), n);
    anchor_->incident_cells.clear();
    anchor_->core.partitions = partitions_for_insertion();
    const std::size_t added = anchor_->core.insert(xyz.data(), n, vertex_of_input, &xyz);
    anchor_->vertices_added(points->empty() ? nullptr : points, vertex_of_input);
    return static_cast<std::ptrdiff_t>(added);
  }

  std::size_t cell_slots() const { return dimension() < 3 ? 0 : anchor_->core.mesh.number_of_slots(); }
  // Vertex ids are below it; removed vertices keep their (dead) records.
  Vertex_id vertex_count() const { return static_cast<Vertex_id>(anchor_->core.vertex_slots()); }

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

  // ---------------------------------------------------------------- kernel points (Kernel_points.h)
  static constexpr bool keeps_kernel_points = Anchor::keeps_kernel_points;
  // The doubles of p, if they are exactly its coordinates (always, for a
  // kernel with double coordinates).
  static bool exact_coordinates(const Point& p, double* xyz)
  {
    return Fast_Delaunay_triangulation_3_internal::exact_coordinates(p, xyz);
  }
  // The doubles the engine takes for p: they must be p's coordinates
  // exactly and finite, else std::invalid_argument.
  static void engine_coordinates(const Point& p, double* xyz)
  {
    if(!exact_coordinates(p, xyz)) throw_not_doubles(p, "the point");
    Core::check_finite(xyz, 1);
  }
  [[noreturn]] static void throw_not_doubles(const Point& p, const std::string& which)
  {
    std::ostringstream message;
    message.precision(17);
    message << "Fast_Delaunay_triangulation_3: " << which << " (about " << CGAL::to_double(p.x()) << ' '
            << CGAL::to_double(p.y()) << ' ' << CGAL::to_double(p.z())
            << ") has coordinates not representable as doubles, which the engine needs here;"
            << " the triangulation is unchanged";
    throw std::invalid_argument(message.str());
  }
  // After the insertion of p as vertex v: a new vertex (id from old_count
  // on) keeps the user's object.
  void keep_input(Vertex_id v, const Point& p, Vertex_id old_count)
  {
    if(v >= old_count && v != Fast_Delaunay_triangulation_3_internal::ghost_vertex)
      anchor_->kernel_points.keep_input(v, p);
  }
  Fast_Delaunay_triangulation_3_internal::Kernel_queries<Anchor> kernel_queries() const
  {
    return Fast_Delaunay_triangulation_3_internal::Kernel_queries<Anchor>(*anchor_);
  }

  static constexpr int edge_vertex[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

  // Never null: a moved-from triangulation gets a new, empty anchor.
  std::unique_ptr<Anchor> anchor_;
  Lock_data_structure* lock_ds_ = nullptr;
  int threads_ = std::is_same<Concurrency_tag, Parallel_tag>::value ? 0 : 1;
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
