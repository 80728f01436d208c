// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Surfaces of CGAL's data for the mesher's tests, extracted from
// libcgal-demo's archive by CMake (cmake/Fdt3CgalData.cmake) into
// FDT3_CGAL_DATA_DIR.

#ifndef FDT3_TEST_CGAL_DATA_SURFACE_H
#define FDT3_TEST_CGAL_DATA_SURFACE_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>

#include <gtest/gtest.h>

#include "mesher_shapes.h"

#include <cstddef>
#include <fstream>
#include <string>
#include <vector>

namespace mesher_shapes {

// Reads the triangle surface `name` of CGAL's data into s; false when the
// file is not there (the caller skips).
inline bool read_cgal_data_surface(const std::string& name, Surface& s)
{
  const std::string path = std::string(FDT3_CGAL_DATA_DIR) + "/" + name;
  if(!std::ifstream(path)) return false;
  std::vector<CGAL::Epick::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  EXPECT_TRUE(CGAL::IO::read_polygon_soup(path, points, polygons)) << path;
  for(const auto& p : points) s.points.push_back({p.x(), p.y(), p.z()});
  for(const auto& p : polygons) {
    EXPECT_EQ(p.size(), 3u);
    if(p.size() == 3) s.triangles.push_back({p[0], p[1], p[2]});
  }
  return true;
}

} // namespace mesher_shapes

#endif // FDT3_TEST_CGAL_DATA_SURFACE_H
