#!/usr/bin/python3
# SPDX-License-Identifier: MIT
"""Markdown report of 3D Delaunay construction from delaunay3d_bench's JSON.

Usage:
  delaunay3d_bench --benchmark_repetitions=3 --benchmark_out=bench3.json --benchmark_out_format=json
  scripts/delaunay3d_report.py bench3.json --out-dir report

Reads benchmarks named BM_<algo>/<distribution>/<n> (raw repetitions; medians of the CPU time
computed here) and writes --out-dir/delaunay3d.md: per distribution, median seconds of
Bowyer-Watson, Green-Sibson and CGAL's Delaunay_triangulation_3 at each n with the speedup over
CGAL (CGAL time / ours) and peak heap bytes per point; the least-squares exponent of time vs n;
with the rows BM_<algo>_<T>_threads (issue 17), the strong-scaling table of ours on 1..T threads
beside CGAL's Parallel_tag triangulation on as many, and its plots delaunay3d_scaling_time.png and
delaunay3d_scaling_efficiency.png (delaunay_scaling.py); with the rows BM_memory_floor_<memory>,
the memory floor of the same result beside our one-thread time (delaunay_scaling.floor_section).
Exits 1 when a benchmark reported an error, after writing.
"""

import argparse
import json
import math
import os
import statistics
import sys
from collections import defaultdict

from delaunay_scaling import floor_section, scaling_section  # scripts/, beside this one

UNIT = {"ns": 1e-9, "us": 1e-6, "ms": 1e-3, "s": 1.0}
ALGOS = ["bowyer_watson", "green_sibson", "cgal"]


def slope(points):
    xs = [math.log(n) for n, _ in points]
    ys = [math.log(t) for _, t in points]
    mx, my = sum(xs) / len(xs), sum(ys) / len(ys)
    return sum((x - mx) * (y - my) for x, y in zip(xs, ys)) / sum((x - mx) ** 2 for x in xs)


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("json")
    parser.add_argument("--out-dir", default="report")
    args = parser.parse_args()
    data = json.load(open(args.json))
    times, heap, errors = defaultdict(list), {}, []
    for b in data["benchmarks"]:
        if b.get("run_type") == "aggregate":
            continue
        if b.get("error_occurred"):
            errors.append(f"{b['name']}: {b.get('error_message', '')}")
            continue
        parts = b["name"].split("/")
        if len(parts) < 3 or not parts[0].startswith("BM_"):
            continue
        key = (parts[0][3:], parts[1], int(parts[2]))
        times[key].append(b["cpu_time"] * UNIT[b["time_unit"]])
        heap[key] = b.get("peak_bytes/pt")
    # The one-thread families; the strong-scaling rows (BM_<algo>_<T>_threads) have their section.
    med = {k: statistics.median(v) for k, v in times.items() if k[0] in ALGOS}
    out = ["# 3D Delaunay construction\n",
           f"From `{os.path.basename(args.json)}` (host {data['context'].get('host_name', '?')}, "
           f"{data['context'].get('date', '')}). Median CPU seconds of the repetitions; speedup = CGAL's "
           "time / ours (same points, same run); CGAL is Delaunay_triangulation_3<Epick> built from "
           "the point range.\n"]
    for dist in sorted({k[1] for k in med}):
        out.append(f"## {dist}\n")
        out.append("| n | " + " | ".join(f"{a} s" for a in ALGOS) +
                   " | BW speedup | GS speedup | heap B/pt BW / GS / CGAL |")
        out.append("|---:|" + "---:|" * (len(ALGOS) + 3))
        for n in sorted({k[2] for k in med if k[1] == dist}):
            t = {a: med.get((a, dist, n)) for a in ALGOS}
            cell = lambda v: f"{v:.4f}" if v is not None else "—"  # noqa: E731
            sp = lambda a: f"{t['cgal'] / t[a]:.2f}" if t[a] and t["cgal"] else "—"  # noqa: E731
            hp = " / ".join(f"{heap.get((a, dist, n)) or 0:.0f}" for a in ALGOS)
            out.append(f"| {n:,} | " + " | ".join(cell(t[a]) for a in ALGOS) +
                       f" | {sp('bowyer_watson')} | {sp('green_sibson')} | {hp} |")
        out.append("")
        exps = []
        for a in ALGOS:
            pts = sorted((k[2], v) for k, v in med.items() if k[0] == a and k[1] == dist)
            if len(pts) >= 2:
                exps.append(f"{a} {slope(pts):.3f}")
        out.append("Fitted exponent k of time ~ n^k: " + ", ".join(exps) + ".\n")
    os.makedirs(args.out_dir, exist_ok=True)
    scaling_section(data["benchmarks"], out, args.out_dir, "delaunay3d", "cgal_parallel",
                    "CGAL Parallel_tag", same_threads=True)
    floor_section(data["benchmarks"], out)
    if errors:
        out.append("## Errors\n")
        out += [f"- {e}" for e in errors]
    with open(os.path.join(args.out_dir, "delaunay3d.md"), "w") as f:
        f.write("\n".join(out) + "\n")
    for e in errors:
        print(f"delaunay3d_report: {e}", file=sys.stderr)
    return 1 if errors else 0


if __name__ == "__main__":
    sys.exit(main())
