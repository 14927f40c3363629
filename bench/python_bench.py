#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Benchmarks from Python (issue 16): the binding's cost over the C++ call, exactmesh (one thread,
and every core: threads=0) against scipy.spatial.Delaunay (Qhull, one thread) in 2D and 3D, and how many of scipy's outputs on the degenerate
inputs are not Delaunay (checked exactly by exactmesh's checks).

Usage: PYTHONPATH=build/release/python bench/python_bench.py [--quick] [--json OUT.json]
Prints Markdown tables. Timings: medians of interleaved repetitions (exactmesh, scipy, exactmesh,
...), wall clock around each call; the binding's cost is the call's wall time minus the C++
construction's own time (construct_seconds, measured inside the call with the GIL released),
over the latter.
"""
import argparse
import json
import os
import platform
import statistics
import time

import numpy as np
import scipy
import scipy.spatial

import exactmesh


def timed(f):
    start = time.perf_counter()
    r = f()
    return time.perf_counter() - start, r


def median_spread(values):
    m = statistics.median(values)
    return m, (max(values) - min(values)) / m if m else 0.0


def binding_cost(n, repetitions):
    rows = []
    rng = np.random.default_rng(1)
    for dim, build in ((2, exactmesh.triangulate), (3, exactmesh.tetrahedralize)):
        points = rng.random((n, dim))
        walls, inner = [], []
        for _ in range(repetitions):
            wall, r = timed(lambda: build(points))
            walls.append(wall)
            inner.append(r.construct_seconds)
        overheads = [(w - c) / c for w, c in zip(walls, inner)]
        rows.append({"dim": dim, "points": n, "call_s": statistics.median(walls),
                     "construct_s": statistics.median(inner),
                     "overhead": statistics.median(overheads)})
    return rows


def orient_cells(points, cells):
    """scipy's simplices in exactmesh's orientation (counter-clockwise; orient3d > 0)."""
    cells = np.ascontiguousarray(cells, dtype=np.int64)
    if len(cells) == 0:
        return cells
    p = [np.ascontiguousarray(points[cells[:, i]]) for i in range(cells.shape[1])]
    if cells.shape[1] == 3:
        flip = exactmesh.orient2d(*p) < 0
        cells[flip] = cells[flip][:, [0, 2, 1]]
    else:
        flip = exactmesh.orient3d(*p) < 0
        cells[flip] = cells[flip][:, [0, 1, 3, 2]]
    return cells


def scipy_verdict(points, dim):
    """'ok', 'not Delaunay: ...' (exact check of scipy's output), or 'error: ...'."""
    try:
        cells = scipy.spatial.Delaunay(points).simplices
    except Exception as e:  # Qhull refuses some degenerate inputs
        return "error: " + str(e).splitlines()[0][:80]
    cells = orient_cells(points, cells)
    r = (exactmesh.check_delaunay(points, cells) if dim == 2
         else exactmesh.check_tetrahedralization(points, cells, delaunay=True))
    return "ok" if r.ok else "not Delaunay: " + r.problem[:80]


def ours_verdict(points, dim):
    if dim == 2:
        t = exactmesh.triangulate(points)
        return "ok" if exactmesh.check_delaunay(points, t.triangles).ok else "FAILED"
    t = exactmesh.tetrahedralize(points)
    if t.coplanar:
        return "ok (coplanar)"
    return "ok" if exactmesh.check_tetrahedralization(points, t.tetrahedra).ok else "FAILED"


def speed(sizes2, sizes3, repetitions):
    rows = []
    rng = np.random.default_rng(2)
    for dim, sizes in ((2, sizes2), (3, sizes3)):
        for n in sizes:
            points = rng.random((n, dim))
            ours, ours_all, theirs = [], [], []
            build = exactmesh.triangulate if dim == 2 else exactmesh.tetrahedralize
            for _ in range(repetitions):
                ours.append(timed(lambda: build(points))[0])
                ours_all.append(timed(lambda: build(points, threads=0))[0])
                theirs.append(timed(lambda: scipy.spatial.Delaunay(points))[0])
            (o, so), (a, sa), (t, st) = (median_spread(ours), median_spread(ours_all),
                                         median_spread(theirs))
            rows.append({"dim": dim, "points": n, "exactmesh_s": o, "exactmesh_spread": so,
                         "exactmesh_all_cores_s": a, "exactmesh_all_cores_spread": sa,
                         "scipy_s": t, "scipy_spread": st, "speedup": t / o,
                         "speedup_all_cores": t / a})
    return rows


def corpus_inputs(n2, n3):
    """(name, dim, points): exactmesh's degenerate distributions and the Delaunator corpus."""
    for d in exactmesh.distributions_2d:
        yield d, 2, exactmesh.points_2d(d, n2, 7)
    for d in exactmesh.distributions_3d:
        yield d, 3, exactmesh.points_3d(d, n3, 7)
    corpus = os.path.join(os.path.dirname(__file__), "..", "..", "shared", "corpus", "delaunator")
    if os.path.isdir(corpus):
        for f in sorted(os.listdir(corpus)):
            if f.endswith(".json"):
                with open(os.path.join(corpus, f)) as fh:
                    pts = np.asarray(json.load(fh), dtype=np.float64).reshape(-1, 2)
                yield "delaunator/" + f[:-5], 2, pts


def robustness(n2, n3):
    rows = []
    for name, dim, points in corpus_inputs(n2, n3):
        rows.append({"input": name, "dim": dim, "points": len(points),
                     "scipy": scipy_verdict(points, dim), "exactmesh": ours_verdict(points, dim)})
    return rows


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="small sizes, 3 repetitions")
    parser.add_argument("--json", help="write the rows as JSON here")
    args = parser.parse_args()
    reps = 3 if args.quick else 5
    cost_n = 100_000 if args.quick else 1_000_000
    sizes2 = [100_000] if args.quick else [100_000, 1_000_000]
    sizes3 = [30_000] if args.quick else [100_000, 300_000]
    print("# Python: the binding's cost, scipy.spatial.Delaunay\n")
    print(f"exactmesh {exactmesh.__version__}, scipy {scipy.__version__}, numpy {np.__version__}, "
          f"Python {platform.python_version()}, {platform.processor() or platform.machine()}, "
          f"{os.cpu_count()} cores")
    cost = binding_cost(cost_n, reps)
    print("\n| dim | points | call (s) | C++ construction (s) | binding's cost |\n|---|---|---|---|---|")
    for r in cost:
        print(f"| {r['dim']}D | {r['points']:,} | {r['call_s']:.3f} | {r['construct_s']:.3f} | "
              f"{100 * r['overhead']:.2f}% |")
    sp = speed(sizes2, sizes3, reps)
    print("\n| dim | points | exactmesh, 1 thread (s) | exactmesh, every core (s) | scipy (s) | "
          "scipy / exactmesh (1 thread, every core) |\n|---|---|---|---|---|---|")
    for r in sp:
        print(f"| {r['dim']}D | {r['points']:,} | {r['exactmesh_s']:.3f} (±{100 * r['exactmesh_spread']:.0f}%) "
              f"| {r['exactmesh_all_cores_s']:.3f} (±{100 * r['exactmesh_all_cores_spread']:.0f}%) "
              f"| {r['scipy_s']:.3f} (±{100 * r['scipy_spread']:.0f}%) | {r['speedup']:.2f}x, "
              f"{r['speedup_all_cores']:.2f}x |")
    rb = robustness(2000 if args.quick else 20000, 1000 if args.quick else 5000)
    print("\n| input | dim | points | scipy.spatial.Delaunay | exactmesh |\n|---|---|---|---|---|")
    for r in rb:
        print(f"| {r['input']} | {r['dim']}D | {r['points']:,} | {r['scipy']} | {r['exactmesh']} |")
    bad = sum(1 for r in rb if r["scipy"] != "ok")
    ours_bad = sum(1 for r in rb if not r["exactmesh"].startswith("ok"))
    print(f"\nscipy: {bad} of {len(rb)} inputs not exactly Delaunay (or refused); "
          f"exactmesh: {ours_bad} of {len(rb)}")
    if args.json:
        with open(args.json, "w") as fh:
            json.dump({"binding_cost": cost, "speed": sp, "robustness": rb}, fh, indent=1)


if __name__ == "__main__":
    main()
