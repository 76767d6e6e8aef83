#!/usr/bin/env bash
# Builds the browser playground (play/web/README.md) into build/web: index.html and its scripts,
# the JavaScript package (bindings/js) in build/web/edgeland, the demo module (demo.mjs) and
# planck.js from the npm registry at the version play/web/package-lock.json pins. The library is
# built once, as the package, by scripts/build_js.sh (into EDGELAND_JS_DIR, default build/js);
# the demo module compiles no library code. Needs Debian's emscripten and Node.js with npm.
# Serve it with
#   python3 -m http.server -d build/web 8000     # then open http://127.0.0.1:8000/
# EDGELAND_WEB_DIR / EDGELAND_WEB_OBJ / EDGELAND_JS_DIR choose other folders; EDGELAND_JOBS the
# build's jobs.
set -euo pipefail
cd "$(dirname "$0")/.."
out="${EDGELAND_WEB_DIR:-build/web}"
obj="${EDGELAND_WEB_OBJ:-build/web-obj}"
js="${EDGELAND_JS_DIR:-build/js}"
jobs="${EDGELAND_JOBS:-2}"
export NODE_PATH=/usr/share/nodejs  # Emscripten's optimiser needs Debian's node-acorn

EDGELAND_JS_DIR="$js" EDGELAND_JOBS="$jobs" scripts/build_js.sh

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

# The package as npm would publish it (package.json and its "files"; no tests, examples or
# development dependencies).
rm -rf "$out/edgeland"
mkdir -p "$out/edgeland"
cp "$js/package/package.json" "$js/package/index.js" "$js/package/index.d.ts" \
  "$js/package/edgeland_c.mjs" "$js/package/README.md" "$out/edgeland/"
cp "$out/npm/node_modules/planck/dist/planck.min.js" "$obj/demo.mjs" play/web/page/* "$out/"
gz() { gzip -9 -c "$1" | wc -c; }
echo "build_web.sh: $out/index.html (gzipped: the package's module $(gz "$out/edgeland/edgeland_c.mjs")" \
  "bytes, the demo module $(gz "$out/demo.mjs") bytes)"
