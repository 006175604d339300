# cmake -DPROGRAM=<skeletonize> -DMESH=<mesh> -DWORK_DIR=<dir> -P check_skinning.cmake
# skeletonize's skinning: the rig of a mesh written as JSON, read back with --skeleton, the
# weights added to the report with --weights (non-negative, summing to 1 per vertex), the
# skinned mesh written as .glb and .gltf, and the picture of the segmentation by bone.
include(${CMAKE_CURRENT_LIST_DIR}/skeletonize_runs.cmake)

# The rig of the mesh (a whole report), then the mesh skinned to it, with the weights.
run(${MESH} -o ${WORK_DIR}/rig.json)
run(${MESH} --skeleton ${WORK_DIR}/rig.json --weights --max-bones 3 -o ${WORK_DIR}/skinned.json)
file(READ ${WORK_DIR}/rig.json rig)
file(READ ${WORK_DIR}/skinned.json json)
string(JSON rig_bones LENGTH "${rig}" control bones)
string(JSON bones LENGTH "${json}" control bones)
string(JSON vertices GET "${json}" weights vertices)
if(NOT bones EQUAL rig_bones)
  message(FATAL_ERROR "--skeleton: ${bones} bones, the rig has ${rig_bones}")
endif()
string(JSON entries LENGTH "${json}" weights vertex)
string(JSON bone_entries LENGTH "${json}" weights bone)
string(JSON weight_entries LENGTH "${json}" weights weight)
math(EXPR most "3 * ${vertices}")
if(NOT entries EQUAL bone_entries OR NOT entries EQUAL weight_entries OR entries LESS vertices OR entries GREATER most)
  message(FATAL_ERROR "weights: ${entries} vertices, ${bone_entries} bones, ${weight_entries} weights for "
                      "${vertices} mesh vertices and at most 3 bones each")
endif()
# The first entries: vertices in order, each with at least one bone, bones that exist,
# weights in [0, 1] (their sums are checked by the unit tests: CMake has no floating point).
set(vertex 0)
foreach(i RANGE 0 300)
  string(JSON v GET "${json}" weights vertex ${i})
  string(JSON w GET "${json}" weights weight ${i})
  string(JSON b GET "${json}" weights bone ${i})
  if(b GREATER_EQUAL bones OR NOT w MATCHES "^(0(\\.[0-9]+)?([eE]-[0-9]+)?|1(\\.0*)?|[1-9](\\.[0-9]+)?[eE]-[0-9]+)$")
    message(FATAL_ERROR "weights: entry ${i} has bone ${b} and weight ${w}")
  endif()
  if(NOT v EQUAL vertex)
    math(EXPR vertex "${vertex} + 1")
    if(NOT v EQUAL vertex)
      message(FATAL_ERROR "weights: entry ${i} is for vertex ${v}, after vertex ${vertex} - 1")
    endif()
  endif()
endforeach()

# The skinned mesh as glTF: binary (the "glTF" magic) and text (with a skin), and the
# picture of the bone segmentation.
run(${MESH} --skeleton ${WORK_DIR}/skinned.json -o ${WORK_DIR}/skinned.glb)
file(READ ${WORK_DIR}/skinned.glb magic LIMIT 4 HEX)
if(NOT magic STREQUAL "676c5446") # "glTF"
  message(FATAL_ERROR "skinned.glb does not start with the glTF magic: '${magic}'")
endif()
run(${MESH} -o ${WORK_DIR}/skinned.gltf --svg ${WORK_DIR}/weights.svg --svg-stage weights)
file(READ ${WORK_DIR}/skinned.gltf gltf)
foreach(key "skins;0;inverseBindMatrices" "meshes;0;primitives;0;attributes;JOINTS_0"
            "meshes;0;primitives;0;attributes;WEIGHTS_0" "accessors;0;min")
  string(JSON value ERROR_VARIABLE error GET "${gltf}" ${key})
  if(error)
    message(FATAL_ERROR "skinned.gltf has no '${key}': ${error}")
  endif()
endforeach()
file(READ ${WORK_DIR}/weights.svg svg LIMIT 300)
if(NOT svg MATCHES "^<svg.*bone of largest weight")
  message(FATAL_ERROR "the weights picture is not an SVG of the segmentation")
endif()
# The weights are numbered by the file's vertices even when the repair renumbers the mesh's:
# a cube with a face turned the wrong way, whose vertex 8 repeats vertex 1 (a seam) and
# whose vertex 9 is in no face.
file(WRITE ${WORK_DIR}/seam.obj "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
     "v 1 0 0\nv 5 5 5\nf 1 2 3\nf 1 4 3\nf 5 6 7\nf 5 7 8\nf 1 9 6\nf 1 6 5\nf 2 3 7\nf 2 7 6\n"
     "f 3 4 8\nf 3 8 7\nf 4 1 5\nf 4 5 8\n")
file(WRITE ${WORK_DIR}/seam_rig.json
     "{\"joints\": [{\"position\": [0.5, 0.5, 0.1], \"parent\": -1}, {\"position\": [0.5, 0.5, 0.9], \"parent\": 0}]}")
run(${WORK_DIR}/seam.obj --skeleton ${WORK_DIR}/seam_rig.json --weights -o ${WORK_DIR}/seam.json)
file(READ ${WORK_DIR}/seam.json json)
string(JSON mesh_vertices GET "${json}" mesh vertices)
string(JSON vertices GET "${json}" weights vertices)
string(JSON entries LENGTH "${json}" weights vertex)
math(EXPR last "${entries} - 1")
string(JSON last_vertex GET "${json}" weights vertex ${last})
if(NOT vertices EQUAL 10 OR NOT last_vertex EQUAL 9 OR mesh_vertices EQUAL 10)
  message(FATAL_ERROR "seam.obj: weights for ${vertices} vertices (the last ${last_vertex}), "
                      "the file has 10, the repaired mesh ${mesh_vertices}")
endif()

file(GLOB partial ${WORK_DIR}/*.partial)
if(partial)
  message(FATAL_ERROR "temporary files left: ${partial}")
endif()
