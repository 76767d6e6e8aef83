# cmake -P script: configure SOURCE_DIR afresh in WORK_DIR (the library alone, no tests or tools)
# and check the export set it generates: every library target a consumer links carries the
# installed include directory. A build tree configured twice hides a variable read before it is
# set (the second run finds it in the cache): install.consumer, run on such a tree, passed while
# a clean checkout exported edgeland::c without its include directory.
file(REMOVE_RECURSE ${WORK_DIR})
execute_process(COMMAND ${CMAKE_COMMAND} -S ${SOURCE_DIR} -B ${WORK_DIR}
    -DEDGELAND_BUILD_TESTS=OFF -DEDGELAND_BUILD_CLI=OFF -DEDGELAND_BUILD_PROOFS=OFF
    -DEDGELAND_BUILD_PLAY=OFF -DEDGELAND_BUILD_NET=OFF
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "fresh configure failed (${status}):\n${out}\n${err}")
endif()
file(GLOB_RECURSE exports ${WORK_DIR}/CMakeFiles/Export/*/edgelandTargets.cmake)
if(NOT exports)
  message(FATAL_ERROR "no edgelandTargets.cmake generated under ${WORK_DIR}/CMakeFiles/Export")
endif()
list(GET exports 0 export_file)
file(READ ${export_file} text)
# Each imported target's block: add_library(edgeland::NAME KIND IMPORTED) then its properties.
string(REGEX MATCHALL "add_library\\(edgeland::[a-z_0-9]+ [A-Z]+ IMPORTED\\)" declared "${text}")
if(NOT declared)
  message(FATAL_ERROR "no imported targets in ${export_file}")
endif()
set(missing "")
foreach(declaration IN LISTS declared)
  string(REGEX REPLACE "add_library\\((edgeland::[a-z_0-9]+) .*" "\\1" target "${declaration}")
  string(FIND "${text}" "set_target_properties(${target} PROPERTIES" at)
  set(block "")
  if(NOT at EQUAL -1)  # a target with no properties has no block at all
    string(SUBSTRING "${text}" ${at} 400 block)
    string(REGEX REPLACE "\n\\)\n.*" "" block "${block}")
  endif()
  if(NOT block MATCHES "INTERFACE_INCLUDE_DIRECTORIES \"[^\"]*\\\${_IMPORT_PREFIX}/include")
    list(APPEND missing ${target})
  endif()
endforeach()
if(missing)
  message(FATAL_ERROR "exported without the installed include directory: ${missing}")
endif()
list(LENGTH declared count)
message(STATUS "${count} exported targets, each with \${_IMPORT_PREFIX}/include")
