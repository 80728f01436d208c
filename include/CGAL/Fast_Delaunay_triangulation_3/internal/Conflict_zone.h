// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The conflict zone of a point as a query (CGAL's find_conflicts and
// vertices_on_conflict_zone_boundary): the kernel's CAVITY step (paper §2.4)
// without the DELAUNAYBALL that would follow.  The search marks the zone in
// the tetrahedron records, the lists are read while the marks are on, then
// the marks are removed: the mesh is as before.  Because the test is the
// insertion's own perturbed in-sphere, the zone is exactly the set of cells
// an insertion of p would delete, hence exactly CGAL's, cospherical ties
// included.  As with CGAL (whose search writes the cells' conflict flags),
// a query writes into the triangulation while it runs: no other thread may
// read the same triangulation meanwhile.  Dimension 3 only.

#ifndef CGAL_FDT3_INTERNAL_CONFLICT_ZONE_H
#define CGAL_FDT3_INTERNAL_CONFLICT_ZONE_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

struct Conflict_zone
{
  std::vector<Tet_id> cells;         // in conflict, breadth-first from the start
  std::vector<Facet_code> boundary;  // facet of a zone cell whose neighbour is outside the zone
  std::vector<Facet_code> internal;  // between two zone cells, once, from the cell of smaller index
};

// The zone of p grown from `start`, which must be in conflict with p.
inline void find_conflict_zone(const Flat_storage& m, Tet_id start, const double* p, bool with_internal,
                               Conflict_zone& zone)
{
  // Marks only: they are all removed before returning (see above).
  Flat_storage& mesh = const_cast<Flat_storage&>(m);
  Insertion_scratch scratch;
  Delaunay_kernel<> kernel(mesh, scratch, Mesh_slots{&mesh});
  zone.boundary.clear();
  zone.internal.clear();
  kernel.conflict_zone(start, p, [&] {
    zone.cells.assign(scratch.cavity.begin(), scratch.cavity.end());
    // The boundary record names the outside tetrahedron's facet; its
    // neighbour code names the same facet from inside the zone.
    for(const Boundary_facet& b : scratch.boundary) zone.boundary.push_back(m.neighbor_code(b.outside));
    if(!with_internal) return;
    for(Tet_id t : zone.cells)
      for(int f = 0; f < 4; ++f) {
        const Tet_id u = m.neighbor(t, f);
        if(!m.is_live(u) && t < u) zone.internal.push_back(facet_code(t, f));
      }
  });
}

// Conflict test of one live tetrahedron, as the cavity search makes it.
inline bool cell_in_conflict(const Flat_storage& m, Tet_id t, const double* p)
{
  Flat_storage& mesh = const_cast<Flat_storage&>(m); // the test only reads
  Insertion_scratch scratch;
  return Delaunay_kernel<>(mesh, scratch, Mesh_slots{&mesh}).in_conflict(t, p);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_CONFLICT_ZONE_H
