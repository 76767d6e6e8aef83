#!/usr/bin/env bash
# Builds the browser playground (play/web/README.md) into build/web: index.html, its scripts,
# the WebAssembly module (edgeland.js + edgeland.wasm) and planck.js from the npm registry at
# the version play/web/package-lock.json pins. Needs Debian's emscripten, npm and the headers
# of libboost-dev, nlohmann-json3-dev and libcli11-dev. Serve it with
#   python3 -m http.server -d build/web 8000     # then open http://127.0.0.1:8000/
# EDGELAND_WEB_DIR / EDGELAND_WEB_OBJ choose other folders; EDGELAND_JOBS the build's jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${EDGELAND_WEB_DIR:-build/web}"
obj="${EDGELAND_WEB_OBJ:-build/web-obj}"
jobs="${EDGELAND_JOBS:-2}"
export NODE_PATH=/usr/share/nodejs  # Emscripten's optimiser needs Debian's node-acorn

launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
emcmake cmake -S play/web -B "$obj" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" > /dev/null
cmake --build "$obj" -j "$jobs"

# planck.js, exactly as locked; installed again only when the lock file changed.
mkdir -p "$out/npm"
if ! cmp -s play/web/package-lock.json "$out/npm/package-lock.json" ||
  [ ! -f "$out/npm/node_modules/planck/dist/planck.min.js" ]; then
  cp play/web/package.json play/web/package-lock.json "$out/npm/"
  (cd "$out/npm" && npm ci --no-audit --no-fund --loglevel=error)
fi

cp "$out/npm/node_modules/planck/dist/planck.min.js" "$obj/edgeland.js" "$obj/edgeland.wasm" \
  play/web/page/* "$out/"
echo "build_web.sh: $out/index.html ($(gzip -9 -c "$out/edgeland.wasm" | wc -c) bytes of gzipped wasm)"
