// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_GRAFT_COARSE_END_BRANCHES_H
#define CGAL_GEODESIC_SKELETON_GRAFT_COARSE_END_BRANCHES_H

/// \file graft_coarse_end_branches.h
/// Grafts onto a pruned skeleton the end branches that the skeleton of the same shape on a
/// coarser grid has and it lacks, so that a finer grid does not lose limbs.

#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/internal/path_through_the_middle.h>
#include <CGAL/Geodesic_skeleton/internal/prune/coarse_end_points.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

namespace internal {

// The voxel whose cell holds the finite point `p` given in grid coordinates (a point far
// outside any grid gets a voxel far outside it).
inline Voxel_key voxel_holding(const std::array<double, 3>& p)
{
  const double far = double((std::numeric_limits<int>::max)() / 2);
  auto coordinate = [&](double x) { return static_cast<int>(std::clamp(std::floor(x), -far, far)); };
  return Voxel_key{coordinate(p[0]), coordinate(p[1]), coordinate(p[2])};
}

// The coarse end point that the skeleton lacks most: of those inside the solid, tried not
// yet, that no end point of the skeleton's graph is within `tolerance` of and that no voxel
// of the skeleton is within `tolerance` or the point's MAT radius of, the farthest from the
// skeleton (ties: the first). `coarse.size()` when there is none. `ends` are the end points
// of the skeleton's graph.
template <typename VoxelSet>
std::size_t coarse_end_point_lacked_most(const VoxelSet& skeleton, const std::vector<Voxel_key>& ends,
                                         const Voxel_distance_field& distances,
                                         const std::vector<std::array<double, 3>>& coarse, double tolerance,
                                         const std::vector<bool>& tried)
{
  std::size_t lacked_most = coarse.size();
  double farthest = 0;
  for(std::size_t c = 0; c < coarse.size(); ++c)
  {
    const Voxel_key voxel = voxel_holding(coarse[c]);
    if(tried[c] || !distances.inside(voxel) || has_end_near(ends, coarse[c], tolerance * tolerance))
      continue;
    double nearest = std::numeric_limits<double>::infinity();
    skeleton.for_each([&](const Voxel_key& k) {
      nearest = (std::min)(nearest, squared_distance3(coarse[c], centre_in_grid(k)));
    });
    const double reach = (std::max)(tolerance, distances.radius(voxel) / distances.frame().voxel_size());
    if(nearest > reach * reach && nearest > farthest)
    {
      farthest = nearest;
      lacked_most = c;
    }
  }
  return lacked_most;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Grafts onto a pruned skeleton the end branches that the skeleton of the same shape on a
/// coarser grid ends in and that it lacks, while its graph has fewer end points than the
/// coarser skeleton: each along the middle of the solid, from the coarse end point to the
/// skeleton.
///
/// A finer grid thins a part differently: a rim one voxel thick on the coarser grid is two
/// voxels thick on the finer one, a leg that the coarser grid thins to a branch may thin to
/// a stub on the finer one, and pruning cannot give back what thinning did not make (the
/// tripod has 3 legs at resolution 64 and 2 at 128). This function gives the finer skeleton
/// the limbs of the level of detail. While the graph of `skeleton` (the one `to_graph()`
/// makes) has fewer end points than `coarse_end_points` has points, it takes the coarse end
/// point that the skeleton lacks most: of those inside the solid, that no end point of the
/// graph is within `coarse_end_point_tolerance` of and that no voxel of the skeleton is
/// within that tolerance or the point's MAT radius of (whichever is larger), the farthest
/// from the skeleton (ties: the first given). It inserts the cheapest 26-connected path
/// inside the solid from the voxel holding that point to the skeleton, where a step costs
/// its length over the MAT radius of the voxel it enters: the path keeps to the middle of
/// the part, and its cost is a length in MAT radii, the same on any grid. Each coarse end
/// point is tried once; one whose piece of the solid holds no skeleton voxel gets no branch.
///
/// `extract_control_skeleton()` calls it after `prune_skeleton()`, at a resolution finer
/// than its `level_of_detail_resolution`, with the coarse end points that pruning took.
///
/// \tparam VoxelSet a model of `VoxelSet`, e.g. `Sparse_voxel_set`; read through
///         `for_each()` and `contains()`, and grown with `insert()`.
/// \param skeleton a pruned one-voxel-thick skeleton inside the solid of `distances`;
///        receives the branches.
/// \param distances the distance transform of the solid (`distance_transform()`): which
///        voxels are inside, and their MAT radii.
/// \param coarse_end_points the end points of the pruned skeleton of the same shape on a
///        coarser grid, in the grid coordinates of `skeleton`'s voxels (voxel `k` covers
///        [k, k + 1) along each axis), e.g. `Coarse_skeleton_level_of_detail::end_points`.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters" among
///        the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{coarse_end_point_tolerance}
///     \cgalParamDescription{how near an end point of the skeleton, in voxels, a coarse end
///                           point must be for the skeleton to have its branch, in [0, 1e6]
///                           (package parameter; as `prune_skeleton()` takes it)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{4}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns the number of branches grafted.
/// \pre `skeleton` and `distances` share a frame.
/// \throws std::invalid_argument when a coarse end point is not finite or
///         `coarse_end_point_tolerance` is out of range.
///
/// \b Complexity: O(C (N log N + N C) + G (V log V + W)) for C coarse end points and N
/// skeleton voxels (the graph is traced, and every coarse end point compared with every
/// skeleton voxel, once per try, of which there are at most C), and G searches, each of
/// which visits the V solid voxels cheaper to reach than the skeleton (at most the voxels of
/// the piece) and clears W voxels of arrays: a box around the coarse end point, 33 voxels
/// wide and twice as wide each time the search reaches its side (at most the box of
/// `distances`), 9 bytes per voxel. Nothing is done, beyond tracing the graph once, when
/// the graph has as many end points as `coarse_end_points`.
template <typename VoxelSet, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::size_t graft_coarse_end_branches(VoxelSet& skeleton, const Voxel_distance_field& distances,
                                      const std::vector<std::array<double, 3>>& coarse_end_points,
                                      const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  const double tolerance = internal::checked_parameter(
      parameter_ranges::coarse_end_point_tolerance,
      choose_parameter(get_parameter(np, internal_np::coarse_end_point_tolerance_tag),
                       parameter_ranges::coarse_end_point_tolerance.default_value),
      "graft_coarse_end_branches");
  internal::check_coarse_end_points_are_finite(coarse_end_points, "graft_coarse_end_branches");

  std::vector<bool> tried(coarse_end_points.size(), false);
  std::size_t grafted = 0;
  for(std::vector<Voxel_key> ends = internal::graph_end_points(skeleton); ends.size() < coarse_end_points.size();
      ends = internal::graph_end_points(skeleton))
  {
    const std::size_t lacked =
        internal::coarse_end_point_lacked_most(skeleton, ends, distances, coarse_end_points, tolerance, tried);
    if(lacked == coarse_end_points.size())
      break;
    tried[lacked] = true;
    const std::vector<Voxel_key> branch = internal::path_through_the_middle(
        distances, internal::voxel_holding(coarse_end_points[lacked]),
        [&](const Voxel_key& k) { return skeleton.contains(k); });
    for(const Voxel_key& k : branch)
      skeleton.insert(k);
    grafted += branch.empty() ? 0 : 1;
  }
  return grafted;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_GRAFT_COARSE_END_BRANCHES_H
