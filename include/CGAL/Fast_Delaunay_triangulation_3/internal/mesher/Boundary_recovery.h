// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lines 2-3 of the paper's Algorithm 2: EMPTYMESH, the Delaunay
// triangulation of the surface vertices built by this package's engine, then
// RECOVERBOUNDARY, a mesh of the convex hull in which every input triangle
// is a facet, the surface neither moved nor split.
//
// When the empty mesh already has every input triangle (fine surface meshes
// often do) it is kept as it is.  Otherwise the recovery is local: the
// region of the empty mesh that the missing triangles cross (every
// tetrahedron whose closure may meet a missing triangle anywhere but at its
// corners; 7% to 13% of the empty mesh on CGAL's mechanical parts) falls
// apart into small components, each re-tetrahedralised alone while the rest
// of the empty mesh is kept: by flips of our own where a few suffice, else
// by TetGen (Debian's libtet1.5-dev; the paper used Gmsh's copy of TetGen's
// recovery) given the component as a piecewise linear complex (its walls,
// the missing triangles, the input triangles it holds), with no Steiner
// point on any of those facets.  TetGen's own Delaunay of all the surface
// points is not redone.
//
// Should TetGen refuse a component twice (hull facets left out, then as
// constraints), or return a mesh that does not fit its walls, the whole
// surface goes to TetGen as before (switch c keeps the convex hull, which
// the colouring needs to tell the outside).
// Both paths may add Steiner points strictly inside the region, never on an
// input triangle; they come after the surface points, whose ids stay.
//
// TetGen switches: p (a piecewise linear complex), Y (no Steiner point on
// the complex's facets), M (coplanar facets are not merged: a merged facet
// could be re-triangulated, and the region's boundary must come back as it
// went), O0 (no mesh optimisation: the refinement that follows replaces
// these tetrahedra anyway; -O's smoothing was 5% of TetGen's time on
// fandisk), z (numbering from 0), Q (quiet).

#ifndef CGAL_FDT3_INTERNAL_MESHER_BOUNDARY_RECOVERY_H
#define CGAL_FDT3_INTERNAL_MESHER_BOUNDARY_RECOVERY_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Tetrahedra_replacement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_core.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>

#include <tetgen.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

struct Recovery_report
{
  std::size_t missing_triangles = 0;  // input triangles not facets of the empty mesh
  bool used_tetgen = false;
  std::size_t region_tetrahedra = 0;  // empty-mesh tetrahedra re-meshed by the local recovery
  // The local recovery's components, counted when it succeeds (0 when
  // TetGen re-meshed the whole surface instead).
  std::size_t flipped_components = 0;  // region components recovered by flips of ours
  std::size_t tetgen_components = 0;   // region components recovered by TetGen
  bool whole_surface_to_tetgen = false; // the local recovery failed: TetGen re-meshed everything
  std::size_t steiner_points = 0;     // added by TetGen inside the volumes
  double empty_mesh_seconds = 0, recovery_seconds = 0;
};

// The input triangles, as sorted keys, in vertex ids of `vertex_of_input`.
inline std::vector<Triangle_key> input_triangle_keys(const Surface_soup& soup,
                                                     const std::vector<Vertex_id>& vertex_of_input)
{
  std::vector<Triangle_key> keys;
  keys.reserve(soup.triangles.size());
  for(const auto& t : soup.triangles)
    keys.push_back(Triangle_key::of(vertex_of_input[t[0]], vertex_of_input[t[1]], vertex_of_input[t[2]]));
  std::sort(keys.begin(), keys.end());
  return keys;
}

inline bool contains(const std::vector<Triangle_key>& sorted, const Triangle_key& k)
{
  return std::binary_search(sorted.begin(), sorted.end(), k);
}

// The sorted `wanted` keys that are not facets of a live tetrahedron of m,
// searched for on `threads` threads.
inline std::vector<Triangle_key> missing_facets(const Flat_storage& m, const std::vector<Triangle_key>& wanted,
                                                int threads = 1)
{
  const Triangles_by_smallest_vertex lookup(wanted, m.vertices.size());
  const std::vector<char> found = listed_facets(m, lookup, threads, [](Tet_id, int) {});
  std::vector<Triangle_key> missing;
  for(std::size_t i = 0; i < wanted.size(); ++i)
    if(!found[i]) missing.push_back(wanted[i]);
  return missing;
}

// EMPTYMESH with our engine.  On return `out.vertex_of_input` maps surface
// points to the engine's vertex ids.
inline void empty_mesh(const Surface_soup& soup, int threads, Constrained_mesh& out)
{
  Triangulation_core core;
  core.partitions = std::max(1, threads);
  core.set_sub_determinants(false);
  std::vector<double> xyz;
  xyz.reserve(3 * soup.points.size());
  for(const auto& p : soup.points) xyz.insert(xyz.end(), p.begin(), p.end());
  core.insert(xyz.data(), soup.points.size(), &out.vertex_of_input);
  if(core.dimension != 3) throw Invalid_surface("Tetrahedral_mesher: the surface points are coplanar");
  out.mesh = std::move(core.mesh);
}

// What TetGen returns: its points (the given ones first, unmoved, then the
// Steiner points) and its tetrahedra, positively oriented.
struct Tetgen_mesh
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<Vertex_id, 4>> tets;
};

// Points (x, y, z) and triangles (three point indices, from 0) as TetGen's
// piecewise linear complex; `in` owns the arrays (tetgenio frees them).
template <class Points, class Triangles>
void write_tetgen_plc(const Points& points, const Triangles& triangles, tetgenio& in)
{
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size());
  in.pointlist = new REAL[3 * points.size()];
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int a = 0; a < 3; ++a) in.pointlist[3 * i + a] = points[i][a];
  in.numberoffacets = static_cast<int>(triangles.size());
  in.facetlist = new tetgenio::facet[triangles.size()];
  for(std::size_t t = 0; t < triangles.size(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for(int i = 0; i < 3; ++i) f.polygonlist[0].vertexlist[i] = static_cast<int>(triangles[t][i]);
  }
}

// TetGen on the complex of `triangles` (indices into `points`).  Throws
// std::runtime_error when TetGen fails or moves a given point.
inline Tetgen_mesh tetgen_recovery(const std::vector<std::array<double, 3>>& points,
                                   const std::vector<std::array<Vertex_id, 3>>& triangles, const char* switches)
{
  tetgenio in, result;
  write_tetgen_plc(points, triangles, in);
  std::string s(switches);
  try {
    tetrahedralize(&s[0], &in, &result);
  } catch(int code) {
    std::ostringstream message;
    message << "Tetrahedral_mesher: TetGen's boundary recovery failed (TetGen error " << code << ")";
    throw std::runtime_error(message.str());
  }
  if(result.numberofpoints < in.numberofpoints || result.numberofcorners != 4)
    throw std::runtime_error("Tetrahedral_mesher: TetGen returned an unexpected mesh");

  Tetgen_mesh out;
  out.points.resize(static_cast<std::size_t>(result.numberofpoints));
  for(std::size_t i = 0; i < out.points.size(); ++i) {
    for(int a = 0; a < 3; ++a) out.points[i][a] = result.pointlist[3 * i + a];
    if(i < points.size() && out.points[i] != points[i])
      throw std::runtime_error("Tetrahedral_mesher: TetGen moved an input point");
  }
  out.tets.resize(static_cast<std::size_t>(result.numberoftetrahedra));
  for(std::size_t t = 0; t < out.tets.size(); ++t) {
    std::array<Vertex_id, 4>& tv = out.tets[t];
    for(int i = 0; i < 4; ++i) tv[i] = static_cast<Vertex_id>(result.tetrahedronlist[4 * t + i]);
    const int o = orientation(out.points[tv[0]].data(), out.points[tv[1]].data(), out.points[tv[2]].data(),
                              out.points[tv[3]].data());
    if(o == 0) throw std::runtime_error("Tetrahedral_mesher: TetGen returned a flat tetrahedron");
    if(o < 0) std::swap(tv[0], tv[1]);
  }
  return out;
}

// The recovered tetrahedra as flat arrays.  What flat_storage_from_tetrahedra
// refuses in a user's mesh can only be a recovery's fault here.
inline Flat_storage recovered_flat_storage(const std::vector<std::array<double, 3>>& points,
                                           const std::vector<std::array<Vertex_id, 4>>& tets)
{
  try {
    return flat_storage_from_tetrahedra(points, tets);
  } catch(const std::invalid_argument& e) {
    throw std::logic_error(std::string("Tetrahedral_mesher: the recovered mesh is not a closed tetrahedral mesh: ") +
                           e.what());
  }
}

// RECOVERBOUNDARY of the whole surface by TetGen; replaces out.mesh.  Vertex
// ids of the result are the input point numbers, then the Steiner points.
inline void recover_with_tetgen(const Surface_soup& soup, Constrained_mesh& out, Recovery_report& report)
{
  std::vector<std::array<Vertex_id, 3>> triangles(soup.triangles.size());
  for(std::size_t t = 0; t < triangles.size(); ++t)
    for(int i = 0; i < 3; ++i) triangles[t][i] = soup.triangles[t][i];
  const Tetgen_mesh result = tetgen_recovery(soup.points, triangles, "pYcMO0zQ");
  out.mesh = recovered_flat_storage(result.points, result.tets);
  out.vertex_of_input.resize(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i) out.vertex_of_input[i] = static_cast<Vertex_id>(i);
  report.used_tetgen = true;
  report.whole_surface_to_tetgen = true;
  report.steiner_points = result.points.size() - soup.points.size();
}

// True unless tetrahedron t (finite, positive) provably meets the closed
// triangle (a, b, c) of mesh vertices at most in vertices they share, that
// is unless a plane of t's facets or the triangle's plane separates them.
// Exact, and conservative: the nine edge-pair separating axes are not tried,
// so a few tetrahedra near the triangle are kept that need not be.
inline bool may_meet_triangle(const Flat_storage& m, Tet_id t, const Triangle_key& tri)
{
  const Vertex_id* tv = m.vertex_ids(t);
  auto is_triangle_vertex = [&](Vertex_id v) { return v == tri.v[0] || v == tri.v[1] || v == tri.v[2]; };
  auto is_tet_vertex = [&](Vertex_id v) { return v == tv[0] || v == tv[1] || v == tv[2] || v == tv[3]; };
  const double* abc[3] = {m.point(tri.v[0]), m.point(tri.v[1]), m.point(tri.v[2])};

  // On the triangle's plane, t may only have vertices of the triangle: t
  // then meets it in the face of t those vertices span, shared by both.
  // A corner of the triangle is on its plane without a test: every
  // tetrahedron of a corner's star has one, and the exact evaluation of
  // that zero was most of the region's time on flat-faced parts.
  int below = 0, above = 0;
  bool foreign_on_plane = false;
  for(int i = 0; i < 4; ++i) {
    if(is_triangle_vertex(tv[i])) continue;
    const int o = orientation(abc[0], abc[1], abc[2], m.point(tv[i]));
    below += o < 0;
    above += o > 0;
    if(o == 0) foreign_on_plane = true;
  }
  if(!foreign_on_plane && (below == 0 || above == 0)) return false;

  for(int f = 0; f < 4; ++f) {
    const double* w[3] = {m.point(tv[facet_vertex[f][0]]), m.point(tv[facet_vertex[f][1]]),
                          m.point(tv[facet_vertex[f][2]])};
    bool separated = true;
    for(int i = 0; i < 3 && separated; ++i) {
      // > 0: on t's side of facet f.  A corner that is a vertex of t is on
      // facet f (0) or is its opposite vertex (> 0, t being positive).
      if(is_tet_vertex(tri.v[i])) {
        separated = tri.v[i] != tv[f];
        continue;
      }
      separated = orientation(abc[i], w[0], w[1], w[2]) < 0;
    }
    if(separated) return false;
  }
  return true;
}

// A finite tetrahedron incident to each vertex (no_tet for a vertex of none).
inline std::vector<Tet_id> incident_tetrahedra(const Flat_storage& m)
{
  std::vector<Tet_id> incident(m.vertices.size(), no_tet);
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || m.is_ghost(t)) continue;
    for(int i = 0; i < 4; ++i) incident[m.vertex(t, i)] = t;
  }
  return incident;
}

// The region of the local recovery: in_region[t] for the finite
// tetrahedra that may meet a missing triangle elsewhere than at its corners.
// Outside it, every tetrahedron meets every input triangle in a face they
// share at most, so the region's boundary and the input triangles form a
// valid complex.  Per triangle, a search across facets from the finite star
// of its first corner (where the triangle leaves that corner): the
// tetrahedra a triangle meets are connected across facets, since it never
// passes through a mesh vertex other than its corners.
//
// The region falls apart into many small components (on fandisk 266, most
// of two to five tetrahedra), each recovered on its own: TetGen meshes the
// convex hull of what it is given, and the hull of the whole region is the
// hull of the part.  A component holds whole triangles: the conservative
// test lets in star tetrahedra that do not meet the triangle, unconnected
// to those that do, so a triangle's tetrahedra are joined explicitly.  A
// component made only of such tetrahedra has no missing triangle, and is
// left as it is.
struct Recovery_region
{
  std::vector<char> in_region;                   // per slot
  std::vector<Tet_id> tets;                      // grouped by component
  std::vector<std::size_t> component_begin;      // component c: [begin[c], begin[c + 1]) of tets
  std::vector<std::size_t> component_of_missing; // per missing triangle
  std::size_t number_of_components() const { return component_begin.size() - 1; }
};

// Union-find over tetrahedron slots, for the components.
class Tet_partition
{
public:
  explicit Tet_partition(std::size_t slots) : parent_(slots)
  {
    for(std::size_t t = 0; t < slots; ++t) parent_[t] = static_cast<Tet_id>(t);
  }
  Tet_id find(Tet_id t)
  {
    while(parent_[t] != t) {
      parent_[t] = parent_[parent_[t]];
      t = parent_[t];
    }
    return t;
  }
  void join(Tet_id s, Tet_id t) { parent_[find(s)] = find(t); }

private:
  std::vector<Tet_id> parent_;
};

// The tetrahedra that may meet each of a run of missing triangles: the
// run's k-th triangle's are tets[end_of[k - 1]..end_of[k]) (from 0 for the
// first), the first of them where it leaves its first corner.
struct Triangle_fronts
{
  std::vector<Tet_id> tets;
  std::vector<std::size_t> end_of;
};

// The fronts of the missing triangles [begin, end); reads the mesh only.
inline void search_fronts(const Flat_storage& m, const std::vector<Tet_id>& incident,
                          const std::vector<Triangle_key>& missing, std::size_t begin, std::size_t end,
                          Triangle_fronts& fronts)
{
  std::vector<std::uint32_t> seen(m.number_of_slots(), 0);
  std::uint32_t stamp = 0;
  std::vector<Tet_id> star;
  for(std::size_t i = begin; i < end; ++i) {
    const Triangle_key& tri = missing[i];
    ++stamp;
    const Vertex_id a = tri.v[0];
    CGAL_assertion(incident[a] != no_tet);
    star.assign(1, incident[a]);
    seen[incident[a]] = stamp;
    const std::size_t first = fronts.tets.size();
    for(std::size_t k = 0; k < star.size(); ++k) {
      const Tet_id t = star[k];
      if(may_meet_triangle(m, t, tri)) fronts.tets.push_back(t);
      for(int f = 0; f < 4; ++f) {
        const Tet_id u = m.neighbor(t, f);
        if(m.vertex(t, f) == a || m.is_ghost(u) || seen[u] == stamp) continue;
        seen[u] = stamp;
        star.push_back(u);
      }
    }
    // A missing triangle leaves its corner through some tetrahedron.
    CGAL_assertion(fronts.tets.size() > first);
    // A new stamp for the search: star tetrahedra rejected above are tested
    // again when the search reaches them, which is rare and cheap.
    ++stamp;
    for(std::size_t k = first; k < fronts.tets.size(); ++k) seen[fronts.tets[k]] = stamp;
    for(std::size_t k = first; k < fronts.tets.size(); ++k) {
      const Tet_id t = fronts.tets[k];
      for(int f = 0; f < 4; ++f) {
        const Tet_id u = m.neighbor(t, f);
        if(m.is_ghost(u) || seen[u] == stamp) continue;
        seen[u] = stamp;
        if(may_meet_triangle(m, u, tri)) fronts.tets.push_back(u);
      }
    }
    fronts.end_of.push_back(fronts.tets.size());
  }
}

// The searches run on `threads` threads, each on a run of the missing
// triangles (a search costs a few microseconds: runs of at least 64), and
// are joined in the triangles' order, as one thread would.
inline Recovery_region recovery_region(const Flat_storage& m, const std::vector<Triangle_key>& missing,
                                       int threads = 1)
{
  Recovery_region region;
  region.in_region.assign(m.number_of_slots(), 0);
  const std::vector<Tet_id> incident = incident_tetrahedra(m);
  const int runs = static_cast<int>(
      std::max<std::size_t>(1, std::min<std::size_t>(std::max(threads, 1), missing.size() / 64)));
  std::vector<Triangle_fronts> fronts(runs);
  for_each_chunk(runs, [&](int r) {
    search_fronts(m, incident, missing, chunk_begin(missing.size(), runs, r), chunk_begin(missing.size(), runs, r + 1),
                  fronts[r]);
  });
  Tet_partition partition(m.number_of_slots());
  std::vector<Tet_id> unsorted, met_by(missing.size());
  std::size_t i = 0;
  for(const Triangle_fronts& run : fronts)
    for(std::size_t k = 0, first = 0; k < run.end_of.size(); first = run.end_of[k++], ++i) {
      met_by[i] = run.tets[first];
      for(std::size_t j = first; j < run.end_of[k]; ++j) {
        const Tet_id t = run.tets[j];
        partition.join(t, met_by[i]);
        if(!region.in_region[t]) {
          region.in_region[t] = 1;
          unsorted.push_back(t);
        }
      }
    }
  for(Tet_id t : unsorted)
    for(int f = 0; f < 4; ++f) {
      const Tet_id u = m.neighbor(t, f);
      if(region.in_region[u]) partition.join(t, u);
    }

  // Components without a missing triangle leave the region.
  std::vector<char> needed(m.number_of_slots(), 0);
  for(Tet_id t : met_by) needed[partition.find(t)] = 1;
  std::vector<Tet_id> by_root;
  for(Tet_id t : unsorted) {
    if(needed[partition.find(t)]) by_root.push_back(t);
    else region.in_region[t] = 0;
  }
  std::sort(by_root.begin(), by_root.end(),
            [&](Tet_id s, Tet_id t) { return partition.find(s) < partition.find(t); });
  const std::size_t unset = std::size_t(-1);
  std::vector<std::size_t> component(m.number_of_slots(), unset);
  for(std::size_t k = 0; k < by_root.size(); ++k) {
    if(k == 0 || partition.find(by_root[k]) != partition.find(by_root[k - 1]))
      region.component_begin.push_back(k);
    component[by_root[k]] = region.component_begin.size() - 1;
  }
  region.component_begin.push_back(by_root.size());
  region.tets = std::move(by_root);
  for(Tet_id t : met_by) region.component_of_missing.push_back(component[t]);
  return region;
}

// A facet between a region tetrahedron and a kept one, in local vertex
// ids, listed as the region tetrahedron lists it: orientation(x, a, b, c)
// > 0 for x on the region's side.
struct Region_wall
{
  Triangle_key key;
  Vertex_id a, b, c;
  friend bool operator<(const Region_wall& x, const Region_wall& y) { return x.key < y.key; }
};

// A component as TetGen's input: its vertices numbered locally, and the
// complex of its walls, the missing triangles and the input triangles
// between two of its tetrahedra or on the convex hull.  Its other facets on
// the convex hull are left out: an input triangle in a hull plane may cross
// them (flat faces of mechanical parts: 14% to 28% of the missing triangles
// on couplingdown, anchor_dense and fandisk), so TetGen re-triangulates the
// convex hull of the component's points (switch c), and carve_region keeps
// what lies inside the walls.
struct Local_problem
{
  std::vector<Vertex_id> vertex_of_local;
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<Vertex_id, 3>> triangles; // local ids
  std::vector<Region_wall> walls;                  // sorted by key
  std::vector<std::array<Vertex_id, 3>> hull_facets; // with hull facets: those that are not input triangles
  double volume = 0;                               // six times the region's
};

// Component c of the region; `local` maps mesh vertices to local ids, all
// unset (Vertex_id(-1)) before and after.  `with_hull_facets`: the
// component's hull facets are constraints too (TetGen without switch c).
inline Local_problem local_problem(const Flat_storage& m, const Recovery_region& region, std::size_t c,
                                   const std::vector<Triangle_key>& input,
                                   const std::vector<Triangle_key>& missing_here, std::vector<Vertex_id>& local,
                                   bool with_hull_facets = false)
{
  Local_problem p;
  const Vertex_id unset = Vertex_id(-1);
  const Tet_id* first = region.tets.data() + region.component_begin[c];
  const Tet_id* last = region.tets.data() + region.component_begin[c + 1];
  for(const Tet_id* t = first; t != last; ++t) {
    const Vertex_id* tv = m.vertex_ids(*t);
    for(int i = 0; i < 4; ++i) {
      if(local[tv[i]] != unset) continue;
      local[tv[i]] = static_cast<Vertex_id>(p.vertex_of_local.size());
      p.vertex_of_local.push_back(tv[i]);
      p.points.push_back({m.point(tv[i])[0], m.point(tv[i])[1], m.point(tv[i])[2]});
    }
    p.volume += orientation_determinant(m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3]));
  }
  auto local_key = [&](const Triangle_key& k) { return Triangle_key::of(local[k.v[0]], local[k.v[1]], local[k.v[2]]); };

  std::vector<Triangle_key> facets;
  for(const Triangle_key& k : missing_here) facets.push_back(local_key(k));
  for(const Tet_id* it = first; it != last; ++it)
    for(int f = 0; f < 4; ++f) {
      const Tet_id t = *it;
      const Tet_id u = m.neighbor(t, f);
      const Triangle_key k = facet_key(m, t, f);
      if(m.is_ghost(u)) {
        const bool is_input = contains(input, k);
        if(with_hull_facets || is_input) facets.push_back(local_key(k));
        if(with_hull_facets && !is_input) {
          const Triangle_key h = local_key(k);
          p.hull_facets.push_back({h.v[0], h.v[1], h.v[2]});
        }
      } else if(!region.in_region[u]) {
        const Vertex_id* tv = m.vertex_ids(t);
        p.walls.push_back({local_key(k), local[tv[facet_vertex[f][0]]], local[tv[facet_vertex[f][1]]],
                           local[tv[facet_vertex[f][2]]]});
        facets.push_back(local_key(k));
      } else if(t < u && contains(input, k)) {
        facets.push_back(local_key(k));
      }
    }
  std::sort(p.walls.begin(), p.walls.end());
  // A missing triangle is never a region facet, but a wall may be an input
  // triangle: listed once.
  std::sort(facets.begin(), facets.end());
  facets.erase(std::unique(facets.begin(), facets.end()), facets.end());
  p.triangles.reserve(facets.size());
  for(const Triangle_key& k : facets) p.triangles.push_back({k.v[0], k.v[1], k.v[2]});
  for(Vertex_id v : p.vertex_of_local) local[v] = unset;
  return p;
}

// Whether the interiors of triangles a and b, which lie in one plane, meet:
// they do unless the line through an edge of one leaves the other on its
// outer side, the line included (separating axes of two convex polygons of
// the plane), each side decided exactly.
inline bool coplanar_interiors_meet(const std::array<const double*, 3>& a, const std::array<const double*, 3>& b)
{
  auto separates = [](const std::array<const double*, 3>& x, const std::array<const double*, 3>& y) {
    for(int e = 0; e < 3; ++e) {
      bool outside = true;
      for(int k = 0; k < 3 && outside; ++k)
        outside = predicates_detail::coplanar_orientation_exact(x[e], x[(e + 1) % 3], x[(e + 2) % 3], y[k]) <= 0;
      if(outside) return true;
    }
    return false;
  };
  return !separates(a, b) && !separates(b, a);
}

// Whether a hull facet of the problem and another of its triangles lie in
// one plane with interiors that meet (an input triangle in a hull plane
// crossing it).  TetGen is not given such a complex: on it, TetGen crashed
// the process (a segmentation fault), as it did on 10 of fandisk's 39
// components when their hull facets were constraints.
inline bool hull_facet_crosses_a_triangle(const Local_problem& p)
{
  auto corners = [&p](const std::array<Vertex_id, 3>& t) {
    return std::array<const double*, 3>{p.points[t[0]].data(), p.points[t[1]].data(), p.points[t[2]].data()};
  };
  for(const auto& h : p.hull_facets) {
    const std::array<const double*, 3> hull = corners(h);
    for(const auto& t : p.triangles) {
      if(Triangle_key::of(t[0], t[1], t[2]) == Triangle_key::of(h[0], h[1], h[2])) continue;
      const std::array<const double*, 3> other = corners(t);
      bool coplanar = true;
      for(int k = 0; k < 3 && coplanar; ++k) coplanar = orientation(hull[0], hull[1], hull[2], other[k]) == 0;
      if(coplanar && coplanar_interiors_meet(hull, other)) return true;
    }
  }
  return false;
}

// The tetrahedra of TetGen's mesh of the region's convex hull that lie
// inside the region: from the region's side of each wall, across every
// facet but the walls.  The region's complement in its convex hull touches
// the region only at walls, since the region's other boundary facets lie on
// the convex hull of the whole mesh.  Empty when TetGen's mesh does not
// fit: a wall missing or split, a kept facet on the convex hull with a
// Steiner point (only surface points may lie there), or another volume.
inline std::vector<std::size_t> carve_region(const Local_problem& problem, const Tetgen_mesh& local)
{
  struct Keyed_facet
  {
    Triangle_key key;
    std::uint32_t code; // 4 * tetrahedron + facet
  };
  const std::uint32_t none = std::uint32_t(-1);
  const std::size_t n = local.tets.size();
  std::vector<Keyed_facet> facets;
  facets.reserve(4 * n);
  for(std::size_t t = 0; t < n; ++t) {
    const auto& tv = local.tets[t];
    for(int f = 0; f < 4; ++f)
      facets.push_back({Triangle_key::of(tv[facet_vertex[f][0]], tv[facet_vertex[f][1]], tv[facet_vertex[f][2]]),
                        static_cast<std::uint32_t>(4 * t + f)});
  }
  std::sort(facets.begin(), facets.end(), [](const Keyed_facet& x, const Keyed_facet& y) { return x.key < y.key; });
  std::vector<std::uint32_t> neighbour(4 * n, none);
  for(std::size_t k = 0; k + 1 < facets.size(); ++k)
    if(facets[k].key == facets[k + 1].key) {
      if(k + 2 < facets.size() && facets[k + 2].key == facets[k].key) return {};
      neighbour[facets[k].code] = facets[k + 1].code;
      neighbour[facets[k + 1].code] = facets[k].code;
    }

  std::vector<char> wall(4 * n, 0), inside(n, 0);
  std::vector<std::size_t> kept;
  // No wall: the component is the whole mesh (a cube's six tetrahedra).
  if(problem.walls.empty() && n > 0) {
    inside[0] = 1;
    kept.push_back(0);
  }
  for(const Region_wall& w : problem.walls) {
    auto it = std::lower_bound(facets.begin(), facets.end(), w.key,
                               [](const Keyed_facet& x, const Triangle_key& k) { return x.key < k; });
    if(it == facets.end() || !(it->key == w.key)) return {};
    int seeds = 0;
    for(std::uint32_t code : {it->code, neighbour[it->code]}) {
      if(code == none) continue;
      wall[code] = 1;
      const std::size_t t = code / 4;
      const Vertex_id apex = local.tets[t][code % 4];
      if(orientation(local.points[apex].data(), local.points[w.a].data(), local.points[w.b].data(),
                     local.points[w.c].data()) <= 0)
        continue;
      ++seeds;
      if(!inside[t]) {
        inside[t] = 1;
        kept.push_back(t);
      }
    }
    if(seeds != 1) return {};
  }
  double volume = 0;
  for(std::size_t k = 0; k < kept.size(); ++k) {
    const std::size_t t = kept[k];
    const auto& tv = local.tets[t];
    volume += orientation_determinant(local.points[tv[0]].data(), local.points[tv[1]].data(),
                                      local.points[tv[2]].data(), local.points[tv[3]].data());
    for(int f = 0; f < 4; ++f) {
      const std::uint32_t code = static_cast<std::uint32_t>(4 * t + f);
      if(wall[code]) continue;
      if(neighbour[code] == none) {
        for(int i = 0; i < 3; ++i)
          if(tv[facet_vertex[f][i]] >= problem.points.size()) return {};
        continue;
      }
      const std::size_t u = neighbour[code] / 4;
      if(!inside[u]) {
        inside[u] = 1;
        kept.push_back(u);
      }
    }
  }
  // The flood stays inside the walls; the volumes agreeing (the same volume
  // tiled two ways, summed in floating point) is the check, costing nothing,
  // that nothing outside the region was reached through the convex hull.
  if(std::abs(volume - problem.volume) > 1e-9 * std::abs(problem.volume)) return {};
  return kept;
}

// Small components recovered by flips of our own, before any TetGen call
// (each costs a quarter of a millisecond even on two tetrahedra, most of it
// TetGen's set-up): 2-3 flips across a facet, and removals of an edge whose
// ring lies in the component, the ring's polygon re-triangulated (3-2 and
// 4-4 flips and larger, and the 2-2 flip of two hull facets in one plane
// when the ring is open on the convex hull).  A flip keeps the component's
// walls; hull facets it replaces stay in their plane; every new tetrahedron
// is checked positive exactly.  Greedy: each flip must add a wanted facet,
// at most eight flips (a flat quadrilateral with the wrong diagonal takes
// one, two neighbouring ones two, a cube's six faces six).
struct Small_component
{
  std::vector<std::array<Vertex_id, 4>> tets;
  std::vector<Triangle_key> walls; // facets shared with tetrahedra outside the region, sorted
};

inline std::size_t count_facets(const std::vector<std::array<Vertex_id, 4>>& tets,
                                const std::vector<Triangle_key>& wanted)
{
  std::size_t n = 0;
  for(const Triangle_key& k : wanted) {
    bool found = false;
    for(const auto& t : tets)
      for(int f = 0; f < 4 && !found; ++f)
        found = Triangle_key::of(t[facet_vertex[f][0]], t[facet_vertex[f][1]], t[facet_vertex[f][2]]) == k;
    n += found;
  }
  return n;
}

// The component's tetrahedra with those in `removed` replaced by `added`.
inline std::vector<std::array<Vertex_id, 4>> replaced(const std::vector<std::array<Vertex_id, 4>>& tets,
                                                      const std::vector<std::size_t>& removed,
                                                      const std::vector<std::array<Vertex_id, 4>>& added)
{
  std::vector<std::array<Vertex_id, 4>> out;
  for(std::size_t i = 0; i < tets.size(); ++i)
    if(std::find(removed.begin(), removed.end(), i) == removed.end()) out.push_back(tets[i]);
  out.insert(out.end(), added.begin(), added.end());
  return out;
}

class Component_flips
{
public:
  // `wanted`: the component's missing triangles and the input triangles it has.
  Component_flips(const Flat_storage& m, const Small_component& c, const std::vector<Triangle_key>& wanted)
      : m_(m), tets_(c.tets), walls_(c.walls), wanted_(wanted)
  {}

  // The component re-tetrahedralised with every wanted facet, or empty.
  std::vector<std::array<Vertex_id, 4>> run()
  {
    const int max_flips = 8;
    std::size_t present = count_facets(tets_, wanted_);
    for(int flip = 0; flip < max_flips && present < wanted_.size(); ++flip) {
      hull_ = hull_facets();
      present_ = present;
      std::vector<std::array<Vertex_id, 4>> next;
      for(std::size_t i = 0; i < tets_.size() && next.empty(); ++i)
        for(std::size_t j = i + 1; j < tets_.size() && next.empty(); ++j) next = flip_2_3(i, j);
      for(std::size_t i = 0; i < tets_.size() && next.empty(); ++i)
        for(int a = 0; a < 4 && next.empty(); ++a)
          for(int b = a + 1; b < 4 && next.empty(); ++b) next = remove_edge(tets_[i][a], tets_[i][b]);
      if(next.empty()) return {};
      tets_.swap(next);
      present = count_facets(tets_, wanted_);
    }
    return present == wanted_.size() ? tets_ : std::vector<std::array<Vertex_id, 4>>();
  }

private:
  int orient(Vertex_id a, Vertex_id b, Vertex_id c, Vertex_id d) const
  {
    return orientation(m_.point(a), m_.point(b), m_.point(c), m_.point(d));
  }

  // Facets of the component's boundary that are not walls, sorted.
  std::vector<Triangle_key> hull_facets() const
  {
    std::vector<Triangle_key> facets;
    for(const auto& t : tets_)
      for(int f = 0; f < 4; ++f)
        facets.push_back(Triangle_key::of(t[facet_vertex[f][0]], t[facet_vertex[f][1]], t[facet_vertex[f][2]]));
    std::sort(facets.begin(), facets.end());
    std::vector<Triangle_key> hull;
    for(std::size_t k = 0; k < facets.size();) {
      std::size_t e = k + 1;
      while(e < facets.size() && facets[e] == facets[k]) ++e;
      if(e - k == 1 && !contains(walls_, facets[k])) hull.push_back(facets[k]);
      k = e;
    }
    return hull;
  }

  // The flipped tetrahedra, when every new one is positive and the flip
  // adds a wanted facet without losing one; else empty.
  std::vector<std::array<Vertex_id, 4>> accepted(const std::vector<std::size_t>& removed,
                                                 const std::vector<std::array<Vertex_id, 4>>& added) const
  {
    for(const auto& t : added)
      if(orient(t[0], t[1], t[2], t[3]) <= 0) return {};
    std::vector<std::array<Vertex_id, 4>> out = replaced(tets_, removed, added);
    return count_facets(out, wanted_) > present_ ? out : std::vector<std::array<Vertex_id, 4>>();
  }

  // Tetrahedra i and j sharing facet (a, b, c), with apexes p and q, become
  // three around the edge pq, when pq crosses the facet's interior.
  std::vector<std::array<Vertex_id, 4>> flip_2_3(std::size_t i, std::size_t j) const
  {
    const auto& s = tets_[i];
    const auto& t = tets_[j];
    for(int f = 0; f < 4; ++f) {
      const Vertex_id a = s[facet_vertex[f][0]], b = s[facet_vertex[f][1]], c = s[facet_vertex[f][2]];
      const Triangle_key k = Triangle_key::of(a, b, c);
      for(int g = 0; g < 4; ++g) {
        if(!(Triangle_key::of(t[facet_vertex[g][0]], t[facet_vertex[g][1]], t[facet_vertex[g][2]]) == k)) continue;
        // (p, a, b, c) is an even permutation of s: p on the positive side of (a, b, c) read as CGAL does
        // with p first; q on the other.
        const Vertex_id p = s[f], q = t[g];
        return accepted({i, j}, {{a, b, p, q}, {b, c, p, q}, {c, a, p, q}});
      }
    }
    return {};
  }

  // Edge uv removed: the ring r0, r1, ... of its tetrahedra (u, v, r_i,
  // r_i+1), all in the component, its polygon triangulated; each triangle (x, y, z) gives (x, y, z, v) and (y, x, z, u).  An open ring
  // (uv on the convex hull) needs u, v, r0, r_last in one plane, r0 r_last
  // crossing uv.
  std::vector<std::array<Vertex_id, 4>> remove_edge(Vertex_id u, Vertex_id v) const
  {
    std::vector<std::size_t> around;
    std::vector<std::array<Vertex_id, 2>> sides;
    for(std::size_t i = 0; i < tets_.size(); ++i) {
      const auto& t = tets_[i];
      if(std::count(t.begin(), t.end(), u) == 0 || std::count(t.begin(), t.end(), v) == 0) continue;
      std::array<Vertex_id, 2> xy;
      int k = 0;
      for(Vertex_id w : t)
        if(w != u && w != v) xy[k++] = w;
      if(orient(u, v, xy[0], xy[1]) < 0) std::swap(xy[0], xy[1]);
      around.push_back(i);
      sides.push_back(xy);
    }
    if(around.size() < 2) return {};
    // The ring in order: from the side whose first vertex no side ends at
    // (open ring), else from any.
    std::size_t start = 0;
    for(std::size_t i = 0; i < sides.size(); ++i) {
      bool ends_here = false;
      for(const auto& s : sides) ends_here = ends_here || s[1] == sides[i][0];
      if(!ends_here) start = i;
    }
    std::vector<Vertex_id> ring{sides[start][0]};
    for(std::size_t n = 0; n < sides.size(); ++n) {
      auto next = std::find_if(sides.begin(), sides.end(),
                               [&](const std::array<Vertex_id, 2>& s) { return s[0] == ring.back(); });
      if(next == sides.end()) return {};
      ring.push_back((*next)[1]);
    }
    const bool closed = ring.front() == ring.back();
    if(closed) {
      ring.pop_back();
    } else {
      const Triangle_key first = Triangle_key::of(u, v, ring.front()), last = Triangle_key::of(u, v, ring.back());
      if(!contains(hull_, first) || !contains(hull_, last)) return {}; // the ring goes on outside
      if(orient(u, v, ring.front(), ring.back()) != 0) return {};
      const Vertex_id off = ring[1]; // not in that plane: (u, v, r0, r1) is a tetrahedron
      if(orient(ring.front(), ring.back(), off, u) * orient(ring.front(), ring.back(), off, v) >= 0) return {};
    }
    const std::vector<std::array<Vertex_id, 4>> added = ring_triangulation(u, v, ring);
    if(added.empty()) return {};
    return accepted(around, added);
  }

  // A triangulation of the ring's polygon (closed by r_last r0) whose
  // triangles (x, y, z), in ring order, give positive (x, y, z, v) and
  // (y, x, z, u), and which has every chord xy that a wanted facet (x, y, u)
  // or (x, y, v) needs: Klincsek's dynamic programme over sub-polygons,
  // triangles crossing a needed chord forbidden.  Empty when there is none.
  std::vector<std::array<Vertex_id, 4>> ring_triangulation(Vertex_id u, Vertex_id v,
                                                           const std::vector<Vertex_id>& ring) const
  {
    const std::size_t n = ring.size();
    if(n < 3) return {};
    std::vector<std::array<std::size_t, 2>> needed;
    for(std::size_t p = 0; p < n; ++p)
      for(std::size_t q = p + 2; q < n; ++q)
        if(!(p == 0 && q == n - 1) && (contains_wanted(Triangle_key::of(ring[p], ring[q], u)) ||
                                       contains_wanted(Triangle_key::of(ring[p], ring[q], v))))
          needed.push_back({p, q});
    auto crosses_needed = [&](std::size_t a, std::size_t b) {
      for(const auto& c : needed)
        if((a < c[0] && c[0] < b && b < c[1]) || (c[0] < a && a < c[1] && c[1] < b)) return true;
      return false;
    };
    const std::size_t none = std::size_t(-1);
    // apex[i][j]: the third corner of the triangle on chord ij in a valid
    // triangulation of ring[i..j]; none when that sub-polygon has none.
    std::vector<std::vector<std::size_t>> apex(n, std::vector<std::size_t>(n, none));
    for(std::size_t length = 2; length < n; ++length)
      for(std::size_t i = 0; i + length < n; ++i) {
        const std::size_t j = i + length;
        if(crosses_needed(i, j)) continue;
        for(std::size_t k = i + 1; k < j && apex[i][j] == none; ++k) {
          if((k - i > 1 && apex[i][k] == none) || (j - k > 1 && apex[k][j] == none)) continue;
          if(orient(ring[i], ring[k], ring[j], v) > 0 && orient(ring[k], ring[i], ring[j], u) > 0) apex[i][j] = k;
        }
      }
    if(apex[0][n - 1] == none) return {};
    std::vector<std::array<Vertex_id, 4>> added;
    std::vector<std::array<std::size_t, 2>> chords{{0, n - 1}};
    while(!chords.empty()) {
      const std::size_t i = chords.back()[0], j = chords.back()[1];
      chords.pop_back();
      if(j - i < 2) continue;
      const std::size_t k = apex[i][j];
      added.push_back({ring[i], ring[k], ring[j], v});
      added.push_back({ring[k], ring[i], ring[j], u});
      chords.push_back({i, k});
      chords.push_back({k, j});
    }
    return added;
  }

  bool contains_wanted(const Triangle_key& k) const
  {
    return std::find(wanted_.begin(), wanted_.end(), k) != wanted_.end();
  }

  const Flat_storage& m_;
  std::vector<std::array<Vertex_id, 4>> tets_;
  const std::vector<Triangle_key> walls_;
  std::vector<Triangle_key> hull_;
  const std::vector<Triangle_key>& wanted_;
  std::size_t present_ = 0;
};

// Larger components were not recovered by flips on CGAL's mechanical parts.
constexpr std::size_t max_flipped_component = 12;

inline std::size_t component_size(const Recovery_region& region, std::size_t c)
{
  return region.component_begin[c + 1] - region.component_begin[c];
}

// Component c by flips when it has at most max_flipped_component
// tetrahedra; appends its new tetrahedra to `tets` and returns true, or
// returns false.  The flips must also keep the input triangles the
// component already had.
inline bool recover_by_flips(const Flat_storage& m, const Recovery_region& region, std::size_t c,
                             const std::vector<Triangle_key>& input, const std::vector<Triangle_key>& missing_here,
                             std::vector<std::array<Vertex_id, 4>>& tets)
{
  if(component_size(region, c) > max_flipped_component) return false;
  const std::size_t begin = region.component_begin[c], end = region.component_begin[c + 1];
  Small_component component;
  std::vector<Triangle_key> wanted = missing_here;
  for(std::size_t k = begin; k < end; ++k) {
    const Tet_id t = region.tets[k];
    const Vertex_id* tv = m.vertex_ids(t);
    component.tets.push_back({tv[0], tv[1], tv[2], tv[3]});
    for(int f = 0; f < 4; ++f) {
      const Triangle_key key = facet_key(m, t, f);
      const Tet_id u = m.neighbor(t, f);
      if(!m.is_ghost(u) && !region.in_region[u]) component.walls.push_back(key);
      if(contains(input, key)) wanted.push_back(key);
    }
  }
  std::sort(component.walls.begin(), component.walls.end());
  std::sort(wanted.begin(), wanted.end());
  wanted.erase(std::unique(wanted.begin(), wanted.end()), wanted.end());
  const std::vector<std::array<Vertex_id, 4>> flipped = Component_flips(m, component, wanted).run();
  if(flipped.empty()) return false;
  tets.insert(tets.end(), flipped.begin(), flipped.end());
  return true;
}

// A region of the mesh and the tetrahedra that replace it.
struct Component_replacement
{
  std::vector<Tet_id> old;
  std::vector<std::array<Vertex_id, 4>> made;
};

// Component c of the region with the ghosts on its facets on the convex
// hull, and `tets` (which tile the same volume and have its walls) with
// ghosts on their own hull facets: those neither two of them share nor a
// wall.  The border of the component's hull patch is kept (a wall through
// each of its edges holds it), so the new ghosts close up with the old
// ones around it.
inline Component_replacement component_replacement(const Flat_storage& m, const Recovery_region& region,
                                                   std::size_t c, std::vector<std::array<Vertex_id, 4>> tets)
{
  Component_replacement r;
  r.old.assign(region.tets.begin() + region.component_begin[c], region.tets.begin() + region.component_begin[c + 1]);
  std::vector<Triangle_key> walls;
  const std::size_t finite = r.old.size();
  for(std::size_t k = 0; k < finite; ++k)
    for(int f = 0; f < 4; ++f) {
      const Tet_id u = m.neighbor(r.old[k], f);
      if(m.is_ghost(u)) r.old.push_back(u); // a ghost's one finite neighbour is this
      else if(!region.in_region[u]) walls.push_back(facet_key(m, r.old[k], f));
    }
  std::sort(walls.begin(), walls.end());
  struct Keyed_facet
  {
    Triangle_key key;
    std::size_t at; // 4 * tetrahedron + facet
  };
  std::vector<Keyed_facet> facets;
  facets.reserve(4 * tets.size());
  for(std::size_t k = 0; k < tets.size(); ++k)
    for(int f = 0; f < 4; ++f)
      facets.push_back({Triangle_key::of(tets[k][facet_vertex[f][0]], tets[k][facet_vertex[f][1]],
                                         tets[k][facet_vertex[f][2]]),
                        4 * k + f});
  std::sort(facets.begin(), facets.end(), [](const Keyed_facet& x, const Keyed_facet& y) { return x.key < y.key; });
  r.made = std::move(tets);
  for(std::size_t i = 0; i < facets.size();) {
    std::size_t j = i + 1;
    while(j < facets.size() && facets[j].key == facets[i].key) ++j;
    if(j - i == 1 && !std::binary_search(walls.begin(), walls.end(), facets[i].key)) {
      // Listed as the finite tetrahedron lists it, as a ghost is (see
      // flat_storage_from_tetrahedra).
      const std::array<Vertex_id, 4> t = r.made[facets[i].at / 4];
      const int f = static_cast<int>(facets[i].at % 4);
      r.made.push_back({t[facet_vertex[f][0]], t[facet_vertex[f][1]], t[facet_vertex[f][2]], ghost_vertex});
    }
    i = j;
  }
  return r;
}

// How component c was recovered: by our flips (their tetrahedra, in mesh
// vertex ids), or by TetGen (its mesh of the component's local problem and
// the tetrahedra of it kept).
struct Component_recovery
{
  bool by_flips = false;
  std::vector<std::array<Vertex_id, 4>> flipped;
  Local_problem problem;
  Tetgen_mesh mesh;
  std::vector<std::size_t> kept; // empty: not recovered by TetGen
};

// Component c by TetGen: hull facets left out first (the convex hull of the
// component's points meshed, then carved); then, should TetGen split a wall
// that way, as constraints too, TetGen removing what lies outside them: on
// couplingdown's one failing component this second try holds.  The second
// try is skipped when a hull facet crosses another triangle.  False when
// neither fits.  `local` as for local_problem.
inline bool recover_component_with_tetgen(const Flat_storage& m, const Recovery_region& region, std::size_t c,
                                          const std::vector<Triangle_key>& input,
                                          const std::vector<Triangle_key>& missing_here,
                                          std::vector<Vertex_id>& local, Component_recovery& out)
{
  for(bool with_hull_facets : {false, true}) {
    out.problem = local_problem(m, region, c, input, missing_here, local, with_hull_facets);
    if(with_hull_facets && hull_facet_crosses_a_triangle(out.problem)) break;
    try {
      out.mesh = tetgen_recovery(out.problem.points, out.problem.triangles, with_hull_facets ? "pYMO0zQ" : "pYcMO0zQ");
    } catch(const std::runtime_error&) {
      continue;
    }
    out.kept = carve_region(out.problem, out.mesh);
    if(!out.kept.empty()) return true;
  }
  return false;
}

// Calls a() and b(), side by side on two threads when `parallel`
// (for_each_chunk rethrows an exception of either once both have returned).
template <class A, class B>
void run_side_by_side(bool parallel, const A& a, const B& b)
{
  if(!parallel) {
    a();
    b();
    return;
  }
  for_each_chunk(2, [&](int k) {
    if(k == 0) a();
    else b();
  });
}

// RECOVERBOUNDARY of the region only, component by component, in place;
// returns true, or leaves the mesh untouched and returns false when TetGen
// fails on a component or its mesh does not fit the walls (and throws
// logic_error, the mesh untouched too, should a recovered component not
// close up with the rest, which would be a bug).  The rest of the
// mesh (on fandisk 97% of its tetrahedra) is not rebuilt: that took as long
// as the region's search.  With `threads` > 1, the region's search, our
// flips beside TetGen's calls, and the checks of the replacements run on
// several threads; the mesh is the same whatever the number.
inline bool recover_locally(const std::vector<Triangle_key>& input, const std::vector<Triangle_key>& missing,
                            Constrained_mesh& out, Recovery_report& report, int threads = 1)
{
  Flat_storage& m = out.mesh;
  const Recovery_region region = recovery_region(m, missing, threads);
  report.region_tetrahedra = region.tets.size();
  const std::size_t components = region.number_of_components();
  std::vector<std::vector<Triangle_key>> missing_in(components);
  for(std::size_t i = 0; i < missing.size(); ++i) missing_in[region.component_of_missing[i]].push_back(missing[i]);

  // Every component's tetrahedra first, so that a failure changes nothing.
  // TetGen keeps its predicates' error bounds in globals that each call
  // sets from its input's box: its calls run one after the other, on the
  // large components (on fandisk one of 950 tetrahedra takes half of the
  // recovery) while our flips try the small ones; the small ones the flips
  // miss go to TetGen last.
  std::vector<Component_recovery> recovery(components);
  std::vector<std::size_t> small, large;
  for(std::size_t c = 0; c < components; ++c)
    (component_size(region, c) <= max_flipped_component ? small : large).push_back(c);
  std::vector<Vertex_id> local(m.vertices.size(), Vertex_id(-1));
  bool recovered = true;
  auto by_tetgen = [&](std::size_t c) {
    recovered = recovered && recover_component_with_tetgen(m, region, c, input, missing_in[c], local, recovery[c]);
  };
  run_side_by_side(
      threads > 1 && !large.empty() && !small.empty(),
      [&] {
        for(std::size_t c : large) by_tetgen(c);
      },
      [&] {
        for(std::size_t c : small)
          recovery[c].by_flips = recover_by_flips(m, region, c, input, missing_in[c], recovery[c].flipped);
      });
  for(std::size_t c : small)
    if(!recovery[c].by_flips) by_tetgen(c);
  if(!recovered) return false;

  // Steiner points get the ids after the mesh's vertices, in component
  // order; those outside a component went with the tetrahedra dropped.
  std::vector<std::vector<std::array<Vertex_id, 4>>> made(components);
  std::vector<std::array<double, 3>> steiner_points;
  for(std::size_t c = 0; c < components; ++c) {
    Component_recovery& r = recovery[c];
    if(r.by_flips) {
      ++report.flipped_components;
      made[c] = std::move(r.flipped);
      continue;
    }
    ++report.tetgen_components;
    std::vector<Vertex_id> global(r.mesh.points.size(), Vertex_id(-1));
    std::copy(r.problem.vertex_of_local.begin(), r.problem.vertex_of_local.end(), global.begin());
    for(std::size_t t : r.kept) {
      std::array<Vertex_id, 4> tv;
      for(int i = 0; i < 4; ++i) {
        const Vertex_id v = r.mesh.tets[t][i];
        if(global[v] == Vertex_id(-1)) {
          global[v] = static_cast<Vertex_id>(m.vertices.size() + steiner_points.size());
          steiner_points.push_back(r.mesh.points[v]);
        }
        tv[i] = global[v];
      }
      made[c].push_back(tv);
    }
  }
  // Each replacement checked in full before the first is made: one that
  // does not close up (a bug, not a bad input) leaves the mesh as it was.
  // The checks read each component's own tetrahedra and ghosts, which the
  // other components' replacements do not change.
  std::vector<Component_replacement> replacements(components);
  std::vector<std::string> misfit(components);
  const int runs = static_cast<int>(std::max<std::size_t>(1, std::min<std::size_t>(std::max(threads, 1), components)));
  for_each_chunk(runs, [&](int k) {
    for(std::size_t c = chunk_begin(components, runs, k); c < chunk_begin(components, runs, k + 1); ++c) {
      replacements[c] = component_replacement(m, region, c, std::move(made[c]));
      const Component_replacement& r = replacements[c];
      try {
        check_replacement(m, r.old.data(), r.old.size(), r.made.data(), r.made.size());
      } catch(const std::logic_error& e) {
        misfit[c] = e.what();
      }
    }
  });
  for(const std::string& why : misfit)
    if(!why.empty())
      throw std::logic_error("Tetrahedral_mesher: a recovered component does not fit its walls: " + why);
  for(const auto& p : steiner_points) {
    Vertex_record record;
    std::copy(p.begin(), p.end(), record.xyz);
    record.scratch = 0;
    m.vertices.push_back(record);
  }
  Replacement_scratch scratch;
  std::vector<Tet_id> slots;
  for(const Component_replacement& r : replacements) {
    slots.resize(r.made.size());
    replace_tetrahedra(m, r.old.data(), r.old.size(), r.made.data(), r.made.size(), slots.data(), scratch);
  }
  report.used_tetgen = report.tetgen_components > 0;
  report.steiner_points = steiner_points.size();
  return true;
}

// Lines 2-3 of Algorithm 2.
inline Recovery_report empty_mesh_and_recovery(const Surface_soup& soup, int threads, Constrained_mesh& out)
{
  typedef std::chrono::steady_clock Clock;
  Recovery_report report;
  const Clock::time_point t0 = Clock::now();
  empty_mesh(soup, threads, out);
  const Clock::time_point t1 = Clock::now();
  const std::vector<Triangle_key> input = input_triangle_keys(soup, out.vertex_of_input);
  const std::vector<Triangle_key> missing = missing_facets(out.mesh, input, threads);
  report.missing_triangles = missing.size();
  if(!missing.empty() && !recover_locally(input, missing, out, report, threads))
    recover_with_tetgen(soup, out, report);
  report.empty_mesh_seconds = std::chrono::duration<double>(t1 - t0).count();
  report.recovery_seconds = std::chrono::duration<double>(Clock::now() - t1).count();
  set_box(soup.points, out);
  out.fit_slot_arrays();
  return report;
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_BOUNDARY_RECOVERY_H
