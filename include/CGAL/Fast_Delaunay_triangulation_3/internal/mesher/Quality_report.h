// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Quality figures of a Tetrahedral_mesh (what the paper's Figure 12 shows,
// and what a finite-element user checks): counts; the shape measures of
// Tetrahedron_quality.h as minimum, 1st percentile, mean and histogram
// (gamma = 3 r_in / r_circ, and the smallest dihedral angle of each
// tetrahedron), the extreme dihedral angles and the number of tetrahedra
// under gamma 0.3 and under 10 degrees, and of those under gamma 0.3 the
// ones the input surface forces (on an input triangle under which no
// tetrahedron reaches 0.3, gamma_ceiling_on_triangle); a histogram of the radius-edge ratio
// (circumradius / shortest edge; 0.612 for the regular tetrahedron); edge
// lengths relative to the target size h; the number of tetrahedra that are
// not positively oriented (exact test) and whether the mesh boundary is
// exactly the input surface: the facets that separate two subdomains or a
// subdomain from the outside, as a set, equal the input triangles.

#ifndef CGAL_FDT3_INTERNAL_MESHER_QUALITY_REPORT_H
#define CGAL_FDT3_INTERNAL_MESHER_QUALITY_REPORT_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Tetrahedra_replacement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Records_by_vertex.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Refinement.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedral_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Tetrahedron_quality.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <ostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_mesher_3 {

struct Quality_report
{
  std::size_t vertices = 0, tetrahedra = 0, boundary_triangles = 0;
  std::vector<std::size_t> tetrahedra_per_subdomain; // index 0 unused
  double min_dihedral_degrees = 180, max_dihedral_degrees = 0;
  // Of the smallest dihedral angle of each tetrahedron: 1st percentile, mean,
  // and a histogram in bins of min_dihedral_bin_degrees from 0.
  double min_dihedral_1st_percentile = 0, mean_min_dihedral = 0;
  double min_dihedral_bin_degrees = 5;
  std::vector<std::size_t> min_dihedral_histogram;
  std::size_t tetrahedra_below_10_degrees = 0;
  // gamma = 3 r_in / r_circ per tetrahedron; histogram bins [0, 0.1), ...
  // [0.9, 1] (an inverted tetrahedron counts in the first).
  double min_gamma = 1, gamma_1st_percentile = 0, mean_gamma = 0;
  std::vector<std::size_t> gamma_histogram;
  std::size_t tetrahedra_below_gamma_0_3 = 0;
  // Input triangles under which no tetrahedron reaches gamma 0.3 (a proven
  // bound, whatever the fourth corner), and the tetrahedra standing on one:
  // all of them are under 0.3, and no mesh that keeps the boundary avoids
  // them.  Only tetrahedra whose facet is the input triangle count, so a
  // mesh that remeshes the surface has none.
  std::size_t input_triangles_forcing_gamma_0_3 = 0;
  std::size_t tetrahedra_forced_below_gamma_0_3 = 0;
  std::size_t tetrahedra_below_gamma_0_3_not_forced() const
  {
    return tetrahedra_below_gamma_0_3 - tetrahedra_forced_below_gamma_0_3;
  }
  // Radius-edge ratio histogram: bins [0.6,0.7), [0.7,0.8), ... [2.0,inf).
  std::vector<double> radius_edge_bin_lower;
  std::vector<std::size_t> radius_edge_histogram;
  double max_radius_edge = 0;
  // Edge length over the mean h of its ends; all 0 without sizes.
  bool has_sizes = true; // the mesh has a size per point
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

// The value below which a share p of `values` lies (nearest rank), and the
// mean; `values` is reordered.
inline double percentile(std::vector<double>& values, double p)
{
  if(values.empty()) return 0;
  const std::size_t k = std::min(values.size() - 1, static_cast<std::size_t>(p * values.size()));
  std::nth_element(values.begin(), values.begin() + k, values.end());
  return values[k];
}
inline double mean(const std::vector<double>& values)
{
  double sum = 0;
  for(double x : values) sum += x;
  return values.empty() ? 0 : sum / values.size();
}

// The vertices of facet f of a tetrahedron, in increasing order.
inline std::array<std::uint32_t, 3> sorted_facet(const std::array<std::uint32_t, 4>& tv, int f)
{
  std::array<std::uint32_t, 3> key;
  sorted_facet_key(tv.data(), f, key.data());
  return key;
}

// `threads`: the loops over the tetrahedra and the vertices run on as many
// (TBB); the figures are the same for any number.
inline CGAL::Fast_mesher_3::Quality_report quality_report(const CGAL::Fast_mesher_3::Tetrahedral_mesh& mesh,
                                                          int threads = 1)
{
  // The loops below index the points and sizes by the tetrahedra's vertex
  // ids and the tags by tetrahedron: a mesh they would read past is refused
  // first.  Without sizes (improve_mesh keeps a mesh's none) the edges are
  // counted, not measured against h.
  const std::string defect = index_defect(mesh);
  if(!defect.empty()) throw std::invalid_argument("quality_report: " + defect);
  CGAL::Fast_mesher_3::Quality_report q;
  q.has_sizes = !mesh.size.empty();
  q.vertices = mesh.points.size();
  q.tetrahedra = mesh.tetrahedra.size();
  q.boundary_triangles = mesh.triangles.size();
  q.tetrahedra_per_subdomain.assign(mesh.number_of_subdomains + 1, 0);
  for(double x = 0.6; x < 2.05; x += 0.1) q.radius_edge_bin_lower.push_back(std::round(x * 10) / 10);
  q.radius_edge_histogram.assign(q.radius_edge_bin_lower.size(), 0);
  q.min_dihedral_histogram.assign(static_cast<std::size_t>(std::ceil(75 / q.min_dihedral_bin_degrees)), 0);
  q.gamma_histogram.assign(10, 0);
  std::vector<double> gammas, smallest_angles;

  std::vector<std::array<std::uint32_t, 3>> input, forcing;
  for(auto t : mesh.triangles) {
    // A triangle of points the mesh does not have is no facet of it.
    if(std::max({t[0], t[1], t[2]}) >= mesh.points.size()) {
      ++q.missing_input_triangles;
      continue;
    }
    const double ceiling = gamma_ceiling_on_triangle(mesh.points[t[0]].data(), mesh.points[t[1]].data(),
                                                     mesh.points[t[2]].data());
    std::sort(t.begin(), t.end());
    input.push_back(t);
    if(ceiling < 0.3) forcing.push_back(t);
  }
  std::sort(input.begin(), input.end());
  std::sort(forcing.begin(), forcing.end());
  forcing.erase(std::unique(forcing.begin(), forcing.end()), forcing.end());
  q.input_triangles_forcing_gamma_0_3 = forcing.size();

  // Per tetrahedron: its gamma and smallest angle, by index; counts and
  // extremes per chunk, added up in chunk order: the figures do not depend
  // on the number of threads.
  const std::size_t n = mesh.tetrahedra.size();
  gammas.resize(n);
  smallest_angles.resize(n);
  const int chunks = chunk_count(n, threads);
  std::vector<CGAL::Fast_mesher_3::Quality_report> tallies(chunks, q);
  for_each_chunk(chunks, [&](int c) {
    CGAL::Fast_mesher_3::Quality_report& tally = tallies[c];
    for(std::size_t t = chunk_begin(n, chunks, c); t < chunk_begin(n, chunks, c + 1); ++t) {
      const auto& tv = mesh.tetrahedra[t];
      const double* w[4] = {mesh.points[tv[0]].data(), mesh.points[tv[1]].data(), mesh.points[tv[2]].data(),
                            mesh.points[tv[3]].data()};
      const int s = mesh.subdomain[t];
      if(s >= 1 && s <= mesh.number_of_subdomains) ++tally.tetrahedra_per_subdomain[s];
      if(orientation(w[0], w[1], w[2], w[3]) <= 0) ++tally.inverted_tetrahedra;
      const Dihedral_range angles = dihedral_range(w);
      tally.min_dihedral_degrees = std::min(tally.min_dihedral_degrees, angles.smallest);
      tally.max_dihedral_degrees = std::max(tally.max_dihedral_degrees, angles.largest);
      smallest_angles[t] = angles.smallest;
      tally.tetrahedra_below_10_degrees += angles.smallest < 10 ? 1 : 0;
      ++tally.min_dihedral_histogram[std::min(tally.min_dihedral_histogram.size() - 1,
                                              static_cast<std::size_t>(angles.smallest / q.min_dihedral_bin_degrees))];
      const double gamma = gamma_quality(w[0], w[1], w[2], w[3]);
      gammas[t] = gamma;
      tally.tetrahedra_below_gamma_0_3 += gamma < 0.3 ? 1 : 0;
      ++tally.gamma_histogram[static_cast<std::size_t>(std::min(9.0, std::max(0.0, gamma * 10)))];
      double shortest = std::numeric_limits<double>::infinity();
      for(int k = 0; k < 6; ++k) {
        const auto& e = cell_edge_vertices[k];
        shortest = std::min(shortest, distance(w[e[0]], w[e[1]]));
      }
      double centre[3];
      if(circumcentre(w[0], w[1], w[2], w[3], centre)) {
        const double ratio = distance(centre, w[0]) / shortest;
        tally.max_radius_edge = std::max(tally.max_radius_edge, ratio);
        std::size_t bin = 0;
        while(bin + 1 < q.radius_edge_bin_lower.size() && ratio >= q.radius_edge_bin_lower[bin + 1]) ++bin;
        ++tally.radius_edge_histogram[bin];
      }
      bool forced = false;
      for(int f = 0; f < 4 && !forcing.empty(); ++f)
        forced = forced || std::binary_search(forcing.begin(), forcing.end(), sorted_facet(tv, f));
      // (The bound makes every forced gamma smaller; the test keeps the count
      // a part of the one under 0.3 whatever the roundings.)
      tally.tetrahedra_forced_below_gamma_0_3 += forced && gamma < 0.3 ? 1 : 0;
    }
  });
  auto add = [](std::vector<std::size_t>& sum, const std::vector<std::size_t>& part) {
    for(std::size_t i = 0; i < sum.size(); ++i) sum[i] += part[i];
  };
  for(const auto& tally : tallies) {
    add(q.tetrahedra_per_subdomain, tally.tetrahedra_per_subdomain);
    add(q.min_dihedral_histogram, tally.min_dihedral_histogram);
    add(q.gamma_histogram, tally.gamma_histogram);
    add(q.radius_edge_histogram, tally.radius_edge_histogram);
    q.inverted_tetrahedra += tally.inverted_tetrahedra;
    q.tetrahedra_below_10_degrees += tally.tetrahedra_below_10_degrees;
    q.tetrahedra_below_gamma_0_3 += tally.tetrahedra_below_gamma_0_3;
    q.tetrahedra_forced_below_gamma_0_3 += tally.tetrahedra_forced_below_gamma_0_3;
    q.min_dihedral_degrees = std::min(q.min_dihedral_degrees, tally.min_dihedral_degrees);
    q.max_dihedral_degrees = std::max(q.max_dihedral_degrees, tally.max_dihedral_degrees);
    q.max_radius_edge = std::max(q.max_radius_edge, tally.max_radius_edge);
  }

  if(!gammas.empty()) q.min_gamma = *std::min_element(gammas.begin(), gammas.end());
  q.mean_gamma = mean(gammas);
  q.gamma_1st_percentile = percentile(gammas, 0.01);
  q.mean_min_dihedral = mean(smallest_angles);
  q.min_dihedral_1st_percentile = percentile(smallest_angles, 0.01);

  // Edges and facets, each found once at its lowest vertex among the
  // tetrahedra around that vertex: one grouping of the 4n (vertex,
  // tetrahedron) incidences, then every vertex alone, on the report's
  // threads, its edges listed once with a per-thread mark and its facets
  // sorted in a local buffer.  (Grouping 6n edge and 4n facet records by
  // vertex, each group sorted, took about 0.5 s of the report's 0.64 s on
  // bunny00's mesh; this, about 0.35 s, mostly reading the tetrahedra
  // around each vertex.)
  const std::size_t nv = mesh.points.size();
  const Records_by_vertex<std::uint32_t> tetrahedra_around(
      nv, 4 * n, [&](std::size_t i) { return mesh.tetrahedra[i / 4][i % 4]; },
      [&](std::size_t i) { return static_cast<std::uint32_t>(i / 4); }, threads, Group_order::as_made);
  // The input triangles (sorted) whose lowest vertex is v: input_begin[v] ..
  // input_begin[v + 1].
  std::vector<std::size_t> input_begin(nv + 1, input.size());
  for(std::size_t i = input.size(); i-- > 0;) input_begin[input[i][0]] = i;
  for(std::size_t v = nv; v-- > 0;) input_begin[v] = std::min(input_begin[v], input_begin[v + 1]);

  // A facet seen from its lowest vertex: the other two, packed, and the
  // subdomain of the tetrahedron; sorted by both, the sides of one facet are
  // consecutive.
  struct Facet_side
  {
    std::uint64_t others;
    std::uint32_t subdomain;
    bool operator<(const Facet_side& o) const
    {
      return others != o.others ? others < o.others : subdomain < o.subdomain;
    }
  };
  auto pack = [](std::uint32_t b, std::uint32_t c) { return (std::uint64_t(b) << 32) | c; };
  struct Tally
  {
    std::size_t edges = 0, edges_below_0_7h = 0, boundary_facets = 0, input_on_boundary = 0, missing = 0;
    double min_edge = std::numeric_limits<double>::infinity(), max_edge = 0;
  };
  // Per vertex, the sum of its edges' ratios, added up in vertex order
  // afterwards: the mean does not depend on the number of threads.
  std::vector<double> edge_sum(nv, 0.0);
  // Each chunk's marks span every vertex: no more chunks than keep them
  // within the incidences' own memory (4n words).
  const int vertex_chunks =
      chunk_count_within(nv, threads, nv * sizeof(std::uint32_t), 4 * n * sizeof(std::uint32_t));
  std::vector<Tally> vertex_tallies(vertex_chunks);
  for_each_chunk(vertex_chunks, [&](int c) {
    Tally& tally = vertex_tallies[c];
    std::vector<std::uint32_t> ends;
    std::vector<Facet_side> sides;
    // listed_from[b] == a: the edge (a, b) is listed (no vertex is marked
    // from the last one at first: it has no higher vertex).
    std::vector<std::uint32_t> listed_from(nv, std::uint32_t(nv - 1));
    auto list_edge = [&](std::uint32_t a, std::uint32_t b) {
      if(listed_from[b] != a) {
        listed_from[b] = a;
        ends.push_back(b);
      }
    };
    for(std::uint32_t a = std::uint32_t(chunk_begin(nv, vertex_chunks, c));
        a < chunk_begin(nv, vertex_chunks, c + 1); ++a) {
      ends.clear();
      sides.clear();
      bool edge_to_itself = false;
      for(std::size_t k = tetrahedra_around.begin[a]; k < tetrahedra_around.begin[a + 1]; ++k) {
        const std::uint32_t tetrahedron = tetrahedra_around.records[k];
        // A tetrahedron with a twice is listed twice, one after the other
        // (the incidences are in the order they were made).
        if(k > tetrahedra_around.begin[a] && tetrahedra_around.records[k - 1] == tetrahedron) continue;
        const auto& tv = mesh.tetrahedra[tetrahedron];
        const std::uint32_t subdomain = static_cast<std::uint32_t>(mesh.subdomain[tetrahedron]);
        std::uint32_t higher[3];
        int count = 0, copies_of_a = 0;
        for(int j = 0; j < 4; ++j) {
          if(tv[j] > a) higher[count++] = tv[j];
          copies_of_a += tv[j] == a ? 1 : 0;
        }
        // The edges of a towards higher vertices.
        for(int j = 0; j < count; ++j) list_edge(a, higher[j]);
        if(copies_of_a > 1) {
          // A flat tetrahedron with a repeated vertex: its 4 facets and 6
          // edges as they are, the edge (a, a) and facets with a twice too.
          edge_to_itself = true;
          for(int f = 0; f < 4; ++f) {
            std::uint32_t key[3];
            sorted_facet_key(tv.data(), f, key);
            if(key[0] == a) sides.push_back({pack(key[1], key[2]), subdomain});
          }
          continue;
        }
        // The facets whose lowest vertex is a: those of a and two higher vertices.
        if(count < 2) continue;
        std::sort(higher, higher + count);
        sides.push_back({pack(higher[0], higher[1]), subdomain});
        if(count == 3) {
          sides.push_back({pack(higher[0], higher[2]), subdomain});
          sides.push_back({pack(higher[1], higher[2]), subdomain});
        }
      }
      if(edge_to_itself) ends.push_back(a);
      // Each edge once, (a, b) with a <= b: its length over the mean h of its
      // ends (where the mesh has sizes).
      double sum = 0;
      const std::size_t measured = q.has_sizes ? ends.size() : 0;
      for(std::size_t k = 0; k < measured; ++k) {
        const std::uint32_t b = ends[k];
        const double ratio =
            distance(mesh.points[a].data(), mesh.points[b].data()) / ((mesh.size[a] + mesh.size[b]) / 2);
        tally.min_edge = std::min(tally.min_edge, ratio);
        tally.max_edge = std::max(tally.max_edge, ratio);
        sum += ratio;
        if(ratio < 0.7) ++tally.edges_below_0_7h;
      }
      tally.edges += ends.size();
      edge_sum[a] = sum;

      // Each facet with the subdomains on its sides: a boundary facet has
      // one side, or two different ones.  The boundary facets are counted,
      // then the input triangles looked up (each distinct one once): a
      // boundary facet that is no input triangle is extra; an input
      // triangle is missing where it is no facet (counted for each copy) or
      // a facet inside a subdomain.
      std::sort(sides.begin(), sides.end());
      auto sides_of = [&](std::size_t k) {
        std::size_t end = k + 1;
        while(end < sides.size() && sides[end].others == sides[k].others) ++end;
        return end - k;
      };
      auto on_boundary = [&](std::size_t k, std::size_t count) {
        return count == 1 || (count == 2 && sides[k].subdomain != sides[k + 1].subdomain);
      };
      for(std::size_t k = 0; k < sides.size();) {
        const std::size_t count = sides_of(k);
        tally.boundary_facets += on_boundary(k, count) ? 1 : 0;
        k += count;
      }
      for(std::size_t i = input_begin[a]; i < input_begin[a + 1]; ++i) {
        const auto& triangle = input[i];
        const Facet_side lowest = {pack(triangle[1], triangle[2]), 0};
        const std::size_t k = std::size_t(std::lower_bound(sides.begin(), sides.end(), lowest) - sides.begin());
        if(k == sides.size() || sides[k].others != lowest.others) {
          ++tally.missing;
          continue;
        }
        if(i > input_begin[a] && input[i - 1] == triangle) continue; // a copy: the facet is counted
        if(on_boundary(k, sides_of(k))) ++tally.input_on_boundary;
        else ++tally.missing;
      }
    }
  });
  std::size_t boundary_facets = 0, input_on_boundary = 0;
  q.min_edge_over_h = std::numeric_limits<double>::infinity();
  for(const Tally& tally : vertex_tallies) {
    q.edges += tally.edges;
    q.edges_below_0_7h += tally.edges_below_0_7h;
    q.min_edge_over_h = std::min(q.min_edge_over_h, tally.min_edge);
    q.max_edge_over_h = std::max(q.max_edge_over_h, tally.max_edge);
    boundary_facets += tally.boundary_facets;
    input_on_boundary += tally.input_on_boundary;
    q.missing_input_triangles += tally.missing;
  }
  double sum = 0;
  for(const double s : edge_sum) sum += s;
  if(q.edges != 0) q.mean_edge_over_h = sum / q.edges;
  if(!q.has_sizes) q.min_edge_over_h = q.max_edge_over_h = q.mean_edge_over_h = 0;
  q.extra_boundary_facets = boundary_facets - input_on_boundary;
  return q;
}

inline void print_quality_report(std::ostream& out, const CGAL::Fast_mesher_3::Quality_report& q)
{
  out << "vertices " << q.vertices << ", tetrahedra " << q.tetrahedra << ", boundary triangles "
      << q.boundary_triangles << "\n";
  for(std::size_t s = 1; s < q.tetrahedra_per_subdomain.size(); ++s)
    out << "  subdomain " << s << ": " << q.tetrahedra_per_subdomain[s] << " tetrahedra\n";
  out << "dihedral angles: min " << q.min_dihedral_degrees << ", max " << q.max_dihedral_degrees << " degrees\n";
  out << "smallest dihedral angle per tetrahedron: 1st percentile " << q.min_dihedral_1st_percentile << ", mean "
      << q.mean_min_dihedral << " degrees; " << q.tetrahedra_below_10_degrees << " tetrahedra under 10 degrees\n";
  for(std::size_t b = 0; b < q.min_dihedral_histogram.size(); ++b)
    out << "  [" << b * q.min_dihedral_bin_degrees << ", " << (b + 1) * q.min_dihedral_bin_degrees << ") "
        << q.min_dihedral_histogram[b] << "\n";
  out << "gamma = 3 r_in / r_circ: min " << q.min_gamma << ", 1st percentile " << q.gamma_1st_percentile
      << ", mean " << q.mean_gamma << "; " << q.tetrahedra_below_gamma_0_3 << " tetrahedra under 0.3";
  if(q.input_triangles_forcing_gamma_0_3 != 0)
    out << " (" << q.tetrahedra_forced_below_gamma_0_3 << " of them forced: on one of the "
        << q.input_triangles_forcing_gamma_0_3 << " surface triangles under which no tetrahedron reaches 0.3)";
  out << "\n";
  for(std::size_t b = 0; b < q.gamma_histogram.size(); ++b)
    out << "  [" << b / 10.0 << ", " << (b + 1) / 10.0 << (b + 1 == q.gamma_histogram.size() ? "] " : ") ")
        << q.gamma_histogram[b] << "\n";
  out << "radius-edge ratio (max " << q.max_radius_edge << "):\n";
  for(std::size_t b = 0; b < q.radius_edge_histogram.size(); ++b) {
    out << "  ";
    if(b + 1 < q.radius_edge_bin_lower.size())
      out << "[" << q.radius_edge_bin_lower[b] << ", " << q.radius_edge_bin_lower[b + 1] << ") ";
    else
      out << "[" << q.radius_edge_bin_lower[b] << ", inf) ";
    out << q.radius_edge_histogram[b] << "\n";
  }
  if(q.has_sizes)
    out << "edge length / h: min " << q.min_edge_over_h << ", mean " << q.mean_edge_over_h << ", max "
        << q.max_edge_over_h << " (" << q.edges_below_0_7h << " of " << q.edges << " edges below 0.7)\n";
  else
    out << "edges: " << q.edges << " (no sizes in the mesh: none measured against h)\n";
  out << "inverted tetrahedra: " << q.inverted_tetrahedra << "\n";
  out << "boundary equals the surface: " << (q.boundary_equals_input() ? "yes" : "NO") << " ("
      << q.missing_input_triangles << " surface triangles missing, " << q.extra_boundary_facets
      << " extra boundary facets)\n";
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_QUALITY_REPORT_H
