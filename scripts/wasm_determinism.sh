#!/usr/bin/env bash
# Builds the pinned landscape sequence (tests/spatial/pinned_sequence.hpp) with Debian's
# Emscripten 3.1.6 into WebAssembly (wasm32: 32-bit size_t) and runs it under Node: the state
# hashes must be the pinned ones, as in the native builds. Then edgeland::io (io/, which the
# browser playground compiles) replays the landscape logs of tests/replay/data into the same JSON
# as the native `edgeland replay` (EDGELAND, default build/test/cli/edgeland; timing left out).
# Needs `apt-get install -y emscripten` (not part of CI). Builds in build/wasm; about 3 minutes.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${EDGELAND_BUILD_DIR:-build/wasm}"
mkdir -p "$out"
export NODE_PATH=/usr/share/nodejs  # Emscripten's optimiser needs Debian's node-acorn
em++ -std=gnu++20 -O2 -fexceptions -sSINGLE_FILE=1 -sENVIRONMENT=node -sALLOW_MEMORY_GROWTH=1 \
  -I kernel/include -I kernel/internal -I clip/include -I spatial/include tests/spatial/determinism_main.cpp \
  kernel/src/*.cpp clip/src/*.cpp spatial/src/*.cpp -o "$out/determinism.js"
node --no-experimental-fetch "$out/determinism.js"

# edgeland::io in WebAssembly: the same replay JSON as the native command, log by log.
edgeland="${EDGELAND:-build/test/cli/edgeland}"
em++ -std=gnu++20 -O2 -fexceptions -sENVIRONMENT=node -sNODERAWFS=1 -sALLOW_MEMORY_GROWTH=1 \
  -I kernel/include -I kernel/internal -I clip/include -I spatial/include -I io/include \
  tests/io/wasm_replay_main.cpp kernel/src/*.cpp clip/src/*.cpp spatial/src/*.cpp io/src/*.cpp \
  -o "$out/wasm_replay.js"
untimed() { sed -E 's/,"edits_per_second":[0-9]+//'; }
status=0
for log in tests/replay/data/landscape_*.log; do
  native=$("$edgeland" replay "$log" 2>/dev/null | head -n 1 | untimed || true)
  wasm=$(node --no-experimental-fetch "$out/wasm_replay.js" "$log" | untimed || true)
  if [ "$native" = "$wasm" ]; then echo "io replay agrees: $log"; else
    echo "io replay DIFFERS: $log"; echo "  native: $native"; echo "  wasm:   $wasm"; status=1; fi
done
exit $status
