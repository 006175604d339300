// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_COMPUTE_SKINNING_WEIGHTS_H
#define CGAL_GEODESIC_SKELETON_COMPUTE_SKINNING_WEIGHTS_H

/// \file compute_skinning_weights.h
/// Skinning weights of a mesh for a control skeleton: bone heat, with the solid of the mesh
/// deciding which bone sees a vertex.

#include <CGAL/Geodesic_skeleton/Bone_weights.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/internal/grid_layout.h>
#include <CGAL/Geodesic_skeleton/internal/parallel_parts.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/bones_in_grid.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/cluster_normals.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/finish_weights.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/heat_sources.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/inscribed_balls.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/skinning_fields.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/surface_clusters.h>
#include <CGAL/Geodesic_skeleton/internal/skinning/surface_heat.h>
#include <CGAL/Geodesic_skeleton/internal/voxelize/solid_voxels.h>
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
#include <future>
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
  /// Whether the heat diffused over the surface; false if its solve failed (it should not:
  /// the system is positive definite), when each vertex follows the bone that heats it.
  bool heat_diffused = true;
  double milliseconds = 0;        ///< wall-clock time of the call
};

/// \ingroup PkgGeodesicSkeletonRef
/// Computes, for every vertex of `mesh`, the skinning weights of at most
/// `max_bones_per_vertex` bones of `skeleton`: non-negative, summing to 1, for linear
/// blend skinning (as glTF 2.0 and every animation tool use them).
///
/// The method is bone heat (Baran and Popovic, <i>Automatic Rigging and Animation of 3D
/// Characters</i>, SIGGRAPH 2007) with the solid deciding what a bone sees. Distances from the
/// bones run through the voxels of the mesh's solid (`voxelize()`, as in Dionne and de Lasa's
/// geodesic voxel binding); a bone sees a vertex when that distance is about the straight one.
/// Each vertex is heated by the bone nearest to the centre of its <i>inscribed ball</i> (the
/// largest ball inside the solid that touches the surface at the vertex, found along the
/// inward normal) among those that see it: the bone of the part of the body the vertex
/// bounds, not the one that passes nearest to it (an arm's bone running through the lower
/// part of a big head; bones within 10^-4 of the least distance share the heat equally; the
/// bone nearest through the solid when none sees the vertex, the bone nearest in straight
/// line in a detached piece that no bone's search reaches). The heat is set by the
/// <i>facing distance</i> to that bone: the straight distance divided by
/// `(1 + cos a + 0.001) / 2`, with `a` the angle between the vertex's outward normal and the
/// direction from the bone to the vertex (as Blender's bone heat has it; the normals point
/// out of each connected piece whatever the winding). The heat is `A / d^2` (`A` the vertex's
/// area, `d` the facing distance), and it diffuses over the surface: the weights of bone
/// `b` solve `(L + diag(A / d^2)) w_b = diag(A / d^2) [heated by b]`, with `L` the cotangent
/// Laplacian (obtuse angles' negative cotangents clamped to 0, so that the weights stay in
/// [0, 1]). The system is positive definite on any mesh (open, in pieces, with degenerate
/// triangles), so the solve does not fail where bone heat does, and all lengths are in
/// voxels, so the weights do not depend on the mesh's scale. All of this is done at the
/// scale of the voxels, where the heat varies: the vertices are clustered by cells half a
/// voxel across (a cell's vertices joined by the mesh's edges inside it, so that two limbs
/// through one cell stay apart), each cluster standing at its vertices' centroid with their
/// area and mean normal; the heat is solved on the clustered surface (a vertex per cluster,
/// a triangle per mesh triangle whose corners fall in three clusters), and each vertex reads
/// its cluster's weights with their gradient there (a least-squares fit over the
/// neighbouring clusters). A mesh no finer than the cells is its own clustering; a finer one
/// costs the solve no more than the grid does. Each joint's weight (the sum
/// over the bones leaving it) is raised to the power `sharpness` (artists blend over a
/// narrower band than the heat does), the `max_bones_per_vertex` largest weights are kept,
/// those under `minimum_weight` of a vertex's total dropped, and the rest scaled to sum 1.
/// The manual, section \ref manual_skinning_method, explains the method and its constants; the
/// calibration on artists' weights is in benchmark/EXPERIMENTS.md.
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
///   \cgalParamNBegin{sharpness}
///     \cgalParamDescription{the exponent the diffused weights are raised to, in [1, 16]
///                           (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{2.5: the sharpest blend with which a limb bent by 60 degrees
///                       stretches no edge of its surface past twice its length (artists'
///                       weights are matched best at 4, section \ref manual_skinning_method);
///                       1 is bone heat's blend}
///   \cgalParamNEnd
///   \cgalParamNBegin{minimum_weight}
///     \cgalParamDescription{weights under this share of a vertex's total are dropped, in
///                           [0, 0.5] (package parameter)}
///     \cgalParamType{`double`}
///     \cgalParamDefault{0.05}
///   \cgalParamNEnd
///   \cgalParamNBegin{influence_ratio}
///     \cgalParamDescription{a bone's search through the solid stops where it is this many
///                           times as far as the nearest bone, in [1.05, 100] (package
///                           parameter): only bones that near may heat a vertex}
///     \cgalParamType{`double`}
///     \cgalParamDefault{1.25: the bone that heats a vertex is rarely farther than that
///                       through the solid (on artists' weights, section
///                       \ref manual_skinning_method, 1.5 and 2 give about the same and cost
///                       10 and 20 % more)}
///     \cgalParamExtra{A larger ratio costs more: `Skinning_report::voxel_visits`.}
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
///     \cgalParamExtra{The memory need is checked first: about 21 bytes per voxel of the
///                     solid's box, 16 per solid voxel and about 250 per vertex (its position, weights and cluster), besides
///                     `voxelize()`'s.}
///   \cgalParamNEnd
///   \cgalParamNBegin{voxelized_solid}
///     \cgalParamDescription{the solid that `voxelize()` gives this mesh with the parameters
///                           above, such as `extract_control_skeleton()` writes through the
///                           same name: it is used instead of voxelizing the mesh again
///                           (package parameter)}
///     \cgalParamType{a pointer to a `const Dense_voxel_grid`}
///     \cgalParamDefault{none: the mesh is voxelized}
///     \cgalParamExtra{A grid whose frame is not the one `voxelize()` gives this mesh at
///                     `resolution` (another mesh's, another resolution's) is refused
///                     (`std::invalid_argument`); the frame costs O(F). A grid of the right
///                     frame but other `fill_holes` or `keep_surface_voxels` settings is
///                     used as it is.}
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
///          straight line, whether the heat diffused, the time.
/// \pre the skeleton has at least one bone, every point is finite; the mesh satisfies `voxelize()`'s preconditions.
/// \throws std::invalid_argument when a precondition does not hold or a parameter is out of
///         range (the message names it); what `voxelize()` throws.
/// \throws std::length_error when the fields would need more memory than `memory_limit`.
///
/// \b Complexity: `voxelize()`'s (O(N) for the check of the frame instead, with a
/// `voxelized_solid`), plus O(N + F) for the clustering of the N vertices and F faces into
/// C clusters (C is at most N, and about 8 per surface voxel on a mesh finer than the grid),
/// plus O(V) for the nearest-bone search over the V solid voxels (a bucket queue), plus
/// O(V_b) per bone for the V_b voxels its bounded search visits (in total a small multiple
/// of V: `Skinning_report::voxel_visits`), plus O(C B_c P) for B_c bones reaching a
/// cluster and P points per bone polyline, plus O(V_box) for the solid's
/// `distance_transform()` over the V_box voxels of its box and O(C R) for the inscribed
/// balls (R the solid's largest MAT radius in voxels), plus the sparse Cholesky
/// factorisation of the C x C system (about O(C^1.5)) and one solve per bone, plus O(N) to
/// read the weights at the vertices; O(V_box + V + N + F) memory.
///
/// \tparam ConcurrencyTag `CGAL::Sequential_tag` (the default) or `CGAL::Parallel_tag`: the
///         second runs the passes over the vertices, the faces and the clusters, the bones'
///         searches and solves, and the ordering of the heat system (beside the searches) on
///         as many of the standard library's threads as the hardware has (link
///         `Threads::Threads`). The weights are the same, bit for bit, either way.
template <typename ConcurrencyTag = CGAL::Sequential_tag, typename TriangleMesh, typename Point, typename WeightMap,
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
  const unsigned threads = internal::thread_count<ConcurrencyTag>();

  const std::size_t k = internal::checked_parameter(
      ranges::max_bones_per_vertex,
      std::size_t(choose_parameter(get_parameter(np, internal_np::max_bones_per_vertex_tag),
                                   int(ranges::max_bones_per_vertex.default_value))),
      caller);
  const double sharpness = internal::checked_parameter(
      ranges::sharpness,
      double(choose_parameter(get_parameter(np, internal_np::sharpness_tag), ranges::sharpness.default_value)),
      caller);
  const double minimum_weight = internal::checked_parameter(
      ranges::minimum_weight,
      double(choose_parameter(get_parameter(np, internal_np::minimum_weight_tag), ranges::minimum_weight.default_value)),
      caller);
  const double s = internal::checked_parameter(
      ranges::influence_ratio,
      double(choose_parameter(get_parameter(np, internal_np::influence_ratio_tag), ranges::influence_ratio.default_value)),
      caller);
  internal::check_bones(skeleton, caller);
  const double limit = internal::memory_limit(np, caller);

  Skinning_report report;
  const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                    get_const_property_map(CGAL::vertex_point, mesh));
  Dense_voxel_grid own_grid;
  const Dense_voxel_grid* given_grid =
      choose_parameter(get_parameter(np, internal_np::voxelized_solid_tag), static_cast<const Dense_voxel_grid*>(nullptr));
  // The weights need no rasterised surface: a `voxelized_surface` in the pack (the other
  // stages') is neither written nor read.
  const auto voxelize_np =
      parameters::combine(parameters::voxelized_surface(static_cast<Voxelized_surface*>(nullptr)), np);
  if(given_grid == nullptr)
    voxelize(mesh, own_grid, voxelize_np);
  const Dense_voxel_grid& grid = given_grid != nullptr ? *given_grid : own_grid;
  report.solid_voxels = grid.size();
  const Voxel_frame frame = grid.frame();
  report.voxel_size = frame.voxel_size();

  const auto vim = CGAL::get_initialized_vertex_index_map(mesh, np);
  const std::size_t n = num_vertices(mesh);
  {
    const internal::Grid_layout layout(grid.bounding_box().grown(1));
    internal::require_memory(21. * double(layout.volume()) + 16. * double(report.solid_voxels) + 250. * double(n),
                             limit, layout, caller, "the distance fields of a grid");
  }
  const internal::Solid_voxels solid(grid);
  Voxel_distance_field depth = distance_transform(grid, np); // freed once the centres are found
  own_grid = Dense_voxel_grid(); // the solid is indexed: free the grid

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
  const auto triangles = internal::triangles_of(mesh, vim);
  if(given_grid != nullptr)
    internal::check_grid_frame(grid_points, triangles, internal::voxelize_settings(voxelize_np, caller).resolution,
                               given_grid->empty(), caller);

  // The surface at the scale of the voxels: what follows is done per cluster of vertices
  // (internal/skinning/surface_clusters.h), each vertex reading its cluster's weights at
  // the end. A cluster stands at its vertices' centroid, with their area and the mean of
  // their outward normals.
  const internal::Surface_clusters clusters = internal::cluster_surface(grid_points, triangles, threads);
  const std::size_t m = clusters.number_of_clusters();
  // The heat system's pattern is the clustered surface's: it is ordered and analysed beside
  // what follows, until the heat sources are known.
  internal::Heat_system heat_system;
  std::future<void> heat_system_analysed =
      internal::start_beside(threads, [&] { internal::analyse_heat_system(clusters, heat_system); });
  std::vector<internal::Vec3> normals;
  std::vector<double> areas;
  internal::outward_cluster_normals(grid_points, triangles, clusters, normals, areas, threads);
  const internal::Point_cells cells(solid, clusters.centroid);

  // Each cluster's centre: where it sits in the shape, which decides the bone that heats it.
  std::vector<internal::Vec3> centres(m);
  internal::for_each_index(m, threads, [&](std::size_t c) {
    centres[c] = internal::inscribed_ball_centre(cells.grid_point[c], normals[c], depth);
  });
  depth = Voxel_distance_field();

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

  // One bounded search per bone; each cluster finds the bone that heats it.
  // A bone's search stops at a voxel where d_b + 1/2 >= s (d1 + 1/2) + 1 (in voxels).
  std::vector<internal::Voxel_distance> stop(solid.size());
  for(std::size_t u = 0; u < solid.size(); ++u)
    stop[u] = nearest[u] == internal::unreached
                  ? 0
                  : internal::Voxel_distance(std::min(4e9, (s * (nearest[u] * internal::voxels_per_unit + 0.5) + 0.5) /
                                                               internal::voxels_per_unit));
  // The searches run side by side, the bones shared among the threads, each thread with its
  // own scratch arrays; each keeps the clusters its bone reaches with their distances to it.
  // Then the clusters are offered their bones bone after bone, as one thread would.
  struct Reached_cluster
  {
    std::uint32_t cluster;
    double through_solid, straight, facing;
  };
  std::vector<std::vector<Reached_cluster>> reached_clusters(bones);
  std::vector<std::size_t> visits(bones, 0);
  internal::for_each_part(bones, std::min<std::size_t>(threads, bones), threads, [&](std::size_t, std::size_t begin, std::size_t end) {
    std::vector<internal::Voxel_distance> distance(solid.size(), internal::unreached);
    std::vector<std::uint32_t> visited;
    internal::Bucket_queue search_queue;
    // The slots (cells with clusters) a search reached, each once per bone.
    std::vector<std::uint32_t> stamp(cells.number_of_slots(), 0), touched_slots;
    for(std::size_t b = begin; b < end; ++b)
    {
      visited.clear();
      internal::voxel_dijkstra(solid, seeds[b], distance, visited, search_queue,
                               [&](std::uint32_t u, internal::Voxel_distance d) { return d < stop[u]; });
      visits[b] = visited.size();
      touched_slots.clear();
      for(std::uint32_t u : visited)
        for(std::uint32_t k = cells.first_slot[u]; k < cells.first_slot[u + 1]; ++k)
          if(const std::uint32_t slot = cells.slots[k]; stamp[slot] != b + 1)
          {
            stamp[slot] = std::uint32_t(b + 1);
            touched_slots.push_back(slot);
          }
      for(std::uint32_t slot : touched_slots)
        cells.read_slot(solid, slot, distance, [&](std::uint32_t c, double d) {
          const internal::Vec3 offset = internal::offset_from_polyline(cells.grid_point[c], polylines[b]);
          const double straight = internal::norm3(offset);
          const double cosine = straight > 0 ? internal::dot3(offset, normals[c]) / straight : 1.;
          reached_clusters[b].push_back(
              {c, d, straight, internal::Heat_source_finder::facing_distance(straight, cosine)});
        });
      for(std::uint32_t u : visited)
        distance[u] = internal::unreached;
    }
  });
  internal::Heat_source_finder finder(m);
  for(std::size_t b = 0; b < bones; ++b)
  {
    report.voxel_visits += visits[b];
    for(const Reached_cluster& r : reached_clusters[b])
      finder.add(r.cluster, std::uint32_t(b), r.through_solid,
                 [&r] { return std::array<double, 2>{r.straight, r.facing}; });
  }
  reached_clusters.clear();
  internal::Heat_sources sources = finder.sources(
      [&](std::size_t c, std::uint32_t b) { return internal::distance_to_polyline(centres[c], polylines[b]); },
      threads);
  for(std::size_t c = 0; c < m; ++c)
    if(sources.bone[c] == internal::Heat_source_finder::none)
      report.vertices_bound_in_straight_line += clusters.size[c];
  internal::for_each_index(m, threads, [&](std::size_t c) {
    if(sources.bone[c] != internal::Heat_source_finder::none)
      return;
    // No bone in the cluster's part of the solid: the bone nearest in straight line.
    sources.distance[c] = HUGE_VAL;
    for(std::size_t b = 0; b < bones; ++b)
      if(const double d = internal::distance_to_polyline(cells.grid_point[c], polylines[b]); d < sources.distance[c])
      {
        sources.distance[c] = d;
        sources.bone[c] = std::uint32_t(b);
      }
  });

  std::vector<std::uint32_t> joint_of_bone(bones);
  for(std::size_t b = 0; b < bones; ++b)
    joint_of_bone[b] = std::uint32_t(source(numbered[b], skeleton));
  const std::vector<std::uint32_t> joint_depth = internal::joint_depths(skeleton, numbered);
  // The diffusion keeps all the bones a vertex holds, so that a joint's share counts all its
  // bones before the sharpening; then the k largest are kept.
  std::vector<Bone_weights> weights(n);
  heat_system_analysed.get();
  auto finish = [&](std::size_t v) {
    internal::finish_weights(weights[v], sharpness, joint_of_bone, joint_depth, k, minimum_weight);
    if(weights[v].empty()) // the diffusion failed (it should not): the heating bone alone
      weights[v].push_back(sources.bone[clusters.cluster_of[v]], 1.f);
  };
  report.heat_diffused = internal::diffuse_bone_heat(grid_points, clusters, areas, sources, bones,
                                                     Bone_weights::capacity, heat_system, weights, threads, finish);
  if(!report.heat_diffused)
    internal::for_each_index(n, threads, finish);
  for(std::size_t v = 0; v < n; ++v) // the output map, on the caller's thread: any map will do
  {
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
