#!/usr/bin/env bash
# The main job (for now): build the `edgeland` command and run `edgeland validate` on every
# sample shape in examples/, printing `file: verdict`. Later parts replace it with the
# clipping and landscape demos. Run from anywhere; builds in build/release.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/release}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DEDGELAND_BUILD_TESTS=OFF -DEDGELAND_BUILD_PROOFS=OFF
cmake --build "$build" -j "$jobs" --target edgeland_cli
echo
examples/run_validate.sh "$build/cli/edgeland"
