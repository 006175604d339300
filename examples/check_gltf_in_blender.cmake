# cmake -DPROGRAM=<skeletonize> -DBLENDER=<blender> -DSCRIPT=<check_gltf_in_blender.py>
#       -DMESH=<mesh> -DWORK_DIR=<dir> -P check_gltf_in_blender.cmake
# skeletonize's skinned .glb, imported and posed by Blender (scripts/check_gltf_in_blender.py):
# one armature with the skeleton's bones, weights summing to 1, the rest pose the mesh, a
# turned bone moving what it carries and nothing else.
include(${CMAKE_CURRENT_LIST_DIR}/skeletonize_runs.cmake)

run(${MESH} -o ${WORK_DIR}/rig.json)
run(${MESH} -o ${WORK_DIR}/rig.glb)
file(READ ${WORK_DIR}/rig.json rig)
string(JSON bones LENGTH "${rig}" control bones)
execute_process(COMMAND ${BLENDER} -b --factory-startup --python ${SCRIPT} -- ${WORK_DIR}/rig.glb ${bones}
                RESULT_VARIABLE result OUTPUT_VARIABLE out ERROR_VARIABLE err)
string(REGEX MATCH "check_gltf_in_blender: [^\n]*" verdict "${out}")
message(STATUS "${verdict}")
if(NOT result EQUAL 0 OR NOT verdict MATCHES "^check_gltf_in_blender: OK")
  message(FATAL_ERROR "Blender (${result}): ${verdict}\n${err}")
endif()
