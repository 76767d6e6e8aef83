#!/usr/bin/env python3
"""Turns the JSON files written by run_ratios.sh into the Markdown tables of bench/README.md.

One-shot workloads: peer CPU time / edgeland CPU time (above 1: edgeland is faster).
Carving: the first operation whose result fails the validity check, and CPU ms per operation
for each block of operations.
"""
import json
import pathlib
import sys

PEERS = ["edgeland", "edgeland_valid", "boost_int64", "boost_double", "clipper1", "geos", "cgal_epeck", "cgal_epick"]
FAMILIES = ["smooth_intersection", "smooth_difference", "spiky_intersection",
            "spiky_difference", "checkerboard_union"]


def load(directory):
    """name -> result dict (a benchmark entry, or {"failed": why})."""
    results = {}
    for path in sorted(pathlib.Path(directory).glob("*.json")):
        text = path.read_text()
        try:
            data = json.loads(text)
        except json.JSONDecodeError:
            continue
        if "failed" in data:
            results[data["failed"]["name"]] = {"failed": data["failed"]["why"]}
            continue
        for entry in data.get("benchmarks", []):
            results[entry["name"]] = entry
    return results


def ms(entry):
    scale = {"ns": 1e-6, "us": 1e-3, "ms": 1.0, "s": 1e3}[entry.get("time_unit", "ns")]
    return entry["cpu_time"] * scale


def problem(entry):
    """Why an entry has no usable time, or None."""
    if entry is None:
        return "not run"
    if "failed" in entry:
        return entry["failed"]
    if entry.get("error_occurred"):
        return "threw"
    return None


def one_shot(results, notes):
    sizes = {}
    for name in results:
        parts = name.split("/")
        if len(parts) >= 3 and parts[0] in FAMILIES:
            sizes.setdefault(parts[0], set()).add(int(parts[2]))
    header = ["workload", "n", "edgeland ms"] + PEERS[1:]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for family in FAMILIES:
        for n in sorted(sizes.get(family, [])):
            get = lambda peer: results.get(f"{family}/{peer}/{n}")
            base = get("edgeland")
            base_problem = problem(base)
            row = [family, f"{n:,}"]
            if base_problem:
                row.append(base_problem)
                notes.append(f"edgeland {family} n={n}: {base_problem} "
                             f"{(base or {}).get('error_message', '')}".rstrip())
            else:
                cell = f"{ms(base):.3g}"
                if base.get("valid", 1) != 1:
                    cell += " invalid"
                    notes.append(f"edgeland {family} n={n}: {base.get('label', '')}")
                row.append(cell)
            for peer in PEERS[1:]:
                entry = get(peer)
                why = problem(entry)
                if why:
                    row.append(why)
                    if why != "not run":
                        notes.append(f"{peer} {family} n={n}: {why} "
                                     f"{entry.get('error_message', '')}".rstrip())
                    continue
                if base_problem:
                    row.append(f"({ms(entry):.3g} ms)")
                    continue
                ratio = ms(entry) / ms(base)
                cell = f"{ratio:.2g}" if ratio < 10 else f"{ratio:.0f}"
                if entry.get("valid", 1) != 1:
                    cell += " ✗"
                if ratio < 0.01:
                    notes.append(f"PATHOLOGICAL: edgeland is {1 / ratio:.0f}x slower than {peer} "
                                 f"on {family} n={n}")
                row.append(cell)
            lines.append("| " + " | ".join(row) + " |")
    return lines


def carving(results, notes):
    runs = {}
    for name, entry in results.items():
        parts = name.split("/")
        if parts[0] == "carving" and len(parts) >= 3:
            runs[parts[1]] = entry
    if not runs:
        return []
    lines = ["| peer | ops run | first invalid op | same, repeated vertices merged | threw at op "
             "| first problem |", "|---|---|---|---|---|---|"]
    blocks = {}
    block_size = None
    ops_run = 0
    for peer in PEERS:
        entry = runs.get(peer)
        why = problem(entry)
        if why and "failed" in (entry or {}):
            lines.append(f"| {peer} | {why} | | | | |")
            continue
        if why:
            continue
        invalid = int(entry["first_invalid_op"])
        threw = int(entry["threw_at_op"])
        lenient = int(entry.get("first_invalid_op_lenient", -2))
        lenient_cell = "" if lenient == -2 else ("none" if lenient < 0 else f"{lenient:,}")
        lines.append(f"| {peer} | {int(entry['ops_done']):,} | "
                     f"{'none' if invalid < 0 else f'{invalid:,}'} | {lenient_cell} | "
                     f"{'' if threw < 0 else f'{threw:,}'} | {entry.get('label', '')} |")
        if peer == "edgeland" and (invalid >= 0 or threw >= 0):
            notes.append(f"edgeland carving: {entry.get('label', '')}")
        block_size = int(entry["block_size"])
        ops_run = max(ops_run, int(entry["ops_done"]))
        b = 0
        while f"block{b:02d}_ms_per_op" in entry:
            partial = (b + 1) * block_size > int(entry["ops_done"])
            blocks.setdefault(b, {})[peer] = (entry[f"block{b:02d}_ms_per_op"],
                                              entry[f"block{b:02d}_vertices"], partial)
            b += 1
    present = [p for p in PEERS if p in runs and not problem(runs[p])]
    lines += ["", "CPU ms per operation, mean over each block (edgeland's output vertex count "
              "at the end of the block in brackets; * a partial block, the peer's last):", "",
              "| ops | " + " | ".join(present) + " |", "|" + "---|" * (len(present) + 1)]
    for b in sorted(blocks):
        row = [f"{b * block_size + 1:,}-{min((b + 1) * block_size, ops_run):,}"]
        for peer in present:
            if peer not in blocks[b]:
                row.append("")
                continue
            t, v, partial = blocks[b][peer]
            cell = f"{t:.3g} ({int(v):,})" if peer == "edgeland" else f"{t:.3g}"
            row.append(cell + ("*" if partial else ""))
        lines.append("| " + " | ".join(row) + " |")
    return lines


def main():
    results = load(sys.argv[1] if len(sys.argv) > 1 else ".")
    notes = []
    out = ["### Peer CPU time / edgeland CPU time (above 1: edgeland is faster)", "",
           "✗: the peer's result, rounded to integers, fails the validity check "
           "(bench/README.md).", ""]
    out += one_shot(results, notes)
    carve = carving(results, notes)
    if carve:
        out += ["", "### Carving (each result is the next subject)", ""] + carve
    if notes:
        out += ["", "### Notes", ""] + [f"- {n}" for n in notes]
    print("\n".join(out))


if __name__ == "__main__":
    main()
