# The JavaScript package in ctest: bindings.js_build builds it into the build tree with
# scripts/build_js.sh (Emscripten, then npm ci for the example's planck.js and the declarations'
# TypeScript), then Node's test runner runs its tests, the mirror script, the TypeScript check,
# the planck.js example and the README's example. Without Emscripten, Node or npm one test
# stands in, reported as skipped and naming what is missing (as play.web_browser does). Not under
# the sanitizers: the module is WebAssembly, which that build's flags do not reach.
set(EDGELAND_JS_MISSING "")
foreach(tool emcmake node npm)
  find_program(EDGELAND_JS_${tool} ${tool})
  if(NOT EDGELAND_JS_${tool})
    list(APPEND EDGELAND_JS_MISSING ${tool})
  endif()
endforeach()
if(EDGELAND_SANITIZE)
  message(STATUS "bindings.js: not in the sanitizer build")
elseif(EDGELAND_JS_MISSING)
  string(REPLACE ";" ", " missing "${EDGELAND_JS_MISSING}")
  add_test(NAME bindings.js COMMAND ${CMAKE_COMMAND} -E echo
    "skipped: the JavaScript package needs ${missing} (apt-get install -y emscripten; npm comes with Node.js)")
  set_tests_properties(bindings.js PROPERTIES SKIP_REGULAR_EXPRESSION "skipped:" LABELS bindings)
else()
  set(js_dir ${CMAKE_BINARY_DIR}/js)
  set(package ${js_dir}/package)
  add_test(NAME bindings.js_build COMMAND ${CMAKE_COMMAND} -E env EDGELAND_JS_DIR=${js_dir}
    ${PROJECT_SOURCE_DIR}/scripts/build_js.sh)
  set_tests_properties(bindings.js_build PROPERTIES FIXTURES_SETUP js_package LABELS bindings
    TIMEOUT 1800)
  add_test(NAME bindings.js COMMAND ${EDGELAND_JS_node} --test ${package}/test/landscape.test.mjs
    ${package}/test/game.test.mjs ${package}/test/driver.test.mjs)
  add_test(NAME mirror.js COMMAND ${CMAKE_COMMAND} -E env
    EDGELAND_MIRROR_HASHES=${EDGELAND_MIRROR_HASHES}
    ${EDGELAND_JS_node} --test ${package}/test/mirror.test.mjs)
  add_test(NAME bindings.js_types COMMAND ${package}/node_modules/.bin/tsc --noEmit --strict
    --target es2022 --module nodenext --moduleResolution nodenext ${package}/test/usage.ts)
  add_test(NAME bindings.js_planck_example COMMAND ${EDGELAND_JS_node}
    ${package}/examples/planck_terrain.mjs)
  add_test(NAME bindings.js_readme COMMAND ${EDGELAND_PYTHON}
    ${PROJECT_SOURCE_DIR}/tests/readme/run_block.py js ${CMAKE_CURRENT_SOURCE_DIR}/js/README.md
    ${EDGELAND_JS_node} ${package})
  set_tests_properties(bindings.js bindings.js_types bindings.js_planck_example
    bindings.js_readme PROPERTIES FIXTURES_REQUIRED js_package LABELS bindings)
  set_tests_properties(bindings.js_planck_example PROPERTIES
    PASS_REGULAR_EXPRESSION "the ball fell into the crater")
  set_tests_properties(mirror.js PROPERTIES FIXTURES_REQUIRED "js_package;mirror_hashes"
    LABELS "mirror;bindings")
endif()
