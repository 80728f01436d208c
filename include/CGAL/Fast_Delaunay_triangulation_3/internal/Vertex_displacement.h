// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Whether the triangulation stays the Delaunay triangulation when one vertex
// v moves to p, in dimension 3, and nothing but v's point changes.  Only the
// star of v (its tetrahedra, ghosts included) changes shape, so it suffices
// that
//   - every finite tetrahedron of the star is positively oriented with p, and
//   - every facet of a tetrahedron of the star is locally Delaunay with p:
//     the vertex opposite it on the other side is not in conflict with the
//     tetrahedron on this side (its sphere, or for a ghost the half-space
//     beyond its hull facet), under CGAL's symbolic perturbation.
// A triangulation whose every facet is locally Delaunay is the Delaunay
// triangulation, and the perturbed one is unique: the star as it stands is
// then exactly what removing v and inserting p would build.  Both facets of
// the star's boundary (opposite v) and facets inside it (through v) are
// checked; CGAL 5.5's own test looks at the facets through v only.
//
// A move that passes costs a few dozen predicates instead of a removal and an
// insertion.  Most short moves do not pass, but p stays in the kernel of the
// star of v (every tetrahedron of v positive with p): moving 10% of 1e6
// uniform points by up to a tenth of the mean spacing, 94% of the moves.
// Inside the hull, Displacement_flips.h then restores the Delaunay property
// by flips (3.4 on average; none for the 12% of moves that keep the cells).
// Where the flips get stuck, add_conflicts_of_moved_point (below) makes the
// star and p's conflict zone one hole, which Vertex_removal.h fills from the
// triangulation of its vertices and p.

#ifndef CGAL_FDT3_INTERNAL_VERTEX_DISPLACEMENT_H
#define CGAL_FDT3_INTERNAL_VERTEX_DISPLACEMENT_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Adjacency_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_removal.h>

#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

namespace vertex_displacement_detail {

// The points of tetrahedron t with p in place of v's point.
struct Displaced_points
{
  const Flat_storage& m;
  Vertex_id v;
  const double* p;

  const double* operator()(Vertex_id w) const { return w == v ? p : m.point(w); }
};

// Whether x (finite) is in conflict with tetrahedron t, whose points are
// read through `at`: inside its sphere, or for a ghost beyond its hull facet.
inline bool in_conflict(const Flat_storage& m, Tet_id t, const double* x, const Displaced_points& at,
                        const Static_filter& filter)
{
  const Vertex_id* tv = m.vertex_ids(t);
  if(tv[3] == ghost_vertex) return ghost_cell_in_conflict(at(tv[0]), at(tv[1]), at(tv[2]), x, filter);
  return finite_cell_in_conflict(at(tv[0]), at(tv[1]), at(tv[2]), at(tv[3]), x);
}

} // namespace vertex_displacement_detail

// Whether every finite tetrahedron of `star` (every tetrahedron of v,
// cells_around_vertex) is positively oriented with p for v's point;
// on_hull: whether the star has a ghost.  Exact.  filter: valid for a box
// holding every point and p.
inline bool star_positive_with(const Flat_storage& m, Vertex_id v, const double* p, const std::vector<Tet_id>& star,
                               const Static_filter& filter, bool& on_hull)
{
  using namespace vertex_displacement_detail;
  const Displaced_points at{m, v, p};
  on_hull = false;
  for(Tet_id t : star) {
    const Vertex_id* tv = m.vertex_ids(t);
    if(tv[3] == ghost_vertex) on_hull = true;
    else if(orientation(filter, at(tv[0]), at(tv[1]), at(tv[2]), at(tv[3])) <= 0) return false;
  }
  return true;
}

// Whether every facet of a tetrahedron of `star` is locally Delaunay with p
// for v's point.  Exact.
inline bool star_locally_delaunay_with(const Flat_storage& m, Vertex_id v, const double* p,
                                       const std::vector<Tet_id>& star, const Static_filter& filter)
{
  using namespace vertex_displacement_detail;
  const Displaced_points at{m, v, p};
  // The far vertices beyond the star are met afresh: their loads overlap.
  for(Tet_id t : star) {
    const Facet_code beyond = m.neighbor_code(t, index_of(m, t, v));
    const Vertex_id y = m.vertex(tet_of(beyond), facet_of(beyond));
    if(y != ghost_vertex) __builtin_prefetch(m.point(y));
  }
  for(Tet_id t : star) {
    for(int i = 0; i < 4; ++i) {
      const Facet_code across = m.neighbor_code(t, i);
      const Tet_id u = tet_of(across);
      const Vertex_id x = m.vertex(t, i), y = m.vertex(u, facet_of(across));
      // A facet through v lies between two tetrahedra of the star: once.
      if(x != v && u < t) continue;
      // The finite one of x and y against the other side (a ghost's far
      // vertex is never in conflict with a finite sphere).
      if(y != ghost_vertex) {
        if(in_conflict(m, t, at(y), at, filter)) return false;
      } else if(in_conflict(m, u, at(x), at, filter)) {
        return false;
      }
    }
  }
  return true;
}

// The hole of a move of v to p in the kernel of the star of v (v not on the
// hull), carved as for a removal: the tetrahedra beyond the star whose
// spheres hold p go too, since the triangulation with p has none of them.
// They are found from the star's boundary across tetrahedra in conflict
// with p (the conflict zone of p is connected and meets the star, which
// holds p).  Every other tetrahedron has an empty sphere without v and
// with p, so it stays; the hole's link then gets every vertex of its
// tetrahedra but v, its boundary the facets towards the others.
inline void add_conflicts_of_moved_point(Flat_storage& m, Vertex_id v, const double* p, Removal_hole& hole,
                                         const Static_filter& filter)
{
  using namespace vertex_displacement_detail;
  const Displaced_points at{m, v, p}; // the cells tested do not have v
  Id_set in_conflict_with_p, tested;
  auto conflicts = [&](Tet_id u) {
    if(index_of(m, u, v) >= 0 || !tested.insert(u)) return false;
    const bool yes = in_conflict(m, u, p, at, filter);
    if(yes) in_conflict_with_p.insert(u);
    return yes;
  };
  const std::size_t star_size = hole.star.size();
  for(std::size_t k = 0; k < star_size; ++k) {
    const Tet_id u = tet_of(hole.boundary[k].outside);
    if(conflicts(u)) hole.star.push_back(u);
  }
  if(hole.star.size() == star_size) return;
  for(std::size_t k = star_size; k < hole.star.size(); ++k)
    for(int f = 0; f < 4; ++f) {
      const Tet_id u = m.neighbor(hole.star[k], f);
      if(conflicts(u)) hole.star.push_back(u);
    }
  hole.link.clear();
  hole.boundary.clear();
  Link_numbering link_id{m, hole.link};
  for(Tet_id t : hole.star) {
    Vertex_id id[4];
    for(int i = 0; i < 4; ++i) id[i] = m.vertex(t, i) == v ? v : link_id(m.vertex(t, i));
    for(int f = 0; f < 4; ++f) {
      const Tet_id u = m.neighbor(t, f);
      if(index_of(m, u, v) >= 0 || in_conflict_with_p.contains(u)) continue;
      hole.boundary.push_back(
          {oriented_facet_key(id[facet_vertex[f][0]], id[facet_vertex[f][1]], id[facet_vertex[f][2]]),
           m.neighbor_code(t, f)});
    }
  }
  link_id.finish();
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_VERTEX_DISPLACEMENT_H
