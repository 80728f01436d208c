// Copyright (c) 2026 Fast_Delaunay_triangulation_3 authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// The machine's byte order, for the binary files read (PLY, NumPy) and
// written (VTK's raw arrays declare it).  C++17 has no std::endian.

#ifndef CGAL_FDT3_INTERNAL_BYTE_ORDER_H
#define CGAL_FDT3_INTERNAL_BYTE_ORDER_H

#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Fast_Delaunay_triangulation_3_internal {

inline bool machine_is_little_endian()
{
  const std::uint16_t one = 1;
  unsigned char first;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

} // namespace Fast_Delaunay_triangulation_3_internal
} // namespace CGAL

#endif // CGAL_FDT3_INTERNAL_BYTE_ORDER_H
