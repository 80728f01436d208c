// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Many vertices removed at once on several threads: CGAL's remove(first,
// last) with a Parallel_tag data structure.  The idea is the paper's (§3):
// space is cut into partitions, each thread works where it alone works,
// and what reaches another partition is left for later.  Here the
// partitions are slabs along the longest axis of the vertices to remove,
// cut at quantiles so each holds as many of them; a vertex (any, not only
// one to remove) belongs to the slab its coordinate falls in, the infinite
// vertex to every slab.
//
// The rule that makes the threads independent: a thread writes only cells
// whose finite vertices all belong to its slab.  Removing v writes the
// cells of v's star (freed), the cells beyond the star's boundary facets
// (their neighbour entries) and the new cells (made of the star's link), so
// v is removed by its slab's thread only when the link and the far vertices
// of the cells beyond are all in the slab; otherwise v is deferred, and
// removed after the threads, one by one.  The checks read only cells that
// no other thread writes: the cells of v (v is in the slab), then each
// cell beyond the boundary (three of its vertices are on the boundary,
// checked to be in the slab).  Each thread numbers its link vertices in
// their records' scratch words, which no other thread reads then, and keeps
// v->cell() (incident_cells) for the vertices of its new cells.
//
// Slots: a thread reuses the slots of the stars it frees and its share of
// the free slots the arrays had, so the array never moves meanwhile; a
// removal that would need more (a hole filled with more cells than its star
// and the pool hold, rare: a removal leaves 6.7 cells fewer on average) is
// deferred before it writes anything.  Counts of cells and of dead vertices
// are kept per thread and added at the end.  A link that is flat (v on the
// hull with a coplanar link, or the last points becoming coplanar) is
// deferred too: the sequential removal knows those cases.
//
// The triangulation after the removals is unique (CGAL's perturbation), so
// the cells are CGAL's whatever the threads did; only the slots they occupy
// depend on the scheduling.

#ifndef CGAL_FDT3_INTERNAL_PARALLEL_REMOVAL_H
#define CGAL_FDT3_INTERNAL_PARALLEL_REMOVAL_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Adjacency_queries.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Vertex_removal.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

class Parallel_removal
{
public:
  // Removes what it can of `vertices` (live, distinct, dimension 3) on
  // `partitions` threads.  incident_cells is v->cell() for every vertex
  // (complete and current on entry, kept so).  `deferred` receives the
  // vertices left for the sequential removal; `made`, unless null, the
  // slots of the new cells that are still live (one may be listed twice:
  // made, freed and made again).
  static void run(Flat_storage& m, std::vector<Tet_id>& incident_cells, const std::vector<Vertex_id>& vertices,
                  int partitions, std::vector<Vertex_id>& deferred, std::vector<Tet_id>* made)
  {
    deferred.clear();
    if(made) made->clear();
    Slabs slabs(m, vertices, partitions);
    std::vector<std::vector<Vertex_id>> mine(slabs.count());
    for(Vertex_id v : vertices) mine[slabs.of(v)].push_back(v);

    // The free slots of the arrays are dealt out; the array does not grow
    // (a bigger capacity would copy it whole).
    std::vector<Partition> work(slabs.count());
    for(std::size_t k = 0; k < m.free_tets.size(); ++k) work[k % work.size()].free.push_back(m.free_tets[k]);
    m.free_tets.clear();

    for_each_chunk(static_cast<int>(work.size()), [&](int p) {
      work[p].keep_made = made != nullptr;
      work[p].remove(m, incident_cells, slabs, p, mine[p]);
    });

    for(Partition& w : work) {
      m.live_tets = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(m.live_tets) + w.live_delta);
      m.ghost_tets = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(m.ghost_tets) + w.ghost_delta);
      m.dead_vertices += w.removed;
      m.free_tets.insert(m.free_tets.end(), w.free.begin(), w.free.end());
      deferred.insert(deferred.end(), w.deferred.begin(), w.deferred.end());
      if(made) made->insert(made->end(), w.made.begin(), w.made.end());
    }
  }

private:
  // Slabs along the longest axis of the vertices to remove, as many of them
  // in each.  The slab of every vertex is looked up in a byte array made
  // once (the checks read it some 150 times per removal).
  class Slabs
  {
  public:
    Slabs(const Flat_storage& m, const std::vector<Vertex_id>& vertices, int partitions)
    {
      double lo[3], hi[3];
      for(int a = 0; a < 3; ++a) lo[a] = hi[a] = m.point(vertices.front())[a];
      for(Vertex_id v : vertices)
        for(int a = 0; a < 3; ++a) {
          lo[a] = std::min(lo[a], m.point(v)[a]);
          hi[a] = std::max(hi[a], m.point(v)[a]);
        }
      axis_ = 0;
      for(int a = 1; a < 3; ++a)
        if(hi[a] - lo[a] > hi[axis_] - lo[axis_]) axis_ = a;
      std::vector<double> along;
      along.reserve(vertices.size());
      for(Vertex_id v : vertices) along.push_back(m.point(v)[axis_]);
      for(int p = 1; p < partitions; ++p) {
        auto at = along.begin() + static_cast<std::ptrdiff_t>(along.size() * std::size_t(p) / std::size_t(partitions));
        std::nth_element(along.begin(), at, along.end());
        bounds_.push_back(*at);
      }
      std::sort(bounds_.begin(), bounds_.end());
      slab_.resize(m.vertices.size());
      const int chunks = chunk_count(slab_.size(), partitions);
      for_each_chunk(chunks, [&](int c) {
        const std::size_t end = chunk_begin(slab_.size(), chunks, c + 1);
        for(std::size_t v = chunk_begin(slab_.size(), chunks, c); v < end; ++v)
          slab_[v] = static_cast<std::uint8_t>(
              std::upper_bound(bounds_.begin(), bounds_.end(), m.point(static_cast<Vertex_id>(v))[axis_]) -
              bounds_.begin());
      });
    }
    std::size_t count() const { return bounds_.size() + 1; }
    int of(Vertex_id v) const { return slab_[v]; }
    // The infinite vertex belongs to every slab.
    bool in(Vertex_id v, int p) const { return v == ghost_vertex || slab_[v] == p; }

  private:
    int axis_ = 0;
    std::vector<double> bounds_;
    std::vector<std::uint8_t> slab_; // by vertex id
  };

  // One thread's removals, with its own buffers, slots and counts.
  struct Partition
  {
    std::vector<Tet_id> free; // slots this partition may take
    std::vector<Vertex_id> deferred;
    std::vector<Tet_id> made;
    bool keep_made = false;
    std::ptrdiff_t live_delta = 0, ghost_delta = 0;
    std::size_t removed = 0;
    Removal_hole hole;
    Link_triangulation link;
    Hole_filling_buffers filling;
    std::vector<Tet_id> new_cells;

    // Shared_slots's interface over this partition's pool (Vertex_removal.h).
    struct Slots
    {
      Partition& p;
      Flat_storage& m;
      void release(Tet_id t)
      {
        if(m.is_ghost(t)) --p.ghost_delta;
        --p.live_delta;
        m.mark_free(t);
        p.free.push_back(t);
      }
      Tet_id take()
      {
        const Tet_id t = p.free.back();
        p.free.pop_back();
        return t;
      }
      void count_in(Tet_id t)
      {
        ++p.live_delta;
        if(m.is_ghost(t)) ++p.ghost_delta;
        if(m.with_sub_determinants) update_sub_determinants(m, t);
      }
    };

    void remove(Flat_storage& m, std::vector<Tet_id>& incident_cells, const Slabs& slabs, int p,
                const std::vector<Vertex_id>& vertices)
    {
      for(Vertex_id v : vertices) {
        if(!remove_one(m, incident_cells, slabs, p, v)) deferred.push_back(v);
      }
      // Some were freed again by later removals here (never by another thread).
      made.erase(std::remove_if(made.begin(), made.end(), [&m](Tet_id t) { return !m.is_live(t); }), made.end());
    }

    bool remove_one(Flat_storage& m, std::vector<Tet_id>& incident_cells, const Slabs& slabs, int p, Vertex_id v)
    {
      cells_around_vertex(m, incident_cells[v], v, hole.star, hole.seen);
      for(Tet_id t : hole.star)
        for(int i = 0; i < 4; ++i)
          if(!slabs.in(m.vertex(t, i), p)) return false;
      // Every cell beyond the star has the three vertices of a boundary
      // facet, all in the slab now: no other thread writes it.  (Read now,
      // they are read later anyway: their loads overlap.)
      for(Tet_id t : hole.star) __builtin_prefetch(m.vertex_ids(m.neighbor(t, index_of(m, t, v))));
      for(Tet_id t : hole.star) {
        const Facet_code outside = m.neighbor_code(t, index_of(m, t, v));
        if(!slabs.in(m.vertex(tet_of(outside), facet_of(outside)), p)) return false;
      }
      carve_found_star(m, v, hole);
      if(!link.build(m, hole.link)) return false; // flat: the sequential removal knows
      if(!find_hole_cells(hole, link.mesh(), filling))
        throw std::logic_error("Fast_Delaunay_triangulation_3: a facet of the hole of a removed vertex is not in "
                               "the Delaunay triangulation of its link");
      if(filling.inside.size() > free.size() + hole.star.size()) return false;
      write_hole_cells(m, hole, link.mesh(), filling, new_cells, Slots{*this, m});
      m.vertices[v].scratch = dead_vertex; // counted in at the end
      ++removed;
      for(Tet_id t : new_cells) {
        if(keep_made) made.push_back(t);
        for(int i = 0; i < 4; ++i) {
          const Vertex_id w = m.vertex(t, i);
          if(w != ghost_vertex) incident_cells[w] = t;
        }
      }
      return true;
    }
  };
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_PARALLEL_REMOVAL_H
