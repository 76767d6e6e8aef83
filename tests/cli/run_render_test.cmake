# `edgeland render` of a save file, as SVG (cmake -P): `edgeland demo` writes the save file of
# a small world, render draws it; the SVG is a cairo SVG document whose width is the world's
# 2048 pixels plus the legend's column, and without --no-legend it is only the world's.
#   EDGELAND  the command;  WORK  a scratch folder
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
function(run)
  execute_process(COMMAND "${EDGELAND}" ${ARGN} RESULT_VARIABLE status OUTPUT_VARIABLE out
    ERROR_VARIABLE err TIMEOUT 240)
  if(NOT status EQUAL 0)
    message(FATAL_ERROR "edgeland ${ARGN}: exit ${status}\n${out}${err}")
  endif()
endfunction()
run(demo --edits 20 --unchecked --out "${WORK}" --save "${WORK}/world.save")
run(render "${WORK}/world.save" --svg "${WORK}/legend.svg")
run(render "${WORK}/world.save" --svg "${WORK}/plain.svg" --no-legend)
foreach(name legend plain)
  file(READ "${WORK}/${name}.svg" svg LIMIT 600)
  if(NOT svg MATCHES "^<\\?xml" OR NOT svg MATCHES "<svg")
    message(FATAL_ERROR "${WORK}/${name}.svg is not an SVG document:\n${svg}")
  endif()
  string(REGEX MATCH "width=\"([0-9]+)(pt)?\"" width "${svg}")
  set(${name}_width ${CMAKE_MATCH_1})
endforeach()
if(NOT plain_width EQUAL 2048 OR NOT legend_width GREATER plain_width)
  message(FATAL_ERROR "widths: without legend ${plain_width} (want 2048), with ${legend_width}")
endif()
