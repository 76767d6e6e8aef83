# Fails if a source or header of kernel/, clip/, spatial/, io/, game/ or play/core/ (the front
# ends' shared core) names a floating-point type or function (results must be bit-identical
# across compilers: issue 15, "Standards"). Comments are stripped first, so prose may mention them.
file(GLOB_RECURSE files ${ROOT}/kernel/*.hpp ${ROOT}/kernel/*.cpp ${ROOT}/clip/*.hpp
  ${ROOT}/clip/*.cpp ${ROOT}/spatial/*.hpp ${ROOT}/spatial/*.cpp ${ROOT}/io/*.hpp ${ROOT}/io/*.cpp
  ${ROOT}/game/*.hpp ${ROOT}/game/*.cpp ${ROOT}/play/core/*.hpp ${ROOT}/play/core/*.cpp)
set(found "")
foreach(f ${files})
  file(STRINGS ${f} lines)
  set(n 0)
  foreach(line IN LISTS lines)
    math(EXPR n "${n} + 1")
    string(REGEX REPLACE "//.*$" "" code "${line}")
    if(code MATCHES "(^|[^A-Za-z0-9_])(float|double|long double|sqrt|std::sin|std::cos|std::atan2|std::floor|std::ceil|std::round|std::lround|std::llround)([^A-Za-z0-9_]|$)")
      string(APPEND found "${f}:${n}: ${line}\n")
    endif()
  endforeach()
endforeach()
list(LENGTH files count)
if(found)
  message(FATAL_ERROR "floating point in the library:\n${found}")
endif()
message(STATUS "no floating point in ${count} library files")
