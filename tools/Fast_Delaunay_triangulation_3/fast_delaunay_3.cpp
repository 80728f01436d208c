// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// fast_delaunay_3 POINTS -o OUTPUT [--threads K] [--quiet]
//
// The Delaunay tetrahedralization of a point cloud (.xyz, .ply, .off, .npy;
// Point_cloud_io.h) written as .vtu, .mesh, .msh (the finite tetrahedra),
// .off (the convex hull) or .cgal (CGAL's triangulation format), by
// extension (Triangulation_writers.h).  On a terminal a progress line shows
// the phases read, sort, insert and write; a summary line follows, unless
// --quiet.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Point_cloud_io.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Triangulation_writers.h>

#include "Progress_bar.h"

#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Triangulation;
typedef K::Point_3 Point;

int usage(const char* program)
{
  std::fprintf(stderr,
               "usage: %s POINTS -o OUTPUT [--threads K] [--quiet]\n"
               "  POINTS  .xyz (x y z per line), .ply (ascii or binary), .off, .npy (float64/float32, shape (n, 3))\n"
               "  OUTPUT  .vtu (VTK, binary), .mesh (Medit), .msh (Gmsh 4.1): the finite tetrahedra;\n"
               "          .off: the convex hull; .cgal: CGAL's triangulation format (operator<<)\n"
               "  --threads K  Moore partitions (threads) of the parallel insertion (default: all hardware threads\n"
               "               with TBB, else 1)\n"
               "  --quiet      print nothing but errors\n",
               program);
  return 2;
}

// The points of a flat x y z array as Point_3, without a copy of the array:
// the triangulation gathers the coordinates once from these.
class Point_iterator
{
public:
  typedef std::random_access_iterator_tag iterator_category;
  typedef Point value_type;
  typedef std::ptrdiff_t difference_type;
  typedef const Point* pointer;
  typedef Point reference;

  Point_iterator(const double* xyz, std::size_t i) : xyz_(xyz), i_(i) {}
  Point operator*() const { return Point(xyz_[3 * i_], xyz_[3 * i_ + 1], xyz_[3 * i_ + 2]); }
  Point_iterator& operator++()
  {
    ++i_;
    return *this;
  }
  Point_iterator operator++(int)
  {
    Point_iterator old = *this;
    ++i_;
    return old;
  }
  difference_type operator-(const Point_iterator& other) const
  {
    return difference_type(i_) - difference_type(other.i_);
  }
  bool operator==(const Point_iterator& other) const { return i_ == other.i_; }
  bool operator!=(const Point_iterator& other) const { return i_ != other.i_; }

private:
  const double* xyz_;
  std::size_t i_;
};

double seconds_since(std::chrono::steady_clock::time_point t0)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

double peak_memory_gib()
{
  rusage usage;
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / (1024.0 * 1024.0); // ru_maxrss is in KiB on Linux
}

} // namespace

int main(int argc, char** argv)
{
  std::string input, output;
#ifdef CGAL_LINKED_WITH_TBB
  int threads = int(std::thread::hardware_concurrency());
#else
  int threads = 1; // without TBB the partitions would run one after the other
#endif
  bool quiet = false;
  for(int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    auto value = [&]() -> std::string {
      if(i + 1 >= argc) {
        std::fprintf(stderr, "fast_delaunay_3: %s needs a value\n", arg.c_str());
        std::exit(usage(argv[0]));
      }
      return argv[++i];
    };
    if(arg == "-o" || arg == "--output") output = value();
    else if(arg == "--threads") {
      const std::string v = value();
      char* end = nullptr;
      const long k = std::strtol(v.c_str(), &end, 10);
      if(end == v.c_str() || *end != '\0' || k < 1 || k > 255) {
        std::fprintf(stderr, "fast_delaunay_3: --threads takes a number from 1 to 255, not '%s'\n", v.c_str());
        return 2;
      }
      threads = int(k);
    } else if(arg == "--quiet") quiet = true;
    else if(arg == "-h" || arg == "--help") return usage(argv[0]);
    else if(!arg.empty() && arg[0] == '-') {
      std::fprintf(stderr, "fast_delaunay_3: unknown option %s\n", arg.c_str());
      return usage(argv[0]);
    } else if(input.empty()) input = arg;
    else {
      std::fprintf(stderr, "fast_delaunay_3: one input file only (%s and %s given)\n", input.c_str(), arg.c_str());
      return 2;
    }
  }
  if(input.empty() || output.empty()) return usage(argv[0]);
  threads = std::max(1, std::min(threads, 255));

  fdt3_tools::Progress_bar bar(stderr, !quiet);
  try {
    // Refuse a bad output name before the work, not after.
    using CGAL::Fast_Delaunay_triangulation_3_internal::ends_with;
    if(!(ends_with(output, ".vtu") || ends_with(output, ".mesh") || ends_with(output, ".msh") ||
         ends_with(output, ".off") || ends_with(output, ".cgal")))
      throw std::invalid_argument("unknown output format for '" + output + "' (use .vtu, .mesh, .msh, .off or .cgal)");

    const auto t0 = std::chrono::steady_clock::now();
    std::vector<double> xyz = CGAL::Fast_Delaunay_triangulation_3_io::read_points(
        input, [&](std::size_t done, std::size_t total) { bar.update("read", done, total); });
    const std::size_t n = xyz.size() / 3;
    const double read_seconds = seconds_since(t0);

    const auto t1 = std::chrono::steady_clock::now();
    Triangulation tr;
    tr.set_number_of_threads(threads);
    tr.set_progress([&](std::size_t done, std::size_t total) { bar.update("insert", done, total); });
    bar.update("sort", "sorting " + std::to_string(n) + " points");
    const std::ptrdiff_t vertices = tr.insert(Point_iterator(xyz.data(), 0), Point_iterator(xyz.data(), n));
    std::vector<double>().swap(xyz);
    const double triangulate_seconds = seconds_since(t1);

    const auto t2 = std::chrono::steady_clock::now();
    bar.update("write", "writing " + output);
    CGAL::Fast_Delaunay_triangulation_3_io::write_triangulation(output, tr);
    const double write_seconds = seconds_since(t2);
    bar.finish();
    if(!quiet)
      std::printf("fast_delaunay_3: %zu points read, %zu duplicates, %zu vertices, %zu finite tetrahedra; "
                  "read %.2f s, triangulate %.2f s (%d threads), write %.2f s; peak memory %.2f GiB; wrote %s\n",
                  n, n - std::size_t(vertices), std::size_t(tr.number_of_vertices()),
                  std::size_t(tr.number_of_finite_cells()), read_seconds, triangulate_seconds, threads, write_seconds,
                  peak_memory_gib(), output.c_str());
  } catch(const std::exception& e) {
    bar.finish();
    std::fprintf(stderr, "fast_delaunay_3: %s\n", e.what());
    return 1;
  }
  return 0;
}
