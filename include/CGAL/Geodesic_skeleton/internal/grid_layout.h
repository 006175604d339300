// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_INTERNAL_GRID_LAYOUT_H
#define CGAL_GEODESIC_SKELETON_INTERNAL_GRID_LAYOUT_H

#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The default of the `memory_limit` named parameter of the voxel functions (`voxelize()`,
/// `distance_transform()`, `thin()`, `to_graph()`): 2 GiB.
constexpr double default_voxel_memory_limit = parameter_ranges::memory_limit.default_value;

namespace internal {

// The memory layout of a dense array over a box of voxels (x fastest, then y, then z),
// used by the voxel algorithms for their working arrays: index <-> key, and the index
// offsets of the 26 neighbours (valid for voxels not on the box's border).
struct Grid_layout
{
  Voxel_box box;
  std::size_t nx = 0, ny = 0, nz = 0;
  std::ptrdiff_t stride_y = 0, stride_z = 0;

  Grid_layout() = default;
  explicit Grid_layout(const Voxel_box& b) : box(b)
  {
    const auto e = b.extent();
    nx = e[0];
    ny = e[1];
    nz = e[2];
    stride_y = std::ptrdiff_t(nx);
    stride_z = std::ptrdiff_t(nx * ny);
  }

  std::size_t volume() const { return nx * ny * nz; }
  std::size_t index(const Voxel_key& k) const
  {
    return std::size_t(k.x - box.min.x) + std::size_t(k.y - box.min.y) * nx +
           std::size_t(k.z - box.min.z) * nx * ny;
  }
  Voxel_key key(std::size_t i) const
  {
    const std::size_t x = i % nx, yz = i / nx;
    return Voxel_key{box.min.x + int(x), box.min.y + int(yz % ny), box.min.z + int(yz / ny)};
  }
  // Index offsets of the 26 neighbours, in the order of neighbourhood_26().
  std::array<std::ptrdiff_t, 26> neighbour_offsets() const
  {
    std::array<std::ptrdiff_t, 26> o{};
    const auto& n = neighbourhood_26();
    for(std::size_t i = 0; i < 26; ++i)
      o[i] = n[i].x + n[i].y * stride_y + n[i].z * stride_z;
    return o;
  }
};

// Calls f(i, k) for every voxel k of the layout's box, i its index, in increasing index
// order (no division to find the keys).
template <typename Function>
void for_each_cell(const Grid_layout& layout, Function f)
{
  std::size_t i = 0;
  for(int z = layout.box.min.z; z < layout.box.max.z; ++z)
    for(int y = layout.box.min.y; y < layout.box.max.y; ++y)
      for(int x = layout.box.min.x; x < layout.box.max.x; ++x, ++i)
        f(i, Voxel_key{x, y, z});
}

// Indices 0..5 of neighbourhood_26() that are face neighbours, in that order.
inline const std::array<int, 6>& face_neighbour_positions()
{
  static const std::array<int, 6> positions = [] {
    std::array<int, 6> p{};
    int n = 0;
    for(int i = 0; i < 26; ++i)
      if(offset_order(neighbourhood_26()[i]) == 1)
        p[n++] = i;
    return p;
  }();
  return positions;
}

// The `memory_limit` named parameter (bytes), or its default; checked (a NaN limit would
// let every allocation through).
template <typename NamedParameters>
double memory_limit(const NamedParameters& np, const std::string& caller = "the voxel stages")
{
  return checked_parameter(parameter_ranges::memory_limit,
                           double(CGAL::parameters::choose_parameter(
                               CGAL::parameters::get_parameter(np, internal_np::memory_limit_tag),
                               default_voxel_memory_limit)),
                           caller);
}

// Throws std::length_error, naming the bytes needed, when `bytes` exceeds `limit`, or when
// the box of `layout` is too big to be indexed with 32-bit indices. The message reads
// "<caller>: <what> of NX x NY x NZ voxels needs about ... bytes".
inline void require_memory(double bytes, double limit, const Grid_layout& layout,
                           const std::string& caller, const std::string& what)
{
  std::ostringstream msg;
  msg.precision(4);
  msg << caller << ": " << what << " of " << layout.nx << " x " << layout.ny << " x "
      << layout.nz << " voxels";
  if(double(layout.nx) * double(layout.ny) * double(layout.nz) >=
     double(std::numeric_limits<std::uint32_t>::max()))
  {
    msg << " has more than the 2^32 - 1 voxels that the voxel algorithms index; lower the "
           "resolution";
    throw std::length_error(msg.str());
  }
  if(bytes > limit)
  {
    msg << " needs about " << bytes << " bytes (" << bytes / (1024. * 1024.)
        << " MiB), more than the memory limit of " << limit
        << " bytes; lower the resolution or raise the memory_limit named parameter";
    throw std::length_error(msg.str());
  }
}

// The voxels of `voxels` (any VoxelSet) as bytes (1 = in the set) over `layout`, whose box
// must contain them.
template <typename VoxelSet>
std::vector<std::uint8_t> to_bytes(const VoxelSet& voxels, const Grid_layout& layout)
{
  std::vector<std::uint8_t> bytes(layout.volume(), 0);
  voxels.for_each([&](const Voxel_key& k) { bytes[layout.index(k)] = 1; });
  return bytes;
}

// The box of the set grown by `margin`, or an exception naming `caller` when the set is
// empty.
template <typename VoxelSet>
Voxel_box require_nonempty_box(const VoxelSet& voxels, int margin, const char* caller)
{
  if(voxels.size() == 0)
    throw std::invalid_argument(std::string(caller) + ": the voxel set is empty");
  Voxel_box box;
  voxels.for_each([&](const Voxel_key& k) { box.extend(k); });
  return box.grown(margin);
}

} // namespace internal
} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_INTERNAL_GRID_LAYOUT_H
