// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Hand-off to CGAL: builds a genuine CGAL::Triangulation_3 (a
// Delaunay_triangulation_3 with any data structure, sequential or
// Parallel_tag, or a Triangulation_3 with mesh bases such as
// Tetrahedral_remeshing::Remeshing_triangulation_3) from a
// Fast_Delaunay_triangulation_3, and a Mesh_complex_3_in_triangulation_3 on
// top of it.  For the CGAL algorithms that need CGAL's own type: Alpha_shape_3
// derives from the triangulation, Mesh_3 / tetrahedral remeshing take a C3T3.
//
// Linear time: the data structure's vertices and cells are created directly
// from the flat arrays, in the same order (vertex k of ours is the k-th finite
// vertex, cell slot t the t-th cell), with the infinite vertex where ours has
// the ghost vertex (slot 3); nothing is re-inserted.  Below dimension 3 ours
// stores no cells, so there the points are inserted into the target instead.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_CONVERT_TO_CGAL_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_CONVERT_TO_CGAL_H

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <map>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {

namespace Fast_Delaunay_triangulation_3_internal {

// The target's point (a Point_3, or a Weighted_point_3 of weight 0 for the
// regular triangulations of Mesh_3) from one of our points.
template <class Target_point, class Point>
Target_point to_target_point(const Point& p)
{
  typedef typename std::decay<decltype(p.x())>::type Coordinate;
  typedef typename std::decay<decltype(std::declval<const Target_point&>().x())>::type Target_coordinate;
  if constexpr(std::is_constructible<Target_point, const Point&>::value)
    return Target_point(p);
  else if constexpr(std::is_convertible<Coordinate, Target_coordinate>::value)
    return Target_point(p.x(), p.y(), p.z());
  else // e.g. EPEC to Epick: our coordinates are doubles exactly
    return Target_point(CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z()));
}

// The cells of the target, indexed by our cell slot (empty handle for a free
// slot), filled by copy_cells.
template <class Target>
using Cell_map = std::vector<typename Target::Cell_handle>;

template <class Source, class Target>
Cell_map<Target> copy_cells(const Source& source, Target& target)
{
  typedef typename Target::Vertex_handle Target_vertex;
  typedef typename Target::Cell_handle Target_cell;
  const Flat_storage& mesh = source.flat_storage();
  auto& tds = target.tds();

  target.clear();
  // clear() leaves the infinite vertex in a dimension -1 cell of its own.
  const Target_vertex infinite = target.infinite_vertex();
  tds.delete_cell(infinite->cell());

  std::vector<Target_vertex> vertex_of(mesh.vertices.size());
  for(std::size_t v = 0; v < vertex_of.size(); ++v) {
    if(mesh.is_dead(static_cast<Vertex_id>(v))) continue; // a removed vertex: in no cell
    vertex_of[v] = tds.create_vertex();
    vertex_of[v]->set_point(to_target_point<typename Target::Point>(source.point_of(static_cast<Vertex_id>(v))));
  }
  auto target_vertex = [&](Vertex_id v) { return v == ghost_vertex ? infinite : vertex_of[v]; };

  Cell_map<Target> cell_of(mesh.number_of_slots());
  for(Tet_id t = 0; t < mesh.number_of_slots(); ++t) {
    if(!mesh.is_live(t)) continue;
    const Target_cell c = tds.create_cell(target_vertex(mesh.vertex(t, 0)), target_vertex(mesh.vertex(t, 1)),
                                          target_vertex(mesh.vertex(t, 2)), target_vertex(mesh.vertex(t, 3)));
    cell_of[t] = c;
    for(int i = 0; i < 4; ++i) c->vertex(i)->set_cell(c);
  }
  // Each side of each facet is set once, from its own cell.
  for(Tet_id t = 0; t < mesh.number_of_slots(); ++t) {
    if(!mesh.is_live(t)) continue;
    for(int i = 0; i < 4; ++i) cell_of[t]->set_neighbor(i, cell_of[mesh.neighbor(t, i)]);
  }
  tds.set_dimension(3);
  return cell_of;
}

// Default surface patch of the facet between subdomains a and b (0 is
// outside): the pair (min, max) when the patch index type is made from a
// pair (CGAL's mesh domains), else 1, 2, 3, ... in the order pairs are met.
template <class Subdomain_index, class Surface_patch_index>
class Default_surface_patch
{
public:
  Surface_patch_index operator()(Subdomain_index a, Subdomain_index b)
  {
    const std::pair<Subdomain_index, Subdomain_index> key(std::min(a, b), std::max(a, b));
    if constexpr(std::is_constructible<Surface_patch_index, std::pair<Subdomain_index, Subdomain_index>>::value) {
      return Surface_patch_index(key);
    } else {
      auto found = numbers_.find(key);
      if(found == numbers_.end())
        found = numbers_.emplace(key, Surface_patch_index(static_cast<int>(numbers_.size()) + 1)).first;
      return found->second;
    }
  }

private:
  std::map<std::pair<Subdomain_index, Subdomain_index>, Surface_patch_index> numbers_;
};

} // namespace Fast_Delaunay_triangulation_3_internal

// Replaces `target` by a triangulation of the same points with exactly the
// same cells: same finite cells with their vertex order, same adjacency, the
// infinite vertex last in each infinite cell.  `target` is a CGAL
// Triangulation_3 or a class derived from it (Delaunay_triangulation_3,
// Remeshing_triangulation_3, ...) with any data structure.
template <class Gt, class Tds, class Lp, class Lds, class Cgal_triangulation>
void convert_to_cgal(const Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& source, Cgal_triangulation& target)
{
  if(source.dimension() == 3) {
    Fast_Delaunay_triangulation_3_internal::copy_cells(source, target);
    return;
  }
  target.clear();
  for(auto v = source.finite_vertices_begin(); v != source.finite_vertices_end(); ++v)
    target.insert(Fast_Delaunay_triangulation_3_internal::to_target_point<typename Cgal_triangulation::Point>(
        v->point()));
}

// A subdomain for every cell: the default puts all cells in subdomain 1.
struct Same_subdomain_for_all_cells
{
  int subdomain = 1;
  template <class Cell_handle>
  int operator()(Cell_handle) const { return subdomain; }
};

// Replaces `c3t3` (a Mesh_complex_3_in_triangulation_3) by our triangulation
// (as convert_to_cgal) where every finite cell c with
// subdomain_of_cell(c) != Subdomain_index() (our Cell_handle) is in the
// complex with that subdomain, and every facet between two different
// subdomains, the outside (infinite cells, and cells of index 0) included,
// is a surface facet with index surface_patch(s1, s2).  Vertices get
// CGAL's Mesh_3 dimension: 2 on a surface facet (index: its patch), else 3
// (index: the subdomain of one incident cell).
template <class Gt, class Tds, class Lp, class Lds, class C3t3,
          class Subdomain_of_cell = Same_subdomain_for_all_cells,
          class Surface_patch_of_pair = Fast_Delaunay_triangulation_3_internal::Default_surface_patch<
              typename C3t3::Subdomain_index, typename C3t3::Surface_patch_index>>
void convert_to_c3t3(const Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds>& source, C3t3& c3t3,
                     Subdomain_of_cell subdomain_of_cell = Subdomain_of_cell(),
                     Surface_patch_of_pair surface_patch = Surface_patch_of_pair())
{
  typedef Fast_Delaunay_triangulation_3<Gt, Tds, Lp, Lds> Source;
  typedef typename C3t3::Triangulation Target;
  typedef typename C3t3::Subdomain_index Subdomain_index;
  typedef typename C3t3::Surface_patch_index Surface_patch_index;
  using namespace Fast_Delaunay_triangulation_3_internal;

  c3t3.clear();
  if(source.dimension() < 3) {
    convert_to_cgal(source, c3t3.triangulation());
    return;
  }
  const Cell_map<Target> cell_of = copy_cells(source, c3t3.triangulation());
  const Flat_storage& mesh = source.flat_storage();

  std::vector<Subdomain_index> subdomain(mesh.number_of_slots(), Subdomain_index());
  for(Tet_id t = 0; t < mesh.number_of_slots(); ++t) {
    if(!mesh.is_live(t) || mesh.is_ghost(t)) continue;
    subdomain[t] = subdomain_of_cell(typename Source::Cell_handle(source.storage_anchor(), t));
    for(int i = 0; i < 4; ++i) {
      cell_of[t]->vertex(i)->set_dimension(3);
      cell_of[t]->vertex(i)->set_index(subdomain[t]);
    }
    if(subdomain[t] != Subdomain_index()) c3t3.add_to_complex(cell_of[t], subdomain[t]);
  }
  for(Tet_id t = 0; t < mesh.number_of_slots(); ++t) {
    if(!mesh.is_live(t)) continue;
    for(int i = 0; i < 4; ++i) {
      const Tet_id u = mesh.neighbor(t, i);
      // Each facet once, from the smaller slot; hull facets from the finite side.
      if(mesh.is_ghost(t) || (u < t && !mesh.is_ghost(u)) || subdomain[t] == subdomain[u]) continue;
      const Surface_patch_index patch = surface_patch(subdomain[t], subdomain[u]);
      c3t3.add_to_complex(cell_of[t], i, patch);
      for(int k = 0; k < 4; ++k) {
        if(k == i) continue;
        cell_of[t]->vertex(k)->set_dimension(2);
        cell_of[t]->vertex(k)->set_index(patch);
      }
    }
  }
}

} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_CONVERT_TO_CGAL_H
