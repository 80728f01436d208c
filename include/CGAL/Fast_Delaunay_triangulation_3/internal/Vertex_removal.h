// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Removal of one vertex v in dimension 3, on the flat arrays.  The star of v
// (every tetrahedron that has v, ghosts included when v is on the hull) is
// the hole; its boundary facets are those opposite v.  Every tetrahedron of
// the Delaunay triangulation of the remaining points that lies in the hole
// has an empty (perturbed) circumsphere, so it is also a tetrahedron of the
// Delaunay triangulation of the link (the hole's finite vertices), and the
// boundary facets are facets of that small triangulation.  The triangulation
// with CGAL's symbolic perturbation is unique (the perturbation ranks points
// by their lexicographic order, not by ids), so the small triangulation,
// built by the same kernel and predicates as the big one, holds exactly the
// cells that fill the hole:
//
//   1. carve_hole: the star, the link, and each boundary facet with the
//      neighbour outside the hole and its vertices oriented as seen from v;
//   2. Link_triangulation: the Delaunay triangulation of the link's points,
//      in arrays kept from one removal to the next;
//   3. fill_hole_with_link_cells: each boundary facet is found in the small
//      triangulation, oriented the same way, which picks the small cell on
//      v's side; a flood from those cells across the facets that are not
//      boundary facets collects the cells of the hole, copied into the freed
//      slots and glued to the outside neighbours.  The small ghost is our
//      ghost: the copied ghost tetrahedra keep it in slot 3, the small ones
//      being oriented as ours.
//
// One case has no 3D small triangulation: v on the hull whose finite link
// vertices are coplanar (a pyramid's apex).  All remaining points are then
// on the far side of that plane, so the finite boundary facets become hull
// facets: fill_flat_hole puts a ghost tetrahedron on each.  If besides every
// finite tetrahedron has v, the remaining points are coplanar and the caller
// drops to dimension 2.

#ifndef CGAL_FDT3_INTERNAL_VERTEX_REMOVAL_H
#define CGAL_FDT3_INTERNAL_VERTEX_REMOVAL_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Adjacency_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Three vertex ids of a facet in the cyclic order of their orientation,
// rotated so that the smallest comes first: two tetrahedra on the same side
// of a facet give the same key, the tetrahedron on the other side the
// reversed one.
typedef std::array<Vertex_id, 3> Oriented_facet_key;

inline Oriented_facet_key oriented_facet_key(Vertex_id a, Vertex_id b, Vertex_id c)
{
  if(b < a && b < c) return {{b, c, a}};
  if(c < a && c < b) return {{c, a, b}};
  return {{a, b, c}};
}

// Facet f of t with its vertices in the order of facet_vertex[f], which
// faces away from t (orientation(facet, t's vertex f) < 0).
inline Oriented_facet_key oriented_facet_key(const Flat_storage& m, Tet_id t, int f)
{
  return oriented_facet_key(m.vertex(t, facet_vertex[f][0]), m.vertex(t, facet_vertex[f][1]),
                            m.vertex(t, facet_vertex[f][2]));
}

// The hole of a removed vertex v.  Its vertices are named by link ids: k for
// link[k], link.size() for `inner` (a moved v's new place, if any, inside the
// hole), and ghost_vertex for the ghost (larger than every link id).
struct Removal_hole
{
  struct Boundary_facet
  {
    Oriented_facet_key key; // link ids, as seen from the hole (facing away from v)
    Facet_code outside;     // the facet of the tetrahedron beyond it
  };
  std::vector<Tet_id> star;
  std::vector<Vertex_id> link;      // finite vertices of the star but v
  std::vector<Boundary_facet> boundary;
  std::size_t finite_star = 0;      // tetrahedra of the star without the ghost
  Vertex_id inner = ghost_vertex;   // a vertex inside the hole, or ghost_vertex
  Id_set seen;                      // cells_around_vertex's, kept from one hole to the next

  Vertex_id global_id(Vertex_id link_id) const
  {
    return link_id == ghost_vertex ? ghost_vertex : link_id == link.size() ? inner : link[link_id];
  }
};

// Numbers vertices in the order they are met (their link ids), appending
// them to `link`: the scratch word of each holds its link id + 1 meanwhile
// (0 at rest, as the kernel requires), 0 again after finish().
struct Link_numbering
{
  Flat_storage& m;
  std::vector<Vertex_id>& link;

  Vertex_id operator()(Vertex_id w)
  {
    if(w == ghost_vertex) return ghost_vertex;
    auto& number = m.vertices[w].scratch;
    if(number == 0) {
      link.push_back(w);
      number = static_cast<Vertex_id>(link.size());
    }
    return static_cast<Vertex_id>(number - 1);
  }
  void finish()
  {
    for(Vertex_id w : link) m.vertices[w].scratch = 0;
  }
};

// The link and the boundary facets of v's star, hole.star being the cells
// of v (cells_around_vertex).
inline void carve_found_star(Flat_storage& m, Vertex_id v, Removal_hole& hole)
{
  hole.link.clear();
  hole.boundary.clear();
  hole.finite_star = 0;
  hole.inner = ghost_vertex;
  Link_numbering link_id{m, hole.link};
  // Every vertex of the link is on the facet opposite v of a tetrahedron of
  // the star.
  for(Tet_id t : hole.star) {
    if(!m.is_ghost(t)) ++hole.finite_star;
    const int i = index_of(m, t, v);
    const Vertex_id a = link_id(m.vertex(t, facet_vertex[i][0]));
    const Vertex_id b = link_id(m.vertex(t, facet_vertex[i][1]));
    const Vertex_id c = link_id(m.vertex(t, facet_vertex[i][2]));
    hole.boundary.push_back({oriented_facet_key(a, b, c), m.neighbor_code(t, i)});
    // The cells beyond the star are read later (their neighbour codes are
    // rewritten; a move tests them): their loads overlap from here on.
    __builtin_prefetch(m.vertex_ids(m.neighbor(t, i)));
  }
  link_id.finish();
}

// The star of v (start has v), its link and its boundary facets.
inline void carve_hole(Flat_storage& m, Vertex_id v, Tet_id start, Removal_hole& hole)
{
  cells_around_vertex(m, start, v, hole.star, hole.seen);
  carve_found_star(m, v, hole);
}

// Where a removal's cells come from and go: the arrays' own free list and
// counts (one removal at a time), or a partition's pool while several
// removals run at once (Parallel_removal.h), which must not touch what the
// others share.
struct Shared_slots
{
  Flat_storage& m;

  void release(Tet_id t)
  {
    if(m.is_ghost(t)) --m.ghost_tets;
    --m.live_tets;
    m.free_tet(t);
  }
  Tet_id take() { return m.new_tet(); }
  void count_in(Tet_id t)
  {
    ++m.live_tets;
    if(m.is_ghost(t)) ++m.ghost_tets;
    if(m.with_sub_determinants) update_sub_determinants(m, t);
  }
};

// The Delaunay triangulation of the link's points (its vertex k is link[k]),
// by the same kernel and predicates as the big one, in arrays kept from one
// removal to the next: a removal re-triangulates some fifteen points, for
// which the general insertion path's sort, buffers and lower-dimensional
// start cost more than the insertions themselves.
class Link_triangulation
{
public:
  Link_triangulation() { small_.with_sub_determinants = false; }

  // False, with nothing built, if the points are coplanar (exact).  `inner`,
  // if not null, is one more point (vertex link.size()), inside the hole.
  bool build(const Flat_storage& m, const std::vector<Vertex_id>& link, const double* inner = nullptr)
  {
    small_.clear();
    const std::size_t n = link.size() + (inner != nullptr);
    if(n < 4) return false;
    small_.vertices.resize(n);
    double lo[3], hi[3];
    for(int a = 0; a < 3; ++a) {
      lo[a] = std::numeric_limits<double>::infinity();
      hi[a] = -lo[a];
    }
    for(std::size_t k = 0; k < n; ++k) {
      Vertex_record& r = small_.vertices[k];
      const double* q = k < link.size() ? m.point(link[k]) : inner;
      for(int a = 0; a < 3; ++a) {
        r.xyz[a] = q[a];
        lo[a] = std::min(lo[a], q[a]);
        hi[a] = std::max(hi[a], q[a]);
      }
      r.scratch = 0;
    }
    Vertex_id simplex[4];
    if(!find_simplex(simplex)) return false;
    make_initial_tetrahedron(small_, simplex);
    Delaunay_kernel<> kernel(small_, scratch_, Mesh_slots{&small_}, Static_filter::for_box(lo, hi));
    Tet_id hint = 0;
    for(Vertex_id k = 0; k < n; ++k) {
      if(std::find(simplex, simplex + 4, k) != simplex + 4) continue;
      Vertex_id existing = ghost_vertex;
      const Insertion_result inserted = kernel.insert(k, hint, existing);
      CGAL_assertion(inserted == Insertion_result::inserted); // the link's points are distinct
      (void)inserted;
    }
    small_.live_tets += scratch_.live_delta;
    small_.ghost_tets += scratch_.ghost_delta;
    scratch_.live_delta = scratch_.ghost_delta = 0;
    scratch_.stats = Kernel_statistics();
    return true;
  }

  const Flat_storage& mesh() const { return small_; }

private:
  // Four points spanning 3D, the first two being 0 and 1; false if there are
  // none, that is if all are coplanar.
  bool find_simplex(Vertex_id simplex[4]) const
  {
    const Vertex_id n = static_cast<Vertex_id>(small_.vertices.size());
    for(Vertex_id c = 2; c < n; ++c)
      for(Vertex_id d = 2; d < n; ++d)
        if(d != c && orientation(small_.point(0), small_.point(1), small_.point(c), small_.point(d)) != 0) {
          simplex[0] = 0;
          simplex[1] = 1;
          simplex[2] = c;
          simplex[3] = d;
          return true;
        }
    return false;
  }

  Flat_storage small_;
  Insertion_scratch scratch_;
};

// The buffers of fill_hole_with_link_cells, kept from one removal to the next.
struct Hole_filling_buffers
{
  std::vector<std::uint32_t> bucket_start;            // boundary facets by their first link id
  std::vector<std::array<Vertex_id, 3>> second_third; // their other two link ids and their index
  std::vector<Tet_id> inside;                          // small cells in the hole
  std::vector<std::array<int, 4>> boundary_of;         // per inside cell, per facet: boundary index or -1
  std::vector<char> reached;                           // per small slot
  std::vector<Tet_id> slot_of;                         // per small slot: its new tetrahedron
};

// Fills the hole with the cells of `small` (the link's triangulation) on v's
// side of the boundary.  Writes the new slots to new_cells.  Returns false,
// changing nothing, if a boundary facet is not in `small` (which the
// uniqueness of the perturbed triangulation rules out).
//
// The cells in the hole are found by a flood from one cell with a boundary
// facet, across the facets that are not boundary facets: each facet of a
// cell in the hole is looked up once among the boundary facets of its first
// vertex (two on average), and the cells outside the hole are not looked at.
//
// find_hole_cells finds them (b.inside), write_hole_cells writes them: a
// caller that must know how many slots it will take looks in between.
inline bool find_hole_cells(const Removal_hole& hole, const Flat_storage& small, Hole_filling_buffers& b)
{
  const std::size_t link_size = hole.link.size() + (hole.inner != ghost_vertex);
  b.bucket_start.assign(link_size + 1, 0);
  for(const Removal_hole::Boundary_facet& f : hole.boundary) ++b.bucket_start[f.key[0] + 1];
  for(std::size_t i = 1; i <= link_size; ++i) b.bucket_start[i] += b.bucket_start[i - 1];
  b.second_third.resize(hole.boundary.size());
  for(std::size_t k = 0; k < hole.boundary.size(); ++k) {
    const Oriented_facet_key& key = hole.boundary[k].key;
    b.second_third[b.bucket_start[key[0]]++] = {{key[1], key[2], static_cast<Vertex_id>(k)}};
  }
  // The loop above moved each start to the next bucket's: shift them back.
  for(std::size_t i = link_size; i > 0; --i) b.bucket_start[i] = b.bucket_start[i - 1];
  b.bucket_start[0] = 0;
  // The boundary facet that facet f of small cell s is, or -1.
  auto boundary_index = [&](Tet_id s, int f) {
    const Oriented_facet_key key = oriented_facet_key(small, s, f);
    for(std::uint32_t r = b.bucket_start[key[0]]; r < b.bucket_start[key[0] + 1]; ++r)
      if(b.second_third[r][0] == key[1] && b.second_third[r][1] == key[2]) return static_cast<int>(b.second_third[r][2]);
    return -1;
  };

  b.inside.clear();
  b.boundary_of.clear();
  b.reached.assign(small.number_of_slots(), 0);
  for(Tet_id s = 0; s < small.number_of_slots() && b.inside.empty(); ++s) {
    if(!small.is_live(s)) continue;
    for(int f = 0; f < 4; ++f)
      if(boundary_index(s, f) >= 0) {
        b.inside.push_back(s);
        b.reached[s] = 1;
        break;
      }
  }
  std::size_t found = 0;
  for(std::size_t k = 0; k < b.inside.size(); ++k) {
    const Tet_id s = b.inside[k];
    std::array<int, 4> across;
    for(int f = 0; f < 4; ++f) {
      across[f] = boundary_index(s, f);
      if(across[f] >= 0) {
        ++found;
        continue;
      }
      const Tet_id u = small.neighbor(s, f);
      if(!b.reached[u]) {
        b.reached[u] = 1;
        b.inside.push_back(u);
      }
    }
    b.boundary_of.push_back(across);
  }
  return found == hole.boundary.size();
}

template <class Slots>
void write_hole_cells(Flat_storage& m, const Removal_hole& hole, const Flat_storage& small,
                      Hole_filling_buffers& b, std::vector<Tet_id>& new_cells, Slots&& slots)
{
  for(Tet_id t : hole.star) slots.release(t);
  b.slot_of.resize(small.number_of_slots());
  new_cells.clear();
  for(Tet_id s : b.inside) {
    b.slot_of[s] = slots.take();
    new_cells.push_back(b.slot_of[s]);
  }
  for(std::size_t k = 0; k < b.inside.size(); ++k) {
    const Tet_id s = b.inside[k], t = b.slot_of[s];
    for(int i = 0; i < 4; ++i) {
      m.tets[t].v[i] = hole.global_id(small.vertex(s, i));
      const int f = b.boundary_of[k][i];
      if(f >= 0) {
        const Facet_code outside = hole.boundary[f].outside;
        m.tets[t].n[i] = outside;
        m.neighbor_code(outside) = facet_code(t, i);
      } else {
        const Facet_code across = small.neighbor_code(s, i);
        m.tets[t].n[i] = facet_code(b.slot_of[tet_of(across)], facet_of(across));
      }
    }
  }
  for(Tet_id t : new_cells) slots.count_in(t);
}

inline bool fill_hole_with_link_cells(Flat_storage& m, const Removal_hole& hole, const Flat_storage& small,
                                      Hole_filling_buffers& b, std::vector<Tet_id>& new_cells)
{
  if(!find_hole_cells(hole, small, b)) return false;
  write_hole_cells(m, hole, small, b, new_cells, Shared_slots{m});
  return true;
}

// v on the hull, finite link coplanar (see the top of this file): a ghost
// tetrahedron on each finite boundary facet, glued along the hull edges to
// each other and to the ghosts outside the hole.
inline void fill_flat_hole(Flat_storage& m, const Removal_hole& hole, std::vector<Tet_id>& new_cells)
{
  struct Edge_side
  {
    std::array<Vertex_id, 2> edge;
    Facet_code code; // a new ghost's facet, or the outside facet of a boundary ghost facet
    bool operator<(const Edge_side& other) const { return edge < other.edge; }
  };
  std::vector<Edge_side> sides;
  std::vector<const Removal_hole::Boundary_facet*> finite;
  for(const Removal_hole::Boundary_facet& b : hole.boundary) {
    const int g = static_cast<int>(std::find(b.key.begin(), b.key.end(), ghost_vertex) - b.key.begin());
    if(g < 3) {
      const Vertex_id a = hole.global_id(b.key[(g + 1) % 3]), c = hole.global_id(b.key[(g + 2) % 3]);
      sides.push_back({{{std::min(a, c), std::max(a, c)}}, b.outside});
    } else {
      finite.push_back(&b);
    }
  }
  Shared_slots slots{m};
  for(Tet_id t : hole.star) slots.release(t);
  new_cells.clear();
  for(const Removal_hole::Boundary_facet* b : finite) {
    const Tet_id t = slots.take();
    new_cells.push_back(t);
    // The key faces away from v, which is now beyond the hull: reversed, it
    // is the base of a ghost on v's side.
    Vertex_id* v = m.tets[t].v;
    v[0] = hole.global_id(b->key[0]);
    v[1] = hole.global_id(b->key[2]);
    v[2] = hole.global_id(b->key[1]);
    v[3] = ghost_vertex;
    m.tets[t].n[3] = b->outside;
    m.neighbor_code(b->outside) = facet_code(t, 3);
    for(int i = 0; i < 3; ++i) {
      const Vertex_id a = v[(i + 1) % 3], c = v[(i + 2) % 3];
      sides.push_back({{{std::min(a, c), std::max(a, c)}}, facet_code(t, i)});
    }
  }
  std::sort(sides.begin(), sides.end());
  CGAL_assertion(sides.size() % 2 == 0);
  for(std::size_t k = 0; k + 1 < sides.size(); k += 2) {
    CGAL_assertion(sides[k].edge == sides[k + 1].edge);
    m.neighbor_code(sides[k].code) = sides[k + 1].code;
    m.neighbor_code(sides[k + 1].code) = sides[k].code;
  }
  for(Tet_id t : new_cells) slots.count_in(t);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_VERTEX_REMOVAL_H
