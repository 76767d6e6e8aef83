#!/usr/bin/env bash
# The test suite again with the portable Int128 (-DEDGELAND_PORTABLE_INT128=ON: two 64-bit words
# and portable overflow checks, the code MSVC compiles) in build/portable: every test, the pinned
# state hashes included, must pass as with __int128. Left out: what is WebAssembly (the browser
# playground, label `web`, and the JavaScript package, `bindings.js*` and `mirror.js`: Emscripten
# builds them with its own Int128 whatever this build's flags). Step of .ci/run after the gcc
# pass; prints the build's and the tests' times. Run from anywhere.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/portable}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

start=$(date +%s)
cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O2 -g1" \
  -DEDGELAND_CHECKED=ON -DEDGELAND_PORTABLE_INT128=ON
cmake --build "$build" -j "$jobs"
built=$(date +%s)
ctest --test-dir "$build" --output-on-failure -j "$jobs" -LE web -E '^(bindings\.js|mirror\.js)'
echo "test_portable.sh: built in $((built - start)) s, tested in $(($(date +%s) - built)) s"
