#!/usr/bin/python3
"""The function-size check (issue 38, item 5): no function of production code longer than 80
lines, none of the benchmarks, fuzzers and proofs longer than 100, except those named in
scripts/function_sizes_allow.txt with a reason and the length they may keep.

Functions are found by Universal Ctags (universal-ctags: it parses the sources without a compile
database, so the Emscripten-only sources of play/web count too); a function's length is its
lines from its first line to its closing brace, comments and blank lines included. An
allow-list entry that no longer applies (the function is gone, or within its limit, or longer
than the entry allows) fails the check as well, so that the list can only shrink.

Usage: scripts/check_function_sizes.py [--top N]   (run from anywhere; ctest library.function_sizes)
Prints a table per folder (functions, median, longest, how many over 60 and 80 lines) and the N
longest functions (default 5), then every problem.
"""
import json
import os
import re
import shutil
import statistics
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
# Folder -> the most lines a function may have there.
LIMITS = {
    "kernel": 80, "clip": 80, "spatial": 80, "io": 80, "game": 80, "adapters": 80,
    "cli": 80, "play": 80, "demo": 80,
    "bench": 100, "fuzz": 100, "proofs": 100,
}
ALLOW_FILE = os.path.join(ROOT, "scripts", "function_sizes_allow.txt")


def functions():
    """(lines, path, line, qualified name) of every C++ function defined in LIMITS' folders."""
    ctags = shutil.which("ctags-universal") or shutil.which("ctags")
    if ctags is None:
        sys.exit("function_sizes: universal-ctags is not installed (apt-get install -y universal-ctags)")
    command = [ctags, "--output-format=json", "--fields=+ne", "--languages=C++",
               "--kinds-C++=f", "-R", "-f", "-"] + sorted(LIMITS)
    out = subprocess.run(command, cwd=ROOT, check=True, capture_output=True, text=True).stdout
    found = []
    for line in out.splitlines():
        tag = json.loads(line)
        if tag.get("_type") != "tag":
            continue
        if "end" not in tag:
            sys.exit(f"function_sizes: ctags gave no end for {tag['path']}:{tag['line']}")
        # Anonymous namespaces and lambdas get hashed names from ctags: one stable spelling.
        name = re.sub(r"__anon[0-9a-f]+", "(anonymous)", tag.get("scope", "") + "::" + tag["name"])
        name = name.lstrip(":")
        found.append((tag["end"] - tag["line"] + 1, tag["path"], tag["line"], name))
    return found


def allow_list():
    """(path, name) -> (lines allowed, reason), from ALLOW_FILE's `path name lines reason` lines."""
    allowed = {}
    with open(ALLOW_FILE, encoding="utf-8") as f:
        for number, text in enumerate(f, 1):
            text = text.strip()
            if not text or text.startswith("#"):
                continue
            parts = text.split(None, 3)
            if len(parts) < 4 or not parts[2].isdigit():
                sys.exit(f"{ALLOW_FILE}:{number}: expected `path name lines reason`")
            allowed[(parts[0], parts[1])] = (int(parts[2]), parts[3])
    return allowed


def print_table(found):
    """One line per folder: functions, median and longest length, how many over 60 and 80."""
    print(f"{'folder':9} {'functions':>9} {'median':>6} {'longest':>7} {'>60':>4} {'>80':>4}")
    for folder in sorted(LIMITS):
        lines = [f[0] for f in found if f[1].split("/")[0] == folder]
        if lines:
            print(f"{folder:9} {len(lines):9} {statistics.median(lines):6.0f} {max(lines):7} "
                  f"{sum(n > 60 for n in lines):4} {sum(n > 80 for n in lines):4}")


def main():
    top = int(sys.argv[2]) if len(sys.argv) == 3 and sys.argv[1] == "--top" else 0
    found = functions()
    allowed = allow_list()
    problems, used = [], set()
    for lines, path, line, name in found:
        limit = LIMITS[path.split("/")[0]]
        key = (path, name)
        if key in allowed:
            used.add(key)
            most, _ = allowed[key]
            if lines <= limit:
                problems.append(f"{path}:{line} {name}: {lines} lines, within {limit}: "
                                "remove its allow-list entry")
            elif lines > most:
                problems.append(f"{path}:{line} {name}: {lines} lines, the allow-list says {most}")
        elif lines > limit:
            problems.append(f"{path}:{line} {name}: {lines} lines, over {limit}")
    for key in sorted(set(allowed) - used):
        problems.append(f"{key[0]} {key[1]}: in the allow-list but not found: remove the entry")
    print_table(found)
    by_length = sorted(found, reverse=True)
    print(f"function_sizes: {len(found)} functions in {len(LIMITS)} folders; longest:")
    for lines, path, line, name in by_length[:max(top, 5)]:
        print(f"  {lines:4} {path}:{line} {name}")
    for p in problems:
        print("function_sizes: " + p)
    print(f"function_sizes: {len(problems)} problem(s)")
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
