// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The triangulation layer of Fast_Delaunay_triangulation_3: the geometry
// over the flat data structure, as CGAL's Triangulation_3 is over its
// Triangulation_data_structure_3.  Types, handles and iterators, access,
// point location, adjacency and circulators, the segment traverser, and the
// storage they all read (the anchor).  It inserts, removes and moves no
// vertex: the Delaunay layer (CGAL/Fast_Delaunay_triangulation_3.h) derives
// from it and does.  What it writes: clear(), and the combinatorial updates
// of tds() (flips, create_vertex, copy_tds), as CGAL's Triangulation_3 does.

#ifndef CGAL_FDT3_INTERNAL_FLAT_TRIANGULATION_3_H
#define CGAL_FDT3_INTERNAL_FLAT_TRIANGULATION_3_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Adjacency_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Face_iterators.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Handles.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_points.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Lower_dimension_view.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Point_location.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Segment_traverser.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Simplex.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Storage_anchor.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_core.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/User_bases.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_and_cell_infos.h>

#include <CGAL/Default.h>
#include <CGAL/Triangulation_3.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/Location_policy.h>
#include <CGAL/Triangulation_utils_3.h>
#include <CGAL/enum.h>
#include <CGAL/iterator.h>
#include <CGAL/utility.h>
#include <CGAL/tags.h>

#include <algorithm>
#include <cstdint>
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

// A namespace of its own, with no free function in it: the namespace of a
// base class joins the argument-dependent lookup of every call with the
// public class as an argument, and the internal namespace's functions
// (write_vtu, locate, ...) would then compete with CGAL's and the user's.
namespace Fast_Delaunay_triangulation_3_layers {

// The triangulation layer of CGAL::Fast_Delaunay_triangulation_3, which
// derives from it as CGAL's Delaunay_triangulation_3 derives from
// Triangulation_3.  Not built on its own (its constructors are protected).
template <class Gt, class Tds_, class Location_policy_, class Lock_data_structure_>
class Flat_triangulation_3 : public Triangulation_utils_3
{
  typedef Flat_triangulation_3<Gt, Tds_, Location_policy_, Lock_data_structure_> Self;

protected:
  typedef Fast_Delaunay_triangulation_3_internal::Template_arguments<Tds_, Location_policy_> Arguments;
  typedef Fast_Delaunay_triangulation_3_internal::Triangulation_core Core;
  typedef Fast_Delaunay_triangulation_3_internal::Flat_storage Flat_storage;
  typedef Fast_Delaunay_triangulation_3_internal::Vertex_id Vertex_id;
  typedef Fast_Delaunay_triangulation_3_internal::Tet_id Tet_id;

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

  // Facets and edges once each (Face_iterators.h); bidirectional, as CGAL's.
  typedef Fast_Delaunay_triangulation_3_internal::Facet_iterator<Anchor, Facet, false> All_facets_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Facet_iterator<Anchor, Facet, true> Finite_facets_iterator;
  typedef All_facets_iterator Facet_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Edge_iterator<Anchor, Edge, false> All_edges_iterator;
  typedef Fast_Delaunay_triangulation_3_internal::Edge_iterator<Anchor, Edge, true> Finite_edges_iterator;
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
protected:
  // Only the Delaunay layer is built: this layer inserts nothing.
  Flat_triangulation_3(const Geom_traits& gt, Lock_data_structure* lock_ds)
      : anchor_(new Anchor(gt)), lock_ds_(lock_ds)
  {}
  // A copy has an anchor of its own: handles of `other` stay with `other`.
  Flat_triangulation_3(const Self& other)
      : anchor_(new Anchor(*other.anchor_)), lock_ds_(other.lock_ds_), threads_(other.threads_)
  {}
  // The data and its anchor change hands, so handles of `other` designate
  // the same vertices and cells, now in *this; `other` is left empty and
  // valid, with an anchor of its own (an allocation: a bad_alloc there
  // terminates).
  Flat_triangulation_3(Self&& other) noexcept
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

public:
  Lock_data_structure* get_lock_data_structure() const { return lock_ds_; }
  void set_lock_data_structure(Lock_data_structure* lock_ds) { lock_ds_ = lock_ds; }
  bool is_parallel() const { return std::is_same<Concurrency_tag, Parallel_tag>::value; }
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
      return Segment_cell_iterator(below_3().segment_cells(p, q, hint));
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
  // answers (Lower_dimension_view.h), from the start cell given; a point that is
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
    if(dimension() < 3) return below_3().locate(p, lt, li, lj, start);
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
    return below_3().side_of_facet(p, c, lt, li, lj);
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
    return below_3().side_of_edge(p, c, lt, li);
  }
  Bounded_side side_of_edge(const Point& p, const Edge& e, Locate_type& lt, int& li) const
  {
    CGAL_precondition(e.second == 0 && e.third == 1);
    return side_of_edge(p, e.first, lt, li);
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
  // Below dimension 3 CGAL's triangulation answers (Lower_dimension_view.h).
  bool is_edge(Vertex_handle u, Vertex_handle v, Cell_handle& c, int& i, int& j) const
  {
    if(dimension() < 3) return below_3().is_edge(u, v, c, i, j);
    int index[2];
    const Vertex_handle others[1] = {v};
    if(u == v || !Fast_Delaunay_triangulation_3_internal::find_cell_with(*this, u, others, c, index)) return false;
    i = index[0]; j = index[1];
    return true;
  }
  bool is_facet(Vertex_handle u, Vertex_handle v, Vertex_handle w, Cell_handle& c, int& i, int& j, int& k) const
  {
    if(dimension() < 3) return below_3().is_facet(u, v, w, c, i, j, k);
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
  // Below dimension 3, CGAL's triangulation answers, in its order
  // (Lower_dimension_view.h).
  template <class OutputIterator>
  OutputIterator incident_cells(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().incident_cells(v, out, false);
    return cells_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_incident_cells(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().incident_cells(v, out, true);
    return cells_around(v, out, true);
  }
  template <class OutputIterator>
  OutputIterator incident_facets(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().incident_facets(v, out, false);
    return facets_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_incident_facets(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().incident_facets(v, out, true);
    return facets_around(v, out, true);
  }
  template <class OutputIterator>
  OutputIterator incident_edges(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().incident_edges(v, out, false);
    return edges_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_incident_edges(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().incident_edges(v, out, true);
    return edges_around(v, out, true);
  }
  template <class OutputIterator>
  OutputIterator adjacent_vertices(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().adjacent_vertices(v, out, false);
    return vertices_around(v, out, false);
  }
  template <class OutputIterator>
  OutputIterator finite_adjacent_vertices(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 3) return below_3().adjacent_vertices(v, out, true);
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
    if(dimension() < 3) return below_3().degree(v);
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

protected:
  // Every answer below dimension 3 (Lower_dimension_view.h).
  Fast_Delaunay_triangulation_3_internal::Lower_dimension_view<Self> below_3() const
  {
    return Fast_Delaunay_triangulation_3_internal::Lower_dimension_view<Self>(anchor_.get());
  }
  friend class Fast_Delaunay_triangulation_3_internal::Lower_dimension_view<Self>;

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
  std::size_t cell_slots() const { return dimension() < 3 ? 0 : anchor_->core.mesh.number_of_slots(); }
  // Vertex ids are below it; removed vertices keep their (dead) records.
  Vertex_id vertex_count() const { return static_cast<Vertex_id>(anchor_->core.vertex_slots()); }

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
  Fast_Delaunay_triangulation_3_internal::Kernel_queries<Anchor> kernel_queries() const
  {
    return Fast_Delaunay_triangulation_3_internal::Kernel_queries<Anchor>(*anchor_);
  }

  // Never null: a moved-from triangulation gets a new, empty anchor.
  std::unique_ptr<Anchor> anchor_;
  Lock_data_structure* lock_ds_ = nullptr;
  int threads_ = std::is_same<Concurrency_tag, Parallel_tag>::value ? 0 : 1;
};

} // namespace Fast_Delaunay_triangulation_3_layers
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_FLAT_TRIANGULATION_3_H
