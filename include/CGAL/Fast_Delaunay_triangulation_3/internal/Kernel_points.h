// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Points of any CGAL kernel beside the engine's doubles.  The engine (paper
// §2) works on double coordinates; a kernel whose FT is not double (EPEC,
// Simple_cartesian<Gmpq>) gives it the points whose coordinates are exactly
// doubles, so its arithmetic decides exactly what CGAL's kernel would
// decide, and the triangulation is exactly CGAL's.  Here:
//
//   exact_coordinates(p, xyz)  the doubles of p, if they are exactly p's;
//   nearest_coordinates(p, xyz) each coordinate rounded to the nearest
//                               double (reading files, whose points are
//                               written as doubles);
//   Kernel_points              the user's Point_3 objects, one per vertex,
//                               so v->point() is the object inserted (for a
//                               lazy kernel, the same lazy value), not one
//                               rebuilt from the doubles at every call.
//
// For a kernel with double coordinates (Epick, Simple_cartesian<double>)
// the conversions are copies and Kernel_points is empty: the vertex records
// are the points.

#ifndef CGAL_FDT3_INTERNAL_KERNEL_POINTS_H
#define CGAL_FDT3_INTERNAL_KERNEL_POINTS_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Flat_storage.h>

#include <CGAL/Interval_nt.h>
#include <CGAL/number_utils.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <initializer_list>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

// CGAL's lazy objects (Lazy_exact_nt, the points of a lazy kernel) carry an
// interval approximation and compute their exact value on demand.
template <class T, class = void>
struct Is_lazy : std::false_type {};
template <class T>
struct Is_lazy<T, std::void_t<decltype(std::declval<const T&>().approx()),
                              decltype(std::declval<const T&>().exact())>> : std::true_type {};

// A lazy number made from NaN or infinity (which CGAL's debug builds refuse),
// or beyond the doubles' range, has an interval with a NaN or infinite bound
// and an exact value that GMP cannot make (it raises SIGFPE): that bound
// goes on as the coordinate, for check_finite to name.
inline bool non_finite_bound(const Interval_nt<false>& i, double& d)
{
  if(std::isfinite(i.inf()) && std::isfinite(i.sup())) return false;
  d = std::isnan(i.inf()) || !std::isfinite(i.sup()) ? i.sup() : i.inf();
  return true;
}

// True, with d = x, when the number x is exactly a double.  An interval
// that is one double proves it; otherwise the exact value decides (for a
// lazy number made from doubles the first test answers, without computing
// anything).  CGAL's intervals of its exact rationals are the tightest pair
// of doubles around the value; for a number type whose interval is wider,
// an end equal to x still counts.
template <class FT>
bool exact_double(const FT& x, double& d)
{
  if constexpr(std::is_same<FT, double>::value) {
    d = x;
    return true;
  } else if constexpr(Is_lazy<FT>::value) {
    const Interval_nt<false>& i = x.approx();
    if(non_finite_bound(i, d)) return true;
    if(i.inf() == i.sup()) {
      d = i.inf();
      return true;
    }
    return exact_double(x.exact(), d);
  } else {
    const std::pair<double, double> i = CGAL::to_interval(x);
    for(const double end : {i.first, i.second})
      if(i.first == i.second || FT(end) == x) {
        d = end;
        return true;
      }
    return false;
  }
}

// The double coordinates of p, when they are exactly p's.  For a lazy
// point the interval point answers first: reading p.x() would build a new
// lazy number per coordinate.
template <class Point>
bool exact_coordinates(const Point& p, double* xyz)
{
  if constexpr(Is_lazy<Point>::value) {
    const auto& a = p.approx();
    const Interval_nt<false> i[3] = {a.x(), a.y(), a.z()};
    bool doubles = true, non_finite = false;
    for(int k = 0; k < 3; ++k) {
      if(non_finite_bound(i[k], xyz[k])) non_finite = true;
      else xyz[k] = i[k].inf();
      doubles = doubles && i[k].is_point();
    }
    return doubles || non_finite || exact_coordinates(p.exact(), xyz);
  } else {
    return exact_double(p.x(), xyz[0]) && exact_double(p.y(), xyz[1]) && exact_double(p.z(), xyz[2]);
  }
}

// x rounded to the nearest double, ties to even.
template <class FT>
double nearest_double(const FT& x)
{
  double d;
  if(exact_double(x, d)) return d;
  if constexpr(Is_lazy<FT>::value) {
    return nearest_double(x.exact());
  } else {
    // x is strictly between the two doubles of its (tightest) interval.
    const std::pair<double, double> i = CGAL::to_interval(x);
    const FT middle = (FT(i.first) + FT(i.second)) / FT(2);
    if(x < middle) return i.first;
    if(middle < x) return i.second;
    std::uint64_t bits;
    std::memcpy(&bits, &i.first, sizeof bits);
    return (bits & 1) == 0 ? i.first : i.second;
  }
}

template <class Point>
void nearest_coordinates(const Point& p, double* xyz)
{
  if(exact_coordinates(p, xyz)) return;
  xyz[0] = nearest_double(p.x());
  xyz[1] = nearest_double(p.y());
  xyz[2] = nearest_double(p.z());
}

// One kernel point per vertex id (`keep`: the kernel's FT is not double).
// After every insertion resize() gives each new vertex the user's object
// inserted[i] for which vertex_of_input[i] is that vertex, if given, else
// the point of its doubles (equal to the one inserted: only exact doubles
// are inserted); building a lazy point per vertex only to drop it for the
// user's was +64 bytes and one allocation per point.
template <class Point, bool keep>
class Kernel_points
{
public:
  Kernel_points() : infinite_(0, 0, 0) {}

  const Point& at(Vertex_id v) const
  {
    if(v == ghost_vertex) return infinite_;
    CGAL_assertion(v < points_.size());
    return points_[v];
  }
  void resize(const Flat_storage& m, const std::vector<Point>* inserted = nullptr,
              const std::vector<Vertex_id>* vertex_of_input = nullptr)
  {
    const std::size_t n = m.vertices.size();
    if(points_.size() >= n) {
      points_.resize(n, infinite_);
      return;
    }
    const std::size_t first_new = points_.size();
    std::vector<bool> given(n - first_new, false);
    points_.resize(n, infinite_);
    if(inserted != nullptr)
      for(std::size_t i = 0; i < inserted->size(); ++i) {
        const Vertex_id v = (*vertex_of_input)[i];
        if(v < first_new || given[v - first_new]) continue;
        points_[v] = (*inserted)[i];
        given[v - first_new] = true;
      }
    for(std::size_t v = first_new; v < n; ++v) {
      if(given[v - first_new]) continue;
      const double* x = m.point(static_cast<Vertex_id>(v));
      points_[v] = Point(x[0], x[1], x[2]);
    }
  }
  // The user's object for vertex v (equal to the point of its doubles).
  void keep_input(Vertex_id v, const Point& p)
  {
    CGAL_assertion(v < points_.size() && points_[v] == p);
    points_[v] = p;
  }
  // Vertex v now stands at p (a move, or a vertex of tds().create_vertex()
  // placed by insert_in_hole): the same id, another point.
  void replace(Vertex_id v, const Point& p)
  {
    CGAL_assertion(v < points_.size());
    points_[v] = p;
  }
  void clear() { points_.clear(); }

private:
  std::vector<Point> points_;
  Point infinite_;
};

template <class Point>
class Kernel_points<Point, false>
{
public:
  void resize(const Flat_storage&, const std::vector<Point>* = nullptr, const std::vector<Vertex_id>* = nullptr) {}
  void keep_input(Vertex_id, const Point&) {}
  void replace(Vertex_id, const Point&) {}
  void clear() {}
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_KERNEL_POINTS_H
