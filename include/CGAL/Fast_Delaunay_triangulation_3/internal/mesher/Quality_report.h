// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality figures of a Tetrahedral_mesh (what the paper's Figure 12 and the
// issue ask for): counts, extreme dihedral angles, a histogram of the
// radius-edge ratio (circumradius / shortest edge; 0.612 for the regular
// tetrahedron), edge lengths relative to the target size h, the number of
// tetrahedra that are not positively oriented (exact test) and whether the
// mesh boundary is exactly the input surface: the facets that separate two
// subdomains or a subdomain from the outside, as a set, equal the input
// triangles.

#ifndef CGAL_FDT3_INTERNAL_MESHER_QUALITY_REPORT_H
#define CGAL_FDT3_INTERNAL_MESHER_QUALITY_REPORT_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Refinement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedral_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <ostream>
#include <vector>

namespace CGAL {
namespace Fast_mesher_3 {

struct Quality_report
{
  std::size_t vertices = 0, tetrahedra = 0, boundary_triangles = 0;
  std::vector<std::size_t> tetrahedra_per_subdomain; // index 0 unused
  double min_dihedral_degrees = 180, max_dihedral_degrees = 0;
  // Radius-edge ratio histogram: bins [0.6,0.7), [0.7,0.8), ... [2.0,inf).
  std::vector<double> radius_edge_bin_lower;
  std::vector<std::size_t> radius_edge_histogram;
  double max_radius_edge = 0;
  double min_edge_over_h = 0, max_edge_over_h = 0, mean_edge_over_h = 0;
  std::size_t edges = 0, edges_below_0_7h = 0;
  std::size_t inverted_tetrahedra = 0;     // orientation <= 0, exact
  std::size_t missing_input_triangles = 0; // input triangles that are not mesh boundary facets
  std::size_t extra_boundary_facets = 0;   // mesh boundary facets that are not input triangles
  bool boundary_equals_input() const { return missing_input_triangles == 0 && extra_boundary_facets == 0; }
};

} // namespace Fast_mesher_3

namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

inline double dihedral_degrees(const double* a, const double* b, const double* c, const double* d)
{
  // Angle at edge (a, b) between faces (a, b, c) and (a, b, d).
  double e[3], u[3], v[3];
  for(int i = 0; i < 3; ++i) {
    e[i] = b[i] - a[i];
    u[i] = c[i] - a[i];
    v[i] = d[i] - a[i];
  }
  auto cross = [](const double* x, const double* y, double* z) {
    z[0] = x[1] * y[2] - x[2] * y[1];
    z[1] = x[2] * y[0] - x[0] * y[2];
    z[2] = x[0] * y[1] - x[1] * y[0];
  };
  double n1[3], n2[3];
  cross(e, u, n1);
  cross(e, v, n2);
  const double dot = n1[0] * n2[0] + n1[1] * n2[1] + n1[2] * n2[2];
  const double l = std::sqrt((n1[0] * n1[0] + n1[1] * n1[1] + n1[2] * n1[2]) *
                             (n2[0] * n2[0] + n2[1] * n2[1] + n2[2] * n2[2]));
  if(!(l > 0)) return 0;
  return std::acos(std::max(-1.0, std::min(1.0, dot / l))) * 180.0 / 3.14159265358979323846;
}

inline CGAL::Fast_mesher_3::Quality_report quality_report(const CGAL::Fast_mesher_3::Tetrahedral_mesh& mesh)
{
  CGAL::Fast_mesher_3::Quality_report q;
  q.vertices = mesh.points.size();
  q.tetrahedra = mesh.tetrahedra.size();
  q.boundary_triangles = mesh.triangles.size();
  q.tetrahedra_per_subdomain.assign(mesh.number_of_subdomains + 1, 0);
  for(double x = 0.6; x < 2.05; x += 0.1) q.radius_edge_bin_lower.push_back(std::round(x * 10) / 10);
  q.radius_edge_histogram.assign(q.radius_edge_bin_lower.size(), 0);

  static const int edge_of[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};
  std::map<std::pair<std::uint32_t, std::uint32_t>, double> edges;
  std::map<std::array<std::uint32_t, 3>, std::vector<int>> facet_sides;
  for(std::size_t t = 0; t < mesh.tetrahedra.size(); ++t) {
    const auto& tv = mesh.tetrahedra[t];
    const double* w[4] = {mesh.points[tv[0]].data(), mesh.points[tv[1]].data(), mesh.points[tv[2]].data(),
                          mesh.points[tv[3]].data()};
    const int s = mesh.subdomain[t];
    if(s >= 1 && s <= mesh.number_of_subdomains) ++q.tetrahedra_per_subdomain[s];
    if(orientation(w[0], w[1], w[2], w[3]) <= 0) ++q.inverted_tetrahedra;
    double shortest = std::numeric_limits<double>::infinity();
    for(const auto& e : edge_of) {
      int others[2], k = 0;
      for(int i = 0; i < 4; ++i)
        if(i != e[0] && i != e[1]) others[k++] = i;
      const double angle = dihedral_degrees(w[e[0]], w[e[1]], w[others[0]], w[others[1]]);
      q.min_dihedral_degrees = std::min(q.min_dihedral_degrees, angle);
      q.max_dihedral_degrees = std::max(q.max_dihedral_degrees, angle);
      const double l = distance(w[e[0]], w[e[1]]);
      shortest = std::min(shortest, l);
      const double h = (mesh.size[tv[e[0]]] + mesh.size[tv[e[1]]]) / 2;
      edges[{std::min(tv[e[0]], tv[e[1]]), std::max(tv[e[0]], tv[e[1]])}] = l / h;
    }
    double centre[3];
    if(circumcentre(w[0], w[1], w[2], w[3], centre)) {
      const double ratio = distance(centre, w[0]) / shortest;
      q.max_radius_edge = std::max(q.max_radius_edge, ratio);
      std::size_t bin = 0;
      while(bin + 1 < q.radius_edge_bin_lower.size() && ratio >= q.radius_edge_bin_lower[bin + 1]) ++bin;
      ++q.radius_edge_histogram[bin];
    }
    for(int f = 0; f < 4; ++f) {
      std::array<std::uint32_t, 3> key;
      for(int i = 0, k = 0; i < 4; ++i)
        if(i != f) key[k++] = tv[i];
      std::sort(key.begin(), key.end());
      facet_sides[key].push_back(s);
    }
  }

  q.edges = edges.size();
  double sum = 0;
  q.min_edge_over_h = std::numeric_limits<double>::infinity();
  for(const auto& e : edges) {
    q.min_edge_over_h = std::min(q.min_edge_over_h, e.second);
    q.max_edge_over_h = std::max(q.max_edge_over_h, e.second);
    sum += e.second;
    if(e.second < 0.7) ++q.edges_below_0_7h;
  }
  if(q.edges != 0) q.mean_edge_over_h = sum / q.edges;

  std::vector<std::array<std::uint32_t, 3>> input;
  for(auto t : mesh.triangles) {
    std::sort(t.begin(), t.end());
    input.push_back(t);
  }
  std::sort(input.begin(), input.end());
  for(const auto& entry : facet_sides) {
    const std::vector<int>& sides = entry.second;
    const bool boundary = sides.size() == 1 || (sides.size() == 2 && sides[0] != sides[1]);
    const bool is_input = std::binary_search(input.begin(), input.end(), entry.first);
    if(boundary && !is_input) ++q.extra_boundary_facets;
    if(!boundary && is_input) ++q.missing_input_triangles;
  }
  for(const auto& t : input)
    if(facet_sides.find(t) == facet_sides.end()) ++q.missing_input_triangles;
  return q;
}

inline void print_quality_report(std::ostream& out, const CGAL::Fast_mesher_3::Quality_report& q)
{
  out << "vertices " << q.vertices << ", tetrahedra " << q.tetrahedra << ", boundary triangles "
      << q.boundary_triangles << "\n";
  for(std::size_t s = 1; s < q.tetrahedra_per_subdomain.size(); ++s)
    out << "  subdomain " << s << ": " << q.tetrahedra_per_subdomain[s] << " tetrahedra\n";
  out << "dihedral angles: min " << q.min_dihedral_degrees << ", max " << q.max_dihedral_degrees << " degrees\n";
  out << "radius-edge ratio (max " << q.max_radius_edge << "):\n";
  for(std::size_t b = 0; b < q.radius_edge_histogram.size(); ++b) {
    out << "  ";
    if(b + 1 < q.radius_edge_bin_lower.size())
      out << "[" << q.radius_edge_bin_lower[b] << ", " << q.radius_edge_bin_lower[b + 1] << ") ";
    else
      out << "[" << q.radius_edge_bin_lower[b] << ", inf) ";
    out << q.radius_edge_histogram[b] << "\n";
  }
  out << "edge length / h: min " << q.min_edge_over_h << ", mean " << q.mean_edge_over_h << ", max "
      << q.max_edge_over_h << " (" << q.edges_below_0_7h << " of " << q.edges << " edges below 0.7)\n";
  out << "inverted tetrahedra: " << q.inverted_tetrahedra << "\n";
  out << "boundary equals the input: " << (q.boundary_equals_input() ? "yes" : "NO") << " ("
      << q.missing_input_triangles << " input triangles missing, " << q.extra_boundary_facets
      << " extra boundary facets)\n";
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_QUALITY_REPORT_H
