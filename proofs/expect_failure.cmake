# Runs a proof that must NOT go through and checks how it fails: exit status 1 (so its own
# ctest test would fail) and a printed counterexample. Usage:
#   cmake -DPROVER=<edgeland_prove> -DBITS=64 -DTHEOREM=orient_int128 -P expect_failure.cmake
execute_process(COMMAND ${PROVER} --bits ${BITS} ${THEOREM} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
message("${out}${err}")
if(NOT rc EQUAL 1)
  message(FATAL_ERROR "expected exit status 1 from a refuted proof, got '${rc}'")
endif()
if(NOT out MATCHES "counterexample for [^\n]*:\n  ax = -?[0-9]+\n")
  message(FATAL_ERROR "the refuted proof printed no counterexample")
endif()
