# `edgeland replay LOG --dump DUMP`, then `edgeland validate DUMP` must say `valid` (cmake -P).
#   EDGELAND  the built command;  LOG  the log to replay;  DUMP  where to write the state
file(REMOVE "${DUMP}")
execute_process(COMMAND "${EDGELAND}" replay --check --dump "${DUMP}" "${LOG}"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT status EQUAL 0 OR NOT EXISTS "${DUMP}")
  message(FATAL_ERROR "replay --dump failed (exit ${status}):\n${out}${err}")
endif()
file(READ "${DUMP}" dumped)
if(NOT dumped MATCHES "^MULTIPOLYGON [^\n]*\n$")
  message(FATAL_ERROR "the dump is not one MULTIPOLYGON line:\n${dumped}")
endif()
execute_process(COMMAND "${EDGELAND}" validate "${DUMP}"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT status EQUAL 0 OR NOT out STREQUAL "valid\n")
  message(FATAL_ERROR "edgeland validate rejects the dump (exit ${status}):\n${out}${err}\n${dumped}")
endif()
