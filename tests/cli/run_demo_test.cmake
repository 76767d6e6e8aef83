# `edgeland demo --edits N --out DIR --log DIR/demo.log` (cmake -P):
#   * exits 0, reports check(): ok and writes DIR/landscape.png (PNG signature);
#   * the edit log the library recorded replays (`edgeland replay --check`) to the state hash
#     the demo printed, with as many edits as the demo reported.
#   EDGELAND  the built command;  EDITS  N;  DIR  a scratch directory
file(REMOVE_RECURSE "${DIR}")
execute_process(COMMAND "${EDGELAND}" demo --edits ${EDITS} --out "${DIR}" --log "${DIR}/demo.log"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
set(shown "--- exit: ${status}\n--- stdout:\n${out}--- stderr:\n${err}")
if(NOT status EQUAL 0)
  message(FATAL_ERROR "edgeland demo failed\n${shown}")
endif()
if(NOT out MATCHES "\ncheck\\(\\): +ok\n")
  message(FATAL_ERROR "the demo's check() did not report ok\n${shown}")
endif()
if(NOT out MATCHES "\nactions: +${EDITS} edits")
  message(FATAL_ERROR "the demo did not make ${EDITS} edits after building its world\n${shown}")
endif()
if(NOT out MATCHES "\nedits: +([0-9]+)\n")
  message(FATAL_ERROR "no edit count\n${shown}")
endif()
set(edits "${CMAKE_MATCH_1}")
if(NOT out MATCHES "\nstate hash: +([0-9a-f]+)\n")
  message(FATAL_ERROR "no state hash\n${shown}")
endif()
set(hash "${CMAKE_MATCH_1}")
file(READ "${DIR}/landscape.png" head LIMIT 8 HEX)
if(NOT head STREQUAL "89504e470d0a1a0a")
  message(FATAL_ERROR "${DIR}/landscape.png is not a PNG: ${head}\n${shown}")
endif()

execute_process(COMMAND "${EDGELAND}" replay --check "${DIR}/demo.log"
  RESULT_VARIABLE status OUTPUT_VARIABLE replayed ERROR_VARIABLE err TIMEOUT 120)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "replay of the demo's log failed (exit ${status}):\n${replayed}${err}")
endif()
if(NOT replayed MATCHES "^{\"edits\":${edits},.*\"state_hash\":\"${hash}\"")
  message(FATAL_ERROR "the demo made ${edits} edits to state ${hash}; its log replays to\n${replayed}")
endif()
