// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Remeshing of the mesher's input surfaces to a target edge length, before
// they are meshed.  The mesher keeps its input triangles exactly, so a
// triangle much larger than the size next to it, or a wall thinner than its
// triangles, forces flat tetrahedra that no improvement can mend
// (Mesher_statistics::triangles_over_size counts such triangles).  A user
// who may change the boundary's triangles, as CGAL's Mesh_3 always does,
// remeshes it first, and meshes the result:
//
//   #include <CGAL/Fast_Delaunay_triangulation_3/Surface_remeshing.h>
//   CGAL::Fast_mesher_3::Tetrahedral_mesh mesh =
//       CGAL::Fast_mesher_3::mesh_remeshed_surface_files({"part.off"}, {0.02}, options);
//
// (remesh_surface_files alone returns the remeshed triangles).  Where a
// wall or a step is thinner than the length, the triangles on one side lie
// over the vertices of the other and the tetrahedra between them are flat;
// mesh_remeshed_surfaces sees them in the mesh and remeshes shorter.
//
// The remeshing is CGAL's isotropic_remeshing (Polygon_mesh_processing),
// run on each closed surface alone (a vertex is projected onto its own
// surface, never onto a neighbouring one).  Sharp edges, those where the
// normals of the two triangles differ by more than sharp_edge_angle, are
// kept as polylines: split and collapsed along themselves, never flipped;
// their vertices do not move, and a vertex where other than two sharp edges
// meet (a corner) is never removed.  Then edges between nearly coplanar
// triangles are flipped where that widens their smallest angle.  The
// output is checked as the mesher checks its input.

#ifndef CGAL_FAST_DELAUNAY_TRIANGULATION_3_SURFACE_REMESHING_H
#define CGAL_FAST_DELAUNAY_TRIANGULATION_3_SURFACE_REMESHING_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/detect_features.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/Euler_operations.h>

#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
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
  // mesh_remeshed_surfaces: times, at most 20, the surfaces are remeshed
  // again, each time 10% shorter, while the mesh keeps tetrahedra under
  // Mesher_options::quality_threshold (gamma) whose four vertices are on
  // the surface and that no triangle's shape forces (a wall or a step
  // narrower than the triangles; the improvement counts them, so with
  // Mesher_options::optimize off there is one attempt); the attempt with
  // the fewest is kept.  Mesher_options::progress reports each attempt's
  // passes.  0: one attempt.
  unsigned int shortenings = 3;
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
  if(options.shortenings > 20) throw std::invalid_argument("remesh_surfaces: shortenings must be at most 20");
}

// The smallest angle of triangle (a, b, c), in radians.
template <class Point>
double smallest_angle(const Point& a, const Point& b, const Point& c)
{
  auto angle = [](const Point& apex, const Point& p, const Point& q) {
    const auto u = p - apex, v = q - apex;
    const double cosine = u * v / std::sqrt(u.squared_length() * v.squared_length());
    return std::acos(std::max(-1.0, std::min(1.0, cosine)));
  };
  return std::min({angle(a, b, c), angle(b, c, a), angle(c, a, b)});
}

// isotropic_remeshing flips edges for the vertices' valences, not for the
// triangles' angles, and leaves caps (a vertex almost on the opposite edge)
// beside kept polylines; a triangle with an angle of 9 degrees forces
// tetrahedra with dihedral angles about as small.  Flips an edge that is
// not a feature where its two triangles are nearly coplanar (normals within
// 10 degrees: the surface moves by a few percent of the edge length, as
// the remeshing's own flips move it) and where that raises the smaller of
// their smallest angles.  Every flip raises that minimum over the pair, so
// the sweeps end; 10 of them bound the time where flips keep moving on.
// On CGAL's anchor_dense remeshed to 0.03 the smallest angle goes from
// 9.4 to 13.2 degrees, the mesh's smallest dihedral angle from 9.9 to 14.9.
//
//        c                 c
//       / \               /|\      edge a-b now,
//      a---b     -->     a | b     c-d after
//       \ /               \|/
//        d                 d
template <class Mesh, class Sharp_edges>
void flip_to_wider_angles(Mesh& mesh, const Sharp_edges& sharp)
{
  typedef typename boost::graph_traits<Mesh>::vertex_descriptor Vertex;
  const double flat_cosine = std::cos(10 * CGAL_PI / 180);
  for(int sweep = 0; sweep < 10; ++sweep) {
    std::size_t flips = 0;
    for(auto e : edges(mesh)) {
      if(get(sharp, e)) continue;
      const auto h = halfedge(e, mesh), o = opposite(h, mesh);
      const Vertex a = source(h, mesh), b = target(h, mesh);
      const Vertex c = target(next(h, mesh), mesh), d = target(next(o, mesh), mesh);
      // Flipping would make a vertex of degree 2, or an edge twice.
      if(c == d || degree(a, mesh) <= 3 || degree(b, mesh) <= 3) continue;
      bool joined = false;
      for(auto around : halfedges_around_target(c, mesh)) joined = joined || source(around, mesh) == d;
      if(joined) continue;
      const auto &pa = mesh.point(a), &pb = mesh.point(b), &pc = mesh.point(c), &pd = mesh.point(d);
      // Triangles (a, b, c) and (b, a, d) now, (a, d, c) and (b, c, d) after.
      const auto normal_abc = CGAL::cross_product(pb - pa, pc - pa);
      const auto normal_bad = CGAL::cross_product(pa - pb, pd - pb);
      const auto normal_adc = CGAL::cross_product(pd - pa, pc - pa);
      const auto normal_bcd = CGAL::cross_product(pc - pb, pd - pb);
      // A triangle whose sine of its angle at a or b is under 1e-10 (its
      // apex on the line ab, as the remeshing may leave one) has no normal
      // to trust; the other triangle's decides.
      const double ab = (pb - pa).squared_length();
      const bool flat_abc = !(normal_abc.squared_length() > 1e-20 * ab * (pc - pa).squared_length());
      const bool flat_bad = !(normal_bad.squared_length() > 1e-20 * ab * (pd - pb).squared_length());
      if(flat_abc && flat_bad) continue;
      if(!flat_abc && !flat_bad &&
         !(normal_abc * normal_bad >
           flat_cosine * std::sqrt(normal_abc.squared_length() * normal_bad.squared_length())))
        continue;
      auto facing = [&](const auto& normal) { return normal_adc * normal > 0 && normal_bcd * normal > 0; };
      if((!flat_abc && !facing(normal_abc)) || (!flat_bad && !facing(normal_bad))) continue;
      const double now = std::min(smallest_angle(pa, pb, pc), smallest_angle(pb, pa, pd));
      const double after = std::min(smallest_angle(pa, pd, pc), smallest_angle(pb, pc, pd));
      // Wider by more than rounding: no two flips undo each other.
      if(after > now * (1 + 1e-6)) {
        CGAL::Euler::flip_edge(h, mesh);
        ++flips;
      }
    }
    if(flips == 0) break;
  }
}

// A checked soup (Surface_input.h: closed, oriented outward, manifold, not
// intersecting), each of its surfaces remeshed alone; `checked` receives
// the output as the mesher reads it.
inline Surface_triangles remeshed(const Surface_soup& soup, const Surface_remeshing_options& options,
                                  Surface_soup& checked)
{
  typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
  typedef CGAL::Surface_mesh<K::Point_3> Mesh;
  typedef boost::graph_traits<Mesh>::vertex_descriptor Vertex;
  typedef boost::graph_traits<Mesh>::edge_descriptor Edge;

  // A target far below the surfaces' scale would allocate without bound
  // before failing: refused when it would give over 5e7 triangles (the
  // remeshing's mesh and search tree then take gigabytes).  An equilateral
  // triangle of side 4/5 of the length, the shortest edges the remeshing
  // keeps, covers 0.28 length^2; 0.25 length^2 errs on the side of more.
  double area = 0;
  for(const auto& t : soup.triangles) {
    const auto& a = soup.points[t[0]];
    const auto& b = soup.points[t[1]];
    const auto& c = soup.points[t[2]];
    const K::Vector_3 u(b[0] - a[0], b[1] - a[1], b[2] - a[2]), v(c[0] - a[0], c[1] - a[1], c[2] - a[2]);
    area += 0.5 * std::sqrt(CGAL::cross_product(u, v).squared_length());
  }
  const double length = options.target_edge_length;
  const double expected_triangles = area / (0.25 * length * length);
  if(!(expected_triangles < 5e7)) {
    std::ostringstream message;
    message << "remesh_surfaces: target_edge_length " << length << " would give about " << expected_triangles
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
        faces(mesh), length, mesh,
        CGAL::parameters::number_of_iterations(options.iterations)
            .edge_is_constrained_map(sharp)
            .vertex_is_constrained_map(corner)
            .protect_constraints(false));
    flip_to_wider_angles(mesh, sharp);
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
  // sides of a thin wall, into contact, and a cap may be left flat: the
  // mesher would refuse that, so this does first, saying why.
  try {
    checked = Fast_Delaunay_triangulation_3_internal::mesher::surfaces_from_triangles(out.points, out.triangles);
  } catch(const std::invalid_argument& e) {
    std::string defect = e.what();
    const std::string mesher_prefix = "Tetrahedral_mesher: ";
    if(defect.compare(0, mesher_prefix.size(), mesher_prefix) == 0) defect.erase(0, mesher_prefix.size());
    std::ostringstream message;
    message << "remesh_surfaces: the surfaces remeshed to edge length " << length
            << " are not valid mesher input (triangle numbers are the remeshed ones): " << defect
            << "; a smaller length follows close surfaces and thin walls more closely";
    throw Fast_Delaunay_triangulation_3_internal::mesher::Invalid_surface(message.str());
  }
  return out;
}

inline Surface_triangles remeshed(const Surface_soup& soup, const Surface_remeshing_options& options)
{
  Surface_soup checked;
  return remeshed(soup, options, checked);
}

// Each shortening multiplies the length by this: 10% is about the step
// between lengths that do and do not resolve a thin part (couplingdown:
// 0.040 does, 0.042 does not), and 3 of them reach 0.73 times the length.
constexpr double shortening_factor = 0.9;

// Remeshes what read_soup reads and meshes it, shortening the length as
// Surface_remeshing_options::shortenings says.  A wall or a step narrower
// than the triangles leaves tetrahedra with four vertices on the surface
// that no interior point can mend: on CGAL's couplingdown remeshed to
// 0.048 a triangle 0.048 wide lies 0.0094 over the foot of a step, and the
// smallest dihedral angle stays at 8.3 degrees; 0.9 and 0.81 times that
// length leave such tetrahedra too, 0.73 times none (15.0 degrees).
// Which length works is not monotone (0.040 works there, 0.042 does not),
// so each attempt is meshed and judged by its mesh, and an attempt that
// fails (a shorter surface the mesher refuses, a recovery that fails)
// does not end the search.
template <class Read_soup>
Tetrahedral_mesh mesh_remeshed(Read_soup read_soup, const Surface_remeshing_options& remeshing,
                               const Mesher_options& options, Mesher_statistics* statistics)
{
  using mesher_detail::seconds_since;
  check_options(remeshing);
  mesher_detail::check_mesher_options(options); // before any work
  auto t0 = std::chrono::steady_clock::now();
  const Surface_soup soup = read_soup();
  const double input_seconds = seconds_since(t0);
  double remeshing_seconds = 0, discarded_seconds = 0;
  Tetrahedral_mesh kept;
  Mesher_statistics kept_stats;
  std::size_t kept_left = 0;
  bool have_kept = false;
  double length = remeshing.target_edge_length;
  unsigned int attempts = 0;
  for(unsigned int attempt = 0; attempt <= remeshing.shortenings; ++attempt, length *= shortening_factor) {
    Surface_remeshing_options shorter = remeshing;
    shorter.target_edge_length = length;
    ++attempts;
    Surface_soup checked;
    std::size_t triangles = 0;
    Mesher_statistics stats;
    Tetrahedral_mesh mesh;
    t0 = std::chrono::steady_clock::now();
    try {
      remeshed(soup, shorter, checked);
      triangles = checked.triangles.size();
      remeshing_seconds += seconds_since(t0);
      t0 = std::chrono::steady_clock::now();
      mesh = mesher_detail::read_and_mesh([&] { return std::move(checked); }, options, &stats,
                                          [](const auto&, const auto&) {});
    } catch(const std::exception&) {
      // The first attempt's failure is the caller's; a later one is an
      // attempt not kept.
      if(!have_kept) throw;
      discarded_seconds += seconds_since(t0);
      continue;
    }
    const std::size_t left = stats.improvement.bad_after_on_surface_not_forced;
    if(!have_kept || left < kept_left) {
      if(have_kept) discarded_seconds += kept_stats.input_seconds + kept_stats.total_seconds;
      kept = std::move(mesh);
      kept_stats = stats;
      kept_stats.remeshed_edge_length = length;
      kept_stats.remeshed_triangles = triangles;
      kept_left = left;
      have_kept = true;
    } else {
      discarded_seconds += stats.input_seconds + stats.total_seconds;
    }
    // Without the improvement the bad tetrahedra are not counted.
    if(left == 0 || !options.optimize) break;
  }
  kept_stats.input_seconds += input_seconds;
  kept_stats.remeshing_seconds = remeshing_seconds;
  kept_stats.remeshing_attempts = attempts;
  kept_stats.discarded_meshing_seconds = discarded_seconds;
  kept_stats.total_seconds += remeshing_seconds + discarded_seconds;
  if(statistics) *statistics = kept_stats;
  return kept;
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

// Remeshes the surfaces (as remesh_surfaces) and meshes them (as
// mesh_surfaces), remeshing shorter where the mesh asks for it
// (Surface_remeshing_options::shortenings).  `statistics` gets the kept
// attempt's figures and the remeshing's.  Throws what both functions throw.
inline Tetrahedral_mesh mesh_remeshed_surfaces(const std::vector<std::array<double, 3>>& points,
                                               const std::vector<std::array<std::size_t, 3>>& triangles,
                                               const Surface_remeshing_options& remeshing,
                                               const Mesher_options& options = Mesher_options(),
                                               Mesher_statistics* statistics = nullptr)
{
  return remeshing_detail::mesh_remeshed(
      [&] { return Fast_Delaunay_triangulation_3_internal::mesher::surfaces_from_triangles(points, triangles); },
      remeshing, options, statistics);
}

// The same for surface files, read as mesh_surface_files reads them.
inline Tetrahedral_mesh mesh_remeshed_surface_files(const std::vector<std::string>& paths,
                                                    const Surface_remeshing_options& remeshing,
                                                    const Mesher_options& options = Mesher_options(),
                                                    Mesher_statistics* statistics = nullptr)
{
  return remeshing_detail::mesh_remeshed(
      [&] { return Fast_Delaunay_triangulation_3_internal::mesher::read_surfaces(paths); }, remeshing, options,
      statistics);
}

} // namespace Fast_mesher_3
} // namespace CGAL

#endif // CGAL_FAST_DELAUNAY_TRIANGULATION_3_SURFACE_REMESHING_H
