// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// mpirun -np K fast_delaunay_3_mpi POINTS [--threads T] [-o OUT.pvtu | -o OUT.msh] [--write-cells PREFIX]
//                                  [--json] [--quiet]
//
// The Delaunay tetrahedralization of a point cloud over the ranks of MPI_COMM_WORLD
// (Distributed_Delaunay_triangulation_3.h): every rank ends with the tetrahedra it owns, named by the points'
// 0-based positions in POINTS. An .xyz file is read by every rank in parallel, each its own byte range; the other
// formats of fast_delaunay_3 (.ply, .off, .npy) are read by rank 0 and scattered.
//   -o OUT.pvtu         one VTK piece per rank (OUT.RANK.vtu beside it, with the points' global ids as point data)
//                       and the .pvtu that gathers them, for ParaView;
//   -o OUT.msh          one Gmsh 4.1 file per rank, OUT.RANK.msh, node tags = global ids + 1: the pieces of a
//                       partitioned mesh that share the tags of their common nodes;
//   --write-cells P     each rank writes P.RANK.txt: its tetrahedra, one a line, four 0-based point numbers;
//   --json              rank 0 prints one JSON line of figures (per phase, the slowest rank) for the benchmark.
// Bad input (an unreadable file, a line that is not three numbers, a coordinate that is not finite) is reported by
// rank 0 with the same words on every rank's behalf, and every rank exits with status 1.

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Distributed_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/Point_cloud_io.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/Mesh_file_writers.h>

#include <mpi.h>
#include <sys/resource.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Distributed_Delaunay_triangulation_3<K> Distributed;
typedef Distributed::Global_id Global_id;
typedef CGAL::Fast_Delaunay_triangulation_3_internal::distributed::Communicator Communicator;
namespace point_files = CGAL::Fast_Delaunay_triangulation_3_internal::point_files;

struct Options
{
  std::string points, output, cells_prefix;
  int threads = 1;
  bool json = false, quiet = false;
};

const char* usage_text =
    "usage: mpirun -np K fast_delaunay_3_mpi POINTS [--threads T] [-o OUT.pvtu|OUT.msh] [--write-cells PREFIX]\n"
    "                                       [--json] [--quiet]\n"
    "  POINTS               .xyz (x y z per line; read by every rank, each a byte range), .ply, .off, .npy\n"
    "  --threads T          threads of each rank's shared-memory engine (default 1)\n"
    "  -o OUT.pvtu          one VTK piece per rank, OUT.RANK.vtu, and the .pvtu gathering them\n"
    "  -o OUT.msh           one Gmsh 4.1 file per rank, OUT.RANK.msh, node tags = point numbers + 1\n"
    "  --write-cells PREFIX each rank writes PREFIX.RANK.txt: its tetrahedra, four 0-based point numbers a line\n"
    "  --json               one JSON line of figures on rank 0 (the benchmark's input)\n"
    "  --quiet              print nothing but errors\n";

// Empty if the arguments are fine, else what is wrong.
std::string parse(int argc, char** argv, Options& o)
{
  for(int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto value = [&]() -> std::string { return i + 1 < argc ? argv[++i] : std::string(); };
    if(a == "--threads") {
      const std::string v = value();
      if(!point_files::parse_integer(v, o.threads) || o.threads < 0) return "--threads wants a count, got '" + v + "'";
    } else if(a == "-o") {
      o.output = value();
      const std::string e = point_files::lower_extension(o.output);
      if(e != "pvtu" && e != "msh") return "-o wants a .pvtu or .msh file name, got '" + o.output + "'";
    } else if(a == "--write-cells") {
      o.cells_prefix = value();
      if(o.cells_prefix.empty()) return "--write-cells wants a prefix";
    } else if(a == "--json") {
      o.json = true;
    } else if(a == "--quiet") {
      o.quiet = true;
    } else if(a == "-h" || a == "--help") {
      return "help";
    } else if(!a.empty() && a[0] == '-') {
      return "unknown option " + a;
    } else if(o.points.empty()) {
      o.points = a;
    } else {
      return "one POINTS file expected, got '" + o.points + "' and '" + a + "'";
    }
  }
  return o.points.empty() ? "no POINTS file" : std::string();
}

// This rank's share of the points and how far it got; a complaint names a line counted from this rank's first.
struct Share
{
  std::vector<double> xyz;
  std::size_t lines = 0;       // lines that start in this rank's byte range
  std::size_t bad_line = 0;    // 1-based within those; 0: none
  std::string complaint;
};

// The lines that start in bytes [size * rank / ranks, size * (rank + 1) / ranks) of an .xyz file.
Share read_xyz_range(const std::string& path, int rank, int ranks)
{
  Share share;
  std::ifstream in(path, std::ios::binary);
  if(!in) {
    share.complaint = "cannot open " + path;
    return share;
  }
  in.seekg(0, std::ios::end);
  const std::uint64_t size = std::uint64_t(in.tellg());
  const std::uint64_t begin = size * std::uint64_t(rank) / std::uint64_t(ranks);
  const std::uint64_t end = size * std::uint64_t(rank + 1) / std::uint64_t(ranks);
  // One byte before the range says whether a line starts at its first byte; bytes after it finish its last line.
  const std::uint64_t first = begin == 0 ? 0 : begin - 1;
  std::string bytes(std::size_t(end - first), '\0');
  in.seekg(std::streamoff(first));
  in.read(&bytes[0], std::streamsize(bytes.size()));
  if(end < size && (bytes.empty() || bytes.back() != '\n')) {
    std::string rest;
    std::getline(in, rest);
    bytes += rest;
  }
  std::size_t i = 0;
  if(begin > 0) {
    const std::size_t newline = bytes.find('\n');
    i = newline == std::string::npos ? bytes.size() : newline + 1;
  }
  while(i < bytes.size() && first + i < end) {
    std::size_t stop = bytes.find('\n', i);
    if(stop == std::string::npos) stop = bytes.size();
    const std::string_view line(bytes.data() + i, stop - i);
    ++share.lines;
    i = stop + 1;
    if(point_files::is_comment_or_blank(line)) continue;
    point_files::Words words(line, true);
    std::string_view word;
    double p[3];
    for(int a = 0; a < 3; ++a) {
      if(!words.next(word)) {
        share.complaint = std::to_string(a) + (a == 1 ? " column" : " columns") + ", expected at least 3 (x y z)";
      } else if(!point_files::parse_double(word, p[a])) {
        share.complaint = point_files::quoted(word) + " is not a number";
      }
      if(!share.complaint.empty()) {
        share.bad_line = share.lines;
        return share;
      }
    }
    share.xyz.insert(share.xyz.end(), p, p + 3);
  }
  return share;
}

// Rank 0 reads a whole file of another format and hands each rank an equal run of points.
Share read_and_scatter(const Communicator& comm, const std::string& path)
{
  Share share;
  std::vector<double> all;
  if(comm.rank() == 0) {
    try {
      all = CGAL::Fast_Delaunay_triangulation_3_io::read_points(path);
    } catch(const std::exception& e) {
      share.complaint = e.what();
    }
  }
  std::uint64_t n = all.size() / 3;
  MPI_Bcast(&n, 1, MPI_UINT64_T, 0, comm.get());
  std::vector<int> counts(std::size_t(comm.size())), offsets(std::size_t(comm.size()));
  for(int r = 0; r < comm.size(); ++r) {
    offsets[std::size_t(r)] = int(3 * (n * std::uint64_t(r) / std::uint64_t(comm.size())));
    counts[std::size_t(r)] = int(3 * (n * std::uint64_t(r + 1) / std::uint64_t(comm.size()))) - offsets[std::size_t(r)];
  }
  share.xyz.resize(std::size_t(counts[std::size_t(comm.rank())]));
  MPI_Scatterv(all.data(), counts.data(), offsets.data(), MPI_DOUBLE, share.xyz.data(), int(share.xyz.size()),
               MPI_DOUBLE, 0, comm.get());
  return share;
}

double peak_memory_gib()
{
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return double(usage.ru_maxrss) / (1024.0 * 1024.0);  // ru_maxrss is in KiB on Linux
}

// The owned tetrahedra of one rank as a mesh source for the writers (Mesh_file_writers.h), in local point numbers.
class Owned_piece
{
public:
  explicit Owned_piece(const Distributed& dt)
  {
    std::vector<std::uint32_t> number(dt.local_triangulation().number_of_vertices() + 2, ~std::uint32_t(0));
    dt.for_each_owned_cell([&](Distributed::Cell_handle c) {
      for(int k = 0; k < 4; ++k) {
        const Distributed::Vertex_handle v = c->vertex(k);
        if(v.index() >= number.size()) number.resize(2 * std::size_t(v.index()) + 2, ~std::uint32_t(0));
        std::uint32_t& n = number[v.index()];
        if(n == ~std::uint32_t(0)) {
          n = std::uint32_t(ids_.size());
          ids_.push_back(dt.global_id(v));
          const K::Point_3& p = v->point();
          xyz_.insert(xyz_.end(), {p.x(), p.y(), p.z()});
        }
        cells_.push_back(n);
      }
    });
  }
  std::size_t number_of_points() const { return ids_.size(); }
  const double* point(std::size_t i) const { return &xyz_[3 * i]; }
  std::size_t number_of_tetrahedra() const { return cells_.size() / 4; }
  template <class F>
  void for_each_tetrahedron(F f) const
  {
    for(std::size_t t = 0; t < cells_.size(); t += 4) f(&cells_[t], 1);
  }
  std::size_t number_of_triangles() const { return 0; }
  template <class F>
  void for_each_triangle(F) const {}
  int number_of_subdomains() const { return 1; }
  int number_of_surfaces() const { return 0; }
  const std::vector<Global_id>& global_ids() const { return ids_; }

private:
  std::vector<double> xyz_;
  std::vector<Global_id> ids_;
  std::vector<std::uint32_t> cells_;
};

std::string piece_name(const std::string& output, int rank, const char* extension)
{
  const std::size_t dot = output.find_last_of('.');
  return output.substr(0, dot) + "." + std::to_string(rank) + "." + extension;
}

std::string base_name(const std::string& path)
{
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

// Empty, or why the files could not be written.
std::string write_outputs(const Communicator& comm, const Options& o, const Distributed& dt)
{
  namespace writers = CGAL::Fast_Delaunay_triangulation_3_internal;
  try {
    if(!o.cells_prefix.empty()) {
      const std::string name = o.cells_prefix + "." + std::to_string(comm.rank()) + ".txt";
      std::ofstream out(name, std::ios::binary);
      writers::Output_buffer b(out);
      dt.for_each_owned_cell([&](Distributed::Cell_handle c) {
        const Distributed::Global_cell g = dt.global_cell(c);
        b.integer(g[0]).character(' ').integer(g[1]).character(' ').integer(g[2]).character(' ').integer(g[3])
            .character('\n');
      });
      b.flush();
      if(!out) return "cannot write " + name;
    }
    if(o.output.empty()) return std::string();
    const Owned_piece piece(dt);
    const std::uint64_t first_element_tag = comm.exclusive_prefix_sum(piece.number_of_tetrahedra()) + 1;
    const bool vtk = point_files::lower_extension(o.output) == "pvtu";
    const std::string name = piece_name(o.output, comm.rank(), vtk ? "vtu" : "msh");
    std::ofstream out(name, std::ios::binary);
    if(vtk) writers::write_vtu(out, piece, piece.global_ids().data());
    else writers::write_msh41(out, piece, piece.global_ids().data(), first_element_tag);
    if(!out) return "cannot write " + name;
    if(vtk && comm.rank() == 0) {
      std::ofstream p(o.output);
      p << "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" header_type=\"UInt64\">\n"
        << "<PUnstructuredGrid GhostLevel=\"0\">\n<PPoints>\n"
        << "<PDataArray type=\"Float64\" NumberOfComponents=\"3\"/>\n</PPoints>\n"
        << "<PPointData>\n<PDataArray type=\"UInt64\" Name=\"global_id\"/>\n</PPointData>\n";
      for(int r = 0; r < comm.size(); ++r) p << "<Piece Source=\"" << base_name(piece_name(o.output, r, "vtu")) << "\"/>\n";
      p << "</PUnstructuredGrid>\n</VTKFile>\n";
      if(!p) return "cannot write " + o.output;
    }
  } catch(const std::exception& e) {
    return e.what();
  }
  return std::string();
}

int run(const Communicator& comm, const Options& o)
{
  const auto start = std::chrono::steady_clock::now();
  const bool xyz = point_files::lower_extension(o.points) == "xyz" || point_files::lower_extension(o.points) == "txt";
  Share share = xyz ? read_xyz_range(o.points, comm.rank(), comm.size()) : read_and_scatter(comm, o.points);
  std::string complaint = share.complaint;
  if(xyz) {
    const std::uint64_t first_line = comm.exclusive_prefix_sum(share.lines);
    if(share.bad_line > 0) complaint = o.points + ":" + std::to_string(first_line + share.bad_line) + ": " + complaint;
  }
  complaint = comm.lowest_rank_complaint(complaint);
  if(!complaint.empty()) {
    if(comm.rank() == 0) std::fprintf(stderr, "fast_delaunay_3_mpi: %s\n", complaint.c_str());
    return 1;
  }
  const double read_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  CGAL::Distributed_delaunay_options options;
  options.threads = o.threads;
  try {
    const Distributed dt(comm.get(), share.xyz, options);
    share = Share();
    complaint = comm.lowest_rank_complaint(write_outputs(comm, o, dt));
    if(!complaint.empty()) {
      if(comm.rank() == 0) std::fprintf(stderr, "fast_delaunay_3_mpi: %s\n", complaint.c_str());
      return 1;
    }
    const double total_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    const CGAL::Distributed_delaunay_statistics& s = dt.statistics();
    const std::uint64_t points = comm.sum(s.input_points), tets = comm.sum(s.owned_cells);
    const std::uint64_t ghosts = comm.sum(s.ghost_points), bytes = comm.sum(s.bytes_sent);
    const std::uint64_t duplicates = comm.sum(s.duplicate_points), balls = comm.sum(s.balls_sent);
    const double peak = comm.max(peak_memory_gib()), lowest_peak = -comm.max(-peak_memory_gib());
    const double partition = comm.max(s.partition_seconds), local = comm.max(s.local_seconds);
    const double exchange = comm.max(s.exchange_seconds), finalize = comm.max(s.finalize_seconds);
    const double read = comm.max(read_seconds), total = comm.max(total_seconds);
    const double per_point = points > 0 ? double(bytes) / double(points) : 0;
    const double ghost_share = points > 0 ? double(ghosts) / double(points) : 0;
    if(comm.rank() == 0 && o.json) {
      std::printf("{\"ranks\": %d, \"threads\": %d, \"points\": %llu, \"tetrahedra\": %llu, \"duplicates\": %llu, "
                  "\"read_s\": %.4f, \"partition_s\": %.4f, \"local_s\": %.4f, \"exchange_s\": %.4f, "
                  "\"finalize_s\": %.4f, \"total_s\": %.4f, \"rounds\": %d, \"bytes_per_point\": %.2f, "
                  "\"balls\": %llu, \"ghost_share\": %.5f, \"peak_gib_max\": %.4f, \"peak_gib_min\": %.4f}\n",
                  comm.size(), o.threads, (unsigned long long)points, (unsigned long long)tets,
                  (unsigned long long)duplicates, read, partition, local, exchange, finalize, total,
                  s.exchange_rounds, per_point, (unsigned long long)balls, ghost_share, peak, lowest_peak);
    } else if(comm.rank() == 0 && !o.quiet) {
      std::printf("fast_delaunay_3_mpi: %llu points on %d ranks (%d threads each), %llu duplicates, %llu tetrahedra "
                  "(dimension %d); read %.2f s, partition %.2f s, local %.2f s, exchange %.2f s in %d rounds, "
                  "finalize %.2f s (slowest rank); sent %.1f bytes per point; ghosts %.2f%% of the points; "
                  "peak memory per rank %.2f GiB (lowest %.2f GiB)\n",
                  (unsigned long long)points, comm.size(), o.threads, (unsigned long long)duplicates,
                  (unsigned long long)tets, dt.dimension(), read, partition, local, exchange, s.exchange_rounds,
                  finalize, per_point, 100 * ghost_share, peak, lowest_peak);
    }
  } catch(const CGAL::Distributed_input_error& e) {
    if(comm.rank() == 0) std::fprintf(stderr, "fast_delaunay_3_mpi: %s\n", e.what());
    return 1;
  }
  return 0;
}

} // namespace

int main(int argc, char** argv)
{
  MPI_Init(&argc, &argv);
  int status = 0;
  {
    const Communicator comm(MPI_COMM_WORLD);
    Options o;
    const std::string wrong = parse(argc, argv, o);
    if(!wrong.empty()) {
      if(comm.rank() == 0) {
        if(wrong != "help") std::fprintf(stderr, "fast_delaunay_3_mpi: %s\n", wrong.c_str());
        std::fprintf(wrong == "help" ? stdout : stderr, "%s", usage_text);
      }
      status = wrong == "help" ? 0 : 2;
    } else {
      status = run(comm, o);
    }
  }
  MPI_Finalize();
  return status;
}
