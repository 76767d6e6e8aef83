# Fails when clip/ or spatial/ does 128-bit arithmetic of its own (issue 17): every exact
# product belongs to a kernel function whose formula is proven in proofs/. Those folders may
# hold Int128 values the kernel returns (areas, projections) and add or compare them; they
# may not make one from a narrower value or multiply one. A 128-bit product needs one of:
#   a cast to Int128 / __int128 (Int128(x), Int128{x}, static_cast<Int128>(x)), or
#   a raw __int128 type,
# or a `*` on a line that names Int128 (an Int128 variable multiplied where it is declared).
# Usage: cmake -DROOTS="dir;dir" -P no_wide_arithmetic.cmake   (exit status 1 on a finding)
set(findings "")
foreach(root IN LISTS ROOTS)
  if(IS_DIRECTORY "${root}")
    file(GLOB_RECURSE sources "${root}/*.cpp" "${root}/*.hpp" "${root}/*.txt")
  else()
    set(sources "${root}")
  endif()
  foreach(source IN LISTS sources)
    file(STRINGS "${source}" lines)
    set(number 0)
    foreach(line IN LISTS lines)
      math(EXPR number "${number} + 1")
      string(REGEX REPLACE "//.*$" "" code "${line}")  # comments may talk about products
      set(bad FALSE)
      if(code MATCHES "Int128[({]|static_cast<Int128>|__int128")
        set(bad TRUE)
      elseif(code MATCHES "Int128" AND code MATCHES "[^*/] \\* |[A-Za-z0-9_)\\]]\\*[A-Za-z0-9_(]")
        set(bad TRUE)
      endif()
      if(bad)
        string(APPEND findings "${source}:${number}: ${line}\n")
      endif()
    endforeach()
  endforeach()
endforeach()
if(findings)
  message(FATAL_ERROR "128-bit arithmetic outside the kernel (move it into a kernel function "
                      "with a formula in formulas.hpp and a theorem in proofs/):\n${findings}")
endif()
message(STATUS "no 128-bit arithmetic outside the kernel in: ${ROOTS}")
