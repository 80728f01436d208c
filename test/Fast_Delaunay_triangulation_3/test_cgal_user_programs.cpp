// The programs of CGAL's Triangulation_3 user manual, written as templates on
// the triangulation class and run once with CGAL::Delaunay_triangulation_3 and
// once with CGAL::Fast_Delaunay_triangulation_3 (issue 4: a user's program
// compiles unchanged but for the class name and prints the same output).
// Each program prints into a string; where CGAL's order is arbitrary (handle
// order, order of incident vertices or of the conflict zone) the program sorts
// what it prints by the points, so the two strings must be equal.
#include "triangulation_checks.h"

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/IO/Color.h>
#include <CGAL/Linear_cell_complex_for_combinatorial_map.h>
#include <CGAL/Triangulation_3_to_lcc.h>
#include <CGAL/Unique_hash_map.h>
#include <CGAL/point_generators_3.h>
#include <CGAL/Random.h>
#include <CGAL/Triangulation_data_structure_3.h>
#include <CGAL/Triangulation_vertex_base_with_info_3.h>

#include <boost/iterator/counting_iterator.hpp>
#include <boost/iterator/transform_iterator.hpp>
#include <boost/iterator/zip_iterator.hpp>

#include <algorithm>
#include <iterator>
#include <list>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

using namespace fdt3_test;

namespace test_cgal_user_programs {

// ---------------------------------------------------------------- printing helpers
template <class Tr>
std::string vertex_text(const Tr& t, typename Tr::Vertex_handle v)
{
  if(t.is_infinite(v)) return "inf";
  std::ostringstream os;
  os << '(' << v->point() << ')';
  return os.str();
}

template <class Tr>
std::string cell_text(const Tr& t, typename Tr::Cell_handle c)
{
  std::vector<std::string> vs;
  for(int i = 0; i < 4; ++i) vs.push_back(vertex_text(t, c->vertex(i)));
  std::sort(vs.begin(), vs.end());
  std::string s = "[";
  for(const std::string& v : vs) s += v + ' ';
  return s + ']';
}

template <class Tr>
std::string facet_text(const Tr& t, const typename Tr::Facet& f)
{
  std::vector<std::string> vs;
  for(int k = 1; k < 4; ++k) vs.push_back(vertex_text(t, f.first->vertex((f.second + k) & 3)));
  std::sort(vs.begin(), vs.end());
  std::string s = "<";
  for(const std::string& v : vs) s += v + ' ';
  return s + '>';
}

template <class Strings>
std::string sorted_lines(Strings lines)
{
  std::sort(lines.begin(), lines.end());
  std::string s;
  for(const std::string& l : lines) s += l + '\n';
  return s;
}

std::vector<Point> random_points(std::size_t n, int seed)
{
  CGAL::Random random(seed);
  CGAL::Random_points_in_cube_3<Point> generator(1.0, random);
  std::vector<Point> points;
  std::copy_n(generator, n, std::back_inserter(points));
  return points;
}

// ---------------------------------------------------------------- simple_triangulation_3
// Construction from a list, insertion of a range, locate, adjacency through
// the cells, incident vertices, write and read back.
template <class Triangulation>
std::string simple_triangulation()
{
  typedef typename Triangulation::Cell_handle Cell_handle;
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  typedef typename Triangulation::Locate_type Locate_type;
  std::ostringstream out;

  std::list<Point> L;
  L.push_front(Point(0, 0, 0));
  L.push_front(Point(1, 0, 0));
  L.push_front(Point(0, 1, 0));
  Triangulation T(L.begin(), L.end());
  typename Triangulation::size_type n = T.number_of_vertices();
  out << "dimension " << T.dimension() << " vertices " << n << '\n';

  std::vector<Point> V(3);
  V[0] = Point(0, 0, 1);
  V[1] = Point(1, 1, 1);
  V[2] = Point(2, 2, 2);
  n = n + T.insert(V.begin(), V.end());
  out << "vertices " << n << " valid " << T.is_valid() << " dimension " << T.dimension() << '\n';

  Locate_type lt;
  int li = 0, lj = 0;
  Point p(0, 0, 0);
  Cell_handle c = T.locate(p, lt, li, lj);
  out << "locate type " << int(lt) << " at vertex " << (c->vertex(li)->point() == p) << '\n';

  Vertex_handle v = c->vertex((li + 1) & 3);
  Cell_handle nc = c->neighbor(li);
  int nli = 0;
  out << "neighbour has vertex " << nc->has_vertex(v, nli) << " at " << (nc->vertex(nli) == v) << '\n';

  Vertex_handle w;
  out << "is_vertex (1 1 1) " << T.is_vertex(Point(1, 1, 1), w) << " (0.5 0.5 0.5) "
      << T.is_vertex(Point(0.5, 0.5, 0.5), w) << '\n';
  T.is_vertex(Point(1, 1, 1), w);
  std::vector<Vertex_handle> around;
  T.incident_vertices(w, std::back_inserter(around));
  std::vector<std::string> names;
  for(Vertex_handle u : around) names.push_back(vertex_text(T, u));
  out << "around (1 1 1):\n" << sorted_lines(names);

  std::stringstream file;
  file << T;
  Triangulation T1;
  file >> T1;
  out << "read back valid " << T1.is_valid() << " vertices " << T1.number_of_vertices() << " cells "
      << T1.number_of_cells() << " same cells count " << (T1.number_of_cells() == T.number_of_cells()) << '\n';
  return out.str();
}

// ---------------------------------------------------------------- fast_location_3 / hints
// The `v = T.insert(p, v)` idiom on a grid (degenerate: the symbolic
// perturbation decides), then locate and insert with a cell hint.
template <class Triangulation>
std::string insertion_with_hints()
{
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  typedef typename Triangulation::Cell_handle Cell_handle;
  std::ostringstream out;
  Triangulation T;
  Vertex_handle v;
  for(int z = 0; z < 5; ++z)
    for(int y = 0; y < 5; ++y)
      for(int x = 0; x < 5; ++x) v = T.insert(Point(x, y, z), v);
  out << "grid: vertices " << T.number_of_vertices() << " cells " << T.number_of_cells() << " finite "
      << T.number_of_finite_cells() << " valid " << T.is_valid() << '\n';

  for(const Point& p : random_points(200, 3)) {
    Cell_handle c = T.locate(p);
    T.insert(p, c);
  }
  out << "after hinted: vertices " << T.number_of_vertices() << " finite cells " << T.number_of_finite_cells()
      << " edges " << T.number_of_finite_edges() << " facets " << T.number_of_finite_facets() << '\n';

  // Not equidistant from two grid points: on a tie CGAL's answer depends
  // on its traversal order.
  const Point q(2.2, 2.4, 1.7);
  Vertex_handle nearest = T.nearest_vertex(q);
  out << "nearest to " << q << ": " << nearest->point() << '\n';
  std::vector<std::string> cells;
  for(Cell_handle c : T.finite_cell_handles())
    if(c->has_vertex(nearest)) cells.push_back(cell_text(T, c));
  out << "finite cells of nearest:\n" << sorted_lines(cells);
  return out.str();
}

// ---------------------------------------------------------------- info_insert_with_pair_iterator_3 and friends
typedef CGAL::Triangulation_vertex_base_with_info_3<unsigned, K> Vb_unsigned;
typedef CGAL::Triangulation_data_structure_3<Vb_unsigned, CGAL::Delaunay_triangulation_cell_base_3<K>> Tds_unsigned;

template <class Triangulation>
std::string check_infos(const Triangulation& T, const std::vector<Point>& points)
{
  std::ostringstream out;
  bool all = true;
  for(typename Triangulation::Finite_vertices_iterator vit = T.finite_vertices_begin();
      vit != T.finite_vertices_end(); ++vit)
    if(points[vit->info()] != vit->point()) all = false;
  out << "vertices " << T.number_of_vertices() << " infos match " << all << '\n';
  return out.str();
}

template <class Triangulation>
std::string info_with_pairs()
{
  std::vector<std::pair<Point, unsigned>> pairs;
  std::vector<Point> points = random_points(100, 5);
  for(unsigned i = 0; i < points.size(); ++i) pairs.push_back(std::make_pair(points[i], i));
  Triangulation T(pairs.begin(), pairs.end());
  return check_infos(T, points);
}

template <class Triangulation>
std::string info_with_zip_iterator()
{
  std::vector<Point> points = random_points(100, 6);
  std::vector<unsigned> indices;
  for(unsigned i = 0; i < points.size(); ++i) indices.push_back(i);
  Triangulation T(boost::make_zip_iterator(boost::make_tuple(points.begin(), indices.begin())),
                  boost::make_zip_iterator(boost::make_tuple(points.end(), indices.end())));
  return check_infos(T, points);
}

struct Auto_count
{
  const std::vector<Point>* points;
  typedef std::pair<Point, unsigned> result_type;
  std::pair<Point, unsigned> operator()(unsigned i) const { return std::make_pair((*points)[i], i); }
};

template <class Triangulation>
std::string info_with_transform_iterator()
{
  std::vector<Point> points = random_points(100, 7);
  Auto_count count{&points};
  Triangulation T(boost::make_transform_iterator(boost::counting_iterator<unsigned>(0), count),
                  boost::make_transform_iterator(boost::counting_iterator<unsigned>(unsigned(points.size())), count));
  return check_infos(T, points);
}

// ---------------------------------------------------------------- color_3: an info written through handles
typedef CGAL::Triangulation_vertex_base_with_info_3<CGAL::IO::Color, K> Vb_color;
typedef CGAL::Triangulation_data_structure_3<Vb_color, CGAL::Delaunay_triangulation_cell_base_3<K>> Tds_color;

template <class Triangulation>
std::string color_by_degree()
{
  Triangulation T;
  for(int z = 0; z < 3; ++z)
    for(int y = 0; y < 3; ++y)
      for(int x = 0; x < 3; ++x) T.insert(Point(x, y, z));
  for(typename Triangulation::Vertex_handle v : T.finite_vertex_handles())
    v->info() = T.degree(v) == 6 ? CGAL::IO::red() : CGAL::IO::blue();
  std::vector<std::string> lines;
  for(typename Triangulation::Vertex_handle v : T.finite_vertex_handles()) {
    std::ostringstream os;
    os << v->point() << " degree " << T.degree(v) << " red " << (v->info() == CGAL::IO::red());
    lines.push_back(os.str());
  }
  return sorted_lines(lines);
}

// ---------------------------------------------------------------- adding_handles_3: a user vertex base
// The manual's pattern: a vertex base with extra members, rebound to the data
// structure's handles through Rebind_TDS.
template <class GT, class Vb = CGAL::Triangulation_vertex_base_3<GT>>
class My_vertex_base : public Vb
{
public:
  typedef typename Vb::Vertex_handle Vertex_handle;
  typedef typename Vb::Cell_handle Cell_handle;
  typedef typename Vb::Point Point;

  template <class TDS2>
  struct Rebind_TDS
  {
    typedef typename Vb::template Rebind_TDS<TDS2>::Other Vb2;
    typedef My_vertex_base<GT, Vb2> Other;
  };

  My_vertex_base() {}
  My_vertex_base(const Point& p) : Vb(p) {}
  My_vertex_base(const Point& p, Cell_handle c) : Vb(p, c) {}

  Vertex_handle vh;
  Cell_handle ch;
  int color = 0;
  std::vector<Vertex_handle> marked;
};

typedef CGAL::Triangulation_data_structure_3<My_vertex_base<K>, CGAL::Delaunay_triangulation_cell_base_3<K>>
    Tds_handles;

template <class Triangulation>
std::string adding_handles()
{
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  std::ostringstream out;
  Triangulation T;
  Vertex_handle v0 = T.insert(Point(0, 0, 0));
  Vertex_handle v1 = T.insert(Point(0, 0, 1));
  Vertex_handle v2 = T.insert(Point(0, 1, 0));
  Vertex_handle v3 = T.insert(Point(1, 0, 0));
  Vertex_handle v4 = T.insert(Point(2, 2, 2));
  Vertex_handle v5 = T.insert(Point(-1, 0, 1));

  // A cycle of vertices, walked from v0.
  v0->vh = v1;
  v1->vh = v2;
  v2->vh = v3;
  v3->vh = v4;
  v4->vh = v5;
  v5->vh = v0;
  Vertex_handle v = v0;
  for(int k = 0; k < 7; ++k, v = v->vh) out << v->point() << " -> ";
  out << '\n';

  // Each vertex remembers one of its cells and its neighbours of larger x.
  for(typename Triangulation::Finite_vertices_iterator vit = T.finite_vertices_begin();
      vit != T.finite_vertices_end(); ++vit) {
    vit->ch = vit->cell();
    vit->color = int(T.degree(vit));
  }
  for(Vertex_handle u : T.finite_vertex_handles()) {
    std::vector<Vertex_handle> around;
    T.finite_adjacent_vertices(u, std::back_inserter(around));
    for(Vertex_handle w : around)
      if(w->point().x() > u->point().x()) u->marked.push_back(w);
  }
  std::vector<std::string> lines;
  for(Vertex_handle u : T.finite_vertex_handles()) {
    std::ostringstream os;
    os << u->point() << " color " << u->color << " cell has it " << u->ch->has_vertex(u) << " marked";
    std::vector<std::string> names;
    for(Vertex_handle w : u->marked) names.push_back(vertex_text(T, w));
    std::sort(names.begin(), names.end());
    for(const std::string& name : names) os << ' ' << name;
    lines.push_back(os.str());
  }
  out << sorted_lines(lines);

  // The members survive later insertions, and a copy of the triangulation
  // has its own.
  T.insert(Point(0.25, 0.25, 0.25));
  Triangulation copy(T);
  Vertex_handle c0;
  copy.is_vertex(Point(0, 0, 0), c0);
  c0->color = -1;
  out << "after insertion: v0 color " << v0->color << " next " << v0->vh->point() << " copy color " << c0->color
      << " copy next " << c0->vh->point() << '\n';
  out << "valid " << T.is_valid() << ' ' << copy.is_valid() << '\n';
  return out.str();
}

// ---------------------------------------------------------------- a user base under an info, with an id()
// Infos given with the points reach a user base layered below
// Triangulation_vertex_base_with_info_3; the user's id() is not hidden.
template <class GT, class Vb = CGAL::Triangulation_vertex_base_3<GT>>
class Vertex_base_with_id : public Vb
{
public:
  typedef typename Vb::Cell_handle Cell_handle;
  typedef typename Vb::Point Point;

  template <class TDS2>
  struct Rebind_TDS
  {
    typedef typename Vb::template Rebind_TDS<TDS2>::Other Vb2;
    typedef Vertex_base_with_id<GT, Vb2> Other;
  };

  std::size_t& id() { return id_; }
  std::size_t id() const { return id_; }

private:
  std::size_t id_ = 0;
};

typedef CGAL::Triangulation_vertex_base_with_info_3<unsigned, K, Vertex_base_with_id<K>> Vb_info_id;
typedef CGAL::Triangulation_data_structure_3<Vb_info_id, CGAL::Delaunay_triangulation_cell_base_3<K>> Tds_info_id;

template <class Triangulation>
std::string info_over_user_base()
{
  std::vector<std::pair<Point, unsigned>> pairs;
  std::vector<Point> points = random_points(60, 11);
  for(unsigned i = 0; i < points.size(); ++i) pairs.push_back(std::make_pair(points[i], i));
  Triangulation T(pairs.begin(), pairs.end());
  // Ids in the order of the infos, then read back through the cells.
  for(typename Triangulation::Vertex_handle v : T.finite_vertex_handles()) v->id() = 1000 + v->info();
  // Before the next insertion: CGAL leaves the new vertex's unsigned info
  // uninitialised.
  const std::string infos = check_infos(T, points);
  T.insert(Point(0.5, 0.5, 0.5));
  std::vector<std::string> lines;
  for(typename Triangulation::Cell_handle c : T.finite_cell_handles()) {
    std::ostringstream os;
    std::vector<std::size_t> ids;
    for(int i = 0; i < 4; ++i) ids.push_back(c->vertex(i)->id());
    std::sort(ids.begin(), ids.end());
    for(std::size_t id : ids) os << id << ' ';
    lines.push_back(os.str());
  }
  return infos + sorted_lines(lines);
}

// ---------------------------------------------------------------- a user cell base
// Cells with members of their own: a depth (the number of facets to cross to
// reach the outside) found by breadth-first search through c->neighbor(i),
// with the cell it was reached from.
template <class GT, class Cb = CGAL::Delaunay_triangulation_cell_base_3<GT>>
class My_cell_base : public Cb
{
public:
  typedef typename Cb::Vertex_handle Vertex_handle;
  typedef typename Cb::Cell_handle Cell_handle;

  template <class TDS2>
  struct Rebind_TDS
  {
    typedef typename Cb::template Rebind_TDS<TDS2>::Other Cb2;
    typedef My_cell_base<GT, Cb2> Other;
  };

  My_cell_base() {}
  My_cell_base(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Vertex_handle v3) : Cb(v0, v1, v2, v3) {}
  My_cell_base(Vertex_handle v0, Vertex_handle v1, Vertex_handle v2, Vertex_handle v3, Cell_handle n0,
               Cell_handle n1, Cell_handle n2, Cell_handle n3)
      : Cb(v0, v1, v2, v3, n0, n1, n2, n3)
  {}

  int depth = -1;
  Cell_handle parent;
};

typedef CGAL::Triangulation_data_structure_3<My_vertex_base<K>, My_cell_base<K>> Tds_cells;

template <class Triangulation>
std::string cell_depths()
{
  typedef typename Triangulation::Cell_handle Cell_handle;
  std::ostringstream out;
  std::vector<Point> points = random_points(150, 17);
  Triangulation T(points.begin(), points.end());
  std::vector<Cell_handle> front;
  for(Cell_handle c : T.all_cell_handles())
    if(T.is_infinite(c)) {
      c->depth = 0;
      front.push_back(c);
    }
  for(std::size_t k = 0; k < front.size(); ++k)
    for(int i = 0; i < 4; ++i) {
      Cell_handle n = front[k]->neighbor(i);
      if(n->depth >= 0) continue;
      n->depth = front[k]->depth + 1;
      n->parent = front[k];
      front.push_back(n);
    }
  std::vector<std::string> lines;
  bool parents = true;
  for(typename Triangulation::Finite_cells_iterator c = T.finite_cells_begin(); c != T.finite_cells_end(); ++c) {
    std::ostringstream os;
    os << cell_text(T, c) << " depth " << c->depth;
    lines.push_back(os.str());
    parents = parents && c->parent->depth + 1 == c->depth && c->has_neighbor(c->parent);
  }
  Cell_handle c = T.locate(Point(0, 0, 0));
  const Point center = c->circumcenter();
  out << "parents " << parents << " circumcenter " << (center == T.dual(c)) << '\n' << sorted_lines(lines);

  // Cells made by an insertion are new: their members are default again.
  typename Triangulation::Vertex_handle v = T.insert(Point(0.01, 0.02, 0.03));
  std::vector<Cell_handle> ball;
  T.incident_cells(v, std::back_inserter(ball));
  int reset = 0;
  for(Cell_handle b : ball) reset += b->depth == -1;
  out << "new cells " << ball.size() << " reset " << reset << " valid " << T.is_valid() << '\n';
  return out.str();
}

// ---------------------------------------------------------------- find_conflicts
template <class Triangulation>
std::string conflicts()
{
  typedef typename Triangulation::Cell_handle Cell_handle;
  typedef typename Triangulation::Facet Facet;
  std::ostringstream out;
  std::vector<Point> points = random_points(300, 9);
  Triangulation T(points.begin(), points.end());
  const Point p(0.1, -0.2, 0.3);
  Cell_handle c = T.locate(p);
  std::vector<Facet> boundary;
  std::vector<Cell_handle> cells;
  std::vector<Facet> internal;
  T.find_conflicts(p, c, std::back_inserter(boundary), std::back_inserter(cells), std::back_inserter(internal));
  std::vector<std::string> lines;
  for(Cell_handle k : cells) lines.push_back("cell " + cell_text(T, k));
  for(const Facet& f : boundary) lines.push_back("boundary " + facet_text(T, f));
  for(const Facet& f : internal) lines.push_back("internal " + facet_text(T, f));
  out << sorted_lines(lines);

  std::vector<typename Triangulation::Vertex_handle> vertices;
  T.vertices_on_conflict_zone_boundary(p, c, std::back_inserter(vertices));
  std::vector<std::string> names;
  for(auto v : vertices) names.push_back(vertex_text(T, v));
  out << "boundary vertices\n" << sorted_lines(names);

  // Inserting into the zone gives the cells a plain insertion would.
  Triangulation U(T);
  auto v = T.insert_in_hole(p, cells.begin(), cells.end(), boundary.front().first, boundary.front().second);
  U.insert(p);
  out << "degree " << T.degree(v) << " same as insert " << (T == U) << " valid " << T.is_valid() << '\n';
  return out.str();
}

// ---------------------------------------------------------------- simplices
// Every face as a Simplex, reached from several cells: a set holds each face
// once, and the conversions give the face back.
template <class Triangulation>
std::string simplices()
{
  typedef typename Triangulation::Simplex Simplex;
  typedef typename Triangulation::Vertex_handle Vertex_handle;
  typedef typename Triangulation::Cell_handle Cell_handle;
  typedef typename Triangulation::Edge Edge;
  typedef typename Triangulation::Facet Facet;
  std::ostringstream out;
  std::vector<Point> points = random_points(80, 13);
  Triangulation T(points.begin(), points.end());

  std::set<Simplex> faces;
  std::size_t representations = 0;
  for(Cell_handle c : T.finite_cell_handles()) {
    faces.insert(Simplex(c));
    for(int i = 0; i < 4; ++i) {
      faces.insert(Simplex(c->vertex(i)));
      faces.insert(Simplex(Facet(c, i)));
      faces.insert(Simplex(T.mirror_facet(Facet(c, i))));
      for(int j = 0; j < 4; ++j)
        if(i != j) faces.insert(Simplex(Edge(c, i, j)));
      representations += 1 + 2 + 3 + 4;
    }
  }
  std::size_t count[4] = {0, 0, 0, 0};
  bool round_trip = true;
  for(const Simplex& s : faces) {
    ++count[s.dimension()];
    switch(s.dimension()) {
      case 0: { Vertex_handle v = s; round_trip = round_trip && Simplex(v) == s; break; }
      case 1: { Edge e = s; round_trip = round_trip && Simplex(Edge(e.first, e.third, e.second)) == s; break; }
      case 2: { Facet f = s; round_trip = round_trip && Simplex(T.mirror_facet(f)) == s; break; }
      case 3: { Cell_handle c = s; round_trip = round_trip && c->has_vertex(c->vertex(0)); break; }
    }
  }
  out << "representations " << (representations > faces.size()) << " vertices " << count[0] << " edges " << count[1]
      << " facets " << count[2] << " cells " << count[3] << " round trip " << round_trip << '\n';
  out << "counts " << T.number_of_vertices() << ' ' << T.number_of_edges() << ' ' << T.number_of_facets() << ' '
      << T.number_of_cells() << '\n';
  // Edges and facets from the iterators are the same faces.
  std::size_t found = 0;
  for(typename Triangulation::Finite_edges_iterator e = T.finite_edges_begin(); e != T.finite_edges_end(); ++e)
    found += faces.count(Simplex(*e));
  for(typename Triangulation::Finite_facets_iterator f = T.finite_facets_begin(); f != T.finite_facets_end(); ++f)
    found += faces.count(Simplex(*f));
  out << "iterated faces found " << found << " of " << T.number_of_finite_edges() + T.number_of_finite_facets()
      << '\n';
  out << "undefined < vertex " << (Simplex() < Simplex(T.finite_vertices_begin())) << '\n';
  return out.str();
}

// ---------------------------------------------------------------- segment traverser
template <class Triangulation>
std::string segment_traverser()
{
  typedef typename Triangulation::Cell_handle Cell_handle;
  std::ostringstream out;
  std::vector<Point> points = random_points(400, 15);
  Triangulation T(points.begin(), points.end());
  std::vector<Point> ends = random_points(20, 16);
  for(std::size_t k = 0; k + 1 < ends.size(); k += 2) {
    const Point p(ends[k].x() / 2, ends[k].y() / 2, ends[k].z() / 2);
    const Point q(ends[k + 1].x() / 2, ends[k + 1].y() / 2, ends[k + 1].z() / 2);
    typename Triangulation::Segment_cell_iterator ct = T.segment_traverser_cells_begin(p, q);
    typename Triangulation::Segment_cell_iterator end = T.segment_traverser_cells_end();
    std::size_t cells = 0, infinite = 0;
    for(; ct != end; ++ct) {
      Cell_handle c = ct;
      ++cells;
      if(T.is_infinite(c)) ++infinite;
    }
    out << "segment " << k / 2 << ": " << cells << " cells, " << infinite << " infinite\n";
    for(Cell_handle c : T.segment_traverser_cell_handles(p, q)) out << "  " << cell_text(T, c) << '\n';
  }
  // Between vertices (a segment between two vertices stays in the hull).
  std::vector<typename Triangulation::Vertex_handle> vertices;
  for(const Point& p : ends) {
    typename Triangulation::Vertex_handle v;
    if(!T.is_vertex(p, v)) v = T.nearest_vertex(p);
    vertices.push_back(v);
  }
  for(std::size_t k = 0; k + 1 < vertices.size(); k += 2) {
    if(vertices[k] == vertices[k + 1]) continue;
    out << "from " << vertices[k]->point() << " to " << vertices[k + 1]->point() << '\n';
    for(Cell_handle c : T.segment_traverser_cell_handles(vertices[k], vertices[k + 1]))
      out << "  " << cell_text(T, c) << '\n';
  }
  return out.str();
}

// ---------------------------------------------------------------- the tests
// ---------------------------------------------------------------- CGAL packages over the triangulation
// CGAL's Alpha_shape_3 derives from the triangulation class given.  Both
// comparison modes: the exact one keeps references to the vertices' points
// (Lazy_alpha_nt_3) and evaluates from them later.  Random points, and the
// four nearly coplanar points of CGAL's own exact-alpha example.
template <class Alpha_tag>
struct Alpha_tds
{
  typedef CGAL::Alpha_shape_vertex_base_3<K, CGAL::Default, Alpha_tag> Vb;
  typedef CGAL::Alpha_shape_cell_base_3<K, CGAL::Default, Alpha_tag> Cb;
  typedef CGAL::Triangulation_data_structure_3<Vb, Cb> type;
};
template <class Alpha_tag, class Triangulation>
std::string alpha_shape_of(const std::vector<Point>& points)
{
  typedef CGAL::Alpha_shape_3<Triangulation, Alpha_tag> Alpha_shape;
  std::ostringstream os;
  // Alphas are squared radii computed from a cell's points in its vertex
  // order, which is not CGAL's: the last bits may differ.
  os.precision(12);
  Alpha_shape shape(points.begin(), points.end(), 0, Alpha_shape::GENERAL);
  os << shape.number_of_alphas() << " alphas";
  if(shape.number_of_alphas() == 0) return os.str();
  const auto optimal = shape.find_optimal_alpha(1);
  os << ", optimal " << CGAL::to_double(*optimal);
  shape.set_alpha(*optimal);
  os << ", solid components " << shape.number_of_solid_components();
  std::vector<typename Alpha_shape::Facet> facets[3];
  shape.get_alpha_shape_facets(std::back_inserter(facets[0]), Alpha_shape::REGULAR);
  shape.get_alpha_shape_facets(std::back_inserter(facets[1]), Alpha_shape::SINGULAR);
  shape.get_alpha_shape_facets(std::back_inserter(facets[2]), Alpha_shape::INTERIOR);
  os << ", facets regular " << facets[0].size() << " singular " << facets[1].size() << " interior "
     << facets[2].size();
  std::vector<std::string> regular;
  for(const auto& f : facets[0]) regular.push_back(facet_text(shape, f));
  return os.str() + "\n" + sorted_lines(regular);
}
template <template <class...> class Dt>
std::string alpha_shapes()
{
  std::vector<Point> points = to_points<Point>(uniform_points(400, 31));
  const std::vector<Point> nearly_flat = {Point(49.2559, 29.1767, 6.7723), Point(49.3696, 31.4775, 5.33777),
                                          Point(49.4264, 32.6279, 4.6205), Point(49.3127, 30.3271, 6.05503)};
  return alpha_shape_of<CGAL::Tag_false, Dt<K, typename Alpha_tds<CGAL::Tag_false>::type>>(points) +
         alpha_shape_of<CGAL::Tag_true, Dt<K, typename Alpha_tds<CGAL::Tag_true>::type>>(points) +
         alpha_shape_of<CGAL::Tag_true, Dt<K, typename Alpha_tds<CGAL::Tag_true>::type>>(nearly_flat);
}

// Linear_cell_complex's import, as CGAL's voronoi_3 example calls it: it
// keys std::maps by Cell_handle and looks Cell_iterators up in them.  Then
// CGAL's Unique_hash_map over handles, looked up by copies of the handles.
template <class Triangulation>
std::string linear_cell_complex_import()
{
  typedef CGAL::Linear_cell_complex_for_combinatorial_map<3> Lcc;
  const std::vector<Point> points = to_points<Point>(uniform_points(300, 32));
  const Triangulation T(points.begin(), points.end());
  Lcc lcc;
  std::map<typename Triangulation::Cell_handle, typename Lcc::Dart_handle> dart_of_cell;
  CGAL::import_from_triangulation_3(lcc, T, &dart_of_cell);
  std::ostringstream os;
  lcc.display_characteristics(os) << ", valid " << lcc.is_valid() << ", cells " << dart_of_cell.size() << '\n';
  CGAL::Unique_hash_map<typename Triangulation::Cell_handle, int> number(-1);
  int n = 0;
  for(typename Triangulation::Cell_iterator c = T.cells_begin(); c != T.cells_end(); ++c) number[c] = n++;
  std::size_t symmetric = 0;
  for(typename Triangulation::Cell_handle c : T.all_cell_handles())
    for(int i = 0; i < 4; ++i) {
      const typename Triangulation::Cell_handle d = c->neighbor(i);
      if(number[d] >= 0 && number[d->neighbor(d->index(c))] == number[c]) ++symmetric;
    }
  os << n << " cells numbered, " << symmetric << " neighbour pairs found back\n";
  return os.str();
}

template <class Cgal, class Fast, class Program>
void expect_same_output(Program program_of)
{
  const std::string expected = program_of(static_cast<Cgal*>(nullptr));
  const std::string actual = program_of(static_cast<Fast*>(nullptr));
  EXPECT_FALSE(expected.empty());
  EXPECT_EQ(expected, actual);
}

#define FDT3_SAME_OUTPUT(Cgal_type, Fast_type, program)                                                    \
  expect_same_output<Cgal_type, Fast_type>([](auto* tag) {                                                  \
    return program<std::remove_pointer_t<decltype(tag)>>();                                                 \
  })

typedef CGAL::Fast_Delaunay_triangulation_3<K> Fast_dt;

TEST(CgalUserPrograms, SimpleTriangulation) { FDT3_SAME_OUTPUT(Cgal_dt, Fast_dt, simple_triangulation); }

TEST(CgalUserPrograms, InsertionWithHints) { FDT3_SAME_OUTPUT(Cgal_dt, Fast_dt, insertion_with_hints); }

TEST(CgalUserPrograms, InfoWithPairs)
{
  typedef CGAL::Delaunay_triangulation_3<K, Tds_unsigned> Cgal_info;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds_unsigned> Fast_info;
  FDT3_SAME_OUTPUT(Cgal_info, Fast_info, info_with_pairs);
  FDT3_SAME_OUTPUT(Cgal_info, Fast_info, info_with_zip_iterator);
  FDT3_SAME_OUTPUT(Cgal_info, Fast_info, info_with_transform_iterator);
}

TEST(CgalUserPrograms, ColorInfo)
{
  typedef CGAL::Delaunay_triangulation_3<K, Tds_color> Cgal_color;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds_color> Fast_color;
  FDT3_SAME_OUTPUT(Cgal_color, Fast_color, color_by_degree);
}

TEST(CgalUserPrograms, AddingHandles)
{
  typedef CGAL::Delaunay_triangulation_3<K, Tds_handles> Cgal_handles;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds_handles> Fast_handles;
  FDT3_SAME_OUTPUT(Cgal_handles, Fast_handles, adding_handles);
}

TEST(CgalUserPrograms, InfoOverUserBase)
{
  typedef CGAL::Delaunay_triangulation_3<K, Tds_info_id> Cgal_info_id;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds_info_id> Fast_info_id;
  FDT3_SAME_OUTPUT(Cgal_info_id, Fast_info_id, info_over_user_base);
}

// Without a user base the vertices stay facades over the flat arrays (of
// the triangulation layer, as CGAL names it: Tr_Base).
static_assert(std::is_same<Fast_dt::Vertex,
                           CGAL::Fast_Delaunay_triangulation_3_internal::Vertex_facade<Fast_dt::Tr_Base>>::value,
              "default vertices are facades");
typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds_color> Fast_with_color;
static_assert(std::is_same<Fast_with_color::Vertex,
                           CGAL::Fast_Delaunay_triangulation_3_internal::Vertex_facade<Fast_with_color::Tr_Base>>::value,
              "vertices with an info only are facades");

TEST(CgalUserPrograms, UserCellBase)
{
  typedef CGAL::Delaunay_triangulation_3<K, Tds_cells> Cgal_cells;
  typedef CGAL::Fast_Delaunay_triangulation_3<K, Tds_cells> Fast_cells;
  FDT3_SAME_OUTPUT(Cgal_cells, Fast_cells, cell_depths);
  FDT3_SAME_OUTPUT(Cgal_cells, Fast_cells, adding_handles);
  EXPECT_NE(cell_depths<Fast_cells>().find("parents 1 circumcenter 1"), std::string::npos);
}

TEST(CgalPackages, AlphaShape3)
{
  const std::string cgal = alpha_shapes<CGAL::Delaunay_triangulation_3>();
  EXPECT_NE(cgal.find("solid components 1"), std::string::npos) << cgal;
  EXPECT_EQ(alpha_shapes<CGAL::Fast_Delaunay_triangulation_3>(), cgal);
}

TEST(CgalPackages, LinearCellComplexImport)
{
  FDT3_SAME_OUTPUT(Cgal_dt, Fast_dt, linear_cell_complex_import);
  EXPECT_NE(linear_cell_complex_import<Fast_dt>().find("valid 1"), std::string::npos);
}

TEST(CgalUserPrograms, FindConflicts) { FDT3_SAME_OUTPUT(Cgal_dt, Fast_dt, conflicts); }

TEST(CgalUserPrograms, Simplices) { FDT3_SAME_OUTPUT(Cgal_dt, Fast_dt, simplices); }

TEST(CgalUserPrograms, SegmentTraverser)
{
  FDT3_SAME_OUTPUT(Cgal_dt, Fast_dt, segment_traverser);
  // The walks cross facets: more cells listed than segments.
  const std::string text = segment_traverser<Fast_dt>();
  EXPECT_GT(std::count(text.begin(), text.end(), '['), 30);
}

} // namespace test_cgal_user_programs
