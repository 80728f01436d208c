// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mesher_benchmark's Gmsh side, a process of its own (mesher_benchmark_io.h says why):
//
//   mesher_benchmark_gmsh fibres COUNT H SEED OUT   the paper's fibre cube, surface-meshed by Gmsh, to OUT
//   mesher_benchmark_gmsh hxt SURFACE THREADS OPT OUT  SURFACE meshed by HXT (Mesh.Algorithm3D = 10) to OUT;
//                                                    OPT: none (Mesh.Optimize = 0), gmsh (Mesh.Optimize = 1, Gmsh's
//                                                    default) or netgen (also Mesh.OptimizeNetgen = 1)
//
// Files in mesher_benchmark_io.h's binary format.

#include "mesher_benchmark_io.h"

#include <gmsh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

namespace {

using namespace mesher_benchmark;
typedef std::chrono::steady_clock Clock;

struct Fibre
{
  Point from, to;
};

// Distance between segments [p0, p1] and [q0, q1]: closest parameters clamped to [0, 1], as in any textbook.
double segment_distance(const Point& p0, const Point& p1, const Point& q0, const Point& q1)
{
  Point d1, d2, r;
  for(int i = 0; i < 3; ++i) {
    d1[i] = p1[i] - p0[i];
    d2[i] = q1[i] - q0[i];
    r[i] = p0[i] - q0[i];
  }
  auto dot = [](const Point& x, const Point& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  const double a = dot(d1, d1), e = dot(d2, d2), f = dot(d2, r), c = dot(d1, r), b = dot(d1, d2);
  const double denominator = a * e - b * b;
  double s = denominator > 1e-14 * a * e ? std::clamp((b * f - c * e) / denominator, 0.0, 1.0) : 0.0;
  double t = (b * s + f) / e;
  if(t < 0) {
    t = 0;
    s = std::clamp(-c / a, 0.0, 1.0);
  } else if(t > 1) {
    t = 1;
    s = std::clamp((b - c) / a, 0.0, 1.0);
  }
  double d = 0;
  for(int i = 0; i < 3; ++i) {
    const double x = (p0[i] + s * d1[i]) - (q0[i] + t * d2[i]);
    d += x * x;
  }
  return std::sqrt(d);
}

// Random fibres of one radius and length in the unit cube, at least `gap` apart from each other and from the
// cube's faces (the mesher takes nested surfaces, not touching ones).
std::vector<Fibre> random_fibres(int count, double radius, double length, double gap, unsigned seed)
{
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::normal_distribution<double> normal;
  std::vector<Fibre> fibres;
  const double margin = radius + gap;
  for(int attempt = 0; attempt < 100000 && static_cast<int>(fibres.size()) < count; ++attempt) {
    Point axis{normal(random), normal(random), normal(random)};
    const double norm = std::sqrt(axis[0] * axis[0] + axis[1] * axis[1] + axis[2] * axis[2]);
    Fibre f;
    bool inside = true;
    for(int i = 0; i < 3; ++i) {
      const double centre = margin + unit(random) * (1 - 2 * margin);
      f.from[i] = centre - axis[i] / norm * length / 2;
      f.to[i] = centre + axis[i] / norm * length / 2;
      inside = inside && std::min(f.from[i], f.to[i]) >= margin && std::max(f.from[i], f.to[i]) <= 1 - margin;
    }
    if(!inside) continue;
    bool apart = true;
    for(const Fibre& g : fibres)
      apart = apart && segment_distance(f.from, f.to, g.from, g.to) > 2 * radius + gap;
    if(apart) fibres.push_back(f);
  }
  return fibres;
}

// The paper's test case: the unit cube and the fibres as OpenCASCADE solids, fragmented so that the matrix and the
// fibres share the fibres' surfaces, surface-meshed by Gmsh at size h, handed over as one triangle soup.
Benchmark_surface fibre_cube(int count, double h, unsigned seed)
{
  const double radius = 0.04, length = 0.4;
  const std::vector<Fibre> fibres = random_fibres(count, radius, length, 0.02, seed);
  gmsh::clear();
  gmsh::model::add("fibres");
  const int box = gmsh::model::occ::addBox(0, 0, 0, 1, 1, 1);
  gmsh::vectorpair tools;
  for(const Fibre& f : fibres)
    tools.push_back({3, gmsh::model::occ::addCylinder(f.from[0], f.from[1], f.from[2], f.to[0] - f.from[0],
                                                      f.to[1] - f.from[1], f.to[2] - f.from[2], radius)});
  gmsh::vectorpair out;
  std::vector<gmsh::vectorpair> out_map;
  gmsh::model::occ::fragment({{3, box}}, tools, out, out_map);
  gmsh::model::occ::synchronize();
  gmsh::option::setNumber("Mesh.MeshSizeMax", h);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::model::mesh::generate(2);

  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, -1, -1, false, false);
  std::map<std::size_t, std::size_t> index_of_tag;
  Benchmark_surface s;
  std::vector<std::size_t> element_tags, element_nodes;
  gmsh::model::mesh::getElementsByType(2, element_tags, element_nodes);
  std::map<std::size_t, std::size_t> position;
  for(std::size_t k = 0; k < node_tags.size(); ++k) position[node_tags[k]] = k;
  for(std::size_t k = 0; k < element_nodes.size(); k += 3) {
    Triangle t;
    for(int i = 0; i < 3; ++i) {
      auto inserted = index_of_tag.insert({element_nodes[k + i], s.points.size()});
      if(inserted.second) {
        const std::size_t p = position.at(element_nodes[k + i]);
        s.points.push_back({coordinates[3 * p], coordinates[3 * p + 1], coordinates[3 * p + 2]});
      }
      t[i] = inserted.first->second;
    }
    s.triangles.push_back(t);
  }
  orient_components(s);
  s.name = "fibres" + std::to_string(fibres.size());
  // The component with the lowest x is the cube's; the matrix is bounded by it and every fibre.
  std::size_t lowest = 0;
  for(std::size_t t = 0; t < s.triangles.size(); ++t)
    if(s.points[s.triangles[t][0]][0] < s.points[s.triangles[lowest][0]][0]) lowest = t;
  const int cube = s.component[lowest];
  s.volumes.assign(1, {cube});
  for(int c = 0; c < s.number_of_components; ++c)
    if(c != cube) {
      s.volumes[0].push_back(c);
      s.volumes.push_back({c});
    }
  return s;
}

// The number after "`label`" and '=' in Gmsh's log (0 if absent).
double logged_seconds(const std::string& log, const std::string& label)
{
  const std::size_t at = log.find(label);
  if(at == std::string::npos) return 0;
  const std::size_t equals = log.find('=', at + label.size());
  return equals == std::string::npos ? 0 : std::atof(log.c_str() + equals + 1);
}


// HXT through Gmsh's API, from the same triangles: one discrete surface per component.
Tool_mesh run_hxt(const Benchmark_surface& s, int threads, const std::string& optimisation)
{
  gmsh::clear();
  gmsh::model::add(s.name);
  std::vector<std::vector<std::size_t>> component_nodes(s.number_of_components),
      component_triangles(s.number_of_components);
  std::vector<int> component_of_point(s.points.size(), -1);
  for(std::size_t t = 0; t < s.triangles.size(); ++t)
    for(int i = 0; i < 3; ++i) {
      const std::size_t p = s.triangles[t][i];
      component_triangles[s.component[t]].push_back(p + 1);
      if(component_of_point[p] < 0) {
        component_of_point[p] = s.component[t];
        component_nodes[s.component[t]].push_back(p);
      }
    }
  for(int c = 0; c < s.number_of_components; ++c) {
    gmsh::model::addDiscreteEntity(2, c + 1);
    std::vector<std::size_t> tags;
    std::vector<double> coordinates;
    for(std::size_t p : component_nodes[c]) {
      tags.push_back(p + 1);
      coordinates.insert(coordinates.end(), s.points[p].begin(), s.points[p].end());
    }
    gmsh::model::mesh::addNodes(2, c + 1, tags, coordinates);
    gmsh::model::mesh::addElementsByType(c + 1, 2, {}, component_triangles[c]);
  }
  // Gmsh does not mesh a discrete volume (it holds a mesh already): a volume of its built-in kernel on the discrete
  // surfaces, one surface loop per component, the first the outer one, is what it meshes.
  for(std::size_t v = 0; v < s.volumes.size(); ++v) {
    std::vector<int> loops;
    for(int c : s.volumes[v]) loops.push_back(gmsh::model::geo::addSurfaceLoop({c + 1}));
    gmsh::model::geo::addVolume(loops, static_cast<int>(v) + 1);
  }
  gmsh::model::geo::synchronize();
  gmsh::option::setNumber("Mesh.Algorithm3D", 10);
  gmsh::option::setNumber("General.NumThreads", threads);
  gmsh::option::setNumber("Mesh.MaxNumThreads3D", threads);
  gmsh::option::setNumber("Mesh.Optimize", optimisation == "none" ? 0 : 1);
  gmsh::option::setNumber("Mesh.OptimizeNetgen", optimisation == "netgen" ? 1 : 0);
  gmsh::option::setNumber("Mesh.MeshSizeExtendFromBoundary", 1);
  gmsh::option::setNumber("Mesh.MeshSizeFromCurvature", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMin", 0);
  gmsh::option::setNumber("Mesh.MeshSizeMax", std::isfinite(s.maximum_size) ? s.maximum_size : 1e22);

  gmsh::logger::start();
  const Clock::time_point t0 = Clock::now();
  gmsh::model::mesh::generate(3);
  Tool_mesh mesh;
  mesh.total = std::chrono::duration<double>(Clock::now() - t0).count();
  std::vector<std::string> lines;
  gmsh::logger::get(lines);
  gmsh::logger::stop();
  std::string log;
  for(const std::string& line : lines) log += line + "\n";
  // HXT's own split: empty mesh, boundary check, recovery (TetGen's, in HXT), conversion; then refinement.
  mesh.recovery = logged_seconds(log, "tEmptyMesh") + logged_seconds(log, "tVerifyBnd") +
                 logged_seconds(log, "tBndRecovery") + logged_seconds(log, "tConvertMesh");
  mesh.refinement = logged_seconds(log, "tRefine");
  // Gmsh logs no figure of its own for the optimisation: what generate(3) spent after HXT returned.
  mesh.improvement = optimisation == "none" ? 0 : std::max(0.0, mesh.total - mesh.recovery - mesh.refinement);

  std::vector<std::size_t> node_tags;
  std::vector<double> coordinates, parametric;
  gmsh::model::mesh::getNodes(node_tags, coordinates, parametric, -1, -1, false, false);
  std::size_t largest = 0;
  for(std::size_t tag : node_tags) largest = std::max(largest, tag);
  std::vector<std::uint32_t> index_of_tag(largest + 1, std::uint32_t(-1));
  // Input points first, at their own numbers, found by their coordinates: Gmsh renumbers the nodes of some
  // inputs after meshing (the elephant's came back with other tags), so tags cannot be trusted.  A surface node at
  // a new position is a Steiner point on the surface, and the boundary check will say so.
  std::map<Point, std::uint32_t> input_point;
  for(std::size_t i = 0; i < s.points.size(); ++i) input_point.emplace(s.points[i], static_cast<std::uint32_t>(i));
  mesh.points = s.points;
  for(std::size_t k = 0; k < node_tags.size(); ++k) {
    const Point xyz{coordinates[3 * k], coordinates[3 * k + 1], coordinates[3 * k + 2]};
    auto it = input_point.find(xyz);
    if(it != input_point.end()) {
      index_of_tag[node_tags[k]] = it->second;
    } else {
      index_of_tag[node_tags[k]] = static_cast<std::uint32_t>(mesh.points.size());
      mesh.points.push_back(xyz);
    }
  }
  for(std::size_t v = 0; v < s.volumes.size(); ++v) {
    std::vector<std::size_t> tet_tags, tet_nodes;
    gmsh::model::mesh::getElementsByType(4, tet_tags, tet_nodes, static_cast<int>(v) + 1);
    for(std::size_t k = 0; k < tet_nodes.size(); k += 4) {
      mesh.tetrahedra.push_back({index_of_tag[tet_nodes[k]], index_of_tag[tet_nodes[k + 1]],
                                 index_of_tag[tet_nodes[k + 2]], index_of_tag[tet_nodes[k + 3]]});
      mesh.subdomain.push_back(static_cast<int>(v) + 1);
    }
  }
  return mesh;
}

} // namespace

int main(int argc, char** argv)
{
  const std::string command = argc > 1 ? argv[1] : "";
  const std::string optimisation = command == "hxt" && argc == 6 ? argv[4] : "";
  if(!((command == "fibres" && argc == 6) ||
       (command == "hxt" && argc == 6 && (optimisation == "none" || optimisation == "gmsh" || optimisation == "netgen")))) {
    std::fprintf(stderr, "usage: mesher_benchmark_gmsh fibres COUNT H SEED OUT | hxt SURFACE THREADS none|gmsh|netgen OUT\n");
    return 2;
  }
  try {
    gmsh::initialize();
    gmsh::option::setNumber("General.Terminal", 0);
    if(command == "fibres")
      write_surface(argv[5], fibre_cube(std::atoi(argv[2]), std::atof(argv[3]), static_cast<unsigned>(std::atoi(argv[4]))));
    else
      write_tool_mesh(argv[5], run_hxt(read_surface(argv[2]), std::atoi(argv[3]), optimisation));
    gmsh::finalize();
  } catch(const std::exception& e) {
    std::fprintf(stderr, "mesher_benchmark_gmsh: %s\n", e.what());
    return 1;
  } catch(...) {
    // Gmsh 4.8's API throws its error codes, not exceptions: the message is in its log.
    std::string error;
    gmsh::logger::getLastError(error);
    std::fprintf(stderr, "mesher_benchmark_gmsh: Gmsh failed: %s\n", error.c_str());
    return 1;
  }
  return 0;
}
