# Runs the `edgeland` command (which must exit 0) and checks that it wrote a PNG file: the
# file starts with the 8-byte PNG signature 89 50 4E 47 0D 0A 1A 0A (PNG spec, 5.2) followed by
# an IHDR chunk (cmake -P).
#   EDGELAND  the command;  ARGS  its arguments separated by '|';  PNG  the file it must write
#   STDOUT_REGEX  optional regex its standard output must match
string(REPLACE "|" ";" args "${ARGS}")
file(REMOVE "${PNG}")
execute_process(COMMAND "${EDGELAND}" ${args}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 120)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "edgeland ${args}: exit ${status}\n${out}${err}")
endif()
if(DEFINED STDOUT_REGEX AND NOT out MATCHES "${STDOUT_REGEX}")
  message(FATAL_ERROR "stdout does not match '${STDOUT_REGEX}':\n${out}")
endif()
if(NOT EXISTS "${PNG}")
  message(FATAL_ERROR "edgeland ${args} wrote no ${PNG}\n${out}${err}")
endif()
file(READ "${PNG}" head LIMIT 16 HEX)
if(NOT head MATCHES "^89504e470d0a1a0a0000000d49484452")
  message(FATAL_ERROR "${PNG} does not start with the PNG signature and IHDR: ${head}")
endif()
