#!/usr/bin/env bash
# The C API as a Windows DLL: libedgeland_c built by mingw-w64 with the portable Int128 (the
# code MSVC would compile: two 64-bit words, no __builtin_*_overflow), the C test
# (tests/capi/capi_test.c and driver_test.c) built as a Windows program against it, and run under wine64.
# Prints the test's "capi: N checks passed" and the times; exit 0 when it passed.
# EDGELAND_WINDOWS_BUILD chooses the build folder (default build/windows), EDGELAND_JOBS the jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_WINDOWS_BUILD:-build/windows}"
jobs="${EDGELAND_JOBS:-2}"
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi

start=$(date +%s)
cmake -S . -B "$build" -DCMAKE_TOOLCHAIN_FILE=cmake/mingw-w64.cmake -DCMAKE_BUILD_TYPE=Release \
  -DEDGELAND_PORTABLE_INT128=ON -DEDGELAND_BUILD_TESTS=OFF -DEDGELAND_BUILD_CLI=OFF \
  -DEDGELAND_BUILD_PROOFS=OFF -DEDGELAND_BUILD_PLAY=OFF "${launcher[@]}" > /dev/null
cmake --build "$build" -j "$jobs" --target edgeland_c_shared
x86_64-w64-mingw32-gcc -std=c99 -pedantic -Wall -Wextra -Werror -Icapi/include \
  tests/capi/capi_test.c tests/capi/driver_test.c -o "$build/capi_test.exe" -L"$build/capi" -ledgeland_c
cp "$build/capi/libedgeland_c.dll" "$build/"
built=$(date +%s)

# A prefix of its own in the build folder (the first run creates it), no Wine debug chatter.
export WINEPREFIX="$PWD/$build/wine" WINEDEBUG=-all WINEDLLOVERRIDES="mscoree,mshtml="
wine_bin=$(command -v wine64 || echo /usr/lib/wine/wine64)
"$wine_bin" "$build/capi_test.exe"
echo "test_capi_windows.sh: built in $((built - start)) s, ran under wine64 in $(($(date +%s) - built)) s"
