// Triangulate random points, print the counts, add up the volumes of the
// finite cells and check the result.  The finite cells tile the convex hull of
// the points, so their total volume is the hull's volume (a little under 8 for
// points drawn in the cube [-1, 1]^3).

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/point_generators_3.h>

#include <algorithm>
#include <iostream>
#include <iterator>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Fast_Delaunay_triangulation_3<K> Triangulation;
typedef Triangulation::Point Point;
typedef Triangulation::Cell_handle Cell_handle;

int main()
{
  CGAL::Random random(42);
  CGAL::Random_points_in_cube_3<Point> generator(1.0, random);
  std::vector<Point> points;
  std::copy_n(generator, 10000, std::back_inserter(points));

  Triangulation triangulation(points.begin(), points.end());

  std::cout << "dimension:      " << triangulation.dimension() << "\n"
            << "vertices:       " << triangulation.number_of_vertices() << "\n"
            << "finite cells:   " << triangulation.number_of_finite_cells() << "\n"
            << "finite facets:  " << triangulation.number_of_finite_facets() << "\n"
            << "finite edges:   " << triangulation.number_of_finite_edges() << "\n"
            << "all cells:      " << triangulation.number_of_cells()
            << " (the others have the infinite vertex)\n";

  double volume = 0;
  for(Cell_handle c : triangulation.finite_cell_handles())
    volume += triangulation.tetrahedron(c).volume();
  std::cout << "total volume:   " << volume << "\n";

  std::cout << "is_valid:       " << std::boolalpha << triangulation.is_valid() << std::endl;
  return triangulation.is_valid() ? 0 : 1;
}
