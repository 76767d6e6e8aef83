#!/usr/bin/env bash
# Function length and nesting figures for the library's folders (issue 17's "before / after").
# Usage: scripts/function_sizes.sh [BUILD_DIR]   (BUILD_DIR needs compile_commands.json; default
# build/test, configured with -DCMAKE_EXPORT_COMPILE_COMMANDS=ON)
# Counts every function defined in kernel/, clip/ and spatial/ (sources and their headers) with
# clang-tidy's readability-function-size: lines from the opening to the closing brace, and the
# deepest nesting of compound statements. Prints one summary per folder and the longest ones.
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build/test}
tidy=$(command -v clang-tidy-14 || command -v clang-tidy)
out=$(mktemp)
trap 'rm -f "$out"' EXIT
files=$(ls kernel/src/*.cpp clip/src/*.cpp spatial/src/*.cpp)
# clang-tidy notes only the first block past the nesting threshold, so the depth is found by
# running once per threshold: every function's length, with blocks nested deeper than 3, then
# only the functions with blocks nested deeper than 4.
for nesting in 3 4; do
  lines=$([ "$nesting" = 3 ] && echo 0 || echo 100000)
  config="{Checks: '-*,readability-function-size', CheckOptions: [
    {key: readability-function-size.LineThreshold, value: $lines},
    {key: readability-function-size.NestingThreshold, value: $nesting}]}"
  # One output file per source: parallel runs appending to one file would interleave lines.
  parts=$(mktemp -d)
  printf '%s\n' $files | TIDY="$tidy" BUILD="$build" CONFIG="$config" PARTS="$parts" \
    xargs -P "${EDGELAND_JOBS:-2}" -I{} sh -c '"$TIDY" -p "$BUILD" --quiet --config="$CONFIG" \
      --header-filter="/(kernel|clip|spatial)/" "$1" >"$PARTS/$(echo "$1" | tr / _)" 2>/dev/null \
      || true' _ {}
  echo "=== nesting $nesting" >>"$out"
  cat "$parts"/* >>"$out"
  rm -rf "$parts"
done
# Each finding: "<file>:<line>:<col>: warning: function 'f' exceeds ..." then notes
# "<n> lines including whitespace and comments" and "nesting level <k> starts here".
python3 - "$out" <<'PY'
import re, sys, statistics, collections
text = open(sys.argv[1]).read().splitlines()
funcs = {}
cur = None
threshold = 3
for line in text:
    if line.startswith("=== nesting"):
        threshold = int(line.split()[2])
        cur = None
        continue
    m = re.match(r"(.*?):(\d+):\d+: warning: function '([^']*)' exceeds", line)
    if m:
        path = m.group(1)
        inside = re.search(r'(kernel|clip|spatial)/.*', path)  # relative to the checkout
        path = inside.group(0) if inside else path
        cur = (path, int(m.group(2)), m.group(3))
        funcs.setdefault(cur, [0, 0])
        continue
    if cur is None:
        continue
    m = re.search(r"(\d+) lines including whitespace", line)
    if m:
        funcs[cur][0] = int(m.group(1))
    if re.search(r"nesting level \d+ starts here", line):
        funcs[cur][1] = max(funcs[cur][1], threshold + 1)  # nested deeper than the threshold
by_folder = collections.defaultdict(list)
for (path, ln, name), (lines, nest) in funcs.items():
    folder = path.split('/')[0]
    by_folder[folder].append((lines, nest, f"{path}:{ln} {name}"))
print(f"{'folder':8} {'functions':>9} {'median':>6} {'longest':>7} {'>60':>4} {'>80':>4} {'nest>3':>6} {'nest>4':>6}")
for folder in sorted(by_folder):
    v = by_folder[folder]
    lines = [x[0] for x in v]
    print(f"{folder:8} {len(v):9} {statistics.median(lines):6.0f} {max(lines):7} "
          f"{sum(l > 60 for l in lines):4} {sum(l > 80 for l in lines):4} "
          f"{sum(x[1] >= 4 for x in v):6} {sum(x[1] >= 5 for x in v):6}")
print("\nlongest (lines; nest: 4 = blocks nested deeper than 3, 5 = deeper than 4):")
allv = sorted((x for v in by_folder.values() for x in v), reverse=True)
for lines, nest, where in allv[:12]:
    print(f"{lines:5} {nest or '':>2}  {where}")
deep = sorted((x for v in by_folder.values() for x in v if x[1] >= 4), key=lambda x: (-x[1], -x[0]))
print("\nnested deeper than 3:")
for lines, nest, where in deep:
    print(f"{lines:5} {nest:2}  {where}")
PY
