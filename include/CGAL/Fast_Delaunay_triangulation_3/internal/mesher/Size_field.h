// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The size field h, one type for everything that reads it: a value at each
// vertex (refinement compares circumradii with it, the improvement gives
// its Steiner points one, the output carries it), linear inside each
// tetrahedron (Sizing.h interpolates it), and the bounds the user sets,
// which every value is clipped to where it is made: a global cap, a cap
// per subdomain, and a function of the position.  All at the mesher's unit
// scale (Unit_scaling.h); the user's function is wrapped to it by the
// caller.
//
// The user's function is called from the refinement's threads at once.  A
// value that is not a positive finite number, or an exception, is kept
// (the first one) instead of thrown there, where no thread could catch it;
// rethrow_user_error() throws it on the caller's thread after the step.

#ifndef CGAL_FDT3_INTERNAL_MESHER_SIZE_FIELD_H
#define CGAL_FDT3_INTERNAL_MESHER_SIZE_FIELD_H

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <sstream>
#include <string>
#include <stdexcept>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

class Size_field
{
public:
  typedef std::function<double(const double* p)> Function;

  // ------------------------------------------------------------ values at vertices
  double& operator[](std::size_t v) { return values_[v]; }
  double operator[](std::size_t v) const { return values_[v]; }
  std::size_t size() const { return values_.size(); }
  void assign(std::size_t n, double h) { values_.assign(n, h); }
  void push_back(double h) { values_.push_back(h); }
  void resize(std::size_t n) { values_.resize(n); }
  const std::vector<double>& values() const { return values_; }
  std::vector<double>::iterator begin() { return values_.begin(); }
  std::vector<double>::iterator end() { return values_.end(); }

  // ------------------------------------------------------------ the user's bounds
  void set_cap(double h) { cap_ = h; }
  double cap() const { return cap_; }
  // cap_per_subdomain[s]: the cap in subdomain s (index 0 unused); 0 or
  // absent, none.
  void set_subdomain_caps(std::vector<double> cap_per_subdomain) { subdomain_caps_ = std::move(cap_per_subdomain); }
  void set_function(Function f) { function_ = std::move(f); }

  // h clipped to the caps in `subdomain` (0: no subdomain's cap).
  double capped(double h, int subdomain) const
  {
    h = std::min(h, cap_);
    if(subdomain > 0 && std::size_t(subdomain) < subdomain_caps_.size() && subdomain_caps_[subdomain] > 0)
      h = std::min(h, subdomain_caps_[subdomain]);
    return h;
  }

  // h clipped to all the bounds at p in `subdomain`.
  double bounded(double h, const double* p, int subdomain) const
  {
    h = capped(h, subdomain);
    if(function_) h = std::min(h, user_value(p, h));
    return h;
  }

  // Throws, on the caller's thread, what the user's function did wrong.
  void rethrow_user_error() const
  {
    if(!error_->failed.load()) return;
    std::lock_guard<std::mutex> lock(error_->mutex);
    if(error_->exception) std::rethrow_exception(error_->exception);
    throw std::invalid_argument(error_->message);
  }

private:
  double user_value(const double* p, double fallback) const
  {
    try {
      const double h = function_(p);
      if(std::isfinite(h) && h > 0) return h;
      record(nullptr, p, h);
    } catch(...) {
      record(std::current_exception(), p, 0);
    }
    return fallback;
  }

  void record(std::exception_ptr e, const double* p, double h) const
  {
    std::lock_guard<std::mutex> lock(error_->mutex);
    if(error_->failed.load()) return;
    error_->exception = e;
    std::ostringstream s;
    s << "the size function gave " << h << " (not a positive finite size) at the mesher's unit-scale point ("
      << p[0] << ", " << p[1] << ", " << p[2] << ")";
    error_->message = s.str();
    error_->failed.store(true);
  }

  struct User_error
  {
    std::mutex mutex;
    std::atomic<bool> failed{false};
    std::exception_ptr exception;
    std::string message;
  };

  std::vector<double> values_;
  double cap_ = std::numeric_limits<double>::infinity();
  std::vector<double> subdomain_caps_;
  Function function_;
  // Shared by copies (a mutex and an atomic do not copy); the mesher makes
  // one field per run.
  std::shared_ptr<User_error> error_ = std::make_shared<User_error>();
};

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_SIZE_FIELD_H
