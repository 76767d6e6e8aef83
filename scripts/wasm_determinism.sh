#!/usr/bin/env bash
# Builds the pinned landscape sequence (tests/spatial/pinned_sequence.hpp) with Debian's
# Emscripten 3.1.6 into WebAssembly (wasm32: 32-bit size_t) and runs it under Node: the state
# hashes must be the pinned ones, as in the native builds. Needs `apt-get install -y emscripten`
# (not part of CI). Builds in build/wasm; about 2 minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${EDGELAND_BUILD_DIR:-build/wasm}"
mkdir -p "$out"
export NODE_PATH=/usr/share/nodejs  # Emscripten's optimiser needs Debian's node-acorn
em++ -std=gnu++20 -O2 -fexceptions -sSINGLE_FILE=1 -sENVIRONMENT=node -sALLOW_MEMORY_GROWTH=1 \
  -I kernel/include -I kernel/internal -I clip/include -I spatial/include tests/spatial/determinism_main.cpp \
  kernel/src/*.cpp clip/src/*.cpp spatial/src/*.cpp -o "$out/determinism.js"
node --no-experimental-fetch "$out/determinism.js"
