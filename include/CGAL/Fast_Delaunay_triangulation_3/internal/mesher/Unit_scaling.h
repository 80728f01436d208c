// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher works on its input scaled by a power of two, 2^k, chosen so
// that the largest absolute coordinate lies in [0.5, 1).  Multiplying a
// double by a power of two is exact unless it overflows or leaves the
// normal range, so the scaled input is the same surface, exactly: every
// predicate gives the same signs and the mesh is the same, only its
// coordinates are scaled, and scaling back returns the input points bit
// for bit.  What it removes is the range problem: circumradii, sizes and
// TetGen's own arithmetic square and cube coordinates, which overflows from
// about 1e100 (TetGen aborted in its point location on a cube scaled by
// 1e100 and crashed in its memory pool on one scaled by 1e-100) and
// underflows below 1e-100.

#ifndef CGAL_FDT3_INTERNAL_MESHER_UNIT_SCALING_H
#define CGAL_FDT3_INTERNAL_MESHER_UNIT_SCALING_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Constrained_mesh.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Surface_input.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

class Unit_scaling
{
public:
  // The exponent for `soup`; throws Invalid_surface when a coordinate would
  // not survive the scaling exactly (coordinates spanning more binary orders
  // of magnitude than a double holds, e.g. 1e300 beside 1e-300).
  explicit Unit_scaling(const Surface_soup& soup)
  {
    const double largest = largest_coordinate(soup);
    if(largest == 0) return; // no extent at all: refused later as degenerate
    int e;
    std::frexp(largest, &e); // largest = m * 2^e, m in [0.5, 1)
    exponent_ = -e;
    for(std::size_t i = 0; i < soup.points.size(); ++i)
      for(double x : soup.points[i])
        if(std::ldexp(std::ldexp(x, exponent_), -exponent_) != x) {
          std::ostringstream s;
          s << "point #" << i << " has coordinate " << x << ", too small beside the largest coordinate, " << largest
            << ", to keep exactly at a common scale (it would fall below the normal range of doubles)";
          surface_detail::fail(s.str());
        }
  }

  int exponent() const { return exponent_; }
  double to_unit(double length) const { return std::ldexp(length, exponent_); }
  double from_unit(double length) const { return std::ldexp(length, -exponent_); }

  void scale(Surface_soup& soup) const
  {
    for(auto& p : soup.points)
      for(double& x : p) x = to_unit(x);
  }

  // The mesh back at the input's scale: vertices and sizes.
  void unscale(Constrained_mesh& cm) const
  {
    for(Vertex_record& r : cm.mesh.vertices)
      for(double& x : r.xyz) x = from_unit(x);
    for(double& h : cm.size) h = from_unit(h);
    for(int a = 0; a < 3; ++a) {
      cm.box_lo[a] = from_unit(cm.box_lo[a]);
      cm.box_hi[a] = from_unit(cm.box_hi[a]);
    }
  }

private:
  int exponent_ = 0;
};

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_UNIT_SCALING_H
