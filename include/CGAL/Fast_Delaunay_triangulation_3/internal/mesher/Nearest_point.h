// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The nearest points of a fixed set to a query, by CGAL's k-d tree: built
// once, then only searched, so several threads may search at once.  The
// size field's background points and the sizes of the recovery's Steiner
// points ask it.

#ifndef CGAL_FDT3_INTERNAL_MESHER_NEAREST_POINT_H
#define CGAL_FDT3_INTERNAL_MESHER_NEAREST_POINT_H

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/tuple/tuple.hpp>

#include <array>
#include <cstddef>
#include <memory>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

class Nearest_point_index
{
  typedef Simple_cartesian<double> K;
  typedef boost::tuple<K::Point_3, std::size_t> Point_and_index;
  typedef Search_traits_adapter<Point_and_index, Nth_of_tuple_property_map<0, Point_and_index>, Search_traits_3<K>>
      Traits;
  typedef Orthogonal_k_neighbor_search<Traits> Search;
  typedef Search::Tree Tree;

public:
  // `points` must not be empty.
  explicit Nearest_point_index(const std::vector<std::array<double, 3>>& points)
  {
    std::vector<Point_and_index> items;
    items.reserve(points.size());
    for(std::size_t i = 0; i < points.size(); ++i)
      items.push_back(boost::make_tuple(K::Point_3(points[i][0], points[i][1], points[i][2]), i));
    tree_ = std::make_shared<Tree>(items.begin(), items.end());
    tree_->build(); // searches alone from here on
  }

  // The index of a nearest point to q.
  std::size_t nearest(const double* q) const
  {
    Search search(*tree_, K::Point_3(q[0], q[1], q[2]), 1);
    return boost::get<1>(search.begin()->first);
  }

  // The indices of the k points nearest to q (all of them if there are
  // fewer), in no promised order.
  void nearest(const double* q, std::size_t k, std::vector<std::size_t>& out) const
  {
    out.clear();
    Search search(*tree_, K::Point_3(q[0], q[1], q[2]), static_cast<unsigned int>(k));
    for(auto it = search.begin(); it != search.end(); ++it) out.push_back(boost::get<1>(it->first));
  }

private:
  std::shared_ptr<Tree> tree_;
};

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_NEAREST_POINT_H
