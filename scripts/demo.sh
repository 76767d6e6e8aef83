#!/usr/bin/env bash
# The main job: build the `edgeland` command, run `edgeland validate` on every sample shape in
# examples/ (printing `file: verdict`), then the clipping demo: a terrain carved and filled
# again and again, every result fed back in and validated; then the landscape demo (`edgeland
# demo`): a layered 8192 x 8192 world hit by thousands of explosions, tunnels and floods in
# checked mode, its summary printed and its picture drawn into $build/demo/landscape.png; then
# the physics demo (`edgeland demo --physics`), frames in $build/demo/physics_*.png.
# Run from anywhere; builds in build/release.
set -euo pipefail
cd "$(dirname "$0")/.."
build="${EDGELAND_BUILD_DIR:-build/release}"
jobs="${EDGELAND_JOBS:-$(nproc)}"

cmake -S . -B "$build" -DCMAKE_BUILD_TYPE=Release \
  -DEDGELAND_BUILD_TESTS=OFF -DEDGELAND_BUILD_PROOFS=OFF
cmake --build "$build" -j "$jobs" --target edgeland_cli
echo
examples/run_validate.sh "$build/cli/edgeland"
echo
examples/run_clip_demo.sh "$build/cli/edgeland"
echo
"$build/cli/edgeland" demo --out "$build/demo"
echo
# The physics demo (issue 26): Box2D bodies on the landscape's surface chains while blasts and
# fills change the ground under them; debris islands fall. PNG frames in $build/demo/.
"$build/cli/edgeland" demo --physics --out "$build/demo"
