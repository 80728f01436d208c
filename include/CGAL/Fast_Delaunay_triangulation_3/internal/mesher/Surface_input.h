// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The input of the mesher (paper §4: "a set of triangles t that defines the
// boundary of a closed volume"): one or more triangulated surfaces read as
// polygon soups, their equal vertices merged, and checked before any
// tetrahedron is built.  A surface that is not the closed, oriented,
// non-self-intersecting boundary of a volume is refused with an
// Invalid_surface exception that names the problem and the triangles.
//
// Triangle numbers in the messages are positions in the merged soup: the
// triangles of the first file first, in file order, then the second file's.

#ifndef CGAL_FDT3_INTERNAL_MESHER_SURFACE_INPUT_H
#define CGAL_FDT3_INTERNAL_MESHER_SURFACE_INPUT_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/IO/polygon_soup_io.h>
#include <CGAL/Polygon_mesh_processing/orient_polygon_soup.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/self_intersections.h>
#include <CGAL/Surface_mesh.h>

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Predicates.h>
#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Records_by_vertex.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

// Thrown for an input the mesher cannot take; what() names the problem.
class Invalid_surface : public std::invalid_argument
{
public:
  explicit Invalid_surface(const std::string& what) : std::invalid_argument(what) {}
};

// Triangles with merged vertices.  surface[t] is the closed surface (the
// connected component, numbered from 1) that triangle t belongs to.
struct Surface_soup
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<int> surface;
  int number_of_surfaces = 0;
};

namespace surface_detail {

// Lists at most a few indices: a message stays readable on a broken input
// with thousands of bad triangles.
template <class Range>
std::string list_of(const Range& indices, std::size_t at_most = 10)
{
  std::ostringstream s;
  std::size_t k = 0;
  for(const auto& i : indices) {
    if(k == at_most) {
      s << ", ... (" << indices.size() << " in all)";
      break;
    }
    s << (k == 0 ? "" : ", ") << i;
    ++k;
  }
  return s.str();
}

inline void fail(const std::string& what) { throw Invalid_surface("Tetrahedral_mesher: " + what); }

// Every edge of the soup, undirected, with the triangles using it and the
// direction each uses it in (+1 from the smaller id to the larger): the
// uses sorted by edge, then by triangle, in one array, built once for the
// checks and the surface numbers (on bunny00 a map took 0.05 s, a vector of
// uses per edge, built twice, 0.055 s, this 0.017 s); the uses of edge k
// are uses[first[k]] to uses[first[k + 1]].
struct Edge_uses
{
  struct Use
  {
    std::uint64_t edge; // smaller id << 32 | larger id
    std::uint32_t triangle;
    int direction;
  };
  std::vector<Use> uses;
  std::vector<std::size_t> first;

  explicit Edge_uses(const Surface_soup& soup)
  {
    uses.reserve(3 * soup.triangles.size());
    for(std::uint32_t t = 0; t < soup.triangles.size(); ++t)
      for(int i = 0; i < 3; ++i) {
        const std::uint64_t a = soup.triangles[t][i], b = soup.triangles[t][(i + 1) % 3];
        uses.push_back({std::min(a, b) << 32 | std::max(a, b), t, a < b ? 1 : -1});
      }
    std::sort(uses.begin(), uses.end(), [](const Use& x, const Use& y) {
      return x.edge != y.edge ? x.edge < y.edge : x.triangle < y.triangle;
    });
    for(std::size_t k = 0; k < uses.size(); ++k)
      if(k == 0 || uses[k].edge != uses[k - 1].edge) first.push_back(k);
    first.push_back(uses.size());
  }

  std::size_t number_of_edges() const { return first.size() - 1; }
  const Use* begin(std::size_t k) const { return uses.data() + first[k]; }
  const Use* end(std::size_t k) const { return uses.data() + first[k + 1]; }
};

// The lines of a text held in memory, as views into it, each without its
// comment (`#` to the end of the line), blank ones skipped, with their
// numbers; and the words of a line.
class Line_reader
{
public:
  explicit Line_reader(const std::string& text) : text_(text) {}

  // The next line with a word in it (false at the end); line_number() is its line.
  bool next(std::string_view& line)
  {
    while(position_ < text_.size()) {
      const std::size_t end = std::min(text_.find('\n', position_), text_.size());
      std::string_view content(text_.data() + position_, end - position_);
      content = content.substr(0, content.find('#'));
      position_ = end + 1;
      ++number_;
      if(content.find_first_not_of(spaces) != std::string_view::npos) {
        line = content;
        return true;
      }
    }
    return false;
  }

  std::size_t line_number() const { return number_; }

  // The words of `line`, in `words`.
  static void split(std::string_view line, std::vector<std::string_view>& words)
  {
    words.clear();
    for(std::size_t first = line.find_first_not_of(spaces); first != std::string_view::npos;) {
      const std::size_t last = std::min(line.find_first_of(spaces, first), line.size());
      words.push_back(line.substr(first, last - first));
      first = line.find_first_not_of(spaces, last);
    }
  }

private:
  static constexpr const char* spaces = " \t\r\v\f";
  const std::string& text_;
  std::size_t position_ = 0, number_ = 0;
};

inline bool all_digits(std::string_view word)
{
  return !word.empty() && word.find_first_not_of("0123456789") == std::string_view::npos;
}

// The value of a word of at most 18 digits (all_digits).
inline std::uintmax_t digits_value(std::string_view word)
{
  std::uintmax_t n = 0;
  for(char c : word) n = 10 * n + std::uintmax_t(c - '0');
  return n;
}

// The whole file, for the OFF reader.
inline std::string file_text(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if(!in) fail("cannot open '" + path + "'");
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  if(size < 0) fail("cannot read '" + path + "'");
  std::string text(static_cast<std::size_t>(size), '\0');
  in.seekg(0);
  in.read(&text[0], static_cast<std::streamsize>(text.size()));
  if(!in) fail("cannot read '" + path + "'");
  return text;
}

// CGAL's reader answers every defect of an OFF file with one "cannot read";
// this reader of ASCII OFF files (header "OFF") names the first defect and
// its line: the counts, a coordinate that is not a finite decimal number
// (nan, inf, 0x10, 1e400), a face index out of range.  A well-formed file
// gives what CGAL's reader gives (a vertex or a face a line, words after
// the coordinates or the indices, colours, left aside), in the same doubles
// (CGAL converts with sscanf, which rounds as strtod does); where CGAL
// reads the start of a word (3abc as 3) this reader refuses it.  One pass
// over the file in memory: checking bunny00 (2.6 MB) first and then
// reading it with CGAL took 0.18 s, this 0.04 s.
// False, with nothing read, for the other headers (COFF, NOFF, OFF BINARY,
// ...), which CGAL reads.
inline bool read_ascii_off(const std::string& path, std::vector<std::array<double, 3>>& points,
                           std::vector<std::vector<std::size_t>>& polygons)
{
  const std::string text = file_text(path);
  Line_reader lines(text);
  std::string_view line;
  std::vector<std::string_view> words;
  auto where = [&]() { return "'" + path + "', line " + std::to_string(lines.line_number()) + ": "; };
  auto quoted = [](std::string_view w) { return "'" + std::string(w) + "'"; };
  // The header: "OFF", then the numbers of vertices, faces and edges, on
  // its line or the next ones.
  std::size_t word = 0;
  auto next_word = [&](const char* what) {
    while(word == words.size()) {
      if(!lines.next(line)) fail(where() + "the file ends before the number of " + what);
      Line_reader::split(line, words);
      word = 0;
    }
    return words[word++];
  };
  if(!lines.next(line)) return false;
  Line_reader::split(line, words);
  if(words[word++] != "OFF") return false;
  // A count: digits only, at most what the file's bytes can hold (a vertex
  // takes at least 6 bytes, "0 0 0\n", a face 8).
  auto count = [&](std::string_view w, const char* what, std::uintmax_t bytes_each) -> std::uintmax_t {
    if(!all_digits(w)) fail(where() + "the number of " + what + " is " + quoted(w) + ", not a count");
    const std::uintmax_t n = w.size() > 18 ? std::uintmax_t(-2) : digits_value(w);
    if(n > text.size() / bytes_each)
      fail(where() + "the file claims " + std::string(w) + " " + what + ", more than its " +
           std::to_string(text.size()) + " bytes can hold");
    return n;
  };
  const std::string_view first_count = next_word("vertices");
  if(first_count == "BINARY") return false; // OFF BINARY
  const std::uintmax_t vertices = count(first_count, "vertices", 6);
  const std::uintmax_t faces = count(next_word("faces"), "faces", 8);
  // The number of edges is not used: CGAL takes any integer there, -1 too.
  const std::string_view edges = next_word("edges");
  if(!(edges.size() > 1 && edges[0] == '-' && all_digits(edges.substr(1)))) count(edges, "edges", 1);
  std::vector<std::array<double, 3>> file_points(vertices);
  for(std::uintmax_t v = 0; v < vertices; ++v) {
    if(!lines.next(line))
      fail(where() + "the file ends before vertex " + std::to_string(v) + " of " + std::to_string(vertices));
    Line_reader::split(line, words);
    if(words.size() < 3)
      fail(where() + "vertex " + std::to_string(v) + " has " + std::to_string(words.size()) +
           " coordinates, not 3");
    for(int a = 0; a < 3; ++a) {
      // Decimal only, as CGAL reads (strtod would take hexadecimal, nan and
      // inf).  A word ends at a space, a '#', a line's end or the text's
      // terminating null, where strtod stops too.  Underflow is no defect:
      // tiny values read as CGAL reads them, subnormal or zero.
      char* end = nullptr;
      const double x = words[a].find_first_not_of("0123456789.eE+-") == std::string_view::npos
                           ? std::strtod(words[a].data(), &end)
                           : 0;
      if(end != words[a].data() + words[a].size())
        fail(where() + "vertex " + std::to_string(v) + " has coordinate " + quoted(words[a]) +
             ", not a finite decimal number (NaN, infinities and hexadecimal are refused)");
      if(!std::isfinite(x))
        fail(where() + "vertex " + std::to_string(v) + " has coordinate " + quoted(words[a]) +
             ", not a finite double (out of range)");
      file_points[v][a] = x;
    }
  }
  std::vector<std::vector<std::size_t>> file_polygons(faces);
  for(std::uintmax_t f = 0; f < faces; ++f) {
    if(!lines.next(line))
      fail(where() + "the file ends before face " + std::to_string(f) + " of " + std::to_string(faces));
    Line_reader::split(line, words);
    if(!all_digits(words[0]) || words[0].size() > 9)
      fail(where() + "face " + std::to_string(f) + " starts with " + quoted(words[0]) +
           ", not a number of vertices");
    const std::size_t corners = digits_value(words[0]);
    if(words.size() <= corners)
      fail(where() + "face " + std::to_string(f) + " has " + std::to_string(words.size() - 1) + " of its " +
           std::to_string(corners) + " vertices");
    std::vector<std::size_t>& polygon = file_polygons[f];
    polygon.resize(corners);
    for(std::size_t k = 0; k < corners; ++k) {
      const std::string_view w = words[k + 1];
      if(!all_digits(w) || w.size() > 18 || digits_value(w) >= vertices)
        fail(where() + "face " + std::to_string(f) + " refers to vertex " + quoted(w) + ", not one of the " +
             std::to_string(vertices) + " vertices");
      polygon[k] = digits_value(w);
    }
  }
  points = std::move(file_points);
  polygons = std::move(file_polygons);
  return true;
}

} // namespace surface_detail

// Appends the polygon soup of one file to `points` / `polygons`: ASCII OFF
// with read_ascii_off, any other format CGAL::IO::read_polygon_soup reads
// (COFF, binary OFF, STL, OBJ, PLY, ...) with it.
inline void read_soup_file(const std::string& path, std::vector<std::array<double, 3>>& points,
                           std::vector<std::vector<std::size_t>>& polygons)
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  std::ifstream probe(path, std::ios::binary);
  if(!probe) surface_detail::fail("cannot open '" + path + "'");
  if(probe.peek() == std::ifstream::traits_type::eof()) surface_detail::fail("'" + path + "' is an empty file");
  const std::string extension = path.size() >= 4 ? path.substr(path.size() - 4) : std::string();
  std::vector<std::array<double, 3>> file_points;
  std::vector<std::vector<std::size_t>> file_polygons;
  if(!((extension == ".off" || extension == ".OFF") &&
       surface_detail::read_ascii_off(path, file_points, file_polygons))) {
    std::vector<K::Point_3> cgal_points;
    if(!IO::read_polygon_soup(path, cgal_points, file_polygons, parameters::verbose(false)))
      surface_detail::fail("cannot read '" + path + "' as a polygon soup (OFF, STL, OBJ, PLY)");
    for(const K::Point_3& p : cgal_points) file_points.push_back({p.x(), p.y(), p.z()});
  }
  const std::size_t offset = points.size();
  points.insert(points.end(), file_points.begin(), file_points.end());
  for(std::vector<std::size_t>& polygon : file_polygons) {
    for(std::size_t& v : polygon) v += offset;
    polygons.push_back(std::move(polygon));
  }
}

// Merges equal points and keeps triangles only (anything else is refused).
inline Surface_soup merge_soup(const std::vector<std::array<double, 3>>& points,
                               const std::vector<std::vector<std::size_t>>& polygons)
{
  using surface_detail::fail;
  if(polygons.empty()) fail("the input has no triangles (empty file?)");
  for(std::size_t i = 0; i < points.size(); ++i)
    for(int a = 0; a < 3; ++a)
      if(!std::isfinite(points[i][a])) {
        std::ostringstream s;
        s << "point #" << i << " has a " << (std::isnan(points[i][a]) ? "NaN" : "infinite") << " coordinate";
        fail(s.str());
      }
  // Equal points get the number of the first of them; numbers in the order
  // of first appearance.  (Sorted, not a map: the map took 0.01 to 0.03 s
  // on bunny00.)
  if(points.size() > std::numeric_limits<std::uint32_t>::max())
    fail("more than 2^32 - 1 points: the mesher numbers them in 32 bits");
  Surface_soup soup;
  std::vector<std::array<double, 3>> keys(points);
  for(auto& key : keys)
    for(double& x : key) x = x + 0.0; // -0.0 and 0.0 are the same point
  std::vector<std::uint32_t> order(points.size()), merged(points.size());
  for(std::uint32_t i = 0; i < order.size(); ++i) order[i] = i;
  std::sort(order.begin(), order.end(),
            [&](std::uint32_t a, std::uint32_t b) { return keys[a] != keys[b] ? keys[a] < keys[b] : a < b; });
  for(std::size_t k = 0; k < order.size(); ++k) // the first of its equals
    merged[order[k]] = k > 0 && keys[order[k]] == keys[order[k - 1]] ? merged[order[k - 1]] : order[k];
  for(std::size_t i = 0; i < points.size(); ++i) {
    if(merged[i] == i) {
      merged[i] = static_cast<std::uint32_t>(soup.points.size());
      soup.points.push_back(keys[i]);
    } else {
      merged[i] = merged[merged[i]]; // an earlier point, numbered already
    }
  }
  for(std::size_t t = 0; t < polygons.size(); ++t) {
    if(polygons[t].size() != 3) {
      std::ostringstream s;
      s << "polygon #" << t << " has " << polygons[t].size() << " vertices; only triangles are meshed";
      fail(s.str());
    }
    std::array<std::uint32_t, 3> tri;
    for(int i = 0; i < 3; ++i) {
      if(polygons[t][i] >= points.size()) {
        std::ostringstream s;
        s << "triangle #" << t << " refers to point #" << polygons[t][i] << ", past the " << points.size()
          << " points";
        fail(s.str());
      }
      tri[i] = merged[polygons[t][i]];
    }
    soup.triangles.push_back(tri);
  }
  return soup;
}

// Repeated vertices (after merging) and zero area (collinear vertices, exact).
inline void check_degenerate_triangles(const Surface_soup& soup)
{
  std::vector<std::size_t> bad;
  for(std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const auto& v = soup.triangles[t];
    if(v[0] == v[1] || v[1] == v[2] || v[2] == v[0] ||
       collinear(soup.points[v[0]].data(), soup.points[v[1]].data(), soup.points[v[2]].data()))
      bad.push_back(t);
  }
  if(!bad.empty())
    surface_detail::fail("degenerate triangles (repeated vertex or zero area): #" + surface_detail::list_of(bad));
}

// Closed, manifold at edges, consistently oriented, no triangle twice: every
// edge is used by exactly two triangles, in opposite directions.
inline void check_closed_oriented_manifold(const surface_detail::Edge_uses& edges)
{
  using namespace surface_detail;
  std::vector<std::size_t> open, non_manifold, flipped;
  for(std::size_t k = 0; k < edges.number_of_edges(); ++k) {
    const Edge_uses::Use* u = edges.begin(k);
    const std::size_t n = std::size_t(edges.end(k) - u);
    if(n == 1) open.push_back(u[0].triangle);
    else if(n > 2)
      for(const Edge_uses::Use* e = u; e != edges.end(k); ++e) non_manifold.push_back(e->triangle);
    else if(u[0].direction == u[1].direction) {
      flipped.push_back(u[0].triangle);
      flipped.push_back(u[1].triangle);
    }
  }
  for(std::vector<std::size_t>* list : {&open, &non_manifold, &flipped}) {
    std::sort(list->begin(), list->end());
    list->erase(std::unique(list->begin(), list->end()), list->end());
  }
  if(!open.empty()) fail("the surface is open: triangles with a boundary edge #" + list_of(open));
  if(!non_manifold.empty())
    fail("non-manifold edges (more than two triangles): triangles #" + list_of(non_manifold));
  if(!flipped.empty())
    fail("inconsistent orientation: neighbouring triangles with the same edge direction #" + list_of(flipped));
}

// Around every vertex, one fan of triangles: two surfaces, or two sheets of
// one, may not touch at a vertex (CGAL's Surface_mesh, which the
// self-intersection test builds, could not hold them either).  The
// surface is closed, edge-manifold and oriented (checked before), so each
// directed edge a -> b is in one triangle and b -> a in another: from a
// triangle (v, x, y), the next one around v is the one with x -> v.  A
// vertex whose walk comes back before it met all its triangles is named.
inline void check_manifold_vertices(const Surface_soup& soup)
{
  using namespace surface_detail;
  const std::size_t n = soup.points.size();
  // The directed edges (corner i to corner i + 1 of a triangle) by their
  // first vertex: (second vertex, triangle).
  const Records_by_vertex<std::pair<std::uint32_t, std::uint32_t>> edges(
      n, 3 * soup.triangles.size(), [&](std::size_t e) { return soup.triangles[e / 3][e % 3]; },
      [&](std::size_t e) {
        return std::make_pair(soup.triangles[e / 3][(e % 3 + 1) % 3], static_cast<std::uint32_t>(e / 3));
      });
  const std::vector<std::size_t>& begin = edges.begin;
  const auto& out = edges.records;
  auto triangle_of = [&](std::uint32_t a, std::uint32_t b) { // the one with a -> b
    const auto found = std::lower_bound(out.begin() + begin[a], out.begin() + begin[a + 1],
                                        std::make_pair(b, std::uint32_t(0)));
    CGAL_assertion(found != out.begin() + begin[a + 1] && found->first == b);
    return found->second;
  };
  auto after = [&](std::uint32_t t, std::uint32_t v) { // the corner after v in t
    const auto& c = soup.triangles[t];
    return c[0] == v ? c[1] : c[1] == v ? c[2] : c[0];
  };
  std::vector<std::uint32_t> bad;
  for(std::uint32_t v = 0; v < n; ++v) {
    const std::size_t fan = begin[v + 1] - begin[v];
    if(fan == 0) continue;
    const std::uint32_t first = out[begin[v]].second;
    std::size_t met = 0;
    std::uint32_t t = first;
    do {
      t = triangle_of(after(t, v), v);
      ++met;
    } while(t != first && met <= fan);
    if(met != fan) bad.push_back(v);
  }
  if(!bad.empty()) {
    const auto& p = soup.points[bad.front()];
    std::ostringstream first;
    first << " (the first at " << p[0] << ", " << p[1] << ", " << p[2] << ")";
    fail("non-manifold vertices: two surfaces or two sheets of one surface touch at a vertex: points #" +
         list_of(bad) + first.str());
  }
}

// Numbers the closed surfaces: connected components through shared edges.
inline void number_surfaces(Surface_soup& soup, const surface_detail::Edge_uses& edges)
{
  const std::size_t n = soup.triangles.size();
  std::vector<std::uint32_t> parent(n);
  for(std::uint32_t t = 0; t < n; ++t) parent[t] = t;
  auto root = [&](std::uint32_t t) {
    while(parent[t] != t) t = parent[t] = parent[parent[t]];
    return t;
  };
  for(std::size_t k = 0; k < edges.number_of_edges(); ++k)
    for(const auto* use = edges.begin(k); use != edges.end(k); ++use)
      parent[root(use->triangle)] = root(edges.begin(k)->triangle);
  std::vector<int> number(n, 0);
  soup.surface.assign(n, 0);
  soup.number_of_surfaces = 0;
  for(std::uint32_t t = 0; t < n; ++t) {
    int& s = number[root(t)];
    if(s == 0) s = ++soup.number_of_surfaces;
    soup.surface[t] = s;
  }
}

// Self-intersections with CGAL's exact test on the soup as a Surface_mesh
// (faces keep the soup's order); the soup is a closed manifold surface
// (checked before), which the Surface_mesh can hold.
inline void check_self_intersections(const Surface_soup& soup)
{
  typedef Exact_predicates_inexact_constructions_kernel K;
  typedef Surface_mesh<K::Point_3> Mesh;
  std::vector<K::Point_3> points;
  for(const auto& p : soup.points) points.emplace_back(p[0], p[1], p[2]);
  std::vector<std::vector<std::size_t>> faces;
  for(const auto& t : soup.triangles) faces.push_back({t[0], t[1], t[2]});
  Mesh mesh;
  Polygon_mesh_processing::polygon_soup_to_polygon_mesh(points, faces, mesh);
  CGAL_assertion(mesh.number_of_faces() == soup.triangles.size());
  std::vector<std::pair<Mesh::Face_index, Mesh::Face_index>> pairs;
  Polygon_mesh_processing::self_intersections(mesh, std::back_inserter(pairs));
  if(pairs.empty()) return;
  std::vector<std::string> described;
  for(const auto& p : pairs) {
    std::ostringstream s;
    s << std::size_t(p.first) << " x " << std::size_t(p.second);
    described.push_back(s.str());
  }
  surface_detail::fail("self-intersecting surface: intersecting triangle pairs #" +
                       surface_detail::list_of(described));
}

// Every closed surface must face outward (its triangles counterclockwise
// seen from outside), nested ones included: each bounds a volume of its own.
// The volume a closed surface encloses, summed over its triangles as cones
// from one of its points, is positive then; inside out, it is negative.
// (A closed surface without self-intersections encloses a volume far above
// the rounding of that sum.)  The differences are scaled by a power of two
// that brings the coordinates below 1, so that cubes of 1e200 or 1e-200 do
// not overflow or vanish.
inline double largest_coordinate(const Surface_soup& soup)
{
  double largest = 0;
  for(const auto& p : soup.points)
    for(double x : p) largest = std::max(largest, std::abs(x));
  return largest;
}

inline void check_outward_orientation(const Surface_soup& soup)
{
  int exponent = 0;
  std::frexp(largest_coordinate(soup), &exponent);
  std::vector<double> volume(soup.number_of_surfaces + 1, 0);
  std::vector<const std::array<double, 3>*> apex(soup.number_of_surfaces + 1, nullptr);
  std::vector<std::size_t> first(soup.number_of_surfaces + 1, 0);
  for(std::size_t t = 0; t < soup.triangles.size(); ++t) {
    const int s = soup.surface[t];
    const auto& a = soup.points[soup.triangles[t][0]];
    const auto& b = soup.points[soup.triangles[t][1]];
    const auto& c = soup.points[soup.triangles[t][2]];
    if(apex[s] == nullptr) {
      apex[s] = &a;
      first[s] = t;
    }
    const auto& o = *apex[s];
    double u[3], v[3], w[3];
    for(int k = 0; k < 3; ++k) {
      u[k] = std::ldexp(a[k], -exponent) - std::ldexp(o[k], -exponent);
      v[k] = std::ldexp(b[k], -exponent) - std::ldexp(o[k], -exponent);
      w[k] = std::ldexp(c[k], -exponent) - std::ldexp(o[k], -exponent);
    }
    volume[s] += (u[0] * (v[1] * w[2] - v[2] * w[1]) - u[1] * (v[0] * w[2] - v[2] * w[0]) +
                  u[2] * (v[0] * w[1] - v[1] * w[0])) / 6;
  }
  for(int s = 1; s <= soup.number_of_surfaces; ++s)
    if(!(volume[s] > 0)) {
      std::ostringstream message;
      message << "surface " << s << " (the one with triangle #" << first[s] << ") is inside out: its triangles face "
              << "inward (the volume it encloses comes out negative); reverse their orientation";
      surface_detail::fail(message.str());
    }
}

// The checks, from the cheapest to the costliest, then the surface numbers.
inline Surface_soup checked(Surface_soup soup)
{
  check_degenerate_triangles(soup);
  const surface_detail::Edge_uses edges(soup);
  check_closed_oriented_manifold(edges);
  check_manifold_vertices(soup);
  check_self_intersections(soup);
  number_surfaces(soup, edges);
  check_outward_orientation(soup);
  return soup;
}

inline Surface_soup read_surfaces(const std::vector<std::string>& paths)
{
  std::vector<std::array<double, 3>> points;
  std::vector<std::vector<std::size_t>> polygons;
  for(const std::string& path : paths) read_soup_file(path, points, polygons);
  return checked(merge_soup(points, polygons));
}

// The same for triangles given in memory.
inline Surface_soup surfaces_from_triangles(const std::vector<std::array<double, 3>>& points,
                                            const std::vector<std::array<std::size_t, 3>>& triangles)
{
  std::vector<std::vector<std::size_t>> polygons;
  for(const auto& t : triangles) polygons.push_back({t[0], t[1], t[2]});
  return checked(merge_soup(points, polygons));
}

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_SURFACE_INPUT_H
