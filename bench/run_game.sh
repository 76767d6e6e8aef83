#!/usr/bin/env bash
# Builds edgeland_game_bench (Release, in build/bench-game), runs the game-layer benchmarks in one
# process (JSON to BUILD/game-results/game.json) and prints the Markdown tables of bench/README.md
# ("Game layer"). Needs Debian's libopencv-dev besides the bench's other packages. About 10
# minutes on the 2-core machine with the defaults.
#
# Environment (all optional):
#   EDGELAND_GAME_BUILD_DIR   build directory (default: build/bench-game)
#   EDGELAND_GAME_FILTER      regex over benchmark names (default: everything)
#   EDGELAND_GAME_EDITS       edits per workload (default 10000)
#   EDGELAND_GAME_REPEATS     repeats of every timed run, each edit keeping its fastest (default 5)
#   EDGELAND_GAME_DEMO_EDITS  actions after the demo world is built, for the export (default 6000)
set -euo pipefail
repo=$(cd "$(dirname "$0")/.." && pwd)
build=${EDGELAND_GAME_BUILD_DIR:-$repo/build/bench-game}
filter=${EDGELAND_GAME_FILTER:-.}
out=$build/game-results

cmake -S "$repo" -B "$build" -DCMAKE_BUILD_TYPE=Release -DEDGELAND_BUILD_BENCH=ON \
  -DEDGELAND_BUILD_TESTS=OFF -DEDGELAND_BUILD_PROOFS=OFF >&2
cmake --build "$build" --target edgeland_game_bench -j2 >&2
mkdir -p "$out"
# Run a copy: a rebuild in the same tree during the run must not mix two binaries.
cp "$build/bench/edgeland_game_bench" "$out/"
"$out/edgeland_game_bench" "--benchmark_filter=$filter" \
  "--benchmark_out=$out/game.json" --benchmark_out_format=json >&2
python3 "$repo/bench/game_tables.py" "$out/game.json" | tee "$out/tables.md"
