// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// delaunay_benchmark's HXT row: the paper's own Delaunay kernel, hxtDelaunay, as Debian's libgmsh 4.8 exports it,
// in a process of its own (libgmsh carries its own TetGen under libtet's symbol names; mesher_benchmark_io.h says
// why that matters).
//
//   delaunay_benchmark_hxt POINTS THREADS
//
// POINTS: a 64-bit count n, then n x, y, z triples of doubles.  Prints one line, "seconds finite_tetrahedra
// peak_kib": the seconds cover what a caller of hxtDelaunay does, the mesh's creation, the copy of the points into
// HXT's four doubles per vertex and the insertion (HXT sorts and inserts the points itself); the peak is this
// process's peak RSS less its resident size on entering main (libgmsh and the libraries it loads, some 40 MiB that
// delaunay_benchmark's children do not have), with the points held once, as those children hold them.  Exits 1
// with a message on stderr when HXT fails or returns what cannot be a triangulation of the points (a vertex number
// out of range, no finite tetrahedron).
//
// Gmsh installs no header of HXT, so the structures are declared here: the two that cross the call, in the layout
// of Gmsh 4.8's contrib/hxt (CMake builds this program only for Gmsh 4.8); of HXTMesh only the part read and
// written here, since hxtMeshCreate allocates it.

#include <sys/resource.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

extern "C" {

struct Hxt_mesh_head
{
  struct
  {
    double* coord; // x, y, z and a scratch double per vertex
    std::uint32_t num, size;
  } vertices;
  struct
  {
    std::uint32_t* node; // four vertices per tetrahedron; a ghost's fourth is UINT32_MAX
    std::uint64_t* neigh;
    std::uint32_t* color;
    std::uint16_t* flag;
    std::uint64_t num, size;
  } tetrahedra;
};

struct Hxt_delaunay_options
{
  void* bbox;       // null: HXT computes the bounding box
  void* nodalSizes; // null: no minimum edge length
  std::uint32_t numVerticesInMesh;
  std::uint32_t insertionFirst;
  double partitionability;
  int perfectDelaunay;
  int verbosity;
  int reproducible;
  int delaunayThreads;
};

int hxtMeshCreate(Hxt_mesh_head** mesh);
int hxtMeshDelete(Hxt_mesh_head** mesh);
int hxtDelaunay(Hxt_mesh_head* mesh, Hxt_delaunay_options* options);
}

namespace {

const std::uint32_t ghost_vertex = UINT32_MAX;

std::vector<double> read_points(const char* path)
{
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> file(std::fopen(path, "rb"), std::fclose);
  if(!file) throw std::runtime_error(std::string("cannot open ") + path);
  std::uint64_t n = 0;
  if(std::fread(&n, sizeof n, 1, file.get()) != 1 || n > UINT32_MAX - 1)
    throw std::runtime_error(std::string(path) + ": no point count, or more points than HXT numbers");
  std::vector<double> xyz(3 * n);
  if(std::fread(xyz.data(), sizeof(double), xyz.size(), file.get()) != xyz.size())
    throw std::runtime_error(std::string(path) + ": fewer coordinates than the count says");
  return xyz;
}

// HXT frees what it allocated with its own aligned allocator; the coordinates are ours, given back before
// hxtMeshDelete (HXT permutes them in place and never reallocates them).
struct Hxt_run
{
  Hxt_mesh_head* mesh = nullptr;
  double* coordinates = nullptr;
  ~Hxt_run()
  {
    if(mesh) {
      mesh->vertices.coord = nullptr;
      hxtMeshDelete(&mesh);
    }
    std::free(coordinates);
  }
};

long resident_kib()
{
  long pages = 0, resident = 0;
  std::unique_ptr<std::FILE, int (*)(std::FILE*)> statm(std::fopen("/proc/self/statm", "r"), std::fclose);
  if(!statm || std::fscanf(statm.get(), "%ld %ld", &pages, &resident) != 2) return 0;
  return resident * (::sysconf(_SC_PAGESIZE) / 1024);
}

void check(int status, const char* call)
{
  if(status != 0) throw std::runtime_error(std::string(call) + " returned HXT status " + std::to_string(status));
}

} // namespace

int main(int argc, char** argv)
{
  if(argc != 3) {
    std::fprintf(stderr, "usage: delaunay_benchmark_hxt POINTS THREADS\n");
    return 2;
  }
  const long kib_on_entry = resident_kib();
  try {
    const std::vector<double> xyz = read_points(argv[1]);
    const int threads = std::atoi(argv[2]);
    if(threads < 1) throw std::invalid_argument(std::string("THREADS must be at least 1, not ") + argv[2]);
    const std::uint32_t n = static_cast<std::uint32_t>(xyz.size() / 3);
    // HXT aborts the process on an empty bounding box.
    if(n < 4) throw std::invalid_argument("fewer than 4 points: nothing for HXT to tetrahedralize");

    Hxt_run run;
    const auto start = std::chrono::steady_clock::now();
    check(hxtMeshCreate(&run.mesh), "hxtMeshCreate");
    // 64-byte alignment, as HXT's allocator gives, for its vector loads.
    run.coordinates = static_cast<double*>(std::aligned_alloc(64, (4 * sizeof(double) * n + 63) / 64 * 64));
    if(!run.coordinates) throw std::bad_alloc();
    for(std::uint32_t i = 0; i < n; ++i) {
      for(int a = 0; a < 3; ++a) run.coordinates[4 * i + a] = xyz[3 * i + a];
      run.coordinates[4 * i + 3] = 0;
    }
    run.mesh->vertices.coord = run.coordinates;
    run.mesh->vertices.num = run.mesh->vertices.size = n;
    Hxt_delaunay_options options = {nullptr, nullptr, 0, 0, 0.0, 1, 0, 0, threads};
    check(hxtDelaunay(run.mesh, &options), "hxtDelaunay");
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

    // A triangulation of the points: every vertex of a tetrahedron one of them (HXT drops duplicates), about six
    // and a half finite tetrahedra per vertex for points in general position.
    const std::uint32_t vertices = run.mesh->vertices.num;
    std::uint64_t finite = 0;
    for(std::uint64_t t = 0; t < run.mesh->tetrahedra.num; ++t) {
      const std::uint32_t* node = run.mesh->tetrahedra.node + 4 * t;
      for(int k = 0; k < 4; ++k)
        if(node[k] >= vertices && !(k == 3 && node[k] == ghost_vertex))
          throw std::runtime_error("hxtDelaunay returned tetrahedron " + std::to_string(t) + " with vertex " +
                                   std::to_string(node[k]) + " of " + std::to_string(vertices));
      finite += node[3] != ghost_vertex;
    }
    if(vertices > n || (n >= 4 && finite == 0))
      throw std::runtime_error("hxtDelaunay returned " + std::to_string(finite) + " tetrahedra on " +
                               std::to_string(vertices) + " of " + std::to_string(n) + " points");

    rusage usage;
    ::getrusage(RUSAGE_SELF, &usage);
    std::printf("%.6f %llu %ld\n", seconds, static_cast<unsigned long long>(finite), usage.ru_maxrss - kib_on_entry);
    return 0;
  } catch(const std::exception& e) {
    std::fprintf(stderr, "delaunay_benchmark_hxt: %s\n", e.what());
    return 1;
  }
}
