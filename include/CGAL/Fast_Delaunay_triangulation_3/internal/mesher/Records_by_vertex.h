// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Records grouped by a vertex: the tetrahedra around each vertex for the
// quality report, the edges of the input surface for its check.

#ifndef CGAL_FDT3_INTERNAL_MESHER_RECORDS_BY_VERTEX_H
#define CGAL_FDT3_INTERNAL_MESHER_RECORDS_BY_VERTEX_H

#include <CGAL/Fast_Delaunay_triangulation_3/internal/Radix_sort.h>

#include <algorithm>
#include <cstddef>
#include <memory>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {
namespace mesher {

// An allocator whose construct() without arguments default-initialises:
// a vector of plain records that are all written next is not zero-filled
// first (20 MB of incidences for bunny00's mesh).  Its own rebind is
// needed: the one inherited from std::allocator (C++17) would make the
// vector use std::allocator again.
template <class T>
struct Default_init_allocator : std::allocator<T>
{
  template <class U>
  struct rebind
  {
    typedef Default_init_allocator<U> other;
  };
  Default_init_allocator() = default;
  template <class U>
  Default_init_allocator(const Default_init_allocator<U>&) noexcept
  {}
  template <class U>
  void construct(U* p) noexcept(std::is_nothrow_default_constructible<U>::value)
  {
    ::new(static_cast<void*>(p)) U;
  }
  template <class U, class... Args>
  void construct(U* p, Args&&... args)
  {
    ::new(static_cast<void*>(p)) U(std::forward<Args>(args)...);
  }
};

// Whether Records_by_vertex sorts each group, or keeps its records in the
// order they were made (increasing index).
enum class Group_order { sorted, as_made };

// Records keyed by a vertex, grouped by it (a counting sort: offsets per
// vertex, then the records): the edges and facets of a mesh or a surface,
// or the tetrahedra around each vertex, without a map of them (on bunny00's
// 1.25 million tetrahedra, maps of edges and facets made the quality report
// take 5.5 s).
template <class Record>
struct Records_by_vertex
{
  std::vector<std::size_t> begin; // of vertex v's records: begin[v] .. begin[v + 1]
  std::vector<Record, Default_init_allocator<Record>> records;

  // key(i) and record(i) for i in [0, n): the vertex and its record.  On
  // `threads` threads: each chunk of [0, n) counts its records per vertex
  // and writes them from its own offsets, after the earlier chunks' (the
  // order of a sequential pass: bunny00's 5 million facets took 0.25 s
  // with one pass), then the groups are sorted unless `order` is as_made.
  // The chunks' offsets take at most the records' own memory: fewer chunks
  // where vertices are many.
  template <class Key, class Make>
  Records_by_vertex(std::size_t vertices, std::size_t n, const Key& key, const Make& record, int threads = 1,
                    Group_order order = Group_order::sorted)
      : begin(vertices + 1, 0), records(n)
  {
    const int parts = chunk_count_within(n, threads, vertices * sizeof(std::size_t), n * sizeof(Record));
    // Per chunk and vertex: its count, then where its next record goes.
    std::vector<std::vector<std::size_t>> position(parts, std::vector<std::size_t>(vertices, 0));
    for_each_chunk(parts, [&](int c) {
      for(std::size_t i = chunk_begin(n, parts, c); i < chunk_begin(n, parts, c + 1); ++i) ++position[c][key(i)];
    });
    std::size_t offset = 0;
    for(std::size_t v = 0; v < vertices; ++v) {
      begin[v] = offset;
      for(int c = 0; c < parts; ++c) {
        const std::size_t count = position[c][v];
        position[c][v] = offset;
        offset += count;
      }
    }
    begin[vertices] = offset;
    for_each_chunk(parts, [&](int c) {
      for(std::size_t i = chunk_begin(n, parts, c); i < chunk_begin(n, parts, c + 1); ++i)
        records[position[c][key(i)]++] = record(i);
    });
    if(order == Group_order::as_made) return;
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
