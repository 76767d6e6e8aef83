# Registers the install/consumer test (included from tests/CMakeLists.txt): install the current
# build into a fresh prefix inside the build tree, then configure, build and run this folder's
# consumer project against it with find_package(edgeland CONFIG REQUIRED).
set(consumer_flags "")
if(EDGELAND_SANITIZE)
  # The installed static libraries carry ASan/UBSan references; the consumer must link the runtimes.
  set(consumer_flags "-fsanitize=address,undefined -fno-sanitize=vptr")
endif()
add_test(NAME install.consumer
  COMMAND ${CMAKE_COMMAND}
    -DEDGELAND_BUILD_DIR=${PROJECT_BINARY_DIR}
    -DCONSUMER_SOURCE_DIR=${CMAKE_CURRENT_LIST_DIR}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/consumer
    -DCXX_COMPILER=${CMAKE_CXX_COMPILER}
    -DC_COMPILER=${CMAKE_C_COMPILER}
    -DBUILD_TYPE=${CMAKE_BUILD_TYPE}
    "-DCXX_FLAGS=${consumer_flags}"
    -P ${CMAKE_CURRENT_LIST_DIR}/run_consumer_test.cmake)
# RUN_SERIAL: `cmake --install` copies the build tree's libraries and programs; alone, it never
# reads a file another test (or a build step a test starts) is writing.
set_tests_properties(install.consumer PROPERTIES LABELS install TIMEOUT 600 RUN_SERIAL TRUE)
# The export set of a first configure (install.consumer installs from this tree, which may have
# been configured more than once): fresh_configure_test.cmake.
add_test(NAME install.fresh_configure_exports_include_dirs
  COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR}
    -DWORK_DIR=${CMAKE_CURRENT_BINARY_DIR}/fresh_configure
    -P ${CMAKE_CURRENT_LIST_DIR}/fresh_configure_test.cmake)
set_tests_properties(install.fresh_configure_exports_include_dirs PROPERTIES LABELS install
  TIMEOUT 300)
