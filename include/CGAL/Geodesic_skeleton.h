// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later

#ifndef CGAL_GEODESIC_SKELETON_H
#define CGAL_GEODESIC_SKELETON_H

/// \file Geodesic_skeleton.h
/// The umbrella header of the package: includes every public header that needs no more than
/// CGAL, Boost and Eigen, in the order of the data flow (the manual's overview). The headers that need a
/// file-format library are included on their own: `IO/json.h` and
/// `IO/read_control_skeleton_json.h` (nlohmann_json), `IO/gltf.h` (tinygltf),
/// `IO/read_mesh_with_assimp.h` (Assimp). Include a single stage's header instead to
/// compile less.

#include <CGAL/Geodesic_skeleton/parameter_ranges.h>
#include <CGAL/Geodesic_skeleton/parameters.h>

// Geodesic distances and the Reeb graph.
#include <CGAL/Geodesic_skeleton/geodesic_distances.h>
#include <CGAL/Geodesic_skeleton/geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/integral_geodesic_mapping_function.h>
#include <CGAL/Geodesic_skeleton/reeb_graph.h>

// The voxel medial axis.
#include <CGAL/Geodesic_skeleton/Voxel_key.h>
#include <CGAL/Geodesic_skeleton/Voxel_frame.h>
#include <CGAL/Geodesic_skeleton/Dense_voxel_grid.h>
#include <CGAL/Geodesic_skeleton/Sparse_voxel_set.h>
#include <CGAL/Geodesic_skeleton/Voxelized_surface.h>
#include <CGAL/Geodesic_skeleton/Voxel_skeleton.h>
#include <CGAL/Geodesic_skeleton/No_enclosed_volume.h>
#include <CGAL/Geodesic_skeleton/voxelize.h>
#include <CGAL/Geodesic_skeleton/remove_small_pieces.h>
#include <CGAL/Geodesic_skeleton/Voxel_distance_field.h>
#include <CGAL/Geodesic_skeleton/distance_transform.h>
#include <CGAL/Geodesic_skeleton/thin.h>
#include <CGAL/Geodesic_skeleton/reach_sheet_lobes.h>
#include <CGAL/Geodesic_skeleton/cut_spurious_cycles.h>

// Pruning (Algorithm 1) and the curve skeleton.
#include <CGAL/Geodesic_skeleton/classify_skeleton_points.h>
#include <CGAL/Geodesic_skeleton/prune_skeleton.h>
#include <CGAL/Geodesic_skeleton/route_skeleton_on_finer_grid.h>
#include <CGAL/Geodesic_skeleton/Curve_skeleton.h>
#include <CGAL/Geodesic_skeleton/to_graph.h>
#include <CGAL/Geodesic_skeleton/skeleton_statistics.h>

// Smoothing and bones.
#include <CGAL/Geodesic_skeleton/smooth_skeleton.h>
#include <CGAL/Geodesic_skeleton/move_skeleton_inside.h>
#include <CGAL/Geodesic_skeleton/chord_to_point_distance_accumulation.h>
#include <CGAL/Geodesic_skeleton/Control_skeleton.h>
#include <CGAL/Geodesic_skeleton/split_into_bones.h>

// The whole chain.
#include <CGAL/Geodesic_skeleton/extract_control_skeleton.h>
// Skinning weights.
#include <CGAL/Geodesic_skeleton/Bone_weights.h>
#include <CGAL/Geodesic_skeleton/compute_skinning_weights.h>

// Writers.
#include <CGAL/Geodesic_skeleton/IO/bvh.h>
#include <CGAL/Geodesic_skeleton/IO/obj.h>
#include <CGAL/Geodesic_skeleton/IO/polylines.h>
#include <CGAL/Geodesic_skeleton/IO/read_mesh.h>

#endif // CGAL_GEODESIC_SKELETON_H
