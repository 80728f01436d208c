// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// What mesher_benchmark and its Gmsh helper, mesher_benchmark_gmsh, exchange: the triangle surface every mesher
// gets and the tetrahedra a tool returns, as raw binary files.  Two programs, because Debian's libgmsh carries its
// own, different build of TetGen's classes under the same symbol names as libtet: in one process, one library's
// calls land in the other's code (TetGen crashed inside libgmsh's tetgenmesh::incrementaldelaunay).  The mesher
// needs libtet; so HXT runs in a process that links libgmsh alone.

#ifndef FDT3_BENCHMARK_MESHER_BENCHMARK_IO_H
#define FDT3_BENCHMARK_MESHER_BENCHMARK_IO_H

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mesher_benchmark {

typedef std::array<double, 3> Point;
typedef std::array<std::size_t, 3> Triangle;

// The input every mesher gets.  Each closed surface (connected set of triangles) is a component; a volume is
// bounded by one or more components (the fibres' matrix by the cube and every fibre).
struct Benchmark_surface
{
  std::string name;
  std::vector<Point> points;
  std::vector<Triangle> triangles;
  std::vector<int> component; // per triangle, from 0
  int number_of_components = 0;
  std::vector<std::vector<int>> volumes;
  double maximum_size = std::numeric_limits<double>::infinity();
};

// Gives every component of `s` one orientation, outward, by walking across edges: a neighbour must use the shared
// edge in the other direction.  Gmsh's surface meshes are oriented per CAD face, not per closed surface.
inline void orient_components(Benchmark_surface& s)
{
  std::map<std::pair<std::size_t, std::size_t>, std::vector<std::size_t>> edge_triangles;
  for(std::size_t t = 0; t < s.triangles.size(); ++t)
    for(int i = 0; i < 3; ++i) {
      const std::size_t a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
      edge_triangles[{std::min(a, b), std::max(a, b)}].push_back(t);
    }
  auto uses_edge_forward = [&](std::size_t t, std::size_t a, std::size_t b) {
    for(int i = 0; i < 3; ++i)
      if(s.triangles[t][i] == a && s.triangles[t][(i + 1) % 3] == b) return true;
    return false;
  };
  s.component.assign(s.triangles.size(), -1);
  s.number_of_components = 0;
  for(std::size_t seed = 0; seed < s.triangles.size(); ++seed) {
    if(s.component[seed] >= 0) continue;
    const int c = s.number_of_components++;
    std::vector<std::size_t> stack{seed}, members;
    s.component[seed] = c;
    while(!stack.empty()) {
      const std::size_t t = stack.back();
      stack.pop_back();
      members.push_back(t);
      for(int i = 0; i < 3; ++i) {
        const std::size_t a = s.triangles[t][i], b = s.triangles[t][(i + 1) % 3];
        for(std::size_t u : edge_triangles[{std::min(a, b), std::max(a, b)}]) {
          if(u == t || s.component[u] >= 0) continue;
          if(uses_edge_forward(u, a, b)) std::swap(s.triangles[u][0], s.triangles[u][1]);
          s.component[u] = c;
          stack.push_back(u);
        }
      }
    }
    double volume = 0;
    for(std::size_t t : members) {
      const Point &a = s.points[s.triangles[t][0]], &b = s.points[s.triangles[t][1]], &c3 = s.points[s.triangles[t][2]];
      volume += a[0] * (b[1] * c3[2] - b[2] * c3[1]) - a[1] * (b[0] * c3[2] - b[2] * c3[0]) +
                a[2] * (b[0] * c3[1] - b[1] * c3[0]);
    }
    if(volume < 0)
      for(std::size_t t : members) std::swap(s.triangles[t][0], s.triangles[t][1]);
  }
}

// A tool's output: its points (the input points first, at their own numbers), tetrahedra with a subdomain from 1,
// and its own split of the seconds.
struct Tool_mesh
{
  std::vector<Point> points;
  std::vector<std::array<std::uint32_t, 4>> tetrahedra;
  std::vector<int> subdomain;
  double recovery = 0, refinement = 0, improvement = 0, total = 0;
};

class Binary_file
{
public:
  Binary_file(const std::string& path, const char* mode) : file_(std::fopen(path.c_str(), mode)), path_(path)
  {
    if(!file_) throw std::runtime_error("cannot open " + path);
  }
  ~Binary_file() { std::fclose(file_); }
  Binary_file(const Binary_file&) = delete;
  Binary_file& operator=(const Binary_file&) = delete;

  template <class T> void put(const T& value) { put_bytes(&value, sizeof value); }
  template <class T> void put(const std::vector<T>& values)
  {
    put(static_cast<std::uint64_t>(values.size()));
    put_bytes(values.data(), values.size() * sizeof(T));
  }
  template <class T> void get(T& value) { get_bytes(&value, sizeof value); }
  template <class T> void get(std::vector<T>& values)
  {
    std::uint64_t n = 0;
    get(n);
    values.resize(n);
    get_bytes(values.data(), n * sizeof(T));
  }

private:
  void put_bytes(const void* data, std::size_t size)
  {
    if(std::fwrite(data, 1, size, file_) != size) throw std::runtime_error("cannot write " + path_);
  }
  void get_bytes(void* data, std::size_t size)
  {
    if(std::fread(data, 1, size, file_) != size) throw std::runtime_error("truncated file " + path_);
  }
  std::FILE* file_;
  std::string path_;
};

inline void write_surface(const std::string& path, const Benchmark_surface& s)
{
  Binary_file f(path, "wb");
  std::vector<char> name(s.name.begin(), s.name.end());
  f.put(name);
  f.put(s.points);
  f.put(s.triangles);
  f.put(s.component);
  f.put(s.number_of_components);
  f.put(static_cast<std::uint64_t>(s.volumes.size()));
  for(const auto& v : s.volumes) f.put(v);
  f.put(s.maximum_size);
}

inline Benchmark_surface read_surface(const std::string& path)
{
  Binary_file f(path, "rb");
  Benchmark_surface s;
  std::vector<char> name;
  f.get(name);
  s.name.assign(name.begin(), name.end());
  f.get(s.points);
  f.get(s.triangles);
  f.get(s.component);
  f.get(s.number_of_components);
  std::uint64_t volumes = 0;
  f.get(volumes);
  s.volumes.resize(volumes);
  for(auto& v : s.volumes) f.get(v);
  f.get(s.maximum_size);
  return s;
}

inline void write_tool_mesh(const std::string& path, const Tool_mesh& m)
{
  Binary_file f(path, "wb");
  f.put(m.points);
  f.put(m.tetrahedra);
  f.put(m.subdomain);
  f.put(m.recovery);
  f.put(m.refinement);
  f.put(m.improvement);
  f.put(m.total);
}

inline Tool_mesh read_tool_mesh(const std::string& path)
{
  Binary_file f(path, "rb");
  Tool_mesh m;
  f.get(m.points);
  f.get(m.tetrahedra);
  f.get(m.subdomain);
  f.get(m.recovery);
  f.get(m.refinement);
  f.get(m.improvement);
  f.get(m.total);
  return m;
}

} // namespace mesher_benchmark

#endif // FDT3_BENCHMARK_MESHER_BENCHMARK_IO_H
