// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_BYTE_RUNS_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_BYTE_RUNS_H

// Scans of a row of byte labels for the next zero or non-zero byte, eight bytes at a time:
// the rows of a voxel grid hold long runs of one value (empty space, filled solid).

#include <cstddef>
#include <cstdint>
#include <cstring>

namespace CGAL {
namespace Geodesic_skeleton {
namespace internal {

// The first x in [x, end) where row[x] is 0, or `end`.
inline std::size_t first_zero(const std::uint8_t* row, std::size_t x, std::size_t end)
{
  for(; x + 8 <= end; x += 8)
  {
    std::uint64_t word;
    std::memcpy(&word, row + x, 8);
    if(((word - 0x0101010101010101ull) & ~word & 0x8080808080808080ull) != 0)
      break; // a zero byte in this word
  }
  while(x < end && row[x] != 0)
    ++x;
  return x;
}

// The first x in [x, end) where row[x] is not 0, or `end`.
inline std::size_t first_nonzero(const std::uint8_t* row, std::size_t x, std::size_t end)
{
  for(; x + 8 <= end; x += 8)
  {
    std::uint64_t word;
    std::memcpy(&word, row + x, 8);
    if(word != 0)
      break;
  }
  while(x < end && row[x] == 0)
    ++x;
  return x;
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_BYTE_RUNS_H
