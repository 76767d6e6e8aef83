# Runs the `edgeland` command once and checks its exit status and output (cmake -P script).
#   EDGELAND       the command to run (the built `edgeland`, or a script around it)
#   ARGS           its arguments, separated by '|'
#   STDIN_FILE     optional file fed to standard input
#   EXPECT_EXIT    the exit status the test requires
#   ONE_LINE_ON    optional: stdout or stderr; that stream must hold exactly one line and the
#                  other stream nothing (the CLI's one-line verdict contract)
#   STDOUT_REGEX / STDERR_REGEX   optional regexes the streams must match
string(REPLACE "|" ";" args "${ARGS}")
set(stdin_option)
if(DEFINED STDIN_FILE)
  set(stdin_option INPUT_FILE "${STDIN_FILE}")
endif()
# TIMEOUT: a hang is a failure, never a stuck test run.
execute_process(COMMAND "${EDGELAND}" ${args} ${stdin_option}
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)

set(shown "edgeland ${args}\n--- exit: ${status}\n--- stdout:\n${out}--- stderr:\n${err}")
if(NOT status STREQUAL "${EXPECT_EXIT}")
  message(FATAL_ERROR "expected exit status ${EXPECT_EXIT}\n${shown}")
endif()
if(DEFINED ONE_LINE_ON)
  if(ONE_LINE_ON STREQUAL "stdout")
    set(line "${out}")
    set(other "${err}")
  else()
    set(line "${err}")
    set(other "${out}")
  endif()
  if(NOT line MATCHES "^[^\n]+\n$" OR NOT other STREQUAL "")
    message(FATAL_ERROR "expected exactly one line on ${ONE_LINE_ON} and nothing else\n${shown}")
  endif()
endif()
if(DEFINED STDOUT_REGEX AND NOT out MATCHES "${STDOUT_REGEX}")
  message(FATAL_ERROR "stdout does not match '${STDOUT_REGEX}'\n${shown}")
endif()
if(DEFINED STDERR_REGEX AND NOT err MATCHES "${STDERR_REGEX}")
  message(FATAL_ERROR "stderr does not match '${STDERR_REGEX}'\n${shown}")
endif()
