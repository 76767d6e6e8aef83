#!/usr/bin/env python3
"""Markdown tables of edgeland_landscape_bench's JSON output (bench/README.md, "Landscape").

    landscape_tables.py RESULTS.json [CROSSOVER.tsv]

Prints the tables; with a second argument also writes the crossover curves for plot_crossover
(write_plot_data). The crossover radius of a terrain is where the landscape's median carve
time, interpolated log-log between measured radii, falls to the bitmap's.
"""
import json
import math
import sys


def load(path):
    """Benchmarks by their name without the iterations/manual_time suffixes."""
    with open(path) as f:
        data = json.load(f)
    out = {}
    for b in data["benchmarks"]:
        parts = [p for p in b["name"].split("/") if not p.startswith("iterations:") and p != "manual_time"]
        out["/".join(parts)] = b
    return out


def fmt(value, digits=3):
    if value is None:
        return ""
    if isinstance(value, str):
        return value
    if value == 0:
        return "0"
    if abs(value) >= 1000:
        return f"{value:,.0f}"
    return f"{value:.{digits}g}"


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(fmt(c) for c in row) + " |" for row in rows]
    return "\n".join(lines)


def error_or(b, key):
    if b is None:
        return None
    if b.get("error_occurred"):
        return "error: " + b.get("error_message", "")
    return b.get(key)


RIVALS = ["bitmap", "quadtree", "kdtree", "grid"]
WORKLOADS = ["carve", "dig", "fill", "spot", "pit"]


def edit_tables(r):
    out = []
    rows, blocks = [], {}
    for name, b in r.items():
        parts = name.split("/")
        if parts[0] != "landscape_edit":
            continue
        workload, rival = parts[1], parts[2]
        rows.append((WORKLOADS.index(workload), RIVALS.index(rival), [
            workload, rival, error_or(b, "median_us"), b.get("p99_us"), b.get("mean_us"),
            b.get("median_vs_bitmap"), b.get("p99_vs_bitmap"), b.get("flatness"),
            b.get("vertices"), b.get("cells"), b.get("bytes")]))
        keys = sorted(k for k in b if k.startswith("block") and k.endswith("_median_us"))
        blocks.setdefault(workload, {})[rival] = [b[k] for k in keys]
    rows.sort(key=lambda t: (t[0], t[1]))
    out.append("#### Edits (8192 x 8192 world; us per edit, each edit its fastest of the repeats)\n")
    out.append(table(["workload", "rival", "median us", "p99 us", "mean us", "median / bitmap",
                      "p99 / bitmap", "flatness (last block / first)", "vertices", "cells", "bytes"],
                     [t[2] for t in rows]))
    for workload in WORKLOADS:
        if workload not in blocks:
            continue
        per = blocks[workload]
        present = [x for x in RIVALS if x in per]
        n = max(len(v) for v in per.values())
        out.append(f"\nMedian us per edit in each block of edits, `{workload}`:\n")
        out.append(table(["block"] + present,
                         [[str(i + 1)] + [per[x][i] if i < len(per[x]) else None for x in present]
                          for i in range(n)]))
    return out


def query_tables(r):
    order = ["material_at", "material_at_walk", "raycast", "overlaps"]
    who_order = ["bitmap", "box2d", "quadtree", "kdtree", "grid"]
    rows = []
    for name, b in r.items():
        parts = name.split("/")
        if parts[0] != "landscape_query":
            continue
        rows.append((order.index(parts[1]), who_order.index(parts[2]), [
            parts[1], parts[2], error_or(b, "median_ns"), b.get("median_vs_bitmap"),
            b.get("median_vs_box2d"), b.get("agree_bitmap"), b.get("agree_box2d"),
            b.get("nonzero_answers")]))
    rows.sort(key=lambda t: (t[0], t[1]))
    return ["#### Queries (8192 x 8192 cave terrain; ns per query, median over batches of 64)\n",
            table(["query", "contender", "median ns", "/ bitmap", "/ box2d", "agrees with bitmap",
                   "agrees with box2d", "answers hit / solid"], [t[2] for t in rows])]


def scaling_tables(r):
    rows = []
    for name, b in r.items():
        parts = name.split("/")
        if parts[0] != "landscape_scaling":
            continue
        rows.append((int(parts[2]), parts[1] != "bitmap", [
            f"{int(parts[2])}^2", parts[1], b.get("edits"), error_or(b, "edit_median_us"),
            b.get("edit_p99_us"), b.get("material_at_ns"), b.get("raycast_ns"), b.get("vertices"),
            b.get("bytes"), b.get("bytes_per_vertex"), b.get("bytes_vs_bitmap"),
            b.get("edit_median_vs_bitmap"), b.get("edit_p99_vs_bitmap"),
            b.get("material_at_vs_bitmap"), b.get("raycast_vs_bitmap")]))
    sizes = sorted({t[0] for t in rows})
    for side in sizes:
        if not any(t[0] == side and not t[1] for t in rows):
            missing = [f"{side}^2", "bitmap", None, "not built: 4 GiB" if side > 16384 else "missing",
                       None, None, None, None, side * side]
            rows.append((side, False, missing + [None] * 6))
    rows.sort(key=lambda t: (t[0], t[1]))
    return ["#### World size (one 32-gon of radius 40 carved per 128 x 128 units; the last 1,000 edits timed)\n",
            table(["world", "rival", "edits", "edit median us", "edit p99 us", "material_at ns",
                   "raycast ns", "vertices", "bytes", "bytes / vertex", "bytes / bitmap bytes",
                   "edit median / bitmap", "edit p99 / bitmap", "material_at / bitmap",
                   "raycast / bitmap"], [t[2] for t in rows])]


TERRAINS = [("caves", "cave terrain"), ("solid", "solid rock")]


def crossover(r, terrain):
    """[(radius, sides, landscape_us, bitmap_us)] of a terrain and the interpolated crossover
    radius (0: none in the range)."""
    curve = []
    for name, b in r.items():
        parts = name.split("/")
        if parts[0] == "landscape_crossover" and parts[1] == terrain and parts[2] == "quadtree":
            other = r.get(f"landscape_crossover/{terrain}/bitmap/{parts[3]}")
            if other and "median_us" in b and "median_us" in other:
                curve.append((int(parts[3]), b["shape_vertices"], b["median_us"], other["median_us"]))
    curve.sort()
    radius = 0.0
    for (r0, _, l0, b0), (r1, _, l1, b1) in zip(curve, curve[1:]):
        d0, d1 = math.log(l0 / b0), math.log(l1 / b1)
        if d0 > 0 >= d1:  # the landscape becomes faster between r0 and r1
            f = d0 / (d0 - d1)
            radius = math.exp(math.log(r0) + f * (math.log(r1) - math.log(r0)))
            break
    return curve, radius


def crossover_tables(curves):
    out = []
    for (terrain, title), (curve, radius) in zip(TERRAINS, curves):
        rows = [[str(r), s, l, b, l / b] for r, s, l, b in curve]
        verdict = (f"Crossover (log-log interpolation): radius ~{radius:.0f}."
                   if radius > 0 else "No crossover in the measured range.")
        out += [f"#### Crossover, {title} (one carve into a 16384 x 16384 world; median over the centres)\n",
                table(["radius", "shape vertices", "landscape us", "bitmap us", "landscape / bitmap"], rows),
                "\n" + verdict + "\n"]
    return out


def write_plot_data(path, curves):
    """plot_crossover's input: a names line, one line per radius with (bitmap, landscape) per
    terrain, and a crossover line per terrain."""
    with open(path, "w") as f:
        f.write("names\t" + "\t".join(title for _, title in TERRAINS) + "\n")
        by_radius = {}
        for k, (curve, _) in enumerate(curves):
            for rad, _, l, b in curve:
                by_radius.setdefault(rad, [None] * (2 * len(curves)))[2 * k:2 * k + 2] = [b, l]
        for rad in sorted(by_radius):
            if None not in by_radius[rad]:
                f.write(f"{rad}\t" + "\t".join(str(v) for v in by_radius[rad]) + "\n")
        for k, (_, radius) in enumerate(curves):
            f.write(f"crossover\t{k}\t{radius:.1f}\n")


def snapshot_tables(r):
    """The ratios from the two rows themselves (the landscape's counters divide by a bitmap run
    of their own, made earlier in the process)."""
    rows = []
    bitmap = r.get("landscape_snapshot/bitmap", {})
    for rival in ["bitmap", "quadtree"]:
        b = r.get("landscape_snapshot/" + rival)
        if not b:
            continue
        total = b.get("copy_and_carve_us")
        fresh, reuse = bitmap.get("copy_and_carve_us"), bitmap.get("copy_reuse_and_carve_us")
        rows.append([rival, error_or(b, "copy_us"), b.get("copy_reuse_us"), b.get("carve_us"), total,
                     b.get("copy_reuse_and_carve_us"),
                     total / fresh if rival != "bitmap" and total and fresh else None,
                     total / reuse if rival != "bitmap" and total and reuse else None])
    return ["#### Snapshot + one carve (the 8192 x 8192 world after the carve workload; medians)\n",
            table(["rival", "copy us", "copy into an existing array us", "carve us",
                   "copy + carve us", "copy into existing + carve us", "copy + carve / bitmap",
                   "copy + carve / bitmap into existing"], rows)]


def main():
    r = load(sys.argv[1])
    parts = edit_tables(r) + [""] + query_tables(r) + [""] + scaling_tables(r) + [""]
    curves = [crossover(r, terrain) for terrain, _ in TERRAINS]
    parts += crossover_tables(curves) + snapshot_tables(r)
    print("\n".join(parts))
    if len(sys.argv) > 2:
        write_plot_data(sys.argv[2], curves)


if __name__ == "__main__":
    main()
