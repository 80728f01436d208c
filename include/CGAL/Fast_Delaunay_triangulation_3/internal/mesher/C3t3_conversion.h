// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher's result as CGAL's Mesh_complex_3_in_triangulation_3, so that
// CGAL's tetrahedral remeshing and Mesh_3's optimisers can run on it.  Same
// approach as convert_to_c3t3 (convert_to_cgal.h): the data structure's
// cells are created from the flat arrays (the whole convex hull, outside
// and ghosts included, as a CGAL triangulation must), then the tetrahedra of
// subdomains 1, 2, ... and the input triangles (constrained facets) are put
// in the complex.  The mesh is not Delaunay, so the target should be a plain
// triangulation such as Tetrahedral_remeshing::Remeshing_triangulation_3.

#ifndef CGAL_FDT3_INTERNAL_MESHER_C3T3_CONVERSION_H
#define CGAL_FDT3_INTERNAL_MESHER_C3T3_CONVERSION_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/convert_to_cgal.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Boundary_recovery.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>

#include <algorithm>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

// What copy_cells reads from a source: the flat arrays and the points.
struct Constrained_mesh_source
{
  const Constrained_mesh* cm;
  const Flat_storage& flat_storage() const { return cm->mesh; }
  Exact_predicates_inexact_constructions_kernel::Point_3 point_of(Vertex_id v) const
  {
    const double* p = cm->mesh.point(v);
    return Exact_predicates_inexact_constructions_kernel::Point_3(p[0], p[1], p[2]);
  }
};

// A surface patch index from the input surface number and the two
// subdomains on either side: the pair for CGAL's labeled domains, else the
// surface number.
template <class Surface_patch_index, class Subdomain_index>
Surface_patch_index patch_index(int surface, Subdomain_index a, Subdomain_index b)
{
  if constexpr(std::is_constructible<Surface_patch_index, std::pair<Subdomain_index, Subdomain_index>>::value)
    return Surface_patch_index(std::make_pair(std::min(a, b), std::max(a, b)));
  else
    return Surface_patch_index(surface);
}

template <class C3t3>
void constrained_mesh_to_c3t3(const Constrained_mesh& cm, const Surface_soup& soup, C3t3& c3t3)
{
  typedef typename C3t3::Triangulation Target;
  typedef typename C3t3::Subdomain_index Subdomain_index;
  typedef typename C3t3::Surface_patch_index Surface_patch_index;
  const Flat_storage& m = cm.mesh;

  struct Keyed_surface { Triangle_key key; int surface; };
  std::vector<Keyed_surface> surface_of;
  for(std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& v = soup.triangles[t];
    surface_of.push_back({Triangle_key::of(cm.vertex_of_input[v[0]], cm.vertex_of_input[v[1]],
                                           cm.vertex_of_input[v[2]]), soup.surface[t]});
  }
  std::sort(surface_of.begin(), surface_of.end(),
            [](const Keyed_surface& x, const Keyed_surface& y) { return x.key < y.key; });
  auto surface_number = [&](const Triangle_key& k) {
    auto it = std::lower_bound(surface_of.begin(), surface_of.end(), k,
                               [](const Keyed_surface& x, const Triangle_key& key) { return x.key < key; });
    CGAL_assertion(it != surface_of.end() && it->key == k);
    return it->surface;
  };

  c3t3.clear();
  const Cell_map<Target> cell_of = copy_cells(Constrained_mesh_source{&cm}, c3t3.triangulation());
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || m.is_ghost(t)) continue;
    const Subdomain_index s = static_cast<Subdomain_index>(cm.subdomain[t]);
    for(int i = 0; i < 4; ++i) {
      cell_of[t]->vertex(i)->set_dimension(3);
      cell_of[t]->vertex(i)->set_index(s);
    }
    if(cm.subdomain[t] > 0) c3t3.add_to_complex(cell_of[t], s);
  }
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || m.is_ghost(t)) continue;
    for(int i = 0; i < 4; ++i) {
      const Tet_id u = m.neighbor(t, i);
      // Each input triangle once, from its finite side with the smaller slot.
      if(!cm.is_constrained(t, i) || (u < t && !m.is_ghost(u))) continue;
      const Surface_patch_index patch = patch_index<Surface_patch_index>(
          surface_number(facet_key(m, t, i)), static_cast<Subdomain_index>(cm.subdomain[t]),
          static_cast<Subdomain_index>(cm.subdomain[u]));
      c3t3.add_to_complex(cell_of[t], i, patch);
      for(int k = 0; k < 4; ++k) {
        if(k == i) continue;
        cell_of[t]->vertex(k)->set_dimension(2);
        cell_of[t]->vertex(k)->set_index(patch);
      }
    }
  }
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_C3T3_CONVERSION_H
