#!/usr/bin/env python3
"""Turns the JSON files of run_pieces.sh into the Markdown tables of bench/README.md
("Triangulation and convex pieces"): triangles per second of triangulate() and CGAL's
constrained Delaunay triangulation, and convex pieces per polygon of convex_pieces() and
CGAL's partitions, with their times.
"""
import json
import pathlib
import sys

PARTITIONS = ["edgeland_8", "edgeland_unbounded", "cgal_approx", "cgal_greene", "cgal_optimal"]


def load(directory):
    results = {}
    for path in sorted(pathlib.Path(directory).glob("*.json")):
        data = json.loads(path.read_text())
        if "failed" in data:
            results[data["failed"]["name"]] = {"failed": data["failed"]["why"]}
            continue
        for entry in data.get("benchmarks", []):
            results[entry["name"]] = entry
    return results


def workloads(results):
    seen = []
    for name in results:
        w = name.split("/")[-1]
        if w not in seen:
            seen.append(w)
    order = ["demo", "demo_small", "stars_40"]
    return sorted(seen, key=lambda w: (order.index(w) if w in order else len(order), w))


def ms(entry):
    return entry["real_time"] if entry.get("time_unit") == "ms" else entry["real_time"] / 1e6


def triangle_table(results):
    print("| workload | polygons | triangles | edgeland triangles/s | of its time validate() | CGAL CDT triangles/s | edgeland / CGAL |")
    print("|---|---|---|---|---|---|---|")
    for w in workloads(results):
        e = results.get(f"triangulate/edgeland/{w}")
        c = results.get(f"triangulate/cgal_cdt/{w}")
        v = results.get(f"triangulate/validate_only/{w}")
        if not e or "failed" in e:
            continue
        e_rate = e["items_per_second"]
        c_rate = c["items_per_second"] if c and "failed" not in c else None
        ratio = f"{e_rate / c_rate:.1f}x" if c_rate else "-"
        c_text = f"{c_rate:,.0f}" if c_rate else (c["failed"] if c else "-")
        share = f"{100 * e_rate / v['items_per_second']:.0f}%" if v and "failed" not in v else "-"
        print(f"| {w} | {e['polygons']:,.0f} | {e['triangles']:,.0f} | {e_rate:,.0f} | {share} | {c_text} | {ratio} |")


def pieces_table(results):
    head = " | ".join(f"{p} pieces (ms)" for p in PARTITIONS)
    print(f"| workload | polygons | triangles | {head} |")
    print("|---|---|---|" + "---|" * len(PARTITIONS))
    for w in workloads(results):
        cells = []
        base = None
        for p in PARTITIONS:
            r = results.get(f"convex_pieces/{p}/{w}")
            if r is None:
                cells.append("-")
            elif "failed" in r:
                cells.append(r["failed"])
            else:
                base = base or r
                per = r["pieces"] / r["polygons"]
                cells.append(f"{r['pieces']:,.0f} ({per:.2f}/polygon, {ms(r):,.1f} ms)")
        if base is None:
            continue
        print(f"| {w} | {base['polygons']:,.0f} | {base['triangles']:,.0f} | " + " | ".join(cells) + " |")


def main():
    results = load(sys.argv[1])
    print("Triangulation\n")
    triangle_table(results)
    print("\nConvex pieces (counts: fewer is better; time per whole workload)\n")
    pieces_table(results)


if __name__ == "__main__":
    main()
