// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesh the mesher works on (paper §4): the flat arrays of the Delaunay
// engine (Flat_storage, ghost tetrahedra included, covering the convex hull
// of the input) plus, per tetrahedron slot, its subdomain (0 outside every
// volume, and for ghosts) and which of its facets are input triangles, and
// per vertex the target size h.  The constrained facets are what refinement
// cavities may never cross.
//
// Also builds such arrays from a plain list of positively oriented
// tetrahedra (what a boundary recovery returns): adjacency by matching
// sorted facet keys, then one ghost tetrahedron per hull facet.

#ifndef CGAL_FDT3_INTERNAL_MESHER_CONSTRAINED_MESH_H
#define CGAL_FDT3_INTERNAL_MESHER_CONSTRAINED_MESH_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Size_field.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

// Unordered triangle as a key: its vertex ids, sorted.
struct Triangle_key
{
  Vertex_id v[3];

  static Triangle_key of(Vertex_id a, Vertex_id b, Vertex_id c)
  {
    Triangle_key k{{a, b, c}};
    std::sort(k.v, k.v + 3);
    return k;
  }
  friend bool operator<(const Triangle_key& x, const Triangle_key& y)
  {
    return std::lexicographical_compare(x.v, x.v + 3, y.v, y.v + 3);
  }
  friend bool operator==(const Triangle_key& x, const Triangle_key& y)
  {
    return x.v[0] == y.v[0] && x.v[1] == y.v[1] && x.v[2] == y.v[2];
  }
};

// Facet f of tetrahedron t as a key (mark bits must be clear).
inline Triangle_key facet_key(const Flat_storage& m, Tet_id t, int f)
{
  const Vertex_id* tv = m.vertex_ids(t);
  return Triangle_key::of(tv[facet_vertex[f][0]], tv[facet_vertex[f][1]], tv[facet_vertex[f][2]]);
}

// A list of triangles bucketed by their smallest vertex (a counting sort).
// Looking a mesh facet up compares it with a handful (a vertex starts two
// input triangles on average), where a binary search over the whole sorted
// list cost ~15 unpredictable branches per facet; the buckets also pair up
// the facets of a set of tetrahedra.
class Triangles_by_smallest_vertex
{
public:
  static constexpr std::size_t none = std::size_t(-1);

  Triangles_by_smallest_vertex(const std::vector<Triangle_key>& keys, std::size_t vertices)
      : keys_(keys), first_(vertices + 1, 0), index_(keys.size())
  {
    for(const Triangle_key& k : keys) ++first_[k.v[0] + 1];
    for(std::size_t v = 0; v < vertices; ++v) first_[v + 1] += first_[v];
    std::vector<std::size_t> next(first_.begin(), first_.end() - 1);
    for(std::size_t i = 0; i < keys.size(); ++i) index_[next[keys[i].v[0]]++] = i;
  }

  std::size_t size() const { return keys_.size(); }

  // The position of k in the list (the first one if listed twice), or none.
  std::size_t find(const Triangle_key& k) const
  {
    if(k.v[0] + std::size_t(1) >= first_.size()) return none; // the ghost, or not a listed vertex
    for(std::size_t j = first_[k.v[0]]; j < first_[k.v[0] + 1]; ++j)
      if(keys_[index_[j]] == k) return index_[j];
    return none;
  }

  // The positions of the triangles whose smallest vertex is v, in list order.
  const std::size_t* begin(std::size_t v) const { return index_.data() + first_[v]; }
  const std::size_t* end(std::size_t v) const { return index_.data() + first_[v + 1]; }

private:
  const std::vector<Triangle_key>& keys_;
  std::vector<std::size_t> first_;
  std::vector<std::size_t> index_;
};

// Which listed triangles are facets of m's live tetrahedra: found[i] for
// triangle i of `lookup`.  `on_facet(t, f)` sees every
// facet f of tetrahedron t that is listed (a ghost's one facet, 3,
// included).  The slots are cut into one run per thread: `on_facet` may
// run concurrently, never twice at once for the same t.
template <class On_facet>
std::vector<char> listed_facets(const Flat_storage& m, const Triangles_by_smallest_vertex& lookup, int threads,
                                const On_facet& on_facet)
{
  const std::size_t slots = m.number_of_slots(), listed = lookup.size();
  const int chunks = chunk_count(slots, threads);
  // Two runs may find the same triangle (its two sides): each has its own flags.
  std::vector<std::vector<char>> found(chunks, std::vector<char>(listed, 0));
  for_each_chunk(chunks, [&](int c) {
    const Tet_id end = static_cast<Tet_id>(chunk_begin(slots, chunks, c + 1));
    for(Tet_id t = static_cast<Tet_id>(chunk_begin(slots, chunks, c)); t < end; ++t) {
      if(!m.is_live(t)) continue;
      for(int f = m.is_ghost(t) ? 3 : 0; f < 4; ++f) {
        const std::size_t i = lookup.find(facet_key(m, t, f));
        if(i == Triangles_by_smallest_vertex::none) continue;
        found[c][i] = 1;
        on_facet(t, f);
      }
    }
  });
  for(int c = 1; c < chunks; ++c)
    for(std::size_t i = 0; i < listed; ++i) found[0][i] |= found[c][i];
  return std::move(found[0]);
}

struct Constrained_mesh
{
  Flat_storage mesh;
  std::vector<int> subdomain;            // per slot
  std::vector<std::uint8_t> constrained; // per slot, bit f: facet f is an input triangle
  Size_field size;                       // h: per vertex, and the user's bounds
  std::vector<Vertex_id> vertex_of_input; // surface point -> vertex id
  // The input's bounding box, and filters valid for points inside it.
  double box_lo[3] = {0, 0, 0}, box_hi[3] = {0, 0, 0};
  Static_filter filter;
  int number_of_subdomains = 0;

  bool in_box(const double* p) const
  {
    for(int a = 0; a < 3; ++a)
      if(!(p[a] >= box_lo[a] && p[a] <= box_hi[a])) return false;
    return true;
  }

  void fit_slot_arrays()
  {
    subdomain.resize(mesh.number_of_slots(), 0);
    constrained.resize(mesh.number_of_slots(), 0);
  }
  bool is_constrained(Tet_id t, int f) const { return (constrained[t] >> f) & 1; }

  // Exact validity, for debug builds and tests: symmetric adjacency across
  // facets with the same vertices, positive finite tetrahedra, constrained
  // flags and ghost-free subdomains agreeing on both sides.
  bool is_valid(std::string* why = nullptr) const
  {
    auto fail = [why](const std::string& what) {
      if(why) *why = what;
      return false;
    };
    for(Tet_id t = 0; t < mesh.number_of_slots(); ++t) {
      if(!mesh.is_live(t)) continue;
      const Vertex_id* tv = mesh.vertex_ids(t);
      if(!mesh.is_ghost(t) &&
         predicates_detail::orientation_exact(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(tv[3])) <= 0)
        return fail("tetrahedron " + std::to_string(t) + " is not positively oriented");
      if(mesh.is_ghost(t) && subdomain[t] != 0) return fail("a ghost tetrahedron in a subdomain");
      for(int f = 0; f < 4; ++f) {
        const Facet_code back = mesh.neighbor_code(t, f);
        const Tet_id u = tet_of(back);
        if(u >= mesh.number_of_slots() || !mesh.is_live(u)) return fail("neighbour is not live");
        if(mesh.neighbor_code(back) != facet_code(t, f)) return fail("adjacency is not symmetric");
        Vertex_id a[3], b[3];
        for(int i = 0; i < 3; ++i) {
          a[i] = tv[facet_vertex[f][i]];
          b[i] = mesh.vertex(u, facet_vertex[facet_of(back)][i]);
        }
        std::sort(a, a + 3);
        std::sort(b, b + 3);
        if(!std::equal(a, a + 3, b)) return fail("neighbours do not share the facet's vertices");
        if(is_constrained(t, f) != is_constrained(u, facet_of(back)))
          return fail("constrained flag differs on the two sides of a facet");
        if(!is_constrained(t, f) && subdomain[t] != subdomain[u])
          return fail("two subdomains meet at an unconstrained facet");
      }
    }
    return true;
  }
};

// The box spanned by `points` and its filters (refinement only adds points
// inside the convex hull).
inline void set_box(const std::vector<std::array<double, 3>>& points, Constrained_mesh& cm)
{
  for(int a = 0; a < 3; ++a) {
    cm.box_lo[a] = points.front()[a];
    cm.box_hi[a] = points.front()[a];
  }
  for(const auto& p : points)
    for(int a = 0; a < 3; ++a) {
      cm.box_lo[a] = std::min(cm.box_lo[a], p[a]);
      cm.box_hi[a] = std::max(cm.box_hi[a], p[a]);
    }
  cm.filter = Static_filter::for_box(cm.box_lo, cm.box_hi);
}

// Flat arrays with ghost tetrahedra from finite, positively oriented
// tetrahedra whose boundary is closed (a ghost on each boundary facet).
// Throws std::invalid_argument naming the facet or the edge where that is
// not so: a facet in three or more tetrahedra, a boundary edge in other
// than two boundary facets (volumes meeting at an edge only, or an open
// boundary).
inline Flat_storage flat_storage_from_tetrahedra(const std::vector<std::array<double, 3>>& points,
                                                 const std::vector<std::array<Vertex_id, 4>>& tets)
{
  Flat_storage m;
  m.with_sub_determinants = false;
  m.vertices.resize(points.size());
  for(std::size_t i = 0; i < points.size(); ++i) {
    Vertex_record& r = m.vertices[i];
    r.xyz[0] = points[i][0]; r.xyz[1] = points[i][1]; r.xyz[2] = points[i][2];
    r.scratch = 0;
  }
  m.resize_tets(tets.size());
  for(std::size_t t = 0; t < tets.size(); ++t)
    for(int i = 0; i < 4; ++i) m.tets[t].v[i] = tets[t][i];

  // Facets bucketed by their smallest vertex, then each bucket, a few dozen
  // facets, sorted: the same order as sorting all 4T facet keys, which took
  // most of this function's time.  Equal keys are the two sides of a facet;
  // a lone key is a hull facet.  Facet f of tetrahedron t is key 4 t + f.
  std::vector<Triangle_key> keys(4 * tets.size());
  for(Tet_id t = 0; t < tets.size(); ++t)
    for(int f = 0; f < 4; ++f) keys[4 * std::size_t(t) + f] = facet_key(m, t, f);
  const Triangles_by_smallest_vertex buckets(keys, points.size());
  auto code_of = [](std::size_t k) { return facet_code(static_cast<Tet_id>(k / 4), static_cast<int>(k % 4)); };
  std::vector<Facet_code> hull;
  std::vector<std::size_t> bucket;
  for(std::size_t v = 0; v < points.size(); ++v) {
    bucket.assign(buckets.begin(v), buckets.end(v));
    std::sort(bucket.begin(), bucket.end(), [&](std::size_t x, std::size_t y) { return keys[x] < keys[y]; });
    for(std::size_t k = 0; k < bucket.size();) {
      if(k + 1 < bucket.size() && keys[bucket[k]] == keys[bucket[k + 1]]) {
        std::size_t run = 2;
        while(k + run < bucket.size() && keys[bucket[k]] == keys[bucket[k + run]]) ++run;
        if(run > 2) {
          const Triangle_key& key = keys[bucket[k]];
          throw std::invalid_argument("the facet (" + std::to_string(key.v[0]) + ", " + std::to_string(key.v[1]) +
                                      ", " + std::to_string(key.v[2]) + ") is in " + std::to_string(run) +
                                      " tetrahedra");
        }
        m.neighbor_code(code_of(bucket[k])) = code_of(bucket[k + 1]);
        m.neighbor_code(code_of(bucket[k + 1])) = code_of(bucket[k]);
        k += 2;
      } else {
        hull.push_back(code_of(bucket[k]));
        k += 1;
      }
    }
  }

  // Ghost (a, b, c, ghost) on hull facet (a, b, c) listed as facet_vertex
  // lists it: the finite side then has negative orientation, as CGAL's
  // infinite cells and ghost_cell_in_conflict expect.
  struct Keyed_edge { Vertex_id a, b; Facet_code code; };
  std::vector<Keyed_edge> edges;
  const Tet_id first_ghost = tets.size();
  m.resize_tets(tets.size() + hull.size());
  for(std::size_t k = 0; k < hull.size(); ++k) {
    const Tet_id g = first_ghost + k;
    const Tet_id t = tet_of(hull[k]);
    const int f = facet_of(hull[k]);
    Tet_record& r = m.tets[g];
    for(int i = 0; i < 3; ++i) r.v[i] = m.tets[t].v[facet_vertex[f][i]];
    r.v[3] = ghost_vertex;
    r.n[3] = hull[k];
    m.neighbor_code(hull[k]) = facet_code(g, 3);
    for(int i = 0; i < 3; ++i) {
      const Vertex_id a = r.v[(i + 1) % 3], b = r.v[(i + 2) % 3];
      edges.push_back({std::min(a, b), std::max(a, b), facet_code(g, i)});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const Keyed_edge& x, const Keyed_edge& y) {
    return x.a != y.a ? x.a < y.a : x.b < y.b;
  });
  for(std::size_t k = 0; k < edges.size(); k += 2) {
    std::size_t run = 1;
    while(k + run < edges.size() && edges[k + run].a == edges[k].a && edges[k + run].b == edges[k].b) ++run;
    if(run != 2)
      throw std::invalid_argument("the boundary edge (" + std::to_string(edges[k].a) + ", " +
                                  std::to_string(edges[k].b) + ") is in " + std::to_string(run) +
                                  " boundary facets, not two");
    m.neighbor_code(edges[k].code) = edges[k + 1].code;
    m.neighbor_code(edges[k + 1].code) = edges[k].code;
  }
  m.live_tets = tets.size() + hull.size();
  m.ghost_tets = hull.size();
  return m;
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_CONSTRAINED_MESH_H
