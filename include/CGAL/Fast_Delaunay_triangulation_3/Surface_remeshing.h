// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Remeshing of the mesher's input surfaces to a target edge length, before
// they are meshed.  The mesher keeps its input triangles exactly, so a
// triangle much larger than the size next to it, or a wall thinner than its
// triangles, forces flat tetrahedra that no improvement can mend
// (Mesher_statistics::triangles_over_size counts such triangles).  A user
// who may change the boundary's triangles, as CGAL's Mesh_3 always does,
// remeshes it first:
//
//   #include <CGAL/Fast_Delaunay_triangulation_3/Surface_remeshing.h>
//   CGAL::Fast_mesher_3::Surface_triangles surface =
//       CGAL::Fast_mesher_3::remesh_surface_files({"part.off"}, {0.02});
//   CGAL::Fast_mesher_3::Tetrahedral_mesh mesh =
//       CGAL::Fast_mesher_3::mesh_surfaces(surface.points, surface.triangles, options);
//
// The remeshing is CGAL's isotropic_remeshing (Polygon_mesh_processing),
// run on each closed surface alone (a vertex is projected onto its own
// surface, never onto a neighbouring one).  Sharp edges, those where the
// normals of the two triangles differ by more than sharp_edge_angle, are
// kept as polylines: split and collapsed along themselves, never flipped;
// their vertices do not move, and a vertex where other than two sharp edges
// meet (a corner) is never removed.  The output is checked as the mesher
// checks its input.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_SURFACE_REMESHING_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_SURFACE_REMESHING_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_mesher_3 {

struct Surface_remeshing_options
{
  // The edge length to reach, in the input's coordinates (isotropic_remeshing
  // keeps edges between 4/5 and 4/3 of it).
  double target_edge_length = 0;
  // Degrees between the normals of two triangles over which their edge is a
  // feature to keep; 180: none is.
  double sharp_edge_angle = 60;
  // Rounds of split, collapse, flip, smoothing and projection.
  unsigned int iterations = 3;
};

// Closed surfaces as points and triangles (indices into points), outward.
struct Surface_triangles
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

namespace remeshing_detail {

using Fast_Delaunay_triangulation_3_internal::mesher::Surface_soup;

inline void check_options(const Surface_remeshing_options& options)
{
  if(!(options.target_edge_length > 0) || std::isinf(options.target_edge_length))
    throw std::invalid_argument("remesh_surfaces: target_edge_length must be positive and finite");
  if(!(options.sharp_edge_angle >= 0 && options.sharp_edge_angle <= 180))
    throw std::invalid_argument("remesh_surfaces: sharp_edge_angle must be in [0, 180] degrees");
  if(options.iterations < 1) throw std::invalid_argument("remesh_surfaces: iterations must be at least 1");
}

// A checked soup (Surface_input.h: closed, oriented outward, manifold, not
// intersecting), each of its surfaces remeshed alone.
inline Surface_triangles remeshed(const Surface_soup& soup, const Surface_remeshing_options& options)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor Vertex;
  typedef boost::graph_traits<Mesh>::edge_descriptor Edge;

  // The largest edge count a surface may reach: a target far below the
  // surface's scale would allocate without bound before failing.
  double area = 0;
  for(const auto& t : soup.triangles) {
    const auto& a = soup.points[t[0]];
    const auto& b = soup.points[t[1]];
    const auto& c = soup.points[t[2]];
    const K::Vector_3 u(b[0] - a[0], b[1] - a[1], b[2] - a[2]), v(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
    area += 0.5 * std::sqrt(CGAL::cross_product(u, v).squared_length());
  }
  const double l = options.target_edge_length;
  // An equilateral triangle of side 4/5 l, the shortest isotropic_remeshing
  // keeps, covers about 0.28 l^2.
  const double expected_triangles = area / (0.25 * l * l);
  if(!(expected_triangles < 2e8)) {
    std::ostringstream message;
    message << "remesh_surfaces: target_edge_length " << l << " would give about " << expected_triangles
            << " triangles on these surfaces (area " << area << "); choose a larger one";
    throw std::invalid_argument(message.str());
  }

  Surface_triangles out;
  std::vector<std::vector<std::size_t>> triangles_of(soup.number_of_surfaces + 1);
  for(std::size_t t = 0; t < soup.triangles.size(); ++t) triangles_of[soup.surface[t]].push_back(t);
  for(int s = 1; s <= soup.number_of_surfaces; ++s) {
    Mesh mesh;
    std::vector<Vertex> vertex_of(soup.points.size());
    std::vector<bool> added(soup.points.size(), false);
    for(std::size_t t : triangles_of[s]) {
      std::array<Vertex, 3> v;
      for(int i = 0; i < 3; ++i) {
        const std::uint32_t p = soup.triangles[t][i];
        if(!added[p]) {
          vertex_of[p] = mesh.add_vertex(K::Point_3(soup.points[p][0], soup.points[p][1], soup.points[p][2]));
          added[p] = true;
        }
        v[i] = vertex_of[p];
      }
      // The soup's surfaces are closed, oriented and manifold (checked).
      if(mesh.add_face(v[0], v[1], v[2]) == Mesh::null_face())
        throw std::logic_error("remesh_surfaces: a checked surface is not a polygon mesh");
    }

    auto sharp = mesh.add_property_map<Edge, bool>("e:sharp", false).first;
    auto corner = mesh.add_property_map<Vertex, bool>("v:corner", false).first;
    if(options.sharp_edge_angle < 180) {
      CGAL::Polygon_mesh_processing::detect_sharp_edges(mesh, options.sharp_edge_angle, sharp);
      for(Vertex v : vertices(mesh)) {
        int sharp_edges = 0;
        for(auto h : halfedges_around_target(v, mesh)) sharp_edges += get(sharp, edge(h, mesh)) ? 1 : 0;
        put(corner, v, sharp_edges != 0 && sharp_edges != 2);
      }
    }
    CGAL::Polygon_mesh_processing::isotropic_remeshing(
        faces(mesh), l, mesh,
        CGAL::parameters::number_of_iterations(options.iterations)
            .edge_is_constrained_map(sharp)
            .vertex_is_constrained_map(corner)
            .protect_constraints(false));
    mesh.collect_garbage();

    const std::size_t first = out.points.size();
    for(Vertex v : vertices(mesh)) {
      const K::Point_3& p = mesh.point(v);
      out.points.push_back({p.x(), p.y(), p.z()});
    }
    for(auto f : faces(mesh)) {
      std::array<std::size_t, 3> t;
      int i = 0;
      for(Vertex v : vertices_around_face(mesh.halfedge(f), mesh)) t[i++] = first + std::size_t(v);
      out.triangles.push_back(t);
    }
  }
  // Vertices projected onto curved parts may bring two surfaces, or two
  // sides of a thin wall, into contact: the mesher would refuse that, so
  // this does first, saying why.
  try {
    Fast_Delaunay_triangulation_3_internal::mesher::surfaces_from_triangles(out.points, out.triangles);
  } catch(const std::invalid_argument& e) {
    std::ostringstream message;
    message << "remesh_surfaces: remeshed to edge length " << l
            << ", the surfaces are no longer valid input (a smaller length may keep them apart): " << e.what();
    throw Fast_Delaunay_triangulation_3_internal::mesher::Invalid_surface(message.str());
  }
  return out;
}

} // namespace remeshing_detail

// Remeshes closed triangulated surfaces to options.target_edge_length.
// Throws std::invalid_argument for bad options, Invalid_surface (naming the
// problem) for surfaces the mesher would refuse, before or after remeshing.
inline Surface_triangles remesh_surfaces(const std::vector<std::array<double, 3>>& points,
                                         const std::vector<std::array<std::size_t, 3>>& triangles,
                                         const Surface_remeshing_options& options)
{
  remeshing_detail::check_options(options);
  return remeshing_detail::remeshed(
      Fast_Delaunay_triangulation_3_internal::mesher::surfaces_from_triangles(points, triangles), options);
}

// The same for surface files (any format CGAL::IO::read_polygon_soup reads,
// and ASCII OFF), read as mesh_surface_files reads them.
inline Surface_triangles remesh_surface_files(const std::vector<std::string>& paths,
                                              const Surface_remeshing_options& options)
{
  remeshing_detail::check_options(options);
  return remeshing_detail::remeshed(Fast_Delaunay_triangulation_3_internal::mesher::read_surfaces(paths), options);
}

} // namespace Fast_mesher_3
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_SURFACE_REMESHING_H
