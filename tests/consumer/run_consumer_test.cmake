# cmake -P script: install EDGELAND_BUILD_DIR into WORK_DIR/prefix, then configure, build and
# run the consumer project against that prefix only. Any failing step fails the test.
function(step what)
  execute_process(COMMAND ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "${what} failed (${status}):\n${ARGN}\n${out}\n${err}")
  endif()
  message(STATUS "${what}: ok")
  set(step_output "${out}" PARENT_SCOPE)
endfunction()

set(prefix ${WORK_DIR}/prefix)
set(build ${WORK_DIR}/build)
file(REMOVE_RECURSE ${WORK_DIR})

step("cmake --install" ${CMAKE_COMMAND} --install ${EDGELAND_BUILD_DIR} --prefix ${prefix})
# The installed tree holds the public headers and the package files, and nothing private.
foreach(expected include/edgeland/kernel/validate.hpp include/edgeland/clip/clip.hpp
    include/edgeland/io/landscape_replay.hpp include/edgeland/edgeland.h bin/edgeland)
  if(NOT EXISTS ${prefix}/${expected})
    message(FATAL_ERROR "not installed: ${expected}")
  endif()
endforeach()
file(GLOB_RECURSE configs ${prefix}/*/edgelandConfig.cmake)
file(GLOB_RECURSE private_headers ${prefix}/include/*wkt_tokens.hpp ${prefix}/include/*log_text.hpp ${prefix}/include/*commands.hpp
  ${prefix}/include/*scratch.hpp ${prefix}/include/*assert.hpp ${prefix}/include/*point_text.hpp)
if(NOT configs OR private_headers)
  message(FATAL_ERROR "config files: '${configs}'; private headers installed: '${private_headers}'")
endif()
step("installed edgeland --version" ${prefix}/bin/edgeland --version)

step("configure consumer" ${CMAKE_COMMAND} -S ${CONSUMER_SOURCE_DIR} -B ${build}
  -DCMAKE_PREFIX_PATH=${prefix} -DCMAKE_FIND_USE_PACKAGE_REGISTRY=OFF
  -DCMAKE_CXX_COMPILER=${CXX_COMPILER} -DCMAKE_C_COMPILER=${C_COMPILER}
  -DCMAKE_BUILD_TYPE=${BUILD_TYPE} "-DCMAKE_CXX_FLAGS=${CXX_FLAGS}" "-DCMAKE_C_FLAGS=${CXX_FLAGS}"
  "-DCMAKE_EXE_LINKER_FLAGS=${CXX_FLAGS}")
string(FIND "${step_output}" "edgeland_DIR=${prefix}/" found_at)
if(found_at EQUAL -1)
  message(FATAL_ERROR "the consumer did not find edgeland in ${prefix}:\n${step_output}")
endif()
step("build consumer" ${CMAKE_COMMAND} --build ${build})
step("run consumer" ${build}/consumer)
if(NOT step_output MATCHES "consumer: ok")
  message(FATAL_ERROR "consumer printed: ${step_output}")
endif()
step("run C consumer" ${build}/consumer_c)
if(NOT step_output MATCHES "consumer_c: ok")
  message(FATAL_ERROR "consumer_c printed: ${step_output}")
endif()
