#!/usr/bin/env python3
"""Turns the JSON files written by run_scale.sh into the Markdown table of bench/README.md,
"Scale: many crossings, large inputs (issue 16)".

Per shape and size: edgeland's crossing count; per peer the CPU seconds of apply() with the
ratio peer / edgeland (above 1: edgeland is faster), and the process's peak resident memory
before apply() -> after it, in MB.
"""
import json
import pathlib
import sys

PEERS = ["edgeland", "edgeland_valid", "geos", "clipper1", "boost_int64"]
SHAPES = ["comb_short", "comb_long", "zigzag", "minus_empty"]


def load(directory):
    """name SHAPE/PEER/SIZE -> a benchmark entry, or {"failed": {...}}; and meta.json."""
    results = {}
    meta = {}
    for path in sorted(pathlib.Path(directory).glob("*.json")):
        try:
            data = json.loads(path.read_text())
        except json.JSONDecodeError:
            continue
        if path.name == "meta.json":
            meta = data
        elif "failed" in data:
            results[short(data["failed"]["name"])] = {"failed": data["failed"]}
        else:
            for entry in data.get("benchmarks", []):
                results[short(entry["name"])] = entry
    return results, meta


def short(name):
    return "/".join(name.split("/")[:3])


def seconds(entry, key="cpu_time"):
    scale = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}[entry.get("time_unit", "ns")]
    return entry[key] * scale


def mb(value):
    return f"{value:,.0f}"


def time_cell(entry, base):
    """CPU seconds and the ratio to edgeland's, or why there is no time."""
    if entry is None:
        return "not run"
    if "failed" in entry:
        f = entry["failed"]
        if f["why"] == "timeout":
            return f"> {f['limit_s']} s"
        if f["why"] == "skipped":
            return f"> {f['limit_s']} s (skipped)"
        return f["why"]
    if entry.get("error_occurred"):
        return "threw"
    t = seconds(entry)
    cell = f"{t:.3g}"
    if base is not None and base is not entry:
        ratio = t / seconds(base)
        cell += f" ({ratio:.2g}x)" if ratio < 10 else f" ({ratio:.0f}x)"
    if entry.get("valid", 1) != 1:
        cell += " ✗"
    return cell


def memory_cell(entry):
    if entry is None:
        return ""
    if "failed" in entry:
        peak = entry["failed"].get("rss_peak_mb")
        return f"{mb(peak)} at kill" if peak is not None else ""
    if "rss_peak_mb" not in entry:
        return ""
    return f"{mb(entry['rss_before_mb'])} → {mb(entry['rss_peak_mb'])}"


def usable(entry):
    return entry is not None and "failed" not in entry and not entry.get("error_occurred")


def notes_for(name, entry, notes):
    if entry is None:
        return
    if "failed" in entry:
        f = entry["failed"]
        if f["why"] == "skipped":
            notes.append(f"{name}: not run, over the limit at size {f['after']:,}")
        elif f["why"] != "timeout":
            notes.append(f"{name}: {f['why']}")
        return
    if entry.get("error_occurred"):
        notes.append(f"{name}: {entry.get('error_message', '')}")
        return
    if entry.get("valid", 1) != 1:
        notes.append(f"{name}: {entry.get('label', 'invalid result')}")
    wall, cpu = seconds(entry, "real_time"), seconds(entry)
    if wall > 1.2 * cpu and wall - cpu > 1:  # below a second it is noise, not load
        notes.append(f"{name}: wall {wall:.3g} s against CPU {cpu:.3g} s (machine busy)")


def table(results, notes):
    sizes = {}
    for name in results:
        shape, _, size = name.split("/")
        sizes.setdefault(shape, set()).add(int(size))
    peers = [p for p in PEERS if any(n.split("/")[1] == p for n in results)]
    header = ["shape", "n per operand", "crossings"]
    for peer in peers:
        header += [f"{peer} s" + ("" if peer == "edgeland" else " (ratio)"), f"{peer} MB"]
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    for shape in [s for s in SHAPES if s in sizes]:
        for n in sorted(sizes[shape]):
            base = results.get(f"{shape}/edgeland/{n}")
            base = base if usable(base) else None
            crossings = base.get("intersections", 0) if base else None
            row = [shape, f"{n:,}", "" if crossings is None else f"{crossings:,.0f}"]
            for peer in peers:
                name = f"{shape}/{peer}/{n}"
                entry = results.get(name)
                row += [time_cell(entry, base), memory_cell(entry)]
                notes_for(name, entry, notes)
            lines.append("| " + " | ".join(row) + " |")
    return lines


def main():
    results, meta = load(sys.argv[1] if len(sys.argv) > 1 else ".")
    notes = []
    out = []
    if meta:
        dirty = (f", with {meta['dirty_files']} uncommitted or new files in kernel/ clip/ "
                 f"spatial/" if meta.get("dirty_files") else "")
        out += [f"Measured {meta['date']}, library at {meta['commit']}{dirty}; wall-clock "
                f"limit {meta['limit_s']} s per process.", ""]
    out += ["CPU seconds of apply() (ratio: peer / edgeland, above 1 edgeland is faster); MB: "
            "the process's peak resident set before apply() → after it. ✗: the result, "
            "rounded to integers, fails the validity check.", ""]
    out += table(results, notes)
    if notes:
        out += ["", "Notes:", ""] + [f"- {n}" for n in notes]
    print("\n".join(out))


if __name__ == "__main__":
    main()
