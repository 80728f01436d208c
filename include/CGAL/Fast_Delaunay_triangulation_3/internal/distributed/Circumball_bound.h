// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A ball, in doubles, that surely contains the closed circumscribed ball of a tetrahedron: what one rank asks the
// others about ("which of your points lie in here?"). The distributed triangulation is exact only if no point of
// the true circumball is missed, so the bound is computed with interval arithmetic, and, where the intervals are
// too wide to be useful (a tetrahedron so flat that its orientation determinant's interval holds 0), exactly with
// rationals. Answering with a few points too many costs a ghost; missing one would cost a wrong cell.
//
// With a = p1 - p0, b = p2 - p0, c = p3 - p0 the centre is p0 + (|a|^2 b x c + |b|^2 c x a + |c|^2 a x b) / (2 a.(b x c)).
// If the true centre lies in the interval box [z] and m is the box's midpoint, every point q of the true ball has
// |q - m| <= |q - z| + |z - m| <= R + half-diagonal of [z], and R <= sup |[z] - p0|: that sum is the radius sent.

#ifndef CGAL_FDT3_INTERNAL_DISTRIBUTED_CIRCUMBALL_BOUND_H
#define CGAL_FDT3_INTERNAL_DISTRIBUTED_CIRCUMBALL_BOUND_H

#include <CGAL/Exact_rational.h>
#include <CGAL/Interval_nt.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace distributed {

// Centre and radius in doubles; contains(q) holds for every q of the true closed circumball (and a few more).
struct Ball_bound
{
  double center[3];
  double radius;

  // The relative slack covers the rounding of |q - m|^2 in doubles (a few units in the last place).
  bool contains(const double q[3]) const
  {
    const double dx = q[0] - center[0], dy = q[1] - center[1], dz = q[2] - center[2];
    return dx * dx + dy * dy + dz * dz <= radius * radius * (1 + 1e-12);
  }
  bool is_finite() const
  {
    return std::isfinite(center[0]) && std::isfinite(center[1]) && std::isfinite(center[2]) && std::isfinite(radius);
  }
};

template <class NT>
void circumcenter_offset(const double* p[4], NT offset[3], NT& denominator)
{
  NT a[3], b[3], c[3];
  for(int k = 0; k < 3; ++k) {
    a[k] = NT(p[1][k]) - NT(p[0][k]);
    b[k] = NT(p[2][k]) - NT(p[0][k]);
    c[k] = NT(p[3][k]) - NT(p[0][k]);
  }
  const NT bc[3] = {b[1] * c[2] - b[2] * c[1], b[2] * c[0] - b[0] * c[2], b[0] * c[1] - b[1] * c[0]};
  const NT ca[3] = {c[1] * a[2] - c[2] * a[1], c[2] * a[0] - c[0] * a[2], c[0] * a[1] - c[1] * a[0]};
  const NT ab[3] = {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
  const NT a2 = a[0] * a[0] + a[1] * a[1] + a[2] * a[2];
  const NT b2 = b[0] * b[0] + b[1] * b[1] + b[2] * b[2];
  const NT c2 = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  denominator = 2 * (a[0] * bc[0] + a[1] * bc[1] + a[2] * bc[2]);
  for(int k = 0; k < 3; ++k) offset[k] = a2 * bc[k] + b2 * ca[k] + c2 * ab[k];
}

// The bound from intervals around the centre: the box's midpoint, and the radius of the header's argument.
inline Ball_bound ball_around(const double* p0, const Interval_nt<false> z[3])
{
  typedef Interval_nt<false> I;
  Ball_bound ball;
  double half_diagonal2 = 0;
  I r2 = 0;
  for(int k = 0; k < 3; ++k) {
    ball.center[k] = 0.5 * z[k].inf() + 0.5 * z[k].sup();
    const double half = 0.5 * (z[k].sup() - z[k].inf());
    half_diagonal2 += half * half;
    const I d = z[k] - I(p0[k]);
    r2 += d * d;
  }
  // Rounded up by a relative 1e-15 on top of the intervals' outward rounding, for the sum and the square root.
  ball.radius = (std::sqrt(r2.sup()) + std::sqrt(half_diagonal2)) * (1 + 1e-15);
  return ball;
}

// Must run with the FPU rounding upward (a Protect_FPU_rounding<true> in the caller's scope), as Interval_nt<false>
// requires; the caller sets it once for a whole scan of cells.
inline Ball_bound circumball_bound(const double* p[4])
{
  typedef Interval_nt<false> I;
  I offset[3], denominator;
  circumcenter_offset(p, offset, denominator);
  if(denominator.inf() > 0 || denominator.sup() < 0) {
    const I z[3] = {I(p[0][0]) + offset[0] / denominator, I(p[0][1]) + offset[1] / denominator,
                    I(p[0][2]) + offset[2] / denominator};
    const Ball_bound ball = ball_around(p[0], z);
    // Wide intervals mean bad conditioning (a flat tetrahedron): the exact centre gives a tighter bound.
    const double widest = std::max({z[0].sup() - z[0].inf(), z[1].sup() - z[1].inf(), z[2].sup() - z[2].inf()});
    if(ball.is_finite() && widest <= 1e-6 * ball.radius) return ball;
  }
  I z[3];
  {
    // GMP's rationals and their conversion to intervals expect the default rounding.
    Protect_FPU_rounding<true> nearest(CGAL_FE_TONEAREST);
    Exact_rational exact_offset[3], exact_denominator;
    circumcenter_offset(p, exact_offset, exact_denominator);
    for(int k = 0; k < 3; ++k) {
      const Exact_rational coordinate = Exact_rational(p[0][k]) + exact_offset[k] / exact_denominator;
      const std::pair<double, double> bounds = CGAL::to_interval(coordinate);
      z[k] = I(bounds.first, bounds.second);
    }
  }
  return ball_around(p[0], z);
}

} // namespace distributed
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_DISTRIBUTED_CIRCUMBALL_BOUND_H
