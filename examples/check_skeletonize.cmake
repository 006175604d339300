# cmake -DPROGRAM=<skeletonize> -DMESH=<mesh> -DWORK_DIR=<dir> -P check_skeletonize.cmake
# Runs skeletonize on MESH with every output format and checks the JSON contract's keys,
# the counts' consistency, and that the other files and the SVG preview are written.
include(${CMAKE_CURRENT_LIST_DIR}/skeletonize_runs.cmake)

run(${MESH} -o ${WORK_DIR}/out.json --svg ${WORK_DIR}/out.svg)
file(READ ${WORK_DIR}/out.json json)
foreach(path "input" "mesh;vertices" "mesh;faces" "mesh;closed" "mesh;components" "parameters;resolution"
             "timings_ms;total" "timings_ms;voxelize" "timings_ms;thin" "timings_ms;prune"
             "stages;thinned;points" "stages;thinned;end_points" "stages;thinned;junctions" "stages;thinned;cycles"
             "stages;pruned;points" "stages;pruned;end_points" "stages;pruned;junctions" "stages;pruned;cycles"
             "stages;routed;branches_along_level_of_detail" "stages;solid;voxels_joining_pieces"
             "stages;inside;curve_points_moved" "stages;inside;joints_moved"
             "computed" "timings_ms;read" "peak_memory_mib" "skeleton;points" "skeleton;radii" "skeleton;edges"
             "control;joints" "control;bones")
  string(JSON value ERROR_VARIABLE error GET "${json}" ${path})
  if(error)
    message(FATAL_ERROR "the JSON has no key '${path}': ${error}")
  endif()
endforeach()

# The Reeb graph (a comparison baseline) is computed only when asked for, and the JSON says
# what was computed.
string(JSON reeb ERROR_VARIABLE no_reeb GET "${json}" stages reeb)
if(NOT no_reeb OR json MATCHES "\"reeb_graph\"")
  message(FATAL_ERROR "the Reeb graph was computed without --reeb")
endif()
run(${MESH} --reeb -o ${WORK_DIR}/reeb.json)
file(READ ${WORK_DIR}/reeb.json reeb_json)
string(JSON reeb_nodes GET "${reeb_json}" stages reeb nodes)
string(JSON computed GET "${reeb_json}" computed)
if(reeb_nodes LESS 2 OR NOT computed MATCHES "reeb_graph")
  message(FATAL_ERROR "--reeb: ${reeb_nodes} Reeb graph nodes, computed: ${computed}")
endif()

string(JSON joints LENGTH "${json}" control joints)
string(JSON bones LENGTH "${json}" control bones)
string(JSON roots LENGTH "${json}" control roots)
math(EXPR tree_bones "${joints} - ${roots}")
if(NOT bones EQUAL tree_bones OR bones LESS 1)
  message(FATAL_ERROR "control skeleton: ${joints} joints, ${roots} roots but ${bones} bones")
endif()
string(JSON kind GET "${json}" control joints 0 kind)
string(JSON parent GET "${json}" control joints 0 parent)
if(NOT kind STREQUAL "root" OR NOT parent EQUAL -1)
  message(FATAL_ERROR "the first joint is not a root: kind ${kind}, parent ${parent}")
endif()
string(JSON points LENGTH "${json}" skeleton points)
string(JSON radii LENGTH "${json}" skeleton radii)
string(JSON pruned GET "${json}" stages pruned points)
if(NOT points EQUAL radii OR NOT points EQUAL pruned)
  message(FATAL_ERROR "skeleton: ${points} points, ${radii} radii, pruned stage says ${pruned}")
endif()

file(READ ${WORK_DIR}/out.svg svg LIMIT 200)
if(NOT svg MATCHES "^<svg")
  message(FATAL_ERROR "the preview is not an SVG file")
endif()

# Peeling the surface voxels opens the camel-like false loops; here it must run and give a
# control skeleton too.
run(${MESH} --peel-surface-voxels -o ${WORK_DIR}/peeled.json)
file(READ ${WORK_DIR}/peeled.json peeled)
string(JSON peeled_flag GET "${peeled}" parameters keep_surface_voxels)
string(JSON peeled_bones LENGTH "${peeled}" control bones)
if(peeled_flag OR peeled_bones LESS 1)
  message(FATAL_ERROR "--peel-surface-voxels: keep_surface_voxels ${peeled_flag}, ${peeled_bones} bones")
endif()

# Without -o the JSON goes to standard output.
run(${MESH} --resolution 32)
string(JSON value ERROR_VARIABLE error GET "${stdout}" control bones)
if(error)
  message(FATAL_ERROR "no JSON on standard output: ${error}")
endif()

# The split's smallest radius: by default the library's (positive: half a voxel of the
# default grid), reported; a given one is used and reported as given.
string(JSON default_smallest_radius GET "${stdout}" parameters smallest_radius)
if(NOT default_smallest_radius GREATER 0)
  message(FATAL_ERROR "the default smallest_radius is ${default_smallest_radius}, not positive")
endif()
run(${MESH} --resolution 32 --smallest-radius 0.25)
string(JSON given_smallest_radius GET "${stdout}" parameters smallest_radius)
if(NOT given_smallest_radius EQUAL 0.25)
  message(FATAL_ERROR "--smallest-radius 0.25: the JSON says ${given_smallest_radius}")
endif()

# The thinning's thin-part radius: by default the library's (sqrt(2) voxels up to the
# default resolution), reported; a given one is used and reported as given.
string(JSON default_thin_part_radius GET "${stdout}" parameters thin_part_radius)
if(NOT (default_thin_part_radius GREATER 1.414 AND default_thin_part_radius LESS 1.415))
  message(FATAL_ERROR "the default thin_part_radius at 32 is ${default_thin_part_radius}, not sqrt(2)")
endif()
run(${MESH} --resolution 32 --thin-part-radius 2.5)
string(JSON given_thin_part_radius GET "${stdout}" parameters thin_part_radius)
if(NOT given_thin_part_radius EQUAL 2.5)
  message(FATAL_ERROR "--thin-part-radius 2.5: the JSON says ${given_thin_part_radius}")
endif()

# The split's floor on bone lengths, in largest MAT radii of the piece: by default the
# library's 0.5, reported; 0 turns it off, which never gives fewer bones.
string(JSON default_piece_floor GET "${stdout}" parameters minimum_bone_length_of_piece_factor)
string(JSON floored_bones LENGTH "${stdout}" control bones)
if(NOT default_piece_floor EQUAL 0.5)
  message(FATAL_ERROR "the default minimum_bone_length_of_piece_factor is ${default_piece_floor}, not 0.5")
endif()
run(${MESH} --resolution 32 --thin-part-radius 2.5 --min-bone-length-of-piece 0)
string(JSON given_piece_floor GET "${stdout}" parameters minimum_bone_length_of_piece_factor)
string(JSON unfloored_bones LENGTH "${stdout}" control bones)
if(NOT given_piece_floor EQUAL 0 OR unfloored_bones LESS floored_bones)
  message(FATAL_ERROR "--min-bone-length-of-piece 0: the JSON says ${given_piece_floor}, "
                      "${unfloored_bones} bones against ${floored_bones} with the floor")
endif()

# The other formats: the OBJ and the polylines hold every bone, cut or not.
string(JSON cut_bones LENGTH "${json}" control cut_bones)
math(EXPR all_bones "${bones} + ${cut_bones}")
run(${MESH} -o ${WORK_DIR}/out.bvh)
file(READ ${WORK_DIR}/out.bvh bvh LIMIT 40)
if(NOT bvh MATCHES "^HIERARCHY\nROOT root_0")
  message(FATAL_ERROR "the BVH does not start with its root: ${bvh}")
endif()
run(${MESH} -o ${WORK_DIR}/out.obj)
file(STRINGS ${WORK_DIR}/out.obj lines REGEX "^l ")
list(LENGTH lines obj_bones)
if(NOT obj_bones EQUAL all_bones)
  message(FATAL_ERROR "the OBJ has ${obj_bones} bone lines, the JSON ${all_bones} bones")
endif()
run(${MESH} -o ${WORK_DIR}/out.polylines.txt)
file(STRINGS ${WORK_DIR}/out.polylines.txt polylines)
list(LENGTH polylines polyline_count)
if(NOT polyline_count EQUAL all_bones)
  message(FATAL_ERROR "${polyline_count} polylines for ${all_bones} bones")
endif()
message(STATUS "skeletonize: ${joints} joints, ${bones} bones, ${points} skeleton points")
