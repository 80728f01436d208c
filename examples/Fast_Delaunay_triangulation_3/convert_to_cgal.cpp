// Triangulate fast, then hand the result to CGAL code that needs CGAL's own
// triangulation type: CGAL::Alpha_shape_3 derives from the triangulation, so
// it cannot take a Fast_Delaunay_triangulation_3.  convert_to_cgal creates
// the CGAL triangulation's vertices and cells directly (linear time, nothing
// re-inserted); the file round trip shows CGAL's text format, which both
// classes read and write.

#include <CGAL/Alpha_shape_3.h>
#include <CGAL/Alpha_shape_cell_base_3.h>
#include <CGAL/Alpha_shape_vertex_base_3.h>
#include <CGAL/Delaunay_triangulation_3.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fast_Delaunay_triangulation_3.h>
#include <CGAL/Fast_Delaunay_triangulation_3/convert_to_cgal.h>
#include <CGAL/Random.h>

#include <iostream>
#include <sstream>
#include <vector>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;

typedef CGAL::Alpha_shape_vertex_base_3<K> Vb;
typedef CGAL::Alpha_shape_cell_base_3<K> Fb;
typedef CGAL::Triangulation_data_structure_3<Vb, Fb> Tds;
typedef CGAL::Delaunay_triangulation_3<K, Tds> Delaunay;
typedef CGAL::Alpha_shape_3<Delaunay> Alpha_shape;

int main()
{
  CGAL::Random random(7);
  std::vector<Point> points;
  for(int i = 0; i < 20000; ++i)
    points.push_back(Point(random.get_double(), random.get_double(), random.get_double()));

  const CGAL::Fast_Delaunay_triangulation_3<K> fast(points.begin(), points.end());

  Delaunay delaunay;
  CGAL::convert_to_cgal(fast, delaunay);
  std::cout << "CGAL triangulation: " << delaunay.number_of_finite_cells() << " finite cells, valid "
            << std::boolalpha << delaunay.is_valid() << "\n";

  // Alpha_shape_3 takes the triangulation over (it swaps it in).
  Alpha_shape shape(delaunay, 0, Alpha_shape::REGULARIZED);
  shape.set_alpha(*shape.find_optimal_alpha(1));
  std::cout << "smallest alpha with one solid component: " << shape.get_alpha() << "\n";

  // CGAL's file format, written by ours, read back by ours (and by CGAL's
  // operator>> as well).  Precision 17 makes the round trip exact.
  std::stringstream file;
  file.precision(17);
  file << fast;
  CGAL::Fast_Delaunay_triangulation_3<K> copy;
  std::string error;
  if(!copy.read(file, &error)) {
    std::cerr << "read failed: " << error << "\n";
    return 1;
  }
  std::cout << "read back: " << copy.number_of_finite_cells() << " finite cells\n";
  return 0;
}
