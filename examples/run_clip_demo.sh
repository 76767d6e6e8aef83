#!/usr/bin/env bash
# Clipping demo: carves and fills a two-piece terrain again and again, feeding every result
# back in as the next subject, and validates each result with the kernel's checkers.
# Usage: examples/run_clip_demo.sh PATH/TO/edgeland
set -euo pipefail
edgeland="$1"
here="$(cd "$(dirname "$0")" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

state="$here/clip/terrain.wkt"
step() {  # step OP TOOL: state := state OP tool, then validate and summarise
  local op="$1" tool="$2" out="$work/state_$RANDOM.wkt"
  "$edgeland" clip --op "$op" --check "$state" "$here/clip/$tool" > "$out"
  local polygons vertices verdict
  polygons=$(grep -o '((' "$out" | wc -l)
  vertices=$(grep -o ',' "$out" | wc -l)
  verdict=$("$edgeland" validate "$out")
  printf '%-13s %-15s -> %3d polygons, ~%4d vertices: %s\n' "$op" "$tool" "$polygons" "$vertices" "$verdict"
  state="$out"
}
echo "terrain: $("$edgeland" validate "$state")"
step difference crater.wkt
step difference tunnel.wkt
step union bridge.wkt
step xor crater.wkt
step intersection terrain.wkt
echo "final result:"
cat "$state"
echo
echo "a self-intersecting ring (bow-tie) read as an OGC polygon (every lobe it winds around):"
printf '  %-9s %s\n' "ogc" "$("$edgeland" clip --op union --check \
  "$here/clip/bowtie_rings.wkt" "$here/clip/bowtie_rings.wkt")"
echo "and imported with each fill rule:"
for rule in evenodd nonzero positive negative; do
  printf '  %-9s %s\n' "$rule" "$("$edgeland" clip --op union --fill-rule "$rule" --check \
    "$here/clip/bowtie_rings.wkt" "$here/clip/bowtie_rings.wkt")"
done
