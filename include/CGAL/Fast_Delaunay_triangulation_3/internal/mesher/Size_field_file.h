// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// A size field from a text file (fast_mesh_3 --size-field FILE): one entry
// a line, `#` starts a comment, blank lines are skipped.
//
//   subdomain S H     h at most H in subdomain S (1, 2, ... as the mesher
//                     numbers the volumes)
//   X Y Z H           a background point and its size: h at most the size
//                     of the background point nearest to where h is asked
//
// Both kinds may be mixed.  A malformed line is refused with its number.
// The nearest background point is found with CGAL's k-d tree, built once
// and then only searched, so several threads may ask at once.

#ifndef CGAL_FDT3_INTERNAL_MESHER_SIZE_FIELD_FILE_H
#define CGAL_FDT3_INTERNAL_MESHER_SIZE_FIELD_FILE_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/mesher/Nearest_point.h>

#include <array>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

struct Size_field_entries
{
  std::vector<double> subdomain_sizes; // [S - 1], 0 where the file gives none
  std::vector<std::array<double, 3>> points;
  std::vector<double> sizes;           // per background point
};

namespace size_file_detail {

// A finite double, the whole word.
inline bool parse_number(const std::string& word, double& x)
{
  errno = 0;
  char* end = nullptr;
  x = std::strtod(word.c_str(), &end);
  return !word.empty() && end == word.c_str() + word.size() && errno != ERANGE && std::isfinite(x);
}

} // namespace size_file_detail

inline Size_field_entries read_size_field_entries(const std::string& path)
{
  using size_file_detail::parse_number;
  std::ifstream in(path);
  if(!in) throw std::invalid_argument("size field: cannot open '" + path + "'");
  Size_field_entries entries;
  std::string text;
  std::size_t line = 0;
  auto fail = [&](const std::string& what) {
    throw std::invalid_argument("size field '" + path + "', line " + std::to_string(line) + ": " + what);
  };
  while(std::getline(in, text)) {
    ++line;
    std::istringstream split(text.substr(0, text.find('#')));
    std::vector<std::string> words;
    for(std::string w; split >> w;) words.push_back(w);
    if(words.empty()) continue;
    if(words[0] == "subdomain") {
      if(words.size() != 3) fail("'subdomain S H' takes two numbers, not " + std::to_string(words.size() - 1));
      const bool digits = words[1].find_first_not_of("0123456789") == std::string::npos && words[1].size() <= 6;
      const long s = digits ? std::stol(words[1]) : 0;
      if(s < 1) fail("'" + words[1] + "' is not a subdomain number (1, 2, ...)");
      double h;
      if(!parse_number(words[2], h) || !(h > 0)) fail("'" + words[2] + "' is not a positive finite size");
      if(entries.subdomain_sizes.size() < std::size_t(s)) entries.subdomain_sizes.resize(s, 0.0);
      if(entries.subdomain_sizes[s - 1] > 0) fail("subdomain " + words[1] + " is given twice");
      entries.subdomain_sizes[s - 1] = h;
      continue;
    }
    if(words.size() != 4)
      fail("expected 'X Y Z H' or 'subdomain S H', found " + std::to_string(words.size()) + " words");
    std::array<double, 3> p;
    for(int a = 0; a < 3; ++a)
      if(!parse_number(words[a], p[a])) fail("'" + words[a] + "' is not a finite coordinate");
    double h;
    if(!parse_number(words[3], h) || !(h > 0)) fail("'" + words[3] + "' is not a positive finite size");
    entries.points.push_back(p);
    entries.sizes.push_back(h);
  }
  if(entries.subdomain_sizes.empty() && entries.points.empty())
    throw std::invalid_argument("size field '" + path + "': no entries");
  return entries;
}

// h(x, y, z) = the size of the nearest background point.
class Nearest_point_size
{
public:
  Nearest_point_size(const std::vector<std::array<double, 3>>& points, std::vector<double> sizes)
      : index_(std::make_shared<Nearest_point_index>(points)), sizes_(std::move(sizes))
  {}

  double operator()(double x, double y, double z) const
  {
    const double q[3] = {x, y, z};
    return sizes_[index_->nearest(q)];
  }

private:
  std::shared_ptr<const Nearest_point_index> index_;
  std::vector<double> sizes_;
};

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_SIZE_FIELD_FILE_H
