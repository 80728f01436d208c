// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesher_benchmark's CGAL Mesh_3 row, in a translation unit of its own (Mesh_3's headers are the slowest of the
// benchmark to compile): make_mesh_3 on a Polyhedral_mesh_domain_3 of the surface, then perturb_mesh_3 and
// exude_mesh_3 (Mesh_3's sliver removal, its defaults: no time limit, the best bound it can reach), each timed.
// Mesh_3 samples the surface anew, so its boundary is never the input's; its sizing is one constant, the median
// of the same per-point surface sizes the other tools interpolate (capped the same way).

#include "mesher_benchmark_cgal.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
// CGAL 5.5's exuder uses this header's types under TBB without including it.
#include <CGAL/Mesh_3/Worksharing_data_structures.h>
#include <CGAL/Mesh_complex_3_in_triangulation_3.h>
#include <CGAL/Mesh_criteria_3.h>
#include <CGAL/Mesh_triangulation_3.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polyhedral_mesh_domain_3.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/exude_mesh_3.h>
#include <CGAL/make_mesh_3.h>
#include <CGAL/perturb_mesh_3.h>

#include <algorithm>
#include <chrono>
#include <map>
#include <stdexcept>
#include <vector>

namespace mesher_benchmark {

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef CGAL::Polyhedral_mesh_domain_3<Polyhedron, K> Domain;
typedef CGAL::Mesh_triangulation_3<Domain, CGAL::Default, CGAL::Sequential_tag>::type Tr;
typedef CGAL::Mesh_complex_3_in_triangulation_3<Tr> C3t3;
typedef CGAL::Mesh_criteria_3<Tr> Criteria;
typedef std::chrono::steady_clock Clock;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

} // namespace

Cgal_mesh_3_run run_cgal_mesh_3(const Benchmark_surface& s, double h)
{
  if(s.number_of_components != 1)
    throw std::runtime_error("one closed surface only (Polyhedral_mesh_domain_3 has one volume)");
  std::vector<K::Point_3> points;
  for(const Point& p : s.points) points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t>> faces;
  for(const Triangle& t : s.triangles) faces.push_back({t[0], t[1], t[2]});
  Polyhedron polyhedron;
  CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, polyhedron);

  Cgal_mesh_3_run run;
  const Clock::time_point t0 = Clock::now();
  Domain domain(polyhedron);
  namespace params = CGAL::parameters;
  const Criteria criteria(params::facet_angle = 25, params::facet_size = h, params::facet_distance = 0.1 * h,
                          params::cell_radius_edge_ratio = 2, params::cell_size = h);
  C3t3 c3t3 = CGAL::make_mesh_3<C3t3>(domain, criteria, params::no_perturb(), params::no_exude());
  run.refinement = seconds_since(t0);
  const Clock::time_point t1 = Clock::now();
  CGAL::perturb_mesh_3(c3t3, domain);
  CGAL::exude_mesh_3(c3t3);
  run.improvement = seconds_since(t1);
  run.total = seconds_since(t0);

  std::map<Tr::Vertex_handle, std::uint32_t> number;
  const Tr& tr = c3t3.triangulation();
  for(auto c = c3t3.cells_in_complex_begin(); c != c3t3.cells_in_complex_end(); ++c) {
    std::array<std::uint32_t, 4> tet;
    for(int i = 0; i < 4; ++i) {
      const auto inserted = number.emplace(c->vertex(i), static_cast<std::uint32_t>(run.points.size()));
      if(inserted.second) {
        const K::Point_3 p = tr.geom_traits().construct_point_3_object()(c->vertex(i)->point());
        run.points.push_back({p.x(), p.y(), p.z()});
      }
      tet[i] = inserted.first->second;
    }
    run.tetrahedra.push_back(tet);
  }
  return run;
}

} // namespace mesher_benchmark
