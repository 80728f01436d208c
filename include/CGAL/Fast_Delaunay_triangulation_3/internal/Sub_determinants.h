// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// In-sphere sub-determinants (paper §2.4): the 4x4 in-sphere determinant of a
// tetrahedron (a, b, c, d) and a query e, expanded along the row of e, is
//     det = Ex*S0 + Ey*S1 + Ez*S2 + |E|^2*S3,   E = e - a,
// where S0..S3 are signed 3x3 minors that depend on the tetrahedron only.
// They are computed once when the tetrahedron is created, so each of the
// ~1.6 conflict tests per created tetrahedron reads one vertex and four
// doubles instead of four vertices, and costs 7 flops instead of ~70.
// For a ghost tetrahedron (a, b, c, ghost) the stored values are the facet
// normal (b - a) x (c - a): the test is then orientation(a, b, c, e).
//
// The evaluation is filtered by a static error bound of the extent of the
// bounding box; undecided cases fall back to the robust predicates, so the
// result is always exact and perturbed as CGAL's.

#ifndef CGAL_FDT3_INTERNAL_SUB_DETERMINANTS_H
#define CGAL_FDT3_INTERNAL_SUB_DETERMINANTS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>

#include <algorithm>
#include <limits>

// Default of the runtime option (Fast_Delaunay_triangulation_3::set_sub_determinants).
// Off: on 1e6 uniform points, 1 thread, they made the insertion slower
// (1.71 s against 1.42 s: the Delaunay ball 80% longer, the cavity 9%, whose
// reads they double) for 32 more bytes per tetrahedron (the manual's Options
// section has the table).
#ifndef CGAL_FDT3_SUB_DETERMINANTS
#define CGAL_FDT3_SUB_DETERMINANTS 0
#endif

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

constexpr bool sub_determinants_by_default = CGAL_FDT3_SUB_DETERMINANTS != 0;

// Error bounds of the expanded evaluation, for coordinates whose pairwise
// differences are at most W per axis.  Forward error analysis of a
// straight-line program of +, -, *: |error| <= gamma_k * permanent, k the
// longest chain of roundings, gamma_k ~ k eps (eps = 2^-53).
//  - in-sphere: k = 11 (difference, lift, 2x2 minor, product with the lift,
//    3-term sum, product with E, 4-term sum); permanent <= 3 W * 18 W^4
//    (three minors of 6 terms coordinate^2 * lift <= 3 W^4) + 3 W^2 * 6 W^3
//    = 72 W^5; 11 * 72 eps = 8.79e-14, rounded up to 1e-13.
//  - ghost (orientation with a stored normal): k = 6, permanent <= 3 W * 2 W^2
//    = 6 W^3; 36 eps = 4.0e-15, rounded up to 5e-15.
struct Sub_determinant_filter
{
  static constexpr double in_sphere_factor = 1e-13;
  static constexpr double orientation_factor = 5e-15;

  // Infinite bounds send every test to the full predicate.
  double in_sphere = std::numeric_limits<double>::infinity();
  double orientation = std::numeric_limits<double>::infinity();

  static Sub_determinant_filter for_box(const double lo[3], const double hi[3])
  {
    Sub_determinant_filter f;
    double w = 0;
    for(int a = 0; a < 3; ++a) w = std::max(w, hi[a] - lo[a]);
    w *= 1.0 + 4 * Filter_bounds::unit_roundoff; // hi - lo may round down
    // Outside this range W^5 may underflow or overflow.
    if(w > 1e-50 && w < 1e50) {
      f.in_sphere = in_sphere_factor * w * w * w * w * w * (1.0 + 1e-12);
      f.orientation = orientation_factor * w * w * w * (1.0 + 1e-12);
    }
    return f;
  }
};

// Sub-determinants of the positively oriented (a, b, c, d).
inline void compute_sub_determinants(const double* a, const double* b, const double* c,
                                     const double* d, double* s)
{
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  const double dx = d[0] - a[0], dy = d[1] - a[1], dz = d[2] - a[2];
  const double bl = bx * bx + by * by + bz * bz;
  const double cl = cx * cx + cy * cy + cz * cz;
  const double dl = dx * dx + dy * dy + dz * dz;

  const double cy_dz = cy * dz - cz * dy, by_dz = by * dz - bz * dy, by_cz = by * cz - bz * cy;
  const double cx_dz = cx * dz - cz * dx, bx_dz = bx * dz - bz * dx, bx_cz = bx * cz - bz * cx;
  const double cx_dy = cx * dy - cy * dx, bx_dy = bx * dy - by * dx, bx_cy = bx * cy - by * cx;

  // Cofactors of the row (Ex, Ey, Ez, |E|^2) in the matrix with rows
  // (B, |B|^2), (C, |C|^2), (D, |D|^2), (E, |E|^2).
  s[0] = -(bl * cy_dz - cl * by_dz + dl * by_cz);
  s[1] = bl * cx_dz - cl * bx_dz + dl * bx_cz;
  s[2] = -(bl * cx_dy - cl * bx_dy + dl * bx_cy);
  s[3] = bx * cy_dz - by * cx_dz + bz * cx_dy;
}

// Normal of the hull facet (a, b, c) of the ghost (a, b, c, ghost).
inline void compute_ghost_normal(const double* a, const double* b, const double* c, double* s)
{
  const double bx = b[0] - a[0], by = b[1] - a[1], bz = b[2] - a[2];
  const double cx = c[0] - a[0], cy = c[1] - a[1], cz = c[2] - a[2];
  s[0] = by * cz - bz * cy;
  s[1] = bz * cx - bx * cz;
  s[2] = bx * cy - by * cx;
  s[3] = 0;
}

// +1: e strictly inside the sphere of the finite tetrahedron (in conflict),
// -1: strictly outside, 0: undecided by the filter.
inline int filtered_sub_determinant_side(const double* a, const double* s, const double* e,
                                         const Sub_determinant_filter& f)
{
  const double ex = e[0] - a[0], ey = e[1] - a[1], ez = e[2] - a[2];
  const double det = ex * s[0] + ey * s[1] + ez * s[2] + (ex * ex + ey * ey + ez * ez) * s[3];
  if(det < -f.in_sphere) return 1;
  if(det > f.in_sphere) return -1;
  return 0;
}

// Sign of orientation(a, b, c, e) for a ghost (a, b, c, ghost) from its
// stored normal, 0 if undecided.
inline int filtered_ghost_orientation(const double* a, const double* s, const double* e,
                                      const Sub_determinant_filter& f)
{
  const double det = (e[0] - a[0]) * s[0] + (e[1] - a[1]) * s[1] + (e[2] - a[2]) * s[2];
  if(det > f.orientation) return 1;
  if(det < -f.orientation) return -1;
  return 0;
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_SUB_DETERMINANTS_H
