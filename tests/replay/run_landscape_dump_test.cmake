# `edgeland replay --check --dump DUMP LOG` on a landscape log, then checks the dump (cmake -P):
#   * every line is `MATERIAL<TAB>MULTIPOLYGON (...)`, one per solid material of the JSON's area;
#   * `edgeland validate` accepts every line's MULTIPOLYGON (a valid set);
#   * `world WORLD` followed by `fill MATERIAL WKT` for every line, replayed, gives the same
#     area object as the original log: the dump holds exactly the landscape's regions.
#   EDGELAND  the built command;  LOG  a landscape log;  WORLD  its world box "X0 Y0 X1 Y1";
#   WORK  a scratch directory
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
set(dump "${WORK}/dump.txt")

function(replay_areas log out_var)
  execute_process(COMMAND "${EDGELAND}" replay --check ${ARGN} "${log}"
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if(NOT status EQUAL 0 OR NOT out MATCHES "\"area\":({[^}]*})")
    message(FATAL_ERROR "replay of ${log} failed (exit ${status}):\n${out}${err}")
  endif()
  set(${out_var} "${CMAKE_MATCH_1}" PARENT_SCOPE)
endfunction()

replay_areas("${LOG}" areas --dump "${dump}")
file(STRINGS "${dump}" lines)
list(LENGTH lines count)
if(count EQUAL 0)
  message(FATAL_ERROR "empty dump of ${LOG}")
endif()

set(refill "world ${WORLD}\n")
set(index 0)
foreach(line IN LISTS lines)
  if(NOT line MATCHES "^([0-9]+)\t(MULTIPOLYGON \\(.*\\)\\))$")
    message(FATAL_ERROR "not `MATERIAL<TAB>MULTIPOLYGON`: ${line}")
  endif()
  set(material "${CMAKE_MATCH_1}")
  set(wkt "${CMAKE_MATCH_2}")
  if(NOT areas MATCHES "\"${material}\":\"[1-9]")
    message(FATAL_ERROR "material ${material} is dumped but has no area in ${areas}")
  endif()
  math(EXPR index "${index} + 1")
  file(WRITE "${WORK}/material_${material}.wkt" "${wkt}\n")
  execute_process(COMMAND "${EDGELAND}" validate "${WORK}/material_${material}.wkt"
    RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if(NOT status EQUAL 0 OR NOT out STREQUAL "valid\n")
    message(FATAL_ERROR "edgeland validate rejects material ${material}: ${out}${err}")
  endif()
  string(APPEND refill "fill ${material} ${wkt}\n")
endforeach()

# Every solid material with an area is in the dump (the area object also holds "0").
string(REGEX MATCHALL "\"[0-9]+\":" keys "${areas}")
list(LENGTH keys key_count)
math(EXPR solid_count "${key_count} - 1")
if(areas MATCHES "\"0\":" AND NOT solid_count EQUAL count)
  message(FATAL_ERROR "${count} dump lines for the materials of ${areas}")
endif()

file(WRITE "${WORK}/refill.log" "${refill}")
replay_areas("${WORK}/refill.log" refilled)
if(NOT refilled STREQUAL areas)
  message(FATAL_ERROR "re-importing the dump gives ${refilled}, the log gave ${areas}")
endif()
