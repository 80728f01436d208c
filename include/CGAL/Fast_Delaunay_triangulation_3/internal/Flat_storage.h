// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The flat mesh data structure of the paper (§2.2, Listing 1): one array of
// 32-byte vertex records, and tetrahedra as parallel arrays of 4 vertex ids,
// 4 neighbour codes and a flag byte.  The ghost vertex (§2.6) has no record; it
// is the id `ghost_vertex` and sits in slot 3 of every ghost tetrahedron.
//
//                 v3
//                 /|\          facet i is opposite vertex i;
//                / | \         neighbour code 4*t + i names facet i of t;
//               /  |  \        neighbors[4*t + i] = 4*u + j where facet j of
//            v0 ---|--- v2     u is the same facet, so the back pointer is
//               \  |  /        neighbors[4*u + j] == 4*t + i.
//                \ | /         Stored tetrahedra are positively oriented:
//                 \|/          orientation(v0, v1, v2, v3) > 0 (CGAL's sign).
//                 v1
//
// Deleted slots are flagged and kept on a free list; iterators skip them.

#ifndef CGAL_FDT3_INTERNAL_FLAT_STORAGE_H
#define CGAL_FDT3_INTERNAL_FLAT_STORAGE_H

#include <CGAL/assertions.h>

#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <new>
#include <type_traits>
#include <utility>
#include <vector>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

typedef std::uint32_t Vertex_id;
typedef std::uint64_t Tet_id;
typedef std::uint64_t Facet_code; // 4 * tetrahedron + facet

constexpr Vertex_id ghost_vertex = std::numeric_limits<Vertex_id>::max();
constexpr Vertex_id max_vertices = ghost_vertex - 1;

inline Tet_id tet_of(Facet_code code) { return code >> 2; }
inline int facet_of(Facet_code code) { return static_cast<int>(code & 3); }
inline Facet_code facet_code(Tet_id t, int facet) { return (t << 2) | static_cast<Facet_code>(facet); }

// Growable array of trivially copyable elements that never value-initialises:
// the kernel writes every slot before reading it, and zero-filling hundreds of
// megabytes would cost as much as a triangulation round.
template <class T>
class Raw_array
{
  static_assert(std::is_trivially_copyable<T>::value, "Raw_array holds plain records");

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
  ~Raw_array() { std::free(data_); }

  void swap(Raw_array& other) noexcept
  {
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

  void reserve(std::size_t n)
  {
    if(n <= capacity_) return;
    T* grown = static_cast<T*>(std::realloc(static_cast<void*>(data_), n * sizeof(T)));
    if(grown == nullptr) throw std::bad_alloc();
    data_ = grown;
    capacity_ = n;
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
  void shrink_to_fit()
  {
    if(size_ == capacity_) return;
    if(size_ == 0) {
      std::free(data_);
      data_ = nullptr;
      capacity_ = 0;
      return;
    }
    T* shrunk = static_cast<T*>(std::realloc(static_cast<void*>(data_), size_ * sizeof(T)));
    if(shrunk != nullptr) {
      data_ = shrunk;
      capacity_ = size_;
    }
  }

private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

// A vertex: its coordinates and a scratch word.  During an insertion the
// scratch word holds the vertex's local number on the cavity boundary (tagged
// with the insertion's stamp, so it never needs clearing); between insertions
// it is free for other passes (e.g. the incident-cell cache).
struct Vertex_record
{
  double xyz[3];
  std::uint64_t scratch;
};
static_assert(sizeof(Vertex_record) == 32, "a vertex record is half a cache line");

// A scoped enum, not a plain byte: writes through unsigned char may alias
// anything, which would make the compiler reload every array pointer in the
// cavity loop after each flag write.
enum class Tet_flags : std::uint8_t {
  none = 0,
  deleted = 1,  // slot free, or in the cavity being carved
  outside = 2,  // tested outside the current cavity (cleared after the insertion)
};
inline Tet_flags operator|(Tet_flags a, Tet_flags b)
{
  return static_cast<Tet_flags>(static_cast<std::uint8_t>(a) | static_cast<std::uint8_t>(b));
}
inline Tet_flags without(Tet_flags a, Tet_flags b)
{
  return static_cast<Tet_flags>(static_cast<std::uint8_t>(a) & ~static_cast<std::uint8_t>(b));
}
inline bool has(Tet_flags a, Tet_flags b)
{
  return (static_cast<std::uint8_t>(a) & static_cast<std::uint8_t>(b)) != 0;
}

struct Flat_storage
{
  Raw_array<Vertex_record> vertices;
  Raw_array<Vertex_id> tet_vertices;   // 4 per tetrahedron
  Raw_array<Facet_code> tet_neighbors; // 4 per tetrahedron
  Raw_array<Tet_flags> tet_flags;     // 1 per tetrahedron
  // 4 per tetrahedron when sub-determinants are on (Sub_determinants.h), else empty.
  Raw_array<double> tet_sub_determinants;
  bool with_sub_determinants = false;
  std::vector<Tet_id> free_tets;       // deleted slots available for reuse
  std::size_t live_tets = 0;           // slots in use (finite and ghost)
  std::size_t ghost_tets = 0;          // slots in use that have the ghost vertex

  std::size_t number_of_slots() const { return tet_flags.size(); }
  bool is_live(Tet_id t) const { return !has(tet_flags[t], Tet_flags::deleted); }
  bool is_ghost(Tet_id t) const { return tet_vertices[4 * t + 3] == ghost_vertex; }
  const double* point(Vertex_id v) const { return vertices[v].xyz; }
  Vertex_id vertex(Tet_id t, int i) const { return tet_vertices[4 * t + i]; }
  Facet_code neighbor_code(Tet_id t, int i) const { return tet_neighbors[4 * t + i]; }
  Tet_id neighbor(Tet_id t, int i) const { return tet_of(tet_neighbors[4 * t + i]); }

  void clear()
  {
    vertices.clear();
    tet_vertices.clear();
    tet_neighbors.clear();
    tet_flags.clear();
    tet_sub_determinants.clear();
    free_tets.clear();
    live_tets = 0;
    ghost_tets = 0;
  }

  // Room for `n` more tetrahedron slots without reallocation.
  void reserve_tets(std::size_t n)
  {
    const std::size_t total = number_of_slots() + n;
    tet_vertices.reserve(4 * total);
    tet_neighbors.reserve(4 * total);
    tet_flags.reserve(total);
    if(with_sub_determinants) tet_sub_determinants.reserve(4 * total);
  }

  // A live tetrahedron to start walks from when no better hint is known.
  Tet_id first_live_tet() const
  {
    for(Tet_id t = 0; t < number_of_slots(); ++t)
      if(is_live(t)) return t;
    return 0;
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
    tet_vertices.resize(4 * (t + 1));
    tet_neighbors.resize(4 * (t + 1));
    tet_flags.resize(t + 1);
    if(with_sub_determinants) tet_sub_determinants.resize(4 * (t + 1));
    return t;
  }

  // Moves the live tetrahedra into the lowest slots, keeping their relative
  // order, so that the arrays hold no holes (after bulk insertion).
  void compact()
  {
    const std::size_t slots = number_of_slots();
    if(live_tets == slots) {
      free_tets.clear();
      return;
    }
    std::vector<Tet_id> new_index(slots);
    Tet_id next = 0;
    for(Tet_id t = 0; t < slots; ++t)
      new_index[t] = is_live(t) ? next++ : Tet_id(-1);
    for(Tet_id t = 0; t < slots; ++t) {
      if(!is_live(t)) continue;
      const Tet_id u = new_index[t];
      for(int i = 0; i < 4; ++i) {
        const Facet_code code = tet_neighbors[4 * t + i];
        tet_vertices[4 * u + i] = tet_vertices[4 * t + i];
        tet_neighbors[4 * u + i] = facet_code(new_index[tet_of(code)], facet_of(code));
        if(with_sub_determinants) tet_sub_determinants[4 * u + i] = tet_sub_determinants[4 * t + i];
      }
      tet_flags[u] = Tet_flags::none;
    }
    tet_vertices.resize(4 * next);
    tet_neighbors.resize(4 * next);
    tet_flags.resize(next);
    if(with_sub_determinants) tet_sub_determinants.resize(4 * next);
    free_tets.clear();
    CGAL_assertion(next == live_tets);
  }
};

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_FLAT_STORAGE_H
