// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The interface of mesher_benchmark_cgal.cpp: CGAL Mesh_3 on one benchmark surface.

#ifndef FDT3_MESHER_BENCHMARK_CGAL_H
#define FDT3_MESHER_BENCHMARK_CGAL_H

#include "mesher_benchmark_io.h"

#include <array>
#include <cstdint>
#include <vector>

namespace mesher_benchmark {

struct Cgal_mesh_3_run
{
  double refinement = 0, improvement = 0, total = 0; // make_mesh_3; perturb + exude; both
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra; // positively oriented, one subdomain
};

// Throws std::runtime_error for a surface Polyhedral_mesh_domain_3 cannot take (more than one closed surface).
Cgal_mesh_3_run run_cgal_mesh_3(const Benchmark_surface& s, double h);

} // namespace mesher_benchmark

#endif // FDT3_MESHER_BENCHMARK_CGAL_H
