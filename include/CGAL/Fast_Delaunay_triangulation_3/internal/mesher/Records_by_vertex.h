// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Records grouped by a vertex, for the mesher's edge and facet look-ups:
// the quality report's and the input check's.

#ifndef CGAL_FDT3_INTERNAL_MESHER_RECORDS_BY_VERTEX_H
#define CGAL_FDT3_INTERNAL_MESHER_RECORDS_BY_VERTEX_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>

#include <algorithm>
#include <cstddef>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

// Records keyed by a vertex, grouped by it (a counting sort: offsets per
// vertex, then the records), each group sorted: the edges and facets of a
// mesh or a surface without a map of them (on bunny00's 1.25 million
// tetrahedra, maps of edges and facets made the quality report take 5.5 s).
template <class Record>
struct Records_by_vertex
{
  std::vector<std::size_t> begin; // of vertex v's records: begin[v] .. begin[v + 1]
  std::vector<Record> records;

  // key(i) and record(i) for i in [0, n): the vertex and its record; the
  // groups are sorted on `threads` threads.
  template <class Key, class Make>
  Records_by_vertex(std::size_t vertices, std::size_t n, const Key& key, const Make& record, int threads = 1)
      : begin(vertices + 2, 0), records(n)
  {
    for(std::size_t i = 0; i < n; ++i) ++begin[key(i) + 2];
    for(std::size_t v = 2; v < begin.size(); ++v) begin[v] += begin[v - 1];
    for(std::size_t i = 0; i < n; ++i) records[begin[key(i) + 1]++] = record(i);
    begin.pop_back();
    const int chunks = chunk_count(vertices, threads);
    for_each_chunk(chunks, [&](int c) {
      for(std::size_t v = chunk_begin(vertices, chunks, c); v < chunk_begin(vertices, chunks, c + 1); ++v)
        std::sort(records.begin() + begin[v], records.begin() + begin[v + 1]);
    });
  }
};

} // namespace mesher
} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_MESHER_RECORDS_BY_VERTEX_H
