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
void circumcenter_offset(const double* const p[4], NT offset[3], NT& denominator)
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
    // The rounded midpoint may be off the middle by an ulp, as much as the box's half-width far from the origin:
    // the distance to the farther end, rounded up, is what the bound needs.
    const double half = std::max(z[k].sup() - ball.center[k], ball.center[k] - z[k].inf());
    half_diagonal2 += half * half;
    const I d = z[k] - I(p0[k]);
    r2 += d * d;
  }
  // Rounded up by a relative 1e-15 on top of the intervals' outward rounding, for the sum and the square root.
  ball.radius = (std::sqrt(r2.sup()) + std::sqrt(half_diagonal2)) * (1 + 1e-15);
  return ball;
}

// The same bound in plain doubles, for the well-conditioned tetrahedra that are almost all of them; false (and
// nothing computed) for the others. With M the largest |coordinate| of a, b, c and u the unit roundoff: each
// coordinate of num is 18 monomials of degree 4 (|a|^2 times a component of b x c, ...), at most 18 M^4 in all, and
// den is 12 monomials of degree 3, at most 12 M^3. Evaluated in floating point, with the rounding of a, b, c
// themselves, each monomial errs by about 12 u of its size at most (degree plus depth), so num by some 216 u M^4 and
// den by 144 u M^3. The bound takes 8000 u M^4 and 2000 u M^3, enough in any rounding mode (the caller runs with the
// rounding upward, one ulp per operation instead of half). The centre p0 + num / den then errs by at most
// delta = (8000 u M^4 + |num / den| 2000 u M^3) / |den| plus the last division and addition, and the ball of
// centre c~ and radius |c~ - p0| + 2 delta, rounded up, contains the true one. Refused when |den| < 10^4 u M^3 or
// when delta is not small beside the radius: there the intervals or the rationals decide.
// How loose a bound may be before a tighter one is computed: 1e-9 of the radius, or 64 ulps of the coordinates.
inline double tolerated_slack(double radius, const double* p0)
{
  return std::max(1e-9 * radius,
                  64 * std::numeric_limits<double>::epsilon() *
                      std::max({std::abs(p0[0]), std::abs(p0[1]), std::abs(p0[2])}));
}

inline bool fast_circumball_bound(const double* const p[4], Ball_bound& ball)
{
  constexpr double u = std::numeric_limits<double>::epsilon() / 2;
  double m = 0;
  for(int k = 0; k < 3; ++k)
    for(int v = 1; v < 4; ++v) m = std::max(m, std::abs(p[v][k] - p[0][k]));
  double offset[3], den;
  circumcenter_offset(p, offset, den);
  const double m3 = m * m * m;
  if(!(std::abs(den) >= 1e4 * u * m3) || !std::isfinite(m3 * m)) return false;
  double offset2 = 0;
  for(int k = 0; k < 3; ++k) {
    offset[k] /= den;
    offset2 += offset[k] * offset[k];
  }
  const double offset_norm = std::sqrt(offset2);
  const double delta = (8000 * u * m3 * m + offset_norm * 2000 * u * m3) / std::abs(den) +
                       8 * u * (offset_norm + std::max({std::abs(p[0][0]), std::abs(p[0][1]), std::abs(p[0][2])}));
  for(int k = 0; k < 3; ++k) ball.center[k] = p[0][k] + offset[k];
  const double dx = ball.center[0] - p[0][0], dy = ball.center[1] - p[0][1], dz = ball.center[2] - p[0][2];
  const double radius = std::sqrt(dx * dx + dy * dy + dz * dz);
  // A bound looser than 1e-9 of the radius is left to the intervals: the shell it adds around a large ball holds
  // points that the answering rank must then test with the exact predicate, one by one, and the predicate's filter
  // fails on such nearly cospherical points (measured: 26 s of 31 on 4e6 points, two ranks). A few ulps of the
  // coordinates are always allowed: no bound in doubles is tighter far from the origin, where points are that
  // coarse anyway (without it, 2000 points at 1e9 took the rationals for every cell).
  if(!(2 * delta <= tolerated_slack(radius, p[0]))) return false;
  ball.radius = (radius + 2 * delta) * (1 + 16 * u);
  return ball.is_finite();
}

// Must run with the FPU rounding upward (a Protect_FPU_rounding<true> in the caller's scope), as Interval_nt<false>
// requires; the caller sets it once for a whole scan of cells.
inline Ball_bound circumball_bound(const double* const p[4])
{
  typedef Interval_nt<false> I;
  {
    Ball_bound fast;
    if(fast_circumball_bound(p, fast)) return fast;
  }
  I offset[3], denominator;
  circumcenter_offset(p, offset, denominator);
  if(denominator.inf() > 0 || denominator.sup() < 0) {
    const I z[3] = {I(p[0][0]) + offset[0] / denominator, I(p[0][1]) + offset[1] / denominator,
                    I(p[0][2]) + offset[2] / denominator};
    const Ball_bound ball = ball_around(p[0], z);
    // Wide intervals mean bad conditioning (a flat tetrahedron): the exact centre gives a tighter bound.
    const double widest = std::max({z[0].sup() - z[0].inf(), z[1].sup() - z[1].inf(), z[2].sup() - z[2].inf()});
    if(ball.is_finite() && widest <= tolerated_slack(ball.radius, p[0])) return ball;
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
