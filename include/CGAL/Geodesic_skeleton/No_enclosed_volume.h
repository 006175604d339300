// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_NO_ENCLOSED_VOLUME_H
#define CGAL_GEODESIC_SKELETON_NO_ENCLOSED_VOLUME_H

/// \file No_enclosed_volume.h
/// The exception `voxelize()` throws when the mesh encloses no volume at the resolution.

#include <stdexcept>
#include <string>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// Thrown by `voxelize()` when the mesh encloses no voxel at the resolution: an open sheet,
/// a surface with holes wider than a voxel, or a shape thinner than a voxel. A
/// `std::invalid_argument`, so that code that catches bad input catches it too; a finer
/// resolution, or a closed mesh, may enclose volume where this one does not.
class No_enclosed_volume : public std::invalid_argument
{
public:
  /// \param what the message, which names the caller and the resolution.
  explicit No_enclosed_volume(const std::string& what) : std::invalid_argument(what) {}
};

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_NO_ENCLOSED_VOLUME_H
