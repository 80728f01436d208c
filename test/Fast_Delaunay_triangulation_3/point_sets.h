// Point distributions shared by the tests and the benchmarks: uniform,
// Gaussian, clustered, on a sphere, shuffled integer grid, near a sphere or
// a torus (noisy scans of closed surfaces), with duplicates, far from the
// origin, tiny, in a plane, each at its own scale.  Deterministic for a given seed.
#ifndef CGAL_FDT3_TEST_POINT_SETS_H
#define CGAL_FDT3_TEST_POINT_SETS_H

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace fdt3_test {

struct Xyz { double x, y, z; };

inline std::vector<Xyz> uniform_points(std::size_t n, std::uint64_t seed = 1)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::vector<Xyz> p(n);
  for(Xyz& q : p) q = {u(rng), u(rng), u(rng)};
  return p;
}

inline std::vector<Xyz> gaussian_points(std::size_t n, std::uint64_t seed = 2)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Xyz> p(n);
  for(Xyz& q : p) q = {g(rng), g(rng), g(rng)};
  return p;
}

// 20 tight Gaussian blobs (sigma 1e-3) at uniform random centres.
inline std::vector<Xyz> clustered_points(std::size_t n, std::uint64_t seed = 3)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, 1e-3);
  Xyz centre[20];
  for(Xyz& c : centre) c = {u(rng), u(rng), u(rng)};
  std::vector<Xyz> p(n);
  for(std::size_t i = 0; i < n; ++i) {
    const Xyz& c = centre[i % 20];
    p[i] = {c.x + g(rng), c.y + g(rng), c.z + g(rng)};
  }
  return p;
}

// On the unit sphere (rounded to doubles, so only nearly cospherical).
inline std::vector<Xyz> sphere_points(std::size_t n, std::uint64_t seed = 4)
{
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<Xyz> p(n);
  for(Xyz& q : p) {
    double x, y, z, r;
    do { x = g(rng); y = g(rng); z = g(rng); r = std::sqrt(x * x + y * y + z * z); } while(r < 1e-9);
    q = {x / r, y / r, z / r};
  }
  return p;
}

// Near the unit sphere: uniform directions, each point moved along its
// normal by a Gaussian of deviation `noise`.  What a scan of a closed
// surface looks like: nearly all tetrahedra are long and thin, spanning the
// thin shell.
inline std::vector<Xyz> shell_points(std::size_t n, double noise = 1e-3, std::uint64_t seed = 9)
{
  std::vector<Xyz> p = sphere_points(n, seed);
  std::mt19937_64 rng(seed + 1);
  std::normal_distribution<double> g(0.0, noise);
  for(Xyz& q : p) {
    const double r = 1 + g(rng);
    q = {q.x * r, q.y * r, q.z * r};
  }
  return p;
}

// Near the torus of radii R (of the centre circle, around z) and r (of the
// tube), uniform by area, each point moved along its normal by a Gaussian of
// deviation `noise`.  The area element is proportional to R + r cos(phi)
// (phi around the tube), hence the rejection of phi.
inline std::vector<Xyz> torus_points(std::size_t n, double R = 1.0, double r = 0.3, double noise = 1e-3,
                                     std::uint64_t seed = 10)
{
  const double pi = 3.14159265358979323846;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  std::normal_distribution<double> g(0.0, noise);
  std::vector<Xyz> p(n);
  for(Xyz& q : p) {
    double phi;
    do phi = 2 * pi * u(rng);
    while(u(rng) * (R + r) > R + r * std::cos(phi));
    const double theta = 2 * pi * u(rng);
    const double tube = r + g(rng);
    const double ring = R + tube * std::cos(phi);
    q = {ring * std::cos(theta), ring * std::sin(theta), tube * std::sin(phi)};
  }
  return p;
}

// The k x k x k integer grid (exactly cospherical and coplanar subsets), shuffled.
inline std::vector<Xyz> grid_points(std::size_t n, std::uint64_t seed = 5)
{
  const int k = std::max(2, static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n)))));
  std::vector<Xyz> p;
  p.reserve(static_cast<std::size_t>(k) * k * k);
  for(int i = 0; i < k; ++i)
    for(int j = 0; j < k; ++j)
      for(int l = 0; l < k; ++l) p.push_back({double(i), double(j), double(l)});
  std::mt19937_64 rng(seed);
  std::shuffle(p.begin(), p.end(), rng);
  p.resize(std::min(p.size(), n));
  return p;
}

// Uniform points, each present twice or three times, shuffled.
inline std::vector<Xyz> duplicated_points(std::size_t n, std::uint64_t seed = 6)
{
  std::vector<Xyz> base = uniform_points((n + 1) / 2, seed);
  std::vector<Xyz> p = base;
  p.insert(p.end(), base.begin(), base.end());
  p.insert(p.end(), base.begin(), base.begin() + base.size() / 4);
  std::mt19937_64 rng(seed);
  std::shuffle(p.begin(), p.end(), rng);
  return p;
}

inline std::vector<Xyz> offset_points(std::size_t n, double offset = 1e9, std::uint64_t seed = 7)
{
  std::vector<Xyz> p = uniform_points(n, seed);
  for(Xyz& q : p) q = {q.x + offset, q.y + offset, q.z + offset};
  return p;
}

// Uniform in the unit square of the plane z = x (exactly coplanar: z is a
// copy of x), the triangulation of dimension 2.
inline std::vector<Xyz> plane_points(std::size_t n, std::uint64_t seed = 10)
{
  std::vector<Xyz> p = uniform_points(n, seed);
  for(Xyz& q : p) q.z = q.x;
  return p;
}

// Every point at its own scale: uniform in [-1, 1]^3 times 10^e, e an
// integer uniform in [-200, 200].
inline std::vector<Xyz> multiscale_points(std::size_t n, std::uint64_t seed = 11)
{
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  std::uniform_int_distribution<int> exponent(-200, 200);
  std::vector<Xyz> p(n);
  for(Xyz& q : p) {
    const double scale = std::pow(10.0, exponent(rng));
    q = {scale * unit(rng), scale * unit(rng), scale * unit(rng)};
  }
  return p;
}

inline std::vector<Xyz> scaled_points(std::size_t n, double scale = 1e-9, std::uint64_t seed = 8)
{
  std::vector<Xyz> p = uniform_points(n, seed);
  for(Xyz& q : p) q = {q.x * scale, q.y * scale, q.z * scale};
  return p;
}

// All integer points with x^2 + y^2 + z^2 = r2: exactly cospherical, with
// many coplanar (cocircular) subsets.
inline std::vector<Xyz> integer_sphere_points(int r2)
{
  std::vector<Xyz> p;
  const int r = static_cast<int>(std::sqrt(static_cast<double>(r2))) + 1;
  for(int x = -r; x <= r; ++x)
    for(int y = -r; y <= r; ++y)
      for(int z = -r; z <= r; ++z)
        if(x * x + y * y + z * z == r2) p.push_back({double(x), double(y), double(z)});
  return p;
}

// The 12 integer points of the circle u^2 + v^2 = 25, mapped by u*a + v*b
// with a = (1, 2, 2), b = (2, 1, -2): orthogonal, both of length 3, so the
// image is exactly a circle of radius 15 around the origin, in the plane
// normal to (2, -2, 1).
inline std::vector<Xyz> tilted_circle_points()
{
  std::vector<Xyz> p;
  for(int u = -5; u <= 5; ++u)
    for(int v = -5; v <= 5; ++v)
      if(u * u + v * v == 25) p.push_back({double(u + 2 * v), double(2 * u + v), double(2 * u - 2 * v)});
  return p;
}

// What the benchmark's --dist all runs (the tests name the distributions
// they use).
inline std::vector<std::string> distribution_names()
{
  return {"uniform", "gauss", "clusters", "sphere", "grid", "shell", "torus"};
}

inline std::vector<Xyz> make_points(const std::string& name, std::size_t n, std::uint64_t seed = 1)
{
  if(name == "uniform") return uniform_points(n, seed);
  if(name == "gauss") return gaussian_points(n, seed + 1);
  if(name == "clusters") return clustered_points(n, seed + 2);
  if(name == "sphere") return sphere_points(n, seed + 3);
  if(name == "grid") return grid_points(n, seed + 4);
  if(name == "shell") return shell_points(n, 1e-3, seed + 8);
  if(name == "torus") return torus_points(n, 1.0, 0.3, 1e-3, seed + 9);
  if(name == "duplicates") return duplicated_points(n, seed + 5);
  if(name == "offset") return offset_points(n, 1e9, seed + 6);
  if(name == "tiny") return scaled_points(n, 1e-9, seed + 7);
  if(name == "plane") return plane_points(n, seed + 10);
  if(name == "scales") return multiscale_points(n, seed + 11);
  throw std::invalid_argument("unknown distribution '" + name + "'");
}

template <class Point>
std::vector<Point> to_points(const std::vector<Xyz>& xyz)
{
  std::vector<Point> p;
  p.reserve(xyz.size());
  for(const Xyz& q : xyz) p.emplace_back(q.x, q.y, q.z);
  return p;
}

} // namespace fdt3_test

#endif
