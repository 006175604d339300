// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_CLASSIFY_SKELETON_POINTS_H
#define CGAL_GEODESIC_SKELETON_CLASSIFY_SKELETON_POINTS_H

/// \file classify_skeleton_points.h
/// The degree of a skeleton point and the four classes of the paper's Definition 7 (end,
/// middle, connection, branched connection), steps (1) and (2) of Algorithm 1.

#include <CGAL/Geodesic_skeleton/Voxel_key.h>

#include <boost/property_map/property_map.hpp>

#include <cstddef>
#include <unordered_map>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The class of a point of a one-voxel-thick skeleton (paper, Definition 7).
enum class Skeleton_point_class
{
  isolated,           ///< degree 0: a component of one voxel
  end,                ///< degree 1
  middle,             ///< degree 2
  connection,         ///< degree 3 or more, every neighbour an end or a middle point
  branched_connection ///< degree 3 or more, some neighbour neither an end nor a middle point
};

/// \ingroup PkgGeodesicSkeletonRef
/// How many points of each class a skeleton has.
struct Skeleton_point_counts
{
  std::size_t isolated = 0;            ///< points of degree 0
  std::size_t end = 0;                 ///< end points (degree 1)
  std::size_t middle = 0;              ///< middle points (degree 2)
  std::size_t connection = 0;          ///< connection points
  std::size_t branched_connection = 0; ///< branched connection points
  /// The points of degree 3 or more.
  std::size_t junctions() const { return connection + branched_connection; }
  /// All the points.
  std::size_t total() const { return isolated + end + middle + connection + branched_connection; }
};

/// \ingroup PkgGeodesicSkeletonRef
/// The degree of `k` in `skeleton`: how many of its 26 neighbours belong to the set
/// (paper, Definition 6). O(1).
/// \tparam VoxelSet a model of `VoxelSet`.
template <typename VoxelSet>
int skeleton_degree(const VoxelSet& skeleton, const Voxel_key& k)
{
  int degree = 0;
  for(const Voxel_key& offset : neighbourhood_26())
    degree += skeleton.contains(k + offset) ? 1 : 0;
  return degree;
}

/// \ingroup PkgGeodesicSkeletonRef
/// Classifies every point of a one-voxel-thick skeleton by its degree in the
/// 26-neighbourhood (paper, Definitions 6 and 7) and writes the class of each voxel to
/// `classes`.
///
/// \tparam VoxelSet a model of `VoxelSet`.
/// \tparam PointClassMap a writable property map from `Voxel_key` to `Skeleton_point_class`,
///         e.g. `boost::associative_property_map<std::unordered_map<Voxel_key, Skeleton_point_class>>`.
/// \returns how many points of each class there are.
///
/// \pre `skeleton` is meant to be one voxel thick (the output of thinning); a thicker set
///      is classified all the same, its inner voxels becoming branched connection points.
///
/// \b Complexity: O(N) for N skeleton voxels (two passes over the 26-neighbourhoods),
/// O(N) extra memory.
template <typename VoxelSet, typename PointClassMap>
Skeleton_point_counts classify_skeleton_points(const VoxelSet& skeleton, PointClassMap classes)
{
  std::unordered_map<Voxel_key, int, Voxel_key_hash> degree;
  degree.reserve(skeleton.size());
  skeleton.for_each([&](const Voxel_key& k) { degree.emplace(k, skeleton_degree(skeleton, k)); });

  auto is_end_or_middle = [&](const Voxel_key& k) {
    const int d = degree.at(k);
    return d == 1 || d == 2;
  };
  Skeleton_point_counts counts;
  for(const auto& [k, d] : degree)
  {
    Skeleton_point_class c = Skeleton_point_class::isolated;
    if(d == 1)
      c = Skeleton_point_class::end;
    else if(d == 2)
      c = Skeleton_point_class::middle;
    else if(d >= 3)
    {
      c = Skeleton_point_class::connection;
      for(const Voxel_key& offset : neighbourhood_26())
      {
        const Voxel_key n = k + offset;
        if(skeleton.contains(n) && !is_end_or_middle(n))
        {
          c = Skeleton_point_class::branched_connection;
          break;
        }
      }
    }
    put(classes, k, c);
    switch(c)
    {
      case Skeleton_point_class::isolated: ++counts.isolated; break;
      case Skeleton_point_class::end: ++counts.end; break;
      case Skeleton_point_class::middle: ++counts.middle; break;
      case Skeleton_point_class::connection: ++counts.connection; break;
      case Skeleton_point_class::branched_connection: ++counts.branched_connection; break;
    }
  }
  return counts;
}

/// \ingroup PkgGeodesicSkeletonRef
/// Counts the points of each class without storing the classes.
/// \b Complexity: O(N) for N skeleton voxels.
template <typename VoxelSet>
Skeleton_point_counts count_skeleton_points(const VoxelSet& skeleton)
{
  return classify_skeleton_points(skeleton, boost::dummy_property_map());
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_CLASSIFY_SKELETON_POINTS_H
