// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The combinatorial layer seen as CGAL's Triangulation_data_structure_3:
// what `tr.tds()` returns.  It is a view over the flat arrays of one storage
// anchor (Storage_anchor.h), owned by that anchor, so its handles and
// iterators are the triangulation's own (a raw cell iterator assigns to the
// triangulation's Cell_iterator).  Everything here is combinatorial, as in
// CGAL's TDS: no predicate is evaluated, so a flip done here may leave the
// triangulation non-Delaunay or wrongly oriented; the triangulation's
// is_valid() then says so, while tds().is_valid() still holds.
//
// Vertices made by create_vertex() are dead records (Flat_storage.h) until
// insert_in_hole(p, ..., v) places them: neither the triangulation nor this
// view counts or iterates them before that, but is_vertex() knows them and
// delete_vertex() takes them back.
//
// Flips keep the representation's invariants: stored tetrahedra stay
// combinatorially positively oriented (each new tetrahedron is an old one
// with one vertex replaced by the vertex on the far side of the shared
// facet, which is how CGAL's TDS orients them too) and the ghost vertex
// stays in slot 3, by starting each flip from a tetrahedron where that holds.

#ifndef CGAL_FDT3_INTERNAL_FLAT_TDS_H
#define CGAL_FDT3_INTERNAL_FLAT_TDS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Adjacency_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Data_structure_copy.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Lower_dimensions.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Tetrahedra_replacement.h>

#include <CGAL/assertions.h>
#include <CGAL/Iterator_range.h>

#include <algorithm>
#include <cstddef>
#include <iostream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Types provides the triangulation's handle, iterator and circulator types
// (a class of typedefs, complete before the anchor is).
template <class Anchor, class Types>
class Flat_tds
{
public:
  typedef typename Types::Vertex_handle Vertex_handle;
  typedef typename Types::Cell_handle Cell_handle;
  typedef typename Types::Vertex Vertex;
  typedef typename Types::Cell Cell;
  typedef typename Types::Facet Facet;
  typedef typename Types::Edge Edge;
  typedef typename Types::Cell_iterator Cell_iterator;
  typedef typename Types::Vertex_iterator Vertex_iterator;
  typedef typename Types::Facet_iterator Facet_iterator;
  typedef typename Types::Edge_iterator Edge_iterator;
  typedef typename Types::Cell_circulator Cell_circulator;
  typedef typename Types::Facet_circulator Facet_circulator;
  typedef typename Types::Concurrency_tag Concurrency_tag;
  typedef std::size_t size_type;
  typedef std::ptrdiff_t difference_type;

  explicit Flat_tds(Anchor* anchor) : anchor_(anchor) {}
  // The view of a copied anchor: the copy's created vertices are the same ids.
  Flat_tds(Anchor* anchor, const Flat_tds& other) : anchor_(anchor), created_(other.created_) {}
  Flat_tds(const Flat_tds&) = delete;
  Flat_tds& operator=(const Flat_tds&) = delete;
  // The anchor is cleared (not a TDS member: CGAL's tds().clear() would clear the triangulation).
  void forget_created() { created_.clear(); }

  // ---------------------------------------------------------------- counts
  int dimension() const { return anchor_->dimension(); }
  // The infinite vertex included, as CGAL's TDS; created vertices not yet
  // in a cell are not counted (they are not iterated either).
  size_type number_of_vertices() const { return mesh().live_vertices() + 1; }
  size_type number_of_cells() const { return dimension() < 3 ? 0 : mesh().live_tets; }
  size_type number_of_facets() const { return static_cast<size_type>(std::distance(facets_begin(), facets_end())); }
  size_type number_of_edges() const { return static_cast<size_type>(std::distance(edges_begin(), edges_end())); }

  // ---------------------------------------------------------------- iterators
  // Every cell in the arrays, whatever the dimension (CGAL's raw cells).
  // Iterators are handles (Handles.h).
  Cell_iterator raw_cells_begin() const
  {
    return Cell_iterator(anchor_, first_index_from(*anchor_, Cell_kind(), Tet_id(0)));
  }
  Cell_iterator raw_cells_end() const { return Cell_iterator(anchor_, mesh().number_of_slots()); }
  Cell_iterator cells_begin() const { return dimension() < 3 ? cells_end() : raw_cells_begin(); }
  Cell_iterator cells_end() const { return raw_cells_end(); }
  // The infinite vertex first, as CGAL's.
  Vertex_iterator vertices_begin() const { return Vertex_iterator(anchor_, ghost_vertex); }
  Vertex_iterator vertices_end() const { return Vertex_iterator(anchor_, mesh().vertices.size()); }
  Facet_iterator facets_begin() const { return Facet_iterator(anchor_, 0); }
  Facet_iterator facets_end() const { return Facet_iterator(anchor_, 4 * anchor_->slots_of_faces(2)); }
  Edge_iterator edges_begin() const { return Edge_iterator(anchor_, 0); }
  Edge_iterator edges_end() const { return Edge_iterator(anchor_, 6 * anchor_->slots_of_faces(1)); }
  typedef Iterator_range<Facet_iterator> Facets;
  typedef Iterator_range<Edge_iterator> Edges;
  typedef Iterator_range<Cell_iterator> Cells;
  typedef Iterator_range<Vertex_iterator> Vertices;
  Facets facets() const { return Facets(facets_begin(), facets_end()); }
  Edges edges() const { return Edges(edges_begin(), edges_end()); }
  // The raw cells, as CGAL's cells() (its copy_tds() reads them so).
  Cells cells() const { return Cells(raw_cells_begin(), raw_cells_end()); }
  Vertices vertices() const { return Vertices(vertices_begin(), vertices_end()); }

  // ---------------------------------------------------------------- membership
  bool is_vertex(Vertex_handle v) const
  {
    if(v.owner() != anchor_) return false;
    if(v.index() == ghost_vertex) return true;
    return v.index() < mesh().vertices.size() && (!mesh().is_dead(v.index()) || is_created(v.index()));
  }
  bool is_cell(Cell_handle c) const
  {
    return dimension() == 3 && c.owner() == anchor_ && c.index() < mesh().number_of_slots() &&
           mesh().is_live(c.index());
  }
  bool is_edge(Cell_handle c, int i, int j) const
  {
    return dimension() >= 1 && live_slot(c) && i != j && 0 <= std::min(i, j) && std::max(i, j) <= dimension();
  }
  bool is_facet(Cell_handle c, int i) const
  {
    return dimension() >= 2 && live_slot(c) && 0 <= i && i <= 3 && (dimension() == 3 || i == 3);
  }
  bool is_edge(Vertex_handle u, Vertex_handle v) const
  {
    Cell_handle c;
    int i, j;
    return is_edge(u, v, c, i, j);
  }
  bool is_edge(Vertex_handle u, Vertex_handle v, Cell_handle& c, int& i, int& j) const
  {
    if(dimension() < 1) return false;
    const Vertex_id w[2] = {u.index(), v.index()};
    int at[4];
    return find_cell_with(w, 2, c, at) && (i = at[0], j = at[1], true);
  }
  bool is_facet(Vertex_handle u, Vertex_handle v, Vertex_handle w, Cell_handle& c, int& i, int& j, int& k) const
  {
    if(dimension() < 2) return false;
    const Vertex_id ids[3] = {u.index(), v.index(), w.index()};
    int at[4];
    return find_cell_with(ids, 3, c, at) && (i = at[0], j = at[1], k = at[2], true);
  }
  bool is_cell(Vertex_handle u, Vertex_handle v, Vertex_handle w, Vertex_handle t) const
  {
    Cell_handle c;
    int i, j, k, l;
    return is_cell(u, v, w, t, c, i, j, k, l);
  }
  bool is_cell(Vertex_handle u, Vertex_handle v, Vertex_handle w, Vertex_handle t, Cell_handle& c, int& i, int& j,
               int& k, int& l) const
  {
    if(dimension() < 3) return false;
    const Vertex_id ids[4] = {u.index(), v.index(), w.index(), t.index()};
    int at[4];
    return find_cell_with(ids, 4, c, at) && (i = at[0], j = at[1], k = at[2], l = at[3], true);
  }

  // ---------------------------------------------------------------- adjacency
  int mirror_index(Cell_handle c, int i) const { return facet_of(mesh().neighbor_code(c.index(), i)); }
  Vertex_handle mirror_vertex(Cell_handle c, int i) const { return c->neighbor(i)->vertex(mirror_index(c, i)); }
  Facet mirror_facet(const Facet& f) const { return Facet(f.first->neighbor(f.second), mirror_index(f.first, f.second)); }

  // Dimension 2 and 3, as CGAL's TDS (no cells around a vertex below).
  template <class OutputIterator>
  OutputIterator incident_cells(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 2) return out;
    for(Tet_id t : cells_of(v.index())) *out++ = Cell_handle(anchor_, t);
    return out;
  }
  // Dimension 1 to 3: the vertices joined to v by an edge, the infinite one included.
  template <class OutputIterator>
  OutputIterator adjacent_vertices(Vertex_handle v, OutputIterator out) const
  {
    if(dimension() < 1) return out;
    std::vector<Vertex_id> around;
    vertices_around_vertex(mesh(), cells_of(v.index()), v.index(), around, nullptr);
    for(Vertex_id w : around)
      if(w != no_vertex) *out++ = Vertex_handle(anchor_, w);
    return out;
  }
  size_type degree(Vertex_handle v) const
  {
    std::vector<Vertex_handle> around;
    adjacent_vertices(v, std::back_inserter(around));
    return around.size();
  }

  // ---------------------------------------------------------------- creation and deletion
  // A vertex in no cell, for insert_in_hole(p, ..., v) to place.
  Vertex_handle create_vertex()
  {
    const Vertex_id v = anchor_->core.create_unplaced_vertex();
    created_.push_back(v);
    anchor_->vertices_added();
    return Vertex_handle(anchor_, v);
  }
  // Only a vertex of create_vertex() that is in no cell yet: the others are
  // the triangulation's to remove.
  void delete_vertex(Vertex_handle v)
  {
    if(v.owner() != anchor_ || v.index() == ghost_vertex || !is_created(v.index()))
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::tds().delete_vertex: only a vertex made by "
                                  "create_vertex() and not yet in a cell can be deleted");
    placed(v.index());
  }
  // insert_in_hole placed created vertex v.
  void placed(Vertex_id v) { created_.erase(std::find(created_.begin(), created_.end(), v)); }
  bool is_created(Vertex_id v) const { return std::find(created_.begin(), created_.end(), v) != created_.end(); }

  // ---------------------------------------------------------------- copies (Data_structure_copy.h)
  // The triangulation becomes a copy of `source`, a data structure with
  // CGAL's interface whose vertex `infinite` is its infinite vertex, with
  // CGAL's conversion functors; returns the copy's infinite vertex, for
  // set_infinite_vertex().  The copy keeps the source's vertex order and, in
  // dimension 3, its cells in order; the points must be exactly doubles and
  // the source the Delaunay triangulation of its points (checked exactly),
  // else std::invalid_argument names the defect and nothing changes.
  template <class Source, class Convert_vertex, class Convert_cell>
  Vertex_handle copy_tds(const Source& source, typename Source::Vertex_handle infinite,
                         const Convert_vertex& convert_vertex, const Convert_cell& convert_cell)
  {
    copy_data_structure(*anchor_, source, infinite, convert_vertex, convert_cell);
    return Vertex_handle(anchor_, ghost_vertex);
  }
  // The points (and infos of the same type) go over as they are.
  template <class Source>
  Vertex_handle copy_tds(const Source& source, typename Source::Vertex_handle infinite)
  {
    return copy_tds(source, infinite, Default_vertex_conversion(), Default_cell_conversion());
  }

  // ---------------------------------------------------------------- flips (dimension 3)
  // 2-3 flip of facet (c, i): the two cells sharing it become three around
  // the new edge joining their opposite vertices; false, and nothing
  // changes, when that edge exists already (CGAL's only test).  Cell c's
  // slot holds one of the new cells.
  bool flip(Cell_handle c, int i)
  {
    check_flip(c, i, -1);
    const Facet_code across = mesh().neighbor_code(c.index(), i);
    if(shares_edge(mesh().vertex(c.index(), i), mesh().vertex(tet_of(across), facet_of(across)))) return false;
    flip_2_3(c.index(), i);
    return true;
  }
  bool flip(const Facet& f) { return flip(f.first, f.second); }
  void flip_flippable(Cell_handle c, int i)
  {
    const bool flipped = flip(c, i);
    CGAL_precondition(flipped);
    (void)flipped;
  }
  void flip_flippable(const Facet& f) { flip_flippable(f.first, f.second); }

  // 3-2 flip of edge (c, i, j): the three cells around an edge of degree 3
  // become two sharing the triangle of the three other vertices; false, and
  // nothing changes, when the edge has another degree or either new cell
  // exists already (CGAL's tests).
  bool flip(Cell_handle c, int i, int j)
  {
    check_flip(c, i, j);
    Ring ring;
    if(!ring_of_degree_3(c.index(), i, j, ring)) return false;
    const Vertex_id a = mesh().vertex(ring.cells[0], ring.i), b = mesh().vertex(ring.cells[0], ring.j);
    const Vertex_id z = mesh().vertex(ring.cells[1], ring.far[1]);
    const Vertex_id x = mesh().vertex(ring.cells[0], ring.k), y = mesh().vertex(ring.cells[0], ring.l);
    if(has_cell(a, x, y, z) || has_cell(b, x, y, z)) return false;
    flip_3_2(ring);
    return true;
  }
  bool flip(const Edge& e) { return flip(e.first, e.second, e.third); }
  void flip_flippable(Cell_handle c, int i, int j)
  {
    const bool flipped = flip(c, i, j);
    CGAL_precondition(flipped);
    (void)flipped;
  }
  void flip_flippable(const Edge& e) { flip_flippable(e.first, e.second, e.third); }

  // ---------------------------------------------------------------- checking
  // Combinatorial validity, as CGAL's TDS checks it: in dimension 3 live
  // distinct vertices in every cell, symmetric adjacency across shared
  // facets, neighbours oriented consistently, every live vertex in a cell,
  // the counts, and Euler's relation V - E + F - C = 0 of the 3-sphere.
  // Below dimension 3 the cells are CGAL's own, checked by
  // lower_dimensional_cells_are_valid (which checks their geometry too).
  bool is_valid(bool verbose = false, int = 0) const
  {
    std::string why;
    const bool ok = dimension() < 3 ? lower_dimensional_cells_are_valid(mesh(), dimension(), &why) : valid_3(why);
    if(!ok && verbose) std::cerr << "Fast_Delaunay_triangulation_3::tds().is_valid: " << why << std::endl;
    return ok;
  }

  // One vertex: a vertex of this TDS, in one of its cells unless it waits
  // for insert_in_hole.
  bool is_valid(Vertex_handle v, bool verbose = false, int = 0) const
  {
    bool ok = is_vertex(v);
    if(ok && !(v.index() != ghost_vertex && is_created(v.index()))) {
      const Tet_id t = some_cell_of(v.index());
      ok = t < mesh().number_of_slots() && mesh().is_live(t) && slot_of(t, v.index(), std::max(dimension(), 0)) >= 0;
    }
    if(!ok && verbose) std::cerr << "Fast_Delaunay_triangulation_3::tds().is_valid(v): not a vertex in its cell\n";
    return ok;
  }
  // One cell: live, and its neighbours point back at it across the same face.
  bool is_valid(Cell_handle c, bool verbose = false, int = 0) const
  {
    bool ok = live_slot(c);
    for(int i = 0; ok && i <= dimension(); ++i) {
      const Facet_code code = mesh().neighbor_code(c.index(), i);
      ok = tet_of(code) < mesh().number_of_slots() && mesh().is_live(tet_of(code)) &&
           mesh().neighbor_code(code) == facet_code(c.index(), i);
    }
    if(!ok && verbose) std::cerr << "Fast_Delaunay_triangulation_3::tds().is_valid(c): not a live cell with its neighbours\n";
    return ok;
  }

private:
  const Flat_storage& mesh() const { return anchor_->core.mesh; }
  Flat_storage& mesh() { return anchor_->core.mesh; }
  bool live_slot(Cell_handle c) const
  {
    return c.owner() == anchor_ && c.index() < mesh().number_of_slots() && mesh().is_live(c.index());
  }

  // The cells that have v: around it in dimension 3, by a scan below.
  std::vector<Tet_id> cells_of(Vertex_id v) const
  {
    std::vector<Tet_id> cells;
    if(dimension() == 3) {
      cells_around_vertex(mesh(), some_cell_of(v), v, cells);
      return cells;
    }
    for(Tet_id t = 0; t < mesh().number_of_slots(); ++t)
      if(mesh().is_live(t) && slot_of(t, v, dimension()) >= 0) cells.push_back(t);
    return cells;
  }
  Tet_id some_cell_of(Vertex_id v) const
  {
    return (v == ghost_vertex ? anchor_->infinite_cell() : anchor_->incident_cell_of(v)).index();
  }
  int slot_of(Tet_id t, Vertex_id v, int last) const
  {
    for(int s = 0; s <= last; ++s)
      if(mesh().vertex(t, s) == v) return s;
    return -1;
  }
  // A cell with the n distinct vertices ids[0..n), and their slots in it.
  bool find_cell_with(const Vertex_id* ids, int n, Cell_handle& c, int* at) const
  {
    for(int a = 0; a < n; ++a) {
      if(ids[a] != ghost_vertex && (ids[a] >= mesh().vertices.size() || mesh().is_dead(ids[a]))) return false;
      for(int b = 0; b < a; ++b)
        if(ids[a] == ids[b]) return false;
    }
    for(Tet_id t : cells_of(ids[0])) {
      int a = 0;
      for(; a < n; ++a)
        if((at[a] = slot_of(t, ids[a], dimension())) < 0) break;
      if(a == n) {
        c = Cell_handle(anchor_, t);
        return true;
      }
    }
    return false;
  }
  bool shares_edge(Vertex_id u, Vertex_id v) const
  {
    for(Tet_id t : cells_of(u))
      if(slot_of(t, v, 3) >= 0) return true;
    return false;
  }
  bool has_cell(Vertex_id u, Vertex_id v, Vertex_id w, Vertex_id x) const
  {
    for(Tet_id t : cells_of(u))
      if(slot_of(t, v, 3) >= 0 && slot_of(t, w, 3) >= 0 && slot_of(t, x, 3) >= 0) return true;
    return false;
  }

  // j < 0: a facet flip.  CGAL's preconditions; a handle of another
  // triangulation or a bad index would write outside the arrays, so it throws.
  void check_flip(Cell_handle c, int i, int j) const
  {
    CGAL_precondition(dimension() == 3 && number_of_vertices() >= 6);
    if(!is_cell(c) || i < 0 || i > 3 || j > 3 || j == i)
      throw std::invalid_argument("Fast_Delaunay_triangulation_3::tds().flip: not a cell of this triangulation "
                                  "or not a facet or edge of it");
  }

  // The new cells of a flip are written; the incident-cell cache, the infos
  // and the sub-determinants follow them.
  void flipped(const std::vector<Tet_id>& made)
  {
    Flat_storage& m = mesh();
    if(m.with_sub_determinants)
      for(Tet_id t : made) update_sub_determinants(m, t);
    anchor_->cells_made(made);
  }
  // c = (p, f...) with p in slot i, n its neighbour across facet i with
  // opposite vertex q.  New cell C_k (k != i) is c with f_k replaced by q,
  // in c's, n's and a new slot, in that order.
  void flip_2_3(Tet_id c, int i)
  {
    Flat_storage& m = mesh();
    Tet_id n = m.neighbor(c, i);
    int in = facet_of(m.neighbor_code(c, i));
    if(m.vertex(n, in) == ghost_vertex) { // start from the cell whose opposite vertex is the ghost
      std::swap(c, n);
      std::swap(i, in);
    }
    const Vertex_id q = m.vertex(n, in);
    const Tet_id region[2] = {c, n};
    std::array<Vertex_id, 4> made[3];
    for(int k = 0, count = 0; k < 4; ++k) {
      if(k == i) continue;
      for(int s = 0; s < 4; ++s) made[count][s] = m.vertex(c, s);
      made[count++][k] = q;
    }
    Tet_id slots[3];
    Replacement_scratch scratch;
    replace_tetrahedra(m, region, 2, made, 3, slots, scratch);
    flipped({slots[0], slots[1], slots[2]});
  }

  // The three cells around edge (a, b) = (v_i, v_j) of cells[0]; k and l are
  // the other slots of cells[0] (x = v_k, y = v_l); cells[1] is the
  // neighbour across facet l (it has z = the vertex in slot far[1]),
  // cells[2] the one across facet k.
  struct Ring
  {
    Tet_id cells[3];
    int i, j, k, l;
    int far[3];
  };
  bool ring_of_degree_3(Tet_id c, int i, int j, Ring& ring) const
  {
    const Flat_storage& m = mesh();
    for(int turn = 0; turn < 3; ++turn) {
      Ring r;
      r.cells[0] = c;
      r.i = i;
      r.j = j;
      r.k = -1;
      for(int s = 0; s < 4; ++s)
        if(s != i && s != j) (r.k < 0 ? r.k : r.l) = s;
      r.cells[1] = m.neighbor(c, r.l); // {a, b, x, z}
      r.cells[2] = m.neighbor(c, r.k); // {a, b, y, z}
      if(r.cells[1] == r.cells[2] || r.cells[1] == c) return false;
      const Vertex_id a = m.vertex(c, i), b = m.vertex(c, j), x = m.vertex(c, r.k);
      r.far[1] = facet_of(m.neighbor_code(c, r.l));
      const Vertex_id z = m.vertex(r.cells[1], r.far[1]);
      // Degree 3: cells[1] and cells[2] share the facet {a, b, z}.
      const int x_in_1 = slot_of(r.cells[1], x, 3);
      if(x_in_1 < 0 || m.neighbor(r.cells[1], x_in_1) != r.cells[2]) return false;
      if(slot_of(r.cells[2], a, 3) < 0 || slot_of(r.cells[2], b, 3) < 0 || slot_of(r.cells[2], z, 3) < 0)
        return false;
      if(z != ghost_vertex) {
        ring = r;
        return true;
      }
      // The ghost must stay in slot 3: start from cells[1], which has it there.
      const Tet_id next = r.cells[1];
      i = slot_of(next, a, 3);
      j = slot_of(next, b, 3);
      c = next;
    }
    return false;
  }
  // A = cells[0] with b replaced by z, B = cells[0] with a replaced by z
  // (both keep its orientation), in the slots of cells[0] and cells[1].
  void flip_3_2(const Ring& r)
  {
    Flat_storage& m = mesh();
    const Vertex_id z = m.vertex(r.cells[1], r.far[1]);
    std::array<Vertex_id, 4> made[2];
    for(int s = 0; s < 4; ++s) made[0][s] = made[1][s] = m.vertex(r.cells[0], s);
    made[0][r.j] = z;
    made[1][r.i] = z;
    Tet_id slots[2];
    Replacement_scratch scratch;
    replace_tetrahedra(m, r.cells, 3, made, 2, slots, scratch);
    flipped({slots[0], slots[1]});
  }

  bool valid_3(std::string& why) const
  {
    const Flat_storage& m = mesh();
    auto fail = [&why](const std::string& message) {
      why = message;
      return false;
    };
    std::size_t live = 0, ghosts = 0;
    std::vector<char> used(m.vertices.size(), 0);
    bool ghost_used = false;
    for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t)) continue;
      ++live;
      const std::string at = "cell " + std::to_string(t) + ": ";
      const Vertex_id* v = m.vertex_ids(t);
      for(int i = 0; i < 4; ++i) {
        if(v[i] == ghost_vertex) {
          if(i != 3) return fail(at + "infinite vertex not in slot 3");
          ghost_used = true;
          continue;
        }
        if(v[i] >= m.vertices.size() || m.is_dead(v[i])) return fail(at + "not a live vertex in slot " + std::to_string(i));
        used[v[i]] = 1;
        for(int j = 0; j < i; ++j)
          if(v[j] == v[i]) return fail(at + "repeated vertex");
      }
      ghosts += m.is_ghost(t);
      for(int i = 0; i < 4; ++i) {
        const Facet_code code = m.neighbor_code(t, i);
        const Tet_id u = tet_of(code);
        if(u >= m.number_of_slots() || !m.is_live(u) || u == t) return fail(at + "neighbour is not another live cell");
        if(m.neighbor_code(code) != facet_code(t, i)) return fail(at + "asymmetric adjacency");
        // The same facet, seen with the opposite orientation: t with v_i
        // replaced by the far vertex is an odd permutation of u.
        Vertex_id mirrored[4];
        std::copy(v, v + 4, mirrored);
        mirrored[i] = m.vertex(u, facet_of(code));
        int parity = 0;
        for(int s = 0; s < 4; ++s) {
          const int at_u = slot_of(u, mirrored[s], 3);
          if(at_u < 0 || (s != i && at_u == facet_of(code))) return fail(at + "neighbours do not share the facet");
          for(int r = 0; r < s; ++r)
            if(slot_of(u, mirrored[r], 3) > at_u) parity ^= 1;
        }
        if(parity == 0) return fail(at + "neighbour across facet " + std::to_string(i) + " not consistently oriented");
      }
    }
    if(live != m.live_tets || ghosts != m.ghost_tets) return fail("cell counts out of date");
    if(!ghost_used) return fail("the infinite vertex is in no cell");
    for(Vertex_id v = 0; v < used.size(); ++v) {
      if(m.is_dead(v)) continue;
      if(!used[v]) return fail("vertex " + std::to_string(v) + " is in no cell");
    }
    for(Vertex_id v : created_)
      if(v >= used.size() || used[v]) return fail("created vertex " + std::to_string(v) + " is in a cell");
    const std::ptrdiff_t euler = std::ptrdiff_t(number_of_vertices()) - std::ptrdiff_t(number_of_edges()) +
                                 std::ptrdiff_t(number_of_facets()) - std::ptrdiff_t(number_of_cells());
    if(euler != 0) return fail("V - E + F - C = " + std::to_string(euler) + " instead of 0");
    return true;
  }

  Anchor* anchor_;
  std::vector<Vertex_id> created_; // made by create_vertex(), in no cell yet
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_FLAT_TDS_H
