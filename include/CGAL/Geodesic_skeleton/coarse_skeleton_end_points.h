// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_COARSE_SKELETON_END_POINTS_H
#define CGAL_GEODESIC_SKELETON_COARSE_SKELETON_END_POINTS_H

/// \file coarse_skeleton_end_points.h
/// What a mesh's voxel skeleton on a coarser grid tells the stages on a finer one, to keep
/// the level of detail of that grid: the end points of the pruned skeleton, which
/// `prune_skeleton()` reads (its `coarse_end_points`), and the widest sheet of each piece,
/// which `split_into_bones()` reads (its `piece_radius_map`).

#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/No_enclosed_volume.h>
#include <CGAL/Geodesic_skeleton/Skeleton_radius_in_voxels_map.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/internal/prune/coarse_end_points.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/sheet_half_widths.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/Orthogonal_k_neighbor_search.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/Simple_cartesian.h>
#include <CGAL/property_map.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/counting_iterator.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <array>
#include <optional>
#include <utility>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// The `coarse_end_point_tolerance` that goes with the end points of
/// `coarse_skeleton_end_points()` at `coarse_resolution`, given to `prune_skeleton()` on a
/// grid of `resolution`: the default tolerance (4 voxels) on the coarser grid, in voxels of
/// the finer one, as `extract_control_skeleton()` gives it.
/// \pre `coarse_resolution` > 0.
/// \b Complexity: constant.
inline double default_coarse_end_point_tolerance(int resolution, int coarse_resolution)
{
  return parameter_ranges::coarse_end_point_tolerance.default_value * double(resolution) /
         double(coarse_resolution);
}

/// \ingroup PkgGeodesicSkeletonRef
/// What the voxel skeleton of a mesh on a coarser grid tells the stages on a finer one, in
/// the grid coordinates of the finer grid (a voxel `k` covers [k, k + 1) along each axis):
/// made by `coarse_skeleton_level_of_detail()`.
struct Coarse_skeleton_level_of_detail
{
  /// The end points of the pruned skeleton: the centres of the voxels of degree 1 in its
  /// graph, the one `to_graph()` makes (26-adjacency without the little triangles of
  /// junctions). `prune_skeleton()` reads them as its `coarse_end_points`.
  std::vector<std::array<double, 3>> end_points;
  /// The centres of the voxels of the skeleton before pruning.
  std::vector<std::array<double, 3>> piece_points;
  /// For each of `piece_points`, the half width (world units) of the widest thin sheet of
  /// the piece it is in (`widest_sheet_radius_of_pieces()`, in world units as
  /// `sheet_half_widths()` gives them), 0 for a piece without any.
  std::vector<double> piece_half_widths;
  /// The solid on the coarser grid, as `voxelize()` made it (in that grid's own frame): the
  /// pieces it joins, `join_pieces_joined_on_coarser_grid()` joins on the finer grid.
  Dense_voxel_grid solid;
};

namespace internal {

// coarse_skeleton_level_of_detail() with the parameters of its stages read into one pack
// of a fixed type: compiled once per mesh and point map type, whatever pack the caller has.
template <typename FaceGraph, typename CoarseParameters>
std::optional<Coarse_skeleton_level_of_detail>
coarse_skeleton_level_of_detail_with(const FaceGraph& mesh, const Voxel_frame& frame, const CoarseParameters& coarse_np)
{
  Dense_voxel_grid solid;
  Voxelized_surface surface;
  try
  {
    voxelize(mesh, solid, parameters::combine(parameters::voxelized_surface_output(&surface), coarse_np));
  }
  catch(const No_enclosed_volume&)
  {
    return std::nullopt;
  }
  Coarse_skeleton_level_of_detail coarse;
  coarse.solid = solid; // before thinning, which deletes voxels of `solid`
  const Voxel_distance_field distances = distance_transform(solid, coarse_np);
  Sheet_radii sheet_radii, slanted_sheet_radii;
  thin(solid, distances,
       parameters::combine(
           parameters::sheet_radius_map(boost::associative_property_map<Sheet_radii>(sheet_radii)),
           parameters::slanted_sheet_radius_map(boost::associative_property_map<Sheet_radii>(slanted_sheet_radii)),
           coarse_np));
  Sparse_voxel_set skeleton;
  skeleton.reset(solid.frame(), solid.bounding_box());
  solid.for_each([&](const Voxel_key& k) { skeleton.insert(k); });
  remove_small_pieces(skeleton, distances, coarse_np);
  cut_spurious_cycles(skeleton, mesh, parameters::combine(parameters::voxelized_surface(&std::as_const(surface)), coarse_np));

  const auto in_frame = [&](const Voxel_key& k) { return frame.to_grid(solid.frame().centre(k)); };
  const Sheet_radii widest = widest_sheet_radius_of_pieces(skeleton, slanted_sheet_radii);
  std::vector<std::pair<Voxel_key, double>> in_voxel_order(widest.begin(), widest.end());
  std::sort(in_voxel_order.begin(), in_voxel_order.end());
  for(const auto& [k, rounds] : in_voxel_order)
  {
    coarse.piece_points.push_back(in_frame(k));
    coarse.piece_half_widths.push_back(internal::sheet_half_width(rounds, solid.frame().voxel_size()));
  }
  prune_skeleton(skeleton, parameters::combine(parameters::mat_radius_map(mat_radius_in_voxels_map(distances)),
                                               parameters::sheet_radius_map(sheet_radius_in_voxels_map(sheet_radii)),
                                               parameters::piece_radius_map(sheet_radius_in_voxels_map(widest)),
                                               coarse_np));
  for(const Voxel_key& k : internal::graph_end_points(skeleton))
    coarse.end_points.push_back(in_frame(k));
  return coarse;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// The skeleton of `mesh` at `resolution`, as far as it sets the level of detail of a
/// finer grid: the end points of the pruned voxel skeleton (the branches that the level of
/// detail of that resolution keeps) and the widest sheet of each piece of the voxel
/// skeleton before pruning (the width that pruning judges the piece's twigs by), in the grid
/// coordinates of `frame` (usually the finer grid's), and the solid on that grid (the
/// pieces it joins).
///
/// The voxel stages run as `extract_control_skeleton()` runs them on the grid of its level
/// of detail: `voxelize()`, `distance_transform()`, `thin()` (with the sheet radii, read at
/// one level and across close levels, and `default_thin_part_radius(resolution)`),
/// `remove_small_pieces()`, `cut_spurious_cycles()`, then `widest_sheet_radius_of_pieces()`
/// of the radii read across close levels and `prune_skeleton()` (with the MAT and sheet
/// radii and those widest sheets as its `piece_radius_map`), with the settings of `np` but
/// the resolution. The points are voxel centres moved from the coarser grid's frame to `frame`.
///
/// \tparam FaceGraph a model of `FaceListGraph`, as for `voxelize()`.
/// \param mesh the mesh.
/// \param resolution the resolution of the coarser grid, as `voxelize()`'s `resolution`.
/// \param frame the grid whose coordinates the points are given in, e.g. the finer grid's
///        `Dense_voxel_grid::frame()`.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters": those
///        of the stages above (`vertex_point_map`, `fill_holes`, `memory_limit`,
///        `small_piece_fraction`, `spur_length_factor`, `limb_protrusion_factor`, ...); a
///        `resolution` or `thin_part_radius` in it is not used.
///
/// \returns the level of detail, or `std::nullopt` when the mesh encloses no volume at
///          `resolution` (a shape thinner than a voxel of that grid).
/// \throws std::invalid_argument for any other bad input or parameter, as the stages do.
///
/// \b Complexity: that of the stages on the grid of `resolution`: linear in its voxels and
/// the mesh's faces, in practice.
template <typename FaceGraph, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::optional<Coarse_skeleton_level_of_detail>
coarse_skeleton_level_of_detail(const FaceGraph& mesh, int resolution, const Voxel_frame& frame,
                                const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  namespace ranges = parameter_ranges;
  // Every parameter that the stages below read; each keeps its meaning, unchecked values
  // are checked by the stage that reads them.
  const auto coarse_np = parameters::combine(
      parameters::resolution(resolution), parameters::thin_part_radius(default_thin_part_radius(resolution)),
      parameters::vertex_point_map(choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                                    get_const_property_map(CGAL::vertex_point, mesh))),
      parameters::fill_holes(bool(choose_parameter(get_parameter(np, internal_np::fill_holes_tag), true))),
      parameters::keep_surface_voxels(bool(choose_parameter(get_parameter(np, internal_np::keep_surface_voxels_tag), true))),
      parameters::memory_limit(internal::memory_limit(np, "coarse_skeleton_level_of_detail")),
      parameters::small_piece_fraction(double(choose_parameter(get_parameter(np, internal_np::small_piece_fraction_tag),
                                                               ranges::small_piece_fraction.default_value))),
      parameters::spur_length_factor(double(choose_parameter(get_parameter(np, internal_np::spur_length_factor_tag),
                                                             ranges::spur_length_factor.default_value))),
      parameters::limb_protrusion_factor(double(choose_parameter(
          get_parameter(np, internal_np::limb_protrusion_factor_tag), ranges::limb_protrusion_factor.default_value))));
  return internal::coarse_skeleton_level_of_detail_with(mesh, frame, coarse_np);
}

/// \ingroup PkgGeodesicSkeletonRef
/// The end points of the pruned voxel skeleton of `mesh` at `resolution`, in the grid
/// coordinates of `frame`: the `end_points` of `coarse_skeleton_level_of_detail()`.
///
/// \tparam FaceGraph a model of `FaceListGraph`, as for `voxelize()`.
/// \param mesh the mesh.
/// \param resolution the resolution of the coarser grid.
/// \param frame the grid whose coordinates the points are given in.
/// \param np the named parameters of `coarse_skeleton_level_of_detail()`.
/// \returns the end points, or `std::nullopt` when the mesh encloses no volume at
///          `resolution`.
/// \throws std::invalid_argument as `coarse_skeleton_level_of_detail()` does.
///
/// \b Complexity: that of `coarse_skeleton_level_of_detail()`.
template <typename FaceGraph, typename NamedParameters = CGAL::parameters::Default_named_parameters>
std::optional<std::vector<std::array<double, 3>>>
coarse_skeleton_end_points(const FaceGraph& mesh, int resolution, const Voxel_frame& frame,
                           const NamedParameters& np = CGAL::parameters::default_values())
{
  std::optional<Coarse_skeleton_level_of_detail> coarse = coarse_skeleton_level_of_detail(mesh, resolution, frame, np);
  if(!coarse)
    return std::nullopt;
  return std::move(coarse->end_points);
}

/// \ingroup PkgGeodesicSkeletonRef
/// The half width of the widest sheet of the coarser skeleton's piece nearest each vertex
/// of a curve skeleton: the `piece_half_widths` value of the `piece_points` point nearest
/// the centre of the vertex's voxel (ties to the first found). `extract_control_skeleton()`
/// takes the larger of it and the vertex's own piece width as the `piece_radius_map` of
/// `split_into_bones()`, so that a piece is split at the level of detail that the coarser
/// grid measures for it: the rounds of a burn that measure a sheet's width (`thin()`'s sheet
/// radius) do not always double when the grid does (a piece of plates without thickness has
/// its widest sheet 13.5 wide at 64 and 9.4 at 128).
///
/// \tparam CurveSkeleton an undirected `boost::adjacency_list` with `vecS` vertex storage
///         whose vertex bundle has a `voxel` member (`Voxel_key`), e.g. the
///         `Curve_skeleton<Point, MeshVertex>` that `to_graph()` writes.
/// \param curve the curve skeleton, on the grid whose coordinates `coarse` is given in.
/// \param coarse what `coarse_skeleton_level_of_detail()` returned for that grid.
/// \returns one width per vertex (world units), indexed by vertex descriptor (0 to N-1); all
///          0 when `coarse` has no piece points.
/// \pre `coarse.piece_points` and `coarse.piece_half_widths` have the same size.
///
/// \b Complexity: O(P log P) for the P piece points (a k-d tree), then about O(log P) for
/// each vertex.
template <typename CurveSkeleton>
std::vector<double> coarse_piece_half_widths(const CurveSkeleton& curve, const Coarse_skeleton_level_of_detail& coarse)
{
  CGAL_precondition(coarse.piece_points.size() == coarse.piece_half_widths.size());
  using Kernel = CGAL::Simple_cartesian<double>;
  using Point = Kernel::Point_3;
  using Point_of_index = CGAL::Pointer_property_map<Point>::const_type;
  using Traits = CGAL::Search_traits_adapter<std::size_t, Point_of_index, CGAL::Search_traits_3<Kernel>>;
  using Search = CGAL::Orthogonal_k_neighbor_search<Traits>;

  std::vector<double> widths(num_vertices(curve), 0.0);
  if(coarse.piece_points.empty())
    return widths;
  std::vector<Point> points;
  points.reserve(coarse.piece_points.size());
  for(const std::array<double, 3>& p : coarse.piece_points)
    points.emplace_back(p[0], p[1], p[2]);
  const Point_of_index point_of_index = CGAL::make_property_map(std::as_const(points));
  const typename Search::Tree tree(boost::counting_iterator<std::size_t>(0),
                                   boost::counting_iterator<std::size_t>(points.size()),
                                   typename Search::Tree::Splitter(), Traits(point_of_index));
  const typename Search::Distance distance(point_of_index);
  for(std::size_t v = 0; v < widths.size(); ++v)
  {
    const internal::Vec3 c = internal::centre_in_grid(curve[v].voxel);
    const Search nearest(tree, Point(c[0], c[1], c[2]), 1, 0, true, distance);
    widths[v] = coarse.piece_half_widths[nearest.begin()->first];
  }
  return widths;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_COARSE_SKELETON_END_POINTS_H
