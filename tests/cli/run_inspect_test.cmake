# `edgeland inspect` of good and bad save files (cmake -P; issue 27, point 14). `edgeland demo`
# writes the save file and the edit log of a small world; inspect must pass it (exit 0,
# "check":"ok") with the state hash and areas that replaying the log gives (an independent
# path to the same world); a truncated copy and a file of another kind are read but refused
# (exit 1, "valid":false, one JSON line).
#   EDGELAND  the command;  WORK  a scratch folder;  TEXT  a file that is no save file
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")

# Runs edgeland; sets `out` to its stdout, requires exit `want` and one line on stdout only.
function(run want)
  execute_process(COMMAND "${EDGELAND}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE stdout
    ERROR_VARIABLE stderr TIMEOUT 240)
  if(NOT status EQUAL want OR NOT stdout MATCHES "^[^\n]+\n$" OR NOT stderr STREQUAL "")
    message(FATAL_ERROR "edgeland ${ARGN}: exit ${status} (want ${want}, one line on stdout)\n"
      "${stdout}--- stderr:\n${stderr}")
  endif()
  set(out "${stdout}" PARENT_SCOPE)
endfunction()

function(require json)
  foreach(pair ${ARGN})
    string(REPLACE "=" ";" kv "${pair}")
    list(GET kv 0 key)
    list(GET kv 1 want)
    string(REPLACE "." ";" path "${key}")  # config.edge_cap: a member of a member
    string(JSON got ERROR_VARIABLE error GET "${json}" ${path})
    if(error OR NOT got STREQUAL want)
      message(FATAL_ERROR "${key}: '${got}' (want '${want}') in\n${json}")
    endif()
  endforeach()
endfunction()

execute_process(COMMAND "${EDGELAND}" demo --edits 20 --unchecked --out "${WORK}"
  --save "${WORK}/world.save" --log "${WORK}/world.log" RESULT_VARIABLE status
  OUTPUT_QUIET ERROR_VARIABLE err TIMEOUT 240)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "edgeland demo: exit ${status}\n${err}")
endif()

run(0 inspect "${WORK}/world.save")
set(good "${out}")
file(SIZE "${WORK}/world.save" size)
require("${good}" valid=ON check=ok bytes=${size} config.edge_cap=64)
run(0 replay "${WORK}/world.log")
set(replayed "${out}")
string(JSON hash GET "${replayed}" state_hash)
string(JSON area GET "${replayed}" area)
string(JSON polygons GET "${replayed}" polygons)
require("${good}" state_hash=${hash} polygons=${polygons})
string(JSON good_area GET "${good}" area)
string(JSON same EQUAL "${area}" "${good_area}")
if(NOT same)
  message(FATAL_ERROR "areas differ: inspect ${good_area}, replay ${area}")
endif()

# Standard input reads the same file.
execute_process(COMMAND "${EDGELAND}" inspect - INPUT_FILE "${WORK}/world.save"
  OUTPUT_VARIABLE piped RESULT_VARIABLE status)
string(JSON piped_hash GET "${piped}" state_hash)
if(NOT status EQUAL 0 OR NOT piped_hash STREQUAL hash)
  message(FATAL_ERROR "inspect - : exit ${status}\n${piped}")
endif()

# The first 100 bytes: read, refused.
execute_process(COMMAND head -c 100 "${WORK}/world.save" OUTPUT_FILE "${WORK}/truncated.save")
run(1 inspect "${WORK}/truncated.save")
require("${out}" valid=OFF bytes=100)
string(JSON error GET "${out}" error)
if(error STREQUAL "")
  message(FATAL_ERROR "no error named:\n${out}")
endif()
run(1 inspect "${TEXT}")
require("${out}" valid=OFF)
