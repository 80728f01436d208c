// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Robust orientation and in-sphere predicates on double coordinates (paper
// §2.4 "Implementation details"), with CGAL's symbolic perturbation so that the
// Delaunay triangulation is unique and identical to CGAL's.
//
// Stages: an inline floating-point evaluation with an error bound from the
// bounding box (the cavity's in-sphere test: from its own points), a
// semi-static bound from the actual coordinate differences (no global state,
// so triangulations of different extents can live side by side), an exact
// evaluation in doubles where the differences allow it, a double-double one
// for the in-sphere test, then CGAL's own filtered exact predicates (interval
// arithmetic, then exact numbers) out of line.  Perturbation follows
// Delaunay_triangulation_3::side_of_oriented_sphere and
// coplanar_side_of_bounded_circle of CGAL 5.5: ties are broken by the
// lexicographic order of the points, which makes the triangulation independent
// of the insertion order.
//
// Sign conventions are CGAL's: orientation(p,q,r,s) is the sign of
// det[q-p, r-p, s-p]; side_of_oriented_sphere(p,q,r,s,t) is positive when t is
// inside the sphere through a positively oriented p,q,r,s.

#ifndef CGAL_FDT3_INTERNAL_PREDICATES_H
#define CGAL_FDT3_INTERNAL_PREDICATES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>

// The AVX2 and FMA forms of the hot predicates (CGAL_FDT3_SIMD_RECORDS).
// Built for AVX2 (-march=native on a recent x86-64), they are the only
// forms the insertion uses.  Otherwise GCC and clang on x86-64 still
// compile them, as functions for that target (CGAL_FDT3_TARGET_AVX2), and
// an insertion picks them once, at its start, where the processor has AVX2
// and FMA (use_avx2_paths): a plain Release build, what a user who adds the
// headers to a project gets, is then as fast as a native one.  Other
// compilers and targets have the vector forms only when built for AVX2 and
// FMA.  The insertion loop with the AVX2 forms is one function with every
// call below it inlined (flatten), so that the vector predicates are inlined
// into the walk and the cavity search and, in a plain build, the whole loop
// is built for AVX2.  Measured on 1e6 uniform points, 1 thread, GCC 12: 2-4%
// faster than the compiler's own inlining choices in a -march=native build.
#if defined(__AVX2__) && defined(__FMA__)
#define CGAL_FDT3_SIMD_RECORDS 1
#define CGAL_FDT3_TARGET_AVX2
#if defined(__GNUC__) || defined(__clang__)
#define CGAL_FDT3_AVX2_FLATTEN __attribute__((flatten))
#else
#define CGAL_FDT3_AVX2_FLATTEN
#endif
#elif(defined(__GNUC__) || defined(__clang__)) && defined(__x86_64__) && !defined(CGAL_FDT3_NO_AVX2_DISPATCH)
#define CGAL_FDT3_SIMD_RECORDS 1
#define CGAL_FDT3_AVX2_DISPATCH 1
#define CGAL_FDT3_TARGET_AVX2 __attribute__((target("avx2,fma")))
#define CGAL_FDT3_AVX2_FLATTEN __attribute__((target("avx2,fma"), flatten))
#endif

#ifdef CGAL_FDT3_SIMD_RECORDS
#include <immintrin.h>
#endif

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// Which forms of the predicates a kernel instantiation calls: a template
// argument, so that the choice is made once per insertion, not per test.
struct Scalar_paths
{
  static constexpr bool avx2 = false;
};
struct Avx2_paths
{
  static constexpr bool avx2 = true;
};
#if defined(CGAL_FDT3_SIMD_RECORDS) && !defined(CGAL_FDT3_AVX2_DISPATCH)
typedef Avx2_paths Default_paths; // built for AVX2: no choice to make
#else
typedef Scalar_paths Default_paths; // for the kernels that do not choose (single insertions, queries)
#endif

// Forces the scalar forms, for the tests (both forms must build the same
// triangulation) and for measurements.  Read at the start of an insertion.
inline std::atomic<bool>& scalar_paths_forced()
{
  static std::atomic<bool> forced(false);
  return forced;
}

// Whether this processor runs the AVX2 and FMA forms; asked once per process.
inline bool processor_has_avx2_and_fma()
{
#if defined(CGAL_FDT3_SIMD_RECORDS) && !defined(CGAL_FDT3_AVX2_DISPATCH)
  return true;
#elif defined(CGAL_FDT3_AVX2_DISPATCH)
  static const bool has = [] {
    __builtin_cpu_init();
    return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
  }();
  return has;
#else
  return false;
#endif
}

inline bool use_avx2_paths()
{
  return processor_has_avx2_and_fma() && !scalar_paths_forced().load(std::memory_order_relaxed);
}

#ifdef CGAL_FDT3_SIMD_RECORDS
// f(Avx2_paths()) with f inlined into a function built for AVX2.
template <class F>
CGAL_FDT3_AVX2_FLATTEN void call_with_avx2_paths(F& f)
{
  f(Avx2_paths());
}
#endif

// f(Avx2_paths()) where the processor runs them (and they are not forced
// off), else f(Scalar_paths()): the one branch of an insertion on the
// choice.
template <class F>
void with_vector_paths(F&& f)
{
#ifdef CGAL_FDT3_SIMD_RECORDS
  if(use_avx2_paths()) call_with_avx2_paths(f);
  else f(Scalar_paths());
#else
  f(Scalar_paths());
#endif
}

// Error bounds of the floating-point stages.  Both follow Shewchuk's analysis
// of approximation "A" (which includes the rounding of the initial coordinate
// differences): |error| <= c(eps) * permanent, eps = 2^-53, with
//   orient3d:  c = (7 + 56 eps) eps,    permanent <= 6 * mx * my * mz
//   insphere:  c = (16 + 224 eps) eps,  permanent <= 4 * 6 * mx * my * mz * L,
// where mx, my, mz are the largest absolute differences per axis and
// L = mx^2 + my^2 + mz^2 bounds every lifted coordinate.  The constants below
// are 42 eps and 384 eps rounded up (relative margin 1e-5, far above the few
// ulps of error made when the bound itself is evaluated and above the
// 56 eps^2 and 224 eps^2 terms); test_predicates recomputes them.
struct Filter_bounds
{
  static constexpr double unit_roundoff = 1.1102230246251565e-16; // 2^-53
  static constexpr double orientation = 4.6630e-15;               // 42 eps = 4.66294e-15
  static constexpr double in_sphere = 4.2634e-14;                 // 384 eps = 4.26326e-14
  // Outside these magnitudes products may underflow or overflow and the bound
  // above is no longer valid: the exact stage decides.
  static constexpr double orientation_min = 1e-97, orientation_max = 1e102;
  static constexpr double in_sphere_min = 1e-58, in_sphere_max = 1e61;
  // The cavity search's per-call in-sphere bound, in the largest difference
  // M alone: mx my mz L <= 3 M^5, so 3 * 384 eps (rounded up).  Instead of
  // a lower limit it adds an absolute term for underflow: with every
  // difference below in_sphere_max, nothing overflows, and a product that
  // underflows is off by at most 2^-1075, which the later products multiply
  // by at most 6 max(1, M)^3 < 6e183; either form of the determinant rounds
  // fewer than 64 products, so together they are off by less than 1e-137
  // (64 * 2^-1075 * 6e183 = 9.5e-138).
  static constexpr double in_sphere_of_largest = 1.27899e-13; // 1152 eps = 1.278977e-13
  static constexpr double in_sphere_underflow = 1e-137;
  // The double-double stage of side_of_oriented_sphere: the same analysis
  // with exact differences and a unit roundoff of 5 eps^2 per operation
  // (Joldes, Muller, Popescu 2017: at most 4 eps^2 for a product, 3 eps^2 /
  // (1 - 4 eps) for a sum of two double-words), c = 16 * 5 eps^2 = 80 eps^2,
  // taken four times: 320 eps^2 * 24 = 9.4663e-29 (rounded up).  Within its
  // range every coordinate difference that matters is far from underflow and
  // the few that underflow add far less than the bound.
  static constexpr double in_sphere_double_double = 9.467e-29;
  static constexpr double in_sphere_double_double_min = 1e-30, in_sphere_double_double_max = 1e30;
};

namespace predicates_detail {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Exact_kernel;
typedef Exact_kernel::Point_3 Exact_point;

inline Exact_point to_point(const double* p) { return Exact_point(p[0], p[1], p[2]); }

// The exact stages live out of line: they are rare, and keeping them out of
// the inline fast path keeps the walk and cavity loops small.
__attribute__((noinline)) inline int orientation_exact(const double* p, const double* q,
                                                       const double* r, const double* s)
{
  return static_cast<int>(Exact_kernel().orientation_3_object()(to_point(p), to_point(q),
                                                                to_point(r), to_point(s)));
}

__attribute__((noinline)) inline int side_of_oriented_sphere_exact(const double* p, const double* q,
                                                                   const double* r, const double* s,
                                                                   const double* t)
{
  return static_cast<int>(Exact_kernel().side_of_oriented_sphere_3_object()(
      to_point(p), to_point(q), to_point(r), to_point(s), to_point(t)));
}

inline bool collinear_exact(const double* p, const double* q, const double* r)
{
  return Exact_kernel().collinear_3_object()(to_point(p), to_point(q), to_point(r));
}

inline int coplanar_orientation_exact(const double* p, const double* q, const double* r)
{
  return static_cast<int>(
      Exact_kernel().coplanar_orientation_3_object()(to_point(p), to_point(q), to_point(r)));
}

inline int coplanar_orientation_exact(const double* p, const double* q, const double* r,
                                      const double* s)
{
  return static_cast<int>(Exact_kernel().coplanar_orientation_3_object()(
      to_point(p), to_point(q), to_point(r), to_point(s)));
}

// CGAL's Bounded_side: +1 inside the circle, 0 on it, -1 outside.
inline int coplanar_side_of_bounded_circle_exact(const double* p, const double* q, const double* r,
                                                 const double* t)
{
  return static_cast<int>(Exact_kernel().coplanar_side_of_bounded_circle_3_object()(
      to_point(p), to_point(q), to_point(r), to_point(t)));
}

} // namespace predicates_detail

// Lexicographic order on (x, y, z): CGAL's Perturbation_order.
inline bool lexicographically_smaller(const double* p, const double* q)
{
  if(p[0] != q[0]) return p[0] < q[0];
  if(p[1] != q[1]) return p[1] < q[1];
  return p[2] < q[2];
}

inline bool same_point(const double* p, const double* q)
{
  return p[0] == q[0] && p[1] == q[1] && p[2] == q[2];
}

inline bool collinear(const double* p, const double* q, const double* r)
{
  return predicates_detail::collinear_exact(p, q, r);
}

// CGAL's coplanar_orientation(p, q, r): the 2D orientation in the first of
// the xy, yz and xz projections where it is not zero.  When the xy one is
// certainly not zero (Shewchuk's orient2d bound, 3 eps rounded up to 4 eps,
// with differences rounded in double) it is the answer; otherwise CGAL's
// exact predicate decides.  Products that may have underflowed have no bound.
inline int coplanar_orientation(const double* p, const double* q, const double* r)
{
  const double left = (q[0] - p[0]) * (r[1] - p[1]);
  const double right = (q[1] - p[1]) * (r[0] - p[0]);
  const double det = left - right;
  const double magnitude = std::fabs(left) + std::fabs(right);
  if(magnitude > 1e-280 && std::fabs(det) > 4 * std::numeric_limits<double>::epsilon() / 2 * magnitude)
    return det > 0 ? 1 : -1;
  return predicates_detail::coplanar_orientation_exact(p, q, r);
}

// The floating-point determinants.  orientation_determinant has CGAL's sign;
// in_sphere_determinant is Shewchuk's insphere(p,q,r,s,t), positive for t
// inside when orient3d(p,q,r,s) > 0, i.e. when CGAL's orientation is negative.
inline double orientation_determinant(const double* p, const double* q, const double* r,
                                      const double* s)
{
  const double qx = q[0] - p[0], qy = q[1] - p[1], qz = q[2] - p[2];
  const double rx = r[0] - p[0], ry = r[1] - p[1], rz = r[2] - p[2];
  const double sx = s[0] - p[0], sy = s[1] - p[1], sz = s[2] - p[2];
  return qx * (ry * sz - rz * sy) - qy * (rx * sz - rz * sx) + qz * (rx * sy - ry * sx);
}

// The rows p - t, q - t, r - t, s - t of the in-sphere determinant.
struct In_sphere_rows
{
  double ax, ay, az, bx, by, bz, cx, cy, cz, dx, dy, dz;

  In_sphere_rows(const double* p, const double* q, const double* r, const double* s, const double* t)
      : ax(p[0] - t[0]), ay(p[1] - t[1]), az(p[2] - t[2]), bx(q[0] - t[0]), by(q[1] - t[1]), bz(q[2] - t[2]),
        cx(r[0] - t[0]), cy(r[1] - t[1]), cz(r[2] - t[2]), dx(s[0] - t[0]), dy(s[1] - t[1]), dz(s[2] - t[2])
  {
  }

  // The largest |coordinate difference|: the per-call bound's M.
  double largest() const
  {
    const double x = std::max(std::max(std::fabs(ax), std::fabs(bx)), std::max(std::fabs(cx), std::fabs(dx)));
    const double y = std::max(std::max(std::fabs(ay), std::fabs(by)), std::max(std::fabs(cy), std::fabs(dy)));
    const double z = std::max(std::max(std::fabs(az), std::fabs(bz)), std::max(std::fabs(cz), std::fabs(dz)));
    return std::max(std::max(x, y), z);
  }

  double determinant() const
  {
    const double ab = ax * by - bx * ay, bc = bx * cy - cx * by;
    const double cd = cx * dy - dx * cy, da = dx * ay - ax * dy;
    const double ac = ax * cy - cx * ay, bd = bx * dy - dx * by;

    const double abc = az * bc - bz * ac + cz * ab;
    const double bcd = bz * cd - cz * bd + dz * bc;
    const double cda = cz * da + dz * ac + az * cd;
    const double dab = dz * ab + az * bd + bz * da;

    const double alift = ax * ax + ay * ay + az * az;
    const double blift = bx * bx + by * by + bz * bz;
    const double clift = cx * cx + cy * cy + cz * cz;
    const double dlift = dx * dx + dy * dy + dz * dz;
    return (dlift * abc - clift * dab) + (blift * cda - alift * bcd);
  }
};

inline double in_sphere_determinant(const double* p, const double* q, const double* r,
                                    const double* s, const double* t)
{
  return In_sphere_rows(p, q, r, s, t).determinant();
}

#ifdef CGAL_FDT3_SIMD_RECORDS
// Predicates on four points (the coordinates of vertex records; only x, y, z
// are read), with the 4x4 matrix held in AVX registers: lane i of a
// register is point i.  The scalar forms spend most of their instructions on
// loads and on products that several cofactors share; the cavity search
// evaluates the in-sphere determinant ~45 times per inserted point and the
// walk the four facet orientations ~5 times.  The vectorised forms use the
// same minors and the same sums as the scalar ones (only the association of
// the final sum and the FMA contractions differ), so the error bounds of the
// filters hold unchanged.
namespace simd_records {

struct Columns
{
  __m256d x, y, z; // coordinates of the four points relative to a fifth one
};

CGAL_FDT3_TARGET_AVX2 inline Columns columns_relative_to(const double* a, const double* b, const double* c,
                                                         const double* d, const double* t)
{
  // (x, y) pairs in 128-bit halves and z gathered, so that nothing past the
  // three coordinates is read: in a partitioned insertion another thread
  // may be writing the scratch word that follows them.
  const __m256d ac = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(a)), _mm_loadu_pd(c), 1);
  const __m256d bd = _mm256_insertf128_pd(_mm256_castpd128_pd256(_mm_loadu_pd(b)), _mm_loadu_pd(d), 1);
  return {_mm256_sub_pd(_mm256_unpacklo_pd(ac, bd), _mm256_broadcast_sd(t)),
          _mm256_sub_pd(_mm256_unpackhi_pd(ac, bd), _mm256_broadcast_sd(t + 1)),
          _mm256_sub_pd(_mm256_set_pd(d[2], c[2], b[2], a[2]), _mm256_broadcast_sd(t + 2))};
}

constexpr int next = _MM_SHUFFLE(0, 3, 2, 1), opposite = _MM_SHUFFLE(1, 0, 3, 2);

// Lane i: the 3x3 determinant of points i, i+1, i+2 (mod 4), expanded along
// z on the 2x2 minors of consecutive points (ab, bc, cd, da) and of opposite
// ones (ac, bd, ca, db): (abc, bcd, cda, dab).
CGAL_FDT3_TARGET_AVX2 inline __m256d consecutive_triple_minors(const Columns& q)
{
  const __m256d x1 = _mm256_permute4x64_pd(q.x, next), y1 = _mm256_permute4x64_pd(q.y, next);
  const __m256d x2 = _mm256_permute4x64_pd(q.x, opposite), y2 = _mm256_permute4x64_pd(q.y, opposite);
  const __m256d m1 = _mm256_fmsub_pd(q.x, y1, _mm256_mul_pd(x1, q.y));
  const __m256d m2 = _mm256_fmsub_pd(q.x, y2, _mm256_mul_pd(x2, q.y));
  const __m256d z1 = _mm256_permute4x64_pd(q.z, next), z2 = _mm256_permute4x64_pd(q.z, opposite);
  return _mm256_fmadd_pd(z2, m1, _mm256_fmsub_pd(q.z, _mm256_permute4x64_pd(m1, next), _mm256_mul_pd(z1, m2)));
}

// in_sphere_determinant(a, b, c, d, t) from the Columns of a, b, c, d
// relative to t.
CGAL_FDT3_TARGET_AVX2 inline double in_sphere_determinant_of_columns(const Columns& q)
{
  const __m256d lift = _mm256_fmadd_pd(q.z, q.z, _mm256_fmadd_pd(q.y, q.y, _mm256_mul_pd(q.x, q.x)));
  const __m256d triples = consecutive_triple_minors(q);
  // det = (blift cda + dlift abc) - (alift bcd + clift dab).
  const __m256d terms = _mm256_mul_pd(lift, _mm256_permute4x64_pd(triples, next));
  const __m128d pairs = _mm_add_pd(_mm256_castpd256_pd128(terms), _mm256_extractf128_pd(terms, 1));
  return _mm_cvtsd_f64(_mm_unpackhi_pd(pairs, pairs)) - _mm_cvtsd_f64(pairs);
}

// The largest absolute coordinate of the Columns.
CGAL_FDT3_TARGET_AVX2 inline double largest_of_columns(const Columns& q)
{
  const __m256d sign = _mm256_set1_pd(-0.0);
  const __m256d m = _mm256_max_pd(_mm256_andnot_pd(sign, q.x),
                                  _mm256_max_pd(_mm256_andnot_pd(sign, q.y), _mm256_andnot_pd(sign, q.z)));
  const __m128d h = _mm_max_pd(_mm256_castpd256_pd128(m), _mm256_extractf128_pd(m, 1));
  return _mm_cvtsd_f64(_mm_max_sd(h, _mm_unpackhi_pd(h, h)));
}

} // namespace simd_records

// Lane f: orientation_determinant of the tetrahedron (a, b, c, d) of vertex
// records with its vertex f replaced by t, i.e. the signed volume that t
// makes with facet f.  With t as origin, that volume is (-1)^f times the
// determinant of the three other points, a cyclic triple up to an even
// permutation: (bcd, -cda, dab, -abc).
CGAL_FDT3_TARGET_AVX2 inline __m256d facet_orientations_of_records(const double* a, const double* b, const double* c,
                                             const double* d, const double* t)
{
  using namespace simd_records;
  const __m256d triples = consecutive_triple_minors(columns_relative_to(a, b, c, d, t));
  return _mm256_xor_pd(_mm256_permute4x64_pd(triples, next), _mm256_set_pd(-0.0, 0.0, -0.0, 0.0));
}

// The walk's use of facet_orientations_of_records: bit f of `beyond` when
// the static bound certifies t strictly beyond facet f (negative volume),
// of `before` when it certifies it strictly before.
CGAL_FDT3_TARGET_AVX2 inline void certified_facet_sides_of_records(const double* a, const double* b, const double* c,
                                                                  const double* d, const double* t, double bound,
                                                                  int& beyond, int& before)
{
  const __m256d volumes = facet_orientations_of_records(a, b, c, d, t);
  beyond = _mm256_movemask_pd(_mm256_cmp_pd(volumes, _mm256_set1_pd(-bound), _CMP_LT_OQ));
  before = _mm256_movemask_pd(_mm256_cmp_pd(volumes, _mm256_set1_pd(bound), _CMP_GT_OQ));
}
#endif

// Largest absolute difference per axis between `base` and the other points.
template <int N>
inline void max_differences(const double* base, const double* const (&points)[N], double m[3])
{
  for(int a = 0; a < 3; ++a) {
    m[a] = 0;
    for(int i = 0; i < N; ++i) m[a] = std::max(m[a], std::fabs(points[i][a] - base[a]));
  }
}

// Exact-in-double stage, between the filters and CGAL's exact number types.
// When every coordinate difference is computed exactly and the significant
// bits of all of them span at most `max_span` binary orders, each product
// and sum of a determinant of degree k is a multiple of 2^(k * lowest bit)
// smaller than 2^53 times that granularity, hence exactly representable: the
// floating-point value is the exact one, zero included.  Integer grids and
// other low-precision degenerate inputs are decided here, about a hundred
// times faster than with exact numbers.  Spans (|d| < 2^(high+1), d a
// multiple of 2^low): in-sphere, degree 5, permanent <= 72 |d|^5, needs
// 5 (high + 1 - low) + log2(72) <= 53, i.e. a span of at most 9;
// orientation, degree 3, permanent <= 6 |d|^3: a span of at most 16.
struct Bit_span
{
  int high = std::numeric_limits<int>::min();
  int low = std::numeric_limits<int>::max();
  bool exact = true;

  void add_difference(double a, double b)
  {
    const double d = a - b;
    // Knuth's two-difference: the rounding error of a - b, zero iff exact.
    const double b_virtual = a - d;
    const double a_virtual = d + b_virtual;
    if((a - a_virtual) + (b_virtual - b) != 0) exact = false;
    if(d == 0 || !exact) return;
    std::uint64_t bits;
    std::memcpy(&bits, &d, sizeof bits);
    const int biased = static_cast<int>((bits >> 52) & 0x7ff);
    if(biased == 0) { // subnormal
      exact = false;
      return;
    }
    const std::uint64_t mantissa = (bits & ((std::uint64_t(1) << 52) - 1)) | (std::uint64_t(1) << 52);
    const int exponent = biased - 1075;
    low = std::min(low, exponent + __builtin_ctzll(mantissa));
    high = std::max(high, exponent + 52);
  }

  // Also keeps every product of up to five differences away from underflow
  // and overflow.
  bool at_most(int max_span) const
  {
    if(!exact) return false;
    if(high == std::numeric_limits<int>::min()) return true; // all differences zero
    return low >= -200 && high <= 190 && high + 1 - low <= max_span;
  }
};

// Double-double arithmetic for the stage between the per-call bound and
// CGAL's exact numbers: a value is hi + lo with |lo| <= ulp(hi) / 2.  Points
// on a sphere make nearly every in-sphere test fall through the double
// stages (their determinants are of the order of the rounding of the
// coordinates, eps times the permanent); in double-double with exact
// coordinate differences the error is of order eps^2 times the permanent,
// so this stage decides them at a fraction of the cost of exact numbers.
// Every operation is written out: an error-free transformation must not be
// contracted or reassociated by the compiler.
// Inlined: GCC keeps the product out of line, and a call per product makes
// the stage 10% slower.
#if defined(__GNUC__)
#define CGAL_FDT3_DD_INLINE inline __attribute__((always_inline))
#else
#define CGAL_FDT3_DD_INLINE inline
#endif
#define CGAL_FDT3_DD_LANES_INLINE CGAL_FDT3_TARGET_AVX2 CGAL_FDT3_DD_INLINE

namespace double_double {

struct Number
{
  double hi, lo;
};

// Knuth's two-sum: hi + lo == a + b exactly.
CGAL_FDT3_DD_INLINE Number two_sum(double a, double b)
{
  const double s = a + b;
  const double b_virtual = s - a;
  const double a_virtual = s - b_virtual;
  return {s, (a - a_virtual) + (b - b_virtual)};
}

// Dekker's fast two-sum, for |a| >= |b| (or a == 0).
CGAL_FDT3_DD_INLINE Number fast_two_sum(double a, double b)
{
  const double s = a + b;
  return {s, b - (s - a)};
}

CGAL_FDT3_DD_INLINE Number difference(double a, double b) { return two_sum(a, -b); }

// Accurate sum of two double-words (Joldes, Muller, Popescu, Algorithm 6).
CGAL_FDT3_DD_INLINE Number add(const Number& x, const Number& y)
{
  const Number s = two_sum(x.hi, y.hi);
  const Number t = two_sum(x.lo, y.lo);
  const Number v = fast_two_sum(s.hi, s.lo + t.hi);
  return fast_two_sum(v.hi, t.lo + v.lo);
}

CGAL_FDT3_DD_INLINE Number negate(const Number& x) { return {-x.hi, -x.lo}; }
CGAL_FDT3_DD_INLINE Number subtract(const Number& x, const Number& y) { return add(x, negate(y)); }

// Product of two double-words with FMA (same paper, Algorithm 12).
CGAL_FDT3_DD_INLINE Number multiply(const Number& x, const Number& y)
{
  const double high = x.hi * y.hi;
  const double high_error = std::fma(x.hi, y.hi, -high);
  const double low = std::fma(x.lo, y.hi, std::fma(x.hi, y.lo, x.lo * y.lo));
  return fast_two_sum(high, high_error + low);
}

} // namespace double_double

#ifdef CGAL_FDT3_SIMD_RECORDS
// The same operations on the four lanes of AVX registers (lane i: point i of
// p, q, r, s), arranged as in_sphere_determinant_of_columns: the same minors
// and sums, so the same depth and the same bound.
namespace double_double_lanes {

struct Numbers
{
  __m256d hi, lo;
};

CGAL_FDT3_DD_LANES_INLINE Numbers two_sum(__m256d a, __m256d b)
{
  const __m256d s = _mm256_add_pd(a, b);
  const __m256d b_virtual = _mm256_sub_pd(s, a);
  const __m256d a_virtual = _mm256_sub_pd(s, b_virtual);
  return {s, _mm256_add_pd(_mm256_sub_pd(a, a_virtual), _mm256_sub_pd(b, b_virtual))};
}

CGAL_FDT3_DD_LANES_INLINE Numbers fast_two_sum(__m256d a, __m256d b)
{
  const __m256d s = _mm256_add_pd(a, b);
  return {s, _mm256_sub_pd(b, _mm256_sub_pd(s, a))};
}

CGAL_FDT3_DD_LANES_INLINE Numbers add(const Numbers& x, const Numbers& y)
{
  const Numbers s = two_sum(x.hi, y.hi);
  const Numbers t = two_sum(x.lo, y.lo);
  const Numbers v = fast_two_sum(s.hi, _mm256_add_pd(s.lo, t.hi));
  return fast_two_sum(v.hi, _mm256_add_pd(t.lo, v.lo));
}

CGAL_FDT3_DD_LANES_INLINE Numbers subtract(const Numbers& x, const Numbers& y)
{
  const __m256d sign = _mm256_set1_pd(-0.0);
  return add(x, {_mm256_xor_pd(y.hi, sign), _mm256_xor_pd(y.lo, sign)});
}

CGAL_FDT3_DD_LANES_INLINE Numbers multiply(const Numbers& x, const Numbers& y)
{
  const __m256d high = _mm256_mul_pd(x.hi, y.hi);
  const __m256d high_error = _mm256_fmsub_pd(x.hi, y.hi, high);
  const __m256d low = _mm256_fmadd_pd(x.lo, y.hi, _mm256_fmadd_pd(x.hi, y.lo, _mm256_mul_pd(x.lo, y.lo)));
  return fast_two_sum(high, _mm256_add_pd(high_error, low));
}

// Axis a of p, q, r, s minus that of t, exactly (no lambda: a lambda would
// not be built for the target of its enclosing function).
CGAL_FDT3_DD_LANES_INLINE Numbers differences(const double* p, const double* q, const double* r, const double* s,
                                              const double* t, int a)
{
  return two_sum(_mm256_set_pd(s[a], r[a], q[a], p[a]), _mm256_set1_pd(-t[a]));
}

template <int control>
CGAL_FDT3_DD_LANES_INLINE Numbers permute(const Numbers& x)
{
  return {_mm256_permute4x64_pd(x.hi, control), _mm256_permute4x64_pd(x.lo, control)};
}

} // namespace double_double_lanes
#endif

// Sign of in_sphere_determinant(p, q, r, s, t) (Shewchuk's sign), evaluated
// in double-double from exact differences with the same expression, or 0
// when the result is within the error bound `bound` (see Filter_bounds).
inline int in_sphere_determinant_sign_double_double_scalar(const double* p, const double* q, const double* r,
                                                           const double* s, const double* t, double bound)
{
  using namespace double_double;
  const Number ax = difference(p[0], t[0]), ay = difference(p[1], t[1]), az = difference(p[2], t[2]);
  const Number bx = difference(q[0], t[0]), by = difference(q[1], t[1]), bz = difference(q[2], t[2]);
  const Number cx = difference(r[0], t[0]), cy = difference(r[1], t[1]), cz = difference(r[2], t[2]);
  const Number dx = difference(s[0], t[0]), dy = difference(s[1], t[1]), dz = difference(s[2], t[2]);

  const Number ab = subtract(multiply(ax, by), multiply(bx, ay));
  const Number bc = subtract(multiply(bx, cy), multiply(cx, by));
  const Number cd = subtract(multiply(cx, dy), multiply(dx, cy));
  const Number da = subtract(multiply(dx, ay), multiply(ax, dy));
  const Number ac = subtract(multiply(ax, cy), multiply(cx, ay));
  const Number bd = subtract(multiply(bx, dy), multiply(dx, by));

  const Number abc = add(subtract(multiply(az, bc), multiply(bz, ac)), multiply(cz, ab));
  const Number bcd = add(subtract(multiply(bz, cd), multiply(cz, bd)), multiply(dz, bc));
  const Number cda = add(add(multiply(cz, da), multiply(dz, ac)), multiply(az, cd));
  const Number dab = add(add(multiply(dz, ab), multiply(az, bd)), multiply(bz, da));

  const Number alift = add(add(multiply(ax, ax), multiply(ay, ay)), multiply(az, az));
  const Number blift = add(add(multiply(bx, bx), multiply(by, by)), multiply(bz, bz));
  const Number clift = add(add(multiply(cx, cx), multiply(cy, cy)), multiply(cz, cz));
  const Number dlift = add(add(multiply(dx, dx), multiply(dy, dy)), multiply(dz, dz));

  const Number det = add(subtract(multiply(dlift, abc), multiply(clift, dab)),
                         subtract(multiply(blift, cda), multiply(alift, bcd)));
  if(det.hi > bound) return 1;
  if(det.hi < -bound) return -1;
  return 0;
}

#ifdef CGAL_FDT3_SIMD_RECORDS
// The same on AVX registers, with the minors of in_sphere_determinant_of_columns.
CGAL_FDT3_TARGET_AVX2 inline int in_sphere_determinant_sign_double_double_lanes(const double* p, const double* q,
                                                                                const double* r, const double* s,
                                                                                const double* t, double bound)
{
  using namespace double_double_lanes;
  using simd_records::next;
  using simd_records::opposite;
  const Numbers x = differences(p, q, r, s, t, 0), y = differences(p, q, r, s, t, 1),
                z = differences(p, q, r, s, t, 2);
  const Numbers x1 = permute<next>(x), y1 = permute<next>(y), z1 = permute<next>(z);
  const Numbers x2 = permute<opposite>(x), y2 = permute<opposite>(y), z2 = permute<opposite>(z);
  // Lane i: minors of points (i, i + 1) and (i, i + 2), then the triple
  // minor of points i, i + 1, i + 2 (abc, bcd, cda, dab).
  const Numbers m1 = subtract(multiply(x, y1), multiply(x1, y));
  const Numbers m2 = subtract(multiply(x, y2), multiply(x2, y));
  const Numbers triples =
      add(multiply(z2, m1), subtract(multiply(z, permute<next>(m1)), multiply(z1, m2)));
  const Numbers lift = add(add(multiply(x, x), multiply(y, y)), multiply(z, z));
  const Numbers terms = multiply(lift, permute<next>(triples));
  alignas(32) double hi[4], lo[4];
  _mm256_store_pd(hi, terms.hi);
  _mm256_store_pd(lo, terms.lo);
  using namespace double_double;
  // det = (blift cda + dlift abc) - (alift bcd + clift dab).
  const Number det = subtract(add(Number{hi[1], lo[1]}, Number{hi[3], lo[3]}),
                              add(Number{hi[0], lo[0]}, Number{hi[2], lo[2]}));
  if(det.hi > bound) return 1;
  if(det.hi < -bound) return -1;
  return 0;
}
#endif

template <class Paths = Default_paths>
inline int in_sphere_determinant_sign_double_double(const double* p, const double* q, const double* r,
                                                    const double* s, const double* t, double bound)
{
#ifdef CGAL_FDT3_SIMD_RECORDS
  if constexpr(Paths::avx2) return in_sphere_determinant_sign_double_double_lanes(p, q, r, s, t, bound);
#endif
  return in_sphere_determinant_sign_double_double_scalar(p, q, r, s, t, bound);
}

#undef CGAL_FDT3_DD_LANES_INLINE
#undef CGAL_FDT3_DD_INLINE

// Whether every difference point - base is exact with significant bits
// spanning at most max_span orders (Bit_span::at_most).  at_most only turns
// false as differences are added, and on random coordinates the first
// difference already does: checked alone first, it spares them the eleven
// others (13% of the time on points rounded onto a sphere), while grids,
// which pass, pay one more check.
template <int N>
inline __attribute__((always_inline)) bool differences_within_span(const double* base,
                                                                   const double* const (&points)[N], int max_span)
{
  Bit_span span;
  span.add_difference(points[0][0], base[0]);
  if(!span.at_most(max_span)) return false;
  for(int i = 0; i < N; ++i)
    for(int a = i == 0 ? 1 : 0; a < 3; ++a) span.add_difference(points[i][a], base[a]);
  return span.at_most(max_span);
}

// Exact sign of orientation(p, q, r, s).
inline int orientation(const double* p, const double* q, const double* r, const double* s)
{
  const double det = orientation_determinant(p, q, r, s);
  const double* const others[3] = {q, r, s};
  double m[3];
  max_differences(p, others, m);
  const double lo = std::min(std::min(m[0], m[1]), m[2]);
  const double hi = std::max(std::max(m[0], m[1]), m[2]);
  if(lo > Filter_bounds::orientation_min && hi < Filter_bounds::orientation_max) {
    const double bound = Filter_bounds::orientation * m[0] * m[1] * m[2];
    if(det > bound) return 1;
    if(det < -bound) return -1;
  }
  if(differences_within_span(p, others, 16)) return (det > 0) - (det < 0);
  return predicates_detail::orientation_exact(p, q, r, s);
}

// Exact sign of side_of_oriented_sphere(p, q, r, s, t): positive when t is
// strictly inside the sphere of the positively oriented p, q, r, s.  `det`
// is in_sphere_determinant(p, q, r, s, t), already computed by the caller.
template <class Paths = Default_paths>
inline int side_of_oriented_sphere_from(double det, const double* p, const double* q, const double* r,
                                        const double* s, const double* t)
{
  const double* const others[4] = {p, q, r, s};
  double m[3];
  max_differences(t, others, m);
  const double lo = std::min(std::min(m[0], m[1]), m[2]);
  const double hi = std::max(std::max(m[0], m[1]), m[2]);
  if(lo > Filter_bounds::in_sphere_min && hi < Filter_bounds::in_sphere_max) {
    const double bound = Filter_bounds::in_sphere * (m[0] * m[1] * m[2]) * (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    if(det > bound) return -1;
    if(det < -bound) return 1;
  }
  if(differences_within_span(t, others, 9)) return (det < 0) - (det > 0);
  if(lo > Filter_bounds::in_sphere_double_double_min && hi < Filter_bounds::in_sphere_double_double_max) {
    // |lo part| <= eps |hi part|: twice the bound decides the sign of hi + lo.
    const double bound =
        2 * Filter_bounds::in_sphere_double_double * (m[0] * m[1] * m[2]) * (m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
    const int sign = in_sphere_determinant_sign_double_double<Paths>(p, q, r, s, t, bound);
    if(sign != 0) return -sign;
  }
  return predicates_detail::side_of_oriented_sphere_exact(p, q, r, s, t);
}

inline int side_of_oriented_sphere(const double* p, const double* q, const double* r,
                                   const double* s, const double* t)
{
  return side_of_oriented_sphere_from(in_sphere_determinant(p, q, r, s, t), p, q, r, s, t);
}

// A first, static stage in front of the per-call bounds above: the same error
// bounds evaluated once with the extent of a bounding box, which bounds every
// coordinate difference of points inside it.  Saves the per-call maxima where
// they cost more than they save; a determinant below the static bound falls
// through to the per-call stage.  The conflict tests do not use the static
// in-sphere bound: points near a surface or in clusters make tetrahedra
// thousands of times smaller than the box, whose determinants fall below it
// (56% of the cavity's tests on 1e6 points near a sphere, nearly all in 20
// tight clusters, each then out of line after a mispredicted branch), so
// they compute the per-call bound beside the determinant
// (Filter_bounds::in_sphere_of_largest).  In the vectorised cavity search
// the box still decides whether that bound is valid: it bounds the
// differences from above.  No global state: the kernel owns its copy.
struct Static_filter
{
  double orientation = std::numeric_limits<double>::infinity();
  double in_sphere = std::numeric_limits<double>::infinity();
  // The absolute term of the per-call in-sphere bound:
  // Filter_bounds::in_sphere_underflow inside a box whose widths are below
  // in_sphere_max, infinite (every test to the later stages) outside.
  double in_sphere_underflow = std::numeric_limits<double>::infinity();

  static Static_filter for_box(const double lo[3], const double hi[3])
  {
    Static_filter f;
    double w[3];
    for(int a = 0; a < 3; ++a) w[a] = hi[a] - lo[a];
    const double smallest = std::min(std::min(w[0], w[1]), w[2]);
    const double largest = std::max(std::max(w[0], w[1]), w[2]);
    // Round the widths up: hi - lo may round down below a true difference.
    for(double& x : w) x *= 1.0 + 4 * Filter_bounds::unit_roundoff;
    if(smallest > Filter_bounds::orientation_min && largest < Filter_bounds::orientation_max)
      f.orientation = Filter_bounds::orientation * w[0] * w[1] * w[2] * (1.0 + 1e-12);
    if(smallest > Filter_bounds::in_sphere_min && largest < Filter_bounds::in_sphere_max)
      f.in_sphere = Filter_bounds::in_sphere * (w[0] * w[1] * w[2]) *
                    (w[0] * w[0] + w[1] * w[1] + w[2] * w[2]) * (1.0 + 1e-12);
    if(largest < Filter_bounds::in_sphere_max) f.in_sphere_underflow = Filter_bounds::in_sphere_underflow;
    return f;
  }
};

inline int orientation(const Static_filter& filter, const double* p, const double* q,
                       const double* r, const double* s)
{
  const double det = orientation_determinant(p, q, r, s);
  if(det > filter.orientation) return 1;
  if(det < -filter.orientation) return -1;
  return orientation(p, q, r, s);
}

inline int side_of_oriented_sphere(const Static_filter& filter, const double* p, const double* q,
                                   const double* r, const double* s, const double* t)
{
  const double det = in_sphere_determinant(p, q, r, s, t);
  if(det > filter.in_sphere) return -1;
  if(det < -filter.in_sphere) return 1;
  return side_of_oriented_sphere(p, q, r, s, t);
}

inline int perturbed_tie_break(const double* p0, const double* p1, const double* p2, const double* p3,
                               const double* p);

// CGAL's Delaunay_triangulation_3::side_of_oriented_sphere(..., perturb = true):
// never zero for distinct points.  p0..p3 positively oriented.
inline int perturbed_side_of_oriented_sphere(const double* p0, const double* p1, const double* p2,
                                             const double* p3, const double* p,
                                             const Static_filter& filter = Static_filter())
{
  const int side = side_of_oriented_sphere(filter, p0, p1, p2, p3, p);
  if(side != 0) return side;
  return perturbed_tie_break(p0, p1, p2, p3, p);
}

// The sign CGAL's perturbation gives to an exact cospherical tie of p with
// the positively oriented p0..p3.
inline int perturbed_tie_break(const double* p0, const double* p1, const double* p2, const double* p3,
                               const double* p)
{
  // Only the two lexicographically largest points matter: on integer grids
  // most tests are exact ties, so this path is hot there.
  const double* const points[5] = {p0, p1, p2, p3, p};
  const double* largest = points[0];
  const double* second = nullptr;
  for(int i = 1; i < 5; ++i) {
    if(lexicographically_smaller(largest, points[i])) {
      second = largest;
      largest = points[i];
    } else if(second == nullptr || lexicographically_smaller(second, points[i])) {
      second = points[i];
    }
  }
  // The perturbation is a polynomial in an infinitesimal whose monomials are
  // ranked by the lexicographic order; the two largest points decide
  // (Devillers & Teillaud, "Perturbations for Delaunay and weighted Delaunay 3D
  // triangulations", 2011).
  for(const double* top : {largest, second}) {
    if(top == p) return -1;
    int o = 0;
    if(top == p3 && (o = orientation(p0, p1, p2, p)) != 0) return o;
    if(top == p2 && (o = orientation(p0, p1, p, p3)) != 0) return o;
    if(top == p1 && (o = orientation(p0, p, p2, p3)) != 0) return o;
    if(top == p0 && (o = orientation(p, p1, p2, p3)) != 0) return o;
  }
  CGAL_assertion_msg(false, "perturbation did not decide: duplicate points?");
  return -1;
}

// CGAL's coplanar_side_of_bounded_circle(p, q, r, t) for coplanar p, q,
// r, t (p, q, r not collinear): +1 inside the circle through p, q, r, 0 on
// it, -1 outside.  A floating-point stage first: with P = p - t, Q, R alike
// and the plane's normal n = (q - p) x (r - p),
//   S = n . (|P|^2 Q x R + |Q|^2 R x P + |R|^2 P x Q)
// is |n| times the in-circle determinant of p, q, r, t in an orthonormal
// frame of the plane in which p, q, r turn counterclockwise (each cross
// product of two vectors of the plane is its 2D determinant times the unit
// normal), so S has the sign of the answer.
// The bound: each monomial of S, as evaluated, carries at most 19 roundings
// (a coordinate difference, 1, counted twice where squared; a lift, 5; a
// cross product's entry or the normal's, 4; their products, sums and the
// final sum, the rest), so S is off by at most gamma_19 = 19 eps (1 + 1e-14)
// times its permanent (the same with absolute values everywhere); 32 eps
// covers that and the rounding of the permanent itself.  With every
// difference 0 or of magnitude in [2^-60, 2^60], no product overflows, and a
// product underflows only after a cancellation, each then off by at most
// 2^-1075, times at most 2^121 afterwards: 2^-950 more covers the twelve.
// Outside that range, and for ties, CGAL's exact predicate decides.  On flat
// faces of a convex hull every ghost conflict test of a point in their plane
// comes here (fandisk's surface points: CGAL's interval filter was a tenth of
// their Delaunay triangulation).
inline int coplanar_side_of_bounded_circle(const double* p, const double* q, const double* r, const double* t)
{
  const double P[3] = {p[0] - t[0], p[1] - t[1], p[2] - t[2]};
  const double Q[3] = {q[0] - t[0], q[1] - t[1], q[2] - t[2]};
  const double R[3] = {r[0] - t[0], r[1] - t[1], r[2] - t[2]};
  const double a[3] = {q[0] - p[0], q[1] - p[1], q[2] - p[2]};
  const double b[3] = {r[0] - p[0], r[1] - p[1], r[2] - p[2]};
  bool in_range = true;
  for(const double* d : {P, Q, R, a, b})
    for(int i = 0; i < 3; ++i) {
      const double m = std::fabs(d[i]);
      in_range = in_range && (m == 0 || (m >= 0x1p-60 && m <= 0x1p60));
    }
  if(!in_range) return predicates_detail::coplanar_side_of_bounded_circle_exact(p, q, r, t);
  const double lift_p = P[0] * P[0] + P[1] * P[1] + P[2] * P[2];
  const double lift_q = Q[0] * Q[0] + Q[1] * Q[1] + Q[2] * Q[2];
  const double lift_r = R[0] * R[0] + R[1] * R[1] + R[2] * R[2];
  double sum = 0, permanent = 0;
  for(int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const double qr = Q[j] * R[k] - Q[k] * R[j], rp = R[j] * P[k] - R[k] * P[j], pq = P[j] * Q[k] - P[k] * Q[j];
    const double qr_abs = std::fabs(Q[j] * R[k]) + std::fabs(Q[k] * R[j]);
    const double rp_abs = std::fabs(R[j] * P[k]) + std::fabs(R[k] * P[j]);
    const double pq_abs = std::fabs(P[j] * Q[k]) + std::fabs(P[k] * Q[j]);
    const double normal = a[j] * b[k] - a[k] * b[j];
    const double normal_abs = std::fabs(a[j] * b[k]) + std::fabs(a[k] * b[j]);
    sum += normal * (lift_p * qr + lift_q * rp + lift_r * pq);
    permanent += normal_abs * (lift_p * qr_abs + lift_q * rp_abs + lift_r * pq_abs);
  }
  if(std::fabs(sum) > 32 * Filter_bounds::unit_roundoff * permanent + 0x1p-950) return sum > 0 ? 1 : -1;
  return predicates_detail::coplanar_side_of_bounded_circle_exact(p, q, r, t);
}

// CGAL's coplanar_side_of_bounded_circle(..., perturb = true) for coplanar
// p0, p1, p2, p (p0, p1, p2 not collinear): +1 inside, -1 outside.
inline int perturbed_coplanar_side_of_bounded_circle(const double* p0, const double* p1,
                                                     const double* p2, const double* p)
{
  using namespace predicates_detail;
  const int side = coplanar_side_of_bounded_circle(p0, p1, p2, p);
  if(side != 0) return side;

  const double* points[4] = {p0, p1, p2, p};
  std::sort(points, points + 4,
            [](const double* a, const double* b) { return lexicographically_smaller(a, b); });
  const int local = coplanar_orientation_exact(p0, p1, p2);
  for(int i = 3; i > 0; --i) {
    if(points[i] == p) return -1;
    int o = 0;
    if(points[i] == p2 && (o = coplanar_orientation_exact(p0, p1, p)) != 0) return o * local;
    if(points[i] == p1 && (o = coplanar_orientation_exact(p0, p, p2)) != 0) return o * local;
    if(points[i] == p0 && (o = coplanar_orientation_exact(p, p1, p2)) != 0) return o * local;
  }
  return -local;
}

// Conflict test of a finite tetrahedron (positively oriented a, b, c, d).
// Only the first stage (the per-call bound) is inline: the cavity search
// runs it ~45 times per point, and keeping the rare later stages in a
// separate function spares this path their register saves and lets it be
// inlined into the search.
template <class Paths>
inline bool finite_cell_in_conflict_after_first_stage(double det, const double* a, const double* b, const double* c,
                                                      const double* d, const double* p)
{
  const int side = side_of_oriented_sphere_from<Paths>(det, a, b, c, d, p);
  if(side != 0) return side > 0;
  return perturbed_tie_break(a, b, c, d, p) > 0;
}

// The later stages, out of line, one function for each form of the first
// stage: scalar (finite_cell_in_conflict, for every caller but the
// vectorised cavity search, in any build) and vector.
__attribute__((noinline)) inline bool finite_cell_in_conflict_beyond_first_stage_scalar(
    double det, const double* a, const double* b, const double* c, const double* d, const double* p)
{
  return finite_cell_in_conflict_after_first_stage<Scalar_paths>(det, a, b, c, d, p);
}

#ifdef CGAL_FDT3_SIMD_RECORDS
__attribute__((noinline)) CGAL_FDT3_TARGET_AVX2 inline bool finite_cell_in_conflict_beyond_first_stage_avx2(
    double det, const double* a, const double* b, const double* c, const double* d, const double* p)
{
  return finite_cell_in_conflict_after_first_stage<Avx2_paths>(det, a, b, c, d, p);
}
#endif

// The conflict tests return the sign of a filtered determinant as data,
// with one rarely taken branch for undecided values: the cavity search uses
// the result without branching on it, because no predictor can learn it.
// Written so that the compiler cannot turn |det| > bound back into two
// branches on the sign of det.
inline bool beyond_bound(double det, double bound)
{
  double magnitude = std::fabs(det);
#if defined(__GNUC__) && (defined(__x86_64__) || defined(__i386__))
  __asm__("" : "+x"(magnitude)); // opaque: keeps the comparison on the magnitude
#endif
  return magnitude > bound;
}

inline bool sign_bit(double x)
{
  std::uint64_t bits;
  std::memcpy(&bits, &x, sizeof bits);
  return (bits >> 63) != 0;
}

// The per-call bound on the in-sphere determinant's error, from the largest
// |coordinate difference| of its points and the absolute term for underflow
// (see Filter_bounds::in_sphere_of_largest).
inline double in_sphere_bound_of_largest(double largest, double underflow)
{
  const double square = largest * largest;
  return Filter_bounds::in_sphere_of_largest * (square * square * largest) + underflow;
}

#ifdef CGAL_FDT3_SIMD_RECORDS
CGAL_FDT3_TARGET_AVX2 inline bool finite_record_in_conflict_avx2(const double* a, const double* b, const double* c,
                                                                 const double* d, const double* p,
                                                                 const Static_filter& filter)
{
  using namespace simd_records;
  const Columns q = columns_relative_to(a, b, c, d, p);
  const double det = in_sphere_determinant_of_columns(q);
  const double bound = in_sphere_bound_of_largest(largest_of_columns(q), filter.in_sphere_underflow);
  if(__builtin_expect(!beyond_bound(det, bound), 0))
    return finite_cell_in_conflict_beyond_first_stage_avx2(det, a, b, c, d, p);
  return sign_bit(det);
}
#endif

// The same test for every caller but the vectorised cavity search (moves,
// validity checks, the scalar cavity search), whose tetrahedra are as small
// next to the bounding box as the cavity's: the per-call bound, whose
// validity (every difference below Filter_bounds::in_sphere_max) is checked
// per call rather than taken from a box.
inline bool finite_cell_in_conflict(const double* a, const double* b, const double* c,
                                    const double* d, const double* p)
{
  const In_sphere_rows rows(a, b, c, d, p);
  const double det = rows.determinant();
  const double largest = rows.largest();
  const double underflow = largest < Filter_bounds::in_sphere_max ? Filter_bounds::in_sphere_underflow
                                                                   : std::numeric_limits<double>::infinity();
  if(__builtin_expect(!beyond_bound(det, in_sphere_bound_of_largest(largest, underflow)), 0))
    return finite_cell_in_conflict_beyond_first_stage_scalar(det, a, b, c, d, p);
  return sign_bit(det);
}

// finite_cell_in_conflict in the cavity search's form: the sign returned as
// data, with the vectorised determinant for Avx2_paths, whose first stage
// takes the validity of its bound from the box (`filter`, see
// Static_filter) and so spares the per-call check.
template <class Paths = Default_paths>
inline bool finite_record_in_conflict(const double* a, const double* b, const double* c,
                                      const double* d, const double* p, const Static_filter& filter)
{
#ifdef CGAL_FDT3_SIMD_RECORDS
  if constexpr(Paths::avx2) return finite_record_in_conflict_avx2(a, b, c, d, p, filter);
#endif
  (void)filter;
  return finite_cell_in_conflict(a, b, c, d, p);
}

// Conflict test of a ghost tetrahedron (a, b, c, infinite): its "sphere" is
// the open half-space beyond the hull facet a, b, c, closed by CGAL's
// perturbed in-circle test inside the facet's plane.
__attribute__((noinline)) inline bool ghost_cell_in_conflict_beyond_first_stage(
    const double* a, const double* b, const double* c, const double* p)
{
  const int o = orientation(a, b, c, p);
  if(o != 0) return o > 0;
  return perturbed_coplanar_side_of_bounded_circle(a, b, c, p) > 0;
}

inline bool ghost_cell_in_conflict(const double* a, const double* b, const double* c,
                                   const double* p, const Static_filter& filter = Static_filter())
{
  const double det = orientation_determinant(a, b, c, p);
  if(__builtin_expect(!beyond_bound(det, filter.orientation), 0))
    return ghost_cell_in_conflict_beyond_first_stage(a, b, c, p);
  return !sign_bit(det);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_PREDICATES_H
