// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_PARAMETER_RANGES_H
#define CGAL_GEODESIC_SKELETON_PARAMETER_RANGES_H

/// \file parameter_ranges.h
/// The valid ranges and defaults of the package's numeric named parameters: the one place
/// that the functions which read them and the `skeletonize` program both use.

#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The valid values and the default of a numeric named parameter: every value in
/// [`low`, `high`] (NaN never), an integer when `integer` is set, an odd one when `odd` is.
struct Parameter_range
{
  const char* name;     ///< the named parameter
  double low;           ///< smallest valid value
  double high;          ///< largest valid value (may be infinite)
  double default_value; ///< the value taken when the parameter is not given
  bool integer;         ///< only whole numbers
  bool odd;             ///< only odd whole numbers

  /// Whether `value` is valid.
  bool contains(double value) const
  {
    if(!(value >= low && value <= high)) // false for NaN
      return false;
    if(integer && value != std::floor(value))
      return false;
    return !odd || std::fmod(value, 2.) != 0.;
  }

  /// The valid values in words, e.g. "an odd number in [1, 1001]".
  std::string valid_values() const
  {
    std::ostringstream text;
    text.precision(12);
    text << (odd ? "an odd number in [" : integer ? "an integer in [" : "in [") << low << ", " << high << "]";
    return text.str();
  }
};

/// \ingroup PkgGeodesicSkeletonRef
/// The ranges and defaults of the package's numeric named parameters (the functions that
/// read each one document it).
namespace parameter_ranges {

/// `voxelize()`: the longest principal extent of the mesh, in voxels.
inline constexpr Parameter_range resolution{"resolution", 4, 8192, 64, true, false};
/// `remove_small_pieces()`: pieces of the solid smaller than this fraction of the largest
/// are removed (0 keeps all).
inline constexpr Parameter_range small_piece_fraction{"small_piece_fraction", 0, 1, 0.05, false, false};
/// The voxel stages: the most memory a stage may allocate, in bytes (default 2 GiB).
inline constexpr Parameter_range memory_limit{"memory_limit", 1, std::numeric_limits<double>::infinity(),
                                              2147483648., false, false};
/// `split_into_bones()`: the smallest radius that the split's lengths are measured in, world
/// units (0: the MAT radius as it is). `extract_control_skeleton()` gives half a voxel of the
/// default grid (the mesh's longest principal extent / 128) unless told otherwise.
inline constexpr Parameter_range smallest_radius{"smallest_radius", 0, std::numeric_limits<double>::infinity(),
                                                 0., false, false};
/// `thin()`: the largest MAT radius of a thin part, in voxels (sqrt(2): a part about two
/// voxels thick). `extract_control_skeleton()` gives `default_thin_part_radius()`.
inline constexpr Parameter_range thin_part_radius{"thin_part_radius", 0, 1000, 1.4142135623730951, false, false};
/// `prune_skeleton()`: end branches shorter than this many MAT radii are snipped.
inline constexpr Parameter_range spur_length_factor{"spur_length_factor", 0, 100, 1.2, false, false};
/// `prune_skeleton()`: end branches whose MAT balls reach out of their junction's ball by
/// less than this many times the largest MAT radius of their piece are snipped (the rig's
/// level of detail; 0 keeps them).
inline constexpr Parameter_range limb_protrusion_factor{"limb_protrusion_factor", 0, 100, 0.75, false, false};
/// `reach_sheet_lobes()`: a lobe of a thick plate's medial sheet that reaches out of the
/// skeleton's balls by this many times the largest MAT radius of its piece gets a path into
/// it (0: none).
inline constexpr Parameter_range sheet_lobe_reach_factor{"sheet_lobe_reach_factor", 0, 100, 1.0, false, false};
/// `extract_control_skeleton()`: the resolution of the grid that decides which branches the
/// rig has; a finer grid routes them (0, or at least the resolution, turns this off).
inline constexpr Parameter_range level_of_detail_resolution{"level_of_detail_resolution", 0, 8192, 64, true, false};
/// `smooth_skeleton()`: points averaged along the branches.
inline constexpr Parameter_range smoothing_window{"smoothing_window", 1, 1001, 5, true, true};
/// `split_into_bones()`: the chord-to-point accumulation that makes a bend joint.
inline constexpr Parameter_range bend_threshold{"bend_threshold", 0, 1, 0.08, false, false};
/// `split_into_bones()`: allowed deviation of a bone from its chord, in MAT radii.
inline constexpr Parameter_range straightness_tolerance{"straightness_tolerance", 0, 100, 0.5, false, false};
/// `split_into_bones()`: every bone is longer than this, in MAT radii.
inline constexpr Parameter_range minimum_bone_length_factor{"minimum_bone_length_factor", 0, 1000, 2.0,
                                                            false, false};
/// `split_into_bones()`: a straight bone longer than this many times the largest MAT radius
/// of its piece is cut into equal bones at its narrowings (0: no limit).
inline constexpr Parameter_range maximum_bone_length_factor{"maximum_bone_length_factor", 0, 1000, 3.0,
                                                            false, false};
/// `split_into_bones()`: every bone is longer than this, in largest MAT radii of its piece: the rig's
/// level of detail, whatever the grid resolves (0: no such floor).
inline constexpr Parameter_range minimum_bone_length_of_piece_factor{"minimum_bone_length_of_piece_factor", 0, 1000,
                                                                     0.5, false, false};
/// `split_into_bones()`: how far back from a tip of the skeleton its joint sits, in lengths of
/// its bone (0 in `split_into_bones()` unless given; the default is `extract_control_skeleton()`'s).
inline constexpr Parameter_range tip_joint_setback{"tip_joint_setback", 0, 0.45, 0.3, false, false};
/// `split_into_bones()`: the length that bones are cut into, in world units (0: no cut).
inline constexpr Parameter_range joint_spacing{"joint_spacing", 0, std::numeric_limits<double>::infinity(), 0,
                                               false, false};
/// `extract_control_skeleton()`: the `joint_spacing` of `split_into_bones()`, in longest principal
/// extents of the mesh (0: no cut).
inline constexpr Parameter_range joint_spacing_factor{"joint_spacing_factor", 0, 1, 0.1, false, false};
/// `split_into_bones()`: each chord length, in mean MAT radii (defaults: 3 and 6).
inline constexpr Parameter_range chord_length_factor{"chord_length_factors", 1e-3, 1000, 3.0, false, false};
/// `chord_to_point_distance_accumulation()`: chords averaged per point.
inline constexpr Parameter_range number_of_chords{"number_of_chords", 1, 1000, 16, true, false};
/// `reeb_graph()` and `extract_control_skeleton()`: intervals of the Reeb graph.
inline constexpr Parameter_range number_of_reeb_intervals{"number_of_reeb_intervals", 1, 1000000, 30, true,
                                                          false};
/// `integral_geodesic_mapping_function()`: base vertices of the integral.
inline constexpr Parameter_range number_of_base_vertices{"number_of_base_vertices", 1, 100000, 50, true,
                                                         false};
/// `compute_skinning_weights()`: bones that may influence one vertex (glTF reads 4 per set).
inline constexpr Parameter_range max_bones_per_vertex{"max_bones_per_vertex", 1, 8, 4, true, false};
/// `compute_skinning_weights()`: the exponent the diffused weights are raised to before they
/// are scaled to sum 1 (larger: sharper transitions at the joints).
inline constexpr Parameter_range sharpness{"sharpness", 1, 16, 2.5, false, false};
/// `compute_skinning_weights()`: weights under this share of a vertex's total are dropped.
inline constexpr Parameter_range minimum_weight{"minimum_weight", 0, 0.5, 0.05, false, false};
/// `compute_skinning_weights()`: a bone may heat a vertex only when its distance through the
/// solid is less than this many times the nearest bone's.
inline constexpr Parameter_range influence_ratio{"influence_ratio", 1.05, 100, 1.25, false, false};

} // namespace parameter_ranges

namespace internal {

// Returns `value` when `range` contains it; otherwise throws std::invalid_argument
// "<caller>: <name> must be <valid values>, got <value>" (`name` defaults to the range's).
template <typename T>
T checked_parameter(const Parameter_range& range, T value, const std::string& caller,
                    const char* name = nullptr)
{
  const double v = static_cast<double>(value);
  if(!range.contains(v))
  {
    std::ostringstream msg;
    msg.precision(12);
    msg << caller << ": " << (name ? name : range.name) << " must be " << range.valid_values() << ", got "
        << value;
    throw std::invalid_argument(msg.str());
  }
  return value;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// The default of the `resolution` named parameter of `voxelize()`: the longest principal
/// extent of the mesh, in voxels (see benchmark/README.md for the measurement behind it).
constexpr int default_voxel_resolution = static_cast<int>(parameter_ranges::resolution.default_value);

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_PARAMETER_RANGES_H
