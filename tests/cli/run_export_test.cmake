# `edgeland export` on tests/replay/data/landscape_fill.log (cmake -P script), checked against
# the world worked out by hand in that log's comments:
#   block A = material 3 [10,15]x[10,30] + 1 [15,20]x[10,30] + 2 [20,35]x[10,20], clear of the
#   world border: one closed chain of 9 points (kept where the material changes along it), and
#   the one debris island;
#   block B = material 4 [60,80]x[30,50] minus the hole [65,75]x[35,45], on the top border: an
#   open chain (60 50)-(60 30)-(80 30)-(80 50) whose ghosts go straight on past the border, and
#   the hole's closed chain of 4 points;
#   triangles: 2 per rectangle, and 8 for the holed square (12 vertices in its two pieces).
#   EDGELAND  the command;  LOG  the log;  OUT  a scratch directory
file(MAKE_DIRECTORY "${OUT}")
execute_process(COMMAND "${EDGELAND}" export "${LOG}" --chains "${OUT}/chains.txt"
  --islands "${OUT}/islands.txt" --mesh "${OUT}/mesh.txt" --pieces "${OUT}/pieces.txt"
  RESULT_VARIABLE status OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
if(NOT status EQUAL 0)
  message(FATAL_ERROR "export failed (${status}): ${err}")
endif()
if(NOT out MATCHES "^\\{\"chains\":3,\"chain_vertices\":17,\"pieces\":[0-9]+,\"triangles\":14,\"islands\":1,\"seconds\":[0-9.e+-]+\\}\n$")
  message(FATAL_ERROR "unexpected summary: ${out}")
endif()
file(READ "${OUT}/chains.txt" chains)
foreach(expected
    "LINESTRING (60 50, 60 30, 80 30, 80 50)\tPOINT (60 70)\tPOINT (80 70)\n"
    "LINESTRING (10 10, 15 10, 20 10, 35 10, 35 20, 20 20, 20 30, 15 30, 10 30, 10 10)\tPOINT (10 30)\tPOINT (10 10)\n"
    "LINESTRING (65 35, 65 45, 75 45, 75 35, 65 35)\tPOINT (75 35)\tPOINT (65 35)\n")
  string(FIND "${chains}" "${expected}" at)
  if(at EQUAL -1)
    message(FATAL_ERROR "chains.txt lacks the line '${expected}':\n${chains}")
  endif()
endforeach()
file(READ "${OUT}/islands.txt" islands)
if(NOT islands STREQUAL "MULTIPOLYGON (((10 10, 35 10, 35 20, 20 20, 20 30, 10 30, 10 10)))\n")
  message(FATAL_ERROR "unexpected islands.txt:\n${islands}")
endif()
file(STRINGS "${OUT}/mesh.txt" triangles)
list(LENGTH triangles count)
if(NOT count EQUAL 14)
  message(FATAL_ERROR "mesh.txt: ${count} triangles, expected 14")
endif()
foreach(t IN LISTS triangles)
  if(NOT t MATCHES "^[1-4]\tPOLYGON \\(\\([-0-9]+ [-0-9]+, [-0-9]+ [-0-9]+, [-0-9]+ [-0-9]+, [-0-9]+ [-0-9]+\\)\\)$")
    message(FATAL_ERROR "mesh.txt: not a triangle line: '${t}'")
  endif()
endforeach()
file(STRINGS "${OUT}/pieces.txt" pieces)
foreach(p IN LISTS pieces)
  if(NOT p MATCHES "^[1-4]\tPOLYGON \\(\\(")
    message(FATAL_ERROR "pieces.txt: not a piece line: '${p}'")
  endif()
endforeach()
message(STATUS "export matches the hand-made world")
