// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Equality of two triangulations given by points (operator== between two
// Fast_Delaunay_triangulation_3, or with a CGAL::Delaunay_triangulation_3):
// the meaning of CGAL's operator== on Triangulation_3, an isomorphism that
// maps each vertex to the vertex with the same point.  Vertex and cell
// numbering differ between the two, so both sides are reduced to sorted
// lists of point tuples through the public interface only.

#ifndef CGAL_FDT3_INTERNAL_EQUALITY_H
#define CGAL_FDT3_INTERNAL_EQUALITY_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Kernel_points.h>

#include <CGAL/number_utils.h>

#include <algorithm>
#include <array>
#include <vector>

namespace CGAL {

// Declared without its default arguments (CGAL's header gives them), so that
// operator== can name it without pulling in CGAL's triangulation.
template <class Gt, class Tds_, class Location_policy, class Lock_data_structure_>
class Delaunay_triangulation_3;

namespace Fast_Delaunay_triangulation_3_internal {

typedef std::array<double, 3> Point_tuple;

// Only for vertices whose coordinates are doubles (see sorted_vertex_tuples).
template <class Point>
Point_tuple point_tuple(const Point& p)
{
  return {{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())}};
}

// False if a vertex has coordinates that are no doubles: an exact kernel's
// CGAL triangulation may have one, this package's triangulations never do,
// so such a triangulation equals none of ours (and rounding it could make
// two different points one).
template <class Tr>
bool sorted_vertex_tuples(const Tr& tr, std::vector<Point_tuple>& keys)
{
  keys.clear();
  keys.reserve(tr.number_of_vertices());
  for(auto v = tr.finite_vertices_begin(); v != tr.finite_vertices_end(); ++v) {
    Point_tuple k;
    if(!exact_coordinates(v->point(), k.data())) return false;
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return true;
}

template <class Tr>
std::vector<std::array<Point_tuple, 4>> sorted_cell_tuples(const Tr& tr)
{
  std::vector<std::array<Point_tuple, 4>> keys;
  keys.reserve(tr.number_of_finite_cells());
  for(auto c = tr.finite_cells_begin(); c != tr.finite_cells_end(); ++c) {
    std::array<Point_tuple, 4> k;
    for(int i = 0; i < 4; ++i) k[i] = point_tuple(c->vertex(i)->point());
    std::sort(k.begin(), k.end());
    keys.push_back(k);
  }
  std::sort(keys.begin(), keys.end());
  return keys;
}

// Same dimension and vertices; in dimension 3 the same finite cells (the
// infinite ones are determined by the hull of the finite ones).  Below
// dimension 3 the vertices decide: see the comment of operator==.
template <class A, class B>
bool same_triangulation(const A& a, const B& b)
{
  if(a.dimension() != b.dimension() || a.number_of_vertices() != b.number_of_vertices()) return false;
  std::vector<Point_tuple> va, vb;
  if(!sorted_vertex_tuples(a, va) || !sorted_vertex_tuples(b, vb) || va != vb) return false;
  if(a.dimension() < 3) return true;
  if(a.number_of_finite_cells() != b.number_of_finite_cells()) return false;
  return sorted_cell_tuples(a) == sorted_cell_tuples(b);
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_EQUALITY_H
