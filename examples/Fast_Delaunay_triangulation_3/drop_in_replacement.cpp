// Code written for CGAL::Delaunay_triangulation_3 compiles unchanged with
// CGAL::Fast_Delaunay_triangulation_3.  describe() below uses only the CGAL
// interface (counts, finite facet and edge iterators, cells and neighbours,
// vertex handles as std::map keys) and is called with both classes on the same
// points.  The points are small integers: many are repeated, and many groups of
// four are coplanar or five cospherical.  Both triangulations still print the
// same lines, because both break those ties with the same symbolic
// perturbation and both store a repeated point once.

#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Random.h>

#include <cstddef>
#include <iostream>
#include <map>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

template <class Triangulation>
void describe(const Triangulation& tr)
{
  typedef typename Triangulation::Vertex_handle Vertex_handle;

  std::cout << "  vertices " << tr.number_of_vertices() << ", finite cells " << tr.number_of_finite_cells()
            << ", finite facets " << tr.number_of_finite_facets() << ", finite edges "
            << tr.number_of_finite_edges() << "\n";

  // A facet (c, i) lies on the convex hull when one of its two cells is infinite.
  std::size_t hull_facets = 0;
  for(auto f = tr.finite_facets_begin(); f != tr.finite_facets_end(); ++f)
    if(tr.is_infinite(f->first) || tr.is_infinite(f->first->neighbor(f->second)))
      ++hull_facets;

  // Vertex degrees, with the vertex handles as map keys.
  std::map<Vertex_handle, int> degree;
  double squared_lengths = 0;
  for(auto e = tr.finite_edges_begin(); e != tr.finite_edges_end(); ++e) {
    const Vertex_handle a = e->first->vertex(e->second);
    const Vertex_handle b = e->first->vertex(e->third);
    ++degree[a];
    ++degree[b];
    squared_lengths += CGAL::squared_distance(a->point(), b->point());
  }

  // The vertex of highest degree; ties go to the lexicographically smallest
  // point, so that the choice does not depend on the order of the map.
  Vertex_handle busiest;
  for(const auto& vd : degree)
    if(busiest == Vertex_handle() || vd.second > degree[busiest] ||
       (vd.second == degree[busiest] && vd.first->point() < busiest->point()))
      busiest = vd.first;

  std::cout << "  hull facets " << hull_facets << ", sum of squared edge lengths " << squared_lengths << "\n"
            << "  highest degree " << degree[busiest] << " at (" << busiest->point() << ")\n"
            << "  valid " << std::boolalpha << tr.is_valid() << "\n";
}

int main()
{
  // 400 random nodes of a 6 x 6 x 6 integer grid, so some are drawn twice.
  CGAL::Random random(3);
  std::vector<Point> points;
  for(int k = 0; k < 400; ++k)
    points.push_back(Point(random.get_int(0, 6), random.get_int(0, 6), random.get_int(0, 6)));

  const CGAL::Delaunay_triangulation_3<K> cgal(points.begin(), points.end());
  const CGAL::Fast_Delaunay_triangulation_3<K> fast(points.begin(), points.end());

  std::cout << points.size() << " input points\n";
  std::cout << "CGAL::Delaunay_triangulation_3\n";
  describe(cgal);
  std::cout << "CGAL::Fast_Delaunay_triangulation_3\n";
  describe(fast);
  return 0;
}
