// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Shape measures of one tetrahedron, shared by the quality report and the
// mesh improvement so that what is optimised is what is reported.
//
//   gamma = 3 r_in / r_circ  (1 for the regular tetrahedron, 0 for a flat
//   one, negative for an inverted one).  With u, v, w the edges from a,
//   D = u . (v x w) = 6 V, A the total facet area and
//   N = |u|^2 (v x w) + |v|^2 (w x u) + |w|^2 (u x v), the circumcentre is
//   a + N / (2 D) and r_in = 3 V / A, so gamma = 3 D |D| / (A |N|): no
//   square root but the areas', no division by a vanishing D.
//
//   dihedral angles at the six edges, in degrees (70.53 for the regular
//   tetrahedron); a sliver has some near 0 and some near 180.

#ifndef CGAL_FDT3_INTERNAL_MESHER_TETRAHEDRON_QUALITY_H
#define CGAL_FDT3_INTERNAL_MESHER_TETRAHEDRON_QUALITY_H

#include <algorithm>
#include <cmath>
#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

namespace quality_detail {

inline void cross(const double* x, const double* y, double* z)
{
  z[0] = x[1] * y[2] - x[2] * y[1];
  z[1] = x[2] * y[0] - x[0] * y[2];
  z[2] = x[0] * y[1] - x[1] * y[0];
}
inline double dot(const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
inline double norm(const double* x) { return std::sqrt(dot(x, x)); }

// The lengths of x and y.  Two square roots in one instruction where there
// is one: the facet areas' four roots were a third of gamma_quality's time
// (1 thread, GCC 12 -march=native on an AMD EPYC: 36 ns a call, 27 ns in
// pairs); the roots are correctly rounded either way, so the results are
// the same.
inline void norms(const double* x, const double* y, double& x_length, double& y_length)
{
#if defined(__SSE2__)
  const __m128d roots = _mm_sqrt_pd(_mm_setr_pd(dot(x, x), dot(y, y)));
  x_length = _mm_cvtsd_f64(roots);
  y_length = _mm_cvtsd_f64(_mm_unpackhi_pd(roots, roots));
#else
  x_length = norm(x);
  y_length = norm(y);
#endif
}
constexpr double pi = 3.14159265358979323846;

} // namespace quality_detail

// gamma of (a, b, c, d), with the sign of its orientation; with
// `smallest_dihedral_sine`, also the sine of its smallest dihedral angle,
// from the same facet normals (a positive tetrahedron's only: 0 otherwise).
inline double gamma_quality(const double* a, const double* b, const double* c, const double* d,
                            double* smallest_dihedral_sine = nullptr)
{
  using namespace quality_detail;
  double u[3], v[3], w[3], vw[3], wu[3], uv[3];
  for(int i = 0; i < 3; ++i) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = d[i] - a[i];
  }
  cross(v, w, vw);
  cross(w, u, wu);
  cross(u, v, uv);
  const double D = dot(u, vw);
  const double uu = dot(u, u), vv = dot(v, v), ww = dot(w, w);
  double N[3];
  for(int i = 0; i < 3; ++i) N[i] = uu * vw[i] + vv * wu[i] + ww * uv[i];
  // Facet areas times 2: (b, c, d) from (c - b) x (d - b) = vw + wu + uv.
  double bcd[3] = {vw[0] + wu[0] + uv[0], vw[1] + wu[1] + uv[1], vw[2] + wu[2] + uv[2]};
  double l_uv, l_vw, l_wu, l_bcd;
  norms(uv, vw, l_uv, l_vw);
  norms(wu, bcd, l_wu, l_bcd);
  const double twice_area = l_uv + l_vw + l_wu + l_bcd;
  const double denominator = twice_area * norm(N);
  if(smallest_dihedral_sine) {
    *smallest_dihedral_sine = 0;
    if(D > 0 && l_uv > 0 && l_vw > 0 && l_wu > 0 && l_bcd > 0) {
      // With D > 0 the outward normals are -uv, -vw, -wu (the facets
      // opposite d, b, c) and bcd (opposite a); the dihedral angle at the
      // edge two facets share has the cosine of minus their normals' dot
      // product.  The smallest angle has the largest cosine, and is at most
      // the regular tetrahedron's 70.5 degrees, where the sine still rises.
      const double highest = std::max({-dot(uv, vw) / (l_uv * l_vw), -dot(uv, wu) / (l_uv * l_wu),
                                       -dot(vw, wu) / (l_vw * l_wu), dot(uv, bcd) / (l_uv * l_bcd),
                                       dot(vw, bcd) / (l_vw * l_bcd), dot(wu, bcd) / (l_wu * l_bcd)});
      *smallest_dihedral_sine = std::sqrt(std::max(0.0, 1 - highest * highest));
    }
  }
  if(!(denominator > 0)) return 0;
  // 3 D |D| / (A |N|) with A = twice_area / 2.
  return 6 * D * std::abs(D) / denominator;
}

// An upper bound on the gamma of every tetrahedron that has (a, b, c) as a
// facet, wherever its fourth corner is: a surface triangle under which no
// tetrahedron reaches a threshold forces a bad one on whoever keeps it.
// With the triangle's area A, circumradius R and perimeter P, and the apex
// at height h above its plane: the volume is A h / 3 and each other facet
// has an area of at least its edge times h / 2, so r_in = 3 V / area is at
// most A h / (A + h P / 2); the circumscribed sphere meets the plane in the
// triangle's circumcircle and holds two points at least h apart, so r_circ
// is at least max(R, h / 2).  The bound on 3 r_in / r_circ these give is
// largest at h = 2 R, where it is 6 A / (A + R P); with R = l1 l2 l3 / (4 A) and
// n = (b - a) x (c - a), |n| = 2 A, that is 6 |n|^2 / (|n|^2 + l1 l2 l3 P).
// 1.2 for the equilateral triangle; about 1.5 times the radius ratio
// 2 r / R for a skinny one; 0 for a degenerate one.
inline double gamma_ceiling_on_triangle(const double* a, const double* b, const double* c)
{
  using namespace quality_detail;
  double u[3], v[3], w[3], n[3];
  for(int i = 0; i < 3; ++i) {
    u[i] = b[i] - a[i];
    v[i] = c[i] - a[i];
    w[i] = c[i] - b[i];
  }
  cross(u, v, n);
  const double nn = dot(n, n);
  const double lu = norm(u), lv = norm(v), lw = norm(w);
  const double denominator = nn + lu * lv * lw * (lu + lv + lw);
  return denominator > 0 ? 6 * nn / denominator : 0;
}

// The cosine of the angle at edge (a, b) between facets (a, b, c) and
// (a, b, d); 1 (a zero angle) for a degenerate facet.
inline double dihedral_cosine(const double* a, const double* b, const double* c, const double* d)
{
  using namespace quality_detail;
  double e[3], u[3], v[3];
  for(int i = 0; i < 3; ++i) {
    e[i] = b[i] - a[i];
    u[i] = c[i] - a[i];
    v[i] = d[i] - a[i];
  }
  double n1[3], n2[3];
  cross(e, u, n1);
  cross(e, v, n2);
  const double l = norm(n1) * norm(n2);
  if(!(l > 0)) return 1;
  return std::max(-1.0, std::min(1.0, dot(n1, n2) / l));
}

inline double degrees_of_cosine(double cosine) { return std::acos(cosine) * 180.0 / quality_detail::pi; }
// For the smallest dihedral angle, at most 70.5 degrees.
inline double degrees_of_sine(double sine) { return std::asin(std::min(1.0, sine)) * 180 / quality_detail::pi; }

// Angle at edge (a, b) between facets (a, b, c) and (a, b, d), in degrees.
inline double dihedral_degrees(const double* a, const double* b, const double* c, const double* d)
{
  return degrees_of_cosine(dihedral_cosine(a, b, c, d));
}

struct Dihedral_range
{
  double smallest = 180, largest = 0;
};

// The six edges of a tetrahedron, each with the two other corners.
static const int dihedral_edges[6][4] = {{0, 1, 2, 3}, {0, 2, 1, 3}, {0, 3, 1, 2},
                                         {1, 2, 0, 3}, {1, 3, 0, 2}, {2, 3, 0, 1}};

// Two arc cosines per tetrahedron, not six: the angle falls as the cosine rises.
inline Dihedral_range dihedral_range(const double* const w[4])
{
  double highest = -1, lowest = 1;
  for(const auto& e : dihedral_edges) {
    const double c = dihedral_cosine(w[e[0]], w[e[1]], w[e[2]], w[e[3]]);
    highest = std::max(highest, c);
    lowest = std::min(lowest, c);
  }
  Dihedral_range r;
  r.smallest = degrees_of_cosine(highest);
  r.largest = degrees_of_cosine(lowest);
  return r;
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_TETRAHEDRON_QUALITY_H
