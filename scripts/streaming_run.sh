#!/usr/bin/env bash
# The long form of the streaming test (issue 37, item 4; store/README.md "StreamingWorld"): a
# world of more than 10^7 vertices built and tunnelled region by region (`edgeland stream`), once
# in memory and once through a SQLite region store under a memory budget of a sixteenth of the
# in-memory world's bytes, each in its own process. Prints both runs' JSON lines and one line of
# figures: the two state hashes (they must agree), the budget, and the streaming process's peak
# resident memory against its baseline plus the budget. Exit 1 when the hashes differ, or when the
# peak passes the baseline plus the budget plus the stated overhead (16 MB: SQLite's page cache
# and WAL, the records being written, freed memory malloc keeps; 11.8 MB measured,
# store/README.md "Figures").
# Usage: scripts/streaming_run.sh [EDGELAND] [WORLD_SIDE] [REGION_DEPTH]
set -euo pipefail
cd "$(dirname "$0")/.."
edgeland="${1:-build/test/cli/edgeland}"
side="${2:-65536}"
depth="${3:-6}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

memory=$("$edgeland" stream --world-size "$side" --region-depth "$depth")
echo "$memory"
budget=$(/usr/bin/python3 -c 'import json,sys; print(json.loads(sys.argv[1])["world_bytes"] // 16)' "$memory")
streamed=$("$edgeland" stream --world-size "$side" --region-depth "$depth" --budget "$budget" \
  --store "sqlite:$work/regions.db")
echo "$streamed"
/usr/bin/python3 - "$memory" "$streamed" "$(stat -c %s "$work/regions.db")" <<'PY'
import json, sys
m, s, db = json.loads(sys.argv[1]), json.loads(sys.argv[2]), int(sys.argv[3])
mb = lambda kb: round(kb / 1024, 1)
budget_mb = round(s["budget"] / 2**20, 1)
overhead = s["peak_rss_kb"] - s["baseline_rss_kb"] - s["budget"] / 1024
print(json.dumps({
    "same_hash": m["state_hash"] == s["state_hash"], "state_hash": s["state_hash"],
    "vertices": s["vertices"], "in_memory_world_mb": round(m["world_bytes"] / 2**20, 1),
    "in_memory_peak_rss_mb": mb(m["peak_rss_kb"]), "budget_mb": budget_mb,
    "streaming_peak_rss_mb": mb(s["peak_rss_kb"]), "baseline_rss_mb": mb(s["baseline_rss_kb"]),
    "overhead_beyond_baseline_and_budget_mb": round(overhead / 1024, 1),
    "peak_loaded_mb": round(s["peak_loaded_bytes"] / 2**20, 1), "loads": s["loads"],
    "evictions": s["evictions"], "commits": s["commits"], "database_mb": round(db / 2**20, 1),
    "memory_seconds": round(m["seconds"], 1), "streaming_seconds": round(s["seconds"], 1)}))
stated_overhead_mb = 16
within = overhead / 1024 <= stated_overhead_mb
if not within:
    print(f"peak RSS passes baseline + budget + {stated_overhead_mb} MB", file=sys.stderr)
sys.exit(0 if m["state_hash"] == s["state_hash"] and within else 1)
PY
