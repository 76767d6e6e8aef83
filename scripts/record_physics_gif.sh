#!/usr/bin/env bash
# Records the README's animation of the physics demo: `edgeland demo --physics` drawing every
# 15th frame (Box2D bodies on the landscape's surface chains, blasts and fills under them, debris
# falling), cropped to the ground and assembled into an animated GIF by ImageMagick (Debian's
# `imagemagick`). Usage: scripts/record_physics_gif.sh [EDGELAND] [OUT.gif]
# Default: build/release/cli/edgeland (scripts/demo.sh builds it), play/pictures/physics_demo.gif.
set -euo pipefail
cd "$(dirname "$0")/.."
edgeland="${1:-build/release/cli/edgeland}"
out="${2:-play/pictures/physics_demo.gif}"
frames="$(mktemp -d)"
trap 'rm -rf "$frames"' EXIT

"$edgeland" demo --physics --frames 600 --frame-every 15 --out "$frames" > /dev/null
# The frames are 1024 x 1024 with the ground in the middle band: crop it, show each for
# 15/100 s, and keep 32 colours (the picture has few): about half a megabyte.
convert -delay 15 -loop 0 "$frames"/physics_*.png -crop 1024x380+0+150 +repage \
  -resize 560x -layers Optimize -colors 32 "$out"
echo "$out: $(identify "$out" | wc -l) frames, $(stat -c %s "$out") bytes"
