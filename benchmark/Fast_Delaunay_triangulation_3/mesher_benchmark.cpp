// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The mesher of the paper's §4 beside Gmsh's HXT mesher and TetGen, on the same triangle surfaces: closed surfaces
// of CGAL's data (libcgal-demo) and the paper's test case, a cube filled with random non-intersecting cylindrical
// fibres built with Gmsh's OpenCASCADE kernel and surface-meshed by Gmsh.  Every mesher gets the same points and
// triangles; the tools run interleaved, round after round, and the table shows medians.  The quality columns come
// from one function, the mesher's own quality report, applied to every tool's output rebuilt as a Tetrahedral_mesh,
// so that the figures are computed the same way for all.
//
// The size field is the same for all: h at a surface point is the average length of its surface edges, interpolated
// inside, capped by --max-size.  Ours does that itself; HXT does it with Mesh.MeshSizeExtendFromBoundary
// (Mesh.MeshSizeMax = the cap); TetGen gets h at the input points through -m (pointmtrlist) and the cap as a volume
// bound (-a, the volume of the regular tetrahedron of edge h); CGAL's Mesh_3 takes one constant, the median of the
// surface sizes (mesher_benchmark_cgal.cpp).
//
// Every tool runs as a finite-element user runs it, with its mesh improvement: ours (Mesh_improvement.h, on by
// default), HXT with Gmsh's default Mesh.Optimize = 1 and, as a second row, Mesh.OptimizeNetgen = 1, TetGen with its
// default optimisation, Mesh_3 with perturb_mesh_3 and exude_mesh_3.  One row of each without it (ours with
// optimize off, HXT with Mesh.Optimize = 0, TetGen -O0) shows what the step costs and gains.  Mesh_3 samples the
// surface anew; the row ours-remeshed does the same for ours (Surface_remeshing.h: CGAL's isotropic remeshing to
// Mesh_3's constant, sharp edges kept, shorter where walls thinner than it leave flat tetrahedra), so that its
// quality is compared with Mesh_3's on equal terms.

// Gmsh runs in a helper process, mesher_benchmark_gmsh (mesher_benchmark_io.h says why); without Gmsh
// (libgmsh-dev) at build time there is no helper, and the HXT rows and the fibre surface are left out.
//
// --json FILE writes every row with its quality histograms (from the report: radius-edge ratio, gamma, the smallest
// dihedral angle of each tetrahedron); --plot FIGURE writes them to FIGURE's name with .json and has
// scripts/plot_mesh_quality.py draw every tool's histograms on one figure.

#include <CGAL/Fast_Delaunay_triangulation_3/Surface_remeshing.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Tetrahedral_mesher.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/version.h>

#include <tetgen.h>

#include "mesher_benchmark_cgal.h"
#include "mesher_benchmark_io.h"

#include <sched.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <functional>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace {

typedef CGAL::Fast_mesher_3::Tetrahedral_mesh Mesh;
typedef std::chrono::steady_clock Clock;
using namespace mesher_benchmark;

double seconds_since(Clock::time_point t0) { return std::chrono::duration<double>(Clock::now() - t0).count(); }

Benchmark_surface read_cgal_surface(const std::string& path)
{
  Benchmark_surface s;
  s.name = path.substr(path.find_last_of('/') + 1);
  s.name = s.name.substr(0, s.name.find('.'));
  std::vector<CGAL::Epick::Point_3> points;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_polygon_soup(path, points, polygons) || polygons.empty())
    throw std::runtime_error("cannot read the surface " + path);
  for(const auto& p : points) s.points.push_back({p.x(), p.y(), p.z()});
  for(const auto& p : polygons) {
    if(p.size() != 3) throw std::runtime_error(path + " has a polygon that is not a triangle");
    s.triangles.push_back({p[0], p[1], p[2]});
  }
  orient_components(s);
  // CGAL's data surfaces chosen here are single closed surfaces; several would have to be tested for nesting.
  if(s.number_of_components != 1) throw std::runtime_error(path + " is not one closed surface");
  s.volumes = {{0}};
  return s;
}


// ------------------------------------------------------------------------------------------------ Gmsh helper

// Where the files for the Gmsh helper go: a fresh folder under the temporary directory, removed at exit.
const std::string& scratch_directory()
{
  static const std::string path = [] {
    std::string pattern = (std::filesystem::temp_directory_path() / "mesher_benchmark_XXXXXX").string();
    if(!::mkdtemp(pattern.data())) throw std::runtime_error("cannot create a scratch folder");
    return pattern;
  }();
  return path;
}

// mesher_benchmark_gmsh beside this program; empty when it was not built (no libgmsh-dev).
std::string gmsh_helper()
{
  std::error_code error;
  const std::filesystem::path self = std::filesystem::read_symlink("/proc/self/exe", error);
  if(error) return "";
  const std::string helper = (self.parent_path() / "mesher_benchmark_gmsh").string();
  return ::access(helper.c_str(), X_OK) == 0 ? helper : "";
}

void run_gmsh_helper(const std::vector<std::string>& arguments)
{
  std::vector<std::string> words{gmsh_helper()};
  words.insert(words.end(), arguments.begin(), arguments.end());
  std::vector<char*> argv;
  for(std::string& w : words) argv.push_back(w.data());
  argv.push_back(nullptr);
  std::fflush(stdout);
  const pid_t pid = ::fork();
  if(pid < 0) throw std::runtime_error("fork failed");
  if(pid == 0) {
    // libgomp's default lets idle threads spin: on a machine with other work, HXT's 2 threads then wait for each
    // other at every parallel section (elephant at load 4.3: 1.9 s on 2 threads, 0.07 s on 1; 0.07 s on 2 with
    // PASSIVE).  An OMP_WAIT_POLICY given by the caller is kept.
    ::setenv("OMP_WAIT_POLICY", "PASSIVE", 0);
    ::execv(argv[0], argv.data());
    std::_Exit(127);
  }
  int status = 0;
  ::waitpid(pid, &status, 0);
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("mesher_benchmark_gmsh " + arguments.front() + " failed (status " +
                             std::to_string(status) + ")");
}

Benchmark_surface fibre_cube(int count, double h, unsigned seed)
{
  const std::string path = scratch_directory() + "/fibres.bin";
  run_gmsh_helper({"fibres", std::to_string(count), std::to_string(h), std::to_string(seed), path});
  return read_surface(path);
}

// ------------------------------------------------------------------------------------------------ meshers

// One mesher on one surface.  `mesh` holds the tool's tetrahedra with a subdomain number each and the input
// triangles in the tool's point numbering (the input points keep their positions in every tool's output).
struct Run
{
  double recovery = 0, refinement = 0, improvement = 0, total = 0;
  Mesh mesh;
  bool surface_remeshed = false; // the tool samples the surface anew (Mesh_3): its boundary is not the input's
};

struct Tool
{
  std::string name;
  int threads;
  std::function<Run(const Benchmark_surface&)> run;
};

// The average length of the surface edges at each point (both triangles of an edge count it: still the average).
std::vector<double> surface_sizes(const Benchmark_surface& s)
{
  std::vector<double> sum(s.points.size(), 0);
  std::vector<int> count(s.points.size(), 0);
  for(const Triangle& t : s.triangles)
    for(int i = 0; i < 3; ++i) {
      const std::size_t a = t[i], b = t[(i + 1) % 3];
      double l = 0;
      for(int k = 0; k < 3; ++k) l += (s.points[a][k] - s.points[b][k]) * (s.points[a][k] - s.points[b][k]);
      l = std::sqrt(l);
      sum[a] += l;
      sum[b] += l;
      count[a] += 1;
      count[b] += 1;
    }
  std::vector<double> h(s.points.size());
  for(std::size_t i = 0; i < h.size(); ++i) h[i] = std::min(s.maximum_size, count[i] ? sum[i] / count[i] : 0);
  return h;
}

CGAL::Fast_mesher_3::Mesher_options ours_options(const Benchmark_surface& s, int threads, bool optimize)
{
  CGAL::Fast_mesher_3::Mesher_options options;
  options.threads = threads;
  options.optimize = optimize;
  options.maximum_size = s.maximum_size;
  return options;
}

// Algorithm 2's lines 2-3 are the recovery; colouring and sizes belong with the refinement they prepare.
Run ours_run(CGAL::Fast_mesher_3::Tetrahedral_mesh mesh, const CGAL::Fast_mesher_3::Mesher_statistics& stats)
{
  Run run;
  run.mesh = std::move(mesh);
  run.recovery = stats.empty_mesh_seconds + stats.recovery_seconds;
  run.refinement = stats.colouring_seconds + stats.refinement_seconds;
  run.improvement = stats.improvement_seconds;
  run.total = stats.total_seconds;
  return run;
}

Run run_ours(const Benchmark_surface& s, int threads, bool optimize)
{
  CGAL::Fast_mesher_3::Mesher_statistics stats;
  CGAL::Fast_mesher_3::Tetrahedral_mesh mesh =
      CGAL::Fast_mesher_3::mesh_surfaces(s.points, s.triangles, ours_options(s, threads, optimize), &stats);
  return ours_run(std::move(mesh), stats);
}

// The median of the surface sizes: the one constant given to Mesh_3, and the length ours-remeshed remeshes to.
double median_surface_size(const Benchmark_surface& s)
{
  std::vector<double> h = surface_sizes(s);
  std::nth_element(h.begin(), h.begin() + h.size() / 2, h.end());
  return h[h.size() / 2];
}

// Ours on the surface remeshed to the median size, shorter where the mesh asks for it
// (mesh_remeshed_surfaces); the remeshings and the attempts not kept count as part of the recovery.
Run run_ours_remeshed(const Benchmark_surface& s, int threads)
{
  CGAL::Fast_mesher_3::Surface_remeshing_options remeshing;
  remeshing.target_edge_length = median_surface_size(s);
  CGAL::Fast_mesher_3::Mesher_statistics stats;
  CGAL::Fast_mesher_3::Tetrahedral_mesh mesh = CGAL::Fast_mesher_3::mesh_remeshed_surfaces(
      s.points, s.triangles, remeshing, ours_options(s, threads, true), &stats);
  Run run = ours_run(std::move(mesh), stats);
  run.recovery += stats.remeshing_seconds + stats.discarded_meshing_seconds;
  run.surface_remeshed = true;
  return run;
}

// Runs `work` with the process's standard output sent to a temporary file, and returns what was written there:
// TetGen prints its phase times with printf.
std::string captured_stdout(const std::function<void()>& work)
{
  std::fflush(stdout);
  std::FILE* file = std::tmpfile();
  const int saved = ::dup(1);
  ::dup2(::fileno(file), 1);
  try {
    work();
  } catch(...) {
    std::fflush(stdout);
    ::dup2(saved, 1);
    ::close(saved);
    std::fclose(file);
    throw;
  }
  std::fflush(stdout);
  ::dup2(saved, 1);
  ::close(saved);
  std::rewind(file);
  std::string text;
  char buffer[4096];
  for(std::size_t n; (n = std::fread(buffer, 1, sizeof buffer, file)) > 0;) text.append(buffer, n);
  std::fclose(file);
  return text;
}

// The number after "`label`:" in TetGen's log (0 if absent).
double logged_seconds(const std::string& log, const std::string& label)
{
  const std::size_t at = log.find(label);
  if(at == std::string::npos) return 0;
  const std::size_t colon = log.find(':', at + label.size());
  return colon == std::string::npos ? 0 : std::atof(log.c_str() + colon + 1);
}

// Subdomain numbers 1, 2, ... for the distinct values of a per-tetrahedron attribute.
std::vector<int> subdomains_of(const std::vector<double>& attribute)
{
  std::vector<double> values = attribute;
  std::sort(values.begin(), values.end());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  std::vector<int> subdomain(attribute.size());
  for(std::size_t t = 0; t < attribute.size(); ++t)
    subdomain[t] = 1 + static_cast<int>(std::lower_bound(values.begin(), values.end(), attribute[t]) - values.begin());
  return subdomain;
}

void set_input_triangles(const Benchmark_surface& s, Mesh& mesh)
{
  mesh.triangles.clear();
  for(const Triangle& t : s.triangles)
    mesh.triangles.push_back({static_cast<std::uint32_t>(t[0]), static_cast<std::uint32_t>(t[1]),
                              static_cast<std::uint32_t>(t[2])});
  mesh.surface.assign(s.component.begin(), s.component.end());
  mesh.number_of_surfaces = s.number_of_components;
}

// `optimisation`: TetGen's -O switch, or "" for its default.
Run run_tetgen(const Benchmark_surface& s, const std::string& quality_switches, const std::string& optimisation)
{
  tetgenio in, out;
  CGAL::Fast_Delaunay_triangulation_3_internal::mesher::write_tetgen_plc(s.points, s.triangles, in);
  const std::vector<double> h = surface_sizes(s);
  in.numberofpointmtrs = 1;
  in.pointmtrlist = new REAL[s.points.size()];
  std::copy(h.begin(), h.end(), in.pointmtrlist);
  // A: one attribute per region (the subdomains); m: sizes at the points; z: from 0.
  std::string switches = quality_switches + "Amz" + optimisation;
  if(std::isfinite(s.maximum_size)) {
    std::ostringstream bound;
    bound << "a" << std::pow(s.maximum_size, 3) / (6 * std::sqrt(2.0));
    switches += bound.str();
  }
  std::vector<char> argument(switches.begin(), switches.end());
  argument.push_back('\0');
  const Clock::time_point t0 = Clock::now();
  const std::string log = captured_stdout([&] { tetrahedralize(argument.data(), &in, &out); });
  Run run;
  run.total = seconds_since(t0);
  run.refinement = logged_seconds(log, "Refinement seconds");
  run.improvement = logged_seconds(log, "Optimization seconds");
  // TetGen's Delaunay, surface recovery and exterior removal: all that precedes the refinement.
  run.recovery = run.total - run.refinement - run.improvement;

  Mesh& mesh = run.mesh;
  mesh.points.resize(static_cast<std::size_t>(out.numberofpoints));
  for(std::size_t i = 0; i < mesh.points.size(); ++i)
    for(int k = 0; k < 3; ++k) mesh.points[i][k] = out.pointlist[3 * i + k];
  std::vector<double> attribute(static_cast<std::size_t>(out.numberoftetrahedra), 0);
  for(std::size_t t = 0; t < attribute.size(); ++t) {
    mesh.tetrahedra.push_back({static_cast<std::uint32_t>(out.tetrahedronlist[4 * t]),
                               static_cast<std::uint32_t>(out.tetrahedronlist[4 * t + 1]),
                               static_cast<std::uint32_t>(out.tetrahedronlist[4 * t + 2]),
                               static_cast<std::uint32_t>(out.tetrahedronlist[4 * t + 3])});
    if(out.numberoftetrahedronattributes > 0)
      attribute[t] = out.tetrahedronattributelist[t * out.numberoftetrahedronattributes];
  }
  mesh.subdomain = subdomains_of(attribute);
  mesh.number_of_subdomains = *std::max_element(mesh.subdomain.begin(), mesh.subdomain.end());
  set_input_triangles(s, mesh);
  return run;
}

// HXT in the helper process; its seconds are measured there, around Gmsh's generate(3) alone.
// `optimisation`: none, gmsh or netgen (mesher_benchmark_gmsh.cpp).
Run run_hxt(const Benchmark_surface& s, int threads, const std::string& optimisation)
{
  const std::string in = scratch_directory() + "/" + s.name + ".surface", out = scratch_directory() + "/hxt.mesh";
  write_surface(in, s);
  run_gmsh_helper({"hxt", in, std::to_string(threads), optimisation, out});
  Tool_mesh result = read_tool_mesh(out);
  Run run;
  run.recovery = result.recovery;
  run.refinement = result.refinement;
  run.improvement = result.improvement;
  run.total = result.total;
  run.mesh.points = std::move(result.points);
  run.mesh.tetrahedra = std::move(result.tetrahedra);
  run.mesh.subdomain = std::move(result.subdomain);
  run.mesh.number_of_subdomains = static_cast<int>(s.volumes.size());
  set_input_triangles(s, run.mesh);
  return run;
}

Run run_cgal(const Benchmark_surface& s)
{
  Cgal_mesh_3_run result = run_cgal_mesh_3(s, median_surface_size(s));
  Run run;
  run.refinement = result.refinement;
  run.improvement = result.improvement;
  run.total = result.total;
  run.mesh.points = std::move(result.points);
  run.mesh.tetrahedra = std::move(result.tetrahedra);
  run.mesh.subdomain.assign(run.mesh.tetrahedra.size(), 1);
  run.mesh.number_of_subdomains = 1;
  run.surface_remeshed = true;
  return run;
}

// ------------------------------------------------------------------------------------------------ quality

// The mesher's quality report on any tool's mesh.  Tools differ in which orientation they call positive (TetGen
// lists its tetrahedra the other way round): the majority orientation is taken as the tool's, and the report's
// inverted count is then the tetrahedra against it or flat.
CGAL::Fast_mesher_3::Quality_report quality_of(Mesh mesh)
{
  std::size_t negative = 0;
  for(const auto& t : mesh.tetrahedra)
    if(CGAL::Fast_Delaunay_triangulation_3_internal::orientation(mesh.points[t[0]].data(), mesh.points[t[1]].data(),
                                                                 mesh.points[t[2]].data(), mesh.points[t[3]].data()) < 0)
      ++negative;
  if(2 * negative > mesh.tetrahedra.size())
    for(auto& t : mesh.tetrahedra) std::swap(t[0], t[1]);
  mesh.size.assign(mesh.points.size(), 1.0); // edge length / h is not in the table
  return CGAL::Fast_mesher_3::quality_report(mesh, std::max(1, int(std::thread::hardware_concurrency())));
}

// ------------------------------------------------------------------------------------------------ table

struct Row
{
  const Benchmark_surface* surface;
  const Tool* tool;
  std::vector<double> recovery, refinement, improvement, total;
  std::size_t tetrahedra = 0;
  CGAL::Fast_mesher_3::Quality_report quality;
  bool surface_remeshed = false;
  std::string failure;
};

double median(std::vector<double> v)
{
  if(v.empty()) return std::numeric_limits<double>::quiet_NaN();
  std::sort(v.begin(), v.end());
  return v.size() % 2 ? v[v.size() / 2] : (v[v.size() / 2 - 1] + v[v.size() / 2]) / 2;
}

std::string cpu_model()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  for(std::string line; std::getline(cpuinfo, line);)
    if(line.compare(0, 10, "model name") == 0) return line.substr(line.find_first_not_of(" \t:", 10));
  return "unknown CPU";
}

double load_average()
{
  std::ifstream loadavg("/proc/loadavg");
  double load = -1;
  loadavg >> load;
  return load;
}

std::string utc_now()
{
  const std::time_t now = std::time(nullptr);
  char date[64];
  std::strftime(date, sizeof date, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return date;
}

// The cores this process may run on; -1 if unknown.
int usable_cores()
{
  cpu_set_t set;
  return ::sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : -1;
}

std::string machine()
{
  return cpu_model() + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads, " +
         std::to_string(usable_cores()) + " usable";
}

void print_header(const std::string& date, int rounds)
{
  std::printf("mesher benchmark, %s\n", date.c_str());
  std::printf("machine: %s; load average %.2f at the start\n", machine().c_str(), load_average());
  std::printf("build:   GCC %s, CGAL %s, TetGen 1.5", __VERSION__, CGAL_VERSION_STR);
  if(gmsh_helper().empty())
    std::printf(", no Gmsh helper (libgmsh-dev absent at build time: no HXT rows, no fibres)");
  else
    std::printf(", Gmsh's HXT through %s (OMP_WAIT_POLICY=%s)", gmsh_helper().c_str(),
                std::getenv("OMP_WAIT_POLICY") ? std::getenv("OMP_WAIT_POLICY") : "PASSIVE");
#ifndef NDEBUG
  std::printf(", assertions ON (not a Release build: times are not representative)");
#endif
  std::printf("\nmethod:  medians of %d interleaved rounds; seconds from the triangle surface in memory to the tool's\n"
              "         mesh (ours: without the input checks); tetrahedra / s = tetrahedra / total; quality by the\n"
              "         mesher's own report on each tool's output; 'improve' is each tool's mesh improvement (ours,\n"
              "         HXT Mesh.Optimize=1 [+netgen], TetGen's default -O, Mesh_3 perturb+exude); -noopt rows without it;\n"
              "         dih1%% = 1st percentile of each tetrahedron's smallest dihedral angle; g<0.3 = share of\n"
              "         tetrahedra with gamma = 3 r_in / r_circ under 0.3; forced = share of tetrahedra on an input\n"
              "         triangle under which no tetrahedron reaches gamma 0.3 (a proven bound: every tool that keeps\n"
              "         the boundary has them; all are in g<0.3)\n\n",
              rounds);
}

void print_surfaces(const std::vector<Benchmark_surface>& surfaces)
{
  for(const Benchmark_surface& s : surfaces)
    std::printf("surface %-12s %8zu points %8zu triangles %3d closed surfaces %3zu volumes, h cap %g\n",
                s.name.c_str(), s.points.size(), s.triangles.size(), s.number_of_components, s.volumes.size(),
                s.maximum_size);
  std::printf("\n");
}

void print_table(const std::vector<Row>& rows)
{
  std::printf("%-12s %-17s %3s %8s %8s %8s %8s %9s %9s %7s %7s %8s %7s %7s %4s  %s\n", "surface", "tool", "thr",
              "recovery", "refine", "improve", "total s", "tets", "tets/s", "min dih", "dih1%", "min g", "g<0.3",
              "forced", "inv",
              "boundary = input (missing input triangles / extra boundary facets)");
  for(const Row& r : rows) {
    if(!r.failure.empty()) {
      std::printf("%-12s %-17s %3d failed: %s\n", r.surface->name.c_str(), r.tool->name.c_str(), r.tool->threads,
                  r.failure.c_str());
      continue;
    }
    const double total = median(r.total);
    const CGAL::Fast_mesher_3::Quality_report& q = r.quality;
    const double percent = q.tetrahedra ? 100.0 / q.tetrahedra : 0.0;
    std::printf("%-12s %-17s %3d %8.3f %8.3f %8.3f %8.3f %9zu %9.0f %7.3f %7.2f %8.2g %6.2f%% %6.2f%% %4zu  %s",
                r.surface->name.c_str(), r.tool->name.c_str(), r.tool->threads, median(r.recovery),
                median(r.refinement), median(r.improvement), total, r.tetrahedra, r.tetrahedra / total,
                q.min_dihedral_degrees, q.min_dihedral_1st_percentile, q.min_gamma,
                percent * q.tetrahedra_below_gamma_0_3, percent * q.tetrahedra_forced_below_gamma_0_3,
                q.inverted_tetrahedra,
                r.surface_remeshed ? "remeshed" : q.boundary_equals_input() ? "yes" : "NO");
    if(!r.surface_remeshed && !q.boundary_equals_input())
      std::printf(" (%zu / %zu)", q.missing_input_triangles, q.extra_boundary_facets);
    std::printf("\n");
  }
}

// ------------------------------------------------------------------------------------------------ figure

std::string json_string(const std::string& text)
{
  std::string quoted = "\"";
  for(const char c : text) {
    if(c == '"' || c == '\\') quoted += '\\';
    quoted += static_cast<unsigned char>(c) < 0x20 ? ' ' : c;
  }
  return quoted + "\"";
}

template <class T>
std::string json_list(const std::vector<T>& values)
{
  std::ostringstream text;
  text << "[";
  for(std::size_t i = 0; i < values.size(); ++i) text << (i ? ", " : "") << values[i];
  text << "]";
  return text.str();
}

// What plot_mesh_quality.py reads: the header's date and machine, and every row of the table with its histograms.
void write_json(const std::string& path, const std::string& date, int rounds, const std::vector<Row>& rows)
{
  std::vector<double> radius_edge_bins;
  for(const Row& r : rows)
    if(r.failure.empty() && !r.quality.radius_edge_bin_lower.empty())
      radius_edge_bins = r.quality.radius_edge_bin_lower;
  std::ofstream out(path);
  if(!out) throw std::runtime_error("cannot write " + path);
  out << "{\n  \"benchmark\": \"mesher_benchmark\",\n  \"date\": " << json_string(date)
      << ",\n  \"machine\": " << json_string(machine()) << ",\n  \"rounds\": " << rounds
      << ",\n  \"radius_edge_bin_lower\": " << json_list(radius_edge_bins)
      << ",\n  \"min_dihedral_bin_degrees\": " << CGAL::Fast_mesher_3::Quality_report().min_dihedral_bin_degrees
      << ",\n  \"rows\": [";
  for(std::size_t i = 0; i < rows.size(); ++i) {
    const Row& r = rows[i];
    out << (i ? "," : "") << "\n    {\"surface\": " << json_string(r.surface->name)
        << ", \"tool\": " << json_string(r.tool->name) << ", \"threads\": " << r.tool->threads;
    if(!r.failure.empty()) {
      out << ", \"failure\": " << json_string(r.failure) << "}";
      continue;
    }
    const CGAL::Fast_mesher_3::Quality_report& q = r.quality;
    out << ",\n     \"recovery_seconds\": " << median(r.recovery) << ", \"refinement_seconds\": "
        << median(r.refinement) << ", \"total_seconds\": " << median(r.total) << ", \"tetrahedra\": "
        << r.tetrahedra << ",\n     \"min_dihedral_degrees\": " << q.min_dihedral_degrees
        << ", \"max_dihedral_degrees\": " << q.max_dihedral_degrees << ", \"max_radius_edge\": "
        << q.max_radius_edge << ", \"inverted_tetrahedra\": " << q.inverted_tetrahedra
        << ", \"boundary_equals_input\": " << (q.boundary_equals_input() ? "true" : "false")
        << ",\n     \"radius_edge_histogram\": " << json_list(q.radius_edge_histogram)
        << ",\n     \"min_dihedral_histogram\": " << json_list(q.min_dihedral_histogram)
        << ",\n     \"gamma_histogram\": " << json_list(q.gamma_histogram) << ", \"min_gamma\": " << q.min_gamma
        << ", \"tetrahedra_below_gamma_0_3\": " << q.tetrahedra_below_gamma_0_3
        << ", \"tetrahedra_forced_below_gamma_0_3\": " << q.tetrahedra_forced_below_gamma_0_3
        << ", \"improvement_seconds\": " << median(r.improvement) << "}";
  }
  out << "\n  ]\n}\n";
  if(!out) throw std::runtime_error("cannot write " + path);
}

std::string shell_quoted(const std::string& word)
{
  std::string quoted = "'";
  for(const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
  return quoted + "'";
}

// The interpreter and script that draw --plot's figure, both set by CMake (FDT3_PYTHON: Debian's /usr/bin/python3,
// where python3-matplotlib installs matplotlib).
std::string plot_command(const std::string& json, const std::string& figure)
{
  return shell_quoted(FDT3_PYTHON) + " " + shell_quoted(FDT3_SCRIPTS_DIR "/plot_mesh_quality.py") + " " +
         shell_quoted(json) + " " + shell_quoted(figure);
}

// Before the tools run, so that minutes of meshing are not lost for want of matplotlib.
void check_plotting()
{
  const std::string command = shell_quoted(FDT3_PYTHON) + " -c 'import matplotlib' 2>/dev/null";
  if(std::system(command.c_str()) != 0)
    throw std::runtime_error(std::string("--plot needs matplotlib for ") + FDT3_PYTHON +
                             " (Debian: apt-get install python3-matplotlib)");
  if(::access(FDT3_SCRIPTS_DIR "/plot_mesh_quality.py", R_OK) != 0)
    throw std::runtime_error("--plot needs " FDT3_SCRIPTS_DIR "/plot_mesh_quality.py, which is not there");
}

// ------------------------------------------------------------------------------------------------ options

struct Options
{
  int rounds = 3;
  std::string data_directory = FDT3_CGAL_DATA_DIR;
  // bunny00 (1.3 million tetrahedra) takes about 5 minutes a round on 2 cores: asked for by name only.
  std::vector<std::string> surfaces{"elephant", "fandisk", "anchor_dense"};
  int fibres = 30;
  double fibre_size = 0.04;
  double maximum_size = std::numeric_limits<double>::infinity();
  std::string json_path; // empty: no data file
  std::string plot_path; // empty: no figure
  std::vector<std::string> tools; // empty: every tool
};

std::vector<std::string> split(const std::string& list)
{
  std::vector<std::string> items;
  std::stringstream stream(list);
  for(std::string item; std::getline(stream, item, ',');)
    if(!item.empty()) items.push_back(item);
  return items;
}

void print_usage(std::FILE* to)
{
  std::fprintf(to,
               "usage: mesher_benchmark [--rounds N] [--surfaces A,B,...] [--data DIR] [--fibres N]\n"
               "                        [--fibre-size H] [--max-size H] [--tools A,B,...] [--json FILE]\n"
               "                        [--plot FIGURE]\n"
               "  --surfaces  names of CGAL data surfaces (NAME.off in --data) or paths; default\n"
               "              elephant,fandisk,anchor_dense (also extracted: bunny00, couplingdown,\n"
               "              refined_elephant, joint); 'none' for the fibres alone\n"
               "  --data      where CGAL's data meshes are (default: extracted from libcgal-demo by CMake)\n"
               "  --fibres    fibres in the cube (default 30; 0: no fibre surface), --fibre-size its surface size\n"
               "  --max-size  cap on h for the CGAL surfaces (default: none, h from the surface alone)\n"
               "  --tools     the rows to run, by tool name (ours, ours-noopt, ours-remeshed, gmsh-hxt,\n"
               "              gmsh-hxt+netgen, gmsh-hxt-noopt, tetgen-pq1.4, tetgen-pq1.4-O0, tetgen-pYq1.4,\n"
               "              cgal-mesh-3); default: all\n"
               "  --json      write every row and its quality histograms (radius-edge ratio, smallest dihedral\n"
               "              angle per tetrahedron) to FILE\n"
               "  --plot      draw those histograms of every tool, one row of panels per surface, to FIGURE (.png,\n"
               "              .svg or .pdf) with scripts/plot_mesh_quality.py; the data go to FIGURE's name with\n"
               "              .json unless --json names a file\n");
}

Options parse(int argc, char** argv)
{
  Options o;
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) throw std::invalid_argument(a + " needs a value");
      return argv[++i];
    };
    if(a == "--rounds") o.rounds = std::max(1, std::stoi(value()));
    else if(a == "--surfaces") {
      const std::string list = value();
      o.surfaces = list == "none" ? std::vector<std::string>() : split(list);
    } else if(a == "--data") o.data_directory = value();
    else if(a == "--fibres") o.fibres = std::stoi(value());
    else if(a == "--fibre-size") o.fibre_size = std::stod(value());
    else if(a == "--max-size") o.maximum_size = std::stod(value());
    else if(a == "--tools") o.tools = split(value());
    else if(a == "--json") o.json_path = value();
    else if(a == "--plot") {
      o.plot_path = value();
      const std::string extension = std::filesystem::path(o.plot_path).extension().string();
      if(extension != ".png" && extension != ".svg" && extension != ".pdf")
        throw std::invalid_argument("--plot " + o.plot_path + ": the figure must end in .png, .svg or .pdf");
    }
    else if(a == "--help" || a == "-h") {
      print_usage(stdout);
      std::exit(0);
    } else
      throw std::invalid_argument("unknown option " + a);
  }
  if(!o.plot_path.empty() && o.json_path.empty())
    o.json_path = std::filesystem::path(o.plot_path).replace_extension(".json").string();
  return o;
}

std::vector<Benchmark_surface> load_surfaces(const Options& o)
{
  std::vector<Benchmark_surface> surfaces;
  for(const std::string& name : o.surfaces) {
    const std::string path = name.find('/') != std::string::npos || name.find('.') != std::string::npos
                                 ? name
                                 : o.data_directory + "/" + name + ".off";
    if(!std::ifstream(path)) {
      std::printf("note: %s not found (install libcgal-demo and re-run CMake, or give --data): skipped\n",
                  path.c_str());
      continue;
    }
    surfaces.push_back(read_cgal_surface(path));
    surfaces.back().maximum_size = o.maximum_size;
  }
  if(o.fibres > 0 && gmsh_helper().empty())
    std::printf("note: no Gmsh helper (libgmsh-dev absent at build time): no fibre cube\n");
  else if(o.fibres > 0)
    surfaces.push_back(fibre_cube(o.fibres, o.fibre_size, 1));
  return surfaces;
}

std::vector<Tool> tools()
{
  std::vector<Tool> t;
  t.push_back({"ours", 1, [](const Benchmark_surface& s) { return run_ours(s, 1, true); }});
  t.push_back({"ours", 2, [](const Benchmark_surface& s) { return run_ours(s, 2, true); }});
  t.push_back({"ours-noopt", 2, [](const Benchmark_surface& s) { return run_ours(s, 2, false); }});
  t.push_back({"ours-remeshed", 2, [](const Benchmark_surface& s) { return run_ours_remeshed(s, 2); }});
  // HXT on 1 thread too, beside ours on 1 thread.
  if(!gmsh_helper().empty()) {
    t.push_back({"gmsh-hxt", 1, [](const Benchmark_surface& s) { return run_hxt(s, 1, "gmsh"); }});
    t.push_back({"gmsh-hxt", 2, [](const Benchmark_surface& s) { return run_hxt(s, 2, "gmsh"); }});
    t.push_back({"gmsh-hxt+netgen", 2, [](const Benchmark_surface& s) { return run_hxt(s, 2, "netgen"); }});
    t.push_back({"gmsh-hxt-noopt", 2, [](const Benchmark_surface& s) { return run_hxt(s, 2, "none"); }});
  }
  t.push_back({"tetgen-pq1.4", 1, [](const Benchmark_surface& s) { return run_tetgen(s, "pq1.4", ""); }});
  t.push_back({"tetgen-pq1.4-O0", 1, [](const Benchmark_surface& s) { return run_tetgen(s, "pq1.4", "O0"); }});
  t.push_back({"tetgen-pYq1.4", 1, [](const Benchmark_surface& s) { return run_tetgen(s, "pYq1.4", ""); }});
  t.push_back({"cgal-mesh-3", 1, [](const Benchmark_surface& s) { return run_cgal(s); }});
  return t;
}

} // namespace

int main(int argc, char** argv)
{
  try {
    const Options options = parse(argc, argv);
    if(!options.plot_path.empty()) check_plotting();
    const std::string date = utc_now();
    print_header(date, options.rounds);
    const std::vector<Benchmark_surface> surfaces = load_surfaces(options);
    print_surfaces(surfaces);
    std::vector<Tool> all_tools = tools();
    for(const std::string& name : options.tools)
      if(std::none_of(all_tools.begin(), all_tools.end(), [&](const Tool& t) { return t.name == name; }))
        throw std::invalid_argument("--tools: no tool named " + name + " (without Gmsh there are no gmsh-hxt rows)");
    if(!options.tools.empty())
      all_tools.erase(std::remove_if(all_tools.begin(), all_tools.end(),
                                     [&](const Tool& t) {
                                       return std::find(options.tools.begin(), options.tools.end(), t.name) ==
                                              options.tools.end();
                                     }),
                      all_tools.end());
    std::vector<Row> rows;
    for(const Benchmark_surface& s : surfaces)
      for(const Tool& t : all_tools) rows.push_back(Row{&s, &t, {}, {}, {}, {}, 0, {}, false, ""});

    for(int round = 0; round < options.rounds; ++round)
      for(Row& row : rows) {
        if(!row.failure.empty()) continue;
        try {
          Run run = row.tool->run(*row.surface);
          row.recovery.push_back(run.recovery);
          row.refinement.push_back(run.refinement);
          row.improvement.push_back(run.improvement);
          row.total.push_back(run.total);
          row.surface_remeshed = run.surface_remeshed;
          row.tetrahedra = run.mesh.tetrahedra.size();
          // The report is slow (std::map of facets): once, on the last round's mesh.
          if(round + 1 == options.rounds) row.quality = quality_of(std::move(run.mesh));
        } catch(const std::exception& e) {
          row.failure = e.what();
        } catch(...) {
          row.failure = "the tool threw something that is not a std::exception";
        }
        std::fprintf(stderr, "round %d: %s %s %d threads done\n", round + 1, row.surface->name.c_str(),
                     row.tool->name.c_str(), row.tool->threads);
      }
    print_table(rows);
    const double load_at_end = load_average();
    std::printf("load average %.2f at the end%s\n", load_at_end,
                usable_cores() > 0 && load_at_end > usable_cores()
                    ? " (above the usable cores: other work competed with the tools)"
                    : "");
    std::filesystem::remove_all(scratch_directory());
    if(!options.json_path.empty()) write_json(options.json_path, date, options.rounds, rows);
    if(!options.plot_path.empty()) {
      std::fflush(stdout);
      const std::string command = plot_command(options.json_path, options.plot_path);
      const int status = std::system(command.c_str());
      if(status != 0) {
        std::fprintf(stderr, "mesher_benchmark: the figure was not drawn: %s failed (status %d); the data are in %s\n",
                     command.c_str(), status, options.json_path.c_str());
        return 1;
      }
    }
  } catch(const std::exception& e) {
    std::fprintf(stderr, "mesher_benchmark: %s\n", e.what());
    print_usage(stderr);
    return 1;
  }
  return 0;
}
