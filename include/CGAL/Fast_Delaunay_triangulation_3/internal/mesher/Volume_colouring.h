// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Colouring of the volumes (paper §4, the "color flag ... used to
// distinguish volumes"): the input triangles are flagged as constrained
// facets on both of their tetrahedra, then each connected set of
// tetrahedra that does not cross a constrained facet is one volume.  The set
// that holds the ghost tetrahedra is the outside (subdomain 0); the others
// are numbered 1, 2, ... in the order of their first tetrahedron slot, so a
// surface nested in another gives two subdomains.

#ifndef CGAL_FDT3_INTERNAL_MESHER_VOLUME_COLOURING_H
#define CGAL_FDT3_INTERNAL_MESHER_VOLUME_COLOURING_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Boundary_recovery.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>

#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

// Sets the constrained bits, on `threads` threads; throws if an input
// triangle is not a facet.
inline void flag_constrained_facets(const Surface_soup& soup, Constrained_mesh& cm, int threads = 1)
{
  const std::vector<Triangle_key> keys = input_triangle_keys(soup, cm.vertex_of_input);
  const Triangles_by_smallest_vertex lookup(keys, cm.mesh.vertices.size());
  std::fill(cm.constrained.begin(), cm.constrained.end(), 0);
  const std::vector<char> found = listed_facets(cm.mesh, lookup, threads, [&](Tet_id t, int f) {
    cm.constrained[t] |= std::uint8_t(1u << f);
  });
  if(std::count(found.begin(), found.end(), 0) != 0)
    throw std::runtime_error("Tetrahedral_mesher: boundary recovery left input triangles out of the mesh");
}

// Flood fill across unconstrained facets; returns the number of subdomains.
inline int colour_volumes(Constrained_mesh& cm)
{
  const Flat_storage& m = cm.mesh;
  const int unset = -1;
  std::fill(cm.subdomain.begin(), cm.subdomain.end(), unset);
  std::vector<Tet_id> stack;
  auto fill_from = [&](Tet_id seed, int colour) {
    cm.subdomain[seed] = colour;
    stack.push_back(seed);
    while(!stack.empty()) {
      const Tet_id t = stack.back();
      stack.pop_back();
      for(int f = 0; f < 4; ++f) {
        if(cm.is_constrained(t, f)) continue;
        const Tet_id u = m.neighbor(t, f);
        if(cm.subdomain[u] != unset) continue;
        cm.subdomain[u] = colour;
        stack.push_back(u);
      }
    }
  };
  for(Tet_id t = 0; t < m.number_of_slots(); ++t)
    if(m.is_live(t) && m.is_ghost(t) && cm.subdomain[t] == unset) fill_from(t, 0);
  int colours = 0;
  for(Tet_id t = 0; t < m.number_of_slots(); ++t)
    if(m.is_live(t) && cm.subdomain[t] == unset) fill_from(t, ++colours);
  for(Tet_id t = 0; t < m.number_of_slots(); ++t)
    if(!m.is_live(t)) cm.subdomain[t] = 0;
  cm.number_of_subdomains = colours;
  return colours;
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_VOLUME_COLOURING_H
