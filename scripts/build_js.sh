#!/usr/bin/env bash
# Builds the JavaScript package (bindings/js/README.md) into build/js/package: the WebAssembly
# module (edgeland_c.mjs, built by Debian's Emscripten from bindings/js/CMakeLists.txt in
# build/js/obj) next to the package's own files (index.js, index.d.ts, package.json). The
# package's example dependencies (planck.js) come from the npm registry as its lock file pins
# them (`npm ci`, again only when the lock changes).
# EDGELAND_JS_DIR chooses the output folder, EDGELAND_JOBS the build's jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${EDGELAND_JS_DIR:-build/js}"
jobs="${EDGELAND_JOBS:-2}"
export NODE_PATH=/usr/share/nodejs  # Emscripten's optimiser needs Debian's node-acorn
launcher=()
if command -v ccache > /dev/null; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache); fi
emcmake cmake -S bindings/js -B "$out/obj" -DCMAKE_BUILD_TYPE=Release "${launcher[@]}" > /dev/null
cmake --build "$out/obj" -j "$jobs" --target edgeland_js

package="$out/package"
mkdir -p "$package"
cp bindings/js/package.json bindings/js/package-lock.json bindings/js/index.js bindings/js/index.d.ts \
  bindings/js/README.md "$out/obj/edgeland_c.mjs" "$package/"
rm -rf "$package/test" "$package/examples"
cp -r bindings/js/test bindings/js/examples "$package/"
if ! cmp -s bindings/js/package-lock.json "$out/npm-lock" || [ ! -d "$package/node_modules" ]; then
  (cd "$package" && npm ci --no-audit --no-fund --loglevel=error)
  cp bindings/js/package-lock.json "$out/npm-lock"
fi
echo "build_js.sh: $package ($(gzip -9 -c "$package/edgeland_c.mjs" | wc -c) bytes gzipped)"
