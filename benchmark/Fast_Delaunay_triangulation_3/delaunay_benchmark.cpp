// The side-by-side benchmark of issue 2 (and the parallel columns of issue 3): Fast_Delaunay_triangulation_3 beside
// CGAL::Delaunay_triangulation_3 on the same points, printing seconds, tetrahedra, Mtets/s, peak memory and the
// speed-up over CGAL's sequential triangulation, plus our per-phase breakdown in the shape of the paper's Table 1.
//
// Every engine run is a forked child process, so that the peak RSS it reports belongs to that engine alone. The
// points are generated once per (n, distribution) in the parent before forking; each child therefore also holds
// them, equally for every engine, and each table states that baseline. Engines are interleaved round by round
// (round r: fast, cgal, cgal-par, ...) so that a drift of the machine hits them alike; the table shows medians.
//
// Rows fast-remove / cgal-remove and fast-move / cgal-move (not run by default) time the removal of 10% of the
// vertices one by one, and the move of 10% by a small random displacement, after an untimed insertion of all points;
// fast-par-remove / cgal-par-remove the removal of the same 10% as one range, remove(first, last), on --threads;
// rows fast-epec / cgal-epec (not run by default) time the insertion of the same points as points of CGAL's exact
// constructions kernel; rows fast-loop / cgal-loop and fast-hint / cgal-hint (not run by default) time insert(p)
// called once per point, without and with the previous vertex as hint; rows fast-apex / cgal-apex time insert(p) of
// one point above the bounding box after an untimed insertion of the points (with --dist plane, points in the plane
// z = x: the lift from dimension 2 to 3); each is compared with its CGAL counterpart. Built with TetGen, the row
// tetgen (run by default) is TetGen's Delaunay tetrahedralization of the same points, for comparison: its failures
// and other cell counts are notes. Built with Gmsh, the row hxt (run by default, on every --threads value) is the
// paper's own kernel, Gmsh's hxtDelaunay, run by the helper delaunay_benchmark_hxt; a comparison too.
//
// Usage: delaunay_benchmark [--n 1e6[,1e7...]] [--dist uniform[,shell,torus,surface...]|all] [--surface FILE]
//                           [--engines fast,cgal,cgal-par,fast-par,fast-remove,cgal-remove,fast-par-remove,
//                                      cgal-par-remove,fast-move,cgal-move,
//                                      fast-epec,cgal-epec,fast-loop,cgal-loop,fast-hint,cgal-hint,
//                                      fast-apex,cgal-apex,tetgen,hxt]
//                           [--rounds 3] [--threads 1,2] [--phases] [--verbose] [--scalar-paths] [--csv FILE|-]
//
// Besides the volume distributions of the tests, shell, torus and surface are what scans give: points near a closed
// surface (the unit sphere, the torus R = 1, r = 0.3, both with noise 1e-3 along the normal), and points sampled by
// area on a scanned model of CGAL's data (bunny00.off, or --surface FILE) with noise 1e-3 of its bounding box's
// diagonal. Their tetrahedra are long and thin, which is where a parallel insertion by space partitions suffers.
//
// --csv FILE writes one row per engine, thread count, n and distribution (the medians) beside the table, with the
// machine in '#' lines above them: scripts/plot_benchmark.py draws it (scripts/benchmark.sh --plot does both).

#include <CGAL/Fast_Delaunay_triangulation_3.h>

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/version.h>
#ifdef CGAL_LINKED_WITH_TBB
#include <CGAL/Delaunay_triangulation_cell_base_3.h>
#include <CGAL/Spatial_lock_grid_3.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_3.h>
#include <tbb/global_control.h>
#include <tbb/version.h>
#endif
#ifdef FDT3_WITH_TETGEN
#include <tetgen.h>
#endif

#include "../../test/Fast_Delaunay_triangulation_3/point_sets.h"

#include <malloc.h>
#include <poll.h>
#include <sched.h>
#include <signal.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <random>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>
#include <thread>
#include <type_traits>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel Kernel;
typedef Kernel::Point_3 Point;
typedef std::vector<Point> Points;
typedef CGAL::Fast_Delaunay_triangulation_3<Kernel> Fast_dt;
typedef CGAL::Delaunay_triangulation_3<Kernel> Cgal_dt;
typedef Fast_dt::Insertion_report Insertion_report;
typedef std::chrono::steady_clock Clock;

// ------------------------------------------------------------------------------------------------ engines

// Our Table 1 breakdown, copied field by field out of Insertion_report so that it stays plain bytes.
struct Phase_report
{
  double sort_seconds = 0, init_seconds = 0, walk_seconds = 0, cavity_seconds = 0, ball_seconds = 0;
  std::uint64_t inserted = 0, duplicates = 0, walk_steps = 0, cavity_tets = 0, ball_tets = 0, conflict_tests = 0;
  std::uint64_t small_cavities = 0, large_cavities = 0;
};

Phase_report phase_report_of(const Insertion_report& r)
{
  Phase_report p;
  p.sort_seconds = r.sort_seconds;
  p.init_seconds = r.init_seconds;
  p.walk_seconds = r.kernel.walk_seconds;
  p.cavity_seconds = r.kernel.cavity_seconds;
  p.ball_seconds = r.kernel.ball_seconds;
  p.inserted = r.kernel.inserted;
  p.duplicates = r.kernel.duplicates;
  p.walk_steps = r.kernel.walk_steps;
  p.cavity_tets = r.kernel.cavity_tets;
  p.ball_tets = r.kernel.ball_tets;
  p.conflict_tests = r.kernel.conflict_tests;
  p.small_cavities = r.kernel.small_cavities;
  p.large_cavities = r.kernel.large_cavities;
  return p;
}

// The paper's Table 2: one row per attempt of the partitioned insertion.
struct Attempt_report
{
  std::uint64_t points = 0, inserted = 0, mesh_vertices = 0;
  int partitions = 0;
  bool plane_cut = false;
  double seconds = 0;
};
constexpr int max_attempt_rows = 48;

// With the attempts: the report's seconds outside them.
struct Outside_attempts
{
  double sort = 0, init = 0, finish = 0;
};

// What one run of an engine sends back. Trivially copyable: it crosses the pipe from the child as bytes.
struct Engine_result
{
  double seconds = 0;                // insertion of all points into an empty triangulation
  std::uint64_t finite_cells = 0;
  bool has_phases = false;
  Phase_report phases;               // when has_phases
  int attempt_rows = 0;              // rows of `attempts` filled (--verbose runs of fast-par)
  int attempts_left_out = 0;         // rows beyond max_attempt_rows
  Attempt_report attempts[max_attempt_rows];
  Outside_attempts outside_attempts; // with attempts
  long peak_kib = 0;                 // an engine run in a process of its own (hxt): that process's peak RSS
};
static_assert(std::is_trivially_copyable<Engine_result>::value, "Engine_result is sent through a pipe");

double seconds_since(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

// Times `operation` alone; counting the cells and destroying the triangulation stay outside the clock.
template <class Triangulation, class Operation>
Engine_result time_and_count(Triangulation& triangulation, Operation&& operation)
{
  Engine_result result;
  const Clock::time_point start = Clock::now();
  operation();
  result.seconds = seconds_since(start);
  result.finite_cells = triangulation.number_of_finite_cells();
  return result;
}

template <class Triangulation, class Point_range>
Engine_result insert_and_count(Triangulation& triangulation, const Point_range& points)
{
  return time_and_count(triangulation, [&] { triangulation.insert(points.begin(), points.end()); });
}

Engine_result run_fast(const Points& points, int /*threads*/)
{
  Fast_dt triangulation;
  return insert_and_count(triangulation, points);
}

// The same as run_fast with the per-phase clocks on; a separate run, because the clock reads cost time.
Engine_result run_fast_with_phases(const Points& points, int /*threads*/)
{
  Fast_dt triangulation;
  triangulation.set_phase_timing(true);
  Engine_result result = insert_and_count(triangulation, points);
  result.has_phases = true;
  result.phases = phase_report_of(triangulation.last_insertion_report());
  return result;
}

Engine_result run_cgal(const Points& points, int /*threads*/)
{
  Cgal_dt triangulation;
  return insert_and_count(triangulation, points);
}

// Every tenth input point: the vertices that the removal and move rows change, in input order (random in space),
// the same points in the same order for both triangulations; a point given twice counts once.  Not timed.
template <class Triangulation>
std::vector<typename Triangulation::Vertex_handle> every_tenth_vertex(const Triangulation& triangulation,
                                                                      const Points& points)
{
  std::vector<typename Triangulation::Vertex_handle> vertices;
  std::set<Point> seen;
  for(std::size_t i = 0; i < points.size(); i += 10) {
    typename Triangulation::Vertex_handle v;
    if(seen.insert(points[i]).second && triangulation.is_vertex(points[i], v)) vertices.push_back(v);
  }
  return vertices;
}

// Times the removal of every tenth vertex, one by one.
template <class Triangulation>
Engine_result remove_tenth(const Points& points)
{
  Triangulation triangulation(points.begin(), points.end());
  const auto vertices = every_tenth_vertex(triangulation, points);
  return time_and_count(triangulation, [&] {
    for(const auto& v : vertices) triangulation.remove(v);
  });
}

// Times the move of every tenth vertex by a random displacement of at most a tenth of the mean spacing per axis
// (from the bounding box and the number of points).
template <class Triangulation>
Engine_result move_tenth(const Points& points)
{
  Triangulation triangulation(points.begin(), points.end());
  const auto vertices = every_tenth_vertex(triangulation, points);
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  const double spacing = std::cbrt((box.xmax() - box.xmin()) * (box.ymax() - box.ymin()) * (box.zmax() - box.zmin()) /
                                   static_cast<double>(std::max<std::size_t>(points.size(), 1)));
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> d(-0.1 * spacing, 0.1 * spacing);
  std::vector<Point> targets;
  for(const auto& v : vertices) {
    const Point p = v->point();
    targets.emplace_back(p.x() + d(rng), p.y() + d(rng), p.z() + d(rng));
  }
  return time_and_count(triangulation, [&] {
    for(std::size_t k = 0; k < vertices.size(); ++k) triangulation.move(vertices[k], targets[k]);
  });
}

// Times insert(p) called once per point in input order (random in space), as code that receives points one at a
// time does; with_hint: the `v = insert(p, v)` idiom, each walk starting at the previous vertex.
template <class Triangulation>
Engine_result insert_one_by_one(const Points& points, bool with_hint)
{
  Triangulation triangulation;
  return time_and_count(triangulation, [&] {
    typename Triangulation::Vertex_handle v;
    if(with_hint)
      for(const Point& p : points) v = triangulation.insert(p, v);
    else
      for(const Point& p : points) triangulation.insert(p);
  });
}

Engine_result run_fast_loop(const Points& points, int /*threads*/) { return insert_one_by_one<Fast_dt>(points, false); }
Engine_result run_cgal_loop(const Points& points, int /*threads*/) { return insert_one_by_one<Cgal_dt>(points, false); }
Engine_result run_fast_hint(const Points& points, int /*threads*/) { return insert_one_by_one<Fast_dt>(points, true); }
Engine_result run_cgal_hint(const Points& points, int /*threads*/) { return insert_one_by_one<Cgal_dt>(points, true); }

// Times insert(p) of one point above the points' bounding box, after an untimed insertion of the points: on
// --dist plane the point off the plane that lifts the triangulation from dimension 2 to 3.
template <class Triangulation>
Engine_result insert_apex(const Points& points)
{
  Triangulation triangulation(points.begin(), points.end());
  const CGAL::Bbox_3 box = CGAL::bbox_3(points.begin(), points.end());
  const Point apex(0.5 * (box.xmin() + box.xmax()), 0.5 * (box.ymin() + box.ymax()),
                   box.zmax() + (box.zmax() - box.zmin()) + 1);
  return time_and_count(triangulation, [&] { triangulation.insert(apex); });
}

Engine_result run_fast_apex(const Points& points, int /*threads*/) { return insert_apex<Fast_dt>(points); }
Engine_result run_cgal_apex(const Points& points, int /*threads*/) { return insert_apex<Cgal_dt>(points); }

Engine_result run_fast_remove(const Points& points, int /*threads*/) { return remove_tenth<Fast_dt>(points); }
Engine_result run_cgal_remove(const Points& points, int /*threads*/) { return remove_tenth<Cgal_dt>(points); }
Engine_result run_fast_move(const Points& points, int /*threads*/) { return move_tenth<Fast_dt>(points); }
Engine_result run_cgal_move(const Points& points, int /*threads*/) { return move_tenth<Cgal_dt>(points); }

// The same points in CGAL's exact-constructions kernel, made in the child before the clock starts (both EPEC
// engines hold them alike): ours keeps the user's points beside its doubles and runs the double engine, CGAL's
// triangulation runs on the lazy points throughout.
typedef CGAL::Exact_predicates_exact_constructions_kernel Exact_kernel;
std::vector<Exact_kernel::Point_3> exact_points(const Points& points)
{
  std::vector<Exact_kernel::Point_3> exact;
  exact.reserve(points.size());
  for(const Point& p : points) exact.emplace_back(p.x(), p.y(), p.z());
  return exact;
}

template <class Triangulation>
Engine_result insert_exact_points_and_count(const Points& points)
{
  const std::vector<Exact_kernel::Point_3> exact = exact_points(points);
  Triangulation triangulation;
  return insert_and_count(triangulation, exact);
}

Engine_result run_fast_epec(const Points& points, int /*threads*/)
{
  return insert_exact_points_and_count<CGAL::Fast_Delaunay_triangulation_3<Exact_kernel>>(points);
}

Engine_result run_cgal_epec(const Points& points, int /*threads*/)
{
  return insert_exact_points_and_count<CGAL::Delaunay_triangulation_3<Exact_kernel>>(points);
}

#ifdef FDT3_WITH_TETGEN
// TetGen's Delaunay tetrahedralization of the points (switch Q alone: no PLC, no refinement, quiet). The points
// are copied into TetGen's input array before the clock starts, as EPEC's are made; the clock covers
// tetrahedralize(), which sorts (BRIO and Hilbert curve), inserts and writes its output arrays. TetGen reports
// its errors by throwing an int (its library mode).
Engine_result run_tetgen(const Points& points, int /*threads*/)
{
  // TetGen counts points and their coordinates in int.
  if(points.size() > static_cast<std::size_t>(std::numeric_limits<int>::max() / 3))
    throw std::length_error("TetGen takes at most " + std::to_string(std::numeric_limits<int>::max() / 3) +
                            " points");
  tetgenio in, out;
  in.firstnumber = 0;
  in.numberofpoints = static_cast<int>(points.size());
  in.pointlist = new REAL[3 * points.size()]; // tetgenio frees it
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int a = 0; a < 3; ++a) in.pointlist[3 * i + a] = points[i][a];
  tetgenbehavior switches;
  char quiet_delaunay[] = "Q";
  if(!switches.parse_commandline(quiet_delaunay)) throw std::runtime_error("TetGen refused the switches");
  Engine_result result;
  const Clock::time_point start = Clock::now();
  try {
    tetrahedralize(&switches, &in, &out);
  } catch(int code) {
    throw std::runtime_error("TetGen stopped with error code " + std::to_string(code));
  }
  result.seconds = seconds_since(start);
  result.finite_cells = static_cast<std::uint64_t>(out.numberoftetrahedra);
  return result;
}
#endif

#ifdef CGAL_LINKED_WITH_TBB
typedef CGAL::Triangulation_data_structure_3<CGAL::Triangulation_vertex_base_3<Kernel>,
                                             CGAL::Delaunay_triangulation_cell_base_3<Kernel>, CGAL::Parallel_tag>
    Parallel_tds;
typedef CGAL::Delaunay_triangulation_3<Kernel, Parallel_tds> Cgal_parallel_dt;
typedef CGAL::Fast_Delaunay_triangulation_3<Kernel, Parallel_tds> Fast_parallel_dt;

// CGAL's parallel idiom as its users write it: a lock grid over the bounding box (50 cells per side, as in CGAL's
// examples) and the thread count limited by tbb::global_control. Building the lock grid counts as insertion time.
Engine_result run_cgal_parallel(const Points& points, int threads)
{
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  const Clock::time_point start = Clock::now();
  Cgal_parallel_dt::Lock_data_structure locks(CGAL::bbox_3(points.begin(), points.end()), 50);
  const double lock_seconds = seconds_since(start);
  Cgal_parallel_dt triangulation(&locks);
  Engine_result result = insert_and_count(triangulation, points);
  result.seconds += lock_seconds;
  return result;
}

// The same idiom with only the class name changed; ours needs no lock grid (it partitions space instead).
Engine_result run_fast_parallel(const Points& points, int threads)
{
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Fast_parallel_dt triangulation;
  return insert_and_count(triangulation, points);
}

// The same with the barrier-synchronised engine (the two-level kernel of "Multi-threaded mesh generation") instead
// of the partitions.
Engine_result run_fast_barrier(const Points& points, int threads)
{
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Fast_parallel_dt triangulation;
  triangulation.set_parallel_engine(Fast_parallel_dt::Parallel_engine::barrier);
  return insert_and_count(triangulation, points);
}

// Every tenth vertex removed as one range, remove(first, last), on `threads` threads: CGAL's parallel removal
// (its lock grid, built before the clock starts, as the insertion is) and ours (slabs of space).
template <class Triangulation>
Engine_result remove_tenth_as_range(Triangulation& triangulation, const Points& points)
{
  const auto vertices = every_tenth_vertex(triangulation, points);
  return time_and_count(triangulation, [&] { triangulation.remove(vertices.begin(), vertices.end()); });
}
Engine_result run_cgal_parallel_remove(const Points& points, int threads)
{
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Cgal_parallel_dt::Lock_data_structure locks(CGAL::bbox_3(points.begin(), points.end()), 50);
  Cgal_parallel_dt triangulation(points.begin(), points.end(), &locks);
  return remove_tenth_as_range(triangulation, points);
}
Engine_result run_fast_parallel_remove(const Points& points, int threads)
{
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Fast_parallel_dt triangulation(points.begin(), points.end());
  return remove_tenth_as_range(triangulation, points);
}

// --verbose: one more run with exactly `threads` partitions (even beyond the cores, as the paper's Table 2 at
// 8 threads), reporting every attempt of the partitioned insertion.
Engine_result run_fast_parallel_with_attempts(const Points& points, int threads)
{
  tbb::global_control limit(tbb::global_control::max_allowed_parallelism, static_cast<std::size_t>(threads));
  Fast_parallel_dt triangulation;
  triangulation.set_number_of_threads(threads);
  Engine_result result = insert_and_count(triangulation, points);
  const Insertion_report& report = triangulation.last_insertion_report();
  result.outside_attempts = {report.sort_seconds, report.init_seconds, report.finish_seconds};
  for(const auto& round : report.rounds) {
    if(result.attempt_rows == max_attempt_rows) {
      ++result.attempts_left_out;
      continue;
    }
    Attempt_report& a = result.attempts[result.attempt_rows++];
    a.points = round.points;
    a.inserted = round.inserted;
    a.mesh_vertices = round.mesh_vertices;
    a.partitions = round.partitions;
    a.plane_cut = round.plane_cut;
    a.seconds = round.seconds;
  }
  return result;
}
#endif

// ------------------------------------------------------------------------------------------------ HXT

// delaunay_benchmark_hxt beside this program (built where Debian's libgmsh-dev 4.8 is installed); empty without it.
std::string hxt_helper()
{
  char self[4096];
  const ssize_t length = ::readlink("/proc/self/exe", self, sizeof self - 1);
  if(length <= 0) return "";
  std::string helper(self, static_cast<std::size_t>(length));
  helper = helper.substr(0, helper.rfind('/') + 1) + "delaunay_benchmark_hxt";
  return ::access(helper.c_str(), X_OK) == 0 ? helper : "";
}

// Gmsh's HXT, the paper's own kernel (hxtDelaunay), on `threads` OpenMP threads, in the helper process: the points
// go through a scratch file (not timed); the helper times its own call and reports its peak RSS.
bool write_all(int fd, const void* data, std::size_t size);
Engine_result run_hxt(const Points& points, int threads)
{
  const std::string helper = hxt_helper();
  if(helper.empty()) throw std::runtime_error("delaunay_benchmark_hxt was not built (it needs libgmsh-dev 4.8)");
  std::string path = (std::filesystem::temp_directory_path() / "delaunay_benchmark_hxt_XXXXXX").string();
  const int file = ::mkstemp(path.data());
  if(file < 0) throw std::system_error(errno, std::generic_category(), "mkstemp");
  struct Remove_on_exit
  {
    const std::string& path;
    ~Remove_on_exit() { ::unlink(path.c_str()); }
  } remove_on_exit{path};
  std::vector<double> xyz;
  xyz.reserve(3 * points.size());
  for(const Point& p : points) xyz.insert(xyz.end(), {p.x(), p.y(), p.z()});
  const std::uint64_t n = points.size();
  const bool written = write_all(file, &n, sizeof n) && write_all(file, xyz.data(), xyz.size() * sizeof(double));
  ::close(file);
  if(!written) throw std::runtime_error("cannot write the points to " + path);
  xyz = std::vector<double>();

  int out[2];
  if(::pipe(out) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  std::string thread_count = std::to_string(threads);
  char* argv[] = {const_cast<char*>(helper.c_str()), path.data(), thread_count.data(), nullptr};
  const pid_t pid = ::fork();
  if(pid < 0) throw std::system_error(errno, std::generic_category(), "fork");
  if(pid == 0) {
    ::dup2(out[1], STDOUT_FILENO);
    ::close(out[0]);
    ::close(out[1]);
    // libgomp's idle threads spin by default, which costs HXT's threads on a busy machine (mesher_benchmark.cpp
    // measured it); a policy given by the caller is kept.
    ::setenv("OMP_WAIT_POLICY", "PASSIVE", 0);
    ::execv(argv[0], argv);
    _exit(127);
  }
  ::close(out[1]);
  // HXT loops forever on some inputs (points in a plane): the helper is stopped after 20 s plus 20 us a point,
  // some twenty times what it takes on 1e6 uniform points.
  const double limit = 20 + 2e-5 * double(points.size());
  const Clock::time_point start = Clock::now();
  std::string line;
  bool stopped = false;
  for(;;) {
    pollfd readable{out[0], POLLIN, 0};
    const double left = limit - seconds_since(start);
    if(left <= 0) {
      ::kill(pid, SIGKILL);
      stopped = true;
      break;
    }
    const int ready = ::poll(&readable, 1, static_cast<int>(std::ceil(1000 * std::min(left, 1.0))));
    if(ready < 0 && errno == EINTR) continue;
    if(ready <= 0) continue;
    char buffer[256];
    const ssize_t got = ::read(out[0], buffer, sizeof buffer);
    if(got < 0 && errno == EINTR) continue;
    if(got <= 0) break;
    line.append(buffer, static_cast<std::size_t>(got));
  }
  ::close(out[0]);
  int status = 0;
  while(::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  Engine_result result;
  unsigned long long finite = 0;
  if(stopped) throw std::runtime_error("delaunay_benchmark_hxt stopped after " + std::to_string(int(limit)) + " s");
  if(WIFSIGNALED(status))
    throw std::runtime_error(std::string("delaunay_benchmark_hxt killed by signal ") + strsignal(WTERMSIG(status)) +
                             " (HXT's message, if any, is above)");
  if(!WIFEXITED(status) || WEXITSTATUS(status) != 0 ||
     std::sscanf(line.c_str(), "%lf %llu %ld", &result.seconds, &finite, &result.peak_kib) != 3)
    throw std::runtime_error("delaunay_benchmark_hxt failed (its message is above)");
  result.finite_cells = finite;
  return result;
}

struct Engine
{
  const char* name;
  bool parallel;   // runs once per --threads value; a sequential engine runs once, on 1 thread
  bool by_default; // runs when --engines is not given
  Engine_result (*run)(const Points& points, int threads);
  // The row this one's speed-up and cell count are compared with.
  const char* reference = "cgal";
  // Run for comparison only: its failures and a cell count other than the reference's are notes, not warnings, and
  // leave the exit status alone. TetGen stops on an assertion where the points are coplanar or span 10^400, and
  // breaks ties between cospherical points (the sphere, the grid) its own way: another triangulation of the same
  // points can have another number of cells.
  bool comparison_only = false;
};

// The engines, in the order of the table; a new engine is one more row and one run function.
// `cgal` is the reference of the speed-up and of the cell counts.
const std::vector<Engine>& engine_table()
{
  static const std::vector<Engine> engines = {
      {"fast", false, true, run_fast},
      {"cgal", false, true, run_cgal},
#ifdef CGAL_LINKED_WITH_TBB
      {"cgal-par", true, true, run_cgal_parallel},
      {"fast-par", true, true, run_fast_parallel},
      {"fast-barrier", true, false, run_fast_barrier},
#endif
      {"fast-loop", false, false, run_fast_loop, "cgal-loop"},
      {"cgal-loop", false, false, run_cgal_loop, "cgal-loop"},
      {"fast-hint", false, false, run_fast_hint, "cgal-hint"},
      {"cgal-hint", false, false, run_cgal_hint, "cgal-hint"},
      {"fast-apex", false, false, run_fast_apex, "cgal-apex"},
      {"cgal-apex", false, false, run_cgal_apex, "cgal-apex"},
      {"fast-remove", false, false, run_fast_remove, "cgal-remove"},
      {"cgal-remove", false, false, run_cgal_remove, "cgal-remove"},
#ifdef CGAL_LINKED_WITH_TBB
      {"fast-par-remove", true, false, run_fast_parallel_remove, "cgal-remove"},
      {"cgal-par-remove", true, false, run_cgal_parallel_remove, "cgal-remove"},
#endif
      {"fast-move", false, false, run_fast_move, "cgal-move"},
      {"cgal-move", false, false, run_cgal_move, "cgal-move"},
      {"fast-epec", false, false, run_fast_epec, "cgal-epec"},
      {"cgal-epec", false, false, run_cgal_epec, "cgal-epec"},
#ifdef FDT3_WITH_TETGEN
      {"tetgen", false, true, run_tetgen, "cgal", true},
#endif
      {"hxt", true, true, run_hxt, "cgal", true},
  };
  return engines;
}


// ------------------------------------------------------------------------------------------------ surface input

#ifndef FDT3_CGAL_DATA_DIR
#define FDT3_CGAL_DATA_DIR "."
#endif

bool readable(const std::string& path) { return static_cast<bool>(std::ifstream(path)); }

// n points sampled uniformly by area on the triangles of the OFF surface at `path` (polygons split into fans), each
// moved along its triangle's unit normal by a Gaussian of deviation 1e-3 times the diagonal of the surface's
// bounding box: a noisy scan of the model. Deterministic for a given seed.
std::vector<fdt3_test::Xyz> surface_points(const std::string& path, std::size_t n, std::uint64_t seed = 12)
{
  std::vector<Point> vertices;
  std::vector<std::vector<std::size_t>> polygons;
  if(!CGAL::IO::read_OFF(path, vertices, polygons) || vertices.empty())
    throw std::runtime_error("cannot read the surface " + path);
  struct Triangle
  {
    Kernel::Vector_3 origin, u, v, normal; // origin + s u + t v, s, t >= 0, s + t <= 1
  };
  std::vector<Triangle> triangles;
  std::vector<double> cumulative_area; // area of triangles[0..i]
  double total = 0;
  for(const auto& polygon : polygons)
    for(std::size_t k = 1; k + 1 < polygon.size(); ++k) {
      const Kernel::Vector_3 a = vertices.at(polygon[0]) - CGAL::ORIGIN;
      const Kernel::Vector_3 u = vertices.at(polygon[k]) - vertices[polygon[0]];
      const Kernel::Vector_3 v = vertices.at(polygon[k + 1]) - vertices[polygon[0]];
      const Kernel::Vector_3 cross = CGAL::cross_product(u, v);
      const double twice_area = std::sqrt(cross.squared_length());
      if(!(twice_area > 0)) continue; // a degenerate triangle gets no sample
      total += twice_area / 2;
      triangles.push_back({a, u, v, cross / twice_area});
      cumulative_area.push_back(total);
    }
  if(triangles.empty()) throw std::runtime_error("the surface " + path + " has no triangle of positive area");
  const CGAL::Bbox_3 box = CGAL::bbox_3(vertices.begin(), vertices.end());
  const double diagonal = std::sqrt(CGAL::square(box.xmax() - box.xmin()) + CGAL::square(box.ymax() - box.ymin()) +
                                    CGAL::square(box.zmax() - box.zmin()));

  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> uniform(0.0, 1.0);
  std::normal_distribution<double> noise(0.0, 1e-3 * diagonal);
  std::vector<fdt3_test::Xyz> points(n);
  for(fdt3_test::Xyz& q : points) {
    const std::size_t i = std::min<std::size_t>(
        std::upper_bound(cumulative_area.begin(), cumulative_area.end(), uniform(rng) * total) -
            cumulative_area.begin(),
        triangles.size() - 1);
    const Triangle& t = triangles[i];
    // Uniform on the triangle: sqrt of the first variable spreads the samples evenly from the origin vertex out.
    const double r = std::sqrt(uniform(rng)), w = uniform(rng);
    const Kernel::Vector_3 p = t.origin + r * (1 - w) * t.u + r * w * t.v + noise(rng) * t.normal;
    q = {p.x(), p.y(), p.z()};
  }
  return points;
}

// ------------------------------------------------------------------------------------------------ child processes

struct Child_report
{
  bool ok = false;
  Engine_result result;
  long peak_kib = 0;     // getrusage(RUSAGE_SELF).ru_maxrss of the child
  char error[240] = {};
};
static_assert(std::is_trivially_copyable<Child_report>::value, "Child_report is sent through a pipe");

void copy_message(char (&to)[240], const char* message)
{
  std::snprintf(to, sizeof to, "%s", message);
}

// Moves `size` bytes with ::read or ::write, resuming after partial transfers and signals.
template <class Byte, class Transfer>
bool transfer_all(int fd, Byte* p, std::size_t size, Transfer transfer)
{
  while(size > 0) {
    const ssize_t done = transfer(fd, p, size);
    if(done < 0 && errno == EINTR) continue;
    if(done <= 0) return false;
    p += done;
    size -= static_cast<std::size_t>(done);
  }
  return true;
}

bool write_all(int fd, const void* data, std::size_t size)
{
  return transfer_all(fd, static_cast<const char*>(data), size, ::write);
}

bool read_all(int fd, void* data, std::size_t size)
{
  return transfer_all(fd, static_cast<char*>(data), size, ::read);
}

// Runs work() -> Engine_result in a forked child and returns what it measured. Linux starts a child's peak RSS at
// its resident size after fork (the parent's current pages, not the parent's peak), so the peak is this run's own.
template <class Work>
Child_report run_in_child(const Work& work)
{
  int fds[2];
  if(::pipe(fds) != 0) throw std::system_error(errno, std::generic_category(), "pipe");
  std::fflush(nullptr); // nothing buffered may be printed twice
  const pid_t pid = ::fork();
  if(pid < 0) throw std::system_error(errno, std::generic_category(), "fork");

  if(pid == 0) {
    ::close(fds[0]);
    Child_report report;
    try {
      report.result = work();
      report.ok = true;
    } catch(const std::exception& e) {
      copy_message(report.error, e.what());
    } catch(...) {
      copy_message(report.error, "an exception that is not a std::exception");
    }
    rusage usage;
    ::getrusage(RUSAGE_SELF, &usage);
    report.peak_kib = report.result.peak_kib > 0 ? report.result.peak_kib : usage.ru_maxrss;
    _exit(write_all(fds[1], &report, sizeof report) ? 0 : 1);
  }

  ::close(fds[1]);
  Child_report report;
  const bool complete = read_all(fds[0], &report, sizeof report);
  ::close(fds[0]);
  int status = 0;
  while(::waitpid(pid, &status, 0) < 0 && errno == EINTR) {}
  if(!complete) {
    report = Child_report();
    char why[240];
    if(WIFSIGNALED(status))
      std::snprintf(why, sizeof why, "killed by signal %d (%s)", WTERMSIG(status), strsignal(WTERMSIG(status)));
    else
      std::snprintf(why, sizeof why, "exited with status %d without a report", WEXITSTATUS(status));
    copy_message(report.error, why);
  }
  return report;
}

// ------------------------------------------------------------------------------------------------ options

struct Options
{
  std::vector<std::size_t> sizes = {1000000};
  std::vector<std::string> distributions = {"uniform"};
  std::vector<std::string> engines;   // empty: the engines marked by_default
  std::vector<int> threads = {1, 2};
  std::string surface = FDT3_CGAL_DATA_DIR "/bunny00.off"; // the points of --dist surface
  int rounds = 3;
  bool phases = false;
  bool verbose = false;
  bool scalar_paths = false;          // our engines with the scalar forms of the predicates forced
  std::string csv_path;               // empty: no CSV; "-": CSV on standard output instead of the table
};

std::vector<std::string> split(const std::string& list)
{
  std::vector<std::string> items;
  std::size_t begin = 0;
  while(begin <= list.size()) {
    const std::size_t end = std::min(list.find(',', begin), list.size());
    if(end > begin) items.push_back(list.substr(begin, end - begin));
    begin = end + 1;
  }
  return items;
}

std::string join(const std::vector<std::string>& items)
{
  std::string all;
  for(const std::string& item : items) all += (all.empty() ? "" : ",") + item;
  return all;
}

// A positive number, also written as 1e6.
double parse_number(const std::string& text, const char* option)
{
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if(text.empty() || *end != '\0' || !(value >= 1) || value > 1e12)
    throw std::invalid_argument(std::string(option) + ": '" + text + "' is not a positive number");
  return value;
}

const Engine* find_engine(const std::string& name)
{
  for(const Engine& engine : engine_table())
    if(name == engine.name) return &engine;
  return nullptr;
}

std::vector<std::string> engine_names(bool default_only)
{
  std::vector<std::string> names;
  for(const Engine& engine : engine_table())
    // HXT's row is a default where its helper was built (with Gmsh).
    if(!default_only || (engine.by_default && (engine.run != run_hxt || !hxt_helper().empty())))
      names.push_back(engine.name);
  return names;
}

void print_usage(std::FILE* to)
{
  std::fprintf(to,
               "usage: delaunay_benchmark [options]\n"
               "  --n LIST        numbers of points, e.g. 1e5,1e6 (default 1e6)\n"
               "  --dist LIST     uniform, gauss, clusters, sphere, grid, shell, torus, surface, duplicates,\n"
               "                  offset, tiny, plane, scales, or all (all = the first eight; default uniform);\n"
               "                  shell: near the unit sphere, torus: near the torus R = 1, r = 0.3 (noise 1e-3\n"
               "                  along the normal);\n"
               "                  surface: sampled by area on --surface, noise 1e-3 of its bounding box diagonal;\n"
               "                  plane: uniform in the plane z = x (dimension 2); scales: each point at its own\n"
               "                  scale, [-1, 1]^3 times 10^e, e from -200 to 200\n"
               "  --surface FILE  the OFF surface of --dist surface (default %s;\n"
               "                  missing: that distribution is skipped)\n"
               "  --engines LIST  among %s (default %s)\n"
               "  --rounds R      runs of every engine, interleaved; the table shows the median (default 3)\n"
               "  --threads LIST  thread counts of the parallel engines (default 1,2)\n"
               "  --phases        also print our per-phase breakdown (sort, init, walk, cavity, ball, other)\n"
               "  --verbose       also print the attempts of our parallel engine (paper Table 2), one more run per\n"
               "                  --threads value with exactly that many partitions\n"
               "  --scalar-paths  our engines with the scalar forms of the predicates, as on a processor without\n"
               "                  AVX2 and FMA (by default they take the AVX2 forms where the processor has them)\n"
               "  --csv FILE      also write the table as comma-separated values to FILE, the machine in lines\n"
               "                  that start with '#' (scripts/plot_benchmark.py draws it); '-': on standard\n"
               "                  output, instead of the table\n",
               FDT3_CGAL_DATA_DIR "/bunny00.off", join(engine_names(false)).c_str(), join(engine_names(true)).c_str());
}

Options parse_options(int argc, char** argv)
{
  Options options;
  for(int k = 1; k < argc; ++k) {
    const std::string option = argv[k];
    auto value = [&]() -> std::string {
      if(k + 1 >= argc) throw std::invalid_argument(option + " needs a value");
      return argv[++k];
    };
    if(option == "--n") {
      options.sizes.clear();
      for(const std::string& item : split(value()))
        options.sizes.push_back(static_cast<std::size_t>(parse_number(item, "--n")));
    } else if(option == "--dist") {
      const std::string list = value();
      options.distributions = split(list);
      if(list == "all") {
        options.distributions = fdt3_test::distribution_names();
        options.distributions.push_back("surface");
      }
      for(const std::string& name : options.distributions)
        if(name != "surface") fdt3_test::make_points(name, 0); // throws on an unknown name
    } else if(option == "--surface") {
      options.surface = value();
    } else if(option == "--engines") {
      options.engines = split(value());
      for(const std::string& name : options.engines)
        if(!find_engine(name))
          throw std::invalid_argument("unknown engine '" + name + "' (known: " + join(engine_names(false)) +
                                      (name.find("-par") != std::string::npos ? "; parallel engines need TBB" : "") +
                                      ")");
    } else if(option == "--rounds") {
      options.rounds = static_cast<int>(parse_number(value(), "--rounds"));
    } else if(option == "--threads") {
      options.threads.clear();
      for(const std::string& item : split(value()))
        options.threads.push_back(static_cast<int>(parse_number(item, "--threads")));
    } else if(option == "--phases") {
      options.phases = true;
    } else if(option == "--verbose") {
      options.verbose = true;
    } else if(option == "--scalar-paths") {
      options.scalar_paths = true;
    } else if(option == "--csv") {
      options.csv_path = value();
    } else if(option == "--help" || option == "-h") {
      print_usage(stdout);
      std::exit(0);
    } else {
      throw std::invalid_argument("unknown option '" + option + "'");
    }
  }
  if(options.engines.empty()) options.engines = engine_names(true);
  if(options.sizes.empty() || options.distributions.empty() || options.engines.empty() || options.threads.empty())
    throw std::invalid_argument("an empty list");
  return options;
}

// ------------------------------------------------------------------------------------------------ machine

std::string cpu_model()
{
  std::ifstream cpuinfo("/proc/cpuinfo");
  std::string line;
  while(std::getline(cpuinfo, line))
    if(line.compare(0, 10, "model name") == 0) {
      const std::size_t colon = line.find(':');
      return colon == std::string::npos ? line : line.substr(line.find_first_not_of(' ', colon + 1));
    }
  return "unknown CPU";
}

int usable_cores()
{
  cpu_set_t set;
  return ::sched_getaffinity(0, sizeof set, &set) == 0 ? CPU_COUNT(&set) : -1;
}

std::string compiler()
{
#if defined(__clang__)
  return "clang " __clang_version__;
#elif defined(__GNUC__)
  return "GCC " __VERSION__;
#else
  return "unknown compiler";
#endif
}

// The 1-minute load average: other work on the machine slows the engines, the parallel ones most.
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
  char text[64];
  std::strftime(text, sizeof text, "%Y-%m-%d %H:%M UTC", std::gmtime(&now));
  return text;
}

// The machine, build and method, each line after `prefix` ("# " in a CSV file, which plot_benchmark.py reads for its
// title).
void print_machine(std::FILE* out, const char* prefix)
{
  const char* c = prefix;
  std::fprintf(out, "%sFast_Delaunay_triangulation_3 benchmark, %s\n", c, utc_now().c_str());
  std::fprintf(out, "%smachine: %s, %u hardware threads, %d usable by this process\n", c, cpu_model().c_str(),
               std::thread::hardware_concurrency(), usable_cores());
  std::fprintf(out, "%sbuild:   %s, CGAL %s, ", c, compiler().c_str(), CGAL_VERSION_STR);
#ifdef CGAL_LINKED_WITH_TBB
  std::fprintf(out, "TBB %d.%d", TBB_VERSION_MAJOR, TBB_VERSION_MINOR);
#else
  std::fprintf(out, "no TBB");
#endif
  std::fprintf(out, ", predicates: %s",
               CGAL::Fast_Delaunay_triangulation_3_internal::use_avx2_paths() ? "AVX2 and FMA forms" : "scalar forms");
#ifdef NDEBUG
  std::fprintf(out, ", NDEBUG\n");
#else
  std::fprintf(out, ", assertions ON (not a Release build: times are not representative)\n");
#endif
  std::fprintf(out,
               "%smethod:  every engine run is its own forked process; seconds = insertion into an empty\n"
               "%s         triangulation (-remove, -move rows: removing / moving 10%% of the vertices one by one\n"
               "%s         after an untimed insertion, -par-remove rows: the same 10%% removed as one range),\n"
               "%s         median over the rounds, engines interleaved in each;\n"
               "%s         fast = ours, 1 thread; peak MiB = the child's max RSS, which includes the input points\n"
               "%s         (generated once in the parent before forking, %zu bytes each) and the baseline process,\n"
               "%s         alike for every engine\n",
               c, c, c, c, c, c, sizeof(Point), c);
#ifdef FDT3_WITH_TETGEN
  std::fprintf(out,
               "%s         tetgen = TetGen's tetrahedralize() with switch Q (the Delaunay tetrahedralization), the\n"
               "%s         points copied into its input array before the clock starts\n",
               c, c);
#endif
  if(!hxt_helper().empty())
    std::fprintf(out,
                 "%s         hxt = Gmsh's hxtDelaunay (libgmsh), in a helper process: seconds from the creation of\n"
                 "%s         its mesh (the points copied in) to the end of the insertion, OpenMP threads; peak MiB\n"
                 "%s         = the helper's max RSS less its size on start (libgmsh's code), with the points\n",
                 c, c, c);
}

// ------------------------------------------------------------------------------------------------ measuring

// One row of the table: an engine at a thread count.
struct Row
{
  Row(const Engine* engine, int threads, std::string label) : engine(engine), threads(threads), label(label) {}

  const Engine* engine;
  int threads;
  std::string label;            // the engine name, or "fast+phases" for the timed-phases run
  std::vector<double> seconds;  // one per round
  std::uint64_t finite_cells = 0;
  bool cells_vary = false;      // different counts in different rounds
  long peak_kib = 0;            // the largest over the rounds
  std::string error;
  Phase_report phases;
  bool has_phases = false;
  std::vector<Attempt_report> attempts; // --verbose rows of fast-par
  int attempts_left_out = 0;
  Outside_attempts outside_attempts;    // with attempts
  double attempts_run_seconds = 0;      // with attempts: the whole run
};

std::vector<Row> rows_of(const Options& options)
{
  std::vector<Row> rows;
  for(const std::string& name : options.engines) {
    const Engine* engine = find_engine(name);
    if(engine->parallel)
      for(int t : options.threads) rows.emplace_back(engine, t, name);
    else
      rows.emplace_back(engine, 1, name);
  }
  return rows;
}

void record(Row& row, const Child_report& report)
{
  if(!report.ok) {
    if(row.error.empty()) row.error = report.error;
    return;
  }
  if(!row.seconds.empty() && report.result.finite_cells != row.finite_cells) row.cells_vary = true;
  row.seconds.push_back(report.result.seconds);
  row.finite_cells = report.result.finite_cells;
  row.peak_kib = std::max(row.peak_kib, report.peak_kib);
  if(report.result.has_phases) {
    row.has_phases = true;
    row.phases = report.result.phases;
  }
  if(report.result.attempt_rows > 0) {
    row.attempts.assign(report.result.attempts, report.result.attempts + report.result.attempt_rows);
    row.attempts_left_out = report.result.attempts_left_out;
    row.outside_attempts = report.result.outside_attempts;
    row.attempts_run_seconds = report.result.seconds;
  }
}

double median(std::vector<double> v)
{
  std::sort(v.begin(), v.end());
  const std::size_t m = v.size() / 2;
  return v.size() % 2 ? v[m] : (v[m - 1] + v[m]) / 2;
}

struct Measurement
{
  std::size_t n = 0;
  std::string distribution;
  std::size_t input_points = 0; // may differ from n: the grid rounds n up to k^3 and cuts it back
  long baseline_kib = 0;        // peak RSS of a child that does nothing
  double load_before = 0;       // load average of the machine when the measurement started
  std::vector<Row> rows;
  std::string skipped;          // why nothing was measured (the surface file is missing), or empty
};

Measurement measure(const Options& options, std::size_t n, const std::string& distribution)
{
  Measurement m;
  m.n = n;
  m.distribution = distribution;
  m.load_before = load_average();
  ::malloc_trim(0); // the previous measurement's points must not stay resident in every child
  if(distribution == "surface" && !readable(options.surface)) {
    m.skipped = "the surface " + options.surface +
                " is not there (Debian: apt install libcgal-demo, then configure again; or --surface FILE)";
    return m;
  }
  const Points points = fdt3_test::to_points<Point>(distribution == "surface"
                                                        ? surface_points(options.surface, n)
                                                        : fdt3_test::make_points(distribution, n));
  m.input_points = points.size();
  m.baseline_kib = run_in_child([] { return Engine_result(); }).peak_kib;

  m.rows = rows_of(options);
  for(int round = 0; round < options.rounds; ++round)
    for(Row& row : m.rows)
      record(row, run_in_child([&] { return row.engine->run(points, row.threads); }));

  if(options.phases) {
    static const Engine fast_with_phases = {"fast", false, false, run_fast_with_phases};
    Row row(&fast_with_phases, 1, "fast+phases");
    record(row, run_in_child([&] { return run_fast_with_phases(points, 1); }));
    m.rows.push_back(row);
  }
#ifdef CGAL_LINKED_WITH_TBB
  if(options.verbose) {
    static const Engine fast_with_attempts = {"fast-par", true, false, run_fast_parallel_with_attempts};
    for(int threads : options.threads) {
      Row row(&fast_with_attempts, threads, "fast-par+log");
      record(row, run_in_child([&] { return run_fast_parallel_with_attempts(points, threads); }));
      m.rows.push_back(row);
    }
  }
#endif
  return m;
}

// ------------------------------------------------------------------------------------------------ printing

std::string with_commas(std::uint64_t value)
{
  std::string digits = std::to_string(value), text;
  for(std::size_t i = 0; i < digits.size(); ++i) {
    if(i > 0 && (digits.size() - i) % 3 == 0) text += ',';
    text += digits[i];
  }
  return text;
}

double mib(long kib) { return static_cast<double>(kib) / 1024.0; }

const Row* reference_row(const Measurement& m, const Row& of)
{
  for(const Row& row : m.rows)
    if(row.label == of.engine->reference && !row.seconds.empty()) return &row;
  return nullptr;
}

// Speed-up of a row over CGAL's sequential triangulation doing the same (insertion, removal or move), or 0 when
// CGAL did not run.
double speedup(const Measurement& m, const Row& row)
{
  const Row* reference = reference_row(m, row);
  if(!reference || row.seconds.empty()) return 0;
  return median(reference->seconds) / median(row.seconds);
}

// Speed-up of an insertion row over CGAL's parallel triangulation on as many threads (cgal-par with --threads 1 for
// the sequential rows), or 0 when that did not run.
double speedup_over_cgal_parallel(const Measurement& m, const Row& row)
{
  if(std::string(row.engine->reference) != "cgal" || row.seconds.empty()) return 0;
  for(const Row& other : m.rows)
    if(other.label == "cgal-par" && other.threads == row.threads && !other.seconds.empty())
      return median(other.seconds) / median(row.seconds);
  return 0;
}

// Speed-up of a parallel row over the same engine on 1 thread (with --threads 1 among the thread counts), or 0.
double speedup_over_one_thread(const Measurement& m, const Row& row)
{
  if(!row.engine->parallel || row.threads == 1 || row.seconds.empty()) return 0;
  for(const Row& other : m.rows)
    if(other.label == row.label && other.threads == 1 && !other.seconds.empty())
      return median(other.seconds) / median(row.seconds);
  return 0;
}

// Our Table 1 breakdown. `total` is the whole insertion as the benchmark timed it; `other` is what the phases do
// not cover: removal of duplicates, the insertion loop, and the clock reads themselves.
struct Phase_split
{
  double sort, init, walk, cavity, ball, other, total;
};

Phase_split phase_split(const Row& row)
{
  const Phase_report& r = row.phases;
  Phase_split s;
  s.sort = r.sort_seconds;
  s.init = r.init_seconds;
  s.walk = r.walk_seconds;
  s.cavity = r.cavity_seconds;
  s.ball = r.ball_seconds;
  s.total = row.seconds.front();
  s.other = s.total - (s.sort + s.init + s.walk + s.cavity + s.ball);
  return s;
}

double per_point(std::uint64_t count, const Phase_report& r)
{
  return r.inserted ? static_cast<double>(count) / static_cast<double>(r.inserted) : 0.0;
}

void print_phases(const Row& row)
{
  const Phase_split s = phase_split(row);
  const double part[7] = {s.sort, s.init, s.walk, s.cavity, s.ball, s.other, s.total};
  std::printf("\nfast per phase (one more run with the phase clocks on; other = finishing, loop and clock reads)\n");
  std::printf("%-9s %8s %8s %8s %8s %8s %8s %8s\n", "", "sort", "init", "walk", "cavity", "ball", "other", "total");
  std::printf("%-9s", "seconds");
  for(double t : part) std::printf(" %8.3f", t);
  std::printf("\n%-9s", "share");
  for(double t : part) std::printf(" %7.1f%%", s.total > 0 ? 100 * t / s.total : 0.0);
  const Phase_report& r = row.phases;
  const std::uint64_t cavities = r.small_cavities + r.large_cavities;
  std::printf("\nper inserted point: %.2f walk steps, %.2f cavity tets, %.2f ball tets, %.2f conflict tests\n",
              per_point(r.walk_steps, r), per_point(r.cavity_tets, r), per_point(r.ball_tets, r),
              per_point(r.conflict_tests, r));
  std::printf("cavities: %s small (adjacency table), %s large (fallback, %.4f%%); %s inserted, %s duplicates\n",
              with_commas(r.small_cavities).c_str(), with_commas(r.large_cavities).c_str(),
              cavities ? 100.0 * static_cast<double>(r.large_cavities) / static_cast<double>(cavities) : 0.0,
              with_commas(r.inserted).c_str(), with_commas(r.duplicates).c_str());
}

// The paper's Table 2 for one fast-par+log run.
void print_attempts(const Row& row)
{
  std::printf("\nfast-par attempts with %d partitions (paper Table 2; 1 partition = sequential finish; cut: along the "
              "curve, or by median planes)\n",
              row.threads);
  std::printf("%8s %12s %12s %8s %11s %6s %14s %9s\n", "attempt", "points", "inserted", "ratio", "partitions",
              "cut", "mesh vertices", "seconds");
  std::uint64_t total = 0;
  std::vector<std::uint64_t> by_partitions(256, 0);
  for(std::size_t i = 0; i < row.attempts.size(); ++i) {
    const Attempt_report& a = row.attempts[i];
    std::printf("%8zu %12s %12s %7.1f%% %11d %6s %14s %9.3f\n", i + 1, with_commas(a.points).c_str(),
                with_commas(a.inserted).c_str(), a.points ? 100.0 * double(a.inserted) / double(a.points) : 0.0,
                a.partitions, a.partitions == 1 ? "-" : a.plane_cut ? "plane" : "curve",
                with_commas(a.mesh_vertices).c_str(), a.seconds);
    total += a.inserted;
    by_partitions[static_cast<std::size_t>(std::min(a.partitions, 255))] += a.inserted;
  }
  if(row.attempts_left_out > 0) std::printf("(%d more attempts not shown)\n", row.attempts_left_out);
  // What the attempts leave out: the sort (BRIO, with the vertex records and the bounding box), the first
  // tetrahedron, the finishing (duplicates, the input's vertex ids), and the rest (reading the user's points,
  // the rounds' point lists).
  double in_attempts = 0;
  for(const Attempt_report& a : row.attempts) in_attempts += a.seconds;
  const Outside_attempts& o = row.outside_attempts;
  std::printf("outside the attempts: sort %.3f s, initial tetrahedron %.3f s, finishing %.3f s, other %.3f s; "
              "run %.3f s\n",
              o.sort, o.init, o.finish, std::max(0.0, row.attempts_run_seconds - in_attempts - o.sort - o.init - o.finish),
              row.attempts_run_seconds);
  std::printf("inserted by:");
  for(int k = 255; k >= 1; --k)
    if(by_partitions[k] > 0)
      std::printf(" %d partition%s %.1f%%", k, k == 1 ? "" : "s",
                  total ? 100.0 * double(by_partitions[k]) / double(total) : 0.0);
  std::printf("\n");
}

// What the cell counts say: every engine must find the finite cells of its CGAL counterpart (of the first engine
// doing the same when CGAL did not run), in every round; a failure or a different count is a warning, and makes the
// exit status non-zero, but only a note for an engine run for comparison only (TetGen).
struct Cell_count_check
{
  std::vector<std::string> warnings, notes;
};

Cell_count_check check_cell_counts(const Measurement& m)
{
  Cell_count_check check;
  std::map<std::string, const Row*> first_of; // by reference name
  for(const Row& row : m.rows) {
    std::vector<std::string>& findings = row.engine->comparison_only ? check.notes : check.warnings;
    if(!row.error.empty())
      findings.push_back(row.label + " failed: " + row.error);
    if(row.cells_vary)
      findings.push_back(row.label + " found different numbers of finite cells in different rounds");
    const Row* reference = reference_row(m, row);
    if(!reference && !row.seconds.empty() && !first_of.count(row.engine->reference)) first_of[row.engine->reference] = &row;
    if(!reference && first_of.count(row.engine->reference)) reference = first_of[row.engine->reference];
    if(reference && !row.seconds.empty() && row.finite_cells != reference->finite_cells)
      findings.push_back(row.label + " has " + with_commas(row.finite_cells) + " finite cells, " + reference->label +
                         " has " + with_commas(reference->finite_cells));
  }
  return check;
}

void print_table(const Measurement& m, int rounds)
{
  std::printf("\nn = %s %s points (%s in the input), %d round%s; baseline peak (process + points) %.0f MiB; "
              "load average %.2f\n",
              with_commas(m.n).c_str(), m.distribution.c_str(), with_commas(m.input_points).c_str(), rounds,
              rounds == 1 ? "" : "s", mib(m.baseline_kib), m.load_before);
  std::printf("%-15s %7s %9s %13s %8s %9s %9s %9s %9s\n", "engine", "threads", "seconds", "tetrahedra", "Mtets/s",
              "peak MiB", "vs cgal", "vs c-par", "vs 1 thr");
  for(const Row& row : m.rows) {
    if(row.seconds.empty()) {
      std::printf("%-15s %7d   failed: %s\n", row.label.c_str(), row.threads, row.error.c_str());
      continue;
    }
    const double t = median(row.seconds);
    std::printf("%-15s %7d %9.3f %13s %8.2f %9.0f", row.label.c_str(), row.threads, t,
                with_commas(row.finite_cells).c_str(), static_cast<double>(row.finite_cells) / t / 1e6,
                mib(row.peak_kib));
    for(const double s : {speedup(m, row), speedup_over_cgal_parallel(m, row), speedup_over_one_thread(m, row)})
      if(s > 0) std::printf(" %8.2fx", s);
      else std::printf(" %9s", "-");
    std::printf("\n");
  }
  const Cell_count_check check = check_cell_counts(m);
  for(const std::string& warning : check.warnings) std::printf("WARNING: %s\n", warning.c_str());
  for(const std::string& note : check.notes) std::printf("note: %s\n", note.c_str());
  for(const Row& row : m.rows)
    if(row.has_phases) print_phases(row);
  for(const Row& row : m.rows)
    if(!row.attempts.empty()) print_attempts(row);
  std::fflush(stdout);
}

void print_csv_header(std::FILE* out)
{
  std::fprintf(out, "n,distribution,input_points,engine,threads,rounds,median_seconds,finite_cells,mtets_per_second,"
               "peak_mib,baseline_mib,load_average,speedup_vs_cgal,sort_s,init_s,walk_s,cavity_s,ball_s,other_s,"
               "total_s,walk_steps_per_point,cavity_tets_per_point,ball_tets_per_point,conflict_tests_per_point,"
               "small_cavities,large_cavities,speedup_vs_cgal_par,speedup_vs_1_thread\n");
}

void print_csv(std::FILE* out, const Measurement& m)
{
  const Cell_count_check check = check_cell_counts(m);
  for(const std::string& warning : check.warnings) std::fprintf(out, "# WARNING: %s\n", warning.c_str());
  for(const std::string& note : check.notes) std::fprintf(out, "# note: %s\n", note.c_str());
  for(const Row& row : m.rows) {
    if(row.seconds.empty()) continue;
    const double t = median(row.seconds);
    std::fprintf(out, "%zu,%s,%zu,%s,%d,%zu,%.6f,%llu,%.4f,%.1f,%.1f,%.2f,", m.n, m.distribution.c_str(),
                 m.input_points, row.label.c_str(), row.threads, row.seconds.size(), t,
                 static_cast<unsigned long long>(row.finite_cells), static_cast<double>(row.finite_cells) / t / 1e6,
                 mib(row.peak_kib), mib(m.baseline_kib), m.load_before);
    const double s = speedup(m, row);
    if(s > 0) std::fprintf(out, "%.4f", s);
    if(!row.has_phases) {
      std::fprintf(out, ",,,,,,,,,,,,");
    } else {
      const Phase_split p = phase_split(row);
      const Phase_report& r = row.phases;
      std::fprintf(out, ",%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.6f,%.4f,%.4f,%.4f,%.4f,%llu,%llu", p.sort, p.init,
                   p.walk, p.cavity, p.ball, p.other, p.total, per_point(r.walk_steps, r),
                   per_point(r.cavity_tets, r), per_point(r.ball_tets, r), per_point(r.conflict_tests, r),
                   static_cast<unsigned long long>(r.small_cavities),
                   static_cast<unsigned long long>(r.large_cavities));
    }
    for(const double ratio : {speedup_over_cgal_parallel(m, row), speedup_over_one_thread(m, row)}) {
      std::fputc(',', out);
      if(ratio > 0) std::fprintf(out, "%.4f", ratio);
    }
    std::fputc('\n', out);
  }
  std::fflush(out);
}

} // namespace

int main(int argc, char** argv)
{
  Options options;
  try {
    options = parse_options(argc, argv);
  } catch(const std::exception& e) {
    std::fprintf(stderr, "delaunay_benchmark: %s\n", e.what());
    print_usage(stderr);
    return 2;
  }

  // Set before the engines' processes are forked: they inherit it.
  CGAL::Fast_Delaunay_triangulation_3_internal::scalar_paths_forced() = options.scalar_paths;

  const bool table = options.csv_path != "-";
  std::FILE* csv = nullptr;
  if(!table)
    csv = stdout;
  else if(!options.csv_path.empty() && !(csv = std::fopen(options.csv_path.c_str(), "w"))) {
    std::fprintf(stderr, "delaunay_benchmark: cannot write %s: %s\n", options.csv_path.c_str(), std::strerror(errno));
    return 2;
  }

  if(table) print_machine(stdout, "");
  if(csv) {
    print_machine(csv, "# ");
    print_csv_header(csv);
  }
  bool all_agree = true;
  for(std::size_t n : options.sizes)
    for(const std::string& distribution : options.distributions) {
      const Measurement m = measure(options, n, distribution);
      if(!m.skipped.empty()) {
        // Said on every output, so that a table or a CSV without the surface rows says why.
        std::fprintf(stderr, "delaunay_benchmark: --dist %s skipped: %s\n", distribution.c_str(), m.skipped.c_str());
        if(table) std::printf("\nn = %s %s points: skipped: %s\n", with_commas(n).c_str(), distribution.c_str(),
                              m.skipped.c_str());
        if(csv) std::fprintf(csv, "# %s skipped: %s\n", distribution.c_str(), m.skipped.c_str());
        continue;
      }
      all_agree = all_agree && check_cell_counts(m).warnings.empty();
      if(table) print_table(m, options.rounds);
      if(csv) print_csv(csv, m);
    }
  if(csv && csv != stdout && std::fclose(csv) != 0) {
    std::fprintf(stderr, "delaunay_benchmark: cannot write %s: %s\n", options.csv_path.c_str(), std::strerror(errno));
    return 2;
  }
  return all_agree ? 0 : 1;
}
