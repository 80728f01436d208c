// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Triangulations of dimension 0, 1 and 2 (one point, collinear points,
// coplanar points) in the flat arrays, with the cells CGAL's
// Delaunay_triangulation_3 has there.  The paper's engine is 3D only; these
// inputs are a corner case, so their triangulation is delegated to CGAL
// (whose 2D Delaunay triangulation under symbolic perturbation is unique) and
// its cells are copied into Tet_records, slot for slot and neighbour for
// neighbour, so handles and iterators read them like tetrahedra:
//
//   dimension 0:  2 cells (v) and (infinite), neighbours of each other;
//   dimension 1:  segments (v0, v1); neighbour i is opposite vertex i; the
//                 n - 1 finite segments and 2 infinite ones form a cycle in
//                 which neighbor(0)->vertex(0) == vertex(1);
//   dimension 2:  triangles (v0, v1, v2), consistently oriented (the shared
//                 edge runs the other way in the neighbour), finite ones and
//                 one infinite triangle per hull edge: 2n - 2 in all.
//
// Slots above the dimension hold `no_vertex` and a neighbour code pointing
// back at the cell itself (never followed: handles answer null there).  The
// infinite vertex may sit in any slot of a lower-dimensional cell, as in
// CGAL, so Flat_storage::is_ghost (slot 3) is meaningless below dimension 3;
// `ghost_tets` still counts the cells that have it.  Nothing here runs in
// dimension 3: lifting to 3D rebuilds the arrays from scratch
// (Triangulation_core::build_or_stay_low_dimensional).

#ifndef CGAL_FDT3_INTERNAL_LOWER_DIMENSIONS_H
#define CGAL_FDT3_INTERNAL_LOWER_DIMENSIONS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Triangulation_cell_base_with_info_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

namespace lower_dimensions_detail {
typedef Exact_predicates_inexact_constructions_kernel Epick;
// Vertex info: our vertex id; cell info: the slot the cell is copied to.
typedef Triangulation_vertex_base_with_info_3<Vertex_id, Epick> Vb;
typedef Triangulation_cell_base_with_info_3<Tet_id, Epick, Delaunay_triangulation_cell_base_3<Epick>> Cb;
typedef Delaunay_triangulation_3<Epick, Triangulation_data_structure_3<Vb, Cb>> Reference_delaunay;

inline bool has_vertex(const Tet_record& r, int dimension, Vertex_id v)
{
  return std::find(r.v, r.v + dimension + 1, v) != r.v + dimension + 1;
}
} // namespace lower_dimensions_detail

// Replaces the cells of `mesh` by the triangulation of its vertices, which
// are distinct and span exactly `dimension` (0, 1 or 2).
inline void build_lower_dimensional_cells(Flat_storage& mesh, int dimension)
{
  using namespace lower_dimensions_detail;
  CGAL_precondition(dimension >= 0 && dimension <= 2);
  std::vector<std::pair<Epick::Point_3, Vertex_id>> points;
  points.reserve(mesh.vertices.size());
  for(Vertex_id v = 0; v < mesh.vertices.size(); ++v) {
    const double* p = mesh.point(v);
    points.emplace_back(Epick::Point_3(p[0], p[1], p[2]), v);
  }
  Reference_delaunay reference(points.begin(), points.end());
  CGAL_assertion(reference.dimension() == dimension && reference.number_of_vertices() == points.size());
  reference.infinite_vertex()->info() = ghost_vertex;

  auto& tds = reference.tds();
  Tet_id count = 0;
  for(auto c = tds.raw_cells_begin(); c != tds.raw_cells_end(); ++c) c->info() = count++;

  mesh.free_tets.clear();
  mesh.tets.clear();
  mesh.tet_sub_determinants.clear();
  mesh.resize_tets(count);
  mesh.live_tets = count;
  mesh.ghost_tets = 0;
  for(auto c = tds.raw_cells_begin(); c != tds.raw_cells_end(); ++c) {
    const Tet_id t = c->info();
    Tet_record& r = mesh.tets[t];
    for(int i = 0; i < 4; ++i) {
      if(i > dimension) {
        r.v[i] = no_vertex;
        r.n[i] = facet_code(t, i);
        continue;
      }
      r.v[i] = c->vertex(i)->info();
      const auto n = c->neighbor(i);
      r.n[i] = facet_code(n->info(), n->index(c));
    }
    if(has_vertex(r, dimension, ghost_vertex)) ++mesh.ghost_tets;
  }
}

// Checks the cells of a triangulation of dimension -1 to 2: CGAL's
// combinatorial conventions (counts, adjacency, orientation of neighbours,
// connectivity) and, exactly, the geometry: collinear vertices in order along
// the line; coplanar vertices, consistently oriented non-degenerate finite
// triangles, a locally convex hull and the perturbed local Delaunay property.
inline bool lower_dimensional_cells_are_valid(const Flat_storage& m, int dimension, std::string* why)
{
  using namespace lower_dimensions_detail;
  auto fail = [why](const std::string& message) {
    if(why) *why = message;
    return false;
  };
  const std::size_t n = m.vertices.size();
  if(dimension == -1) return n == 0 && m.live_tets == 0 ? true : fail("vertices or cells in dimension -1");
  const std::size_t expected_cells = dimension == 0 ? 2 : dimension == 1 ? n + 1 : 2 * n - 2;
  if(m.live_tets != expected_cells) return fail("wrong number of cells for dimension " + std::to_string(dimension));

  std::size_t live = 0, ghosts = 0;
  std::vector<char> used(n, 0);
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t)) continue;
    ++live;
    const Tet_record& r = m.tets[t];
    const std::string at = "cell " + std::to_string(t) + ": ";
    for(int i = 0; i < 4; ++i) {
      const Vertex_id v = r.v[i];
      if(i > dimension) {
        if(v != no_vertex) return fail(at + "vertex slot above the dimension is used");
        continue;
      }
      if(v != ghost_vertex && v >= n) return fail(at + "vertex id out of range");
      if(v != ghost_vertex) used[v] = 1;
      for(int j = 0; j < i; ++j)
        if(r.v[j] == v) return fail(at + "repeated vertex");
    }
    if(has_vertex(r, dimension, ghost_vertex)) ++ghosts;
    for(int i = 0; i <= dimension; ++i) {
      const Facet_code code = r.n[i];
      const Tet_id u = tet_of(code);
      const int j = facet_of(code);
      if(u >= m.number_of_slots() || !m.is_live(u) || j > dimension)
        return fail(at + "neighbour is not a live cell");
      if(m.neighbor_code(code) != facet_code(t, i)) return fail(at + "asymmetric adjacency");
      for(int k = 0; k <= dimension; ++k)
        if(k != i && !has_vertex(m.tets[u], dimension, r.v[k])) return fail(at + "neighbours do not share a face");
      // CGAL's orientation of neighbours (Triangulation_data_structure_3::is_valid).
      if(dimension == 1 && j != 1 - i) return fail(at + "segments not chained head to tail");
      if(dimension == 2 && r.v[(i + 1) % 3] != m.vertex(u, (j + 2) % 3))
        return fail(at + "neighbouring triangles not consistently oriented");
    }
  }
  if(live != m.live_tets || ghosts != m.ghost_tets) return fail("cell counts out of date");
  for(std::size_t v = 0; v < n; ++v)
    if(!used[v]) return fail("vertex " + std::to_string(v) + " is in no cell");

  // One connected cycle / sphere.
  std::vector<char> reached(m.number_of_slots(), 0);
  std::vector<Tet_id> stack(1, m.first_live_tet());
  reached[stack[0]] = 1;
  std::size_t reached_count = 1;
  while(!stack.empty()) {
    const Tet_id t = stack.back();
    stack.pop_back();
    for(int i = 0; i <= dimension; ++i) {
      const Tet_id u = m.neighbor(t, i);
      if(!reached[u]) { reached[u] = 1; ++reached_count; stack.push_back(u); }
    }
  }
  if(reached_count != live) return fail("cells are not connected");

  const Epick k;
  auto point = [&m, &k](Vertex_id v) {
    const double* p = m.point(v);
    return Epick::Point_3(p[0], p[1], p[2]);
  };
  if(dimension == 0) return ghosts == 1 ? true : fail("dimension 0 needs one infinite cell");
  if(dimension == 1) {
    if(ghosts != 2) return fail("dimension 1 needs two infinite segments");
    for(Vertex_id v = 2; v < n; ++v)
      if(!k.collinear_3_object()(point(0), point(1), point(v))) return fail("vertices of dimension 1 not collinear");
    for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t)) continue;
      const Vertex_id a = m.vertex(t, 0), b = m.vertex(t, 1), c = m.vertex(m.neighbor(t, 0), 1);
      if(a == ghost_vertex || b == ghost_vertex || c == ghost_vertex) continue;
      if(!k.collinear_are_strictly_ordered_along_line_3_object()(point(a), point(b), point(c)))
        return fail("segments " + std::to_string(t) + " and its neighbour overlap");
    }
    return true;
  }

  // Dimension 2: the orientation of the first finite triangle is the reference.
  Tet_id first = 0;
  while(!m.is_live(first) || has_vertex(m.tets[first], 2, ghost_vertex)) ++first;
  const double* ref[3] = {m.point(m.vertex(first, 0)), m.point(m.vertex(first, 1)), m.point(m.vertex(first, 2))};
  const int reference_orientation = predicates_detail::coplanar_orientation_exact(ref[0], ref[1], ref[2]);
  if(reference_orientation == 0) return fail("flat finite triangle");
  for(Vertex_id v = 0; v < n; ++v)
    if(orientation(ref[0], ref[1], ref[2], m.point(v)) != 0) return fail("vertices of dimension 2 not coplanar");
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t)) continue;
    const std::string at = "triangle " + std::to_string(t) + ": ";
    const Tet_record& r = m.tets[t];
    const int g = static_cast<int>(std::find(r.v, r.v + 3, ghost_vertex) - r.v);
    if(g < 3) {
      // Hull edge (a, b); w beyond it inside, r the next hull vertex after b.
      const Vertex_id a = r.v[(g + 1) % 3], b = r.v[(g + 2) % 3];
      const Facet_code inside = r.n[g];
      const Vertex_id w = m.vertex(tet_of(inside), facet_of(inside));
      const Facet_code next = r.n[(g + 1) % 3];
      const Vertex_id after = m.vertex(tet_of(next), facet_of(next));
      if(w == ghost_vertex || after == ghost_vertex) return fail(at + "infinite triangle next to an infinite edge");
      if(predicates_detail::coplanar_orientation_exact(m.point(a), m.point(b), m.point(w), m.point(after)) < 0)
        return fail(at + "hull not convex");
      continue;
    }
    const double* p[3] = {m.point(r.v[0]), m.point(r.v[1]), m.point(r.v[2])};
    if(predicates_detail::coplanar_orientation_exact(p[0], p[1], p[2]) != reference_orientation)
      return fail(at + "not oriented as the other finite triangles");
    for(int i = 0; i < 3; ++i) {
      const Vertex_id opposite = m.vertex(tet_of(r.n[i]), facet_of(r.n[i]));
      if(opposite == ghost_vertex) continue;
      if(perturbed_coplanar_side_of_bounded_circle(p[0], p[1], p[2], m.point(opposite)) > 0)
        return fail(at + "not locally Delaunay across edge " + std::to_string(i));
    }
  }
  return true;
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_LOWER_DIMENSIONS_H
