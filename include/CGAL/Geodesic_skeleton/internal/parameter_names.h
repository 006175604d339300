// Copyright (c) 2026 The Geodesic_skeleton authors.
// SPDX-License-Identifier: LGPL-3.0-or-later
//
// The one list of the package's own named-parameter names (no include guard on purpose:
// it is included with different definitions of CGAL_GEODESIC_SKELETON_NAMED_PARAMETER).
// CGAL's names (vertex_point_map, vertex_index_map, geom_traits, ...)
// are not repeated here. Each name is documented where the function that reads it is.

// geodesic_distances
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(vertex_predecessor_map)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(edge_weight_map)

// geodesic_mapping_function, integral_geodesic_mapping_function
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(source_vertices)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(number_of_base_vertices)

// voxel medial axis: voxelize, distance_transform, thin, to_graph
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(resolution)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(memory_limit)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(fill_holes)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(keep_surface_voxels)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(small_piece_fraction)

// thin, reach_sheet_lobes
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(thin_part_radius)

// the mesh in the grid: voxelize writes it, to_graph, cut_spurious_cycles and
// move_skeleton_inside read it
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(voxelized_surface)

// the MAT radius of each element of the skeleton a function takes, in that skeleton's own
// length unit: voxels for prune_skeleton()'s voxel set, world units for the curve skeleton
// that to_graph() writes and smooth_skeleton() and split_into_bones() read
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(mat_radius_map)

// prune_skeleton (spur_length_factor, limb_protrusion_factor), reach_sheet_lobes
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(spur_length_factor)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(limb_protrusion_factor)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(sheet_lobe_reach_factor)

// smooth_skeleton
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(smoothing_window)

// chord_to_point_distance_accumulation
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(number_of_chords)

// split_into_bones
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(bend_threshold)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(straightness_tolerance)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(minimum_bone_length_factor)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(maximum_bone_length_factor)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(minimum_bone_length_of_piece_factor)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(smallest_radius)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(chord_length_factors)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(tip_joint_setback)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(joint_spacing)

// extract_control_skeleton (joint_spacing_factor: split_into_bones()'s joint_spacing in
// the mesh's longest principal extents)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(joint_spacing_factor)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(curve_skeleton_output)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(thinned_skeleton_output)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(reeb_graph_output)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(number_of_reeb_intervals)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(level_of_detail_resolution)

// the chain's solid: extract_control_skeleton writes it, compute_skinning_weights reads it
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(voxelized_solid)

// compute_skinning_weights
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(max_bones_per_vertex)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(sharpness)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(minimum_weight)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(influence_ratio)
CGAL_GEODESIC_SKELETON_NAMED_PARAMETER(bone_segmentation_map)
