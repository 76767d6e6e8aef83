# Strict warnings for our own targets only; never installed or exported.
add_library(edgeland_warnings INTERFACE)
target_compile_options(edgeland_warnings INTERFACE
  -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wno-sign-conversion -ffp-contract=off)
# -Wpedantic complains about __int128; the kernel uses it on purpose.
target_compile_options(edgeland_warnings INTERFACE -Wno-pedantic)
