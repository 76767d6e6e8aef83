# The browser test (play/web/test/browser_test.py) in ctest: play.web_build puts the page together
# in the build tree with scripts/build_web.sh, from the JavaScript package that bindings.js_build
# built there (the fixture js_package: the library is built once for both), and play.web_browser
# loads it in headless Chromium. Both need Emscripten, Node.js with npm, Chromium, its driver and
# python3-selenium; without them one test stands in and is reported as skipped, naming what is
# missing. Not under the sanitizers: the page is WebAssembly built by Emscripten, which that
# build's flags do not reach.
set(EDGELAND_WEB_MISSING "")
foreach(tool emcmake node npm chromium chromedriver)
  find_program(EDGELAND_${tool}_PROGRAM ${tool})
  if(NOT EDGELAND_${tool}_PROGRAM)
    list(APPEND EDGELAND_WEB_MISSING ${tool})
  endif()
endforeach()
# Debian's python3-selenium is for Debian's python3, which may not be the first on the PATH.
set(EDGELAND_WEB_PYTHON "")
foreach(python /usr/bin/python3 python3)
  execute_process(COMMAND ${python} -c "import selenium" RESULT_VARIABLE no_selenium
    OUTPUT_QUIET ERROR_QUIET)
  if(no_selenium EQUAL 0)
    set(EDGELAND_WEB_PYTHON ${python})
    break()
  endif()
endforeach()
if(NOT EDGELAND_WEB_PYTHON)
  list(APPEND EDGELAND_WEB_MISSING python3-selenium)
endif()

if(EDGELAND_SANITIZE)
  message(STATUS "play.web_browser: not in the sanitizer build")
elseif(EDGELAND_WEB_MISSING)
  string(REPLACE ";" ", " missing "${EDGELAND_WEB_MISSING}")
  add_test(NAME play.web_browser COMMAND ${CMAKE_COMMAND} -E echo
    "skipped: the browser test needs ${missing} (apt-get install -y emscripten chromium chromium-driver python3-selenium; npm comes with Node.js)")
  set_tests_properties(play.web_browser PROPERTIES SKIP_REGULAR_EXPRESSION "skipped:" LABELS web)
else()
  set(web_dir ${CMAKE_BINARY_DIR}/web)
  add_test(NAME play.web_build COMMAND ${CMAKE_COMMAND} -E env EDGELAND_WEB_DIR=${web_dir}
    EDGELAND_WEB_OBJ=${CMAKE_BINARY_DIR}/web-obj EDGELAND_JS_DIR=${CMAKE_BINARY_DIR}/js
    ${PROJECT_SOURCE_DIR}/scripts/build_web.sh)
  set_tests_properties(play.web_build PROPERTIES FIXTURES_SETUP web_page FIXTURES_REQUIRED
    js_package LABELS web TIMEOUT 1200)
  add_test(NAME play.web_browser COMMAND ${EDGELAND_WEB_PYTHON}
    ${CMAKE_CURRENT_SOURCE_DIR}/web/test/browser_test.py --web-dir ${web_dir}
    --edgeland $<TARGET_FILE:edgeland_cli> --screenshot ${web_dir}/screenshot.png)
  set_tests_properties(play.web_browser PROPERTIES FIXTURES_REQUIRED web_page LABELS web
    TIMEOUT 600)
endif()
