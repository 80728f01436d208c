// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The one combinatorial update behind every flip on the flat arrays: a small
// set of live tetrahedra (a region) is replaced by new tetrahedra that cover
// the same region and have the same boundary facets.  A 2-3 flip is the
// region of two tetrahedra sharing a facet, a 3-2 or 4-4 flip and Shewchuk's
// edge removal the ring of tetrahedra around an edge, small polyhedron
// reconnection any star-shaped cavity; the TDS view (Flat_tds.h), the mesh
// improvement (mesher/Mesh_improvement.h) and the mesher's boundary
// recovery (mesher/Boundary_recovery.h, a component and its ghosts) call
// this.
//
// What the caller guarantees: the new tetrahedra are combinatorially
// positively oriented (the ghost vertex, if any, in slot 3), their facets
// are either facets of the region's boundary (each used exactly once) or
// shared by exactly two new tetrahedra.  What it gets: the old slots reused
// in order, then slots from `new_slot()`; the surplus old slots handed to
// `free_slot(t)`; every boundary facet linked both ways to the tetrahedron
// outside, which is the only record outside the region that is written.
// No predicate is evaluated: geometry is the caller's business.
//
// A flip's region has a few tetrahedra, and linear scans match its facets
// fastest; a region of more than `large_replacement` old and new
// tetrahedra (no flip and no Steiner cavity of the mesh improvement, but a
// component of the mesher's boundary recovery: up to a few thousand) has
// its facets matched by sorting instead.

#ifndef CGAL_FDT3_INTERNAL_TETRAHEDRA_REPLACEMENT_H
#define CGAL_FDT3_INTERNAL_TETRAHEDRA_REPLACEMENT_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <CGAL/assertions.h>

#include <algorithm>
#include <array>
#include <cstddef>
#include <stdexcept>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// The facets of a region, each by its sorted vertex ids and where it is.
struct Region_facet
{
  Vertex_id key[3];
  Facet_code outside; // the facet's code as seen from the other side
  bool used;
};

// Reused buffers: a small replacement (any flip) allocates nothing once
// they have grown.
struct Replacement_scratch
{
  std::vector<Region_facet> boundary;
  std::vector<Region_facet> open_inner; // new facets waiting for their twin
};

// Net change of the storage's counters, for callers that sum them per
// partition instead of writing the shared counters.
struct Replacement_counts
{
  std::ptrdiff_t live = 0, ghost = 0;
};

// Three compare-exchanges: std::sort's insertion sort costs several times
// more on three elements (a tenth of a short move's time went there).
inline void sorted_facet_key(const Vertex_id* tv, int f, Vertex_id key[3])
{
  Vertex_id a = tv[facet_vertex[f][0]], b = tv[facet_vertex[f][1]], c = tv[facet_vertex[f][2]];
  if(b < a) std::swap(a, b);
  if(c < b) std::swap(b, c);
  if(b < a) std::swap(a, b);
  key[0] = a;
  key[1] = b;
  key[2] = c;
}

inline bool in_region(const Tet_id* region, std::size_t n, Tet_id t)
{
  return std::find(region, region + n, t) != region + n;
}

constexpr std::size_t large_replacement = 256;

namespace replacement_detail {

// A facet of a made tetrahedron: its sorted vertex ids and 4 k + f.
struct Made_facet
{
  Vertex_id key[3];
  std::size_t at;
};

inline bool key_less(const Vertex_id* x, const Vertex_id* y)
{
  return std::lexicographical_compare(x, x + 3, y, y + 3);
}
inline bool same_key(const Vertex_id* x, const Vertex_id* y) { return x[0] == y[0] && x[1] == y[1] && x[2] == y[2]; }

// The facets of a region paired by sorting: each made facet with its twin
// or with the boundary facet it covers.
struct Sorted_matching
{
  std::vector<Region_facet> boundary;                      // sorted by key
  std::vector<std::pair<std::size_t, std::size_t>> inner;  // two made facets (4 k + f)
  std::vector<std::pair<std::size_t, std::size_t>> covers; // made facet, boundary index
  std::ptrdiff_t ghosts_before = 0;
};

// Throws logic_error, reading the storage only, unless every key is that
// of two made facets and no boundary facet, or of one of each.
inline Sorted_matching match_by_sorting(const Flat_storage& m, const Tet_id* region, std::size_t region_size,
                                        const std::array<Vertex_id, 4>* made, std::size_t made_size)
{
  Sorted_matching r;
  std::vector<Tet_id> members(region, region + region_size);
  std::sort(members.begin(), members.end());
  for(std::size_t k = 0; k < region_size; ++k) {
    const Tet_id t = region[k];
    r.ghosts_before += m.is_ghost(t) ? 1 : 0;
    for(int f = 0; f < 4; ++f) {
      if(std::binary_search(members.begin(), members.end(), m.neighbor(t, f))) continue;
      Region_facet b;
      sorted_facet_key(m.vertex_ids(t), f, b.key);
      b.outside = m.neighbor_code(t, f);
      b.used = false;
      r.boundary.push_back(b);
    }
  }
  std::sort(r.boundary.begin(), r.boundary.end(),
            [](const Region_facet& x, const Region_facet& y) { return key_less(x.key, y.key); });
  std::vector<Made_facet> facets(4 * made_size);
  for(std::size_t k = 0; k < made_size; ++k)
    for(int f = 0; f < 4; ++f) {
      Made_facet& facet = facets[4 * k + f];
      sorted_facet_key(made[k].data(), f, facet.key);
      facet.at = 4 * k + f;
    }
  std::sort(facets.begin(), facets.end(),
            [](const Made_facet& x, const Made_facet& y) { return key_less(x.key, y.key); });
  const std::vector<Region_facet>& boundary = r.boundary;
  std::size_t b = 0;
  for(std::size_t i = 0; i < facets.size();) {
    std::size_t j = i + 1;
    while(j < facets.size() && same_key(facets[j].key, facets[i].key)) ++j;
    while(b < boundary.size() && key_less(boundary[b].key, facets[i].key)) ++b;
    const bool in_boundary = b < boundary.size() && same_key(boundary[b].key, facets[i].key);
    if(j - i == 2 && !in_boundary) {
      r.inner.emplace_back(facets[i].at, facets[i + 1].at);
    } else if(j - i == 1 && in_boundary && (b + 1 == boundary.size() || !same_key(boundary[b + 1].key, facets[i].key))) {
      r.covers.emplace_back(facets[i].at, b);
    } else {
      throw std::logic_error("replace_tetrahedra: the new tetrahedra do not have the region's boundary");
    }
    i = j;
  }
  if(r.covers.size() != boundary.size())
    throw std::logic_error("replace_tetrahedra: the new tetrahedra do not have the region's boundary");
  return r;
}

// A large region replaced: the same contract as replace_tetrahedra below.
template <class New_slot, class Free_slot>
void replace_large_region(Flat_storage& m, const Tet_id* region, std::size_t region_size,
                          const std::array<Vertex_id, 4>* made, std::size_t made_size, Tet_id* slots,
                          Replacement_counts& counts, New_slot new_slot, Free_slot free_slot)
{
  const Sorted_matching matching = match_by_sorting(m, region, region_size, made, made_size);
  for(std::size_t k = 0; k < made_size; ++k) slots[k] = k < region_size ? region[k] : new_slot();
  for(std::size_t r = made_size; r < region_size; ++r) free_slot(region[r]);
  std::ptrdiff_t ghosts_after = 0;
  for(std::size_t k = 0; k < made_size; ++k) {
    Tet_record& record = m.tets[slots[k]];
    for(int i = 0; i < 4; ++i) record.v[i] = made[k][i];
    ghosts_after += made[k][3] == ghost_vertex ? 1 : 0;
  }
  auto code_of = [&](std::size_t at) { return facet_code(slots[at / 4], static_cast<int>(at % 4)); };
  for(const auto& pair : matching.inner) {
    m.neighbor_code(code_of(pair.first)) = code_of(pair.second);
    m.neighbor_code(code_of(pair.second)) = code_of(pair.first);
  }
  for(const auto& cover : matching.covers) {
    const Facet_code outside = matching.boundary[cover.second].outside;
    m.neighbor_code(code_of(cover.first)) = outside;
    m.neighbor_code(outside) = code_of(cover.first);
  }
  counts.live += std::ptrdiff_t(made_size) - std::ptrdiff_t(region_size);
  counts.ghost += ghosts_after - matching.ghosts_before;
}

} // namespace replacement_detail

// Throws logic_error unless `made` closes up with the region's boundary:
// replace_tetrahedra's check, in full whatever the size (the linear path's
// own check of inner facets is an assertion), without writing anything.
// For a caller replacing several regions that must refuse before the first.
inline void check_replacement(const Flat_storage& m, const Tet_id* region, std::size_t region_size,
                              const std::array<Vertex_id, 4>* made, std::size_t made_size)
{
  (void)replacement_detail::match_by_sorting(m, region, region_size, made, made_size);
}

// `slots` receives the slot of each made tetrahedron.  Throws logic_error,
// before anything is written, when the made tetrahedra do not close up with
// the region's boundary (a caller's bug: the arrays stay as they were).
template <class New_slot, class Free_slot>
void replace_tetrahedra(Flat_storage& m, const Tet_id* region, std::size_t region_size,
                        const std::array<Vertex_id, 4>* made, std::size_t made_size, Tet_id* slots,
                        Replacement_scratch& scratch, Replacement_counts& counts, New_slot new_slot,
                        Free_slot free_slot)
{
  CGAL_precondition(region_size > 0 && made_size > 0);
  if(region_size + made_size > large_replacement) {
    replacement_detail::replace_large_region(m, region, region_size, made, made_size, slots, counts, new_slot,
                                             free_slot);
    return;
  }
  std::vector<Region_facet>& boundary = scratch.boundary;
  boundary.clear();
  std::ptrdiff_t ghosts_before = 0;
  for(std::size_t r = 0; r < region_size; ++r) {
    const Tet_id t = region[r];
    ghosts_before += m.is_ghost(t) ? 1 : 0;
    for(int f = 0; f < 4; ++f) {
      if(in_region(region, region_size, m.neighbor(t, f))) continue;
      Region_facet b;
      sorted_facet_key(m.vertex_ids(t), f, b.key);
      b.outside = m.neighbor_code(t, f);
      b.used = false;
      boundary.push_back(b);
    }
  }
  // The boundary check comes first, so that a bad call changes nothing.
  std::size_t boundary_facets_made = 0;
  for(std::size_t k = 0; k < made_size; ++k)
    for(int f = 0; f < 4; ++f) {
      Vertex_id key[3];
      sorted_facet_key(made[k].data(), f, key);
      for(Region_facet& b : boundary)
        if(!b.used && replacement_detail::same_key(b.key, key)) {
          b.used = true;
          ++boundary_facets_made;
          break;
        }
    }
  if(boundary_facets_made != boundary.size() || (4 * made_size - boundary.size()) % 2 != 0)
    throw std::logic_error("replace_tetrahedra: the new tetrahedra do not have the region's boundary");
  for(Region_facet& b : boundary) b.used = false;

  for(std::size_t k = 0; k < made_size; ++k) slots[k] = k < region_size ? region[k] : new_slot();
  for(std::size_t r = made_size; r < region_size; ++r) free_slot(region[r]);

  std::vector<Region_facet>& open = scratch.open_inner;
  open.clear();
  std::ptrdiff_t ghosts_after = 0;
  for(std::size_t k = 0; k < made_size; ++k) {
    Tet_record& record = m.tets[slots[k]];
    for(int i = 0; i < 4; ++i) record.v[i] = made[k][i];
    ghosts_after += made[k][3] == ghost_vertex ? 1 : 0;
  }
  for(std::size_t k = 0; k < made_size; ++k)
    for(int f = 0; f < 4; ++f) {
      Region_facet facet;
      sorted_facet_key(made[k].data(), f, facet.key);
      const Facet_code here = facet_code(slots[k], f);
      bool linked = false;
      for(Region_facet& b : boundary)
        if(!b.used && replacement_detail::same_key(b.key, facet.key)) {
          b.used = true;
          m.tets[slots[k]].n[f] = b.outside;
          m.neighbor_code(b.outside) = here;
          linked = true;
          break;
        }
      if(linked) continue;
      for(std::size_t j = 0; j < open.size(); ++j)
        if(replacement_detail::same_key(open[j].key, facet.key)) {
          m.tets[slots[k]].n[f] = open[j].outside;
          m.neighbor_code(open[j].outside) = here;
          open[j] = open.back();
          open.pop_back();
          linked = true;
          break;
        }
      if(!linked) {
        facet.outside = here;
        open.push_back(facet);
      }
    }
  CGAL_postcondition(open.empty());
  counts.live += std::ptrdiff_t(made_size) - std::ptrdiff_t(region_size);
  counts.ghost += ghosts_after - ghosts_before;
}

// The same on the storage's own slot list and counters (sequential callers).
inline void replace_tetrahedra(Flat_storage& m, const Tet_id* region, std::size_t region_size,
                               const std::array<Vertex_id, 4>* made, std::size_t made_size, Tet_id* slots,
                               Replacement_scratch& scratch)
{
  Replacement_counts counts;
  replace_tetrahedra(m, region, region_size, made, made_size, slots, scratch, counts, [&m] { return m.new_tet(); },
                     [&m](Tet_id t) { m.free_tet(t); });
  m.live_tets = std::size_t(std::ptrdiff_t(m.live_tets) + counts.live);
  m.ghost_tets = std::size_t(std::ptrdiff_t(m.ghost_tets) + counts.ghost);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_TETRAHEDRA_REPLACEMENT_H
