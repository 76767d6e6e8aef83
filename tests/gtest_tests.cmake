# edgeland_gtest_tests(TARGET [LABEL label] [TIMEOUT seconds] [SHARDS n] [COST c]
#                      [SANITIZER_FILTER gtest-filter])
#
# Registers a GoogleTest executable with ctest.
# - Normal builds: one ctest test per GoogleTest test (gtest_discover_tests), so a failure
#   names its test and `ctest -R` picks single tests.
# - Sanitizer builds (EDGELAND_SANITIZE): SHARDS ctest tests (default 4), each running one
#   GoogleTest shard (GTEST_TOTAL_SHARDS / GTEST_SHARD_INDEX) of the whole executable. Starting
#   an ASan process costs 0.2-0.5 s, which over ~1,800 single-test processes was about a fifth
#   of CI's time; shards keep both cores busy without it. TIMEOUT is per GoogleTest test in
#   normal builds and is multiplied by 4 for a shard. COST (ctest's scheduling weight) starts
#   the long shards first, so no long one is left alone at the end; SANITIZER_FILTER narrows
#   what runs under the sanitizers (GTEST_FILTER).
function(edgeland_gtest_tests target)
  # One label: gtest_discover_tests (CMake 3.25) splits a list-valued property into words.
  cmake_parse_arguments(arg "" "LABEL;TIMEOUT;SHARDS;COST;SANITIZER_FILTER" "" ${ARGN})
  if(NOT arg_TIMEOUT)
    set(arg_TIMEOUT 300)
  endif()
  if(NOT arg_SHARDS)
    set(arg_SHARDS 4)
  endif()
  if(NOT EDGELAND_SANITIZE)
    set(properties TIMEOUT ${arg_TIMEOUT})
    if(arg_LABEL)
      list(APPEND properties LABELS ${arg_LABEL})
    endif()
    gtest_discover_tests(${target} DISCOVERY_TIMEOUT 120 PROPERTIES ${properties})
    return()
  endif()
  math(EXPR last "${arg_SHARDS} - 1")
  math(EXPR shard_timeout "${arg_TIMEOUT} * 4")
  foreach(index RANGE ${last})
    set(name ${target}.shard${index}of${arg_SHARDS})
    add_test(NAME ${name} COMMAND ${target})
    set_tests_properties(${name} PROPERTIES TIMEOUT ${shard_timeout}
      ENVIRONMENT "GTEST_TOTAL_SHARDS=${arg_SHARDS};GTEST_SHARD_INDEX=${index}")
    if(arg_COST)
      set_tests_properties(${name} PROPERTIES COST ${arg_COST})
    endif()
    if(arg_SANITIZER_FILTER)
      set_tests_properties(${name} PROPERTIES
        ENVIRONMENT "GTEST_TOTAL_SHARDS=${arg_SHARDS};GTEST_SHARD_INDEX=${index};GTEST_FILTER=${arg_SANITIZER_FILTER}")
    endif()
    if(arg_LABEL)
      set_tests_properties(${name} PROPERTIES LABELS ${arg_LABEL})
    endif()
  endforeach()
endfunction()

# edgeland_test_pch(TARGET)
#
# Precompiles GoogleTest and RapidCheck for a test executable that links both: parsing them
# was about 4 of the 8 seconds of a small test file, once per file and per build (the gcc and
# the sanitizer build of CI).
function(edgeland_test_pch target)
  target_precompile_headers(${target} PRIVATE <gtest/gtest.h> <rapidcheck.h> <rapidcheck/gtest.h>
    <algorithm> <cstdint> <string> <vector>)
endfunction()
