#!/usr/bin/env python3
"""The Markdown tables of bench/README.md ("Game layer") from edgeland_game_bench's JSON.

usage: game_tables.py RESULT.json
"""
import json
import sys


def fmt(v, digits=3):
    if v is None:
        return ""
    if v == 0:
        return "0"
    if abs(v) >= 1000:
        return f"{v:,.0f}"
    return f"{v:.{digits}g}"


def load(path):
    with open(path) as f:
        data = json.load(f)
    runs = {}
    for b in data["benchmarks"]:
        name = b["name"].split("/iterations")[0]
        if b.get("error_occurred"):
            print(f"{name}: {b.get('error_message')}", file=sys.stderr)
            continue
        runs[name] = b
    return data.get("context", {}), runs


def workload_runs(runs):
    order = {"explosion": 0, "tunnel": 1, "fill": 2}
    edits = [(n.split("/")[1], n.split("/")[2], b) for n, b in runs.items() if n.startswith("game_edit/")]
    return sorted(edits, key=lambda e: order.get(e[0], 9))


def end_to_end(edits):
    print("#### End to end per edit: edgeland (GameDriver::apply + Terrain::apply + debris bodies) "
          "against the pixel pipeline")
    print()
    print("| workload | edits | edgeland median us | pixel median us | median ratio | edgeland p99 us "
          "| pixel p99 us | p99 ratio | median ratio per repeat (min-max) |")
    print("|---|---|---|---|---|---|---|---|---|")
    for w, n, b in edits:
        print(f"| {w} | {int(n):,} | {fmt(b['edgeland_median_us'])} | {fmt(b['pixel_median_us'])} "
              f"| {fmt(b['median_ratio'])} | {fmt(b['edgeland_p99_us'])} | {fmt(b['pixel_p99_us'])} "
              f"| {fmt(b['p99_ratio'])} | {fmt(b['repeat_median_ratio_min'])}-"
              f"{fmt(b['repeat_median_ratio_max'])} |")
    print()


STAGES = [
    ("landscape_edit", "the edit alone (a plain landscape)"),
    ("game_update", "GameDriver::apply"),
    ("terrain_update", "Terrain::apply"),
    ("debris_bodies", "debris bodies"),
    ("edgeland_step", "Step (edgeland world)"),
    ("bitmap_edit", "bitmap edit"),
    ("chunk_trace", "chunk trace"),
    ("chunk_rebuild", "chunk rebuild"),
    ("pixel_step", "Step (pixel world)"),
]


def stages(edits):
    print("#### Each stage per edit: median / p99 us (each edit's fastest of the repeats)")
    print()
    print("| stage | " + " | ".join(w for w, _, _ in edits) + " |")
    print("|---|" + "---|" * len(edits))
    for key, label in STAGES:
        cells = [f"{fmt(b[key + '_median_us'])} / {fmt(b[key + '_p99_us'])}" for _, _, b in edits]
        print(f"| {label} | " + " | ".join(cells) + " |")
    print()


COUNTS = [
    ("cells_per_edit", "cells replaced per edit"),
    ("chains_removed_per_edit", "chains removed per edit"),
    ("chains_added_per_edit", "chains added per edit"),
    ("triangles_per_edit", "triangles built per edit"),
    ("chunks_per_edit", "chunks traced per edit"),
    ("pixel_loops_per_edit", "pixel loops created per edit"),
    ("islands_detached", "islands detached (all edits)"),
    ("cells_traced_max", "cells traced, worst edit"),
    ("game_update_max_us", "GameDriver::apply worst us"),
    ("terrain_fixtures", "edgeland fixtures at the end"),
    ("pixel_fixtures", "pixel fixtures at the end"),
    ("pixel_vertices", "pixel loop vertices at the end"),
]


def counts(edits):
    print("#### What the edits did")
    print()
    print("| | " + " | ".join(w for w, _, _ in edits) + " |")
    print("|---|" + "---|" * len(edits))
    for key, label in COUNTS:
        print(f"| {label} | " + " | ".join(fmt(b.get(key)) for _, _, b in edits) + " |")
    print()


EXPORT = [
    ("surface_chains_ms", "surface_chains ms"),
    ("surface_loops_ms", "surface_loops ms"),
    ("all_meshes_ms", "all_meshes ms"),
    ("find_islands_ms", "find_islands ms"),
    ("terrain_build_ms", "box2d::Terrain built ms"),
    ("pixel_build_ms", "PixelTerrain built ms (every chunk traced)"),
    ("polygons", "polygons"),
    ("vertices", "vertices"),
    ("cells", "cells"),
    ("chains", "chains"),
    ("chain_vertices", "chain points"),
    ("loops", "whole loops"),
    ("triangles", "triangles"),
    ("islands", "islands"),
    ("terrain_fixtures", "edgeland fixtures"),
    ("pixel_fixtures", "pixel fixtures"),
    ("pixel_vertices", "pixel loop vertices"),
]


def export(runs):
    rows = [(n, b) for n, b in runs.items() if n.startswith("game_export/")]
    for name, b in rows:
        print(f"#### Whole world: the demo world after {int(name.split('/')[2]):,} actions "
              "(fastest of the repeats)")
        print()
        print("| | |")
        print("|---|---|")
        for key, label in EXPORT:
            print(f"| {label} | {fmt(b.get(key))} |")
        print()


def main():
    context, runs = load(sys.argv[1])
    print(f"<!-- {context.get('date', '')}, {context.get('num_cpus', '?')} cpus, "
          f"{context.get('library_build_type', '')} benchmark library -->")
    print()
    edits = workload_runs(runs)
    if edits:
        end_to_end(edits)
        stages(edits)
        counts(edits)
    export(runs)


if __name__ == "__main__":
    main()
