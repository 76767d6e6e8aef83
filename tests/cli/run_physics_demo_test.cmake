# `edgeland demo --physics` (cmake -P script): runs a short physics demo twice and checks that it
# reports its work (edits, collider updates, islands, times), writes its frames, and is
# deterministic (the same state hash both times: the edits follow the bodies, so the physics
# steps must replay exactly too).
#   EDGELAND  the command;  OUT  a scratch directory
foreach(run 1 2)
  file(REMOVE_RECURSE "${OUT}/${run}")
  execute_process(COMMAND "${EDGELAND}" demo --physics --frames 60 --frame-every 20
    --out "${OUT}/${run}" RESULT_VARIABLE status OUTPUT_VARIABLE out_${run} ERROR_VARIABLE err
    TIMEOUT 300)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "demo --physics failed (${status}): ${err}")
  endif()
  foreach(line "edits: +180 " "collider updates: +[0-9]+ chains removed, [0-9]+ added"
      "islands detached: +[0-9]+" "step time: +[0-9.]+ us per step" "state hash: +[0-9a-f]+")
    if(NOT out_${run} MATCHES "${line}")
      message(FATAL_ERROR "the summary lacks '${line}':\n${out_${run}}")
    endif()
  endforeach()
  foreach(frame 0000 0001 0002)
    if(NOT EXISTS "${OUT}/${run}/physics_${frame}.png")
      message(FATAL_ERROR "frame physics_${frame}.png was not written")
    endif()
  endforeach()
  string(REGEX MATCH "state hash: +[0-9a-f]+" hash_${run} "${out_${run}}")
endforeach()
if(NOT hash_1 STREQUAL hash_2)
  message(FATAL_ERROR "two runs differ: '${hash_1}' and '${hash_2}'")
endif()
message(STATUS "physics demo: ${hash_1}, twice")
