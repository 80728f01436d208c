// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flat mesh data structure of the paper (§2.2, Listing 1): one array of
// 32-byte vertex records and one array of tetrahedron records, each holding
// the 4 vertex ids and the 4 neighbour codes of a tetrahedron side by side.
// The paper keeps them in separate arrays; a cavity search then misses the
// cache once per array for every tetrahedron it looks at, while one record
// costs one miss.  With 32-bit neighbour codes (the default) a record is 32
// bytes, two per cache line; CGAL_FDT3_64_BIT_FACET_CODES lifts the limit of
// 2^30 tetrahedra (about 160 million points) at 48 bytes per record.  The
// ghost vertex (§2.6) has no vertex record; it is the id `ghost_vertex` and
// sits in slot 3 of every ghost tetrahedron.
//
//                 v3
//                 /|\          facet i is opposite vertex i;
//                / | \         neighbour code 4*t + i names facet i of t;
//               /  |  \        n[i] of t = 4*u + j where facet j of u is
//            v0 ---|--- v2     the same facet, so the back pointer is
//               \  |  /        n[j] of u == 4*t + i.
//                \ | /         Stored tetrahedra are positively oriented:
//                 \|/          orientation(v0, v1, v2, v3) > 0 (CGAL's sign).
//                 v1
//
// Marks live in the top bit of the vertex ids (vertex ids stay below 2^31):
// the top bit of v[0] flags a free slot or a tetrahedron of the cavity being
// carved, the top bit of v[1] a tetrahedron found outside that cavity.  Live
// tetrahedra carry no marks between insertions, so every reader outside the
// kernel sees plain vertex ids.  Free slots are kept on a free list;
// iterators skip them.  Removed vertices keep dead records (Vertex_record):
// their ids are never given again, so iterators skip them too.

#ifndef CGAL_FDT3_INTERNAL_FLAT_STORAGE_H
#define CGAL_FDT3_INTERNAL_FLAT_STORAGE_H

#include <CGAL/assertions.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#include <unistd.h>
#endif

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

typedef std::uint32_t Vertex_id;
typedef std::uint64_t Tet_id;
#ifdef CGAL_FDT3_64_BIT_FACET_CODES
typedef std::uint64_t Facet_code; // 4 * tetrahedron + facet
#else
typedef std::uint32_t Facet_code; // 4 * tetrahedron + facet
#endif

constexpr Vertex_id mark_bit = Vertex_id(1) << 31;
constexpr Vertex_id ghost_vertex = mark_bit - 1;
constexpr Vertex_id max_vertices = ghost_vertex - 1;
// Fills the unused vertex slots of a cell below dimension 3 (slot 3 of a
// triangle, slots 2 and 3 of a segment); never a vertex id, since ids stay
// below max_vertices.  Handles show it as a null Vertex_handle, as CGAL does.
constexpr Vertex_id no_vertex = max_vertices;
// Tetrahedron slots addressable by a facet code.
constexpr std::uint64_t max_tets = (std::uint64_t(std::numeric_limits<Facet_code>::max()) >> 2) + 1;

// The slots of the two vertices of each of a tetrahedron's six edges (the
// order of the edge iterators' codes, Face_iterators.h).
inline constexpr int cell_edge_vertices[6][2] = {{0, 1}, {0, 2}, {0, 3}, {1, 2}, {1, 3}, {2, 3}};

inline Tet_id tet_of(Facet_code code) { return Tet_id(code >> 2); }
inline int facet_of(Facet_code code) { return static_cast<int>(code & 3); }
inline Facet_code facet_code(Tet_id t, int facet)
{
  return static_cast<Facet_code>((t << 2) | static_cast<Tet_id>(facet));
}

// Growable array of trivially copyable elements that never value-initialises:
// the kernel writes every slot before reading it, and zero-filling hundreds of
// megabytes would cost as much as a triangulation round.  Elements start on a
// cache-line boundary: glibc returns large blocks 16 bytes past a page
// boundary, which would make every other 32-byte record straddle two lines.
// Growth still goes through realloc (page remapping, no copy for large
// blocks); the rare change of offset inside the block is a memmove.
template <class T>
class Raw_array
{
  static_assert(std::is_trivially_copyable<T>::value, "Raw_array holds plain records");
  static constexpr std::size_t alignment = 64;

public:
  Raw_array() = default;
  Raw_array(const Raw_array& other) { *this = other; }
  Raw_array(Raw_array&& other) noexcept { swap(other); }
  Raw_array& operator=(const Raw_array& other)
  {
    if(this != &other) {
      Raw_array copy;
      copy.reserve(other.size_);
      if(other.size_ != 0) std::memcpy(copy.data_, other.data_, other.size_ * sizeof(T));
      copy.size_ = other.size_;
      swap(copy);
    }
    return *this;
  }
  Raw_array& operator=(Raw_array&& other) noexcept
  {
    Raw_array empty;
    swap(empty);
    swap(other);
    return *this;
  }
  ~Raw_array() { std::free(block_); }

  void swap(Raw_array& other) noexcept
  {
    std::swap(block_, other.block_);
    std::swap(data_, other.data_);
    std::swap(size_, other.size_);
    std::swap(capacity_, other.capacity_);
  }

  std::size_t size() const { return size_; }
  std::size_t capacity() const { return capacity_; }
  bool empty() const { return size_ == 0; }
  T* data() { return data_; }
  const T* data() const { return data_; }
  T& operator[](std::size_t i) { return data_[i]; }
  const T& operator[](std::size_t i) const { return data_[i]; }
  T* begin() { return data_; }
  T* end() { return data_ + size_; }
  const T* begin() const { return data_; }
  const T* end() const { return data_ + size_; }
  T& front() { return data_[0]; }
  const T& front() const { return data_[0]; }

  void reserve(std::size_t n)
  {
    if(n > capacity_) reallocate(n);
  }
  // New elements are left uninitialised.
  void resize(std::size_t n)
  {
    if(n > capacity_) reserve(std::max(n, capacity_ + capacity_ / 2));
    size_ = n;
  }
  void push_back(const T& value)
  {
    resize(size_ + 1);
    data_[size_ - 1] = value;
  }
  void clear() { size_ = 0; }
  // Hands the block over to the caller, who frees it with std::free();
  // data() was at `data` in it.  The array is left empty.
  char* release(T*& data) noexcept
  {
    char* block = block_;
    data = data_;
    block_ = nullptr;
    data_ = nullptr;
    size_ = capacity_ = 0;
    return block;
  }
  // Maps the whole pages of elements [begin, end) (within the capacity) in
  // one system call, before they are first written (Linux 5.14+; elsewhere,
  // or if the call fails, the first writes fault the pages in as usual).
  // The contents do not change.  Threads that fault pages of one process in
  // concurrently contend in the kernel: the partitioned insertion maps each
  // partition's slots this way (1e6 points, 2 threads: 1.03 -> 0.99 s; 1e7:
  // 10.9 -> 10.1 s); a single thread gains nothing.
  void prefault(std::size_t begin, std::size_t end)
  {
#if defined(__linux__) && defined(MADV_POPULATE_WRITE)
    CGAL_precondition(begin <= end && end <= capacity_);
    const std::uintptr_t page = static_cast<std::uintptr_t>(sysconf(_SC_PAGESIZE));
    const std::uintptr_t first = (reinterpret_cast<std::uintptr_t>(data_ + begin) + page - 1) / page * page;
    const std::uintptr_t last = reinterpret_cast<std::uintptr_t>(data_ + end) / page * page;
    if(first < last) (void)madvise(reinterpret_cast<void*>(first), last - first, MADV_POPULATE_WRITE);
#else
    (void)begin;
    (void)end;
#endif
  }
  void shrink_to_fit()
  {
    if(size_ == capacity_) return;
    if(size_ == 0) {
      std::free(block_);
      block_ = nullptr;
      data_ = nullptr;
      capacity_ = 0;
      return;
    }
    reallocate(size_);
  }

private:
  void reallocate(std::size_t n)
  {
    const std::size_t old_offset =
        block_ == nullptr ? 0 : static_cast<std::size_t>(reinterpret_cast<char*>(data_) - block_);
    char* grown = static_cast<char*>(std::realloc(block_, n * sizeof(T) + alignment));
    if(grown == nullptr) throw std::bad_alloc();
    const std::size_t offset =
        (alignment - reinterpret_cast<std::uintptr_t>(grown) % alignment) % alignment;
    if(offset != old_offset && size_ != 0)
      std::memmove(grown + offset, grown + old_offset, size_ * sizeof(T));
    block_ = grown;
    data_ = reinterpret_cast<T*>(grown + offset);
    capacity_ = n;
  }

  char* block_ = nullptr;
  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

// A vertex: its coordinates and a scratch word.  During an insertion the
// scratch word holds the vertex's local number on the cavity boundary (tagged
// with the insertion's stamp, so it never needs clearing); between insertions
// it is 0.  A removed vertex keeps its record (ids of the others must not
// change, as CGAL's handles do not) with `dead_vertex` in the scratch word:
// it is in no tetrahedron, so the kernel never reads the word, and its
// coordinates stay finite for the passes that read every record.
constexpr std::uint64_t dead_vertex = ~std::uint64_t(0);
struct Vertex_record
{
  double xyz[3];
  std::uint64_t scratch;
};
static_assert(sizeof(Vertex_record) == 32, "a vertex record is half a cache line");

struct Tet_record
{
  Vertex_id v[4];
  Facet_code n[4];
};
static_assert(sizeof(Tet_record) == 16 + 4 * sizeof(Facet_code), "tetrahedron record without padding");

struct Flat_storage
{
  Raw_array<Vertex_record> vertices;
  Raw_array<Tet_record> tets;
  // 4 per tetrahedron when sub-determinants are on (Sub_determinants.h), else empty.
  Raw_array<double> tet_sub_determinants;
  bool with_sub_determinants = false;
  std::vector<Tet_id> free_tets;       // free slots available for reuse
  std::size_t live_tets = 0;           // slots in use (finite and ghost)
  std::size_t ghost_tets = 0;          // slots in use that have the ghost vertex
  std::size_t dead_vertices = 0;       // removed vertices whose records stay

  std::size_t number_of_slots() const { return tets.size(); }
  bool is_live(Tet_id t) const { return (tets[t].v[0] & mark_bit) == 0; }
  bool is_ghost(Tet_id t) const { return tets[t].v[3] == ghost_vertex; }
  const double* point(Vertex_id v) const { return vertices[v].xyz; }
  bool is_dead(Vertex_id v) const { return vertices[v].scratch == dead_vertex; }
  std::size_t live_vertices() const { return vertices.size() - dead_vertices; }
  void kill_vertex(Vertex_id v)
  {
    CGAL_precondition(!is_dead(v));
    vertices[v].scratch = dead_vertex;
    ++dead_vertices;
  }
  // A dead record comes back with point p (move keeps the vertex's id).
  void revive_vertex(Vertex_id v, const double* p)
  {
    CGAL_precondition(is_dead(v));
    for(int a = 0; a < 3; ++a) vertices[v].xyz[a] = p[a];
    vertices[v].scratch = 0;
    --dead_vertices;
  }
  Vertex_id vertex(Tet_id t, int i) const { return tets[t].v[i]; }
  Vertex_id* vertex_ids(Tet_id t) { return tets[t].v; }
  const Vertex_id* vertex_ids(Tet_id t) const { return tets[t].v; }
  Facet_code neighbor_code(Tet_id t, int i) const { return tets[t].n[i]; }
  Facet_code& neighbor_code(Facet_code code) { return tets[tet_of(code)].n[facet_of(code)]; }
  Facet_code neighbor_code(Facet_code code) const { return tets[tet_of(code)].n[facet_of(code)]; }
  Tet_id neighbor(Tet_id t, int i) const { return tet_of(tets[t].n[i]); }

  // Marks of the kernel (see the top of this file).
  void mark_free(Tet_id t) { tets[t].v[0] |= mark_bit; }
  void unmark_free(Tet_id t) { tets[t].v[0] &= ~mark_bit; }
  void mark_outside(Tet_id t) { tets[t].v[1] |= mark_bit; }
  void unmark_outside(Tet_id t) { tets[t].v[1] &= ~mark_bit; }

  void clear()
  {
    vertices.clear();
    tets.clear();
    tet_sub_determinants.clear();
    free_tets.clear();
    live_tets = 0;
    ghost_tets = 0;
    dead_vertices = 0;
  }

  // `slots` tetrahedron slots in all; new slots are free (marked) until
  // written, unless the caller marks the ones it leaves unused itself
  // (unmarked slots are never touched, so their pages cost no memory).
  enum class New_slots { marked_free, left_unwritten };
  void resize_tets(std::size_t slots, New_slots new_slots = New_slots::marked_free)
  {
    if(slots > max_tets)
      throw std::length_error("Fast_Delaunay_triangulation_3: more than 2^30 tetrahedra; "
                              "define CGAL_FDT3_64_BIT_FACET_CODES for larger triangulations");
    const std::size_t old = tets.size();
    tets.resize(slots);
    if(new_slots == New_slots::marked_free)
      for(std::size_t t = old; t < slots; ++t) tets[t].v[0] = mark_bit;
    if(with_sub_determinants) tet_sub_determinants.resize(4 * slots);
  }

  // Room for `n` more tetrahedron slots without reallocation.  The capacity
  // grows by half at least: insertions of one point at a time each ask for a
  // few dozen slots, and reserving exactly that much would reallocate the
  // whole array at every insertion (quadratic under an allocator whose
  // realloc copies).
  void reserve_tets(std::size_t n)
  {
    const std::size_t wanted = std::min<std::size_t>(number_of_slots() + n, max_tets);
    if(wanted <= tets.capacity()) return;
    const std::size_t total = std::min<std::size_t>(std::max(wanted, tets.capacity() + tets.capacity() / 2), max_tets);
    tets.reserve(total);
    if(with_sub_determinants) tet_sub_determinants.reserve(4 * total);
  }

  // A live tetrahedron to start walks from when no better hint is known.
  Tet_id first_live_tet() const
  {
    for(Tet_id t = 0; t < number_of_slots(); ++t)
      if(is_live(t)) return t;
    return 0;
  }

  void free_tet(Tet_id t)
  {
    mark_free(t);
    free_tets.push_back(t);
  }

  // A slot for a new tetrahedron: a freed one if any, else a new one at the end.
  Tet_id new_tet()
  {
    if(!free_tets.empty()) {
      const Tet_id t = free_tets.back();
      free_tets.pop_back();
      return t;
    }
    const Tet_id t = number_of_slots();
    if(t + 1 > max_tets || with_sub_determinants) {
      resize_tets(t + 1);
    } else {
      tets.resize(t + 1); // written by the caller right away
    }
    return t;
  }
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_FLAT_STORAGE_H
