// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Lines 2-3 of the paper's Algorithm 2: EMPTYMESH, the Delaunay
// triangulation of the surface vertices built by this package's engine, then
// RECOVERBOUNDARY, a mesh of the convex hull in which every input triangle
// is a facet, the surface neither moved nor split.
//
// When the empty mesh already has every input triangle (fine surface meshes
// often do) it is kept as it is.  Otherwise the recovery is TetGen's
// (Debian's libtet1.5-dev), as in the paper, which went through Gmsh's copy
// of TetGen's: switches p (a piecewise linear complex), Y (no Steiner point
// on the boundary), c (keep the convex hull, which the colouring needs to
// tell the outside), z (numbering from 0), Q (quiet).  TetGen rebuilds its
// own Delaunay mesh; it may add Steiner points inside the volumes, after the
// input points, which keep their numbers.

#ifndef CGAL_FDT3_INTERNAL_MESHER_BOUNDARY_RECOVERY_H
#define CGAL_FDT3_INTERNAL_MESHER_BOUNDARY_RECOVERY_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Triangulation_core.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>

#include <tetgen.h>

#include <algorithm>
#include <chrono>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

struct Recovery_report
{
  std::size_t missing_triangles = 0; // input triangles not facets of the empty mesh
  bool used_tetgen = false;
  std::size_t steiner_points = 0;    // added by TetGen inside the volumes
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

// How many sorted `wanted` keys are not facets of a live tetrahedron of m.
inline std::size_t count_missing_facets(const Flat_storage& m, const std::vector<Triangle_key>& wanted)
{
  std::vector<std::size_t> found;
  for(Tet_id t = 0; t < m.number_of_slots(); ++t) {
    if(!m.is_live(t) || m.is_ghost(t)) continue;
    for(int f = 0; f < 4; ++f) {
      const Triangle_key k = facet_key(m, t, f);
      auto it = std::lower_bound(wanted.begin(), wanted.end(), k);
      if(it != wanted.end() && *it == k) found.push_back(static_cast<std::size_t>(it - wanted.begin()));
    }
  }
  std::sort(found.begin(), found.end());
  return wanted.size() - static_cast<std::size_t>(std::unique(found.begin(), found.end()) - found.begin());
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

// RECOVERBOUNDARY by TetGen; replaces out.mesh.  Vertex ids of the result
// are the input point numbers, then the Steiner points.
inline void recover_with_tetgen(const Surface_soup& soup, Constrained_mesh& out, Recovery_report& report)
{
  tetgenio in, result;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(soup.points.size());
  in.pointlist = new REAL[3 * soup.points.size()];
  for(std::size_t i = 0; i < soup.points.size(); ++i)
    for(int a = 0; a < 3; ++a) in.pointlist[3 * i + a] = soup.points[i][a];
  in.numberoffacets = static_cast<int>(soup.triangles.size());
  in.facetlist = new tetgenio::facet[soup.triangles.size()];
  for(std::size_t t = 0; t < soup.triangles.size(); ++t) {
    tetgenio::facet& f = in.facetlist[t];
    tetgenio::init(&f);
    f.numberofpolygons = 1;
    f.polygonlist = new tetgenio::polygon[1];
    tetgenio::init(&f.polygonlist[0]);
    f.polygonlist[0].numberofvertices = 3;
    f.polygonlist[0].vertexlist = new int[3];
    for(int i = 0; i < 3; ++i) f.polygonlist[0].vertexlist[i] = static_cast<int>(soup.triangles[t][i]);
  }
  char switches[] = "pYczQ";
  try {
    tetrahedralize(switches, &in, &result);
  } catch(int code) {
    std::ostringstream s;
    s << "Tetrahedral_mesher: TetGen's boundary recovery failed (TetGen error " << code << ")";
    throw std::runtime_error(s.str());
  }
  if(result.numberofpoints < in.numberofpoints || result.numberofcorners != 4)
    throw std::runtime_error("Tetrahedral_mesher: TetGen returned an unexpected mesh");

  std::vector<std::array<double, 3>> points(static_cast<std::size_t>(result.numberofpoints));
  for(std::size_t i = 0; i < points.size(); ++i) {
    for(int a = 0; a < 3; ++a) points[i][a] = result.pointlist[3 * i + a];
    if(i < soup.points.size() && points[i] != soup.points[i])
      throw std::runtime_error("Tetrahedral_mesher: TetGen moved an input point");
  }
  std::vector<std::array<Vertex_id, 4>> tets(static_cast<std::size_t>(result.numberoftetrahedra));
  for(std::size_t t = 0; t < tets.size(); ++t) {
    for(int i = 0; i < 4; ++i) tets[t][i] = static_cast<Vertex_id>(result.tetrahedronlist[4 * t + i]);
    const int o = orientation(points[tets[t][0]].data(), points[tets[t][1]].data(), points[tets[t][2]].data(),
                              points[tets[t][3]].data());
    if(o == 0) throw std::runtime_error("Tetrahedral_mesher: TetGen returned a flat tetrahedron");
    if(o < 0) std::swap(tets[t][0], tets[t][1]);
  }
  out.mesh = flat_storage_from_tetrahedra(points, tets);
  out.vertex_of_input.resize(soup.points.size());
  for(std::size_t i = 0; i < soup.points.size(); ++i) out.vertex_of_input[i] = static_cast<Vertex_id>(i);
  report.used_tetgen = true;
  report.steiner_points = points.size() - soup.points.size();
}

// Lines 2-3 of Algorithm 2.
inline Recovery_report empty_mesh_and_recovery(const Surface_soup& soup, int threads, Constrained_mesh& out)
{
  typedef std::chrono::steady_clock Clock;
  Recovery_report report;
  const Clock::time_point t0 = Clock::now();
  empty_mesh(soup, threads, out);
  const Clock::time_point t1 = Clock::now();
  report.missing_triangles = count_missing_facets(out.mesh, input_triangle_keys(soup, out.vertex_of_input));
  if(report.missing_triangles != 0) recover_with_tetgen(soup, out, report);
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
