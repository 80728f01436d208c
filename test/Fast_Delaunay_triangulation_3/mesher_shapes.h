// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Closed surfaces for the mesher's tests, generated: a cube, an icosphere,
// a torus, and helpers to combine them and write them as OFF files.  Each
// surface is oriented outward, consistently.

#ifndef FDT3_TEST_MESHER_SHAPES_H
#define FDT3_TEST_MESHER_SHAPES_H

#include <array>
#include <cmath>
#include <cstddef>
#include <fstream>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace mesher_shapes {

struct Surface
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::size_t, 3>> triangles;
};

// Axis-aligned cube [lo, hi]^3, two triangles per face.
inline Surface cube(double lo = 0, double hi = 1)
{
  Surface s;
  for(int i = 0; i < 8; ++i) s.points.push_back({i & 1 ? hi : lo, i & 2 ? hi : lo, i & 4 ? hi : lo});
  // Each face as a quad (a, b, c, d) counter-clockwise seen from outside.
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for(const auto& q : quads) {
    s.triangles.push_back({std::size_t(q[0]), std::size_t(q[1]), std::size_t(q[2])});
    s.triangles.push_back({std::size_t(q[0]), std::size_t(q[2]), std::size_t(q[3])});
  }
  return s;
}

// Icosahedron subdivided `levels` times, projected on the sphere.
inline Surface icosphere(int levels, double radius = 1, std::array<double, 3> centre = {0, 0, 0})
{
  Surface s;
  const double t = (1 + std::sqrt(5.0)) / 2;
  const double base[12][3] = {{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                              {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}};
  for(const auto& p : base) s.points.push_back({p[0], p[1], p[2]});
  s.triangles = {{0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
                 {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
                 {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
  for(int level = 0; level < levels; ++level) {
    std::map<std::pair<std::size_t, std::size_t>, std::size_t> middle;
    auto middle_of = [&](std::size_t a, std::size_t b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      auto it = middle.find(key);
      if(it != middle.end()) return it->second;
      std::array<double, 3> m;
      for(int k = 0; k < 3; ++k) m[k] = (s.points[a][k] + s.points[b][k]) / 2;
      s.points.push_back(m);
      return middle[key] = s.points.size() - 1;
    };
    std::vector<std::array<std::size_t, 3>> finer;
    for(const auto& tr : s.triangles) {
      const std::size_t ab = middle_of(tr[0], tr[1]), bc = middle_of(tr[1], tr[2]), ca = middle_of(tr[2], tr[0]);
      finer.push_back({tr[0], ab, ca});
      finer.push_back({tr[1], bc, ab});
      finer.push_back({tr[2], ca, bc});
      finer.push_back({ab, bc, ca});
    }
    s.triangles.swap(finer);
  }
  for(auto& p : s.points) {
    const double l = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
    for(int k = 0; k < 3; ++k) p[k] = centre[k] + radius * p[k] / l;
  }
  return s;
}

// Torus around the z axis: major radius R, minor r, n x m quads split in two.
inline Surface torus(double R, double r, int n, int m)
{
  Surface s;
  const double pi = 3.14159265358979323846;
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j) {
      const double u = 2 * pi * i / n, v = 2 * pi * j / m;
      s.points.push_back({(R + r * std::cos(v)) * std::cos(u), (R + r * std::cos(v)) * std::sin(u), r * std::sin(v)});
    }
  auto id = [&](int i, int j) { return std::size_t(((i + n) % n) * m + (j + m) % m); };
  for(int i = 0; i < n; ++i)
    for(int j = 0; j < m; ++j) {
      s.triangles.push_back({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      s.triangles.push_back({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  return s;
}

inline Surface combine(const Surface& a, const Surface& b)
{
  Surface s = a;
  for(const auto& p : b.points) s.points.push_back(p);
  for(const auto& t : b.triangles)
    s.triangles.push_back({t[0] + a.points.size(), t[1] + a.points.size(), t[2] + a.points.size()});
  return s;
}

// Signed volume enclosed (positive for an outward orientation).
inline double enclosed_volume(const Surface& s)
{
  double v = 0;
  for(const auto& t : s.triangles) {
    const auto &a = s.points[t[0]], &b = s.points[t[1]], &c = s.points[t[2]];
    v += (a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
          a[2] * (b[0] * c[1] - b[1] * c[0])) / 6;
  }
  return v;
}

inline void write_off(const std::string& path, const Surface& s)
{
  std::ofstream out(path);
  out.precision(17);
  out << "OFF\n" << s.points.size() << ' ' << s.triangles.size() << " 0\n";
  for(const auto& p : s.points) out << p[0] << ' ' << p[1] << ' ' << p[2] << "\n";
  for(const auto& t : s.triangles) out << "3 " << t[0] << ' ' << t[1] << ' ' << t[2] << "\n";
}

} // namespace mesher_shapes

#endif // FDT3_TEST_MESHER_SHAPES_H
