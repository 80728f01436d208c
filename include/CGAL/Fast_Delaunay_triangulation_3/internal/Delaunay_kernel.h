// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The Delaunay kernel (paper §2.1, Algorithm 1): insert one point into a
// Delaunay triangulation held in Flat_storage, in three steps
//   WALK          visibility walk from a hint to a tetrahedron containing p;
//   CAVITY        breadth-first search of the tetrahedra in conflict with p (§2.4);
//   DELAUNAYBALL  one new tetrahedron per cavity boundary facet, adjacencies
//                 found through the cavity adjacency table (§2.5).
// The kernel allocates nothing per point: buffers live in Insertion_scratch.
// Ghost tetrahedra (§2.6) keep the ghost vertex in slot 3.

#ifndef CGAL_FDT3_INTERNAL_DELAUNAY_KERNEL_H
#define CGAL_FDT3_INTERNAL_DELAUNAY_KERNEL_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Sub_determinants.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Facet f of a positively oriented tetrahedron (v0, v1, v2, v3), as the
// slots (a, b, c) of an even permutation (v_f, a, b, c) of the tetrahedron:
// replacing v_f by any point on v_f's side of the facet keeps (x, a, b, c)
// positively oriented.  Used for the cavity boundary facets, whose new
// tetrahedron is (p, a, b, c).
constexpr int facet_vertex[4][3] = {{1, 2, 3}, {0, 3, 2}, {0, 1, 3}, {0, 2, 1}};

// aborted: the point met another partition (or its partition's slots ran
// out) and is tried again later; rejected: dropped for good by the caller's
// own rules (the mesher's refinement), never returned by the Delaunay kernel.
enum class Insertion_result { inserted, duplicate, aborted, rejected };

// A facet of the cavity boundary: the new tetrahedron (p, v[0], v[1], v[2]),
// rotated so that a ghost vertex comes last, and the facet code of the
// tetrahedron outside the cavity that shares it.
struct Boundary_facet
{
  Vertex_id v[3];
  std::uint8_t local[3]; // numbers of v[] on the cavity boundary (0 = ghost), see number_vertex
  std::uint8_t unused;
  Facet_code outside;
};
static_assert(sizeof(Boundary_facet) <= 24, "boundary facet record");

// The next walk's start: of the new tetrahedra (one per boundary facet, in
// the same order), the one whose boundary facet has its centroid nearest to
// q; 0 if all facets are on the hull.  Every new tetrahedron has the
// inserted point as a vertex, so a walk from an arbitrary one first turns
// around that point (5.1 steps per point on uniform input); from this one,
// 2.1.  The facets' vertices were just read to build the ball, so the scan
// runs in cache.
inline std::size_t nearest_boundary_facet(const Flat_storage& m, const Boundary_facet* facets, std::size_t n,
                                          const double* q)
{
  std::size_t best = 0;
  double best_distance = std::numeric_limits<double>::infinity();
  for(std::size_t k = 0; k < n; ++k) {
    const Boundary_facet& b = facets[k];
    if(b.v[2] == ghost_vertex) continue;
    const double *a = m.point(b.v[0]), *c = m.point(b.v[1]), *d = m.point(b.v[2]);
    const double x = a[0] + c[0] + d[0] - 3 * q[0], y = a[1] + c[1] + d[1] - 3 * q[1],
                 z = a[2] + c[2] + d[2] - 3 * q[2];
    const double distance = x * x + y * y + z * z;
    if(distance < best_distance) {
      best_distance = distance;
      best = k;
    }
  }
  return best;
}

// Counters and optional per-phase times (paper Table 1).
struct Kernel_statistics
{
  std::uint64_t inserted = 0, duplicates = 0, aborted = 0;
  std::uint64_t walk_steps = 0;
  std::uint64_t cavity_tets = 0, ball_tets = 0;
  std::uint64_t conflict_tests = 0;
  std::uint64_t small_cavities = 0, large_cavities = 0; // adjacency table vs. sorted fallback
  double walk_seconds = 0, cavity_seconds = 0, ball_seconds = 0;

  void add(const Kernel_statistics& o)
  {
    inserted += o.inserted; duplicates += o.duplicates; aborted += o.aborted; walk_steps += o.walk_steps;
    cavity_tets += o.cavity_tets; ball_tets += o.ball_tets; conflict_tests += o.conflict_tests;
    small_cavities += o.small_cavities; large_cavities += o.large_cavities;
    walk_seconds += o.walk_seconds; cavity_seconds += o.cavity_seconds; ball_seconds += o.ball_seconds;
  }
};

// Per-thread buffers of the kernel.
struct Insertion_scratch
{
  // The adjacency table is indexed by directed edges between cavity boundary
  // vertices numbered 0..31 (0 is the ghost); the paper's n_max = 32 covers
  // cavities of up to 60 boundary facets.
  static constexpr int table_size = 32;

  // Raw arrays: the cavity search fills them through plain pointers and sets
  // their sizes at the end, without a capacity check per element.
  Raw_array<Tet_id> cavity;              // BFS queue, then the deleted tetrahedra
  Raw_array<Boundary_facet> boundary;    // facets of the cavity boundary
  Raw_array<Facet_code> boundary_inner;  // the same facets seen from the cavity, while searching
  Raw_array<Tet_id> ball;              // slots of the new tetrahedra
  Raw_array<Vertex_id> boundary_vertices;  // numbered cavity boundary vertices, in order
  struct Half_edge { std::uint64_t key; Facet_code facet; };
  std::vector<Half_edge> large_edges;     // hash table of the large cavities' edges
  Facet_code edge_table[table_size * table_size];
  std::uint32_t random_state = 0x9e3779b9u;
  bool timed = false;
  Kernel_statistics stats;
  // Changes of Flat_storage::live_tets / ghost_tets, applied by the caller
  // (partitioned insertions run several kernels at once).
  std::ptrdiff_t live_delta = 0, ghost_delta = 0;

  unsigned next_random()
  {
    // xorshift32: only picks the first facet a walk step looks at.
    random_state ^= random_state << 13;
    random_state ^= random_state >> 17;
    random_state ^= random_state << 5;
    return random_state;
  }
};

// Glues facets 1, 2, 3 of the new tetrahedra ball[k] = (p, boundary[k].v),
// already written, to one another; for cavities with more than 31 boundary
// vertices, whose vertices have no small numbers for the adjacency table.
// Large cavities (the mesher's first refinement passes make cavities of
// hundreds of tetrahedra): the directed boundary edges in an open-addressing
// hash table twice their number, then each edge finds its reverse there.
// Linear in the cavity; the sort and binary searches it replaces were most
// of the mesher's ball time.
inline void glue_ball_by_edge_hash(Flat_storage& m, const Boundary_facet* boundary, const Tet_id* ball,
                                   std::size_t facets, std::vector<Insertion_scratch::Half_edge>& table)
{
  auto key = [](Vertex_id from, Vertex_id to) { return (static_cast<std::uint64_t>(from) << 32) | to; };
  // Vertex ids are below 2^31: no edge has this key.
  constexpr std::uint64_t empty = ~std::uint64_t(0);
  std::size_t capacity = 64;
  while(capacity < 6 * facets) capacity *= 2;
  const int shift = 64 - __builtin_ctzll(capacity);
  table.assign(capacity, {empty, 0});
  auto slot_of = [&](std::uint64_t k) { return static_cast<std::size_t>((k * 0x9e3779b97f4a7c15ull) >> shift); };
  auto put = [&](std::uint64_t k, Facet_code facet) {
    std::size_t i = slot_of(k);
    while(table[i].key != empty) i = (i + 1) & (capacity - 1);
    table[i] = {k, facet};
  };
  auto find = [&](std::uint64_t k) -> Facet_code {
    std::size_t i = slot_of(k);
    while(table[i].key != k) {
      CGAL_assertion(table[i].key != empty);
      i = (i + 1) & (capacity - 1);
    }
    return table[i].facet;
  };
  for(std::size_t k = 0; k < facets; ++k) {
    const Boundary_facet& b = boundary[k];
    put(key(b.v[1], b.v[2]), facet_code(ball[k], 1));
    put(key(b.v[2], b.v[0]), facet_code(ball[k], 2));
    put(key(b.v[0], b.v[1]), facet_code(ball[k], 3));
  }
  // Facet i of a new tetrahedron holds p and the edge opposite b.v[i - 1];
  // across it lies the tetrahedron that has the same edge reversed.
  for(std::size_t k = 0; k < facets; ++k) {
    const Boundary_facet& b = boundary[k];
    m.neighbor_code(facet_code(ball[k], 1)) = find(key(b.v[2], b.v[1]));
    m.neighbor_code(facet_code(ball[k], 2)) = find(key(b.v[0], b.v[2]));
    m.neighbor_code(facet_code(ball[k], 3)) = find(key(b.v[1], b.v[0]));
  }
}

// Recomputes the cached sub-determinants of tetrahedron t from its vertices.
inline void update_sub_determinants(Flat_storage& m, Tet_id t)
{
  const Vertex_id* tv = m.vertex_ids(t);
  double* s = &m.tet_sub_determinants[4 * t];
  if(tv[3] == ghost_vertex)
    compute_ghost_normal(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), s);
  else
    compute_sub_determinants(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]), s);
}

constexpr Tet_id no_tet = Tet_id(-1);

// INIT (paper Algorithm 1): the empty storage `mesh` (its vertex records
// written) becomes the tetrahedron of the four given vertices, not coplanar,
// and the four ghosts on its facets.  `simplex` is reordered to be
// positively oriented.
inline void make_initial_tetrahedron(Flat_storage& mesh, Vertex_id simplex[4])
{
  if(orientation(mesh.point(simplex[0]), mesh.point(simplex[1]), mesh.point(simplex[2]),
                 mesh.point(simplex[3])) < 0)
    std::swap(simplex[2], simplex[3]);
  mesh.free_tets.clear();
  mesh.tets.clear();
  mesh.tet_sub_determinants.clear();
  for(int t = 0; t < 5; ++t) mesh.new_tet();
  for(int i = 0; i < 4; ++i) mesh.vertex_ids(0)[i] = simplex[i];
  // The ghost f + 1 on facet f sees that facet from outside: (a, b, c, ghost)
  // with (a, b, c) = facet_vertex[f], an even permutation of the reversed
  // facet.  Its facet i < 3, opposite simplex[k] with k = facet_vertex[f][i],
  // holds the ghost and the edge that facet f shares with facet k: it is the
  // facet of ghost k + 1 opposite simplex[f].
  for(int f = 0; f < 4; ++f) {
    Vertex_id* g = mesh.vertex_ids(f + 1);
    for(int i = 0; i < 3; ++i) g[i] = simplex[facet_vertex[f][i]];
    g[3] = ghost_vertex;
    mesh.tets[0].n[f] = facet_code(f + 1, 3);
    mesh.tets[f + 1].n[3] = facet_code(0, f);
    for(int i = 0; i < 3; ++i) {
      const int k = facet_vertex[f][i];
      const int j = static_cast<int>(std::find(facet_vertex[k], facet_vertex[k] + 3, f) - facet_vertex[k]);
      mesh.tets[f + 1].n[i] = facet_code(k + 1, j);
    }
  }
  if(mesh.with_sub_determinants)
    for(Tet_id t = 0; t < 5; ++t) update_sub_determinants(mesh, t);
  mesh.live_tets = 5;
  mesh.ghost_tets = 4;
}

// The first point off the plane of a triangulation of dimension 2: `mesh`
// holds the triangles of CGAL's dimension 2 (Lower_dimensions.h: consistently
// oriented, the infinite vertex in any slot, one infinite triangle per hull
// edge) and `apex` is a vertex not in their plane.  Each triangle becomes in
// its slot the tetrahedron of it and the apex, an infinite triangle (hull
// edge ab) the ghost on the hull facet (a, b, apex), and each finite
// triangle gets a ghost under it in a free or new slot.  This is what CGAL's
// insertion outside the affine hull does: every circumscribed sphere of a
// cone cuts the plane in the empty circumcircle of its triangle, so the
// tetrahedra are Delaunay; for a point of the plane on such a sphere, the
// apex's term in the perturbed in-sphere test is the orientation of four
// coplanar points, zero, and the other terms decide as the perturbed
// in-circle test did, so they are the tetrahedra of the symbolic
// perturbation too (tested against CGAL on cocircular grids and circles).
// Linear in the triangles, against a fresh 3D insertion of all the points,
// whose coplanar ones are all degenerate for the 3D predicates.
inline void cone_over_triangles(Flat_storage& mesh, Vertex_id apex)
{
  const Tet_id slots = mesh.number_of_slots();
  // The triangles as they were: their neighbour codes are read while the
  // slots are rewritten.
  std::vector<Tet_record> flat(mesh.tets.begin(), mesh.tets.end());
  // Triangle slots (the ghosts below take free slots, which are not).
  auto triangle = [&](Tet_id t) { return t < slots && (flat[t].v[0] & mark_bit) == 0; };
  // Where triangle t has the infinite vertex; 3 for a finite triangle.
  auto infinite_index = [&](Tet_id t) {
    return flat[t].v[0] == ghost_vertex ? 0 : flat[t].v[1] == ghost_vertex ? 1 : flat[t].v[2] == ghost_vertex ? 2 : 3;
  };
  // Triangles are consistently oriented, so the apex lies on the same side
  // of every finite one: slot k of a tetrahedron holds vertex at[k] of its
  // triangle (at[] swaps 0 and 1 when the apex is below; its own inverse).
  int at[3] = {0, 1, 2};
  for(Tet_id t = 0; t < slots; ++t) {
    if(!triangle(t) || infinite_index(t) != 3) continue;
    const Vertex_id* tv = flat[t].v;
    if(orientation(mesh.point(tv[0]), mesh.point(tv[1]), mesh.point(tv[2]), mesh.point(apex)) < 0)
      std::swap(at[0], at[1]);
    break;
  }
  // Where each vertex of a triangle goes, by its index j in the triangle:
  // slot at[j] of the cone; slot under_at[j] of the ghost below (the cone's
  // facet 3 seen from outside); in the ghost of a hull edge whose triangle
  // has the infinite vertex at g, the apex takes slot at[g], the infinite
  // vertex slot 3 and the edge's other end j the slot left, 3 - at[g] - at[j].
  int under_at[3];
  for(int j = 0; j < 3; ++j) under_at[j] = facet_vertex[3][at[j]]; // facet_vertex[3] is its own inverse
  auto hull_at = [&](Tet_id t, int j) { return 3 - at[infinite_index(t)] - at[j]; };

  // The ghost under triangle t: its slot, or no_tet for a free or infinite slot.
  std::vector<Tet_id> below(slots, no_tet);
  std::size_t finite_count = 0, hull_edges = 0;
  for(Tet_id t = 0; t < slots; ++t) {
    if(!triangle(t)) continue;
    Vertex_id* tv = mesh.vertex_ids(t);
    const int g = infinite_index(t);
    if(g == 3) {
      ++finite_count;
      for(int j = 0; j < 3; ++j) tv[at[j]] = flat[t].v[j];
      tv[3] = apex;
      continue;
    }
    // (x, y, ghost, apex) in the slots at[] would be positive with a point
    // beyond the hull edge in the ghost's place, which is beyond the hull
    // facet of the apex too: moving the ghost to slot 3 and swapping the
    // other two (hull_at) keeps that orientation, the ghosts' convention.
    ++hull_edges;
    for(int j = 0; j < 3; ++j)
      if(j != g) tv[hull_at(t, j)] = flat[t].v[j];
    tv[at[g]] = apex;
    tv[3] = ghost_vertex;
  }
  mesh.reserve_tets(finite_count);
  for(Tet_id t = 0; t < slots; ++t) {
    if(!triangle(t) || infinite_index(t) != 3) continue;
    const Tet_id b = mesh.new_tet();
    below[t] = b;
    Vertex_id* bv = mesh.vertex_ids(b);
    for(int j = 0; j < 3; ++j) bv[under_at[j]] = flat[t].v[j];
    bv[3] = ghost_vertex;
  }
  for(Tet_id t = 0; t < slots; ++t) {
    if(!triangle(t)) continue;
    const int g = infinite_index(t);
    if(g == 3) {
      // Facet at[j] of the cone holds the apex and the edge opposite vertex
      // j: across it, the neighbouring triangle's cone or hull ghost; facet
      // 3 is the triangle itself, the ghost below across.  The ghost below
      // has the edge opposite j in its facet under_at[j]: across it, the
      // ghost below the neighbouring triangle, or the facet of the hull
      // ghost of that edge opposite its apex.
      const Tet_id b = below[t];
      for(int j = 0; j < 3; ++j) {
        const Facet_code across = flat[t].n[j];
        const Tet_id u = tet_of(across);
        const int i = facet_of(across);
        const int ug = infinite_index(u);
        mesh.tets[t].n[at[j]] = ug == 3 ? facet_code(u, at[i]) : facet_code(u, 3);
        mesh.tets[b].n[under_at[j]] = ug == 3 ? facet_code(below[u], under_at[i]) : facet_code(u, at[ug]);
      }
      mesh.tets[t].n[3] = facet_code(b, 3);
      mesh.tets[b].n[3] = facet_code(t, 3);
      continue;
    }
    // The hull ghost of edge xy: opposite the infinite vertex, the cone
    // across the edge; opposite the apex, the ghost below that cone; opposite
    // x (or y), the hull ghost of the other hull edge at y (or x).
    const Facet_code inner = flat[t].n[g];
    const Tet_id f = tet_of(inner);
    mesh.tets[t].n[3] = facet_code(f, at[facet_of(inner)]);
    mesh.tets[t].n[at[g]] = facet_code(below[f], under_at[facet_of(inner)]);
    for(int j = 0; j < 3; ++j) {
      if(j == g) continue;
      const Facet_code across = flat[t].n[j];
      const Tet_id h = tet_of(across);
      mesh.tets[t].n[hull_at(t, j)] = facet_code(h, hull_at(h, facet_of(across)));
    }
  }
  if(mesh.with_sub_determinants)
    for(Tet_id t = 0; t < mesh.number_of_slots(); ++t)
      if(mesh.is_live(t)) update_sub_determinants(mesh, t);
  mesh.live_tets = 2 * finite_count + hull_edges;
  mesh.ghost_tets = finite_count + hull_edges;
}

// Which tetrahedra a kernel may walk through, delete and refill (paper §3.2).
// Sequentially, all of them.
struct Sequential_ownership
{
  static constexpr bool partitioned = false;
  bool owns(const Flat_storage&, Tet_id) const { return true; }
  bool owns_across(const Vertex_id*, int) const { return true; }
};

// In a partitioned insertion, a tetrahedron belongs to a thread when all its
// finite vertices are in the thread's partition; the others (foreign or in
// the buffer zone) are never modified, so threads never touch the same
// tetrahedron: an outside neighbour of a cavity shares a facet of three owned
// vertices with it, hence cannot have three vertices of another partition,
// and nothing is written atomically.  The paper's rule (at most one vertex
// outside the partition) fails fewer walks near a surface, whose long
// tetrahedra join the two sides, but lets two cavities share an outside
// neighbour; the walk's detours (Delaunay_kernel::nearest_owned_around) do
// that job here instead (the manual has the measurements).
struct Partition_ownership
{
  static constexpr bool partitioned = true;
  const std::uint8_t* partition_of_vertex = nullptr;
  std::uint8_t partition = 0;

  bool owns(const Flat_storage& m, Tet_id t) const
  {
    const Vertex_id* tv = m.vertex_ids(t);
    return partition_of_vertex[tv[0]] == partition && partition_of_vertex[tv[1]] == partition &&
           partition_of_vertex[tv[2]] == partition &&
           (tv[3] == ghost_vertex || partition_of_vertex[tv[3]] == partition);
  }
  // Whether the kernel owns the tetrahedron of vertices `tv` entered from an
  // owned one through the facet opposite tv[i]: the three shared vertices
  // are owned, so only tv[i] is looked up (one load instead of four, and no
  // short-circuit for the branch predictor).  Across a hull facet (tv[i] the
  // ghost) the answer is yes: its vertex 0 is a shared one.
  bool owns_across(const Vertex_id* tv, int i) const
  {
    const Vertex_id w = tv[i] == ghost_vertex ? tv[0] : tv[i];
    return partition_of_vertex[w] == partition;
  }
};

// What a walk does past its step limit.  On a Delaunay triangulation the
// visibility walk cannot cycle, so the limit is only a guard against a
// corrupted state (an assertion, then a scan).  A refined mesh with
// constrained facets is not Delaunay any more and a visibility walk may
// cycle there: Walk_giving_up stops after a few thousand steps and reports
// no_tet, and the mesher drops the point.
struct Walk_to_the_end
{
  static constexpr bool gives_up = false;
  static constexpr std::uint64_t step_limit = 0; // unused: 64 + 8 * slots
};
struct Walk_giving_up
{
  static constexpr bool gives_up = true;
  static constexpr std::uint64_t step_limit = 4096;
};

// Where new tetrahedra slots come from: sequentially, the mesh's free list
// and then the end of the arrays.
struct Mesh_slots
{
  Flat_storage* mesh;
  bool reserve(std::size_t) { return true; }
  Tet_id take() { return mesh->new_tet(); }
  void give(Tet_id t) { mesh->free_tets.push_back(t); }
};

// Inserts points one at a time into a 3D Delaunay triangulation stored in a
// Flat_storage.  Preconditions of insert(): the storage holds a valid
// triangulation of dimension 3 with ghost tetrahedra, and the point's vertex
// record has been written; vertex scratch words are 0 at rest.  The
// sequential instantiation pays nothing for ownership (owns() is constant).
// Paths (Scalar_paths or Avx2_paths) chooses the forms of the walk's and the
// cavity search's predicates; both build the same triangulation.  A loop of
// insertions picks it once with with_vector_paths (see insert_in_order).
template <class Ownership = Sequential_ownership, class Slots = Mesh_slots, class Walk = Walk_to_the_end,
          class Paths = Default_paths>
class Delaunay_kernel
{
public:
  static constexpr bool partitioned = Ownership::partitioned;
  typedef Paths Vector_paths;

  Delaunay_kernel(Flat_storage& mesh, Insertion_scratch& scratch, Slots slots,
                  const Static_filter& filter = Static_filter(),
                  const Sub_determinant_filter& sub_filter = Sub_determinant_filter(),
                  const Ownership& ownership = Ownership())
      : m_(mesh), s_(scratch), slots_(slots), filter_(filter), sub_filter_(sub_filter), ownership_(ownership)
  {}

  Slots& slots() { return slots_; }
  const Insertion_scratch& scratch() const { return s_; }
  // Whether this kernel may walk through, delete and refill t (t live).
  bool owns(Tet_id t) const { return ownership_.owns(m_, t); }

  // Inserts vertex v.  `hint` is a live tetrahedron where the walk starts; on
  // return it is a tetrahedron near v, or, when the caller passes the point
  // it inserts next, the new tetrahedron nearest to that point.  A point
  // equal to an existing vertex is not inserted: `duplicate_of` receives that vertex.
  // Partitioned and aborted: `hint` is where a blocked walk stopped, else unchanged.
  Insertion_result insert(Vertex_id v, Tet_id& hint, Vertex_id& duplicate_of, const double* next = nullptr)
  {
    const double* p = m_.point(v);
    Clock::time_point t0, t1, t2, t3;
    if(s_.timed) t0 = Clock::now();
    const Tet_id start = walk(hint, p);
    if(s_.timed) t1 = Clock::now();
    if(Ownership::partitioned && start == no_tet) {
      // The next point, near this one along the curve, starts where this
      // walk stopped: from the last ball it would meet the same foreign
      // tetrahedra, and so would the points after it.
      if(blocked_at_ != no_tet) hint = blocked_at_;
      ++s_.stats.aborted;
      return Insertion_result::aborted;
    }

    if(!m_.is_ghost(start)) {
      for(int i = 0; i < 4; ++i) {
        const Vertex_id w = m_.vertex(start, i);
        if(same_point(m_.point(w), p)) {
          duplicate_of = w;
          hint = start;
          ++s_.stats.duplicates;
          if(s_.timed) s_.stats.walk_seconds += seconds(t0, t1);
          return Insertion_result::duplicate;
        }
      }
    }

    if(!cavity(start, p)) {
      ++s_.stats.aborted;
      return Insertion_result::aborted;
    }
    if(s_.timed) t2 = Clock::now();
    if(!delaunay_ball(v)) {
      ++s_.stats.aborted;
      return Insertion_result::aborted;
    }
    if(s_.timed) {
      t3 = Clock::now();
      s_.stats.walk_seconds += seconds(t0, t1);
      s_.stats.cavity_seconds += seconds(t1, t2);
      s_.stats.ball_seconds += seconds(t2, t3);
    }
    hint = s_.ball[next == nullptr ? 0 : nearest_boundary_facet(m_, s_.boundary.data(), s_.boundary.size(), next)];
    ++s_.stats.inserted;
    return Insertion_result::inserted;
  }

  // WALK: a tetrahedron whose closure contains p, or a ghost tetrahedron whose
  // hull facet sees p strictly.  Visibility walk with a random first facet
  // per step, which cannot cycle forever (Devillers, Pion, Teillaud 2002).
  // Partitioned: the walk enters only tetrahedra the kernel owns; where
  // every facet p lies beyond leads to another one, it goes around them
  // (nearest_owned_around) at most max_walk_detours times, then gives no_tet
  // and keeps where it stopped in blocked_at_.  no_tet too when the start is
  // not owned (the ghost start's real neighbour included) and, with
  // Walk_giving_up, past the step limit.
  Tet_id walk(Tet_id t, const double* p)
  {
    blocked_at_ = no_tet;
    if(m_.is_ghost(t)) t = m_.neighbor(t, 3);
    if(!ownership_.owns(m_, t)) return no_tet;
    Tet_id previous = Tet_id(-1);
    std::uint64_t steps = 0;
    int detours = 0;
    const std::uint64_t step_limit = Walk::gives_up ? Walk::step_limit : 64 + 8 * m_.number_of_slots();
    for(;;) {
      if(m_.is_ghost(t)) break;
      const Vertex_id* tv = m_.vertex_ids(t);
      const double* w[4] = {m_.point(tv[0]), m_.point(tv[1]), m_.point(tv[2]), m_.point(tv[3])};
      const int first = static_cast<int>(s_.next_random() & 3);
      // The four facet orientations at once; the bits say which are
      // certified negative (p strictly beyond) or positive by the static filter.
      int beyond = 0, before = 0;
#ifdef CGAL_FDT3_SIMD_RECORDS
      if constexpr(Paths::avx2)
        certified_facet_sides_of_records(w[0], w[1], w[2], w[3], p, filter_.orientation, beyond, before);
#endif
      Tet_id next = Tet_id(-1);
      // Partitioned: a facet p lies beyond may lead to a tetrahedron the
      // kernel does not own; the walk then takes another such facet if one
      // leads to an owned one (any choice among the facets p lies beyond
      // terminates in a Delaunay triangulation), and goes around the foreign
      // tetrahedra (nearest_owned_around) only if none does.
      bool blocked = false;
      auto step_to = [&](Tet_id u, Facet_code code) __attribute__((always_inline)) {
        const bool owned = ownership_.owns_across(m_.vertex_ids(u), facet_of(code));
        if(owned) next = u;
        else blocked = true;
        return owned;
      };
      for(int k = 0; k < 4; ++k) {
        const int f = (first + k) & 3;
        const Facet_code code = m_.neighbor_code(t, f);
        const Tet_id u = tet_of(code);
        if(u == previous) continue;
        if constexpr(Paths::avx2) {
          if(beyond & (1 << f)) {
            if(step_to(u, code)) break;
            continue;
          }
          if(before & (1 << f)) continue;
        }
        const double* q[4] = {w[0], w[1], w[2], w[3]};
        q[f] = p;
        if(orientation(filter_, q[0], q[1], q[2], q[3]) < 0 && step_to(u, code)) break;
      }
      if(next == Tet_id(-1)) {
        if constexpr(Ownership::partitioned) {
          if(blocked) {
            const Tet_id around = detours < max_walk_detours ? nearest_owned_around(t, p) : t;
            if(around == t) {
              blocked_at_ = t;
              s_.stats.walk_steps += steps;
              return no_tet;
            }
            ++detours;
            previous = Tet_id(-1);
            t = around;
            continue;
          }
        }
        break;
      }
      previous = t;
      t = next;
      if(++steps > step_limit) return Walk::gives_up ? no_tet : locate_by_scan(p);
    }
    s_.stats.walk_steps += steps;
    return t;
  }

  // A partitioned walk blocked by foreign tetrahedra between it and p may
  // still end in an owned one: on points near a surface the straight path
  // often dips into a long tetrahedron joining the two sides, while p lies
  // in a tetrahedron of the partition.  The walk then goes on from the owned
  // tetrahedron whose centroid is nearest p, among the first `detour_reach`
  // ones found breadth first from t through owned tetrahedra; t itself when
  // none is nearer.
  static constexpr int max_walk_detours = 4;
  static constexpr int detour_reach = 32;
  Tet_id nearest_owned_around(Tet_id t, const double* p) const
  {
    auto squared_distance_to_centroid = [&](Tet_id u) {
      const Vertex_id* uv = m_.vertex_ids(u);
      double d = 0;
      for(int a = 0; a < 3; ++a) {
        const double c = 0.25 * (m_.point(uv[0])[a] + m_.point(uv[1])[a] + m_.point(uv[2])[a] + m_.point(uv[3])[a]);
        d += (c - p[a]) * (c - p[a]);
      }
      return d;
    };
    Tet_id reached[detour_reach];
    int n = 1;
    reached[0] = t;
    Tet_id nearest = t;
    double nearest_distance = squared_distance_to_centroid(t);
    for(int k = 0; k < n && n < detour_reach; ++k) {
      for(int f = 0; f < 4 && n < detour_reach; ++f) {
        const Facet_code code = m_.neighbor_code(reached[k], f);
        const Tet_id u = tet_of(code);
        if(m_.is_ghost(u) || std::find(reached, reached + n, u) != reached + n ||
           !ownership_.owns_across(m_.vertex_ids(u), facet_of(code)))
          continue;
        reached[n++] = u;
        const double d = squared_distance_to_centroid(u);
        if(d < nearest_distance) {
          nearest_distance = d;
          nearest = u;
        }
      }
    }
    return nearest;
  }

  // Conflict test of a live tetrahedron with p (perturbed, never a tie).
  __attribute__((always_inline)) bool in_conflict(Tet_id t, const double* p) const
  {
    const Vertex_id* tv = m_.vertex_ids(t);
    if(m_.with_sub_determinants) {
      const double* s = &m_.tet_sub_determinants[4 * t];
      const int side = tv[3] == ghost_vertex
                           ? filtered_ghost_orientation(m_.point(tv[0]), s, p, sub_filter_)
                           : filtered_sub_determinant_side(m_.point(tv[0]), s, p, sub_filter_);
      if(side != 0) return side > 0;
    }
    if(tv[3] == ghost_vertex)
      return ghost_cell_in_conflict(m_.point(tv[0]), m_.point(tv[1]), m_.point(tv[2]), p, filter_);
    return finite_record_in_conflict<Paths>(m_.point(tv[0]), m_.point(tv[1]), m_.point(tv[2]),
                                            m_.point(tv[3]), p, filter_);
  }

  // CAVITY alone, as a query (CGAL's find_conflicts): the tetrahedra in
  // conflict with p grown from `start` (in conflict with p), with the same
  // perturbed test as an insertion.  `visit` runs while they carry the cavity
  // mark (is_live() false for them only), with the scratch's cavity and
  // boundary lists filled; then every mark and boundary number is removed,
  // so the mesh is bit for bit as before.
  template <class Visit>
  void conflict_zone(Tet_id start, const double* p, Visit&& visit)
  {
    CGAL_precondition(in_conflict(start, p));
    const bool complete = cavity(start, p);
    CGAL_assertion(complete); // only a partitioned kernel stops early
    (void)complete;
    visit();
    undo_cavity();
  }

  // DELAUNAYBALL on a hole the caller chose (CGAL's insert_in_hole): the
  // distinct live tetrahedra cells[0..n), star-shaped from vertex v's point,
  // are replaced by v joined to their boundary facets.  No test on p: the
  // hole need not be the conflict zone.  False, with the mesh as before, only
  // when a partition's slot supply cannot provide the extra tetrahedra.
  bool fill_hole(Vertex_id v, const Tet_id* cells, std::size_t n)
  {
    s_.cavity.resize(n);
    std::copy(cells, cells + n, s_.cavity.begin());
    s_.boundary_inner.clear();
    cavity_ghosts_ = 0;
    for(Tet_id t : s_.cavity) {
      CGAL_precondition(m_.is_live(t));
      m_.mark_free(t);
      cavity_ghosts_ += m_.is_ghost(t) ? 1 : 0;
    }
    for(Tet_id t : s_.cavity)
      for(int f = 0; f < 4; ++f)
        if(m_.is_live(m_.neighbor(t, f))) s_.boundary_inner.push_back(facet_code(t, f));
    complete_boundary();
    if(!delaunay_ball(v)) {
      ++s_.stats.aborted;
      return false;
    }
    ++s_.stats.inserted;
    return true;
  }

private:
  typedef std::chrono::steady_clock Clock;
  static double seconds(Clock::time_point a, Clock::time_point b)
  {
    return std::chrono::duration<double>(b - a).count();
  }

  // Fallback of the walk: cannot happen with exact predicates on a valid
  // triangulation, kept so a corrupted state is detected rather than looped on.
  Tet_id locate_by_scan(const double* p)
  {
    CGAL_assertion_msg(false, "visibility walk exceeded its step limit");
    for(Tet_id t = 0; t < m_.number_of_slots(); ++t)
      if(m_.is_live(t) && in_conflict(t, p)) return t;
    return 0;
  }

  // CAVITY: marks every tetrahedron in conflict with p as deleted and lists
  // the boundary facets.  Afterwards: s_.cavity holds exactly the deleted
  // tetrahedra, no tetrahedron carries the outside mark, and every boundary
  // facet has its outside tetrahedron live.  Partitioned: returns false, with
  // the mesh as before, when a tetrahedron in conflict is not owned.
  bool cavity(Tet_id start, const double* p)
  {
    Raw_array<Tet_id>& cavity = s_.cavity;
    Raw_array<Facet_code>& inner = s_.boundary_inner;
    // Both arrays are used up to their capacity; a popped tetrahedron adds at
    // most 4 entries to either, so capacity is checked once per pop.
    cavity.resize(std::max<std::size_t>(cavity.capacity(), 64));
    inner.resize(std::max<std::size_t>(inner.capacity(), 64));
    Tet_id* queue = cavity.data();
    Facet_code* facets = inner.data();
    std::size_t queued = 0, found = 0;

    // Whether a neighbour is in conflict is a coin toss that the branch
    // predictor cannot learn, and a mispredicted branch on it is resolved
    // only once the in-sphere determinant is known, ~40 cycles after its
    // loads.  So the outcome steers no branch: the neighbour is written both
    // as the next queue entry and as the next boundary candidate, and only
    // the counts move with it.  Boundary records, whose vertex numbering
    // branches, are built after the search (complete_boundary).
    // Returns false when a partitioned search meets a foreign tetrahedron in
    // conflict: the search stops there (a rare branch out of the loop, which
    // the sequential instantiation, always true, compiles away).
    auto visit = [&](Tet_id t, int f) __attribute__((always_inline)) -> bool {
      const Facet_code code = m_.neighbor_code(t, f);
      const Tet_id u = tet_of(code);
      Vertex_id* uv = m_.tets[u].v;
      if(uv[0] & mark_bit) return true; // in the cavity already
      // A tetrahedron touching the cavity through several facets is tested once.
      bool conflict = false;
      if(!(uv[1] & mark_bit)) {
        ++s_.stats.conflict_tests;
        // Partitioned: ownership is read whatever the outcome, so that the
        // only branch is on the rare foreign conflict, not on the coin toss.
        const bool owned = ownership_.owns_across(uv, facet_of(code));
        conflict = in_conflict(u, p);
        if(Ownership::partitioned && (conflict & !owned)) return false;
        cavity_ghosts_ += conflict & (uv[3] == ghost_vertex);
        uv[0] |= static_cast<Vertex_id>(conflict) << 31;
        uv[1] |= static_cast<Vertex_id>(!conflict) << 31;
      }
      prefetch_neighbors(u);
      // Queued as the facet through which it was entered, which the search
      // then does not look back through.
      queue[queued] = code;
      queued += conflict;
      facets[found] = facet_code(t, f);
      found += !conflict;
      return true;
    };

    cavity_ghosts_ = m_.is_ghost(start) ? 1 : 0;
    m_.mark_free(start);
    queue[queued++] = start;
    bool complete = visit(start, 0) && visit(start, 1) && visit(start, 2) && visit(start, 3);
    for(std::size_t k = 1; k < queued && complete; ++k) {
      if(queued + 3 > cavity.size()) {
        cavity.resize(2 * cavity.size());
        queue = cavity.data();
      }
      if(found + 3 > inner.size()) {
        inner.resize(2 * inner.size());
        facets = inner.data();
      }
      const Facet_code entered = static_cast<Facet_code>(queue[k]);
      const Tet_id t = tet_of(entered);
      const int back = facet_of(entered);
      if(!(visit(t, (back + 1) & 3) && visit(t, (back + 2) & 3) && visit(t, (back + 3) & 3))) {
        complete = false;
        break;
      }
    }
    for(std::size_t k = 1; k < queued; ++k) queue[k] = tet_of(static_cast<Facet_code>(queue[k]));
    cavity.resize(queued);
    inner.resize(found);
    if(!complete) {
      undo_search();
      return false;
    }
    static_assert(mark_bit == Vertex_id(1) << 31, "the marks are the top bits");
    complete_boundary();
    s_.stats.cavity_tets += queued;
    return true;
  }

  // The boundary records of the facets the search found: inner facet codes
  // (cavity side) become facets of new tetrahedra, with the outside
  // tetrahedron's code, vertex numbers, and the outside marks cleared.
  void complete_boundary()
  {
    const std::size_t found = s_.boundary_inner.size();
    s_.boundary.resize(found);
    Boundary_facet* facets = s_.boundary.data();
    // A closed triangulated surface of F facets has F / 2 + 2 vertices.
    s_.boundary_vertices.resize(found + 4);
    numbered_ = s_.boundary_vertices.data();
    numbered_count_ = 0;
    for(std::size_t k = 0; k < found; ++k) {
      const Facet_code code = s_.boundary_inner[k];
      const Facet_code outside = m_.neighbor_code(code);
      m_.unmark_outside(tet_of(outside));
      write_boundary_facet(facets[k], tet_of(code), facet_of(code), outside);
    }
    s_.boundary_vertices.resize(numbered_count_);
  }

  // A tetrahedron joins the cavity queue long before it is popped, and its
  // record (hence its neighbour codes) is in cache right now: fetching the
  // neighbours' records here hides the miss the pop would take.
  void prefetch_neighbors(Tet_id t) const
  {
    const Facet_code* n = m_.tets[t].n;
    for(int f = 0; f < 4; ++f) __builtin_prefetch(&m_.tets[tet_of(n[f])]);
  }

  // Puts back what an interrupted search changed: the cavity and outside
  // marks (no boundary record or vertex number exists yet).
  void undo_search()
  {
    for(Tet_id t : s_.cavity) m_.unmark_free(t);
    for(Facet_code code : s_.boundary_inner) m_.unmark_outside(tet_of(m_.neighbor_code(code)));
  }

  // Puts back what a complete CAVITY changed: cavity marks and boundary
  // vertex numbers (complete_boundary has cleared the outside marks).
  void undo_cavity()
  {
    for(Tet_id t : s_.cavity) m_.unmark_free(t);
    clear_boundary_numbers();
  }

  void clear_boundary_numbers()
  {
    for(Vertex_id v : s_.boundary_vertices) m_.vertices[v].scratch = 0;
  }

  void write_boundary_facet(Boundary_facet& record, Tet_id t, int f, Facet_code outside)
  {
    // t is in the cavity: its v[0] carries the mark.
    const Vertex_id* tv = m_.vertex_ids(t);
    Vertex_id a = tv[facet_vertex[f][0]] & ~mark_bit, b = tv[facet_vertex[f][1]] & ~mark_bit,
              c = tv[facet_vertex[f][2]] & ~mark_bit;
    // An even rotation keeps the orientation and puts the ghost in slot 3.
    if(a == ghost_vertex) {
      a = b; b = c; c = ghost_vertex;
    } else if(b == ghost_vertex) {
      b = a; a = c; c = ghost_vertex;
    }
    // Written field by field: building the record on the stack and copying
    // it stalled on store forwarding (measured 6% of the insertion time).
    record.v[0] = a;
    record.v[1] = b;
    record.v[2] = c;
    record.local[0] = number_vertex(a);
    record.local[1] = number_vertex(b);
    record.local[2] = number_vertex(c);
    record.outside = outside;
  }

  // DELAUNAYBALL: fills the cavity with (p, a, b, c) for every boundary facet.
  // Facet 0 of a new tetrahedron is the boundary facet; facets 1, 2, 3 contain
  // p and the boundary edges (b,c), (c,a), (a,b), and are glued to the new
  // tetrahedron on the other side of that edge, which sees it reversed.
  // Returns false, with the mesh as before the cavity, when the slot supply
  // cannot provide the extra tetrahedra (partitioned insertion only).
  bool delaunay_ball(Vertex_id p)
  {
    const std::size_t facets = s_.boundary.size();
    if(facets > s_.cavity.size() && !slots_.reserve(facets - s_.cavity.size())) {
      undo_cavity();
      return false;
    }
    take_ball_slots(facets);
    if(s_.boundary_vertices.size() < Insertion_scratch::table_size) {
      glue_with_table(p);
      ++s_.stats.small_cavities;
    } else {
      glue_with_edge_hash(p);
      ++s_.stats.large_cavities;
    }
    clear_boundary_numbers();
    s_.live_delta += static_cast<std::ptrdiff_t>(facets) - static_cast<std::ptrdiff_t>(s_.cavity.size());
    s_.stats.ball_tets += facets;
    return true;
  }

  // New tetrahedra reuse the cavity's slots (cache-hot), then free slots.
  void take_ball_slots(std::size_t facets)
  {
    Raw_array<Tet_id>& ball = s_.ball;
    ball.resize(facets);
    const std::size_t reused = std::min(facets, s_.cavity.size());
    std::copy(s_.cavity.begin(), s_.cavity.begin() + reused, ball.begin());
    for(std::size_t k = reused; k < s_.cavity.size(); ++k)
      slots_.give(s_.cavity[k]); // stays flagged deleted
    s_.ghost_delta -= static_cast<std::ptrdiff_t>(cavity_ghosts_);
    for(std::size_t k = reused; k < facets; ++k) ball[k] = slots_.take();
  }

  void write_ball_tet(Tet_id t, Vertex_id p, const Boundary_facet& b)
  {
    Tet_record& r = m_.tets[t];
    r.v[0] = p; r.v[1] = b.v[0]; r.v[2] = b.v[1]; r.v[3] = b.v[2];
    r.n[0] = b.outside;
    m_.neighbor_code(b.outside) = facet_code(t, 0);
    if(b.v[2] == ghost_vertex) ++s_.ghost_delta;
    if(m_.with_sub_determinants) update_sub_determinants(m_, t);
  }

  // Local numbers 1..31 of the cavity boundary vertices, for the adjacency
  // table, live in the vertex scratch words (0 = not numbered yet; the ghost
  // is always 0) and are cleared after the Delaunay ball.  Numbering happens
  // while the boundary facet is recorded, when the vertex is in cache anyway.
  // Past 31 vertices the numbers are meaningless (saturated) and the ball
  // uses the hashed fallback.
  // Whether v is new on the boundary is, again, a branch no predictor
  // learns: v is written at the end of the list either way and the count
  // moves only for a new one.
  std::uint8_t number_vertex(Vertex_id v)
  {
    if(v == ghost_vertex) return 0;
    std::uint64_t& tag = m_.vertices[v].scratch;
    const std::uint64_t old = tag;
    const bool fresh = old == 0;
    numbered_[numbered_count_] = v;
    numbered_count_ += fresh;
    const std::uint64_t number =
        fresh ? std::min<std::uint64_t>(numbered_count_, Insertion_scratch::table_size - 1) : old;
    tag = number;
    return static_cast<std::uint8_t>(number);
  }

  // Every table entry read in the second pass was written in the first: the
  // cavity boundary is a closed surface, so each directed edge appears once
  // in each direction.
  void glue_with_table(Vertex_id p)
  {
    constexpr unsigned n = Insertion_scratch::table_size;
    const std::size_t facets = s_.boundary.size();
    for(std::size_t k = 0; k < facets; ++k) {
      const Boundary_facet& b = s_.boundary[k];
      const unsigned a = b.local[0], bb = b.local[1], c = b.local[2];
      const Tet_id t = s_.ball[k];
      write_ball_tet(t, p, b);
      s_.edge_table[bb * n + c] = facet_code(t, 1);
      s_.edge_table[c * n + a] = facet_code(t, 2);
      s_.edge_table[a * n + bb] = facet_code(t, 3);
    }
    for(std::size_t k = 0; k < facets; ++k) {
      const Boundary_facet& b = s_.boundary[k];
      const unsigned a = b.local[0], bb = b.local[1], c = b.local[2];
      Facet_code* nb = m_.tets[s_.ball[k]].n;
      nb[1] = s_.edge_table[c * n + bb];
      nb[2] = s_.edge_table[a * n + c];
      nb[3] = s_.edge_table[bb * n + a];
    }
  }

  // Fallback for cavities with more than 31 boundary vertices.
  __attribute__((noinline)) void glue_with_edge_hash(Vertex_id p)
  {
    const std::size_t facets = s_.boundary.size();
    for(std::size_t k = 0; k < facets; ++k) write_ball_tet(s_.ball[k], p, s_.boundary[k]);
    glue_ball_by_edge_hash(m_, s_.boundary.data(), s_.ball.data(), facets, s_.large_edges);
  }

  Flat_storage& m_;
  Insertion_scratch& s_;
  Slots slots_;
  Static_filter filter_;
  Sub_determinant_filter sub_filter_;
  Ownership ownership_;
  std::size_t cavity_ghosts_ = 0;
  Vertex_id* numbered_ = nullptr; // boundary_vertices while complete_boundary() fills it
  std::size_t numbered_count_ = 0;
  Tet_id blocked_at_ = no_tet; // owned, where the last walk stopped blocked; else no_tet
};

// Does nothing: insert_in_order without progress reports.
struct No_progress_report
{
  void operator()(std::size_t) const {}
};

// Algorithm 1's loop: inserts the vertices of `points` (records written) in
// order with the sequential kernel, starting from `hint`.  For a duplicate v,
// duplicate_of[v - first_new] receives the vertex it equals.  With step > 0,
// report(i) follows the first i points every `step` points (the loop is cut
// into chunks, so the per-point path is unchanged and reads no clock).
// The predicates' forms are chosen once, here (with_vector_paths).
template <class Report = No_progress_report>
void insert_in_order(Flat_storage& m, const std::vector<Vertex_id>& points, Vertex_id first_new,
                     std::vector<Vertex_id>& duplicate_of, Tet_id& hint, const Static_filter& filter,
                     const Sub_determinant_filter& sub_filter, bool timed, Kernel_statistics& stats,
                     std::size_t step = 0, const Report& report = Report())
{
  Insertion_scratch scratch;
  scratch.timed = timed;
  if(!m.is_live(hint)) hint = m.first_live_tet();
  with_vector_paths([&](auto paths) {
    Delaunay_kernel<Sequential_ownership, Mesh_slots, Walk_to_the_end, decltype(paths)> kernel(
        m, scratch, Mesh_slots{&m}, filter, sub_filter);
    const std::size_t n = points.size();
    const std::size_t chunk = step == 0 ? n : step;
    for(std::size_t begin = 0; begin < n; begin += chunk) {
      const std::size_t end = std::min(n, begin + chunk);
      for(std::size_t i = begin; i < end; ++i) {
        const Vertex_id v = points[i];
        const double* next = i + 1 < n ? m.point(points[i + 1]) : nullptr;
        Vertex_id existing = ghost_vertex;
        if(kernel.insert(v, hint, existing, next) == Insertion_result::duplicate) {
          CGAL_assertion(v >= first_new);
          duplicate_of[v - first_new] = existing;
        }
      }
      if(step != 0) report(end);
    }
  });
  m.live_tets += scratch.live_delta;
  m.ghost_tets += scratch.ghost_delta;
  stats.add(scratch.stats);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_DELAUNAY_KERNEL_H
