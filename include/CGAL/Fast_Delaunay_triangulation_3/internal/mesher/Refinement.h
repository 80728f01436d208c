// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lines 4-8 of the paper's Algorithm 2: while the mesh has large
// tetrahedra, SAMPLEPOINTS (circumcentres of the tetrahedra whose
// circumradius exceeds 1.4 h; the centroid when the centre falls outside
// the tetrahedron's subdomain), FILTERPOINTS (no two accepted points closer
// than 0.7 h) and INSERTPOINTS in one large batch per pass.
//
// The cavity of a refinement point is the Delaunay cavity with the two
// changes of §4: it never crosses a constrained facet (so the surface is
// never broken and each cavity stays in one subdomain), and, since the mesh
// is then not Delaunay any more, it is made star-shaped from the point: a
// tetrahedron whose boundary facet does not see the point leaves the
// cavity, and the test repeats.  The cavity also aborts the point when one
// of its vertices is closer than 0.7 h (§2.4's modified cavity).
//
// This milestone inserts each batch sequentially with the kernel's
// DELAUNAYBALL (Delaunay_kernel::fill_hole); the batches are what the
// partitioned engine will take.

#ifndef CGAL_FDT3_INTERNAL_MESHER_REFINEMENT_H
#define CGAL_FDT3_INTERNAL_MESHER_REFINEMENT_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Delaunay_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Sizing.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <string>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

struct Refinement_options
{
  double radius_ratio = 1.4;   // refine when circumradius > radius_ratio * h
  double min_edge_ratio = 0.7; // no new edge shorter than min_edge_ratio * h
  int max_passes = 200;
};

struct Refinement_pass
{
  std::size_t candidates = 0, filtered_out = 0, aborted = 0, inserted = 0;
  std::size_t tetrahedra = 0; // live finite tetrahedra inside the volumes after the pass
  double seconds = 0;
};

// A refinement point: where, its size, the tetrahedron that contains it
// and the subdomain it must fall in.
struct Refinement_point
{
  double p[3];
  double h;
  Tet_id containing;
  int subdomain;
};

// Circumcentre of a tetrahedron (floating point; an imprecise centre only
// moves the point a little, it never breaks the mesh since every
// combinatorial decision below is exact).  False when the tetrahedron is flat.
inline bool circumcentre(const double* a, const double* b, const double* c, const double* d, double centre[3])
{
  double u[3], v[3], w[3];
  for(int i = 0; i < 3; ++i) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = d[i] - a[i];
  }
  const double uu = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  const double vv = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const double ww = w[0] * w[0] + w[1] * w[1] + w[2] * w[2];
  const double vxw[3] = {v[1] * w[2] - v[2] * w[1], v[2] * w[0] - v[0] * w[2], v[0] * w[1] - v[1] * w[0]};
  const double wxu[3] = {w[1] * u[2] - w[2] * u[1], w[2] * u[0] - w[0] * u[2], w[0] * u[1] - w[1] * u[0]};
  const double uxv[3] = {u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]};
  const double det = 2 * (u[0] * vxw[0] + u[1] * vxw[1] + u[2] * vxw[2]);
  if(det == 0 || !std::isfinite(det)) return false;
  for(int i = 0; i < 3; ++i) centre[i] = a[i] + (uu * vxw[i] + vv * wxu[i] + ww * uxv[i]) / det;
  return true;
}

class Constrained_refinement
{
public:
  Constrained_refinement(Constrained_mesh& cm, const Refinement_options& options)
      : cm_(cm), options_(options), kernel_(cm.mesh, scratch_, Mesh_slots{&cm.mesh}, cm.filter)
  {}

  // Runs passes until no point is inserted; `progress` sees every pass.
  std::vector<Refinement_pass> run(const std::function<void(const Refinement_pass&, int)>& progress)
  {
    std::vector<Refinement_pass> passes;
    for(int k = 0; k < options_.max_passes; ++k) {
      typedef std::chrono::steady_clock Clock;
      const Clock::time_point t0 = Clock::now();
      Refinement_pass pass;
      std::vector<Refinement_point> points = sample_points();
      pass.candidates = points.size();
      filter_points(points);
      pass.filtered_out = pass.candidates - points.size();
      insert_points(points, pass);
      CGAL_assertion_code(std::string why;)
      CGAL_assertion_msg(cm_.is_valid(&why), why.c_str());
      pass.tetrahedra = count_volume_tetrahedra();
      pass.seconds = std::chrono::duration<double>(Clock::now() - t0).count();
      passes.push_back(pass);
      if(progress) progress(pass, k);
      if(pass.inserted == 0) break;
    }
    return passes;
  }

private:
  std::size_t count_volume_tetrahedra() const
  {
    std::size_t n = 0;
    for(Tet_id t = 0; t < cm_.mesh.number_of_slots(); ++t)
      n += cm_.mesh.is_live(t) && cm_.subdomain[t] > 0 ? 1 : 0;
    return n;
  }

  // SAMPLEPOINTS: circumcentres of large tetrahedra that fall in their own
  // subdomain (a centre beyond the surface would need the surface split,
  // which this mesher never does).
  std::vector<Refinement_point> sample_points()
  {
    const Flat_storage& m = cm_.mesh;
    std::vector<Refinement_point> points;
    for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
      if(!m.is_live(t) || cm_.subdomain[t] <= 0) continue;
      const Vertex_id* tv = m.vertex_ids(t);
      const double* w[4] = {m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])};
      const double h_mean = (cm_.size[tv[0]] + cm_.size[tv[1]] + cm_.size[tv[2]] + cm_.size[tv[3]]) / 4;
      Refinement_point r;
      if(!circumcentre(w[0], w[1], w[2], w[3], r.p)) continue;
      const double radius = distance(r.p, w[0]);
      if(radius <= options_.radius_ratio * h_mean) continue;
      // Outside the input's box the static filters do not hold (and the
      // centre is outside every volume anyway): no walk there.
      Tet_id u = cm_.in_box(r.p) ? walk(t, r.p) : no_tet;
      if(u == no_tet || m.is_ghost(u) || cm_.subdomain[u] != cm_.subdomain[t]) {
        // The centre lies beyond the surface, which is never split: the
        // centroid, inside t, refines t instead (the corners of a cube
        // have all their centres outside after the first point).
        for(int a = 0; a < 3; ++a) r.p[a] = (w[0][a] + w[1][a] + w[2][a] + w[3][a]) / 4;
        u = t;
      }
      r.h = interpolated_size(cm_, u, r.p);
      if(radius <= options_.radius_ratio * r.h) continue;
      r.containing = u;
      r.subdomain = cm_.subdomain[t];
      points.push_back(r);
    }
    return points;
  }

  // FILTERPOINTS: greedy in sampling order with a hash grid whose cells are
  // the smallest distance threshold; a point is dropped when an accepted one
  // is closer than min_edge_ratio times its size.
  void filter_points(std::vector<Refinement_point>& points) const
  {
    if(points.empty()) return;
    double cell = std::numeric_limits<double>::infinity();
    for(const Refinement_point& r : points) cell = std::min(cell, options_.min_edge_ratio * r.h);
    auto cell_of = [cell](double x) { return static_cast<std::int64_t>(std::floor(x / cell)); };
    auto key = [](std::int64_t i, std::int64_t j, std::int64_t k) {
      return (static_cast<std::uint64_t>(i) * 73856093u) ^ (static_cast<std::uint64_t>(j) * 19349663u) ^
             (static_cast<std::uint64_t>(k) * 83492791u);
    };
    std::unordered_multimap<std::uint64_t, std::size_t> grid;
    std::vector<Refinement_point> kept;
    for(const Refinement_point& r : points) {
      const double radius = options_.min_edge_ratio * r.h;
      const std::int64_t reach = static_cast<std::int64_t>(std::ceil(radius / cell));
      const std::int64_t ci = cell_of(r.p[0]), cj = cell_of(r.p[1]), ck = cell_of(r.p[2]);
      bool too_close = false;
      for(std::int64_t i = ci - reach; i <= ci + reach && !too_close; ++i)
        for(std::int64_t j = cj - reach; j <= cj + reach && !too_close; ++j)
          for(std::int64_t k = ck - reach; k <= ck + reach && !too_close; ++k) {
            auto range = grid.equal_range(key(i, j, k));
            for(auto it = range.first; it != range.second; ++it)
              if(distance(kept[it->second].p, r.p) < radius) {
                too_close = true;
                break;
              }
          }
      if(too_close) continue;
      grid.emplace(key(ci, cj, ck), kept.size());
      kept.push_back(r);
    }
    points.swap(kept);
  }

  void insert_points(const std::vector<Refinement_point>& points, Refinement_pass& pass)
  {
    Tet_id hint = cm_.mesh.first_live_tet();
    for(const Refinement_point& r : points) {
      if(insert_point(r, hint)) ++pass.inserted;
      else ++pass.aborted;
    }
    cm_.mesh.live_tets += scratch_.live_delta;
    cm_.mesh.ghost_tets += scratch_.ghost_delta;
    scratch_.live_delta = scratch_.ghost_delta = 0;
  }

  bool insert_point(const Refinement_point& r, Tet_id& hint)
  {
    Flat_storage& m = cm_.mesh;
    Tet_id start = r.containing;
    if(!m.is_live(start)) start = hint;
    start = walk(start, r.p);
    if(start == no_tet || m.is_ghost(start) || cm_.subdomain[start] != r.subdomain) return false;
    if(!constrained_cavity(start, r)) return false;

    Vertex_record record;
    record.xyz[0] = r.p[0]; record.xyz[1] = r.p[1]; record.xyz[2] = r.p[2];
    record.scratch = 0;
    const Vertex_id v = static_cast<Vertex_id>(m.vertices.size());
    m.vertices.push_back(record);
    cm_.size.push_back(r.h);
    kernel_.fill_hole(v, cavity_.data(), cavity_.size());
    inherit_flags(r.subdomain);
    hint = scratch_.ball.front();
    return true;
  }

  // The new tetrahedra are in the cavity's subdomain; facet 0 of each is a
  // cavity boundary facet and is constrained when the outside one was; the
  // other facets contain the new point, never on the surface.
  void inherit_flags(int subdomain)
  {
    cm_.fit_slot_arrays();
    for(std::size_t k = 0; k < scratch_.ball.size(); ++k) {
      const Tet_id t = scratch_.ball[k];
      const Facet_code outside = scratch_.boundary[k].outside;
      cm_.subdomain[t] = subdomain;
      cm_.constrained[t] = cm_.is_constrained(tet_of(outside), facet_of(outside)) ? 1 : 0;
    }
  }

  // Stochastic visibility walk (random first facet per step) to a
  // tetrahedron whose closure holds p, or a ghost beyond whose hull facet p
  // lies.  Once the mesh is not Delaunay any more a visibility walk may
  // cycle (the termination proof needs the Delaunay property), so it gives
  // up after a number of steps: no_tet, and the caller drops the point.
  Tet_id walk(Tet_id t, const double* p)
  {
    const Flat_storage& m = cm_.mesh;
    const int max_steps = 4096;
    Tet_id previous = no_tet;
    for(int step = 0; step < max_steps; ++step) {
      if(m.is_ghost(t)) return t;
      const Vertex_id* tv = m.vertex_ids(t);
      const double* w[4] = {m.point(tv[0]), m.point(tv[1]), m.point(tv[2]), m.point(tv[3])};
      const int first = static_cast<int>(scratch_.next_random() & 3);
      Tet_id next = no_tet;
      for(int k = 0; k < 4 && next == no_tet; ++k) {
        const int f = (first + k) & 3;
        const Tet_id u = m.neighbor(t, f);
        if(u == previous) continue;
        const double* q[4] = {w[0], w[1], w[2], w[3]};
        q[f] = p;
        if(orientation(cm_.filter, q[0], q[1], q[2], q[3]) < 0) next = u;
      }
      if(next == no_tet) return t;
      previous = t;
      t = next;
    }
    return no_tet;
  }

  bool in_cavity(Tet_id t) const { return t < stamp_.size() && stamp_[t] == current_stamp_; }

  // CAVITY with constraints, then made star-shaped.  Leaves the cavity in
  // cavity_ and returns true, or returns false to abort the point.
  bool constrained_cavity(Tet_id start, const Refinement_point& r)
  {
    const Flat_storage& m = cm_.mesh;
    stamp_.resize(m.number_of_slots(), 0);
    ++current_stamp_;
    cavity_.clear();
    const double too_close = options_.min_edge_ratio * r.h;
    // Before any conflict test: a point equal to a vertex of `start` (the
    // only vertices it can equal) has no perturbed conflict status.
    for(int i = 0; i < 4; ++i)
      if(distance(m.point(m.vertex(start, i)), r.p) < too_close || same_point(m.point(m.vertex(start, i)), r.p))
        return false;
    if(!kernel_.in_conflict(start, r.p)) return false;
    stamp_[start] = current_stamp_;
    cavity_.push_back(start);
    for(std::size_t k = 0; k < cavity_.size(); ++k) {
      const Tet_id t = cavity_[k];
      for(int i = 0; i < 4; ++i)
        if(distance(m.point(m.vertex(t, i)), r.p) < too_close) return false;
      for(int f = 0; f < 4; ++f) {
        if(cm_.is_constrained(t, f)) continue;
        const Tet_id u = m.neighbor(t, f);
        if(in_cavity(u)) continue;
        CGAL_assertion(!m.is_ghost(u) && cm_.subdomain[u] == r.subdomain);
        if(!kernel_.in_conflict(u, r.p)) continue;
        stamp_[u] = current_stamp_;
        cavity_.push_back(u);
      }
    }
    return make_star_shaped(start, r.p);
  }

  // The paper's rule: drop every tetrahedron with a boundary facet that
  // does not see p strictly, until none is left (or the start is dropped).
  bool make_star_shaped(Tet_id start, const double* p)
  {
    const Flat_storage& m = cm_.mesh;
    for(bool changed = true; changed;) {
      changed = false;
      for(std::size_t k = 0; k < cavity_.size();) {
        const Tet_id t = cavity_[k];
        bool sees_all = true;
        for(int f = 0; f < 4 && sees_all; ++f) {
          if(in_cavity(m.neighbor(t, f))) continue;
          const Vertex_id* tv = m.vertex_ids(t);
          sees_all = orientation(cm_.filter, p, m.point(tv[facet_vertex[f][0]]), m.point(tv[facet_vertex[f][1]]),
                                 m.point(tv[facet_vertex[f][2]])) > 0;
        }
        if(sees_all) {
          ++k;
          continue;
        }
        if(t == start) return false;
        stamp_[t] = 0;
        cavity_[k] = cavity_.back();
        cavity_.pop_back();
        changed = true;
      }
    }
    return true;
  }

  Constrained_mesh& cm_;
  Refinement_options options_;
  Insertion_scratch scratch_;
  Delaunay_kernel<> kernel_;
  std::vector<std::uint32_t> stamp_;
  std::uint32_t current_stamp_ = 0;
  std::vector<Tet_id> cavity_;
};

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_REFINEMENT_H
