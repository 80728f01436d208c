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
//   2. the caller triangulates the link's points (Triangulation_core);
//   3. fill_hole: each boundary facet is found in the small triangulation,
//      oriented the same way, which picks the small cell on v's side; a flood
//      from those cells across the facets that are not boundary facets
//      collects the cells of the hole, copied into the freed slots and glued
//      to the outside neighbours.  The small ghost is our ghost: the copied
//      ghost tetrahedra keep it in slot 3, the small ones being oriented as
//      ours.
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

struct Removal_hole
{
  struct Boundary_facet
  {
    Oriented_facet_key key; // as seen from the hole (facing away from v)
    Facet_code outside;     // the facet of the tetrahedron beyond it
  };
  std::vector<Tet_id> star;
  std::vector<Vertex_id> link;      // finite vertices of the star but v
  std::vector<Boundary_facet> boundary;
  std::size_t finite_star = 0;      // tetrahedra of the star without the ghost
};

// The star of v (start has v), its link and its boundary facets.
inline void carve_hole(const Flat_storage& m, Vertex_id v, Tet_id start, Removal_hole& hole)
{
  cells_around_vertex(m, start, v, hole.star);
  vertices_around_vertex(m, hole.star, v, hole.link, nullptr);
  hole.link.erase(std::remove(hole.link.begin(), hole.link.end(), ghost_vertex), hole.link.end());
  hole.boundary.clear();
  hole.finite_star = 0;
  for(Tet_id t : hole.star) {
    if(!m.is_ghost(t)) ++hole.finite_star;
    const int i = index_of(m, t, v);
    hole.boundary.push_back({oriented_facet_key(m, t, i), m.neighbor_code(t, i)});
  }
}

// Whether the link's vertices lie in one plane (exact).
inline bool link_is_coplanar(const Flat_storage& m, const Removal_hole& hole)
{
  const std::vector<Vertex_id>& l = hole.link;
  CGAL_precondition(l.size() >= 3);
  std::size_t third = 2;
  while(third < l.size() && collinear(m.point(l[0]), m.point(l[1]), m.point(l[third]))) ++third;
  if(third == l.size()) return true;
  for(std::size_t k = 2; k < l.size(); ++k)
    if(orientation(m.point(l[0]), m.point(l[1]), m.point(l[third]), m.point(l[k])) != 0) return false;
  return true;
}

namespace vertex_removal_detail {

// Frees the star's slots and counts them out.
inline void free_star(Flat_storage& m, const Removal_hole& hole)
{
  for(Tet_id t : hole.star) {
    if(m.is_ghost(t)) --m.ghost_tets;
    --m.live_tets;
    m.free_tet(t);
  }
}

inline void count_in(Flat_storage& m, Tet_id t)
{
  ++m.live_tets;
  if(m.is_ghost(t)) ++m.ghost_tets;
  if(m.with_sub_determinants) update_sub_determinants(m, t);
}

} // namespace vertex_removal_detail

// Fills the hole with the cells of `small` (a dimension-3 triangulation of
// the link's points: link[k] is its vertex small_of_link[k], and
// global_of_small the inverse) on v's side of the boundary.  Writes the new
// slots to new_cells.  Returns false, changing nothing, if a boundary facet
// is not in `small` (which the uniqueness of the perturbed triangulation
// rules out).
inline bool fill_hole(Flat_storage& m, const Removal_hole& hole, const Flat_storage& small,
                      const std::vector<Vertex_id>& small_of_link, const std::vector<Vertex_id>& global_of_small,
                      std::vector<Tet_id>& new_cells)
{
  // Boundary facets in the small ids (the ghost as `ghost`, larger than all),
  // bucketed by their first id: each small facet is compared with the few
  // of its bucket (a binary search over all of them mispredicted at every
  // step: a third of the removal's time).  The link vertices' scratch words
  // hold their small ids meanwhile; they are 0 again before returning.
  const Vertex_id ghost = static_cast<Vertex_id>(hole.link.size());
  for(std::size_t k = 0; k < hole.link.size(); ++k) m.vertices[hole.link[k]].scratch = small_of_link[k];
  auto small_id = [&](Vertex_id g) { return g == ghost_vertex ? ghost : static_cast<Vertex_id>(m.vertices[g].scratch); };
  struct Rest_of_key
  {
    Vertex_id second, third;
    int boundary;
  };
  std::vector<std::uint32_t> bucket(ghost + 2, 0);
  std::vector<Oriented_facet_key> keys(hole.boundary.size());
  for(std::size_t b = 0; b < hole.boundary.size(); ++b) {
    const Oriented_facet_key& g = hole.boundary[b].key;
    keys[b] = oriented_facet_key(small_id(g[0]), small_id(g[1]), small_id(g[2]));
    ++bucket[keys[b][0] + 1];
  }
  for(std::size_t k = 0; k < hole.link.size(); ++k) m.vertices[hole.link[k]].scratch = 0;
  for(std::size_t i = 1; i < bucket.size(); ++i) bucket[i] += bucket[i - 1];
  std::vector<Rest_of_key> rest(hole.boundary.size());
  {
    std::vector<std::uint32_t> next(bucket.begin(), bucket.end() - 1);
    for(std::size_t b = 0; b < keys.size(); ++b) rest[next[keys[b][0]]++] = {keys[b][1], keys[b][2], static_cast<int>(b)};
  }

  // boundary_of[code of a small facet]: the hole's boundary facet it is, or -1.
  std::vector<int> boundary_of(4 * small.number_of_slots(), -1);
  std::vector<Tet_id> inside; // small cells of the hole
  std::vector<char> reached(small.number_of_slots(), 0);
  std::size_t found = 0;
  for(Tet_id s = 0; s < small.number_of_slots(); ++s) {
    if(!small.is_live(s)) continue;
    for(int f = 0; f < 4; ++f) {
      Vertex_id v[3];
      for(int k = 0; k < 3; ++k) {
        const Vertex_id w = small.vertex(s, facet_vertex[f][k]);
        v[k] = w == ghost_vertex ? ghost : w;
      }
      const Oriented_facet_key key = oriented_facet_key(v[0], v[1], v[2]);
      for(std::uint32_t r = bucket[key[0]]; r < bucket[key[0] + 1]; ++r) {
        if(rest[r].second != key[1] || rest[r].third != key[2]) continue;
        boundary_of[facet_code(s, f)] = rest[r].boundary;
        ++found;
        if(!reached[s]) { reached[s] = 1; inside.push_back(s); }
        break;
      }
    }
  }
  if(found != hole.boundary.size()) return false;
  for(std::size_t k = 0; k < inside.size(); ++k)
    for(int f = 0; f < 4; ++f) {
      if(boundary_of[facet_code(inside[k], f)] >= 0) continue;
      const Tet_id u = small.neighbor(inside[k], f);
      if(!reached[u]) { reached[u] = 1; inside.push_back(u); }
    }

  vertex_removal_detail::free_star(m, hole);
  std::vector<Tet_id> slot_of(small.number_of_slots(), 0);
  new_cells.clear();
  for(Tet_id s : inside) {
    slot_of[s] = m.new_tet();
    new_cells.push_back(slot_of[s]);
  }
  for(Tet_id s : inside) {
    const Tet_id t = slot_of[s];
    for(int i = 0; i < 4; ++i) {
      const Vertex_id w = small.vertex(s, i);
      m.tets[t].v[i] = w == ghost_vertex ? ghost_vertex : global_of_small[w];
      const int b = boundary_of[facet_code(s, i)];
      if(b >= 0) {
        const Facet_code outside = hole.boundary[b].outside;
        m.tets[t].n[i] = outside;
        m.neighbor_code(outside) = facet_code(t, i);
      } else {
        const Facet_code across = small.neighbor_code(s, i);
        m.tets[t].n[i] = facet_code(slot_of[tet_of(across)], facet_of(across));
      }
    }
  }
  for(Tet_id t : new_cells) vertex_removal_detail::count_in(m, t);
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
      const Vertex_id a = b.key[(g + 1) % 3], c = b.key[(g + 2) % 3];
      sides.push_back({{{std::min(a, c), std::max(a, c)}}, b.outside});
    } else {
      finite.push_back(&b);
    }
  }
  vertex_removal_detail::free_star(m, hole);
  new_cells.clear();
  for(const Removal_hole::Boundary_facet* b : finite) {
    const Tet_id t = m.new_tet();
    new_cells.push_back(t);
    // The key faces away from v, which is now beyond the hull: reversed, it
    // is the base of a ghost on v's side.
    Vertex_id* v = m.tets[t].v;
    v[0] = b->key[0]; v[1] = b->key[2]; v[2] = b->key[1]; v[3] = ghost_vertex;
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
  for(Tet_id t : new_cells) vertex_removal_detail::count_in(m, t);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_VERTEX_REMOVAL_H
