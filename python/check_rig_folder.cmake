# The test of examples/rig_folder.py: three small demo meshes and one that cannot be rigged
# (a single triangle encloses no volume), two threads. Every good mesh must give a .glb
# (glTF's binary magic), the bad one a message naming it, and the exit code must be 1.
# -DPYTHON= -DMODULE_DIR= -DSCRIPT= -DDATA_DIR= -DWORK_DIR=
file(REMOVE_RECURSE ${WORK_DIR})
file(MAKE_DIRECTORY ${WORK_DIR}/in)
set(meshes cactus eight hand)
foreach(mesh IN LISTS meshes)
  file(COPY ${DATA_DIR}/${mesh}.off DESTINATION ${WORK_DIR}/in)
endforeach()
file(COPY ${CMAKE_CURRENT_LIST_DIR}/../test/data/bad_meshes/single_triangle.off DESTINATION ${WORK_DIR}/in)
execute_process(
  COMMAND ${CMAKE_COMMAND} -E env PYTHONPATH=${MODULE_DIR}
          ${PYTHON} ${SCRIPT} ${WORK_DIR}/in ${WORK_DIR}/out --threads 2 resolution=48
  RESULT_VARIABLE result OUTPUT_VARIABLE output ERROR_VARIABLE errors)
message(STATUS "${output}${errors}")
if(NOT result EQUAL 1)
  message(FATAL_ERROR "rig_folder.py: expected exit code 1 (one mesh fails), got ${result}")
endif()
if(NOT output MATCHES "single_triangle.off: failed: .*encloses no volume")
  message(FATAL_ERROR "rig_folder.py: the failure of single_triangle.off is not reported")
endif()
if(NOT output MATCHES "3 of 4 meshes rigged")
  message(FATAL_ERROR "rig_folder.py: the summary line is missing")
endif()
foreach(mesh IN LISTS meshes)
  if(NOT EXISTS ${WORK_DIR}/out/${mesh}.glb)
    message(FATAL_ERROR "rig_folder.py wrote no ${mesh}.glb")
  endif()
  file(READ ${WORK_DIR}/out/${mesh}.glb magic LIMIT 4 HEX)
  if(NOT magic STREQUAL "676c5446") # "glTF"
    message(FATAL_ERROR "${mesh}.glb is not a binary glTF file")
  endif()
endforeach()
