#!/usr/bin/env bash
# The front ends' headless tests alone (play/README.md), without the library's test suite and
# its dependencies: builds the `edgeland` command and the desktop demo (Release, in build/play),
# then runs ctest's `play` and `web` labels: play.desktop_headless, and play.web_build +
# play.web_browser (the page built with Emscripten and loaded in headless Chromium), each
# reported as skipped, naming what is missing, when its tools are not installed.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/play}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGELAND_BUILD_TESTS=OFF \
  -DEDGELAND_BUILD_PROOFS=OFF -DEDGELAND_BUILD_PLAY_TESTS=ON
cmake --build "$build" -j "$jobs"
ctest --test-dir "$build" --output-on-failure -L 'play|web'
