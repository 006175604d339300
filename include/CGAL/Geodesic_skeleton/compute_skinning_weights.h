// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_COMPUTE_SKINNING_WEIGHTS_H
#define CGAL_GEODESIC_SKELETON_COMPUTE_SKINNING_WEIGHTS_H

/// \file compute_skinning_weights.h
/// Skinning weights of a mesh for a control skeleton, by geodesic voxel binding.

#include <CGAL/Geodesic_skeleton/Bone_weights.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/skinning_fields.h>
#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>

#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/number_utils.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace CGAL {
namespace Geodesic_skeleton {

/// \ingroup PkgGeodesicSkeletonRef
/// What `compute_skinning_weights()` did.
struct Skinning_report
{
  std::size_t solid_voxels = 0;   ///< voxels of the solid the distances run through
  double voxel_size = 0;          ///< edge of a voxel, in world units
  /// Voxels reached by the bones' distance fields, summed over the bones (the work of the
  /// bounded Dijkstra searches; the solid voxels times the bones would be the unbounded cost).
  std::size_t voxel_visits = 0;
  /// Vertices bound to the bone nearest in straight line, because no bone is in the part
  /// of the solid they touch (a detached piece without a bone, such as a loose eye).
  std::size_t vertices_bound_in_straight_line = 0;
  double milliseconds = 0;        ///< wall-clock time of the call
};

namespace internal {

// The polyline of a bone, in grid coordinates: its points, or the segment from its parent
// joint to its child joint when it has fewer than two.
template <typename Point>
std::vector<Vec3> bone_polyline_in_grid(const Control_skeleton<Point>& skeleton,
                                        typename boost::graph_traits<Control_skeleton<Point>>::edge_descriptor e,
                                        const Voxel_frame& frame)
{
  const Control_bone<Point>& bone = skeleton[e];
  auto grid = [&](const Point& p) {
    return frame.to_grid(Vec3{CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())});
  };
  std::vector<Vec3> polyline;
  if(bone.points.size() >= 2)
    for(const Point& p : bone.points)
      polyline.push_back(grid(p));
  else
    polyline = {grid(skeleton[source(e, skeleton)].point), grid(skeleton[target(e, skeleton)].point)};
  for(const Vec3& g : polyline)
    if(!std::isfinite(g[0]) || !std::isfinite(g[1]) || !std::isfinite(g[2]))
      throw std::invalid_argument("compute_skinning_weights: a bone has a non-finite point");
  return polyline;
}

template <typename Point>
void check_bones(const Control_skeleton<Point>& skeleton, const char* caller)
{
  if(num_edges(skeleton) == 0)
    throw std::invalid_argument(std::string(caller) + ": the control skeleton has no bone");
  if(num_edges(skeleton) > std::size_t(std::numeric_limits<std::uint32_t>::max()))
    throw std::invalid_argument(std::string(caller) + ": too many bones");
}

// Keeps the `k` largest weights of a vertex.
inline void keep_largest(Bone_weights& weights, std::size_t k, std::uint32_t bone, float weight)
{
  if(weights.size() < k)
  {
    weights.push_back(bone, weight);
    return;
  }
  std::size_t smallest = 0;
  for(std::size_t i = 1; i < weights.size(); ++i)
    if(weights.weight[i] < weights.weight[smallest])
      smallest = i;
  if(weight > weights.weight[smallest])
  {
    weights.bone[smallest] = bone;
    weights.weight[smallest] = weight;
  }
}

// Sorts the pairs by decreasing weight (bone index for ties) and scales them to sum 1.
inline void normalise(Bone_weights& weights)
{
  const std::size_t n = weights.size();
  std::array<std::size_t, Bone_weights::capacity> order{};
  for(std::size_t i = 0; i < n; ++i)
    order[i] = i;
  std::sort(order.begin(), order.begin() + std::ptrdiff_t(n), [&](std::size_t a, std::size_t b) {
    return weights.weight[a] != weights.weight[b] ? weights.weight[a] > weights.weight[b]
                                                  : weights.bone[a] < weights.bone[b];
  });
  const double total = weights.total();
  Bone_weights sorted;
  for(std::size_t i = 0; i < n; ++i)
    sorted.push_back(weights.bone[order[i]], float(weights.weight[order[i]] / total));
  weights = sorted;
}

} // namespace internal

/// \ingroup PkgGeodesicSkeletonRef
/// Computes, for every vertex of `mesh`, the skinning weights of at most
/// `max_bones_per_vertex` bones of `skeleton`: non-negative, summing to 1, for linear
/// blend skinning (as glTF 2.0 and every animation tool use them).
///
/// The method is geodesic voxel binding (after Dionne and de Lasa, <i>Geodesic Voxel
/// Binding for Production Character Meshes</i>, SCA 2013): distances from the bones run
/// through the voxels of the mesh's solid (`voxelize()`), and the weight of bone `b` at a
/// vertex is `w_b = max(0, (d_b + 1/2)^(-p) - (s (d1 + 1/2))^(-p))`, with `d_b` its
/// distance to bone `b`, `d1` to the nearest bone (in voxels), `p` = `falloff` and `s` =
/// `influence_ratio`; the `max_bones_per_vertex` largest are kept and scaled to sum 1. A
/// vertex that no bone's search reaches (a detached piece without a bone) is bound with
/// weight 1 to the bone nearest in straight line. The searches, the reading of a field at
/// a vertex and what bounds the cost are described in the manual, section
/// \ref manual_skinning_method.
///
/// The skeleton may be any: from `extract_control_skeleton()` or `split_into_bones()`, or
/// filled by hand (joints with their points, bones as edges from parent to child; `points`
/// may be empty). Its joints may be in any order; the cut bones are ignored.
///
/// \tparam TriangleMesh a model of `FaceListGraph` (`Surface_mesh`, `Polyhedron_3`, ...), as
///         for `voxelize()`.
/// \tparam Point the skeleton's point type, with `x()`, `y()`, `z()`.
/// \tparam WeightMap a model of `WritablePropertyMap` with the mesh's vertex descriptor as
///         key type and `Bone_weights` as value type (e.g. a `Surface_mesh` property map, or
///         `boost::make_iterator_property_map()` over a `std::vector<Bone_weights>` and the
///         vertex index map). A bone is a bone number (see `numbered_bones()`).
/// \param mesh the mesh.
/// \param skeleton the control skeleton, in the mesh's coordinates.
/// \param weight_output receives the weights of every vertex, by decreasing weight.
/// \param np an optional sequence of \ref manual_named_parameters "named parameters"
///        among the ones listed below:
/// \cgalNamedParamsBegin
///   \cgalParamNBegin{max_bones_per_vertex}
///     \cgalParamDescription{the most bones that influence one vertex, in [1, 8] (package
///                           parameter)}
///     \cgalParamType{`int`}
///     \cgalParamDefault{4, what glTF's `JOINTS_0`/`WEIGHTS_0` hold}
///   \cgalParamNEnd
///   \cgalParamNBegin{falloff}
///     \cgalParamDescription{the exponent `p` above, in [0.5, 16] (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2: inverse square distance; larger gives sharper transitions at
///                       the joints}
///   \cgalParamNEnd
///   \cgalParamNBegin{influence_ratio}
///     \cgalParamDescription{`s` above, in [1.05, 100] (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2: a bone influences vertices up to twice as far from it as from
///                       the nearest bone, so the blend around a joint of a limb of radius
///                       r spans about 1.7 r on each side}
///     \cgalParamExtra{A larger ratio blends more widely and costs more:
///                     `Skinning_report::voxel_visits`.}
///   \cgalParamNEnd
///   \cgalParamNBegin{bone_segmentation_map}
///     \cgalParamDescription{receives the bone of largest weight of each vertex (the hard
///                           segmentation of the mesh by bone) (package parameter)}
///     \cgalParamType{a model of `WritablePropertyMap` with the mesh's vertex descriptor as
///                    key type and an integer type as value type}
///     \cgalParamDefault{none}
///   \cgalParamNEnd
///   \cgalParamNBegin{resolution, fill_holes, keep_surface_voxels, memory_limit, vertex_point_map}
///     \cgalParamDescription{as for `voxelize()`: the voxel grid of the distances}
///     \cgalParamType{as for `voxelize()`}
///     \cgalParamDefault{as for `voxelize()` (resolution `default_voxel_resolution`, 64)}
///     \cgalParamExtra{The memory need is checked first: about 13 bytes per voxel of the
///                     solid's box, 16 per solid voxel and 112 per vertex, besides
///                     `voxelize()`'s.}
///   \cgalParamNEnd
///   \cgalParamNBegin{vertex_index_map}
///     \cgalParamDescription{a vertex index map}
///     \cgalParamType{a model of `ReadablePropertyMap` with the mesh's vertex descriptor as
///                    key type and an integer type as value type}
///     \cgalParamDefault{the mesh's, initialised if needed}
///   \cgalParamNEnd
/// \cgalNamedParamsEnd
///
/// \returns what was done: the voxels, the work of the searches, the vertices bound in
///          straight line, the time.
/// \pre the skeleton has at least one bone, every point is finite; the mesh satisfies `voxelize()`'s preconditions.
/// \throws std::invalid_argument when a precondition does not hold or a parameter is out of
///         range (the message names it); what `voxelize()` throws.
/// \throws std::length_error when the fields would need more memory than `memory_limit`.
///
/// \b Complexity: `voxelize()`'s, plus O(V) for the nearest-bone search over the V solid
/// voxels (a bucket queue), plus O(V_b) per bone for the V_b voxels its bounded search visits
/// (in total a small multiple of V: `Skinning_report::voxel_visits`), plus O(N (B_v + 1))
/// for N vertices and B_v bones reaching a vertex; O(V_box + V + N) memory.
template <typename TriangleMesh, typename Point, typename WeightMap,
          typename NamedParameters = CGAL::parameters::Default_named_parameters>
Skinning_report compute_skinning_weights(const TriangleMesh& mesh, const Control_skeleton<Point>& skeleton,
                                         WeightMap weight_output,
                                         const NamedParameters& np = CGAL::parameters::default_values())
{
  using CGAL::parameters::choose_parameter;
  using CGAL::parameters::get_parameter;
  using CGAL::parameters::is_default_parameter;
  namespace ranges = parameter_ranges;
  const char* caller = "compute_skinning_weights";
  const auto start = std::chrono::steady_clock::now();

  const std::size_t k = internal::checked_parameter(
      ranges::max_bones_per_vertex,
      std::size_t(choose_parameter(get_parameter(np, internal_np::max_bones_per_vertex_tag),
                                   int(ranges::max_bones_per_vertex.default_value))),
      caller);
  const double p = internal::checked_parameter(
      ranges::falloff, double(choose_parameter(get_parameter(np, internal_np::falloff_tag), ranges::falloff.default_value)),
      caller);
  const double s = internal::checked_parameter(
      ranges::influence_ratio,
      double(choose_parameter(get_parameter(np, internal_np::influence_ratio_tag), ranges::influence_ratio.default_value)),
      caller);
  internal::check_bones(skeleton, caller);
  const double limit = internal::memory_limit(np, caller);

  Skinning_report report;
  Dense_voxel_grid grid;
  report.solid_voxels = voxelize(mesh, grid, np);
  const Voxel_frame frame = grid.frame();
  report.voxel_size = frame.voxel_size();

  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  const std::size_t n = num_vertices(mesh);
  {
    const internal::Grid_layout layout(grid.bounding_box().grown(1));
    internal::require_memory(13. * double(layout.volume()) + 16. * double(report.solid_voxels) + 112. * double(n),
                             limit, layout, caller, "the distance fields of a grid");
  }
  const internal::Solid_voxels solid(grid);
  grid = Dense_voxel_grid(); // the solid is indexed: free the grid

  using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
  std::vector<vertex_descriptor> vertex_of(n);
  std::vector<internal::Vec3> grid_points(n);
  for(vertex_descriptor v : vertices(mesh))
  {
    const std::size_t i = get(vim, v);
    const auto& q = get(vpm, v);
    vertex_of[i] = v;
    grid_points[i] =
        frame.to_grid(internal::Vec3{CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())});
  }
  const internal::Vertex_cells cells(solid, std::move(grid_points));

  // The bones in the grid, and the distance to the nearest one.
  const auto numbered = numbered_bones(skeleton);
  const std::size_t bones = numbered.size();
  std::vector<std::vector<internal::Vec3>> polylines(bones);
  std::vector<std::vector<std::uint32_t>> seeds(bones);
  std::vector<std::uint32_t> all_seeds;
  for(std::size_t b = 0; b < bones; ++b)
  {
    polylines[b] = internal::bone_polyline_in_grid(skeleton, numbered[b], frame);
    seeds[b] = internal::rasterize_polyline(solid, polylines[b]);
    all_seeds.insert(all_seeds.end(), seeds[b].begin(), seeds[b].end());
  }
  std::vector<internal::Voxel_distance> nearest(solid.size(), internal::unreached);
  std::vector<std::uint32_t> reached;
  internal::Bucket_queue queue;
  internal::voxel_dijkstra(solid, all_seeds, nearest, reached, queue,
                           [](std::uint32_t, internal::Voxel_distance) { return true; });
  // (s (d1 + 1/2))^-p at each vertex, the term that makes a bone's weight zero where it is s
  // times as far as the nearest bone (d1 in voxels, read in float precision; 0 where no bone
  // reaches the vertex). Computed once here, not once per bone that reaches the vertex.
  std::vector<double> zero_weight_term(n, 0.);
  // The solid voxels at a corner of a cell with vertices: the only ones read at vertices.
  std::vector<std::uint8_t> read_at_vertices(solid.size(), 0);
  for(std::size_t cell = 0; cell < solid.layout.volume(); ++cell)
    if(cells.has_vertices(cell))
    {
      cells.read_cell(solid, cell, nearest, [&](std::uint32_t v, double d) {
        zero_weight_term[v] = std::pow(s * (double(float(d)) + 0.5), -p);
      });
      for(std::ptrdiff_t offset : cells.corner_offsets)
        if(const std::int32_t u = solid.solid_of_cell[std::size_t(std::ptrdiff_t(cell) + offset)]; u >= 0)
          read_at_vertices[std::size_t(u)] = 1;
    }

  // One bounded search per bone; each vertex keeps its k largest weights.
  std::vector<Bone_weights> weights(n);
  std::vector<internal::Voxel_distance> distance(solid.size(), internal::unreached);
  // A bone's search stops at a voxel where d_b + 1/2 >= s (d1 + 1/2) + 1 (in voxels).
  std::vector<internal::Voxel_distance> stop(solid.size());
  for(std::size_t u = 0; u < solid.size(); ++u)
    stop[u] = nearest[u] == internal::unreached
                  ? 0
                  : internal::Voxel_distance(std::min(4e9, (s * (nearest[u] * internal::voxels_per_unit + 0.5) + 0.5) /
                                                               internal::voxels_per_unit));
  std::vector<std::uint32_t> stamp(solid.layout.volume(), 0), touched_cells;
  for(std::size_t b = 0; b < bones; ++b)
  {
    reached.clear();
    internal::voxel_dijkstra(solid, seeds[b], distance, reached, queue,
                             [&](std::uint32_t u, internal::Voxel_distance d) { return d < stop[u]; });
    report.voxel_visits += reached.size();
    touched_cells.clear();
    for(std::uint32_t u : reached)
      if(read_at_vertices[u])
        for(std::ptrdiff_t offset : cells.corner_offsets)
        {
          const std::size_t cell = std::size_t(std::ptrdiff_t(solid.cell_of_solid[u]) - offset);
          if(stamp[cell] != b + 1 && cells.has_vertices(cell))
          {
            stamp[cell] = std::uint32_t(b + 1);
            touched_cells.push_back(std::uint32_t(cell));
          }
        }
    for(std::uint32_t cell : touched_cells)
      cells.read_cell(solid, cell, distance, [&](std::uint32_t v, double d) {
        const double w = std::pow(d + 0.5, -p) - zero_weight_term[v];
        if(w > 0)
          internal::keep_largest(weights[v], k, std::uint32_t(b), float(w));
      });
    for(std::uint32_t u : reached)
      distance[u] = internal::unreached;
  }

  for(std::size_t v = 0; v < n; ++v)
  {
    if(weights[v].empty())
    {
      // No bone in the vertex's part of the solid: the bone nearest in straight line.
      double best = HUGE_VAL;
      std::uint32_t nearest_bone = 0;
      for(std::size_t b = 0; b < bones; ++b)
        if(const double d = internal::distance_to_polyline(cells.grid_point[v], polylines[b]); d < best)
        {
          best = d;
          nearest_bone = std::uint32_t(b);
        }
      weights[v].push_back(nearest_bone, 1.f);
      ++report.vertices_bound_in_straight_line;
    }
    internal::normalise(weights[v]);
    put(weight_output, vertex_of[v], weights[v]);
    if constexpr(!is_default_parameter<NamedParameters, internal_np::bone_segmentation_map_t>::value)
    {
      auto segmentation = get_parameter(np, internal_np::bone_segmentation_map_tag);
      using Label = typename boost::property_traits<decltype(segmentation)>::value_type;
      put(segmentation, vertex_of[v], static_cast<Label>(weights[v].bone[0]));
    }
  }
  report.milliseconds =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  return report;
}

} // namespace Geodesic_skeleton
} // namespace CGAL

#endif // CGAL_GEODESIC_SKELETON_COMPUTE_SKINNING_WEIGHTS_H
